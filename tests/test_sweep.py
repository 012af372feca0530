"""Parameter studies: Dask matches serial, failures are recorded, interrupted studies resume."""

import itertools
import json
import math
import re
import subprocess
import sys
import time

import numpy as np
import pytest
import xarray as xr

from asperity.ehl.checkpoint import Checkpointer
from asperity.errors import InputError
from asperity.sweep import load_study, local_cluster, run_one, run_study

BASE = """
analysis = "normal"
title = "small sphere"
source = "a handbook"
[body1]
youngs_modulus = "210 GPa"
[body2]
youngs_modulus = "210 GPa"
[geometry]
shape = "sphere"
rx = "10 mm"
[loading]
load = "20 N"
[grid]
nx = 24
ny = 24
x_extent = "0.5 mm"
y_extent = "0.5 mm"
"""


def _study(tmp_path, axes, mode="cross"):
    (tmp_path / "base.toml").write_text(BASE)
    path = tmp_path / "study.toml"
    path.write_text(f'title = "t"\nbase = "base.toml"\nmode = "{mode}"\n' + axes)
    return load_study(path)


AXES = """
[[axis]]
key = "loading.load"
values = ["5 N", "10 N", "20 N"]
[[axis]]
key = "geometry.rx"
range = {start = 5, stop = 10, num = 2, unit = "mm"}
"""


@pytest.fixture(scope="module")
def cross_study(tmp_path_factory):
    tmp_path = tmp_path_factory.mktemp("cross")
    study = _study(tmp_path, AXES)
    return study, run_study(study, tmp_path / "out"), tmp_path / "out"


def test_cross_study_has_the_axes_as_dimensions(cross_study):
    study, ds, out = cross_study
    assert len(study.cases) == 6
    assert ds["max_pressure_pa"].dims == ("loading__load", "geometry__rx")
    assert np.allclose(ds["loading__load"], [5, 10, 20])
    assert np.allclose(ds["geometry__rx"], [0.005, 0.01])
    assert (ds["state"] == "done").all()
    # Hertz: p_max grows like P^(1/3) at fixed radius
    p = ds["max_pressure_pa"].sel(geometry__rx=0.01).values
    assert p[2] / p[0] == pytest.approx(4 ** (1 / 3), rel=0.03)
    with xr.open_dataset(out / "study.nc") as saved:
        assert saved["load_n"].shape == (3, 2)


def test_every_variable_of_study_nc_has_units(cross_study):
    _, _, out = cross_study
    with xr.open_dataset(out / "study.nc") as ds:
        for name, var in {**ds.data_vars, **ds.coords}.items():
            assert var.attrs.get("units"), name
            assert var.attrs.get("long_name"), name
        # CF spellings of the summary keys' units; the swept quantities in SI
        assert ds["max_pressure_pa"].attrs["units"] == "Pa"
        assert ds["contact_area_m2"].attrs["units"] == "m2"
        assert ds["contact_area_fraction"].attrs["units"] == "1"
        assert ds["max_pressure_pa"].attrs["long_name"] == "maximum pressure"
        assert ds["loading__load"].attrs["units"] == "N"
        assert ds["geometry__rx"].attrs["units"] == "m"


def test_study_report_plots_results_against_the_axes_and_lists_cases(cross_study):
    _, _, out = cross_study
    html = (out / "report.html").read_text()
    assert (out / "study.png").stat().st_size > 10_000
    assert html.count("data:image/png;base64,") == 1
    assert html.count("<tr><td>00") == 6                  # one row per case
    # axis values in one unit per column, named in the heading
    assert "<th>geometry.<wbr>rx (mm)</th>" in html and "<th>loading.<wbr>load (N)</th>" in html
    assert "<td>10</td>" in html and "<td>5</td>" in html
    assert "maximum pressure" in html and "max_pressure_pa" not in html
    assert "6 of 6 cases done" in html
    # a long key may wrap after its dots and the table scrolls on its own: at 1200 px a study of
    # loading.load x body2.youngs_modulus had pushed its last column off the page
    assert "<th>geometry.<wbr>rx (mm)</th>" in html and "<div class=scroll><table>" in html


def test_dask_two_workers_match_serial_and_share_the_cores(tmp_path):
    """The local cluster of the command line: same numbers as a serial run, and each of two
    workers on two cores runs numba on one thread, not two."""
    from dask.distributed import Client

    study = _study(tmp_path, AXES)
    serial = run_study(study, tmp_path / "serial")
    with local_cluster(2, cores=2) as cluster, Client(cluster) as client:
        parallel = run_study(study, tmp_path / "dask", client=client)

        def pools():
            import numba
            return numba.config.NUMBA_NUM_THREADS, numba.get_num_threads()

        assert set(client.run(pools).values()) == {(1, 1)}
    for key in ("max_pressure_pa", "contact_area_m2", "approach_m"):
        np.testing.assert_allclose(parallel[key], serial[key], rtol=1e-12)


def test_failing_case_is_recorded_and_others_run(tmp_path, monkeypatch):
    import asperity.runners

    real = asperity.runners.run_case

    def flaky(case, progress=None, **folder):
        if case.loading.load == 10.0:
            raise RuntimeError("solver exploded")
        return real(case, progress, **folder)

    monkeypatch.setattr(asperity.runners, "run_case", flaky)
    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = [5, 10, 20]\n')
    ds = run_study(study, tmp_path / "out")
    assert list(ds["state"].values) == ["done", "failed", "done"]
    assert "solver exploded" in str(ds["error"].values[1])
    assert np.isnan(ds["max_pressure_pa"].values[1]) and ds["max_pressure_pa"].values[2] > 0


def test_bad_study_is_one_line(tmp_path):
    with pytest.raises(InputError, match="case 1"):
        _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "5 kg"]\n')
    with pytest.raises(InputError, match="axis"):
        _study(tmp_path, "")


