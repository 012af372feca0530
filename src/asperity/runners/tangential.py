"""Runner of ``analysis = "tangential"``: partial slip under a tangential force and a moment.

Builds the pressure field the case describes (Hertz, uniform regions, or ``solve_normal``),
solves the frictional contact with :func:`asperity.contact.solve_tangential` at the applied
load and, with a ``[load_path]``, along the path with
:func:`asperity.contact.tangential_load_path` (compliance, centre of rotation, slip progression,
load sharing, energy per cycle). :func:`asperity.references.tangential_comparisons` sets the
result beside the closed forms that apply and the published numbers of the case's
``[reference]`` table.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from .. import diagnostics
from ..cases.doubts import unit_doubts
from ..cases.roughness import roughness_on_grid, undeformed_gap
from ..contact import hertz_point, solve_normal, solve_tangential
from ..contact.load_path import proportional_path, tangential_load_path
from ..contact.reference import (
    cattaneo_mindlin,
    gross_slip_moment_hertz,
    lubkin_stick_radius,
    lubkin_twist,
    masing_history,
)
from ..contact.spots import contact_spots
from ..contact.stick_zone import stick_zone
from ..errors import InputError
from ..formatting import format_quantity
from ..materials import contact_modulus, coupling_compliance
from ..references import fretting_cycle_comparisons, tangential_comparisons
from ..results import Outcome, variable

__all__ = ["run"]

_PER_BODY_NOTE = (
    "asperity's shift and rotation are those of body 1 relative to body 2 (distant points); "
    "for identical bodies each body moves half of it relative to the interface, which is what "
    "the book reports ('per body' rows).")


# --- the pressure field ------------------------------------------------------------------


class _Field:
    """Pressure (Pa) and friction coefficient on the grid, with what built them."""

    def __init__(self, x, y, pressure, mu, hertz=None, normal=None, roughness=None):
        self.x, self.y, self.pressure, self.mu = x, y, pressure, mu
        self.hertz, self.normal, self.roughness = hertz, normal, roughness

    @property
    def cell_area(self):
        return (self.x[1] - self.x[0]) * (self.y[1] - self.y[0])


def _length(value: float, unit: str) -> str:
    """A length in ``unit`` ("mm" or "um"), three significant digits, no float noise."""
    return f"{value * (1e3 if unit == 'mm' else 1e6):.3g}"


def _bound(value: float, unit: str, up: bool) -> str:
    """A bound in ``unit`` rounded outward to three significant digits (so that the value
    shown passes the check it is quoted for)."""
    v = value * (1e3 if unit == "mm" else 1e6)
    if v == 0.0:
        return "0"
    factor = 10.0 ** (2 - math.floor(math.log10(abs(v))))
    v = (math.ceil(v * factor) if up else math.floor(v * factor)) / factor
    return f"{v:.3g}"


def _check_domain(grid, axis: str, coord, half: float) -> None:
    """Refuse a domain along ``axis`` that leaves part of the contact (-half, half) out,
    naming the key that does: ``{axis}_start`` when the given start lies inside the contact,
    else ``{axis}_extent`` (too short from its start, or centred and narrower than the
    contact)."""
    edge = 0.5 * (coord[1] - coord[0])
    lo, hi = coord[0] - edge, coord[-1] + edge
    slack = 1e-9 * edge
    if lo <= -half + slack and hi >= half - slack:
        return
    unit = "mm" if max(abs(lo), abs(hi), half) >= 1e-4 else "um"
    shown = "µm" if unit == "um" else unit
    start = getattr(grid, f"{axis}_start")
    what = (f"domain {_length(lo, unit)} to {_length(hi, unit)} {shown} does not cover the "
            f"contact {_length(-half, unit)} to {_length(half, unit)} {shown}")
    if start is not None and lo > -half + slack:
        raise InputError(f"grid.{axis}_start", "", problem=(
            f"{what}; set {axis}_start <= {_bound(-half, unit, False)} {shown} or leave it out"))
    need = half - lo if start is not None else 2.0 * half
    raise InputError(f"grid.{axis}_extent", "", problem=(
        f"{what}; set {axis}_extent >= {_bound(need, unit, True)} {shown} or leave it out"))


def _hertz_field(case, body1, body2):
    """Hertz pressure at the cell centres, scaled so that the discrete load is the applied one."""
    spec = case.pressure
    rx, ry = spec.radii()
    h = hertz_point(spec.load, rx, ry, body1, body2)
    margin = 1.05 if spec.source == "hertz" else 1.5
    x, y = case.grid.coordinates((-margin * h.a, margin * h.a, -margin * h.b, margin * h.b))
    _check_domain(case.grid, "x", x, h.a)
    _check_domain(case.grid, "y", y, h.b)
    X, Y = np.meshgrid(x, y, indexing="ij")
    if spec.source == "normal":
        rough = None if spec.roughness is None else roughness_on_grid(
            spec.roughness, x, y, "pressure.roughness")
        gap = undeformed_gap(rx, ry, x, y, None if rough is None else rough.heights)
        res = solve_normal(gap, x, y, body1, body2, load=spec.load, tol=spec.normal_tolerance)
        return _Field(x, y, res.pressure, np.full(X.shape, case.mu), h, res, rough)
    p = h.pressure(X, Y)
    total = p.sum() * (x[1] - x[0]) * (y[1] - y[0])
    if not total > 0:
        raise InputError("grid", "cells inside the Hertz contact (refine nx, ny)")
    return _Field(x, y, p * spec.load / total, np.full(X.shape, case.mu), h)


def _uniform_field(case):
    """Uniform pressure (and friction) per region; every region must cover a cell.

    A region's cells (those whose centres lie inside it) cover a staircase of its shape; its
    pressure is scaled by area / (cells x cell area) so that it carries its load p A exactly
    (a circle of radius 3 mm on 0.094 mm cells covered 0.33 % too much; rectangles on whole
    cells are not changed). Returns the field and the scale factor of each region.
    """
    spec = case.pressure
    x, y = case.grid.coordinates(spec.bounding_box())
    X, Y = np.meshgrid(x, y, indexing="ij")
    cell = (x[1] - x[0]) * (y[1] - y[0])
    p, mu = np.zeros(X.shape), np.full(X.shape, case.mu)
    scales = []
    for k, (region, center) in enumerate(zip(spec.regions, spec.centers(), strict=True)):
        m = region.mask(X, Y, center)
        if not m.any():
            raise InputError(f"pressure.regions[{k}]", "a region covering at least one grid "
                                                        "cell (refine grid.nx / ny)")
        scales.append(region.area() / (np.count_nonzero(m) * cell))
        p[m] = region.pressure * scales[-1]
        if region.mu is not None:
            mu[m] = region.mu
    return _Field(x, y, p, mu), scales


def _region_notes(scales) -> list[str]:
    """Where a region's cells cover more or less than its area (:func:`_uniform_field`)."""
    off = [(k, s) for k, s in enumerate(scales) if abs(s - 1.0) > 1e-9]
    if not off:
        return []
    each = ", ".join(f"pressure.regions[{k}] by {s:.5g}" for k, s in off)
    return [f"The cells of a region cover a staircase of its shape; its pressure is scaled so "
            f"that it carries its load, pressure times area ({each}); the summary's normal "
            "load is the regions' exact load."]


