"""The HTML report: self-contained, with a reference table; renders in headless Chromium."""

import re
import shutil
import subprocess

import pytest
import xarray as xr
from typer.testing import CliRunner

from asperity.cli import app
from asperity.report import render_report
from asperity.results import Comparison, Outcome


@pytest.fixture(scope="module")
def report(tmp_path_factory):
    out = tmp_path_factory.mktemp("report")
    result = CliRunner().invoke(app, ["run", "gear-dry-hertz", "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    return out / "report.html"


def test_report_is_self_contained_with_references(report):
    html = report.read_text()
    assert html.count("data:image/png;base64,") == 2
    assert "<img" in html and 'src="http' not in html and "<script" not in html
    assert "maximum pressure" in html and "Hertz (exact elliptical)" in html
    assert "class=pass" in html


def test_key_results_in_words_with_units_and_headline_first(report):
    html = report.read_text()
    assert "max_pressure_pa" not in html and "contact_area_m2" not in html  # no raw keys
    # the gear case: p0 = 1.046 GPa, a = 0.336 mm, b = 1.30 mm (Hertz; values of the run)
    assert re.search(r"<td class=l>maximum pressure</td><td>1\.04\d GPa</td>", html)
    assert re.search(r"Hertz semi-axis a \(along x\)</td><td>33\d\.\d µm</td>", html)
    assert html.index("class=headline") < html.index("<h2>Key results")
    assert "lbf" not in html  # given in SI: no imperial column
    assert "0.019100000000000002" not in html and "<code>geometry.rx</code>" in html


def _outcome(**summary):
    return Outcome(xr.Dataset(), summary, comparisons=[
        Comparison("gross-slip force", 5765.0, 1296 * 4.4482216, "Seireg", "N", 1e-3)])


def test_imperial_case_reports_imperial_beside_si():
    case = {"analysis": "tangential", "mu": 0.12,
            "body1": {"youngs_modulus": 30e6 * 6894.757, "poisson_ratio": 0.3}}
    html = render_report("t", case, _outcome(normal_load_n=10800 * 4.4482216), {},
                         imperial=True)
    assert "48.04 kN (10800 lbf)" in html
    assert "5.765 kN (1296 lbf)" in html            # the comparison table too
    assert "206.8 GPa (3×10⁷ psi)" in html          # and the case's parameters
    assert "Case parameters (SI and imperial)" in html


def test_zero_and_differences_without_noise():
    html = render_report("t", {"analysis": "normal"},
                         _outcome(force_x_n=0.0, load_n=962.0, approach_m=8.6e-6), {})
    assert "<td class=l>force x</td><td>0 N</td>" in html
    assert "<td class=l>approach</td><td>8.6 µm</td>" in html
    assert "+0.00 %" not in html and "-0.00 %" not in html


CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.mark.skipif(CHROMIUM is None, reason="headless Chromium not installed")
def test_report_renders_in_headless_chromium(report, tmp_path):
    png = tmp_path / "shot.png"
    subprocess.run([CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic",
                    "--no-first-run", "--disable-background-networking",
                    "--disable-component-update", "--disable-sync",
                    f"--user-data-dir={tmp_path / 'profile'}", f"--screenshot={png}",
                    "--window-size=1200,1600", report.as_uri()],
                   capture_output=True, timeout=120, check=False)
    assert png.is_file() and png.stat().st_size > 20_000  # a rendered page, not a blank one
