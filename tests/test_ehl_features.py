"""A single dent or groove through a circular EHL contact: where its film disturbance travels.

Literature (docs/ehl-robustness.md, "Single features"): in pure rolling a dent is carried
through the contact with its surface, locally deformed (partly flattened) but in place, so
the film change sits on the dent and moves at the rolling speed (Venner & Lubrecht 1994; Ai &
Cheng 1994). With sliding, the dent still moves with its own surface, but the film change it
creates, generated as it passes the inlet, travels with the lubricant at the mean entrainment
speed, so on the slower surface it runs ahead of the dent (Venner & Lubrecht 1994, line
contact; Kaneta et al. 1993 and Ai & Cheng 1994 in optical and numerical point contacts).

The argument: where the viscosity is high the Poiseuille flow vanishes and the Reynolds
equation reduces to transport, ``d(rho h)/dt + u d(rho h)/dx = 0``: the film pattern formed
in the inlet is carried at the mean speed ``u``, whatever the surfaces do.

A transverse groove (a straight dent across the rolling direction, the line-contact case of
Venner & Lubrecht 1994) does the same on the centre line. Checked on a coarse mesh (81 x 17
nodes, dx = a/16), along the centre line within 0.5 a of the centre: the speed of the largest
film increase (the feature's mark in the film) against the feature's speed ``u1`` and the mean
speed ``u``, and its position against the feature's.
"""

import numpy as np
import pytest
import tomllib

from asperity.cases import load_case
from asperity.ehl import Lubricant, PointContact, solve_steady
from asperity.ehl.transient import solve_transient
from asperity.errors import InputError
from asperity.examples import example_text
from asperity.materials import Material
from asperity.surfaces import Profile, Topography
from asperity.surfaces.features import feature_shape, feature_surface

STEEL = Material(210e9, 0.3)


def _ball(xi):
    """12.5 mm steel ball on a steel disc, 15 N, 0.25 Pa s oil at 0.1 m/s (M = 49, L = 9.4),
    Barus viscosity, incompressible: in the Hertz zone the Poiseuille flow vanishes, the
    premise of the transport argument (with Roelands' lower viscosity at pressure the
    disturbance ran at 0.85 u instead)."""
    u = 0.1
    return PointContact(0.0125, 0.0125, 15.0, u * (1 + xi / 2), u * (1 - xi / 2), STEEL, STEEL,
                        Lubricant(0.25, 2e-8, viscosity_model="barus", compressible=False))


def _run(xi, kind="dent", nx=81, ny=17, contact=_ball):
    """The dent or groove (depth hc/2, radius or half-width 0.3 a) on surface 1 across the
    whole domain."""
    prob = contact(xi)
    a = prob.a
    domain = prob.default_domain()
    x, y = prob.grid(nx, ny, domain)
    dx = x[1] - x[0]
    dt = 0.5 * dx / max(prob.u1, prob.u2)
    width = 0.3 * a
    steps = int(np.ceil((x[-1] - x[0] + 2 * width) / (prob.u1 * dt)))
    depth = 0.5 * prob.film_estimate()
    length = prob.u1 * dt * steps + 4 * width
    spacing = dx / 4
    end = (np.ceil(length / spacing) - 0.5) * spacing
    dent = feature_surface(kind, length, spacing, amplitude=depth, half_width=width,
                           position=end - width, y=y)
    steady = solve_steady(prob, nx=nx, ny=ny, domain=domain)
    res = solve_transient(prob, dent, None, nx=nx, ny=ny, domain=domain, warmup_steps=0,
                          counting_steps=steps, steady=steady,
                          snapshot_steps=np.arange(1, steps + 1))
    t = res.snapshot_steps * dt
    centre = x[0] + prob.u1 * t - width       # the dent's centre: at x0 - width at t = 0
    return prob, res, steady, t, centre, depth


@pytest.fixture(scope="module", params=[("dent", 0.0), ("dent", -0.5), ("groove", 0.0),
                                        ("groove", -0.5), ("groove", 2.5)],
                ids=["dent rolling", "dent sliding xi=-0.5", "groove rolling",
                     "groove sliding xi=-0.5", "groove sliding xi=2.5"])