def _field(case, body1, body2) -> tuple[_Field, list[float]]:
    """The pressure field and, for uniform regions, each region's scale factor."""
    if case.pressure.source == "uniform":
        return _uniform_field(case)
    return _hertz_field(case, body1, body2), []


# --- outputs --------------------------------------------------------------------------------


#: Below this fraction of its scale a summary value is round-off and reported as 0 (a
#: force's twist of 5.6e-19 rad beside a shift of 0.9 um over a 0.2 mm contact).
ROUND_OFF = 1e-9


def _zeroed(value: float, scale: float) -> float:
    """``value``, or 0.0 when it is round-off of zero at ``scale`` (:data:`ROUND_OFF`)."""
    value = float(value)
    return 0.0 if abs(value) <= ROUND_OFF * scale else value


#: Most contact regions whose forces, capacity and stick fraction are listed one by one in
#: the summary: a rough normal solve's contact is a region per spot (a user's rough ball had
#: 104, five rows each); beyond it only their number is given, and the map is in result.nc.
REGION_ROWS = 10


def _summary(case, fld, res, applied, identical):
    contact_area = float((fld.pressure > 0).sum() * fld.cell_area)
    # equivalent contact radius: the length scale (the domain's if nothing touches)
    size = math.sqrt(contact_area / math.pi) or float(np.ptp(fld.x) + np.ptp(fld.y))
    force, moment = math.hypot(*applied[:2]), abs(applied[2])
    force_scale, moment_scale = force + moment / size, force * size + moment
    s = {
        "normal_load_n": float(fld.pressure.sum() * fld.cell_area),
        "contact_area_m2": contact_area,
        "friction_capacity_n": float((fld.mu * fld.pressure).sum() * fld.cell_area),
        "force_x_n": applied[0], "force_y_n": applied[1], "moment_nm": applied[2],
        "gross_slip": bool(res.gross_slip),
        "load_capacity": float(res.load_capacity),
        "stick_fraction": float(res.stick.sum() / max((res.labels > 0).sum(), 1)),
    }
    zone = None if res.gross_slip else stick_zone(res.stick, fld.x, fld.y)
    if zone is not None:
        s.update(stick_area_m2=zone.area, stick_parts=zone.parts)
    if zone is not None and zone.elliptical and fld.roughness is None:
        # one ellipse (Mindlin's, or an off-centre one under force and moment): its centre and
        # semi-axes; a radius only for a circle. (A rough contact's stick zone is scattered
        # over its spots, two pads' over the pads: its area and parts say what it is.)
        s.update(stick_center_x_m=_zeroed(zone.centre[0], size),
                 stick_center_y_m=_zeroed(zone.centre[1], size),
                 stick_semi_axis_x_m=zone.semi_axes[0], stick_semi_axis_y_m=zone.semi_axes[1])
        if zone.circular:
            s["stick_radius_m"] = zone.radius
    # undefined quantities are left out, not NaN: the rigid motion in gross slip, the centre
    # of a motion without rotation; round-off (a force's twist, a moment's shift) is 0
    if not res.gross_slip:
        shift = math.hypot(*res.shift)
        motion = shift + abs(res.rotation) * size  # the largest displacement it causes
        s.update(shift_x_m=_zeroed(res.shift[0], motion), shift_y_m=_zeroed(res.shift[1], motion),
                 shift_m=_zeroed(shift, motion),
                 rotation_rad=_zeroed(res.rotation, motion / size))
        if identical:
            s["shift_per_body_m"] = 0.5 * s["shift_m"]
            s["rotation_per_body_rad"] = 0.5 * s["rotation_rad"]
    if np.all(np.isfinite(res.centre_of_rotation)):
        far = max(size, float(np.max(np.abs(res.centre_of_rotation))))
        s.update(center_of_rotation_x_m=_zeroed(res.centre_of_rotation[0], far),
                 center_of_rotation_y_m=_zeroed(res.centre_of_rotation[1], far))
    if math.isfinite(res.load_capacity):
        if any(applied[:2]):
            s["gross_slip_force_n"] = float(res.load_capacity * force)
        if applied[2] != 0.0 and case.loading.rotation == "free":
            s["gross_slip_moment_nm"] = float(res.load_capacity * moment)
    if res.gross_slip:
        s.update(excess_force_x_n=_zeroed(res.excess[0], force_scale),
                 excess_force_y_n=_zeroed(res.excess[1], force_scale),
                 excess_moment_nm=_zeroed(res.excess[2], moment_scale))
    if case.loading.rotation == "fixed":
        s["reaction_moment_nm"] = _zeroed(res.reaction_moment, moment_scale)
    for reg in res.regions if len(res.regions) <= REGION_ROWS else ():
        k = reg.label
        s.update({f"region_{k}_force_x_n": _zeroed(reg.force[0], force_scale),
                  f"region_{k}_force_y_n": _zeroed(reg.force[1], force_scale),
                  f"region_{k}_moment_nm": _zeroed(reg.moment, moment_scale),
                  f"region_{k}_capacity_n": float(reg.capacity),
                  f"region_{k}_stick_fraction": float(reg.stick_fraction)})
    s.update(regions=len(res.regions), iterations=int(res.iterations),
             residual=float(res.residual), convolutions=int(res.convolutions),
             converged=bool(res.converged))
    # the reference point of the moment (loading.center, or the centre of the normal load)
    far = max(size, float(np.max(np.abs(res.centre))))
    s.update(moment_center_x_m=_zeroed(res.centre[0], far),
             moment_center_y_m=_zeroed(res.centre[1], far))
    return s


