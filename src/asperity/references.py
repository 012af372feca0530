"""Which references apply to a run: the comparison rows of each analysis.

A runner solves; this module decides which closed forms and published numbers its result is set
beside, and with what tolerance, so that the choice is tested on its own
(``tests/test_references.py``). Every formula and number is stated, with its source, in
``docs/references.md``; the closed forms themselves live in :mod:`asperity.contact.reference`
and :mod:`asperity.ehl.formulas`.

- :func:`tangential_comparisons`: equilibrium, Cattaneo-Mindlin (Johnson eq. 7.42), Lubkin
  torsion (Johnson eq. 7.50), uniform-pressure torsion (Johnson sec. 7.3), gross-slip loads, and
  the case's ``[reference]`` table (Seireg ch. 3).
- :func:`fretting_cycle_comparisons`: a fretting cycle's energy per cycle and loop width
  against Mindlin and Deresiewicz (Johnson eqs. 7.56, 7.60).
- :func:`ehl_steady_comparisons`: the case's ``[reference]`` table, the Newtonian film formulas
  (Moes 1992 and Dowson-Higginson 1977 for line contacts; Nijenbanning, Venner & Moes 1994 and
  Hamrock-Dowson 1977 for point contacts) and the dry Hertz pressure.
"""

from __future__ import annotations

import math

import numpy as np

from .contact import reference as ref
from .contact.stick_zone import stick_zone
from .ehl import formulas
from .ehl.formula_range import dowson_higginson_range_note, hamrock_dowson_range_note
from .ehl.problem import ELASTIC_M, ISOVISCOUS, LineContact
from .results import Comparison

__all__ = ["DOCS", "cite", "ehl_steady_comparisons", "film_formula_comparisons",
           "film_formulas", "fretting_cycle_comparisons", "lubricant_laws",
           "tangential_comparisons"]

DOCS = "docs/references.md"
"""The page that states every formula and published number a comparison uses."""


# ISOVISCOUS and ELASTIC_M (the soft-EHL regime) are defined with the contact that uses
# them in its solve (asperity.ehl.problem, PointContact.soft) and imported above.


def cite(text: str, anchor: str) -> str:
    """``"<text>; docs/references.md#<anchor>"``: the source and where the project states it."""
    return f"{text}; {DOCS}#{anchor}"


# --- tangential contact ---------------------------------------------------------------------


def _equilibrium(res, applied, free):
    """Carried vs applied load (the solver's constraints), below gross slip."""
    if res.gross_slip:
        return []
    rows = []
    force = np.array(applied[:2])
    if np.any(force):
        along = float(np.dot(res.force, force) / np.linalg.norm(force))
        rows.append(Comparison("force carried", along, float(np.linalg.norm(force)),
                               "equilibrium", "N", 1e-6))
    if free and applied[2] != 0.0:
        rows.append(Comparison("moment carried", res.moment, applied[2], "equilibrium", "N m",
                               1e-6))
    return rows


def _rectangles(spec, mu):
    """Boxes (x1, x2, y1, y2) and weights mu p of the uniformly loaded rectangular regions."""
    weights, boxes = [], []
    for region, center in zip(spec.regions, spec.centers(), strict=True):
        hx, hy = region.half_extents()
        weights.append((region.mu or mu) * region.pressure)
        boxes.append((center[0] - hx, center[0] + hx, center[1] - hy, center[1] + hy))
    return boxes, weights


def _ellipse_rows(mu, h, res, body1, body2, force, axis, identical, x, y):
    """Mindlin's elliptical partial slip under a force along an axis of the Hertz ellipse: the
    shift and the stick ellipse's semi-axes (:func:`asperity.contact.reference.
    cattaneo_mindlin_ellipse`); tolerances as the circle's, with the cell size over the
    semi-axis along the same direction."""
    shift, cx, cy = ref.cattaneo_mindlin_ellipse(h.load, force, mu, h.a, h.b, body1, body2,
                                                 axis)
    fine = max((x[1] - x[0]) / h.a, (y[1] - y[0]) / h.b)
    tol = max(0.01, 2.0 * fine**2)
    src = cite("Mindlin's ellipse, Cattaneo's construction (Johnson sec. 7.2)",
               "cattaneo-mindlin-on-an-ellipse")
    rows = [Comparison("rigid shift (relative)", math.hypot(*res.shift), shift, src, "m", tol)]
    if identical:
        rows.append(Comparison("rigid shift per body", 0.5 * math.hypot(*res.shift), 0.5 * shift,
                               src, "m", tol))
    zone = stick_zone(res.stick, x, y)
    if zone is not None and zone.elliptical:
        for name, measured, exact, cell in (("x", zone.semi_axes[0], cx, x[1] - x[0]),
                                            ("y", zone.semi_axes[1], cy, y[1] - y[0])):
            if exact > 2 * cell:
                rows.append(Comparison(f"stick semi-axis along {name}", measured, exact, src,
                                       "m", max(0.01, 1.5 * cell / exact)))
    return rows


