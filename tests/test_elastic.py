"""Half-space influence coefficients and their FFT convolutions against independent references.

References: REFERENCE.md (centre deflection of a uniformly loaded square), direct summation,
the periodic sinusoidal-pressure solution u = 2 p / (E* q) (Johnson 1985, sec. 13.2), and
numerical quadrature of the Boussinesq and Cerruti point-load solutions (Johnson eqs. 3.19,
3.86).
"""

import numpy as np
import pytest
from scipy.integrate import dblquad

from asperity.elastic import (
    Convolution,
    cerruti_integrals,
    love_integral,
    normal_influence,
    normal_operator,
    tangential_influence,
    tangential_transfer,
)
from asperity.errors import InputError
from asperity.materials import Material, contact_modulus

STEEL = Material(206e9, 0.3, "steel")
BRONZE = Material(110e9, 0.34, "bronze")


def test_centre_deflection_of_uniformly_loaded_square():
    """w = (2 / (pi E')) 4 ln(1 + sqrt 2) p s (REFERENCE.md)."""
    s, p = 1.3e-5, 2.0e8
    e_prime = 2 * contact_modulus(STEEL, BRONZE)
    expected = 2.0 / (np.pi * e_prime) * 4.0 * np.log(1.0 + np.sqrt(2.0)) * p * s
    w = normal_influence(0.0, 0.0, s, s, STEEL, BRONZE) * p
    assert w == pytest.approx(expected, rel=1e-6)
    assert love_integral(0.0, 0.0, s, s) == pytest.approx(3.5255 * s, rel=1e-4)


def _minimal_image(n):
    return np.fft.fftfreq(n, 1.0 / n)  # offset index of each wrap-around position


@pytest.mark.parametrize("periodic", [False, True])
@pytest.mark.parametrize("shape", [(7, 5), (9, 1)])
@pytest.mark.parametrize("order", ["C", "F"])
def test_fft_convolution_equals_direct_summation(periodic, shape, order):
    """Also a single row (line contacts) and loads stored x-fastest (the EHL fields)."""
    (nx, ny), dx, dy = shape, 2.0e-6, 3.0e-6
    rng = np.random.default_rng(7)
    load = np.asarray(rng.uniform(0.0, 1.0, (nx, ny)), order=order)

    def kernel(X, Y):
        return love_integral(X, Y, dx, dy)

    conv = Convolution.from_coefficients(kernel, dx, dy, (nx, ny), periodic)
    direct = np.zeros((nx, ny))
    for i in range(nx):
        for j in range(ny):
            for k in range(nx):
                for m in range(ny):
                    if periodic:
                        ox = _minimal_image(nx)[(i - k) % nx]
                        oy = _minimal_image(ny)[(j - m) % ny]
                    else:
                        ox, oy = i - k, j - m
                    direct[i, j] += kernel(ox * dx, oy * dy) * load[k, m]
    np.testing.assert_allclose(conv(load), direct, rtol=1e-10, atol=0)


