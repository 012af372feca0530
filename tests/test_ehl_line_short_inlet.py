"""A user's cam contact (line) on a domain with a short inlet, with default settings.

The case as its user wrote it: R = 8 mm, 250 N/mm (p_h 1.06 GPa, a = 150 um), u1 = 2.5 and
u2 = 1.5 m/s, eta0 = 12 mPa s, alpha = 18 1/GPa, tau0 = 5 MPa (Moes M = 26.8, L = 9.3), on
-1.5 a..1.5 a. There the point update's load loop of the first grid sequence cycles at a
residual of 0.02-0.1 on 101-201 nodes; the fallback sequence steered by every grid's load
tangent cycled as well (0.15 on 161 nodes) until it refreshed the far field more often once
stalled (``stall_refresh`` of :func:`asperity.ehl.solver._relax`). Measured (central film,
sweeps on the finest grid / all grids): 101 nodes 142.2 nm, 1660 / 10910; 161 nodes 146.0 nm,
2165 / 16925; 201 nodes 146.9 nm, 915 / 21825. Without the refresh change none converges
(``STALL_RATIO = inf``: residual 0.03, 0.11, 0.02 after 5000 sweeps).

The short inlet starves the film: with the inlet at -2.55 a (the default domain's, Hamrock &
Dowson's fully flooded distance) the steady film on 81 nodes is 9.2 % thicker at the centre
and 7.7 % at the minimum. Line contacts had no inlet check beyond the inlet pressure (0.1 a
downstream of the boundary, here below 1 % of p_h); the report now measures it with the
inlet probe (:func:`asperity.ehl.sides.inlet_probe`) as for point contacts
(docs/ehl-robustness.md, "Line contacts on a short domain").

With ground surfaces (Ra 0.25 and 0.3 um) on its default domain the cam's transient run is
the case of the default film histogram's range (docs/ehl-transient.md, "The film
histogram's range").
"""

from pathlib import Path

import numpy as np
import pytest

from asperity.cases import load_case, parse_toml
from asperity.ehl import solve_steady
from asperity.ehl import solver as steady_solver
from asperity.ehl.formulas import moes_line
from asperity.runners import run_case

#: The cam as its user wrote it: the steady case of the corpus (81 nodes on -1.5 a..1.5 a)
CAM = (Path(__file__).parent / "corpus" / "warn-ehl-line-inlet-short-cam.toml").read_text()


@pytest.fixture(scope="module")
def cam():
    """The cam contact and its short x-domain -1.5 a..1.5 a (m)."""
    prob = load_case(parse_toml(CAM)).problem()
    return prob, ((-1.5 * prob.a, 1.5 * prob.a), (0.0, 0.0))


@pytest.fixture(scope="module")
def solutions(cam):
    prob, domain = cam
    return {nx: solve_steady(prob, nx=nx, domain=domain) for nx in (101, 161, 201)}


@pytest.mark.parametrize("nx, film", [(101, 142.2e-9), (161, 146.0e-9), (201, 146.9e-9)])
def test_short_domain_converges_with_defaults(solutions, nx, film):
    """Since session 38 the first sequence's finest grid, unconverged after its 5000 sweeps,
    is solved by Newton (:mod:`asperity.ehl.line_newton`) and converges there, to the films
    the refresh-on-stall fallback had found (the numbers of the module docstring, 0.1 %)."""
    res = solutions[nx]
    assert res.converged and abs(res.load_error) < 1e-5
    assert res.central_film == pytest.approx(film, rel=1e-3)


def test_short_domain_films_agree_across_meshes(cam, solutions):
    """161 against 201 nodes within 1 % (measured 0.6 %); Moes' Newtonian Barus film is a
    fit for another oil model: the robustness table's Roelands + Eyring rows lie at 0.7-1.05
    of the formulas, and this starved film below that of the flooded inlet (0.80 of Moes on
    the default domain, measured): tested 0.65-0.85."""
    prob, _ = cam
    hc = {nx: res.central_film for nx, res in solutions.items()}
    assert hc[161] == pytest.approx(hc[201], rel=1e-2)
    lub = prob.lubricant
    moes = moes_line(prob.load_per_length, prob.radius, prob.mean_speed, lub.viscosity,
                     lub.pressure_viscosity, prob.reduced_modulus).central
    assert 0.65 < hc[201] / moes < 0.85


