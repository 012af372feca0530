"""Unit conversion at the edge: pint strings to SI floats, with one-line errors."""

import math

import pytest

from asperity.errors import InputError
from asperity.units import to_si

LBF, PSI, IN = 4.4482216152605, 6894.757293168361, 0.0254


@pytest.mark.parametrize(
    "text, dimension, expected",
    [
        ("2160 lbf", "force", 2160 * LBF),
        ("30e6 psi", "pressure", 30e6 * PSI),
        ("0.6 in", "length", 0.6 * IN),
        ("25 m/s", "speed", 25.0),
        ("11.1 1/GPa", "inverse_pressure", 11.1e-9),
        ("2.45 in lbf", "moment", 2.45 * IN * LBF),
        ("527 kN/m", "force_per_length", 527e3),
        ("0.005 Pa s", "viscosity", 0.005),
        (3.5, "length", 3.5),
    ],
)
def test_to_si_converts(text, dimension, expected):
    assert math.isclose(to_si(text, dimension, "f"), expected, rel_tol=1e-12)


@pytest.mark.parametrize("bad", ["3 parsecs per fortnight squared", "abc", "2 kg", "nan m", True,
                                 [1.0], "1 +"])
def test_bad_quantities_name_the_field(bad):
    with pytest.raises(InputError) as exc:
        to_si(bad, "length", "geometry.rx")
    assert str(exc.value).startswith("geometry.rx: ")
    assert "\n" not in str(exc.value)


@pytest.mark.parametrize("text", ["12,5 mm", "12, 5 mm", "1 000 N", "1,000 N", "0,25 mm"])
def test_a_decimal_comma_or_thousands_separator_is_refused(text):
    """pint drops commas and multiplies numbers side by side: "12,5 mm" was 125 mm, "12, 5 mm"
    60 mm and "1 000 N" 0 N, each without a word."""
    with pytest.raises(InputError, match="one number with a decimal point") as exc:
        to_si(text, "force" if "N" in text else "length", "contact.rx")
    assert str(exc.value).startswith("contact.rx: ")


@pytest.mark.parametrize("text, expected", [("20 1/GPa", 20e-9), ("1 / GPa", 1e-9),
                                            (".5 1/GPa", 0.5e-9), ("2e1 GPa^-1", 20e-9)])
def test_a_unit_that_starts_with_one_over_is_still_read(text, expected):
    assert math.isclose(to_si(text, "inverse_pressure", "f"), expected, rel_tol=1e-12)


@pytest.mark.parametrize("text, expected", [("1500 rpm", 25.0), ("3000 cycle/s", 3000.0),
                                            ("25 revolution/s", 25.0), ("1500 1/min", 25.0),
                                            ("2 kHz", 2000.0)])
def test_a_frequency_in_turns_counts_cycles(text, expected):
    """pint's turn is 2 pi radians, so "3000 cycle/s" was 18,850 Hz and "1500 rpm" 157 Hz."""
    assert math.isclose(to_si(text, "frequency", "f"), expected, rel_tol=1e-12)


@pytest.mark.parametrize("text, dimension, expected", [
    ("0.127 mm/rev", "length", 0.127e-3), ("0.127 mm/revolution", "length", 0.127e-3),
    ("0.005 in/rev", "length", 0.005 * IN), ("0.5 turn", "angle", math.pi),
    ("5 mil", "length", 0.005 * IN),
    ("90 deg", "angle", math.pi / 2)])
def test_a_feed_per_revolution_is_a_length_and_a_turn_is_still_an_angle(text, dimension,
                                                                         expected):
    """A turning feed written as machinists write it, "0.127 mm/revolution", was 0.0202 mm (pint
    divides by 2 pi radians) and "mm/rev" an unknown unit; as an angle a turn stays 2 pi. A
    length of "5 mil" (0.005 in) was refused, pint's mil being an angle."""
    assert math.isclose(to_si(text, dimension, "feed"), expected, rel_tol=1e-12)


@pytest.mark.parametrize("text, dimension, hint", [
    ("250 cSt", "viscosity", "kinematic viscosity"), ("15 kg", "force", "a mass"),
    ("1500 rpm", "speed", "rotational speed")])
def test_a_quantity_of_a_related_kind_says_what_it_is(text, dimension, hint):
    """A kinematic viscosity for eta0, a mass for a load and an rpm for a surface speed are
    refused saying what they are and how to convert (1500 rpm on a 50 mm radius is
    1500 x 2 pi / 60 x 0.05 = 7.85 m/s)."""
    with pytest.raises(InputError, match=hint):
        to_si(text, dimension, "f")


@pytest.mark.parametrize("text, dimension, converted", [
    ("50 kg", "force", "'50 kgf' or 50 kg x 9.81 m/s^2 = 490.3 N"),
    ("2.5 lb", "force", "'2.5 lbf' or 2.5 lb x 9.81 m/s^2 = 11.12 N"),
    ("320 cSt", "viscosity", "320 cSt x 850 kg/m^3 (a mineral oil's) = 272 mPa s"),
    ("3000 rpm", "speed", "3000 rpm on a 50 mm radius = 15.71 m/s")])
def test_the_conversion_offered_is_of_the_users_own_number(text, dimension, converted):
    """The hint converts what the user wrote: 50 kg was told "its weight is '15 kgf' or
    15 kg x 9.81 = 147 N", a fixed example. By hand: 50 x 9.80665 = 490.3 N,
    2.5 x 0.45359 x 9.80665 = 11.12 N, 320e-6 m^2/s x 850 kg/m^3 = 0.272 Pa s,
    3000 / 60 x 2 pi x 0.05 = 15.71 m/s."""
    with pytest.raises(InputError) as info:
        to_si(text, dimension, "f")
    assert converted in str(info.value)


@pytest.mark.parametrize("text", ["73 degC", "150 degF"])
def test_a_temperature_for_another_quantity_is_called_a_temperature(text):
    """'73 degC' for a modulus was refused as "a number with a known unit", as if degC were
    unknown (pint will not multiply an offset unit); it is a known unit of the wrong kind."""
    with pytest.raises(InputError) as info:
        to_si(text, "pressure", "body2.youngs_modulus")
    assert str(info.value) == (f"body2.youngs_modulus: expected a quantity convertible to Pa "
                               f"(this is a temperature), got '{text}'")


@pytest.mark.parametrize("text", ["30 mPas", "0.03 Pas", "30 cp", "30 cps", "30 mPa.s"])
def test_viscosities_written_without_the_space_are_read_as_meant(text):
    """A bearing user's "30 mPas" and "0.03 Pas" were refused with no hint, and "30 cp"
    (pint: candlepower) too; each is 30 mPa s."""
    assert to_si(text, "viscosity", "lubricant.eta0") == pytest.approx(0.03, rel=1e-12)