def _dataset(case, fld, res, path):
    q = res.traction
    xy = ("x", "y")
    data = {
        "pressure": variable(xy, fld.pressure, "Pa", "normal pressure"),
        "mu": variable(xy, fld.mu, "1", "coefficient of friction"),
        "traction_x": variable(xy, q[0], "Pa", "tangential traction on body 2, x"),
        "traction_y": variable(xy, q[1], "Pa", "tangential traction on body 2, y"),
        "traction_magnitude": variable(xy, np.hypot(q[0], q[1]), "Pa",
                                       "magnitude of the tangential traction"),
        "stick": variable(xy, res.stick.astype("i1"), "1", "stick indicator",
                          flag_values=[0, 1], flag_meanings="slip_or_open stick"),
        "slip_x": variable(xy, res.slip[0], "1" if res.gross_slip else "m",
                           "slip of body 1 vs body 2, x" + (" (direction)" if res.gross_slip
                                                           else "")),
        "slip_y": variable(xy, res.slip[1], "1" if res.gross_slip else "m",
                           "slip of body 1 vs body 2, y" + (" (direction)" if res.gross_slip
                                                           else "")),
        "region": variable(xy, res.labels.astype("i4"), "1",
                           "connected contact region (0 outside the contact)"),
    }
    coords = {"x": variable("x", fld.x, "m", "x (first in-plane direction)"),
              "y": variable("y", fld.y, "m", "y (second in-plane direction)")}
    if path is not None:
        st, rg = ("step",), ("step", "region_index")
        coords["step"] = variable("step", np.arange(1, len(path.loads) + 1), "1", "load step")
        coords["region_index"] = variable("region_index",
                                          np.arange(1, path.region_moment.shape[1] + 1), "1",
                                          "contact region label")
        data.update({
            "path_force_x": variable(st, path.loads[:, 0], "N", "applied force x"),
            "path_force_y": variable(st, path.loads[:, 1], "N", "applied force y"),
            "path_moment": variable(st, path.loads[:, 2], "N m", "applied moment"),
            "path_shift_x": variable(st, path.shift[:, 0], "m", "relative rigid shift x"),
            "path_shift_y": variable(st, path.shift[:, 1], "m", "relative rigid shift y"),
            "path_rotation": variable(st, path.rotation, "rad", "relative rigid rotation"),
            "path_center_x": variable(st, path.centre_of_rotation[:, 0], "m",
                                      "centre of rotation x"),
            "path_center_y": variable(st, path.centre_of_rotation[:, 1], "m",
                                      "centre of rotation y"),
            "path_stick_fraction": variable(st, path.stick_fraction, "1", "stuck area share"),
            "path_work": variable(st, path.work, "J", "cumulative work of the applied loads"),
            "path_reaction_moment": variable(st, path.reaction_moment, "N m",
                                             "moment of the fixture (rotation fixed)"),
            "path_region_force_x": variable(rg, path.region_force[:, :, 0], "N",
                                            "force carried by each region, x"),
            "path_region_force_y": variable(rg, path.region_force[:, :, 1], "N",
                                            "force carried by each region, y"),
            "path_region_moment": variable(rg, path.region_moment, "N m",
                                           "moment carried by each region"),
            "path_stick": variable(("step", "x", "y"), path.stick.astype("i1"), "1",
                                   "stick indicator per step"),
        })
    return xr.Dataset(data, coords=coords, attrs={
        "title": case.title, "analysis": "tangential", "Conventions": "CF-1.8",
        "source": "asperity", "method": res.method, "rotation": case.loading.rotation,
        "iterations": res.iterations, "converged": int(res.converged)})


