"""Runner of ``analysis = "ehl-steady"``: smooth steady EHL of a point or line contact.

Solves the case with :func:`asperity.ehl.solve_steady`;
:func:`asperity.references.ehl_steady_comparisons` sets the result beside the published numbers
of the case's ``[reference]`` table, the Newtonian film formulas and the dry Hertz pressure.
"""

from __future__ import annotations

import warnings

import numpy as np
import xarray as xr

from .. import diagnostics
from ..cases.doubts import unit_doubts
from ..cases.ehl import MAX_BOUND, MAX_NODES, MAX_NX, MAX_NY
from ..ehl import solve_steady
from ..ehl.line_newton import MAX_NODES as NEWTON_MAX_NODES
from ..ehl.problem import LineContact
from ..ehl.rows import doubled_rows
from ..ehl.sides import domain_probe, inlet_probe, side_probe
from ..ehl.solver import (
    FINE_CELL_ASPECT,
    NEWTON_CHECK_SWEEPS,
    SOFT_CELL_ASPECT,
    SOFT_MAX_NY,
    Y_LINES_BELOW,
)
from ..references import (
    ISOVISCOUS,
    RIGID_SHARE,
    ehl_steady_comparisons,
    film_formulas,
    fit_rigid_share,
    lubricant_laws,
)
from ..results import Outcome, variable

__all__ = ["SIDE_LOBE_MAX_NODES", "SIDE_LOBE_SHORT_ASPECT", "SIDE_LOBE_SHORT_CELLS_M",
           "STALLED_WITHIN", "TESTED_M", "beyond_tested_range", "chosen_mesh", "ehl_warnings",
           "isoviscous_line_advice", "relaxed_cells", "run", "side_lobe_rows", "stall_advice"]

#: A steady solve that stopped before its sweep limit with a residual below this many times
#: its tolerance stalled near a solution (:func:`stall_advice`).
STALLED_WITHIN = 10.0

#: Most nodes of the mesh on which :func:`side_lobe_rows` solves a contact again: on about
#: 200,000 nodes a heavily loaded ball takes about a minute (2 cores); the 394,000 nodes of
#: a probe case at M = 3300 took 112 s in all and 395,000 at M = 4900 more than 180 s, where
#: the mesh line's advice is left to the user (docs/ehl-robustness.md).
SIDE_LOBE_MAX_NODES = 200_000

#: Moes M up to which :func:`side_lobe_rows` doubles the rows down to cells
#: ``dY >= SIDE_LOBE_SHORT_ASPECT dX`` instead of ``FINE_CELL_ASPECT dX``: a user's steel ball
#: on glass (M = 213, L = 5.5) and a slow ball-on-disc (M = 183) converged on cells of 1.6
#: dX (19-23 s; a user's 1.2 dX too), where their default meshes' minimum films were 45 % and
#: 30 % too thin and no doubling kept 6 dX. Session 48: on the default x spacing 161 rows
#: (about 1.6 dX) also converged at M = 367, 538, 611 and 1008 (steel balls at 80 N and a
#: ball on glass at 20 N, 6-20 s), where 41 rows gave minimum films of 20.9, 0.64, 0.0009 and
#: 0.0014 nm against 63.8, 39.1, 11.6 and 16.9 nm; the short cells that diverged were on finer
#: x spacings (M = 611 on 865 x 289, 3 dX; M = 1822 on 4.1 dX, docs/ehl-robustness.md). Cells
#: under Y_LINES_BELOW = 3 dX that do not converge are relaxed again with y-line sweeps, and
#: a re-solve that does not converge is not taken.
SIDE_LOBE_SHORT_CELLS_M = 1000.0
SIDE_LOBE_SHORT_ASPECT = 1.5


