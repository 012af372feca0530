"""The steady point-contact solver against an independent reference at L = 0.

The reference (tests/point_ehl_reference.py) shares nothing with :mod:`asperity.ehl`: the
deflection is a dense matrix of Love's rectangular panels, the wedge term a QUICK face
value, the Reynolds exit condition a Fischer-Burmeister complementarity, and all equations
with the load balance are solved at once by semismooth Newton. The case is the soft contact
of docs/ehl-robustness.md (session 37): a PDMS ball (2 MPa, 0.49, R = 6.35 mm) on glass
(70 GPa, 0.22), 0.5 N, 0.011 Pa s, alpha = 0, rolling at 1 m/s (Moes M = 102, L = 0), on the
solver's default domain -2.5a..1.5a, +-2b (docs/ehl-robustness.md, session 39, has the
meshes, the timings and M = 964).
"""

import sys
from pathlib import Path

import numpy as np
import pytest

from asperity.cases import load_case
from asperity.ehl import solve_steady
from asperity.ehl.formulas import nijenbanning_point

sys.path.insert(0, str(Path(__file__).parent))
from point_ehl_reference import (  # noqa: E402
    PointReference,
    love_panel,
    richardson,
    solve_sequence,
)

R, LOAD, ETA, SPEED = 6.35e-3, 0.5, 0.011, 1.0
E_PRIME = 2.0 / ((1 - 0.49**2) / 2e6 + (1 - 0.22**2) / 70e9)
A = (3.0 * LOAD * R / (2.0 * E_PRIME)) ** (1.0 / 3.0)  # Hertz circle, a^3 = 3 w R / (4 E*)
P_H = 3.0 * LOAD / (2.0 * np.pi * A**2)
LAM = 12.0 * ETA * SPEED * R**2 / (A**3 * P_H)
C = 2.0 * P_H * R / (np.pi * E_PRIME * A)  # = 2/pi^2 for a circle
DOMAIN = (-2.5, 1.5, 2.0)

CASE = {
    "analysis": "ehl-steady", "title": "PDMS ball on glass, water-glycerol",
    "body1": {"youngs_modulus": "2 MPa", "poisson_ratio": 0.49},
    "body2": {"youngs_modulus": "70 GPa", "poisson_ratio": 0.22},
    "contact": {"type": "point", "rx": "6.35 mm", "ry": "6.35 mm", "load": "0.5 N"},
    "speeds": {"u": f"{SPEED} m/s"},
    "lubricant": {"eta0": "0.011 Pa s", "alpha": "0 1/GPa", "viscosity_model": "barus",
                  "density_model": "incompressible"},
}


def _reference(spacings):
    return solve_sequence(spacings=spacings, film=0.8 * 0.043, lam=LAM, c=C, k=1.0,
                          ratio=1.0, domain=DOMAIN)


def _solver(nx, ny, levels):
    """asperity's central and minimum films (Hertzian units) on the reference's domain."""
    problem = load_case(CASE).problem()
    assert (problem.a, problem.p_hertz, problem.lam) == pytest.approx((A, P_H, LAM), rel=1e-9)
    a = problem.a
    res = solve_steady(problem, nx=nx, ny=ny, levels=levels, max_iter=20000,
                       domain=((DOMAIN[0] * a, DOMAIN[1] * a), (-DOMAIN[2] * a, DOMAIN[2] * a)))
    assert res.converged
    return res.central_film / problem.film_scale, res.minimum_film / problem.film_scale


def test_love_panels_give_hertz_a_flat_gap():
    """Love's panel integral: ``8 ln(1 + sqrt 2)`` at the centre of a 2 x 2 square, and the
    dense deflection of Hertz's pressure keeps the gap ``X^2/2 + Y^2/2 + c K P`` flat inside
    the contact (Hertz: exactly flat) to ``0.35 dX^2``, falling 2.65 times with dX halved
    (measured spread within 0.9 a 1.41e-3, 5.3e-4, 1.7e-4 at dX = 1/12, 1/24, 1/48; the
    panels' midpoint rule on the square-root edge of Hertz's pressure is not quite second
    order)."""
    assert love_panel(0.0, 0.0, 1.0, 1.0) == pytest.approx(8.0 * np.log(1.0 + np.sqrt(2.0)),
                                                           rel=1e-14)
    spreads = []
    for dx in (1 / 12, 1 / 24):
        ref = PointReference(lam=LAM, c=C, k=1.0, ratio=1.0, domain=(-1.5, 1.5, 1.5),
                             dx=dx, dy=dx)
        P, H0 = ref.hertz_start(0.0)
        gap = ref.film(P, H0).reshape(ref.nx, ref.ny)
        gx, gy = np.meshgrid(ref.X, ref.Y, indexing="ij")
        inside = gap[gx**2 + gy**2 < 0.81]
        spreads.append(inside.max() - inside.min())
        assert spreads[-1] < 0.35 * dx**2
    assert spreads[0] / spreads[1] > 2.5


