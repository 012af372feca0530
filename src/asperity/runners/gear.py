"""Runner of ``analysis = "gear"``: a gear pair along its path of contact.

:func:`solve` builds the pair, the surfaces' composite roughness and the path, and calls
:func:`asperity.gears.solve_path`; :func:`run` packages the result (one row per path position,
the critical points in the summary, figures against the roll angle); :func:`handoff` gives the
``ehl-transient`` case of a chosen position (``asperity gear --emit-transient``).
"""

from __future__ import annotations

import math
import time

import numpy as np
import xarray as xr

from ..cases.doubts import unit_doubts
from ..ehl.formula_range import dowson_higginson_range_note, hamrock_dowson_range_note
from ..ehl.problem import FILM_ERROR
from ..gears.handoff import point_index, toml_text, transient_case
from ..gears.loading import normal_force
from ..gears.mixed import composite_roughness
from ..gears.path import (
    BOUNDARY_LUBRICATION_LAMBDA,
    GEAR_FILM_MESH_ERROR,
    GEAR_FILM_MESH_TARGET,
    GearPathResult,
    contact_problem,
    solve_path,
)
from ..gears.rating import nominal_contact_stress
from ..results import Comparison, Outcome, variable
from ..surfaces import Profile, autocorrelation_length, roughness_parameters

__all__ = ["correlation_length", "handoff", "outcome", "roughness_values", "run", "solve"]

#: Length and spacing of the profiles built from [surface1]/[surface2] to measure Ra or Rq.
PROFILE_LENGTH = 4e-3
PROFILE_SPACING = 0.5e-6


def roughness_values(case) -> tuple[float, float]:
    """Ra or Rq (``[roughness] parameter``) of the pinion and wheel surfaces, m."""
    key = "Ra" if case.roughness.parameter == "ra" else "Rq"
    first, second = (roughness_parameters(surf)[key] for surf in _profiles(case))
    return first, second


def _profiles(case) -> tuple:
    """The pinion and wheel surfaces of ``[surface1]``/``[surface2]`` built over
    :data:`PROFILE_LENGTH` at :data:`PROFILE_SPACING` (profiles, or maps for 2-D kinds)."""
    return tuple(spec.build(PROFILE_LENGTH, PROFILE_SPACING, np.zeros(1), PROFILE_SPACING)
                 for spec in (case.surface1, case.surface2))


def correlation_length(case) -> float:
    """The shorter autocorrelation length (ACF down to 0.2) of the pinion and wheel surfaces
    along x, m, measured on the profiles built as for :func:`roughness_values`; NaN for
    surfaces without roughness along x."""
    lengths = [autocorrelation_length(surf) for surf in _profiles(case)
               if isinstance(surf, Profile)]
    lengths = [v for v in lengths if math.isfinite(v)]
    return min(lengths) if lengths else math.nan


def solve(case, progress=None) -> tuple[GearPathResult, float]:
    """The path result of the case and the wall time of its EHL solves (s)."""
    pair = case.pair()
    body1, body2 = case.bodies()
    s1, s2 = roughness_values(case)
    sigma = composite_roughness(s1, s2, case.roughness.combination)
    start = time.perf_counter()
    result = solve_path(
        pair, pair.path(case.ehl.points), pinion_speed=case.operation.speed,
        torque=case.operation.torque, body1=body1, body2=body2,
        lubricant=case.lubricant.lubricant(), roughness=sigma,
        thermal=case.thermal_model(), mesh=case.ehl.mesh(),
        boundary_friction=case.friction.boundary,
        boundary_lambda=case.friction.boundary_lambda,
        full_film_lambda=case.friction.full_film_lambda, two_pair_sides=True,
        progress=progress)
    return result, time.perf_counter() - start


def run(case, progress=None) -> Outcome:
    """Solve the path of contact of the case's gear pair."""
    result, seconds = solve(case, progress)
    return outcome(case, result, seconds)


def _at(result, i, name: str) -> dict:
    """Where position ``i`` lies: roll angle (deg) and distance from the pitch point (m)."""
    return {f"{name}_roll_angle_deg": math.degrees(float(result.kin.roll_angle[i])),
            f"{name}_distance_from_pitch_m": float(result.kin.distance[i])}


