"""``asperity surface``: roughness statistics, surface generation and plots.

Quantities may be plain SI numbers or strings with units (``--spacing "0.5 um"``). Bad input
prints one line ``error: <field>: expected ...`` on stderr and exits with status 2.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from dataclasses import replace
from functools import wraps
from pathlib import Path
from typing import Annotated

import numpy as np
import typer
from rich.console import Console, Group
from rich.table import Table
from rich.text import Text

from ..errors import InputError
from ..units import to_si

__all__ = ["surface_app"]

surface_app = typer.Typer(add_completion=False, no_args_is_help=True,
                          help="Rough surfaces: statistics, generation, plots.")

#: Parameters with the dimension of length (printed in um, JSON keys suffixed _m).
_LENGTHS = {"Ra", "Rq", "Rp", "Rv", "Rz", "Rt", "Sa", "Sq", "Sp", "Sv", "Sz"}
KINDS = ("gaussian", "self-affine", "ground", "builtin", "turned")


def _one_line_errors(command: Callable) -> Callable:
    """Turn an InputError (or OSError) into one ``error: ...`` line on stderr, exit status 2."""

    @wraps(command)
    def wrapper(*args, **kwargs):
        try:
            return command(*args, **kwargs)
        except InputError as err:
            typer.echo(f"error: {err}", err=True)
            raise typer.Exit(code=2) from None
        except OSError as err:
            typer.echo(f"error: file: expected a readable/writable path, got {err}", err=True)
            raise typer.Exit(code=2) from None

    return wrapper


def _length(value: str | None, field: str) -> float | None:
    return _quantity(value, "length", field)


def _quantity(value: str | None, dimension: str, field: str) -> float | None:
    return None if value is None else to_si(_numeric(value), dimension, field)


def _numeric(value: str):
    try:
        return float(value)
    except ValueError:
        return value


def _spacing(spacing: str | None, spacing_y: str | None):
    dx = _length(spacing, "--spacing")
    dy = _length(spacing_y, "--spacing-y")
    if dy is not None and dx is None:
        raise InputError("--spacing", "a spacing along x when --spacing-y is given")
    return dx if dy is None else (dx, dy)


def _statistics(surface) -> dict:
    from ..surfaces import Profile, autocorrelation_length, roughness_parameters

    params = roughness_parameters(surface)
    ell = autocorrelation_length(surface)
    spacing = [surface.spacing] if isinstance(surface, Profile) else list(surface.spacing)
    out = {
        "kind": "profile" if isinstance(surface, Profile) else "topography",
        "points": list(surface.z.shape),
        "spacing_m": spacing,
        "periodic": surface.periodic,
    }
    for key, value in params.items():
        out[f"{key}_m" if key in _LENGTHS else key] = value
    out["correlation_length_m"] = None if math.isnan(ell) else ell
    return out


def _table(stats: dict, title: str) -> Table:
    table = Table(title=title)
    table.add_column("parameter")
    table.add_column("value", justify="right")
    table.add_column("unit")
    for key, value in stats.items():
        if key in ("kind", "points", "spacing_m", "periodic"):
            continue
        if value is None:
            table.add_row(key, "n/a", "")
        elif key.endswith("_m"):
            table.add_row(key[:-2], f"{value * 1e6:.4g}", "um")
        elif key == "Sdr":
            table.add_row(key, f"{value * 100:.4g}", "%")
        else:
            table.add_row(key, f"{value:.4g}", "")
    points = " x ".join(str(n) for n in stats["points"])
    spacing = " x ".join(f"{s * 1e6:.4g}" for s in stats["spacing_m"])
    table.caption = f"{stats['kind']}, {points} points, spacing {spacing} um"
    return table


#: SI unit -> (display unit, factor) in the stats tables.
_DISPLAY = {"m": ("um", 1e6), "m3/m2": ("ml/m2", 1e6), "deg": ("deg", 1.0), "1": ("", 1.0)}


def _read(file: Path, spacing, spacing_y, unit, x_unit, z_unit, missing, resample):
    from ..surfaces.io import read_measured

    return read_measured(file, _spacing(spacing, spacing_y), unit=unit, x_unit=x_unit,
                         z_unit=z_unit, missing=missing, resample=resample)


def _evaluated(reading, surface, cutoff, **options):
    """:func:`~asperity.surfaces.texture.evaluate_texture` of ``surface``; an error it raises
    with the doubt on the units read first, when they are in doubt
    (:meth:`~asperity.surfaces.io.Reading.explained`)."""
    from ..surfaces.texture import evaluate_texture

    try:
        return evaluate_texture(surface, cutoff, **options)
    except InputError as err:
        raise reading.explained(err) from None


def _texture_json(file: Path, reading, texture) -> dict:
    from ..surfaces.texture import suffixed

    surface = reading.surface
    spacing = ([surface.spacing] if surface.z.ndim == 1 else list(surface.spacing))
    fam = texture.families
    filters = ({"cutoff_m": fam.cutoff, "lambda_s_m": fam.lambda_s,
                "sampling_lengths": fam.sampling_lengths,
                "evaluation_length_m": fam.evaluation_length} if surface.z.ndim == 1 else
               {"surface": fam.label, "l_filter_m": fam.l_filter, "s_filter_m": fam.s_filter,
                "evaluated_points": list(fam.scale_limited.shape)})
    groups = {}
    for key, values in texture.groups.items():
        groups[key] = {"title": texture.titles[key]}
        for name, value in values.items():
            groups[key][suffixed(name)] = value if math.isfinite(value) else None
    return {"file": str(file), "format": reading.style,
            "kind": "profile" if surface.z.ndim == 1 else "topography",
            "points": list(surface.z.shape), "spacing_m": spacing, "periodic": surface.periodic,
            "filled_points": reading.filled, "filters": filters, "parameters": groups,
            "notes": [*reading.notes, *texture.notes], "warnings": _warnings(reading, texture)}


def _warnings(reading, texture) -> list[str]:
    """The reader's warnings, a doubt on the units when the rms slope is implausible, and the
    texture evaluation's warnings."""
    return [*reading.warnings, *reading.slope_warnings(*texture.rms_slope), *texture.warnings]


