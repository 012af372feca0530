"""P, W and R profiles (ISO 4287 / 16610-21), ISO 4288 cut-offs and ISO 3274 lambda_s.

References: the Gaussian filter's amplitude transmission exp(-pi (alpha lambda_c / lambda)^2),
alpha = sqrt(ln 2 / pi), 50 % at lambda = lambda_c (ISO 16610-21 eq. 2); the moments of a
Gaussian height distribution, Rq/Ra = sqrt(pi/2) and Rku = 3; the tables of ISO 4288 and
ISO 3274 (docs/surfaces.md).
"""

import math

import numpy as np
import pytest
from scipy.special import ndtri

from asperity.errors import InputError
from asperity.surfaces import Profile
from asperity.surfaces.cutoffs import cutoff_for_ra, cutoff_for_rsm, lambda_s_for
from asperity.surfaces.profiles import profile_families, profile_parameters

ALPHA = math.sqrt(math.log(2) / math.pi)
H = 0.5e-6


def trace(length, heights_of_x):
    x = (np.arange(int(round(length / H))) + 0.5) * H
    return Profile(x, heights_of_x(x))


def amplitude(z, x, wavelength):
    """Amplitude of the sine of ``wavelength`` in z by least squares (with a constant)."""
    basis = np.column_stack([np.sin(2 * np.pi * x / wavelength),
                             np.cos(2 * np.pi * x / wavelength), np.ones_like(x)])
    coef = np.linalg.lstsq(basis, z, rcond=None)[0]
    return float(np.hypot(*coef[:2]))


@pytest.mark.parametrize("ratio", [1.0, 1 / 3, 3.0, 0.5, 2.0])
def test_sine_transmission_is_the_gaussian_one(ratio):
    cutoff = 0.8e-3
    wavelength = ratio * cutoff
    # form_degree=0: a least-squares line would take part of a long sine with it
    fam = profile_families(trace(6e-3, lambda x: 1e-6 * np.sin(2 * np.pi * x / wavelength)),
                           cutoff, lambda_s=None, form_degree=0)
    x = fam.primary.x[fam.evaluation]
    w = amplitude(fam.evaluated("W"), x, wavelength) / 1e-6
    r = amplitude(fam.evaluated("R"), x, wavelength) / 1e-6
    expected = math.exp(-math.pi * (ALPHA * cutoff / wavelength) ** 2)
    assert w == pytest.approx(expected, abs=2e-3)
    assert r == pytest.approx(1 - expected, abs=2e-3)
    if ratio == 1.0:
        assert w == pytest.approx(0.5, abs=2e-3)  # 50 % at lambda_c


def test_sum_of_sines_split_by_wavelength():
    # 5 um ripples are roughness, 4 mm waves are waviness, at lambda_c = 0.8 mm
    fam = profile_families(trace(12e-3, lambda x: 0.3e-6 * np.sin(2 * np.pi * x / 50e-6)
                                 + 2e-6 * np.sin(2 * np.pi * x / 4e-3)), 0.8e-3,
                           lambda_s=None, form_degree=0)
    x = fam.primary.x[fam.evaluation]
    t_long = math.exp(-math.pi * (ALPHA * 0.8e-3 / 4e-3) ** 2)
    t_short = math.exp(-math.pi * (ALPHA * 0.8e-3 / 50e-6) ** 2)
    assert amplitude(fam.evaluated("R"), x, 50e-6) == pytest.approx(0.3e-6 * (1 - t_short),
                                                                   rel=1e-3)
    assert amplitude(fam.evaluated("W"), x, 4e-3) == pytest.approx(2e-6 * t_long, rel=2e-3)
    params = profile_parameters(fam)
    # Rq of the remaining sines: amplitude / sqrt(2) each, in quadrature
    rq = math.hypot(0.3e-6 * (1 - t_short), 2e-6 * (1 - t_long)) / math.sqrt(2)
    assert params["R"]["Rq"] == pytest.approx(rq, rel=0.02)


