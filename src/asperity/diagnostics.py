"""Trust checks of a result: does the answer depend on a choice the user made badly?

Each function takes fields and grids (SI units) and returns a list of warning lines, empty when
there is nothing to say. A line names the quantity, its value, the limit, and what to change
in the case, e.g. ``inlet: x_min = -1.05 a leaves pressure 3.1 % of p_h within 0.1 a of the
inlet boundary (limit 1 %); the film is starved and too thin; use x_min <= -2.5 a``. Runners
append the lines to :attr:`asperity.results.Outcome.warnings`; the command line prints them,
and ``asperity run --strict`` fails on them.

The checks are deliberately simple and conservative: a warning means "this answer is not the
answer to the problem you meant", not "this answer is wrong by exactly so much".
"""

from __future__ import annotations

import math
from collections.abc import Iterable

import numpy as np

from .ehl.formulas import flooded_film, flooded_inlet_distance, starved_film_ratio
from .ehl.problem import FILM_ERROR, MESH_TARGET, MIN_CELL_ASPECT
from .ehl.smooth_start import touching_mask
from .formatting import format_quantity
from .surfaces.parameters import rms_gradient
from .surfaces.topography import Topography

__all__ = [
    "FILL_FRACTION",
    "PATCH_PERIOD_FRACTION",
    "MIN_CELLS_PER_SEMI_AXIS",
    "BOUNDARY_PRESSURE",
    "BOUNDARY_BAND",
    "FILM_MESH_ERROR",
    "COLLAPSED_FILM",
    "SIDE_CENTRAL_CHANGE",
    "SIDE_FILM_CHANGE",
    "SIDE_PROBE_PRESSURE",
    "STARVED_FILM_LOSS",
    "RIGID_FILM_LOSS",
    "RIGID_MARGIN",
    "RIGID_PRESSURE",
    "RIGID_OUTLET",
    "RIGID_REACH",
    "RIGID_SPACING",
    "UNRESOLVED_WAVELENGTH_CELLS",
    "UNRESOLVED_RMS_SHARE",
    "LOWPASS_RMS_SHARE",
    "NEWTONIAN_TRACTION_LIMIT",
    "COARSE_FILE_FACTOR",
    "MIN_CORRELATION_LENGTHS_ON_GRID",
    "DECIMATED_FILE_FACTOR",
    "SEAM_JUMP_RATIO",
    "above_hardness",
    "asperity_plasticity_note",
    "hardness_given",
    "coarse_roughness_file",
    "decimated_roughness_file",
    "contact_at_grid_edge",
    "flat_on_open_grid",
    "contact_resolution",
    "spot_resolution",
    "roughness_extent",
    "MIN_CELLS_PER_SPOT",
    "ehl_inlet",
    "ehl_rigid_domain",
    "ehl_inlet_film",
    "ehl_inlet_length",
    "flooded_inlet_distance_of",
    "ehl_film_collapse",
    "ehl_film_mesh",
    "ehl_mesh",
    "ehl_minimum_film_mesh",
    "minimum_film_curvature",
    "MIN_FILM_MESH_ERROR",
    "ehl_side_film",
    "ehl_sides",
    "DomainAdvice",
    "advised_domain",
    "feature_passage",
    "measured_file_on_grid",
    "side_pressure",
    "smooth_start_contact",
    "stopped_run",
    "steps_above_hardness",
    "lowpass_removed",
    "newtonian_traction",
    "periodic_contact",
    "periodic_seam",
    "unconverged_steps",
    "unresolved_feature",
    "unresolved_roughness",
    "HERTZ_SIZE_LIMIT",
    "HERTZ_STRAIN_LIMIT",
    "hertz_first_yield",
    "hertz_validity",
    "hertz_plasticity_note",
    "ELASTOMER_MODULUS",
    "FIRST_YIELD_STRAIN",
]

#: Contact fraction of a periodic cell above which the contact "fills the cell".
FILL_FRACTION = 0.9
#: Width of one contact patch, as a fraction of the period, above which its periodic images
#: interact (the periodic answer is then not that of an isolated contact).
PATCH_PERIOD_FRACTION = 0.5
#: Fewest cells across the smallest semi-axis of a contact (dry or the EHL Hertz zone).
MIN_CELLS_PER_SEMI_AXIS = 10
#: Friction coefficient of a Newtonian EHL film above which it is reported as no traction: the
#: solvers' default boundary friction of dry nodes. A film that transmits more shear than a dry
#: contact does is the Newtonian stress eta du / h, unbounded as the pressure raises eta,
#: not a lubricated traction, which the oil's limiting shear stress keeps lower.
NEWTONIAN_TRACTION_LIMIT = 0.1
#: EHL pressure, as a fraction of the Hertz pressure, allowed near an inlet or side boundary.
BOUNDARY_PRESSURE = 0.01
#: Width of the band next to an EHL boundary, in semi-axes, where that pressure is measured.
BOUNDARY_BAND = 0.1
#: Side pressure, as a fraction of the Hertz pressure, above which (up to
#: ``BOUNDARY_PRESSURE``) the film's dependence on the side boundaries is measured by a
#: re-solve with wider sides (:func:`asperity.ehl.sides.side_probe`).
SIDE_PROBE_PRESSURE = 1e-4
#: Change of the minimum film, and of the central film, between that re-solve and the case's
#: domain above which the sides are reported.
SIDE_FILM_CHANGE = 0.02
SIDE_CENTRAL_CHANGE = 0.01
#: Estimated discretisation error of the EHL central film (``FILM_ERROR dX^2 / H_c``, the
#: default mesh's rule) above which a mesh is reported coarse for the film.
FILM_MESH_ERROR = 0.05
#: Discretisation error of the minimum film per relative second difference of the film at
#: its node (across y or along x), and the estimated error above which it is reported
#: (docs/ehl-robustness.md, "A minimum film the mesh does not resolve").
MIN_FILM_ERROR_PER_CURVATURE = 0.33
MIN_FILM_MESH_ERROR = 0.05
#: Share of the film formulas' central film below which a smooth steady film in the Hertz
#: zone has collapsed (:func:`ehl_film_collapse`).
COLLAPSED_FILM = 0.01
#: Loss of central film a short inlet may cause (Hamrock & Dowson's starvation fit) before it is
#: reported.
STARVED_FILM_LOSS = 0.02
#: Roughness at wavelengths shorter than this many mesh spacings is not resolved by the mesh.
UNRESOLVED_WAVELENGTH_CELLS = 4.0
#: Share of the rms height at unresolved wavelengths above which the mesh is reported coarse.
UNRESOLVED_RMS_SHARE = 0.2
#: Share of the rms height a low-pass filter may remove before it is reported.
LOWPASS_RMS_SHARE = 0.01


def _pct(value: float) -> str:
    return f"{100.0 * value:.3g} %"


def _spacing(coord) -> float:
    coord = np.asarray(coord, dtype=float)
    return float(coord[1] - coord[0]) if coord.size > 1 else math.inf


class DomainAdvice(str):
    """A warning line that advises domain bounds, with those bounds in ``bounds`` (m; the keys
    of the ones it advises: ``x_min``, ``x_max``, ``y_min``, ``y_max``).

    The mesh lines of the same run count the nodes they advise on the domain these lines
    advise (:func:`advised_domain`): a contact warned of sides at +-1.2 b ("use +-2 b") and of
    a minimum film unresolved across y was told ``ny >= 81``, the count for dy = b/33 on its
    own 2.4 b; on the advised 4 b those 81 nodes give b/20.
    """

    bounds: dict

    def __new__(cls, text: str, **bounds: float):
        line = super().__new__(cls, text)
        line.bounds = bounds
        return line