def _texture_tables(file: Path, reading, texture) -> list[Group]:
    """One table per texture group under its title as a line of its own (a table's title
    wraps to the table's width: 'Primary profile P (ISO 4287; ' over three lines)."""
    from ..surfaces.texture import PERCENT, unit_of

    tables = []
    for key, values in texture.groups.items():
        table = Table()
        table.add_column("parameter")
        table.add_column("value", justify="right")
        table.add_column("unit")
        for name, value in values.items():
            shown, factor = ("%", 100.0) if name in PERCENT else _DISPLAY[unit_of(name)]
            table.add_row(name, f"{value * factor:.4g}" if math.isfinite(value) else "n/a",
                          shown if math.isfinite(value) else "")
        tables.append(Group(Text(texture.titles[key], style="italic"), table))
    return tables


def _describe(file: Path, reading) -> str:
    surface = reading.surface
    points = " x ".join(str(n) for n in surface.z.shape)
    spacing = " x ".join(f"{h * 1e6:.4g}" for h in np.atleast_1d(surface.spacing))
    return (f"{file.name}: {reading.style}; {points} points, spacing {spacing} um"
            + ("; periodic" if surface.periodic else ""))


Spacing = Annotated[str | None, typer.Option(help="Grid spacing, e.g. '0.5 um' (files "
                                                  "without x).")]
SpacingY = Annotated[str | None, typer.Option(help="Grid spacing along y, if different.")]
Unit = Annotated[str | None, typer.Option(help="Length unit of the file's numbers (um, nm, ...) "
                                               "when it does not say; replaces what it says.")]
XUnit = Annotated[str | None, typer.Option(help="Unit of the coordinates only.")]
ZUnit = Annotated[str | None, typer.Option(help="Unit of the heights only.")]
Missing = Annotated[str, typer.Option(help="Missing points: 'refuse', 'fill' (linear along a "
                                           "profile, harmonic over an area) or 'mask' (filled "
                                           "for the filters, left out of the parameters).")]
Resample = Annotated[bool, typer.Option("--resample", help="Resample non-uniform x onto a "
                                                           "uniform grid by cubic spline.")]
Cutoff = Annotated[str | None, typer.Option(help="lambda_c of a profile (default: ISO 4288's "
                                                 "choice) or L-filter of an area.")]
