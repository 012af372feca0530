"""Seed Fig. 10: the rough line contact follows the rough point contact on the centre line.

Holmes, Evans & Snidle (J. Tribol. 127 (2005) 61), "Behavior in the Center of the Contact":
with profile A on both surfaces at xi = 0.25, "the film thickness behavior is identical
between the two methods and the minor differences in pressure are no greater than inevitably
exist in the comparison of these equivalent smooth surface solutions". Both cases are the
shipped examples holmes-rough-AA (point, Table 1 gear case) and holmes-rough-AA-line (line,
Table 1 line column: 527 kN/m, eta0 = 4.8 mPa s), run on the same x grid in metres (the point
contact's reduced domain -2a..1.25a, 131 nodes), the same timestep dx/(2 u_max) and the same
surfaces.

Measured on the default run (131 x 29 / 131 nodes, 20 counting steps after the 335-step
warm-up, every counting step compared; the line contact relaxed by the row solve, its
default; docs/ehl-transient.md): film difference over |x| <= a RMS 0.027-0.030 and max
0.072-0.079 of the smooth central film, at most 2.3 % of the RMS change of the film by the
roughness (1.3-1.6 central films); pressure RMS difference 0.047-0.056 p_h against 0.033 p_h
between the smooth solutions. Over the examples' 200 counting steps (slow test, 10
snapshots): film RMS 0.023-0.044, max 0.056-0.11, at most 3.6 % of the roughness' film
change; pressure RMS 0.041-0.056 p_h. Smooth films differ by 0.0020 (RMS) central films.
Shifting the line contact's snapshots by one step (surfaces moved by half a mesh spacing)
raises the film RMS difference to 0.28-0.36.
"""

import dataclasses

import numpy as np
import pytest

from asperity.cases import load_case
from asperity.ehl import compare_centre_lines, solve_steady, solve_transient
from asperity.ehl.transient import default_warmup_steps
from asperity.errors import InputError
from asperity.examples import example_text
from asperity.plotting.ehl_comparison import plot_line_vs_point
from asperity.plotting.style import plt

NX = 131
# the seed's mesh and domain (holmes-rough-CC-paper): 801 x 201 on -2.5a..1.5a, -2b..2b
SEED_NX, SEED_NY = 801, 201
SEED_DOMAIN = ((-2.5, 1.5), (-2.0, 2.0))
# The line contact's smooth steady start at 801 nodes (a/200) converges with the defaults
# (grid sequencing from 101 nodes, load gain scaled with the mesh: docs/ehl-robustness.md,
# tests/test_ehl_line_steady.py); before, one grid with gain 0.01 never converged there.


def _fig10_setup(counting_steps, snapshots, nx=NX, ny=None, domain=None, lowpass=True,
                 line_steady=None):
    """Inputs of both AA runs on the point contact's grid in m.

    ``ny`` and ``domain`` (in Hertz semi-axes, ((x0, x1), (y0, y1))) default to the
    holmes-rough-AA example's; ``lowpass=False`` keeps the profiles' shortest wavelengths (as
    the paper-mesh example does); ``line_steady``: extra options of the line contact's smooth
    steady start (:func:`solve_steady` keywords). Returns a dict for :func:`_run_point` /
    :func:`_run_line`.
    """
    point_case = load_case(example_text("holmes-rough-AA"))
    line_case = load_case(example_text("holmes-rough-AA-line"))
    point, line = point_case.problem(), line_case.problem()
    ny = point_case.grid.ny if ny is None else ny
    if domain is None:
        domain = point_case.grid.domain(point)
    else:
        (x0, x1), (y0, y1) = domain
        domain = ((x0 * point.a, x1 * point.a), (y0 * point.b, y1 * point.b))
    line_domain = (domain[0], (0.0, 0.0))
    x, y = point.grid(nx, ny, domain)
    dx = x[1] - x[0]
    dt = 0.5 * dx / max(point.u1, point.u2)
    warmup = default_warmup_steps(x, [point.u1, point.u2], dt)
    total = warmup + counting_steps
    snaps = np.unique(np.linspace(warmup + 1, total, snapshots).round().astype(int))
    # as the runner builds them: long enough to feed the run, sampled finer than the mesh
    length = max(5e-3, point.u1 * dt * total + (x[-1] - x[0]) + 20 * dx)
    spacing = min(0.5e-6, dx / 4)
    specs = [point_case.surface1, point_case.surface2]
    if not lowpass:
        specs = [spec.model_copy(update={"lowpass": 0.0}) for spec in specs]
    s1, s2 = (spec.build(length, spacing, y, dx) for spec in specs)
    common = dict(dt=dt, counting_steps=counting_steps, warmup_steps=warmup,
                  snapshot_steps=snaps)
    return dict(point=point, line=line, nx=nx, ny=ny, domain=domain, line_domain=line_domain,
                surfaces=(s1, s2), common=common, line_sweeps=line_case.solver.max_sweeps,
                line_steady=dict(line_steady or {}))


