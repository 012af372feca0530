"""A bare Young's modulus below 0.1 MPa (read in Pa) is refused in every analysis
(cases/bodies.py): ``youngs_modulus = 206`` meant as GPa was 206 Pa. The ambiguous range
1e5..2e8 stays a warning (a soft solid in Pa or a metal in psi)."""

import pytest

from asperity.cases import load_case
from asperity.cases.bodies import PSI_AMBIGUOUS, SOFTEST_BARE_MODULUS
from asperity.cases.doubts import unit_doubts
from asperity.errors import InputError

TANGENTIAL = """analysis = "tangential"
title = "ball on flat"
mu = 0.3
[body1]
youngs_modulus = {e1}
poisson_ratio = 0.3
[body2]
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[pressure]
source = "hertz"
load = "100 N"
rx = "10 mm"
[loading]
force = "10 N"
[grid]
nx = 32
ny = 32
"""

GEAR = """analysis = "gear"
[gear]
teeth = [20, 40]
normal_module = "4 mm"
pressure_angle = "20 deg"
face_width = "40 mm"
[operation]
torque = "500 N m"
speed = "1500 rpm"
[body1]
youngs_modulus = {e1}
[lubricant]
eta0 = "0.05 Pa s"
alpha = "20 1/GPa"
[surface1]
kind = "ground"
ra = "0.4 um"
[surface2]
kind = "ground"
ra = "0.4 um"
"""


@pytest.mark.parametrize("template", [TANGENTIAL, GEAR])
@pytest.mark.parametrize(("bare", "readings"), [
    ("206", ('"206 GPa"', '"206 MPa"')),     # steel meant in GPa: 206 Pa
    ("210", ('"210 GPa"', '"210 MPa"')),
    ("70000", ('"70000 MPa"',)),              # aluminium in MPa; 70000 GPa is past diamond
    ("2.5", ('"2.5 GPa"', '"2.5 MPa"')),      # a polymer in GPa
])
def test_a_bare_modulus_below_0p1_mpa_is_refused(template, bare, readings):
    """Refused in one line naming body1.youngs_modulus, the Pa reading and the units to
    write; a reading past diamond's 1.2 TPa is not offered."""
    with pytest.raises(InputError) as err:
        load_case(template.format(e1=bare))
    text = str(err.value)
    assert text.startswith("body1.youngs_modulus: expected a Young's modulus with its unit: "
                           f"the bare number {bare} is read in Pa")
    assert "\n" not in text
    for reading in readings:
        assert reading in text
    if "GPa" not in "".join(readings):
        assert f'"{bare} GPa"' not in text


def test_the_threshold_is_the_ambiguous_ranges_lower_end():
    """1e5 Pa bare is in the warned range (read in Pa, or psi?), just below it refused; with
    its unit a soft modulus runs ("20 kPa", a hydrogel), and SI numbers of solids too."""
    assert SOFTEST_BARE_MODULUS == PSI_AMBIGUOUS[0] == 1e5
    warned = load_case(TANGENTIAL.format(e1="1e5"))
    assert warned.body1.youngs_modulus == 1e5
    assert any(line.startswith("body1.youngs_modulus:") for line in unit_doubts(warned))
    with pytest.raises(InputError, match="body1.youngs_modulus"):
        load_case(TANGENTIAL.format(e1="99999"))
    assert load_case(TANGENTIAL.format(e1='"20 kPa"')).body1.youngs_modulus == 20e3
    assert load_case(TANGENTIAL.format(e1="2.1e11")).body1.youngs_modulus == 2.1e11
    assert load_case(TANGENTIAL.format(e1='"206 GPa"')).body1.youngs_modulus == 206e9


def test_a_bare_modulus_in_mpa_is_offered_its_mpa_reading():
    """``youngs_modulus = 210000`` (steel in MPa, as data sheets give it) was offered the psi
    reading (1.448 GPa) and the soft body only; 210000 MPa = 210 GPa is now named too. 3e7,
    whose MPa reading (30 TPa) is stiffer than diamond, is not offered it."""
    from asperity.cases.bodies import MaterialSpec

    (line,) = MaterialSpec(youngs_modulus=210000, poisson_ratio=0.3).unit_doubts("body1")
    assert "in MPa 210 GPa" in line and '"210000 MPa"' in line and "1.448 GPa" in line
    (line,) = MaterialSpec(youngs_modulus=3e7, poisson_ratio=0.3).unit_doubts("body1")
    assert "MPa for a modulus" not in line and "in MPa" not in line
