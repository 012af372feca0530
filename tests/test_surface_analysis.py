"""analysis = "surface": examples run and pass their references; parameters against closed forms;
bad [surface] tables give one line naming the key."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
import xarray as xr
from typer.testing import CliRunner

from asperity import surfaces as s
from asperity.cases import load_case
from asperity.cli import app
from asperity.errors import InputError
from asperity.examples import example_text
from asperity.runners import run_case
from asperity.surfaces.filters import ALPHA

EXAMPLES = ["seireg-turning-vibration", "seireg-turning-kinematic", "holmes-profiles",
            "measured-profile"]
# rows checked against a reference (tolerance set) in each example's report
CHECKED = {"seireg-turning-vibration": {"kinematic Rt of the feed marks",
                                        "kinematic Ra of the feed marks"},
           "seireg-turning-kinematic": {"kinematic Rt of the feed marks",
                                        "kinematic Ra of the feed marks"},
           "holmes-profiles": {f"Ra of profile {p}" for p in "ABC"},
           "measured-profile": set()}


def _run(text):
    return run_case(load_case(text))


def _check_dataset(ds):
    for name in ds.variables:
        assert {"units", "long_name"} <= set(ds[name].attrs), name
    assert ds["x"].attrs["units"] == "m"
    assert ds["height"].attrs["units"] == "m"


@pytest.fixture(scope="module")
def outcomes():
    return {name: _run(example_text(name)) for name in EXAMPLES}


@pytest.mark.parametrize("name", EXAMPLES)
def test_example_runs_and_passes_its_references(outcomes, name):
    outcome = outcomes[name]
    assert outcome.converged
    _check_dataset(outcome.dataset)
    for key in ("ra_m", "rq_m", "rt_m", "rsk", "rku", "spacing_m"):
        assert key in outcome.summary, key
    for key, value in outcome.summary.items():
        if isinstance(value, float):
            assert math.isfinite(value), key
    checked = [row for row in outcome.comparisons if row.tolerance is not None]
    assert {row.quantity for row in checked} == CHECKED[name]
    for row in checked:
        assert row.passed, (row.quantity, row.value, row.reference)
    assert outcome.figures and all(callable(draw) for draw, _ in outcome.figures.values())


def test_kinematic_example_against_eq_4_1(outcomes):
    out = outcomes["seireg-turning-kinematic"]
    f, r = 0.127e-3, 0.794e-3
    assert out.summary["kinematic_rt_m"] == pytest.approx(f * f / (8 * r), rel=1e-12)
    # Circular arcs: the cusps (f/2 from a valley) fall on grid points, the valleys half a
    # cell h/2 beside the nearest ones.
    h = out.summary["spacing_m"]
    assert h == pytest.approx(f / 201)
    arc = r - math.sqrt(r * r - f * f / 4) - (r - math.sqrt(r * r - h * h / 4))
    assert out.summary["rt_m"] == pytest.approx(arc, rel=1e-9)
    assert out.summary["periodic"] is True
    rows = {c.quantity: c for c in out.comparisons}
    assert rows["kinematic Rt of the feed marks"].tolerance == 0.01
    table = [c for c in out.comparisons if "Table 4.1" in c.quantity]
    assert {c.reference for c in table} == {16.0, 250.0} and all(c.passed is None for c in table)


def test_vibration_example_is_rougher_at_low_natural_frequency(outcomes):
    out = outcomes["seireg-turning-vibration"]
    sm = out.summary
    kin = sm["kinematic_rt_m"]
    assert sm["rt_along_mean_28hz_m"] > sm["rt_along_mean_34hz_m"] > sm["rt_along_mean_150hz_m"]
    assert sm["rt_along_mean_150hz_m"] == pytest.approx(kin, rel=0.1)
    ds = out.dataset
    assert list(ds["surface"].values) == ["28 Hz", "34 Hz", "150 Hz", "kinematic"]
    assert ds["rt_along"].dims == ("surface", "window")
    assert ds["window"].size == 19  # 157 feeds = 19.94 mm in 1 mm windows
    # The kinematic profile is the same in every window: Rt is the cusp height everywhere.
    np.testing.assert_allclose(ds["rt_along"].sel(surface="kinematic"), sm["rt_kinematic_m"],
                               rtol=1e-9)
    assert np.isnan(ds["natural_frequency"].sel(surface="kinematic"))


def test_holmes_profiles_keep_their_ra_and_order_of_slopes(outcomes):
    out = outcomes["holmes-profiles"]
    sm = out.summary
    # the stand-ins are generated to the paper's Ra exactly, and the summary reports it
    assert (sm["ra_a_m"], sm["ra_b_m"], sm["ra_c_m"]) == pytest.approx((0.32e-6, 0.22e-6,
                                                                        0.31e-6), rel=1e-9)
    # the report sets each profile beside the Ra the paper gives (Holmes et al. 2005)
    assert [c.reference for c in out.comparisons] == pytest.approx([0.32e-6, 0.22e-6, 0.31e-6])
    assert all(c.source.startswith("Holmes, Evans & Snidle (2005)") for c in out.comparisons)
    rdq = out.dataset["rdq"].values
    assert rdq[2] > rdq[1] > rdq[0]  # C sharpest, A most run-in
    assert sm["rsk_a"] < 0 and sm["rsk_b"] < 0
    assert [c.quantity for c in out.comparisons] == [f"Ra of profile {p}" for p in "ABC"]


def test_measured_profile_is_read_filtered_and_split(outcomes):
    out = outcomes["measured-profile"]
    ds = out.dataset
    raw = np.loadtxt(str(load_case(example_text("measured-profile")).surface.path),
                     delimiter=",")
    np.testing.assert_array_equal(ds["height"].values[0], raw[:, 1])
    # the mean line by direct summation of the ISO 16610-21 weighting function
    # s(t) = exp(-pi (t / (alpha lc))^2) / (alpha lc), alpha = sqrt(ln 2 / pi), lc = 0.8 mm,
    # away from the ends (one cut-off each side: no end correction there)
    x, z = raw[:, 0], raw[:, 1]
    width = math.sqrt(math.log(2) / math.pi) * 0.8e-3
    inner = np.flatnonzero((x > x[0] + 0.8e-3) & (x < x[-1] - 0.8e-3))
    mean_line = np.array([(x[1] - x[0]) / width * np.sum(z * np.exp(-np.pi * ((x - x[i]) / width)
                                                                      ** 2)) for i in inner])
    scale = np.ptp(z)
    np.testing.assert_allclose(ds["waviness"].values[0, inner], mean_line, rtol=0,
                               atol=1e-5 * scale)
    np.testing.assert_allclose(ds["roughness"].values[0, inner], z[inner] - mean_line, rtol=0,
                               atol=1e-5 * scale)
    sm = out.summary
    assert sm["ra_m"] < sm["pa_m"] and sm["wt_m"] > 0  # the waviness is gone from Ra
    assert "cutoff_m" in ds.attrs and "waviness" in out.figures


def _sine_file(tmp_path, amplitudes, wavelengths, n=4000, h=1e-6):
    x = s.cell_centres(n, h)
    z = sum(a * np.sin(2 * np.pi * x / w) for a, w in zip(amplitudes, wavelengths, strict=True))
    path = tmp_path / "sine.txt"
    s.write_surface(s.Profile(x, z, periodic=True), path)
    return path


def test_sampling_lengths_of_a_sine_give_the_closed_forms(tmp_path):
    a, lam = 0.5e-6, 100e-6
    path = _sine_file(tmp_path, [a], [lam])
    out = _run(f'analysis = "surface"\n[surface]\nkind = "file"\npath = "{path}"\n'
               f'[evaluation]\nsampling_length = {4 * lam}\n')
    sm = out.summary
    assert sm["ra_m"] == pytest.approx(2 * a / math.pi, rel=5e-4)  # 100 points a period
    assert sm["rq_m"] == pytest.approx(a / math.sqrt(2), rel=1e-4)
    assert sm["rz_m"] == pytest.approx(2 * a, rel=1e-3)  # ISO 4287: mean peak-to-valley
    assert sm["rku"] == pytest.approx(1.5, rel=1e-4)


def test_cutoff_removes_the_long_wave_by_the_gaussian_transmission(tmp_path):
    cutoff = 0.8e-3
    long_w, short_w = 4e-3, 50e-6  # periodic over the 4 mm profile
    a_long, a_short = 2e-6, 0.3e-6
    path = _sine_file(tmp_path, [a_long, a_short], [long_w, short_w])
    out = _run(f'analysis = "surface"\n[surface]\nkind = "file"\npath = "{path}"\n'
               f'[evaluation]\ncutoff = "0.8 mm"\n')

    def passed(lam):  # the roughness keeps 1 - mean-line transmission
        return 1 - math.exp(-math.pi * (ALPHA * cutoff / lam) ** 2)

    rq = math.hypot(a_long * passed(long_w), a_short * passed(short_w)) / math.sqrt(2)
    assert out.summary["rq_m"] == pytest.approx(rq, rel=1e-9)
    assert out.summary["pq_m"] == pytest.approx(math.hypot(a_long, a_short) / math.sqrt(2),
                                                rel=1e-9)
    # Rp here is the highest peak of the whole evaluated R, ISO Rp the mean of the sampling
    # lengths' highest; the notes say which (they read as the same "Rp" before)
    assert out.summary["rp_m"] >= out.summary["iso_rp_m"]
    assert any("not the ISO 4288 means over sampling lengths" in n and "iso_*" in n
               for n in out.notes)


def test_topography_gives_areal_parameters():
    out = _run('analysis = "surface"\n[surface]\nkind = "gaussian"\nlength = "0.2 mm"\n'
               'width = "0.1 mm"\nspacing = "2 um"\nrms = "0.5 um"\ncorrelation_length = "10 um"'
               '\ncorrelation_length_y = "40 um"\nseed = 4\n')
    sm = out.summary
    assert {"sa_m", "sq_m", "ssk", "sku", "sdq", "sdr_percent"} <= set(sm)
    assert out.dataset["height"].dims == ("surface", "x", "y")
    assert "topography" in out.figures
    row = out.comparisons[0]
    assert row.quantity == "Sq" and row.passed is None
    assert row.value == pytest.approx(0.5e-6, rel=0.3)


def test_cutoff_on_a_topography_is_one_clear_error():
    text = ('analysis = "surface"\n[surface]\nkind = "self-affine"\nlength = "0.1 mm"\n'
            'width = "0.1 mm"\nspacing = "2 um"\nhurst = 0.8\nrms = "0.5 um"\n'
            '[evaluation]\ncutoff = "20 um"\n')
    with pytest.raises(InputError, match=r"^evaluation\.cutoff: "):
        _run(text)


def test_turned_spacing_is_snapped_to_an_odd_fraction_of_the_feed():
    out = _run('analysis = "surface"\n[surface]\nkind = "turned"\nfeed = "0.1 mm"\n'
               'nose_radius = "0.8 mm"\nspacing = "1 um"\nlength = "1.04 mm"\n')
    assert out.summary["spacing_m"] == pytest.approx(0.1e-3 / 101)
    assert out.summary["length_m"] == pytest.approx(1.0e-3)
    assert any("odd fraction of the feed" in note for note in out.notes)
    rows = {c.quantity: c for c in out.comparisons}
    # Seireg eq. (4.1): Rt = f^2 / (8 r) = 1.5625 um; Ra of parabolic marks f^2 / (18 sqrt 3 r)
    rt, ra = rows["kinematic Rt of the feed marks"], rows["kinematic Ra of the feed marks"]
    assert rt.reference == pytest.approx(0.1e-3**2 / (8 * 0.8e-3), rel=1e-3)
    assert ra.reference == pytest.approx(0.1e-3**2 / (18 * math.sqrt(3) * 0.8e-3), rel=2e-3)
    assert rt.passed and ra.passed


def test_relative_path_is_relative_to_the_case_file(tmp_path):
    _sine_file(tmp_path, [1e-6], [100e-6])
    case = tmp_path / "case.toml"
    case.write_text('analysis = "surface"\n[surface]\nkind = "file"\npath = "sine.txt"\n')
    assert load_case(case).surface.path == str(tmp_path / "sine.txt")


TURNED = """analysis = "surface"
[surface]
kind = "turned"
feed = "0.127 mm"
nose_radius = "0.794 mm"
natural_frequency = [28, 34]
depth_of_cut = "0.305 mm"
cutting_speed = "61 m/min"
workpiece_diameter = "50 mm"
mass = "250 kg"
[evaluation]
window = "0.5 mm"
"""


@pytest.mark.parametrize("old, new, field", [
    ('feed = "0.127 mm"', 'feed = "0.127 mm"\nrms = "1 um"', "surface.rms"),
    ('mass = "250 kg"', "", "surface.mass"),
    ('natural_frequency = [28, 34]', 'natural_frequency = [28, 28]', "surface.natural_frequency"),
    ('natural_frequency = [28, 34]', 'natural_frequency = [28, "x"]',
     "surface.natural_frequency[1]"),
    # one value where a list is taken is named as written, not as the list of one it becomes
    ('natural_frequency = [28, 34]', 'natural_frequency = "x"', "surface.natural_frequency"),
    ('natural_frequency = [28, 34]', 'natural_frequency = -5', "surface.natural_frequency"),
    ('"0.794 mm"', '"0.01 mm"', "surface.feed"),
    ('"61 m/min"', '"0.001 m/min"', "surface.length"),
    ('"61 m/min"', '"61 kg"', "surface.cutting_speed"),
    ('kind = "turned"', 'kind = "milled"', "surface.kind"),
    ('window = "0.5 mm"', 'windw = "0.5 mm"', "evaluation.windw"),
    ('feed = "0.127 mm"', 'feed = "0.127 mm"\nspacing = "0.1 mm"', "surface.spacing"),
])
def test_bad_surface_case_gives_one_line_naming_the_key(old, new, field):
    assert old in TURNED
    with pytest.raises(InputError) as exc:
        load_case(TURNED.replace(old, new))
    message = str(exc.value)
    assert message.startswith(field + ":") and "\n" not in message, message


@pytest.mark.parametrize("text, field", [
    ('kind = "builtin"\nprofile = "D"', "surface.profile"),
    ('kind = "builtin"\nprofile = ["A", "D"]', "surface.profile[1]"),
    ('kind = "builtin"\nprofile = "A"\nmass = 3', "surface.mass"),
    ('kind = "file"\npath = "no-such-file.csv"', "surface.path"),
    ('kind = "gaussian"\nlength = 1e-3\nspacing = 1e-6\nrms = 1e-6', "surface.correlation_length"),
    ('kind = "gaussian"\nlength = 1e-3\nspacing = 1e-6\nrms = 1e-6\ncorrelation_length = 1e-5\n'
     'correlation_length_y = 1e-5', "surface.correlation_length_y"),
    ('kind = "gaussian"\nlength = 1e3\nspacing = 1e-6\nrms = 1e-6\ncorrelation_length = 1e-5',
     "surface.length"),
    ('kind = "self-affine"\nlength = 1e-3\nspacing = 1e-6\nhurst = 0.8', "surface.rms"),
    ('kind = "builtin"\nprofile = "A"\n[evaluation]\nwindow = 1e-3', "evaluation.window"),
])
def test_bad_kind_keys_name_the_key(text, field):
    with pytest.raises(InputError) as exc:
        load_case(f'analysis = "surface"\n[surface]\n{text}\n')
    assert str(exc.value).startswith(field + ":"), str(exc.value)


def test_form_degree_under_surface_is_sent_to_evaluation():
    """A surface analysis takes form_degree under [evaluation] (a contact under [roughness]);
    under [surface] it read "unknown key (check the spelling)"."""
    with pytest.raises(InputError, match=r"^surface\.form_degree: expected it under "
                                         r"\[evaluation\] .*\(evaluation\.form_degree\)"):
        load_case('analysis = "surface"\n[surface]\nkind = "file"\n'
                  'path = "builtin:ground-profile.csv"\nform_degree = 2\n')


@pytest.mark.parametrize("profile, message", [
    ('"D"', "surface.profile: expected 'A', 'B' or 'C', got 'D'"),
    ("[]", "surface.profile: expected a list of at least 1 item, got 0"),
])
def test_a_single_value_for_a_list_is_reported_as_written(profile, message):
    with pytest.raises(InputError) as exc:
        load_case(f'analysis = "surface"\n[surface]\nkind = "builtin"\nprofile = {profile}\n')
    assert str(exc.value) == message


@pytest.mark.parametrize("evaluation, field", [
    ('cutoff = "1 um"', "evaluation.cutoff"),          # below two spacings
    ('cutoff = "3 mm"', "evaluation.cutoff"),          # over half a non-periodic profile
    ('sampling_length = "1 m"', "evaluation.sampling_length"),
])
def test_bad_evaluation_is_one_line_at_run_time(evaluation, field):
    text = example_text("measured-profile").split("[evaluation]")[0]
    with pytest.raises(InputError, match=rf"^{field}: "):
        _run(text + "[evaluation]\n" + evaluation + "\n")


def test_cli_run_writes_the_report(tmp_path):
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", "holmes-profiles", "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    html = (out / "report.html").read_text()
    # profiles, three spectra, and the ISO texture figure of the first profile
    assert html.count("data:image/png;base64,") == 5
    assert "Ra of profile C" in html and "class=pass" in html
    summary = json.loads((out / "summary.json").read_text())
    assert summary["ra_c_m"] == pytest.approx(0.31e-6)
    with xr.open_dataset(out / "result.nc") as ds:
        _check_dataset(ds)
        assert list(ds["surface"].values) == ["A", "B", "C"]


def test_copied_example_runs_where_it_is_written(tmp_path, monkeypatch):
    # the issue: `asperity example measured-profile > mp.toml && asperity run mp.toml`
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(app, ["example", "measured-profile"])
    (tmp_path / "mp.toml").write_text(result.stdout)
    assert 'path = "builtin:ground-profile.csv"' in result.stdout
    ran = CliRunner().invoke(app, ["run", "mp.toml", "--out", "o", "--quiet"])
    assert ran.exit_code == 0, ran.output
    # --out DIR writes the case and its data beside it, the path made relative
    result = CliRunner().invoke(app, ["example", "measured-profile", "--out", "copy"])
    assert result.exit_code == 0, result.output
    assert (tmp_path / "copy" / "ground-profile.csv").is_file()
    case = (tmp_path / "copy" / "measured-profile.toml").read_text()
    assert 'path = "ground-profile.csv"' in case
    assert load_case(tmp_path / "copy" / "measured-profile.toml").surface.path == str(
        tmp_path / "copy" / "ground-profile.csv")


def test_unknown_builtin_data_and_bad_unit_are_named():
    text = example_text("measured-profile")
    with pytest.raises(InputError, match="surface.path: .*builtin:ground-profile.csv"):
        load_case(text.replace("builtin:ground-profile.csv", "builtin:nope.csv"))
    with pytest.raises(InputError, match="surface.unit: expected a length unit"):
        load_case(text.replace('path = "builtin', 'unit = "parsec per fortnight"\npath = "builtin'))


def test_surface_case_reports_the_iso_texture(outcomes):
    out = outcomes["measured-profile"]
    sm = out.summary
    assert sm["iso_cutoff_m"] == pytest.approx(0.8e-3) and sm["iso_sampling_lengths"] == 5
    assert 0 < sm["iso_mr1_percent"] < sm["iso_mr2_percent"] < 100 and sm["iso_rk_m"] > 0
    assert sm["iso_rz_m"] <= sm["iso_rt_m"]
    assert "texture" in out.figures
    assert any(note.startswith("File read as text") for note in out.notes)


def test_case_file_units_and_missing_points(tmp_path):
    # the corpus profile f(x) (tests/test_surfaces_text_corpus.py) given in nm without a unit,
    # and in angstrom with three missing points
    data = Path(__file__).parent / "data" / "text"
    x = np.arange(64) * 0.5e-6
    f = 0.5e-6 * np.sin(2 * np.pi * x / 40e-6) + 0.2e-6 * np.cos(2 * np.pi * x / 13e-6)
    case = tmp_path / "case.toml"
    case.write_text(f'analysis = "surface"\n[surface]\nkind = "file"\npath = '
                    f'"{data / "unlabelled_nm.txt"}"\nspacing = "0.5 um"\nz_unit = "nm"\n'
                    '[evaluation]\ncutoff = "8 um"\n')
    out = run_case(load_case(case))
    np.testing.assert_allclose(out.dataset["height"].values[0], f, atol=1e-12)
    assert not any("peak-to-valley" in w for w in out.warnings)
    case.write_text(case.read_text().replace('z_unit = "nm"\n', ""))
    with pytest.raises(InputError, match=r"surface.path: expected heights in metres.*z_unit"):
        run_case(load_case(case))  # 663 "m": refused, not only warned
    case.write_text(f'analysis = "surface"\n[surface]\nkind = "file"\npath = '
                    f'"{data / "tab_angstrom_missing.txt"}"\nmissing = "fill"\n')
    out = run_case(load_case(case))
    assert any("filled 3 of 64 points" in n for n in out.notes)
    with pytest.raises(InputError, match="surface.path: .*3 of 64 points"):
        run_case(load_case(case.read_text().replace('missing = "fill"\n', "")))


def test_roughness_table_reads_units_too():
    from asperity.cases.roughness import RoughnessSpec, surface_heights

    data = Path(__file__).parent / "data" / "text"
    spec = RoughnessSpec(kind="file", path=str(data / "unlabelled_nm.txt"), spacing=0.5e-6,
                         z_unit="nm")
    x = (np.arange(64) + 0.5) * 0.5e-6
    z = surface_heights(spec, x, x[:4])
    f = 0.5e-6 * np.sin(2 * np.pi * (x - x[0]) / 40e-6) + 0.2e-6 * np.cos(
        2 * np.pi * (x - x[0]) / 13e-6)
    # a contact sees the file referred to its least-squares mean line (form_degree = 1)
    np.testing.assert_allclose(z[:, 0], f - np.polyval(np.polyfit(x, f, 1), x), atol=1e-12)
    with pytest.raises(ValueError, match="for a measured file"):
        RoughnessSpec(kind="gaussian", rms=1e-6, correlation_length=1e-5, unit="um")


def test_areal_iso_rows_read_as_iso_writes_them(tmp_path):
    # the summary printed "ISO vmp m3 per  7775 µm²" for Vmp = 7.775e-9 m3/m2 (the "_m2" of
    # "_m3_per_m2" read as an area), and "ISO sal", "ISO rsm" in lower case
    from asperity.formatting import summary_rows

    x = (np.arange(64) + 0.5) * 1e-6
    z = 0.3e-6 * np.sin(2 * np.pi * x / 16e-6)[:, None] * np.cos(2 * np.pi * x / 24e-6)[None, :48]
    path = tmp_path / "map.npz"
    np.savez(path, x=x, y=x[:48], z=z)
    out = _run(f'analysis = "surface"\n[surface]\nkind = "file"\npath = "{path}"\n')
    rows = {r.key: r for r in summary_rows(out.summary)}
    vmp = out.summary["iso_vmp_m3_per_m2"]
    assert 1e-10 < vmp < 1e-6
    assert rows["iso_vmp_m3_per_m2"].label == "ISO Vmp"
    assert rows["iso_vmp_m3_per_m2"].text == f"{vmp * 1e9:.4g} nm"
    assert rows["iso_sal_m"].label == "ISO Sal" and rows["iso_smr1_percent"].label == "ISO Smr1"
    profile = _run('analysis = "surface"\n[surface]\nkind = "file"\n'
                   'path = "builtin:ground-profile.csv"\n')
    assert {r.key: r for r in summary_rows(profile.summary)}["iso_rsm_m"].label == "ISO RSm"


def test_sdr_of_a_map_shows_in_percent_beside_iso_sdr(tmp_path):
    """Sdr of a 0.3 um, 16 x 24 um egg-box: the headline row was a bare fraction (0.01274 for a
    map whose ISO Sdr row read 1.274 %); it is now in percent, the same number as ISO Sdr and as
    ``surface stats`` prints."""
    from asperity.formatting import summary_rows
    from asperity.surfaces import evaluate_texture
    from asperity.surfaces.io import read_measured

    x = (np.arange(64) + 0.5) * 1e-6
    z = 0.3e-6 * np.sin(2 * np.pi * x / 16e-6)[:, None] * np.cos(2 * np.pi * x / 24e-6)[None, :]
    path = tmp_path / "map.npz"
    np.savez(path, x=x, y=x, z=z)
    out = _run(f'analysis = "surface"\n[surface]\nkind = "file"\npath = "{path}"\n')
    rows = {r.key: r for r in summary_rows(out.summary)}
    stats = evaluate_texture(read_measured(path).surface).groups["hybrid"]["Sdr"]
    assert rows["sdr_percent"].text == f"{100 * stats:.4g} %" == rows["iso_sdr_percent"].text
    assert "sdr" not in out.summary


def test_material_ratios_show_in_percent_as_surface_stats_shows_them(outcomes):
    """Mr1 and Mr2 of the measured-profile example: the case summary's rows are in percent,
    the number ``surface stats`` prints (its table: 100 x the fraction, 4 digits); they were
    shown as fractions (0.224) beside the stats' 22.4 %."""
    from asperity.formatting import summary_rows
    from asperity.surfaces import evaluate_texture
    from asperity.surfaces.io import read_measured

    rows = {r.key: r for r in summary_rows(outcomes["measured-profile"].summary)}
    data = Path(s.__file__).parents[1] / "examples" / "data"
    reading = read_measured(data / "ground-profile.csv", None)
    rk = evaluate_texture(reading.surface).groups["Rk"]
    for name in ("Mr1", "Mr2"):
        row = rows[f"iso_{name.lower()}_percent"]
        assert row.label == f"ISO {name}"
        assert row.text == f"{100 * rk[name]:.4g} %"