def outcome(case, result: GearPathResult, seconds: float) -> Outcome:
    """Dataset, summary (geometry, critical points), figures and comparisons of a path."""
    pair, kin = result.pair, result.kin
    newtonian = case.lubricant.lubricant().newtonian
    dims = ("point",)
    fields = {
        "rho1": (kin.rho1, "m", "pinion transverse radius of curvature"),
        "rho2": (kin.rho2, "m", "wheel transverse radius of curvature (negative: a ring "
                 "gear's concave flank)" if pair.internal
                 else "wheel transverse radius of curvature"),
        "distance": (kin.distance, "m", "distance from the pitch point on the line of action"),
        "reduced_radius": (kin.reduced_radius, "m", "reduced radius of curvature (normal)"),
        "u1": (kin.u1, "m/s", "pinion rolling speed"),
        "u2": (kin.u2, "m/s", "wheel rolling speed"),
        "sum_speed": (kin.sum_speed, "m/s", "sum velocity u1 + u2"),
        "sliding_speed": (kin.sliding_speed, "m/s", "sliding speed u1 - u2"),
        "slide_roll_ratio": (kin.slide_roll_ratio, "1", "slide/roll ratio (u1 - u2)/u"),
        "load_sharing": (result.share, "1", "load sharing factor X"),
        "normal_load": (result.load, "N/m" if result.line else "N",
                        "normal load per unit length of contact line" if result.line
                        else "normal load"),
        "hertz_pressure": (result.hertz_pressure, "Pa", "Hertz maximum pressure"),
        "hertz_a": (result.hertz_a, "m", "Hertz semi-width along the motion"),
        "central_film": (result.central_film, "m", "central film (steady EHL solver)"),
        "minimum_film": (result.minimum_film, "m", "minimum film (steady EHL solver)"),
        "max_pressure": (result.max_pressure, "Pa", "maximum EHL pressure"),
        "formula_central_film": (result.formula_central, "m",
                                 f"central film ({result.formula_names[0]})"),
        "formula_minimum_film": (result.formula_minimum, "m",
                                 f"minimum film ({result.formula_names[1]})"),
        "specific_film": (result.specific_film, "1", "lambda = h_min / composite roughness"),
        "ehl_friction": (result.ehl_friction, "1", "EHL traction coefficient (Newtonian, no "
                         "Eyring stress: left out, NaN)" if newtonian
                         else "EHL traction coefficient (Eyring)"),
        "asperity_share": (result.asperity_share, "1", "load share on asperities"),
        "friction": (result.friction, "1", "friction coefficient"),
        "flash_temperature": (result.flash_temperature, "K", "Blok flash temperature"),
        "contact_temperature": (result.contact_temperature, "degC", "contact temperature"),
        "peclet": (result.peclet, "1", "Peclet number (slower surface)"),
        "converged": (result.converged.astype(np.int8), "1", "EHL solve converged"),
        "ehl_nodes": (result.nodes, "1", "nodes along x of the EHL solve"),
    }
    ds = xr.Dataset(
        {k: variable(dims, v, u, n) for k, (v, u, n) in fields.items()},
        coords={"roll_angle": variable(dims, np.degrees(kin.roll_angle), "degree",
                                       "pinion roll angle")},
        attrs={"title": case.title, "analysis": "gear", "source": "asperity",
               "contact": "line" if result.line else "point"},
    )
    crit = result.critical()
    i_lam, i_fl, i_p = (crit[k] for k in ("minimum_lambda", "maximum_flash_temperature",
                                          "maximum_hertz_pressure"))
    # the pitch point, or where it lies outside the path the end nearest it (its rows NaN)
    on_path = pair.pitch_on_path
    i_c = int(np.argmin(np.abs(kin.distance)))
    at_pitch = (lambda v: float(v)) if on_path else (lambda v: math.nan)
    end = "A" if pair.points["C"] < pair.points["A"] else "E"  # nearest C when off the path
    where = "the pitch point" if on_path else f"{end} (the pitch point lies outside the path)"
    if i_fl is None:  # unknown somewhere along the path (a Newtonian film): not a maximum
        hottest = {"maximum_flash_temperature_k": math.nan,
                   "maximum_contact_temperature_c": math.nan,
                   "maximum_flash_temperature_roll_angle_deg": math.nan,
                   "maximum_flash_temperature_distance_from_pitch_m": math.nan}
    else:
        hottest = {"maximum_flash_temperature_k": float(result.flash_temperature[i_fl]),
                   "maximum_contact_temperature_c": float(result.contact_temperature[i_fl]),
                   **_at(result, i_fl, "maximum_flash_temperature")}
    rb1 = pair.rb[0]
    iso = nominal_contact_stress(pair, case.operation.torque, *case.bodies())
    summary = {
        "internal_pair": pair.internal,
        "transverse_contact_ratio": pair.contact_ratio,
        "overlap_ratio": pair.overlap_ratio,
        "centre_distance_m": pair.aw,
        "working_pressure_angle_deg": math.degrees(pair.alpha_wt),
        "tip_diameter_pinion_m": pair.da[0],
        "tip_diameter_wheel_m": pair.da[1],
        **{f"roll_angle_{k}_deg": math.degrees(v / rb1) for k, v in pair.points.items()},
        "normal_force_n": normal_force(pair, case.operation.torque),
        "composite_roughness_m": result.composite_roughness,
        "minimum_lambda": float(result.specific_film[i_lam]),
        "boundary_lubrication_points": int(np.sum((result.load > 0) & (
            result.specific_film < BOUNDARY_LUBRICATION_LAMBDA))),
        **_at(result, i_lam, "minimum_lambda"),
        **hottest,
        "maximum_hertz_pressure_pa": float(result.hertz_pressure[i_p]),
        **_at(result, i_p, "maximum_hertz_pressure"),
        "pitch_hertz_pressure_pa": at_pitch(result.hertz_pressure[i_c]),
        "iso_nominal_contact_stress_pa": iso.stress,
        "iso_zone_factor": iso.zone,
        "iso_elasticity_factor_sqrt_mpa": iso.elasticity / 1e3,
        "iso_contact_ratio_factor": iso.contact_ratio,
        "iso_helix_angle_factor": iso.helix,
        "iso_nominal_tangential_force_n": iso.tangential_force,
        "minimum_film_m": float(np.nanmin(result.minimum_film)),
        "pitch_central_film_m": at_pitch(result.central_film[i_c]),
        "pitch_minimum_film_m": at_pitch(result.minimum_film[i_c]),
        "pitch_lambda": at_pitch(result.specific_film[i_c]),
        # NaN when any loaded point's friction is unknown (a Newtonian film): a mean of the
        # boundary points alone would pass for the path's
        "mean_friction_coefficient": float(np.mean(result.friction[result.load > 0])),
        "points": int(kin.rho1.size),
        "ehl_solves_converged": int(result.converged.sum()),
        "ehl_wall_time_s": seconds,
        "converged": bool(result.converged.all()),
    }
    formula_note = "Newtonian isothermal formula; the solver uses the case's lubricant laws"
    central_note = minimum_note = formula_note
    pitch = contact_problem(pair, kin, i_c, float(result.load[i_c]), *case.bodies(),
                            case.lubricant.lubricant())
    if result.line:
        minimum_note = dowson_higginson_range_note(pitch.G) or formula_note
    else:  # crowned flanks: Hamrock-Dowson's point films, fitted for 1 <= k <= 8
        outside = hamrock_dowson_range_note(pitch.b / pitch.a)
        central_note = minimum_note = f"{formula_note}; {outside}" if outside else formula_note
    comparisons = [
        Comparison(f"central film at {where}", float(result.central_film[i_c]),
                   float(result.formula_central[i_c]), result.formula_names[0], "m", None,
                   central_note),
        Comparison(f"minimum film at {where}", float(result.minimum_film[i_c]),
                   float(result.formula_minimum[i_c]), result.formula_names[1], "m", None,
                   minimum_note),
    ]
    notes = [
        "Load sharing: ISO/TR 13989-1 linear form (1/3 - 2/3 - 1 for unrelieved spur gears). "
        "Friction: (1 - f) mu_EHL + f mu_b with the asperity share f linear in lambda from 1 at "
        f"lambda = {case.friction.boundary_lambda:g} to 0 at {case.friction.full_film_lambda:g}"
        f" and mu_b = {case.friction.boundary:g} (an engineering assumption). Flash "
        "temperature: Blok's formula (band source, high Peclet number, equal maximum surface "
        "temperatures); the EHL solutions are isothermal.",
        f"ISO 6336-2:2019 nominal contact stress sigma_H0 = Z_H Z_E Z_eps Z_beta "
        f"sqrt(F_t/(d1 b) (u+1)/u) = {iso.stress / 1e6:.4g} MPa (Z_H {iso.zone:.4g}, Z_E "
        f"{iso.elasticity / 1e3:.4g} sqrt(MPa), Z_eps {iso.contact_ratio:.4g}, Z_beta = "
        f"1/sqrt(cos beta) {iso.helix:.4g}, F_t {iso.tangential_force:.5g} N; no K or Z_B/Z_D "
        + (f"factors) beside the Hertz pressure {result.hertz_pressure[i_c] / 1e6:.4g} MPa at "
           "the pitch point: " if on_path else
           "factors), at a pitch point that lies outside the path of contact, where no pair of "
           "teeth touches: ")
        + "Z_eps is ISO's contact-ratio factor, not the load sharing of the path, "
        "and Z_beta an empirical factor of the standard (for eps_beta >= 1 sigma_H0 is exactly "
        "Z_beta times the pitch Hertz pressure; docs/gears.md).",
        f"Mesh: {case.ehl.nx} nodes on {case.ehl.levels} grid(s) over "
        f"{case.ehl.x_min:g}a..{case.ehl.x_max:g}a"
        + (f" (at the same spacing, the inlet moved upstream to the fully flooded distance "
           f"where the film needs it: {_span(result.nodes[result.nodes > 0])} nodes)"
           if case.ehl.adapt else "")
        + _mesh_accuracy(case.ehl, result),
        *result.notes,  # solve_path's: a Newtonian traction no result uses
    ]
    if not on_path:
        angle = {k: summary[f"roll_angle_{k}_deg"] for k in "ACE"}
        notes.append(
            f"The pitch point C (pinion roll angle {angle['C']:.4g} deg) lies outside the path "
            f"of contact A-E ({angle['A']:.4g}-{angle['E']:.4g} deg): the pair meshes in "
            f"{'recess' if end == 'A' else 'approach'} alone, sliding everywhere, so the pitch "
            "rows of the summary are left out (NaN) and the films are compared with the "
            f"formulas at {end}, the end of the path nearest it.")
    title = case.title
    from ..plotting.gear import conditions_figure, film_figure, friction_temperature_figure

    figures = {
        "path_film": (lambda: film_figure(result, title, _sigma_label(case)),
                      "Central and minimum film from the steady EHL solver (solid) and the "
                      "film formulas (dashed), and lambda = h_min / sigma (sigma the composite "
                      "roughness named on the axis), against the pinion roll angle; A-E "
                      "marked, single tooth contact B-D shaded; at B and D both sides of the "
                      "load-sharing jump are solved and drawn."),
        "path_conditions": (lambda: conditions_figure(result, title),
                            "Load and Hertz pressure (stepping at B and D, where the load "
                            "sharing jumps), rolling and sliding speeds and the reduced radius "
                            "along the path of contact."),
        "path_friction_temperature": (
            lambda: friction_temperature_figure(result, title,
                                                case.operation.bulk_temperature, newtonian),
            "Friction coefficient (EHL traction and with the boundary share) and the contact "
            "temperature (deg C, bulk + Blok's flash temperature; the flash temperature rise "
            "in K on the right axis) along the path."
            + (" Newtonian lubricant: the EHL traction is left out, and friction and "
               "temperatures are drawn only where the asperities carry all the load."
               if newtonian else "")),
    }
    # solve_path's lines include the lubricant.tau0 line of a Newtonian film (its traction
    # left out) and the minimum film <= 0 of an implausible load
    trust = unit_doubts(case) + case.thermal_notes() + list(result.warnings)
    return Outcome(ds, summary, figures, comparisons, converged=bool(result.converged.all()),
                   notes=notes, warnings=trust)


