"""Form removal, the areal S-/L-filters (ISO 16610-61) and the spatial parameters Str, Std.

References: a polynomial form is removed exactly by a least-squares polynomial of its degree;
the areal Gaussian filter transmits 50 % at its nesting index (its weighting function is the
product of two ISO 16610-21 profile ones); grooves z = sin(2 pi (-x sin b + y cos b) / lam)
run along direction b (Std = b), and their ACF does not decay along the grooves (Str near 0);
an isotropic Gaussian surface has Str near 1.
"""

import math

import numpy as np
import pytest

from asperity.errors import InputError
from asperity.surfaces import Topography, gaussian_topography
from asperity.surfaces.areal import (
    areal_families,
    areal_parameters,
    texture_aspect_ratio,
    texture_direction,
)
from asperity.surfaces.form import principal_radii, remove_form

H = 1e-6
X1 = (np.arange(200) + 0.5) * H
Y1 = (np.arange(160) + 0.5) * H
X, Y = np.meshgrid(X1, Y1, indexing="ij")


def grooves(angle_deg, wavelength=17e-6, noise=0.02e-6):
    b = math.radians(angle_deg)
    z = 0.5e-6 * np.sin(2 * np.pi * (-X * math.sin(b) + Y * math.cos(b)) / wavelength)
    return Topography(X1, Y1, z + noise * np.random.default_rng(1).standard_normal(X.shape))


def test_polynomial_form_is_removed_exactly():
    ripple = 0.1e-6 * np.sin(2 * np.pi * X / 20e-6) * np.sin(2 * np.pi * Y / 16e-6)
    quadric = 1e-3 * X + 2e-3 * Y + 50 * X * X - 30 * X * Y + 20 * Y * Y + 1e-6
    flat = remove_form(Topography(X1, Y1, quadric + ripple), 2)
    # the quadric goes entirely: what remains is what the ripple alone leaves
    alone = remove_form(Topography(X1, Y1, ripple), 2)
    assert np.abs(flat.z - alone.z).max() < 1e-9 * 0.1e-6
    assert np.std(flat.z) == pytest.approx(np.std(ripple), rel=0.05)
    tilted = remove_form(Topography(X1, Y1, 1e-3 * X - 2e-3 * Y + 5e-6), 1)
    assert np.abs(tilted.z).max() < 1e-15
    with pytest.raises(InputError, match="form_degree"):
        remove_form(tilted, -1)


@pytest.mark.parametrize("angle", [0.0, 30.0, 75.0, 91.0, 120.0, 165.0])
def test_std_is_the_lay_direction(angle):
    std = texture_direction(grooves(angle))
    assert abs((std - angle + 90) % 180 - 90) < 0.5


def test_str_separates_lay_from_isotropy():
    ratio, exact = texture_aspect_ratio(grooves(30.0))
    assert ratio < 0.1 and not exact  # along the grooves the ACF never decays
    iso = gaussian_topography((200e-6, 160e-6), H, 0.3e-6, 10e-6, seed=3)
    ratio, exact = texture_aspect_ratio(iso)
    assert ratio > 0.7 and exact


def test_l_filter_transmits_half_at_its_nesting_index():
    cut = 40e-6
    wave = Topography(X1, Y1, 1e-6 * np.sin(2 * np.pi * X / cut))
    fam = areal_families(wave, form_degree=0, l_filter=cut, s_filter=None)
    inner = fam.scale_limited.z
    cx = X[fam.evaluation]
    basis = np.column_stack([np.sin(2 * np.pi * cx.ravel() / cut),
                             np.cos(2 * np.pi * cx.ravel() / cut), np.ones(inner.size)])
    coef = np.linalg.lstsq(basis, inner.ravel(), rcond=None)[0]
    assert math.hypot(*coef[:2]) / 1e-6 == pytest.approx(0.5, abs=3e-3)
    assert fam.label == "S-L" and any("L-filter" in n for n in fam.notes)


