"""Runner of ``analysis = "normal"``: ellipsoid on a flat, smooth or rough, by solve_normal."""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from .. import diagnostics
from ..cases.doubts import unit_doubts
from ..cases.roughness import roughness_on_grid, undeformed_gap
from ..contact import hertz_point, solve_normal
from ..contact.greenwood_tripp import greenwood_tripp_sphere, summit_parameters
from ..contact.spots import contact_spots
from ..errors import InputError
from ..formatting import format_quantity
from ..materials import contact_modulus
from ..references import cite
from ..results import Comparison, Outcome, variable
from ..surfaces.ground import GROUND_CORRELATION_LENGTH

__all__ = ["run"]


def _centre_row(y):
    return int(np.argmin(np.abs(y)))


#: Largest ratio of a surface's mean squared slopes along x and y (either way) at which it is
#: set beside Greenwood & Tripp's isotropic model.
ISOTROPY = 1.25


def _greenwood_tripp_rows(case, res, x, y, heights, e_star):
    """A rough sphere beside Greenwood & Tripp's estimate (:mod:`asperity.contact.
    greenwood_tripp`), with McCool's summits from the heights on this grid: the load's rms
    radius about the apex and the real area, as unchecked rows with the model's known
    accuracy. Only a sphere on a near-isotropic surface (:data:`ISOTROPY`) with a summit
    height distribution; no rows when the model does not converge."""
    rx, ry = case.geometry.radii()
    if abs(rx - ry) > 1e-9 * rx:
        return [], {}
    summits = summit_parameters(heights, x[1] - x[0], y[1] - y[0])
    if summits is None or not 1.0 / ISOTROPY <= summits.anisotropy <= ISOTROPY:
        return [], {}
    gt = greenwood_tripp_sphere(res.load, rx, e_star, summits)
    if not gt.converged:
        return [], {}
    rr2 = x[:, None] ** 2 + y[None, :] ** 2
    rms = math.sqrt(float((res.pressure * rr2).sum() / res.pressure.sum()))
    src = cite("Greenwood & Tripp (1967), McCool's summits of this grid's heights",
               "greenwood-and-tripps-rough-sphere")
    rows = [Comparison("load rms radius", rms, gt.rms_radius, src, "m", note=(
                "an estimate, not a check: its summits do not interact; the solve's is 4-5 % "
                "under it on gaussian surfaces")),
            Comparison("real contact area", res.contact_area, gt.real_area, src, "m^2", note=(
                "an estimate, not a check: on gaussian surfaces the solve's real area is 28 % "
                "above it on a converged mesh, more on a coarse one (40-46 % at 256 cells); the "
                "summits follow the sampling"))]
    return rows, {"greenwood_tripp_rms_radius_m": gt.rms_radius,
                  "greenwood_tripp_real_area_m2": gt.real_area,
                  "load_rms_radius_m": rms}


def _check_approach(approach: float, gap0: np.ndarray, periodic: bool, rough: bool):
    """Refuse a ``loading.approach`` at which the bodies do not touch (at or below the first
    contact: 0 for smooth bodies, ``min(gap0)`` for rough ones, whose approach is measured
    from the roughness's mean plane, so below 0) or, on a periodic grid, at or beyond the mean
    undeformed gap, where they are in full contact, which only load control solves. A rough
    flat in partial contact has a negative approach; a rule of ``> 0`` refused every one."""
    first = float(gap0.min()) if rough else 0.0  # smooth: Hertz's apex, cell-centred or not
    mean = float(gap0.mean())
    if abs(mean) < 1e-9 * float(np.ptp(gap0)):
        mean = 0.0  # the mean plane of the heights, to round-off
    got = format_quantity(approach, "m")
    if not approach > first:
        where = (f"the rough surfaces first touch at {format_quantity(first, 'm')}, measured "
                 "from the roughness's mean plane through the apex" if rough else
                 "the smooth bodies first touch at 0")
        raise InputError("loading.approach", f"more than {format_quantity(first, 'm')} ({where};"
                         " below it they do not touch)", got)
    if periodic and not approach < mean:
        raise InputError("loading.approach", f"less than the mean undeformed gap "
                         f"{format_quantity(mean, 'm')} of a periodic contact (from there on the "
                         "surfaces are in full contact, which needs load control: "
                         "loading.load)", got)