def _figures(case, fld, res, path, body1, body2):
    from ..plotting import tangential as tplot

    x, y = fld.x, fld.y
    figs = {"traction": (lambda: tplot.traction_map(res, x, y, case.title),
                         "Traction magnitude (contours), direction (arrows), stick/slip border "
                         "(dashed) and centre of rotation (+)." + (
                             " Gross slip: the full-slip traction." if res.gross_slip else ""))}
    if case.pressure.source == "normal":
        from ..plotting.normal import pressure_map

        figs["pressure"] = (lambda: pressure_map(x, y, fld.pressure, fld.pressure > 0),
                            "Normal pressure from solve_normal, held fixed.")
    if path is None:
        return figs
    closed = _mindlin_compliance(case, fld, path, body1, body2)
    figs["compliance"] = (lambda: tplot.compliance_curves(path, closed_form=closed),
                          "Compliance along the load path: force vs relative rigid shift and "
                          "moment vs relative twist" + (
                              f", with {closed[2]} (dashed)" if closed is not None else "")
                          + ("; the gross-slip load dotted" if path.gross_slip_step >= 0
                             else "") + ".")
    fraction, label = _path_fraction(case, fld, res, path)
    figs["slip_progression"] = (
        lambda: tplot.slip_progression(path, x, y, load_fraction=fraction,
                                       fraction_label=label),
        "Stick-zone borders along the first loading, coloured by the load"
        + (f" ({label})" if label else "") + ".")
    if path.region_moment.shape[1] > 1:  # one region carries the whole load: nothing to share
        figs["load_sharing"] = (lambda: tplot.load_sharing(path),
                                "Force and moment carried by each contact region along the "
                                "path.")
    if case.loading.rotation == "free" and np.any(np.isfinite(path.centre_of_rotation)):
        figs["center_of_rotation"] = (
            lambda: tplot.centre_of_rotation_curve(path, res.centre),
            "Centre of rotation relative to the moment's reference point vs the moment.")
    return figs


def _uniform_mu(case, fld) -> bool:
    return bool(np.all(fld.mu == case.mu))


def _centred_moment(case) -> float:
    """The moment about a Hertz contact's centre that twists it (0 with the rotation fixed):
    what the closed forms of a force alone need to be zero."""
    if case.loading.rotation == "fixed":
        return 0.0
    return case.loading.moment_about_origin()


def _circular_hertz(case, fld) -> bool:
    h = fld.hertz
    return (case.pressure.source == "hertz" and h is not None
            and abs(h.a - h.b) <= 1e-9 * h.a and _uniform_mu(case, fld))


def _path_fraction(case, fld, res, path):
    """Each path step's load over the gross-slip load along the applied load, and its label
    (``Q / (mu P)`` for a force alone); ``(None, None)`` when the capacity is unknown."""
    applied = np.array([*case.loading.vector(), case.loading.moment])
    t = float(res.load_capacity)
    j = int(np.argmax(np.abs(applied)))
    if not (math.isfinite(t) and t > 0 and applied[j] != 0):
        return None, None
    fraction = path.loads[:, j] / (t * applied[j])
    force, moment = math.hypot(*applied[:2]), applied[2]
    if moment == 0.0:
        mu_p = float((fld.mu * fld.pressure).sum() * fld.cell_area)
        label = "Q / (mu P)" if math.isclose(t * force, mu_p, rel_tol=1e-6) else "Q / Q_gross"
    elif force == 0.0:
        label = "M / M_gross"
    else:
        label = "load / gross-slip load"
    return fraction, label


def _mindlin_compliance(case, fld, path, body1, body2):
    """The closed-form compliance curve of the path (shift, force along the largest force,
    label) where it applies: a circular Hertz contact of similar bodies (beta = 0) under a
    force alone; else None."""
    if (not _circular_hertz(case, fld) or _centred_moment(case) != 0.0
            or abs(_dundurs_beta(body1, body2)) >= 1e-3):
        return None
    h = fld.hertz
    force = np.hypot(path.loads[:, 0], path.loads[:, 1])
    e = path.loads[np.argmax(force), :2] / force.max()
    shift, along = masing_history(path.loads[:, :2] @ e, h.load, case.mu, h.a, body1, body2)
    reversed_ = case.load_path.history != "load"
    label = "Cattaneo-Mindlin" + (" / Mindlin-Deresiewicz (Masing)" if reversed_ else "")
    return shift, along, label


#: Semi-axis ratio of a Hertz ellipse above which a run says it is not a line contact.
LONG_ELLIPSE = 5.0