def test_periodic_operator_on_a_sinusoidal_pressure():
    """u = 2 p0 cos(q x) / (E* q) for p = p0 cos(q x) on a periodic half-space."""
    n, length, p0 = 64, 1e-3, 1e7
    x = (np.arange(n) + 0.5) * length / n
    y = (np.arange(n // 2) + 0.5) * length / 2 / (n // 2)
    q = 2 * np.pi * 3 / length
    pressure = p0 * np.cos(q * x)[:, None] * np.ones(y.size)[None, :]
    u = normal_operator(x, y, STEEL, BRONZE, periodic=True)(pressure)
    expected = 2 * pressure / (contact_modulus(STEEL, BRONZE) * q)
    np.testing.assert_allclose(u, expected, rtol=0, atol=1e-12 * np.abs(expected).max())


def _cell_quad(fun, x, y, dx, dy):
    """int over the cell centred at 0 of fun(x - s, y - t) ds dt (field point outside)."""
    value, _ = dblquad(lambda t, s: fun(x - s, y - t), -dx / 2, dx / 2, -dy / 2, dy / 2,
                       epsabs=0, epsrel=1e-11)
    return value


POINTS = [(2.5e-6, 0.3e-6), (-1.7e-6, 2.2e-6), (4.0e-6, -3.5e-6)]


@pytest.mark.parametrize("point", POINTS)
def test_cell_integrals_match_quadrature(point):
    dx, dy = 1.0e-6, 1.5e-6
    g = cerruti_integrals(point[0], point[1], dx, dy)

    def r(a, b):
        return np.hypot(a, b)

    references = {
        "inv_r": lambda a, b: 1 / r(a, b),
        "xx": lambda a, b: a * a / r(a, b) ** 3,
        "yy": lambda a, b: b * b / r(a, b) ** 3,
        "xy": lambda a, b: a * b / r(a, b) ** 3,
        "x_r2": lambda a, b: a / r(a, b) ** 2,
        "y_r2": lambda a, b: b / r(a, b) ** 2,
    }
    for name, fun in references.items():
        expected = _cell_quad(fun, point[0], point[1], dx, dy)
        assert float(g[name]) == pytest.approx(expected, rel=1e-8, abs=1e-20), name
    assert float(love_integral(*point, dx, dy)) == pytest.approx(
        _cell_quad(references["inv_r"], *point, dx, dy), rel=1e-8)


@pytest.mark.parametrize("point", POINTS)
def test_cerruti_one_body_matches_point_load_quadrature(point):
    """Johnson eq. 3.86 at z = 0, integrated over the cell by quadrature."""
    dx, dy = 1.0e-6, 1.5e-6
    G, nu = BRONZE.shear_modulus, BRONZE.poisson_ratio
    c = 1 / (2 * np.pi * G)
    inf = tangential_influence(point[0], point[1], dx, dy, BRONZE)

    def r(a, b):
        return np.hypot(a, b)

    expected = {
        "xx": lambda a, b: c * ((1 - nu) / r(a, b) + nu * a * a / r(a, b) ** 3),
        "xy": lambda a, b: c * nu * a * b / r(a, b) ** 3,
        "yy": lambda a, b: c * ((1 - nu) / r(a, b) + nu * b * b / r(a, b) ** 3),
        "zx": lambda a, b: (1 - 2 * nu) / (4 * np.pi * G) * a / r(a, b) ** 2,
    }
    for name, fun in expected.items():
        assert float(getattr(inf, name)) == pytest.approx(
            _cell_quad(fun, point[0], point[1], dx, dy), rel=1e-8), name


@pytest.mark.parametrize("point", POINTS)
def test_betti_reciprocity_between_two_cells(point):
    """u_x at B due to unit pressure on cell A = u_z at A due to unit shear q_x on cell B.

    The left side is integrated from Boussinesq's in-plane displacement
    u_x = -(1 - 2 nu) / (4 pi G) x / r^2 (Johnson eq. 3.19a), independently of the code.
    """
    dx, dy = 1.0e-6, 1.5e-6
    G, nu = STEEL.shear_modulus, STEEL.poisson_ratio
    ux_at_b = _cell_quad(
        lambda a, b: -(1 - 2 * nu) / (4 * np.pi * G) * a / np.hypot(a, b) ** 2,
        point[0], point[1], dx, dy)
    uz_at_a = tangential_influence(-point[0], -point[1], dx, dy, STEEL).zx
    assert float(uz_at_a) == pytest.approx(ux_at_b, rel=1e-8)
    # and through the reciprocal property of the result object
    inf = tangential_influence(point[0], point[1], dx, dy, STEEL)
    assert float(inf.xz) == pytest.approx(ux_at_b, rel=1e-8)


def test_identical_materials_decouple():
    x, y = np.meshgrid(np.linspace(-5e-6, 5e-6, 7), np.linspace(-4e-6, 4e-6, 5), indexing="ij")
    two = tangential_influence(x, y, 1e-6, 1e-6, STEEL, STEEL)
    one = tangential_influence(x, y, 1e-6, 1e-6, STEEL)
    assert np.all(two.zx == 0.0) and np.all(two.zy == 0.0)
    np.testing.assert_allclose(two.xx, 2 * one.xx, rtol=1e-15)
    np.testing.assert_allclose(two.yy, 2 * one.yy, rtol=1e-15)
    assert np.any(tangential_influence(x, y, 1e-6, 1e-6, STEEL, BRONZE).zx != 0.0)


def test_cerruti_self_cell_integrals_by_quadrature():
    """The loaded cell's own coefficients (the largest ones) against quadrature over its four
    quadrants (the 1/r singularity then sits at a corner of each)."""
    dx, dy = 1.0, 0.6
    kernels = {"inv_r": lambda x, y: 1.0 / np.hypot(x, y),
               "xx": lambda x, y: x * x / np.hypot(x, y) ** 3,
               "yy": lambda x, y: y * y / np.hypot(x, y) ** 3}
    g = cerruti_integrals(0.0, 0.0, dx, dy)
    for name, f in kernels.items():
        quadrant = dblquad(lambda y, x, f=f: f(x, y), 0.0, dx / 2, 0.0, dy / 2, epsabs=0,
                           epsrel=1e-10)[0]
        assert float(g[name]) == pytest.approx(4.0 * quadrant, rel=1e-8), name
    assert float(g["xy"]) == 0.0 and float(g["x_r2"]) == 0.0


def test_tangential_transfer_limits():
    """nu = 0: the Fourier response is isotropic, 1/(G k), no coupling (FT(1/r) = 2 pi/k);
    the transfer of the cells' kernel is not defined at k = 0 (refused, naming the field)."""
    body = Material(2.0e11, 0.0, "nu0")
    k = np.array([1.0e3, 2.0e3])
    t = tangential_transfer(k, 0.5 * k, body)
    kk = np.hypot(k, 0.5 * k)
    np.testing.assert_allclose(t.xx, 1 / (body.shear_modulus * kk), rtol=1e-14)
    np.testing.assert_allclose(t.yy, t.xx, rtol=1e-14)
    assert np.all(t.xy == 0)
    with pytest.raises(InputError, match="kx, ky"):
        tangential_transfer(0.0, 0.0, body)


def test_kept_buffer_convolves_any_kernel_and_forgets_the_last_load():
    """The non-periodic convolution in its kept FFT buffer: an uneven kernel (complex
    spectrum, not the real product of an even one) against the direct sum, and a second load
    after a first one gives what a fresh operator gives (the padding is cleared)."""
    nx, ny, dx, dy = 7, 5, 0.3, 0.7

    def kernel(X, Y):
        return (X + 2.0 * Y + 0.5) / (1.0 + X**2 + Y**2)

    rng = np.random.default_rng(5)
    first, second = rng.random((2, nx, ny))
    conv = Convolution.from_coefficients(kernel, dx, dy, (nx, ny), False)
    assert conv.even_spectrum is None  # the complex product, not the real one
    conv(first)
    direct = np.zeros((nx, ny))
    for i in range(nx):
        for j in range(ny):
            for k in range(nx):
                for m in range(ny):
                    direct[i, j] += kernel((i - k) * dx, (j - m) * dy) * second[k, m]
    np.testing.assert_allclose(conv(second), direct, rtol=1e-10, atol=1e-12)
    fresh = Convolution.from_coefficients(kernel, dx, dy, (nx, ny), False)
    np.testing.assert_array_equal(conv(second), fresh(second))