def run(case, progress=None) -> Outcome:
    """Solve the case's steady EHL contact and compare it with its references."""
    problem = case.problem()
    line = isinstance(problem, LineContact)
    callback = None
    if progress is not None:
        def callback(sweep, residual):
            progress(sweep, None, f"EHL sweep {sweep}, residual {residual:.1e}")

    def solve(options):
        with warnings.catch_warnings():  # the solver's starved-inlet warning: ehl_warnings
            warnings.filterwarnings("ignore", "domain: the inlet", RuntimeWarning)
            return solve_steady(problem, **options, method=case.solver.method,
                                tol=case.solver.tolerance,
                                max_iter=case.solver.sweep_limit(line),
                                boundary_friction=case.solver.boundary_friction,
                                callback=callback)

    res = solve(case.solve_options(problem))
    res, rows_note = side_lobe_rows(case, problem, res, solve)
    lub = problem.lubricant
    hz = problem.hertz
    ds = xr.Dataset(
        {
            "pressure": variable(("x", "y"), res.pressure, "Pa", "film pressure"),
            "film": variable(("x", "y"), res.film, "m", "film thickness"),
        },
        coords={"x": variable("x", res.x, "m", "x (entrainment direction)"),
                "y": variable("y", res.y, "m", "y (across the entrainment direction)")},
        attrs={"title": case.title, "analysis": "ehl-steady", "Conventions": "CF-1.8",
               "source": "asperity", "contact": "line" if line else "point",
               "lubricant": lubricant_laws(lub), "method": res.method, "sweeps": res.sweeps,
               "total_sweeps": res.total_sweeps, "levels": str(res.levels),
               "converged": int(res.converged)},
    )
    u1, u2 = problem.u1, problem.u2
    summary = {
        "central_film_thickness_m": res.central_film,
        "minimum_film_thickness_m": res.minimum_film,
        "minimum_film_thickness_centreline_m": res.minimum_film_centreline,
        "max_pressure_pa": res.max_pressure,
        "friction_coefficient": abs(res.friction_coefficient),
        "load_error": res.load_error,
        "separation_m": res.separation,
        "sweeps": res.sweeps,
        "total_sweeps": res.total_sweeps,
        "residual": res.residual,
        "converged": res.converged,
        "hertz_max_pressure_pa": hz.p_max,
        "hertz_a_m": hz.a,
        "mean_speed_m_s": problem.mean_speed,
        "u1_m_s": u1,
        "u2_m_s": u2,
        "slide_roll_ratio": problem.slide_roll_ratio,
        "moes_M": problem.M,
        "moes_L": problem.L,
    }
    if not line:
        summary["hertz_b_m"] = hz.b
    summary.update(film_formulas(problem))
    comparisons = ehl_steady_comparisons(problem, res, case.reference)
    figures = _figures(case.title, problem, res, line)
    notes = [rows_note] if rows_note else []
    if problem.sliding_speed != 0.0:
        # the two walls' shear stresses differ by h dp/dx: a cam on a flat read 0.0109 with
        # the cam as surface 1 and 0.0095 with the bodies' speeds swapped
        notes.append("The friction coefficient is the film's shear traction on surface 1 (the "
                     "one moving at u1) over the load; on surface 2 it differs by the "
                     "pressure-gradient part of the wall stress, h dp/dx over the load.")
    if not (lub.newtonian and lub.viscosity_model == "barus" and not lub.compressible):
        notes.append(f"The film formulas are Newtonian, isothermal fits; the solution uses "
                     f"{lubricant_laws(lub)}, so they are shown for orientation only.")
    if not res.converged:
        limit = case.solver.sweep_limit(line)
        counted = ("" if res.sweeps <= limit else  # a line contact's Newton solution checked
                   f"{limit} at most of relaxation, then up to {min(limit, NEWTON_CHECK_SWEEPS)} "
                   "checking Newton's solution; ")
        # cells too short across y are the cause the error line names, when they are one (an
        # MTM ball on the advised domain with dy = 2.3 dx: "check the inlet and the mesh")
        cells = [] if line else _cell_advice(problem, res)
        notes.append(f"The solver did not converge in {res.sweeps} sweeps on the finest grid "
                     f"({counted}residual {res.residual:.2e}); the numbers above are not "
                     "trustworthy."
                     + (f" {cells[0]}" if cells else
                        isoviscous_line_advice(problem, res) or stall_advice(case, res))
                     + beyond_tested_range(problem))
    elif not line and res.y_lines:
        notes += _cell_advice(problem, res)
    if res.converged and res.soft_retry:
        notes.append("The default relaxation did not converge on this mesh; the solution is "
                     "that of the solver's fallback for a soft contact, relaxed again from the "
                     "coarser grid with a far-field refresh every sweep and a smaller load "
                     f"gain ({res.sweeps} sweeps on the finest grid).")
    estimate = summary.get("hamrock_dowson_central_film_m", summary.get(
        "chittenden_central_film_m", summary.get("moes_central_film_m")))
    # an unconverged film (e.g. 0.29 mm for a bearing whose iteration had blown up) would set
    # the inlet advice of ehl_inlet_length; the formula's film is the better guess then
    film = res.central_film if res.converged else problem.film_estimate()
    trust = ehl_warnings(case, problem, res.pressure, res.x, res.y, film, smooth_film=res.film,
                         film_solved=res.converged)
    collapse = diagnostics.ehl_film_collapse(res.film, estimate, _hertz_zone(problem, res))
    trust += collapse
    if not collapse and np.isfinite(res.friction_coefficient) \
            and _sheared_piezoviscous(problem, res):
        # a collapsed film's friction is the collapse's, not the Newtonian law's
        trust += diagnostics.newtonian_traction(res.friction_coefficient, lub.newtonian)
    if res.converged:
        trust += diagnostics.friction_undefined(
            res.friction_coefficient, float(lub.eta(res.max_pressure)), res.max_pressure)
    chosen = chosen_mesh(case, problem, res.x, res.y) | case.lubricant.unused_defaults()
    if "levels" not in case.solver.model_fields_set:  # the grid sequence chosen with the mesh
        chosen["solver.levels"] = len(res.levels)
    return Outcome(ds, summary, figures, comparisons, converged=res.converged, notes=notes,
                   warnings=trust, chosen=chosen)