def test_gaussian_heights_moments():
    # Exactly Gaussian quantiles in random order: white noise whose wavelengths lie far below
    # lambda_c, so R keeps the distribution; Rq/Ra = sqrt(pi/2), Rku = 3, Rsk = 0.
    n = int(4.8e-3 / H)
    z = 0.5e-6 * np.random.default_rng(3).permutation(ndtri((np.arange(n) + 0.5) / n))
    fam = profile_families(Profile((np.arange(n) + 0.5) * H, z), 0.8e-3)
    assert fam.sampling_lengths == 5 and fam.lambda_s == pytest.approx(2.5e-6)
    # lambda_s = 2.5 um removes part of the white noise; without it the ratio is exact
    plain = profile_parameters(profile_families(Profile(fam.primary.x, z), 0.8e-3,
                                                lambda_s=None))["R"]
    assert plain["Rq"] / plain["Ra"] == pytest.approx(math.sqrt(math.pi / 2), rel=0.01)
    assert plain["Rku"] == pytest.approx(3.0, abs=0.15)
    assert plain["Rsk"] == pytest.approx(0.0, abs=0.1)


def test_rz_is_the_mean_of_five_sampling_lengths():
    # one spike of height 5 um in one sampling length of a 0.1 um sine profile
    base = trace(4.8e-3, lambda x: 0.1e-6 * np.sin(2 * np.pi * x / 20e-6))
    fam = profile_families(base, 0.8e-3, lambda_s=None)
    z = base.z.copy()
    spike = fam.evaluation.start + 100 + int(np.argmax(fam.evaluated("R")[100:140]))
    z[spike] += 5e-6  # on a crest, so the highest peak of its sampling length rises by 5 um
    spiked = profile_parameters(profile_families(base.with_heights(z), 0.8e-3,
                                                 lambda_s=None))["R"]
    plain = profile_parameters(fam)["R"]
    assert spiked["Rz"] - plain["Rz"] == pytest.approx(5e-6 / 5, rel=0.02)
    assert spiked["Rt"] - plain["Rt"] == pytest.approx(5e-6, rel=0.02)


def test_iso4288_cutoff_from_the_profile():
    # Ra of a fine ripple 0.05 um -> 0.25 mm; 0.5 um -> 0.8 mm; 5 um -> 2.5 mm (Table 1)
    for ra, expected in ((0.05e-6, 0.25e-3), (0.5e-6, 0.8e-3), (5e-6, 2.5e-3)):
        amp = ra * math.pi / 2  # Ra of a sine = 2 A / pi
        fam = profile_families(trace(16e-3, lambda x, a=amp: a * np.sin(2 * np.pi * x / 30e-6)))
        assert fam.cutoff == pytest.approx(expected)
        assert "ISO 4288" in fam.notes[0]
    assert cutoff_for_ra(0.01e-6) == 0.08e-3 and cutoff_for_ra(20e-6) == 8e-3


def test_iso4288_cutoff_nearest_held_when_the_profile_is_short():
    """Ra = 14 um asks for 8 mm (Table 1: (10, 80] um), which a 6 mm profile cannot hold with
    run-in and run-out (8 mm alone is longer); the nearest held, 2.5 mm, is used and named,
    not the 0.8 mm the search began with."""
    amp = 14e-6 * math.pi / 2
    fam = profile_families(trace(6e-3, lambda x: amp * np.sin(2 * np.pi * x / 100e-6)))
    assert fam.cutoff == pytest.approx(2.5e-3)
    assert any("asks for 8 mm" in w and "used 2.5 mm" in w for w in fam.warnings)


def test_a_turned_trace_is_told_the_periodic_cut_off_of_iso_4288():
    """Feed marks of f = 0.3 mm cut by a 0.4 mm nose (arcs r - sqrt(r^2 - u^2)), 6 mm traced:
    Ra 7.4 um puts it at 2.5 mm by Table 1, which the trace holds once, and the warning said
    only to measure 15 mm. ISO 4288 takes a periodic profile's cut-off from RSm (Table 3:
    (0.13, 0.4] mm -> 0.8 mm), which 6 mm hold five times; the warning now says so, and with it
    Ra is the arcs' within 0.5 % (the 0.8 mm mean line passes exp(-pi (alpha 0.8 / 0.3)^2) =
    0.7 % of the fundamental)."""
    f, r = 0.3e-3, 0.4e-3

    def arcs(x):
        u = np.mod(x, f) - f / 2
        return r - np.sqrt(r * r - u * u)

    profile = trace(6e-3, arcs)
    fam = profile_families(profile)
    assert fam.cutoff == pytest.approx(2.5e-3)
    warning = next(w for w in fam.warnings if w.startswith("sampling lengths"))
    assert "RSm = 0.3 mm: 0.8 mm" in warning and '--cutoff "0.8 mm"' in warning
    u = np.linspace(-f / 2, f / 2, 200001)
    z = r - np.sqrt(r * r - u * u)
    ra_arcs = np.mean(np.abs(z - z.mean()))  # 7.432 um
    at = profile_families(profile, 0.8e-3)
    assert at.sampling_lengths == 5 and not at.warnings
    assert profile_parameters(at)["R"]["Ra"] == pytest.approx(ra_arcs, rel=5e-3)
    assert [cutoff_for_rsm(v * 1e-3) for v in (0.03, 0.1, 0.3, 1.0, 3.0)] == pytest.approx(
        [0.08e-3, 0.25e-3, 0.8e-3, 2.5e-3, 8e-3])


