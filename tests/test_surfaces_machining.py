"""Seireg ch. 4: process roughness table, kinematic feed marks (eq. 4.1), tool vibration."""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces import (
    kinematic_peak_to_valley,
    process_names,
    process_roughness,
    roughness_along,
    roughness_parameters,
    turned_profile,
    turned_profile_dynamic,
)

# Fig. 4.2 conditions: V = 61 m/min, f = 0.127 mm/rev, d = 0.305 mm, r = 0.794 mm.
FEED, RADIUS, DEPTH, SPEED = 0.127e-3, 0.794e-3, 0.305e-3, 61.0 / 60.0


def test_table_4_1():
    names = process_names()
    assert len(names) == 24 and names[0] == "Super finishing" and names[-1] == "Sand casting"
    expected = {  # microinches, including the entries the OCR split ("32-1 25", "250-1 000")
        "Super finishing": (2, 8), "Grinding": (4, 63), "Boring, turning": (16, 250),
        "Extruding": (32, 125), "Mold casting": (63, 125), "Sawing": (63, 1000),
        "Snagging": (250, 1000), "Sand casting": (500, 1000),
    }
    for name, (lo, hi) in expected.items():
        entry = process_roughness(name)
        assert (entry.ra_min_microinch, entry.ra_max_microinch) == (lo, hi)
    grinding = process_roughness("grinding")
    assert grinding.ra_max_um == pytest.approx(63 * 0.0254)
    assert grinding.ra_range_m == pytest.approx((4 * 25.4e-9, 63 * 25.4e-9))
    assert process_roughness("turning").process == "Boring, turning"
    with pytest.raises(InputError, match="process: expected one of: Super finishing; Lapping"):
        process_roughness("knurling")


def test_kinematic_peak_to_valley_eq_4_1():
    rt = kinematic_peak_to_valley(FEED, RADIUS)
    assert rt == pytest.approx(FEED**2 / (8 * RADIUS), rel=1e-15)
    # The arcs' exact height r - sqrt(r^2 - f^2/4): with 1001 points per feed the cusps at
    # (k + 1/2) f fall on cell centres, and the flat valleys at k f half a cell away.
    profile = turned_profile(FEED, RADIUS, 20 * FEED, FEED / 1001)
    assert profile.periodic
    measured = roughness_parameters(profile)["Rt"]
    assert measured == pytest.approx(rt, rel=0.01)
    assert measured == pytest.approx(RADIUS - np.sqrt(RADIUS**2 - FEED**2 / 4), rel=1e-6)
    with pytest.raises(InputError, match="feed"):
        kinematic_peak_to_valley(1e-3, 1e-3, end_relief_angle=0.3)


def _dynamic(fn, seed=0):
    return turned_profile_dynamic(FEED, RADIUS, DEPTH, SPEED, 0.05, 20e-3, 1e-6, fn,
                                  mass=250.0, seed=seed)


def test_dynamic_model_reduces_to_kinematic_at_high_natural_frequency():
    res = _dynamic(1000.0)
    _, rt = roughness_along(res.profile, 5 * FEED)
    np.testing.assert_allclose(rt, res.kinematic_rt, rtol=0.01)
    assert res.stiffness == pytest.approx(250.0 * (2 * np.pi * 1000.0) ** 2)
    assert res.pass_positions.size == res.pass_displacements.size
    # The tool's mean position is the static deflection under the mean force.
    assert np.mean(res.pass_displacements[5:]) == pytest.approx(res.static_deflection,
                                                                 rel=0.05)


def test_dynamic_model_low_natural_frequency_roughens_and_varies():
    # Fig. 4.2 (28 and 34 Hz): larger roughness than kinematic, varying along the workpiece.
    for fn in (28.0, 34.0):
        res = _dynamic(fn)
        _, rt = roughness_along(res.profile, 5 * FEED)
        assert rt.mean() > 1.15 * res.kinematic_rt
        assert rt.max() - rt.min() > 0.3 * res.kinematic_rt
    same = _dynamic(28.0)
    np.testing.assert_array_equal(same.profile.z, _dynamic(28.0).profile.z)


def test_dynamic_model_input_errors():
    with pytest.raises(InputError, match="mass"):
        turned_profile_dynamic(FEED, RADIUS, DEPTH, SPEED, 0.05, 1e-3, 1e-6, 30.0)
    with pytest.raises(InputError, match="damping_ratio"):
        turned_profile_dynamic(FEED, RADIUS, DEPTH, SPEED, 0.05, 1e-3, 1e-6, 30.0,
                               stiffness=1e7, damping_ratio=1.5)
    with pytest.raises(InputError, match="window"):
        roughness_along(turned_profile(FEED, RADIUS, 1e-3, 1e-6), 1e-2)
    with pytest.raises(InputError, match="parameter"):
        roughness_along(turned_profile(FEED, RADIUS, 1e-3, 1e-6), 2e-4, "Sa")


