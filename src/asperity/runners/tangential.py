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
from ..cases.roughness import roughness_on_grid, undeformed_gap
from ..contact import hertz_point, solve_normal, solve_tangential
from ..contact.load_path import proportional_path, tangential_load_path
from ..errors import InputError
from ..materials import contact_modulus, coupling_compliance
from ..references import tangential_comparisons
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


def _hertz_field(case, body1, body2):
    """Hertz pressure at the cell centres, scaled so that the discrete load is the applied one."""
    spec = case.pressure
    rx, ry = spec.radii()
    h = hertz_point(spec.load, rx, ry, body1, body2)
    margin = 1.05 if spec.source == "hertz" else 1.5
    x, y = case.grid.coordinates((-margin * h.a, margin * h.a, -margin * h.b, margin * h.b))
    for key, coord, half in (("x_extent", x, h.a), ("y_extent", y, h.b)):
        edge = 0.5 * (coord[1] - coord[0]) * (1.0 + 1e-9)
        if coord[0] - edge > -half or coord[-1] + edge < half:
            raise InputError(f"grid.{key}", f"a domain covering the contact (semi-axis {half:.4g}"
                                            " m about the origin)")
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
    """Uniform pressure (and friction) per region; every region must cover a cell."""
    spec = case.pressure
    x, y = case.grid.coordinates(spec.bounding_box())
    X, Y = np.meshgrid(x, y, indexing="ij")
    p, mu = np.zeros(X.shape), np.full(X.shape, case.mu)
    for k, (region, center) in enumerate(zip(spec.regions, spec.centers(), strict=True)):
        m = region.mask(X, Y, center)
        if not m.any():
            raise InputError(f"pressure.regions[{k}]", "a region covering at least one grid "
                                                        "cell (refine grid.nx / ny)")
        p[m] = region.pressure
        if region.mu is not None:
            mu[m] = region.mu
    return _Field(x, y, p, mu)


def _field(case, body1, body2) -> _Field:
    if case.pressure.source == "uniform":
        return _uniform_field(case)
    return _hertz_field(case, body1, body2)


# --- outputs --------------------------------------------------------------------------------


def _summary(case, fld, res, applied, identical):
    s = {
        "normal_load_n": float(fld.pressure.sum() * fld.cell_area),
        "contact_area_m2": float((fld.pressure > 0).sum() * fld.cell_area),
        "friction_capacity_n": float((fld.mu * fld.pressure).sum() * fld.cell_area),
        "force_x_n": applied[0], "force_y_n": applied[1], "moment_nm": applied[2],
        "gross_slip": bool(res.gross_slip),
        "load_capacity": float(res.load_capacity),
        "stick_fraction": float(res.stick.sum() / max((res.labels > 0).sum(), 1)),
    }
    # undefined quantities are left out, not NaN: the rigid motion in gross slip, the centre
    # of a motion without rotation
    if not res.gross_slip:
        s.update(shift_x_m=float(res.shift[0]), shift_y_m=float(res.shift[1]),
                 shift_m=float(math.hypot(*res.shift)), rotation_rad=float(res.rotation))
        if identical:
            s["shift_per_body_m"] = 0.5 * s["shift_m"]
            s["rotation_per_body_rad"] = 0.5 * s["rotation_rad"]
    if np.all(np.isfinite(res.centre_of_rotation)):
        s.update(center_of_rotation_x_m=float(res.centre_of_rotation[0]),
                 center_of_rotation_y_m=float(res.centre_of_rotation[1]))
    if math.isfinite(res.load_capacity):
        if any(applied[:2]):
            s["gross_slip_force_n"] = float(res.load_capacity * math.hypot(*applied[:2]))
        if applied[2] != 0.0 and case.loading.rotation == "free":
            s["gross_slip_moment_nm"] = float(res.load_capacity * abs(applied[2]))
    if res.gross_slip:
        s.update(excess_force_x_n=float(res.excess[0]), excess_force_y_n=float(res.excess[1]),
                 excess_moment_nm=float(res.excess[2]))
    if case.loading.rotation == "fixed":
        s["reaction_moment_nm"] = float(res.reaction_moment)
    for reg in res.regions:
        k = reg.label
        s.update({f"region_{k}_force_x_n": float(reg.force[0]),
                  f"region_{k}_force_y_n": float(reg.force[1]),
                  f"region_{k}_moment_nm": float(reg.moment),
                  f"region_{k}_capacity_n": float(reg.capacity),
                  f"region_{k}_stick_fraction": float(reg.stick_fraction)})
    s.update(regions=len(res.regions), iterations=int(res.iterations),
             residual=float(res.residual), convolutions=int(res.convolutions),
             converged=bool(res.converged))
    # the reference point of the moment (loading.center, or the centre of the normal load)
    s.update(moment_center_x_m=float(res.centre[0]), moment_center_y_m=float(res.centre[1]))
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


