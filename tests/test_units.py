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
