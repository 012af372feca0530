"""The study figure and report: cases that did not converge or carry warnings drawn apart and
named alike in the table; log x ticks whose labels do not run together; a gear study's pitch
film and lambda among its panels."""

from __future__ import annotations

import itertools

import numpy as np
import pytest
import xarray as xr

from asperity.plotting.study import log_tick_values, plot_study
from asperity.report import render_study_report, study_case_marks, study_variables

MESH_WARNING = ("mesh: the minimum film (1.071 nm at x = 0.159 a, y = 0.972 b) is not resolved "
                "across y (dy = b/36, the film at the nodes beside it thicker by 397 %): "
                "estimated error over 100 %; about 2 % needs nx >= 300")
PECLET_WARNING = "flash temperature: Peclet number down to 2.2 < 5 at 2 point(s)"


def _study(name: str, x, results: dict, converged, warnings, *, scale: str = "linear",
           unit: str = "m s-1", title: str = "probe") -> xr.Dataset:
    """A study.nc as ``asperity.sweep.combine`` writes it, on one axis ``name``."""
    n = len(x)
    data = {key: ((name,), np.asarray(values, dtype=float), {"long_name": key, "units": u})
            for key, (values, u) in results.items()}
    data["state"] = ((name,), np.array(["done"] * n))
    data["converged"] = ((name,), np.asarray(converged, dtype=float))
    data["warnings"] = ((name,), np.array(warnings, dtype=str))
    data["error"] = ((name,), np.array([""] * n))
    data["convergence"] = ((name,), np.array(
        ["" if c else "The solver did not converge in 3 sweeps" for c in converged]))
    coords = {name: ((name,), np.asarray(x, dtype=float),
                     {"units": unit, "long_name": name.replace("__", "."), "scale": scale})}
    return xr.Dataset(data, coords=coords, attrs={"title": title, "mode": "cross",
                                                  "axes": name})


def _film_study() -> xr.Dataset:
    """Four speeds: the first warned of a mesh error over 100 %, the third not converged, the
    fourth with another warning."""
    return _study("speeds__u", [1.0, 2.0, 4.0, 8.0],
                  {"minimum_film_thickness_m": ([10e-9, 20e-9, -4e-9, 60e-9], "m")},
                  converged=[1, 1, 0, 1], warnings=[MESH_WARNING, "", "", PECLET_WARNING])


def _legend_texts(ax) -> list[str]:
    legend = ax.get_legend()
    return [] if legend is None else [t.get_text() for t in legend.get_texts()]


def test_each_case_is_marked_by_its_convergence_and_warnings():
    marks = study_case_marks(_film_study())
    assert list(marks.values) == ["mesh error over 100 %", "", "not converged",
                                  "with warnings"]
    assert marks.dims == ("speeds__u",)


def test_a_case_that_did_not_converge_is_a_red_cross_off_the_line():
    """The probe's gear study drew its unconverged case (a negative film) joined to the good
    one like a trend; the line now breaks there and the case is a red cross of its own."""
    ax = plot_study(_film_study(), ["minimum_film_thickness_m"]).axes[0]
    line = ax.get_lines()[0]
    x, y = line.get_data()
    assert list(x) == [1.0, 2.0, 4.0, 8.0]
    assert y[0] == pytest.approx(10.0) and y[1] == pytest.approx(20.0)
    assert np.isnan(y[2]) and y[3] == pytest.approx(60.0)  # in nm; the line breaks at 4 m/s
    assert list(line.get_markevery()) == [1]  # a filled dot at the one clean case only
    crosses = [ln for ln in ax.get_lines() if ln.get_marker() == "x"]
    assert len(crosses) == 1 and crosses[0].get_color() == "red"
    assert list(crosses[0].get_xdata()) == [4.0]
    assert list(crosses[0].get_ydata()) == pytest.approx([-4.0])
    assert "not converged (not a solution)" in _legend_texts(ax)


def test_warned_cases_are_hollow_markers_named_in_the_legend():
    ax = plot_study(_film_study(), ["minimum_film_thickness_m"]).axes[0]
    squares = [ln for ln in ax.get_lines() if ln.get_marker() == "s"]
    circles = [ln for ln in ax.get_lines() if ln.get_marker() == "o" and ln.get_linestyle()
               == "None"]
    assert [list(ln.get_xdata()) for ln in squares] == [[1.0]]
    assert [list(ln.get_xdata()) for ln in circles] == [[8.0]]
    assert squares[0].get_markerfacecolor() == circles[0].get_markerfacecolor() == "white"
    assert _legend_texts(ax) == ["not converged (not a solution)",
                                 "mesh error over 100 % (warning)",
                                 "with warnings (see the report)"]


