"""Point contacts on meshes finer than the default: grid sequencing and the load tangent.

A point contact with ``nx, ny`` given is solved on the grid sequence of its mesh
(``sequencing_levels``), and a grid with more nodes than the default mesh is steered by the
:class:`~asperity.ehl.solver.LoadTangent` of the converged grid below it instead of a
per-sweep separation shift (docs/ehl-robustness.md, "A thin film on fine meshes"). The films
are checked against the same contact on another mesh, whose discretisation error the default
mesh's own check bounds (about 2 % for the central film).
"""

import numpy as np
import pytest

from asperity.ehl import Lubricant, PointContact, solve_steady
from asperity.ehl.solver import EHLState, LoadTangent
from asperity.materials import Material

STEEL = Material(210e9, 0.29)
GLASS = Material(75e9, 0.22)


def _ball_on_glass():
    """A user's rig: 3/4 in 52100 ball on a glass disc, PAO (0.025 Pa s, 14 1/GPa, Eyring
    5 MPa), 20 N, 0.1 m/s, slide/roll 0.5: Moes M = 611, L = 2.4, central film about 32 nm
    (``H_c`` = 0.017 in Hertzian units)."""
    u, xi = 0.1, 0.5
    return PointContact(9.525e-3, 9.525e-3, 20.0, u * (1 + xi / 2), u * (1 - xi / 2),
                        STEEL, GLASS, Lubricant(0.025, 14e-9, eyring_stress=5e6))


def _seed_domain(prob):
    return (-2.5 * prob.a, 1.5 * prob.a), (-2.0 * prob.b, 2.0 * prob.b)


def test_a_thin_film_on_a_users_fine_mesh_converges_with_the_defaults():
    """433 x 145 nodes (dy = 3 dx, 3.4 times the default mesh's 513 x 41 nodes): before
    session 42 solved on that one grid with the load gain 0.05, it cycled (residual 0.13
    after 5000 sweeps, central film 43 nm); sequenced on 4 grids and steered by the tangent
    it converges (measured 1490 finest-grid sweeps) to the default mesh's film (measured
    31.98 against 31.95 nm). The tolerance is the default mesh's discretisation error."""
    prob = _ball_on_glass()
    domain = _seed_domain(prob)
    fine = solve_steady(prob, nx=433, ny=145, domain=domain)
    default = solve_steady(prob, domain=domain)
    assert fine.converged and default.converged
    assert len(fine.levels) == 4 and fine.levels[-1] == (433, 145)
    assert fine.central_film == pytest.approx(default.central_film, rel=0.02)
    assert 25e-9 < fine.central_film < 40e-9


@pytest.mark.slow  # 25 s: the failure the tangent mends
def test_the_same_mesh_on_one_grid_with_the_gain_cycles():
    prob = _ball_on_glass()
    one = solve_steady(prob, nx=433, ny=145, domain=_seed_domain(prob), levels=1,
                       max_iter=1500)
    assert not one.converged and one.residual > 1e-2


def test_the_seed_circle_on_the_seed_mesh_converges_in_hundreds_of_sweeps():
    """The circular contact of the seed's aspect-ratio study (a/b = 1, M = 174, L = 6.9) on
    the seed's 801 x 201 mesh, three times finer along x than its default 257 x 41. With the
    load gain scaled by dX / dX_default (0.016) it converged in 6271 finest-grid sweeps
    (100 s on session 42's machine; with 0.05 it cycled); with the tangent of the converged
    401 x 101 grid, measured 779 sweeps (13 s), to the film of 401 x 101 (408.2 nm, where
    0.05 converged; here 409.3 nm)."""
    from asperity.cases import load_case
    from asperity.sweep import load_study

    case = load_case(dict((cid, c) for cid, c, _ in
                          load_study("holmes-aspect-ratio-paper").cases)["0001"])
    prob = case.problem()
    nx, ny, domain = case.mesh(prob)
    assert (nx, ny) == (801, 201) and prob.default_nodes(domain) == (257, 41)
    fine = solve_steady(prob, nx=nx, ny=ny, domain=domain, levels=4, near=2)
    assert fine.converged and fine.sweeps < 2000
    assert fine.central_film == pytest.approx(408.2e-9, rel=0.01)