def _hertz_rows(mu, h, res, body1, body2, applied, free, identical, x, y):
    """Closed forms of a Hertz pressure with one friction coefficient."""
    fx, fy, moment = applied
    force = math.hypot(fx, fy)
    rows = []
    circular = abs(h.a - h.b) <= 1e-9 * h.a
    size = min(h.a, h.b)
    dx = max(x[1] - x[0], y[1] - y[0])
    stick = math.sqrt(res.stick.sum() * (x[1] - x[0]) * (y[1] - y[0]) / math.pi)
    if force == 0.0 and free:
        gs = ref.gross_slip_moment_ellipse(mu, h.p_max, h.a, h.b)
        rows.append(Comparison("gross-slip moment", res.load_capacity * abs(moment), gs,
                               cite("(pi/4) mu p0 a^2 b E(1 - b^2/a^2), 3 pi mu P a / 16 for a "
                                     "circle", "gross-slip-loads"),
                               "N m", max(0.005, 0.5 * (dx / size) ** 2)))
    if circular and force == 0.0 and free and not res.gross_slip:
        c = ref.lubkin_stick_radius(abs(moment), h.a, mu, h.p_max)
        twist = ref.lubkin_twist(c, h.a, mu, h.p_max, body1, body2)
        tol = max(0.01, 2.0 * (dx / h.a) ** 2)
        src = cite("Lubkin (1951), Johnson eq. 7.50", "lubkin-torsion")
        rows.append(Comparison("rotation (relative)", abs(res.rotation), twist, src, "rad", tol))
        if identical:
            rows.append(Comparison("rotation per body", 0.5 * abs(res.rotation),
                                   ref.lubkin_twist(c, h.a, mu, h.p_max, body1),
                                   cite("Lubkin (1951), one body vs the interface",
                                         "lubkin-torsion"), "rad", tol))
        rows.append(Comparison("stick radius", stick, c, src, "m", max(0.01, 1.5 * dx / c)))
    if circular and moment == 0.0 and force > 0.0 and not res.gross_slip:
        cm = ref.cattaneo_mindlin(h.load, force, mu, h.a, body1, body2)
        tol = max(0.01, 2.0 * (dx / h.a) ** 2)
        src = cite("Cattaneo-Mindlin, Johnson eq. 7.42", "cattaneo-mindlin")
        rows.append(Comparison("rigid shift (relative)", math.hypot(*res.shift), cm.shift, src,
                               "m", tol))
        if identical:
            rows.append(Comparison("rigid shift per body", 0.5 * math.hypot(*res.shift),
                                   0.5 * cm.shift, cite("Cattaneo-Mindlin, one of two identical "
                                                         "bodies vs the interface",
                                                         "cattaneo-mindlin"), "m", tol))
        if cm.stick_radius > 2 * dx:
            rows.append(Comparison("stick radius", stick, cm.stick_radius, src, "m",
                                   max(0.01, 1.5 * dx / cm.stick_radius)))
    axis = "x" if abs(fy) <= 1e-12 * force else "y" if abs(fx) <= 1e-12 * force else None
    if (not circular and moment == 0.0 and force > 0.0 and axis is not None
            and not res.gross_slip):
        rows += _ellipse_rows(mu, h, res, body1, body2, force, axis, identical, x, y)
    if circular and moment != 0.0 and force > 0.0 and not res.gross_slip:
        note = "one load alone: the combined load couples them; not a check"
        if force < mu * h.load:
            cm = ref.cattaneo_mindlin(h.load, force, mu, h.a, body1, body2)
            rows.append(Comparison("rigid shift (relative)", math.hypot(*res.shift), cm.shift,
                                   cite("Cattaneo-Mindlin, force alone", "cattaneo-mindlin"),
                                   "m", None, note))
        if abs(moment) < ref.gross_slip_moment_hertz(mu, h.load, h.a):
            c = ref.lubkin_stick_radius(abs(moment), h.a, mu, h.p_max)
            rows.append(Comparison("rotation (relative)", abs(res.rotation),
                                   ref.lubkin_twist(c, h.a, mu, h.p_max, body1, body2),
                                   cite("Lubkin, moment alone", "lubkin-torsion"), "rad", None,
                                   note))
    return rows


def _uniform_rows(spec, mu, res, body1, body2, applied, free, dx):
    """Closed forms of uniformly loaded regions with one friction coefficient."""
    fx, fy, moment = applied
    force = math.hypot(fx, fy)
    regions = spec.regions
    rows = []
    if force > 0.0 and not free:
        total = sum(mu * r.pressure * (r.size[0] * r.size[1] if r.shape == "rectangle"
                                       else math.pi * r.radius**2) for r in regions)
        # each region's pressure is scaled to carry p_i A_i exactly (runners.tangential)
        rows.append(Comparison("gross-slip force (rotation fixed)", res.load_capacity * force,
                               total, cite("mu sum p_i A_i", "gross-slip-loads"), "N", 1e-9))
    if force == 0.0 and free and all(r.shape == "rectangle" for r in regions):
        gs, _ = ref.gross_slip_moment_rectangles(*_rectangles(spec, mu))
        rows.append(Comparison("gross-slip moment", res.load_capacity * abs(moment), gs,
                               cite("min over c of sum mu p_i int |r - c| dA (exact "
                                     "rectangles)", "gross-slip-loads"), "N m", 0.01))
    if force == 0.0 and free and len(regions) == 1 and regions[0].shape == "circle":
        r0, a = regions[0], regions[0].radius
        rows.append(Comparison("gross-slip moment", res.load_capacity * abs(moment),
                               ref.gross_slip_moment_uniform(mu, r0.pressure, a),
                               cite("(2 pi / 3) mu p a^3", "uniform-pressure-torsion"), "N m",
                               max(0.01, 2 * dx / a)))
        if not res.gross_slip:
            c = ref.uniform_torsion_stick_radius(abs(moment), a, mu, r0.pressure)
            rows.append(Comparison("rotation (relative)", abs(res.rotation),
                                   ref.uniform_torsion_twist(c, a, mu, r0.pressure, body1, body2),
                                   cite("uniform-pressure torsion, Johnson sec. 7.3",
                                         "uniform-pressure-torsion"), "rad",
                                   max(0.02, 3 * dx / a)))
    return rows


