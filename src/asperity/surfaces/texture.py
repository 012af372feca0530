"""Surface texture of a measured profile or topography, as the standards group the parameters.

:func:`evaluate_texture` runs the whole chain for ``asperity surface stats`` and a surface
case's report: for a profile the P, W and R profiles (:mod:`.profiles`) with their ISO 4287
parameters and the material-ratio parameters of R (:mod:`.material_ratio`); for a topography
the scale-limited surface (:mod:`.areal`) with the ISO 25178-2 groups. Every parameter has its
SI unit in :data:`UNITS`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .areal import AreaFamilies, areal_evaluation, areal_families
from .material_ratio import relative_material_ratio, rk_parameters, section_height_difference
from .profiles import ProfileFamilies, profile_families, profile_parameters
from .topography import Profile, Topography

__all__ = ["PERCENT", "ROUND_OFF", "TextureEvaluation", "UNITS", "evaluate_texture",
           "shape_at_round_off", "suffixed", "unit_of"]

_LENGTH_SUFFIXES = ("a", "q", "p", "v", "z", "t", "k", "pk", "vk", "dc", "al", "Sm")
#: Parameters that are not lengths: their SI unit ("1" for ratios and moments).
UNITS = {"Mr1": "1", "Mr2": "1", "Smr1": "1", "Smr2": "1", "Sdr": "1", "Str": "1",
         "Rmr": "1", "Smr": "1",
         "Std": "deg", "Vmp": "m3/m2", "Vmc": "m3/m2", "Vvc": "m3/m2", "Vvv": "m3/m2"}
#: Ratios that tables and case summaries show in percent (the JSON of ``surface stats`` keeps
#: them as fractions, their SI unit "1"; a case summary has them as ``iso_<name>_percent``).
PERCENT = frozenset({"Mr1", "Mr2", "Smr1", "Smr2", "Sdr", "Str", "Rmr", "Smr"})
#: Fraction of Pq below which the rms of a W or R profile is taken as round-off
#: (:func:`shape_at_round_off`).
ROUND_OFF = 1e-3


def unit_of(name: str) -> str:
    """SI unit of a parameter: ``"m"``, ``"1"``, ``"deg"`` or ``"m3/m2"``."""
    if name in UNITS:
        return UNITS[name]
    return "m" if name[1:] in _LENGTH_SUFFIXES else "1"


def suffixed(name: str) -> str:
    """The parameter's name with its SI unit as a JSON/summary key suffix (``Ra`` -> ``Ra_m``,
    ``Vmp`` -> ``Vmp_m3_per_m2``, ``Std`` -> ``Std_deg``; ratios unchanged)."""
    return name + {"m": "_m", "m3/m2": "_m3_per_m2", "deg": "_deg"}.get(unit_of(name), "")


@dataclass(frozen=True)
class TextureEvaluation:
    """Parameters of a surface in the standards' groups, with the filters that made them.

    Attributes
    ----------
    surface : Profile or Topography
        As measured (read).
    families : ProfileFamilies or AreaFamilies
        The filtered profiles or scale-limited surfaces.
    groups : dict of str to dict of str to float
        Group key -> parameter name -> value in SI (:func:`unit_of`).
    titles : dict of str to str
        Group key -> heading naming the standard and the filters.
    notes, warnings : tuple of str
    excluded : ndarray of bool or None
        The points of ``surface`` left out of the height parameters (masked missing points,
        filled in ``surface`` and the families), for figures to mark.
    """

    surface: Profile | Topography
    families: ProfileFamilies | AreaFamilies
    groups: dict
    titles: dict
    notes: tuple[str, ...]
    warnings: tuple[str, ...]
    excluded: np.ndarray | None = None

    @property
    def rms_slope(self) -> tuple[str, float]:
        """The rms slope reported and its name: Rdq of the roughness profile (ISO 4287) or Sdq
        of the scale-limited surface (ISO 25178-2)."""
        if "R" in self.groups:
            return "Rdq", self.groups["R"]["Rdq"]
        return "Sdq", self.groups["hybrid"]["Sdq"]


def _depth_warnings(heights: np.ndarray, depth, name: str) -> tuple[str, ...]:
    """A warning when the Rmr (Smr) ``depth`` is below the deepest valley: the material ratio
    there is 100 % whatever the surface (``--rmr-depth 2``, meant as 2 um, is 2 m)."""
    span = float(np.ptp(heights))
    if depth is None or depth <= span:
        return ()
    return (f"{name}: the depth {depth:.4g} m is more than the peak-to-valley height "
            f"({span * 1e6:.4g} um), so {name} = 100 % whatever the surface; a plain number is "
            "metres: give the unit, e.g. --rmr-depth \"0.5 um\"",)


def shape_at_round_off(params: dict) -> tuple[str, ...]:
    """Leave out the skewness and kurtosis of a W or R profile whose rms is round-off.

    When Wq (Rq) is below :data:`ROUND_OFF` times Pq the profile holds less than 1e-6 of the
    primary's variance: what is left is the filter's truncation (the weighting function is cut
    at +-lambda_c, 6.5e-7 of its peak), its end correction and the heights' printed precision,
    not the surface (a turned trace at lambda_c = 2.5 mm: Wq 0.05 nm under Pq 463 nm). Wsk and
    Wku, moments divided by Wq^3 and Wq^4, would turn that into numbers of order one (-0.1 and
    1.8 there), so they are set to NaN (shown as n/a) and a note says why; the heights Wa, Wq
    ... stay, as the upper bound they are. ``params`` (of :func:`profile_parameters`) is
    changed in place; returns the notes.
    """
    primary = params["P"]["Pq"]
    notes = []
    for name in ("W", "R"):
        rms = params[name][f"{name}q"]
        if not rms < ROUND_OFF * primary:
            continue
        params[name][f"{name}sk"] = params[name][f"{name}ku"] = float("nan")
        notes.append(f"{name} profile at round-off: {name}q = {rms * 1e9:.3g} nm is "
                     f"{rms / primary:.2g} of Pq ({primary * 1e6:.4g} um; limit "
                     f"{ROUND_OFF:g}), so there is no {name} profile at this cut-off to speak "
                     f"of; {name}sk and {name}ku, which would measure the shape of the "
                     "round-off, are left out (n/a)")
    return tuple(notes)


def _profile(profile: Profile, cutoff, form_degree, rmr_depth, exclude) -> TextureEvaluation:
    fam = profile_families(profile, cutoff, form_degree=form_degree, exclude=exclude)
    params = profile_parameters(fam, exclude)
    round_off = shape_at_round_off(params)
    r = fam.evaluated("R")
    if exclude is not None:
        r = r[~np.asarray(exclude, bool)[fam.evaluation]]
    params["Rk"] = {"Rdc": section_height_difference(r), **rk_parameters(r, "R")}
    if rmr_depth is not None:
        params["Rk"]["Rmr"] = relative_material_ratio(r, rmr_depth)
    lc = f"lambda_c = {fam.cutoff * 1e3:.4g} mm"
    ls = "no lambda_s" if fam.lambda_s is None else f"lambda_s = {fam.lambda_s * 1e6:.4g} um"
    ln = f"ln = {fam.evaluation_length * 1e3:.4g} mm"
    titles = {
        "P": f"Primary profile P (ISO 4287; form removed, {ls}; over {ln})",
        "W": f"Waviness profile W (ISO 4287; Gaussian mean line, {lc}; over {ln})",
        "R": f"Roughness profile R (ISO 4287; {lc}, {ls}; mean of {fam.sampling_lengths} "
             f"sampling lengths, Rt over {ln})",
        "Rk": "Material ratio of R (ISO 4287 Rdc = C(20 %) - C(80 %)"
              + ("" if rmr_depth is None else
                 f", Rmr {rmr_depth * 1e6:.4g} um below the highest peak")
              + "; ISO 13565-2 Rk family)",
    }
    return TextureEvaluation(profile, fam, params, titles, fam.notes + round_off,
                             fam.warnings + _depth_warnings(r, rmr_depth, "Rmr"), exclude)


def _area(topography: Topography, cutoff, form_degree, rmr_depth, exclude) -> TextureEvaluation:
    fam = areal_families(topography, form_degree=form_degree, l_filter=cutoff, exclude=exclude)
    evaluation = areal_evaluation(fam, exclude)
    params, z = evaluation.parameters, evaluation.heights
    if rmr_depth is not None:
        params["functional"]["Smr"] = (relative_material_ratio(z, rmr_depth)
                                       if evaluation.material else float("nan"))
    what = f"{fam.label} surface"
    titles = {
        "height": f"Height (ISO 25178-2), {what}",
        "hybrid": f"Hybrid (ISO 25178-2), {what}",
        "spatial": f"Spatial (ISO 25178-2; Sal, Str at s = 0.2; Std = lay direction), {what}",
        "functional": "Functional, material ratio (ISO 25178-2 Sk family; Sdc = C(20 %) - "
                      "C(80 %)" + ("" if rmr_depth is None else
                                   f"; Smr {rmr_depth * 1e6:.4g} um below the highest peak")
                      + f"), {what}",
        "volume": f"Volume (ISO 25178-2, p = 10 %, q = 80 %), {what}",
    }
    small = () if evaluation.small is None else (evaluation.small,)
    return TextureEvaluation(topography, fam, params, titles, fam.notes + evaluation.notes,
                             fam.warnings + _depth_warnings(z, rmr_depth, "Smr") + small,
                             exclude)


def evaluate_texture(surface, cutoff=None, *, form_degree=1, rmr_depth=None,
                     exclude=None) -> TextureEvaluation:
    """Filter a profile or topography as ISO does and compute its grouped parameters.

    Parameters
    ----------
    surface : Profile or Topography
    cutoff : float, optional
        lambda_c of a profile (default: ISO 4288's choice) or the L-filter nesting index of a
        topography (default: none, the S-F surface).
    form_degree : int
        Degree of the least-squares form removed (1: line or plane).
    rmr_depth : float, optional
        Also report Rmr (Smr): the material ratio this depth (m) below the highest peak.
    exclude : ndarray of bool, optional
        Points left out of the height and material-ratio parameters (masked missing points,
        :attr:`asperity.surfaces.io.Reading.excluded`); filters and slopes use them filled.
    """
    if exclude is not None and np.shape(exclude) != surface.z.shape:
        raise InputError("exclude", f"a mask of the surface's shape {surface.z.shape}",
                         np.shape(exclude))
    if isinstance(surface, Profile):
        return _profile(surface, cutoff, form_degree, rmr_depth, exclude)
    if isinstance(surface, Topography):
        return _area(surface, cutoff, form_degree, rmr_depth, exclude)
    raise InputError("surface", "a Profile or a Topography", type(surface).__name__)
