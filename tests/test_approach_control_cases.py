"""Approach control of rough contacts from a case file, a periodic strip's mesh check and a
measured map in the wrong height unit.

References: Westergaard's periodic contact of a sinusoid (Johnson 1985, section 13.3): full
contact at p* = pi E* g / lambda for heights g cos(2 pi x / lambda), a contact of width
2a with sin^2(pi a / lambda) = p / p*, and the mean separation
g [1 - (p/p*)(1 - ln(p/p*))] at a mean pressure p (the strip is flat along y). A rough
flat's approach is measured from the roughness's mean plane, so in partial contact it is
minus the mean separation: a negative number, which the case file used to refuse (and a
positive one too: no approach could be given at all).
"""

import math

import numpy as np
import pytest

from asperity.cases import load_case
from asperity.errors import InputError
from asperity.runners import run_case

E, NU = 210e9, 0.3
E_STAR = E / (2 * (1 - NU**2))
WAVELENGTH, AMPLITUDE = 100e-6, 0.5e-6


def _gaussian_map(n: int, spacing: float, correlation: float, seed: int) -> np.ndarray:
    """An n x n periodic Gaussian random map of unit rms with a Gaussian spectrum of
    correlation length ``correlation`` (m)."""
    q = 2 * np.pi * np.fft.fftfreq(n, spacing)
    qx, qy = np.meshgrid(q, q, indexing="ij")
    noise = np.random.default_rng(seed).standard_normal((n, n))
    z = np.real(np.fft.ifft2(np.exp(-(qx**2 + qy**2) * correlation**2 / 8) * np.fft.fft2(noise)))
    return z / z.std()


def _strip(tmp_path, approach=None, load=None, ny=8):
    """A 1-D sinusoid (two wavelengths, 256 cells along x) pressed by a flat, periodic."""
    nx = 256
    h = 2 * WAVELENGTH / nx
    x = (np.arange(nx) + 0.5) * h
    z = AMPLITUDE * np.cos(2 * np.pi * x / WAVELENGTH)[:, None] * np.ones((1, ny))
    np.save(tmp_path / "sine.npy", z)
    loading = {"approach": approach} if approach is not None else {"load": load}
    return load_case({
        "analysis": "normal", "body1": {"youngs_modulus": E, "poisson_ratio": NU},
        "body2": {"youngs_modulus": E, "poisson_ratio": NU}, "geometry": {"shape": "flat"},
        "loading": loading,
        "grid": {"nx": nx, "ny": ny, "x_extent": nx * h, "y_extent": ny * h,
                 "periodic": True},
        "roughness": {"kind": "file", "path": str(tmp_path / "sine.npy"), "spacing": h}})


def test_a_rough_flat_under_approach_control_carries_westergaards_load(tmp_path):
    """At the approach -g [1 - q (1 - ln q)] with q = 1/4 (-201.7 nm) the mean pressure is
    q p* = 453.1 MPa within 1 %, and the contact covers (2/pi) asin(sqrt(q)) = 1/3 of the
    period within four cells of 256 (each of the two contacts' edges within a cell)."""
    q = 0.25
    p_star = math.pi * E_STAR * AMPLITUDE / WAVELENGTH
    separation = AMPLITUDE * (1 - q * (1 - math.log(q)))
    out = run_case(_strip(tmp_path, approach=f"{-separation * 1e9:.4f} nm"))
    area = 2 * WAVELENGTH * 8 * (2 * WAVELENGTH / 256)
    assert out.summary["load_n"] / area == pytest.approx(q * p_star, rel=0.01)
    fraction = out.summary["contact_area_m2"] / area
    assert fraction == pytest.approx(2 / math.pi * math.asin(math.sqrt(q)), abs=4 / 256)
    assert out.summary["approach_m"] == pytest.approx(-separation, rel=1e-9)
    # the strip spans its whole periodic y: no semi-axis along y to resolve (8 rows of 8
    # cells were told "8 cells per semi-axis along y ... mesh-dependent")
    assert not [w for w in out.warnings if w.startswith("mesh:")]


def test_an_approach_at_which_a_rough_flat_is_in_full_or_no_contact_is_refused(tmp_path):
    """From the mean plane a rough flat is in full contact at approach 0 and first touches
    at minus the amplitude: a positive approach needs load control, one below -0.5 um does
    not touch. Both name loading.approach and what to give."""
    with pytest.raises(InputError) as info:
        run_case(_strip(tmp_path, approach="10 nm"))
    message = str(info.value)
    assert message.startswith("loading.approach: expected less than the mean undeformed gap 0 m")
    assert "loading.load" in message and "10 nm" in message
    with pytest.raises(InputError) as info:
        run_case(_strip(tmp_path, approach="-0.6 um"))
    message = str(info.value)
    assert message.startswith("loading.approach: expected more than -")
    assert "first touch" in message and "mean plane" in message


def test_a_smooth_ball_needs_a_positive_approach(tmp_path):
    case = load_case({
        "analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
        "body2": {"youngs_modulus": "210 GPa"}, "geometry": {"shape": "sphere", "rx": "10 mm"},
        "loading": {"approach": "-1 um"},
        "grid": {"nx": 32, "ny": 32, "x_extent": "0.4 mm", "y_extent": "0.4 mm"}})
    with pytest.raises(InputError) as info:
        run_case(case)
    assert str(info.value).startswith(
        "loading.approach: expected more than 0 m (the smooth bodies first touch at 0")