def run(case, progress=None) -> Outcome:
    """Solve the case's normal contact; compare with Hertz when the surfaces are smooth."""
    x, y = case.grid.coordinates()
    body1, body2 = case.body1.material(), case.body2.material()
    rough = None if case.roughness is None else roughness_on_grid(case.roughness, x, y)
    gap0 = undeformed_gap(*case.geometry.radii(), x, y, None if rough is None else rough.heights)
    if case.loading.approach is not None:
        _check_approach(case.loading.approach, gap0, case.grid.periodic, rough is not None)
    callback = None
    if progress is not None:
        def callback(iteration, residual):
            progress(iteration, None, f"CG iteration {iteration}, residual {residual:.1e}")
    res = solve_normal(gap0, x, y, body1, body2, load=case.loading.load,
                       approach=case.loading.approach, periodic=case.grid.periodic,
                       tol=case.tolerance, callback=callback)
    ds = xr.Dataset(
        {
            "pressure": variable(("x", "y"), res.pressure, "Pa", "contact pressure"),
            "gap": variable(("x", "y"), res.gap, "m", "deformed gap"),
            "undeformed_gap": variable(("x", "y"), gap0, "m", "undeformed gap"),
            "contact": variable(("x", "y"), res.contact.astype("i1"), "1", "contact indicator",
                                flag_values=[0, 1], flag_meanings="open contact"),
        },
        coords={"x": variable("x", x, "m", "x (first in-plane direction)"),
                "y": variable("y", y, "m", "y (second in-plane direction)")},
        attrs={"title": case.title, "analysis": "normal", "Conventions": "CF-1.8",
               "source": "asperity", "iterations": res.iterations,
               "converged": int(res.converged)},
    )
    summary = {
        "max_pressure_pa": float(res.pressure.max()),
        "mean_contact_pressure_pa": float(res.load / res.contact_area) if res.contact_area else 0.0,
        "contact_area_m2": float(res.contact_area),
        "contact_area_fraction": float(res.contact.mean()),
        "approach_m": float(res.approach),
        "load_n": float(res.load),
        "iterations": int(res.iterations),
        "residual": float(res.residual),
        "converged": bool(res.converged),
    }
    spots = None
    if rough is not None:  # the real area's spots (docs/tangential.md, "Contact spots")
        spots = contact_spots(res.contact, res.pressure, (x[1] - x[0]) * (y[1] - y[0]),
                              periodic=case.grid.periodic)
        summary.update(contact_spots=spots.count,
                       load_median_spot_cells=spots.load_median_cells(),
                       largest_spot_cells=int(spots.cells.max(initial=0)))
    rx, ry = case.geometry.radii()
    if not np.isfinite(rx):  # a nominally flat interface: its mean separation (Persson's u)
        summary["mean_separation_m"] = float(np.mean(res.gap))
    comparisons = []
    reference_line = None
    curved = np.isfinite(rx) and res.load > 0.0  # (no load: a solve that lost its contact)
    if curved and case.roughness is None:
        h = hertz_point(res.load, rx, ry, body1, body2)
        j = _centre_row(y)
        i = _centre_row(x)
        dx, dy = x[1] - x[0], y[1] - y[0]
        a_num = 0.5 * dx * res.contact[:, j].sum()
        b_num = 0.5 * dy * res.contact[i, :].sum()
        reference_line = h.pressure(x, y[j])
        src = cite("Hertz (exact elliptical)", "hertz")
        comparisons += [
            Comparison("maximum pressure", summary["max_pressure_pa"], h.p_max, src, "Pa", 0.01),
            Comparison("semi-axis a (x)", a_num, h.a, src, "m", max(0.01, dx / h.a)),
            Comparison("semi-axis b (y)", b_num, h.b, src, "m", max(0.01, dy / h.b)),
            Comparison("approach", res.approach, h.approach, src, "m", 0.01),
            Comparison("contact area", res.contact_area, h.area, src, "m^2", 0.02),
        ]
        summary.update(hertz_max_pressure_pa=h.p_max, hertz_a_m=h.a, hertz_b_m=h.b,
                       hertz_approach_m=h.approach)
    elif curved:  # rough: show how far roughness takes the contact from smooth Hertz
        h = hertz_point(res.load, rx, ry, body1, body2)
        sigma = float(np.std(rough.heights))
        # Greenwood & Tripp's roughness parameter sigma R / a0^2 (docs/references.md)
        summary.update(greenwood_tripp_alpha=sigma * math.sqrt(rx * ry) / (h.a * h.b),
                       hertz_a_m=float(h.a), hertz_b_m=float(h.b),
                       hertz_max_pressure_pa=float(h.p_max))
        # the approach is the shift of gap0, measured from the roughness's mean plane; Hertz's
        # is from first contact, which a rough gap reaches at approach = min(gap0)
        first = float(res.approach - gap0.min())
        summary.update(approach_from_first_contact_m=first)
        src, note = cite("smooth Hertz", "hertz"), "rough vs smooth, not a check"
        comparisons += [
            Comparison("maximum pressure", summary["max_pressure_pa"], h.p_max, src, "Pa",
                       note=note),
            Comparison("real contact area", res.contact_area, h.area, src, "m^2", note=note),
            Comparison("approach from first contact", first, h.approach, src, "m", note=note),
        ]
        gt_rows, gt_summary = _greenwood_tripp_rows(case, res, x, y, rough.heights,
                                                    contact_modulus(body1, body2))
        comparisons += gt_rows
        summary.update(gt_summary)
    from ..plotting.normal import centre_line, pressure_map

    j = _centre_row(y)
    figures = {
        "pressure_map": (lambda: pressure_map(x, y, res.pressure, res.contact, case.title),
                         "Contact pressure with the contact boundary."),
        "centre_line": (lambda: centre_line(x, res.pressure[:, j], res.gap[:, j],
                                            reference_line),
                        "Pressure and deformed gap along the centre line y = 0."),
    }
    notes = [] if res.converged else [
        f"The solver did not converge in {res.iterations} iterations "
        f"(residual {res.residual:.2e}); the numbers above are not trustworthy."]
    if rough is not None:
        notes += rough.notes
    notes += _unchecked_plasticity(case, res, body1, body2)
    notes += _punch_note(case, res, x, y)
    if "approach_from_first_contact_m" in summary:
        notes.append(
            f"The approach ({format_quantity(res.approach, 'm')}) is measured from the "
            "roughness's mean plane through the apex; the rough surfaces first touch at an "
            "approach of "
            f"{format_quantity(float(gap0.min()), 'm')}, so from first contact, as Hertz's "
            f"approach is, it is {format_quantity(summary['approach_from_first_contact_m'], 'm')}"
            " (approach_from_first_contact_m). loading.approach is read the same way, from the "
            "mean plane.")
    return Outcome(ds, summary, figures, comparisons, converged=res.converged, notes=notes,
                   warnings=_warnings(case, res, x, y, body1, body2, rough, spots))