def advised_domain(x, y, lines: Iterable[str]):
    """The domain ``((x0, x1), (y0, y1))`` (m) of the nodes ``x``, ``y``, widened to every bound
    that a :class:`DomainAdvice` among ``lines`` advises (the farthest where several do)."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    x0, x1, y0, y1 = float(x[0]), float(x[-1]), float(y[0]), float(y[-1])
    for line in lines:
        bounds = getattr(line, "bounds", {})
        x0 = min(x0, bounds.get("x_min", x0))
        x1 = max(x1, bounds.get("x_max", x1))
        y0 = min(y0, bounds.get("y_min", y0))
        y1 = max(y1, bounds.get("y_max", y1))
    return (x0, x1), (y0, y1)


def _span(coord, bounds, semi: float, name: str) -> tuple[float, str]:
    """Length (m) along one axis of the domain whose nodes an advice counts: ``bounds`` (m,
    from :func:`advised_domain`) where they reach beyond the nodes ``coord``, else the nodes'
    own; and a note naming those bounds in the semi-axis ``semi`` called ``name`` ('' for the
    nodes' own)."""
    coord = np.asarray(coord, dtype=float)
    if bounds is None or (bounds[0] >= coord[0] and bounds[1] <= coord[-1]):
        return float(coord[-1] - coord[0]), ""
    return (float(bounds[1] - bounds[0]),
            f" on the advised {bounds[0] / semi:.3g} {name}..{bounds[1] / semi:.3g} {name}")


def contact_at_grid_edge(pressure, x, y, contact_size=None) -> list[str]:
    """Contact on the edge cells of a non-periodic grid: the domain is too small.

    A non-periodic solve takes the pressure beyond the grid to be zero, so a contact that
    reaches the edge is cut off: its pressure is too high and its size too small.

    Parameters
    ----------
    pressure : ndarray, shape (nx, ny)
        Contact pressure, Pa (contact where > 0).
    x, y : ndarray
        Cell-centre coordinates, m.
    contact_size : tuple of float, optional
        The expected contact width along x and y (e.g. Hertz 2a, 2b), m, for the advice.

    Returns
    -------
    list of str
        One line when the contact reaches an edge, else empty.
    """
    p = np.asarray(pressure, dtype=float)
    nx, ny = p.shape
    total = float(p.sum())
    if not total > 0:
        return []
    edge = np.zeros(p.shape, dtype=bool)
    sides = []
    for name, index, axis_len in (("x_min", (0, slice(None)), nx), ("x_max", (-1, slice(None)), nx),
                                  ("y_min", (slice(None), 0), ny),
                                  ("y_max", (slice(None), -1), ny)):
        if axis_len < 3:  # a single row (line contact) has no edge across it
            continue
        edge[index] = True
        if np.any(p[index] > 0):
            sides.append(name)
    if not sides:
        return []
    share = float(p[edge].sum()) / total
    extent = (nx * _spacing(x), ny * _spacing(y) if ny > 1 else math.inf)
    # an axis whose edge the contact reaches needs 1.5 times its extent at least, whatever
    # the expected size (a rough contact spreads beyond its smooth Hertz size)
    widths = (None, None) if contact_size is None else contact_size
    need = []
    for axis, width, e in (("x", widths[0], extent[0]), ("y", widths[1], extent[1])):
        target = 1.5 * width if width is not None else 0.0
        if any(side.startswith(axis) for side in sides):
            target = max(target, 1.5 * e)
        if math.isfinite(e) and e < target:
            need.append(f"{axis}_extent >= {format_quantity(target, 'm', digits=3)}")
    advice = "use " + " and ".join(need)
    if contact_size is not None:
        wx, wy = contact_size
        beyond = all(not math.isfinite(e) or e >= 1.5 * w
                     for w, e in zip(contact_size, extent, strict=True))
        advice = (f"the expected (smooth) contact is {format_quantity(wx, 'm', digits=3)} x "
                  f"{format_quantity(wy, 'm', digits=3)} wide"
                  + (", and this one reaches beyond it" if beyond else "") + "; " + advice)
    return [f"domain: the contact reaches the grid edge at {', '.join(sides)} "
            f"({int(np.count_nonzero(edge & (p > 0)))} edge cells carry {_pct(share)} of the "
            "load; limit: no contact on the edge cells); the pressure beyond the grid is taken "
            f"as zero, so the contact is cut off and its pressures are wrong; {advice}"]


def flat_on_open_grid(pressure, x, y, measured: bool = False) -> list[str]:
    """A nominally flat contact on a non-periodic grid: it reaches the edges by construction.

    :func:`contact_at_grid_edge` would say to enlarge the grid, which does not help a flat:
    its contact spans any grid, and a measured file's size bounds it. The solve is then that
    of a rough punch the size of the grid whose surroundings carry nothing, not of an
    interface (a user's measured 125 um patch at 2 N: real area 733 um^2 on the open grid,
    720 um^2 periodic, docs/tangential.md).

    Parameters
    ----------
    pressure : ndarray, shape (nx, ny)
        Contact pressure, Pa.
    x, y : ndarray
        Cell-centre coordinates, m.
    measured : bool
        The roughness is a measured file, whose extent bounds the grid.

    Returns
    -------
    list of str
        One line when the contact reaches an edge, else empty.
    """
    p = np.asarray(pressure, dtype=float)
    total = float(p.sum())
    edge = np.zeros(p.shape, dtype=bool)
    edge[[0, -1], :] = True
    if p.shape[1] > 2:
        edge[:, [0, -1]] = True
    touching = edge & (p > 0)
    if not total > 0 or not touching.any():
        return []
    share = float(p[edge].sum()) / total
    bound = ("; the measured file's extent bounds the grid, so it cannot be enlarged"
             if measured else "")
    return [f"domain: a nominally flat contact on a non-periodic grid reaches its edges "
            f"({int(np.count_nonzero(touching))} edge cells carry {_pct(share)} of the load; "
            "limit: no contact on the edge cells), as it does on any grid: the answer is that "
            "of a rough punch the size of the grid whose surroundings carry nothing, not of an "
            "interface" + bound + "; for the "
            "interface use grid.periodic = true (with a periodic surface: a measured one "
            "mirrored or windowed first), or a curved body (geometry.shape = \"sphere\") "
            "whose contact lies inside the grid"]


def _patch_widths(contact) -> list[tuple[float, float]]:
    """Widths (fractions of the period along x and y) of the patches of a periodic contact."""
    from scipy import ndimage

    labels, count = ndimage.label(contact)
    if count == 0:
        return []
    parent = np.arange(count + 1)

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    for a, b in ((labels[0, :], labels[-1, :]), (labels[:, 0], labels[:, -1])):
        for i, j in zip(a, b, strict=True):
            if i and j:
                parent[find(i)] = find(j)
    roots = np.array([find(i) for i in range(count + 1)])
    merged = roots[labels]
    widths = []
    for root in np.unique(roots[1:]):
        mask = merged == root
        per_axis = []
        for axis in (0, 1):
            occupied = mask.any(axis=1 - axis)
            n = occupied.size
            if occupied.all():
                per_axis.append(1.0)
                continue
            # the widest run of empty rows, around the circle; the patch fills the rest
            empty = np.concatenate([~occupied, ~occupied]).astype(int)
            run = best = 0
            for v in empty:
                run = run + 1 if v else 0
                best = max(best, run)
            per_axis.append((n - min(best, n)) / n)
        widths.append(tuple(per_axis))
    return widths


def periodic_contact(contact, x, y) -> list[str]:
    """A periodic contact that fills its cell, or one patch wider than half the period.

    A contact that is the same on every row (a profile repeated across y on a flat, a plane
    problem) is judged along x only: its strips span y by design.

    Parameters
    ----------
    contact : ndarray of bool, shape (nx, ny)
        Contact indicator.
    x, y : ndarray
        Cell-centre coordinates, m (the period is the grid length).

    Returns
    -------
    list of str
        At most one line.
    """
    c = np.asarray(contact, dtype=bool)
    fraction = float(c.mean())
    if fraction > FILL_FRACTION:
        return [f"contact: fills {_pct(fraction)} of the periodic cell (limit "
                f"{_pct(FILL_FRACTION)}); the periodic images of the contact merge, so this is "
                "a flat punch, not the contact of the case; use a larger period (x_extent, "
                "y_extent) or, for a single contact, periodic = false"]
    widths = _patch_widths(c)
    if not widths:
        return []
    wx, wy = max(w[0] for w in widths), max(w[1] for w in widths)
    if np.array_equal(c, np.broadcast_to(c[:, :1], c.shape)):
        wy = 0.0  # the same along every row (a profile repeated across y on a flat): the
        # patches are strips across the whole period by design, and a longer one would not
        # change them
    axis, width = ("x", wx) if wx >= wy else ("y", wy)
    if width <= PATCH_PERIOD_FRACTION:
        return []
    period = c.shape[0 if axis == "x" else 1] * _spacing(x if axis == "x" else y)
    return [f"contact: one contact patch spans {_pct(width)} of the period along {axis} "
            f"({format_quantity(width * period, 'm', digits=3)} of "
            f"{format_quantity(period, 'm', digits=3)}; limit {_pct(PATCH_PERIOD_FRACTION)}); "
            f"its periodic images interact; use a period at least twice the patch "
            f"({axis}_extent >= {format_quantity(2 * width * period, 'm', digits=3)}) unless the "
            "case is meant to be a "
            "periodic array"]


def contact_resolution(contact, x, y, min_cells: float = MIN_CELLS_PER_SEMI_AXIS,
                       expected_size=None, file_spacing=None) -> list[str]:
    """A contact resolved by too few cells across its smallest semi-axis, or by none.

    The semi-axes are half the number of grid columns (rows) the contact occupies, so for a
    rough contact they are those of the apparent contact, not of single asperity contacts. An
    axis along which the contact does not change is not judged: a periodic strip (the
    contact of a 1-D waviness, the same at every y) has no semi-axis along it, and was told
    its 16 rows resolved it by 8 cells.

    Parameters
    ----------
    contact : ndarray of bool, shape (nx, ny)
        Contact indicator.
    x, y : ndarray
        Cell-centre coordinates, m.
    min_cells : float
        Fewest cells per semi-axis.
    expected_size : (float, float), optional
        Expected contact widths along x and y, m (e.g. the Hertz 2a, 2b): a solve without a
        cell in contact whose expected contact is narrower than a cell gets a line.
    file_spacing : sequence of float, optional
        A measured roughness file's sampling interval along x (and y), m: where the grid the
        advice asks for would be finer than the file's points, the line says so instead of
        asking for it (a finer grid only interpolates between measured points: a user's map
        at 1 MPa, one contact spot of 10 of its 1 um pixels, was told nx >= 1707 on 256 um).

    Returns
    -------
    list of str
        At most one line.
    """
    c = np.asarray(contact, dtype=bool)
    if not c.any():
        if expected_size is None:
            return []
        spacing = (_spacing(x), _spacing(y))
        narrow = [f"{format_quantity(w, 'm', digits=3)} wide along {name} against cells of "
                  f"{format_quantity(d, 'm', digits=3)}"
                  for w, d, name in zip(expected_size, spacing, "xy", strict=True) if w < d]
        if not narrow:
            return []
        return ["mesh: no cell is in contact; the expected contact is " + " and ".join(narrow)
                + f" (limit {min_cells:g} cells per semi-axis): use more cells or a smaller "
                "x_extent/y_extent"]
    lines = []
    for axis, coord, name in ((0, x, "x"), (1, y, "y")):
        n = c.shape[axis]
        if n < 3:
            continue
        if np.all(c == c.take([0], axis=axis)):
            # the same at every position along the axis (a periodic strip): no semi-axis
            # along it to resolve
            continue
        cells = 0.5 * np.count_nonzero(c.any(axis=1 - axis))
        if cells < min_cells:
            need = math.ceil(n * min_cells / cells)
            measured = None if file_spacing is None or axis >= len(file_spacing) \
                else file_spacing[axis]
            if measured is not None and n * _spacing(coord) / need < measured * (1 - 1e-9):
                advice = (f"a finer grid than the file's points ({measured * 1e6:.3g} um "
                          "apart) only interpolates between them: the contact spans a few "
                          "measured points, so its size and pressures are as coarse as the "
                          "file; measure finer, or read them as the file's resolution allows")
            else:
                advice = f"use n{name} >= {need} on the same extent, or a smaller {name}_extent"
            lines.append(f"{cells:g} cell{'' if cells == 1 else 's'} per semi-axis along "
                         f"{name} (a semi-axis of about "
                         f"{format_quantity(cells * _spacing(coord), 'm', digits=3)}; "
                         f"n{name} = {n}; {advice})")
    if not lines:
        return []
    return ["mesh: the contact is resolved by " + " and ".join(lines) + f" (limit {min_cells:g}"
            " cells per semi-axis); pressures and contact size are then mesh-dependent"]


#: Cells of the spot at the load's median below which a rough contact's spots are reported
#: unresolved: in a refinement study of a rough ball (docs/tangential.md, "Contact spots") the
#: real area was 20 % too large at a median of 20 cells per spot and 9 % at 84, the error
#: falling as about 0.8 / sqrt(cells).
MIN_CELLS_PER_SPOT = 50.0


def spot_resolution(spots, x, y, min_cells: float = MIN_CELLS_PER_SPOT,
                    file_spacing=None, cutoff_key: str | None = None) -> list[str]:
    """A rough contact whose load is carried mostly by spots of a few cells.

    :func:`contact_resolution` judges the apparent contact; this judges its spots (the
    connected patches of the contact mask, :func:`asperity.contact.spots.contact_spots`). A
    spot's boundary cells count whole, so a spot of a few cells has too large an area and too
    low a mean pressure; the error falls as about ``0.8 / sqrt(cells)``.

    Parameters
    ----------
    spots : asperity.contact.spots.ContactSpots
        The contact's spots.
    x, y : ndarray
        Cell-centre coordinates, m.
    min_cells : float
        Fewest cells of the spot at the load's median.
    file_spacing : sequence of float, optional
        A measured file's sampling interval along x (and y), m: where the grid asked for is
        finer than the file's points, the line says that the file limits the answer.
    cutoff_key : str, optional
        The key of a generated surface's shortest wavelength when it was left to the grid
        (a self-affine surface without ``short_cutoff``): a finer grid then adds roughness
        too, and the line says to fix the wavelength before refining.

    Returns
    -------
    list of str
        At most one line.
    """
    median = spots.load_median_cells()
    if spots.count == 0 or not median < min_cells:
        return []
    factor = math.sqrt(min_cells / median)
    need = [(name, math.ceil(len(coord) * factor), len(coord) * _spacing(coord))
            for name, coord in (("x", x), ("y", y)) if len(coord) > 1]
    every = ""
    if file_spacing is not None:
        # a grid coarser than the file's points drops roughness: the spots' grid is then at
        # least the one that takes every point (a user was told nx >= 242 here and
        # nx >= 512 by the roughness line)
        points = [math.ceil(extent / h * (1 - 1e-9)) for (_, _, extent), h
                  in zip(need, file_spacing, strict=False)]
        if any(p > n for p, (_, n, _) in zip(points, need, strict=False)):
            every = ", which also takes every measured point"
            need = [(name, max(n, p), extent) for (name, n, extent), p
                    in zip(need, points + [0] * (len(need) - len(points)), strict=True)]
    advice = "use " + " and ".join(f"n{name} >= {n}" for name, n, _ in need) + \
        f" on the same extents{every}, and check that the real contact area no longer moves"
    if file_spacing is not None:
        coarse = [name for (name, n, extent), h in zip(need, file_spacing, strict=False)
                  if extent / n < h * (1 - 1e-9)]
        if coarse:
            advice = ("that grid would be finer than the measured file's points along "
                      f"{' and '.join(coarse)}: the file's sampling limits the spots' size, so "
                      "read the real contact area as an upper bound and the mean contact "
                      "pressure as a lower bound, or measure finer")
    if cutoff_key is not None:
        shortest = 2.0 * min(_spacing(x), _spacing(y))
        advice += (f"; the surface's shortest wavelength is the grid's (2 cells, "
                   f"{shortest * 1e6:.3g} um), so a finer grid adds roughness as well: give "
                   f"{cutoff_key} (e.g. {shortest * 1e6:.3g} um) to refine the same surface")
    share = spots.load_share_below(min_cells)
    estimate = 0.8 / math.sqrt(max(median, 1.0))
    p10, p50, p90 = spots.cell_percentiles()
    return [f"mesh: half the load is carried by contact spots of {median:g} cells or fewer "
            f"({spots.count} spot{'s' if spots.count != 1 else ''} of {p10:.3g}, {p50:.3g} "
            f"and {p90:.3g} cells at the 10th, 50th and 90th percentiles; {_pct(share)} of the "
            "load on spots under "
            f"{min_cells:g} cells; limit: {min_cells:g} cells at the load's median); a spot's "
            "edge cells count whole, so the real contact area is too large and the mean "
            f"contact pressure too low, by about {_pct(estimate)}; {advice}"]


def hardness_given(materials: Iterable) -> bool:
    """Whether every deformable body of ``materials`` (``(label, Material)`` pairs) gives a
    hardness, so that :func:`above_hardness` judges the pressure (a rigid body needs none)."""
    return all(getattr(m, "hardness", None) is not None for _, m in materials
               if not getattr(m, "rigid", False))


def above_hardness(pressure, materials: Iterable) -> list[str]:
    """Elastic pressures above the hardness of a body (when a material gives one).

    Parameters
    ----------
    pressure : ndarray
        Contact pressure, Pa.
    materials : iterable of (label, Material)
        The bodies, e.g. ``[("body1", m1), ("body2", m2)]``; those without ``hardness`` are
        skipped.

    Returns
    -------
    list of str
        One line per hardness exceeded (bodies of the same material and hardness share it).
    """
    p = np.asarray(pressure, dtype=float)
    in_contact = np.count_nonzero(p > 0)
    if not in_contact:
        return []
    p_max = float(p.max())
    exceeded: dict = {}  # bodies of one material and hardness share a line
    for label, material in materials:
        hardness = getattr(material, "hardness", None)
        if hardness is None or p_max <= hardness:
            continue
        exceeded.setdefault((hardness, material.name), []).append(label)
    lines = []
    for (hardness, name), labels in exceeded.items():
        share = np.count_nonzero(p > hardness) / in_contact
        lines.append(f"pressure: the maximum {p_max / 1e9:.4g} GPa exceeds the hardness of "
                     f"{' and '.join(labels)} ({name}) on {_pct(share)} of the contact area "
                     f"(limit: the hardness, {hardness / 1e9:.4g} GPa); the elastic answer is "
                     "not physical there (the body yields): lower the load, or treat the "
                     "result as an elastic bound")
    return lines


def steps_above_hardness(max_pressure, warmup_steps: int, materials: Iterable) -> list[str]:
    """Counting steps of a transient run whose largest pressure exceeds the hardness of a body.

    A transient mixed-EHL run's asperity contacts are elastic; the last step's pressure field
    (:func:`above_hardness`) tells nothing of the steps before it. The counting steps are
    judged, as the run's reported maximum pressure is taken over them.

    Parameters
    ----------
    max_pressure : ndarray
        Largest pressure of each step done, Pa (NaN for a step that diverged).
    warmup_steps : int
        Steps before counting.
    materials : iterable of (label, Material)
        The bodies; those without ``hardness`` are skipped.

    Returns
    -------
    list of str
        One line per hardness exceeded (bodies of the same material and hardness share it).
    """
    counted = np.asarray(max_pressure, dtype=float)[warmup_steps:]
    if not np.isfinite(counted).any():
        return []
    step = int(np.nanargmax(counted))
    p_max = float(counted[step])
    exceeded: dict = {}
    for label, material in materials:
        hardness = getattr(material, "hardness", None)
        if hardness is not None and p_max > hardness:
            exceeded.setdefault((hardness, material.name), []).append(label)
    lines = []
    for (hardness, name), labels in exceeded.items():
        share = np.count_nonzero(counted > hardness) / counted.size
        lines.append(f"pressure: the largest pressure of the counting steps, {p_max / 1e9:.4g} "
                     f"GPa (step {warmup_steps + step + 1}), exceeds the hardness of "
                     f"{' and '.join(labels)} ({name}), as the largest pressure does in "
                     f"{_pct(share)} of the counting steps (limit: the hardness, "
                     f"{hardness / 1e9:.4g} GPa); the asperity contacts are elastic, so the "
                     "body yields there and the contact pressures are elastic bounds: lower "
                     "the load or the roughness, or read them so")
    return lines


def asperity_plasticity_note(p_max: float, e_star: float, bodies) -> list[str]:
    """A note for a rough contact whose largest pressure exceeds ``HERTZ_STRAIN_LIMIT`` E*
    with no hardness given: its asperities would yield, which nothing checked.

    A note, not a warning: the elastic answer is what such a case asks for, and nearly every
    elastic rough contact's asperities are that loaded (about E* Sdq / 2). A user's rough
    flat reported asperity pressures of 10-29 GPa (0.09-0.25 E*) between steel bodies without
    a word, and a gear flank's transient mixed-EHL run 13 GPa (0.12 E*). An elastomer (E below
    ``ELASTOMER_MODULUS``) does not yield and gets none.

    Parameters
    ----------
    p_max : float
        Largest contact pressure, Pa.
    e_star : float
        Contact modulus, Pa.
    bodies : iterable of (label, Material)
        The bodies.

    Returns
    -------
    list of str
        At most one note.
    """
    bodies = list(bodies)
    _, rubber = _soft_bodies(bodies)
    if rubber or hardness_given(bodies) or not p_max > HERTZ_STRAIN_LIMIT * e_star:
        return []
    return [f"The largest pressure, {p_max / 1e9:.4g} GPa, is {p_max / e_star:.3g} E* (E* = "
            f"{e_star / 1e9:.4g} GPa): asperities yield at such pressures and plasticity was "
            "not checked (no hardness given); give body1.hardness and body2.hardness to see "
            "where, or read the pressures and the real contact area as elastic bounds."]


def ehl_inlet(pressure, x, a: float, p_hertz: float,
              flooded_distance: float | None = None) -> list[str]:
    """Pressure not back to ambient near the inlet boundary: a starved, too thin film.

    Parameters
    ----------
    pressure : ndarray, shape (nx, ny)
        Film pressure on the nodes, Pa (x first, the entrainment direction).
    x : ndarray
        Node coordinates along x, m (the inlet at ``x[0]``).
    a : float
        Hertz semi-axis along x, m.
    p_hertz : float
        Hertz pressure, Pa.
    flooded_distance : float, optional
        A point contact's fully flooded inlet distance ``m*`` in semi-axes
        (:func:`flooded_inlet_distance_of`): the advised inlet reaches it too, so that the
        inlet-length line does not ask again (an MTM ball told -2.5 a was then told that
        m* = 2.8 a).

    Returns
    -------
    list of str
        At most one line.
    """
    x = np.asarray(x, dtype=float)
    near = x <= x[0] + BOUNDARY_BAND * a
    near[0:2] = True
    level = float(np.max(np.asarray(pressure, dtype=float)[near])) / p_hertz
    if level <= BOUNDARY_PRESSURE:
        return []
    x_min = x[0] / a
    use = min(-2.5, math.floor(2 * (x_min - 1.0)) / 2)
    if flooded_distance is not None and math.isfinite(flooded_distance):
        use = min(use, -math.ceil(2.0 * flooded_distance) / 2.0)
    return [DomainAdvice(
        f"inlet: x_min = {x_min:.3g} a leaves pressure {_pct(level)} of p_h within "
        f"{BOUNDARY_BAND:g} a of the inlet boundary (limit {_pct(BOUNDARY_PRESSURE)}); the "
        f"inlet is too short, the film starved and too thin; use x_min <= {use:g} a",
        x_min=use * a)]


def ehl_inlet_length(x_min: float, a: float, rx: float, central_film: float, *,
                     solved: bool = True, probe=None) -> list[str]:
    """An inlet shorter than the fully flooded inlet distance of a point contact.

    Hamrock & Dowson (1977, starvation) put the boundary between fully flooded and starved
    conditions at the dimensionless inlet distance ``m* = 1 + 3.06 ((Rx/a)^2 hc/Rx)^0.58``
    (distances from the contact centre in semi-axes along the entrainment direction, ``hc``
    the fully flooded central film), and the starved central film at
    ``hc ((m - 1)/(m* - 1))^0.29`` for an inlet at ``m < m*``. The p = 0 boundary at
    ``x_min`` is such a meniscus. The fit is short of the solver's loss at high load: a 6206
    bearing's contact (M = 1950) with the inlet at -1.5 a loses 9.6 % of its central film
    against -2.5 a where the fit says 5.5 %; so the line gives the measured loss too where an
    inlet probe has measured it.

    Parameters
    ----------
    x_min : float
        Inlet boundary, m (negative: upstream of the contact centre).
    a : float
        Hertz semi-axis along the entrainment direction, m.
    rx : float
        Reduced radius along the entrainment direction, m.
    central_film : float
        Central film, m: of the solve on this inlet (``solved``, starved by it: the flooded
        film the fit needs is found by inverting the fit,
        :func:`asperity.ehl.formulas.flooded_film`), or a fully flooded estimate.
    solved : bool
        Whether ``central_film`` is the solve's on this inlet.
    probe : asperity.ehl.sides.InletProbe, optional
        Steady solves with this inlet and a longer one; their central (and, where both keep
        it open, minimum) films are quoted when both converged.

    Returns
    -------
    list of str
        At most one line, when the fit's film loss exceeds :data:`STARVED_FILM_LOSS`.
    """
    m = -x_min / a
    film = _flooded_central_film(x_min, a, rx, central_film, solved)
    if film is None:
        return []
    m_star = flooded_inlet_distance(film)
    loss = 1.0 - starved_film_ratio(film, m)
    if loss <= STARVED_FILM_LOSS:
        return []
    use = max(2.5, math.ceil(2.0 * m_star) / 2.0)
    line = (f"inlet: x_min = {-m:.3g} a is inside the fully flooded inlet distance m* = "
            f"{m_star:.3g} a (Hamrock & Dowson 1977, m* = 1 + 3.06 ((Rx/a)^2 hc/Rx)^0.58 with "
            f"the flooded hc); their starvation fit puts the central film {_pct(loss)} below "
            f"the flooded one (limit {_pct(STARVED_FILM_LOSS)})")
    if probe is not None and probe.converged and min(probe.central_film) > 0.0:
        losses = [("central film", -probe.central_film_change)]
        if min(probe.minimum_film) > 0.0:
            losses.append(("minimum film", -probe.minimum_film_change))
        nodes = " x ".join(str(n) for n in probe.nodes if n > 1)
        line += (f"; solved on {nodes} nodes with the inlet here and at "
                 f"{probe.long_x_min / a:.3g} a, the "
                 + " and the ".join(f"{name} is {_pct(d)} below" for name, d in losses)
                 + (" (the fit is short of the solver's loss here)"
                    if -probe.central_film_change > loss else ""))
    return [DomainAdvice(line + f"; use x_min <= -{use:g} a", x_min=-use * a)]


def flooded_inlet_distance_of(x_min: float, a: float, rx: float, central_film: float,
                              solved: bool = True) -> float:
    """Hamrock & Dowson's fully flooded inlet distance ``m*`` (semi-axes) of a point contact
    whose inlet is at ``x_min`` and central film ``central_film`` (m; with ``solved`` the
    solve's own on this inlet, whose flooded film is found by inverting the starvation fit,
    as :func:`ehl_inlet_length` does); NaN where no film or an inlet inside the contact
    leaves it unknown."""
    film = _flooded_central_film(x_min, a, rx, central_film, solved)
    return float("nan") if film is None else flooded_inlet_distance(film)


def _flooded_central_film(x_min, a, rx, central_film, solved):
    """The fully flooded central film in Hamrock & Dowson's units ``(Rx/a)^2 hc/Rx`` (with
    ``solved``, inverted from the starved film of an inlet at ``x_min``), or None."""
    m = -x_min / a
    if not (central_film > 0 and m > 1):
        return None
    film = (rx / a) ** 2 * central_film / rx
    return flooded_film(film, m) if solved else film


def ehl_inlet_film(probe, a: float) -> list[str]:
    """Film moved by the inlet boundary: the steady solves of an inlet probe differ by more
    than ``STARVED_FILM_LOSS`` in the central or the minimum film.

    Hamrock & Dowson's fit (:func:`ehl_inlet_length`) can say the inlet is long enough where
    it is not: a 6205 ball bearing's contact at M = 18,100 lost 5.4 % of its central film
    with the inlet at -1.3 a, where the fit's fully flooded distance is 1.26 a.

    Parameters
    ----------
    probe : asperity.ehl.sides.InletProbe
        The steady film on the case's domain and on one with the inlet moved upstream.
    a : float
        Hertz semi-axis along x, m.

    Returns
    -------
    list of str
        At most one line; none when either solve of the probe did not converge or closed the
        central film. A minimum film closed in either solve (the coarse probe mesh can close
        the side lobes) is left out of the comparison.
    """
    if not probe.converged or min(probe.central_film) <= 0.0:
        return []
    changes = [("central film", probe.central_film_change)]
    if min(probe.minimum_film) > 0.0:
        changes.append(("minimum film", probe.minimum_film_change))
    if all(abs(d) <= STARVED_FILM_LOSS for _, d in changes):
        return []
    moved = " and the ".join(f"{name} is {_pct(abs(d) / (1.0 + d))} "
                             f"{'higher' if d < 0 else 'lower'}" for name, d in changes)
    nodes = " x ".join(str(n) for n in probe.nodes if n > 1)  # one across a line contact
    return [DomainAdvice(
        f"inlet: the inlet at x = {probe.x_min / a:.3g} a changes the film: with it at "
        f"{probe.long_x_min / a:.3g} a the {moved} (steady smooth solutions on "
        f"{nodes} nodes; limit {_pct(STARVED_FILM_LOSS)}); the "
        f"inlet starves the film; use x_min <= {probe.long_x_min / a:.3g} a",
        x_min=probe.long_x_min)]


#: Peak film pressure, as a share of the Hertz pressure, below which a contact's mesh is judged
#: on ``sqrt(2 Rx hc)`` rather than on the Hertz zone (:func:`ehl_rigid_domain`).
RIGID_PRESSURE = 0.1
#: ``sqrt(2 Rx hc)``, in Hertz semi-axes a, from which a contact counts as nearly rigid for
#: :func:`ehl_rigid_domain`: its pressure spreads past the Hertz zone (``hc Rx/a^2 >= 2``).
RIGID_LENGTH = 2.0
#: A rigid ball's load on a square domain of half-width S (in ``sqrt(2 Rx h0)``) is
#: ``1 - RIGID_REACH / S`` of the unbounded one (projected SOR of its Reynolds equation at
#: S = 8, 16, 32: 0.800, 0.899, 0.950; docs/ehl-robustness.md, "A nearly rigid contact").
RIGID_REACH = 1.6
#: A rigid cylinder's load (and film, ``h ~ 1/w'``) with the inlet S upstream is
#: ``1 - RIGID_REACH_LINE / S^2`` of the unbounded (Martin's): 0.963, 0.991, 0.998 at
#: S = 8, 16, 32 by the Swift-Stieber solution integrated here.
RIGID_REACH_LINE = 2.44
#: Film a nearly rigid contact's domain may cost (its estimate) before it is reported.
RIGID_FILM_LOSS = 0.05
#: Outlet, in ``sqrt(2 Rx h0)``, short of which a rigid contact's exit is cut (a ball's load
#: 0.36 % short with the outlet at 0.5, 3.7 % at 0.21; a cylinder's, whose exit lies at
#: 0.475, 0.5 % at 0.4 and 2.6 % at 0.3).
RIGID_OUTLET = 0.5
#: Largest mesh spacing, in ``sqrt(2 Rx h0)``, for a contact whose peak pressure is below
#: ``RIGID_PRESSURE`` p_h; the Hertz-zone mesh checks do not apply to it. A glass ball in
#: glycerol on -8 l..1 l, +-8 l: film 5.8 % thin on l/4, 1.4 % on l/8, 0.25 % on l/16, against
#: the rigid ball's Reynolds equation solved independently (docs/ehl-robustness.md): about
#: 3.6 % at l/5 by the second-order scaling, within the 5 % of the other film-mesh checks.
RIGID_SPACING = 0.2


#: Factor on the domain a nearly rigid contact is advised (:func:`ehl_rigid_domain`): its
#: film grows on the larger domain, and with it ``l = sqrt(2 Rx hc)``.
RIGID_MARGIN = 1.1


def ehl_rigid_domain(pressure, x, y, rx: float, central_film: float, p_hertz: float,
                     a: float, b: float | None, max_bound: float = 100.0,
                     rigid_row: str | None = None) -> list[str]:
    """A nearly rigid contact on a domain too small for its slowly decaying pressure.

    Where ``l = sqrt(2 Rx hc)`` exceeds :data:`RIGID_LENGTH` Hertz semi-axes the contact is
    hydrodynamic rather than elastohydrodynamic: the pressure spreads over ``l``, not the
    Hertz zone, and falls off only slowly beyond it (as ``1/r^3`` for a ball, ``1/x^3`` for a
    cylinder), so the load a bounded domain carries, and with it the film, depends on how far
    the domain reaches. A rigid ball's load on a square domain of half-width S l is
    ``1 - 1.6/S`` of the unbounded one, its film (``h ~ w^-2``) ``(1 - 1.6/S)^2``, the
    estimate here with S the nearer of the inlet and the sides; a rigid cylinder's film with
    the inlet S l upstream ``1 - 2.44/S^2`` of Martin's. A 1/2 in ball at 4 N in a 1 Pa s
    isoviscous oil (Moes M = 0.8) on -58 a..8 a, +-29.6 b (S = 4.1 l at the sides, 8.1 l at
    the inlet) gave 9.59 um, 53 % of the unbounded 18.0 um, with no warning: the boundary
    pressure checks compare with p_h, and the pressure there is 1e-3 of the peak. A roller
    (R = 10 mm, 20 kN/m, M = 0.29) on its default -26.5 a..1.5 a (5.8 l, outlet 0.33 l)
    gave 2.28 um, 6.8 % under Martin's 2.45 um.

    Parameters
    ----------
    pressure : ndarray, shape (nx, ny)
        Film pressure, Pa.
    x, y : ndarray
        Node coordinates, m (``y = [0.]`` for a line contact).
    rx : float
        Radius of relative curvature along x, m.
    central_film : float
        Central film, m.
    p_hertz, a : float
        Hertz pressure (Pa) and semi-axis along x (m).
    b : float or None
        Hertz semi-axis along y, m; None for a line contact.
    max_bound : float
        The farthest domain bound a case takes, in semi-axes (``cases.ehl.MAX_BOUND``): the
        advice stays within it.
    rigid_row : str, optional
        The comparison row that gives the film of an unbounded rigid-isoviscous contact
        (Martin's, Brewe-Hamrock-Taylor's), offered instead of a larger domain; None where the
        run shows none (a piezoviscous-rigid contact, which was told to "take the
        rigid-isoviscous film of the comparison rows" there were none of).

    Returns
    -------
    list of str
        A ``mesh:`` line where the peak pressure is below :data:`RIGID_PRESSURE` p_h and a
        spacing exceeds :data:`RIGID_SPACING` l, and a ``domain:`` line where the estimated
        loss exceeds :data:`RIGID_FILM_LOSS` or the outlet lies short of :data:`RIGID_OUTLET`
        l.
    """
    if not central_film > 0.0:
        return []
    length = math.sqrt(2.0 * rx * central_film)
    if length < RIGID_LENGTH * a:
        return []
    line = b is None
    p_max = float(np.max(pressure))
    spacing = (_spacing(x) if line else max(_spacing(x), _spacing(y))) / length
    lines = [] if spacing <= RIGID_SPACING or p_max >= RIGID_PRESSURE * p_hertz else [
        f"mesh: the contact is nearly rigid (peak pressure {_pct(p_max / p_hertz)} of p_h) and "
        f"its pressure varies over l = sqrt(2 Rx hc) = {length / a:.3g} a, not the Hertz zone; "
        f"the spacing {spacing:.2g} l is coarser than {RIGID_SPACING:g} l (a rigid ball's film "
        f"is 5.8 % thin on l/4, 1.4 % on l/8): use dx <= {RIGID_SPACING * length / a:.3g} a"
        + ("" if line else f" and dy <= {RIGID_SPACING * length / b:.3g} b")]
    if line:
        reach = -float(x[0]) / length
        share = max(0.0, 1.0 - RIGID_REACH_LINE / reach**2)
        need = math.sqrt(RIGID_REACH_LINE / RIGID_FILM_LOSS) * length
        body, law = "cylinder with the inlet S l upstream", "(1 - 2.44/S^2) of its film"
    else:
        reach = min(-float(x[0]), -float(y[0]), float(y[-1])) / length
        share = max(0.0, 1.0 - RIGID_REACH / reach) ** 2
        need = RIGID_REACH / (1.0 - math.sqrt(1.0 - RIGID_FILM_LOSS)) * length
        body = "ball on a square domain of half-width S l"
        law = "(1 - 1.6/S)^2 of its film"
    outlet = float(x[-1]) / length
    if share >= 1.0 - RIGID_FILM_LOSS and outlet >= RIGID_OUTLET:
        return lines
    text = (f"domain: the contact is nearly rigid (l = sqrt(2 Rx hc) = {length / a:.3g} a, more "
            f"than {RIGID_LENGTH:g} a; peak pressure {_pct(p_max / p_hertz)} of p_h): its "
            "pressure spreads over l, not the Hertz zone, and falls off slowly beyond it; the "
            f"domain reaches {reach:.3g} l ({'inlet' if line else 'inlet or sides'}), where a "
            f"rigid {body} has {law}: {_pct(share)} (limit {_pct(1.0 - RIGID_FILM_LOSS)})"
            + (f", and its outlet at {outlet:.2g} l cuts the pressure short of its exit"
               if outlet < RIGID_OUTLET else ""))
    # advised with RIGID_MARGIN: on the larger domain the film, and with it l, grows (a
    # roller told x_min <= -22.7 was, on it, told -22.8)
    need *= RIGID_MARGIN
    x_max = max(RIGID_MARGIN * RIGID_OUTLET * length, float(x[-1])) / a
    sides = "" if line else f", y_min <= {-need / b:.3g}, y_max >= {need / b:.3g}"
    if need <= max_bound * (a if line else min(a, b)):
        advised = {"x_min": -need, "x_max": x_max * a} | (
            {} if line else {"y_min": -need, "y_max": need})
        advice = (f"for 5 % set x_min <= {-need / a:.3g}{sides}, x_max >= {x_max:.3g} (a coarse "
                  "mesh serves: the pressure varies over l)"
                  + (f", or take the {rigid_row} row, an unbounded domain's" if rigid_row
                     else ""))
    else:
        widest = max_bound * (a if line else min(a, b)) / length
        advised = {"x_min": -max_bound * a, "x_max": x_max * a} | (
            {} if line else {"y_min": -max_bound * b, "y_max": max_bound * b})
        kept = (1.0 - RIGID_REACH_LINE / widest**2 if line
                else (1.0 - RIGID_REACH / widest) ** 2)
        bounds = "x_min" if line else "x_min, y_min, y_max"
        at = f"-{max_bound:g}" if line else f"-{max_bound:g}, -{max_bound:g}, {max_bound:g}"
        beyond = f"5 % needs {need / a:.3g} a, beyond the {max_bound:g} semi-axes a case takes"
        instead = (f"take the {rigid_row} row, an unbounded domain's" if rigid_row else
                   f"read the film as about {_pct(1.0 - share)} low")
        if reach >= widest * (1.0 - 1e-6) and outlet >= RIGID_OUTLET:  # already there
            advice = f"{beyond}, which this domain reaches: {instead}"
        else:
            advice = (f"{beyond}, where the film would be {_pct(kept)} of it: set {bounds} at "
                      f"{at} and x_max >= {x_max:.3g}, on a coarse mesh, for that share"
                      + (f", or take the {rigid_row} row, an unbounded domain's" if rigid_row
                         else ""))
    return [*lines, DomainAdvice(f"{text}; {advice}", **advised)]


def ehl_film_collapse(film, estimate: float | None = None, zone=None) -> list[str]:
    """A film at or below zero in a smooth steady contact, or one that has collapsed over
    part of the Hertz zone: below what the solve resolves.

    A collapsed film sits on its floor, not on a thin lobe: on probe case 12 (seed 40, steel
    on steel, k = 0.82, M = 1110, default mesh 513 x 41) 12.6 % of the Hertz area is below
    1 % of Chittenden's central film and 13.0 % below 10 % of it, the nodes at 3e-5 of it; the
    thin lobes of cases 15 and 27 (M 42 and 38) keep 7-11 % of it and pass. Such a film had
    been reported as a minimum film the mesh does not resolve only.

    Parameters
    ----------
    film : ndarray
        Film thickness on the nodes, m.
    estimate : float, optional
        A film-formula estimate of the central film, m, for the message and (with ``zone``)
        the collapse: nodes of the zone below ``COLLAPSED_FILM`` of it.
    zone : ndarray of bool, optional
        The nodes inside the Hertz contact, shape of ``film``.

    Returns
    -------
    list of str
        At most one line.
    """
    h = np.asarray(film, dtype=float)
    h_min = float(np.min(h))
    known = estimate is not None and estimate > 0
    expected = f"; the film formulas expect about {estimate * 1e9:.3g} nm" if known else ""
    if h_min <= 0:
        return [f"film: the film is {h_min * 1e9:.3g} nm at its thinnest, <= 0 on "
                f"{int(np.count_nonzero(h <= 0))} nodes (limit: > 0 in a smooth steady "
                f"contact){expected}; the solution has collapsed below what the mesh and "
                "tolerance resolve: refine the mesh (cells_per_a), lower solver.tolerance, or "
                "check the speeds and viscosity"]
    if not known or zone is None or not np.any(zone):
        return []
    collapsed = np.count_nonzero(zone & (h < COLLAPSED_FILM * estimate))
    if not collapsed:
        return []
    return [f"film: the film has collapsed on {_pct(collapsed / np.count_nonzero(zone))} of "
            f"the Hertz area, below {_pct(COLLAPSED_FILM)} of the film formulas' "
            f"{estimate * 1e9:.3g} nm there ({h_min * 1e9:.3g} nm at its thinnest; limit: "
            f"no node of the Hertz zone below {_pct(COLLAPSED_FILM)} of it in a smooth steady "
            "contact); a film the mesh does not carry, most often side lobes on too few "
            "nodes across y: the minimum film and the friction are not trustworthy; refine "
            "the mesh (a mesh: line says where), or check the speeds and viscosity"]


def side_pressure(pressure, y, b: float) -> float:
    """Largest pressure within ``BOUNDARY_BAND`` b of a side boundary (and on the two nodes
    next to each side), Pa.

    Parameters
    ----------
    pressure : ndarray, shape (nx, ny)
        Film pressure on the nodes, Pa.
    y : ndarray
        Node coordinates across the entrainment direction (at least 3), m.
    b : float
        Hertz semi-axis along y, m.
    """
    y = np.asarray(y, dtype=float)
    near = (y <= y[0] + BOUNDARY_BAND * b) | (y >= y[-1] - BOUNDARY_BAND * b)
    near[[0, 1, -2, -1]] = True
    return float(np.max(np.asarray(pressure, dtype=float)[:, near]))


def _probe_changes(probe) -> tuple[float, float] | None:
    """The minimum and central film changes of a side or domain probe, or None where either
    solve did not converge or closed the film, or neither change exceeds its limit
    (``SIDE_FILM_CHANGE``, ``SIDE_CENTRAL_CHANGE``)."""
    if not probe.converged or min(*probe.minimum_film, *probe.central_film) <= 0.0:
        return None
    dmin, dcen = probe.minimum_film_change, probe.central_film_change
    if abs(dmin) <= SIDE_FILM_CHANGE and abs(dcen) <= SIDE_CENTRAL_CHANGE:
        return None
    return dmin, dcen


def ehl_side_film(probe, b: float) -> list[str]:
    """Film moved by the side boundaries: the steady solves of a side probe differ by more than
    ``SIDE_FILM_CHANGE`` in the minimum film or ``SIDE_CENTRAL_CHANGE`` in the central film.

    Parameters
    ----------
    probe : asperity.ehl.sides.SideProbe
        The steady film on the case's domain and on one with the sides moved out.
    b : float
        Hertz semi-axis along y, m.

    Returns
    -------
    list of str
        At most one line; none when either solve of the probe did not converge or closed the
        film (the side pressure check still applies).
    """
    changes = _probe_changes(probe)
    if changes is None:
        return []
    dmin, dcen = changes
    (y0, y1), (w0, w1) = probe.y_bounds, probe.wide_y_bounds
    return [DomainAdvice(
            f"sides: the side boundaries at y = {y0 / b:.3g} b and {y1 / b:.3g} b change the "
            f"film: with them at {w0 / b:.3g} b and {w1 / b:.3g} b the minimum film is "
            f"{_pct(abs(dmin) / (1.0 + dmin))} {'higher' if dmin < 0 else 'lower'} and the central "
            f"film {_pct(abs(dcen) / (1.0 + dcen))} {'higher' if dcen < 0 else 'lower'} "
            f"(steady smooth solutions on {probe.nodes[0]} x {probe.nodes[1]} nodes; limits "
            f"{_pct(SIDE_FILM_CHANGE)} and {_pct(SIDE_CENTRAL_CHANGE)}); the side leakage is "
            f"cut off; use y_min <= {w0 / b:.2g} b and y_max >= {w1 / b:.2g} b",
            y_min=float(f"{w0 / b:.2g}") * b, y_max=float(f"{w1 / b:.2g}") * b)]


def ehl_domain_film(probe, a: float, b: float) -> list[str]:
    """Film moved by the inlet and the sides together: the steady solves of a domain probe
    differ by more than ``SIDE_FILM_CHANGE`` in the minimum film or ``SIDE_CENTRAL_CHANGE`` in
    the central film (the side probe's limits).

    Parameters
    ----------
    probe : asperity.ehl.sides.DomainProbe
        The steady film on the case's domain and on one with the inlet and sides moved out.
    a, b : float
        Hertz semi-axes along x and y, m.

    Returns
    -------
    list of str
        At most one line; none when either solve did not converge or closed the film.
    """
    changes = _probe_changes(probe)
    if changes is None:
        return []
    dmin, dcen = changes
    (y0, y1), (w0, w1) = probe.y_bounds, probe.wide_y_bounds
    x_min = float(f"{probe.long_x_min / a:.3g}") * a
    return [DomainAdvice(
            f"domain: the inlet at x = {probe.x_min / a:.3g} a and the sides at y = "
            f"{y0 / b:.3g} b and {y1 / b:.3g} b together change the film: with the inlet at "
            f"{probe.long_x_min / a:.3g} a and the sides at {w0 / b:.3g} b and {w1 / b:.3g} b "
            f"the central film is {_pct(abs(dcen) / (1.0 + dcen))} "
            f"{'higher' if dcen < 0 else 'lower'} and the minimum film "
            f"{_pct(abs(dmin) / (1.0 + dmin))} {'higher' if dmin < 0 else 'lower'} (steady "
            f"smooth solutions on {probe.nodes[0]} x {probe.nodes[1]} nodes; limits "
            f"{_pct(SIDE_CENTRAL_CHANGE)} and {_pct(SIDE_FILM_CHANGE)}): the pressure of this "
            "thick film reaches far beyond the contact; take x_min, y_min and y_max out "
            f"together until the film settles (at least x_min <= {probe.long_x_min / a:.3g} a, "
            f"y_min <= {w0 / b:.2g} b, y_max >= {w1 / b:.2g} b), or read the film as a "
            "lower bound", x_min=x_min, y_min=float(f"{w0 / b:.2g}") * b,
            y_max=float(f"{w1 / b:.2g}") * b)]


def newtonian_traction(mu: float, newtonian: bool) -> list[str]:
    """A Newtonian film's friction coefficient above ``NEWTONIAN_TRACTION_LIMIT``.

    The wall shear stress of a Newtonian film, ``eta du / h``, grows with the viscosity
    without bound, and at EHL pressures the viscosity is raised by orders of magnitude: the
    friction coefficient is then not a traction. The Eyring law (``lubricant.tau0``) limits
    it (:func:`asperity.ehl.friction_coefficient`).

    Parameters
    ----------
    mu : float
        Friction coefficient of the solution.
    newtonian : bool
        Whether the lubricant is Newtonian (no Eyring stress).

    Returns
    -------
    list of str
        At most one line.
    """
    if not newtonian or not abs(mu) > NEWTONIAN_TRACTION_LIMIT:
        return []
    return [f"lubricant.tau0: the friction coefficient {abs(mu):.3g} is that of a Newtonian "
            "film, whose shear stress eta du/h grows without bound with the pressure-raised "
            f"viscosity; it is more than a dry contact's {NEWTONIAN_TRACTION_LIMIT:g} and not a "
            "traction. Set lubricant.tau0 (the Eyring stress; the seed's gear oil has 10 MPa) "
            "for the traction coefficient"]


def friction_undefined(mu: float, peak_viscosity: float, peak_pressure: float) -> list[str]:
    """A converged film whose friction coefficient is not a number.

    Where the viscosity law overflows (``eta = inf`` beyond about 1e308 Pa s: a
    pressure-viscosity coefficient of several hundred 1/GPa at 1 GPa), the wall shear stress
    there is unbounded, even with the Eyring law, and the friction coefficient undefined.

    Parameters
    ----------
    mu : float
        Friction coefficient of the solution (NaN or inf for this line).
    peak_viscosity : float
        Viscosity at the largest pressure, Pa s.
    peak_pressure : float
        The largest pressure, Pa.

    Returns
    -------
    list of str
        At most one line.
    """
    if np.isfinite(mu):
        return []
    why = (f"the viscosity law overflows at the pressure peak (eta = {peak_viscosity:g} Pa s "
           f"at {format_quantity(peak_pressure, 'Pa', digits=3)}), where the shear stress is "
           "then unbounded" if not np.isfinite(peak_viscosity)
           else "the shear stress is not finite at every node")
    return [f"lubricant.alpha: the friction coefficient is undefined: {why}; check the "
            "pressure-viscosity coefficient (oils: 5-50 1/GPa) and the viscosity law"]


def ehl_sides(pressure, y, b: float, p_hertz: float) -> list[str]:
    """Pressure at the side boundaries of a point contact: side leakage cut off.

    Parameters
    ----------
    pressure : ndarray, shape (nx, ny)
        Film pressure on the nodes, Pa.
    y : ndarray
        Node coordinates across the entrainment direction, m.
    b : float
        Hertz semi-axis along y, m.
    p_hertz : float
        Hertz pressure, Pa.

    Returns
    -------
    list of str
        At most one line.
    """
    y = np.asarray(y, dtype=float)
    if y.size < 3:
        return []
    level = side_pressure(pressure, y, b) / p_hertz
    if level <= BOUNDARY_PRESSURE:
        return []
    reach = max(abs(y[0]), abs(y[-1])) / b
    use = max(2.0, math.ceil(2 * (reach + 0.5)) / 2)
    return [DomainAdvice(
        f"sides: the side boundaries at y = {y[0] / b:.3g} b and {y[-1] / b:.3g} b leave "
        f"pressure {_pct(level)} of p_h within {BOUNDARY_BAND:g} b of them (limit "
        f"{_pct(BOUNDARY_PRESSURE)}); the side leakage is cut off; use y_min <= -{use:g} b "
        f"and y_max >= {use:g} b", y_min=-use * b, y_max=use * b)]


def ehl_film_mesh(x, a: float, film: float, domain=None) -> list[str]:
    """A mesh along x too coarse for the film: the central film's discretisation error,
    estimated by the rule of the default mesh (:meth:`asperity.ehl.problem.PointContact.
    cells_per_a`: ``FILM_ERROR dX^2 / H_c``, second order, ``dX`` in a), above
    ``FILM_MESH_ERROR``.

    The rule was measured on a Newtonian circle at M = 1000 (-17 % at a/32); with the film
    formula's film, on two Roelands + Dowson-Higginson balls (M 138 and 313) and the gear
    case the error was 0.46-0.57 of the estimate (docs/ehl-robustness.md, "A mesh too coarse
    for the film"), so the line gives it as an upper estimate.

    Parameters
    ----------
    x : ndarray
        Node coordinates along the entrainment direction, m.
    a : float
        Hertz semi-axis along x, m.
    film : float
        Central film in Hertzian units, ``H_c = h_c Rx / a^2``.
    domain : ((float, float), (float, float)), optional
        Domain (m) on which the advised ``nx`` is counted, where it reaches beyond ``x``: the
        one the run's other lines advise (:func:`advised_domain`).

    Returns
    -------
    list of str
        At most one line.
    """
    x = np.asarray(x, dtype=float)
    if x.size < 2 or not film > 0.0:
        return []
    dx = _spacing(x) / a
    error = FILM_ERROR * dx**2 / film
    if error <= FILM_MESH_ERROR:
        return []
    cells = math.ceil(math.sqrt(FILM_ERROR / (MESH_TARGET * film)))
    span, where = _span(x, None if domain is None else domain[0], a, "a")
    need = math.ceil(round(span / a * cells, 6)) + 1
    return [f"mesh: dx = a/{1.0 / dx:.3g} for a central film H_c = {film:.3g} (h_c Rx/a^2) "
            f"gives an estimated discretisation error of the central film of "
            f"{'up to ' + _pct(error) if error < 1.0 else 'more than 100 %'} "
            f"({FILM_ERROR:g} dx^2/H_c, second order; limit "
            f"{_pct(FILM_MESH_ERROR)}); use nx >= {need}{where} (cells_per_a >= {cells}) for about "
            f"{_pct(MESH_TARGET)}"]


def minimum_film_curvature(film, direction: str) -> tuple[float, float] | None:
    """The relative second difference of the film at the node of its least value, and the
    discretisation error of that minimum it gives (:func:`ehl_minimum_film_mesh`).

    ``s = (h[k-1] + h[k+1]) / (2 h[k]) - 1`` across y (``direction = "y"``) or along x
    (``"x"``), the error estimated as ``MIN_FILM_ERROR_PER_CURVATURE s``; ``s`` is infinite
    for a least film of zero.

    Parameters
    ----------
    film : ndarray
        Film thickness, shape (nx, ny) or (nx,), m.
    direction : {"y", "x"}

    Returns
    -------
    (float, float) or None
        ``(s, error)``; None where the least film lies on a boundary node in that direction
        or there are fewer than 3 nodes.
    """
    film = np.asarray(film, dtype=float)
    if film.ndim == 1:
        film = film[:, None]
    i, j = np.unravel_index(np.argmin(film), film.shape)
    line, k = (film[i, :], j) if direction == "y" else (film[:, j], i)
    if line.size < 3 or k in (0, line.size - 1):
        return None
    h = film[i, j]
    thicker = (line[k - 1] + line[k + 1]) / (2.0 * h) - 1.0 if h > 0.0 else np.inf
    return thicker, MIN_FILM_ERROR_PER_CURVATURE * thicker


def ehl_minimum_film_mesh(film, x, y, a: float, b: float | None, domain=None, *,
                          cell_aspect: float = MIN_CELL_ASPECT,
                          max_ny: int | None = None,
                          max_nodes: tuple[int, int, int] | None = None) -> list[str]:
    """A minimum film the mesh does not resolve: its discretisation error estimated from the
    film's relative second difference at its node, in each direction.

    ``s = (h[k-1] + h[k+1]) / (2 h[k]) - 1`` across y (and along x) at the node of the least
    film. The side lobes of a heavily loaded point contact are narrow across y; on a mesh
    too coarse for them the lobe's minimum comes out too thin (a ball on glass, M 313: 11.1,
    28.0, 32.7 nm on dY = b/10, b/20, b/40, against 34.3 nm extrapolated). With the mesh
    refined both ``s`` and the error fall as ``dY^2``, the error at
    ``MIN_FILM_ERROR_PER_CURVATURE s`` (0.30-0.35 s on two balls, docs/ehl-robustness.md,
    "A minimum film the mesh does not resolve"); on a coarser mesh the error is a smaller
    share of ``s``, and where refining moves the minimum elsewhere (out of the lobes onto
    the centre line, the seed's gear case) the estimate is 2-5 times the error. Reported
    above ``MIN_FILM_MESH_ERROR``, with the nodes for about ``MESH_TARGET`` by the
    ``dY^2`` scaling. A minimum on a boundary node is not judged in that direction; a
    minimum film of zero (h = 0 in a smooth contact) is reported as not resolved.

    Parameters
    ----------
    film : ndarray
        Film thickness, shape (nx, ny), m.
    x, y : ndarray
        Node coordinates, m.
    a, b : float
        Hertz semi-axes, m (``b`` None for a line contact).
    domain : ((float, float), (float, float)), optional
        Domain (m) on which the advised node counts are counted, where it reaches beyond the
        nodes: the one the run's other lines advise (:func:`advised_domain`), so that the
        spacing asked for holds on it.
    cell_aspect : float
        Least ``dy / dx`` of the cells advised across y: ``nx`` is raised with ``ny`` to
        keep it (the x-line relaxation needs cells long across y; default
        ``MIN_CELL_ASPECT``, 3).
    max_ny : int, optional
        Most nodes across y on which the relaxation converges for this contact
        (:data:`asperity.ehl.solver.SOFT_MAX_NY` for an isoviscous soft point contact). Where
        more are needed the line names this many, with the error left on it by the ``dY^2``
        scaling, instead of a mesh that does not converge.
    max_nodes : (int, int, int), optional
        Most nodes of a mesh in all, along x and across y that a case takes
        (:data:`asperity.cases.ehl.MAX_NODES`, ``MAX_NX``, ``MAX_NY``). Where the mesh for
        ``MESH_TARGET`` needs more, the line says so and names the finest mesh within them
        (both spacings scaled alike, the cells' aspect kept) with the error the ``dx^2``,
        ``dy^2`` scaling leaves on it: a collapsed side lobe of probe case 04 (M = 4849)
        was told to use 569 x 5993 and 14489 nodes along x, which the case refuses.

    Returns
    -------
    list of str
        At most one line.
    """
    film = np.asarray(film, dtype=float)
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    spans = [_span(c, None if domain is None else d, s, name) if s is not None else (0.0, "")
             for c, d, s, name in zip((y, x), (None, None) if domain is None else domain[::-1],
                                      (b, a), ("b", "a"), strict=True)]
    if film.ndim == 1:
        film = film[:, None]
    i, j = np.unravel_index(np.argmin(film), film.shape)
    h = film[i, j]
    judged = []  # (key, semi-axis name, thicker, error, nodes for MESH_TARGET)
    for (key, semi, name), (span, _) in zip((("y", b, "b"), ("x", a, "a")), spans, strict=True):
        curvature = minimum_film_curvature(film, key)
        if semi is None or curvature is None:
            continue
        thicker, error = curvature
        if error <= MIN_FILM_MESH_ERROR:
            continue
        step = _spacing(y if key == "y" else x) / math.sqrt(min(error, 1.0) / MESH_TARGET)
        judged.append((key, name, thicker, error, 8 * math.ceil(round(span / step / 8, 6)) + 1))
    if not judged:
        return []
    need = {key: n for key, _, _, _, n in judged}
    capped = "y" in need and max_ny is not None and need["y"] > max_ny
    rows = min(need["y"], max_ny) if capped else need.get("y", y.size)
    cells_nx = 1
    if "y" in need and x.size > 1:  # the x-line relaxation needs long cells
        cells_nx = 8 * math.ceil(round(spans[1][0] / (spans[0][0] / (rows - 1) / cell_aspect)
                                       / 8, 6)) + 1
    mesh_nx = max(need.get("x", 1), cells_nx, x.size)
    over = 1.0
    if max_nodes is not None and not capped:
        most, most_x, most_y = max_nodes
        over = max(math.sqrt(mesh_nx * rows / most), mesh_nx / most_x, rows / most_y)
    (y_span, y_where), (x_span, x_where) = spans
    parts = []
    for key, name, thicker, error, _ in judged:
        semi = b if key == "y" else a
        spacing = semi / _spacing(y if key == "y" else x)
        estimate = f"{'up to ' + _pct(error) if error < 1.0 else 'over 100 %'}"
        part = (f"{'across y' if key == 'y' else 'along x'} (d{key} = {name}/{spacing:.3g}, "
                f"the film at the nodes beside it "
                f"{'thicker by ' + _pct(thicker) if h > 0.0 else 'above zero'}): "
                f"estimated error {estimate}")
        if key == "x" or not capped:
            advice = f"n{key} >= {need[key]}{y_where if key == 'y' else x_where}"
            if key == "y" and cells_nx > x.size:
                advice += f" with nx >= {cells_nx}{x_where} (dy >= {cell_aspect:g} dx)"
            part += f"; use {advice} for about {_pct(MESH_TARGET)}" if over <= 1.0 else ""
        else:  # the finest mesh across y that converges, and the error it leaves
            left = min(error, 1.0) * (y_span / (max_ny - 1) / _spacing(y)) ** 2
            advice = (f"ny = {max_ny}{y_where}" if y.size < max_ny else "")
            if advice and cells_nx > x.size:
                advice += f" with nx >= {cells_nx}{x_where} (dy >= {cell_aspect:g} dx)"
            part += (f"; about {_pct(MESH_TARGET)} needs ny >= {need['y']}{y_where}, but the "
                     f"relaxation of this contact converges on at most {max_ny} nodes across "
                     f"and on cells dy >= {cell_aspect:g} dx; "
                     + (f"use {advice}, on which the minimum film is still "
                        f"{'up to ' + _pct(left) if left < 1.0 else 'over 100 %'} low by this "
                        "estimate"
                        if advice else f"with {y.size} nodes across, take the estimate "
                        "as the error bar of the minimum film"))
        parts.append(part)
    at = f"x = {x[i] / a:.3g} a" + (f", y = {y[j] / b:.3g} b" if film.shape[1] > 1 else "")
    head = (f"mesh: the minimum film ({h * 1e9:.4g} nm at {at}) is not resolved "
            + " and ".join(parts))
    if over > 1.0:
        head += "; " + _within_node_limits(judged, rows, mesh_nx, over, (x_span, y_span),
                                           (x_where, y_where), x, y, max_nodes)
    return [head + f" (limit {_pct(MIN_FILM_MESH_ERROR)}); "
            + ("a finer mesh across y does not converge with the solver's relaxation"
               if capped else "refine until the minimum film stops changing")]


def _within_node_limits(judged, rows: int, nx: int, over: float, spans, wheres, x, y,
                        max_nodes) -> str:
    """The clause of :func:`ehl_minimum_film_mesh` for a mesh beyond a case's node limits:
    the mesh for ``MESH_TARGET`` (``nx`` x ``rows``), and the finest within the limits
    (both spacings ``over`` times theirs, in blocks of 8 cells) with the error left on it,
    ``min(error, 1) (d / d_now)^2`` in each direction judged."""
    most, most_x, most_y = max_nodes
    (x_span, y_span), (x_where, y_where) = spans, wheres
    fit_nx = max(8 * math.floor((nx - 1) / over / 8) + 1, x.size)
    fit_ny = max(8 * math.floor((rows - 1) / over / 8) + 1, y.size) if y.size > 1 else 1
    fit_nx = min(fit_nx, most_x, most // fit_ny)
    left = 0.0
    for key, _, _, error, _ in judged:
        coord, span, fit = (y, y_span, fit_ny) if key == "y" else (x, x_span, fit_nx)
        left = max(left, min(error, 1.0) * (span / (fit - 1) / _spacing(coord)) ** 2)
    needs = f"nx >= {nx}{x_where}" + (f", ny >= {rows}{y_where}" if y.size > 1 else "")
    finest = (f"nx = {fit_nx}" + (f", ny = {fit_ny}" if y.size > 1 else "")
              + f" ({fit_nx * fit_ny:,} nodes)")
    clipped = any(error >= 1.0 for _, _, _, error, _ in judged)
    still = ("still over 100 % low by this estimate" if left >= 1.0 else
             f"still up to {_pct(left)} low by this estimate" if not clipped else
             f"still at least {_pct(left)} low by this estimate (over 100 % on this mesh, "
             "counted as 100 % in the scaling)")
    if fit_nx <= x.size and fit_ny <= y.size:
        return (f"about {_pct(MESH_TARGET)} needs {needs} ({nx * rows:,} nodes), more than "
                f"a case takes ({most:,} nodes, nx <= {most_x}, ny <= {most_y}); take the "
                "estimate as the error bar of the minimum film")
    return (f"about {_pct(MESH_TARGET)} needs {needs} ({nx * rows:,} nodes), more than a case "
            f"takes ({most:,} nodes, nx <= {most_x}, ny <= {most_y}); the finest mesh within "
            f"them at these proportions is {finest}, on which the minimum film is {still}")


def smooth_start_contact(steady_film, x, y, a: float, b: float | None,
                         contact_film: float) -> list[str]:
    """Contact in the smooth steady start of a transient run, which the contact statistics
    count as if the roughness had made it.

    A node counts as in contact where ``h <= contact_film``. A smooth contact that already
    touches does so, in the cases seen, in the side lobes of a heavily loaded point contact
    on a mesh too coarse across them: a ball-bearing contact at Moes M = 2520 (k = 0.58) had
    a minimum film of 0 on 1025 x 153 nodes (dY = b/38) and 29 nm on 1025 x 305, and its run
    with a dent counted contact at 99.6 % of the steps, all of it at the edges of the Hertz
    zone across y (docs/ehl-robustness.md, "A smooth start that touches").

    Parameters
    ----------
    steady_film : ndarray
        Film of the smooth steady start, shape (nx, ny), m.
    x, y : ndarray
        Node coordinates, m.
    a, b : float
        Hertz semi-axes, m (``b`` None for a line contact).
    contact_film : float
        Film at or below which a node counts as in contact, m.

    Returns
    -------
    list of str
        At most one line.
    """
    touching = touching_mask(steady_film, contact_film)  # interior nodes, as the statistics
    if not touching.any():
        return []
    i, j = np.nonzero(touching)
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)

    def span(values, unit):
        low, high = f"{values.min():.2f} {unit}", f"{values.max():.2f} {unit}"
        return low if low == high else f"{low} to {high}"

    where = "x = " + span(x[i] / a, "a")
    if b is not None:
        where += ", |y| = " + span(np.abs(y[j]) / b, "b")
    return [f"statistics: the smooth steady start already touches (film <= "
            f"{contact_film * 1e9:.3g} nm) at {touching.sum()} nodes ({where}; limit 0), with no "
            "roughness in the contact; the contact counts and the contact-time fraction include "
            "such contacts; refine the mesh where it touches until the smooth start no longer "
            "does"]


def ehl_mesh(x, y, a: float, b: float | None,
             min_cells: float = MIN_CELLS_PER_SEMI_AXIS, domain=None) -> list[str]:
    """A mesh too coarse for the Hertz zone (fewer than ``min_cells`` spacings per semi-axis).

    Parameters
    ----------
    x, y : ndarray
        Node coordinates, m.
    a, b : float
        Hertz semi-axes, m (``b`` None for a line contact).
    min_cells : float
        Fewest mesh spacings per semi-axis.
    domain : ((float, float), (float, float)), optional
        Domain (m) on which the advised node counts are counted, where it reaches beyond the
        nodes (:func:`advised_domain`).

    Returns
    -------
    list of str
        At most one line.
    """
    parts = []
    for (name, coord, semi, key), bounds in zip(
            (("a", x, a, "x"), ("b", y, b, "y")),
            (None, None) if domain is None else domain, strict=True):
        if semi is None or np.asarray(coord).size < 2:
            continue
        ratio = semi / _spacing(coord)
        cells = round(ratio, 6) or ratio  # rounded off float noise; not to 0 on absurd meshes
        if cells < min_cells:
            n = np.asarray(coord).size
            span, where = _span(coord, bounds, semi, name)
            need = math.ceil(round(span / semi * min_cells, 6)) + 1
            parts.append(f"{name}/d{key} = {cells:.3g} (n{key} = {n}; use n{key} >= {need}{where}, "
                         f"or cells_per_{name} >= {min_cells:g})")
    if not parts:
        return []
    return ["mesh: the Hertz zone is resolved by " + " and ".join(parts) + f" (limit "
            f"{min_cells:g} spacings per semi-axis); film and pressure are mesh-dependent"]


def _rms(z) -> float:
    z = np.asarray(z, dtype=float)
    return float(np.sqrt(np.mean((z - z.mean()) ** 2))) if z.size else 0.0


def unresolved_roughness(label: str, z, spacing: float, dx: float) -> list[str]:
    """Roughness at wavelengths the mesh cannot resolve (shorter than a few mesh spacings).

    Parameters
    ----------
    label : str
        The surface, e.g. ``"surface1"``.
    z : ndarray
        Heights along x (first axis) sampled at ``spacing``, m.
    spacing : float
        Sampling interval of ``z``, m.
    dx : float
        Mesh spacing of the solver, m.

    Returns
    -------
    list of str
        At most one line.
    """
    from .surfaces import gaussian_filter

    z = np.asarray(z, dtype=float)
    total = _rms(z)
    cutoff = UNRESOLVED_WAVELENGTH_CELLS * dx
    if not total > 0 or cutoff <= 2 * spacing or z.shape[0] < 8:
        return []
    xs = spacing * np.arange(z.shape[0])
    smooth = gaussian_filter(z, xs, cutoff, periodic=False)  # along x, every row
    share = _rms(z - smooth) / total
    if share <= UNRESOLVED_RMS_SHARE:
        return []
    return [f"{label}: {_pct(share)} of the rms height ({total * 1e6:.3g} um) lies at "
            f"wavelengths shorter than {UNRESOLVED_WAVELENGTH_CELLS:g} dx = {cutoff * 1e6:.3g} "
            f"um, which the mesh (dx = {dx * 1e6:.3g} um) cannot resolve (limit "
            f"{_pct(UNRESOLVED_RMS_SHARE)}); refine the mesh (dx <= {spacing * 2e6:.3g} um "
            "resolves all of it) or set lowpass to say that the smoothing is intended"]


def lowpass_removed(label: str, raw, filtered, cutoff: float) -> list[str]:
    """The roughness a low-pass filter removed before the solve.

    Parameters
    ----------
    label : str
        The surface, e.g. ``"surface1"``.
    raw, filtered : ndarray
        Heights before and after the filter, m.
    cutoff : float
        The filter's cut-off wavelength, m.

    Returns
    -------
    list of str
        At most one line.
    """
    total = _rms(raw)
    if not total > 0:
        return []
    share = _rms(np.asarray(raw, dtype=float) - np.asarray(filtered, dtype=float)) / total
    if share <= LOWPASS_RMS_SHARE:
        return []
    return [f"{label}: the low-pass filter (lowpass, cut-off {cutoff * 1e6:.3g} um) removed "
            f"{_pct(share)} of the rms height ({total * 1e6:.3g} um; limit "
            f"{_pct(LOWPASS_RMS_SHARE)}); the results are those of the smoothed surface; refine "
            "the mesh and lower lowpass to keep that roughness"]


#: Fewest mesh cells per half-width of a single surface feature along x and across y before
#: the mesh is reported coarse for it (a waviness: per half-wavelength, the x limit in its
#: direction; at 3.2 nodes per wavelength across the seed's transverse waviness was too
#: coarse, docs/ehl-transient.md, "Paper conclusions at the reduced resolution"). The bump of
#: docs/ehl-transient.md ("The default mesh of a transient case") at 5.1 cells along x had
#: its film and largest pressure 1.1-1.9 % off those at 20.4 (second order: about 3 % at 4
#: cells), and at 1.6 cells across within 0.8 % of those at 3.2.
FEATURE_MIN_CELLS_ALONG = 4.0
FEATURE_MIN_CELLS_ACROSS = 1.5


def unresolved_feature(label: str, what: str, size: float, dx: float, dy: float | None = None,
                       min_along: float = FEATURE_MIN_CELLS_ALONG,
                       min_across: float = FEATURE_MIN_CELLS_ACROSS) -> list[str]:
    """A single surface feature (a dent, bump or ridge; a waviness) too coarse on the mesh.

    Parameters
    ----------
    label : str
        The surface, e.g. ``"surface2"``.
    what : str
        The feature and its size, e.g. ``"bump half-width"``.
    size : float
        Its half-width (or half-wavelength), m.
    dx : float
        Mesh spacing along x, m (None: not checked along x).
    dy : float, optional
        Mesh spacing across y, m (None: not checked across y; a ridge, a line contact).

    Returns
    -------
    list of str
        At most one line.
    """
    coarse = []
    if dx is not None and size / dx < min_along:
        coarse.append(("x", size / dx, min_along, dx))
    if dy is not None and size / dy < min_across:
        coarse.append(("y", size / dy, min_across, dy))
    if not coarse:
        return []
    spans = " and ".join(f"{cells:.2g} cells of {step * 1e6:.3g} um along {axis} (limit "
                         f"{limit:g})" for axis, cells, limit, step in coarse)
    # twice the limit, and across y with dx <= dy / MIN_CELL_ASPECT (flatter cells fail)
    target = {axis: size / (2 * limit) for axis, _, limit, _ in coarse}
    if "y" in target:
        target["x"] = min(target.get("x", np.inf), target["y"] / MIN_CELL_ASPECT,
                          dx if dx is not None else np.inf)
    advice = " and ".join(f"d{axis} <= {value * 1e6:.3g} um" for axis, value in target.items())
    return [f"{label}: the {what} {size * 1e6:.3g} um spans {spans}, so the film and pressure "
            f"it causes depend on the mesh; set nx, ny for {advice} (or leave out [grid] nx, "
            "ny: the default mesh follows the feature)"]


def feature_passage(label: str, feature: str, start: float, end: float, a: float,
                    step: float, warmup: int, counting: int) -> list[str]:
    """A single feature whose passage through the Hertz zone the counting period misses.

    Parameters
    ----------
    label : str
        The surface, e.g. ``"surface1"``.
    feature : str
        ``"dent"``, ``"bump"``, ``"ridge"`` or ``"groove"``.
    start, end : float
        Position (m) of the feature's centre when counting starts and at the last step.
    a : float
        Hertz semi-axis along x, m.
    step : float
        Distance the feature moves per time step, m.
    warmup, counting : int
        The run's warm-up and counting steps.

    Returns
    -------
    list of str
        At most one line.
    """
    changes = []
    if start > -a:
        changes.append(f"time.warmup_steps <= {max(warmup - int(np.ceil((start + a) / step)), 0)}")
    if end < a:
        changes.append(f"time.counting_steps >= {counting + int(np.ceil((a - end) / step))}")
    if not changes:
        return []
    return [f"{label}: the {feature}'s centre moves from x = {start / a:.2f} a to "
            f"{end / a:.2f} a in the counting period, which misses part of its passage through "
            f"the Hertz zone (-a to +a) and so part of its effect on the statistics; set "
            f"{' and '.join(changes)} (or leave them out: the defaults count the whole passage)"]


def unconverged_steps(step_converged, tolerance: float, max_sweeps: int, residuals=None,
                      blown_up: float = np.inf, line: bool = False) -> list[str]:
    """Time steps that did not reach the tolerance, and what to change for them.

    A step whose last residual is still at least ``blown_up`` (or not finite) did not run
    short of sweeps: its relaxation blew up or stalled far from the tolerance with every
    setting the solver falls back on, and more sweeps do not mend it (docs/ehl-transient.md,
    "A try that blows up is given up at once"). A finer grid or a smaller timestep may: on a
    user's Newtonian gear contact (docs/ehl-transient.md, "Line contacts: the row solve")
    twice the nodes cut such steps from 1.1 % to 0.3 % of the steps, half the timestep did
    not.

    Parameters
    ----------
    step_converged : ndarray of bool
        One flag per step done.
    tolerance : float
        The solver's tolerance.
    max_sweeps : int
        Sweeps allowed per step.
    residuals : ndarray of float, optional
        The last residual of each step (largest change per sweep, in Hertz pressures or
        central films, or relative load error).
    blown_up : float
        Residual from which a step counts as blown up (default: none does).
    line : bool
        A line contact: its grid has ``nx`` only.

    Returns
    -------
    list of str
        At most one line.
    """
    flags = np.asarray(step_converged, dtype=bool)
    bad = np.flatnonzero(~flags)
    if not bad.size:
        return []
    first = ", ".join(str(k + 1) for k in bad[:5]) + (", ..." if bad.size > 5 else "")
    if residuals is None:
        up = np.zeros(bad.size, dtype=bool)
    else:
        last = np.asarray(residuals, dtype=float)[bad]
        up = ~(last < blown_up)                         # NaN and inf: blown up
    grid = "grid.nx" if line else "grid.nx, grid.ny"
    advice = []
    if (~up).any():
        advice.append(f"{np.count_nonzero(~up)} ran out of {max_sweeps} sweeps: raise "
                      "max_sweeps or use a smaller dt")
    if up.any():
        finite = last[up][np.isfinite(last[up])]
        if not finite.size:
            size = "diverged"
        elif finite.min() == finite.max():
            size = f"last change per sweep {finite.min():.2g}"
        else:
            size = f"last change per sweep {finite.min():.2g}-{finite.max():.2g}"
        advice.append(f"{np.count_nonzero(up)} stayed far from it with every setting the solver "
                      f"falls back on ({size}, at least {blown_up:g}), which more sweeps do "
                      f"not mend: try a finer grid ({grid}) or a smaller [time] dt "
                      "(on a measured gear case twice the nodes cut such steps from 1.1 % to "
                      "0.3 %, half the time step did not)")
    return [f"steps: {bad.size} of {flags.size} time steps ({_pct(bad.size / flags.size)}; "
            f"limit 0) did not reach the tolerance {tolerance:g} (steps {first}); their "
            f"statistics are included; {'; '.join(advice)}"]


#: cells per autocorrelation length below which a rough surface is set by the mesh (heights
#: nearly uncorrelated from one cell to the next; at 2 cells the answer still moves with the
#: mesh: docs/references.md#roughness-on-the-mesh)
MIN_CELLS_PER_CORRELATION_LENGTH = 2.0


def roughness_resolution(label: str, correlation_length: float, x, y,
                         min_cells: float = MIN_CELLS_PER_CORRELATION_LENGTH,
                         correlation_length_y: float | None = None,
                         along_x: bool = True, across_y: bool = True) -> list[str]:
    """A generated roughness whose correlation length is shorter than a couple of cells.

    The surface is generated on the grid: with fewer than ``min_cells`` cells per
    correlation length (the lag where its autocorrelation falls to 0.2) every asperity is a
    cell or two wide, the mesh rather than the surface sets the asperity size, and the real
    contact area and asperity pressures change with the mesh (docs/references.md).

    Parameters
    ----------
    label : str
        The surface, e.g. ``"roughness"``.
    correlation_length : float
        The surface's correlation length, m (along x, and across y unless
        ``correlation_length_y`` is given).
    x, y : ndarray
        Cell-centre coordinates, m.
    min_cells : float
        Smallest acceptable correlation length in cells.
    correlation_length_y : float, optional
        Correlation length across y of an anisotropic surface, m. Each direction is judged
        on its own cells (a transient run's cells are several times longer across y than
        along x), and the line names the worse.
    along_x : bool
        False: judge the cells across y only: a transient
        run's surface is sampled finer than the mesh along x, where
        :func:`unresolved_roughness` judges it, and generated on the mesh's rows across y.
    across_y : bool
        False: judge the cells along x only: a ground profile is extruded across y, the same
        on every row (a ball on a ground plate, 128 x 64 cells over 0.6 mm, was told its
        15 um correlation length was 1.6 cells across y and to use cells of 3.8 um there).

    Returns
    -------
    list of str
        At most one line.
    """
    directions = [("correlation_length", " along x", correlation_length, _spacing(x))
                  ] if along_x else []
    if len(y) > 1 and across_y:
        directions.append(("correlation_length" if correlation_length_y is None else
                           "correlation_length_y", " across y",
                           correlation_length if correlation_length_y is None else
                           correlation_length_y, _spacing(y)))
    if not directions:
        return []
    key, where, ell, cell = min(directions, key=lambda d: d[2] / d[3])
    cells = ell / cell
    if not cells < min_cells:
        return []
    return [f"{label}: {key} = {ell * 1e6:.3g} um is {cells:.2g} cells of {cell * 1e6:.3g} um"
            f"{where} (limit {min_cells:g} cells), so the mesh, not the surface, sets the "
            "asperity size and the real contact area and asperity pressures depend on the "
            f"mesh; use cells <= {ell / 4 * 1e6:.2g} um{where} and check that the answer no "
            "longer moves"]


#: Correlation lengths a generated Gaussian surface needs across the grid for its heights to
#: have the surface's statistics rather than those of a few hills.
MIN_CORRELATION_LENGTHS_ON_GRID = 2.0


def roughness_extent(label: str, x, y, *, rolloff_wavelength: float | None = None,
                     correlation_length: float | None = None) -> list[str]:
    """A generated roughness whose longest length is not on the grid it is generated on.

    A periodic patch holds wavelengths up to its size only. A self-affine surface's
    ``rolloff_wavelength`` longer than the patch is then not represented: its spectrum rises
    to the patch size without its plateau, and the rms asked for sits at wavelengths the
    surface given would not carry it at (``rolloff_wavelength = 100``, meant in um and read in
    m on a 0.5 mm patch, ran without a word). A Gaussian surface whose correlation length is
    more than ``1 / MIN_CORRELATION_LENGTHS_ON_GRID`` of the patch is a hill or two, not a
    sample of the surface.

    Parameters
    ----------
    label : str
        The surface, e.g. ``"roughness"``.
    x, y : ndarray
        Cell-centre coordinates of the grid the surface is generated on, m.
    rolloff_wavelength, correlation_length : float, optional
        The surface's roll-off wavelength (self-affine) or correlation length (Gaussian), m.

    Returns
    -------
    list of str
        At most one line.
    """
    sizes = [np.asarray(c).size * _spacing(c) for c in (x, y) if np.asarray(c).size > 1]
    size = max(sizes)
    extent = " x ".join(format_quantity(s, "m", digits=3) for s in sizes)
    if rolloff_wavelength is not None and rolloff_wavelength > size * (1 + 1e-9):
        return [f"{label}: rolloff_wavelength = "
                f"{format_quantity(rolloff_wavelength, 'm', digits=3)} is longer than the "
                f"grid ({extent}; limit: at most its size), whose longest wavelength is its "
                "size: the roll-off is not represented, the spectrum rises to the grid's size "
                "and the rms sits at shorter wavelengths than the surface given has; enlarge "
                f"the grid to the roll-off or check its value and unit (a bare number is in "
                "m)"]
    if correlation_length is not None and (
            correlation_length * MIN_CORRELATION_LENGTHS_ON_GRID > min(sizes) * (1 + 1e-9)):
        return [f"{label}: correlation_length = "
                f"{format_quantity(correlation_length, 'm', digits=3)} is more than "
                f"1/{MIN_CORRELATION_LENGTHS_ON_GRID:g} of the grid ({extent}; limit "
                f"{MIN_CORRELATION_LENGTHS_ON_GRID:g} correlation lengths across it): the "
                "surface on it is a hill or two, whose heights and contact are not those of "
                "the surface given; enlarge the grid or check the value and its unit (a bare "
                "number is in m)"]
    return []


#: Sampling interval of a measured roughness file, in grid spacings, above which the file is
#: reported too coarse for the grid: beyond it most of the grid's cells get heights that the
#: spline invents between measured points (smooth hills), not measured roughness.
COARSE_FILE_FACTOR = 2.0


def _file_and_grid_axes(spacing, x, y):
    """(axis, file interval, grid spacing, grid nodes) along x (and y) of a measured file's
    sampling against a grid's cell centres."""
    return [(axis, h, _spacing(coord), np.asarray(coord).size)
            for axis, h, coord in zip("xy", spacing, (x, y), strict=False)]


def coarse_roughness_file(label: str, spacing, x, y,
                          factor: float = COARSE_FILE_FACTOR) -> list[str]:
    """A measured roughness file sampled more coarsely than the contact grid.

    Between the file's points the grid gets spline-interpolated heights: smooth hills as wide
    as the sampling interval, without the roughness the instrument did not record, so the
    real contact area and the asperity pressures are those of a smoother surface.

    Parameters
    ----------
    label : str
        The table, e.g. ``"roughness"``; the line names its ``path``.
    spacing : sequence of float
        The file's sampling interval along x (and along y for a topography), m.
    x, y : ndarray
        Cell-centre coordinates of the grid, m.
    factor : float
        Largest acceptable ratio of the file's interval to the grid spacing.

    Returns
    -------
    list of str
        At most one line.
    """
    coarse = [(axis, h, d, max(math.floor(n * d * factor / h + 1e-9), 1))
              for axis, h, d, n in _file_and_grid_axes(spacing, x, y)
              if h > factor * d * (1.0 + 1e-9)]  # (a grid of exactly half: no line)
    if not coarse:
        return []
    found = " and ".join(f"{h * 1e6:.3g} um apart along {axis}, {h / d:.3g} times the grid's "
                         f"d{axis} = {d * 1e6:.3g} um" for axis, h, d, _ in coarse)
    finer = " and ".join(f"<= {factor * d * 1e6:.3g} um along {axis}" for axis, _, d, _ in coarse)
    grid = " and ".join(f"grid.n{axis} <= {cells} (d{axis} >= {h / factor * 1e6:.3g} um)"
                        for axis, h, _, cells in coarse)
    return [f"{label}.path: the file's points are {found} (limit {factor:g}); between them the "
            "grid gets spline-interpolated heights, smooth hills instead of measured roughness, "
            "so the real contact area and pressures are those of a smoother surface; use a "
            f"file sampled at {finer}, or a coarser grid: {grid}"]


#: Grid spacing, in sampling intervals of a measured roughness file, above which the grid is
#: reported to decimate the file: it then drops the file's shortest wavelengths, whose
#: slopes set the real contact area (about inversely proportional to the rms slope).
DECIMATED_FILE_FACTOR = 1.5


def decimated_roughness_file(label: str, spacing, x, y, file_slope: float,
                             grid_slope: float,
                             factor: float = DECIMATED_FILE_FACTOR) -> list[str]:
    """A contact grid coarser than a measured roughness file's sampling interval.

    The grid then takes the file's heights at its cell centres only, and the roughness
    between them is lost: the rms slope on the grid falls below the file's, and the real
    contact area, inversely proportional to the rms slope at small loads (Bush, Gibson &
    Thomas 1975; Persson 2001), rises. A user's 1 um map on 2 um cells lost 14 % of its
    slope and gained 25 % of real contact area.

    Parameters
    ----------
    label : str
        The table, e.g. ``"roughness"``; the line names its ``path``.
    spacing : sequence of float
        The file's sampling interval along x (and y for a topography), m.
    x, y : ndarray
        Cell-centre coordinates of the grid, m.
    file_slope, grid_slope : float
        Rms slope (Rdq or Sdq, :func:`asperity.surfaces.rms_gradient`) of the file's heights
        and of the heights on the grid.
    factor : float
        Largest acceptable ratio of the grid spacing to the file's interval.

    Returns
    -------
    list of str
        At most one line.
    """
    coarse = [(axis, h, d, math.ceil(n * d / h - 1e-9))
              for axis, h, d, n in _file_and_grid_axes(spacing, x, y)
              if n > 1 and d > factor * h * (1.0 + 1e-9)]
    if not coarse:
        return []
    found = " and ".join(f"d{axis} = {d * 1e6:.3g} um, {d / h:.3g} times the file's "
                         f"{h * 1e6:.3g} um" for axis, h, d, _ in coarse)
    grid = " and ".join(f"grid.n{axis} >= {cells}" for axis, _, _, cells in coarse)
    change = grid_slope / file_slope - 1.0 if file_slope > 0 else float("nan")
    return [f"{label}.path: the grid is coarser than the file's points ({found}; limit "
            f"{factor:g}): it takes the file's heights at its cell centres only and drops the "
            f"roughness between them, so its rms slope is {grid_slope:.3g} against the "
            f"file's {file_slope:.3g} ({change:+.0%}) and the real contact area, about "
            "inversely proportional to it, is overstated; use "
            f"{grid} on the same extent, or a smaller extent"]


def measured_file_on_grid(label: str, on_grid, x, y) -> list[str]:
    """A measured roughness file's doubts on a contact grid, the file's first: the reader's
    and the unit's (``on_grid.warnings``), a file coarser than the grid
    (:func:`coarse_roughness_file`) and a grid coarser than the file
    (:func:`decimated_roughness_file`).

    Parameters
    ----------
    label : str
        The table, e.g. ``"roughness"``, ``"pressure.roughness"``.
    on_grid : GridRoughness
        The table's heights on the grid (:func:`asperity.cases.roughness.roughness_on_grid`).
    x, y : ndarray
        Cell-centre coordinates of the grid, m.
    """
    if on_grid.file_spacing is None:
        return []
    grid_slope = rms_gradient(Topography(np.asarray(x, float), np.asarray(y, float),
                                         on_grid.heights))[1]
    return [*on_grid.warnings,
            *coarse_roughness_file(label, on_grid.file_spacing, x, y),
            *decimated_roughness_file(label, on_grid.file_spacing, x, y, on_grid.file_slope,
                                      grid_slope)]


#: Rms jump across a periodic grid's boundary, in rms jumps between neighbouring points,
#: above which the surface is reported as not periodic: a window cut from a larger
#: measurement steps by about sqrt(2) Sq there (a user's 256 um window of a 512 um map: 5.8
#: and 8.2 times), where neighbours differ by the rms slope times a sampling interval; the
#: tilt removed from a periodic map leaves a seam of 2-3 times.
SEAM_JUMP_RATIO = 4.0


def periodic_seam(label: str, heights, lags=(1, 1)) -> list[str]:
    """A surface on a periodic grid whose heights jump at the grid's boundary.

    A periodic solve joins the last cell to the first; a surface that is not periodic (a
    window of a larger measurement) gets a step there, a ridge or a cliff across the whole
    cell that carries load no measured asperity does. Compares the rms of the jumps across
    each boundary with the rms of the jumps over ``lags`` cells along the same axis inside
    (a measured file's sampling interval in cells: on a grid finer than the file the jump
    between neighbouring cells is a spline's, smaller than any measured one).

    Parameters
    ----------
    label : str
        The table, e.g. ``"roughness"``.
    heights : ndarray, shape (nx, ny)
        Heights on the grid, m.
    lags : (int, int)
        Cells along x and y over which the inner jumps are taken (>= 1).

    Returns
    -------
    list of str
        At most one line.
    """
    z = np.asarray(heights, dtype=float)
    seams = []
    for axis, lag in zip((0, 1), lags, strict=True):
        lag = max(int(lag), 1)
        if z.shape[axis] < 2 * lag + 1:
            continue
        n = z.shape[axis]
        inner = np.sqrt(np.mean((np.take(z, range(lag, n), axis=axis)
                                 - np.take(z, range(n - lag), axis=axis)) ** 2))
        seam = np.sqrt(np.mean((np.take(z, 0, axis=axis) - np.take(z, -1, axis=axis)) ** 2))
        if inner > 0 and seam > SEAM_JUMP_RATIO * inner:
            seams.append((("x", "y")[axis], seam, seam / inner))
    if not seams:
        return []
    found = " and ".join(f"{seam * 1e6:.3g} um rms across the {axis} boundary, {ratio:.3g} "
                         "times the jump between neighbouring points inside" for axis, seam,
                         ratio in seams)
    return [f"{label}: the surface is not periodic on the periodic grid ({found}; limit "
            f"{SEAM_JUMP_RATIO:g}): the solve joins its ends by a step that carries load no "
            "measured asperity does; use a periodic surface (a periodic .npz, or a mirrored or "
            "windowed one), or grid.periodic = false with a domain larger than the contact"]


def stopped_run(steps_done: int, warmup_steps: int, counting_steps: int,
                failed_in_a_row: int = 0) -> list[str]:
    """A transient run that stopped before its last step: a step diverged after every
    fallback of the solver (:meth:`asperity.ehl.stepper.TimeStepper.advance`), or
    ``failed_in_a_row`` steps in a row (:data:`asperity.ehl.transient.GIVE_UP_STEPS`) did not
    converge with any of them.

    Parameters
    ----------
    steps_done : int
        Steps done, the diverged one included.
    warmup_steps, counting_steps : int
        The run's warm-up and counting steps.
    failed_in_a_row : int
        Unconverged steps at the end of the run (0: the last step diverged).

    Returns
    -------
    list of str
        At most one line.
    """
    total = warmup_steps + counting_steps
    if steps_done >= total:
        return []
    counted = max(0, steps_done - warmup_steps)
    held = ("no step was counted (counting starts after the warm-up), so every statistic is "
            "empty" if counted == 0 else
            f"the statistics hold {counted} of the {counting_steps} counting steps")
    fallbacks = ("the far field refreshed at every sweep, the density's Newton term, the load "
                 "gain halved, under-relaxation")
    if failed_in_a_row:
        return [f"steps: the run stopped at step {steps_done} of {total}: its last "
                f"{failed_in_a_row} steps did not converge with any fallback of the solver "
                f"({fallbacks}), and a run that fails so many in a row does not recover; "
                f"{held}. Check first that the smooth steady start converged (run the contact "
                "as analysis = \"ehl-steady\"), then try a finer grid, a smaller time.dt or "
                "solver.load_gain"]
    return [f"steps: the run stopped at step {steps_done} of {total}: that step diverged after "
            f"every fallback of the solver ({fallbacks}); {held}. Try a smaller time.dt or "
            "solver.load_gain"]


#: Contact semi-axis over the radius of relative curvature above which Hertz's small-contact
#: (half-space) assumption fails: the surfaces are no longer nearly flat over the contact.
HERTZ_SIZE_LIMIT = 0.1
#: Peak Hertz pressure over the contact modulus, p0 / E*, above which plasticity is likely
#: for metals and polymers (a strain of about 5 %; a hardened steel first yields near
#: p0 / E* = 0.02-0.03, which only its hardness can tell: bodyN.hardness, above_hardness).
HERTZ_STRAIN_LIMIT = 0.05


#: Peak Hertz pressure over the indentation hardness at which a point contact first yields
#: beneath the surface: p0 = 1.60 Y (von Mises, nu = 0.3, at depth 0.48 a; Johnson 1985,
#: sec. 6.2) with Tabor's H = 2.8 Y, 1.60 / 2.8 = 0.57. ISO 76's static limit of a bearing
#: steel of 7.5 GPa, p0 = 4.2 GPa, is 0.56 of it.
FIRST_YIELD_HARDNESS = 0.57


def hertz_first_yield(p0: float, load: float, materials: Iterable,
                      load_key: str = "pressure.load") -> list[str]:
    """A Hertz contact whose peak pressure is past first yield beneath the surface but not
    past the hardness (:func:`above_hardness` judges that).

    Parameters
    ----------
    p0 : float
        Maximum Hertz pressure, Pa.
    load : float
        Normal load, N (the load at first yield is ``load (FIRST_YIELD_HARDNESS H / p0)^3``,
        p0 growing as the cube root of the load).
    materials : iterable of (label, Material)
        The bodies; those without ``hardness`` are skipped.
    load_key : str
        The case key of the load.

    Returns
    -------
    list of str
        One line per body past first yield (one line for bodies of the same material and
        hardness), starting ``pressure:``.
    """
    yielded: dict = {}
    for label, material in materials:
        hardness = getattr(material, "hardness", None)
        if hardness is not None and FIRST_YIELD_HARDNESS * hardness < p0 <= hardness:
            yielded.setdefault((hardness, material.name), []).append(label)
    lines = []
    for (hardness, name), labels in yielded.items():
        limit = FIRST_YIELD_HARDNESS * hardness
        lines.append(
            f"pressure: the Hertz peak p0 = {p0 / 1e9:.4g} GPa is {100 * p0 / hardness:.3g} % "
            f"of the hardness of {' and '.join(labels)} ({name}, {hardness / 1e9:.4g} GPa; limit "
            f"{FIRST_YIELD_HARDNESS:g} H = {limit / 1e9:.4g} GPa, first yield beneath the "
            "surface, p0 = 1.6 Y at depth 0.48 a with H = 2.8 Y): the body yields below the "
            "surface and keeps a dent, which the elastic answer does not have; for an elastic "
            f"contact keep {load_key} below {load * (limit / p0) ** 3:.4g} N, or read the "
            "result as an elastic estimate")
    return lines


#: Young's modulus below which a body is taken for an elastomer, Pa: it does not yield, and a
#: strain of several per cent leaves its linear law (rubbers 1-100 MPa; PTFE, nylon, PEEK
#: 0.4-4 GPa are polymers that do yield).
ELASTOMER_MODULUS = 0.1e9
#: p0 / E* above which a smooth contact with no hardness given gets a note (not a warning)
#: that first yield was not checked: hardened steel first yields near p0 / E* = 0.02-0.03,
#: PEEK against steel near 0.038 (p0 = 1.6 Y, Y about 100 MPa, E* = 4.21 GPa).
FIRST_YIELD_STRAIN = 0.02


def _soft_bodies(bodies) -> tuple[list[str], list[str]]:
    """Labels of the bodies without a hardness, and of those that are elastomers."""
    bodies = list(bodies or [])
    unchecked = [label for label, m in bodies if getattr(m, "hardness", None) is None]
    rubber = [label for label, m in bodies if m.youngs_modulus < ELASTOMER_MODULUS]
    return unchecked, rubber


def hertz_plasticity_note(p0: float, e_star: float, bodies) -> list[str]:
    """A note for a smooth Hertz contact past ``FIRST_YIELD_STRAIN`` E* with no hardness
    given and below the strain limit of :func:`hertz_validity`, which warns above it.

    A user's steel ball on PEEK (R = 10 mm, 200 N: p0 = 189.9 MPa, p0/E* = 0.045) is past
    PEEK's first yield (p0 = 1.6 Y near 160 MPa) and nothing said so. The note names the
    bodies to give a hardness; an elastomer (E below ``ELASTOMER_MODULUS``) does not yield
    and gets none.

    Parameters
    ----------
    p0 : float
        Maximum Hertz pressure, Pa.
    e_star : float
        Contact modulus, Pa.
    bodies : iterable of (label, Material)
        The bodies.

    Returns
    -------
    list of str
        At most one note.
    """
    unchecked, rubber = _soft_bodies(bodies)
    strain = p0 / e_star
    if rubber or len(unchecked) < len(list(bodies)) or not (
            FIRST_YIELD_STRAIN < strain <= HERTZ_STRAIN_LIMIT):
        return []
    return [f"p0/E* = {strain:.3g} (p0 = {format_quantity(p0, 'Pa')}, E* = "
            f"{format_quantity(e_star, 'Pa')}): "
            f"above {FIRST_YIELD_STRAIN:g}, where many bodies first yield beneath the surface "
            "(hardened steel near p0/E* = 0.02-0.03, PEEK on steel near 0.038: p0 = 1.6 Y), "
            "and plasticity was not checked (no hardness given); give "
            + " and ".join(f"{label}.hardness" for label in unchecked) + " to check it"]


def hertz_validity(a: float, radius: float, p0: float, e_star: float,
                   hardness_given: bool = False, load_key: str = "pressure.load",
                   bodies=None) -> list[str]:
    """Whether a Hertz contact is small and elastic enough for half-space theory.

    Two checks of the contact's own numbers, independent of the grid:

    - ``a / radius > HERTZ_SIZE_LIMIT``: the contact is not small against the bodies' radius
      of relative curvature (Hertz's assumption; the half-space solution, and every
      frictional closed form built on it, no longer holds);
    - with no hardness given, ``p0 / e_star > HERTZ_STRAIN_LIMIT``: strains of several per
      cent, at which metals and polymers yield, and nothing checked it.

    Parameters
    ----------
    a : float
        Contact semi-axis, m (for an ellipse the one with the larger ratio to its radius).
    radius : float
        Radius of relative curvature along that semi-axis, m.
    p0 : float
        Maximum Hertz pressure, Pa.
    e_star : float
        Contact modulus E*, Pa (:func:`asperity.materials.contact_modulus`).
    hardness_given : bool
        Whether every deformable body gives a hardness (the pressure is then checked against
        it by :func:`above_hardness`, and the strain check here is skipped).
    load_key : str
        The case key of the load, which the size check names.
    bodies : iterable of (label, Material), optional
        The bodies: the strain line names those without a hardness, and for an elastomer
        (E below ``ELASTOMER_MODULUS``, which does not yield) says that its law, not
        plasticity, is what such strains leave unchecked.

    Returns
    -------
    list of str
        At most two lines, each starting ``pressure:``.
    """
    lines = []
    size = a / radius
    if size > HERTZ_SIZE_LIMIT:
        lines.append(f"pressure: the Hertz contact semi-axis a = {a * 1e3:.4g} mm is "
                     f"{size:.3g} of the radius of relative curvature R = {radius * 1e3:.4g} mm "
                     f"(limit a/R = {HERTZ_SIZE_LIMIT:g}): Hertz's small-contact assumption "
                     "fails, and with it the half-space solution and its closed forms; reduce "
                     f"the load ({load_key}), or the body is too soft for half-space theory "
                     "(a large-deformation model is needed)")
    strain = p0 / e_star
    unchecked, rubber = _soft_bodies(bodies)
    if not hardness_given and strain > HERTZ_STRAIN_LIMIT:
        head = (f"pressure: p0/E* = {strain:.3g} (p0 = {format_quantity(p0, 'Pa')}, E* = "
                f"{format_quantity(e_star, 'Pa')}; limit {HERTZ_STRAIN_LIMIT:g}): strains of "
                "several per cent, ")
        if rubber:
            lines.append(head + f"which an elastomer ({' and '.join(rubber)}) takes without "
                         "yielding but not linearly: Hertz's linear elastic law no longer "
                         "holds (a rubber's stiffens or softens with strain), so read the "
                         "result as a small-strain estimate or reduce the load")
        else:
            keys = " and ".join(f"{label}.hardness" for label in unchecked) if unchecked \
                else "body1.hardness and body2.hardness"
            lines.append(head + "at which metals and polymers yield, and plasticity was not "
                         f"checked (no hardness given); give {keys} to check it, or reduce "
                         "the load")
    return lines
