"""The one surface factory (:mod:`asperity.surfaces.recipe`) against recorded surfaces and
closed forms.

The hashes were recorded from the four dispatches the factory replaced (``[roughness]``,
``[surface1]``/``[surface2]``, ``[surface]`` and ``asperity surface generate``) before the
change: every built-in example's surfaces, and one spec of each kind the examples leave out,
must stay bit-identical.
"""

import hashlib

import numpy as np
import pytest
import typer
from typer.testing import CliRunner

from asperity.cases import load_case
from asperity.cases.ehl_transient import MovingSurfaceSpec
from asperity.cases.roughness import RoughnessSpec, surface_heights, surface_recipe
from asperity.cases.surface import SurfaceSpec
from asperity.cli.surface import surface_app
from asperity.examples import example_text, list_examples
from asperity.runners import run_case
from asperity.surfaces import Profile, read_surface, write_surface
from asperity.surfaces.recipe import SurfaceRecipe, Waviness, build_surface

#: example:table -> hash of its heights (None: no surface), recorded before the factory
EXAMPLES = {
    "dent-rolling:surface1": "cdf90d64bceabdff",
    "dent-rolling:surface2": None,
    "dent-sliding:surface1": "cdf90d64bceabdff",
    "dent-sliding:surface2": None,
    "gear-fzg-c-crowned:surface1": "130236879f741aa3",
    "gear-fzg-c-crowned:surface1:gear": "8cf25a155476a87a",
    "gear-fzg-c-crowned:surface2": "59163fb29972a07e",
    "gear-fzg-c-crowned:surface2:gear": "ff257c462ed3decf",
    "gear-fzg-c:surface1": "130236879f741aa3",
    "gear-fzg-c:surface1:gear": "8cf25a155476a87a",
    "gear-fzg-c:surface2": "59163fb29972a07e",
    "gear-fzg-c:surface2:gear": "ff257c462ed3decf",
    "gear-helical-industrial:surface1": "b49579db89063229",
    "gear-helical-industrial:surface1:gear": "3cf4f1f13a83cee6",
    "gear-helical-industrial:surface2": "3b56bec16d981d5c",
    "gear-helical-industrial:surface2:gear": "884662d42f8f005d",
    "holmes-profiles:surface:A": "63ff0853f502aca8",
    "holmes-profiles:surface:B": "1668eaf06c77a833",
    "holmes-profiles:surface:C": "e92ec2cc9132ad4a",
    "holmes-rough-AA-line:surface1": "1689d5fbd8c65842",
    "holmes-rough-AA-line:surface2": "1689d5fbd8c65842",
    "holmes-rough-AA:surface1": "1689d5fbd8c65842",
    "holmes-rough-AA:surface2": "1689d5fbd8c65842",
    "holmes-rough-AC:surface1": "1689d5fbd8c65842",
    "holmes-rough-AC:surface2": "cf46403bfa6a0d0d",
    "holmes-rough-BB:surface1": "d42e933fb64bf770",
    "holmes-rough-BB:surface2": "d42e933fb64bf770",
    "holmes-rough-C-smooth:surface1": "cf46403bfa6a0d0d",
    "holmes-rough-C-smooth:surface2": None,
    "holmes-rough-CC-paper:surface1": "a3ee27d8efa09c70",
    "holmes-rough-CC-paper:surface2": "a3ee27d8efa09c70",
    "holmes-rough-CC:surface1": "cf46403bfa6a0d0d",
    "holmes-rough-CC:surface2": "cf46403bfa6a0d0d",
    "holmes-rough-sqrt2C-smooth:surface1": "eeda99b64ef083ba",
    "holmes-rough-sqrt2C-smooth:surface2": None,
    "measured-profile:surface:file": "df7c594783754cd1",
    "rough-flat-normal:roughness": "2e141c9c16bd4cca",  # 512 cells, short_cutoff (session 37)
    "rough-sphere-normal:roughness": "e7dc1d6f3e299018",
    "seireg-turning-kinematic:surface:kinematic": "327878a785d2ff10",
    "seireg-turning-vibration:surface:150 Hz": "ae48b6f35aa390e0",
    "seireg-turning-vibration:surface:28 Hz": "707794de8fb5951c",
    "seireg-turning-vibration:surface:34 Hz": "19e57bb1f4276594",
    "seireg-turning-vibration:surface:kinematic": "6353c1c3db4d9f13",
}
#: specs of the kinds the examples leave out, recorded the same way
EXTRA = {
    "extra-moving:builtin-wav": "fa99ca5d0dfb6877",
    "extra-moving:bump": "20b12f2529ec9c0f",
    # session 35: a gaussian moving surface of a point contact is a topography on the rows
    "extra-moving:gauss": "c4c90ae5577287df",
    "extra-moving:ground": "5ef66dea0aa68314",
    "extra-moving:ridge": "e9e23665271e8f2f",
    "extra-moving:smooth-wav": "a6ffc0bf9b14a7fd",
    "extra-moving:smooth-wavy": "da399c9243deef9e",
    "extra-roughness:builtin-wavx": "6398eec993335bfe",
    "extra-roughness:builtin-wavy": "a6585c42a9286b34",
    "extra-roughness:g-aniso": "e9f7d679579e9aa4",
    # session 35: its rows labelled with the grid's own cell centres (the waviness's phase
    # moved by round-off: 8.5e-22 m of 4.8e-6 m)
    "extra-roughness:gauss-wav": "606062a827bc5193",
    "extra-roughness:ground-wav": "bacc7bbfb469dbad",
    "extra-roughness:sa-rms": "264c7121e86096e5",
    "extra-roughness:sa-slope": "7e5dcb68d9115e28",
    "extra-surface:builtin-def:C": "68a5bd3904cfc720",
    "extra-surface:g-prof:gaussian": "0b1d87534052b0ae",
    "extra-surface:g-topo:gaussian": "9ae891064d0bc843",
    "extra-surface:ground-ell:ground": "b8305800e771dca3",
    "extra-surface:ground:ground": "88500ed798aea878",
    "extra-surface:sa-prof:self-affine": "2be02990e9dbb891",
    "extra-surface:sa-topo:self-affine": "b48d213d84f18022",
    "extra-surface:turned:kinematic": "019fc349355cec80",
}