def dent_run(request):
    kind, xi = request.param
    return kind, xi, _run(xi, kind)


def _disturbance(prob, res, steady, depth):
    """Position (m) and size of the largest film increase on y = 0 within 0.7 a of the centre
    at each snapshot; the position is NaN unless it lies within 0.5 a, where the pressure is
    high enough for the flow to be pure Couette, and the increase exceeds a tenth of the dent
    depth."""
    _, _, h_steady = steady.centre_line()
    dh = res.centre_film - h_steady
    inside = np.abs(res.x) < 0.7 * prob.a
    dh_in = np.where(inside, dh, -np.inf)
    i = np.argmax(dh_in, axis=1)
    peak = dh_in[np.arange(i.size), i]
    pos = np.where((peak > 0.1 * depth) & (np.abs(res.x[i]) < 0.5 * prob.a), res.x[i], np.nan)
    return pos, peak


def test_dent_runs_with_default_settings(dent_run):
    kind, xi, (prob, res, steady, t, centre, depth) = dent_run
    assert steady.converged and res.converged
    assert np.all(res.step_converged)
    print(f"\n{kind} xi = {xi}: {res.steps} steps, {res.sweeps.mean():.1f} sweeps per step "
          f"(max {res.sweeps.max()})")


def test_film_disturbance_speed(dent_run):
    """Rolling: the film increase moves at u (10 %) and sits on the dent (0.1 a on average).
    Sliding at xi = -0.5 (dent on the slower surface, u1 = 0.75 u): it moves at the mean
    speed u (15 %), not with the dent (u/u1 = 1.33), and runs ahead of it. At xi = 2.5 the
    smooth surface 2 runs backwards (u2 = -0.25 u) and the groove's surface at u1 = 2.25 u:
    the film change still moves at the mean speed u, not at u1 nor at u2, and falls behind
    the groove (the transport argument of the module docstring holds for any u2)."""
    kind, xi, (prob, res, steady, t, centre, depth) = dent_run
    pos, peak = _disturbance(prob, res, steady, depth)
    ok = np.isfinite(pos)
    assert ok.sum() >= 5
    speed = np.polyfit(t[ok], pos[ok], 1)[0]
    print(f"\n{kind} xi = {xi}: disturbance speed {speed / prob.mean_speed:.3f} u, {kind} "
          f"{prob.u1 / prob.mean_speed:.3f} u; peak {peak[ok].max() / depth:.2f} x its depth")
    if xi == 0.0:
        assert speed == pytest.approx(prob.mean_speed, rel=0.10)
        assert np.mean(np.abs(pos[ok] - centre[ok])) < 0.1 * prob.a
    else:
        assert speed == pytest.approx(prob.mean_speed, rel=0.15)
        late = ok & (t > np.median(t[ok]))
        if prob.u1 < prob.mean_speed:
            assert speed > 1.2 * prob.u1
            assert np.all(pos[late] > centre[late])
        else:
            assert speed < prob.u1 / 1.2
            assert np.all(pos[late] < centre[late])


def test_dent_partly_flattened_in_rolling(dent_run):
    """In the Hertz zone the film over the dent deepens by less than the dent's depth (the
    pressure drop over the dent lifts its floor) but by a sizeable part of it."""
    kind, xi, (prob, res, steady, t, centre, depth) = dent_run
    if xi != 0.0:
        pytest.skip("rolling only")
    pos, peak = _disturbance(prob, res, steady, depth)
    in_hertz = np.isfinite(pos)
    assert in_hertz.any()
    assert np.all((0.3 * depth < peak[in_hertz]) & (peak[in_hertz] < 0.95 * depth))