def _long_ellipse_note(case, fld, res) -> list[str]:
    """A long Hertz ellipse under a force alone (a user's stand-in for a cylinder): its stick
    zone follows Mindlin's ellipse, c/a = (1 - Q/(mu P))^(1/3) (Johnson sec. 7.2), not
    Cattaneo's 2-D strip, sqrt(1 - Q/(mu P)); there is no line (2-D) tangential contact."""
    h = fld.hertz
    force = math.hypot(*case.loading.vector())
    if (case.pressure.source != "hertz" or h is None or res.gross_slip or force == 0.0
            or _centred_moment(case) != 0.0 or max(h.a, h.b) < LONG_ELLIPSE * min(h.a, h.b)):
        return []
    ratio = force / float((fld.mu * fld.pressure).sum() * fld.cell_area)
    zone = stick_zone(res.stick, fld.x, fld.y)
    if zone is None or not zone.elliptical:
        return []
    # the stick ellipse's semi-axis along the contact's short axis, over that axis
    measured, short = ((zone.semi_axes[0] / h.a, fld.x) if h.a < h.b
                       else (zone.semi_axes[1] / h.b, fld.y))
    return [f"A long ellipse (semi-axes {format_quantity(h.a, 'm')} by "
            f"{format_quantity(h.b, 'm')}) is not a line contact: its stick zone follows "
            f"Mindlin's ellipse, c/a = (1 - Q/(mu P))^(1/3) = {(1 - ratio) ** (1 / 3):.3g} at "
            f"Q = {ratio:.3g} mu P (here {measured:.3g} across the short axis, "
            f"{format_quantity(short[1] - short[0], 'm')} cells), not Cattaneo's 2-D strip, "
            f"sqrt(1 - Q/(mu P)) = {math.sqrt(1 - ratio):.3g}, which asperity does not "
            "solve (no line contact in a tangential case)."]


def _spot_warnings(case, fld) -> list[str]:
    """A generated roughness longer than the grid (:func:`asperity.diagnostics.roughness_extent`)
    and a rough normal solve's contact spots of a few cells
    (:func:`asperity.diagnostics.spot_resolution`): its pressures, and the stick and slip on
    each spot, are then set by the mesh."""
    rough = fld.roughness
    if rough is None:
        return []
    spots = contact_spots(fld.pressure > 0, fld.pressure, fld.cell_area)
    spec = case.pressure.roughness
    free = spec.kind == "self-affine" and spec.short_cutoff is None
    extent = diagnostics.roughness_extent("pressure.roughness", fld.x, fld.y,
                                          **spec.longest_lengths())
    return extent + diagnostics.spot_resolution(
        spots, fld.x, fld.y, file_spacing=rough.file_spacing,
        cutoff_key="pressure.roughness.short_cutoff" if free else None)


def _file_warnings(fld) -> list[str]:
    """A measured roughness file's doubts (:func:`asperity.diagnostics.measured_file_on_grid`)."""
    rough = fld.roughness
    if rough is None:
        return []
    return diagnostics.measured_file_on_grid("pressure.roughness", rough, fld.x, fld.y)


def _dundurs_beta(body1, body2) -> float:
    """Dundurs' beta of the pair, E* [(1 - 2 nu1)/G1 - (1 - 2 nu2)/G2] / 4."""
    return contact_modulus(body1, body2) * coupling_compliance(body1, body2) / 4.0


#: |beta| / mu above which the coupling of dissimilar bodies is a warning, not a note.
COUPLING_WARNING = 0.1


def _percent(value: float, reference: float) -> str:
    return f"{100.0 * (value / reference - 1.0):+.2g} %"


def _closed_forms(case, fld, res, body1, body2) -> dict:
    """The summary's closed forms of this load on a circular Hertz pressure with one mu,
    without gross slip: Cattaneo-Mindlin's shift and stick radius under a force alone
    (Johnson eq. 7.42), Lubkin's twist and stick radius under a moment alone about the
    centre (Johnson eq. 7.50), as the comparison rows give them; none otherwise. A study
    draws them beside the solver's shift, rotation and stick radius
    (:data:`asperity.report.REFERENCES`)."""
    if res.gross_slip or not _circular_hertz(case, fld):
        return {}
    h, mu = fld.hertz, case.mu
    force, moment = math.hypot(*case.loading.vector()), _centred_moment(case)
    if moment == 0.0 and 0.0 < force < mu * h.load:
        cm = cattaneo_mindlin(h.load, force, mu, h.a, body1, body2)
        return {"cattaneo_mindlin_shift_m": cm.shift,
                "cattaneo_mindlin_stick_radius_m": cm.stick_radius}
    if force == 0.0 and case.loading.rotation == "free" and 0.0 < abs(moment) < (
            gross_slip_moment_hertz(mu, h.load, h.a)):
        c = lubkin_stick_radius(abs(moment), h.a, mu, h.p_max)
        twist = lubkin_twist(c, h.a, mu, h.p_max, body1, body2)
        return {"lubkin_rotation_rad": math.copysign(twist, moment),
                "lubkin_stick_radius_m": c}
    return {}