def test_iso_s_filter_is_iso_3274s_for_the_l_filter_where_the_spacing_allows():
    # ISO 3274 Table 1: lambda_c 0.08 mm -> lambda_s 2.5 um for spacings up to 0.5 um
    x1, y1 = (np.arange(200) + 0.5) * 0.5e-6, (np.arange(180) + 0.5) * 0.5e-6
    z = 0.1e-6 * np.random.default_rng(2).standard_normal((200, 180))
    fine = areal_families(Topography(x1, y1, z), l_filter=0.08e-3)
    assert fine.s_filter == pytest.approx(2.5e-6, rel=1e-12)
    coarse = areal_families(Topography(2 * x1, 2 * y1, z), l_filter=0.08e-3)  # 1 um spacing
    assert coarse.s_filter is None
    assert areal_families(Topography(x1, y1, z), l_filter=0.05e-3).s_filter is None  # not ISO
    assert areal_families(Topography(x1, y1, z)).s_filter is None  # no L-filter


def test_areal_parameters_are_grouped_and_of_the_scale_limited_surface():
    t = gaussian_topography((200e-6, 160e-6), H, 0.3e-6, 10e-6, seed=3)
    fam = areal_families(t)
    groups = areal_parameters(fam)
    assert list(groups) == ["height", "hybrid", "spatial", "functional", "volume"]
    assert fam.label == "S-F"
    assert groups["height"]["Sq"] == pytest.approx(np.std(t.z), rel=1e-6)  # periodic: mean only
    assert 0 < groups["functional"]["Smr1"] < groups["functional"]["Smr2"] < 1


def test_masked_points_are_left_out_of_the_height_parameters(tmp_path):
    # A step: +1 um for x < 20 columns, -1 um after, with the 4 columns around the step
    # missing. Harmonic filling ramps them linearly (0.6, 0.2, -0.2, -0.6 um), symmetric, so
    # the mean stays 0; masked, only the measured +-1 um remain: Sa = Sq = Sp = Sv = 1 um,
    # Ssk = 0, Sku = 1. Filled, Sa is lower by (2 (1 - 0.6) + 2 (1 - 0.2)) / 40 um.
    from asperity.surfaces.io import read_measured
    from asperity.surfaces.texture import evaluate_texture

    z = np.where(np.arange(40)[:, None] < 20, 1e-6, -1e-6) * np.ones((40, 20))
    z[18:22, :] = np.nan
    np.savez(tmp_path / "step.npz", x=(np.arange(40) + 0.5) * H, y=(np.arange(20) + 0.5) * H,
             z=z)
    masked = read_measured(tmp_path / "step.npz", missing="mask")
    assert masked.filled == 80 and any(n.startswith("masked 80 of 800") for n in masked.notes)
    height = evaluate_texture(masked.surface, form_degree=0,
                              exclude=masked.excluded).groups["height"]
    for key, value in (("Sa", 1e-6), ("Sq", 1e-6), ("Sp", 1e-6), ("Sv", 1e-6), ("Ssk", 0.0),
                       ("Sku", 1.0)):
        assert height[key] == pytest.approx(value, abs=1e-12 if key != "Sku" else 1e-9), key
    filled = read_measured(tmp_path / "step.npz", missing="fill")
    assert filled.excluded is None
    sa = evaluate_texture(filled.surface, form_degree=0).groups["height"]["Sa"]
    assert sa == pytest.approx(1e-6 - (2 * 0.4 + 2 * 0.8) / 40 * 1e-6, rel=1e-9)


def cylinder_under_roughness(radius=5e-3, angle_deg=0.0):
    """A 120 um map: 0.25 um rms roughness (Gaussian-smoothed noise, correlation about 3 um)
    on a cylinder of ``radius`` whose axis is ``angle_deg`` + 90 deg from x, with a tilt."""
    from scipy.ndimage import gaussian_filter

    n, h = 240, 0.5e-6
    c = (np.arange(n) - n / 2) * h
    cx, cy = np.meshgrid(c, c, indexing="ij")
    rough = gaussian_filter(np.random.default_rng(1).standard_normal((n, n)), 3, mode="wrap")
    rough *= 0.25e-6 / rough.std()
    b = math.radians(angle_deg)
    across = cx * math.cos(b) + cy * math.sin(b)
    z = rough + radius - np.sqrt(radius ** 2 - across ** 2) + 2e-3 * cx
    return Topography(c, c, z), rough