def _published_rows(spec, res, applied, identical):
    """Rows for the published numbers of the case's ``[reference]`` table."""
    rows = []
    tol, src = spec.tolerance, spec.source
    if identical and not res.gross_slip:
        if spec.shift_per_body is not None:
            rows.append(Comparison("rigid shift per body", 0.5 * math.hypot(*res.shift),
                                   spec.shift_per_body, src, "m", tol))
        if spec.rotation_per_body is not None:
            rows.append(Comparison("rotation per body", 0.5 * abs(res.rotation),
                                   spec.rotation_per_body, src, "rad", tol))
        if spec.closed_form_rotation_per_body is not None:
            rows.append(Comparison("rotation per body vs the book's closed-form value",
                                   0.5 * abs(res.rotation), spec.closed_form_rotation_per_body,
                                   src, "rad", tol))
    if spec.gross_slip_moment is not None and applied[2] != 0.0:
        rows.append(Comparison("gross-slip moment", res.load_capacity * abs(applied[2]),
                               spec.gross_slip_moment, src, "N m", tol))
    if spec.gross_slip_force is not None and any(applied[:2]):
        rows.append(Comparison("gross-slip force", res.load_capacity * math.hypot(*applied[:2]),
                               spec.gross_slip_force, src, "N", tol))
    return rows


def tangential_comparisons(case, result, x, y, mu, body1, body2, hertz=None) -> list[Comparison]:
    """The comparison rows of a tangential run.

    Parameters
    ----------
    case : asperity.cases.tangential.TangentialCase
        The validated case (pressure source, loading, ``[reference]`` table).
    result : asperity.contact.TangentialResult
        The solution at the applied load.
    x, y : ndarray
        Cell-centre coordinates of the grid, m.
    mu : ndarray
        Friction coefficient per cell.
    body1, body2 : asperity.materials.Material
        The two bodies.
    hertz : asperity.contact.HertzPoint, optional
        The Hertz solution the pressure was built from (``source = "hertz"`` or ``"normal"``).

    Returns
    -------
    list of Comparison
        In this order: equilibrium (force and moment carried, tolerance 1e-6); the closed forms
        that apply, each with a tolerance that grows with the cell size (Cattaneo-Mindlin under
        a force alone on a circular Hertz contact; Lubkin under a moment alone; the gross-slip
        moment of an elliptical Hertz pressure; uniform-pressure torsion and gross-slip loads of
        uniformly loaded regions; under force and moment together the single-load values are
        shown unchecked); then the published numbers of ``case.reference``. "Per body" rows
        (half the relative motion) appear only for identical bodies. Closed forms apply only
        with one friction coefficient everywhere. See ``docs/references.md``.
    """
    fx, fy = case.loading.vector()
    applied = (fx, fy, case.loading.moment)
    identical = (body1.youngs_modulus, body1.poisson_ratio) == (body2.youngs_modulus,
                                                               body2.poisson_ratio)
    mu = np.broadcast_to(np.asarray(mu, dtype=float), result.stick.shape)
    uniform_mu = bool(np.all(mu == case.mu)) and all(
        r.mu is None for r in (case.pressure.regions or []))
    dx = max(x[1] - x[0], y[1] - y[0])
    free = case.loading.rotation == "free"
    rows = _equilibrium(result, applied, free)
    if uniform_mu and case.pressure.source == "hertz" and hertz is not None:
        # the closed forms take the moment about the contact's centre; a fixture that holds
        # the rotation carries it
        centred = (fx, fy, case.loading.moment_about_origin() if free else 0.0)
        rows += _hertz_rows(case.mu, hertz, result, body1, body2, centred, free, identical, x, y)
    if uniform_mu and case.pressure.source == "uniform":
        rows += _uniform_rows(case.pressure, case.mu, result, body1, body2, applied, free, dx)
    if case.reference is not None:
        rows += _published_rows(case.reference, result, applied, identical)
    return rows


