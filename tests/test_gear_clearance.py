"""Tip clearance, root form circles, contact ratio, tip relief and bulk temperature of gear
cases, against numbers worked by hand from the textbook relations (ISO 53 profile A basic
rack: h_fP = 1.25 m_n, rho_fP = 0.38 m_n; ISO 21771; docs/gears.md)."""

import math

import pytest

from asperity.cases import load_case
from asperity.cases.doubts import unit_doubts
from asperity.errors import InputError
from asperity.gears import GearPair
from asperity.gears.rack import form_roll_distance, root_diameter, tip_for_form

DEG = math.pi / 180.0
SIN20, COS20 = math.sin(20 * DEG), math.cos(20 * DEG)

CASE = """analysis = "gear"
title = "spur 20/40 m4"
[gear]
teeth = [20, 40]
normal_module = "4 mm"
pressure_angle = "20 deg"
face_width = "40 mm"
{gear}
[operation]
torque = "500 N m"
speed = "1500 rpm"
bulk_temperature = {temperature}
[body1]
youngs_modulus = "206 GPa"
[body2]
youngs_modulus = "206 GPa"
[lubricant]
eta0 = "0.05 Pa s"
alpha = "20 1/GPa"
viscosity_model = "barus"
density_model = "incompressible"
tau0 = "5 MPa"
[surface1]
kind = "ground"
ra = "0.4 um"
[surface2]
kind = "ground"
ra = "0.4 um"
seed = 1
"""


def case(gear: str = "", temperature="80"):
    return load_case(CASE.format(gear=gear, temperature=temperature))


def spur(tips=None, relief=(0.0, 0.0)):
    """The probe's spur pair: z 20/40, m 4, standard, 120 mm centres."""
    return GearPair((20, 40), 4e-3, 20 * DEG, 0.0, (0.0, 0.0), 40e-3, tip_diameter=tips,
                    tip_relief=relief)


def form_diameter_by_hand(z, m, x):
    """d_Ff = 2 sqrt(r_b^2 + (r sin a - (1.25 m - x m - 0.38 m (1 - sin a)) / sin a)^2), spur
    (ISO 21771 / DIN 3960 for a rack-generated gear)."""
    r = 0.5 * z * m
    rho = r * SIN20 - (1.25 * m - x * m - 0.38 * m * (1 - SIN20)) / SIN20
    return 2 * math.hypot(r * COS20, rho), rho


# --- 1. tip clearance and root form circles -----------------------------------------------


def test_root_and_form_circles_of_a_shifted_helical_pair():
    """z 19/71, m_n 3.5, beta 15 deg, x 0.5/-0.1 (a user's reducer): by hand, d = m_n z /
    cos beta, d_f = d - 2 m_n (1.25 - x), alpha_t = atan(tan 20 deg / cos beta) and
    rho_F = r sin alpha_t - (1.25 - x - 0.38 (1 - sin 20 deg)) m_n / sin alpha_t,
    d_Ff = 2 sqrt(r_b^2 + rho_F^2) with r_b = r cos alpha_t. A sign slip on x or alpha_n
    for alpha_t (which passed the spur, x = 0 cases) fails here."""
    mn, beta, shifts = 3.5e-3, 15 * DEG, (0.5, -0.1)
    pair = GearPair((19, 71), mn, 20 * DEG, beta, shifts, 45e-3)
    alpha_t = math.atan(math.tan(20 * DEG) / math.cos(beta))
    for i, (z, x) in enumerate(zip((19, 71), shifts, strict=True)):
        d = mn * z / math.cos(beta)
        assert pair.df[i] == pytest.approx(d - 2 * mn * (1.25 - x), rel=1e-12)
        rho = 0.5 * d * math.sin(alpha_t) - (1.25 - x - 0.38 * (1 - SIN20)) * mn \
            / math.sin(alpha_t)
        d_ff = 2 * math.hypot(0.5 * d * math.cos(alpha_t), rho)
        assert pair.form_diameter[i] == pytest.approx(d_ff, rel=1e-12)
    assert pair.df[0] == pytest.approx(63.596e-3, abs=1e-6)  # 68.846 - 2 x 3.5 x 0.75


