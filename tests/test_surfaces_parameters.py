"""Roughness parameters, spectra, autocorrelation and the Gaussian filter against closed forms."""

import numpy as np
import pytest
from scipy.special import ellipe

from asperity.errors import InputError
from asperity.surfaces import (
    Profile,
    autocorrelation_length,
    cell_centres,
    gaussian_filter,
    gaussian_transmission,
    power_spectrum,
    residual_heights,
    roughness_parameters,
    split_waviness,
)

A = 1.3e-6
WAVELENGTH = 50e-6


def sine_profile(periods=2, per_period=4000, phase=0.0):
    h = WAVELENGTH / per_period
    x = cell_centres(periods * per_period, h)
    return x, A * np.sin(2 * np.pi * x / WAVELENGTH + phase)


def test_sine_profile_closed_forms():
    # Ra = 2A/pi, Rq = A/sqrt2, Rsk = 0, Rku = 1.5 on whole periods (REFERENCE.md, Roughness).
    x, z = sine_profile()
    p = roughness_parameters(z, x, periodic=True)
    assert p["Ra"] == pytest.approx(2 * A / np.pi, rel=1e-6)
    assert p["Rq"] == pytest.approx(A / np.sqrt(2), rel=1e-6)
    assert abs(p["Rsk"]) < 1e-6
    assert p["Rku"] == pytest.approx(1.5, rel=1e-6)
    assert p["Rp"] == pytest.approx(A, rel=1e-6) and p["Rv"] == pytest.approx(A, rel=1e-6)
    assert p["Rt"] == pytest.approx(2 * A, rel=1e-6)
    # Forward differences of A sin(kx): rms = A (2/h) sin(kh/2) / sqrt2, exactly.
    k, h = 2 * np.pi / WAVELENGTH, x[1] - x[0]
    assert p["Rdq"] == pytest.approx(A * 2 / h * np.sin(k * h / 2) / np.sqrt(2), rel=1e-9)


def test_least_squares_mean_line_removes_a_tilt():
    # A cosine on whole periods, symmetric about the centre, is orthogonal to the line, so the
    # least-squares line is exactly the added a + b x.
    x, z = sine_profile(phase=np.pi / 2)
    tilted = z + 3e-6 + 0.02 * x
    p = roughness_parameters(tilted, x)
    assert p["Ra"] == pytest.approx(2 * A / np.pi, rel=1e-6)
    assert p["Rq"] == pytest.approx(A / np.sqrt(2), rel=1e-6)
    np.testing.assert_allclose(residual_heights(tilted), z, atol=1e-9 * A)


def test_slopes_only_with_coordinates():
    _, z = sine_profile()
    assert "Rdq" not in roughness_parameters(z)
    assert "Sdq" not in roughness_parameters(np.outer(z[:50], z[:40]))


def test_rz_is_the_mean_of_five_sampling_lengths():
    z = np.zeros(500)
    peaks, valleys = [1.0, 2.0, 3.0, 4.0, 5.0], [0.5, 1.5, 2.5, 0.1, 0.2]
    for i, (p, v) in enumerate(zip(peaks, valleys, strict=True)):
        z[100 * i + 10] = p
        z[100 * i + 60] = -v
    out = roughness_parameters(z, periodic=True)
    assert out["Rz"] == pytest.approx(np.mean(np.add(peaks, valleys)), rel=1e-12)
    assert out["Rt"] == pytest.approx(5.0 + 2.5, rel=1e-12)
    short = roughness_parameters(z[:40], periodic=True)
    assert short["Rz"] == short["Rt"]


