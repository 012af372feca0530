"""Frictional-contact figures render from solver results (headless)."""

import numpy as np
import pytest

from asperity.contact import hertz_point, solve_tangential
from asperity.contact.load_path import proportional_path, tangential_load_path
from asperity.materials import Material
from asperity.plotting import tangential as tplot

STEEL = Material(206e9, 0.3, "steel")


def test_figures_render(tmp_path):
    hz = hertz_point(1000.0, 0.01, 0.01, STEEL, STEEL)
    x = np.linspace(-1.1 * hz.a, 1.1 * hz.a, 24)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = hz.pressure(X, Y)
    m = 0.6 * 3 * np.pi * 0.3 * 1000.0 * hz.a / 16
    path = tangential_load_path(p, x, x, 0.3, STEEL, STEEL,
                                proportional_path((50.0, 0.0), m, steps=3))
    figs = [tplot.traction_map(path.final, x, x), tplot.slip_progression(path, x, x),
            tplot.compliance_curves(path), tplot.centre_of_rotation_curve(path)]
    for k, fig in enumerate(figs):
        out = tmp_path / f"fig{k}.png"
        fig.savefig(out)
        assert out.stat().st_size > 5000


def _ball_path(loads, n=24, regions=1):
    """The 10 mm steel ball at 200 N (mu P = 60 N) on n x n cells, or two such balls side by
    side (two contact regions)."""
    steel = Material(210e9, 0.3)
    hz = hertz_point(200.0, 5e-3, 5e-3, steel, steel)
    x = np.linspace(-1.05 * hz.a, 1.05 * hz.a, n)
    if regions == 2:
        x = np.linspace(-3.2 * hz.a, 3.2 * hz.a, 3 * n)
    y = np.linspace(-1.05 * hz.a, 1.05 * hz.a, n)
    X, Y = np.meshgrid(x, y, indexing="ij")
    p = hz.pressure(X, Y) if regions == 1 else (hz.pressure(X - 2 * hz.a, Y)
                                                + 0.5 * hz.pressure(X + 2 * hz.a, Y))
    return tangential_load_path(p, x, y, 0.3, steel, steel, loads), x, y


def test_slip_progression_draws_the_first_loading_coloured_by_q_over_mu_p():
    """A 3-step cycle has 15 steps: 15 dashed borders drawn over each other, coloured by
    "load step". Now the first loading only (3 borders), coloured by Q / (mu P)."""
    path, x, y = _ball_path(proportional_path((45.0, 0.0), steps=3, cycle=True))
    assert len(path.loads) == 15
    fig = tplot.slip_progression(path, x, y, load_fraction=path.loads[:, 0] / 60.0,
                                 fraction_label="Q / (mu P)")
    ax, bar = fig.axes
    assert len(ax.collections) == 1 + 3  # the contact outline and three stick borders
    assert bar.get_ylabel() == "Q / (mu P)" and bar.get_ylim()[1] == pytest.approx(1.0)
    # a long first loading: at most MAX_BORDERS borders
    long_path, x, y = _ball_path(proportional_path((45.0, 0.0), steps=14), n=16)
    fig = tplot.slip_progression(long_path, x, y)
    assert len(fig.axes[0].collections) == 1 + tplot.MAX_BORDERS


def test_load_sharing_keeps_the_sign_of_a_reversed_force_and_drops_round_off():
    """Two regions through a cycle to -45 N: the force along the load direction, signed
    (hypot folded -45 N onto +45 N); one region under a force alone: its line-of-action
    offset, 1e-13 mm of round-off autoscaled as a signal, is 0."""
    path, _, _ = _ball_path(proportional_path((45.0, 0.0), steps=2, cycle=True), n=16,
                            regions=2)
    left, right = tplot.load_sharing(path).axes[:2]
    applied, carried = left.lines[0].get_data()
    assert applied.min() == pytest.approx(-45.0) and applied.max() == pytest.approx(45.0)
    total = sum(line.get_ydata() for line in left.lines)
    assert np.allclose(total, applied, rtol=1e-6, atol=1e-9)  # the regions carry it all
    single, _, _ = _ball_path(proportional_path((30.0, 0.0), steps=3))
    assert np.all(tplot.load_sharing(single).axes[1].lines[0].get_ydata() == 0.0)


def test_traction_map_says_gross_slip():
    path, x, y = _ball_path(proportional_path((90.0, 0.0), steps=1))
    assert path.final.gross_slip
    ax = tplot.traction_map(path.final, x, y, "ball").axes[0]
    assert ax.get_title() == "ball (gross slip)"
    assert any(t.get_text().startswith("gross slip") and "1.5 x capacity" in t.get_text()
               for t in ax.texts)


def test_compliance_overlays_mindlin_deresiewicz_on_a_cycle():
    """The runner's closed form of a fretting cycle to +-0.9 mu N: loading delta(Q), then
    Masing's branches (Mindlin & Deresiewicz 1953): at Q = 0 on unloading
    delta(Q*) - 2 delta(Q*/2), the loop closing at Q*."""
    from asperity.cases import load_case
    from asperity.runners import run_case

    data = {"analysis": "tangential", "mu": 0.3,
            "body1": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
            "body2": {"youngs_modulus": "210 GPa", "poisson_ratio": 0.3},
            "pressure": {"source": "hertz", "load": "200 N", "rx": "5 mm"},
            "loading": {"force": "54 N"}, "grid": {"nx": 24, "ny": 24},
            "load_path": {"steps": 2, "history": "cycle"}}
    out = run_case(load_case(data))
    ax = out.figures["compliance"][0]().axes[0]
    (closed,) = [ln for ln in ax.lines if "Mindlin-Deresiewicz" in ln.get_label()]
    shift, force = closed.get_data()
    g, nu, a = 210e9 / 2.6, 0.3, (3 * 200 * 5e-3 / (4 * 210e9 / (2 * 0.91))) ** (1 / 3)

    def delta(q):  # Cattaneo-Mindlin, relative shift of two equal bodies, um
        return 1e6 * 2 * 3 * 0.3 * 200 * (2 - nu) / (16 * g * a) * (
            1 - (1 - q / 60.0) ** (2 / 3))

    top = int(np.argmax(force))
    assert force[top] == pytest.approx(54.0) and shift[top] == pytest.approx(delta(54.0))
    zero = top + int(np.argmin(abs(force[top:])))  # Q = 0 on unloading
    assert force[zero] == pytest.approx(0.0, abs=1e-12)
    assert shift[zero] == pytest.approx(delta(54.0) - 2 * delta(27.0), rel=1e-9)
    assert shift[-1] == pytest.approx(delta(54.0), rel=1e-9) and force[-1] == pytest.approx(54)


