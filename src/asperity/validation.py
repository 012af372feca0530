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

from .references import cite
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
@check("kernel-square-centre", cite("Love's rectangle, 4 ln(1 + sqrt 2)", "elastic-half-space"))
def _kernel_square():
    from .elastic import love_integral

    s = 1.0e-3
    return [Comparison("I(0,0) of a square / side", float(love_integral(0.0, 0.0, s, s)) / s,
                       4.0 * np.log(1.0 + np.sqrt(2.0)),
                       cite("4 ln(1 + sqrt 2)", "elastic-half-space"), "1", 1e-6)]


# ------------------------------------------------------------------------------------ Hertz
@check("hertz-spheres-1in", cite("Hertz, Seireg ch. 3 example 1", "hertz"))
def _hertz_spheres():
    from .contact import hertz_point
    from .materials import Material

    steel = Material(30e6 * PSI, 0.3, "steel")
    h = hertz_point(2160 * LBF, 0.5 * IN, 0.5 * IN, steel, steel)
    return [Comparison("contact radius a", h.a / IN, 0.036628, cite("Seireg ch. 3", "hertz"), "in",
                       2e-5)]


@check("hertz-gear-ellipse", cite("Hertz, Holmes et al. (2005) Table 1 gear case", "hertz"))
def _hertz_gear():
    from .contact import hertz_point
    from .materials import Material

    m = Material(227e9, 0.0, "E'=227 GPa")  # nu = 0 and E = E' gives E* = E'/2
    h = hertz_point(962.0, 0.0191, 0.151, m, m)
    src = cite("exact elliptical Hertz", "hertz")
    return [Comparison("semi-axis a", h.a * 1e3, 0.3364, src, "mm", 2e-4),
            Comparison("semi-axis b", h.b * 1e3, 1.3045, src, "mm", 1e-4),
            Comparison("maximum pressure", h.p_max / 1e9, 1.0466, src, "GPa", 1e-4)]


# ------------------------------------------------------------------------- normal contact
@check("normal-hertz-ellipse", cite("numerical vs exact Hertz, gear-case ellipse", "hertz"))
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
    src = cite("Hertz (exact elliptical)", "hertz")
    return [Comparison("maximum pressure", res.pressure.max(), h.p_max, src, "Pa", 0.01),
            Comparison("approach", res.approach, h.approach, src, "m", 0.01),
            Comparison("contact area", res.contact_area, h.area, src, "m^2", 0.02)]


# ------------------------------------------------------------------------ rough surfaces
@check("surface-sine-parameters", cite("sine: Ra 2A/pi, Rq A/sqrt 2", "profile-parameters"))
def _sine_parameters():
    from .surfaces import Profile, cell_centres, roughness_parameters

    amplitude, wavelength = 1.0e-6, 100e-6
    x = cell_centres(1000, wavelength / 200)  # five whole periods, periodic
    sine = roughness_parameters(Profile(x, amplitude * np.sin(2 * np.pi * x / wavelength), True))
    # Two harmonics z = A cos t + B cos 2t: <z^3> = 3 A^2 B / 4, <z^2> = (A^2 + B^2) / 2.
    t = 2 * np.pi * x / wavelength
    two = roughness_parameters(Profile(x, np.cos(t) + 0.5 * np.cos(2 * t), True))
    src = cite("closed form", "profile-parameters")
    return [Comparison("Ra of a sine / A", sine["Ra"] / amplitude, 2 / np.pi, src, "1", 1e-4),
            Comparison("Rq of a sine / A", sine["Rq"] / amplitude, 1 / np.sqrt(2), src, "1",
                       1e-9),
            Comparison("Rku of a sine", sine["Rku"], 1.5, src, "1", 1e-9),
            Comparison("Rsk of cos t + cos(2t)/2", two["Rsk"], 0.375 / 0.625**1.5, src, "1",
                       1e-9)]


@check("turning-kinematic", cite("Seireg eq. (4.1), parabolic feed marks", "turning"))
def _turning_kinematic():
    from .surfaces import roughness_parameters, turned_profile

    feed, radius = 0.02e-3, 0.8e-3  # f/r small: circle and parabola differ by ~(f/r)^2
    p = roughness_parameters(turned_profile(feed, radius, 20 * feed, feed / 1001))
    book = roughness_parameters(turned_profile(0.127e-3, 0.794e-3, 2.54e-3, 0.127e-3 / 201))
    src = cite("parabolic feed marks", "turning")
    return [Comparison("Rt / (f^2 / 8 r)", p["Rt"] / (feed**2 / (8 * radius)), 1.0,
                       cite("Seireg eq. (4.1)", "turning"), "1", 1e-3),
            Comparison("Ra / (f^2 / (18 sqrt 3 r))", p["Ra"] / (feed**2 / (18 * np.sqrt(3)
                                                                          * radius)), 1.0, src,
                       "1", 1e-3),
            Comparison("Rsk", p["Rsk"], 2 * np.sqrt(5) / 7, src, "1", 1e-3),
            Comparison("Rku", p["Rku"], 15 / 7, src, "1", 1e-3),
            Comparison("Rt, f = 0.127 mm, r = 0.794 mm", book["Rt"] * 1e6,
                       0.127e-3**2 / (8 * 0.794e-3) * 1e6,
                       cite("Seireg eq. (4.1), Fig. 4.2 tool", "turning"),
                       "um", 0.01)]


