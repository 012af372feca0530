"""Readable quantities: units chosen by magnitude, no float noise, imperial beside SI.

Expected strings are written out by hand from the definitions (1 lbf = 4.4482216 N, 1 psi =
6894.757 Pa, 1 in = 25.4 mm), not computed with the module's own conversions.
"""

import math

import pytest

from asperity.formatting import (
    describe_key,
    format_number,
    format_quantity,
    given_in_imperial,
    summary_rows,
    unit_label,
)


@pytest.mark.parametrize(("value", "text"), [
    (0.0, "0"), (0, "0"), (-0.0, "0"), (962.0, "962"), (962, "962"),
    (0.019100000000000002, "0.0191"), (0.38541666, "0.3854"), (1.0000000000000002, "1"),
    (999.96, "1000"), (123456.0, "123500"), (1e-8, "10⁻⁸"), (7.56334e-9, "7.563×10⁻⁹"),
    (2.5e7, "2.5×10⁷"), (-3.25e-5, "-3.25×10⁻⁵"), (math.nan, "n/a"), (math.inf, "n/a"),
    (True, "yes"),
])
def test_numbers_without_float_noise(value, text):
    assert format_number(value) == text


@pytest.mark.parametrize(("value", "unit", "text"), [
    (1.0464e9, "Pa", "1.046 GPa"),
    (6.9333e8, "Pa", "693.3 MPa"),
    (2.5e5, "Pa", "250 kPa"),
    (8.59746e-6, "m", "8.597 µm"),
    (3.3645e-4, "m", "336.5 µm"),
    (0.0191, "m", "19.1 mm"),
    (2.5e-8, "m", "25 nm"),
    (1.3876e-6, "m^2", "1.388 mm²"),
    (1.3876e-6, "m2", "1.388 mm²"),
    (9608.0, "N", "9.608 kN"),
    (0.5, "N*m", "500 N mm"),
    (2.0, "N m", "2 N m"),
    (3.2, "ms-1", "3.2 1/ms"),
    (38.5, "%", "38.5 %"),
    (4e-6, "s", "4 µs"),
    (0.3, "", "0.3"),
    (7.0, "m/s", "7 m/s"),
])
def test_units_chosen_by_magnitude(value, unit, text):
    assert format_quantity(value, unit) == text


@pytest.mark.parametrize(("unit", "text"), [
    ("N", "0 N"), ("Pa", "0 Pa"), ("m", "0 m"), ("m^2", "0 m²"), ("1/ms", "0 1/ms"),
])
def test_zero_is_zero_in_the_si_unit(unit, text):
    assert format_quantity(0.0, unit) == text


@pytest.mark.parametrize(("value", "unit", "text"), [
    (2160 * 4.4482216, "N", "9.608 kN (2160 lbf)"),          # Seireg's loads in lbf
    (30e6 * 6894.757, "Pa", "206.8 GPa (3×10⁷ psi)"),        # steel's modulus in psi
    (300e3 * 6894.757, "Pa", "2.068 GPa (300000 psi)"),
    (0.6 * 0.0254, "m", "15.24 mm (0.6 in)"),
    (10e-6 * 0.0254, "m", "254 nm (10 µin)"),                # roughness in microinches
    (226.4e-6, "m", "226.4 µm (0.008913 in)"),    # a Hertz semi-axis: it read "(8913 µin)" while
    (884.6e-6, "m", "884.6 µm (0.03483 in)"),     # the other semi-axis of the contact read in in
    (11.74e-6, "m", "11.74 µm (462.2 µin)"),
    (100 * 4.4482216 * 0.0254, "N*m", "11.3 N m (100 in lbf)"),
])
def test_imperial_beside_si(value, unit, text):
    assert format_quantity(value, unit, imperial=True) == text


def test_no_imperial_for_units_without_one():
    assert format_quantity(0.25, "", imperial=True) == "0.25"
    assert format_quantity(12.0, "%", imperial=True) == "12 %"


