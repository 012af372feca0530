"""Case files: validation errors name the key path; examples validate."""

import typing

import pytest
from pydantic import BaseModel, TypeAdapter, ValidationError

from asperity.cases import ANALYSES, load_case
from asperity.cases.keys import case_keys
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


@pytest.mark.parametrize("name, meant", [("ball-on-disk-slow", "did you mean ball-on-disc-slow?"),
                                         ("holmes-rough-cc", "did you mean holmes-rough-CC?")])
def test_a_misspelt_example_is_answered_with_the_name_meant(name, meant):
    """A near miss was answered with all 36 names, cut off in the terminal before the one meant;
    a case-insensitive match is named alone."""
    with pytest.raises(InputError, match=meant):
        example_text(name)


def test_a_folder_given_as_the_case_says_it_is_a_folder(tmp_path):
    with pytest.raises(InputError, match="is a folder; give a .toml file in it"):
        example_text(str(tmp_path))


def test_a_case_file_saved_with_a_byte_order_mark_is_read(tmp_path):
    """Windows editors save UTF-8 with a byte-order mark, which TOML refused at line 1, column 1
    ("Invalid statement")."""
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + example_text("gear-dry-hertz").encode())
    assert load_case(path).loading.load == pytest.approx(962.0)


TOROID = """analysis = "ehl-steady"
[body1]
youngs_modulus = "210 GPa"
[body2]
youngs_modulus = "210 GPa"
[contact]
type = "point"
rx = "30 mm"
ry = "8 mm"
load = "863 N"
[speeds]
u = "10 m/s"
[lubricant]
eta0 = "0.02 Pa s"
alpha = "28 1/GPa"
"""


def test_a_bare_pressure_viscosity_coefficient_is_refused_before_it_runs():
    """A traction-drive user's ``alpha = 28`` (meant 1/GPa, read as 1/Pa): its film estimate
    of 1.4 m asked for a default mesh of 542,009 x 42,345 nodes, and the run was killed for
    memory after 57 s without a word. Now one line names the key and the unit to write; the
    same contact with its unit validates."""
    load_case(TOROID)
    with pytest.raises(InputError) as exc:
        load_case(TOROID.replace('alpha = "28 1/GPa"', "alpha = 28"))
    message = str(exc.value)
    assert message.startswith("lubricant.alpha: expected a pressure-viscosity coefficient")
    assert 'write "20 1/GPa"' in message and "\n" not in message


def test_a_steady_default_mesh_beyond_the_node_limit_is_refused():
    """The traction drive with a 1 Pa s oil at 100 m/s and alpha = 900 1/GPa (within the
    coefficient's range): a film of millimetres whose default mesh of 7,913 x 617 nodes is
    more than a run here can hold; refused naming the default mesh and what to check, as the
    transient case does, instead of running out of memory."""
    huge = TOROID.replace('eta0 = "0.02 Pa s"', 'eta0 = "1 Pa s"').replace(
        'u = "10 m/s"', 'u = "100 m/s"').replace('alpha = "28 1/GPa"', 'alpha = "900 1/GPa"')
    with pytest.raises(InputError, match=r"expected at most 644004 nodes, got \d+ \(the "
                                         r"default mesh \d+ x \d+ .*set grid\.nx"):
        load_case(huge)


def test_an_item_of_a_list_of_tables_is_named_as_the_runners_name_it():
    """A bad region pressure was named pressure.regions.0.pressure by the schema and
    pressure.regions[0] by the runner's own checks."""
    text = example_text("seireg-squares-combined-1").replace('pressure = "20000 psi"',
                                                             'pressure = "10 kg"', 1)
    with pytest.raises(InputError) as err:
        load_case(text)
    assert err.value.field == "pressure.regions[0].pressure"


def test_a_misspelt_required_table_is_named_as_written():
    """``[laoding]`` was answered "loading: missing (a value is required)", naming a table the
    user believes they wrote; the unknown table that reads like it is named instead."""
    text = example_text("rough-sphere-normal").replace("[loading]", "[laoding]")
    with pytest.raises(InputError) as exc:
        load_case(text)
    assert exc.value.field == "laoding"
    assert "did you mean 'loading' (which is missing)?" in str(exc.value)


def test_a_missing_table_with_an_unrelated_unknown_key_is_reported_missing():
    text = example_text("rough-sphere-normal").replace("[loading]", "[colour]")
    with pytest.raises(InputError) as exc:
        load_case(text)
    assert exc.value.field in ("loading", "colour")
    assert "did you mean" not in str(exc.value)