def test_a_point_tangent_moves_the_load_by_the_wanted_fraction():
    """:meth:`LoadTangent.correct` on a point contact: the pressure part is interpolated onto
    the finer grid and scaled to carry the relative load, so a correction by ``-e`` changes
    the load by ``-e`` times the target where no node is clipped at p = 0; the film and the
    separation move by the tangent's own ``dH`` and ``dH0``."""
    prob = _ball_on_glass()
    domain = _seed_domain(prob)
    x, y = prob.grid(33, 17, domain)
    s0, s1 = EHLState(prob, x, y, 4), EHLState(prob, x, y, 4)
    s0.hertz_start(0.02)
    s1.hertz_start(0.021)
    s1.P = s1.P * (1.0 + LoadTangent.STEP) ** (1 / 3)  # any shape: the scaling fixes the load
    tangent = LoadTangent.between(s0, s1)
    fine = EHLState(prob, *prob.grid(65, 33, domain), 4)
    fine.interpolate_from(s0)
    fine.P = fine.P + 0.5  # no node at p = 0 inside, so nothing is clipped
    fine.P[fine.edge] = 0.0
    before, h0, h = fine.P.sum() * fine.cell_area, fine.H0, fine.H.copy()
    tangent.correct(fine, 0.03)
    after = fine.P.sum() * fine.cell_area
    assert (after - before) / prob.load_integral == pytest.approx(-0.03, rel=1e-9)
    assert fine.H0 - h0 == pytest.approx(-0.03 * tangent.dH0, rel=1e-12)
    centre = np.unravel_index(np.argmin(np.abs(fine.X)[:, None] + np.abs(fine.Y)), h.shape)
    assert tangent.dH0 != 0.0 and fine.H[centre] != h[centre]


def test_a_tangent_that_blows_up_is_given_up_for_the_gain(monkeypatch):
    """The fallback of :func:`solve_steady` when the tangent-steered finest grid grows
    unstable (:data:`~asperity.ehl.solver.TANGENT_BLOWUP`; a bearing contact did, in a slow
    test): here the tangent is made to push the load the wrong way 30 times too far, so the
    finest grid's residual grows; the sequence is then solved again with the load gain and
    the result is that of the gain alone (``point_tangent=False``: the same film and sweeps),
    with both sequences' sweeps in ``total_sweeps``. A 1 m/s, 20 N steel ball with a 0.1 Pa s
    oil on 193 x 57 nodes, finer than its default mesh (145 x 41) each way."""
    prob = PointContact(10e-3, 10e-3, 20.0, 1.0, 1.0, STEEL, STEEL, Lubricant(0.1, 20e-9))
    domain = ((-3.0 * prob.a, 1.5 * prob.a), (-2.0 * prob.b, 2.0 * prob.b))
    assert prob.default_nodes(domain) == (145, 41)
    gain = solve_steady(prob, nx=193, ny=57, domain=domain, point_tangent=False)
    correct = LoadTangent.correct
    monkeypatch.setattr(LoadTangent, "correct",
                        lambda self, state, error: correct(self, state, -30.0 * error))
    steered = solve_steady(prob, nx=193, ny=57, domain=domain)
    assert gain.converged and steered.converged
    assert steered.central_film == gain.central_film and steered.sweeps == gain.sweeps
    assert steered.total_sweeps > gain.total_sweeps + 500


def test_row_doublings_keep_the_cells_and_the_node_limit():
    """doubled_rows: 41 -> 81 -> 161 while dy >= 3 dx (or the aspect asked for), none past
    the node limit, and a soft contact's within SOFT_MAX_NY rows and SOFT_CELL_ASPECT
    cells."""
    from asperity.ehl.rows import MAX_ROW_DOUBLINGS, doubled_rows
    from asperity.ehl.solver import SOFT_CELL_ASPECT, SOFT_MAX_NY

    class Contact:
        soft = False

    width, dx = 4.0, 4.0 / 40 / 20  # dy = 20 dx on 41 rows
    assert MAX_ROW_DOUBLINGS == 2
    assert doubled_rows(Contact(), 257, 41, width, dx) == [81, 161]
    assert doubled_rows(Contact(), 257, 41, width, 4.0 / 40 / 7) == [81]  # 161: dy = 1.75 dx
    assert doubled_rows(Contact(), 257, 41, width, dx, aspect=6.0) == [81]  # 161: dy = 5 dx
    assert doubled_rows(Contact(), 257, 41, width, dx, max_nodes=257 * 100) == [81]
    assert doubled_rows(Contact(), 257, 41, width, dx, max_nodes=257 * 60) == []
    soft = Contact()
    soft.soft = True
    rows = doubled_rows(soft, 257, 41, width, dx)
    assert all(r <= SOFT_MAX_NY and width / (r - 1) >= SOFT_CELL_ASPECT * dx for r in rows)