def test_the_solver_and_the_reference_agree_on_a_coarse_mesh():
    """On the same cells (dX = dY = a/16, 65 x 65 nodes on the full domain) the reference's
    central film is 0.0390 (2.9 % under its converged 0.0402) and the solver's 0.0376
    (6.5 % under): the solver's second-order error is about twice the reference's. The films
    agree within the sum of the two errors, 10 %; the minimum films within 5 % (measured
    0.0262 and 0.0258)."""
    ref = _reference([1 / 8, 1 / 16])[-1]
    assert ref.converged
    central, minimum = _solver(65, 65, 3)
    assert ref.central == pytest.approx(0.0390, rel=0.01)
    assert central / ref.central == pytest.approx(1.0, abs=0.10)
    assert minimum / ref.minimum == pytest.approx(1.0, abs=0.05)


@pytest.mark.slow
def test_the_solver_converges_to_the_reference_and_nijenbanning_lies_above_both():
    """Reference on dX = a/16, a/24, a/32 (about 2 min): central films 0.03905, 0.03972,
    0.03994, second order (differences 6.7e-4, 2.2e-4: ratio 3.0, second order 2.86),
    extrapolated 0.04022 (the pair a/16-a/24 gives 0.04025: the extrapolation's own error
    under 0.1 %). The solver on 97 x 97 and 129 x 129 (the same cells, about 3 min)
    extrapolates to 0.04024, within 0.05 % (tested at 0.5 %); Nijenbanning's fit lies 6.8 %
    above them (the reference is 0.936 of it): the gap of docs/ehl-robustness.md is the
    fit's."""
    sols = _reference([1 / 16, 1 / 24, 1 / 32])
    assert all(s.converged for s in sols)
    hc = [s.central for s in sols]
    assert (hc[1] - hc[0]) / (hc[2] - hc[1]) == pytest.approx(2.86, rel=0.15)
    exact = richardson(hc[1], hc[2], 4 / 3)
    assert richardson(hc[0], hc[1], 1.5) == pytest.approx(exact, rel=1e-3)
    solver = richardson(_solver(97, 97, 1)[0], _solver(129, 129, 3)[0], 4 / 3)
    assert solver == pytest.approx(exact, rel=5e-3)
    fit = nijenbanning_point(LOAD, R, R, SPEED, ETA, 0.0, E_PRIME).central * R / A**2
    assert exact / fit == pytest.approx(0.936, abs=0.005)


def test_at_l_zero_nijenbannings_row_is_checked_at_its_measured_accuracy():
    """At L = 0 the fit lies 6.8 % (M = 102) and 7.5 % (M = 964) above the reference that the
    solver matches within 0.1 %: at the 5 % of the other checked rows a right solution read
    "differs". The PDMS ball of the corpus (M = 102): a film 6.8 % under the fit (the
    reference's) passes at 10 %, one 12 % under it does not; a piezoviscous steel ball's row
    keeps 5 %."""
    from asperity.cases import load_case
    from asperity.references import film_formula_comparisons

    def row(text, ratio):
        problem = load_case(text).problem()
        fit = [r for r in film_formula_comparisons(problem, 1e-6, 1e-6)
               if r.source.startswith("Nijenbanning")][0].reference
        (checked,) = [r for r in film_formula_comparisons(problem, ratio * fit, 1e-6)
                      if r.source.startswith("Nijenbanning")]
        return checked

    soft = (Path(__file__).parent / "corpus" / "warn-ehl-point-soft-large-contact.toml"
            ).read_text()
    assert row(soft, 1 / 1.068).tolerance == 0.10
    assert row(soft, 1 / 1.068).passed
    assert not row(soft, 0.88).passed
    steel = soft.replace('"2 MPa"', '"210 GPa"').replace("0.49", "0.3").replace(
        '"0 1/GPa"', '"20 1/GPa"')
    assert row(steel, 1.0).tolerance == 0.05
