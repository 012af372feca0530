"""``asperity surface`` commands through typer's CliRunner, on a throwaway app."""

import json
from pathlib import Path

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from asperity.cli.surface import surface_app
from asperity.surfaces import read_surface, roughness_parameters, write_surface
from asperity.surfaces.generate import gaussian_topography

app = typer.Typer()
app.add_typer(surface_app, name="surface")


@pytest.fixture
def runner():
    return CliRunner()


def test_generate_then_stats(runner, tmp_path):
    out = tmp_path / "c.txt"
    res = runner.invoke(app, ["surface", "generate", "builtin", "--name", "C", "--length",
                              "2 mm", "--spacing", "0.5 um", "--out", str(out)])
    assert res.exit_code == 0, res.output
    assert "Rdq" in res.stdout and "unfiltered" in res.stdout
    res = runner.invoke(app, ["surface", "stats", str(out), "--json"])
    assert res.exit_code == 0, res.output
    stats = json.loads(res.stdout)
    assert stats["kind"] == "profile" and stats["points"] == [4000]
    assert list(stats["parameters"]) == ["P", "W", "R", "Rk"]
    # a periodic profile: lambda_c by ISO 4288 (Ra ~ 0.3 um -> 0.8 mm), 2 sampling lengths
    assert stats["filters"]["cutoff_m"] == pytest.approx(0.8e-3)
    assert stats["filters"]["sampling_lengths"] == 2
    assert "Ra_m" in stats["parameters"]["R"] and "Pa_m" in stats["parameters"]["P"]
    assert "Mr1" in stats["parameters"]["Rk"]
    table = runner.invoke(app, ["surface", "stats", str(out)])
    assert table.exit_code == 0 and "Roughness profile R" in table.stdout
    assert "lambda_c = 0.8 mm" in table.stdout and "Rk" in table.stdout


def test_stats_of_heights_with_a_spacing(runner, tmp_path):
    t = gaussian_topography((40e-6, 30e-6), 1e-6, 0.2e-6, 5e-6)
    write_surface(t, tmp_path / "t.npy")
    res = runner.invoke(app, ["surface", "stats", str(tmp_path / "t.npy"), "--json",
                              "--spacing", "1 um"])
    assert res.exit_code == 0, res.output
    stats = json.loads(res.stdout)
    # a .npy forgets periodicity: the plane is removed, as roughness_parameters does
    assert stats["parameters"]["height"]["Sq_m"] == pytest.approx(
        roughness_parameters(t.z, t.x, t.y)["Sq"])
    assert stats["spacing_m"] == pytest.approx([1e-6, 1e-6])
    assert stats["filters"]["surface"] == "S-F"


def test_stats_units_and_warnings(runner):
    data = Path(__file__).parent / "data" / "text"
    res = runner.invoke(app, ["surface", "stats", str(data / "unlabelled_nm.txt"),
                              "--spacing", "0.5 um", "--cutoff", "8 um"])
    assert res.exit_code == 0, res.output
    assert res.stderr.startswith("warning: heights: peak-to-valley")
    res = runner.invoke(app, ["surface", "stats", str(data / "unlabelled_nm.txt"), "--json",
                              "--spacing", "0.5 um", "--z-unit", "nm", "--cutoff", "8 um"])
    assert res.exit_code == 0 and "heights" not in res.stderr and "sampling lengths" in res.stderr
    assert json.loads(res.stdout)["parameters"]["P"]["Pt_m"] < 2e-6
    res = runner.invoke(app, ["surface", "stats", str(data / "tab_angstrom_missing.txt"),
                              "--missing", "fill", "--cutoff", "8 um", "--json"])
    stats = json.loads(res.stdout)
    assert stats["filled_points"] == 3 and any("filled 3 of 64" in n for n in stats["notes"])


@pytest.mark.parametrize("args", [
    ["gaussian", "--rms", "0.5 um", "--correlation-length", "10 um", "--width", "50 um",
     "--length", "80 um"],
    ["self-affine", "--rms-slope", "0.1", "--hurst", "0.7", "--length", "0.2 mm"],
    ["ground", "--ra", "0.4 um", "--run-in", "0.3", "--waviness-wavelength", "0.1 mm",
     "--waviness-amplitude", "0.1 um"],
    ["turned", "--feed", "0.127 mm", "--nose-radius", "0.794 mm", "--natural-frequency",
     "28 Hz", "--length", "3 mm"],
])
def test_generate_kinds(runner, tmp_path, args):
    out = tmp_path / "s.npz"
    res = runner.invoke(app, ["surface", "generate", *args, "--out", str(out)])
    assert res.exit_code == 0, res.output
    surface = read_surface(out)
    assert np.all(np.isfinite(surface.z))


def test_plot_writes_a_png(runner, tmp_path):
    write_surface(gaussian_topography(30e-6, 1e-6, 0.2e-6, 5e-6), tmp_path / "t.npz")
    for extra in ([], ["--spectrum"]):
        png = tmp_path / f"t{len(extra)}.png"
        res = runner.invoke(app, ["surface", "plot", str(tmp_path / "t.npz"), "--out", str(png),
                                  *extra])
        assert res.exit_code == 0, res.output
        assert png.read_bytes()[:4] == b"\x89PNG"
    # --out without a suffix: matplotlib wrote "<out>.png" and the CLI said "wrote <out>"
    res = runner.invoke(app, ["surface", "plot", str(tmp_path / "t.npz"), "--out",
                              str(tmp_path / "figure")])
    assert res.exit_code == 0, res.output
    assert (tmp_path / "figure.png").read_bytes()[:4] == b"\x89PNG"
    assert res.output.strip().endswith(f"wrote {tmp_path / 'figure.png'}")