X = np.linspace(-50e-6, 50e-6, 32)
Y = np.linspace(-25e-6, 25e-6, 8)
#: arguments of MovingSurfaceSpec.build: length, spacing, y, mesh dx
MOVING = (2e-3, 0.5e-6, np.linspace(-1e-4, 1e-4, 9), 2e-6)
WAVY = {"wavelength": 40e-6, "amplitude": 0.1e-6}


def _hash(z) -> str:
    z = np.ascontiguousarray(np.asarray(z, dtype=float))
    return hashlib.sha256(repr(z.shape).encode() + z.tobytes()).hexdigest()[:16]


def _example_hashes(name: str) -> dict:
    case = load_case(example_text(name))
    out = {}
    if case.analysis == "normal" and case.roughness is not None:
        out[f"{name}:roughness"] = _hash(surface_heights(case.roughness,
                                                         *case.grid.coordinates()))
    for key in ("surface1", "surface2"):
        spec = getattr(case, key, None)
        if spec is None:
            continue
        surf = spec.build(*MOVING)
        out[f"{name}:{key}"] = None if surf is None else _hash(surf.z)
        if case.analysis == "gear":
            surf = spec.build(4e-3, 0.5e-6, np.zeros(1), 0.5e-6)
            out[f"{name}:{key}:gear"] = _hash(surf.z)
    if case.analysis == "surface":
        heights = run_case(case).dataset["height"]
        for label, z in zip(heights["surface"].values, heights.values, strict=True):
            out[f"{name}:surface:{label}"] = _hash(z)
    return out


@pytest.mark.parametrize("name", sorted({key.split(":")[0] for key in EXAMPLES}))
def test_example_surfaces_are_unchanged(name):
    expected = {key: value for key, value in EXAMPLES.items() if key.split(":")[0] == name}
    assert _example_hashes(name) == expected


