"""Hand-off of one point of the path of contact to the transient mixed-EHL analysis.

:func:`transient_case` turns the conditions at a path position (reduced radius, load, surface
speeds, and the crowning radius of a crowned pair) into the tables of an ``analysis =
"ehl-transient"`` case; :func:`toml_text` writes such a case as TOML (strings, numbers,
booleans and nested tables: all a case needs).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .path import GearPathResult

__all__ = ["point_index", "toml_text", "transient_case"]


def point_index(result: GearPathResult, at: str, roll_angle: float | None = None) -> int:
    """Index of the path position named by ``at``: ``"pitch"`` (the position nearest the pitch
    point), ``"min-lambda"``, ``"max-flash"``; or the position nearest ``roll_angle`` (rad)."""
    critical = result.critical()
    if roll_angle is not None:
        return int(np.argmin(np.abs(result.kin.roll_angle - roll_angle)))
    if at == "pitch":
        return int(np.argmin(np.abs(result.kin.distance)))
    if at == "min-lambda":
        return critical["minimum_lambda"]
    if at == "max-flash":
        return critical["maximum_flash_temperature"]
    raise InputError("at", '"pitch", "min-lambda", "max-flash" or a roll angle', at)


def transient_case(result: GearPathResult, index: int, *, title: str, body1: dict, body2: dict,
                   lubricant: dict, surface1: dict, surface2: dict, grid: dict,
                   time: dict) -> dict:
    """The ``ehl-transient`` case (a dict ready for :func:`asperity.cases.load_case`) of the
    path position ``index``, in SI numbers.

    Surface 1 is the pinion flank (speed u1), surface 2 the wheel flank (u2); ``body1`` ...
    ``time`` are the tables as they appear in a case file (dicts, units allowed).
    """
    kin = result.kin
    if not result.load[index] > 0:
        raise InputError("at", "a loaded position of the path (this one is unloaded: tip "
                         "relief)", index)
    if result.line:
        contact = {"type": "line", "radius": float(kin.reduced_radius[index]),
                   "load_per_length": float(result.load[index])}
    else:
        ry = 1.0 / sum(1.0 / r for r in result.pair.crowning_radii)
        contact = {"type": "point", "rx": float(kin.reduced_radius[index]), "ry": ry,
                   "load": float(result.load[index])}
    angle = math.degrees(float(kin.roll_angle[index]))
    description = (f"Path of contact at pinion roll angle {angle:.3f} deg "
                   f"({kin.distance[index] * 1e3:+.3f} mm from the pitch point): "
                   f"lambda = {result.specific_film[index]:.3g} from the steady film.")
    grid = dict(grid)
    if result.line:
        grid.pop("ny", None)
        grid.pop("y_min", None)
        grid.pop("y_max", None)
    return {
        "analysis": "ehl-transient", "title": title, "description": description,
        "source": "asperity gear hand-off",
        "body1": dict(body1), "body2": dict(body2), "contact": contact,
        "speeds": {"u1": float(kin.u1[index]), "u2": float(kin.u2[index])},
        "lubricant": dict(lubricant), "surface1": dict(surface1), "surface2": dict(surface2),
        "grid": grid, "time": dict(time),
    }


def _value(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(float(value)) if isinstance(value, float) else str(value)
    if isinstance(value, list | tuple):
        return "[" + ", ".join(_value(v) for v in value) + "]"
    text = str(value).replace("\\", "\\\\").replace('"', '\\"')
    return f'"{text}"'


def toml_text(case: dict, header: str = "") -> str:
    """TOML text of a case dict: top-level keys first, then one ``[table]`` per dict
    (nested dicts as ``[table.sub]``); None values are left out."""
    lines = [f"# {line}" for line in header.splitlines()]

    def table(prefix: str, data: dict):
        plain = {k: v for k, v in data.items() if not isinstance(v, dict) and v is not None}
        if prefix:
            lines.append(f"\n[{prefix}]")
        lines.extend(f"{k} = {_value(v)}" for k, v in plain.items())
        for key, sub in data.items():
            if isinstance(sub, dict):
                table(f"{prefix}.{key}" if prefix else key, sub)

    table("", case)
    return "\n".join(lines) + "\n"
