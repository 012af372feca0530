"""Shared figure helpers: a headless backend and consistent scaling of axes."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

__all__ = ["MAX_MAP_ASPECT", "hertz_outline", "map_aspect", "map_ylabel", "new_figure", "plt"]

#: Tallest height-to-width ratio of a contour map drawn to scale. A taller domain (a long
#: ellipse: a ball bearing's race contact, b/a = 5-10, on its default domain 4 a by 4 b) is
#: drawn with its y-axis compressed to this ratio (a domain that much wider than tall, a
#: thin measured strip, stretched), and its y label says by how much; drawn to
#: scale, a user's 6205 inner-race contact (b/a = 9.5) was a strip a sixth as wide as its
#: colour bar. The seed's gear contact (b/a = 3.9) is drawn to scale.
MAX_MAP_ASPECT = 5.0


def new_figure(width: float = 6.4, height: float = 4.2, **kwargs):
    """A figure and axes with constrained layout."""
    return plt.subplots(figsize=(width, height), layout="constrained", **kwargs)


def hertz_outline(ax, b_over_a: float = 1.0, label: str | None = None):
    """Draw the Hertz ellipse heavy on axes in units of a: x^2 + (y / (b/a))^2 = 1 (pass
    ``b_over_a = 1`` for axes x/a, y/b, where it is the unit circle)."""
    t = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(np.cos(t), b_over_a * np.sin(t), "k-", lw=2.2, label=label)


def map_aspect(width: float, height: float) -> float:
    """Axes aspect (page length of a unit of y over that of a unit of x) for a map ``width``
    wide and ``height`` tall (in the same unit): 1, drawn to scale, unless one side is more
    than :data:`MAX_MAP_ASPECT` times the other; then y is compressed (stretched) so that the
    map is drawn that many times taller (wider) than wide (tall)."""
    tall = float(height / max(width, 1e-300))
    if tall > MAX_MAP_ASPECT:
        return MAX_MAP_ASPECT / tall
    if tall < 1.0 / MAX_MAP_ASPECT:
        return 1.0 / (MAX_MAP_ASPECT * tall)
    return 1.0


def map_ylabel(aspect: float, label: str = "y / a") -> str:
    """The y label of a map drawn with ``aspect`` (:func:`map_aspect`): ``label``, with the
    compression (stretch) named when the map is not to scale."""
    if aspect == 1.0:
        return label
    return (f"{label}  (compressed {1.0 / aspect:.2g} times)" if aspect < 1.0 else
            f"{label}  (stretched {aspect:.2g} times)")