def test_zip_axes_of_unequal_length_and_key_with_keys_say_what_is_wrong(tmp_path):
    """"axis: expected axes of equal length" named neither the axes nor their lengths; key
    beside keys read "expected lists of 2 values, one per key"."""
    zipped = ('[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "10 N", "20 N"]\n'
              '[[axis]]\nkey = "geometry.rx"\nvalues = ["5 mm", "10 mm"]\n')
    with pytest.raises(InputError) as info:
        _study(tmp_path, zipped, mode="zip")
    assert "loading.load: 3, geometry.rx: 2" in str(info.value)
    both = ('[[axis]]\nkey = "loading.load"\nkeys = ["loading.load", "geometry.rx"]\n'
            'values = [["5 N", "5 mm"]]\n')
    with pytest.raises(InputError) as info:
        _study(tmp_path, both)
    assert str(info.value).startswith("axis[0]: give key") and "not both" in str(info.value)


@pytest.mark.parametrize("range_text, field", [
    ('{start = 1, stop = 5, num = 2.5, unit = "N"}', "axis[0].range.num"),   # ran 2 cases
    ('{start = 1, stop = 5, num = 1, unit = "N"}', "axis[0].range.num"),     # ran 1 N only
    ('{start = 1, stop = 5, num = 3, units = "kN"}', "axis[0].range.units"),  # ran 1-5 N
])
def test_a_range_that_would_run_other_cases_than_written_is_refused(tmp_path, range_text, field):
    """A fractional or single-value ``num`` and a misspelt ``unit`` ran cases the study did not
    describe (``num = 2.5`` two cases, ``units = "kN"`` loads in newtons) in silence."""
    with pytest.raises(InputError) as err:
        _study(tmp_path, f'[[axis]]\nkey = "loading.load"\nrange = {range_text}\n')
    assert err.value.field == field


def test_interrupted_study_resumes_each_case_once(tmp_path):
    axes = '[[axis]]\nkey = "loading.load"\nrange = {start = 5, stop = 40, num = 8, unit = "N"}\n'
    study = _study(tmp_path, axes)
    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "asperity.cli", "sweep", str(tmp_path / "study.toml"),
           "--out", str(out), "--serial", "--quiet"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    deadline = time.time() + 120
    while time.time() < deadline and len(list(out.glob("cases/*/status.json"))) < 2:
        time.sleep(0.05)
    proc.kill()
    proc.wait()
    states = {p.parent.name: json.loads(p.read_text()) for p in out.glob("cases/*/status.json")}
    assert all(s["state"] == "done" for s in states.values()), states
    finished = {p.parent.name: p.stat().st_mtime_ns for p in out.glob("cases/*/status.json")}
    assert 2 <= len(finished) < 8, "the run was not interrupted mid-way"
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    after = {p.parent.name: p.stat().st_mtime_ns for p in out.glob("cases/*/status.json")}
    assert sorted(after) == [c for c, _, _ in study.cases]
    assert all(after[c] == t for c, t in finished.items()), "a finished case ran again"
    with xr.open_dataset(out / "study.nc") as ds:
        assert (ds["state"] == "done").all() and ds.sizes["loading__load"] == 8


def test_axis_with_several_keys_is_one_labelled_dimension(tmp_path):
    axes = """
[[axis]]
name = "shape"
keys = ["geometry.rx", "loading.load"]
values = [["5 mm", "10 N"], ["10 mm", "20 N"]]
labels = ["small", "large"]
[[axis]]
key = "grid.nx"
values = [16, 24]
"""
    study = _study(tmp_path, axes)
    assert len(study.cases) == 4
    ds = run_study(study, tmp_path / "out")
    assert list(ds["shape"].values) == ["small", "large"]
    np.testing.assert_allclose(ds["load_n"].sel(shape="large").values, [20.0, 20.0])
    # the labelled axis is the x axis of the study figure, its labels in the table of cases
    html = (tmp_path / "out" / "report.html").read_text()
    assert html.count("<td>small</td>") == 2 and html.count("<td>large</td>") == 2
    assert (tmp_path / "out" / "study.png").is_file()
    with pytest.raises(InputError, match="axis\\[0\\].values"):
        _study(tmp_path, '[[axis]]\nkeys = ["a.b", "c.d"]\nvalues = [[1]]\n')


def test_axis_in_imperial_units_is_stored_in_si_with_its_unit(tmp_path):
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["2 lbf", "4 lbf"]\n')
    ds = combine(study, tmp_path / "none")      # nothing run: the coordinates alone
    np.testing.assert_allclose(ds["loading__load"].values, [8.8964432, 17.7928864], rtol=1e-7)
    assert ds["loading__load"].attrs["units"] == "N"
    assert (ds["state"] == "missing").all()


def test_study_table_shows_flags_and_round_off_as_people_read_them(tmp_path):
    from asperity.report import render_study_report
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "10 N"]\n')
    out = tmp_path / "out"
    for n, (slip, fx) in enumerate([(False, 2.669e3), (True, 3.3e-13)]):  # 3.3e-13 N: zero
        folder = out / "cases" / f"{n:04d}"
        folder.mkdir(parents=True)
        (folder / "status.json").write_text(json.dumps(
            {"state": "done", "summary": {"gross_slip": slip, "force_x_n": fx}}))
    ds = combine(study, out)
    assert ds["gross_slip"].attrs["flag_meanings"] == "no yes"   # CF flags for a yes/no
    html = render_study_report(ds)
    assert "<td>no</td>" in html and "<td>yes</td>" in html
    assert "<th>force x (kN)</th>" in html
    assert "<td>2.669</td>" in html and "<td>0</td>" in html


def test_study_table_shows_fractions_in_percent_as_a_run_report_does(tmp_path):
    from asperity.report import render_study_report
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "10 N"]\n')
    out = tmp_path / "out"
    for n, fraction in enumerate([0.385, 0.5]):
        folder = out / "cases" / f"{n:04d}"
        folder.mkdir(parents=True)
        (folder / "status.json").write_text(json.dumps(
            {"state": "done", "summary": {"contact_area_fraction": fraction}}))
    ds = combine(study, out)
    assert ds["contact_area_fraction"].attrs["units"] == "1"    # stored as a fraction
    html = render_study_report(ds)
    assert "<th>contact area fraction (%)</th>" in html
    assert "<td>38.5</td>" in html and "<td>50</td>" in html


