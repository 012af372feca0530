"""The HTML report: self-contained, with a reference table; renders in headless Chromium."""

import math
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


def test_case_angles_in_degrees():
    case = {"analysis": "tangential", "loading": {"direction": math.pi / 2, "force": 10.0}}
    html = render_report("t", case, _outcome(), {})
    assert "<code>loading.direction</code></td><td class=l>90 deg</td>" in html


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


# --- figures: legends, equal aspect on maps, overflow bin, arrow scale ---------------------

def _ellipse_fields(a=1e-4, b=4e-4):
    import numpy as np

    x = np.linspace(-2.5 * a, 1.5 * a, 41)
    y = np.linspace(-2.0 * b, 2.0 * b, 33)
    X, Y = np.meshgrid(x, y, indexing="ij")
    inside = (X / a) ** 2 + (Y / b) ** 2 < 1
    pressure = np.where(inside, 1e9 * np.sqrt(np.clip(1 - (X / a) ** 2 - (Y / b) ** 2, 0, 1)),
                        0.0)
    film = 0.5e-6 + 1e-3 * (X**2 + Y**2) * ~inside
    return x, y, pressure, film, a, b


def _displayed_aspect(ax, line):
    """Height / width of a drawn line on the screen (pixels)."""
    import numpy as np

    ax.figure.canvas.draw()
    xy = ax.transData.transform(np.column_stack(line.get_data()))
    return np.ptp(xy[:, 1]) / np.ptp(xy[:, 0])


def test_ehl_contour_maps_show_the_hertz_ellipse_as_an_ellipse():
    from asperity.plotting.ehl import contour_maps

    x, y, p, h, a, b = _ellipse_fields()
    fig = contour_maps(x, y, p, h, a, b, 0.5e-6)
    for ax in fig.axes[:2]:
        ellipse = next(ln for ln in ax.get_lines() if ln.get_label() == "Hertz contact")
        assert _displayed_aspect(ax, ellipse) == pytest.approx(b / a, rel=0.02)
    assert fig.legends and "Hertz contact" in [t.get_text() for t in fig.legends[0].texts]


def test_normal_pressure_map_has_equal_axes_and_a_legend():
    from asperity.plotting.normal import pressure_map

    x, y, p, _, _, _ = _ellipse_fields()
    fig = pressure_map(x, y, p, contact=p > 0)
    ax = fig.axes[0]
    assert ax.get_aspect() == 1.0
    assert [t.get_text() for t in fig.legends[0].texts] == ["contact boundary"]


def _transient_result():
    import types

    import numpy as np

    x, y, _, film, a, b = _ellipse_fields()
    X, _ = np.meshgrid(x, y, indexing="ij")
    edges = np.linspace(0.0, 1e-6, 11)
    counts = np.arange(10)[::-1] + 1
    result = types.SimpleNamespace(
        x=x, y=y, film=film, flow_x=25.0 * film + 0 * X, flow_y=0.1 * 25.0 * film,
        contact_count_rate=np.zeros_like(film), film_edges=edges, film_counts=counts)
    return result, types.SimpleNamespace(a=a, b=b)


def test_film_histogram_labels_its_overflow_bin():
    from asperity.plotting.ehl_transient import plot_film_histogram

    result, _ = _transient_result()
    fig = plot_film_histogram(result)
    labels = [t.get_text() for t in fig.axes[0].get_legend().texts]
    assert any(label.startswith("overflow: h >= 0.9 µm") for label in labels)


def test_flow_vectors_have_an_arrow_scale_and_equal_axes():
    from matplotlib.quiver import QuiverKey

    from asperity.plotting.ehl_transient import plot_flow_vectors

    result, problem = _transient_result()
    fig = plot_flow_vectors(result, problem)
    ax = fig.axes[0]
    keys = [c for c in ax.get_children() if isinstance(c, QuiverKey)]
    assert len(keys) == 1 and "mm²/s" in keys[0].text.get_text()
    # the key's flow is a round 1, 2 or 5 times a power of ten
    mantissa = keys[0].U / 10 ** math.floor(math.log10(keys[0].U))
    assert mantissa in (1.0, 2.0, 5.0)
    assert ax.get_aspect() == 1.0