FormDegree = Annotated[int, typer.Option(help="Degree of the least-squares form removed.")]


@surface_app.command()
@_one_line_errors
def stats(
    file: Annotated[Path, typer.Argument(
        help="Profile or topography file (text/CSV export, .npy, .npz, instrument format).")],
    as_json: Annotated[bool, typer.Option("--json", help="Print JSON (SI units) instead.")] = False,
    spacing: Spacing = None,
    spacing_y: SpacingY = None,
    unit: Unit = None,
    x_unit: XUnit = None,
    z_unit: ZUnit = None,
    missing: Missing = "refuse",
    resample: Resample = False,
    cutoff: Cutoff = None,
    form_degree: FormDegree = 1,
    rmr_depth: Annotated[str | None, typer.Option(
        help="Also give Rmr (Smr): the material ratio this depth below the highest peak.")
    ] = None,
    bin_points: Annotated[int, typer.Option(
        "--bin", help="Average k x k blocks of points into one before the evaluation "
                      "(a large map; 1: none).")] = 1,
):
    """Surface texture parameters, grouped as ISO 4287 / 13565-2 / 25178-2 group them."""
    from ..surfaces.binning import (
        BYTES_PER_POINT,
        available_memory,
        bin_surface,
        large_map,
    )

    reading = _read(file, spacing, spacing_y, unit, x_unit, z_unit, missing, resample)
    surface, excluded, binned = bin_surface(reading.surface, bin_points, reading.excluded)
    points = surface.z.size
    free = available_memory()
    if surface.z.ndim == 2 and free is not None and BYTES_PER_POINT * points > free:
        raise InputError("--bin", f"a block size that brings the map's {points} points within "
                         f"the free memory ({free / 1e9:.3g} GB at about {BYTES_PER_POINT} "
                         f"bytes a point; {large_map(points) or ''})", bin_points)
    texture = _evaluated(reading, surface, _length(cutoff, "--cutoff"), form_degree=form_degree,
                         rmr_depth=_length(rmr_depth, "--rmr-depth"), exclude=excluded)
    result = _texture_json(file, reading, texture)
    if binned:
        result["notes"].insert(len(reading.notes), binned)
        result["points"], result["spacing_m"] = list(surface.z.shape), (
            [surface.spacing] if surface.z.ndim == 1 else list(surface.spacing))
    warning = large_map(points) if surface.z.ndim == 2 else None
    if warning:
        result["warnings"].append(warning)
    if as_json:
        typer.echo(json.dumps(result, indent=2))
    else:
        console = Console()
        console.print(_describe(file, reading), markup=False, highlight=False, soft_wrap=True)
        for table in _texture_tables(file, reading, texture):
            console.print(table)
        for note in result["notes"]:
            console.print(f"note: {note}", markup=False, highlight=False, soft_wrap=True)
    for line in result["warnings"]:
        typer.echo(f"warning: {line}", err=True)


def _require(value, option: str, kind: str):
    if value is None:
        raise InputError(option, f"a value for a {kind} surface")
    return value


def _check_size(length: float, spacing: float, width: float | None) -> None:
    """Bound a generated surface like a case file's (:data:`asperity.cases.surface.MAX_POINTS`)."""
    from ..cases.surface import MAX_POINTS

    for option, value in (("--length", length), ("--spacing", spacing), ("--width", width)):
        if value is not None and not (0 < value < math.inf):
            raise InputError(option, "a finite length > 0", value)
    along = length / spacing
    if along < 8:
        raise InputError("--length", f"at least 8 spacings ({8 * spacing:.4g} m)", length)
    if width is not None and width / spacing < 8:
        raise InputError("--width", f"at least 8 spacings ({8 * spacing:.4g} m)", width)
    points = along * (1.0 if width is None else width / spacing)
    if points > MAX_POINTS:
        option = "--length" if width is None else "--length, --width"
        raise InputError(option, f"at most {MAX_POINTS} points (got {points:.3g}); raise "
                         "--spacing or make the surface smaller")


