"""Reading and writing measured or generated profiles and topographies.

Formats (chosen by the file's suffix):

- Text (``.txt``, ``.csv``, ``.dat``, ``.asc``; commas, semicolons, tabs or spaces): one column
  = heights z (needs a spacing), two columns = x, z, three or more = a height matrix with
  rows along x and columns along y (``z[ix, iy]``, needs a spacing). Lines starting with ``#``
  are comments, except the metadata ``# spacing: dx [dy]``, ``# origin: x0 [y0]`` and
  ``# periodic: true|false`` that :func:`write_surface` writes; a first line of words (a column
  header) is skipped. All values in metres.
- ``.npy``: a 1-D array of heights or a 2-D height matrix (needs a spacing).
- ``.npz``: arrays ``z`` and optionally ``x``, ``y``, ``periodic`` (what :func:`write_surface`
  writes); without ``x`` a spacing is needed.
- Any other suffix (``.x3p``, ``.sur``, ``.opd``, ``.plu``, ``.datx``, ...; note that ``.dat``
  is read as text) is read by
  ``SurfaceTopography.read_topography`` when that optional package is installed
  (``pip install asperity[instruments]``), converted to metres.

Without coordinates in the file, positions are the cell centres ``(i + 1/2) * spacing``.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from ..errors import InputError, check_positive
from .topography import Profile, Topography

__all__ = ["TEXT_SUFFIXES", "read_surface", "write_surface"]

TEXT_SUFFIXES = (".txt", ".csv", ".dat", ".asc")
_SEPARATORS = re.compile(r"[,;\s]+")


def _spacings(spacing, ndim: int, source: str) -> tuple[float, ...]:
    if spacing is None:
        raise InputError("spacing", f"a grid spacing (m) for {source}, which has no coordinates")
    s = np.atleast_1d(np.asarray(spacing, dtype=float))
    if s.size == 1:
        s = np.repeat(s, ndim)
    if s.size != ndim:
        raise InputError("spacing", f"one spacing, or {ndim} (dx, dy)", spacing)
    return tuple(check_positive("spacing", v) for v in s)


def _from_heights(z, spacing, source, origin=None, periodic=False):
    z = np.asarray(z, dtype=float)
    if z.ndim not in (1, 2) or min(z.shape) < 2:
        raise InputError(source, "a 1-D array of heights or a 2-D height matrix", z.shape)
    h = _spacings(spacing, z.ndim, source)
    start = [0.5 * d for d in h] if origin is None else list(np.atleast_1d(origin))
    if len(start) != z.ndim:
        raise InputError("origin", f"{z.ndim} coordinates", origin)
    coords = [s + d * np.arange(n) for s, d, n in zip(start, h, z.shape, strict=True)]
    if z.ndim == 1:
        return Profile(coords[0], z, periodic)
    return Topography(coords[0], coords[1], z, periodic)


def _number(token: str) -> float | None:
    try:
        return float(token)
    except ValueError:
        return None


def _read_text(path: Path, spacing):
    meta: dict[str, list[str]] = {}
    rows: list[list[float]] = []
    first_line = 0
    with path.open("r", encoding="utf-8", errors="replace") as fh:
        for lineno, line in enumerate(fh, start=1):
            text = line.strip()
            if not text:
                continue
            if text.startswith("#"):
                key, sep, value = text[1:].partition(":")
                if sep:
                    meta[key.strip().lower()] = value.split()
                continue
            tokens = [t for t in _SEPARATORS.split(text) if t]
            values = [_number(t) for t in tokens]
            if not rows and all(v is None for v in values):
                continue  # a column header
            where = f"{path}:{lineno}"
            bad = [t for t, v in zip(tokens, values, strict=True) if v is None]
            if bad:
                raise InputError(where, "numbers only", bad[0])
            if rows and len(values) != len(rows[0]):
                raise InputError(where, f"{len(rows[0])} columns like line {first_line}",
                                 f"{len(values)} columns")
            if not all(np.isfinite(values)):
                raise InputError(where, "finite numbers (no NaN or infinity)")
            if not rows:
                first_line = lineno
            rows.append(values)
    if len(rows) < 2:
        raise InputError(str(path), "at least 2 rows of numbers")
    data = np.array(rows)
    periodic = meta.get("periodic", ["false"])[0].lower() == "true"
    if spacing is None and "spacing" in meta:
        spacing = [_number(v) for v in meta["spacing"]]
        if None in spacing:
            raise InputError(f"{path}: spacing", "numbers", " ".join(meta["spacing"]))
    origin = None
    if "origin" in meta:
        origin = [_number(v) for v in meta["origin"]]
        if None in origin:
            raise InputError(f"{path}: origin", "numbers", " ".join(meta["origin"]))
    if data.shape[1] == 2:
        return Profile(data[:, 0], data[:, 1], periodic)
    heights = data[:, 0] if data.shape[1] == 1 else data
    return _from_heights(heights, spacing, str(path), origin, periodic)


def _read_npz(path: Path, spacing):
    with np.load(path, allow_pickle=False) as f:
        arrays = {k: f[k] for k in f.files}
    if "z" not in arrays:
        raise InputError(str(path), "an array named 'z' (and optionally 'x', 'y')",
                         sorted(arrays))
    z = arrays["z"]
    periodic = bool(arrays.get("periodic", False))
    if "x" not in arrays:
        return _from_heights(z, spacing, str(path), periodic=periodic)
    if z.ndim == 1:
        return Profile(arrays["x"], z, periodic)
    if "y" not in arrays:
        raise InputError(str(path), "an array 'y' with the 2-D heights 'z'")
    return Topography(arrays["x"], arrays["y"], z, periodic)


def _read_instrument(path: Path):
    try:
        import SurfaceTopography
    except ImportError:
        raise InputError(str(path), f"a text, .npy or .npz file; {path.suffix or 'this'} files "
                                    "need SurfaceTopography: pip install asperity[instruments]"
                         ) from None
    try:
        topo = SurfaceTopography.read_topography(str(path))
        if getattr(topo, "unit", None) not in (None, "m"):
            topo = topo.to_unit("m")
        if not topo.is_uniform:
            raise InputError(str(path), "uniformly sampled data")
        if topo.has_undefined_data:
            raise InputError(str(path), "data without undefined (missing) points")
        z = np.asarray(topo.heights(), dtype=float)
        h = np.atleast_1d(topo.pixel_size)
    except InputError:
        raise
    except Exception as err:  # any failure of the third-party reader
        raise InputError(str(path), "a file SurfaceTopography can read", str(err)) from err
    return _from_heights(z, tuple(h), str(path), periodic=bool(topo.is_periodic))


def read_surface(path, spacing=None):
    """Read a profile or topography (see the module docstring for the formats).

    Parameters
    ----------
    path : str or Path
    spacing : float or (float, float), optional
        Grid spacing (m), needed when the file holds heights without coordinates; ignored when
        it has them.

    Returns
    -------
    Profile or Topography

    Raises
    ------
    InputError
        Missing file, unknown format, ragged or non-numeric text (naming file and line),
        missing spacing.
    """
    path = Path(path)
    if not path.is_file():
        raise InputError("file", "an existing file", str(path))
    suffix = path.suffix.lower()
    if suffix in TEXT_SUFFIXES:
        return _read_text(path, spacing)
    if suffix == ".npy":
        try:
            z = np.load(path, allow_pickle=False)
        except ValueError as err:
            raise InputError(str(path), "a numeric .npy array", str(err)) from err
        return _from_heights(z, spacing, str(path))
    if suffix == ".npz":
        return _read_npz(path, spacing)
    return _read_instrument(path)


def write_surface(surface, path) -> Path:
    """Write a Profile or Topography; the suffix picks the format.

    ``.npz`` keeps everything (x, y, z, periodic); text keeps everything too (a profile as
    x, z columns, a topography as the height matrix with ``# spacing`` and ``# origin``
    metadata), with 17 significant digits; ``.npy`` keeps only the heights (reading it back
    needs the spacing). ``.csv`` is comma-separated, other text suffixes space-separated.
    """
    if not isinstance(surface, Profile | Topography):
        raise InputError("surface", "a Profile or a Topography", type(surface).__name__)
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".npy":
        np.save(path, surface.z)
    elif suffix == ".npz":
        extra = {"y": surface.y} if isinstance(surface, Topography) else {}
        np.savez(path, x=surface.x, z=surface.z, periodic=surface.periodic, **extra)
    elif suffix in TEXT_SUFFIXES:
        sep = "," if suffix == ".csv" else " "
        head = [f"periodic: {str(surface.periodic).lower()}"]
        if isinstance(surface, Profile):
            data = np.column_stack([surface.x, surface.z])
            head = ["asperity profile, columns x z (m)", *head]
        else:
            data = surface.z
            dx, dy = surface.spacing
            head = ["asperity topography, heights z[ix, iy] (m), rows along x",
                    f"spacing: {dx!r} {dy!r}",
                    f"origin: {float(surface.x[0])!r} {float(surface.y[0])!r}",
                    *head]
        np.savetxt(path, data, fmt="%.17g", delimiter=sep, header="\n".join(head),
                   comments="# ")
    else:
        raise InputError("path", f"a file name ending in one of {', '.join(TEXT_SUFFIXES)}, "
                                 ".npy, .npz", str(path))
    return path