@check("gaussian-filter-50pct", cite("ISO 16610-21, 50 % at the cut-off", "gaussian-filter"))
def _gaussian_filter_half():
    from .surfaces import gaussian_filter, gaussian_transmission

    cutoff, h = 0.8e-3, 2e-6
    x = (np.arange(4000) + 0.5) * h  # 8 mm: ten whole cut-off wavelengths
    z = np.sin(2 * np.pi * x / cutoff)
    rows = [Comparison("transmission formula at lambda_c", float(gaussian_transmission(cutoff,
                                                                                       cutoff)),
                       0.5, cite("exp(-pi alpha^2) = 1/2", "gaussian-filter"),
                       "1", 1e-12)]
    for periodic in (True, False):
        mean_line = gaussian_filter(z, x, cutoff, periodic=periodic)
        # Amplitude of the mean line away from the ends (one cut-off each side), by least squares.
        inner = slice(None) if periodic else slice(400, -400)
        basis = np.column_stack([np.sin(2 * np.pi * x / cutoff), np.cos(2 * np.pi * x / cutoff)])
        coef = np.linalg.lstsq(basis[inner], mean_line[inner], rcond=None)[0]
        rows.append(Comparison(f"mean-line amplitude of a lambda_c sine, "
                               f"{'periodic' if periodic else 'end-corrected'}",
                               float(np.hypot(*coef)), 0.5, cite("ISO 16610-21", "gaussian-filter"),
                               "1",
                               1e-9 if periodic else 1e-6))
    return rows


@check("ground-profile-gaussian", cite("Gaussian heights: Rq/Ra, Rku", "profile-parameters"))
def _ground_profile_gaussian():
    from .surfaces import roughness_parameters, transverse_ground_profile

    # a fresh (not run-in) ground profile has Gaussian heights; Ra is imposed by rescaling, so
    # the checks are the scale-free ratios, averaged over eight seeds
    params = [roughness_parameters(transverse_ground_profile(5e-3, 0.5e-6, 0.3e-6, seed=s))
              for s in range(8)]
    src = cite("Gaussian height distribution", "profile-parameters")
    return [Comparison("Rq / Ra", float(np.mean([d["Rq"] / d["Ra"] for d in params])),
                       float(np.sqrt(np.pi / 2)), src, "1", 0.01),
            Comparison("Rku", float(np.mean([d["Rku"] for d in params])), 3.0, src, "1", 0.05)]


# ------------------------------------------------------------------------------ steady EHL
@check("ehl-moes-line", cite("Moes (1992) central film, M = 10, L = 10", "moes-line"))
def _ehl_moes_line():
    from .ehl import LineContact, Lubricant, moes_line, solve_steady
    from .materials import Material

    body = Material(2e11, 0.3)
    e_prime, alpha, eta0, radius, m_load, l_mat = 2e11 / 0.91, 2e-8, 0.04, 0.01, 10.0, 10.0
    two_u = (l_mat / (alpha * e_prime)) ** 4
    u = 0.5 * two_u * e_prime * radius / eta0
    load = m_load * two_u**0.5 * e_prime * radius
    lub = Lubricant(eta0, alpha, viscosity_model="barus", compressible=False)
    prob = LineContact(radius, load, u, u, body, body, lub)
    res = solve_steady(prob, nx=257, max_iter=40000,
                       domain=((-4.0 * prob.a, 1.5 * prob.a), (0.0, 0.0)))
    ref = moes_line(load, radius, u, eta0, alpha, e_prime).central
    return [Comparison("central film (257 nodes)", res.central_film, ref,
                       cite("Moes (1992) via Venner & Lubrecht (2000)", "moes-line"), "m",
                       0.05),
            Comparison("solver converged (1 = yes)", float(res.converged), 1.0,
                       "a film from a converged solve only", "", 0.0)]


@check("ehl-holmes-smooth-point", cite("Holmes et al. (2005) Fig. 2", "holmes-gear-case"),
       slow=True)
def _ehl_holmes_point():
    from .cases import load_case
    from .examples import example_text
    from .runners import run_case

    out = run_case(load_case(example_text("holmes-smooth-point")))
    return [row for row in out.comparisons if row.tolerance is not None]


# ----------------------------------------------------------------------- frictional contact
def _tangential_hertz(n):
    """Seireg's 1 in steel spheres under 2160 lbf on n x n cells over 2.1 a (Hertz pressure
    scaled to the exact load)."""
    from .contact import hertz_point
    from .materials import Material

    steel = Material(30e6 * PSI, 0.3, "steel")
    h = hertz_point(2160 * LBF, 0.5 * IN, 0.5 * IN, steel, steel)
    x = (np.arange(n) - (n - 1) / 2) * (2.1 * h.a / n)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = h.pressure(X, Y)
    return steel, h, x, p * h.load / (p.sum() * (x[1] - x[0]) ** 2)