def test_areal_closed_forms_and_plane_removal():
    # z = A cos(kx x) cos(ky y): Sq = A/2, Sa = 4A/pi^2, Ssk = 0, Sku = 9/4; plus a plane.
    nx, ny, hx, hy = 1000, 1500, 1e-6, 2e-6
    x, y = cell_centres(nx, hx), cell_centres(ny, hy)
    kx, ky = 2 * np.pi / (nx * hx / 2), 2 * np.pi / (ny * hy / 3)
    z = A * np.outer(np.cos(kx * x), np.cos(ky * y))
    p = roughness_parameters(z + 1e-6 + 0.01 * x[:, None] - 0.03 * y[None, :], x, y)
    assert p["Sq"] == pytest.approx(A / 2, rel=1e-6)
    assert p["Sa"] == pytest.approx(4 * A / np.pi**2, rel=5e-5)
    assert abs(p["Ssk"]) < 1e-6
    assert p["Sku"] == pytest.approx(9 / 4, rel=1e-6)
    assert p["Sz"] == pytest.approx(2 * A, rel=1e-4)  # the grid misses the crests


def test_developed_area_ratio_of_a_sine():
    # Ridges A sin(kx): Sdr = <sqrt(1 + s^2 cos^2)> - 1 = (2/pi) E(-s^2) - 1, s = A k (with the
    # forward-difference factor), and Sdq = s / sqrt2.
    nx, ny, h = 2000, 8, 0.5e-6
    x, y = cell_centres(nx, h), cell_centres(ny, h)
    k = 2 * np.pi / (nx * h / 4)
    amp = 5e-6
    z = np.repeat((amp * np.sin(k * x))[:, None], ny, axis=1)
    p = roughness_parameters(z, x, y, periodic=True)
    s = amp * 2 / h * np.sin(k * h / 2)
    assert p["Sdq"] == pytest.approx(s / np.sqrt(2), rel=1e-9)
    assert p["Sdr"] == pytest.approx(2 / np.pi * ellipe(-(s**2)) - 1, rel=1e-6)


def test_input_errors():
    with pytest.raises(InputError, match="heights"):
        roughness_parameters([1.0, np.nan, 2.0, 3.0])
    with pytest.raises(InputError, match="x"):
        roughness_parameters(np.ones(10) * np.arange(10), x=np.arange(9.0))
    with pytest.raises(InputError, match="Rq > 0"):
        roughness_parameters(np.ones(10))
    with pytest.raises(InputError, match="y"):
        roughness_parameters(np.eye(5), x=np.arange(5.0))


def test_power_spectrum_parseval_and_sine_peak():
    x, z = sine_profile(periods=8, per_period=256)
    spec = power_spectrum(z, x)
    assert spec.dim == 1
    assert np.sum(spec.psd) * spec.dq == pytest.approx(np.var(z), rel=1e-12)
    peak = np.argmax(spec.psd)
    assert spec.q[peak] == pytest.approx(2 * np.pi / WAVELENGTH, rel=1e-12)
    assert spec.psd[peak] * spec.dq == pytest.approx(A**2 / 2, rel=1e-9)
    rng = np.random.default_rng(4)
    noise = rng.standard_normal(1001)
    s2 = power_spectrum(noise, np.arange(1001.0))
    assert np.sum(s2.psd) * s2.dq == pytest.approx(np.var(noise), rel=1e-12)


def test_radial_power_spectrum_of_a_ring():
    # A single isotropic-ish mode cos(k x) + cos(k y): all power sits at |q| = k.
    n, h = 128, 1e-6
    x = cell_centres(n, h)
    k = 2 * np.pi / (n * h / 8)
    z = np.cos(k * x)[:, None] + np.cos(k * x)[None, :]
    spec = power_spectrum(z, x, x)
    assert spec.dim == 2
    peak = np.argmax(spec.psd)
    assert spec.q[peak] == pytest.approx(k, rel=1e-2)  # the mean |q| of the annulus
    # The annulus average spreads the 4 modes over ~2 pi k / dq modes; the sum of
    # 2 pi q C dq still recovers the variance, to the annulus discretisation.
    total = np.sum(2 * np.pi * spec.q * spec.psd * spec.dq)
    assert total == pytest.approx(np.var(z), rel=0.05)