def side_lobe_rows(case, problem, res, solve):
    """The steady solution on rows across y that resolve its minimum film, where asperity
    chose the mesh.

    A point contact's default mesh has ``dY = b/10``; the side lobes of a heavily loaded
    contact are narrower, and there the minimum film comes out too thin or collapses onto a
    line of dry nodes (a steel ball at Moes M = 1000: 0.002 nm on 41 rows, 77 nm on 81,
    124.5 nm on 161, 137.5 nm on 1025 x 321; docs/ehl-robustness.md, "Side lobes on the
    default mesh"). Where the case gives no nodes and the converged solution's minimum film
    has an estimated error across y above :data:`asperity.diagnostics.MIN_FILM_MESH_ERROR`
    (:func:`asperity.diagnostics.minimum_film_curvature`), the contact is solved once more on
    the fewest doublings of the rows that bring the ``dY^2`` scaling of that error under the
    limit, at most those :func:`asperity.ehl.rows.doubled_rows` allows on
    :data:`SIDE_LOBE_MAX_NODES` nodes and cells ``dY >= FINE_CELL_ASPECT dX`` (the cells the
    mesh line advises; ``SIDE_LOBE_SHORT_ASPECT dX`` up to ``SIDE_LOBE_SHORT_CELLS_M``; the
    x spacing and the domain kept). A finer solution that does not
    converge is not taken. A soft contact (:attr:`PointContact.soft`) keeps its mesh and the
    mesh line's advice: its relaxation on the finer rows took 154 s against 18 s for the
    PDMS ball of ``tests/corpus/warn-ehl-point-soft-side-lobes.toml`` (and its advised mesh
    did not converge, docs/ehl-robustness.md).

    Parameters
    ----------
    case : EHLSteadyCase
    problem : PointContact or LineContact
    res : SteadyResult
        The solution on the chosen mesh.
    solve : callable
        ``solve(options)``: the runner's solve with ``nx``, ``ny``, ``domain``, ``levels``.

    Returns
    -------
    (SteadyResult, str)
        The solution kept and a note on the rows ('' where they were not doubled).
    """
    if res.y.size == 1 or problem.soft or not res.converged \
            or not (case.regime_mesh or case.regime_nodes):
        return res, ""
    curvature = diagnostics.minimum_film_curvature(res.film, "y")
    if curvature is None or not curvature[1] > diagnostics.MIN_FILM_MESH_ERROR:
        return res, ""
    nx, ny = res.x.size, res.y.size
    aspect = SIDE_LOBE_SHORT_ASPECT if problem.M <= SIDE_LOBE_SHORT_CELLS_M \
        else FINE_CELL_ASPECT
    finer = doubled_rows(problem, nx, ny, res.y[-1] - res.y[0], res.x[1] - res.x[0],
                         min(MAX_NODES, SIDE_LOBE_MAX_NODES), aspect=aspect)
    if not finer:
        return res, ""
    error = min(curvature[1], 1.0)
    rows = next((n for n in finer if error * ((ny - 1) / (n - 1)) ** 2
                 <= diagnostics.MIN_FILM_MESH_ERROR), finer[-1])
    domain = ((res.x[0], res.x[-1]), (res.y[0], res.y[-1]))
    levels = case.solver.levels if "levels" in case.solver.model_fields_set else None
    trial = solve({"nx": nx, "ny": rows, "domain": domain, "levels": levels})
    b = problem.b
    estimate = "over 100 %" if curvature[1] >= 1.0 else f"{curvature[1]:.0%}"
    before = (f"on the {ny} rows across y of the default mesh "
              f"(dy = b/{b / (res.y[1] - res.y[0]):.3g}) the minimum film, "
              f"{res.minimum_film * 1e9:.4g} nm, was not resolved (estimated error {estimate})")
    if not trial.converged:
        return res, (f"Mesh: {before}; solved again on {rows} rows, which did not converge "
                     f"(residual {trial.residual:.2e}), so the results are those of {ny} rows.")
    return trial, (f"Mesh: {before}; the contact was solved again on {rows} rows "
                   f"(dy = b/{b / (trial.y[1] - trial.y[0]):.3g}, {trial.total_sweeps} sweeps), "
                   f"whose results these are: minimum film {trial.minimum_film * 1e9:.4g} nm.")