def test_a_pinion_tip_running_into_the_wheel_root_is_refused():
    """d_a1 = 91.5 mm on the 20/40 m 4 pair at 120 mm: the wheel's root is d_f2 = 160 -
    2 x 4 x 1.25 = 150 mm, so c = 120 - 45.75 - 75 = -0.75 mm; the largest tip that fits is
    2 (120 - 75) = 90 mm, and 88 mm leaves the rack's 0.25 m_n. It ran with exit 0."""
    assert root_diameter(160e-3, 4e-3, 0.0) == pytest.approx(150e-3, rel=1e-12)
    with pytest.raises(InputError) as err:
        spur((91.5e-3, 168e-3))
    text = str(err.value)
    assert err.value.field == "tip_diameter" and "\n" not in text
    assert "= -0.75 mm" in text and "d_f2" in text and "150.0000 mm" in text
    assert "at most 90.0000 mm" in text and "88.0000 mm" in text and "ISO 53" in text
    with pytest.raises(InputError, match=r"^gear\.tip_diameter: expected a pinion tip "
                                         r"diameter of at most 90\.0000 mm"):
        case('tip_diameter = ["91.5 mm", "168 mm"]')


def test_a_ring_tip_running_into_the_pinion_root_is_refused():
    """Planet 27 in ring -75, m 3, standard: a = 72 mm, the planet's root r_f1 = 40.5 -
    3 x 1.25 = 36.75 mm, so a ring tip of 217.1 mm leaves 108.55 - 72 - 36.75 = -0.2 mm; the
    smallest that fits is 2 (72 + 36.75) = 217.5 mm."""
    with pytest.raises(InputError) as err:
        GearPair((27, -75), 3e-3, 20 * DEG, 0.0, (0.0, 0.0), 30e-3,
                 tip_diameter=(87e-3, 217.1e-3))
    text = str(err.value)
    assert "ring tip diameter of at least 217.5000 mm" in text and "= -0.2 mm" in text
    standard = GearPair((27, -75), 3e-3, 20 * DEG, 0.0, (0.0, 0.0), 30e-3)
    assert math.isnan(standard.tip_clearance[0])  # the ring's root is the cutter's: not judged
    assert standard.tip_clearance[1] == pytest.approx(109.5e-3 - 72e-3 - 36.75e-3, abs=1e-12)


def test_a_small_tip_clearance_is_warned():
    """d_a1 = 90 mm: c = 120 - 45 - 75 = 0, below 0.13 m_n: warned with the 88 mm that
    leaves 0.25 m_n. The standard pair (c = 1 mm = 0.25 m_n both ways) is not."""
    pair = spur((90e-3, 168e-3))
    assert pair.tip_clearance == pytest.approx((0.0, 120e-3 - 84e-3 - 35e-3), abs=1e-12)
    lines = [w for w in pair.design_warnings() if "root circle by" in w]
    assert len(lines) == 1 and lines[0].startswith("gear.tip_diameter: the pinion tip")
    assert "0.13 m_n" in lines[0] and "88.0000 mm leaves 0.25 m_n" in lines[0]
    assert spur().tip_clearance == pytest.approx((1e-3, 1e-3), abs=1e-12)
    assert spur().design_warnings() == []


def test_root_form_diameters_by_the_textbook_formula():
    """d_Ff2 = 153.58 mm for the z 40 wheel, 75.28 mm for the z 20 pinion (by hand above);
    the pinion tip that keeps contact on the wheel's involute is 2 sqrt(r_b1^2 + (T1T2 -
    rho_F2)^2) = 90.70 mm, T1T2 = 120 sin 20 deg."""
    d_ff2, rho2 = form_diameter_by_hand(40, 4e-3, 0.0)
    d_ff1, _ = form_diameter_by_hand(20, 4e-3, 0.0)
    assert d_ff2 == pytest.approx(153.58e-3, abs=0.005e-3)
    pair = spur()
    assert pair.form_diameter == pytest.approx((d_ff1, d_ff2), rel=1e-9)
    assert form_roll_distance(160e-3, 4e-3, 0.0, 20 * DEG, 20 * DEG) == pytest.approx(
        rho2, rel=1e-12)
    limit = 2 * math.hypot(40e-3 * COS20, 120e-3 * SIN20 - rho2)
    assert limit == pytest.approx(90.70e-3, abs=0.005e-3)
    assert tip_for_form(pair.rb[0], pair.t1t2, rho2) == pytest.approx(limit, rel=1e-12)