def _figures(case, fld, res, path):
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
    figs["compliance"] = (lambda: tplot.compliance_curves(path),
                          "Compliance along the load path: force vs relative rigid shift and "
                          "moment vs relative twist.")
    figs["slip_progression"] = (lambda: tplot.slip_progression(path, x, y),
                                "Stick-zone borders at the successive load steps.")
    figs["load_sharing"] = (lambda: tplot.load_sharing(path),
                            "Force and moment carried by each contact region along the path.")
    if case.loading.rotation == "free" and np.any(np.isfinite(path.centre_of_rotation)):
        figs["center_of_rotation"] = (
            lambda: tplot.centre_of_rotation_curve(path, res.centre),
            "Centre of rotation relative to the moment's reference point vs the moment.")
    return figs


def _file_warnings(fld) -> list[str]:
    """A measured roughness file's doubts (:func:`asperity.diagnostics.measured_file_on_grid`)."""
    rough = fld.roughness
    if rough is None:
        return []
    return diagnostics.measured_file_on_grid("pressure.roughness", rough, fld.x, fld.y)


def _coupling_note(body1, body2, mu) -> list[str]:
    """Dissimilar bodies: the pressure's tangential displacement is in the solution, not in
    the closed forms it is compared with (docs/tangential.md, "Dissimilar materials")."""
    beta = contact_modulus(body1, body2) * coupling_compliance(body1, body2) / 4.0
    if abs(beta) < 1e-3:
        return []
    ratio = abs(beta) / float(np.max(mu))
    return [f"Dissimilar bodies (Dundurs beta = {beta:.3g}, beta/mu = {ratio:.2g}): the solution "
            "includes the tangential displacement of the pressure, applied at once (not along "
            "the history of the normal loading), which Cattaneo-Mindlin and Lubkin (beta = 0) "
            "leave out; their shifts, twists and stick zones differ from it by an amount set by "
            "beta/mu (an aluminium sphere on steel, beta/mu = 0.39: shift +5.6 %, stick area "
            "54.5 against 63 % at Q = 0.5 mu N)."]


def _path_summary(path):
    out = {"path_steps": len(path.loads), "path_gross_slip_step": int(path.gross_slip_step),
           "path_iterations": int(path.iterations), "path_converged": bool(path.converged)}
    if math.isfinite(path.dissipated_energy):  # a closed cycle
        out["path_dissipated_energy_j"] = float(path.dissipated_energy)
    return out


def run(case, progress=None) -> Outcome:
    """Solve the case's frictional contact (and its load path); compare with references."""
    body1, body2 = case.body1.material(), case.body2.material()
    # the same steel given as "30457.92 ksi" and "30.45792e6 psi" differs in the last digit
    identical = all(math.isclose(getattr(body1, k), getattr(body2, k), rel_tol=1e-9)
                    for k in ("youngs_modulus", "poisson_ratio"))
    fld = _field(case, body1, body2)
    notes = [] if fld.roughness is None else list(fld.roughness.notes)
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
    summary = _summary(case, fld, res, applied, identical)
    if path is not None:
        summary.update(_path_summary(path))
    free = case.loading.rotation == "free"
    comparisons = tangential_comparisons(case, res, fld.x, fld.y, fld.mu, body1, body2,
                                         fld.hertz)
    if case.reference is not None and case.reference.note:
        notes.append(case.reference.note)
    if identical:
        notes.append(_PER_BODY_NOTE)
    notes += _coupling_note(body1, body2, fld.mu)
    if res.gross_slip:
        notes.append(
            f"Gross slip: friction carries at most {res.load_capacity:.4g} times the applied "
            f"load; the excess is Fx {res.excess[0]:.4g} N, Fy {res.excess[1]:.4g} N, "
            f"M {res.excess[2]:.4g} N m. The traction shown is the full-slip traction.")
    if math.hypot(fx, fy) > 0:
        notes.append(f"The force acts at {math.degrees(case.loading.direction):.4g} deg from +x "
                     "(loading.direction); the moment is about "
                     + ("loading.center" if case.loading.center is not None
                        else "the centre of the normal load")
                     + f" ({res.centre[0]:.4g}, {res.centre[1]:.4g}) m.")
    if not free:
        notes.append("Rotation is fixed (loading.rotation): body 1 translates only, the moment "
                     "equation is dropped and the fixture supplies the reaction moment "
                     f"{res.reaction_moment:.4g} N m.")
    if case.method == "lp":
        notes.append("Method lp: Seireg's predetermined traction directions (exact for pure "
                     "torsion about the true centre and pure translation; an approximation "
                     "otherwise).")
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
    trust = (diagnostics.contact_at_grid_edge(fld.pressure, fld.x, fld.y)
             if case.pressure.source == "normal" else [])
    trust += diagnostics.contact_resolution(fld.pressure > 0, fld.x, fld.y)
    trust += _file_warnings(fld)
    trust += diagnostics.above_hardness(fld.pressure, [("body1", body1), ("body2", body2)])
    if res.reason and not res.converged:  # the solver's own account of its failure (lp)
        trust.append(res.reason)
    return Outcome(_dataset(case, fld, res, path), summary, _figures(case, fld, res, path),
                   comparisons, converged=converged, notes=notes, warnings=trust)