def _sheared_piezoviscous(problem, res) -> bool:
    """Whether a Newtonian film's friction can be the unbounded ``eta du / h`` of a
    pressure-raised viscosity (:func:`asperity.diagnostics.newtonian_traction`): the surfaces
    slide and ``alpha p_max > ISOVISCOUS``. A PTFE ball rolling in silicone oil (alpha = 0,
    0.2 N, xi = 0) has a friction coefficient of 0.105 from its Poiseuille flow alone, the
    rolling resistance ``int p x dA / (2 Rx w)`` of a hydrodynamic contact, which an Eyring
    stress does not change; it was told to set lubricant.tau0."""
    alpha_p = problem.lubricant.pressure_viscosity * res.max_pressure
    return problem.sliding_speed != 0.0 and alpha_p > ISOVISCOUS


def isoviscous_line_advice(problem, res) -> str:
    """What works for an unconverged isoviscous line contact on more than
    :data:`asperity.ehl.line_newton.MAX_NODES` nodes ('' for any other contact).

    With the viscosity constant the Poiseuille flow weighs in everywhere, the Reynolds rows
    are elliptic through the contact, and the point update's smooth pressure errors (and so
    the load) relax only over about ``nx^2`` sweeps: rollers at M = 30-118, L = 0 did not
    converge on 513-2049 nodes. The steady solver then solves the grid by Newton
    (:mod:`asperity.ehl.line_newton`), on at most ``MAX_NODES`` nodes: there they converge
    within 0.3 % of an isoviscous-elastic solution of the same contacts solved independently
    (docs/ehl-robustness.md, session 38)."""
    if not _isoviscous_line(problem) or res.x.size <= NEWTON_MAX_NODES:
        return ""
    alpha_ph = problem.lubricant.pressure_viscosity * problem.p_hertz
    return (f" An isoviscous line contact (alpha p_h = {alpha_ph:.2g}, Moes M = {problem.M:.3g}) "
            f"does not converge on {res.x.size} nodes: its Poiseuille flow relaxes over about "
            f"nx^2 sweeps; on at most grid.nx = {NEWTON_MAX_NODES} nodes the solver finishes "
            "it by Newton's method (converged at M = 30-118).")


#: The largest Moes M of the robustness table the defaults converge on (issue 17:
#: M = 10-1000; docs/ehl-robustness.md).
TESTED_M = 1000.0