def fretting_cycle_comparisons(forces, dissipated, width, hertz, mu, body1, body2,
                               dx) -> list[Comparison]:
    """A fretting cycle's energy and loop width beside Mindlin and Deresiewicz's closed forms.

    Parameters
    ----------
    forces : array_like
        The path's tangential force (a force alone, along one direction) at each step, a
        cycle 0 -> Q* -> -Q* -> Q*, N.
    dissipated : float
        The path's work over the closed loop, J (NaN when the loop did not close).
    width : float or None
        The loop's width, the relative shift between its unloading and reloading branches at
        zero force, m (None: the cycle does not pass through zero).
    hertz : asperity.contact.HertzPoint
        The circular Hertz contact the pressure was built from.
    mu : float
        Friction coefficient (one everywhere).
    body1, body2 : asperity.materials.Material
        Similar bodies (Dundurs beta = 0, where the closed form holds).
    dx : float
        The larger cell side, m.

    Returns
    -------
    list of Comparison
        None when the loop did not close or Q* >= mu P. The loop width against Masing's
        ``2 [delta(Q*) - 2 delta(Q*/2)]`` (Johnson eq. 7.56 at Q = 0 on each branch), a
        difference of shifts, so its tolerance is the shift's 0.2 % of 2 delta(Q*) over the
        width, at least 2 %; then the loop area, by the
        trapezoidal rule through the steps, against
        :func:`asperity.contact.reference.mindlin_deresiewicz_energy`. The same rule on the
        closed-form Masing loop through the same steps (:func:`asperity.contact.reference.
        masing_history`) gives the part of the difference that the steps make (-0.72 % at 6
        steps per quarter cycle, Q* = 0.6 mu P; -0.26 % at 10); it is in the row's note and
        added to its tolerance, ``max(1 %, 2 (dx/a)^2)`` for the grid.
    """
    forces = np.asarray(forces, dtype=float)
    peak = float(np.max(np.abs(forces)))
    if not (math.isfinite(dissipated) and 0.0 < peak < mu * hertz.load):
        return []
    exact = ref.mindlin_deresiewicz_energy(peak, hertz.load, mu, hertz.a, body1, body2)
    shift, force = ref.masing_history(forces, hertz.load, mu, hertz.a, body1, body2, points=1)
    first = int(np.argmax(force >= peak))  # the loop starts at the first visit of Q*
    q, d = force[first:], shift[first:]
    bias = float(np.sum(0.5 * (q[1:] + q[:-1]) * np.diff(d))) / exact - 1.0
    steps = first
    note = (f"the loop's area by the trapezoidal rule through {steps} steps per quarter "
            f"cycle; the same rule on the closed-form loop gives {100 * bias:+.2g} %; raise "
            "load_path.steps for a closer energy")
    rows = []
    if width is not None:
        opening = 2.0 * ref.masing_unloading_shift(0.0, peak, hertz.load, mu, hertz.a, body1,
                                                   body2)
        peak_shift = ref.cattaneo_mindlin(hertz.load, peak, mu, hertz.a, body1, body2).shift
        rows.append(Comparison("loop width at zero force", width, opening,
                               cite("Masing, Johnson eq. 7.56", "masing"), "m",
                               max(0.02, 0.002 * 2.0 * peak_shift / opening)))
    return rows + [Comparison("energy per cycle", dissipated, exact,
                              cite("Mindlin-Deresiewicz, Johnson eq. 7.60", "masing"), "J",
                              max(0.01, 2.0 * (dx / hertz.a) ** 2) + abs(bias), note)]


# --- steady EHL -----------------------------------------------------------------------------

_NEWTONIAN_NOTE = (
    "Newtonian isothermal fit; the solution uses the case's lubricant laws ({laws}), so the "
    "two differ by design: not a check")
#: What is known of the central-film fits at L -> 0 (``alpha p_h <= ISOVISCOUS``), measured in
#: sessions 37 and 39 (docs/ehl-robustness.md, "Isoviscous line contacts at M >= 30",
#: "Low L" and "An independent point contact at L = 0").
_LOW_L_NOTES = {
    "moes_central_film_m": (
        "; at L = 0 the fit lies 2.5-4.2 % above Herrebrugh's isoviscous-elastic line contact "
        "solved independently (M = 30-117)"),
    "nijenbanning_central_film_m": (
        "; at L = 0 an independent point-contact solution (dense Love panels, Newton; "
        "mesh-converged to 0.3 %), which the solver matches within 0.1 %, lies 0.936 "
        "(circle, M = 102), 0.93 (circle, M = 964) and 1.073 (k = 4.9, M = 61; 1.11 on a "
        "domain converged in its inlet and sides) times the fit: a difference up to about 8 % "
        "either way is the fit's, not the solver's"),
}

#: What an independent solution says of a fit in every regime it is shown in, measured in
#: session 39 (docs/ehl-robustness.md, "Ellipses entrained along the major axis").
_FIT_NOTES = {
    "chittenden_central_film_m": (
        "; at Moes M = 100, L = 10 an independent point-contact solution (dense Love panels, "
        "Newton; mesh-converged to 0.2 %), which the solver matches within 0.3 %, gives 1.43 "
        "(k = 0.5) and 1.78 (k = 0.25) times this transcription's central film: a film that "
        "far above it is the formula's difference, not the solver's"),
}


#: The maximum-pressure row's note for a Barus, incompressible oil (:func:`barus_spike`),
#: measured in session 41 (docs/ehl-robustness.md, "Moes' line fit at low M"): its exit
#: spike is not mesh-converged on the default meshes, while the films are.
BARUS_SPIKE_NOTE = (
    "; the exit spike of an incompressible Barus oil sharpens as the mesh is refined, so "
    "this maximum is the mesh's, not a converged value (1.07, 1.26, 1.60 p_h on 145, 289, "
    "577 nodes along x for a circle at Moes M = 100, L = 10; 1.07, 1.34, 2.00 p_h on 157, "
    "313, 625 for a line at M = 10, L = 10, their central films moving 0.6 % and 0.2 % over "
    "the last refinement); with the Roelands law and Dowson-Higginson's density twelve "
    "contacts moved under 0.2 %")