@pytest.mark.parametrize("args, message", [
    (["stats", "missing.txt"], "error: file: expected an existing file"),
    (["generate", "bogus", "--out", "x.txt"], "error: KIND: expected one of"),
    (["generate", "gaussian", "--out", "x.txt"], "error: --rms: expected a value"),
    (["generate", "gaussian", "--rms", "1 kg", "--correlation-length", "1 um", "--out",
      "x.txt"], "error: --rms: expected a quantity convertible to m"),
    (["generate", "builtin", "--name", "Z", "--out", "x.txt"], "error: name: expected one of"),
])
def test_bad_input_is_one_line_and_exit_2(runner, tmp_path, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    res = runner.invoke(app, ["surface", *args])
    assert res.exit_code == 2
    assert res.stderr.startswith(message)
    assert len(res.stderr.strip().splitlines()) == 1
    assert "Traceback" not in res.output


def test_ragged_file_error_names_the_line(runner, tmp_path):
    bad = tmp_path / "bad.txt"
    bad.write_text("0 1\n1 2 3\n")
    res = runner.invoke(app, ["surface", "stats", str(bad)])
    assert res.exit_code == 2 and "bad.txt:2: expected 2 columns" in res.stderr


def test_plot_of_a_stylus_export(runner, tmp_path):
    data = Path(__file__).parent / "data" / "text" / "dektak_meta_block.csv"
    png = tmp_path / "p.png"
    res = runner.invoke(app, ["surface", "plot", str(data), "--cutoff", "8 um", "--out",
                              str(png)])
    assert res.exit_code == 0, res.output
    assert png.read_bytes()[:4] == b"\x89PNG"


def test_stats_of_a_sine_give_its_closed_form_parameters(runner, tmp_path):
    # z = a sin(2 pi x / 20 um) + a tilt, 4.8 mm at 0.5 um, lambda_c = 0.8 mm: the line goes
    # with the form, lambda_c leaves the sine whole (transmission 1 - 1e-700), ISO 3274's
    # lambda_s = 2.5 um keeps exp(-pi (alpha lambda_s / 20 um)^2) of it (ISO 16610-21), and
    # each sampling length holds 40 periods, so with A the amplitude left Ra = 2 A / pi,
    # Rq = A / sqrt 2, Rsk = 0, Rku = 1.5, Rt = 2 A, RSm = 20 um, Rdq = 2 pi A / 20 um / sqrt 2
    # (up to the forward difference)
    a, lam, h = 0.4e-6, 20e-6, 0.5e-6
    amp = a * np.exp(-np.pi * (np.sqrt(np.log(2) / np.pi) * 2.5e-6 / lam) ** 2)
    x = (np.arange(9600) + 0.5) * h
    out = tmp_path / "sine.txt"
    out.write_text("\n".join(f"{a:.9e} {b:.9e}" for a, b in
                             zip(x, a * np.sin(2 * np.pi * x / lam) + 1e-4 * x, strict=True)))
    res = runner.invoke(app, ["surface", "stats", str(out), "--cutoff", "0.8 mm", "--json"])
    assert res.exit_code == 0, res.output
    r = json.loads(res.stdout)["parameters"]["R"]
    # 40 samples a period: their mean |sin| is 2/pi to 0.05 %, their highest 2 pi / 80 off-peak
    assert r["Ra_m"] == pytest.approx(2 * amp / np.pi, rel=2e-3)
    assert r["Rq_m"] == pytest.approx(amp / np.sqrt(2), rel=1e-4)
    assert r["Rsk"] == pytest.approx(0, abs=1e-3) and r["Rku"] == pytest.approx(1.5, rel=1e-3)
    assert r["Rt_m"] == pytest.approx(2 * amp * np.cos(np.pi / 40), rel=1e-3)
    assert r["RSm_m"] == pytest.approx(lam, abs=h)
    assert r["Rdq"] == pytest.approx(2 * np.pi * amp / lam / np.sqrt(2), rel=2e-3)


def test_each_table_title_is_one_line_above_its_table(runner, tmp_path):
    """A texture table's title (filters, evaluation length) was the table's own title, which
    rich wraps to the width of the three narrow columns: "Primary profile P (ISO 4287; " over
    three lines. It is now a line of its own."""
    out = tmp_path / "c.txt"
    runner.invoke(app, ["surface", "generate", "builtin", "--name", "C", "--length", "2 mm",
                        "--spacing", "0.5 um", "--out", str(out)])
    res = runner.invoke(app, ["surface", "stats", str(out)], terminal_width=120)
    assert res.exit_code == 0, res.output
    titles = [line for line in res.stdout.splitlines() if line.startswith("Primary profile P")]
    assert len(titles) == 1 and titles[0].rstrip().endswith("mm)"), res.stdout