def beyond_tested_range(problem) -> str:
    """Where an unconverged contact's Moes M is beyond :data:`TESTED_M`, a sentence saying
    so (a heavy slow roller at M = 4937 was told only to raise max_sweeps)."""
    if not problem.M > TESTED_M:
        return ""
    return (f" Its Moes M = {problem.M:.3g} is beyond the M <= {TESTED_M:g} the default mesh and "
            "relaxation are tested on (docs/ehl-robustness.md): its Hertzian pressure needs a "
            "finer mesh and more levels (grid.nx, solver.levels), and a check of the load, "
            "speed and viscosity units first.")


def _isoviscous_line(problem) -> bool:
    """A line contact whose viscosity hardly rises over the contact (``alpha p_h <=
    ISOVISCOUS``)."""
    return isinstance(problem, LineContact) and \
        problem.lubricant.pressure_viscosity * problem.p_hertz <= ISOVISCOUS


def stall_advice(case, res) -> str:
    """What to change for a steady solve that stopped short of its tolerance: a residual that
    stalled within ``STALLED_WITHIN`` times the tolerance, before the sweep limit, is a
    solution close to converged whose last digits the iteration cannot settle (a user's roller
    bearing stopped at 1.8e-5 against 1e-5 after 5,460 sweeps, its central film 4 % from Moes's
    formula); more sweeps would not help there. A point contact on cells shorter across y
    than ``FINE_CELL_ASPECT`` times their length is told the cells its relaxation needs on
    fine meshes."""
    tol, limit = case.solver.tolerance, case.solver.sweep_limit(res.y.size == 1)
    short = res.y.size > 1 and res.y[1] - res.y[0] < FINE_CELL_ASPECT * (res.x[1] - res.x[0])
    cells = f"; cells at least {FINE_CELL_ASPECT:g} dx across y" if short else ""
    if res.sweeps >= limit or not res.residual < STALLED_WITHIN * tol:
        return (f" Raise solver.max_sweeps (now {limit}) if the residual was still falling, "
                f"else check the inlet and the mesh (grid.nx, solver.levels{cells}).")
    return (f" It stalled at {res.residual / tol:.2g} times the tolerance {tol:g}: close to a "
            "solution, but not one; loosen solver.tolerance (e.g. "
            f"{10 ** np.ceil(np.log10(res.residual)):g}) if that is accurate enough, or change "
            "the mesh (grid.nx, solver.levels) or the inlet (grid.x_min); more sweeps do not "
            "help.")


def relaxed_cells(problem) -> tuple[float, int | None]:
    """The cells (least ``dy / dx``) and the most nodes across y on which the steady
    relaxation of a point contact converges: ``FINE_CELL_ASPECT`` (6) and no limit (on
    cells 3-4 dx across a thin film's x-line relaxation swung on fine meshes,
    :data:`asperity.ehl.solver.FINE_CELL_ASPECT`), but ``SOFT_CELL_ASPECT`` (3, with the
    solver's fallback for soft contacts) and ``SOFT_MAX_NY`` (129) for an isoviscous elastic
    contact (:attr:`PointContact.soft`), which did not converge on 257 nodes across at
    M = 434 and 964, nor on 409 (:data:`asperity.ehl.solver.SOFT_MAX_NY`)."""
    soft = not isinstance(problem, LineContact) and problem.soft
    return (SOFT_CELL_ASPECT, SOFT_MAX_NY) if soft else (FINE_CELL_ASPECT, None)