def lubricant_laws(lubricant) -> str:
    """The lubricant's laws in words, e.g. ``"Roelands, incompressible, Newtonian"``."""
    lub = lubricant
    shear = "Newtonian" if lub.newtonian else f"Eyring tau0 = {lub.eyring_stress / 1e6:.3g} MPa"
    density = "Dowson-Higginson density" if lub.compressible else "incompressible"
    return ", ".join([lub.viscosity_model.capitalize(), density, shear])


def film_formulas(problem) -> dict[str, float]:
    """The Newtonian film-thickness formulas that apply to an EHL problem, m.

    Line contact: Moes (1992) central film, and Dowson-Higginson (1977) minimum film when the
    pressure-viscosity coefficient is positive; Martin's (1916) rigid-isoviscous film where the
    contact is isoviscous and ``M < ELASTIC_M``. Point contact: Nijenbanning, Venner & Moes
    (1994) central film when ``ry >= rx`` (entrainment along the minor axis), and with alpha >
    0 the Hamrock-Dowson (1977) central and minimum films there (their fit covers 1 <= k <= 8,
    and their rows say so beyond;
    left out where Brewe-Hamrock-Taylor's rigid-isoviscous or the soft-EHL rows are given, and
    their rows note the regime below ``ELASTIC_M``: :data:`RIGID_FIT_NOTE`), Chittenden et
    al.'s (1985) where ``ry < rx`` (k < 1, entrainment along the major axis: a traction drive's
    contact, where Hamrock-Dowson was shown before) and ``alpha p_h > ISOVISCOUS`` (like
    Hamrock-Dowson's, a piezoviscous-elastic fit). Where the viscosity hardly rises over the
    contact (``alpha p_h <= ISOVISCOUS``: a soft or a water-lubricated contact), the contact
    deforms (``M >= ELASTIC_M``) and ``ry >= rx``, also Hamrock & Dowson's (1978)
    isoviscous-elastic films (soft EHL); a PDMS ball on glass in water-glycerol (M = 960, L =
    0) had only Nijenbanning's film beside it. Below ``ELASTIC_M`` a contact is set beside
    Brewe, Hamrock & Taylor's (1979) rigid-isoviscous minimum film instead where alpha times
    its own pressure scale (:func:`asperity.ehl.formulas.rigid_mean_pressure`) is at most
    ``ISOVISCOUS``.

    Returns
    -------
    dict
        Summary key (``moes_central_film_m``, ``dowson_higginson_minimum_film_m``,
        ``martin_minimum_film_m``,
        ``nijenbanning_central_film_m``, ``hamrock_dowson_central_film_m``,
        ``hamrock_dowson_minimum_film_m``, ``hamrock_dowson_soft_central_film_m``,
        ``hamrock_dowson_soft_minimum_film_m``, ``brewe_hamrock_taylor_minimum_film_m``,
        ``chittenden_central_film_m``,
        ``chittenden_minimum_film_m``) -> film thickness, m.
    """
    lub = problem.lubricant
    args = (problem.mean_speed, lub.viscosity, lub.pressure_viscosity, problem.reduced_modulus)
    values = {}
    if isinstance(problem, LineContact):
        values["moes_central_film_m"] = formulas.moes_line(problem.load_per_length,
                                                           problem.radius, *args).central
        if lub.pressure_viscosity * problem.p_hertz <= ISOVISCOUS and problem.M < ELASTIC_M:
            values["martin_minimum_film_m"] = formulas.martin_line(
                problem.load_per_length, problem.radius, problem.mean_speed,
                lub.viscosity).minimum
        if lub.pressure_viscosity > 0:
            values["dowson_higginson_minimum_film_m"] = formulas.dowson_higginson_line(
                problem.load_per_length, problem.radius, *args).minimum
        return values
    if problem.ry >= problem.rx:
        values["nijenbanning_central_film_m"] = formulas.nijenbanning_point(
            problem.load, problem.rx, problem.ry, *args).central
    if (problem.ry >= problem.rx and lub.pressure_viscosity * problem.p_hertz <= ISOVISCOUS
            and problem.M >= ELASTIC_M):
        soft = formulas.hamrock_dowson_soft_point(problem.load, problem.rx, problem.ry,
                                                  problem.mean_speed, lub.viscosity,
                                                  problem.reduced_modulus)
        values.update(hamrock_dowson_soft_central_film_m=soft.central,
                      hamrock_dowson_soft_minimum_film_m=soft.minimum)
    if problem.ry >= problem.rx and problem.M < ELASTIC_M:
        # judged on the rigid film's own pressure, not p_h (a glass ball in glycerol: p_h
        # 109 MPa, film pressure 0.7 MPa; its domain line pointed to a row it did not have)
        rigid = formulas.brewe_hamrock_taylor_point(
            problem.load, problem.rx, problem.ry, problem.mean_speed, lub.viscosity,
            problem.reduced_modulus).minimum
        if lub.pressure_viscosity * formulas.rigid_mean_pressure(
                problem.load, problem.rx, rigid) <= ISOVISCOUS:
            values["brewe_hamrock_taylor_minimum_film_m"] = rigid
    # rigid- or elastic-isoviscous: the piezoviscous-elastic fits are left out (Hamrock-Dowson
    # gave the glass ball in glycerol 440 nm against its solution's 8.2 um, a PDMS ball in a
    # silicone oil of 15 1/GPa, alpha p_h = 0.002, 72 nm against the soft fit's 2.5 um)
    isoviscous_rows = {"brewe_hamrock_taylor_minimum_film_m",
                       "hamrock_dowson_soft_central_film_m"} & values.keys()
    if lub.pressure_viscosity > 0 and problem.ry >= problem.rx and not isoviscous_rows:
        hd = formulas.hamrock_dowson_point(problem.load, problem.rx, problem.ry, *args)
        values.update(hamrock_dowson_central_film_m=hd.central,
                      hamrock_dowson_minimum_film_m=hd.minimum)
    elif (lub.pressure_viscosity > 0 and problem.ry < problem.rx
          and lub.pressure_viscosity * problem.p_hertz > ISOVISCOUS):  # k < 1: outside
        # Hamrock-Dowson's fit (1 <= k <= 8), inside Chittenden's (ry/rx from about 1/50);
        # a piezoviscous-elastic fit, left out of an isoviscous contact as Hamrock-Dowson's is
        # (a rubber ellipse k = 0.23 in a silicone oil, alpha p_h = 0.0045: 353.8 nm against
        # Chittenden's 28.6 nm, shown with no word; docs/ehl-robustness.md, session 40)
        ch = formulas.chittenden_point(problem.load, problem.rx, problem.ry, *args)
        values.update(chittenden_central_film_m=ch.central,
                      chittenden_minimum_film_m=ch.minimum)
    return values