@pytest.mark.parametrize(("values", "expected", "units"), [
    (["0 deg", "90 deg", "180 deg"], [0.0, math.pi / 2, math.pi], "rad"),   # angles in radians
    (["10 %", "25 %"], [0.1, 0.25], "1"),                                   # ratios as fractions
    (["0.5 in", "1 in"], [0.0127, 0.0254], "m"),
    (["11.1 1/GPa"], [11.1e-9], "Pa-1"),                                   # CF spelling
    (["steel", "bronze"], ["steel", "bronze"], "1"),                        # labels stay text
])
def test_axis_values_in_the_si_unit_of_their_dimension(values, expected, units):
    from asperity.sweep import _coordinate

    array, unit = _coordinate(values)
    assert unit == units
    if isinstance(expected[0], str):
        assert list(array) == expected
    else:
        np.testing.assert_allclose(array, expected, rtol=1e-12)


def _paper_cases(name):
    from asperity.cases import load_case

    return [(coords, load_case(case)) for _, case, coords in load_study(name).cases]


def test_seed_mesh_studies_run_the_paper_example():
    """The seed-resolution studies (issue 17) are the paper example's mesh, domain and counting
    period with only the swept keys changed; Table 2's paper values agree with the examples
    that carry them (holmes-rough-AA, -BB, -CC, -AC, -C-smooth, -sqrt2C-smooth at xi = 0.25)."""
    from asperity.cases import load_case
    from asperity.examples import example_text

    for name, count in [("holmes-table2-paper", 14), ("holmes-aspect-ratio-paper", 3),
                        ("holmes-transverse-waviness-paper", 6), ("holmes-mesh-CC", 4)]:
        cases = _paper_cases(name)
        assert len(cases) == count
        for _, case in cases:
            assert (case.grid.x_min, case.grid.x_max, case.grid.y_min, case.grid.y_max) \
                == (-2.5, 1.5, -2.0, 2.0)
            assert case.surface1.lowpass == 0 and case.surface2.lowpass == 0
    for _, case in _paper_cases("holmes-table2-paper"):
        assert (case.grid.nx, case.grid.ny, case.time.counting_steps) == (801, 201, 2370)
    table2 = {(c.surface1.profile, c.surface1.scale,
               c.surface2.profile if c.surface2.kind != "smooth" else None, c.speeds.xi):
              c.paper_contact_time_percent for _, c in _paper_cases("holmes-table2-paper")}
    assert len(table2) == 14
    for example in ["AA", "BB", "CC", "AC", "C-smooth", "sqrt2C-smooth"]:
        c = load_case(example_text(f"holmes-rough-{example}"))
        key = (c.surface1.profile, c.surface1.scale,
               c.surface2.profile if c.surface2.kind != "smooth" else None, c.speeds.xi)
        assert table2[key] == c.paper_contact_time_percent
    # the mesh study keeps the counting time: 2370 steps at dx = a/200, dt = dx / (2 u1)
    for _, case in _paper_cases("holmes-mesh-CC"):
        assert case.time.counting_steps / (case.grid.nx - 1) == pytest.approx(2370 / 800, rel=1e-3)
        assert (case.grid.ny - 1) * 4 == case.grid.nx - 1


def test_unset_removes_a_base_key_from_every_case(tmp_path):
    """``unset`` drops a key of the base case (here its source); a key the base does not set
    is refused, naming the entry."""
    study = _study(tmp_path, 'unset = ["source"]\n[[axis]]\nkey = "loading.load"\n'
                             'values = ["5 N", "10 N"]\n')
    assert all("source" not in case and case["grid"]["nx"] == 24 for _, case, _ in study.cases)
    with pytest.raises(InputError, match=r"unset\[0\]"):
        _study(tmp_path, 'unset = ["grid.z_extent"]\n[[axis]]\nkey = "loading.load"\n'
                         'values = ["5 N"]\n')


def test_derived_studies_do_not_compare_with_the_base_paper_value():
    """The aspect-ratio and waviness studies are built on the C-C example, whose Table 2 value
    (95 %) is not the paper's number for their cases."""
    from asperity.cases import load_case

    for name in ["holmes-aspect-ratio", "holmes-aspect-ratio-paper",
                 "holmes-transverse-waviness", "holmes-transverse-waviness-paper"]:
        for _, case, _ in load_study(name).cases:
            assert load_case(case).paper_contact_time_percent is None
    assert {load_case(c).paper_contact_time_percent
            for _, c, _ in load_study("holmes-mesh-CC").cases} == {95}


def test_study_shows_a_quantity_stored_as_fraction_and_percent_once(tmp_path):
    """The transient summary holds the contact time as a fraction and in percent; the study's
    plots and table show it once (they showed two identical 'contact time' panels)."""
    from asperity.report import study_variables
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "10 N"]\n')
    out = tmp_path / "out"
    for n, fraction in enumerate([0.351, 0.988]):
        folder = out / "cases" / f"{n:04d}"
        folder.mkdir(parents=True)
        (folder / "status.json").write_text(json.dumps({"state": "done", "summary": {
            "contact_time_fraction": fraction, "contact_time_percent": 100 * fraction,
            "contact_time_percent_standard_error": 4.2 + n, "max_pressure_pa": 2e9 + n}}))
    ds = combine(study, out)
    assert ds["contact_time_fraction"].attrs["long_name"] == \
        ds["contact_time_percent"].attrs["long_name"]
    # a standard error (session 39) is no column of its own: it stands beside its value
    assert study_variables(ds) == ["contact_time_percent", "max_pressure_pa"]
    from asperity.report import render_study_report

    html = render_study_report(ds)
    assert "<th>contact time (%)</th>" in html
    assert "<td>35.1 ± 4.2</td>" in html and "<td>98.8 ± 5.2</td>" in html


def test_each_case_is_titled_by_its_own_axis_values(tmp_path):
    """A case's title and description name what its axes set (by label where the axis has
    labels), not the base's title: the base "small sphere" at 20 N would otherwise title a
    5 N case. In zip mode repeated values keep their own position's label."""
    study = _study(tmp_path, AXES)
    titles = [case["title"] for _, case, _ in study.cases]
    assert titles[0] == "t: loading.load = 5 N, geometry.rx = 5 mm"
    assert titles[-1] == "t: loading.load = 20 N, geometry.rx = 10 mm"
    assert "loading.load = 10 N; geometry.rx = 5 mm" in study.cases[2][1]["description"]
    zipped = _study(tmp_path, '[[axis]]\nname = "pair"\nkeys = ["loading.load", "geometry.rx"]\n'
                              'values = [["5 N", "5 mm"], ["5 N", "5 mm"]]\n'
                              'labels = ["first", "second"]\n', mode="zip")
    assert [case["title"] for _, case, _ in zipped.cases] == ["t: pair = first", "t: pair = second"]
    titled = _study(tmp_path, '[[axis]]\nkey = "title"\nvalues = ["mine"]\n')
    assert titled.cases[0][1]["title"] == "mine"