def test_a_centre_of_rotation_off_the_map_is_named_without_round_off():
    """40 N along x with 20 N mm on a steel ellipse (Rx 20 mm, Ry 5 mm, 500 N, mu = 0.3): the
    centre of rotation lies on the y axis beyond the map, and the corner text quoted its x as
    round-off (-1.9e-14 mm); a zero coordinate reads 0."""
    steel = Material(210e9, 0.3)
    hz = hertz_point(500.0, 20e-3, 5e-3, steel, steel)
    x = np.linspace(-1.05 * hz.a, 1.05 * hz.a, 32)
    y = np.linspace(-1.05 * hz.b, 1.05 * hz.b, 16)
    X, Y = np.meshgrid(x, y, indexing="ij")
    p = hz.pressure(X, Y)
    res = solve_tangential(p * 500.0 / (p.sum() * (x[1] - x[0]) * (y[1] - y[0])), x, y, 0.3,
                           steel, steel, force=(40.0, 0.0), moment=0.02)
    assert abs(res.centre_of_rotation[0]) < 1e-12 < 1.05 * hz.b < res.centre_of_rotation[1]
    ax = tplot.traction_map(res, x, y).axes[0]
    (text,) = [t.get_text() for t in ax.texts if "off the map" in t.get_text()]
    cy = res.centre_of_rotation[1] * 1e3
    assert text == f"centre of rotation off the map: (0, {cy:.3g}) mm"


def test_the_shift_of_a_twisted_path_names_its_point():
    """Force and moment together: the rigid shift is that of the moment's reference point
    (a user's two pads twisted by 0.4 N m with 8 N along +y moved it along -y), and the
    axis says so; a force alone keeps the plain label."""
    m = 0.3 * 3 * np.pi * 0.3 * 200.0 * 1e-4 / 16
    twisted, x, y = _ball_path(proportional_path((20.0, 0.0), m, steps=2))
    ax = tplot.compliance_curves(twisted).axes[0]
    assert ax.get_xlabel() == ("rigid shift of the moment's reference point along the largest "
                               "force (µm)")
    alone, x, y = _ball_path(proportional_path((20.0, 0.0), steps=2))
    assert tplot.compliance_curves(alone).axes[0].get_xlabel() == (
        "rigid shift along the largest force (µm)")


def test_a_constant_line_of_action_is_drawn_without_round_off():
    """Two balls (two regions) under 20 N with M = 20 N x 0.1 mm through a cycle: the resultant's
    line of action stays M/F = 0.1 mm from the reference point at every step; a user's twisted
    pads drew their constant 50 mm as +-4e-10 mm about an offset text "5e1". The offsets are
    now one value and the axis has no offset text."""
    path, _, _ = _ball_path(proportional_path((20.0, 0.0), 20.0 * 1e-4, steps=2, cycle=True),
                            n=16, regions=2)
    fig = tplot.load_sharing(path)
    ax = fig.axes[1]
    offsets = ax.lines[0].get_ydata()
    assert np.all(offsets == offsets[0]) and offsets[0] == pytest.approx(0.1, rel=1e-6)
    fig.canvas.draw()
    assert ax.yaxis.get_offset_text().get_text() == ""


def test_a_traction_map_of_single_cell_spots_colours_every_contact_cell():
    """Spots of one cell each (a rough contact's smallest, 104 spots of a user's rough ball
    mostly of a few cells) were blank in the traction map: filled contours need four corners
    in contact. Such a map now colours each cell; a Hertz contact keeps its contours."""
    import matplotlib.collections as mcoll

    x = np.linspace(-0.5e-3, 0.5e-3, 20)
    X, Y = np.meshgrid(x, x, indexing="ij")
    p = np.zeros_like(X)
    p[2::4, 2::4] = 1e9  # isolated one-cell spots
    res = solve_tangential(p, x, x, 0.3, STEEL, STEEL, force=(0.2 * 0.3 * p.sum() * (
        x[1] - x[0]) ** 2, 0.0))
    fig = tplot.traction_map(res, x, x)
    (mesh,) = [c for c in fig.axes[0].collections if isinstance(c, mcoll.QuadMesh)]
    coloured = ~np.ma.getmaskarray(mesh.get_array()).reshape(20, 20).T
    assert np.array_equal(coloured, p > 0)
    hz = hertz_point(200.0, 5e-3, 5e-3, STEEL, STEEL)
    x = np.linspace(-1.05 * hz.a, 1.05 * hz.a, 24)
    X, Y = np.meshgrid(x, x, indexing="ij")
    res = solve_tangential(hz.pressure(X, Y), x, x, 0.3, STEEL, STEEL, force=(20.0, 0.0))
    fig = tplot.traction_map(res, x, x)
    assert not [c for c in fig.axes[0].collections if isinstance(c, mcoll.QuadMesh)]
