"""Dry contact: Hertz and other closed forms, normal contact, tangential contact."""

from .gap import ellipsoid_gap, surface_gap
from .hertz import HertzLine, HertzPoint, hertz_line, hertz_point
from .load_path import LoadPathResult, proportional_path, tangential_load_path
from .normal import NormalContactResult, solve_normal
from .tangential import TangentialResult, friction_capacity, solve_tangential

__all__ = ["HertzLine", "HertzPoint", "hertz_line", "hertz_point"]
__all__ += ["NormalContactResult", "ellipsoid_gap", "solve_normal", "surface_gap"]
__all__ += ["TangentialResult", "friction_capacity", "solve_tangential"]
__all__ += ["LoadPathResult", "proportional_path", "tangential_load_path"]
