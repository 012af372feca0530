"""A study run again into its output folder reuses a case only where the case's input is the
one that ran: a changed axis, reordered values, an edited base, another study or a folder that
records no input never hand old results out under new labels."""

import json
import warnings

import pytest

from asperity.errors import InputError
from asperity.sweep import load_study, local_cluster, run_one, run_study

BASE = """
analysis = "normal"
title = "small sphere"
{extra}
[body1]
youngs_modulus = "{modulus}"
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

LOADS = '[[axis]]\nkey = "loading.load"\nvalues = [{}]\n'


def _write(tmp_path, axes, title="t", modulus="210 GPa", extra=""):
    """Write base.toml and study.toml; return the loaded study."""
    (tmp_path / "base.toml").write_text(BASE.format(modulus=modulus, extra=extra))
    path = tmp_path / "study.toml"
    path.write_text(f'title = "{title}"\nbase = "base.toml"\n' + axes)
    return load_study(path)


def _run(study, out, **kw):
    """Run the study; return its dataset and its warnings of cases run again."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ds = run_study(study, out, **kw)
    return ds, [str(w.message) for w in caught if " again: " in str(w.message)]


def _stamps(out):
    return {p.parent.name: p.stat().st_mtime_ns for p in out.glob("cases/*/status.json")}


def _fresh(study, tmp_path, name="fresh"):
    """Each case of the study run on its own, in a folder of its own: load in N -> maximum
    pressure."""
    results = {}
    for cid, case, values in study.cases:
        status = run_one(case, str(tmp_path / name / cid))
        results[float(values["loading__load"].split()[0])] = status["summary"]["max_pressure_pa"]
    return results


def _by_label(ds):
    return dict(zip(ds["loading__load"].values.tolist(), ds["max_pressure_pa"].values.tolist(),
                    strict=True))


def test_a_changed_range_runs_again_only_the_cases_whose_input_changed(tmp_path):
    axes = ('[[axis]]\nkey = "loading.load"\n'
            'range = {{start = 10, stop = 40, num = {}, unit = "N"}}\n')
    out = tmp_path / "out"
    _run(_write(tmp_path, axes.format(3)), out)  # 10, 25, 40 N
    before = _stamps(out)
    study = _write(tmp_path, axes.format(4))  # 10, 20, 30, 40 N: 0001 and 0002 changed
    ds, said = _run(study, out)
    after = _stamps(out)
    assert after["0000"] == before["0000"], "the unchanged case ran again"
    assert all(after[c] != before[c] for c in ("0001", "0002")), "a changed case was reused"
    assert len(said) == 1 and said[0].startswith("2 cases of ") and "0001, 0002" in said[0]
    expected = _fresh(study, tmp_path)
    assert _by_label(ds) == pytest.approx(expected, rel=1e-12)


def test_reordered_values_are_not_relabelled(tmp_path):
    out = tmp_path / "out"
    first, _ = _run(_write(tmp_path, LOADS.format('"10 N", "40 N"')), out)
    study = _write(tmp_path, LOADS.format('"40 N", "10 N"'))
    ds, said = _run(study, out)
    assert _by_label(ds) == pytest.approx(_by_label(first), rel=1e-12)
    assert _by_label(ds)[40.0] > _by_label(ds)[10.0]  # more load, more pressure
    assert said and said[0].startswith("2 cases of ")


def test_an_edited_base_runs_every_case_again(tmp_path):
    out = tmp_path / "out"
    first, _ = _run(_write(tmp_path, LOADS.format('"10 N", "40 N"')), out)
    study = _write(tmp_path, LOADS.format('"10 N", "40 N"'), modulus="420 GPa")
    ds, _ = _run(study, out)
    expected = _fresh(study, tmp_path)
    assert _by_label(ds) == pytest.approx(expected, rel=1e-12)
    assert all(ds["max_pressure_pa"].values > first["max_pressure_pa"].values)  # stiffer


def test_an_unchanged_study_reuses_every_case_and_says_nothing(tmp_path):
    out = tmp_path / "out"
    study = _write(tmp_path, LOADS.format('"10 N", "40 N"'))
    first, _ = _run(study, out)
    before = _stamps(out)
    ds, said = _run(load_study(tmp_path / "study.toml"), out)
    assert _stamps(out) == before and said == []
    assert _by_label(ds) == _by_label(first)


