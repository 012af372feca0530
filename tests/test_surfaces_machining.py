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
