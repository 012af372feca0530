"""Elastohydrodynamic lubrication: lubricant models, film-thickness formulas, EHL solvers."""

from .comparison import CentreLineComparison, compare_centre_lines
from .formulas import (
    FilmThickness,
    HamrockDowsonGroups,
    MoesGroups,
    dowson_higginson_line,
    hamrock_dowson_groups,
    hamrock_dowson_point,
    moes_groups,
    moes_line,
    moes_line_film,
    nijenbanning_film,
    nijenbanning_point,
)
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
from .problem import LineContact, PointContact
from .solver import EHLState, SteadyResult, solve_steady
from .statistics import ContactStatistics, flow_vectors, hertz_mask
from .transient import TransientResult, solve_transient

__all__ = [
    "EHLState", "LineContact", "PointContact", "SteadyResult", "solve_steady",
    "ContactStatistics", "flow_vectors", "hertz_mask",
    "TransientResult", "solve_transient", "CentreLineComparison", "compare_centre_lines",
    "FilmThickness",
    "HamrockDowsonGroups",
    "MoesGroups",
    "dowson_higginson_line",
    "hamrock_dowson_groups",
    "hamrock_dowson_point",
    "moes_groups",
    "moes_line",
    "moes_line_film",
    "nijenbanning_film",
    "nijenbanning_point",
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
