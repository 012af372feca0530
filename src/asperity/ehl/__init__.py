"""Elastohydrodynamic lubrication: lubricant models, film-thickness formulas, EHL solvers."""

from .lubricant import (
    Lubricant,
    barus_viscosity,
    dowson_higginson_density,
    eyring_flow_factors,
    eyring_mean_shear_stress,
    friction_coefficient,
    roelands_index,
    roelands_viscosity,
    wall_shear_stress,
)

__all__ = [
    "Lubricant",
    "barus_viscosity",
    "dowson_higginson_density",
    "eyring_flow_factors",
    "eyring_mean_shear_stress",
    "friction_coefficient",
    "roelands_index",
    "roelands_viscosity",
    "wall_shear_stress",
]
