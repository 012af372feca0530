"""Shared figure helpers: a headless backend and consistent scaling of axes."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

__all__ = ["hertz_outline", "new_figure", "plt"]


def new_figure(width: float = 6.4, height: float = 4.2, **kwargs):
    """A figure and axes with constrained layout."""
    return plt.subplots(figsize=(width, height), layout="constrained", **kwargs)


def hertz_outline(ax, b_over_a: float = 1.0, label: str | None = None):
    """Draw the Hertz ellipse heavy on axes in units of a: x^2 + (y / (b/a))^2 = 1 (pass
    ``b_over_a = 1`` for axes x/a, y/b, where it is the unit circle)."""
    t = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(np.cos(t), b_over_a * np.sin(t), "k-", lw=2.2, label=label)