def test_lambda_s_only_where_the_spacing_allows():
    assert lambda_s_for(0.8e-3, 0.5e-6)[0] == pytest.approx(2.5e-6)
    assert lambda_s_for(2.5e-3, 1.5e-6)[0] == pytest.approx(8e-6)
    value, reason = lambda_s_for(0.8e-3, 1e-6)
    assert value is None and "coarser" in reason


def test_short_profiles_warn_or_refuse():
    fam = profile_families(trace(3e-3, lambda x: 1e-6 * np.sin(2 * np.pi * x / 50e-6)), 0.8e-3)
    assert fam.sampling_lengths == 2 and "2 of the 5" in fam.warnings[0]
    with pytest.raises(InputError, match="cutoff"):
        profile_families(trace(1e-3, lambda x: np.sin(x)), 0.8e-3)


@pytest.mark.parametrize("wavelength", [37e-6, 50e-6, 123e-6])
def test_rsm_of_a_sine_is_its_wavelength(wavelength):
    # a 3 um ripple of 5 % amplitude adds mean-line crossings that the 10 % Rz height
    # discrimination of ISO 4287 must discard
    fam = profile_families(trace(4.8e-3, lambda x: 1e-6 * np.sin(2 * np.pi * x / wavelength)
                                 + 0.05e-6 * np.sin(2 * np.pi * x / 3e-6)), 0.8e-3,
                           lambda_s=None)
    assert profile_parameters(fam)["R"]["RSm"] == pytest.approx(wavelength, abs=H)


def arcs(x, radius=0.8e-3, feed=0.1e-3):
    """Turning marks: nose arcs of ``radius`` every ``feed``."""
    u = x % feed - feed / 2
    return radius - np.sqrt(radius ** 2 - u ** 2)


def test_shape_of_a_round_off_w_profile_is_left_out():
    """Turned arcs (f = 0.1 mm, r = 0.8 mm) at lambda_c = 2.5 mm: the Gaussian transmits
    exp(-pi (alpha 25)^2) ~ 1e-190 of the feed marks, so W is round-off (Wq < 1e-3 Pq):
    Wsk, Wku are n/a with a note. The R profile is the arcs after lambda_s = 8 um: Rq 0.4633 um,
    Rsk 0.621 from numpy's FFT of the same Gaussian (0.1 %). A 2 mm sine of 0.1 um amplitude
    added (16 mm: whole periods, so the least-squares line takes none of it) keeps, at
    lambda_c = 0.8 mm, Wsk 0 and Wku 1.5 (within 0.05), a sine's."""
    from asperity.surfaces import evaluate_texture

    turned = trace(15e-3, arcs)
    texture = evaluate_texture(turned, 2.5e-3)
    w, r = texture.groups["W"], texture.groups["R"]
    assert w["Wq"] < 1e-3 * texture.groups["P"]["Pq"]
    assert math.isnan(w["Wsk"]) and math.isnan(w["Wku"])
    assert any(n.startswith("W profile at round-off") and "Wsk and Wku" in n
               for n in texture.notes)
    assert r["Rq"] == pytest.approx(0.4633e-6, rel=1e-3)
    assert r["Rsk"] == pytest.approx(0.621, rel=1e-3)
    wavy = evaluate_texture(trace(16e-3, lambda x: arcs(x) + 0.1e-6 * np.sin(
        2 * np.pi * x / 2e-3)), 0.8e-3)
    assert wavy.groups["W"]["Wsk"] == pytest.approx(0.0, abs=0.05)
    assert wavy.groups["W"]["Wku"] == pytest.approx(1.5, abs=0.05)
    assert not any(n.startswith("W profile at round-off") for n in wavy.notes)