@check("tangential-cattaneo-mindlin", cite("Cattaneo-Mindlin, Q = mu P / 2", "cattaneo-mindlin"))
def _tangential_cattaneo():
    from .contact import reference as ref
    from .contact import solve_tangential

    steel, h, x, p = _tangential_hertz(64)
    mu, force = 0.1, 0.05 * h.load
    res = solve_tangential(p, x, x, mu, steel, steel, force=(force, 0.0))
    cm = ref.cattaneo_mindlin(h.load, force, mu, h.a, steel, steel)
    stick = np.sqrt(res.stick.sum() * (x[1] - x[0]) ** 2 / np.pi)
    src = cite("Cattaneo (1938), Mindlin (1949)", "cattaneo-mindlin")
    return [Comparison("relative shift", res.shift[0], cm.shift, src, "m", 0.01),
            Comparison("stick radius", stick, cm.stick_radius, src, "m", 0.03)]


@check("tangential-lubkin", cite("Lubkin torsion, Seireg Ex. 3.4.4-1", "lubkin-torsion"))
def _tangential_lubkin():
    from .contact import reference as ref
    from .contact import solve_tangential

    steel, h, x, p = _tangential_hertz(64)
    mu, moment = 0.1, 2.45 * IN * LBF
    res = solve_tangential(p, x, x, mu, steel, steel, moment=moment)
    c = ref.lubkin_stick_radius(moment, h.a, mu, h.p_max)
    src = cite("Lubkin (1951), Johnson eq. 7.50", "lubkin-torsion")
    return [Comparison("twist per body", 0.5 * res.rotation,
                       ref.lubkin_twist(c, h.a, mu, h.p_max, steel), src, "rad", 0.01),
            Comparison("gross-slip moment", res.load_capacity * moment,
                       ref.gross_slip_moment_hertz(mu, h.load, h.a),
                       cite("3 pi mu P a / 16", "lubkin-torsion"),
                       "N m", 0.005)]


@check("tangential-uniform-torsion", cite("uniform pressure, M = 0.6 M_gs",
                                          "uniform-pressure-torsion"))
def _tangential_uniform_torsion():
    from .contact import reference as ref
    from .contact import solve_tangential
    from .materials import Material

    steel = Material(206e9, 0.3, "steel")
    a, p0, mu, n = 1e-3, 100e6, 0.2, 64
    x = (np.arange(n) - (n - 1) / 2) * (2.1 * a / n)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = np.where(np.hypot(X, Y) < a, p0, 0.0)
    # the disc on the grid: the same load on the cells' area, i.e. an equivalent radius
    a_eq = np.sqrt((p > 0).sum() * (x[1] - x[0]) ** 2 / np.pi)
    moment = 0.6 * ref.gross_slip_moment_uniform(mu, p0, a_eq)
    res = solve_tangential(p, x, x, mu, steel, steel, moment=moment)
    c = ref.uniform_torsion_stick_radius(moment, a_eq, mu, p0)
    src = cite("Johnson sec. 7.3 (uniform pressure)", "uniform-pressure-torsion")
    return [Comparison("relative twist", res.rotation,
                       ref.uniform_torsion_twist(c, a_eq, mu, p0, steel, steel), src, "rad",
                       0.03),
            Comparison("gross-slip moment", res.load_capacity * moment,
                       ref.gross_slip_moment_uniform(mu, p0, a_eq),
                       cite("(2 pi / 3) mu p a^3", "uniform-pressure-torsion"),
                       "N m", 0.01)]


@check("tangential-lp-vs-fft", cite("Seireg's LP vs Lubkin and the FFT solver", "lubkin-torsion"))
def _tangential_lp_vs_fft():
    from .contact import reference as ref
    from .contact import solve_tangential

    steel, h, x, p = _tangential_hertz(20)
    moment = 2.45 * IN * LBF
    fft = solve_tangential(p, x, x, 0.1, steel, steel, moment=moment)
    lp = solve_tangential(p, x, x, 0.1, steel, steel, moment=moment, method="lp")
    c = ref.lubkin_stick_radius(moment, h.a, 0.1, h.p_max)
    lubkin = ref.lubkin_twist(c, h.a, 0.1, h.p_max, steel)
    src = "FFT solver, same grid"
    return [Comparison("twist per body (LP, 20 x 20 cells)", 0.5 * lp.rotation, lubkin,
                       cite("Lubkin (1951), Johnson eq. 7.50", "lubkin-torsion"), "rad", 0.02),
            Comparison("rotation (LP)", lp.rotation, fft.rotation, src, "rad", 0.01),
            Comparison("stuck cells (LP)", float(lp.stick.sum()), float(fft.stick.sum()), src,
                       "1", 0.05)]
