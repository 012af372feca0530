"""Material ratio curve, Rk/Sk family (ISO 13565-2, ISO 25178-2) and volume parameters.

Heights are built as the quantiles of a known material ratio curve C(mr) (sampled at
mr = (k + 1/2)/n, in random order: the order does not matter to these parameters), so each
parameter follows from the construction in closed form:

- two-process (plateau-honed-like) curve, piecewise linear: steep peaks from P to the core
  line a - k mr, the core over [m1, m2], steep valleys down to V. The least-gradient 40 %
  window lies in the core, the equivalent line is the core line, Rk = k, Rpk = P - a and
  Rvk = (a - k) - V (triangles), Mr1 = m1 (P - a) / (P - a + k m1),
  Mr2 = m2 + k (1 - m2)^2 / (a - k m2 - V);
- exponential peaks C(mr) = -lam ln(mr): the window is [60 %, 100 %], the least-squares line
  through -lam ln(mr) there follows from the integrals of ln(m) and m ln(m), Mr1 =
  exp(-intercept / lam) and Rpk = 2 lam exactly; the mirror image (exponential valleys) gives
  Rvk = 2 lam.
"""

import math

import numpy as np
import pytest

from asperity.surfaces.material_ratio import (
    equivalent_line,
    material_ratio,
    material_ratio_curve,
    relative_material_ratio,
    rk_parameters,
    section_height_difference,
    volume_parameters,
)

N = 200_000
MR = (np.arange(N) + 0.5) / N


def shuffled(c):
    return np.random.default_rng(0).permutation(c)


def two_process(P=3.0, a=1.0, k=2.0, m1=0.1, m2=0.8, V=-6.0):
    core = lambda m: a - k * m  # noqa: E731
    c = np.where(MR < m1, P + (core(m1) - P) * MR / m1, core(MR))
    c = np.where(MR > m2, core(m2) + (V - core(m2)) * (MR - m2) / (1 - m2), c)
    return shuffled(c * 1e-6)


def test_two_process_profile_follows_its_construction():
    P, a, k, m1, m2, V = 3.0, 1.0, 2.0, 0.1, 0.8, -6.0
    rk = rk_parameters(two_process(P, a, k, m1, m2, V))
    assert rk["Rk"] == pytest.approx(k * 1e-6, rel=1e-4)
    assert rk["Rpk"] == pytest.approx((P - a) * 1e-6, rel=1e-3)
    assert rk["Rvk"] == pytest.approx((a - k - V) * 1e-6, rel=1e-3)
    assert rk["Mr1"] == pytest.approx(m1 * (P - a) / (P - a + k * m1), abs=1e-4)
    assert rk["Mr2"] == pytest.approx(m2 + k * (1 - m2) ** 2 / (a - k * m2 - V), abs=1e-4)
    line = equivalent_line(two_process(P, a, k, m1, m2, V))
    assert m1 <= line.window[0] and line.window[1] <= m2


def _exponential_reference(lam, p=0.6, q=1.0):
    F = lambda m: -lam * (m * math.log(m) - m)  # noqa: E731  integral of -lam ln m
    G = lambda m: -lam * (m * m / 2 * math.log(m) - m * m / 4)  # noqa: E731  of -lam m ln m
    w = q - p
    mean_f, mean_mf = (F(q) - F(p)) / w, (G(q) - G(p)) / w
    mean_m, var_m = (p + q) / 2, w * w / 12
    slope = (mean_mf - mean_m * mean_f) / var_m
    return mean_f - slope * mean_m, slope


def test_exponential_peaks_and_valleys():
    lam = 0.5e-6
    intercept, slope = _exponential_reference(lam)
    rk = rk_parameters(shuffled(-lam * np.log(MR)))
    assert rk["Rk"] == pytest.approx(-slope, rel=1e-3)
    assert rk["Mr1"] == pytest.approx(math.exp(-intercept / lam), abs=1e-4)
    assert rk["Rpk"] == pytest.approx(2 * lam, rel=1e-3)
    assert rk["Mr2"] == 1.0 and rk["Rvk"] == 0.0  # the curve ends above the core line
    mirrored = rk_parameters(shuffled(lam * np.log(MR)), prefix="S")
    assert mirrored["Svk"] == pytest.approx(2 * lam, rel=1e-3)
    assert mirrored["Sk"] == pytest.approx(-slope, rel=1e-3)
    assert mirrored["Smr2"] == pytest.approx(1 - math.exp(-intercept / lam), abs=1e-4)


def test_curve_ratio_and_section_heights_of_a_uniform_distribution():
    z = shuffled(2e-6 * MR - 1e-6)  # C(mr) = 1 um - 2 um mr
    mr, c = material_ratio_curve(z)
    assert np.all(np.diff(c) <= 0) and mr[0] > 0 and mr[-1] < 1
    assert material_ratio(z, 0.0) == pytest.approx(0.5, abs=1e-5)
    assert section_height_difference(z, 0.2, 0.8) == pytest.approx(1.2e-6, rel=1e-4)
    # Rmr: 0.5 um below the highest peak (1 um) is a quarter of the 2 um range; 0.5 um below
    # the level of 10 % (0.8 um) is 35 %
    assert relative_material_ratio(z, 0.5e-6) == pytest.approx(0.25, abs=1e-4)
    assert relative_material_ratio(z, 0.5e-6, reference=0.1) == pytest.approx(0.35, abs=1e-4)
    rk = rk_parameters(z)
    assert rk["Rk"] == pytest.approx(2e-6, rel=1e-4) and rk["Rpk"] == pytest.approx(0, abs=1e-9)


def test_volumes_of_a_uniform_distribution():
    # C(q) = 1 - 2 q (um): Vm(p) = p^2 (um), Vv(p) = (1 - p)^2 (um)
    v = volume_parameters(shuffled(1e-6 * (1 - 2 * MR)))
    assert v["Vmp"] == pytest.approx(0.01e-6, rel=1e-3)
    assert v["Vmc"] == pytest.approx((0.64 - 0.01) * 1e-6, rel=1e-3)
    assert v["Vvc"] == pytest.approx((0.81 - 0.04) * 1e-6, rel=1e-3)
    assert v["Vvv"] == pytest.approx(0.04e-6, rel=1e-3)


def test_rmr_depth_below_the_deepest_valley_warns():
    # --rmr-depth 2 (meant as um) is 2 m: Rmr = 100 % of any surface, said nothing
    from asperity.surfaces import Profile, Topography, evaluate_texture

    x = (np.arange(8000) + 0.5) * 0.5e-6
    z = 0.4e-6 * np.sin(2 * np.pi * x / 37e-6) + 0.1e-6 * np.sin(2 * np.pi * x / 11e-6)
    wrong = evaluate_texture(Profile(x, z), 0.8e-3, rmr_depth=2.0)
    assert wrong.groups["Rk"]["Rmr"] == 1.0
    assert any(w.startswith("Rmr: the depth 2 m is more than the peak-to-valley") and
               '--rmr-depth "0.5 um"' in w for w in wrong.warnings)
    right = evaluate_texture(Profile(x, z), 0.8e-3, rmr_depth=0.5e-6)
    r = right.families.evaluated("R")
    assert right.groups["Rk"]["Rmr"] == pytest.approx(np.mean(r >= r.max() - 0.5e-6), abs=1e-3)
    assert not any(w.startswith("Rmr") for w in right.warnings)
    t = Topography(x[:64], x[:48], z[:64, None] + z[None, :48])
    assert any(w.startswith("Smr: the depth") for w in
               evaluate_texture(t, rmr_depth=1.0).warnings)