@pytest.mark.parametrize("b_over_a", [3.9, 9.5])
def test_maps_of_a_long_ellipse_are_compressed_across_and_say_so(b_over_a):
    """The seed's gear contact (b/a = 3.9, its domain 3.9 times taller than wide) is drawn to
    scale; a ball bearing's race contact (b/a = 9.5) was a strip a sixth as wide as its colour
    bar: its maps are drawn 5 times taller than wide, the Hertz ellipse on the page that much
    taller than wide, and the y labels name the compression (9.5 / 5 = 1.9 times)."""
    import numpy as np

    from asperity.plotting.ehl import contour_maps
    from asperity.plotting.ehl_transient import plot_contact_rate, plot_flow_vectors
    from asperity.plotting.style import plt

    a = 1e-4
    x, y, p, h, a, b = _ellipse_fields(a=a, b=b_over_a * a)
    result, problem = _transient_result()
    result.x, result.y, result.film = x, y, h
    result.flow_x, result.flow_y = 25.0 * h, 2.5 * h
    result.contact_count_rate = np.zeros_like(h)
    problem.b = b
    to_scale = b_over_a <= 5.0
    figures = [contour_maps(x, y, p, h, a, b, 0.5e-6), plot_contact_rate(result, problem),
               plot_flow_vectors(result, problem)]
    axes = [*figures[0].axes[:2], figures[1].axes[0], figures[2].axes[0]]
    for ax in axes:
        ellipse = next(ln for ln in ax.get_lines() if ln.get_label() == "Hertz contact")
        assert _displayed_aspect(ax, ellipse) == pytest.approx(
            b_over_a if to_scale else 5.0, rel=0.02)
    for ax in (axes[0], axes[2], axes[3]):
        assert ax.get_ylabel() == ("y / a" if to_scale else "y / a  (compressed 1.9 times)")
    for fig in figures:
        plt.close(fig)


def test_case_file_in_imperial_units_reports_imperial_beside_si(tmp_path):
    case = tmp_path / "imperial.toml"
    case.write_text('''analysis = "normal"
title = "Ball in inches"
[body1]
youngs_modulus = "30e6 psi"
[body2]
youngs_modulus = "30e6 psi"
[geometry]
shape = "sphere"
rx = "0.5 in"
[loading]
load = "100 lbf"
[grid]
nx = 32
ny = 32
x_extent = "0.04 in"
y_extent = "0.04 in"
''')
    result = CliRunner().invoke(app, ["run", str(case), "--out", str(tmp_path / "out"),
                                      "--quiet"])
    assert result.exit_code == 0, result.output
    html = (tmp_path / "out" / "report.html").read_text()
    assert "444.8 N (100 lbf)" in html                      # 100 lbf = 444.82 N
    assert "12.7 mm (0.5 in)" in html                       # the radius among the parameters
    assert re.search(r"maximum pressure</td><td>\d+(\.\d+)? GPa \(\d+ psi\)", html)
    assert "100 lbf" in result.output                       # the terminal summary too


@pytest.mark.parametrize(("value", "reference", "shown"), [
    (962.0, 962.0, "<td>0 %</td>"),                   # exact
    (5765.0, 1296 * 4.4482216, "<td>&lt; 0.01 %</td>"),  # 0.0019 %: below what two decimals show
    (1006.3, 1000.0, "<td>+0.63 %</td>"),
    (993.7, 1000.0, "<td>\u22120.63 %</td>"),         # a minus sign, not a hyphen
])
def test_comparison_differences_as_people_read_them(value, reference, shown):
    outcome = Outcome(xr.Dataset(), {}, comparisons=[
        Comparison("load", value, reference, "closed form", "N", 1e-2)])
    html = render_report("t", {"analysis": "normal"}, outcome, {})
    assert shown in html


def _parameter(html, key):
    match = re.search(rf"<code>{re.escape(key)}</code></td><td class=l>([^<]*)<", html)
    return match.group(1) if match else None


def test_parameters_show_the_mesh_and_domain_the_run_chose(tmp_path):
    """A transient line contact without a [grid] table: the report gives the mesh and domain
    it ran on (not the schema's 129 x 65 on -2.5..1.5 "m"), leaves out the y bounds a line
    contact does not use, and names the Dowson-Higginson lambda by its case key with its
    unit (it showed as ``lubricant.lambda_`` without one)."""
    path = tmp_path / "cam.toml"
    path.write_text('''analysis = "ehl-transient"
title = "Roller follower on a cam nose"
reduced_modulus = "231 GPa"
[contact]
type = "line"
radius = "7.5 mm"
load_per_length = "250 kN/m"
[speeds]
u = "4 m/s"
xi = 0.1
[lubricant]
eta0 = "9 mPa s"
alpha = "15 1/GPa"
[surface1]
kind = "feature"
feature = "ridge"
amplitude = "0.2 um"
half_width = "20 um"
[time]
counting_steps = 5
''')
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    html = (out / "report.html").read_text()
    nx = xr.open_dataset(out / "result.nc").sizes["x"]
    assert nx != 129
    assert _parameter(html, "grid.nx") == f"{nx} (chosen for the contact)"
    assert _parameter(html, "grid.ny") == "1 (chosen for the contact)"
    assert re.fullmatch(r"-\d+(\.\d+)? Hertz semi-axes \(chosen for the contact\)",
                        _parameter(html, "grid.x_min"))
    assert _parameter(html, "grid.y_min") is None and _parameter(html, "grid.y_max") is None
    assert _parameter(html, "lubricant.lambda") == "1.68 1/GPa"
    assert "lambda_" not in html


