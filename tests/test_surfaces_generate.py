"""Surface data model and generators: splines, reproducibility, rms, Hurst, correlation."""

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces import (
    Profile,
    Topography,
    add_waviness,
    autocorrelation_length,
    builtin_profile,
    cell_centres,
    gaussian_profile,
    gaussian_topography,
    power_spectrum,
    roughness_parameters,
    self_affine_profile,
    self_affine_topography,
    transverse_ground_profile,
)

# --- data model ---------------------------------------------------------------------------


def test_profile_spline_interpolates_and_wraps():
    n, h = 200, 1e-6
    x = cell_centres(n, h)
    lam = n * h / 4
    p = Profile(x, np.sin(2 * np.pi * x / lam), periodic=True)
    np.testing.assert_allclose(p.sample(x), p.z, atol=1e-13)
    xs = np.linspace(0, 3 * n * h, 777)  # beyond one period: wrapped
    np.testing.assert_allclose(p.sample(xs), np.sin(2 * np.pi * xs / lam), atol=2e-6)
    assert p._spline is p._spline  # built once
    assert p.length == pytest.approx(n * h)
    open_p = Profile(x, p.z)
    with pytest.raises(InputError, match="x: expected positions within"):
        open_p.sample([x[-1] + h])
    np.testing.assert_allclose(open_p.sample(x[5:10] + 0.3 * h),
                               np.sin(2 * np.pi * (x[5:10] + 0.3 * h) / lam), atol=1e-6)


def test_profile_validation():
    with pytest.raises(InputError, match="z"):
        Profile(np.arange(4.0), np.arange(3.0))
    with pytest.raises(InputError, match="x"):
        Profile(np.array([0.0, 1.0, 3.0]), np.zeros(3))
    with pytest.raises(InputError, match="z"):
        Profile(np.arange(3.0), [0.0, np.nan, 1.0])
    p = Profile(np.arange(3.0), np.zeros(3))
    with pytest.raises(ValueError):
        p.z[0] = 1.0  # read-only


def test_extrude_and_topography_sample():
    x = cell_centres(64, 1e-6)
    p = Profile(x, np.cos(2 * np.pi * x / 32e-6), periodic=True)
    y = cell_centres(10, 5e-6)
    t = p.extrude(y)
    assert isinstance(t, Topography) and t.shape == (64, 10)
    np.testing.assert_array_equal(t.z[:, 3], p.z)
    shifted = x + 0.25e-6
    np.testing.assert_allclose(t.sample(shifted), np.repeat(p.sample(shifted)[:, None], 10, 1),
                               atol=1e-12)
    ys = np.array([1e-6, 17e-6, 60e-6])
    assert t.sample(shifted, ys).shape == (64, 3)
    np.testing.assert_allclose(t.sample(shifted, ys)[:, 1], p.sample(shifted), atol=1e-12)
    with pytest.raises(InputError, match="z"):
        Topography(x, y, np.zeros((10, 64)))


# --- generators ---------------------------------------------------------------------------


def test_reproducible_from_seed():
    a = gaussian_profile(1e-3, 1e-6, 1e-6, 20e-6, seed=7)
    b = gaussian_profile(1e-3, 1e-6, 1e-6, 20e-6, seed=7)
    c = gaussian_profile(1e-3, 1e-6, 1e-6, 20e-6, seed=8)
    np.testing.assert_array_equal(a.z, b.z)
    assert not np.allclose(a.z, c.z)
    assert a.periodic and a.x[0] == pytest.approx(0.5e-6)


def _mean_square(surfaces):
    return np.mean([np.mean(s.z**2) for s in surfaces])


@pytest.mark.parametrize("acf", ["gaussian", "exponential"])
def test_gaussian_surfaces_hit_the_rms_in_expectation(acf):
    # Over 16 seeds the standard error of the mean square is ~0.5 %: the rms to 1 %.
    rms = 0.4e-6
    ms = _mean_square(gaussian_profile(0.05, 1e-6, rms, 10e-6, acf=acf, seed=s)
                      for s in range(16))
    assert np.sqrt(ms) == pytest.approx(rms, rel=0.01)
    ms2 = _mean_square(gaussian_topography(0.5e-3, 2e-6, rms, (10e-6, 30e-6), acf=acf, seed=s)
                       for s in range(8))
    assert np.sqrt(ms2) == pytest.approx(rms, rel=0.01)


@pytest.mark.parametrize("acf", ["gaussian", "exponential"])
def test_correlation_length_is_where_the_acf_falls_to_0_2(acf):
    ell = 20e-6
    measured = [autocorrelation_length(gaussian_profile(0.02, 1e-6, 1e-6, ell, acf=acf, seed=s))
                for s in range(6)]
    assert np.mean(measured) == pytest.approx(ell, rel=0.05)


