"""Hertz contact against REFERENCE.md numbers and a brute-force surface-displacement check."""

import numpy as np
import pytest
from scipy.integrate import quad

from asperity.contact import hertz_line, hertz_point
from asperity.errors import InputError
from asperity.materials import Material, contact_modulus

PSI = 6894.757293168361  # Pa
LBF = 4.4482216152605  # N
INCH = 0.0254  # m


def test_steel_spheres_one_inch():
    """Two 1-in steel spheres, E = 30e6 psi, nu = 0.3, 2160 lbf: a = 0.036628 in."""
    steel = Material(30e6 * PSI, 0.3)
    radius = 1.0 / (1.0 / INCH + 1.0 / INCH)  # relative radius of curvature
    hz = hertz_point(2160 * LBF, radius, radius, steel, steel)
    assert hz.a / INCH == pytest.approx(0.036628, rel=2e-5)
    assert hz.b == pytest.approx(hz.a, rel=1e-12)
    assert hz.p_max == pytest.approx(1.5 * hz.load / (np.pi * hz.a**2), rel=1e-12)


def _gear_bodies():
    """Two identical bodies with E' = 2 E* = 227 GPa."""
    nu = 0.3
    body = Material(227e9 * (1 - nu**2), nu)
    assert 2 * contact_modulus(body, body) == pytest.approx(227e9, rel=1e-14)
    return body


def test_gear_case_of_the_mixed_ehl_seed():
    """Rx = 0.0191 m, Ry = 0.151 m, w = 962 N, E' = 227 GPa (REFERENCE.md)."""
    body = _gear_bodies()
    hz = hertz_point(962.0, 0.0191, 0.151, body, body)
    assert hz.a == pytest.approx(0.3364e-3, rel=2e-4)
    assert hz.b == pytest.approx(1.3045e-3, rel=1e-4)
    assert hz.p_max == pytest.approx(1.0466e9, rel=1e-4)
    # swapping the radii swaps the axes
    swapped = hertz_point(962.0, 0.151, 0.0191, body, body)
    assert (swapped.a, swapped.b) == pytest.approx((hz.b, hz.a), rel=1e-12)


@pytest.mark.parametrize("eps", [1e-12, 1e-9, 1e-7, 1e-5])
def test_circular_limit_is_continuous(eps):
    body = _gear_bodies()
    circle = hertz_point(100.0, 0.01, 0.01, body, body)
    near = hertz_point(100.0, 0.01, 0.01 * (1 + eps), body, body)
    for name in ("a", "b", "p_max", "approach"):
        assert getattr(near, name) == pytest.approx(getattr(circle, name), rel=3 * eps + 1e-13)
    assert near.b >= near.a  # the major axis lies along the larger radius


def _displacement(hz, x0, y0):
    """Combined displacement 1/(pi E*) int p / r dA at (x0, y0) inside the ellipse.

    Polar coordinates about the field point remove the 1/r singularity: for each direction
    theta, integrate p along the ray from 0 to the ellipse boundary.
    """
    a, b = hz.a, hz.b

    def ray(theta):
        c, s = np.cos(theta), np.sin(theta)
        # (x0 + rho c)^2 / a^2 + (y0 + rho s)^2 / b^2 = 1
        qa = c * c / a**2 + s * s / b**2
        qb = 2 * (x0 * c / a**2 + y0 * s / b**2)
        qc = x0 * x0 / a**2 + y0 * y0 / b**2 - 1
        rho_max = (-qb + np.sqrt(qb * qb - 4 * qa * qc)) / (2 * qa)
        value, _ = quad(lambda rho: hz.pressure(x0 + rho * c, y0 + rho * s), 0, rho_max,
                        epsabs=0, epsrel=1e-10)
        return value

    total, _ = quad(ray, 0, 2 * np.pi, epsabs=0, epsrel=1e-10, limit=200)
    return total / (np.pi * hz.modulus)


