"""Rough surfaces: data model, generation, machining models, parameters, filters, files.

Data model (:mod:`.topography`): a :class:`Profile` holds heights ``z`` (m) on uniform
cell-centre positions ``x``; a :class:`Topography` holds ``z[ix, iy]`` on uniform ``x``, ``y``.
Both are frozen, carry a ``periodic`` flag and evaluate heights anywhere with cached cubic
splines (``sample``); ``Profile.extrude(y)`` makes a transverse-ground topography.
"""

from .filters import gaussian_filter, gaussian_transmission, split_waviness
from .generate import (
    add_waviness,
    gaussian_profile,
    gaussian_topography,
    self_affine_profile,
    self_affine_topography,
)
from .ground import BUILTIN_PROFILES, builtin_profile, transverse_ground_profile
from .io import read_surface, write_surface
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
from .parameters import (
    PowerSpectrum,
    autocorrelation_length,
    power_spectrum,
    residual_heights,
    roughness_parameters,
)
from .topography import Profile, Topography, cell_centres

__all__ = [
    "BUILTIN_PROFILES",
    "PowerSpectrum",
    "ProcessRoughness",
    "Profile",
    "Topography",
    "TurnedSurface",
    "add_waviness",
    "autocorrelation_length",
    "builtin_profile",
    "cell_centres",
    "gaussian_filter",
    "gaussian_profile",
    "gaussian_topography",
    "gaussian_transmission",
    "kinematic_peak_to_valley",
    "power_spectrum",
    "process_names",
    "process_roughness",
    "read_surface",
    "residual_heights",
    "roughness_along",
    "roughness_parameters",
    "self_affine_profile",
    "self_affine_topography",
    "split_waviness",
    "transverse_ground_profile",
    "turned_profile",
    "turned_profile_dynamic",
    "write_surface",
]