def test_parameters_show_a_given_domain_in_hertz_semi_axes(tmp_path):
    """A steady point contact whose [grid] table sets only the inlet and outlet: the bounds as
    given (numbers in Hertz semi-axes, a length as a length), the sides and the nodes as
    chosen for the contact."""
    path = tmp_path / "ball.toml"
    path.write_text('''analysis = "ehl-steady"
reduced_modulus = "220 GPa"
[contact]
rx = "10 mm"
ry = "10 mm"
load = "20 N"
[speeds]
u = "1 m/s"
[lubricant]
eta0 = "0.04 Pa s"
alpha = "20 1/GPa"
viscosity_model = "barus"
density_model = "incompressible"
[grid]
x_min = -3
x_max = "0.5 mm"
''')
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    html = (out / "report.html").read_text()
    data = xr.open_dataset(out / "result.nc")
    assert _parameter(html, "grid.x_min") == "-3 Hertz semi-axes"
    assert _parameter(html, "grid.x_max") == "0.5 mm"
    assert re.fullmatch(r"-\d+(\.\d+)? Hertz semi-axes \(chosen for the contact\)",
                        _parameter(html, "grid.y_min"))
    assert _parameter(html, "grid.nx") == f"{data.sizes['x']} (chosen for the contact)"
    assert _parameter(html, "grid.ny") == f"{data.sizes['y']} (chosen for the contact)"
    # the grids of the sequence, as result.nc lists their shapes: not the key's default of 1
    grids = data.attrs["levels"].count("(") - 1
    assert grids > 1 and _parameter(html, "solver.levels") == f"{grids} (chosen for the contact)"


def test_plain_numbers_of_a_case_show_their_unit():
    """A gear case's speed (rad/s, given as rpm), temperature (deg C) and thermal constants
    are plain numbers in the case model; the report gives their units (they showed as bare
    numbers, the speed as 227.2 where the case file said 2170 rpm)."""
    case = {"analysis": "gear", "operation": {"torque": 302.0, "speed": 227.2,
                                               "bulk_temperature": 90.0},
            "thermal": {"conductivity": [45.0, 45.0], "specific_heat": [460.0, 460.0]}}
    html = render_report("t", case, _outcome(), {})
    assert _parameter(html, "operation.speed") == "227.2 rad/s"
    assert _parameter(html, "operation.bulk_temperature") == "90 °C"
    assert _parameter(html, "thermal.conductivity") == "45 W/(m K), 45 W/(m K)"
    assert _parameter(html, "thermal.specific_heat") == "460 J/(kg K), 460 J/(kg K)"


def test_parameters_leave_out_the_constants_of_laws_not_used(tmp_path):
    """A rigid-isoviscous roller (Barus, alpha = 0, incompressible) listed Roelands' kappa and
    chi and Dowson-Higginson's gamma and lambda, which its laws do not use; a constant the
    case sets stays listed."""
    path = tmp_path / "martin.toml"
    text = '''analysis = "ehl-steady"
title = "Rigid isoviscous roller (Martin)"
reduced_modulus = "230 GPa"
[contact]
type = "line"
radius = "10 mm"
load_per_length = "1 kN/m"
[speeds]
u = "1 m/s"
[lubricant]
eta0 = "50 mPa s"
alpha = "0 1/GPa"
viscosity_model = "barus"
density_model = "incompressible"
'''
    path.write_text(text)
    out = tmp_path / "out"
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "--quiet"])
    assert result.exit_code == 0, result.output
    html = (out / "report.html").read_text()
    for key in ("lubricant.kappa", "lubricant.chi", "lubricant.gamma", "lubricant.lambda"):
        assert _parameter(html, key) is None, key
    assert _parameter(html, "lubricant.viscosity_model") == "barus"
    path.write_text(text + 'chi = "5 1/GPa"\n')
    result = CliRunner().invoke(app, ["run", str(path), "--out", str(out), "--quiet"])
    assert _parameter((out / "report.html").read_text(), "lubricant.chi") == "5 1/GPa"
