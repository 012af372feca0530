"""The material ratio (Abbott-Firestone) curve and the parameters built on it.

The material ratio Mr(c) of a profile or surface at height c is the fraction of the evaluation
length (area) where the material reaches c or higher (ISO 4287 clause 4.5.1, Rmr(c); ISO
25178-2, Smr(c)); the curve C(mr) is its inverse, the height at which the ratio is mr. On
sampled heights the curve is the heights sorted from the highest, the k-th at mr = (k + 1/2)/n.

The Rk family (ISO 13565-2, clause 4; areal Sk family, ISO 25178-2 clause 4.5):

1. the 40 % window of the curve with the smallest height drop (the secant of least gradient);
2. the *equivalent straight line*: the least-squares line through the curve in that window;
3. Rk = the line's height at mr = 0 minus at mr = 100 %; Mr1, Mr2 = the material ratios at
   those two heights;
4. Rpk (Rvk): the height of the triangle over 0..Mr1 (Mr2..100 %) with the area of the peaks
   above (valleys below) the core, ``Rpk = 2 A1 / Mr1``, ``Rvk = 2 A2 / (1 - Mr2)``.

Volumes (ISO 25178-2 clause 4.4, per unit area, so a length in m; 1 um = 1 ml/m^2):
``Vm(p) = integral_0^p (C(q) - C(p)) dq`` and ``Vv(p) = integral_p^1 (C(p) - C(q)) dq``, with
Vmp = Vm(10 %), Vmc = Vm(80 %) - Vm(10 %), Vvc = Vv(10 %) - Vv(80 %), Vvv = Vv(80 %).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError

__all__ = ["CORE_WINDOW", "EquivalentLine", "equivalent_line", "material_ratio",
           "material_ratio_curve", "relative_material_ratio", "rk_parameters", "section_height",
           "section_height_difference", "volume_parameters"]

#: Width of the central region of ISO 13565-2 (a fraction of the material ratio).
CORE_WINDOW = 0.4


def _heights(z) -> np.ndarray:
    z = np.asarray(z, dtype=float).ravel()
    if z.size < 10 or not np.all(np.isfinite(z)):
        raise InputError("heights", "at least 10 finite heights", z.size)
    if np.ptp(z) == 0:
        raise InputError("heights", "heights that are not all equal")
    return z


def material_ratio_curve(z) -> tuple[np.ndarray, np.ndarray]:
    """The Abbott-Firestone curve: (material ratios 0..1 at the midpoints, heights descending)."""
    heights = np.sort(_heights(z))[::-1]
    return (np.arange(heights.size) + 0.5) / heights.size, heights


def material_ratio(z, level) -> float:
    """Rmr(c) / Smr(c): the fraction of points at or above ``level`` (m, from the mean line)."""
    return float(np.mean(_heights(z) >= level))


def relative_material_ratio(z, depth, reference=0.0) -> float:
    """Rmr (ISO 4287 clause 4.5.2): the material ratio ``depth`` (m) below the reference level.

    The reference level is C(``reference``), the height at material ratio ``reference``
    (Rmr0; 0 = the highest peak); Rmr = Rmr(C(Rmr0) - depth).
    """
    if depth < 0:
        raise InputError("depth", "a depth >= 0 below the reference level", depth)
    return material_ratio(z, section_height(z, reference) - depth)


def section_height(z, ratio) -> float:
    """C(mr): the height (m) at which the material ratio is ``ratio`` (0..1)."""
    if not 0.0 <= ratio <= 1.0:
        raise InputError("ratio", "a material ratio between 0 and 1", ratio)
    return float(np.quantile(_heights(z), 1.0 - ratio))


def section_height_difference(z, upper=0.2, lower=0.8) -> float:
    """Rdc / Sdc: C(upper) - C(lower), the height between two material ratios (m)."""
    return section_height(z, upper) - section_height(z, lower)


@dataclass(frozen=True)
class EquivalentLine:
    """The equivalent straight line of ISO 13565-2: ``height = intercept + slope * mr``.

    Attributes
    ----------
    intercept, slope : float
        m, and m per unit material ratio (negative).
    window : tuple of float
        The 40 % window of material ratio it was fitted over.
    """

    intercept: float
    slope: float
    window: tuple[float, float]

    def __call__(self, ratio):
        return self.intercept + self.slope * np.asarray(ratio, dtype=float)


def equivalent_line(z) -> EquivalentLine:
    """Least-squares line through the 40 % window of least height drop (ISO 13565-2)."""
    mr, c = material_ratio_curve(z)
    span = int(round(CORE_WINDOW * mr.size))
    drops = c[:mr.size - span] - c[span:]
    start = int(np.argmin(drops))
    window = slice(start, start + span + 1)
    slope, intercept = np.polyfit(mr[window], c[window], 1)
    return EquivalentLine(float(intercept), float(slope),
                          (float(mr[window][0]), float(mr[window][-1])))


def rk_parameters(z, prefix="R") -> dict:
    """The Rk family (ISO 13565-2) or, with ``prefix="S"``, the Sk family (ISO 25178-2).

    Parameters
    ----------
    z : array_like
        Heights (m) of the roughness profile over the evaluation length, or of the S-L surface.
    prefix : "R" or "S"

    Returns
    -------
    dict
        ``Rk, Rpk, Rvk`` (m), ``Mr1, Mr2`` (fractions 0..1); areal ``Sk, Spk, Svk, Smr1,
        Smr2``. When no valley (peak) lies outside the core, Rvk (Rpk) is 0.
    """
    heights = _heights(z)
    line = equivalent_line(heights)
    top, bottom = line(0.0), line(1.0)
    mr1 = float(np.mean(heights >= top))
    mr2 = float(np.mean(heights > bottom))
    peaks = np.sum(np.clip(heights - top, 0, None)) / heights.size
    valleys = np.sum(np.clip(bottom - heights, 0, None)) / heights.size
    if prefix not in ("R", "S"):
        raise InputError("prefix", '"R" (a profile) or "S" (an area)', prefix)
    keys = ("Sk", "Spk", "Svk", "Smr1", "Smr2") if prefix == "S" else (
        "Rk", "Rpk", "Rvk", "Mr1", "Mr2")
    values = (top - bottom, 2 * peaks / mr1 if mr1 > 0 else 0.0,
              2 * valleys / (1 - mr2) if mr2 < 1 else 0.0, mr1, mr2)
    return {key: float(v) for key, v in zip(keys, values, strict=True)}


def volume_parameters(z, p=0.1, q=0.8) -> dict:
    """Vmp, Vmc, Vvc, Vvv (ISO 25178-2, m^3/m^2 = m) at material ratios ``p`` and ``q``."""
    heights = _heights(z)
    level_p, level_q = section_height(heights, p), section_height(heights, q)

    def vm(level):
        return float(np.sum(np.clip(heights - level, 0, None)) / heights.size)

    def vv(level):
        return float(np.sum(np.clip(level - heights, 0, None)) / heights.size)

    vm_p, vv_q = vm(level_p), vv(level_q)
    return {"Vmp": vm_p, "Vmc": vm(level_q) - vm_p, "Vvc": vv(level_p) - vv_q, "Vvv": vv_q}
