"""Shared figure helpers: a headless backend and consistent scaling of axes."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt  # noqa: E402

__all__ = ["new_figure", "plt"]


def new_figure(width: float = 6.4, height: float = 4.2, **kwargs):
    """A figure and axes with constrained layout."""
    return plt.subplots(figsize=(width, height), layout="constrained", **kwargs)