def _run_point(s, callback=None):
    """Smooth steady start and transient run of the point contact: (steady, run)."""
    steady = solve_steady(s["point"], nx=s["nx"], ny=s["ny"], domain=s["domain"])
    run = solve_transient(s["point"], *s["surfaces"], nx=s["nx"], ny=s["ny"],
                          domain=s["domain"], steady=steady, callback=callback, **s["common"])
    return steady, run


def _run_line(s, callback=None):
    """Smooth steady start and transient run of the line contact: (steady, run)."""
    steady = solve_steady(s["line"], nx=s["nx"], domain=s["line_domain"], max_iter=40000,
                          **s["line_steady"])
    run = solve_transient(s["line"], *s["surfaces"], nx=s["nx"], domain=s["line_domain"],
                          steady=steady, max_iter=s["line_sweeps"], callback=callback,
                          **s["common"])
    return steady, run


def _fig10(counting_steps, snapshots, nx=NX, ny=None, domain=None, lowpass=True,
           line_steady=None):
    """Run both AA examples on the point contact's grid in m; return the comparison."""
    s = _fig10_setup(counting_steps, snapshots, nx, ny, domain, lowpass, line_steady)
    point_steady, point_run = _run_point(s)
    line_steady, line_run = _run_line(s)
    return compare_centre_lines(point_run, line_run, s["point"], s["line"], point_steady,
                                line_steady)


@pytest.fixture(scope="module")
def fig10():
    """20 counting steps, every one a snapshot (about 35 s on 2 cores)."""
    return _fig10(counting_steps=20, snapshots=20)


def _check_seed_statement(c, film_rms=0.06, smooth_ratio=30.0):
    assert c.converged
    # the smooth solutions are equivalent: films within 1 %, pressures within 5 % p_h
    # (measured 0.15-0.20 % / 3.1-3.3 %: p_h of the line contact is 4.6 % lower)
    assert c.smooth_film_rms_difference < 0.01
    assert c.smooth_pressure_rms_difference < 0.05
    # the rough films are "identical" (bounds ~1.4-2 times the worst of the 20-step default
    # and the 200-step slow run): RMS difference < film_rms of the smooth central film
    # (measured <= 4.4 % on the reduced mesh), max < 15 % (<= 11 %), and < 6 % of how far the
    # roughness moves the film (<= 3.6 %); at most smooth_ratio times the smooth film
    # difference (<= 21)
    assert np.all(c.film_rms_difference < film_rms)
    assert np.all(c.film_max_difference < 0.15)
    assert np.all(c.film_rms_difference < 0.06 * c.film_rms_deviation)
    assert np.all(c.film_rms_difference < smooth_ratio * c.smooth_film_rms_difference)
    # pressure differences of the order of the smooth ones (measured <= 2.15 times)
    assert np.all(c.pressure_rms_difference < 2.5 * c.smooth_pressure_rms_difference)


def test_line_contact_follows_point_contact_on_centre_line(fig10):
    """The seed's Fig. 10 statement, at every step of a short counting period."""
    c = fig10
    assert c.steps.size == 20 and c.x.size == NX
    assert c.a == pytest.approx(0.3364e-3, rel=1e-3)
    _check_seed_statement(c)


