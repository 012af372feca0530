"""A rolling-bearing engineer's inputs: a lightly loaded roller (an unloaded-zone roller:
R = 4.167 mm, 10 N/mm, 5 m/s, 30 mPa s), what a nearly rigid line contact is compared with
and told; a ball in its groove with its radii swapped or its groove's radius negative.

References, by hand: Martin's (1916) rigid-isoviscous film of a cylinder,
h = 4.896 eta0 u R / w' (u the mean speed); Moes' (1992) rigid-isoviscous asymptote
H_RI = 3/M, which is a film of 6 eta0 u R / w', 22 % above Martin's by construction
(6 / 4.896 = 1.2255).
"""

import pytest

from asperity.cases import load_case
from asperity.cases.ehl import check_node_count
from asperity.runners import run_case

ROLLER = """
analysis = "ehl-steady"
[body1]
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[body2]
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[contact]
type = "line"
radius = "4.16667 mm"
load_per_length = "10 N/mm"
[speeds]
u = "5 m/s"
xi = 0.0
[lubricant]
eta0 = "0.03 Pa s"
"""
ISOVISCOUS = ROLLER + 'alpha = "0.1 1/GPa"\nviscosity_model = "barus"\n' \
                      'density_model = "incompressible"\n'


def test_an_isoviscous_rigid_roller_is_not_checked_against_moes_rigid_asymptote():
    """M = 0.59, L = 0.1: Moes' fit is mostly its rigid term here, 416 nm, and the run printed
    "differs: -22.6 %" against a film 5 % above Martin's. Martin's film is shown, the Moes
    row is not a check, and the domain line offers the Martin row by name."""
    martin = 4.896 * 0.03 * 5.0 * 4.16667e-3 / 1e4
    out = run_case(load_case(ISOVISCOUS))
    assert out.summary["martin_minimum_film_m"] == pytest.approx(martin, rel=2e-3)
    # the fit adds its elastic-isoviscous term to 3/M: above 6/4.896 of Martin's
    assert out.summary["moes_central_film_m"] / martin > 6 / 4.896
    # elastic and inlet effects of M = 0.59: a few per cent above the rigid film
    assert 1.0 < out.summary["minimum_film_thickness_m"] / martin < 1.1
    (moes,) = [c for c in out.comparisons if "Moes" in c.source]
    assert moes.tolerance is None and "22 % above" in moes.note
    (domain,) = [w for w in out.warnings if w.startswith("domain:")]
    assert "take the Martin minimum film (rigid-isoviscous) row" in domain


def test_a_piezoviscous_rigid_roller_is_not_told_to_take_a_row_it_does_not_have():
    """alpha = 20 1/GPa (L = 19): no rigid-isoviscous row is shown, and the domain line
    used to say "or take the rigid-isoviscous film of the comparison rows"."""
    out = run_case(load_case(ROLLER + 'alpha = "20 1/GPa"\n'))
    assert "martin_minimum_film_m" not in out.summary
    (domain,) = [w for w in out.warnings if w.startswith("domain:")]
    assert "rigid-isoviscous film" not in domain and "row" not in domain
    assert "set x_min <=" in domain


def test_a_default_mesh_over_the_node_limit_is_told_the_largest_mesh_of_its_proportions():
    """A 2 N ball's default mesh (3113 x 233) exceeds 801 x 201 x 4 nodes; the line now
    names 2933 x 219: both odd, 642,327 nodes, the proportions kept to 0.3 %."""
    with pytest.raises(ValueError) as info:
        check_node_count(3113, 233, True)
    assert "at most 2933 x 219 in the same proportions" in str(info.value)
    assert 2933 * 219 <= 801 * 201 * 4 and 2933 / 219 == pytest.approx(3113 / 233, rel=3e-3)