_FILM_ROWS = {  # summary key -> (quantity, result attribute, source, anchor)
    "moes_central_film_m": ("central film", "central_film", "Moes (1992)", "moes-line"),
    "dowson_higginson_minimum_film_m": ("minimum film", "minimum_film",
                                        "Dowson-Higginson (1977)", "dowson-higginson-line"),
    "nijenbanning_central_film_m": ("central film", "central_film",
                                    "Nijenbanning, Venner & Moes (1994)", "nijenbanning-point"),
    "hamrock_dowson_central_film_m": ("central film", "central_film", "Hamrock-Dowson (1977)",
                                      "hamrock-dowson-point"),
    "hamrock_dowson_minimum_film_m": ("minimum film", "minimum_film", "Hamrock-Dowson (1977)",
                                      "hamrock-dowson-point"),
    "hamrock_dowson_soft_central_film_m": ("central film", "central_film",
                                           "Hamrock-Dowson soft EHL (1978)",
                                           "hamrock-dowson-soft-point"),
    "hamrock_dowson_soft_minimum_film_m": ("minimum film", "minimum_film",
                                           "Hamrock-Dowson soft EHL (1978)",
                                           "hamrock-dowson-soft-point"),
    "martin_minimum_film_m": ("minimum film", "minimum_film", "Martin rigid-isoviscous (1916)",
                              "martin-line"),
    "brewe_hamrock_taylor_minimum_film_m": ("minimum film", "minimum_film",
                                            "Brewe-Hamrock-Taylor rigid-isoviscous (1979)",
                                            "brewe-hamrock-taylor-point"),
    "chittenden_central_film_m": ("central film", "central_film",
                                  "Chittenden, Dowson, Dunn & Taylor (1985)", "chittenden-point"),
    "chittenden_minimum_film_m": ("minimum film", "minimum_film",
                                  "Chittenden, Dowson, Dunn & Taylor (1985)", "chittenden-point"),
}
# The central-film fits (Moes, Nijenbanning) are checked at 5 % when the lubricant is their own
# model; Dowson-Higginson and Hamrock-Dowson are regressions over other solutions: shown only.
_CHECKED_FITS = {"moes_central_film_m", "nijenbanning_central_film_m"}
#: Tolerance of a checked fit's row where ``alpha p_h <= ISOVISCOUS`` when its measured
#: accuracy there is worse than 5 %: Nijenbanning's fit lies 6.8 % (M = 102) and 7.5 %
#: (M = 964) above an independent point-contact solution at L = 0, and 6.8 % under it for an
#: ellipse (k = 4.9, M = 61; session 41, "Soft ellipses at L = 0"), which the solver matches
#: within 0.1 % (tests/point_ehl_reference.py): at 5 % a right solution read "differs".
LOW_L_TOLERANCE = {"nijenbanning_central_film_m": 0.10}
#: A checked fit (Moes, Nijenbanning) is not checked where its rigid-isoviscous asymptote
#: ``H_RI`` reaches this share of the part it is added to (:func:`fit_rigid_share`): at low M
#: the fits add a rigid-isoviscous film to another of its size, which independent solutions
#: of the same equations do not do (session 41, docs/ehl-robustness.md, "Nijenbanning's fit
#: where its two parts meet", "Moes' line fit at low M" and "Soft ellipses at L = 0"). In a
#: piezoviscous contact the part is the piezoviscous one: below 0.3 the solver's films over
#: maps of both fits lay within 6 % of them but for one line point (0.915 at L = 20, M = 1.5,
#: share 0.24). At L -> 0 (``alpha p_h <= ISOVISCOUS``), where Nijenbanning's fit is its
#: isoviscous part alone, it is the elastic-isoviscous term ``H_EI00``: an independent
#: solution lay 0.753 and 0.604 times the fit at shares 0.95 and 1.64 (soft ellipses k = 3.4
#: and 9.3, M = 18 and 33) on the default domain, and the solver's film 0.85 and 0.79 times
#: it on a domain converged in its inlet and sides (the film rises 13 % and 30 % there);
#: 0.93-1.07 at shares up to 0.19 (1.11 domain-converged); the solver's films at L = 0 over
#: k = 1-8, M = 10-100 (default meshes) lie 0.93-1.08 of the fit below 0.3, and above it fall
#: from 0.975 (0.30) to 0.90 (0.6) and 0.61-0.67 (1.1-1.6).
RIGID_SHARE = 0.3
#: The note of a checked fit's row above :data:`RIGID_SHARE`, by summary key and by whether
#: the contact is isoviscous (``alpha p_h <= ISOVISCOUS``).
RIGID_SHARE_NOTES = {
    ("nijenbanning_central_film_m", False): (
        "; not a check here: the fit's rigid-isoviscous term is {share:.2g} of its "
        "piezoviscous part (above {limit:g}), where the fit adds the two; an independent "
        "point-contact solution (dense Love panels, Newton), which the solver matches within "
        "0.5 %, lies 0.89, 0.77 and 0.64 times the fit at shares 0.45, 0.60 and 0.97 "
        "(k = 2-4.5, M = 8-20, L = 13.1) on the default domain; the last one's film rises to "
        "0.73 of the fit with the inlet and the sides 8 times as far out (and still rises)"),
    ("nijenbanning_central_film_m", True): (
        "; not a check here: the fit's rigid-isoviscous term is {share:.2g} of the "
        "elastic-isoviscous term it is added to (above {limit:g}); an independent "
        "point-contact solution (dense Love panels, Newton), which the solver matches within "
        "0.02 %, lies 0.75 and 0.60 times the fit at shares 0.95 and 1.64 (soft ellipses "
        "k = 3.4 and 9.3, M = 18 and 33, L = 0) on the default domain, and 0.85 and 0.79 "
        "times it on a domain converged in its inlet and sides"),
    ("moes_central_film_m", True): (
        "; not a check here: the fit's rigid-isoviscous term is {share:.2g} of the "
        "elastic-isoviscous term it is added to (above {limit:g}): a contact that hardly "
        "deforms, where the fit tends to its H_RI = 3/M, a film of 6 eta0 u R / w', 22 % above "
        "the exact rigid-isoviscous film of a cylinder, Martin's 4.9 eta0 u R / w' (a user's "
        "roller at M = 0.59: the solver's 321.8 nm against the fit's 416.1 and Martin's "
        "305.9 nm)"),
    ("moes_central_film_m", False): (
        "; not a check here: the fit's rigid-isoviscous term is {share:.2g} of its "
        "piezoviscous part (above {limit:g}), where the fit adds the two; an independent "
        "line-contact solution (Grubin's reduced pressure, line panels, Newton), which the "
        "solver matches within 0.7 %, lies 0.76-0.98 times the fit at shares 0.32-0.91 "
        "(M = 0.5-3, L = 5-20)"),
}
#: Fits to piezoviscous-elastic solutions, outside their regime in a contact that hardly
#: deforms (Moes M < ``ELASTIC_M``).
_ELASTIC_FITS = {"hamrock_dowson_central_film_m", "hamrock_dowson_minimum_film_m"}
#: The note of an :data:`_ELASTIC_FITS` row below ``ELASTIC_M`` (Hamrock & Dowson 1977 fitted
#: solutions of deforming, piezoviscous contacts; a rigid-piezoviscous ball at M = 2.3,
#: L = 21 gets 1.56 um from it against Nijenbanning's 2.11 um, which covers the rigid limits).
RIGID_FIT_NOTE = (
    "; outside the fit's regime: Moes M = {M:.3g} < {limit:g}, the contact hardly deforms, "
    "and the fit was made to piezoviscous-elastic solutions (Nijenbanning's row covers the "
    "rigid regimes)")