def test_feature_shapes():
    """Cap of peak 1, zero at and beyond the half-width; dent and groove below, bump and ridge
    above, ridge and groove along x only."""
    np.testing.assert_allclose(feature_shape([0.0, 0.5, 1.0, 2.0], 1.0), [1.0, 0.5, 0.0, 0.0],
                               atol=1e-15)
    y = np.linspace(-1e-4, 1e-4, 21)
    dent = feature_surface("dent", 1e-3, 1e-5, amplitude=1e-7, half_width=5e-5,
                           position=5e-4, y=y)
    bump = feature_surface("bump", 1e-3, 1e-5, amplitude=1e-7, half_width=5e-5,
                           position=5e-4, y=y)
    ridge = feature_surface("ridge", 1e-3, 1e-5, amplitude=1e-7, half_width=5e-5,
                            position=5e-4)
    groove = feature_surface("groove", 1e-3, 1e-5, amplitude=1e-7, half_width=5e-5,
                             position=5e-4)
    assert isinstance(dent, Topography) and isinstance(ridge, Profile)
    assert isinstance(groove, Profile)
    np.testing.assert_array_equal(groove.z, -ridge.z)
    assert dent.z.min() == pytest.approx(-1e-7, rel=0.05) and dent.z.max() == 0.0
    np.testing.assert_allclose(bump.z, -dent.z)
    np.testing.assert_allclose(ridge.z, bump.z[:, 10])  # y = 0 row through the centre
    with pytest.raises(InputError, match="kind"):
        feature_surface("pit", 1e-3, 1e-5, amplitude=1e-7, half_width=5e-5, position=0.0)
    with pytest.raises(InputError, match="y"):
        feature_surface("dent", 1e-3, 1e-5, amplitude=1e-7, half_width=5e-5, position=0.0)


def test_feature_position_width_and_volume():
    """The cap sits where asked and is as wide as asked: the ridge's centroid is ``position``,
    it is non-zero only within ``half_width`` of it, and its area is ``amplitude * w`` (the
    integral of cos^2(pi r/(2w)) over -w..w is w); the dent's volume is
    ``amplitude * w^2 (1 - 4/pi^2) pi / 2`` (2 pi times the integral of r cos^2(pi r/(2w)) over
    0..w) and its deepest cell lies at the centre."""
    amp, w, pos, s = 1e-7, 5e-5, 3.7e-4, 1e-6
    ridge = feature_surface("ridge", 1e-3, s, amplitude=amp, half_width=w, position=pos)
    on = ridge.z > 0
    assert np.sum(ridge.x * ridge.z) / np.sum(ridge.z) == pytest.approx(pos, abs=s / 10)
    assert ridge.x[on].min() > pos - w and ridge.x[on].max() < pos + w
    assert ridge.x[on].max() - ridge.x[on].min() == pytest.approx(2 * w, abs=2 * s)
    assert np.sum(ridge.z) * s / (amp * w) == pytest.approx(1.0, rel=1e-3)
    y = s * (np.arange(161) - 80)
    dent = feature_surface("dent", 1e-3, s, amplitude=amp, half_width=w, position=pos, y=y)
    volume = np.sum(dent.z) * s * s  # in units of amp w^2: pytest.approx's abs=1e-12 default
    assert volume / (amp * w**2) == pytest.approx(-0.5 * np.pi * (1 - 4 / np.pi**2), rel=2e-3)
    i, j = np.unravel_index(np.argmin(dent.z), dent.z.shape)
    assert dent.x[i] == pytest.approx(pos, abs=s) and y[j] == 0.0


@pytest.mark.parametrize("name", ["dent-rolling", "dent-sliding"])
def test_example_case_places_the_dent_upstream_of_the_inlet(name):
    """The example case files build a dent whose centre enters the inlet at the start."""
    case = load_case(example_text(name))
    prob = case.problem()
    x, y = prob.grid(*case.grid.nodes(prob), case.grid.domain(prob))
    spacing = (x[1] - x[0]) / 4
    surf = case.surface1.build(2e-3, spacing, y, x[1] - x[0])
    assert isinstance(surf, Topography)
    i, j = np.unravel_index(np.argmin(surf.z), surf.z.shape)
    assert surf.z[i, j] == pytest.approx(-case.surface1.amplitude, rel=0.05)
    assert surf.x[-1] - surf.x[i] == pytest.approx(case.surface1.half_width, abs=spacing)
    assert y[j] == pytest.approx(0.0, abs=y[1] - y[0])


@pytest.mark.parametrize("feature, accepted", [("groove", True), ("ridge", True),
                                               ("dent", False), ("bump", False)])
