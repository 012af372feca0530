"""Single surface features: a dent, a bump, or a transverse ridge or groove on an otherwise
smooth surface.

The classic probes of transient EHL (Venner & Lubrecht 1994; Kaneta et al. 1996; Ai & Cheng
1994): one feature carried through the contact on one surface shows how the film deforms a
local change of the gap and where the disturbance it creates travels (with the surface, or at
the mean entrainment speed under sliding).

Shape: a smooth cosine-squared cap of half-width ``w`` (zero slope at its edge),

    z(r) = A cos^2(pi r / (2 w))  for r < w,  0 elsewhere,

with ``r`` the distance from the feature's centre (dent, bump: circular) or its distance along
x (ridge, groove: straight, across the rolling direction). A dent and a groove have
``A = -depth`` (metal removed), a bump and a ridge ``A = height``.

References
----------
C. H. Venner, A. A. Lubrecht, "Transient analysis of surface features in an EHL line contact
in the case of sliding", J. Tribol. 116 (1994) 186-193.
M. Kaneta, T. Sakai, H. Nishikawa, "Effects of surface roughness on point contact EHL",
Tribol. Trans. 36 (1993) 605-612.
X. Ai, H. S. Cheng, "The influence of moving dent on point EHL contacts", Tribol. Trans. 37
(1994) 323-335.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError, check_positive
from ..formatting import format_quantity
from .topography import Profile, Topography, cell_centres

__all__ = ["FEATURE_KINDS", "STRAIGHT_FEATURES", "feature_shape", "feature_surface"]

#: Kinds of single feature.
FEATURE_KINDS = ("dent", "bump", "ridge", "groove")
#: The features that are straight across the rolling direction (a :class:`Profile`, which a
#: line contact can take); the others are circular.
STRAIGHT_FEATURES = ("ridge", "groove")
#: The features below the surface (metal removed).
_HOLLOWS = ("dent", "groove")


def feature_shape(r, half_width: float) -> np.ndarray:
    """The cosine-squared cap ``cos^2(pi r/(2 w))`` for ``|r| < w``, else 0 (peak 1)."""
    w = check_positive("half_width", half_width)
    r = np.abs(np.asarray(r, dtype=float))
    return np.where(r < w, np.cos(0.5 * np.pi * r / w) ** 2, 0.0)


def feature_surface(kind: str, length: float, spacing: float, *, amplitude: float,
                    half_width: float, position: float, y=None):
    """A smooth surface of ``length`` m (cells of ``spacing`` m from 0) carrying one feature.

    Parameters
    ----------
    kind : {"dent", "bump", "ridge", "groove"}
        A circular dent (heights ``-amplitude``), a circular bump (``+amplitude``), or a
        straight ridge (``+amplitude``) or groove (``-amplitude``) across the rolling
        direction.
    length, spacing : float
        Extent and spacing of the surface along x (m); non-periodic.
    amplitude : float
        Depth of a dent or groove, or height of a bump or ridge, m (> 0).
    half_width : float
        Radius (dent, bump) or half-width along x (ridge, groove) of the cap, m.
    position : float
        Surface coordinate of the feature's centre along x, m (``0 <= position <= length``).
    y : array_like, optional
        Cell-centre positions across the rolling direction (m), needed for a dent or a bump,
        whose centre lies at ``y = 0``.

    Returns
    -------
    Profile or Topography
        A ridge or a groove is a :class:`Profile` (extruded across y by the solvers); a dent
        or a bump a :class:`Topography` on ``x`` by ``y``.
    """
    if kind not in FEATURE_KINDS:
        raise InputError("kind", " or ".join(f'"{k}"' for k in FEATURE_KINDS), kind)
    length = check_positive("length", length)
    spacing = check_positive("spacing", spacing)
    amplitude = check_positive("amplitude", amplitude)
    position = float(position)
    if not 0.0 <= position <= length:
        raise InputError("position", f"a surface coordinate between 0 and "
                         f"{format_quantity(length, 'm')}",
                         position)
    x = cell_centres(int(np.ceil(length / spacing)), spacing)
    height = -amplitude if kind in _HOLLOWS else amplitude
    if kind in STRAIGHT_FEATURES:
        return Profile(x, height * feature_shape(x - position, half_width))
    if y is None:
        raise InputError("y", f"positions across the rolling direction for a {kind}")
    y = np.asarray(y, dtype=float)
    r = np.hypot(x[:, None] - position, y[None, :])
    return Topography(x, y, height * feature_shape(r, half_width))