def test_without_the_refresh_on_stall_the_fallback_cycles(cam, monkeypatch):
    """Negative control: a fallback that never counts as stalled keeps its refresh every 10
    sweeps and ends unconverged (measured residual 0.11 on 161 nodes), with Newton off
    (which solves the case)."""
    prob, domain = cam
    monkeypatch.setattr(steady_solver, "STALL_RATIO", np.inf)
    monkeypatch.setattr(steady_solver, "solve_line_newton", lambda state, target, **options: False)
    res = solve_steady(prob, nx=161, domain=domain)
    assert not res.converged and res.residual > 1e-3


def _run(**grid):
    case = parse_toml(CAM)
    case["grid"] = grid
    return run_case(load_case(case))


def test_a_short_inlet_of_a_line_contact_is_reported():
    """The runner's inlet probe: -1.5 a starves the film by more than 2 % and the warning
    names the inlet to use; from that inlet, on the same spacing, the probe passes and the
    film is thicker by about what the probe measured at twice the spacing (12 % on 41 nodes;
    9.2 % on 81)."""
    short = _run(nx=81, x_min=-1.5, x_max=1.5)
    inlet = [w for w in short.warnings if w.startswith("inlet:")]
    assert len(inlet) == 1 and "central film is" in inlet[0] and "41 nodes" in inlet[0]
    x_min = float(inlet[0].rsplit("use x_min <= ", 1)[1].split(" a")[0])
    assert -3.0 < x_min < -2.0
    cells = round(80 * (1.5 - x_min) / 3.0)  # the same spacing, a / 26.7
    flooded = _run(nx=cells + 1, x_min=1.5 - cells * 3.0 / 80, x_max=1.5)
    assert not [w for w in flooded.warnings if w.startswith("inlet")]
    gain = (flooded.summary["central_film_thickness_m"]
            / short.summary["central_film_thickness_m"] - 1.0)
    assert 0.05 < gain < 0.15


def test_a_stuck_first_sequence_hands_over_early(cam, monkeypatch):
    """With the transient start's 20,000 sweeps per grid the first sequence's 101-node grid
    gives up once its best residual has not fallen by 10 % in ``STUCK_SWEEPS`` (5,000)
    sweeps: 11,955 sweeps on all grids (measured; 161 nodes 18,165) instead of 26,715
    without the give-up (33,155), to the same converged film."""
    prob, domain = cam
    early = solve_steady(prob, nx=101, domain=domain, max_iter=20000)
    monkeypatch.setattr(steady_solver, "STUCK_SWEEPS", 10**9)
    late = solve_steady(prob, nx=101, domain=domain, max_iter=20000)
    assert early.converged and late.converged
    assert early.total_sweeps < 15000 < 20000 < late.total_sweeps
    assert early.central_film == pytest.approx(late.central_film, rel=1e-3)


def test_default_film_histogram_spans_a_rough_film():
    """Ground surfaces (Ra 0.25 and 0.3 um) on the cam's 150 nm film: with bins up to twice the
    estimated central film 60 % of the node-steps fell in the overflow bin (measured on
    161 nodes); the default range now reaches the film plus 4 RMS of the summed heights
    (``HISTOGRAM_RQ``; measured 2.15 um and 0.02 % overflow on 161 nodes). Without
    flattening the film is the smooth film minus the summed heights, so at most a few per
    mille of a Gaussian's node-steps lie beyond 4 RMS: tested below 1 %."""
    data = {**parse_toml(CAM), "analysis": "ehl-transient", "grid": {"nx": 81},
            "time": {"counting_steps": 60},
            "surface1": {"kind": "ground", "ra": "0.25 um", "seed": 3},
            "surface2": {"kind": "ground", "ra": "0.3 um", "seed": 4}}
    case = load_case(data)
    ds = run_case(case).dataset
    counts = ds["film_counts"].values
    centres = ds["film_bin"].values
    assert centres[-1] > 4.0 * case.problem().film_estimate()  # summed Rq ~ 0.49 um, 0.19 um
    assert counts[-1] / counts.sum() < 0.01
