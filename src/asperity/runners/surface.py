"""Runner of ``analysis = "surface"``: roughness parameters, spectra, filtering, turning models.

The surfaces a case names (one, or several on the same grid: built-in profiles A, B, C, or a
turned profile at several tool natural frequencies plus the kinematic one) are characterised by
the ISO parameters (:func:`asperity.surfaces.roughness_parameters`), their power spectrum and
autocorrelation length; a cut-off splits profiles into waviness and roughness with the ISO
16610-21 Gaussian filter. Turned surfaces are compared with Seireg's eq. (4.1) and Table 4.1,
and vibrating ones are evaluated along the workpiece as in his Fig. 4.2.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

import numpy as np
import xarray as xr

from .. import surfaces as s
from ..cases.roughness import surface_recipe
from ..cases.surface import MAX_POINTS, SurfaceSpec
from ..errors import InputError
from ..references import cite
from ..results import Comparison, Outcome, variable
from ..surfaces.io import read_measured
from ..surfaces.machining import (
    MICROINCH,
    PARABOLA_TOLERANCE,
    arc_peak_to_valley,
    parabola_error,
    parabola_feed_limit,
)
from ..surfaces.parameters import amplitude_moments
from ..surfaces.recipe import build_surface

__all__ = ["run"]

#: ISO parameter name without its R/S/P/W prefix -> long name
_NAMES = {
    "a": "arithmetic mean height",
    "q": "root-mean-square height",
    "sk": "skewness",
    "ku": "kurtosis",
    "p": "maximum peak height",
    "v": "maximum valley depth",
    "z": "maximum height",
    "t": "total height",
    "dq": "root-mean-square slope",
    "dr": "developed interfacial area ratio",
}
_LENGTHS = {"a", "q", "p", "v", "z", "t"}
_TURNING = "Boring, turning"
_SYNTHETIC = ("Profiles A, B and C are synthetic stand-ins generated to the paper's Ra values; "
              "the measured traces of Holmes et al. (2005) are not published as data.")
_DYNAMIC = ("The tool-vibration model follows Seireg's description of Jang & Seireg's "
            "simulation (tool assembly as a damped single-degree-of-freedom oscillator under a "
            "random thrust force); its force parameters are illustrative defaults, so the "
            "curves show trends, not the book's numbers.")


@dataclass(frozen=True)
class _Evaluated:
    """What is computed for one surface."""

    parameters: dict  # of the evaluated (roughness) profile or of the topography
    primary: dict  # of the unfiltered surface
    waviness: s.Profile | None
    roughness: s.Profile | None
    spectrum: s.PowerSpectrum
    correlation_length: float


def _key(name: str, tag: str = "") -> str:
    """Summary key of an ISO parameter: ``Ra`` -> ``ra_m``, ``Rsk`` -> ``rsk``."""
    unit = "_m" if name[1:] in _LENGTHS else ""
    return name.lower() + (f"_{tag}" if tag else "") + unit


def _tag(label: str) -> str:
    """A label as part of a key: "28 Hz" -> "28hz", "A" -> "a"."""
    return re.sub(r"[^a-z0-9]+", "_", label.lower().replace(" hz", "hz")).strip("_")


def _prefixed(exc: InputError) -> InputError:
    """An error of a generator, renamed to the case key it comes from."""
    names = {"rms_height": "rms", "size": "length"}
    field = names.get(exc.field, exc.field)
    if field in SurfaceSpec.model_fields:
        return InputError(f"surface.{field}", exc.expected, exc.got)
    return exc


def _generated(spec):
    """The gaussian, self-affine or ground surface of ``spec``, or the
    :class:`~asperity.surfaces.io.Reading` of its file."""
    if spec.kind != "file":
        return build_surface(surface_recipe(spec), spec.profile_length(), spec.profile_spacing(),
                             width=spec.width)
    try:
        reading = read_measured(spec.path, spec.spacing, **spec.read_options())
    except InputError as exc:
        if exc.field == "spacing":
            raise InputError("surface.spacing", exc.expected, exc.got) from None
        if not exc.field.startswith(str(spec.path)):
            raise
        where = exc.field.removeprefix(str(spec.path)).lstrip(":").strip()
        raise InputError("surface.path", exc.expected + (f" (at {where})" if where else ""),
                         exc.got) from None
    surface = reading.surface
    if surface.z.size > MAX_POINTS:
        raise InputError("surface.path", f"a surface of at most {MAX_POINTS} points",
                         surface.z.shape)
    if np.abs(surface.z).max() > 1.0:
        raise InputError("surface.path", "heights in metres (|z| <= 1 m); " + (
            reading.unit_advice or "give the file's unit (unit, z_unit)"),
            float(np.abs(surface.z).max()))
    return reading


def _surfaces(spec, progress) -> tuple[dict, list]:
    """Label -> surface (all on one grid), and the TurnedSurface of each natural frequency."""
    labels = spec.labels()
    total = len(labels)
    made, turned = {}, []
    try:
        if spec.kind == "builtin":
            for label in labels:
                made[label] = build_surface(surface_recipe(spec, profile=label),
                                            spec.profile_length(), spec.profile_spacing())
                if progress is not None:
                    progress(len(made), total, f"profile {label}")
        elif spec.kind == "turned":
            length, h = spec.profile_length(), spec.profile_spacing()
            for fn, label in zip(spec.natural_frequency or (), labels, strict=False):
                res = s.turned_profile_dynamic(
                    spec.feed, spec.nose_radius, spec.depth_of_cut, spec.cutting_speed,
                    spec.workpiece_diameter, length, h, fn,
                    damping_ratio=spec.damping_ratio or 0.05, mass=spec.mass,
                    seed=spec.seed or 0)
                turned.append(res)
                made[label] = res.profile
                if progress is not None:
                    progress(len(made), total, f"tool vibration at {label}")
            made["kinematic"] = build_surface(surface_recipe(spec, natural_frequency=None),
                                              length, h)
        else:
            made[labels[0]] = _generated(spec)
    except InputError as exc:
        raise _prefixed(exc) from None
    return made, turned


def _iso_texture(case, surface, reading):
    """The ISO texture evaluation of ``surface`` as ``asperity surface stats`` makes it, or None
    and the warning saying why it could not be made (the doubt on a file's units first, when
    they are in doubt: :meth:`~asperity.surfaces.io.Reading.explained`)."""
    from ..surfaces.texture import evaluate_texture

    degree = case.evaluation.form_degree
    try:
        return evaluate_texture(surface, case.evaluation.cutoff,
                                exclude=None if reading is None else reading.excluded,
                                form_degree=1 if degree is None else degree), None
    except InputError as exc:
        why = exc if reading is None else reading.explained(exc)
        return None, (f"ISO texture parameters: not evaluated ({why}); give evaluation.cutoff "
                      "that the surface holds")


def _iso_headline(spec, evaluation, texture) -> bool:
    """Whether the main parameters (``ra_m`` ...) are the ISO roughness profile's: those of a
    measured profile evaluated without this analysis' own cut-off or sampling length, so that
    they are the numbers ``asperity surface stats`` gives, not those of the unfiltered trace."""
    return (spec.kind == "file" and texture is not None and "R" in texture.groups
            and evaluation.cutoff is None and evaluation.sampling_length is None)


def _texture(case, texture, summary, notes, warnings, figures):
    """The ISO texture evaluation in the outcome: summary keys ``iso_<name>`` (unit-suffixed),
    its notes and warnings, and the ``texture`` figure."""
    from ..plotting.surfaces import plot_texture
    from ..surfaces.texture import PERCENT, suffixed

    fam = texture.families
    if isinstance(texture.surface, s.Profile):
        summary.update(iso_cutoff_m=fam.cutoff, iso_sampling_lengths=fam.sampling_lengths)
        if fam.lambda_s is not None:
            summary["iso_lambda_s_m"] = fam.lambda_s
    else:
        summary["iso_surface"] = fam.label
    for values in texture.groups.values():
        for name, value in values.items():
            if not math.isfinite(value):
                continue  # left out: W's shape at round-off, an undefined Sal
            if name in PERCENT:  # as the summary shows every ratio, and surface stats these
                summary[f"iso_{name.lower()}_percent"] = 100.0 * value
            else:
                summary["iso_" + suffixed(name).lower()] = value
    notes.extend(f"ISO texture: {note}" for note in texture.notes)
    warnings.extend(texture.warnings)
    figures["texture"] = (lambda: plot_texture(texture, title=case.title),
                          "; ".join(texture.titles.values()) + ". Top: the profiles (or the "
                          "scale-limited surface); bottom: the spectrum as measured and the "
                          "material ratio curve with the ISO 13565-2 equivalent straight line.")


def _trimmed(profile: s.Profile, margin: float) -> s.Profile:
    """The profile without ``margin`` at each end (the filter's run-in and run-out)."""
    keep = (profile.x - profile.x[0] >= margin) & (profile.x[-1] - profile.x >= margin)
    return s.Profile(profile.x[keep], profile.z[keep])


def _parameters(profile: s.Profile, sampling_length) -> dict:
    """ISO 4287 parameters over the whole profile, or averaged over sampling lengths.

    With a sampling length the profile is levelled once (least-squares line, or its mean when
    periodic) and cut into consecutive sampling lengths; the amplitude parameters are the means
    of their values in each (referenced to its own mean, without a tilt, as in
    :func:`~asperity.surfaces.roughness_along`), Rz the mean of the peak-to-valley heights, and
    Rt and Rdq are those of the whole evaluation length.
    """
    whole = s.roughness_parameters(profile)
    if sampling_length is None:
        return whole
    per = int(round(sampling_length / profile.spacing))
    if per < 8 or per > profile.x.size:
        raise InputError("evaluation.sampling_length", "between 8 spacings and the evaluated "
                         f"length ({profile.length:.4g} m)", sampling_length)
    levelled = s.residual_heights(profile.z, profile.periodic)
    count = profile.x.size // per
    parts = [s.roughness_parameters(levelled[k * per:(k + 1) * per], periodic=True)
             for k in range(count)]
    out = {key: float(np.mean([p[key] for p in parts])) if key in parts[0] else value
           for key, value in whole.items()}
    out["Rz"] = float(np.mean([p["Rt"] for p in parts]))
    out["Rt"] = whole["Rt"]
    return out


def _evaluate(surface, evaluation, exclude=None) -> _Evaluated:
    """Parameters, waviness/roughness split, spectrum and correlation length of a surface.

    The spectrum is that of the whole (primary) surface; the parameters and the correlation
    length are those of the evaluated roughness profile when a cut-off is given, after the
    form of ``evaluation.form_degree`` is removed when it is given. A map's points
    ``exclude`` (a file's missing points, filled) are left out of its height parameters
    (``Sa`` ... ``Sz``): its plane and mean are fitted to the measured points, as the iso_*
    keys' are (a filled 8 % blob made Ssk 0.4812 against 0.4585); its slopes, spectrum and
    correlation length are of the filled map.
    """
    spectrum = s.power_spectrum(surface, window=None if surface.periodic else "hann")
    measured = None if exclude is None or not isinstance(surface, s.Topography) else ~exclude
    if evaluation.form_degree is not None:
        surface = s.remove_form(surface, evaluation.form_degree, measured=measured)
    primary = s.roughness_parameters(surface)
    if measured is not None:
        plane = s.remove_form(surface, 0 if surface.periodic else 1, measured=measured)
        heights = plane.z[measured]
        primary.update(amplitude_moments(heights - heights.mean(), "S",
                                           float(np.max(np.abs(surface.z)))))
        primary["Sz"] = primary["Sp"] + primary["Sv"]
    if isinstance(surface, s.Topography):
        for key in ("cutoff", "sampling_length"):
            value = getattr(evaluation, key)
            if value is not None:
                raise InputError(f"evaluation.{key}", "no value for a topography (the filter "
                                 "and sampling lengths apply to profiles)", value)
        return _Evaluated(primary, primary, None, None, spectrum,
                          s.autocorrelation_length(surface))
    cutoff = evaluation.cutoff
    waviness = roughness = None
    evaluated = surface
    if cutoff is not None:
        if cutoff <= 2 * surface.spacing * (1 + 1e-9):
            raise InputError("evaluation.cutoff", "more than two spacings "
                             f"({2 * surface.spacing:.4g} m)", cutoff)
        if not surface.periodic and cutoff > surface.length / 2:
            raise InputError("evaluation.cutoff", "at most half the length of a non-periodic "
                             f"profile ({surface.length / 2:.4g} m)", cutoff)
        waviness, roughness = s.split_waviness(surface, cutoff)
        evaluated = roughness if surface.periodic else _trimmed(roughness, cutoff / 2)
    return _Evaluated(_parameters(evaluated, evaluation.sampling_length), primary, waviness,
                      roughness, spectrum, s.autocorrelation_length(evaluated))


def _window(spec, evaluation, length: float) -> float:
    """Window of the roughness along the workpiece: given, or about length / 20 in feeds."""
    if evaluation.window is None:
        return spec.feed * max(1, round(length / (20 * spec.feed)))
    if not 3 * spec.profile_spacing() <= evaluation.window <= length:
        raise InputError("evaluation.window", "between 3 spacings and the profile length "
                         f"({length:.4g} m)", evaluation.window)
    return evaluation.window


def _dataset(case, surfaces, evaluated, along) -> xr.Dataset:
    """Heights, spectra, filtered profiles, parameters (and Rt along a workpiece) per surface."""
    labels = list(surfaces)
    first = surfaces[labels[0]]
    heights = np.stack([surf.z for surf in surfaces.values()])
    spatial = ("x",) if isinstance(first, s.Profile) else ("x", "y")
    spec0 = evaluated[labels[0]].spectrum
    psd_unit = "m3" if spec0.dim == 1 else "m4"
    coords = {
        "surface": variable("surface", np.array(labels, dtype=object), "1", "surface name"),
        "x": variable("x", first.x, "m", "x (first in-plane direction)"),
        "q": variable("q", spec0.q, "rad m-1", "wavevector 2 pi / wavelength"),
    }
    if isinstance(first, s.Topography):
        coords["y"] = variable("y", first.y, "m", "y (second in-plane direction)")
    data = {
        "height": variable(("surface", *spatial), heights, "m", "surface height (metal below)"),
        "psd": variable(("surface", "q"), np.stack([e.spectrum.psd for e in evaluated.values()]),
                        psd_unit, "power spectral density of heights" +
                        (" (radial average)" if spec0.dim == 2 else "")),
    }
    if evaluated[labels[0]].waviness is not None:
        data["waviness"] = variable(("surface", "x"), np.stack(
            [e.waviness.z for e in evaluated.values()]), "m",
            "waviness: mean line of the ISO 16610-21 Gaussian filter")
        data["roughness"] = variable(("surface", "x"), np.stack(
            [e.roughness.z for e in evaluated.values()]), "m", "roughness: profile minus waviness")
    for name in evaluated[labels[0]].parameters:
        unit = "m" if name[1:] in _LENGTHS else "1"
        data[name.lower()] = variable("surface", [e.parameters[name] for e in evaluated.values()],
                                      unit, f"{name}, {_NAMES.get(name[1:].lower(), name)}")
    data["correlation_length"] = variable(
        "surface", [e.correlation_length for e in evaluated.values()], "m",
        "autocorrelation length (decay to 0.2)")
    if along is not None:
        centres, values, frequencies = along
        coords["window"] = variable("window", centres, "m",
                                    "centre of the evaluation window along the workpiece")
        data["rt_along"] = variable(("surface", "window"), values, "m",
                                    "Rt in consecutive windows along the workpiece")
        data["natural_frequency"] = variable("surface", frequencies, "Hz",
                                             "natural frequency of the tool assembly")
    attrs = {"title": case.title, "analysis": "surface", "Conventions": "CF-1.8",
             "source": "asperity", "kind": case.surface.kind}
    settings = {"seed": case.surface.seed, "cutoff_m": case.evaluation.cutoff,
                "sampling_length_m": case.evaluation.sampling_length}
    attrs.update({key: value for key, value in settings.items() if value is not None})
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _summary(spec, surfaces, evaluated) -> dict:
    labels = list(surfaces)
    first, ev = surfaces[labels[0]], evaluated[labels[0]]
    summary = {"kind": spec.kind, "surfaces": labels, "points": list(first.z.shape)}
    if isinstance(first, s.Profile):
        summary.update(spacing_m=first.spacing, length_m=first.length)
    else:
        summary.update(spacing_m=list(first.spacing),
                       size_m=[first.x.size * first.spacing[0], first.y.size * first.spacing[1]])
    summary["periodic"] = first.periodic
    summary.update({_key(name): value for name, value in ev.parameters.items()
                    if name != "Sdr"})
    if "Sdr" in ev.parameters:  # a ratio: in percent, as the summary shows ratios (ISO Sdr too)
        summary["sdr_percent"] = 100.0 * ev.parameters["Sdr"]
    if ev.waviness is not None:
        waviness = s.roughness_parameters(ev.waviness)
        for name in ("a", "q", "t"):
            summary[f"p{name}_m"] = ev.primary[f"R{name}"]
            summary[f"w{name}_m"] = waviness[f"R{name}"]
    if math.isfinite(ev.correlation_length):
        summary["correlation_length_m"] = ev.correlation_length
    if len(labels) > 1:
        for label in labels:
            params = evaluated[label].parameters
            for name in params:
                if name[1:] in ("a", "q", "t", "sk", "ku"):
                    summary[_key(name, _tag(label))] = params[name]
    return summary


def _turning(spec, surfaces, evaluated, turned, evaluation):
    """Summary entries, comparisons and Rt-along data of a turned case."""
    f, r = spec.feed, spec.nose_radius
    rt_ref = f * f / (8 * r)
    ra_ref = f * f / (18 * math.sqrt(3) * r)
    kin = evaluated["kinematic"].primary
    summary = {"feed_m": f, "nose_radius_m": r, "kinematic_rt_m": rt_ref,
               "kinematic_ra_m": ra_ref, "kinematic_rt_arc_m": arc_peak_to_valley(f, r)}
    arc = (f"the arcs' height r - sqrt(r^2 - f^2/4) is {_um(summary['kinematic_rt_arc_m'])}; "
           f"the parabola is {100 * parabola_error(f, r):.2g} % below it (about f^2/(16 r^2))")
    comparisons = [
        Comparison("kinematic Rt of the feed marks", kin["Rt"], rt_ref,
                   cite("Seireg eq. (4.1), Rmax = f^2/(8 r)", "turning"), "m", 0.01, arc),
        Comparison("kinematic Ra of the feed marks", kin["Ra"], ra_ref,
                   cite("parabolic feed marks, Ra = f^2/(18 sqrt(3) r)", "turning"), "m", 0.01,
                   arc),
    ]
    table = s.process_roughness(_TURNING)
    first = next(iter(surfaces))
    ra = evaluated[first].parameters["Ra"] / MICROINCH
    lo, hi = table.ra_min_microinch, table.ra_max_microinch
    where = "inside" if lo <= ra <= hi else "below" if ra < lo else "above"
    note = f"Ra of {first} is {where} the range {lo:g}-{hi:g} uin"
    table41 = cite("Seireg Table 4.1", "turning")
    comparisons += [
        Comparison("Ra vs Table 4.1 boring/turning, lowest", ra, lo, table41, "uin",
                   note=note),
        Comparison("Ra vs Table 4.1 boring/turning, highest", ra, hi, table41, "uin",
                   note=note),
    ]
    if not turned:
        return summary, comparisons, None
    length = surfaces["kinematic"].length
    window = _window(spec, evaluation, length)
    summary["window_m"] = window
    along = {label: s.roughness_along(profile, window, "Rt")
             for label, profile in surfaces.items()}
    for res, label in zip(turned, surfaces, strict=False):  # the vibrating ones come first
        tag = _tag(label)
        mean = float(np.mean(along[label][1]))
        summary[f"rt_along_mean_{tag}_m"] = mean
        summary[f"static_deflection_{tag}_m"] = res.static_deflection
        comparisons.append(Comparison(
            f"mean Rt along the workpiece, {label}", mean, rt_ref,
            cite("Seireg eq. (4.1) and Fig. 4.2", "turning"), "m",
            note="tool vibration adds to the kinematic roughness; the book finds it essentially "
            "kinematic above 150 Hz"))
    frequencies = [*(float(fn) for fn in spec.natural_frequency), math.nan]
    centres = along["kinematic"][0]
    values = np.stack([v for _, v in along.values()])
    return summary, comparisons, (centres, values, frequencies)


def _um(length: float) -> str:
    return f"{length * 1e6:.4g} um"


def _parabola_warnings(feed: float, nose_radius: float) -> list[str]:
    """A warning line where eq. (4.1)'s kinematic Rt ``f^2/(8 r)`` is more than
    ``PARABOLA_TOLERANCE`` below the arcs' height ``r - sqrt(r^2 - f^2/4)`` (f above about
    0.87 r); none otherwise.

    Parameters
    ----------
    feed, nose_radius : float
        Feed per revolution and tool nose radius (m).
    """
    error = parabola_error(feed, nose_radius)
    if error <= PARABOLA_TOLERANCE:
        return []
    parabola, exact = feed * feed / (8 * nose_radius), arc_peak_to_valley(feed, nose_radius)
    return [f"kinematic Rt: eq. (4.1)'s f^2/(8 r) = {_um(parabola)} is {100 * error:.3g} % below "
            f"the arcs' height r - sqrt(r^2 - f^2/4) = {_um(exact)} at f = {feed * 1e3:.4g} mm, "
            f"r = {nose_radius * 1e3:.4g} mm (limit {100 * PARABOLA_TOLERANCE:g} %, up to f = "
            f"{parabola_feed_limit(nose_radius) * 1e3:.3g} mm); read 'kinematic Rt of the "
            "nose arcs' (kinematic_rt_arc_m, the profile's Rt), not the parabola's "
            "(kinematic_rt_m, kinematic_ra_m), or use a smaller feed"]


def _reference_ra(spec, surfaces, evaluated) -> list:
    """Target-Ra (built-in, ground) and expected-rms (random) comparisons."""
    out = []
    if spec.kind == "builtin":
        for label in surfaces:
            target = s.BUILTIN_PROFILES[label]["ra"]
            out.append(Comparison(f"Ra of profile {label}", evaluated[label].primary["Ra"],
                                  target, cite("Holmes, Evans & Snidle (2005), Fig. 1 text",
                                               "the-papers-ground-profiles"), "m",
                                  0.01, "synthetic stand-in generated to this Ra"))
    elif spec.kind == "ground":
        out.append(Comparison("Ra", evaluated["ground"].primary["Ra"], spec.ra,
                              "target Ra of the case", "m", 0.01))
    elif spec.kind in ("gaussian", "self-affine") and spec.rms is not None:
        name = "Rq" if spec.width is None else "Sq"
        out.append(Comparison(name, evaluated[spec.kind].primary[name], spec.rms,
                              cite("expected rms of the random surface",
                                   "generated-surfaces"), "m",
                              note="one realisation of a random surface, not a check"))
    return out


def _levelled(surface, evaluation, masked=None):
    """The surface as its parameters (``sa_m``, ``pq_m`` ...) are of: the form of
    ``evaluation.form_degree`` removed when given, then the least-squares line or plane (the
    mean when periodic), as :func:`~asperity.surfaces.roughness_parameters` levels it; both
    fitted to the measured points of a map whose points ``masked`` were filled, as
    :func:`_evaluate` fits them."""
    measured = None if masked is None or not isinstance(surface, s.Topography) else ~masked
    if evaluation.form_degree is not None:
        surface = s.remove_form(surface, evaluation.form_degree, measured=measured)
    if measured is not None:
        return s.remove_form(surface, 0 if surface.periodic else 1, measured=measured)
    return surface.with_heights(s.residual_heights(surface.z, surface.periodic))


def _figures(case, surfaces, evaluated, turned, window, masked=None) -> dict:
    """The figures of a surface case: each drawn levelled (:func:`_levelled`), as its numbers
    are of -- a measured trace's tilt was drawn in P and W while pq_m, wq_m were of the
    levelled ones -- with the ``masked`` points of a file marked."""
    from ..plotting.surfaces import (
        plot_profiles,
        plot_spectrum,
        plot_topography,
        plot_turning_roughness,
    )

    labels = list(surfaces)
    first = surfaces[labels[0]]
    evaluation = case.evaluation
    figures = {}
    level = "mean removed" if first.periodic else "least-squares " + (
        "plane" if isinstance(first, s.Topography) else "line") + " removed"
    if isinstance(first, s.Topography):
        figures["topography"] = (lambda: plot_topography(
            _levelled(first, evaluation, masked), f"{case.title} ({level})", masked),
            f"Height map of the surface, its {level.replace(' removed', '')} removed, as the "
            "height parameters (sa_m, sq_m, ...) are of it"
            + ("; masked points grey." if masked is not None else "."))
    else:
        shown = {k: _levelled(p, evaluation) for k, p in surfaces.items()}
        caption = (f"Profiles ({level}, as their parameters are of them) offset for clarity, "
                   "metal below the curves.")
        if case.surface.kind == "turned":
            span = min(first.length, 10 * case.surface.feed)
            shown = {k: _trimmed_to(p, span) for k, p in shown.items()}
            caption = f"The first {span * 1e3:.3g} mm of each profile; " + caption
        if case.surface.kind == "builtin":
            caption += " Compare Holmes, Evans & Snidle (2005), Fig. 1."
        figures["profiles"] = (lambda: plot_profiles(shown, title=f"{case.title} ({level})"),
                               caption)
    ev = evaluated[labels[0]]
    if ev.waviness is not None:
        cut = case.evaluation.cutoff
        split = {f"primary, {level}": _levelled(first, evaluation, masked),
                 f"waviness, lambda_c = {cut * 1e3:.3g} mm, {level}": ev.waviness.with_heights(
                     s.residual_heights(ev.waviness.z, first.periodic)),
                 "roughness": ev.roughness}
        figures["waviness"] = (lambda: plot_profiles(split, title=f"Gaussian filter: {labels[0]}"),
                               f"Primary profile and its waviness (the ISO 16610-21 Gaussian "
                               f"mean line), each with its {level.replace(' removed', '')} "
                               "removed as pq_m and wq_m are of them, and the roughness, offset "
                               "for clarity.")
    # One spectrum per surface; of a turned case only the first (the dataset holds them all).
    drawn = labels[:1] if case.surface.kind == "turned" else labels
    for label in drawn:
        surf = surfaces[label]
        stem = "spectrum" if len(drawn) == 1 else f"spectrum_{_tag(label)}"
        figures[stem] = (lambda surf=surf, label=label: plot_spectrum(
            surf, title=f"Power spectral density: {label}"),
            f"Power spectral density of {label}" +
            ("" if surf.periodic else " (Hann window)") + ".")
    if turned:
        figures["roughness_along"] = (
            lambda: plot_turning_roughness(turned, window, labels[:len(turned)]),
            f"Rt in consecutive {window * 1e3:.3g} mm windows along the workpiece for each tool "
            "natural frequency, with the kinematic f^2/(8r) dashed (cf. Seireg Fig. 4.2).")
    return figures


def _trimmed_to(profile: s.Profile, span: float) -> s.Profile:
    """The first ``span`` of a profile (for drawing)."""
    keep = profile.x - profile.x[0] < span
    return s.Profile(profile.x[keep], profile.z[keep])


def run(case, progress=None) -> Outcome:
    """Characterise the case's surfaces; compare with the closed forms that apply."""
    spec = case.surface
    surfaces, turned = _surfaces(spec, progress)
    reading = None
    if spec.kind == "file":
        reading = surfaces[spec.labels()[0]]
        surfaces[spec.labels()[0]] = reading.surface
    first = next(iter(surfaces))
    texture, failed = _iso_texture(case, surfaces[first], reading)
    evaluated = {label: _evaluate(surf, case.evaluation,
                                  reading.excluded if reading is not None and label == first
                                  else None)
                 for label, surf in surfaces.items()}
    iso = _iso_headline(spec, case.evaluation, texture)
    if iso:
        evaluated[first] = replace(evaluated[first], parameters={
            name: texture.groups["R"][name] for name in evaluated[first].parameters})
    summary = _summary(spec, surfaces, evaluated)
    comparisons = _reference_ra(spec, surfaces, evaluated)
    along, window, notes = None, None, []
    if spec.kind == "turned":
        extra, rows, along = _turning(spec, surfaces, evaluated, turned, case.evaluation)
        summary.update(extra)
        comparisons += rows
        window = summary.get("window_m")
        if spec.spacing is not None and not math.isclose(spec.profile_spacing(), spec.spacing):
            notes.append(f"The spacing was reduced to {spec.profile_spacing():.4g} m, an odd "
                         "fraction of the feed, so that the feed-mark cusps fall on grid points.")
        if turned:
            notes.append(_DYNAMIC)
        parabola = _parabola_warnings(spec.feed, spec.nose_radius)
    else:
        parabola = []
    if spec.kind == "builtin":
        notes.append(_SYNTHETIC)
    if iso:
        notes.append("The ra_m, rq_m, ... keys are those of the ISO 4287 roughness profile (the "
                     f"ISO 4288 cut-off, {texture.families.cutoff * 1e3:g} mm, mean of the "
                     "sampling lengths), as asperity surface stats gives them; the iso_* keys "
                     "hold every group. Give evaluation.cutoff or sampling_length for this "
                     "analysis' own Gaussian split instead.")
    elif case.evaluation.cutoff is None and spec.kind not in ("builtin", "turned"):
        notes.append("Without evaluation.cutoff the ra_m, rq_m, ... (sa_m, ...) keys are of the "
                     "unfiltered surface (heights from the least-squares line/plane); the iso_* "
                     "keys are of the ISO roughness profile (cut-off by ISO 4288) or of the "
                     "S-F surface.")
    if case.evaluation.cutoff is not None:
        per = ("averaged over sampling lengths of evaluation.sampling_length" if
               case.evaluation.sampling_length is not None else "over the profile (less half "
               "a cut-off at each end of a non-periodic one; Rz: the mean "
               "peak-to-valley of five parts), not the ISO 4288 means over sampling lengths of "
               "the cut-off that the iso_* keys hold (Rp here: the highest peak of all; ISO "
               "Rp: the mean of each sampling length's highest)")
        notes.append("Parameters are those of the roughness profile (Gaussian filter, cut-off "
                     f"{case.evaluation.cutoff:.4g} m), {per}; pa/pq/pt are of the primary "
                     "profile and wa/wq/wt of the waviness.")
    dataset = _dataset(case, surfaces, evaluated, along)
    figures = _figures(case, surfaces, evaluated, turned, window,
                       None if reading is None else reading.excluded)
    warnings = list(parabola)
    if reading is not None:
        notes.append(f"File read as {reading.style}.")
        notes.extend(f"Reading: {note}." for note in reading.notes)
        warnings.extend(reading.warnings)
        if texture is not None:
            warnings.extend(reading.slope_warnings(*texture.rms_slope))
    if texture is None:
        warnings.append(failed)
    else:
        _texture(case, texture, summary, notes, warnings, figures)
    return Outcome(dataset, summary, figures, comparisons, notes=notes, warnings=warnings)