def test_anisotropic_topography():
    # Both sides 40 correlation lengths long, so that the profiles' ACFs are not biased short.
    t = gaussian_topography((0.4e-3, 1.6e-3), 2e-6, 1e-6, (10e-6, 40e-6), seed=3)
    along_x = np.mean([autocorrelation_length(t.z[:, j], t.x, periodic=True)
                       for j in range(0, t.shape[1], 20)])
    along_y = np.mean([autocorrelation_length(t.z[i, :], t.y, periodic=True)
                       for i in range(0, t.shape[0], 5)])
    assert along_x == pytest.approx(10e-6, rel=0.1)
    assert along_y == pytest.approx(40e-6, rel=0.1)


def test_self_affine_rms_height_and_slope_in_expectation():
    kw = {"rolloff_wavelength": 1e-4, "short_cutoff": 4e-6}
    ms = _mean_square(self_affine_profile(0.05, 1e-6, 0.7, rms_height=1e-6, seed=s, **kw)
                      for s in range(16))
    assert np.sqrt(ms) == pytest.approx(1e-6, rel=0.01)
    slopes = [roughness_parameters(self_affine_profile(0.05, 1e-6, 0.7, rms_slope=0.1, seed=s,
                                                       **kw))["Rdq"] for s in range(8)]
    assert np.sqrt(np.mean(np.square(slopes))) == pytest.approx(0.1, rel=0.01)
    grads = [roughness_parameters(self_affine_topography(0.5e-3, 2e-6, 0.7, rms_slope=0.1,
                                                         seed=s, **kw))["Sdq"]
             for s in range(4)]
    assert np.sqrt(np.mean(np.square(grads))) == pytest.approx(0.1, rel=0.01)


def _rms(z):
    return np.sqrt(np.mean((z - z.mean()) ** 2))


def _rms_periodic_slope(z, spacings):
    """sqrt(<|grad z|^2>) from periodic forward differences along each axis."""
    return np.sqrt(sum(np.mean(((np.roll(z, -1, axis=k) - z) / h) ** 2)
                       for k, h in enumerate(spacings)))


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_exact_rescales_the_realisation_to_the_requested_rms(seed):
    kw = {"hurst": 0.8, "seed": seed}
    plain = self_affine_topography(0.5e-3, 2e-6, rms_height=1e-6, **kw)
    exact = self_affine_topography(0.5e-3, 2e-6, rms_height=1e-6, exact=True, **kw)
    assert _rms(exact.z) == pytest.approx(1e-6, rel=1e-12)
    # the same realisation, only rescaled (its own Sq scatters about the expected 1 um)
    ratio = exact.z / plain.z
    assert np.ptp(ratio) < 1e-9 * ratio.mean()
    assert ratio.mean() == pytest.approx(1e-6 / _rms(plain.z), rel=1e-12)
    slope = self_affine_profile(0.01, 1e-6, 0.7, rms_slope=0.1, exact=True, seed=seed)
    assert _rms_periodic_slope(slope.z, [1e-6]) == pytest.approx(0.1, rel=1e-12)
    area = self_affine_topography((0.2e-3, 0.1e-3), 1e-6, 0.5, rms_slope=0.2, exact=True,
                                  seed=seed)
    assert _rms_periodic_slope(area.z, [1e-6, 1e-6]) == pytest.approx(0.2, rel=1e-12)
    g = gaussian_profile(1e-3, 1e-6, 0.3e-6, 20e-6, seed=seed, exact=True)
    assert _rms(g.z) == pytest.approx(0.3e-6, rel=1e-12)
    gt = gaussian_topography(0.2e-3, 2e-6, 0.3e-6, 20e-6, seed=seed, exact=True)
    assert _rms(gt.z) == pytest.approx(0.3e-6, rel=1e-12)


def test_without_exact_one_realisation_scatters_about_the_expected_rms():
    sq = [_rms(self_affine_topography(0.5e-3, 2e-6, 0.8, rms_height=1e-6, seed=s).z)
          for s in range(6)]
    assert np.ptp(sq) > 0.1e-6


def _hurst_from_psd(spec, q_lo, q_hi):
    m = (spec.q > q_lo) & (spec.q < q_hi)
    slope = np.polyfit(np.log(spec.q[m]), np.log(spec.psd[m]), 1)[0]
    return (-slope - spec.dim) / 2  # C1 ~ q^-(1+2H), C2 ~ q^-(2+2H)