@pytest.mark.parametrize("angle", [0.0, 30.0, 90.0])
def test_cylinder_left_in_an_areal_map_warns_with_its_radius(angle):
    """A 5 mm cylinder under a plane: Sq 0.2708 um (axis along y) against the roughness'
    0.2500, as numpy's least-squares plane leaves it; the warning names a radius within 12 % of
    5 mm and the direction of its curvature within 5 degrees (the roughness alone has a quadric
    of 44 mm radius, 11 % of the cylinder's curvature; the bare cylinder gives 5 mm to 1e-3);
    --form-degree 2 gives Sq within 0.3 % of the roughness's and no warning."""
    from asperity.surfaces import evaluate_texture

    surface, rough = cylinder_under_roughness(angle_deg=angle)
    flat = evaluate_texture(surface)
    cx, cy = np.meshgrid(surface.x, surface.y, indexing="ij")
    plane = np.stack([np.ones(cx.size), cx.ravel(), cy.ravel()], axis=1)
    levelled = surface.z.ravel() - plane @ np.linalg.lstsq(plane, surface.z.ravel(), rcond=None)[0]
    assert flat.groups["height"]["Sq"] == pytest.approx(levelled.std(), rel=1e-9)
    assert flat.groups["height"]["Sq"] > 1.07 * rough.std()
    (warning,) = [w for w in flat.warnings if w.startswith("form:")]
    radius = float(warning.split("about ")[1].split(" mm")[0]) * 1e-3
    direction = float(warning.split("strongest at ")[1].split(" deg")[0])
    assert radius == pytest.approx(5e-3, rel=0.12)
    assert abs((direction - angle + 90) % 180 - 90) <= 5
    bare = principal_radii(Topography(surface.x, surface.y, surface.z - rough))
    assert bare[0] == pytest.approx(5e-3, rel=1e-3)
    assert abs((bare[2] - angle + 90) % 180 - 90) <= 0.1
    assert "--form-degree 2" in warning
    curved = evaluate_texture(surface, form_degree=2)
    assert not any(w.startswith("form:") for w in curved.warnings)
    assert curved.groups["height"]["Sq"] == pytest.approx(rough.std(), rel=3e-3)


def test_flat_random_maps_do_not_warn_of_form():
    """Gaussian maps of correlation length 1/50 and 1/13 of the field, six seeds each: a quadric
    takes at most 4 % off their Sq, as much as the cubic terms do, so no form warning."""
    from asperity.surfaces import evaluate_texture

    for correlation in (5e-6, 20e-6):
        for seed in range(6):
            t = gaussian_topography(256e-6, 1e-6, 1e-6, correlation, seed=seed)
            t = Topography(t.x, t.y, t.z)  # as measured: not periodic
            assert not any(w.startswith("form:") for w in evaluate_texture(t).warnings)