def test_killed_long_case_of_a_study_resumes_from_its_checkpoint(tmp_path, monkeypatch):
    """A transient case of a study checkpoints into its case folder: killed mid-run and run
    again, it goes on from the checkpoint (not from step 0) and ends with the numbers of an
    uninterrupted run."""
    (tmp_path / "study.toml").write_text(
        'title = "t"\nbase = "holmes-rough-CC"\n[[axis]]\nname = "short"\n'
        'keys = ["grid.nx", "grid.ny", "time.warmup_steps", "time.counting_steps", '
        '"solver.checkpoint_every"]\nvalues = [[65, 33, 10, 30, 4]]\n')
    study = load_study(tmp_path / "study.toml")
    whole = run_one(study.cases[0][1], str(tmp_path / "whole"))
    assert whole["state"] == "done", whole

    out = tmp_path / "out"
    cmd = [sys.executable, "-m", "asperity.cli", "sweep", str(tmp_path / "study.toml"),
           "--out", str(out), "--serial", "--quiet"]
    proc = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    partial = out / "cases" / "0000" / "result.nc"
    deadline, steps = time.time() + 240, 0
    while time.time() < deadline and proc.poll() is None and steps < 12:
        if partial.is_file():
            with xr.open_dataset(partial) as ds:
                steps = int(ds.attrs.get("steps_done", 0))
        time.sleep(0.05)
    proc.kill()
    proc.wait()
    assert 12 <= steps < 40, "the case was not killed mid-way"
    assert not (out / "cases" / "0000" / "status.json").is_file()

    loaded = []
    original = Checkpointer.load

    def load(self):
        arrays = original(self)
        loaded.append(None if arrays is None else arrays)
        return arrays

    monkeypatch.setattr(Checkpointer, "load", load)
    resumed = run_one(study.cases[0][1], str(out / "cases" / "0000"))
    assert len(loaded) == 1 and loaded[0] is not None, "the case started again from step 0"
    assert resumed["state"] == "done", resumed
    for key in ("max_pressure_pa", "minimum_film_thickness_m", "contact_time_fraction"):
        assert resumed["summary"][key] == whole["summary"][key], key
    with xr.open_dataset(tmp_path / "whole" / "result.nc") as da, \
            xr.open_dataset(partial) as db:
        np.testing.assert_array_equal(da["film"].values, db["film"].values)
        assert "partial" not in db.attrs


def test_study_shows_cases_with_warnings_or_without_convergence(tmp_path, monkeypatch):
    """A case that ran to the end with warnings, or without converging, is not a plain "done":
    study.nc keeps its warnings and convergence, the report's banner names the cases and
    lists the warnings, and the command line says so and exits 3 for the unconverged case."""
    from typer.testing import CliRunner

    import asperity.runners
    from asperity.cli import app

    real = asperity.runners.run_case

    def stalled(case, progress=None, **folder):
        outcome = real(case, progress, **folder)
        if case.grid.nx == 96:  # a case that "did not converge"
            outcome.converged = False
        return outcome

    monkeypatch.setattr(asperity.runners, "run_case", stalled)
    _study(tmp_path, '[[axis]]\nkey = "grid.nx"\nvalues = [24, 96]\n'
                     '[[axis]]\nkey = "grid.ny"\nvalues = [96]\n')
    result = CliRunner().invoke(app, ["sweep", str(tmp_path / "study.toml"), "--out",
                                      str(tmp_path / "out"), "--serial", "--quiet"])
    assert result.exit_code == 3, result.output
    assert "2 of 2 cases done, 1 not converged (0001), 1 with warnings (0000)" in \
        " ".join(result.output.split())
    with xr.open_dataset(tmp_path / "out" / "study.nc") as ds:
        warnings = ds["warnings"].values.ravel()
        assert warnings[0].startswith("mesh: the contact is resolved by 5 cells") and \
            warnings[1] == ""
        assert list(ds["converged"].values.ravel()) == [1.0, 0.0]
    html = (tmp_path / "out" / "report.html").read_text()
    assert "note bad" in html and "<h2>Warnings</h2>" in html
    assert "<li>case 0000: mesh: the contact is resolved by 5 cells" in html
    assert "not converged</span>" in html and "1 warning (below)" in html


def _error(tmp_path, axes, mode="cross") -> str:
    with pytest.raises(InputError) as exc:
        _study(tmp_path, axes, mode)
    return str(exc.value)


def test_log_range_from_zero_is_one_line_naming_its_start(tmp_path):
    """A log range must start and stop above zero; numpy's "Geometric sequence cannot include
    zero" came out as an internal error."""
    assert _error(tmp_path, '[[axis]]\nkey = "loading.load"\nrange = {start = 0, stop = 2, '
                            'num = 5, scale = "log", unit = "N"}\n').startswith(
        'axis[0].range.start: expected a number > 0 for scale = "log"')
    assert _error(tmp_path, '[[axis]]\nkey = "loading.load"\nrange = {start = 1, stop = -2, '
                            'num = 5, scale = "log"}\n').startswith('axis[0].range.stop: ')


def test_key_swept_by_two_axes_is_refused_before_anything_runs(tmp_path):
    """Both axes on loading.load: the second overrode the first in every case and study.nc
    failed after all cases had run ("broadcasting cannot handle duplicate dimensions")."""
    message = _error(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "10 N"]\n'
                               '[[axis]]\nkey = "loading.load"\nvalues = ["20 N", "40 N"]\n')
    assert message == "axis[1].key: loading.load is already swept by axis[0]"
    message = _error(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N"]\n'
                               '[[axis]]\nname = "both"\nkeys = ["geometry.rx", "loading.load"]\n'
                               'values = [["5 mm", "20 N"]]\n')
    assert message == "axis[1].keys: loading.load is already swept by axis[0]"