def _cell_advice(problem, res) -> list[str]:
    """What to change for a point contact that did not converge, or converged only in the
    solver's second try with y-line sweeps, on cells shorter across y than
    ``Y_LINES_BELOW`` times their length (:data:`asperity.ehl.solver.Y_LINES_BELOW`, where
    the y-line sweeps are tried) or, for soft EHL, on more than ``SOFT_MAX_NY`` nodes
    across: the largest ``grid.ny`` on the cells :func:`relaxed_cells` allows."""
    dx, dy = res.x[1] - res.x[0], res.y[1] - res.y[0]
    aspect, max_ny = relaxed_cells(problem)
    too_many = max_ny is not None and res.y.size > max_ny and not res.converged
    if dy >= min(aspect, Y_LINES_BELOW) * dx * (1.0 - 1e-9) and not too_many:
        return []  # (cells from 3 dx on: the stall advice names them, stall_advice)
    ny = 1 + int((res.y[-1] - res.y[0]) / (aspect * dx) * (1.0 + 1e-9))
    if max_ny is not None:
        ny = min(ny, max_ny)
    if res.converged:
        outcome = (f"the x-line relaxation did not converge and the solution is that of a "
                   f"second solve with a y-line sweep after every x-line sweep ({res.sweeps} "
                   "sweeps on the finest grid)")
    else:
        outcome = ("the relaxation did not converge" if dy >= Y_LINES_BELOW * dx else
                   "neither the x-line relaxation nor the y-line sweeps tried after it "
                   "converged")
    cells = (f"The cells are {dy / dx:.2g} dx across (dy = {dy * 1e6:.3g} um, dx = "
             f"{dx * 1e6:.3g} um)")
    if max_ny is None:
        return [f"{cells}: on such cells neighbouring rows couple strongly (through the "
                f"flow across y and the elastic deflection), and {outcome}. The relaxation "
                f"converges best, and fastest, on cells with dy >= {aspect:g} dx: "
                f"grid.ny <= {ny} with this nx (for more nodes across, raise nx with ny), or "
                "leave out grid.nx and grid.ny so that the mesh follows the contact."]
    alpha_ph = problem.lubricant.pressure_viscosity * problem.p_hertz
    return [f"{cells} on {res.y.size} nodes across, and {outcome}. For an isoviscous elastic "
            f"contact (alpha p_h = {alpha_ph:.2g}, Moes M = {problem.M:.3g}) the relaxation, "
            "with its fallback of a far-field refresh every sweep and a smaller load gain, "
            f"converges on cells at least {aspect:g} dx across and on at most {max_ny} nodes "
            f"across: use grid.ny <= {ny} with this nx, or leave out grid.nx and grid.ny "
            "(the default mesh converges)."]


def _hertz_zone(problem, res) -> np.ndarray:
    """The nodes of ``res`` inside the Hertz contact of ``problem``, shape of its film."""
    x = res.x[:, None] / problem.a
    if isinstance(problem, LineContact):
        return np.abs(x) < 1.0  # the film of a line contact is (nx, 1)
    return x**2 + (res.y[None, :] / problem.b) ** 2 < 1.0


def chosen_mesh(case, problem, x, y) -> dict:
    """The mesh and domain an EHL run chose for the contact, as case keys
    (:attr:`asperity.results.Outcome.chosen`): ``grid.nx``, ``grid.ny`` where the case gives
    no node count, the domain bounds in Hertz semi-axes the [grid] table does not set; a line
    contact's ``grid.ny`` is 1 and its y bounds do not apply (None)."""
    line = isinstance(problem, LineContact)
    chosen = {}
    if not case.grid.nodes_given:
        chosen.update({"grid.nx": int(x.size), "grid.ny": int(y.size)})
    elif line:
        chosen["grid.ny"] = 1
    if line:
        chosen.update({"grid.y_min": None, "grid.y_max": None})
    bounds = {"x_min": x[0] / problem.a, "x_max": x[-1] / problem.a}
    if not line:
        bounds.update({"y_min": y[0] / problem.b, "y_max": y[-1] / problem.b})
    chosen.update({f"grid.{key}": float(value) for key, value in bounds.items()
                   if key not in case.grid.model_fields_set})
    return chosen


#: The comparison rows of an unbounded rigid-isoviscous contact's film, by summary key.
RIGID_ROWS = {"martin_minimum_film_m": "Martin minimum film (rigid-isoviscous)",
              "brewe_hamrock_taylor_minimum_film_m":
                  "Brewe-Hamrock-Taylor minimum film (rigid-isoviscous)"}


def _rigid_row(problem) -> str | None:
    """The comparison row among :data:`RIGID_ROWS` the run shows, None where it shows none (a
    piezoviscous-rigid contact)."""
    shown = film_formulas(problem)
    return next((label for key, label in RIGID_ROWS.items() if key in shown), None)