def test_a_wheel_tip_on_the_pinion_fillet_is_warned():
    """d_a2 = 169.8 mm: contact starts at rho_A = T1T2 - sqrt(84.9^2 - r_b2^2) = 1.587 mm from
    T1, inside the pinion's form circle (rho_F1 = 1.986 mm): d_Nf1 = 75.27 < d_Ff1 = 75.28 mm;
    the wheel tip that keeps contact on the involute is 2 sqrt(r_b2^2 + (T1T2 - rho_F1)^2)
    = 169.43 mm. The line states the ISO 53 profile A assumption."""
    d_ff1, rho1 = form_diameter_by_hand(20, 4e-3, 0.0)
    rb1, rb2, t1t2 = 40e-3 * COS20, 80e-3 * COS20, 120e-3 * SIN20
    rho_a = t1t2 - math.sqrt(84.9e-3 ** 2 - rb2 ** 2)
    assert rho_a == pytest.approx(1.587e-3, abs=1e-6) and rho_a < rho1
    limit = 2 * math.hypot(rb2, t1t2 - rho1)
    assert limit == pytest.approx(169.43e-3, abs=0.005e-3)
    lines = [w for w in spur((88e-3, 169.8e-3)).design_warnings() if "fillet" in w]
    assert len(lines) == 1
    line = lines[0]
    assert line.startswith("gear.tip_diameter: the wheel tip meets the pinion flank")
    assert f"d_Nf1 = {2e3 * math.hypot(rb1, rho_a):.4f} mm" in line
    assert f"d_Ff1 = {d_ff1 * 1e3:.4f} mm" in line
    assert f"at most {limit * 1e3:.4f} mm" in line
    assert "ISO 53 profile A" in line and "rho_fP = 0.38 m_n" in line


def test_a_ring_tip_on_the_planet_fillet_is_warned():
    """The example's planet 27 in ring -75 (m 3, standard, a standard ring tip of 219 mm; the
    example now gives 220 mm, which keeps contact on the involute): the ring's tip
    meets the planet at rho_A = sqrt(109.5^2 - r_b2^2) - 72 sin 20 deg = 3.914 mm, inside
    the planet's rho_F1 = 5.081 mm (d_Nf1 76.517 < d_Ff1 76.790 mm); a ring tip of at least
    2 sqrt(r_b2^2 + (T1T2 + rho_F1)^2) = 219.62 mm keeps contact on the involute."""
    d_ff1, rho1 = form_diameter_by_hand(27, 3e-3, 0.0)
    rb1, rb2, t1t2 = 40.5e-3 * COS20, 112.5e-3 * COS20, 72e-3 * SIN20
    rho_a = math.sqrt(109.5e-3 ** 2 - rb2 ** 2) - t1t2
    assert rho_a == pytest.approx(3.914e-3, abs=1e-6) and rho1 == pytest.approx(5.081e-3,
                                                                                abs=1e-6)
    limit = 2 * math.hypot(rb2, t1t2 + rho1)
    pair = GearPair((27, -75), 3e-3, 20 * DEG, 0.0, (0.0, 0.0), 30e-3)
    lines = [w for w in pair.design_warnings() if "fillet" in w]
    assert len(lines) == 1 and "the ring tip meets the pinion flank" in lines[0]
    assert f"d_Nf1 = {2e3 * math.hypot(rb1, rho_a):.4f} mm" in lines[0]
    assert f"d_Ff1 = {d_ff1 * 1e3:.4f} mm" in lines[0]
    assert f"at least {limit * 1e3:.4f} mm" in lines[0]
    assert limit == pytest.approx(219.62e-3, abs=0.005e-3)


@pytest.mark.parametrize("pair", [
    GearPair((16, 24), 4.5e-3, 20 * DEG, 0.0, (0.1817, 0.1715), 14e-3, centre_distance=91.5e-3,
             tip_diameter=(82.46e-3, 118.36e-3)),
    GearPair((23, 67), 3e-3, 20 * DEG, 15 * DEG, (0.3, 0.1), 40e-3),
    GearPair((12, 24), 3e-3, 20 * DEG, 0.0, (0.6, 0.36), 20e-3),  # KHK, eps_alpha 1.202
])
def test_sound_external_pairs_are_not_warned(pair):
    """The FZG C pair, the helical example and KHK's shifted 12/24 pair (contact ratio 1.202,
    just above 1.2) clear the roots and keep contact on the involutes."""
    assert pair.design_warnings() == []