def _coupling_effect(case, fld, res, body1, body2) -> str:
    """What the coupling does to this solution against the uncoupled closed form that applies
    (:func:`_closed_forms`: Cattaneo-Mindlin under a force, Lubkin under a moment, circular
    Hertz), in words."""
    closed = _closed_forms(case, fld, res, body1, body2)
    stick = math.sqrt(res.stick.sum() * fld.cell_area / math.pi)
    if "cattaneo_mindlin_shift_m" in closed:
        ref, c = closed["cattaneo_mindlin_shift_m"], closed["cattaneo_mindlin_stick_radius_m"]
        shift = math.hypot(*res.shift)
        force = math.hypot(*case.loading.vector())
        text = (f"at Q = {force / (case.mu * fld.hertz.load):.2g} mu P the shift is "
                f"{format_quantity(shift, 'm')}, {_percent(shift, ref)} from Mindlin's "
                f"{format_quantity(ref, 'm')}")
    elif "lubkin_rotation_rad" in closed:
        ref, c = abs(closed["lubkin_rotation_rad"]), closed["lubkin_stick_radius_m"]
        twist = abs(res.rotation)
        text = (f"the twist is {format_quantity(twist, 'rad')}, {_percent(twist, ref)} from "
                f"Lubkin's {format_quantity(ref, 'rad')}")
    else:
        return ""
    if stick > 0.0:
        text += (", the stick zone's equivalent radius sqrt(A/pi) "
                 f"{format_quantity(stick, 'm')}, {_percent(stick, c)} from "
                 f"{format_quantity(c, 'm')}")
    return text


def _coupling(case, fld, res, body1, body2) -> tuple[list[str], list[str]]:
    """Dissimilar bodies: the pressure's tangential displacement is in the solution, not in
    the closed forms it is compared with (docs/tangential.md, "Dissimilar materials").

    Returns (notes, warnings): a warning when |beta|/mu > :data:`COUPLING_WARNING`, else a
    note; the effect on this solution is computed for the actual pair.
    """
    beta = _dundurs_beta(body1, body2)
    if abs(beta) < 1e-3:
        return [], []
    ratio = abs(beta) / float(np.max(fld.mu))
    effect = _coupling_effect(case, fld, res, body1, body2)
    here = f"; here {effect}" if effect else ""
    what = ("the solution includes the tangential displacement of the whole pressure "
            "(Goodman), applied in one step from zero, which Cattaneo-Mindlin and Lubkin "
            "(beta = 0) leave out, so it differs from their closed forms by design")
    if ratio > COUPLING_WARNING:
        return [], [f"body1, body2: dissimilar materials, Dundurs beta = {beta:.3g}, "
                    f"|beta|/mu = {ratio:.2g} (limit {COUPLING_WARNING:g}): {what}{here}; "
                    "compare with the closed forms only for similar materials (beta = 0), and "
                    "for a joint clamped first and loaded tangentially after treat both as "
                    "estimates (neither follows the history of the normal loading)"]
    return [f"Dissimilar bodies (Dundurs beta = {beta:.3g}, |beta|/mu = {ratio:.2g}): {what}, "
            f"by an amount set by beta/mu{here}."], []


def _gross_slip_warning(case, fld, res, applied) -> list[str]:
    """The applied load beyond the friction capacity: its ratio to the gross-slip load and
    what to check (a ratio above 3 is more likely a wrong unit than a design)."""
    if not res.gross_slip:
        return []
    force, moment = math.hypot(*applied[:2]), abs(applied[2])
    t = float(res.load_capacity)
    ratio = 1.0 / t if t > 0 else math.inf
    free = case.loading.rotation == "free"
    keys = [k for k, on in (("loading.force", force > 0), ("loading.moment",
                                                           moment > 0 and free)) if on]
    mu_p = float((fld.mu * fld.pressure).sum() * fld.cell_area)
    if force > 0 and "loading.moment" not in keys:
        cap = (", the friction capacity mu P" if math.isclose(t * force, mu_p, rel_tol=1e-6)
               else f" (mu P = {format_quantity(mu_p, 'N')})")
        what = (f"the force {format_quantity(force, 'N')} is {ratio:.3g} times the gross-slip "
                f"force {format_quantity(t * force, 'N')}{cap}")
        hint = "check the force and its unit (kN typed as N?), mu and the load"
    elif force == 0:
        cap = ""
        if _circular_hertz(case, fld):
            gs = gross_slip_moment_hertz(case.mu, fld.hertz.load, fld.hertz.a)
            cap = f", 3 pi mu P a / 16 = {format_quantity(gs, 'N*m')} for this Hertz circle"
        what = (f"the moment {format_quantity(moment, 'N*m')} is {ratio:.3g} times the "
                f"gross-slip moment {format_quantity(t * moment, 'N*m')}{cap}")
        hint = "check the moment and its unit (N m typed for N mm?), mu and the load"
    else:
        what = (f"the force {format_quantity(force, 'N')} with the moment "
                f"{format_quantity(moment, 'N*m')} is {ratio:.3g} times the gross-slip load "
                f"along it ({format_quantity(t * force, 'N')} with "
                f"{format_quantity(t * moment, 'N*m')}; mu P = {format_quantity(mu_p, 'N')})")
        hint = "check the force, the moment and their units, mu and the load"
    if ratio <= 3.0:
        hint = (f"for partial slip lower {' and '.join(keys)} below the gross-slip load, or "
                "raise mu or the normal load")
    return [f"{', '.join(keys)}: {what} (limit: at most the gross-slip load): friction "
            "cannot carry the load, the contact slides as a whole (gross slip): there is no "
            f"shift, twist or stick zone, only the full-slip traction; {hint}"]