def _punch_note(case, res, x, y) -> list[str]:
    """A smooth flat on an open grid in full contact is a rigid flat punch the size of the
    grid: its pressure is singular at the edges, as ``1 / sqrt(distance)`` (Boussinesq's
    punch), more strongly at the corners, so its largest value is the
    edge cells' and grows as they shrink (a 1 mm square of steel on steel at 1 kN: 5.58 GPa
    on 32 x 32 cells, 9.02 GPa on 64 x 64), while the approach converges (7.601 and
    7.561 um, as the direct solve of Love's matrix)."""
    rx, ry = case.geometry.radii()
    if (case.roughness is not None or np.isfinite(rx) or np.isfinite(ry) or case.grid.periodic
            or not res.contact.all()):
        return []
    dx = max(x[1] - x[0], y[1] - y[0])
    return [f"A smooth flat on an open grid is a rigid flat punch the size of the grid: its "
            f"pressure is singular at the edges and corners, so the maximum pressure "
            f"({format_quantity(float(res.pressure.max()), 'Pa')} on "
            f"{format_quantity(dx, 'm')} cells) is set by the cell size and grows as the cells "
            "shrink; read the mean pressure and the approach, which converge."]


def _warnings(case, res, x, y, body1, body2, on_grid, spots) -> list[str]:
    """Trust checks (:mod:`asperity.diagnostics`): the case's bare numbers that may mean
    another unit (:func:`asperity.cases.doubts.unit_doubts`) first, then a measured file's
    doubts (the reader's and its units', its sampling against the grid's), a surface that is
    not periodic on a periodic grid, then domain (a curved body's contact against the period;
    a nominally flat patch is a periodic representative surface, whose contact may span the
    period near full contact), mesh (the apparent contact, then a rough contact's spots),
    a generated roughness against the grid (its longest and shortest lengths) and
    hardness."""
    size = None
    lines = unit_doubts(case)
    if on_grid is not None:
        lines += diagnostics.measured_file_on_grid("roughness", on_grid, x, y)
    if on_grid is not None and case.grid.periodic:
        lines += diagnostics.periodic_seam("roughness", on_grid.heights,
                                           on_grid.sampling_cells(x, y))
    rx, ry = case.geometry.radii()
    if case.grid.periodic:
        if np.isfinite(rx) or np.isfinite(ry):  # a nominally flat patch is periodic by design:
            lines += diagnostics.periodic_contact(res.contact, x, y)  # its contact may span it
    else:
        load = case.loading.load if case.loading.load is not None else res.load
        if np.isfinite(rx) and np.isfinite(ry) and load > 0.0:
            h = hertz_point(load, rx, ry, body1, body2)
            size = (2.0 * h.a, 2.0 * h.b)
        if np.isfinite(rx):
            lines += diagnostics.contact_at_grid_edge(res.pressure, x, y, size)
        else:  # a flat reaches any grid's edges
            lines += diagnostics.flat_on_open_grid(
                res.pressure, x, y, measured=on_grid is not None and on_grid.file_spacing
                is not None)
    lines += diagnostics.contact_resolution(
        res.contact, x, y, expected_size=size,
        file_spacing=None if on_grid is None else on_grid.file_spacing)
    if spots is not None:
        free = case.roughness.kind == "self-affine" and case.roughness.short_cutoff is None
        lines += diagnostics.spot_resolution(
            spots, x, y, file_spacing=on_grid.file_spacing,
            cutoff_key="roughness.short_cutoff" if free else None)
    rough = case.roughness
    if rough is not None:
        lines += diagnostics.roughness_extent("roughness", x, y, **rough.longest_lengths())
    if rough is not None and rough.kind in ("gaussian", "ground"):  # generated on the grid
        ell = rough.correlation_length
        if ell is None and rough.kind == "ground":
            ell = GROUND_CORRELATION_LENGTH
        if ell is not None:
            lines += diagnostics.roughness_resolution(
                "roughness", ell, x, y, correlation_length_y=rough.correlation_length_y,
                across_y=rough.kind != "ground")  # a ground profile is the same on every row
    return lines + _plasticity(case, res, body1, body2)


