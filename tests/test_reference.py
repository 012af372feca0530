"""Closed forms of frictional contact against independent checks (quadrature, limits)."""

import numpy as np
import pytest
from scipy.integrate import quad

from asperity.contact import reference as ref
from asperity.errors import InputError
from asperity.materials import Material

STEEL = Material(206e9, 0.3, "steel")
RIGID = Material(float("inf"), 0.3, "rigid")
A, P, MU = 1e-3, 1000.0, 0.3
P0 = 3 * P / (2 * np.pi * A * A)


@pytest.mark.parametrize("ratio", [0.0, 0.25, 0.5, 0.9, 1.0])
def test_cattaneo_traction_carries_force(ratio):
    cm = ref.cattaneo_mindlin(P, ratio * MU * P, MU, A, STEEL, STEEL)
    total, _ = quad(lambda r: 2 * np.pi * r * cm.traction(r), 0, A, points=[cm.stick_radius],
                    epsrel=1e-11)
    assert total == pytest.approx(ratio * MU * P, rel=1e-8, abs=1e-9)
    assert cm.stick_radius == pytest.approx(A * (1 - ratio) ** (1 / 3))


def test_cattaneo_small_force_is_mindlin_stiffness():
    # full-stick stiffness Q/delta = 8 a / C (Mindlin 1949)
    Q = 1e-6 * MU * P
    cm = ref.cattaneo_mindlin(P, Q, MU, A, STEEL, STEEL)
    C = 2 * (2 - 0.3) / STEEL.shear_modulus
    assert Q / cm.shift == pytest.approx(8 * A / C, rel=1e-5)


def test_masing_loop_closes_and_is_odd():
    Qs = 0.6 * MU * P
    peak = ref.cattaneo_mindlin(P, Qs, MU, A, STEEL, STEEL).shift
    assert ref.masing_unloading_shift(Qs, Qs, P, MU, A, STEEL, STEEL) == pytest.approx(peak)
    assert ref.masing_unloading_shift(-Qs, Qs, P, MU, A, STEEL, STEEL) == pytest.approx(-peak)
    # unloading branch is stiffer than the loading curve at the same force
    assert ref.masing_unloading_shift(0.3 * MU * P, Qs, P, MU, A, STEEL, STEEL) > \
        ref.cattaneo_mindlin(P, 0.3 * MU * P, MU, A, STEEL, STEEL).shift


@pytest.mark.parametrize("ratio", [0.01, 0.3, 0.6, 0.9, 0.99, 1.0])
def test_mindlin_deresiewicz_energy_is_the_masing_loop_area(ratio):
    """The loop 0 -> Q* -> -Q* -> Q* encloses 4 Q* delta(Q*) - 8 int_0^Q* delta dQ with
    delta = (3 mu P C / (16 a)) [1 - (1 - Q/(mu P))^(2/3)] written out here (quadrature, not
    the module's shift), and C Q*^3 / (36 mu P a) at small amplitude."""
    C = 2 * (2 - 0.3) / STEEL.shear_modulus
    delta = lambda q: 3 * MU * P * C / (16 * A) * (1 - (1 - q / (MU * P)) ** (2 / 3))  # noqa: E731
    qs = ratio * MU * P
    loop = 4 * qs * delta(qs) - 8 * quad(delta, 0, qs, epsabs=0, epsrel=1e-12)[0]
    energy = ref.mindlin_deresiewicz_energy(qs, P, MU, A, STEEL, STEEL)
    assert energy == pytest.approx(loop, rel=1e-9)
    if ratio <= 0.01:
        assert energy == pytest.approx(C * qs**3 / (36 * MU * P * A), rel=0.02)
    with pytest.raises(InputError, match="peak_force"):
        ref.mindlin_deresiewicz_energy(1.01 * MU * P, P, MU, A, STEEL, STEEL)


def test_lubkin_limits():
    assert ref.lubkin_moment(0.0, A, MU, P0) == pytest.approx(
        ref.gross_slip_moment_hertz(MU, P, A), rel=1e-10)
    assert ref.lubkin_moment(A, A, MU, P0) == 0.0
    # near full stick, M / beta tends to the torsional stiffness (16/3) G a^3 of one body
    c = A * (1 - 1e-7)
    beta = ref.lubkin_twist(c, A, MU, P0, STEEL)
    assert ref.lubkin_moment(c, A, MU, P0) / beta == pytest.approx(
        16 / 3 * STEEL.shear_modulus * A**3, rel=1e-5)
    # relative twist of two equal bodies is twice one body's
    assert ref.lubkin_twist(0.5 * A, A, MU, P0, STEEL, STEEL) == pytest.approx(
        2 * ref.lubkin_twist(0.5 * A, A, MU, P0, STEEL, RIGID))


