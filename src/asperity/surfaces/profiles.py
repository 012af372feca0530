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
from .cutoffs import CUTOFFS, cutoff_for_ra, lambda_s_for
from .filters import gaussian_filter
from .form import remove_form
from .parameters import _amplitude
from .topography import Profile

__all__ = ["ProfileFamilies", "amplitude_parameters", "height_moments", "mean_element_width",
           "profile_families", "profile_parameters"]

#: Sampling lengths in the ISO 4288 default evaluation length.
SAMPLING_LENGTHS = 5


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
                         f"(at most {profile.length / 2:.4g} m)", cutoff)
    start = (profile.x.size - count * per) // 2
    return slice(start, start + count * per), count


def _mean_ra(r: np.ndarray, window: slice, per: int) -> float:
    parts = r[window].reshape(-1, per)
    return float(np.mean(np.abs(parts)))


def _iso4288_cutoff(p: np.ndarray, profile: Profile, notes: list, warnings: list) -> float:
    """ISO 4288 clause 7: the cut-off whose Ra range holds the Ra measured with it."""
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
        _, r = _split(p, profile.x, cutoff, profile.periodic)
        window, _ = _window(profile, cutoff, SAMPLING_LENGTHS)
        ra = _mean_ra(r, window, int(round(cutoff / profile.spacing)))
        wanted = cutoff_for_ra(ra)
        if wanted == cutoff:
            notes.append(f"lambda_c = {cutoff * 1e3:g} mm chosen by ISO 4288 (Table 1: Ra = "
                         f"{ra * 1e6:.4g} um measured with it lies in its range)")
            return cutoff
        if wanted not in fitting:
            warnings.append(f"lambda_c: ISO 4288 asks for {wanted * 1e3:g} mm (Ra = "
                            f"{ra * 1e6:.4g} um) but the profile ({profile.length * 1e3:.4g} mm) "
                            f"holds at most {fitting[-1] * 1e3:g} mm with run-in and run-out; "
                            f"used {cutoff * 1e3:g} mm; measure a longer trace or give --cutoff")
            return cutoff
        cutoff = wanted
    notes.append(f"lambda_c = {cutoff * 1e3:g} mm: the ISO 4288 choice alternates between "
                 f"{' and '.join(f'{c * 1e3:g}' for c in tried[-2:])} mm (Ra at a range limit)")
    return cutoff


def profile_families(profile: Profile, cutoff=None, *, form_degree=1,
                     sampling_lengths=SAMPLING_LENGTHS, lambda_s="iso") -> ProfileFamilies:
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
    p = remove_form(profile, form_degree).z
    if cutoff is None:
        cutoff = _iso4288_cutoff(p, profile, notes, warnings)
    else:
        if not _fits(cutoff, profile):
            raise InputError("cutoff", "a cut-off of at least two spacings that the profile "
                             f"holds with its run-in and run-out (at most "
                             f"{profile.length / (1 if profile.periodic else 2):.4g} m)", cutoff)
        notes.append(f"lambda_c = {cutoff * 1e3:.4g} mm as given")
    if lambda_s == "iso":
        lambda_s, reason = lambda_s_for(cutoff, profile.spacing)
        notes.append(reason)
    elif lambda_s is not None:
        notes.append(f"lambda_s = {lambda_s * 1e6:.4g} um as given")
    if lambda_s is not None:
        p = gaussian_filter(p, profile.x, lambda_s, periodic=profile.periodic,
                            end_correction="linear")
    waviness, roughness = _split(p, profile.x, cutoff, profile.periodic)
    window, count = _window(profile, cutoff, sampling_lengths)
    where = "the whole periodic profile" if profile.periodic else (
        "the middle of the profile, without half a cut-off of run-in and run-out")
    notes.append(f"evaluation length {count} x {cutoff * 1e3:.4g} mm = "
                 f"{count * cutoff * 1e3:.4g} mm, {where}")
    if count < sampling_lengths:
        warnings.append(f"sampling lengths: the profile holds {count} of the {sampling_lengths} "
                        f"that ISO 4288 averages over at lambda_c = {cutoff * 1e3:.4g} mm; "
                        f"measure at least {(sampling_lengths + 1) * cutoff * 1e3:.4g} mm")
    return ProfileFamilies(profile.with_heights(p), profile.with_heights(waviness),
                           profile.with_heights(roughness), float(cutoff), lambda_s, window,
                           count, tuple(notes), tuple(warnings))


def height_moments(z: np.ndarray, prefix: str) -> dict:
    """Amplitude parameters of heights measured from their mean line (plane), any shape.

    ``a`` mean |z|, ``q`` rms, ``sk`` skewness, ``ku`` kurtosis, ``p`` highest peak, ``v``
    deepest valley (positive), ``z`` = p + v (ISO 4287 clause 4.1-4.2, ISO 25178-2 4.1).
    """
    out = _amplitude(np.asarray(z, dtype=float).ravel(), prefix, 0.0)  # flat: Rq == 0
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
