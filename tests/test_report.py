"""The HTML report: self-contained, with a reference table; renders in headless Chromium."""

import shutil
import subprocess

import pytest
from typer.testing import CliRunner

from asperity.cli import app


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
