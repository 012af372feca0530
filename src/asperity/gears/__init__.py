"""Gear pairs: involute geometry (ISO 21771), kinematics and load sharing along the path of
contact, Blok's flash temperature, and the steady EHL film, lambda and friction at every
position (:func:`solve_path`)."""

from .geometry import (
    MAX_TIP_RELIEF,
    MIN_CONTACT_RATIO,
    MIN_TIP_THICKNESS,
    GearPair,
    inverse_involute,
    involute,
)
from .handoff import (
    LINE_MAX_SWEEPS,
    NODES_PER_CORRELATION,
    flooded_grid,
    point_index,
    roughness_nodes,
    toml_text,
    transient_case,
)
from .kinematics import Kinematics, kinematics
from .loading import hertz_along_path, load_per_length, load_sharing, normal_force
from .mixed import asperity_share, composite_roughness, mixed_friction
from .path import (
    BOUNDARY_LUBRICATION_LAMBDA,
    PLAUSIBLE_HERTZ_PRESSURE,
    EHLMesh,
    GearPathResult,
    Thermal,
    contact_problem,
    solve_path,
)
from .rack import MIN_TIP_CLEARANCE, form_roll_distance, root_diameter
from .rating import NominalContactStress, nominal_contact_stress
from .thermal import (
    FLASH_CONSTANTS,
    flash_temperature,
    peclet_number,
    thermal_contact_coefficient,
)

__all__ = [
    "BOUNDARY_LUBRICATION_LAMBDA", "FLASH_CONSTANTS", "LINE_MAX_SWEEPS",
    "MAX_TIP_RELIEF", "MIN_CONTACT_RATIO", "MIN_TIP_CLEARANCE", "MIN_TIP_THICKNESS",
    "NODES_PER_CORRELATION", "PLAUSIBLE_HERTZ_PRESSURE", "EHLMesh", "GearPair", "GearPathResult",
    "Kinematics", "NominalContactStress", "Thermal",
    "asperity_share", "composite_roughness", "contact_problem",
    "flash_temperature", "form_roll_distance", "root_diameter",
    "flooded_grid", "hertz_along_path", "involute", "inverse_involute", "kinematics",
    "load_per_length", "load_sharing", "mixed_friction", "nominal_contact_stress",
    "normal_force", "peclet_number", "point_index",
    "roughness_nodes", "solve_path", "thermal_contact_coefficient", "toml_text", "transient_case",
]