def test_key_naming_a_table_says_so_and_lists_its_keys(tmp_path):
    """key = "loading" is the table: pydantic's "expected a valid dictionary or instance of
    LoadingSpec" did not say so."""
    message = _error(tmp_path, '[[axis]]\nkey = "loading"\nvalues = ["5 N", "10 N"]\n')
    assert message == ("axis[0].key: loading names a table, not a key; name a key in it "
                       "(loading.load, loading.approach)")


def test_bad_value_of_a_case_says_got_once(tmp_path):
    message = _error(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "5 kg"]\n')
    assert message.startswith("case 1 (loading.load): expected ")
    assert message.count("got") == 1 and message.endswith("got '5 kg'")


def test_misspelt_base_names_the_file_it_looked_for(tmp_path):
    """A base that is neither a file nor an example: not "example: expected one of: <35
    names>"."""
    (tmp_path / "study.toml").write_text('base = "bse.toml"\n[[axis]]\nkey = "loading.load"\n'
                                         'values = ["5 N"]\n')
    with pytest.raises(InputError) as exc:
        load_study(tmp_path / "study.toml")
    assert str(exc.value) == (f"base: no file {(tmp_path / 'bse.toml').resolve()} and no "
                              "built-in example of that name (asperity examples lists them)")


def test_mixed_units_on_an_axis_are_si_numbers_and_repeats_are_refused(tmp_path):
    """A bare number is in the key's SI unit, as in a case file: 1 N, 300 cN, 2 and 0.4 daN are
    1, 3, 2 and 4 N (they were strings with units "1" and a categorical x axis). A value given
    twice on a cross axis (2 and "0.2 daN", or "5 N" twice) would run the same case twice."""
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\n'
                             'values = ["1 N", "300 cN", 2.0, "0.4 daN"]\n')
    ds = combine(study, tmp_path / "none")
    assert ds["loading__load"].dtype == float
    np.testing.assert_allclose(ds["loading__load"].values, [1.0, 3.0, 2.0, 4.0], rtol=1e-12)
    assert ds["loading__load"].attrs["units"] == "N"
    bare = combine(_study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = [5, 10]\n'),
                   tmp_path / "none")
    assert bare["loading__load"].attrs["units"] == "N"       # was "1"
    message = _error(tmp_path, '[[axis]]\nkey = "loading.load"\n'
                               'values = ["1 N", 2.0, "0.2 daN"]\n')
    assert message == ("axis[0].values: values 1 and 2 are the same case: 2.0 and '0.2 daN' "
                       "(both 2 N); give each value once")
    assert _error(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "5 N"]\n') \
        .startswith("axis[0].values: values 0 and 1 are the same case")
    # zip pairs axes element-wise: a value may repeat there
    assert len(_study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "5 N"]\n'
                                '[[axis]]\nkey = "geometry.rx"\nvalues = ["5 mm", "6 mm"]\n',
                      mode="zip").cases) == 2


def test_unconverged_case_carries_its_reason_and_failed_cases_are_named(tmp_path, monkeypatch):
    """A case that did not converge keeps its run's own message (a single run says "did not
    converge in 30 sweeps ... Raise solver.max_sweeps") in status.json, study.nc, the report's
    table and on the command line; the last line names the failed cases."""
    from typer.testing import CliRunner

    import asperity.runners
    from asperity.cli import app
    from asperity.report import study_status

    real = asperity.runners.run_case
    reason = ("The solver did not converge in 7 iterations (residual 3.1e-04); the numbers "
              "above are not trustworthy. Raise solver.max_iterations.")

    def uneven(case, progress=None, **folder):
        if case.loading.load == 10.0:
            raise RuntimeError("solver exploded")
        outcome = real(case, progress, **folder)
        if case.loading.load == 20.0:
            outcome.converged = False
            outcome.notes = ["The film formulas are fits.", reason]
        return outcome

    monkeypatch.setattr(asperity.runners, "run_case", uneven)
    _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = [5, 10, 20]\n')
    result = CliRunner().invoke(app, ["sweep", str(tmp_path / "study.toml"), "--out",
                                      str(tmp_path / "out"), "--serial", "--quiet"])
    assert result.exit_code == 3, result.output
    output = " ".join(result.output.split())
    assert f"case 0002 did not converge: {reason}" in output
    assert "case 0001 failed: RuntimeError: solver exploded" in output
    status = json.loads((tmp_path / "out" / "cases" / "0002" / "status.json").read_text())
    assert status["convergence"] == reason
    with xr.open_dataset(tmp_path / "out" / "study.nc") as ds:
        assert list(ds["convergence"].values) == ["", "", reason]
        assert study_status(ds)[1] == ("2 of 3 cases done, 1 not converged (0002), 2 with "
                                       "warnings (0000, 0002), 1 failed (0001)")
    html = (tmp_path / "out" / "report.html").read_text()
    assert "did not converge in 7 iterations (residual 3.1e-04)" in html


def _done_cases(out, summaries):
    """Mark cases 0000, 0001, ... of a study's output folder done with these summaries."""
    for n, summary in enumerate(summaries):
        folder = out / "cases" / f"{n:04d}"
        folder.mkdir(parents=True)
        (folder / "status.json").write_text(json.dumps(
            {"state": "done", "converged": True, "summary": summary}))


def test_log_range_is_drawn_on_a_log_axis_and_study_nc_says_what_made_it(tmp_path):
    """A range with scale = "log" is a log x axis in the study figure (it was linear below a
    ratio of 50); study.nc carries the Conventions, the asperity version and the base case
    as result.nc does."""
    import asperity
    from asperity.plotting.study import plot_study
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\n'
                             'range = {start = 1, stop = 20, num = 4, scale = "log", unit = "N"}\n')
    out = tmp_path / "out"
    _done_cases(out, [{"max_pressure_pa": 1e9 * load} for load in np.geomspace(1, 20, 4)])
    ds = combine(study, out)
    assert plot_study(ds, ["max_pressure_pa"]).axes[0].get_xscale() == "log"
    linear = combine(_study(tmp_path, '[[axis]]\nkey = "loading.load"\nrange = {start = 1, '
                                      'stop = 20, num = 4, unit = "N"}\n'), out)
    assert plot_study(linear, ["max_pressure_pa"]).axes[0].get_xscale() == "linear"
    assert ds.attrs["Conventions"] == "CF-1.8"
    assert ds.attrs["asperity_version"] == asperity.__version__
    assert ds.attrs["base"] == str((tmp_path / "base.toml").resolve())
    assert load_study("holmes-mesh-CC").base == "holmes-rough-CC-paper"   # an example


