"""Case files: validation errors name the key path; examples validate."""

import pytest

from asperity.cases import load_case
from asperity.errors import InputError
from asperity.examples import example_text, list_examples

BASE = """
analysis = "normal"
[body1]
youngs_modulus = "30e6 psi"
[body2]
youngs_modulus = "210 GPa"
poisson_ratio = 0.3
[geometry]
shape = "sphere"
rx = "10 mm"
[loading]
load = "100 N"
[grid]
nx = 32
ny = 32
x_extent = "0.6 mm"
y_extent = "0.6 mm"
"""


def test_units_are_converted_to_si():
    case = load_case(BASE)
    assert case.geometry.rx == pytest.approx(0.01)
    assert case.body1.youngs_modulus == pytest.approx(30e6 * 6894.757293168361)
    x, y = case.grid.coordinates()
    assert len(x) == 32 and x[0] == pytest.approx(-0.3e-3 + 0.3e-3 / 32)


def test_an_unnamed_body_is_not_called_steel():
    """A body named by the user keeps its name; one left unnamed is a neutral "material" in
    the reports, whatever its moduli (a user's glass disc was listed as steel)."""
    named = 'poisson_ratio = 0.21\nname = "BK7 glass"'
    case = load_case(BASE.replace("poisson_ratio = 0.3", named))
    assert case.body2.material().name == "BK7 glass"
    assert case.body1.material().name == "material"


@pytest.mark.parametrize(
    "old, new, field",
    [
        ("rx =", "rxx =", "geometry.rxx"),
        ('"100 N"', '"-3 N"', "loading.load"),
        ('"100 N"', '"100 kg"', "loading.load"),
        ("nx = 32", 'nx = "a"', "grid.nx"),
        ("nx = 32", "nx = 2", "grid.nx"),
        ('"sphere"', '"cube"', "geometry.shape"),
        ('"normal"', '"norml"', "analysis"),
        ('load = "100 N"', "", "loading"),
        ('load = "100 N"', 'load = "100 N"\napproach = "1 um"', "loading"),
        ('"210 GPa"', '"nan GPa"', "body2.youngs_modulus"),
        ("poisson_ratio = 0.3", "poisson_ratio = 0.7", "body2.poisson_ratio"),
        ("[grid]", "[grid]\n[grid]", "case"),
    ],
)
def test_bad_case_gives_one_line_naming_the_key(old, new, field):
    with pytest.raises(InputError) as exc:
        load_case(BASE.replace(old, new))
    message = str(exc.value)
    assert message.startswith(field + ":"), message
    assert "\n" not in message


def test_every_example_validates_and_documents_itself():
    examples = list_examples()
    assert examples
    for ex in examples:
        assert ex.description and ex.source, ex.name
        load_case(example_text(ex.name))


def test_unknown_example_lists_the_valid_names():
    with pytest.raises(InputError, match="gear-dry-hertz"):
        example_text("no-such-example")