def test_feed_of_twice_the_nose_radius_has_rt_of_the_radius():
    """f = 2 r (0.8 mm, 0.4 mm): the arcs meet at their ends, the cusp height is r. The ends
    were left out of the envelope, the cusps covered by no arc (heights of inf, "z: expected
    finite heights")."""
    f, r = 0.8e-3, 0.4e-3
    h = f / 201  # the cusps on cell centres, the valleys half a cell beside the nearest ones
    profile = turned_profile(f, r, 20 * f, h)
    assert np.all(np.isfinite(profile.z))
    exact = r - (r - np.sqrt(r * r - (h / 2) ** 2))  # cusp at r, valley sampled h/2 off
    assert roughness_parameters(profile)["Rt"] == pytest.approx(exact, rel=1e-9)
    from asperity.surfaces.machining import arc_peak_to_valley

    assert arc_peak_to_valley(f, r) == r
    assert kinematic_peak_to_valley(f, r) == pytest.approx(r / 2, rel=1e-15)   # f^2 / (8 r)


def test_parabola_error_against_the_arcs():
    """Eq. (4.1)'s f^2/(8 r) against r - sqrt(r^2 - f^2/4): 42 % low at f = 0.79 mm,
    r = 0.4 mm (195.03 um against 336.95 um); 5 % at the feed limit 4 r sqrt(0.05 * 0.95)."""
    from asperity.surfaces.machining import (
        PARABOLA_TOLERANCE,
        arc_peak_to_valley,
        parabola_error,
        parabola_feed_limit,
    )

    f, r = 0.79e-3, 0.4e-3
    arc = r - np.sqrt(r * r - f * f / 4)
    assert arc_peak_to_valley(f, r) == pytest.approx(336.9524e-6, rel=1e-6)
    assert arc_peak_to_valley(f, r) == pytest.approx(arc, rel=1e-14)
    assert parabola_error(f, r) == pytest.approx(1 - f * f / (8 * r) / arc, rel=1e-12)
    assert parabola_error(f, r) == pytest.approx(0.4212, abs=1e-4)
    assert parabola_error(0.2e-3, 0.4e-3) == pytest.approx(
        1 - 0.2e-3**2 / 3.2e-3 / (0.4e-3 - np.sqrt(0.4e-3**2 - 0.1e-3**2)), rel=1e-12)
    limit = parabola_feed_limit(r)
    assert limit == pytest.approx(0.8718 * r, rel=1e-4)
    assert parabola_error(limit, r) == pytest.approx(PARABOLA_TOLERANCE, rel=1e-12)


def test_feed_above_the_limit_is_refused_in_mm():
    """The limit in mm, sin(kappa_e) named only where an angle was given (it said
    "f <= 2 r sin(kappa_e) = 0.0008 m ... got 0.0009000000000000001")."""
    with pytest.raises(InputError) as exc:
        kinematic_peak_to_valley(0.9e-3, 0.4e-3)
    assert str(exc.value) == ("feed: expected at most 2 r = 0.8 mm (r = 0.4 mm), feed marks "
                              "formed by the nose radius (Seireg eq. 4.1), got 0.9 mm")
    with pytest.raises(InputError) as exc:
        turned_profile(0.5e-3, 0.4e-3, 5e-3, 1e-6, end_relief_angle=np.radians(30))
    assert "2 r sin(kappa_e) = 0.4 mm (r = 0.4 mm, kappa_e = 30 deg)" in str(exc.value)
    assert str(exc.value).endswith("got 0.5 mm")


def test_turning_summary_says_which_kinematic_rt_is_which():
    # the rows read "kinematic Rt" and "kinematic Rt arc": which is eq. (4.1), which the arcs'?
    from asperity.cases import load_case
    from asperity.formatting import summary_rows
    from asperity.runners import run_case

    f, r = 0.3e-3, 0.4e-3
    outcome = run_case(load_case('analysis = "surface"\n[surface]\nkind = "turned"\n'
                                 'feed = "0.3 mm"\nnose_radius = "0.4 mm"\nlength = "3 mm"\n'))
    rows = {row.key: row for row in summary_rows(outcome.summary)}
    arc, parabola = rows["kinematic_rt_arc_m"], rows["kinematic_rt_m"]
    assert "arcs" in arc.label and "r - sqrt(r^2 - f^2/4)" in arc.label
    assert "f^2/(8 r)" in parabola.label and "4.1" in parabola.label
    assert "f^2/(18 sqrt(3) r)" in rows["kinematic_ra_m"].label
    assert outcome.summary["kinematic_rt_arc_m"] == pytest.approx(r - np.sqrt(r**2 - f**2 / 4),
                                                                 rel=1e-12)  # 29.19 um
    assert outcome.summary["kinematic_rt_m"] == pytest.approx(f**2 / (8 * r), rel=1e-12)