def ehl_warnings(case, problem, pressure, x, y, central_film, smooth_film=None,
                 film_solved=True, check_hardness=True) -> list[str]:
    """Trust checks of an EHL solution: inlet, sides, mesh (cells per semi-axis, then the
    discretisation error of the central film and, given the ``smooth_film`` of a steady
    solution, of its minimum film), hardness, and the contact's size against its radius
    (Hertz's small-contact assumption, ``a/R <= 0.1``); a nearly rigid point contact's
    domain against the reach of its pressure (:func:`asperity.diagnostics.ehl_rigid_domain`).

    Shared by the steady and transient runners (:mod:`asperity.diagnostics`). Where the side
    pressure is small but not negligible (``SIDE_PROBE_PRESSURE`` to ``BOUNDARY_PRESSURE`` of
    p_h) on a mesh that resolves the Hertz zone, the film's dependence on the sides is
    measured by :func:`asperity.ehl.sides.side_probe` (two steady solves at twice the mesh
    spacing, or on the default mesh where that is coarser). An inlet shorter than the default
    domain's that the inlet pressure and (point contacts) Hamrock & Dowson's starvation fit
    pass is measured the same way (:func:`asperity.ehl.sides.inlet_probe`, inlet moved to the
    default domain's); where the fit warns, the probe's measured loss is added to its line.
    The node counts of the mesh lines are counted on the domain the inlet, side and rigid
    domain lines advise (:func:`asperity.diagnostics.advised_domain`), so that following
    all of them gives the spacing each asks for.
    ``film_solved``: ``central_film`` is the solution's on this inlet (else a film formula's
    flooded estimate, for an unconverged solve). ``check_hardness`` False leaves the hardness
    to the caller (a transient run judges every step's largest pressure, not one field).
    """
    hz = problem.hertz
    b = None if isinstance(problem, LineContact) else hz.b
    flooded = (None if b is None else diagnostics.flooded_inlet_distance_of(
        x[0], hz.a, problem.rx, central_film, solved=film_solved))
    lines = diagnostics.ehl_inlet(pressure, x, hz.a, hz.p_max, flooded)
    # a nearly rigid contact's pressure varies over sqrt(2 Rx hc), not the Hertz zone: its
    # mesh is judged by ehl_rigid_domain (a lightly loaded ball was told nx >= 1082 x 2001)
    rigid = float(np.max(pressure)) < diagnostics.RIGID_PRESSURE * hz.p_max
    mesh = [] if rigid else diagnostics.ehl_mesh(x, y, hz.a, b)
    fit = []
    # still starved, with the pressure back to ambient? Hamrock & Dowson's fit is of EHL
    # contacts: a nearly rigid one's reach is ehl_rigid_domain's (a light ball was told a
    # 12.9 % loss and x_min <= -160.5 a, beyond the bounds a case takes, beside that line's
    # 87 % loss)
    if b is not None and not lines and not rigid:
        fit = diagnostics.ehl_inlet_length(x[0], hz.a, problem.rx, central_film,
                                           solved=film_solved)
    default_inlet = problem.default_domain()[0][0]
    if not lines and not mesh and not rigid and x[0] > default_inlet + 0.01 * hz.a:
        # an inlet shorter than the default domain's: measured, also where Hamrock & Dowson's
        # fit has warned (it gave 5.5 % for a bearing's 9.6 %)
        probe = inlet_probe(problem, x, y, default_inlet)
        lines += (diagnostics.ehl_inlet_length(x[0], hz.a, problem.rx, central_film,
                                               solved=film_solved, probe=probe)
                  if fit else diagnostics.ehl_inlet_film(probe, hz.a))
    else:
        lines += fit
    if b is not None:
        lines += diagnostics.ehl_sides(pressure, y, b, hz.p_max)
    lines += diagnostics.ehl_rigid_domain(pressure, x, y, problem.rx, central_film, hz.p_max,
                                          hz.a, b, MAX_BOUND, _rigid_row(problem))
    if b is not None and not mesh and diagnostics.SIDE_PROBE_PRESSURE < \
            diagnostics.side_pressure(pressure, y, b) / hz.p_max <= diagnostics.BOUNDARY_PRESSURE:
        lines += diagnostics.ehl_side_film(side_probe(problem, x, y), b)
    if (b is not None and not mesh and not rigid and problem.ry >= problem.rx
            and fit_rigid_share(problem) > RIGID_SHARE):
        # a thick film whose fit adds a rigid-isoviscous film of its size: the inlet and the
        # sides cut off more together than either alone (a soft ellipse: 30 % against 4 %)
        lines += diagnostics.ehl_domain_film(domain_probe(problem, x, y), hz.a, b)
    # the node counts advised below are counted on the domain advised above: a ball whose
    # sides at +-1.2 b were to go to +-2 b was told ny >= 81, b/33 on its 2.4 b, b/20 on 4 b
    advised = diagnostics.advised_domain(x, y, lines)
    if mesh:
        mesh = diagnostics.ehl_mesh(x, y, hz.a, b, domain=advised)
    lines += mesh
    # fine enough for the film? Also where the Hertz zone has too few cells, whose advice
    # alone asked for nx >= 41 where the film needs 209 (a user's nx = 33: -93 % on the film).
    # The film formula's film, as for the default mesh: a starved or unconverged film would
    # ask for a mesh of the wrong film
    if not rigid:
        film_mesh = diagnostics.ehl_film_mesh(x, hz.a,
                                              problem.film_estimate() / problem.film_scale,
                                              domain=advised)
        lines += film_mesh
    if not mesh and smooth_film is not None:  # (a rough film's minimum: its asperity contacts)
        aspect, max_ny = relaxed_cells(problem)
        lines += diagnostics.ehl_minimum_film_mesh(smooth_film, x, y, hz.a, b, domain=advised,
                                                   cell_aspect=aspect, max_ny=max_ny,
                                                   max_nodes=(MAX_NODES, MAX_NX, MAX_NY))
    if check_hardness and getattr(case, "body1", None) is not None:
        lines += diagnostics.above_hardness(pressure, [("body1", case.body1.material()),
                                                       ("body2", case.body2.material())])
    lines += _contact_size(problem)
    return unit_doubts(case) + lines