def test_a_line_contact_takes_the_straight_features_only(feature, accepted):
    """A groove or a ridge runs across the whole width of a line contact; a dent or a bump
    needs a point contact, and the case file says which features a line contact takes."""
    data = tomllib.loads(example_text("holmes-rough-AA-line"))
    data["surface1"] = {"kind": "feature", "feature": feature, "amplitude": "0.2 um",
                        "half_width": "30 um"}
    if not accepted:
        with pytest.raises(InputError, match='"ridge" or "groove"'):
            load_case(data)
        return
    case = load_case(data)
    prob = case.problem()
    x, y = prob.grid(*case.grid.nodes(prob), case.grid.domain(prob))
    surf = case.surface1.build(2e-3, (x[1] - x[0]) / 4, y, x[1] - x[0])
    assert isinstance(surf, Profile)
    sign = -1.0 if feature == "groove" else 1.0
    assert sign * surf.z[np.argmax(np.abs(surf.z))] == pytest.approx(0.2e-6, rel=0.02)
    assert case.feature_spacing()[1] is None          # nothing across y to resolve


@pytest.mark.parametrize("half_width, warned", [("32 um", False), ("150 um", True)])
def test_a_feature_wider_than_the_contact_is_reported(half_width, warned):
    """The example's ball contact has a = b = 106.8 um (Hertz: a^3 = 3 F R / (4 E*), 15 N,
    R = 12.5 mm, E* = 115.4 GPa). A dent of 32 um half-width passes through it; one of 150 um
    reshapes the contact, and the run says so naming surface1.half_width; one 1.5 times as
    wide as the domain across y (4 a) is cut off at the sides, said too (a user's 2 mm dent
    in a 0.67 mm contact ran 2,552 steps without a word). Two steps on the example's mesh."""
    from asperity.runners import run_case

    data = tomllib.loads(example_text("dent-rolling"))
    data["surface1"]["half_width"] = half_width
    data["grid"].update(nx=65, ny=17)
    data["time"].update(counting_steps=2, snapshots=1)
    said = []
    lines = [w for w in run_case(load_case(data), progress=lambda *a: said.append(a)).warnings
             if w.startswith("surface1.half_width")]
    # before the steady start, the run's size and what it will cost
    assert said[0][:2] == (0, 2) and "2 steps on 65 x 17 nodes" in said[0][2]
    assert "about a minute or less" in said[0][2]
    a = (3 * 15.0 * 0.0125 / (4 * 210e9 / (2 * (1 - 0.3**2)))) ** (1 / 3)
    assert a == pytest.approx(106.8e-6, rel=1e-3)
    assert bool(lines) == warned
    if warned:
        assert "wider than the contact" in lines[0] and f"a = {a * 1e6:.4g} um" in lines[0]
    data["surface1"]["half_width"] = "330 um"  # 660 um across, the domain 4 a = 427 um wide
    lines = [w for w in run_case(load_case(data)).warnings
             if w.startswith("surface1.half_width")]
    assert len(lines) == 2 and "wider than the domain across y" in lines[1]


def test_a_feature_run_draws_its_film_change_step_by_step():
    """The film-snapshot figure of a dent run marks the dent's centre at each recorded step
    where the dent's surface is deepest on y = 0 (read off the recorded surface, not the
    track that placed it), within a mesh spacing; the centre-line film change is drawn
    against the smooth steady film."""
    from asperity.runners import run_case

    data = tomllib.loads(example_text("dent-sliding"))
    data["grid"].update(nx=65, ny=17)
    data["time"].update(counting_steps=120, snapshots=4)
    out = run_case(load_case(data))
    assert "film_snapshots" in out.figures
    fig = out.figures["film_snapshots"][0]()
    ds = out.dataset
    a = load_case(data).problem().a
    x = ds.x.values / a
    markers = [line for line in fig.axes[0].get_lines() if line.get_marker() == "v"]
    deepest = [x[int(np.argmin(z))] for z in ds["centre_surface1"].values
               if np.ptp(z) > 0 and 0 < int(np.argmin(z)) < x.size - 1]
    assert len(markers) == len(deepest) >= 2
    for line, xd in zip(markers, deepest, strict=True):
        assert float(line.get_xdata()[0]) == pytest.approx(xd, abs=x[1] - x[0])
    import matplotlib.pyplot as plt

    plt.close(fig)