def test_every_example_with_a_surface_is_recorded():
    recorded = {key.split(":")[0] for key in EXAMPLES}
    for example in list_examples():
        text = example_text(example.name)
        if any(table in text for table in ("[roughness]\nkind", "[surface1]", "[surface]")):
            assert example.name in recorded


def _extra_surfaces():
    rough = {
        "g-aniso": dict(kind="gaussian", rms=1e-6, correlation_length=8e-6,
                        correlation_length_y=4e-6, acf="exponential", seed=3),
        "sa-rms": dict(kind="self-affine", hurst=0.7, rms=0.5e-6, rolloff_wavelength=30e-6,
                       seed=2),
        "sa-slope": dict(kind="self-affine", hurst=0.8, rms_slope=0.1, short_cutoff=30e-6),
        "ground-wav": dict(kind="ground", ra=0.3e-6, correlation_length=10e-6, run_in=0.3,
                           seed=1, scale=2.0, waviness=WAVY),
        "builtin-wavy": dict(kind="builtin", profile="B", scale=0.5,
                             waviness={**WAVY, "direction": "y"}),
        "builtin-wavx": dict(kind="builtin", profile="A", waviness={**WAVY, "direction": "x"}),
        "gauss-wav": dict(kind="gaussian", rms=1e-6, correlation_length=8e-6, scale=1.5,
                          waviness=WAVY),
    }
    for name, keys in rough.items():
        yield "extra-roughness:" + name, surface_heights(RoughnessSpec(**keys), X, Y)
    moving = {
        "ground": dict(kind="ground", ra=0.4e-6, seed=2, run_in=0.2, scale=1.3, lowpass=2.0),
        "gauss": dict(kind="gaussian", rms=0.2e-6, correlation_length=10e-6, seed=5),
        "ridge": dict(kind="feature", feature="ridge", amplitude=0.1e-6, half_width=20e-6,
                      lead=50e-6),
        "bump": dict(kind="feature", feature="bump", amplitude=0.1e-6, half_width=20e-6,
                     scale=2.0),
        "smooth-wav": dict(kind="smooth", waviness={**WAVY, "direction": "x"}),
        "smooth-wavy": dict(kind="smooth", waviness=WAVY),
        "builtin-wav": dict(kind="builtin", profile="A", scale=1.4142, lowpass=3.0,
                            waviness=WAVY),
    }
    for name, keys in moving.items():
        surf = MovingSurfaceSpec(**keys).build(1e-3, 0.5e-6, MOVING[2], MOVING[3])
        yield "extra-moving:" + name, surf.z
    analysed = {
        "g-prof": dict(kind="gaussian", length=1e-3, spacing=1e-6, rms=1e-6,
                       correlation_length=10e-6, seed=4),
        "g-topo": dict(kind="gaussian", length=1e-4, width=5e-5, spacing=1e-6, rms=1e-6,
                       correlation_length=10e-6, correlation_length_y=5e-6, acf="exponential"),
        "sa-prof": dict(kind="self-affine", length=1e-3, spacing=1e-6, hurst=0.8, rms=1e-6,
                        rolloff_wavelength=1e-4, seed=1),
        "sa-topo": dict(kind="self-affine", length=1e-4, width=1e-4, spacing=1e-6, hurst=0.6,
                        rms_slope=0.2, short_cutoff=4e-6),
        "ground": dict(kind="ground", length=1e-3, spacing=1e-6, ra=0.3e-6, run_in=0.5, seed=9),
        "ground-ell": dict(kind="ground", length=1e-3, spacing=1e-6, ra=0.3e-6,
                           correlation_length=20e-6),
        "builtin-def": dict(kind="builtin", profile="C"),
        "turned": dict(kind="turned", feed=0.1e-3, nose_radius=0.8e-3),
    }
    for name, keys in analysed.items():
        spec = SurfaceSpec(**keys)
        label = spec.labels()[0]
        changes = {"profile": label} if spec.kind == "builtin" else {}
        surf = build_surface(surface_recipe(spec, **changes), spec.profile_length(),
                             spec.profile_spacing(), width=spec.width)
        yield f"extra-surface:{name}:{label}", surf.z