def _plasticity(case, res, body1, body2) -> list[str]:
    """The pressures against the bodies' hardness (:func:`diagnostics.above_hardness`) and,
    with no hardness given, a smooth Hertz contact's validity
    (:func:`diagnostics.hertz_validity`: small against its radius, small strains); with one,
    first yield beneath the surface (:func:`diagnostics.hertz_first_yield`)."""
    bodies = [("body1", body1), ("body2", body2)]
    lines = diagnostics.above_hardness(res.pressure, bodies)
    rx, ry = case.geometry.radii()
    if case.roughness is None and np.isfinite(rx) and res.load > 0.0:
        h = hertz_point(res.load, rx, ry, body1, body2)
        a, radius = max((h.a, rx), (h.b, ry), key=lambda pair: pair[0] / pair[1])
        lines += diagnostics.hertz_validity(a, radius, h.p_max, contact_modulus(body1, body2),
                                            diagnostics.hardness_given(bodies),
                                            load_key="loading.load", bodies=bodies)
        lines += diagnostics.hertz_first_yield(h.p_max, res.load, bodies, "loading.load")
    return lines


def _unchecked_plasticity(case, res, body1, body2) -> list[str]:
    """A smooth Hertz contact's note past first yield (:func:`diagnostics.hertz_plasticity_note`)
    or, for a rough contact, :func:`diagnostics.asperity_plasticity_note`."""
    e_star = contact_modulus(body1, body2)
    rx, ry = case.geometry.radii()
    if case.roughness is None and np.isfinite(rx) and res.load > 0.0:
        h = hertz_point(res.load, rx, ry, body1, body2)
        return diagnostics.hertz_plasticity_note(h.p_max, e_star,
                                                 [("body1", body1), ("body2", body2)])
    if case.roughness is None:
        return []
    return diagnostics.asperity_plasticity_note(float(res.pressure.max()), e_star,
                                                [("body1", body1), ("body2", body2)])