@pytest.mark.parametrize(("key", "label", "unit"), [
    ("max_pressure_pa", "maximum pressure", "Pa"),
    ("contact_area_m2", "contact area", "m^2"),
    ("gross_slip_moment_nm", "gross slip moment", "N*m"),    # nm is N m in summary keys
    ("u1_m_s", "surface speed u1", "m/s"),
    ("max_contact_count_rate_per_ms", "maximum contact count rate", "1/ms"),
    ("contact_time_percent", "contact time", "%"),
    ("contact_area_fraction", "contact area fraction", "%"),
    ("load_n", "load", "N"),
    ("iterations", "iterations", ""),
    ("timestep_s", "timestep", "s"),
    ("max_flash_temperature_k", "maximum flash temperature", "K"),     # a rise, in kelvin
    ("max_contact_temperature_c", "maximum contact temperature", "°C"),
    ("working_pressure_angle_deg", "working pressure angle", "deg"),
    ("moes_k", "Moes k", ""),                                          # _k only after temperature
    ("ra_m", "Ra", "m"),                                               # ISO 4287 spellings
    ("rsk_b", "Rsk (B)", ""),                                          # profile B's skewness
    ("iso_wdq", "ISO Wdq", ""),
    ("iso_mr1", "ISO Mr1", ""),
    ("hamrock_dowson_central_film_m", "Hamrock-Dowson central film", "m"),   # one formula's
    ("brewe_hamrock_taylor_minimum_film_m", "Brewe-Hamrock-Taylor minimum film", "m"),
    ("moes_central_film_m", "Moes central film", "m"),
    ("martin_minimum_film_m", "Martin minimum film", "m"),       # it read "martin minimum film"
    ("moment_center_x_m", "moment centre x", "m"),             # the case key keeps "center"
    ("slide_roll_ratio", "slide/roll ratio", ""),
    ("fixed_point_distance_pressure_fraction", "last step's pressure change, relaxed further",
     "%"),                                        # it read "fixed point distance pressure fraction"
])
def test_summary_keys_in_words(key, label, unit):
    assert describe_key(key) == (label, unit)


def test_summary_rows_label_format_and_skip_lists():
    rows = summary_rows({"max_pressure_pa": 1.0464e9, "contact_area_fraction": 0.385,
                         "load_n": 2160 * 4.4482216, "converged": True, "surfaces": ["A"],
                         "kind": "gaussian"}, imperial=True)
    by_key = {r.key: r for r in rows}
    assert "surfaces" not in by_key
    assert by_key["max_pressure_pa"].text == "1.046 GPa (151800 psi)"
    assert by_key["contact_area_fraction"].text == "38.5 %"
    assert by_key["load_n"].text == "9.608 kN (2160 lbf)"
    assert by_key["converged"].text == "yes"
    assert by_key["kind"].text == "gaussian"
    assert by_key["max_pressure_pa"].unit == "Pa"


def test_a_quantity_given_twice_is_one_row():
    """A transient run's summary has the contact time as a fraction and in percent; the CLI
    and the report showed "contact time ... 0.4 %" twice. Different values stay two rows."""
    rows = summary_rows({"contact_time_fraction": 0.004, "max_pressure_pa": 9.56e8,
                         "contact_time_percent": 0.4})
    assert [(r.label, r.text) for r in rows] == [("contact time", "0.4 %"),
                                                 ("maximum pressure", "956 MPa")]
    rows = summary_rows({"contact_time_fraction": 0.004, "contact_time_percent": 0.5})
    assert [r.text for r in rows] == ["0.4 %", "0.5 %"]


def test_unit_labels():
    assert unit_label("m2") == "m²"
    assert unit_label("ms-1") == "1/ms"
    assert unit_label("1") == ""
    assert unit_label("N m") == "N m"