def test_lubkin_stick_radius_inverts_moment():
    m = 0.5 * ref.gross_slip_moment_hertz(MU, P, A)
    c = ref.lubkin_stick_radius(m, A, MU, P0)
    assert ref.lubkin_moment(c, A, MU, P0) == pytest.approx(m, rel=1e-10)


def test_uniform_torsion_limits_and_quadrature():
    p = 1e8
    assert ref.uniform_torsion_moment(0.0, A, MU, p) == pytest.approx(
        ref.gross_slip_moment_uniform(MU, p, A))
    # full slip moment by quadrature: int mu p r dA
    full, _ = quad(lambda r: 2 * np.pi * r * r * MU * p, 0, A)
    assert ref.gross_slip_moment_uniform(MU, p, A) == pytest.approx(full, rel=1e-12)
    c = A * (1 - 1e-8)
    beta = ref.uniform_torsion_twist(c, A, MU, p, STEEL)
    assert ref.uniform_torsion_moment(c, A, MU, p) / beta == pytest.approx(
        16 / 3 * STEEL.shear_modulus * A**3, rel=1e-4)
    m = 0.7 * full
    c = ref.uniform_torsion_stick_radius(m, A, MU, p)
    assert ref.uniform_torsion_moment(c, A, MU, p) == pytest.approx(m, rel=1e-10)


def test_bad_input():
    with pytest.raises(InputError, match="force"):
        ref.cattaneo_mindlin(P, 2 * MU * P, MU, A, STEEL, STEEL)
    with pytest.raises(InputError, match="mu"):
        ref.cattaneo_mindlin(P, 0.1, -0.1, A, STEEL, STEEL)
    with pytest.raises(InputError, match="moment"):
        ref.lubkin_stick_radius(2 * ref.gross_slip_moment_hertz(MU, P, A), A, MU, P0)


def test_ellipse_gross_slip_moment_reduces_to_the_circle_and_matches_quadrature():
    from scipy.integrate import dblquad

    from asperity.contact.reference import gross_slip_moment_ellipse, gross_slip_moment_hertz

    mu, p0, a = 0.1, 1e9, 1e-3
    load = 2.0 / 3.0 * np.pi * a * a * p0
    assert gross_slip_moment_ellipse(mu, p0, a, a) == pytest.approx(
        gross_slip_moment_hertz(mu, load, a), rel=1e-12)
    b = 0.4 * a  # brute force in elliptic coordinates: x = a r cos t, y = b r sin t
    value = dblquad(lambda r, t: mu * p0 * np.sqrt(1 - r * r) * a * b * r
                    * np.hypot(a * r * np.cos(t), b * r * np.sin(t)), 0, 2 * np.pi, 0, 1,
                    epsabs=0, epsrel=1e-11)[0]
    assert gross_slip_moment_ellipse(mu, p0, a, b) == pytest.approx(value, rel=1e-8)


def test_rectangle_distance_integral_matches_quadrature():
    from scipy.integrate import dblquad

    from asperity.contact.reference import rectangle_distance_integral

    def brute(x1, x2, y1, y2):  # split at the axes, where |r| has its kink
        xs = sorted({x1, x2, *([0.0] if x1 < 0 < x2 else [])})
        ys = sorted({y1, y2, *([0.0] if y1 < 0 < y2 else [])})
        return sum(dblquad(lambda y, x: np.hypot(x, y), a, b, c, d, epsabs=0,
                           epsrel=1e-11)[0]
                   for a, b in zip(xs[:-1], xs[1:], strict=True)
                   for c, d in zip(ys[:-1], ys[1:], strict=True))

    for box in [(0.2, 0.8, -0.3, 0.3), (-0.5, -0.1, 0.2, 0.9), (-0.3, 0.4, -0.2, 0.6)]:
        assert rectangle_distance_integral(*box) == pytest.approx(brute(*box), rel=1e-9)
