"""Rough surfaces: data model, generation, machining models, parameters, filters, files.

Measured surfaces: :mod:`.io` and :mod:`.readers` read instrument and text exports;
:mod:`.profiles` (P, W, R per ISO 4287/16610-21 with ISO 4288 cut-offs), :mod:`.areal`
(S-F/S-L surfaces, ISO 25178-2), :mod:`.material_ratio` (Abbott curve, Rk/Sk, volumes) and
:mod:`.texture` (all of them grouped, for ``asperity surface stats``).

Data model (:mod:`.topography`): a :class:`Profile` holds heights ``z`` (m) on uniform
cell-centre positions ``x``; a :class:`Topography` holds ``z[ix, iy]`` on uniform ``x``, ``y``.
Both are frozen, carry a ``periodic`` flag and evaluate heights anywhere with cached cubic
splines (``sample``); ``Profile.extrude(y)`` makes a transverse-ground topography.
"""

from .areal import areal_families, areal_parameters, texture_aspect_ratio, texture_direction
from .filters import (
    areal_gaussian_filter,
    gaussian_filter,
    gaussian_transmission,
    split_waviness,
)
from .form import remove_form
from .generate import (
    add_waviness,
    gaussian_profile,
    gaussian_topography,
    self_affine_profile,
    self_affine_topography,
)
from .ground import BUILTIN_PROFILES, builtin_profile, transverse_ground_profile
from .io import Reading, read_measured, read_surface, write_surface
from .machining import (
    ProcessRoughness,
    TurnedSurface,
    kinematic_peak_to_valley,
    process_names,
    process_roughness,
    roughness_along,
    turned_profile,
    turned_profile_dynamic,
)
from .material_ratio import (
    material_ratio,
    material_ratio_curve,
    rk_parameters,
    section_height_difference,
    volume_parameters,
)
from .missing import fill_missing
from .parameters import (
    PowerSpectrum,
    autocorrelation_length,
    power_spectrum,
    residual_heights,
    rms_gradient,
    roughness_parameters,
)
from .profiles import profile_families, profile_parameters
from .texture import evaluate_texture
from .topography import Profile, Topography, cell_centres

__all__ = [
    "BUILTIN_PROFILES",
    "PowerSpectrum",
    "ProcessRoughness",
    "Profile",
    "Reading",
    "Topography",
    "TurnedSurface",
    "add_waviness",
    "areal_families",
    "areal_gaussian_filter",
    "areal_parameters",
    "autocorrelation_length",
    "builtin_profile",
    "cell_centres",
    "evaluate_texture",
    "fill_missing",
    "gaussian_filter",
    "gaussian_profile",
    "gaussian_topography",
    "gaussian_transmission",
    "kinematic_peak_to_valley",
    "material_ratio",
    "material_ratio_curve",
    "power_spectrum",
    "process_names",
    "process_roughness",
    "profile_families",
    "profile_parameters",
    "read_measured",
    "read_surface",
    "remove_form",
    "residual_heights",
    "rk_parameters",
    "roughness_along",
    "rms_gradient",
    "roughness_parameters",
    "section_height_difference",
    "self_affine_profile",
    "self_affine_topography",
    "split_waviness",
    "texture_aspect_ratio",
    "texture_direction",
    "transverse_ground_profile",
    "turned_profile",
    "turned_profile_dynamic",
    "volume_parameters",
    "write_surface",
]
