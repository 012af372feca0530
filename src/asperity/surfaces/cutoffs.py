"""Choosing the filters of a roughness measurement: ISO 4288 cut-offs, ISO 3274 lambda_s.

ISO 4288 (1996) clause 7 and Table 1: for a non-periodic profile the cut-off lambda_c follows
from the Ra the profile has when filtered with it; one estimates Ra, picks the cut-off of its
range, re-measures with that cut-off and repeats until the measured Ra falls in the range of the
cut-off used. The ranges (Ra in um -> lambda_c in mm):

    (0.006, 0.02] -> 0.08,  (0.02, 0.1] -> 0.25,  (0.1, 2] -> 0.8,  (2, 10] -> 2.5,
    (10, 80] -> 8

For a periodic profile (turned, milled, planed) clause 7.2 and Table 3 take the cut-off from
the mean width of the profile elements RSm instead (RSm in mm -> lambda_c in mm):

    (0.013, 0.04] -> 0.08,  (0.04, 0.13] -> 0.25,  (0.13, 0.4] -> 0.8,  (0.4, 1.3] -> 2.5,
    (1.3, 4] -> 8

ISO 3274 (1996) Table 1 pairs each cut-off with the short-wave filter lambda_s and the largest
sampling spacing for which that lambda_s applies:

    lambda_c 0.08, 0.25, 0.8 mm -> lambda_s 2.5 um (spacing <= 0.5 um);
    2.5 mm -> 8 um (spacing <= 1.5 um);  8 mm -> 25 um (spacing <= 5 um).
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError

__all__ = ["CUTOFFS", "LAMBDA_S", "RSM_CUTOFFS", "cutoff_for_ra", "cutoff_for_rsm",
           "lambda_s_for", "largest_spacing"]

#: ISO 4288 Table 1: (upper Ra bound in m, cut-off in m), Ra ranges open below, closed above.
CUTOFFS = ((0.02e-6, 0.08e-3), (0.1e-6, 0.25e-3), (2e-6, 0.8e-3), (10e-6, 2.5e-3),
           (np.inf, 8e-3))
#: ISO 4288 Table 3 (periodic profiles): (upper RSm bound in m, cut-off in m), ranges open
#: below, closed above; RSm beyond 4 mm takes the longest cut-off.
RSM_CUTOFFS = ((0.04e-3, 0.08e-3), (0.13e-3, 0.25e-3), (0.4e-3, 0.8e-3), (1.3e-3, 2.5e-3),
               (np.inf, 8e-3))
#: ISO 3274 Table 1: cut-off (m) -> (lambda_s in m, largest sampling spacing in m).
LAMBDA_S = {0.08e-3: (2.5e-6, 0.5e-6), 0.25e-3: (2.5e-6, 0.5e-6), 0.8e-3: (2.5e-6, 0.5e-6),
            2.5e-3: (8e-6, 1.5e-6), 8e-3: (25e-6, 5e-6)}


def cutoff_for_ra(ra: float) -> float:
    """The ISO 4288 Table 1 cut-off (m) of a non-periodic profile with roughness ``ra`` (m)."""
    if not np.isfinite(ra) or ra < 0:
        raise InputError("Ra", "a finite roughness >= 0", ra)
    return next(cut for upper, cut in CUTOFFS if ra <= upper)


def cutoff_for_rsm(rsm: float) -> float:
    """The ISO 4288 Table 3 cut-off (m) of a periodic profile whose mean element width is
    ``rsm`` (m); the shortest for RSm up to 0.04 mm."""
    if not np.isfinite(rsm) or rsm <= 0:
        raise InputError("RSm", "a finite mean element width > 0", rsm)
    return next(cut for upper, cut in RSM_CUTOFFS if rsm <= upper)


def largest_spacing(cutoff: float) -> tuple[float, float] | None:
    """ISO 3274 Table 1's lambda_s and largest sampling spacing (m) for ``cutoff``, or None for
    a cut-off outside the table."""
    match = next((key for key in LAMBDA_S if np.isclose(key, cutoff, rtol=1e-6)), None)
    return None if match is None else LAMBDA_S[match]


def lambda_s_for(cutoff: float, spacing: float) -> tuple[float | None, str]:
    """ISO 3274's lambda_s for ``cutoff`` when the sampling ``spacing`` allows it.

    Returns
    -------
    lambda_s : float or None
        The short-wave cut-off (m), or None when it does not apply: a cut-off outside the table,
        or a spacing coarser than the table's largest for it (the data's own spacing then
        bounds the short wavelengths).
    reason : str
        One line saying which and why.
    """
    row = largest_spacing(cutoff)
    if row is None:
        return None, (f"no lambda_s: the cut-off {cutoff * 1e3:.4g} mm is not one of ISO "
                      "3274's (0.08, 0.25, 0.8, 2.5, 8 mm)")
    lam, largest = row
    if spacing > largest * (1 + 1e-9):
        return None, (f"no lambda_s: the spacing {spacing * 1e6:.4g} um is coarser than the "
                      f"{largest * 1e6:g} um ISO 3274 allows for lambda_s = {lam * 1e6:g} um")
    return lam, (f"lambda_s = {lam * 1e6:g} um (ISO 3274 Table 1 for lambda_c = "
                 f"{cutoff * 1e3:g} mm)")