def _contact_size(problem) -> list[str]:
    """Hertz's small-contact assumption (:func:`asperity.diagnostics.hertz_validity`, its
    ``a/R`` check), on which the half-space film solution rests: a PDMS ball of 6.35 mm on
    glass at 0.5 N has a = 0.97 mm, a/R = 0.15, and was solved without a word. The strain check
    is left out: its advice (give a hardness, plasticity) fits metals, not the elastomer of a
    soft contact, and a given hardness is checked by ``above_hardness``."""
    hz = problem.hertz
    if isinstance(problem, LineContact):
        a, radius, key = hz.a, problem.radius, "contact.load_per_length"
    else:
        (a, radius), key = max((hz.a, problem.rx), (hz.b, problem.ry),
                               key=lambda pair: pair[0] / pair[1]), "contact.load"
    return diagnostics.hertz_validity(a, radius, hz.p_max, problem.reduced_modulus / 2.0,
                                      hardness_given=True, load_key=key)


def _figures(title, problem, res, line):
    """Lazy figures: contour maps and sections (point), centre-line profiles (both)."""
    from ..plotting.ehl import centre_line_profiles, contour_maps, transverse_section

    x, p_line, h_line = res.centre_line()
    hertz_line = (problem.hertz.pressure(x) if line else problem.hertz.pressure(x, 0.0))
    figures = {
        "centre_line": (
            lambda: centre_line_profiles(x, p_line, h_line, problem.a, hertz_line,
                                         f"{title}: centre line y = 0"),
            "Pressure and film thickness along the entrainment centre line y = 0 (x in units "
            "of the Hertz semi-axis a; shaded: the Hertz contact; dashed: dry Hertz pressure).",
        ),
    }
    if not line:
        a, b = problem.a, problem.b
        p_x0 = np.array([np.interp(0.0, res.x, col) for col in res.pressure.T])
        h_x0 = np.array([np.interp(0.0, res.x, col) for col in res.film.T])
        figures["contours"] = (
            lambda: contour_maps(res.x, res.y, res.pressure, res.film, a, b, res.central_film,
                                 title),
            "Pressure (left) and film thickness (right) contours, each in the unit its colour "
            "bar names, over x/a and y/a on "
            "equal axes (y compressed where its label says so); the heavy ellipse is the "
            "Hertzian dry contact area (cf. Holmes et al. 2005, Fig. 2).",
        )
        figures["transverse"] = (
            lambda: transverse_section(res.y, p_x0, h_x0, b, f"{title}: section x = 0"),
            "Pressure and film across the contact at x = 0 (side constrictions of the film at "
            "the transverse edges).",
        )
    return figures