def test_a_clean_single_line_has_no_legend():
    ds = _study("speeds__u", [1.0, 2.0, 4.0], {"minimum_film_thickness_m": (
        [10e-9, 20e-9, 30e-9], "m")}, converged=[1, 1, 1], warnings=["", "", ""])
    ax = plot_study(ds, ["minimum_film_thickness_m"]).axes[0]
    assert ax.get_legend() is None
    assert [ln.get_marker() for ln in ax.get_lines()] == ["o"]


def test_the_unit_of_a_panel_follows_the_cases_that_converged():
    """A failed solve's 11.3 MN made the good case's 5.7 kN read 0.0057 MN."""
    ds = _study("operation__torque", [200.0, 400.0], {"normal_force_n": ([5.7e3, 1.13e7],
                                                                         "N")},
                converged=[1, 0], warnings=["", ""], unit="N m")
    ax = plot_study(ds, ["normal_force_n"]).axes[0]
    assert ax.get_ylabel().endswith("(kN)")
    assert list(ax.get_lines()[0].get_ydata())[0] == pytest.approx(5.7)


def test_the_table_of_cases_says_what_the_figure_draws():
    html = render_study_report(_film_study())
    assert "<span class=caution>done, mesh error over 100 %</span>" in html
    assert "<span class=fail>not converged</span>" in html
    assert "<span class=caution>done, with warnings</span>" in html
    assert html.count("<span class=pass>done</span>") == 1


@pytest.mark.parametrize(("x", "expected"), [
    (np.geomspace(0.01, 2.0, 7), [0.01, 0.03, 0.1, 0.3, 1.0]),  # the probe's speed sweep
    (np.geomspace(5.0, 80.0, 4), [5.0, 10.0 * 2**0.333333333333, 31.748021039, 80.0]),
    # 8 values over 3 decades: "2.683" beside "7.197" crowd, and 10 beside 20 at 1-2-5
    (np.geomspace(1.0, 1000.0, 8), [1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0]),
    # 6 decades: "0.001" beside "0.01" crowd; every second power of ten
    (np.geomspace(1e-3, 1e3, 12), [1e-2, 1.0, 100.0]),
])
def test_log_ticks_stand_apart(x, expected):
    """Swept values where their labels stand apart, else round multiples of the decades."""
    ticks = log_tick_values(x, width_pt=223.2, size_pt=10.0)
    assert list(ticks) == pytest.approx(expected, rel=1e-6)


def test_log_tick_labels_of_a_seven_point_speed_sweep_do_not_overlap():
    """0.01-2 m/s in 7 log steps was labelled at each swept value, "0.02418" running into
    "0.05848" on every panel."""
    x = np.geomspace(0.01, 2.0, 7)
    ds = _study("speeds__u", x, {"central_film_thickness_m": (11e-9 * (x / 0.01)**0.67, "m"),
                                 "max_pressure_pa": (829e6 + 30e6 * x, "Pa")},
                converged=[1] * 7, warnings=[""] * 7, scale="log")
    fig = plot_study(ds, ["central_film_thickness_m", "max_pressure_pa"])
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        labels = [t for t in ax.get_xticklabels(which="both")
                  if t.get_visible() and t.get_text()
                  and ax.get_xlim()[0] <= t.get_position()[0] <= ax.get_xlim()[1]]
        assert [t.get_text() for t in labels] == ["0.01", "0.03", "0.1", "0.3", "1"]
        boxes = sorted((t.get_window_extent(renderer) for t in labels), key=lambda b: b.x0)
        assert all(right.x0 - left.x1 > 5.0 for left, right in itertools.pairwise(boxes))


def test_a_gear_study_draws_its_pitch_film_and_lambda():
    """The pitch point's film and lambda had been left out for the normal force and F_t,
    which only follow the torque; those now come last."""
    torque = [100.0, 200.0, 300.0, 400.0]
    rising = np.array([1.0, 2.0, 3.0, 4.0])
    keys = {"minimum_lambda": "1", "minimum_film_m": "m", "maximum_flash_temperature_k": "K",
            "maximum_hertz_pressure_pa": "Pa", "normal_force_n": "N",
            "maximum_contact_temperature_c": "degC", "pitch_hertz_pressure_pa": "Pa",
            "iso_nominal_contact_stress_pa": "Pa", "iso_nominal_tangential_force_n": "N",
            "pitch_minimum_film_m": "m", "pitch_lambda": "1"}
    ds = _study("operation__torque", torque, {k: (rising * (n + 1), u)
                                              for n, (k, u) in enumerate(keys.items())},
                converged=[1] * 4, warnings=[""] * 4, unit="N m")
    assert study_variables(ds) == [
        "minimum_lambda", "minimum_film_m", "maximum_flash_temperature_k",
        "maximum_hertz_pressure_pa", "pitch_minimum_film_m", "pitch_lambda",
        "maximum_contact_temperature_c", "pitch_hertz_pressure_pa",
        "iso_nominal_contact_stress_pa"]
    assert study_variables(ds, limit=11)[-2:] == ["normal_force_n",
                                                  "iso_nominal_tangential_force_n"]
