"""The validation table: every analytical and published-number check in one registry.

Each check is a function returning :class:`asperity.results.Comparison` rows (asperity's
number, the independent reference, the tolerance). ``asperity validate`` prints them as a table
and the test suite runs the same functions (``tests/test_validation.py``), so the table a user
reruns is exactly what CI asserts.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from .results import Comparison

__all__ = ["CHECKS", "Check", "check", "run_checks"]

IN = 0.0254
LBF = 4.4482216152605
PSI = 6894.757293168361


@dataclass(frozen=True)
class Check:
    """A named group of comparisons with the reference it draws on."""

    name: str
    source: str
    function: Callable[[], list]
    slow: bool = False


CHECKS: list[Check] = []


def check(name: str, source: str, slow: bool = False):
    """Register a validation function under ``name`` (``slow``: minutes, not seconds)."""

    def register(fn):
        CHECKS.append(Check(name, source, fn, slow))
        return fn

    return register


def run_checks(select: str | None = None, slow: bool = False) -> list[tuple[str, Comparison]]:
    """Run the checks (those whose name contains ``select``; slow ones only when asked).

    Returns (check name, row) pairs.
    """
    rows = []
    for c in CHECKS:
        if (select and select not in c.name) or (c.slow and not slow):
            continue
        rows += [(c.name, row) for row in c.function()]
    return rows


# ---------------------------------------------------------------------------- elastic kernels
@check("kernel-square-centre", "REFERENCE.md, Elastic half-space")
def _kernel_square():
    from .elastic import love_integral

    s = 1.0e-3
    return [Comparison("I(0,0) of a square / side", float(love_integral(0.0, 0.0, s, s)) / s,
                       4.0 * np.log(1.0 + np.sqrt(2.0)), "4 ln(1 + sqrt 2)", "1", 1e-6)]


# ------------------------------------------------------------------------------------ Hertz
@check("hertz-spheres-1in", "REFERENCE.md, Hertz (Seireg ch. 3 example 1)")
def _hertz_spheres():
    from .contact import hertz_point
    from .materials import Material

    steel = Material(30e6 * PSI, 0.3, "steel")
    h = hertz_point(2160 * LBF, 0.5 * IN, 0.5 * IN, steel, steel)
    return [Comparison("contact radius a", h.a / IN, 0.036628, "REFERENCE.md", "in", 2e-5)]


@check("hertz-gear-ellipse", "REFERENCE.md, Hertz (mixed-EHL seed Table 1)")
def _hertz_gear():
    from .contact import hertz_point
    from .materials import Material

    m = Material(227e9, 0.0, "E'=227 GPa")  # nu = 0 and E = E' gives E* = E'/2
    h = hertz_point(962.0, 0.0191, 0.151, m, m)
    src = "REFERENCE.md"
    return [Comparison("semi-axis a", h.a * 1e3, 0.3364, src, "mm", 2e-4),
            Comparison("semi-axis b", h.b * 1e3, 1.3045, src, "mm", 1e-4),
            Comparison("maximum pressure", h.p_max / 1e9, 1.0466, src, "GPa", 1e-4)]


# ------------------------------------------------------------------------- normal contact
@check("normal-hertz-ellipse", "numerical vs exact Hertz (gear-case ellipse, ~50 cells on 2a)")
def _normal_hertz_ellipse():
    from .contact import hertz_point, solve_normal
    from .materials import Material

    m = Material(227e9, 0.0, "E'=227 GPa")
    h = hertz_point(962.0, 0.0191, 0.151, m, m)
    nx, ny = 80, 64
    x = (np.arange(nx) + 0.5 - nx / 2) * (3.0 * h.a / nx)
    y = (np.arange(ny) + 0.5 - ny / 2) * (3.0 * h.b / ny)
    X, Y = np.meshgrid(x, y, indexing="ij")
    res = solve_normal(X**2 / 0.0382 + Y**2 / 0.302, x, y, m, m, load=962.0)
    src = "Hertz (exact elliptical)"
    return [Comparison("maximum pressure", res.pressure.max(), h.p_max, src, "Pa", 0.01),
            Comparison("approach", res.approach, h.approach, src, "m", 0.01),
            Comparison("contact area", res.contact_area, h.area, src, "m^2", 0.02)]
