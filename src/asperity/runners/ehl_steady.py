"""Runner of ``analysis = "ehl-steady"``: smooth steady EHL of a point or line contact.

Solves the case with :func:`asperity.ehl.solve_steady` and sets the result beside the
published numbers of the case's ``[reference]`` table, the Newtonian film formulas
(Hamrock-Dowson and Nijenbanning for point contacts, Moes and Dowson-Higginson for line
contacts) and the dry Hertz pressure.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..ehl import formulas, solve_steady
from ..ehl.problem import LineContact
from ..results import Comparison, Outcome, variable

__all__ = ["run"]

_NEWTONIAN_NOTE = (
    "Newtonian isothermal fit; the solution uses the case's lubricant laws ({laws}), so the "
    "two differ by design: not a check")


def _formula_comparisons(problem, result, exact_model: bool, laws: str):
    """Film-formula rows and their values for the summary (``*_film_m`` keys).

    A row is checked (5 %) only when the lubricant is the formulas' own model.
    """
    lub = problem.lubricant
    args = (problem.mean_speed, lub.viscosity, lub.pressure_viscosity, problem.reduced_modulus)
    tol, note = (0.05, "Newtonian, Barus, incompressible: the formula's own model") \
        if exact_model else (None, _NEWTONIAN_NOTE.format(laws=laws))
    rows = []
    if isinstance(problem, LineContact):
        moes = formulas.moes_line(problem.load_per_length, problem.radius, *args)
        rows.append(Comparison("central film", result.central_film, moes.central, "Moes (1992)",
                               "m", tol, note))
        values = {"moes_central_film_m": moes.central}
        if lub.pressure_viscosity > 0:
            dh = formulas.dowson_higginson_line(problem.load_per_length, problem.radius, *args)
            rows.append(Comparison("minimum film", result.minimum_film, dh.minimum,
                                   "Dowson-Higginson (1977)", "m", None, note))
            values["dowson_higginson_minimum_film_m"] = dh.minimum
        return rows, values
    values = {}
    if problem.ry >= problem.rx:
        nij = formulas.nijenbanning_point(problem.load, problem.rx, problem.ry, *args)
        rows.append(Comparison("central film", result.central_film, nij.central,
                               "Nijenbanning, Venner & Moes (1994)", "m", tol, note))
        values["nijenbanning_central_film_m"] = nij.central
    if lub.pressure_viscosity > 0:
        hd = formulas.hamrock_dowson_point(problem.load, problem.rx, problem.ry, *args)
        src = "Hamrock-Dowson (1977)"
        rows += [Comparison("central film", result.central_film, hd.central, src, "m", None,
                            note),
                 Comparison("minimum film", result.minimum_film, hd.minimum, src, "m", None,
                            note)]
        values.update(hamrock_dowson_central_film_m=hd.central,
                      hamrock_dowson_minimum_film_m=hd.minimum)
    return rows, values


def _reference_comparisons(ref, result):
    """Rows for the published numbers in the case's [reference] table."""
    rows = []
    for key, quantity, value, unit in (
        ("central_film", "central film", result.central_film, "m"),
        ("minimum_film_centreline", "minimum film on y = 0", result.minimum_film_centreline,
         "m"),
        ("minimum_film", "minimum film", result.minimum_film, "m"),
        ("max_pressure", "maximum pressure", result.max_pressure, "Pa"),
    ):
        published = getattr(ref, key)
        if published is not None:
            rows.append(Comparison(quantity, value, published, ref.source, unit, ref.tolerance))
    return rows


def _laws(lub) -> str:
    """The lubricant's laws in words, e.g. "Roelands, incompressible, Newtonian"."""
    shear = "Newtonian" if lub.newtonian else f"Eyring tau0 = {lub.eyring_stress / 1e6:.3g} MPa"
    density = "Dowson-Higginson density" if lub.compressible else "incompressible"
    return ", ".join([lub.viscosity_model.capitalize(), density, shear])


def run(case, progress=None) -> Outcome:
    """Solve the case's steady EHL contact and compare it with its references."""
    problem = case.problem()
    line = isinstance(problem, LineContact)
    nx, ny = case.grid.nodes(line)
    domain = case.grid.domain(problem.a, None if line else problem.b)
    callback = None
    if progress is not None:
        def callback(sweep, residual):
            progress(sweep, None, f"EHL sweep {sweep}, residual {residual:.1e}")

    res = solve_steady(problem, nx=nx, ny=ny, domain=domain, method=case.solver.method,
                       levels=case.solver.levels, tol=case.solver.tolerance,
                       max_sweeps=case.solver.sweep_limit(line),
                       boundary_friction=case.solver.boundary_friction, callback=callback)
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
               "lubricant": _laws(lub), "method": res.method, "sweeps": res.sweeps,
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
    comparisons = []
    if case.reference is not None:
        comparisons += _reference_comparisons(case.reference, res)
    exact_model = (lub.newtonian and lub.viscosity_model == "barus" and not lub.compressible)
    formula_rows, formula_values = _formula_comparisons(problem, res, exact_model, _laws(lub))
    comparisons += formula_rows
    summary.update(formula_values)
    comparisons.append(Comparison(
        "maximum pressure", res.max_pressure, hz.p_max, "dry Hertz", "Pa",
        note="EHL pressure (inlet build-up, exit spike or shoulder) vs the dry contact"))
    figures = _figures(case.title, problem, res, line)
    notes = []
    if not exact_model:
        notes.append(f"The film formulas are Newtonian, isothermal fits; the solution uses "
                     f"{_laws(lub)}, so they are shown for orientation only.")
    if not res.converged:
        notes.append(f"The solver did not converge in {res.sweeps} sweeps on the finest grid "
                     f"(residual {res.residual:.2e}); the numbers above are not trustworthy.")
    return Outcome(ds, summary, figures, comparisons, converged=res.converged, notes=notes)


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
            "Pressure (GPa, upper) and film thickness (um, lower) contours over x/a and y/b; "
            "the heavy curve is the Hertzian dry contact area (cf. Holmes et al. 2005, Fig. 2).",
        )
        figures["transverse"] = (
            lambda: transverse_section(res.y, p_x0, h_x0, b, f"{title}: section x = 0"),
            "Pressure and film across the contact at x = 0 (side constrictions of the film at "
            "the transverse edges).",
        )
    return figures