def fit_rigid_share(problem) -> float:
    """The rigid-isoviscous asymptote ``H_RI`` of a contact's central-film fit over the part of
    the fit it is added to: Moes' for a line contact, Nijenbanning's for a point contact
    (:func:`asperity.ehl.formulas.moes_line_parts`,
    :func:`asperity.ehl.formulas.nijenbanning_parts`). ``H_RI / piezo`` in a piezoviscous
    contact (``alpha p_h > ISOVISCOUS``); at L -> 0 ``H_RI / H_EI00`` for Nijenbanning's fit,
    which is then its isoviscous part ``(H_RI^(3/2) + H_EI00^(3/2))^(2/3)`` alone, and
    ``H_RI / H_EI`` for Moes', whose isoviscous part ``(H_RI^(7/3) + H_EI^(7/3))^(3/7)`` is
    then the fit (measured within 2.5-4.2 % where ``H_EI`` dominates, :data:`_LOW_L_NOTES`;
    its ``H_RI = 3/M`` is 22 % above the exact rigid-isoviscous film, Martin's)."""
    lub = problem.lubricant
    isoviscous = lub.pressure_viscosity * problem.p_hertz <= ISOVISCOUS
    args = (problem.mean_speed, lub.viscosity, lub.pressure_viscosity, problem.reduced_modulus)
    if isinstance(problem, LineContact):
        parts = formulas.moes_line(problem.load_per_length, problem.radius, *args).dimensionless
        if isoviscous:
            return parts["H_RI"] / parts["H_EI"]
    else:
        parts = formulas.nijenbanning_point(problem.load, problem.rx, problem.ry,
                                            *args).dimensionless
    return parts["H_RI"] / parts["H_EI00" if isoviscous else "H_piezo"]