def test_one_step_shift_breaks_the_agreement(fig10):
    """Negative control: the surfaces half a mesh spacing apart (the line contact one step
    behind) give film differences above the bound of the statement (measured 0.36 h_c)."""
    c = fig10
    inside = np.abs(c.x) <= c.a
    dh = (c.line_film[:-1] - c.point_film[1:])[:, inside]
    rms = np.sqrt(np.mean(dh**2, axis=1)) / c.central_film
    assert np.all(rms > 0.2)


def test_plot_line_vs_point(fig10, tmp_path):
    fig = plot_line_vs_point(fig10, index=-1)
    ax, ax2 = fig.axes
    assert [line.get_linestyle() for line in ax.get_lines()] == ["-", ":"]
    assert len(ax2.get_lines()) == 4  # two films, two surfaces
    np.testing.assert_array_equal(ax.get_lines()[1].get_ydata(), fig10.line_pressure[-1] / 1e9)
    fig.savefig(tmp_path / "fig10.png")
    plt.close(fig)


@pytest.mark.slow
def test_line_contact_follows_point_contact_over_counting_period():
    """The same statement at 10 steps spread over the examples' 200 counting steps."""
    c = _fig10(counting_steps=200, snapshots=10)
    assert c.steps.size == 10
    _check_seed_statement(c)


@pytest.mark.slow
def test_line_contact_follows_point_contact_on_seed_mesh():
    """The statement on the seed's mesh: 801 x 201 / 801 nodes on -2.5a..1.5a (-2b..2b), dx =
    a/200, profiles not low-passed (as holmes-rough-CC-paper), the 2058-step warm-up, then 10
    counting steps with 5 snapshots (32 min for the point run, under a minute for the line
    run, on 2 cores shared with other jobs; docs/ehl-transient.md).

    Measured with the line relaxed by the row solve (session 29): film difference RMS
    0.055-0.056 and max 0.118 of the smooth central film (481.7 nm), 3.3-3.4 % of the RMS
    change of the film by the roughness (1.64-1.66 h_c), 36-37 times the smooth film
    difference (RMS 0.0015, max 0.0072); pressure RMS difference 0.063-0.067 p_h, 2.0-2.1
    times the smooth 0.031 p_h. The line steps relaxed to a tolerance of 1e-6 give the same
    (film RMS 0.055-0.057, within 0.002 h_c of the default), so this is the converged line
    contact's difference, not the relaxation's. It is larger than on the reduced mesh in h_c
    (RMS 0.023-0.044) and against the smooth difference, which the converged smooth line
    start (482.2 nm, grid sequencing; 482.6 nm and 0.0023 before) made smaller; against the
    roughness' film change it is the same. Hence the looser bounds here: RMS < 0.08 h_c and 50 times
    the smooth difference (margins 1.4 and 1.3); the others are the reduced mesh's. An
    earlier line run relaxed by the point update gave 0.043 h_c here; that update stops
    0.095-0.103 h_c (RMS) from the line's fixed point on this mesh.
    """
    c = _fig10(10, 5, SEED_NX, SEED_NY, SEED_DOMAIN, lowpass=False)
    assert c.steps.tolist() == [2059, 2061, 2064, 2066, 2068] and c.x.size == SEED_NX
    assert c.x[1] - c.x[0] == pytest.approx(c.a / 200, rel=1e-6)
    _check_seed_statement(c, film_rms=0.08, smooth_ratio=50.0)


# --- input errors, on small smooth runs -------------------------------------------------------


@pytest.fixture(scope="module")
def small():
    point = load_case(example_text("holmes-rough-AA")).problem()
    line = load_case(example_text("holmes-rough-AA-line")).problem()
    domain = ((-2.0 * point.a, 1.25 * point.a), (-1.4 * point.b, 1.4 * point.b))
    line_domain = (domain[0], (0.0, 0.0))
    point_steady = solve_steady(point, nx=33, ny=17, domain=domain, levels=1)
    line_steady = solve_steady(line, nx=33, domain=line_domain, max_iter=40000)
    point_run = solve_transient(point, nx=33, ny=17, domain=domain, steady=point_steady,
                                counting_steps=2)
    line_run = solve_transient(line, nx=33, domain=line_domain, steady=line_steady,
                               counting_steps=2)
    return dict(point=point, line=line, domain=line_domain, point_run=point_run,
                line_run=line_run, point_steady=point_steady, line_steady=line_steady)