def test_kinds_the_examples_leave_out_are_unchanged():
    assert {key: _hash(z) for key, z in _extra_surfaces()} == EXTRA


def test_waviness_is_added_to_the_scaled_roughness():
    # a smooth surface carries only the waviness: amplitude sin(2 pi x / wavelength)
    recipe = SurfaceRecipe("smooth", scale=3.0, waviness=Waviness(50e-6, 0.2e-6, "x"))
    surf = build_surface(recipe, 1e-3, 1e-6)
    assert isinstance(surf, Profile)
    np.testing.assert_allclose(surf.z, 0.2e-6 * np.sin(2 * np.pi * surf.x / 50e-6), rtol=0,
                               atol=1e-18)
    # across y it needs the y grid; without one it is refused
    y = (np.arange(8) + 0.5) * 5e-6
    wavy = build_surface(SurfaceRecipe("smooth", waviness=Waviness(40e-6, 0.1e-6)), 1e-4, 5e-6,
                         y=y)
    np.testing.assert_allclose(wavy.z[3], 0.1e-6 * np.sin(2 * np.pi * y / 40e-6), atol=1e-18)
    with pytest.raises(ValueError, match="direction"):
        build_surface(SurfaceRecipe("smooth", waviness=Waviness(40e-6, 0.1e-6)), 1e-4, 5e-6)


def test_lowpass_attenuates_as_the_iso_gaussian_filter(tmp_path):
    # ISO 16610-21: a sinusoid of wavelength lambda keeps exp(-pi (alpha lambda_c / lambda)^2)
    # of its amplitude, alpha = sqrt(ln 2 / pi); the filter acts before the scale
    wavelength, cutoff, h = 100e-6, 40e-6, 0.5e-6
    x = (np.arange(4000) + 0.5) * h
    write_surface(Profile(x, 1e-6 * np.sin(2 * np.pi * x / wavelength)), tmp_path / "sine.npz")
    recipe = SurfaceRecipe("file", path=str(tmp_path / "sine.npz"), lowpass_wavelength=cutoff,
                           scale=2.0)
    surf = build_surface(recipe, 0.0, h)
    alpha = np.sqrt(np.log(2) / np.pi)
    kept = np.exp(-np.pi * (alpha * cutoff / wavelength) ** 2)
    inner = slice(400, -400)  # away from the ends of a non-periodic profile
    np.testing.assert_allclose(surf.z[inner], 2.0 * kept * 1e-6 * np.sin(
        2 * np.pi * surf.x[inner] / wavelength), rtol=0, atol=1e-9)


def test_tables_with_the_same_keys_make_the_same_surface():
    keys = dict(kind="gaussian", rms=1e-6, correlation_length=10e-6, seed=7)
    x = (np.arange(64) + 0.5) * 1e-6
    on_grid = surface_heights(RoughnessSpec(**keys), x, x[:16])
    spec = SurfaceSpec(**keys, length=64e-6, width=16e-6, spacing=1e-6)
    analysed = build_surface(surface_recipe(spec), spec.profile_length(),
                             spec.profile_spacing(), width=spec.width)
    np.testing.assert_allclose(on_grid, analysed.z, rtol=1e-12, atol=0)


def test_unknown_kind_is_refused():
    with pytest.raises(ValueError, match="kind"):
        SurfaceRecipe("knurled")