def test_a_bare_light_load_per_length_is_doubted():
    """load_per_length = 1000 (meant 1000 N/mm) ran as 1 N/mm without a word; 1 N/mm is
    1000 N/m, below the 10 N/mm of the lightest rolling-element line loads."""
    from asperity.cases.doubts import unit_doubts

    case = load_case(ROLLER.replace('load_per_length = "10 N/mm"', "load_per_length = 1000")
                     + 'alpha = "20 1/GPa"\n')
    (line,) = unit_doubts(case)
    assert line.startswith("contact.load_per_length: the bare number 1000 is read in N/m, "
                           "1 N/mm")
    assert '"1000 N/mm"' in line
    assert unit_doubts(load_case(ROLLER + 'alpha = "20 1/GPa"\n')) == []


BALL = """
analysis = "ehl-steady"
[body1]
youngs_modulus = "210 GPa"
[body2]
youngs_modulus = "210 GPa"
[contact]
rx = "{rx}"
ry = "{ry}"
load = "500 N"
[speeds]
u = "8 m/s"
[lubricant]
eta0 = "0.02 Pa s"
alpha = "20 1/GPa"
"""


def test_a_ball_with_its_radii_swapped_is_doubted_before_the_solve():
    """A 12 mm ball on a 40 mm race in a 0.52 D groove: rx = 1/(1/6 + 1/20) = 4.615 mm along
    the rolling, ry = 1/(1/6 - 1/6.24) = 156 mm across. Swapped, b/a = 1.0339 (4.615/156)^0.636
    = 0.11 (Hamrock & Brewe's fit): the run took 148 s to a collapsed film. As given, the
    ellipse is b/a = 9.1 and nothing is doubted."""
    from asperity.cases.doubts import unit_doubts

    swapped = load_case(BALL.format(rx="156 mm", ry="4.615385 mm"))
    (line,) = unit_doubts(swapped)
    assert line.startswith("contact.rx, contact.ry: the contact ellipse is about 9.08 times")
    assert "b/a = 0.11" in line and "swapped" in line
    assert unit_doubts(load_case(BALL.format(rx="4.615385 mm", ry="156 mm"))) == []


def test_a_negative_groove_radius_is_told_how_a_concave_surface_enters():
    with pytest.raises(ValueError) as info:
        load_case(BALL.format(rx="4.615385 mm", ry="-6.24 mm"))
    message = str(info.value)
    assert message.startswith("contact.ry: expected a radius of relative curvature > 0")
    assert "1/(1/6 - 1/6.24)" in message and "156 mm" in message


def test_following_the_rigid_domain_advice_clears_it():
    """The piezoviscous-rigid roller was told x_min <= -22.7, x_max >= 1.63; on that domain
    its film grew and it was told -22.8. The advice now has a margin for that growth: on the
    domain it names, no domain line."""
    import re

    text = ROLLER + 'alpha = "20 1/GPa"\n'
    (domain,) = [w for w in run_case(load_case(text)).warnings if w.startswith("domain:")]
    x_min, x_max = (float(v) for v in re.search(
        r"set x_min <= (-?[\d.]+), x_max >= ([\d.]+)", domain).groups())
    grid = f"[grid]\nx_min = {x_min}\nx_max = {x_max}\n"
    again = run_case(load_case(text.replace("[lubricant]", grid + "[lubricant]")))
    assert not [w for w in again.warnings if w.startswith("domain:")]


def test_an_unconverged_contact_beyond_the_tested_moes_m_is_told_so():
    """A heavy slow roller (1500 N/mm at 1.6 mm/s, M = 4937) ran 40 000 sweeps to a residual
    of 0.73 and was told only to raise max_sweeps; M = 4937 is beyond the M <= 1000 the
    defaults are tested on. The note's sentence, for that M and for one inside the range."""
    from types import SimpleNamespace

    from asperity.runners.ehl_steady import beyond_tested_range

    line = beyond_tested_range(SimpleNamespace(M=4937))
    assert "Moes M = 4.94e+03 is beyond the M <= 1000" in line
    assert beyond_tested_range(SimpleNamespace(M=640.0)) == ""