def test_a_power_law_on_a_log_range_is_drawn_on_log_log_axes(tmp_path):
    """A ball bearing's film against a log range of speed (1-20 m/s: 129 nm to 1.09 um, as
    h ~ u^0.71) was drawn on a linear y axis, where a power law looks like an exponential
    rise; it is now a straight line on log-log axes, whose slope is the exponent. A result
    spanning less than a factor LOG_Y_SPAN (Moes L, 13.6-28.9) and a negative one (the
    separation) keep a linear y axis, as does any result on a linear x axis."""
    from asperity.plotting.study import LOG_Y_SPAN, plot_study
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\n'
                             'range = {start = 1, stop = 20, num = 4, scale = "log", unit = "N"}\n')
    out = tmp_path / "out"
    _done_cases(out, [{"central_film_thickness_m": 129e-9 * u**0.71, "moes_L": 13.6 * u**0.25,
                       "separation_m": -7.1e-6 + 3.6e-8 * u} for u in np.geomspace(1, 20, 4)])
    assert 20**0.25 < LOG_Y_SPAN < 20**0.71
    keys = ["central_film_thickness_m", "moes_L", "separation_m"]
    film, moes_l, separation = plot_study(combine(study, out), keys).axes[:3]
    assert film.get_yscale() == "log"
    (line,) = film.get_lines()
    x, y = line.get_data()
    slope = np.polyfit(np.log(x), np.log(y), 1)[0]
    assert slope == pytest.approx(0.71, abs=1e-9)
    assert moes_l.get_yscale() == separation.get_yscale() == "linear"
    linear = combine(_study(tmp_path, '[[axis]]\nkey = "loading.load"\nrange = {start = 1, '
                                      'stop = 20, num = 4, unit = "N"}\n'), out)
    assert plot_study(linear, keys).axes[0].get_yscale() == "linear"


@pytest.mark.parametrize("workers", [0, -2])
def test_a_cluster_of_no_workers_is_one_line_naming_the_option(tmp_path, workers):
    """``asperity sweep --workers 0`` ended in "internal: ZeroDivisionError" and exit code 1;
    it is bad input: one line naming --workers, exit code 2, before anything runs."""
    from typer.testing import CliRunner

    from asperity.cli import app

    _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = [5, 10]\n')
    result = CliRunner().invoke(app, ["sweep", str(tmp_path / "study.toml"), "--out",
                                      str(tmp_path / "out"), "--workers", str(workers), "-q"])
    assert result.exit_code == 2, result.output
    errors = [ln for ln in result.output.splitlines() if ln.startswith("error:")]
    assert errors == [f"error: --workers: expected a whole number of at least 1 (the local "
                      f"cluster's worker processes), got {workers}"], result.output
    assert not (tmp_path / "out" / "cases").exists()


def test_log_axis_tick_labels_do_not_overlap(tmp_path):
    """A log range within about a decade (5-80 N, 4 values) was labelled with matplotlib's minor
    ticks, 2×10¹ 3×10¹ 4×10¹ 6×10¹, written over each other; the ticks are now the swept values
    as plain numbers, side by side."""
    from asperity.plotting.study import plot_study
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\n'
                             'range = {start = 5, stop = 80, num = 4, scale = "log", unit = "N"}\n')
    out = tmp_path / "out"
    _done_cases(out, [{"max_pressure_pa": 1e8 * load} for load in np.geomspace(5, 80, 4)])
    fig = plot_study(combine(study, out), ["max_pressure_pa", "max_pressure_pa"])
    fig.canvas.draw()
    renderer = fig.canvas.get_renderer()
    for ax in fig.axes:
        labels = [t for t in ax.get_xticklabels(which="both")
                  if t.get_visible() and t.get_text() and
                  ax.get_xlim()[0] <= t.get_position()[0] <= ax.get_xlim()[1]]
        assert [t.get_text() for t in labels] == ["5", "12.6", "31.75", "80"]  # as in the table
        boxes = sorted((t.get_window_extent(renderer) for t in labels), key=lambda b: b.x0)
        assert all(left.x1 < right.x0 for left, right in itertools.pairwise(boxes))


def test_local_cluster_is_quiet_and_its_workers_leave_ctrl_c_to_the_command(capfd):
    """Dask's log lines (a nanny's "Worker process still alive after 4.0 seconds, killing" at
    a normal finish) are not printed, and the workers ignore SIGINT: Ctrl-C reaches every
    process of the terminal's group, and each worker printed its tracebacks (about 80 lines)
    before the command line's one line."""
    import logging
    import signal

    from dask.distributed import Client

    def ignores_sigint():
        return signal.getsignal(signal.SIGINT) == signal.SIG_IGN

    with local_cluster(1, cores=1) as cluster, Client(cluster) as client:
        logging.getLogger("distributed.nanny").warning("Worker process still alive after 4.0 "
                                                       "seconds, killing")
        assert set(client.run(ignores_sigint).values()) == {True}
        assert signal.getsignal(signal.SIGINT) is signal.default_int_handler  # put back here
    assert "still alive" not in capfd.readouterr().err


def test_a_result_constant_over_the_study_is_drawn_flat_not_as_a_trend(tmp_path):
    """A central film of 479.320-479.333 nm over three slide/roll ratios (holmes-smooth-xi)
    was drawn over the panel's full height with an offset of +4.793e2, a rise of 0.013 nm
    looking like a trend; it is drawn on +-2 % of its mean, without an offset. A result that
    changes (a load's pressure) keeps the range matplotlib gives it."""
    from asperity.plotting.study import plot_study
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["1 N", "2 N", "3 N"]\n')
    out = tmp_path / "out"
    for n, (film, load) in enumerate([(479.320e-9, 1), (479.330e-9, 2), (479.333e-9, 3)]):
        folder = out / "cases" / f"{n:04d}"
        folder.mkdir(parents=True)
        (folder / "status.json").write_text(json.dumps(
            {"state": "done", "converged": True,
             "summary": {"central_film_thickness_m": film, "max_pressure_pa": 1e9 * load}}))
    fig = plot_study(combine(study, out), ["central_film_thickness_m", "max_pressure_pa"])
    film_ax, pressure_ax = fig.axes[:2]
    low, high = film_ax.get_ylim()
    assert low == pytest.approx(479.328 * 0.98, rel=1e-4)
    assert high == pytest.approx(479.328 * 1.02, rel=1e-4)
    assert not film_ax.yaxis.get_major_formatter().get_useOffset()
    low, high = pressure_ax.get_ylim()
    assert low < 1.0 and 3.0 < high < 3.5