@pytest.mark.parametrize("hurst", [0.3, 0.8])
def test_self_affine_hurst_from_the_psd_slope(hurst):
    rolloff, cutoff = 1e-4, 4e-6
    band = (2 * 2 * np.pi / rolloff, 0.5 * 2 * np.pi / cutoff)
    h1 = np.mean([_hurst_from_psd(power_spectrum(self_affine_profile(
        0.02, 1e-6, hurst, rms_height=1e-6, rolloff_wavelength=rolloff, short_cutoff=cutoff,
        seed=s)), *band) for s in range(4)])
    assert h1 == pytest.approx(hurst, abs=0.05)
    h2 = np.mean([_hurst_from_psd(power_spectrum(self_affine_topography(
        0.4e-3, 1e-6, hurst, rms_height=1e-6, rolloff_wavelength=rolloff, short_cutoff=cutoff,
        seed=s)), *band) for s in range(2)])
    assert h2 == pytest.approx(hurst, abs=0.05)


def test_generator_input_errors():
    with pytest.raises(InputError, match="hurst"):
        self_affine_profile(1e-3, 1e-6, 1.2, rms_height=1e-6)
    with pytest.raises(InputError, match="rms_height"):
        self_affine_profile(1e-3, 1e-6, 0.5, rms_height=1e-6, rms_slope=0.1)
    with pytest.raises(InputError, match="short_cutoff"):
        self_affine_profile(1e-3, 1e-6, 0.5, rms_height=1e-6, short_cutoff=1e-6)
    with pytest.raises(InputError, match="acf"):
        gaussian_profile(1e-3, 1e-6, 1e-6, 1e-5, acf="lorentz")
    with pytest.raises(InputError, match="rms"):
        gaussian_profile(1e-3, 1e-6, -1e-6, 1e-5)
    with pytest.raises(InputError, match="length"):
        gaussian_profile(2e-6, 1e-6, 1e-6, 1e-5)


def test_waviness_is_added_along_x_or_y():
    p = gaussian_profile(1e-3, 1e-6, 0.1e-6, 10e-6)
    w = add_waviness(p, 0.25e-3, 0.5e-6)
    np.testing.assert_allclose(w.z - p.z, 0.5e-6 * np.sin(2 * np.pi * p.x / 0.25e-3))
    t = p.extrude(cell_centres(50, 10e-6))
    ty = add_waviness(t, 0.1e-3, 0.3e-6, direction="y", phase=0.5)
    np.testing.assert_allclose(ty.z - t.z, np.broadcast_to(
        0.3e-6 * np.sin(2 * np.pi * t.y / 0.1e-3 + 0.5), t.shape))
    with pytest.raises(InputError, match="direction"):
        add_waviness(p, 1e-4, 1e-7, direction="y")


# --- ground profiles ----------------------------------------------------------------------


def test_run_in_makes_negative_skew_at_the_target_ra():
    fresh = roughness_parameters(transverse_ground_profile(5e-3, 0.5e-6, 0.4e-6, seed=1))
    worn = roughness_parameters(transverse_ground_profile(5e-3, 0.5e-6, 0.4e-6, run_in=0.3,
                                                          seed=1))
    # Ra is met exactly, fresh or run-in (the docstring's promise)
    assert fresh["Ra"] == pytest.approx(0.4e-6, rel=1e-12)
    assert worn["Ra"] == pytest.approx(0.4e-6, rel=1e-12)
    # fresh: Gaussian heights, Rq / Ra = sqrt(pi / 2) (one 5 mm realisation: 2 %)
    assert fresh["Rq"] / fresh["Ra"] == pytest.approx(np.sqrt(np.pi / 2), rel=0.02)
    assert abs(fresh["Rsk"]) < 0.2
    assert worn["Rsk"] < -0.5
    assert worn["Rp"] < fresh["Rp"]  # peaks truncated
    with pytest.raises(InputError, match="run_in"):
        transverse_ground_profile(1e-3, 1e-6, 1e-6, run_in=1.0)


def test_builtin_profiles_match_the_seed():
    params = {name: roughness_parameters(builtin_profile(name)) for name in "ABC"}
    for name, ra in zip("ABC", (0.32e-6, 0.22e-6, 0.31e-6), strict=True):
        assert params[name]["Ra"] == pytest.approx(ra, rel=0.01)
        assert params[name]["Rsk"] < 0  # skewed by running-in
    # C sharpest (largest rms slope), A the most run-in (smallest slopes, most negative skew).
    assert params["C"]["Rdq"] > params["B"]["Rdq"] > params["A"]["Rdq"]
    assert params["A"]["Rsk"] < params["B"]["Rsk"] < params["C"]["Rsk"]
    again = builtin_profile("a")
    np.testing.assert_array_equal(again.z, builtin_profile("A").z)
    with pytest.raises(InputError, match="name: expected one of A, B, C"):
        builtin_profile("D")
