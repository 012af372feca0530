"""The one surface factory (:mod:`asperity.surfaces.recipe`) against recorded surfaces and
closed forms.

Every built-in example's surfaces, and one spec of each kind the examples leave out, must stay
what the four dispatches the factory replaced (``[roughness]``, ``[surface1]``/``[surface2]``,
``[surface]`` and ``asperity surface generate``) made. They were held bit-identical by
hashes, which an AVX2 machine (session 44) failed on 41 of 65 surfaces with the code unchanged:
numpy's and numba's vectorised sin, exp and sums round differently on other CPUs. They are held
now by fingerprints (:func:`_fingerprint`, recorded on that machine from the same code) to 1e-7
of the rms height.
"""

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

#: the FZG C pair's surfaces, the same with crowning or without
_FZG_C = {
    "surface1": ((4000,),
        (3.38813179e-24, 3.75265008e-07, -9.72340184e-07, 1.29679918e-06, -1.34118592e-07,
        -2.71020397e-07, -3.09147222e-07, -1.15716468e-07)),
    "surface1:gear": ((8000,),
        (3.38813179e-24, 3.73064812e-07, -1.05107806e-06, 1.17072764e-06, 2.98569959e-07,
        1.25865321e-07, 3.74685564e-07, 3.30382364e-07)),
    "surface2": ((4000,),
        (0, 3.81776105e-07, -9.6649806e-07, 1.30902582e-06, 1.01842135e-07, -4.84650069e-07,
        2.13671048e-07, 1.12605024e-07)),
    "surface2:gear": ((8000,),
        (-1.69406589e-24, 3.77153477e-07, -9.77671862e-07, 1.32870018e-06, 5.81302535e-08,
        -3.30828364e-07, 5.18264038e-07, 5.29138138e-08)),
}
#: the dent of both dent examples
_DENT = ((4001, 9),
    (-2.44664877e-10, 4.41120749e-09, -1.2e-07, -0, -0, -0, -0, -0))
#: the seed's profile A as a moving surface, low-passed at 3 dx
_PROFILE_A = ((4000,),
    (2.37169225e-23, 4.17958947e-07, -1.50567299e-06, 3.14903527e-07, -2.30727767e-07,
    -1.08138703e-06, -1.97253556e-07, -2.4249421e-07))
#: the seed's profile C as a moving surface, low-passed at 3 dx
_PROFILE_C = ((4000,),
    (-5.08219768e-24, 3.56795846e-07, -1.21113594e-06, 5.52835713e-07, -4.80351437e-07,
    3.28400108e-07, -5.72922804e-07, -4.31948113e-07))
#: the seed's profile B as a moving surface, low-passed at 3 dx
_PROFILE_B = ((4000,),
    (-8.47032947e-24, 2.68761511e-07, -1.15038554e-06, 2.73797009e-07, 1.44484071e-07,
    -5.93091439e-08, 1.20624717e-07, 1.08734216e-07))
#: the seed's profile C as a moving surface, as measured (the paper case)
_PROFILE_C_PAPER = ((4000,),
    (-3.38813179e-24, 3.75572878e-07, -1.22513024e-06, 5.53162995e-07, -4.56325728e-07,
    3.36236369e-07, -5.94204564e-07, -4.10539442e-07))