def _validity_warnings(case, fld, body1, body2) -> list[str]:
    """Hertz's assumptions (small contact, elastic strains) for a Hertz-built pressure
    (:func:`asperity.diagnostics.hertz_validity`), and first yield beneath the surface of a
    body with a hardness (:func:`asperity.diagnostics.hertz_first_yield`)."""
    h = fld.hertz
    if h is None:
        return []
    rx, ry = case.pressure.radii()
    a, radius = max(((h.a, rx), (h.b, ry)), key=lambda ar: ar[0] / ar[1])
    bodies = [("body1", body1), ("body2", body2)]
    lines = diagnostics.hertz_validity(a, radius, h.p_max, h.modulus,
                                       diagnostics.hardness_given(bodies), bodies=bodies)
    if fld.roughness is None:  # a rough normal solve's pressure is not Hertz's
        lines += diagnostics.hertz_first_yield(h.p_max, h.load, bodies)
    return lines


def _path_summary(path):
    # steps count from 1, as the step coordinate of result.nc; no gross slip: no step
    out = {"path_steps": len(path.loads), "path_gross_slip": bool(path.gross_slip_step >= 0)}
    if path.gross_slip_step >= 0:
        out["path_gross_slip_step"] = int(path.gross_slip_step) + 1
    out.update(path_iterations=int(path.iterations), path_converged=bool(path.converged))
    if math.isfinite(path.dissipated_energy):  # a closed cycle
        out["path_dissipated_energy_j"] = float(path.dissipated_energy)
        out.update(_loop_widths(path))
    return out


def _loop_widths(path) -> dict:
    """The widths of a closed loop where it passes through zero load on its way down and
    back up: the relative shift along the largest force (``path_loop_width_m``) and the
    twist (``path_loop_twist_width_rad``), for the components the path applies; none when
    the loop does not pass through zero twice."""
    loads = path.loads
    scale = np.abs(loads).max(axis=0) + 1e-300
    last = np.all(np.abs(loads - loads[-1]) <= 1e-9 * scale, axis=1)
    start = int(np.argmax(last))  # the loop: from the first visit of the last load
    zero = np.flatnonzero(np.all(np.abs(loads) <= 1e-9 * scale, axis=1))
    zero = zero[zero >= start]
    if len(zero) < 2:
        return {}
    i, j = zero[:2]
    out = {}
    force = np.hypot(loads[:, 0], loads[:, 1])
    if force.max() > 0:
        e = loads[np.argmax(force), :2] / force.max()
        out["path_loop_width_m"] = float(abs((path.shift[i] - path.shift[j]) @ e))
    if np.any(loads[:, 2] != 0):
        out["path_loop_twist_width_rad"] = float(abs(path.rotation[i] - path.rotation[j]))
    return out


def _path_note(case, path, planned: int) -> list[str]:
    """Where a load path reached gross slip (on purpose with load_path.scale > 1)."""
    if path.gross_slip_step < 0:
        return []
    t = float(path.final.load_capacity)
    over = f", {1.0 / t:.3g} times the gross-slip load there" if t > 0 else ""
    return [f"The load path reaches gross slip at step {path.gross_slip_step + 1} of {planned} "
            f"(steps counted from 1, as result.nc's step coordinate){over} "
            f"(load_path.scale = {case.load_path.scale:g}); the path stops there: that step has "
            "the full-slip traction and no shift."]