@pytest.mark.parametrize(("key", "values", "quoted"), [
    ("geometry.rx", "[10, 12]", "'10 mm'"),            # meant in mm: ran 10 m and 12 m radii
    ("body1.youngs_modulus", "[200, 220]", "'210 GPa'"),  # meant in GPa: 200 Pa
])
def test_bare_numbers_meant_in_the_unit_of_the_base_are_refused(tmp_path, key, values, quoted):
    """A bare number is in the key's SI unit: rx = [10, 12] on a base of "10 mm" ran balls of
    10 m and 12 m radius, and a tangential case answered for them without a word. Where every
    bare value is at least 100 times off the base in SI and near it in the base's own unit,
    the study is refused naming the unit to write."""
    message = _error(tmp_path, f'[[axis]]\nkey = "{key}"\nvalues = {values}\n')
    assert message.startswith("axis[0].values: ")
    assert quoted in message
    ratio = {"geometry.rx": 10 / 0.010, "body1.youngs_modulus": 200 / 210e9}[key]
    assert f"{ratio:.4g} times" in message


def test_bare_numbers_in_si_near_the_base_still_run(tmp_path):
    """Metres on a base in mm, a load in N beside its base and a speed-like decade sweep stay
    allowed: only values that read as the base's unit are refused."""
    study = _study(tmp_path, '[[axis]]\nkey = "geometry.rx"\nvalues = [0.005, 0.012]\n'
                             '[[axis]]\nkey = "loading.load"\nvalues = [1, 100, 1000]\n')
    rx = [case["geometry"]["rx"] for _, case, _ in study.cases[::3]]
    assert rx == [0.005, 0.012]


@pytest.mark.parametrize(("range_text", "start"), [
    ('{start = "10 N", stop = "50 N", num = 3}', "axis[0].range.start: expected a number (give "
                                                 "the unit once"),
    ("{start = 1, stop = inf, num = 3}", "axis[0].range.stop: expected a finite number, got inf"),
])
def test_range_ends_are_plain_finite_numbers(tmp_path, range_text, start):
    """start = "10 N" was "expected a table {start, stop, num[, unit, scale]}, got {...}",
    which did not say what was wrong; stop = inf gave numpy's "invalid value encountered in
    multiply" and then "values 1 and 2 are the same case: inf and inf"."""
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        message = _error(tmp_path, f'[[axis]]\nkey = "loading.load"\nrange = {range_text}\n')
    assert message.startswith(start)


def test_the_analysis_key_is_not_swept(tmp_path):
    """values = ["normal", "ehl-steady"] on analysis was refused as "case 1 (geometry):
    missing", a key the user had not touched."""
    message = _error(tmp_path, '[[axis]]\nkey = "analysis"\nvalues = ["normal", "ehl-steady"]\n')
    assert message.startswith("axis[0].key: analysis is not swept")
    assert "'normal'" in message


@pytest.mark.parametrize(("key", "near"), [
    ("contact.load", "loading.load"),   # the EHL cases' load key on a dry normal base
    ("geometry.rxx", "geometry.rx"),
])
def test_an_axis_key_the_analysis_lacks_names_the_axis_and_the_nearest_key(tmp_path, key, near):
    """contact.load on a normal base was "case 0 (contact): unknown key (check the spelling)":
    it named neither the axis nor the analysis, though the key is a good one of another."""
    message = _error(tmp_path, f'[[axis]]\nkey = "{key}"\nvalues = ["5 N", "10 N"]\n')
    assert message == (f'axis[0].key: {key} is not a key of analysis = "normal" (did you mean '
                       f"{near}?); asperity schema normal lists them")


def test_figure_joins_the_points_in_the_order_of_the_axis(tmp_path, monkeypatch):
    """Loads written ["10 N", 20, "0.03 kN", "5 lbf"] (10, 20, 30 and 22.24 N) were joined in
    that order, each result drawn as a loop back from 30 N to 22.24 N; the table keeps the
    study's order of cases."""
    import asperity.plotting.study as study_plot
    from asperity.report import write_study_report
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\n'
                             'values = ["10 N", 20, "0.03 kN", "5 lbf"]\n')
    out = tmp_path / "out"
    loads = [10.0, 20.0, 30.0, 5 * 4.4482216152605]
    _done_cases(out, [{"max_pressure_pa": 1e8 * load ** (1 / 3)} for load in loads])
    figures = []
    real = study_plot.plot_study
    monkeypatch.setattr(study_plot, "plot_study", lambda ds, v, **kw: figures.append(
        real(ds, v, **kw)) or figures[-1])
    write_study_report(combine(study, out), out)
    x = figures[0].axes[0].lines[0].get_xdata()
    np.testing.assert_allclose(x, sorted(loads))
    html = (out / "report.html").read_text()
    assert html.index("<td>0003</td><td>22.24</td>") > html.index("<td>0002</td><td>30</td>")


def _table_columns(html):
    """The headings and the columns of cells (case id first) of a study report's table."""
    table = html[html.index("<h2>Cases</h2>"):]
    table = table[:table.index("</table>")]
    heads = re.findall(r"<th(?: class=l)?>(.*?)</th>", table)
    rows = [re.findall(r"<td(?: class=l)?>(.*?)</td>", row)
            for row in re.findall(r"<tr><td>\d{4}</td>.*?</tr>", table)]
    return heads, [list(column) for column in zip(*rows, strict=True)]