def film_formula_comparisons(problem, central_film: float, minimum_film: float,
                             checked: bool = True, label: str = "",
                             note: str = "") -> list[Comparison]:
    """A smooth steady solution's films beside the film formulas of :func:`film_formulas`.

    Parameters
    ----------
    problem : asperity.ehl.PointContact or asperity.ehl.LineContact
        The solved problem.
    central_film, minimum_film : float
        The solution's film at the contact's centre and its least film over the domain, m.
    checked : bool
        Check the central-film fits of Moes and Nijenbanning at 5 % (Nijenbanning's at 10 %
        where ``alpha p_h <= ISOVISCOUS``: :data:`LOW_L_TOLERANCE`; neither where its
        rigid-isoviscous term exceeds :data:`RIGID_SHARE` of the part it is added to,
        :func:`fit_rigid_share`) when the lubricant is Newtonian, Barus and incompressible,
        the fits' own model (every other row, and every row when False, is shown with a note
        and not checked).
    label : str
        Put before each row's quantity (e.g. ``"steady start: "``).
    note : str
        Added to each row's note.

    Returns
    -------
    list of Comparison
    """
    lub = problem.lubricant
    own_model = lub.newtonian and lub.viscosity_model == "barus" and not lub.compressible
    own_note = "Newtonian, Barus, incompressible: the formula's own model"
    other_note = _NEWTONIAN_NOTE.format(laws=lubricant_laws(lub))
    films = {"central_film": central_film, "minimum_film": minimum_film}
    isoviscous = lub.pressure_viscosity * problem.p_hertz <= ISOVISCOUS
    rows = []
    for key, film in film_formulas(problem).items():
        quantity, attribute, source, anchor = _FILM_ROWS[key]
        check = checked and own_model and key in _CHECKED_FITS
        row_note = own_note if own_model else other_note
        tolerance = 0.05
        if isoviscous:
            row_note += _LOW_L_NOTES.get(key, "")
            tolerance = LOW_L_TOLERANCE.get(key, tolerance)
        row_note += _FIT_NOTES.get(key, "")
        share = fit_rigid_share(problem) if (key, isoviscous) in RIGID_SHARE_NOTES else 0.0
        if share > RIGID_SHARE:
            row_note += RIGID_SHARE_NOTES[key, isoviscous].format(share=share,
                                                                  limit=RIGID_SHARE)
            check = False
        if key in _ELASTIC_FITS and problem.M < ELASTIC_M:
            row_note += RIGID_FIT_NOTE.format(M=problem.M, limit=ELASTIC_M)
        if key == "dowson_higginson_minimum_film_m":
            outside = dowson_higginson_range_note(lub.pressure_viscosity
                                                  * problem.reduced_modulus)
            row_note += f"; {outside}" if outside else ""
        if key in _ELASTIC_FITS:
            outside = hamrock_dowson_range_note(problem.b / problem.a)
            row_note += f"; {outside}" if outside else ""
        rows.append(Comparison(label + quantity, films[attribute], film, cite(source, anchor),
                               "m", tolerance if check else None, row_note + note))
    return rows


def ehl_steady_comparisons(problem, result, reference=None) -> list[Comparison]:
    """The comparison rows of a steady EHL run.

    Parameters
    ----------
    problem : asperity.ehl.PointContact or asperity.ehl.LineContact
        The solved problem (geometry, load, speeds, lubricant).
    result : asperity.ehl.SteadyResult
        The solution.
    reference : asperity.cases.ehl.ReferenceSpec, optional
        The case's ``[reference]`` table of published numbers.

    Returns
    -------
    list of Comparison
        The published numbers (at the table's tolerance); the film formulas of
        :func:`film_formulas` (the central-film fits of Moes and Nijenbanning checked at 5 %
        when the lubricant is Newtonian, Barus and incompressible, the fits' own model; every
        other row is shown with a note); the dry Hertz maximum pressure (shown, not checked:
        the EHL pressure differs by design).
    """
    rows = []
    if reference is not None:
        for key, quantity, unit in (
            ("central_film", "central film", "m"),
            ("minimum_film_centreline", "minimum film on y = 0", "m"),
            ("minimum_film", "minimum film", "m"),
            ("max_pressure", "maximum pressure", "Pa"),
        ):
            published = getattr(reference, key)
            if published is not None:
                rows.append(Comparison(quantity, getattr(result, key), published,
                                       reference.source, unit, reference.tolerance))
    rows += film_formula_comparisons(problem, result.central_film, result.minimum_film)
    rows.append(Comparison(
        "maximum pressure", result.max_pressure, problem.hertz.p_max,
        cite("dry Hertz", "hertz"), "Pa",
        note="EHL pressure (inlet build-up, exit spike or shoulder) vs the dry contact"
        + (BARUS_SPIKE_NOTE if barus_spike(problem.lubricant) else "")))
    return rows


def barus_spike(lubricant) -> bool:
    """Whether the lubricant is piezoviscous, Barus and incompressible: the model whose exit
    spike sharpens with the mesh (:data:`BARUS_SPIKE_NOTE`)."""
    return (lubricant.viscosity_model == "barus" and not lubricant.compressible
            and lubricant.pressure_viscosity > 0)