def test_an_output_folder_of_another_study_is_refused_and_left_as_it_is(tmp_path):
    out = tmp_path / "out"
    _run(_write(tmp_path, LOADS.format('"10 N", "40 N"'), title="loads"), out)
    before = _stamps(out)
    other = _write(tmp_path, '[[axis]]\nkey = "geometry.rx"\nvalues = ["5 mm", "20 mm"]\n',
                   title="radii")
    with pytest.raises(InputError, match=r"^--out: .*holds the study 'loads', not 'radii'; "
                                         r"give a new --out"):
        run_study(other, out)
    assert _stamps(out) == before


def test_case_folders_that_record_no_input_are_refused(tmp_path):
    """An output folder of an asperity that recorded no inputs cannot be matched with the
    study's cases: refused, its files kept."""
    out = tmp_path / "out"
    study = _write(tmp_path, LOADS.format('"10 N", "40 N"'))
    _run(study, out)
    for folder in (out / "cases").iterdir():  # as an earlier asperity wrote them
        (folder / "input.json").unlink()
        status = json.loads((folder / "status.json").read_text())
        status.pop("input_sha256")
        (folder / "status.json").write_text(json.dumps(status))
    before = _stamps(out)
    with pytest.raises(InputError, match=r"^--out: .*holds 2 case folders \(0000, 0001\) that "
                                         r"record no input.*give a new --out"):
        run_study(study, out)
    assert _stamps(out) == before


def test_an_unconverged_case_is_reused_until_its_input_is_fixed(tmp_path):
    out = tmp_path / "out"
    stuck = _write(tmp_path, LOADS.format('"20 N"'), extra="tolerance = 1e-30")
    ds, _ = _run(stuck, out)
    assert ds["converged"].values.tolist() == [0.0]
    before = _stamps(out)
    ds, _ = _run(load_study(tmp_path / "study.toml"), out)
    assert _stamps(out) == before and ds["converged"].values.tolist() == [0.0]
    fixed = _write(tmp_path, LOADS.format('"20 N"'))  # the default tolerance
    ds, said = _run(fixed, out)
    assert ds["converged"].values.tolist() == [1.0] and said[0].startswith("1 case of ")
    assert _by_label(ds) == pytest.approx({20.0: _fresh(fixed, tmp_path)[20.0]}, rel=1e-12)


def test_a_stopped_case_of_another_input_does_not_go_on_from_its_checkpoint(tmp_path):
    """A folder stopped mid-run with another input: its checkpoint and partial result go."""
    study = _write(tmp_path, LOADS.format('"10 N", "40 N"'))
    folder = tmp_path / "out" / "cases" / "0000"
    run_one(study.cases[1][1], str(folder))  # 40 N where 10 N is now
    (folder / "status.json").unlink()
    (folder / "checkpoint.npz").write_bytes(b"not a checkpoint of this case")
    ds, said = _run(study, tmp_path / "out")
    assert not (folder / "checkpoint.npz").exists()
    assert said and "0000" in said[0]
    assert _by_label(ds) == pytest.approx(_fresh(study, tmp_path), rel=1e-12)


def test_dask_workers_record_the_input_and_a_changed_case_runs_again(tmp_path):
    from dask.distributed import Client

    out = tmp_path / "out"
    _run(_write(tmp_path, LOADS.format('"10 N", "40 N"')), out)
    study = _write(tmp_path, LOADS.format('"10 N", "30 N"'))
    before = _stamps(out)
    with local_cluster(1, cores=1) as cluster, Client(cluster) as client:
        ds, said = _run(study, out, client=client)
    after = _stamps(out)
    assert after["0000"] == before["0000"] and after["0001"] != before["0001"]
    assert said and said[0].startswith("1 case of ")
    assert _by_label(ds) == pytest.approx(_fresh(study, tmp_path), rel=1e-12)
    status = json.loads((out / "cases" / "0001" / "status.json").read_text())
    recorded = json.loads((out / "cases" / "0001" / "input.json").read_text())
    assert status["input_sha256"] == recorded["input_sha256"]
    assert recorded["case"]["loading"]["load"] == "30 N"