def test_a_column_of_the_table_of_cases_is_in_one_unit(tmp_path):
    """Each cell was formatted on its own, so one column switched units between rows (a
    contact area read "4608 µm²" in one row and "0.01053 mm²" in the next, a load "500 mN"
    then "20 N"); each quantity column now has one unit, chosen from its largest magnitude and
    named once in its heading, and its cells are plain numbers. Flags and text stay text."""
    from asperity.report import render_study_report
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["500 mN", "20 N"]\n')
    out = tmp_path / "out"
    _done_cases(out, [
        {"max_pressure_pa": 358.8e6, "contact_area_m2": 4608e-12, "approach_m": 254.9e-9,
         "gross_slip": False, "contact_area_fraction": 0.006944},
        {"max_pressure_pa": 1.724e9, "contact_area_m2": 0.01053e-6, "approach_m": 5.528e-6,
         "gross_slip": True, "contact_area_fraction": 0.1233}])
    heads, columns = _table_columns(render_study_report(combine(study, out)))
    by_head = dict(zip(heads, columns, strict=True))
    assert by_head["loading.<wbr>load (N)"] == ["0.5", "20"]
    assert by_head["maximum pressure (GPa)"] == ["0.3588", "1.724"]
    assert by_head["contact area (mm²)"] == ["0.004608", "0.01053"]
    assert by_head["approach (µm)"] == ["0.2549", "5.528"]
    assert by_head["contact area fraction (%)"] == ["0.6944", "12.33"]
    assert by_head["gross slip at the applied load"] == ["no", "yes"]
    assert by_head["state"] == ["<span class=pass>done</span>"] * 2
    for column in columns[1:-2]:  # no cell of a quantity names a unit: the heading does
        assert not any(re.search(r"[a-zA-Zµ%²]", cell) for cell in column
                       if cell not in ("yes", "no")), column


def test_the_figure_draws_the_formulas_beside_the_solver(tmp_path):
    """study.nc carries the closed-form references of the runners' summaries (the EHL film
    formulas, Hertz), but the figure drew the solver alone (and a formula, where it fitted in
    the nine panels, in a panel of its own). Each result's panel now has the formulas of the
    same quantity beside it, dashed, in the result's unit and named in the legend: the
    central film beside the central-film formulas, the minimum film beside the minimum-film
    one, the maximum pressure beside Hertz's (constant over a speed sweep); a formula of
    another quantity is not drawn there, and a formula drawn beside its result has no panel."""
    from asperity.plotting.study import plot_study
    from asperity.report import study_references, study_variables
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\n'
                             'range = {start = 1, stop = 8, num = 4, scale = "log", unit = "N"}\n')
    out = tmp_path / "out"
    speeds = np.geomspace(1, 8, 4)
    _done_cases(out, [{"central_film_thickness_m": 120e-9 * u**0.67,
                       "minimum_film_thickness_m": 60e-9 * u**0.68,
                       "max_pressure_pa": 640e6 + 5e6 * u, "hertz_max_pressure_pa": 628e6,
                       "friction_coefficient": 0.026 + 0.001 * u,
                       "nijenbanning_central_film_m": 135e-9 * u**0.67,
                       "hamrock_dowson_central_film_m": 128e-9 * u**0.67,
                       "hamrock_dowson_minimum_film_m": 75e-9 * u**0.68} for u in speeds])
    ds = combine(study, out)
    variables = study_variables(ds)
    assert variables == ["central_film_thickness_m", "minimum_film_thickness_m",
                         "max_pressure_pa", "friction_coefficient"]   # no panel of a formula
    assert study_references(ds, variables) == {
        "central_film_thickness_m": [("hamrock_dowson_central_film_m", "Hamrock-Dowson (1977)"),
                                     ("nijenbanning_central_film_m",
                                      "Nijenbanning et al. (1994)")],
        "minimum_film_thickness_m": [("hamrock_dowson_minimum_film_m",
                                      "Hamrock-Dowson (1977)")],
        "max_pressure_pa": [("hertz_max_pressure_pa", "Hertz")]}
    central, minimum, pressure, friction = plot_study(
        ds, variables, references=study_references(ds, variables)).axes[:4]

    def drawn(ax):
        return {line.get_label(): line for line in ax.get_lines()}

    def legend(ax):
        return [t.get_text() for t in ax.get_legend().get_texts()]

    assert legend(central) == ["solver", "Hamrock-Dowson (1977)", "Nijenbanning et al. (1994)"]
    assert legend(minimum) == ["solver", "Hamrock-Dowson (1977)"]
    assert legend(pressure) == ["solver", "Hertz"]
    assert friction.get_legend() is None and len(friction.get_lines()) == 1
    lines = drawn(central)
    assert lines["solver"].get_linestyle() == "-"
    assert lines["Hamrock-Dowson (1977)"].get_linestyle() == "--"
    assert central.get_ylabel() == "central film thickness (nm)"   # the formula in nm too
    np.testing.assert_allclose(lines["Hamrock-Dowson (1977)"].get_ydata(), 128 * speeds**0.67)
    np.testing.assert_allclose(drawn(minimum)["Hamrock-Dowson (1977)"].get_ydata(),
                               75 * speeds**0.68)
    np.testing.assert_allclose(drawn(pressure)["Hertz"].get_ydata(), [628] * 4)  # MPa
    assert central.get_yscale() == "log"
    assert plot_study(ds, variables, references={}).axes[0].get_legend() is None


def test_formulas_of_a_cross_study_follow_each_line_and_are_named_once(tmp_path):
    """With a line per value of the other axes, each line's formula is dashed in that line's
    colour, and the legend names each formula once (in grey) after the lines."""
    from asperity.plotting.study import plot_study
    from asperity.report import study_references
    from asperity.sweep import combine

    study = _study(tmp_path, '[[axis]]\nkey = "loading.load"\nvalues = ["5 N", "10 N"]\n'
                             '[[axis]]\nkey = "geometry.rx"\nvalues = ["5 mm", "10 mm"]\n')
    out = tmp_path / "out"
    _done_cases(out, [{"max_pressure_pa": 1e9 * load / rx, "hertz_max_pressure_pa":
                       1.01e9 * load / rx} for load in (5, 10) for rx in (5, 10)])
    ds = combine(study, out)
    ax = plot_study(ds, ["max_pressure_pa"],
                    references=study_references(ds, ["max_pressure_pa"])).axes[0]
    assert [t.get_text() for t in ax.get_legend().get_texts()] == [
        "geometry.rx = 5 mm", "geometry.rx = 10 mm", "Hertz"]
    solid = [line for line in ax.get_lines() if line.get_linestyle() == "-"]
    dashed = [line for line in ax.get_lines() if line.get_linestyle() == "--"]
    assert len(solid) == len(dashed) == 2
    assert [d.get_color() for d in dashed] == [s.get_color() for s in solid]