def test_one_schema_of_surface_keys_across_tables():
    # the same keys give the same profile in [surface1], [surface] and [roughness]
    keys = dict(kind="ground", ra=0.3e-6, run_in=0.2, seed=4)
    length, h = 1e-3, 1e-6
    moving = MovingSurfaceSpec(**keys).build(length, h, np.array([-1e-6, 1e-6]), h)
    spec = SurfaceSpec(**keys, length=length, spacing=h)
    analysed = build_surface(surface_recipe(spec), spec.profile_length(), spec.profile_spacing())
    np.testing.assert_array_equal(moving.z, analysed.z)
    x = (np.arange(1000) + 0.5) * h
    on_grid = surface_heights(RoughnessSpec(**keys), x, x[:2])
    np.testing.assert_allclose(on_grid[:, 1], analysed.z, rtol=1e-9, atol=1e-15)
    # kinds and reading keys now shared: a self-affine moving surface (a profile on a line
    # contact's single row; tests/test_ehl_transient_topography.py: a point contact's rows);
    # unit only for a file
    rough = MovingSurfaceSpec(kind="self-affine", hurst=0.8, rms=0.2e-6, seed=1)
    assert rough.build(length, h, np.zeros(1), h).z.shape == (1000,)
    with pytest.raises(ValueError, match="for a measured file"):
        MovingSurfaceSpec(kind="gaussian", rms=1e-7, correlation_length=1e-5, unit="um")


def test_surface_generate_reads_its_options_as_the_case_keys(tmp_path):
    app = typer.Typer()
    app.add_typer(surface_app, name="surface")
    runner = CliRunner()
    out = tmp_path / "g.npy"
    res = runner.invoke(app, ["surface", "generate", "gaussian", "--rms", "0.5 um",
                              "--correlation-length", "12 um", "--length", "0.4 mm",
                              "--spacing", "1 um", "--seed", "5", "--out", str(out)])
    assert res.exit_code == 0, res.output
    spec = SurfaceSpec(kind="gaussian", rms="0.5 um", correlation_length="12 um",
                       length="0.4 mm", spacing="1 um", seed=5)
    case = build_surface(surface_recipe(spec), spec.profile_length(), spec.profile_spacing())
    np.testing.assert_array_equal(read_surface(out, 1e-6).z, case.z)
    # the bounds of the case keys, named by the option
    res = runner.invoke(app, ["surface", "generate", "ground", "--ra", "2 cm", "--out",
                              str(out)])
    assert res.exit_code == 2
    assert res.stderr.startswith("error: --ra: expected a value less than or equal to 0.01")


def test_a_roller_map_in_a_contact_warns_that_its_curvature_is_in_the_gap(tmp_path):
    """A 128 um map of 0.1 um roughness measured on a 5 mm roller, used as a contact's
    [roughness] with the default plane removed: the roller's curvature stays in the gap (a ball
    on it then touched at the map's edges, 50 % of the load on the edge cells). The warning
    names a radius within 12 % of the 5 mm built in and roughness.form_degree = 2, which
    removes it and the warning."""
    from scipy.ndimage import gaussian_filter

    from asperity.cases.roughness import roughness_on_grid

    n, h = 128, 1e-6
    c = (np.arange(n) - n / 2) * h
    cx = np.meshgrid(c, c, indexing="ij")[0]
    rough = gaussian_filter(np.random.default_rng(2).standard_normal((n, n)), 3, mode="wrap")
    z = 0.1e-6 * rough / rough.std() + 5e-3 - np.sqrt(25e-6 - cx ** 2)
    path = tmp_path / "roller.npz"
    np.savez(path, x=c, y=c, z=z)
    grid = c[:100] - c[0] + 0.5 * h
    got = roughness_on_grid(RoughnessSpec(kind="file", path=str(path)), grid, grid)
    (warning,) = [w for w in got.warnings if "form is left in the map" in w]
    assert warning.startswith("roughness.path: form: ")
    radius = float(warning.split("about ")[1].split(" mm")[0]) * 1e-3
    assert radius == pytest.approx(5e-3, rel=0.12)
    direction = float(warning.split("strongest at ")[1].split(" deg")[0])
    assert min(direction, 180 - direction) <= 5  # the roller curves along x
    assert "roughness.form_degree = 2" in warning
    flat = roughness_on_grid(RoughnessSpec(kind="file", path=str(path), form_degree=2), grid,
                             grid)
    assert not any("form is left in" in w for w in flat.warnings)
