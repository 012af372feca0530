"""Differential-deflection coefficients f_ij against tables, the Laplacian identity and limits."""

import numpy as np
import pytest

from asperity.elastic import love_integral
from asperity.elastic.differential import (
    differential_coefficients,
    line_differential_coefficients,
    strip_integral,
)

# f * dx, rows i (cells along x) 0..2, columns j (cells along y) 0..2 (EHL-NOTES sec. 1,
# tables verified there against quadrature of Love's rectangle)
TABLES = {
    1.0: [[-9.9498, 1.3278, 0.25472], [1.3278, 0.079488, 0.098465],
          [0.25472, 0.098465, 0.036787]],
    4.0: [[-7.0050, 0.18387, 0.016889], [1.7445, 0.027089, 0.015014],
          [0.56630, 0.016315, 0.011301]],
    15.6: [[-6.6394, 0.022337, 0.0011142], [1.8191, 0.0091397, 0.0011046],
           [0.62152, 0.0041211, 0.0010770]],
}


@pytest.mark.parametrize("ratio", sorted(TABLES))
def test_coefficients_match_tables(ratio):
    dx = 2.5e-6
    i, j = np.meshgrid(np.arange(3.0), np.arange(3.0), indexing="ij")
    f = differential_coefficients(i * dx, j * ratio * dx, dx, ratio * dx) * dx
    np.testing.assert_allclose(f, TABLES[ratio], rtol=2e-4)


@pytest.mark.parametrize("ratio", [1.0, 4.0, 15.6])
def test_sum_f_p_is_laplacian_of_deflection(ratio):
    """sum f p == Delta_h (D * p) at interior nodes, for random p (EHL-NOTES identity check)."""
    rng = np.random.default_rng(3)
    nx, ny, dx = 24, 18, 1.0
    dy = ratio * dx
    p = rng.random((nx, ny))
    ix = np.arange(nx)
    iy = np.arange(ny)
    dxo = (ix[:, None, None, None] - ix[None, None, :, None]) * dx
    dyo = (iy[None, :, None, None] - iy[None, None, None, :]) * dy
    D = love_integral(dxo, dyo, dx, dy)  # [i, j, k, l]
    F = differential_coefficients(dxo, dyo, dx, dy)
    w = np.einsum("ijkl,kl->ij", D, p)
    lap = (w[2:, 1:-1] - 2 * w[1:-1, 1:-1] + w[:-2, 1:-1]) / dx**2 + (
        w[1:-1, 2:] - 2 * w[1:-1, 1:-1] + w[1:-1, :-2]
    ) / dy**2
    s = np.einsum("ijkl,kl->ij", F, p)[1:-1, 1:-1]
    assert np.max(np.abs(s - lap)) < 1e-10 * np.max(np.abs(lap))


def test_signs_and_far_field():
    """f_00 < 0, all others > 0, and f -> dx dy / rho^3 far away."""
    dx, dy = 1.0, 4.0
    i, j = np.meshgrid(np.arange(0.0, 30), np.arange(0.0, 10), indexing="ij")
    f = differential_coefficients(i * dx, j * dy, dx, dy)
    assert f[0, 0] < 0
    assert np.all(f.ravel()[1:] > 0)
    rho = np.hypot(60 * dx, 20 * dy)
    far = differential_coefficients(60 * dx, 20 * dy, dx, dy)
    assert far == pytest.approx(dx * dy / rho**3, rel=2e-3)


def test_square_cell_centre_and_strip_integral():
    """Love centre value 4 s asinh 1 feeds f; strip integral against quadrature."""
    assert love_integral(0.0, 0.0, 1.0, 1.0) == pytest.approx(4 * np.arcsinh(1.0), rel=1e-14)
    s = np.linspace(-0.5, 0.5, 200001)
    for x in (0.0, 0.7, 3.0):
        with np.errstate(divide="ignore"):
            g = -2 * np.log(np.abs(x - s))
        g[~np.isfinite(g)] = 0.0
        ref = np.trapezoid(g, s) if x != 0.0 else 2 * (1 + np.log(2.0))
        assert strip_integral(x, 1.0) == pytest.approx(ref, rel=1e-6)


def test_line_coefficients():
    """Line f: f_0 dx = -6.5917, positive elsewhere, 2 dx / x^2 far away, zero sum."""
    dx = 1e-5
    k = np.arange(0, 400)
    f = line_differential_coefficients(k * dx, dx) * dx
    assert f[0] == pytest.approx(-4 * (1 + np.log(2.0)) + 2 * strip_integral(1.0, 1.0), rel=1e-12)
    assert f[0] == pytest.approx(-6.5917, abs=1e-4)
    assert np.all(f[1:] > 0)
    assert f[-1] == pytest.approx(2.0 / k[-1] ** 2, rel=1e-4)
    # total sum f_0 + 2 sum_{k>0} f_k -> 0 (a uniform pressure gives a flat deflection)
    tail = 2 * 2.0 / k[-1]
    assert f[0] + 2 * f[1:].sum() + tail == pytest.approx(0.0, abs=1e-4)
