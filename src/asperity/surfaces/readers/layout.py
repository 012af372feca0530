"""What the columns of a text export mean: x, y, z columns or a height matrix, units, scales.

Rules, in order (documented for users in docs/surfaces.md):

- Named columns: a column named like a position (``x``, ``lateral``, ``position``,
  ``distance``, ``horizontal``, ``length``, ``scan``) is x, one like ``y`` is y, and one named
  like a height (``z``, ``height``, ``raw``, ``profile``, ``data``, ``value``, ``depth``, ...)
  is z; x and z make a profile, x, y and z a point list on a grid (an XYZ export): in any
  order, on uniform steps within the printed precision, positions absent from the list
  missing.
- A first column that counts the points (1, 2, 3, ... or 0, 1, 2, ...; named ``No.``,
  ``Index``, ``Point``, ``#`` or unnamed, with no x unit in the header) is a point number, not
  a position: the heights then take the header's spacing (a pitch key) or the one given. Read
  as x, a stylus export's ``"No.","Profile(um)"`` columns made 8,000 points at 0.5 um an
  8,000 m profile.
- Unnamed columns: one = heights, two = x and z, three or more = a height matrix -- except
  three columns whose first is evenly spaced, increasing positions: a profile export (x and
  two height channels) that would otherwise read as a 3-wide matrix, and three columns that are
  an x, y, z point list (their first two repeat values covering a grid), both refused with how
  to name their columns.
- A height matrix whose first row holds the x positions and first column the y positions
  (``,0.0,0.5,...`` or ``y\\x,0.0,0.5,...`` above ``0.0,h,h,...``: how spreadsheets and
  several instruments' "matrix with axes" exports write it) takes its coordinates from them.
  The corner cell is empty, a label or a number; a number only where the heights beside that
  row and column are not evenly spaced themselves. Read as heights, they made a 64 x 32 map
  of Sq 0.36 um one of 65 x 33 with Sq 3.2 um once the corner was filled.
- A height matrix has one line per y, values along x (how instruments, Gwyddion and
  SurfaceTopography write images), except one written by asperity's ``write_surface`` (its
  first comment says ``asperity topography ... rows along x``), which has one line per x.
- Units: the unit in a column's name (``x_um``, ``Height [nm]``) or the header's ``x-unit``,
  ``z-unit``, ``Lateral units``, ``Value units``, ``Unit`` keys; a height scale factor
  (``Z scale``, ``Height scale``, ``Bit2nm``, ``height conversion factor (-> um)``) multiplies
  the stored values; a ``No data value`` (``Invalid value``, ...) marks missing points. Spacing
  from ``spacing``/``pixel size``/``resolution``/``Scale X`` keys or
  from the physical size (``Width``, ``x-length``) divided by the number of points.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np

from ...errors import InputError
from .text import TextTable, is_number, printed_resolution
from .units import length_factor, unit_of_name

__all__ = ["SIZE_KEYS", "Layout", "interpret"]

_X_WORDS = ("x", "lateral", "position", "distance", "horizontal", "length", "scan", "pos")
_Y_WORDS = ("y",)
_INDEX_WORDS = ("no", "nr", "num", "number", "index", "idx", "point", "points", "pt", "#", "n",
                "count", "sample")
_Z_WORDS = ("z", "height", "heights", "raw", "profile", "data", "value", "depth", "elevation",
            "total", "normal", "roughness", "surface", "amplitude", "h", "topography")
_UNIT_KEYS = ("unit", "units", "length unit", "lateral and height unit")
_X_UNIT_KEYS = ("x unit", "x units", "xunit", "lateral unit", "lateral units", "unit x",
                "horizontal unit", "x axis unit")
_Z_UNIT_KEYS = ("z unit", "z units", "zunit", "value unit", "value units", "height unit",
                "height units", "unit data", "data unit", "vertical unit", "z axis unit")
_SCALE_KEYS = ("z scale", "zscale", "height scale", "scale z", "z factor", "height factor",
               "z scaling", "z multiplier", "height multiplier", "z scale factor",
               "height scale factor")
_SPACING_KEYS = ("spacing", "pixel size", "x spacing", "dx", "sampling interval",
                 "x increment", "resolution", "scale x", "x resolution", "point spacing",
                 "sampling distance", "x pitch", "pitch", "x step", "step size", "x scale")
_Y_SPACING_KEYS = ("y spacing", "dy", "scale y", "y increment", "y resolution", "y pitch",
                   "y step", "y scale")
_WIDTH_KEYS = ("width", "x length", "x size", "image width", "x range")
_HEIGHT_KEYS = ("y length", "y size", "image height", "y range")
#: The header keys of a spacing or a size: the entries a decimal comma changes
#: (:mod:`.header_sizes`).
SIZE_KEYS = _SPACING_KEYS + _Y_SPACING_KEYS + _WIDTH_KEYS + _HEIGHT_KEYS
_MISSING_KEYS = ("no data value", "nodata", "no data", "invalid value", "undefined value",
                 "missing value", "bad value", "void value", "nodata value")
_QUANTITY = re.compile(r"^\s*([+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)\s*(.*?)\s*$")
#: What may stand between two numbers of one header value (``0.5 x 0.8 um``), before a number.
_BETWEEN = re.compile(r"^\s*(?:[x×*,;]|by)\s*(?=[+-]?\.?\d)", re.IGNORECASE)


@dataclass(frozen=True)
class Layout:
    """A text export's data as a surface in the file's units, with what is known of them.

    Attributes
    ----------
    z : ndarray
        Stored heights times any header scale factor (1-D, or 2-D ``[ix, iy]``); NaN missing.
    x, y : ndarray or None
        Coordinates from the file (file units), or None for gridded data without them.
    x_factor, z_factor : float or None
        Metres per file unit of the coordinates and of ``z``, None when the file does not say.
    x_unit_source, z_unit_source : str or None
        Where the file says so (``"the column name 'X (mm)'"``), None where it does not.
    spacing : tuple of float or None
        Grid spacing from the header, in units of ``spacing_factor``.
    spacing_factor : float or None
        Metres per unit of ``spacing``; None when it is in the file's x unit.
    resolution : float
        Printed resolution of the x column (file units), 0 when there is none.
    periodic : bool
    origin : list of float or None
    style : str
        What was recognised, for the user (``"x, z columns named x_um, z_um"``).
    """

    z: np.ndarray
    x: np.ndarray | None
    y: np.ndarray | None
    x_factor: float | None
    z_factor: float | None
    x_unit_source: str | None
    z_unit_source: str | None
    spacing: tuple[float, ...] | None
    spacing_factor: float | None
    resolution: float
    periodic: bool
    origin: list[float] | None
    style: str


def _first(header: dict, keys) -> str | None:
    return next((header[k] for k in keys if k in header), None)


def _header_unit(header: dict, keys) -> tuple[float | None, str | None]:
    """Metres per unit of the first of ``keys`` in the header naming a length unit, and where
    it was found (``"the header's 'unit' entry (mm)"``)."""
    key = next((k for k in keys if k in header), None)
    factor = None if key is None else length_factor(header[key])
    return (None, None) if factor is None else (factor, f"the header's {key!r} entry "
                                                        f"({header[key]})")


def _named_unit(name: str, factor: float | None, source: str | None):
    """The unit in a column name if it has one, else ``(factor, source)``."""
    found = unit_of_name(name)
    return (found[1], f"the column name {name!r}") if found else (factor, source)


def _quantity(text: str | None) -> tuple[list[float], float | None] | None:
    """Numbers and the unit's factor of ``"0.5 um"``, ``"0.333 um/pt"``, ``"1e-6 2e-6"``,
    ``"0.5 x 0.8 um"`` (numbers also between ``x``, ``×``, ``*``, ``,``, ``;`` or ``by``)."""
    if text is None:
        return None
    numbers = []
    rest = text
    while True:
        match = _QUANTITY.match(rest)
        if match is None:
            break
        numbers.append(float(match.group(1)))
        rest = _BETWEEN.sub("", match.group(2), count=1)
    if not numbers:
        return None
    unit = rest.split("/")[0].strip().strip("[]()")
    return numbers, length_factor(unit) if unit else None


def _first_word(name: str) -> str:
    """The first word of a column name, lower case (``"X [um]"`` -> ``"x"``, ``"No."`` ->
    ``"no"``)."""
    return re.split(r"[\s_\[\](),/.:-]+", name.strip().lower())[0] if name.strip() else ""


def _role(name: str) -> str | None:
    word = _first_word(name)
    for role, words in (("x", _X_WORDS), ("y", _Y_WORDS), ("z", _Z_WORDS)):
        if word in words:
            return role
    return None


def _counts_points(table: TextTable, x_unit_known: bool) -> bool:
    """Whether the first of two columns numbers the points (module docstring): consecutive
    integers from 0 or 1, printed without decimals, and named like an index or, unnamed, with
    no x unit in the header."""
    column = table.data[:, 0]
    if table.resolution[0] != 0 or column.size < 2 or not np.all(np.isfinite(column)):
        return False
    if column[0] not in (0.0, 1.0) or not np.all(np.diff(column) == 1.0):
        return False
    if table.names:
        return _first_word(table.names[0]) in _INDEX_WORDS
    return not x_unit_known


def _columns(table: TextTable):
    """Indices of the x, y, z columns from their names (None where a role is absent)."""
    roles = {}
    for j, name in enumerate(table.names or ()):
        role = _role(name)
        if role is not None and role not in roles:
            roles[role] = j
    return roles.get("x"), roles.get("y"), roles.get("z")


def _scale(header: dict, z_unit: tuple[float | None, str | None]):
    """(multiplier of the stored heights, (metres per unit of the product or None, where the
    file says so))."""
    for key, value in header.items():
        match = re.match(r"height conversion factor \(\s*->\s*(.+?)\s*\)", key)
        if match is not None:
            q = _quantity(value)
            if q is not None:
                return q[0][0], (length_factor(match.group(1)), f"the header's {key!r} entry")
    if "bit2nm" in header:
        q = _quantity(header["bit2nm"])
        if q is not None:
            return q[0][0], (1e-9, "the header's 'bit2nm' entry")
    key = next((k for k in _SCALE_KEYS if k in header), None)
    q = None if key is None else _quantity(header[key])
    if q is not None:
        return q[0][0], (z_unit if q[1] is None else
                         (q[1], f"the header's {key!r} entry ({header[key]})"))
    return 1.0, z_unit


def _lattice(values: np.ndarray, resolution: float) -> tuple[np.ndarray, np.ndarray] | None:
    """The uniform lattice that a point list's coordinates lie on, within their printed
    ``resolution``: (the lattice's positions, each value's index on it); None when they do not
    lie on one. Each gap between distinct values is a whole number of median gaps; the step is
    the least-squares line through the values against those indices (so a coordinate printed
    to 4 decimals at a 1/3 um pitch, and a lattice with whole rows absent, are both found)."""
    distinct = np.unique(values)
    if distinct.size < 2:
        return None
    steps = np.diff(distinct)
    index = np.concatenate([[0], np.cumsum(np.rint(steps / np.median(steps)).astype(int))])
    slope, intercept = np.polyfit(index, distinct, 1)
    deviation = np.abs(distinct - (intercept + slope * index)).max()
    if deviation > resolution * (1 + 1e-6) + 1e-9 * abs(slope):
        return None
    return intercept + slope * np.arange(index[-1] + 1), index[np.searchsorted(distinct, values)]


def _grid_from_points(x, y, z, where: str, resolution=(0.0, 0.0)):
    """Heights ``[ix, iy]`` from an XYZ point list: its points in any order on a uniform
    lattice along x and y (within the printed ``resolution`` of each), each position once, at
    least half of the lattice present; absent positions are missing (NaN).

    Returns
    -------
    (xs, ys, grid, absent) : the lattice's positions along x and y (file units), the heights,
    and the number of lattice positions absent from the list.
    """
    if not (np.all(np.isfinite(x)) and np.all(np.isfinite(y))):
        raise InputError(where, "an x and a y position on every line of an x, y, z point list "
                         "(a missing marker is for heights only)",
                         f"{int(np.sum(~np.isfinite(x) | ~np.isfinite(y)))} lines without one")
    found = [_lattice(c, r) for c, r in ((x, resolution[0]), (y, resolution[1]))]
    size = None if None in found else found[0][0].size * found[1][0].size
    if size is None or min(f[0].size for f in found) < 2 or size > 2 * z.size:
        counts = f"{np.unique(x).size} x and {np.unique(y).size} y values"
        raise InputError(where, "x, y, z points on a rectangular grid (uniform steps along x "
                         "and y within the printed precision; at least half of its positions "
                         "present)", f"{z.size} points over {counts}")
    (xs, ix), (ys, iy) = found
    flat = ix * ys.size + iy
    repeated = z.size - np.unique(flat).size
    if repeated:
        raise InputError(where, "x, y, z points with each (x, y) position once",
                         f"{repeated} repeated positions")
    grid = np.full((xs.size, ys.size), np.nan)
    grid[ix, iy] = z
    return xs, ys, grid, size - z.size


def _axis(values: np.ndarray, resolution: float) -> np.ndarray | None:
    """``values`` as an axis: finite, strictly monotonic and evenly spaced within the printed
    ``resolution``; their order (increasing) as indices, or None."""
    if values.size < 2 or not np.all(np.isfinite(values)):
        return None
    steps = np.diff(values)
    if not (np.all(steps > 0) or np.all(steps < 0)) or not _on_a_line(values, resolution):
        return None
    return np.argsort(values)


def _matrix_axes(table: TextTable):
    """(x, y, heights [ix, iy], the corner's value or None) of a height matrix with its x
    positions in the first row and its y positions in the first column (module docstring);
    None for any other block. The corner cell is empty, a label, or a number whose row and
    column are evenly spaced positions while the heights beside them are not (a tilted
    plane's matrix has every row and column on a line, and is read as heights)."""
    data, names = table.data, table.names
    corner = None
    if names and len(names) == data.shape[1] and all(is_number(n) for n in names[1:]):
        row = np.array([float(n) for n in names[1:]])   # a corner label (``y\x``) above
        resolution = max(printed_resolution(n) for n in names[1:])
    elif data.shape[0] >= 3 and data.shape[1] >= 3:
        resolution = float(np.max(table.resolution[1:]))
        if not np.isnan(data[0, 0]):
            if _on_a_line(data[1, 1:], resolution) or _on_a_line(data[1:, 1], resolution):
                return None
            corner = float(data[0, 0])
        row, data = data[0, 1:], data[1:]
    else:
        return None
    if data.shape[0] < 2 or data.shape[1] < 3:
        return None
    order_x = _axis(row, resolution)
    order_y = _axis(data[:, 0], float(table.resolution[0]))
    if order_x is None or order_y is None:
        return None
    return row[order_x], data[:, 0][order_y], data[:, 1:].T[order_x][:, order_y], corner


def _point_grid(data: np.ndarray) -> bool:
    """Whether three unnamed columns hold an x, y, z point list: their first two columns
    repeat few values that together cover a grid, one point each -- which a height matrix
    three points wide does not (its first two columns are heights, nearly all different)."""
    xs, ys = np.unique(data[:, 0]).size, np.unique(data[:, 1]).size
    pairs = np.unique(data[:, :2], axis=0).shape[0]
    return min(xs, ys) >= 2 and pairs == data.shape[0] and xs * ys <= 2 * data.shape[0]


def _unnamed_points(data: np.ndarray, where: str) -> None:
    """Refuse three unnamed columns that are an x, y, z point list (:func:`_point_grid`): as a
    height matrix they would read as a surface three points wide; as points they need units
    the file does not give."""
    if not _point_grid(data):
        return
    raise InputError(where, "named columns for an x, y, z point list: these 3 columns are "
                     f"points ({np.unique(data[:, 0]).size} x by {np.unique(data[:, 1]).size} "
                     "y values, one line per point), not a height matrix 3 points wide; name "
                     "the columns in a line above the numbers with their units, e.g. "
                     "'x_um y_um z_um' (pixel indices multiplied by the pixel size first)",
                     f"{data.shape[0]} lines of 3 unnamed numbers")


def _on_a_line(column: np.ndarray, resolution: float) -> bool:
    """Whether ``column`` is a straight line of its index within its printed ``resolution``."""
    i = np.arange(column.size)
    slope, intercept = np.polyfit(i, column, 1)
    tolerance = resolution * (1 + 1e-6) + 1e-9 * abs(slope)
    return bool(np.max(np.abs(column - (intercept + slope * i))) <= tolerance)


def _positions_first(table: TextTable, where: str) -> None:
    """Refuse three unnamed columns whose first holds evenly spaced, increasing positions and
    the others not (heights): a profile export (x and two height channels), not a height
    matrix three points wide (a plane's matrix has every column on a line)."""
    data, res = table.data, table.resolution
    first = data[:, 0]
    if (first.size < 4 or not np.all(np.isfinite(data)) or np.any(np.diff(first) <= 0)
            or not _on_a_line(first, res[0])
            or all(_on_a_line(data[:, j], res[j]) for j in (1, 2))):
        return
    raise InputError(where, "a height matrix of more than 3 columns; these 3 columns are a "
                     f"profile export (the first is evenly spaced positions, {first[0]:g} to "
                     f"{first[-1]:g} in steps of {first[1] - first[0]:.4g}, with two height "
                     "columns): to read x and the first heights as a profile, name the columns "
                     "in a line above the numbers, e.g. 'x_mm z_um z2_um' (units in the names)",
                     f"{first.size} lines of 3 numbers")


def _line_along(x: np.ndarray, y: np.ndarray, x_name: str, y_name: str):
    """For an x, y, z export of a line profile (one coordinate the same on every line): the
    column it runs along (0: x, 1: y) and a description; None for a map."""
    for along, (moving, fixed, name, other) in enumerate(((x, y, x_name, y_name),
                                                         (y, x, y_name, x_name))):
        if np.unique(fixed).size == 1 and np.unique(moving).size > 1:
            return along, (f"a profile along {name!r} ({other!r} the same, {fixed[0]:g}, on "
                           "every line)")
    return None


def _absent_text(absent: int, size: int) -> str:
    return f", {absent} of the {size} grid positions absent (missing)" if absent else ""


def interpret(table: TextTable, where: str) -> Layout:
    """Decide what the columns of ``table`` are and what units they carry (module docstring)."""
    h = table.header
    unit_all = _header_unit(h, _UNIT_KEYS)
    x_unit = _header_unit(h, _X_UNIT_KEYS)
    x_unit = x_unit if x_unit[0] is not None else unit_all
    z_unit = _header_unit(h, _Z_UNIT_KEYS)
    z_unit = z_unit if z_unit[0] is not None else unit_all
    data, names = table.data, table.names
    ix, iy, iz = _columns(table)
    x = y = None
    resolution = 0.0
    ncol = data.shape[1]
    if names is not None and ix is not None and iz is not None:
        line = None if iy is None else _line_along(data[:, ix], data[:, iy], names[ix],
                                                  names[iy])
        if line is not None:  # a line profile exported as x, y, z: the other coordinate fixed
            ix = (ix, iy)[line[0]]
        x, z = data[:, ix], data[:, iz]
        resolution = float(table.resolution[ix])
        x_unit = _named_unit(names[ix], *x_unit)
        z_unit = _named_unit(names[iz], *z_unit)
        style = f"columns named {names[ix]!r} (x) and {names[iz]!r} (z)"
        if line is not None:
            style = f"{line[1]}, heights {names[iz]!r}"
        elif iy is not None:
            x, y, z, absent = _grid_from_points(
                x, data[:, iy], z, where, (table.resolution[ix], table.resolution[iy]))
            style = (f"x, y, z points named {names[ix]!r}, {names[iy]!r}, {names[iz]!r}"
                     + _absent_text(absent, z.size))
    elif ncol == 1:
        z = data[:, 0]
        z_unit = _named_unit(names[0], *z_unit) if names else z_unit
        style = "one column of heights" + (f" named {names[0]!r}" if names else "")
    elif ncol == 2 and _counts_points(table, x_unit[0] is not None):
        z = data[:, 1]
        z_unit = _named_unit(names[1], *z_unit) if names else z_unit
        style = ("a column of point numbers" + (f" named {names[0]!r}" if names else "")
                 + " and heights" + (f" named {names[1]!r}" if names else ""))
    elif ncol == 2:
        x, z = data[:, 0], data[:, 1]
        resolution = float(table.resolution[0])
        if names:
            x_unit = _named_unit(names[0], *x_unit)
            z_unit = _named_unit(names[1], *z_unit)
        style = "two columns, x and z" + (f" named {names[0]!r}, {names[1]!r}" if names else "")
    elif ncol == 3 and ("lateral units" in h or "lateral unit" in h):
        x, y, z, absent = _grid_from_points(data[:, 0], data[:, 1], data[:, 2], where,
                                            table.resolution[:2])
        style = "x, y, z points (Gwyddion XYZ export)" + _absent_text(absent, z.size)
    elif "asperity topography" in h:
        z = data
        style = "height matrix, one line per x (written by asperity)"
    elif (axes := _matrix_axes(table)) is not None:
        x, y, z, corner = axes
        style = "height matrix, x in its first row and y in its first column" + (
            "" if corner is None else f" (the corner's {corner:g} not read)")
    else:
        if ncol == 3:
            _positions_first(table, where)
            _unnamed_points(data, where)
        z = data.T
        style = "height matrix, one line per y"
    sentinel = _quantity(_first(h, _MISSING_KEYS))
    if sentinel is not None:
        z = np.where(z == sentinel[0][0], np.nan, z)
    scale, z_unit = _scale(h, z_unit)
    spacing = _spacing(h, z, where)
    periodic = str(h.get("periodic", "false")).lower() == "true"
    origin = _quantity(h.get("origin"))
    return Layout(np.asarray(z, float) * scale, x, y, x_unit[0], z_unit[0], x_unit[1],
                  z_unit[1], None if spacing is None else spacing[0],
                  None if spacing is None else spacing[1], resolution,
                  periodic, None if origin is None else origin[0],
                  style + ("" if scale == 1.0 else f", heights scaled by {scale:g}"))


def _spacing(h: dict, z: np.ndarray, where: str) -> tuple[tuple[float, ...], float | None] | None:
    """Spacing from the header's spacing or size keys, and metres per its unit (None: the
    file's x unit). A spacing entry of more than two numbers is refused, naming it: a Wyko
    block table's ``Pixel_size 7 4 0.00164`` (type, length, value) was taken for three spacings
    and ended in a traceback when a spacing was given."""
    text = _first(h, _SPACING_KEYS)
    q = _quantity(text)
    if q is not None and (q[1] is not None or "." in text or len(q[0]) > 1 or "spacing" in h):
        values = list(q[0])
        if len(values) > 2:
            key = next(k for k in _SPACING_KEYS if k in h)
            raise InputError(f"{where}: header {key!r}", "one spacing, or two (dx, dy), with "
                             "their unit: correct that header line, or delete it and give the "
                             "spacing, --spacing \"0.5 um\" (case file: spacing = \"0.5 um\")",
                             text)
        qy = _quantity(_first(h, _Y_SPACING_KEYS))
        if qy is not None and len(values) == 1 and qy[1] == q[1]:
            values += qy[0]
        return tuple(values), q[1]
    width = _quantity(_first(h, _WIDTH_KEYS))
    if width is None:
        return None
    out = [width[0][0] / z.shape[0]]
    height = _quantity(_first(h, _HEIGHT_KEYS) or (h.get("height") if "width" in h else None))
    if z.ndim == 2 and height is not None and height[1] == width[1]:
        out.append(height[0][0] / z.shape[1])
    return tuple(out), width[1]