#: example:table -> fingerprint of its heights (None: no surface)
EXAMPLES = {
    "dent-rolling:surface1": _DENT,
    "dent-rolling:surface2": None,
    "dent-sliding:surface1": _DENT,
    "dent-sliding:surface2": None,
    "gear-helical-industrial:surface1": ((4000,),
        (1.35525272e-23, 5.00353343e-07, -1.29645358e-06, 1.72906557e-06, -1.7882479e-07,
        -3.6136053e-07, -4.12196296e-07, -1.54288624e-07)),
    "gear-helical-industrial:surface1:gear": ((8000,),
        (0, 4.97419749e-07, -1.40143742e-06, 1.56097018e-06, 3.98093278e-07, 1.67820429e-07,
        4.99580752e-07, 4.40509819e-07)),
    "gear-helical-industrial:surface2": ((4000,),
        (0, 4.97083e-07, -1.25996111e-06, 1.47086564e-06, 1.81386708e-07, -5.92095835e-07,
        1.3750094e-06, 1.68657349e-07)),
    "gear-helical-industrial:surface2:gear": ((8000,),
        (6.77626358e-24, 4.92277691e-07, -1.26792455e-06, 1.66254321e-06, 3.93647529e-07,
        -6.49651352e-07, -4.33876553e-08, 3.93962318e-07)),
    "gear-planet-ring:surface1": ((4000,),
        (-3.38813179e-24, 3.75265008e-07, -9.72340184e-07, 1.29679918e-06, -1.34118592e-07,
        -2.71020397e-07, -3.09147222e-07, -1.15716468e-07)),
    "gear-planet-ring:surface1:gear": ((8000,),
        (6.77626358e-24, 3.73064812e-07, -1.05107806e-06, 1.17072764e-06, 2.98569959e-07,
        1.25865321e-07, 3.74685564e-07, 3.30382364e-07)),
    "gear-planet-ring:surface2": ((4000,),
        (1.35525272e-23, 7.45624501e-07, -1.88994167e-06, 2.20629846e-06, 2.72080062e-07,
        -8.88143753e-07, 2.0625141e-06, 2.52986023e-07)),
    "gear-planet-ring:surface2:gear": ((8000,),
        (-1.35525272e-23, 7.38416536e-07, -1.90188683e-06, 2.49381482e-06, 5.90471294e-07,
        -9.74477028e-07, -6.5081483e-08, 5.90943477e-07)),
    "holmes-profiles:surface:A": ((3000,),
        (2.71050543e-23, 3.929153e-07, -1.21311617e-06, 3.08959342e-07, 2.58557725e-07,
        3.0480765e-07, 2.88022938e-07, 2.56035847e-07)),
    "holmes-profiles:surface:B": ((3000,),
        (-1.35525272e-23, 2.67760145e-07, -1.05692811e-06, 2.77061771e-07, 2.73580116e-07,
        -1.37567887e-07, -2.35513218e-07, 2.73726691e-07)),
    "holmes-profiles:surface:C": ((3000,),
        (1.35525272e-23, 3.74176254e-07, -1.26547767e-06, 5.48504733e-07, -3.12949739e-07,
        -4.82059583e-07, 3.95404119e-07, -1.63544341e-07)),
    "holmes-rough-AA-line:surface1": _PROFILE_A,
    "holmes-rough-AA-line:surface2": _PROFILE_A,
    "holmes-rough-AA:surface1": _PROFILE_A,
    "holmes-rough-AA:surface2": _PROFILE_A,
    "holmes-rough-AC:surface1": _PROFILE_A,
    "holmes-rough-AC:surface2": _PROFILE_C,
    "holmes-rough-BB:surface1": _PROFILE_B,
    "holmes-rough-BB:surface2": _PROFILE_B,
    "holmes-rough-C-smooth:surface1": _PROFILE_C,
    "holmes-rough-C-smooth:surface2": None,
    "holmes-rough-CC-paper:surface1": _PROFILE_C_PAPER,
    "holmes-rough-CC-paper:surface2": _PROFILE_C_PAPER,
    "holmes-rough-CC:surface1": _PROFILE_C,
    "holmes-rough-CC:surface2": _PROFILE_C,
    "holmes-rough-sqrt2C-smooth:surface1": ((4000,),
        (-1.01643954e-23, 5.04585524e-07, -1.71280487e-06, 7.81827763e-07, -6.79319517e-07,
        4.64427887e-07, -8.102352e-07, -6.10866879e-07)),
    "holmes-rough-sqrt2C-smooth:surface2": None,
    "measured-profile:surface:file": ((2400,),
        (-8.33333333e-14, 6.33128066e-07, -2.0717e-06, 1.3068e-06, -1.1398e-06, 8.3e-09, 2.57e-08,
        -2.155e-07)),
    "rough-flat-normal:roughness": ((512, 512),
        (0, 4.85817075e-07, -1.53285896e-06, 1.81941515e-06, -9.26628785e-08, 3.42159369e-07,
        2.33337182e-07, -1.4712257e-07)),  # 512 cells, short_cutoff (session 37)
    "rough-sphere-normal:roughness": ((256, 256),
        (-1.03397577e-25, 1.95564272e-07, -8.10594911e-07, 7.79425353e-07, 6.22340883e-08,
        4.64588093e-08, -2.5853947e-07, 8.5847982e-08)),
    "seireg-turning-kinematic:surface:kinematic": ((4020,),
        (3.70840295e-23, 7.581777e-07, -8.47193162e-07, 1.69601744e-06, -8.47193162e-07,
        -8.47193162e-07, -8.47193162e-07, -8.47193162e-07)),
    "seireg-turning-vibration:surface:150 Hz": ((31557,),
        (1.73609947e-22, 7.59756741e-07, -1.0140613e-06, 1.79726985e-06, -8.1343018e-07,
        7.40389625e-07, 1.70079704e-06, -8.43451185e-07)),
    "seireg-turning-vibration:surface:28 Hz": ((31557,),
        (4.08847668e-22, 9.80274793e-07, -3.21728308e-06, 3.22785162e-06, -6.69834469e-07,
        4.80208526e-07, 1.31651895e-06, -2.70145725e-07)),
    "seireg-turning-vibration:surface:34 Hz": ((31557,),
        (5.99528723e-22, 8.86802987e-07, -1.91624942e-06, 2.79775781e-06, -2.50855603e-07,
        8.48942377e-07, 1.55456871e-06, -6.02612295e-07)),
    "seireg-turning-vibration:surface:kinematic": ((31557,),
        (3.22096377e-23, 7.581777e-07, -8.47193162e-07, 1.69601744e-06, -8.47193162e-07,
        7.83551941e-07, 1.69601744e-06, -8.47193162e-07)),
    **{f"gear-fzg-c:{key}": value for key, value in _FZG_C.items()},
    **{f"gear-fzg-c-crowned:{key}": value for key, value in _FZG_C.items()},
}
#: specs of the kinds the examples leave out, recorded the same way
EXTRA = {
    "extra-moving:builtin-wav": ((2000, 9),
        (-6.92684721e-23, 5.67669826e-07, -1.87401516e-06, 5.4986007e-07, 3.93240991e-07,
        3.24132947e-07, 2.76088187e-07, 3.98312071e-07)),
    "extra-moving:bump": ((2001, 9),
        (4.44222333e-10, 8.15082919e-09, 0, 2e-07, 0, 0, 0, 0)),
    # session 35: a gaussian moving surface of a point contact is a topography on the rows
    "extra-moving:gauss": ((2000, 9),
        (0, 2.07125039e-07, -7.3993903e-07, 6.67501683e-07, 1.44185402e-07, 3.24273305e-07,
        2.69799687e-07, -3.08696505e-07)),
    "extra-moving:ground": ((2000,),
        (0, 6.34744732e-07, -2.06985145e-06, 7.64479816e-07, 7.46660288e-07, 4.30844627e-09,
        -5.12945853e-07, 7.44555757e-07)),
    "extra-moving:ridge": ((2001,),
        (1.9990005e-09, 1.2080109e-08, 0, 1e-07, 0, 0, 0, 0)),
    "extra-moving:smooth-wav": ((2001,),
        (1.96200978e-12, 7.06930615e-08, -9.99229036e-08, 9.99229036e-08, 3.92598158e-09,
        3.92598158e-09, -3.92598158e-09, 3.92598158e-09)),
    "extra-moving:smooth-wavy": ((2001, 9),
        (-2.79403229e-23, 6.66666667e-08, -1e-07, 1e-07, -2.38868024e-22, 7.07106781e-08, 0,
        2.38868024e-22)),
    "extra-roughness:builtin-wavx": ((32, 8),
        (1.11187091e-09, 3.70985047e-07, -8.05240545e-07, 4.36443271e-07, 3.6198057e-07,
        3.23461153e-07, -3.06399836e-07, 3.00142697e-07)),
    "extra-roughness:builtin-wavy": ((32, 8),
        (7.24127854e-09, 1.28702428e-07, -2.96658161e-07, 1.88657992e-07, 1.63910389e-07,
        -1.38986508e-07, 2.56806355e-08, 1.16063747e-07)),
    "extra-roughness:g-aniso": ((32, 8),
        (0, 1.01950925e-06, -2.44594227e-06, 2.79030458e-06, 1.29179019e-06, -9.30983984e-07,
        4.52579295e-07, 5.49410578e-07)),
    # session 35: its rows labelled with the grid's own cell centres (the waviness's phase
    # moved by round-off: 8.5e-22 m of 4.8e-6 m)
    "extra-roughness:gauss-wav": ((32, 8),
        (3.34971967e-08, 1.58442408e-06, -4.44838838e-06, 4.75951835e-06, -4.38724713e-07,
        -1.11626009e-06, 1.40215891e-06, 3.53311549e-06)),
    "extra-roughness:ground-wav": ((32, 8),
        (4.4662929e-08, 8.35856484e-07, -2.91056064e-06, 8.96640785e-07, 6.83887121e-07,
        3.3392496e-07, 2.16941825e-07, 8.03249411e-07)),
    "extra-roughness:sa-rms": ((32, 8),
        (-9.92616735e-24, 4.72957102e-07, -1.36272183e-06, 1.18993697e-06, -1.16500276e-07,
        -1.17055766e-06, -2.92957344e-07, -9.12730569e-07)),
    "extra-roughness:sa-slope": ((32, 8),
        (5.29395592e-23, 1.29520802e-06, -2.53170319e-06, 3.09212295e-06, 6.91399848e-07,
        7.12688321e-07, -3.12242894e-07, -1.6110489e-07)),
    "extra-surface:builtin-def:C": ((10000,),
        (-1.08420217e-23, 3.74525592e-07, -1.4740169e-06, 5.57196646e-07, -3.18538594e-07,
        -5.15718823e-07, 4.81534537e-07, -2.71669438e-07)),
    "extra-surface:g-prof:gaussian": ((1000,),
        (0, 1.001392e-06, -3.02021608e-06, 2.95808767e-06, -8.11508202e-07, 3.44771138e-07,
        -1.36775184e-07, -8.49729453e-07)),
    "extra-surface:g-topo:gaussian": ((100, 50),
        (2.16840434e-23, 9.7383435e-07, -3.03492228e-06, 3.69527253e-06, 6.33293319e-07,
        1.40047137e-06, -1.46995125e-06, -5.86900957e-08)),
    "extra-surface:ground-ell:ground": ((1000,),
        (0, 3.78475121e-07, -8.86222913e-07, 1.07557719e-06, -6.13214291e-08, -1.66282431e-07,
        3.32147903e-08, -6.5554748e-08)),
    "extra-surface:ground:ground": ((1000,),
        (-3.04931861e-23, 3.70251691e-07, -1.26897898e-06, 2.98399801e-07, -6.53905686e-07,
        2.83008096e-07, 1.61008893e-07, -6.70572409e-07)),
    "extra-surface:sa-prof:self-affine": ((1000,),
        (-6.77626358e-24, 1.01975481e-06, -2.74686528e-06, 3.05528056e-06, 3.86830262e-07,
        5.33694514e-07, -3.01507249e-07, 2.83902317e-07)),
    "extra-surface:sa-topo:self-affine": ((100, 100),
        (4.33680869e-23, 1.01267874e-06, -2.46366035e-06, 2.61119197e-06, -1.33548571e-06,
        -1.87828613e-06, 7.66847996e-07, -1.45481825e-06)),
    "extra-surface:turned:kinematic": ((4020,),
        (-1.01138262e-23, 4.66295865e-07, -5.21126095e-07, 1.0428641e-06, -5.21126095e-07,
        -5.21126095e-07, -5.21126095e-07, -5.21126095e-07)),
}