#: Option of ``surface generate`` for each surface key it shares with the case files.
_OPTIONS = {"rms": "--rms", "rms_slope": "--rms-slope", "ra": "--ra",
            "correlation_length": "--correlation-length",
            "correlation_length_y": "--correlation-length-y", "hurst": "--hurst",
            "rolloff_wavelength": "--rolloff", "short_cutoff": "--cutoff", "run_in": "--run-in",
            "seed": "--seed"}


def _surface_keys(kind: str, options: dict):
    """The options as the case files' surface keys
    (:class:`~asperity.cases.roughness.SurfaceKeys`: units, bounds), an error naming the
    option."""
    from pydantic import ValidationError

    from ..cases.fields import first_error
    from ..cases.roughness import SurfaceKeys

    given = {key: _numeric(value) if isinstance(value, str) else value
             for key, value in options.items() if value is not None}
    try:
        return SurfaceKeys(kind=kind, **given)
    except ValidationError as exc:
        err = first_error(exc, model=SurfaceKeys, data={"kind": kind, **given})
        raise InputError(_OPTIONS.get(err.field, err.field), err.expected, err.got,
                         problem=err.problem) from None


@surface_app.command()
@_one_line_errors
def generate(
    kind: Annotated[str, typer.Argument(help=f"One of: {', '.join(KINDS)}.")],
    out: Annotated[Path, typer.Option("--out", help="Output file (.txt, .csv, .dat, .npy, .npz).")],
    length: Annotated[str, typer.Option(help="Length along x.")] = "1 mm",
    width: Annotated[str | None, typer.Option(help="Width along y: makes a topography.")] = None,
    spacing: Annotated[str, typer.Option(help="Grid spacing.")] = "1 um",
    rms: Annotated[str | None, typer.Option(help="RMS height (gaussian, self-affine).")] = None,
    rms_slope: Annotated[str | None, typer.Option(
        help="RMS slope instead of rms height (self-affine).")] = None,
    correlation_length: Annotated[str | None, typer.Option(help="ACF decay length to 0.2.")] = None,
    correlation_length_y: Annotated[str | None, typer.Option(
        help="Correlation length along y.")] = None,
    hurst: Annotated[float, typer.Option(help="Hurst exponent (self-affine).")] = 0.8,
    rolloff: Annotated[str | None, typer.Option(help="Roll-off wavelength (self-affine).")] = None,
    cutoff: Annotated[str | None, typer.Option(
        help="Short wavelength cut-off (self-affine).")] = None,
    ra: Annotated[str | None, typer.Option(help="Target Ra (ground).")] = None,
    run_in: Annotated[float, typer.Option(help="Run-in fraction 0..1 (ground).")] = 0.0,
    name: Annotated[str, typer.Option(help="Built-in profile A, B or C (builtin).")] = "C",
    feed: Annotated[str | None, typer.Option(help="Feed per revolution (turned).")] = None,
    nose_radius: Annotated[str | None, typer.Option(help="Tool nose radius (turned).")] = None,
    natural_frequency: Annotated[str | None, typer.Option(
        help="Tool natural frequency: dynamic model.")] = None,
    mass: Annotated[str, typer.Option(help="Tool modal mass (dynamic turned).")] = "250 kg",
    damping_ratio: Annotated[float, typer.Option(
        help="Tool damping ratio (dynamic turned).")] = 0.05,
    depth_of_cut: Annotated[str, typer.Option(help="Depth of cut (dynamic turned).")] = "0.305 mm",
    cutting_speed: Annotated[str, typer.Option(
        help="Cutting speed (dynamic turned).")] = "61 m/min",
    diameter: Annotated[str, typer.Option(help="Workpiece diameter (dynamic turned).")] = "50 mm",
    waviness_wavelength: Annotated[str | None, typer.Option(
        help="Add waviness of this wavelength.")] = None,
    waviness_amplitude: Annotated[str, typer.Option(help="Waviness amplitude.")] = "0",
    waviness_direction: Annotated[str, typer.Option(help="Waviness along x or y.")] = "x",
    seed: Annotated[int, typer.Option(help="Random seed.")] = 0,
):
    """Generate a synthetic surface and write it to --out."""
    from .. import surfaces as s
    from ..cases.roughness import surface_recipe
    from ..surfaces.recipe import Waviness, build_surface

    if kind not in KINDS:
        raise InputError("KIND", f"one of {', '.join(KINDS)}", kind)
    L = _length(length, "--length")
    h = _length(spacing, "--spacing")
    W = _length(width, "--width")
    _check_size(L, h, W)
    keys = _surface_keys(kind, {
        "rms": rms, "rms_slope": rms_slope, "ra": ra, "correlation_length": correlation_length,
        "correlation_length_y": correlation_length_y, "hurst": hurst,
        "rolloff_wavelength": rolloff, "short_cutoff": cutoff, "run_in": run_in, "seed": seed})
    recipe = surface_recipe(keys, profile=name)
    if kind == "gaussian":
        _require(keys.rms, "--rms", kind)
        _require(keys.correlation_length, "--correlation-length", kind)
    elif kind == "ground":
        _require(keys.ra, "--ra", kind)
    elif kind == "turned":
        fn = _quantity(natural_frequency, "frequency", "--natural-frequency")
        recipe = replace(recipe, feed=_require(_length(feed, "--feed"), "--feed", kind),
                         nose_radius=_require(_length(nose_radius, "--nose-radius"),
                                              "--nose-radius", kind))
        if fn is not None:
            recipe = replace(recipe, natural_frequency=fn,
                             depth_of_cut=_length(depth_of_cut, "--depth-of-cut"),
                             cutting_speed=_quantity(cutting_speed, "speed", "--cutting-speed"),
                             workpiece_diameter=_length(diameter, "--diameter"),
                             damping_ratio=damping_ratio, mass=_quantity(mass, "mass", "--mass"))
    if waviness_wavelength is not None:
        recipe = replace(recipe, waviness=Waviness(
            _length(waviness_wavelength, "--waviness-wavelength"),
            _length(waviness_amplitude, "--waviness-amplitude"), waviness_direction))
    y = None if W is None else s.cell_centres(max(2, round(W / h)), h)
    try:
        surface = build_surface(recipe, L, h, width=W, y=y)
    except InputError as exc:  # the recipe's field as the option that set it
        raise InputError(_OPTIONS.get(exc.field, exc.field), exc.expected, exc.got,
                         problem=exc.problem) from None
    if W is not None and isinstance(surface, s.Profile):
        surface = surface.extrude(y)
    s.write_surface(surface, out)
    Console().print(_table(_statistics(surface), f"Generated {kind} surface -> {out} "
                                                 "(unfiltered: heights from the least-squares "
                                                 "line/plane)"))