def _mesh_accuracy(ehl, result: GearPathResult) -> str:
    """The mesh note's second half: the spacing the run used and the central-film error the
    rule ``FILM_ERROR dx^2 / H_c`` estimates on it (:func:`asperity.gears.film_mesh_error`,
    largest over the loaded positions), beside the line above which the run warns."""
    spacing = (ehl.x_max - ehl.x_min) / (ehl.nx - 1)
    loaded = result.load > 0
    worst = float(np.max(result.mesh_error[loaded])) if loaded.any() else 0.0
    verdict = ("above it, so the ehl.nx warning names the positions and the nodes for "
               f"about {GEAR_FILM_MESH_TARGET:.0%}" if worst > GEAR_FILM_MESH_ERROR else
               "under it, so no warning")
    return (f"; dx = a/{1.0 / spacing:.3g}, on which the central film's discretisation error "
            f"is estimated at up to {worst:.1%} ({FILM_ERROR:g} dx^2/H_c; measured against "
            "finer meshes the estimate is 1.2-1.7 times the error at moderate loads and about "
            "the error at high ones, docs/gears.md), films and lambda erring low (the safe "
            f"side); the warning line is {GEAR_FILM_MESH_ERROR:.0%}, {verdict}")


def _span(values) -> str:
    """"129" or "129-263": the range of node counts (empty: "no")."""
    if not values.size:
        return "no"
    low, high = int(values.min()), int(values.max())
    return f"{low}" if low == high else f"{low}-{high}"