X = np.linspace(-50e-6, 50e-6, 32)
Y = np.linspace(-25e-6, 25e-6, 8)
#: arguments of MovingSurfaceSpec.build: length, spacing, y, mesh dx
MOVING = (2e-3, 0.5e-6, np.linspace(-1e-4, 1e-4, 9), 2e-6)
WAVY = {"wavelength": 40e-6, "amplitude": 0.1e-6}


def _fingerprint(z) -> tuple:
    """Shape, mean, rms, least and greatest height and four heights at fixed places of a
    height field (m), to 9 digits."""
    z = np.asarray(z, dtype=float)
    flat = z.ravel()
    picks = flat[[0, flat.size // 5, flat.size // 2, flat.size - 1]]
    values = np.r_[flat.mean(), flat.std(), flat.min(), flat.max(), picks]
    return (z.shape, tuple(float(f"{v:.9g}") for v in values))


def _same(got: dict, recorded: dict) -> list:
    """Keys whose fingerprints differ: another shape, or a value off by more than 1e-7 of the
    recorded rms height (the 9 digits recorded; round-off between machines stays far below)."""
    wrong = []
    for key in recorded.keys() | got.keys():
        a, b = got.get(key, "absent"), recorded.get(key, "absent")
        if a is None or b is None or isinstance(a, str) or isinstance(b, str):
            if a != b:
                wrong.append(key)
            continue
        if a[0] != tuple(b[0]) or not np.allclose(a[1], b[1], rtol=0, atol=1e-7 * b[1][1]):
            wrong.append(key)
    return sorted(wrong)


def _example_fingerprints(name: str) -> dict:
    case = load_case(example_text(name))
    out = {}
    if case.analysis == "normal" and case.roughness is not None:
        out[f"{name}:roughness"] = _fingerprint(surface_heights(case.roughness,
                                                         *case.grid.coordinates()))
    for key in ("surface1", "surface2"):
        spec = getattr(case, key, None)
        if spec is None:
            continue
        surf = spec.build(*MOVING)
        out[f"{name}:{key}"] = None if surf is None else _fingerprint(surf.z)
        if case.analysis == "gear":
            surf = spec.build(4e-3, 0.5e-6, np.zeros(1), 0.5e-6)
            out[f"{name}:{key}:gear"] = _fingerprint(surf.z)
    if case.analysis == "surface":
        heights = run_case(case).dataset["height"]
        for label, z in zip(heights["surface"].values, heights.values, strict=True):
            out[f"{name}:surface:{label}"] = _fingerprint(z)
    return out


@pytest.mark.parametrize("name", sorted({key.split(":")[0] for key in EXAMPLES}))
def test_example_surfaces_are_unchanged(name):
    expected = {key: value for key, value in EXAMPLES.items() if key.split(":")[0] == name}
    assert not _same(_example_fingerprints(name), expected)


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
    assert not _same({key: _fingerprint(z) for key, z in _extra_surfaces()}, EXTRA)


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
    assert res.stderr.startswith("error: --ra: expected at most 10 mm, got '2 cm'")


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