def _models(annotation, found):
    """Every case model an annotation reaches (tables, lists and unions of tables)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        if annotation not in found:
            found.append(annotation)
            for info in annotation.model_fields.values():
                _models(info.annotation, found)
        return found
    for arg in typing.get_args(annotation):
        _models(arg, found)
    return found


def _number_fields(kinds):
    """(model, field name, a valid value) of every field whose key the schema lists as one of
    ``kinds``, over every table of every analysis."""
    fields = []
    found = []
    for analysis in ANALYSES.values():
        _models(analysis, found)
    for model in found:
        for key in case_keys(model):
            if "." in key.key or "[" in key.key or key.type not in kinds or key.unit:
                continue
            info = model.model_fields[key.key]
            bounds = {type(m).__name__: m for m in info.metadata}
            if key.type == "integer":
                low = bounds["Ge"].ge if "Ge" in bounds else 5
                fields.append((model, key.key, low))
            else:
                fields.append((model, key.key, None))
    return fields


def _validate_field(model, name, value):
    info = model.model_fields[name]
    annotation = typing.Annotated[(info.annotation, *info.metadata)] if info.metadata else (
        info.annotation)
    return TypeAdapter(annotation).validate_python(value)


INTEGER_FIELDS = _number_fields({"integer"})


def test_every_integer_key_is_listed_in_the_schema():
    names = {name for _, name, _ in INTEGER_FIELDS}
    assert {"nx", "ny", "seed", "levels", "counting_steps", "snapshots"} <= names


@pytest.mark.parametrize("model, name, value", INTEGER_FIELDS,
                         ids=[f"{m.__name__}.{n}" for m, n, _ in INTEGER_FIELDS])
def test_an_integer_key_takes_a_toml_integer_only(model, name, value):
    """pydantic's lax mode read ``nx = "128"`` as 128 and ``nx = true`` as 1; a count is a TOML
    integer (or a float with no fraction, the same count)."""
    assert _validate_field(model, name, value) == value
    assert _validate_field(model, name, float(value)) == value
    for wrong in (str(value), True, value + 0.5):
        with pytest.raises(ValidationError, match="expected a whole number such as 128"):
            _validate_field(model, name, wrong)


NUMBER_FIELDS = _number_fields({"number"})


@pytest.mark.parametrize("model, name, value", NUMBER_FIELDS,
                         ids=[f"{m.__name__}.{n}" for m, n, _ in NUMBER_FIELDS])
def test_a_number_key_refuses_a_bool(model, name, value):
    with pytest.raises(ValidationError, match="expected a (number|quantity)"):
        _validate_field(model, name, True)


@pytest.mark.parametrize("value, message", [
    ('"128"', "grid.nx: expected a whole number such as 128, got '128'"),
    ("true", "grid.nx: expected a whole number such as 128, got true"),
    ("32.5", "grid.nx: expected a whole number such as 128, got 32.5"),
])
def test_a_quoted_or_true_mesh_size_is_refused_naming_the_key(value, message):
    with pytest.raises(InputError) as exc:
        load_case(BASE.replace("nx = 32", f"nx = {value}"))
    assert str(exc.value) == message


def test_a_mesh_size_written_as_a_float_without_fraction_is_that_count():
    assert load_case(BASE.replace("nx = 32", "nx = 32.0")).grid.nx == 32


def test_a_quoted_or_true_plain_number_is_refused():
    for value in ('"0.3"', "true"):
        with pytest.raises(InputError, match="body2.poisson_ratio: expected a number such as"):
            load_case(BASE.replace("poisson_ratio = 0.3", f"poisson_ratio = {value}"))


@pytest.mark.parametrize("example, old, new, message", [
    ("rough-sphere-normal", 'load = "50 N"', 'lod = "50 N"',
     "loading.lod: unknown key; did you mean 'load'?"),
    ("rough-sphere-normal", "seed = 3", "sed = 3",
     "roughness.sed: unknown key; did you mean 'seed'?"),
    ("seireg-squares-combined-1", 'name = "region 2"', 'nmae = "region 2"',
     "pressure.regions[1].nmae: unknown key; did you mean 'name'?"),
])
def test_an_unknown_key_names_the_key_of_its_table_it_reads_like(example, old, new, message):
    """An unknown key was only "unknown key (check the spelling)"; the table's own key that
    reads like it is named."""
    with pytest.raises(InputError) as exc:
        load_case(example_text(example).replace(old, new, 1))
    assert str(exc.value) == message


@pytest.mark.parametrize("old, new", [
    ('rx = "10 mm"', 'rx = "10 mm"\nrxx = "1 mm"'),  # rx is written: rxx is no misspelt rx
    ("seed = 3", "seed = 3\ncolour = 3"),  # nothing reads like it
])
def test_an_unknown_key_with_no_unwritten_key_like_it_says_check_the_spelling(old, new):
    with pytest.raises(InputError, match=r"unknown key \(check the spelling\)$"):
        load_case(example_text("rough-sphere-normal").replace(old, new, 1))


@pytest.mark.parametrize("rms, message", [
    (0.1, "roughness.rms: expected at most 10 mm, got 0.1 (a bare number is in m: 100 mm)"),
    ('"100 mm"', "roughness.rms: expected at most 10 mm, got '100 mm'"),
    (0, "roughness.rms: expected at least 0.001 nm, got 0"),
])
def test_a_quantity_out_of_its_bounds_is_told_the_bound_in_a_unit(rms, message):
    """``roughness.rms = 0.1`` (meant in um, a bare number in m) was told "expected a value
    less than or equal to 0.01, got 0.1": the bound of the SI value, without a unit. The
    bounds of ``rms`` are 1e-12 m and 1e-2 m (the model's)."""
    text = example_text("rough-flat-normal").replace('rms = "0.5 um"', f"rms = {rms}")
    with pytest.raises(InputError) as info:
        load_case(text)
    assert str(info.value) == message


@pytest.mark.parametrize("example, table, key", [
    ("holmes-smooth-point", "contact", "rx"),
    ("rough-sphere-normal", "geometry", "rx"),
    ("seireg-sphere-torsion", "pressure", "rx"),
])
def test_a_bare_radius_of_metres_is_doubted_with_both_readings(example, table, key):
    """``rx = 9.525`` (a 3/4 in ball's radius typed in mm, read in m) ran a 9.5 m ball: the EHL
    domain is in Hertz semi-axes, so nothing looked wrong. A bare radius of 1 m or more is now
    doubted (:func:`asperity.cases.doubts.unit_doubts`), naming the key, its reading and what
    to write; with a unit, or a bare radius in metres (0.009525), no line."""
    from asperity.cases import parse_toml
    from asperity.cases.doubts import unit_doubts

    def case(value):
        data = parse_toml(example_text(example))
        data[table][key] = value
        data[table].pop("ry", None)   # a sphere's single radius where the example has two
        if example == "holmes-smooth-point":
            data[table]["ry"] = value
        return load_case(data)

    lines = unit_doubts(case(9.525))
    assert lines[0] == (f"{table}.{key}: the bare number 9.525 is read in m, 9.525 m, as a "
                        "radius of relative curvature larger than most contacts have (a bare "
                        "number is in the key's SI unit); if millimetres were meant write "
                        '"9.525 mm", else "9.525 m" to confirm')
    assert unit_doubts(case("9.525 mm")) == [] and unit_doubts(case(0.009525)) == []


@pytest.mark.parametrize("xi, doubted", [(25, True), (-2.5, True), (2.0, False), (0.25, False),
                                         ('"25 %"', False)])
def test_a_slide_roll_ratio_beyond_two_is_doubted(xi, doubted):
    """``xi = 25`` meant as 25 % ran surfaces in opposite directions without a word: at
    u = 25 m/s, u1 = u (1 + xi/2) = 337.5 m/s and u2 = u (1 - xi/2) = -287.5 m/s. Beyond 2
    either way the run now says so; 2 (one surface at rest) and "25 %" (0.25) do not."""
    from asperity.cases.doubts import unit_doubts

    text = example_text("holmes-smooth-point")
    assert "\nxi = 0.25 " in text
    lines = unit_doubts(load_case(text.replace("\nxi = 0.25 ", f"\nxi = {xi} ")))
    assert bool(lines) == doubted
    if xi == 25:
        assert lines == ["speeds.xi: the slide/roll ratio 25 is beyond 2 (limit: at most 2 "
                         "either way), so the surfaces move in opposite directions (u1 = "
                         "337.5 m/s, u2 = -287.5 m/s); a ratio in percent is written \"25 %\" "
                         "(xi = 0.25), and opposite surface speeds are clearer as u1 and u2"]


@pytest.mark.parametrize("eta0, doubted", [(100, True), (10, True), (2, False),
                                           ('"100 mPa s"', False), ('"100 Pa s"', False)])
def test_a_bare_viscosity_beyond_lubricants_is_doubted(eta0, doubted):
    """``eta0 = 100`` (cP meant, read in Pa s) is 100 Pa s, a thousand times the oil: a bare
    viscosity of 10 Pa s or more is doubted, naming the key and what to write; 2 Pa s (a
    heavy gear oil cold, glycerol 1.4) and any value with its unit are not."""
    from asperity.cases.doubts import unit_doubts

    text = example_text("holmes-smooth-point")
    old = next(line for line in text.splitlines() if line.startswith("eta0 = "))
    lines = unit_doubts(load_case(text.replace(old, f"eta0 = {eta0}")))
    assert bool(lines) == doubted
    if eta0 == 100:
        assert lines == ['lubricant.eta0: the bare number 100 is read in Pa s, 100 Pa s, more '
                         'viscous than lubricants are (a bare number is in Pa s); if mPa s (cP) '
                         'were meant write "100 mPa s", else "100 Pa s" to confirm']


def test_a_reference_tolerance_in_percent():
    """``reference.tolerance = "5 %"`` was refused while ``speeds.xi = "25 %"`` was read."""
    from asperity.cases.ehl import ReferenceSpec

    assert ReferenceSpec(source="a rig", central_film="100 nm", tolerance="5 %").tolerance \
        == pytest.approx(0.05)
    with pytest.raises(ValueError, match="less than 1"):
        ReferenceSpec(source="a rig", central_film="100 nm", tolerance="150 %")