def _field(exc):
    return exc.value.field


def test_small_smooth_runs_compare(small):
    """Two smooth runs: the transient differences are the smooth ones."""
    s = small
    c = compare_centre_lines(s["point_run"], s["line_run"], s["point"], s["line"],
                             s["point_steady"], s["line_steady"])
    assert c.steps.tolist() == [2]
    assert c.film_rms_difference[0] == pytest.approx(c.smooth_film_rms_difference, rel=0.05)
    assert c.film_rms_deviation[0] < 1e-2
    bare = compare_centre_lines(s["point_run"], s["line_run"], s["point"], s["line"])
    assert np.isnan(bare.smooth_film_rms_difference) and np.isnan(bare.film_rms_deviation[0])
    assert bare.film_rms_difference[0] == c.film_rms_difference[0]


def test_wrong_types_and_swapped_runs(small):
    s = small
    args = (s["point_run"], s["line_run"], s["point"], s["line"])
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["point_steady"], *args[1:])
    assert _field(exc) == "point_result"
    with pytest.raises(InputError) as exc:
        compare_centre_lines(*args[:2], s["line"], s["line"])
    assert _field(exc) == "point_problem"
    with pytest.raises(InputError) as exc:
        compare_centre_lines(*args[:3], s["point"])
    assert _field(exc) == "line_problem"
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["line_run"], s["point_run"], s["point"], s["line"])
    assert _field(exc) == "point_result"


def test_grid_timestep_and_speeds_must_match(small):
    s = small
    (x0, x1), ys = s["domain"]
    shift = 0.5 * (x1 - x0) / 32
    shifted = solve_transient(s["line"], nx=33, domain=((x0 + shift, x1 + shift), ys),
                              counting_steps=2)
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["point_run"], shifted, s["point"], s["line"])
    assert _field(exc) == "x"
    other_dt = dataclasses.replace(s["line_run"], dt=1.01 * s["line_run"].dt)
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["point_run"], other_dt, s["point"], s["line"])
    assert _field(exc) == "dt"
    xi = 0.5
    faster = dataclasses.replace(s["line"], u1=25.0 * (1 + xi / 2), u2=25.0 * (1 - xi / 2))
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["point_run"], s["line_run"], s["point"], faster)
    assert _field(exc) == "u1, u2"


def test_snapshots_and_surfaces_must_match(small):
    s = small
    early = dataclasses.replace(s["line_run"], snapshot_steps=np.array([1]))
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["point_run"], early, s["point"], s["line"])
    assert _field(exc) == "snapshot_steps"
    unfinished = dataclasses.replace(s["line_run"], steps_done=1)
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["point_run"], unfinished, s["point"], s["line"])
    assert _field(exc) == "snapshot_steps"
    bumped = s["line_run"].centre_surface1 + 1e-7
    rough = dataclasses.replace(s["line_run"], centre_surface1=bumped)
    with pytest.raises(InputError) as exc:
        compare_centre_lines(s["point_run"], rough, s["point"], s["line"])
    assert _field(exc) == "centre_surface1"


def test_steady_solutions_must_be_both_and_on_the_grid(small):
    s = small
    args = (s["point_run"], s["line_run"], s["point"], s["line"])
    with pytest.raises(InputError) as exc:
        compare_centre_lines(*args, point_steady=s["point_steady"])
    assert _field(exc) == "point_steady, line_steady"
    with pytest.raises(InputError) as exc:
        compare_centre_lines(*args, s["line_steady"], s["line_steady"])
    assert _field(exc) == "point_steady"
    coarse = solve_steady(s["line"], nx=17, domain=s["domain"], max_iter=40000)
    with pytest.raises(InputError) as exc:
        compare_centre_lines(*args, s["point_steady"], coarse)
    assert _field(exc) == "line_steady"
    with pytest.raises(InputError) as exc:
        compare_centre_lines(*args, s["point_steady"], s["point_run"])
    assert _field(exc) == "line_steady"