@pytest.mark.parametrize("radii", [(0.01, 0.01), (0.0191, 0.151)])
def test_approach_and_gap_by_quadrature(radii):
    """Inside the contact, u(x, y) + gap0(x, y) = approach (zero deformed gap)."""
    body = _gear_bodies()
    hz = hertz_point(962.0, *radii, body, body)
    for fx, fy in [(0.0, 0.0), (0.5, 0.3), (-0.2, -0.7)]:
        x0, y0 = fx * hz.a, fy * hz.b
        gap0 = x0**2 / (2 * radii[0]) + y0**2 / (2 * radii[1])
        assert _displacement(hz, x0, y0) + gap0 == pytest.approx(hz.approach, rel=1e-8)


def test_pressure_integrates_to_the_load():
    body = _gear_bodies()
    hz = hertz_point(962.0, 0.0191, 0.151, body, body)
    # int p dA = (2/3) p_max pi a b
    assert 2.0 / 3.0 * hz.p_max * hz.area == pytest.approx(962.0, rel=1e-12)
    line = hertz_line(1.0e5, 0.02, body, body)
    integral, _ = quad(line.pressure, -line.a, line.a, epsrel=1e-12)
    assert integral == pytest.approx(1.0e5, rel=1e-9)
    # a^2 = 4 w R / (pi E*)  (Johnson eq. 4.43)
    assert line.a**2 == pytest.approx(4 * 1.0e5 * 0.02 / (np.pi * line.modulus), rel=1e-12)


@pytest.mark.parametrize(
    "kwargs, field",
    [
        ({"load": -1.0}, "load"),
        ({"load": float("nan")}, "load"),
        ({"rx": 0.0}, "rx"),
        ({"ry": -0.01}, "ry"),
        ({"ry": float("inf")}, "ry"),
    ],
)
def test_bad_input(kwargs, field):
    body = _gear_bodies()
    args = {"load": 10.0, "rx": 0.01, "ry": 0.02} | kwargs
    with pytest.raises(InputError, match=field):
        hertz_point(args["load"], args["rx"], args["ry"], body, body)


def test_bad_input_line():
    body = _gear_bodies()
    with pytest.raises(InputError, match="load_per_length"):
        hertz_line(0.0, 0.01, body, body)
    with pytest.raises(InputError, match="radius"):
        hertz_line(1.0, -0.01, body, body)


def _radius_ratio_by_quadrature(aspect):
    """Rx/Ry whose Hertz ellipse has semi-axes a = aspect (along x), b = 1, independently of
    the elliptic-integral closed forms: the ellipsoidal pressure deflects the surface by
    ``const - x^2 I_x - y^2 I_y`` (up to a common factor), ``I_x = int_0^inf dw /
    ((a^2 + w)^3/2 (b^2 + w)^1/2 w^1/2)`` and ``I_y`` alike (Johnson 1985, sec. 3.6), and
    contact requires ``1/(2 Rx) : 1/(2 Ry) = I_x : I_y``. Here w = t^2."""
    from scipy.integrate import quad

    def integral(ex, ey):
        def f(t):
            return 2.0 / ((aspect**2 + t * t) ** ex * (1.0 + t * t) ** ey)

        return quad(f, 0.0, np.inf, epsabs=0.0, epsrel=1e-11, limit=200)[0]

    return integral(0.5, 1.5) / integral(1.5, 0.5)


@pytest.mark.parametrize("aspect", [0.1, 0.25, 0.8, 1.0, 1.3, 4.0, 10.0])
def test_radius_ratio_gives_the_aspect_ratio(aspect):
    """Closed-form Rx/Ry for a/b: the Hertz solution of those radii has a/b to 1e-10, and it
    equals the ratio of the deflection integrals by quadrature (1e-8)."""
    from asperity.contact.hertz import radius_ratio

    assert radius_ratio(aspect) == pytest.approx(_radius_ratio_by_quadrature(aspect), rel=1e-8)

    root_l = np.sqrt(radius_ratio(aspect))
    steel = Material(2e11, 0.3)
    h = hertz_point(10.0, 0.01 * root_l, 0.01 / root_l, steel, steel)
    assert h.a / h.b == pytest.approx(aspect, rel=1e-10)
    assert radius_ratio(aspect) * radius_ratio(1.0 / aspect) == pytest.approx(1.0, rel=1e-12)
