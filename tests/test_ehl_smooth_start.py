"""The smooth steady start of a transient run and the rows on which it has a film
(asperity.ehl.smooth_start; docs/ehl-transient.md, "A probe of users' rough cases (session 40)")."""

import numpy as np
import pytest

from asperity.cases import load_case
from asperity.ehl.smooth_start import start_rows, touching_mask

# A toroidal traction drive as a user wrote it (session 40 probe): 2 kN on rx 15 mm, ry 30 mm,
# 5 m/s at slide/roll 0.05, a 10 mPa s traction fluid of 28 1/GPa: p_h 2.28 GPa, Moes
# M = 3091, L = 15. Its default mesh (513 x 57, dY = b/14) gave a smooth start with no film
# at 148 nodes of its side lobes, and the run counted contact at 100 % of its steps.
TRACTION = {
    "analysis": "ehl-transient", "title": "traction drive",
    "body1": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
    "body2": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
    "contact": {"type": "point", "rx": "15 mm", "ry": "30 mm", "load": "2 kN"},
    "speeds": {"u": "5 m/s", "xi": 0.05},
    "lubricant": {"eta0": "0.01 Pa s", "alpha": "28 1/GPa", "tau0": "8 MPa"}}


def test_touching_mask_skips_the_boundary_nodes():
    film = np.ones((5, 4))
    film[0, 1] = film[2, 0] = film[2, 2] = 0.0
    mask = touching_mask(film, 0.0)
    assert mask.sum() == 1 and mask[2, 2]
    assert touching_mask(np.array([0.0, 0.0, 1.0, 0.0]), 0.0).sum() == 1   # a line contact


def test_the_rows_are_doubled_until_the_smooth_start_has_a_film():
    """On 257 x 29 (dY = 14.5 dX) the traction drive's smooth start has no film at 324
    interior nodes, all in the side lobes; on 57 rows at 74; on 113 (dY = 3.6 dX) nowhere, its
    least film some 50 nm. A smooth EHL contact has a film everywhere, and the central film
    hardly moves with the rows (it is not where the lobes are). About 15 s."""
    case = load_case(TRACTION)
    problem = case.problem()
    domain = problem.default_domain()
    contact_film = 1e-4 * problem.film_estimate()
    coarse = start_rows(problem, 257, 29, domain, max_nodes=257 * 29)   # no room to refine
    assert coarse.ny == 29 and len(coarse.tried) == 1
    lobes = touching_mask(coarse.steady.film, contact_film)
    _, y = problem.grid(257, 29, domain)
    assert lobes.sum() > 100
    assert np.all(np.abs(y[np.nonzero(lobes)[1]]) > 0.7 * problem.b)      # the side lobes
    start = start_rows(problem, 257, 29, domain)
    assert start.ny == 113
    assert [n for n, _, _ in start.tried] == [29, 57, 113]
    assert start.tried[0][1] == lobes.sum()
    assert start.tried[-1][1] == 0 and start.steady.converged
    assert start.steady.film[1:-1, 1:-1].min() > 10e-9
    assert start.steady.central_film == pytest.approx(coarse.steady.central_film, rel=0.02)


def test_a_start_without_contact_keeps_its_rows_and_is_the_runs_own():
    """The gear point contact on 65 x 33 nodes does not touch: one steady solve, the rows
    kept, and the run given that start ends to the bit as one that solved its own."""
    from asperity.ehl import solve_transient

    case = load_case({**TRACTION, "contact": {"type": "point", "rx": "19.1 mm",
                                              "ry": "151 mm", "load": "962 N"},
                      "speeds": {"u": "25 m/s", "xi": 0.25},
                      "lubricant": {"eta0": "0.005 Pa s", "alpha": "11.1 1/GPa"}})
    problem = case.problem()
    domain = problem.default_domain()
    start = start_rows(problem, 65, 33, domain)
    assert start.ny == 33 and len(start.tried) == 1 and start.tried[0][1] == 0
    runs = [solve_transient(problem, None, None, nx=65, ny=33, domain=domain,
                            counting_steps=3, warmup_steps=0, steady=steady)
            for steady in (start.steady, None)]
    assert np.array_equal(runs[0].pressure, runs[1].pressure)
    assert np.array_equal(runs[0].film, runs[1].film)


@pytest.mark.slow
def test_a_default_mesh_whose_smooth_start_touches_gets_more_rows(tmp_path):
    """The traction drive through the runner on its default mesh, smooth, 3 steps: the rows
    are doubled from 57 to 113, the report says so, and no step counts contact (before:
    contact at every step, at 146 nodes of the side lobes). About 25 s."""
    from asperity.runners import run_case

    case = load_case({**TRACTION, "time": {"warmup_steps": 0, "counting_steps": 3}})
    out = run_case(case, workdir=tmp_path)
    assert out.dataset.sizes["y"] == 113
    assert out.summary["contact_time_percent"] == 0.0
    assert not [w for w in out.warnings if "already touches" in w]
    (note,) = [n for n in out.notes if n.startswith("The smooth steady start had no film")]
    assert "513 x 57 (dy = b/14)" in note and "the run uses 513 x 113 (dy = b/28)" in note