def run(case, progress=None) -> Outcome:
    """Solve the case's frictional contact (and its load path); compare with references."""
    body1, body2 = case.body1.material(), case.body2.material()
    # the same steel given as "30457.92 ksi" and "30.45792e6 psi" differs in the last digit
    identical = all(math.isclose(getattr(body1, k), getattr(body2, k), rel_tol=1e-9)
                    for k in ("youngs_modulus", "poisson_ratio"))
    fld, scales = _field(case, body1, body2)
    notes = [] if fld.roughness is None else list(fld.roughness.notes)
    notes += _region_notes(scales)
    if fld.normal is not None and not fld.normal.converged:
        notes.append(f"The normal-contact solve did not converge in {fld.normal.iterations} "
                     "iterations; the pressure, and everything below, is not trustworthy.")
    fx, fy = case.loading.vector()
    applied = (fx, fy, case.loading.moment)
    callback = None
    if progress is not None:
        def callback(iteration, residual):
            progress(iteration, None, f"iteration {iteration}, residual {residual:.1e}")
    res = solve_tangential(fld.pressure, fld.x, fld.y, fld.mu, body1, body2, force=(fx, fy),
                           moment=applied[2], centre=case.loading.center, method=case.method,
                           tol=case.tolerance, callback=callback,
                           rotation=case.loading.rotation)
    path = None
    if case.load_path is not None:
        lp = case.load_path
        loads = proportional_path((lp.scale * fx, lp.scale * fy), lp.scale * applied[2],
                                  lp.steps, cycle=lp.history == "cycle",
                                  unload=lp.history == "unload")
        step_cb = None
        if progress is not None:
            def step_cb(k, _res):
                progress(k + 1, len(loads), f"load step {k + 1} of {len(loads)}")
        path = tangential_load_path(fld.pressure, fld.x, fld.y, fld.mu, body1, body2, loads,
                                    centre=case.loading.center, tol=case.tolerance,
                                    callback=step_cb, rotation=case.loading.rotation)
        planned = len(loads)
    summary = _summary(case, fld, res, applied, identical)
    summary.update(_closed_forms(case, fld, res, body1, body2))
    if path is not None:
        summary.update(_path_summary(path))
    free = case.loading.rotation == "free"
    comparisons = tangential_comparisons(case, res, fld.x, fld.y, fld.mu, body1, body2,
                                         fld.hertz)
    if path is not None and _mindlin_compliance(case, fld, path, body1, body2) is not None and (
            case.load_path.history == "cycle"):
        direction = np.array([fx, fy]) / math.hypot(fx, fy)
        comparisons += fretting_cycle_comparisons(
            path.loads[:, :2] @ direction, path.dissipated_energy,
            summary.get("path_loop_width_m"), fld.hertz, case.mu, body1, body2,
            max(fld.x[1] - fld.x[0], fld.y[1] - fld.y[0]))
    if case.reference is not None and case.reference.note:
        notes.append(case.reference.note)
    if identical:
        notes.append(_PER_BODY_NOTE)
    coupling_notes, coupling_warnings = _coupling(case, fld, res, body1, body2)
    notes += coupling_notes
    if res.gross_slip:
        notes.append(
            f"Gross slip: friction carries at most {res.load_capacity:.4g} times the applied "
            f"load; the excess is Fx {summary['excess_force_x_n']:.4g} N, Fy "
            f"{summary['excess_force_y_n']:.4g} N, M {summary['excess_moment_nm']:.4g} N m. "
            "The traction shown is the full-slip traction.")
    if path is not None:
        notes += _path_note(case, path, planned)
    if math.hypot(fx, fy) > 0:
        notes.append(f"The force acts at {math.degrees(case.loading.direction):.4g} deg from +x "
                     "(loading.direction); the moment is about "
                     + ("loading.center" if case.loading.center is not None
                        else "the centre of the normal load")
                     + f" ({summary['moment_center_x_m']:.4g}, "
                       f"{summary['moment_center_y_m']:.4g}) m"
                     + (f"; about the Hertz contact's centre the load has the moment "
                        f"{format_quantity(case.loading.moment_about_origin(), 'N*m')}, which "
                        "twists it" if fld.hertz is not None and free
                        and case.loading.moment_about_origin() != case.loading.moment else "")
                     + ".")
    if not free:
        notes.append("Rotation is fixed (loading.rotation): body 1 translates only, the moment "
                     "equation is dropped and the fixture supplies the reaction moment "
                     f"{res.reaction_moment:.4g} N m.")
    if case.method == "lp":
        notes.append("Method lp: Seireg's predetermined traction directions (exact for pure "
                     "torsion about the true centre and pure translation; an approximation "
                     "otherwise).")
    notes += _long_ellipse_note(case, fld, res)
    if fld.hertz is not None and fld.roughness is None:  # first yield unchecked (a note)
        notes += diagnostics.hertz_plasticity_note(fld.hertz.p_max, fld.hertz.modulus,
                                                   [("body1", body1), ("body2", body2)])
    if len(res.regions) > REGION_ROWS:
        notes.append(f"The contact has {len(res.regions)} separate regions (a rough contact's "
                     f"spots); their forces are not listed one by one (only up to {REGION_ROWS} "
                     "are): the variable region of result.nc maps them, and the traction and "
                     "stick variables give each region's share.")
    if case.pressure.source == "hertz":
        notes.append("Hertz pressure sampled at the cell centres and scaled so that the "
                     "discrete load equals the applied load.")
    converged = res.converged and (path is None or path.converged) and (
        fld.normal is None or fld.normal.converged)
    if not res.converged:
        notes.append(f"The solver did not converge in {res.iterations} iterations (residual "
                     f"{res.residual:.2e}); the numbers above are not trustworthy."
                     + (f" Why: {res.reason}." if res.reason else ""))
    if path is not None and not path.converged:
        notes.append("A step of the load path did not converge; the path is not trustworthy.")
    # prescribed pressures (Hertz, uniform regions) lie inside the grid by construction; a
    # normal solve's contact can be cut off by it
    trust = unit_doubts(case)
    trust += _gross_slip_warning(case, fld, res, applied)
    trust += (diagnostics.contact_at_grid_edge(fld.pressure, fld.x, fld.y)
              if case.pressure.source == "normal" else [])
    trust += diagnostics.contact_resolution(fld.pressure > 0, fld.x, fld.y)
    trust += _spot_warnings(case, fld)
    trust += _file_warnings(fld)
    trust += diagnostics.above_hardness(fld.pressure, [("body1", body1), ("body2", body2)])
    trust += _validity_warnings(case, fld, body1, body2)
    trust += coupling_warnings
    if res.reason and not res.converged:  # the solver's own account of its failure (lp)
        trust.append(res.reason)
    return Outcome(_dataset(case, fld, res, path), summary,
                   _figures(case, fld, res, path, body1, body2), comparisons,
                   converged=converged, notes=notes, warnings=trust)
