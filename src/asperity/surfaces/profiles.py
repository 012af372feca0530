"""Primary, waviness and roughness profiles (ISO 4287, ISO 16610-21) and their parameters.

From a measured profile (the *traced* profile):

- the *primary* profile P is the trace with its nominal form removed (least-squares line, or a
  polynomial) and the wavelengths shorter than lambda_s removed by the Gaussian filter
  (ISO 3274, :func:`~asperity.surfaces.cutoffs.lambda_s_for`);
- the *waviness* profile W is the mean line of P by the ISO 16610-21 Gaussian filter at the
  cut-off lambda_c (no lambda_f filter is applied: W holds all wavelengths longer than
  lambda_c);
- the *roughness* profile R = P - W.

lambda_c is given, or chosen from the profile by the ISO 4288 procedure
(:func:`~asperity.surfaces.cutoffs.cutoff_for_ra`). The Gaussian filter needs half a cut-off of
data on each side of a point; near the ends its weights keep their first moment (ISO 16610-28's
end correction to first order, :func:`~asperity.surfaces.filters.gaussian_filter`), and the
run-in and run-out lengths of half a cut-off are removed (ISO 4288's
traversing length = evaluation length + lambda_c), so the evaluation length is the middle of
the profile, up to five sampling lengths lr = lambda_c long (ISO 4288 clause 4.4).

Parameters (:func:`profile_parameters`): R parameters defined on a sampling length (Ra, Rq,
Rsk, Rku, Rp, Rv, Rz, Rdq, RSm) are the means of their values in each sampling length (ISO 4288
clause 5); Rt is over the evaluation length. P and W parameters are over the evaluation length
(ISO 4287 clause 3.1.9: for P the sampling length is the evaluation length). Heights are
measured from each profile's mean line, i.e. as the families give them, not re-levelled.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError, check_int
from ..formatting import format_quantity
from .cutoffs import CUTOFFS, cutoff_for_ra, cutoff_for_rsm, lambda_s_for, largest_spacing
from .filters import ALPHA, gaussian_filter
from .form import remove_form
from .parameters import amplitude_moments
from .topography import Profile

__all__ = ["ProfileFamilies", "amplitude_parameters", "height_moments", "mean_element_width",
           "profile_families", "profile_parameters"]

#: Sampling lengths in the ISO 4288 default evaluation length.
SAMPLING_LENGTHS = 5
#: |mean| of the roughness profile over the evaluation length, as a fraction of its rms about
#: that mean, above which form is taken to be left in (Rq then inflated by over 10 %).
FORM_LEFT_IN = 0.5


@dataclass(frozen=True)
class ProfileFamilies:
    """The P, W and R profiles of a trace and the filters that made them.

    Attributes
    ----------
    primary, waviness, roughness : Profile
        Over the whole trace; only ``evaluation`` of them is evaluated.
    cutoff : float
        lambda_c (m).
    lambda_s : float or None
        The short-wave cut-off applied (m), None if none.
    evaluation : slice
        Indices of the evaluation length.
    sampling_lengths : int
        Number of sampling lengths (each ``cutoff`` long) in the evaluation length.
    notes : tuple of str
        How the cut-off and lambda_s were chosen, the evaluation length.
    warnings : tuple of str
        Choices that depart from ISO 4288 (too short a profile for the cut-off it needs).
    """

    primary: Profile
    waviness: Profile
    roughness: Profile
    cutoff: float
    lambda_s: float | None
    evaluation: slice
    sampling_lengths: int
    notes: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()

    @property
    def evaluation_length(self) -> float:
        """ln = sampling_lengths * lambda_c (m)."""
        return self.sampling_lengths * self.cutoff

    def evaluated(self, which: str) -> np.ndarray:
        """Heights of ``"P"``, ``"W"`` or ``"R"`` over the evaluation length."""
        profile = {"P": self.primary, "W": self.waviness, "R": self.roughness}[which]
        return profile.z[self.evaluation]


def _fits(cutoff: float, profile: Profile) -> bool:
    """Whether one sampling length plus run-in and run-out fit (periodic: one sampling length)."""
    need = cutoff if profile.periodic else 2 * cutoff
    return profile.length >= need * (1 - 1e-9) and cutoff >= 2 * profile.spacing


def _split(p: np.ndarray, x: np.ndarray, cutoff: float, periodic: bool):
    waviness = gaussian_filter(p, x, cutoff, periodic=periodic, end_correction="linear")
    return waviness, p - waviness


def _window(profile: Profile, cutoff: float, wanted: int) -> tuple[slice, int]:
    """The evaluation length: whole sampling lengths centred between run-in and run-out."""
    per = int(round(cutoff / profile.spacing))
    usable = profile.x.size if profile.periodic else profile.x.size - per
    count = min(wanted, usable // per)
    if count < 1:
        raise InputError("cutoff", f"a cut-off the profile holds with its run-in and run-out "
                         f"(at most {format_quantity(profile.length / 2, 'm')})", cutoff)
    start = (profile.x.size - count * per) // 2
    return slice(start, start + count * per), count


def _mean_ra(r: np.ndarray, window: slice, per: int) -> float:
    parts = r[window].reshape(-1, per)
    return float(np.mean(np.abs(parts)))


def _chosen_lambda_s(cutoff: float, spacing: float, lambda_s) -> tuple[float | None, str]:
    """The lambda_s applied with ``cutoff`` (``lambda_s`` as :func:`profile_families` takes it)
    and a note saying which ("" for none asked)."""
    if lambda_s == "iso":
        return lambda_s_for(cutoff, spacing)
    if lambda_s is None:
        return None, ""
    return lambda_s, f"lambda_s = {lambda_s * 1e6:.4g} um as given"


def _short_waves_removed(p: np.ndarray, profile: Profile, lam: float | None) -> np.ndarray:
    """The primary profile: ``p`` without the wavelengths shorter than ``lam`` (ISO 3274)."""
    if lam is None:
        return p
    return gaussian_filter(p, profile.x, lam, periodic=profile.periodic, end_correction="linear")


def _unheld_cutoff(wanted: float, fitting: list, profile: Profile) -> str:
    """Why a profile does not hold the cut-off ISO 4288 asks for, and what to do."""
    if wanted > fitting[-1]:
        return (f"the profile ({profile.length * 1e3:.4g} mm) holds at most "
                f"{fitting[-1] * 1e3:g} mm with run-in and run-out", "measure a longer trace")
    return (f"the spacing ({profile.spacing * 1e6:.4g} um) is too coarse for it (a cut-off "
            f"spans at least two spacings; the shortest held is {fitting[0] * 1e3:g} mm)",
            "sample finer or check the x unit and spacing")


def _iso4288_cutoff(p: np.ndarray, profile: Profile, lambda_s, notes: list,
                    warnings: list) -> float:
    """ISO 4288 clause 7: the cut-off whose Ra range holds the Ra measured with it (with the
    lambda_s that goes with each cut-off, so that the Ra named is the one reported). Where
    the profile does not hold the cut-off asked for, the held one nearest to it (the longest,
    or for a coarse spacing the shortest) is measured with and used, with a warning."""
    fitting = [cut for _, cut in CUTOFFS if _fits(cut, profile)]
    if not fitting:
        need = "one ISO 4288 cut-off (0.08 mm)" if profile.periodic else (
            "two ISO 4288 cut-offs (0.16 mm for 0.08 mm)")
        raise InputError("profile", f"a profile at least {need} long, sampled finer than "
                         "0.04 mm, or a shorter cut-off given (--cutoff; evaluation.cutoff)",
                         f"{profile.length:.4g} m")
    cutoff = 0.8e-3 if 0.8e-3 in fitting else fitting[-1]
    tried = []
    while cutoff not in tried:
        tried.append(cutoff)
        lam = _chosen_lambda_s(cutoff, profile.spacing, lambda_s)[0]
        _, r = _split(_short_waves_removed(p, profile, lam), profile.x, cutoff, profile.periodic)
        window, _ = _window(profile, cutoff, SAMPLING_LENGTHS)
        ra = _mean_ra(r, window, int(round(cutoff / profile.spacing)))
        wanted = cutoff_for_ra(ra)
        if wanted == cutoff:
            notes.append(f"lambda_c = {cutoff * 1e3:g} mm chosen by ISO 4288 (Table 1: Ra = "
                         f"{ra * 1e6:.4g} um measured with it lies in its range)")
            return cutoff
        if wanted not in fitting:
            held = fitting[-1] if wanted > fitting[-1] else fitting[0]  # nearest to wanted
            if held != cutoff:
                cutoff = held
                continue
            reason, advice = _unheld_cutoff(wanted, fitting, profile)
            warnings.append(f"lambda_c: ISO 4288 asks for {wanted * 1e3:g} mm (Ra = "
                            f"{ra * 1e6:.4g} um) but {reason}; used {cutoff * 1e3:g} mm; "
                            f"{advice}, or give --cutoff")
            return cutoff
        cutoff = wanted
    notes.append(f"lambda_c = {cutoff * 1e3:g} mm: the ISO 4288 choice alternates between "
                 f"{' and '.join(f'{c * 1e3:g}' for c in tried[-2:])} mm (Ra at a range limit)")
    return cutoff


def _periodic_alternative(evaluated: np.ndarray, profile: Profile, count: int, cutoff: float,
                          wanted: int) -> str:
    """The end of a too-few-sampling-lengths warning when the cut-off came from ISO 4288's Ra
    table: for a periodic profile (turned, milled) ISO 4288 clause 7.2 takes it from RSm
    instead (:func:`~asperity.surfaces.cutoffs.cutoff_for_rsm`), and where that one is
    shorter and the trace holds its ``wanted`` sampling lengths, the warning says so (a turned
    trace of 0.3 mm feed marks, Ra 7.4 um: 2.5 mm by Ra, told to measure 15 mm; 0.8 mm by
    RSm, which its 6 mm hold). Empty otherwise."""
    widths = [mean_element_width(part, profile.spacing, cutoff)
              for part in evaluated.reshape(count, -1)]
    if not np.isfinite(widths).any():
        return ""
    rsm = float(np.nanmean(widths))
    periodic = cutoff_for_rsm(rsm)
    if periodic >= cutoff or _window(profile, periodic, wanted)[1] < wanted:
        return ""
    return (f"; if the profile is periodic (turned, milled), ISO 4288 takes lambda_c from "
            f"RSm instead (RSm = {rsm * 1e3:.3g} mm: {periodic * 1e3:g} mm, which it holds "
            f"{wanted} times): --cutoff \"{periodic * 1e3:g} mm\" (case file: "
            f"evaluation.cutoff)")


def _sampling_warning(cutoff: float, spacing: float) -> str | None:
    """A warning when ``spacing`` is coarser than ISO 3274 allows for ``cutoff``."""
    row = largest_spacing(cutoff)
    if row is None or spacing <= row[1] * (1 + 1e-9):
        return None
    lam, largest = row
    return (f"sampling: the spacing {spacing * 1e6:.4g} um is coarser than the "
            f"{largest * 1e6:g} um ISO 3274 allows at lambda_c = {cutoff * 1e3:g} mm (lambda_s "
            f"= {lam * 1e6:g} um not applied): the wavelengths shorter than "
            f"{2 * spacing * 1e6:.4g} um are not measured, so the slopes and spacings (Rdq, "
            "Pdq, RSm) come out too small, the heights less so; measure with a sampling of "
            f"{largest * 1e6:g} um or finer (the instrument's sampling interval), or check the "
            "spacing if it was given (--spacing; case file: spacing)")


def _form_offset(p: np.ndarray, profile: Profile, cutoff: float, degree: int,
                 window: slice) -> float:
    """Mean over ``window`` of the roughness profile of the least-squares polynomial of
    ``degree`` fitted to ``p``: the offset that form of that degree, left in, gives R."""
    fit = np.polynomial.Polynomial.fit(profile.x, p, degree)(profile.x)
    return float(np.mean(_split(fit, profile.x, cutoff, False)[1][window]))


def _form_warning(p: np.ndarray, r: np.ndarray, profile: Profile, cutoff: float,
                  form_degree: int, window: slice) -> str | None:
    """A warning when form is left in the primary profile ``p``.

    The roughness profile ``r`` is then offset from zero over the evaluation length: the
    Gaussian mean line of a parabola z = x^2 / (2 rho) lies sigma^2 / (2 rho) above it, sigma^2
    = (alpha lambda_c)^2 / (2 pi) being the variance of the ISO 16610-21 weighting function.
    Form is taken to be left in when the offset exceeds :data:`FORM_LEFT_IN` of R's rms about
    its mean and at least half of it is the offset of the next-degree polynomial fitted to
    ``p`` (random waviness offsets R too, but not as a polynomial would); the radius named is
    rho = sigma^2 / (2 |offset|).
    """
    mean, spread = float(np.mean(r[window])), float(np.std(r[window]))
    if abs(mean) <= FORM_LEFT_IN * spread:
        return None
    if _form_offset(p, profile, cutoff, form_degree + 1, window) / mean < 0.5:
        return None
    rho = (ALPHA * cutoff) ** 2 / (2 * np.pi) / (2 * abs(mean))
    curvature = (f"a curvature of about {rho * 1e3:.3g} mm radius that the Gaussian mean "
                 "line does not follow" if form_degree <= 1 else "a form of higher degree")
    return (f"form: the roughness profile's mean over the evaluation length is "
            f"{mean * 1e6:.4g} um, {abs(mean) / spread:.3g} times its rms about that mean "
            f"({spread * 1e6:.4g} um): form is left in ({curvature}), and Ra, Rq, Rp, Rv and "
            f"the cut-off chosen from Ra are wrong; remove it: --form-degree {form_degree + 1} "
            f"(case file: evaluation.form_degree = {form_degree + 1})")


def profile_families(profile: Profile, cutoff=None, *, form_degree=1,
                     sampling_lengths=SAMPLING_LENGTHS, lambda_s="iso",
                     exclude=None) -> ProfileFamilies:
    """P, W and R profiles of a trace (module docstring).

    Parameters
    ----------
    profile : Profile
        The traced profile (m).
    cutoff : float, optional
        lambda_c (m); by default chosen by ISO 4288 from the profile.
    form_degree : int
        Degree of the least-squares polynomial removed as nominal form (1: a line).
    sampling_lengths : int
        Sampling lengths wanted in the evaluation length (fewer if the profile is shorter).
    lambda_s : "iso", None or float
        Short-wave cut-off: ISO 3274's for the cut-off where the spacing allows (``"iso"``),
        none, or a length (m).
    exclude : ndarray of bool, optional
        Points left out of the form's fit (masked missing points, filled): the mean line of P
        is that of the measured points, not tilted by the fill.

    Returns
    -------
    ProfileFamilies
    """
    if not isinstance(profile, Profile):
        raise InputError("profile", "a Profile", type(profile).__name__)
    form_degree = check_int("form_degree", form_degree, 0)
    sampling_lengths = check_int("sampling_lengths", sampling_lengths, 1)
    notes: list[str] = []
    warnings: list[str] = []
    p = remove_form(profile, form_degree, None if exclude is None else
                    ~np.asarray(exclude, bool)).z
    given = cutoff is not None
    if cutoff is None:
        cutoff = _iso4288_cutoff(p, profile, lambda_s, notes, warnings)
    else:
        if not _fits(cutoff, profile):
            raise InputError("cutoff", "a cut-off of at least two spacings that the profile "
                             f"holds with its run-in and run-out (at most "
                             f"{profile.length / (1 if profile.periodic else 2):.4g} m; a plain "
                             "number is metres: give the unit, e.g. \"0.8 mm\")",
                             f"{cutoff:.4g} m")
        notes.append(f"lambda_c = {cutoff * 1e3:.4g} mm as given")
    lambda_s, reason = _chosen_lambda_s(cutoff, profile.spacing, lambda_s)
    coarse = _sampling_warning(cutoff, profile.spacing)
    if coarse is not None:
        warnings.append(coarse)
    elif reason:
        notes.append(reason)
    p = _short_waves_removed(p, profile, lambda_s)
    waviness, roughness = _split(p, profile.x, cutoff, profile.periodic)
    window, count = _window(profile, cutoff, sampling_lengths)
    form = None if profile.periodic else _form_warning(p, roughness, profile, cutoff,
                                                       form_degree, window)
    if form is not None:
        warnings.insert(0, form)
    where = "the whole periodic profile" if profile.periodic else (
        "the middle of the profile, without half a cut-off of run-in and run-out")
    notes.append(f"evaluation length {count} x {cutoff * 1e3:.4g} mm = "
                 f"{count * cutoff * 1e3:.4g} mm, {where}")
    if count < sampling_lengths:
        periodic = "" if given else _periodic_alternative(roughness[window], profile, count,
                                                          cutoff, sampling_lengths)
        warnings.append(f"sampling lengths: the profile holds {count} of the {sampling_lengths} "
                        f"that ISO 4288 averages over at lambda_c = {cutoff * 1e3:.4g} mm; "
                        f"measure at least {(sampling_lengths + 1) * cutoff * 1e3:.4g} mm"
                        + periodic)
    return ProfileFamilies(profile.with_heights(p), profile.with_heights(waviness),
                           profile.with_heights(roughness), float(cutoff), lambda_s, window,
                           count, tuple(notes), tuple(warnings))


def height_moments(z: np.ndarray, prefix: str) -> dict:
    """Amplitude parameters of heights measured from their mean line (plane), any shape.

    ``a`` mean |z|, ``q`` rms, ``sk`` skewness, ``ku`` kurtosis, ``p`` highest peak, ``v``
    deepest valley (positive), ``z`` = p + v (ISO 4287 clause 4.1-4.2, ISO 25178-2 4.1).
    """
    out = amplitude_moments(np.asarray(z, dtype=float).ravel(), prefix, 0.0)  # flat: Rq == 0
    out[f"{prefix}z"] = out[f"{prefix}p"] + out[f"{prefix}v"]
    return out


def amplitude_parameters(z: np.ndarray, spacing: float, prefix: str, keep=None) -> dict:
    """:func:`height_moments` of a profile (over the points ``keep``, default all) and ``dq``,
    the rms of the forward-difference slopes (over all points)."""
    out = height_moments(z if keep is None else z[keep], prefix)
    out[f"{prefix}dq"] = float(np.sqrt(np.mean((np.diff(z) / spacing) ** 2)))
    return out


def mean_element_width(z: np.ndarray, spacing: float, sampling_length: float) -> float:
    """RSm (ISO 4287 clause 4.3.1): mean width of the profile elements in one sampling length.

    A profile element is a peak (the profile above the mean line between two crossings)
    and the valley next to it. Parts of the profile whose extreme height is below 10 % of Rz
    (Rp + Rv of this sampling length) or whose width is below 1 % of the sampling length do
    not count (ISO 4287 3.1.9, the default height and width discrimination): they are merged
    into the parts around them. Incomplete elements at the ends are left out. NaN when no
    complete element remains.
    """
    above = z > 0
    cuts = np.flatnonzero(np.diff(above)) + 1
    starts = np.concatenate([[0], cuts])
    ends = np.concatenate([cuts, [z.size]])
    height = 0.1 * (z.max() - z.min())
    width = 0.01 * sampling_length / spacing
    parts = []  # [start, end, sign] of the significant parts, same signs merged
    for a, b in zip(starts, ends, strict=True):
        sign = bool(above[a])
        extreme = np.abs(z[a:b]).max()
        if extreme < height or b - a < width:
            if parts:
                parts[-1][1] = b  # an insignificant part joins the one before it
            continue
        if parts and parts[-1][2] == sign:
            parts[-1][1] = b
        else:
            parts.append([a, b, sign])
    inner = parts[1:-1] if len(parts) > 2 else []  # parts touching the ends are incomplete
    widths = [(inner[k + 1][1] - inner[k][0]) * spacing for k in range(0, len(inner) - 1, 2)]
    return float(np.mean(widths)) if widths else float("nan")


def profile_parameters(families: ProfileFamilies, exclude=None) -> dict[str, dict[str, float]]:
    """P, W and R parameters grouped as ISO 4287 groups them (module docstring).

    Parameters
    ----------
    families : ProfileFamilies
    exclude : ndarray of bool, optional
        Points (of the whole profile) to leave out of the height parameters: masked missing
        points. Slopes and RSm use every point.

    Returns
    -------
    dict
        ``{"P": {...}, "W": {...}, "R": {...}}``; lengths in m, slopes and moments
        dimensionless. P and W have ``a q sk ku p v t dq`` (Pt = Pz over the evaluation
        length); R has the sampling-length means ``Ra Rq Rsk Rku Rp Rv Rz Rdq RSm``
        (:func:`mean_element_width`) and ``Rt``.
    """
    h = families.primary.spacing
    keep = (np.ones(families.evaluated("R").size, bool) if exclude is None
            else ~np.asarray(exclude, bool)[families.evaluation])
    out = {}
    for name in ("P", "W"):
        values = amplitude_parameters(families.evaluated(name), h, name, keep)
        values[f"{name}t"] = values.pop(f"{name}z")
        out[name] = values
    r = families.evaluated("R")
    sampling = r.reshape(families.sampling_lengths, -1)
    kept = keep.reshape(families.sampling_lengths, -1)
    parts = [amplitude_parameters(part, h, "R", k) for part, k in zip(sampling, kept,
                                                                       strict=True)]
    out["R"] = {key: float(np.mean([part[key] for part in parts])) for key in parts[0]}
    out["R"]["Rt"] = float(r[keep].max() - r[keep].min())
    widths = [mean_element_width(part, h, families.cutoff) for part in sampling]
    out["R"]["RSm"] = float(np.nanmean(widths)) if np.isfinite(widths).any() else float("nan")
    return out