@surface_app.command()
@_one_line_errors
def plot(
    file: Annotated[Path, typer.Argument(help="Profile or topography file.")],
    out: Annotated[Path, typer.Option("--out", help="Figure file (.png, .pdf, .svg).")],
    spacing: Spacing = None,
    spacing_y: SpacingY = None,
    unit: Unit = None,
    x_unit: XUnit = None,
    z_unit: ZUnit = None,
    missing: Missing = "refuse",
    resample: Resample = False,
    cutoff: Cutoff = None,
    form_degree: FormDegree = 1,
    spectrum: Annotated[bool, typer.Option("--spectrum", help="Plot only the PSD.")] = False,
):
    """Plot the surface (or P/W/R profiles), its PSD and its material ratio curve."""
    import matplotlib.pyplot as plt

    from ..plotting.surfaces import plot_spectrum, plot_texture

    reading = _read(file, spacing, spacing_y, unit, x_unit, z_unit, missing, resample)
    warnings = list(reading.warnings)
    if spectrum:
        fig = plot_spectrum(reading.surface, title=f"Power spectral density: {file.name}")
    else:
        texture = _evaluated(reading, reading.surface, _length(cutoff, "--cutoff"),
                             form_degree=form_degree, exclude=reading.excluded)
        warnings = _warnings(reading, texture)
        fig = plot_texture(texture, title=file.name)
    if not out.suffix:  # matplotlib writes a PNG to "<out>.png"; say so
        out = out.with_suffix(".png")
    try:
        fig.savefig(out, dpi=150)
    except (ValueError, OSError) as err:
        raise InputError("--out", "a writable figure file (.png, .pdf, .svg)", str(err)) from err
    finally:
        plt.close(fig)
    for line in warnings:
        typer.echo(f"warning: {line}", err=True)
    typer.echo(f"wrote {out}")