def test_s_l_surface_is_evaluated_inside_half_a_nesting_index_of_the_borders():
    """0.1 um roughness with a 2 um, 300 um wave on a 240 um map (1 um spacing), L-filter
    40 um. Reference: scipy.ndimage's Gaussian (sigma = alpha lambda / sqrt(2 pi)) of the same
    surface measured 60 um further on every side, where no end correction enters; cut to the
    map. Over the interior without 20 um of each border the S-L surface is the reference's to
    0.03 Sq and its Sq to 0.05 %; over the whole map (as before) Sq was 1.2 % low and single
    points 1.8 Sq off."""
    from scipy.ndimage import gaussian_filter

    from asperity.surfaces import evaluate_texture

    n, m, h, cut = 240, 60, 1e-6, 40e-6
    size = n + 2 * m
    rough = gaussian_filter(np.random.default_rng(3).standard_normal((size, size)), 2,
                            mode="wrap")
    c = np.arange(size) * h
    cx, cy = np.meshgrid(c, c, indexing="ij")
    z = 0.1e-6 * rough / rough.std() + 2e-6 * np.sin(2 * np.pi * (cx + 0.5 * cy) / 300e-6)
    sigma = math.sqrt(math.log(2) / math.pi) * cut / math.sqrt(2 * math.pi) / h
    ref = (z - gaussian_filter(z, sigma, mode="constant", truncate=cut / h / sigma))[m:-m, m:-m]
    texture = evaluate_texture(Topography(c[m:-m], c[m:-m], z[m:-m, m:-m]), cut, form_degree=0)
    fam = texture.families
    assert fam.scale_limited.shape == (200, 200)
    inner = ref[fam.evaluation]
    rms = math.sqrt(np.mean(inner ** 2))
    assert np.abs(fam.scale_limited.z - inner).max() < 0.03 * rms
    assert texture.groups["height"]["Sq"] == pytest.approx(rms, rel=5e-4)
    assert any("inside half the nesting index (20 um)" in n for n in texture.notes)


def test_a_field_under_twice_the_nesting_index_is_kept_whole_with_a_warning():
    t = gaussian_topography((200e-6, 160e-6), H, 0.3e-6, 10e-6, seed=3)
    t = Topography(t.x, t.y, t.z)
    fam = areal_families(t, l_filter=100e-6)
    assert fam.scale_limited.shape == t.shape
    (warning,) = fam.warnings
    assert warning.startswith("L-filter: the field is 160 um across") and "limit 200 um" in warning


@pytest.mark.parametrize("angle", [30.0, 120.0])
def test_str_of_a_lay_is_said_to_be_an_upper_bound(angle):
    """Sine grooves along ``angle`` (160 x 200 um): their ACF does not decay along the lay, so
    Str is Sal over half the field, an upper bound; the note says so and names the lay's
    direction within 2 degrees. An isotropic Gaussian surface decays everywhere: no note."""
    from asperity.surfaces import evaluate_texture

    texture = evaluate_texture(grooves(angle))
    (note,) = [n for n in texture.notes if n.startswith("Str = ")]
    assert "is an upper bound" in note
    direction = float(note.split("about ")[1].split(" deg")[0])
    assert abs((direction - angle + 90) % 180 - 90) <= 2
    iso = gaussian_topography((200e-6, 160e-6), H, 0.3e-6, 10e-6, seed=3)
    assert not any(n.startswith(("Str = ", "Sal, Str")) for n in evaluate_texture(iso).notes)


def test_the_lay_direction_of_an_isotropic_surface_is_noted_as_undefined():
    """Std of a user's isotropic map (Str 79.8 %) was printed as 90.66 deg without a word.
    A surface with Str above 0.5 (ISO 25178-2: nearly isotropic) gets a note; a ground one,
    ridges along y (Str a few per cent), does not."""
    from asperity.surfaces.texture import evaluate_texture

    n, h = 128, 1e-6
    rng = np.random.default_rng(7)
    q = 2 * np.pi * np.fft.fftfreq(n, h)
    qx, qy = np.meshgrid(q, q, indexing="ij")
    smooth = np.exp(-(qx**2 + qy**2) * (5e-6) ** 2 / 8)
    z = np.real(np.fft.ifft2(smooth * np.fft.fft2(rng.standard_normal((n, n))))) * 1e-7
    x = (np.arange(n) + 0.5) * h
    iso = evaluate_texture(Topography(x, x, z / z.std() * 1e-7, periodic=True))
    assert iso.groups["spatial"]["Str"] > 0.5
    assert any(note.startswith("Std: the surface is isotropic") for note in iso.notes)
    ridges = np.tile(z[:, :1], (1, n))  # every row the same: ridges along y
    ground = evaluate_texture(Topography(x, x, ridges / ridges.std() * 1e-7, periodic=True))
    assert not any(note.startswith("Std:") for note in ground.notes)