def test_autocorrelation_length_of_a_cosine():
    # ACF of a cosine of wavelength lam is cos(2 pi tau / lam): 0.2 at lam arccos(0.2) / 2 pi.
    x, z = sine_profile(periods=16, per_period=200)
    ell = autocorrelation_length(z, x, periodic=True)
    assert ell == pytest.approx(WAVELENGTH * np.arccos(0.2) / (2 * np.pi), rel=1e-3)


def test_gaussian_filter_transmits_half_at_the_cutoff():
    cutoff = 0.8e-3
    n, h = 8000, 0.5e-6  # 4 mm = 5 cut-offs
    x = cell_centres(n, h)
    z = A * np.sin(2 * np.pi * x / cutoff)
    mean_line = gaussian_filter(z, x, cutoff, periodic=True)
    assert np.max(np.abs(mean_line - 0.5 * z)) < 1e-12 * A
    # Non-periodic: in the interior (one cut-off from the ends) the same 50 %.
    open_line = gaussian_filter(z, x, cutoff)
    inner = slice(int(cutoff / h), n - int(cutoff / h))
    np.testing.assert_allclose(open_line[inner], 0.5 * z[inner], atol=2e-4 * A)
    assert gaussian_transmission(cutoff, cutoff) == pytest.approx(0.5, rel=1e-14)
    for lam in (0.25e-3, 2e-3):
        z2 = np.sin(2 * np.pi * x / lam) * A
        filtered = gaussian_filter(z2, x, cutoff, periodic=True)
        np.testing.assert_allclose(filtered, gaussian_transmission(lam, cutoff) * z2,
                                   atol=1e-12 * A)


def test_gaussian_filter_end_correction_keeps_a_constant():
    x = cell_centres(1000, 1e-6)
    np.testing.assert_allclose(gaussian_filter(np.full(1000, 3e-6), x, 0.25e-3), 3e-6,
                               rtol=1e-12)
    p = Profile(x, np.sin(x / 3e-5) + 0.1 * np.cos(x / 1e-6))
    wavy, rough = split_waviness(p, 0.25e-3)
    np.testing.assert_allclose(wavy.z + rough.z, p.z, atol=1e-15)
    with pytest.raises(InputError, match="cutoff"):
        gaussian_filter(p.z, x, 1e-6)


def test_linear_end_correction_passes_a_line_and_a_plane_undistorted():
    # A Gaussian-weighted least-squares line through points on a line is that line, at the ends
    # too; the zero-order correction (a weighted mean) bends it there. The areal filter is the
    # profile one along x then y, so a plane passes as well.
    from asperity.surfaces.filters import areal_gaussian_filter

    n, h, cutoff = 400, 1e-6, 80e-6
    x = cell_centres(n, h)
    line = 2e-6 + 3e-3 * x
    linear = gaussian_filter(line, x, cutoff, end_correction="linear")
    np.testing.assert_allclose(linear, line, rtol=0, atol=1e-12 * np.abs(line).max())
    zero = gaussian_filter(line, x, cutoff)
    assert abs(zero[0] - line[0]) > 1e-2 * 3e-3 * cutoff  # the weighted mean lags the ends
    inner = slice(int(cutoff / h) + 1, n - int(cutoff / h) - 1)
    np.testing.assert_allclose(zero[inner], line[inner], rtol=0, atol=1e-12 * line.max())
    y = cell_centres(300, h)
    plane = 1e-6 + 2e-3 * x[:, None] - 4e-3 * y[None, :]
    np.testing.assert_allclose(areal_gaussian_filter(plane, x, y, cutoff), plane, rtol=0,
                               atol=1e-12 * np.abs(plane).max())
    with pytest.raises(InputError, match="end_correction"):
        gaussian_filter(line, x, cutoff, end_correction="quadratic")