@pytest.mark.parametrize(("data", "imperial"), [
    ({"loading": {"load": "2160 lbf"}}, True),
    ({"body1": {"youngs_modulus": "30e6 psi"}}, True),
    ({"geometry": {"rx": "0.6 in"}}, True),
    ({"speeds": ["3 ft/s"]}, True),
    ({"geometry": {"rx": "25 mm"}, "loading": {"load": "5 kN"}}, False),   # millimetre != mil
    ({"title": "Tin 1 in a gear", "load": 5.0}, False),                     # text, not a value
])
def test_imperial_input_detected(data, imperial):
    assert given_in_imperial(data) is imperial


def test_round_off_of_zero_shown_as_zero():
    # a force along an unloaded axis comes out as 3e-13 N beside a 48 kN load: zero, not noise
    rows = {r.key: r.text for r in summary_rows(
        {"normal_load_n": 48040.0, "force_x_n": 3.269e-13, "force_y_n": 5338.0,
         "shift_m": 2.606e-6, "shift_x_m": 1.2e-22, "residual": 5.24e-9})}
    assert rows["force_x_n"] == "0 N"
    assert rows["shift_x_m"] == "0 m"
    assert rows["force_y_n"] == "5.338 kN"
    assert rows["residual"] == "5.24×10⁻⁹"      # dimensionless numbers are never rounded away


def test_swept_values_as_shown_in_a_study():
    from asperity.formatting import format_axis_value

    assert format_axis_value(math.pi / 2, "rad") == "90 deg"       # angles as written
    assert format_axis_value(0.005, "m") == "5 mm"
    assert format_axis_value(1.5e-7, "m2") == "0.15 mm²"
    assert format_axis_value("steel-al", "1") == "steel-al"


@pytest.mark.parametrize("key, label", [
    ("iso_elasticity_factor_sqrt_mpa", "ISO 6336-2 elasticity factor Z_E (√MPa)"),
    ("iso_nominal_contact_stress_pa", "ISO 6336-2 nominal contact stress sigma_H0")])
def test_the_iso_6336_rows_of_a_gear_summary_read_as_the_standard_writes_them(key, label):
    """The elasticity factor's row read "ISO elasticity factor sqrt mpa"."""
    assert describe_key(key)[0] == label


@pytest.mark.parametrize("value, unit, text", [
    (0.9999999999, "N", "1 N"), (0.99996, "m", "1 m"), (999.99996, "N", "1 kN"),
    (0.99994, "N", "999.9 mN")])
def test_a_value_that_rounds_up_to_the_next_unit_is_written_in_it(value, unit, text):
    """A gross-slip excess force of 0.9999999999 N was written "1000 mN": the unit is chosen
    from the value as it is printed, to 4 digits."""
    assert format_quantity(value, unit) == text


def test_a_standard_error_is_shown_beside_its_value():
    """``K_standard_error`` takes the unit of ``K`` and joins its row as ``value ± error``
    (a fraction in percent, the unit written once when both share it); without ``K`` it has
    a row of its own, and a NaN error (none estimated) leaves the value alone."""
    rows = summary_rows({"contact_time_fraction": 0.655,
                         "contact_time_fraction_standard_error": 0.0717,
                         "max_contact_count_rate_per_ms": 267.5,
                         "max_contact_count_rate_per_ms_standard_error": 71.05,
                         "max_pressure_pa": 3.66e9,
                         "max_pressure_pa_standard_error": float("nan"),
                         "approach_m_standard_error": 2e-9})
    assert [(r.label, r.text) for r in rows] == [
        ("contact time", "65.5 ± 7.2 %"),
        ("maximum contact count rate", "267.5 ± 71 1/ms"),
        ("maximum pressure", "3.66 GPa"),
        ("approach, standard error", "2 nm")]
    assert describe_key("contact_time_fraction_standard_error") == (
        "contact time, standard error", "%")