# --- 3. and 4. the contact ratio -----------------------------------------------------------


def contact_ratio_by_hand(da1, da2, a=120e-3):
    """(sqrt(r_a1^2 - r_b1^2) + sqrt(r_a2^2 - r_b2^2) - a sin a_w) / (pi m cos a), z 20/40
    m 4."""
    rb1, rb2 = 40e-3 * COS20, 80e-3 * COS20
    alpha_w = math.acos((rb1 + rb2) / a)
    return (math.sqrt((da1 / 2) ** 2 - rb1 ** 2) + math.sqrt((da2 / 2) ** 2 - rb2 ** 2)
            - a * math.sin(alpha_w)) / (math.pi * 4e-3 * COS20)


def test_a_contact_ratio_below_1_names_the_keys_given():
    """Tips 84 / 164 mm: eps_alpha 0.885 by hand; the line named centre_distance, which the
    case did not give: now gear.tip_diameter. A centre distance given too long names it."""
    assert contact_ratio_by_hand(84e-3, 164e-3) == pytest.approx(0.885, abs=5e-4)
    with pytest.raises(InputError) as err:
        case('tip_diameter = ["84 mm", "164 mm"]')
    text = str(err.value)
    assert text.startswith("gear.tip_diameter: expected a transverse contact ratio >= 1 "
                           "(it is 0.885")
    assert "centre_distance" not in text and "raise the tip diameters" in text
    eps = contact_ratio_by_hand(88e-3, 168e-3, a=124e-3)
    assert eps < 1
    with pytest.raises(InputError, match=r"^gear\.centre_distance: expected a transverse "
                                         rf"contact ratio >= 1 \(it is {eps:.3f}"):
        case('centre_distance = "124 mm"')


def test_a_contact_ratio_just_above_1_is_warned():
    """Tips 85.2 / 164.6 mm: eps_alpha = 1.0587 by hand, below 1.2: one pair carries the load
    over (2 - eps)/eps = 89 % of the path; the line names gear.tip_diameter."""
    eps = contact_ratio_by_hand(85.2e-3, 164.6e-3)
    assert eps == pytest.approx(1.0587, abs=1e-4)
    pair = spur((85.2e-3, 164.6e-3))
    assert pair.contact_ratio == pytest.approx(eps, rel=1e-12)
    lines = [w for w in pair.design_warnings() if "contact ratio" in w]
    assert len(lines) == 1 and lines[0].startswith(
        f"gear.tip_diameter: the transverse contact ratio {eps:.4g} is below 1.2")
    assert f"{(2 - eps) / eps:.0%} of the path" in lines[0]
    assert "tolerances" in lines[0] and "deflection" in lines[0]


# --- 5. tip relief and bulk temperature ----------------------------------------------------


def test_a_tip_relief_far_above_the_module_fraction_is_warned():
    """0.5 mm on a 4 mm module is 0.125 m_n (typical C_a: a few to tens of um, about
    0.01-0.02 m_n): warned per gear; 20 um (0.005 m_n) is not."""
    lines = spur(relief=(0.5e-3, 20e-6)).design_warnings()
    assert len(lines) == 1 and lines[0].startswith("gear.tip_relief: the pinion's tip relief "
                                                   "500 um = 0.125 m_n is above 0.05 m_n")
    assert spur(relief=(20e-6, 20e-6)).design_warnings() == []


def test_a_bare_bulk_temperature_of_400_is_doubted():
    """A bare 400 is read in deg C (as a bare bulk temperature always is): 400 deg C, hotter
    than gear teeth run; read as kelvin 400 - 273.15 = 126.85 deg C. "400 K" and a bare 90 are
    not doubted; "250 degC" with its unit is warned as hot."""
    hot = case(temperature="400")
    assert hot.operation.bulk_temperature == 400.0
    lines = [w for w in unit_doubts(hot) if w.startswith("operation.bulk_temperature:")]
    assert len(lines) == 1
    assert "the bare number 400 is read in deg C" in lines[0]
    assert "126.9 deg C" in lines[0] and '"400 K"' in lines[0]
    assert unit_doubts(case(temperature='"400 K"')) == []
    assert unit_doubts(case(temperature="90")) == []
    lines = unit_doubts(case(temperature='"250 degC"'))
    assert len(lines) == 1 and lines[0].startswith("operation.bulk_temperature: 250 deg C is")
