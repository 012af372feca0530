"""Dry contact: Hertz and other closed forms, normal contact, tangential contact."""

from .hertz import HertzLine, HertzPoint, hertz_line, hertz_point

__all__ = ["HertzLine", "HertzPoint", "hertz_line", "hertz_point"]