def _ball_on(path, load: str, extent: str):
    """A 10 mm steel ball pressed on the measured file ``path`` (0.5 um points), 64 x 64
    cells over ``extent`` square."""
    return load_case({
        "analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
        "body2": {"youngs_modulus": "210 GPa"}, "geometry": {"shape": "sphere", "rx": "10 mm"},
        "loading": {"load": load},
        "grid": {"nx": 64, "ny": 64, "x_extent": extent, "y_extent": extent},
        "roughness": {"kind": "file", "path": str(path), "spacing": "0.5 um"}})


def test_heights_in_nm_read_as_metres_are_refused_in_a_contact_case(tmp_path):
    """A map of nm heights (rms 300 nm) without a unit is read as metres: 1.8 km peak to
    valley. It ran to 8738 GPa and exit 0 with a warning; it is refused, and told the case
    file's key, roughness.z_unit, not the command line's --z-unit."""
    z = 300.0 * _gaussian_map(64, 0.5e-6, 6e-6, seed=1)  # nm, rms slope about 0.1 in nm
    np.save(tmp_path / "nm.npy", z)
    with pytest.raises(InputError) as info:
        run_case(_ball_on(tmp_path / "nm.npy", "1 N", "32 um"))
    message = str(info.value)
    assert message.startswith("roughness.path (nm.npy): heights with a peak-to-valley of")
    assert 'roughness.z_unit = "nm"' in message and "--z-unit" not in message


def test_a_profile_as_contact_roughness_is_said_to_be_ridges_across_the_grid(tmp_path):
    """A 1-D trace under a ball is repeated at every y: ridges, whose pressure map a user
    saw without a word on why."""
    x = np.arange(2000) * 0.5e-6
    z = 0.2e-6 * np.sin(2 * np.pi * x / 40e-6)
    np.save(tmp_path / "trace.npy", z)
    out = run_case(_ball_on(tmp_path / "trace.npy", "5 N", "0.25 mm"))
    assert any(n.startswith("roughness.path (trace.npy): a profile along x, repeated at every y")
               for n in out.notes)


def test_a_grid_coarser_than_its_file_is_told_one_mesh_for_the_file_and_the_spots(tmp_path):
    """A 256 x 256 map of 1 um points on a 64 x 64 grid (4 um cells), pressed to a few tens
    of per cent of contact: the roughness line asks for grid.nx >= 256 (every measured
    point) and the spot line asked for fewer (a user's: nx >= 242 beside nx >= 512), two
    advices for one grid. The spot line now asks for the grid that takes every point."""
    n, h = 256, 1e-6
    np.save(tmp_path / "map.npy", 0.2e-6 * _gaussian_map(n, h, 4e-6, seed=2))
    case = load_case({
        "analysis": "normal", "body1": {"youngs_modulus": "210 GPa"},
        "body2": {"youngs_modulus": "210 GPa"}, "geometry": {"shape": "flat"},
        "loading": {"load": "100 N"},
        "grid": {"nx": 64, "ny": 64, "x_extent": n * h, "y_extent": n * h, "periodic": True},
        "roughness": {"kind": "file", "path": str(tmp_path / "map.npy"), "spacing": h}})
    out = run_case(case)
    (rough,) = [w for w in out.warnings if "coarser than the file's points" in w]
    assert "grid.nx >= 256" in rough
    (spots,) = [w for w in out.warnings if w.startswith("mesh: half the load")]
    assert "use nx >= 256 and ny >= 256 on the same extents, which also takes every measured" \
        in spots


def test_a_transient_run_refuses_a_map_whose_heights_are_in_another_unit(tmp_path):
    """A ground map written in nm under a 'Z (um)' header: Sdq 13.7 as read. The transient
    run warned, then diverged at step 3 with advice on the time step (exit 3). It is refused
    before the solve, naming the file's key."""
    n, h = 300, 2e-6
    x, y = np.arange(n) * h, np.arange(40) * h
    rng = np.random.default_rng(4)
    ridges = np.convolve(rng.standard_normal(n + 20), np.ones(8) / 8, "same")[10:-10]
    z_nm = 150.0 * ridges / ridges.std()  # nm: ridges across x, the same at every y
    X, Y = np.meshgrid(x * 1e6, y * 1e6, indexing="ij")
    rows = np.c_[X.ravel(), Y.ravel(), np.repeat(z_nm, y.size)]
    np.savetxt(tmp_path / "map.csv", rows, delimiter=",", fmt="%.5f",
               header="X (um),Y (um),Z (um)", comments="")
    case = load_case({
        "analysis": "ehl-transient", "body1": {"youngs_modulus": "210 GPa"},
        "body2": {"youngs_modulus": "210 GPa"},
        "contact": {"type": "point", "rx": "6.35 mm", "ry": "6.35 mm", "load": "30 N"},
        "speeds": {"u": "0.5 m/s", "xi": 0.2},
        "lubricant": {"eta0": "0.05 Pa s", "alpha": "20 1/GPa"},
        "surface2": {"kind": "file", "path": str(tmp_path / "map.csv")},
        "time": {"counting_steps": 20}})
    with pytest.raises(InputError) as info:
        run_case(case)
    message = str(info.value)
    assert message.startswith("surface2.path (map.csv): heights with an rms slope Sdq = ")
    assert "the units are wrong" in message
