"""Hand-off of one point of the path of contact to the transient mixed-EHL analysis.

:func:`transient_case` turns the conditions at a path position (reduced radius, load, surface
speeds, and the crowning radius of a crowned pair) into the tables of an ``analysis =
"ehl-transient"`` case; :func:`toml_text` writes such a case as TOML (strings, numbers,
booleans and nested tables: all a case needs).

A line contact is written with ``[solver] max_sweeps = 2000`` (:data:`LINE_MAX_SWEEPS`), as
the seed's line-contact example sets it: the point relaxation of a rough line contact at the
sliding of a gear flank needed up to about 800 sweeps in a time step (the row solve, now the
default, at most 188). The mesh is refined until
the shorter autocorrelation length of the two surfaces spans :data:`NODES_PER_CORRELATION`
spacings (:func:`roughness_nodes`): on coarser meshes the steps stall (docs/gears.md). A
line contact's inlet is moved to the contact's fully flooded distance (:func:`flooded_grid`).
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError
from .path import GearPathResult

__all__ = ["LINE_MAX_SWEEPS", "NODES_PER_CORRELATION", "flooded_grid", "point_index",
           "roughness_nodes", "toml_text", "transient_case"]

#: Sweep limit per time step written into the case of a line contact (with the point update
#: the transient solver's default of 400 left 16.5 % of the steps of the FZG example's
#: minimum-lambda point unconverged, the most any step needed being 788; the row solve, the
#: default since, needed at most 59 there and 188 at the FZG pitch point).
LINE_MAX_SWEEPS = 2000

#: Mesh spacings per autocorrelation length (ACF down to 0.2) of the surfaces at least: the
#: FZG example's pitch point stalled at 1.9 (half of the steps unconverged at 2000 sweeps);
#: at 3.8 every step after the first 8 (an unconverged steady start) converged, and both
#: minimum-lambda points converged at 3.8 and 4.8.
NODES_PER_CORRELATION = 3.5


def roughness_nodes(nx: int, span: float, correlation_length: float) -> int:
    """Node count along x that resolves the roughness.

    Parameters
    ----------
    nx : int
        Node count asked for.
    span : float
        Length of the domain along x (m).
    correlation_length : float
        The shorter autocorrelation length of the two surfaces (m).

    Returns
    -------
    int
        ``nx``, or where its spacing exceeds ``correlation_length /``
        :data:`NODES_PER_CORRELATION` the smallest count ``32 m + 1`` whose spacing does not
        (the form of the default 129 and of 257, which keeps grid sequencing).
    """
    cells = math.ceil(span * NODES_PER_CORRELATION / correlation_length)
    if cells <= nx - 1:
        return nx
    return 32 * math.ceil(cells / 32) + 1


def flooded_grid(grid: dict, inlet_extent: float) -> dict:
    """``grid`` with its inlet at ``-inlet_extent`` (in a) where that lies upstream of
    ``grid["x_min"]``, and ``nx`` raised to keep at least the spacing of ``grid`` (in the form
    ``32 m + 1``, as :func:`roughness_nodes`).

    A thick film in Hertzian units needs a long inlet: at a helical pair's minimum-lambda point
    the steady minimum film from the seed's -2.5 a was 3.5 % below that of a fully flooded
    inlet (0.276 against 0.286 um), at a turbo pair's pitch point 13 % (docs/gears.md).
    """
    if not -inlet_extent < grid["x_min"]:
        return dict(grid)
    cells_per_a = (grid["nx"] - 1) / (grid["x_max"] - grid["x_min"])
    cells = math.ceil((grid["x_max"] + inlet_extent) * cells_per_a - 1e-9)
    return {**grid, "x_min": -float(inlet_extent), "nx": 32 * math.ceil(cells / 32) + 1}


def point_index(result: GearPathResult, at: str, roll_angle: float | None = None) -> int:
    """Index of the path position named by ``at``: ``"pitch"`` (the position nearest the pitch
    point), ``"min-lambda"``, ``"max-flash"``; or the position nearest ``roll_angle`` (rad)."""
    critical = result.critical()
    if roll_angle is not None:
        return int(np.argmin(np.abs(result.kin.roll_angle - roll_angle)))
    if at == "pitch":
        if not result.pair.pitch_on_path:
            raise InputError("at", '"min-lambda", "max-flash" or a roll angle on the path: the '
                             "pitch point lies outside the path of contact A-E (the pair "
                             "meshes in approach or recess alone)", at)
        return int(np.argmin(np.abs(result.kin.distance)))
    if at == "min-lambda":
        return critical["minimum_lambda"]
    if at == "max-flash":
        if critical["maximum_flash_temperature"] is None:
            raise InputError("at", '"pitch", "min-lambda" or a roll angle: the flash '
                             "temperature is unknown along the path (a Newtonian lubricant: set "
                             "lubricant.tau0)", at)
        return critical["maximum_flash_temperature"]
    raise InputError("at", '"pitch", "min-lambda", "max-flash" or a roll angle', at)


def transient_case(result: GearPathResult, index: int, *, title: str, body1: dict, body2: dict,
                   lubricant: dict, surface1: dict, surface2: dict, grid: dict,
                   time: dict, solver: dict | None = None,
                   correlation_length: float | None = None,
                   inlet_extent: float | None = None) -> dict:
    """The ``ehl-transient`` case (a dict ready for :func:`asperity.cases.load_case`) of the
    path position ``index``, in SI numbers.

    Parameters
    ----------
    result : GearPathResult
        The path of contact.
    index : int
        Path position handed over (:func:`point_index`).
    title : str
        Title of the case.
    body1, body2, lubricant, surface1, surface2, grid, time : dict
        The tables as they appear in a case file (units allowed). Surface 1 is the pinion
        flank (speed u1), surface 2 the wheel flank (u2).
    solver : dict, optional
        The ``[solver]`` table; a line contact gets ``max_sweeps`` = :data:`LINE_MAX_SWEEPS`
        unless it is given here.
    correlation_length : float, optional
        The shorter autocorrelation length of the two surfaces (m): ``grid["nx"]`` (a count
        over ``x_min`` .. ``x_max`` in Hertz semi-widths) is raised by :func:`roughness_nodes`.
    inlet_extent : float, optional
        The fully flooded inlet distance of the position's contact, in Hertz semi-widths
        (:meth:`asperity.ehl.LineContact.inlet_extent`, as the path's own solves use it):
        a line contact's ``grid["x_min"]`` is moved upstream to ``-inlet_extent`` where that
        is farther, at the same spacing (:func:`flooded_grid`).

    Returns
    -------
    dict
        The case, with a ``[solver]`` table only when it has keys.
    """
    kin = result.kin
    if not result.load[index] > 0:
        raise InputError("at", "a loaded position of the path (this one is unloaded: tip "
                         "relief)", index)
    if result.line:
        contact = {"type": "line", "radius": float(kin.reduced_radius[index]),
                   "load_per_length": float(result.load[index])}
    else:
        contact = {"type": "point", "rx": float(kin.reduced_radius[index]),
                   "ry": result.pair.crowning_radius,
                   "load": float(result.load[index])}
    angle = math.degrees(float(kin.roll_angle[index]))
    description = (f"Path of contact at pinion roll angle {angle:.3f} deg "
                   f"({kin.distance[index] * 1e3:+.3f} mm from the pitch point): "
                   f"lambda = {result.specific_film[index]:.3g} from the steady film.")
    grid = dict(grid)
    if result.line and inlet_extent is not None:
        grid = flooded_grid(grid, inlet_extent)
    if correlation_length is not None:
        span = (grid["x_max"] - grid["x_min"]) * float(result.hertz_a[index])
        grid["nx"] = roughness_nodes(grid["nx"], span, correlation_length)
    if result.line:
        grid.pop("ny", None)
        grid.pop("y_min", None)
        grid.pop("y_max", None)
    solver = dict(solver or {})
    if result.line:
        solver.setdefault("max_sweeps", LINE_MAX_SWEEPS)
    case = {
        "analysis": "ehl-transient", "title": title, "description": description,
        "source": "asperity gear hand-off",
        "body1": dict(body1), "body2": dict(body2), "contact": contact,
        "speeds": {"u1": float(kin.u1[index]), "u2": float(kin.u2[index])},
        "lubricant": dict(lubricant), "surface1": dict(surface1), "surface2": dict(surface2),
        "grid": grid, "time": dict(time),
    }
    if solver:
        case["solver"] = solver
    return case


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