def _sigma_label(case) -> str:
    """What sigma of lambda = h_min / sigma is in this case ("rss of Ra": sqrt(Ra1^2 + Ra2^2))."""
    name = "Ra" if case.roughness.parameter == "ra" else "Rq"
    if case.roughness.combination == "rss":
        return f"sigma = sqrt({name}1² + {name}2²)"
    return f"sigma = ({name}1 + {name}2)/2"


def handoff(case, result: GearPathResult, at: str | None = None) -> tuple[dict, str]:
    """The ``ehl-transient`` case (dict and TOML text) of the position named by ``at``
    (default the case's ``[handoff] at``), its mesh refined to the surfaces' autocorrelation
    length and a line contact's sweep limit raised (:mod:`asperity.gears.handoff`)."""
    from ..cases.gear import HandoffSpec

    spec = case.handoff if at is None else case.handoff.model_copy(
        update={"at": HandoffSpec(at=at).at})
    index = point_index(result, spec.at, spec.roll_angle())
    h = case.handoff
    grid = {"nx": h.nx, "ny": h.ny, "x_min": h.x_min, "x_max": h.x_max}
    length = correlation_length(case)
    inlet = None
    if result.line:
        problem = contact_problem(result.pair, result.kin, index, float(result.load[index]),
                                  *case.bodies(), case.lubricant.lubricant())
        inlet = problem.inlet_extent()
    dump = {"exclude_none": True, "by_alias": True}
    data = transient_case(
        result, index, title=f"{case.title}: transient mixed EHL at {spec.at}",
        body1=case.body1.model_dump(**dump), body2=case.body2.model_dump(**dump),
        lubricant=case.lubricant.model_dump(**dump),
        surface1=case.surface1.model_dump(exclude_defaults=True, **dump),
        surface2=case.surface2.model_dump(exclude_defaults=True, **dump),
        grid=grid, time=h.time.model_dump(**dump),
        solver=None if h.solver is None else h.solver.model_dump(exclude_unset=True, **dump),
        correlation_length=length if math.isfinite(length) else None, inlet_extent=inlet)
    header = (f"Written by `asperity gear` from the case \"{case.title}\" ({spec.at}).\n"
              "Surface 1 is the pinion flank, surface 2 the wheel flank; SI units.")
    return data, toml_text(data, header)
