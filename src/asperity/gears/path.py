"""Film, lambda, friction and flash temperature along the path of contact of a gear pair.

At every position of the path A-E the gear pair is an EHL contact of its own: the reduced
radius, load and surface speeds of :mod:`asperity.gears.kinematics` and
:mod:`asperity.gears.loading` define a :class:`~asperity.ehl.LineContact` (or a
:class:`~asperity.ehl.PointContact` for crowned flanks), which :func:`asperity.ehl.solve_steady`
solves (smooth, isothermal, with the lubricant's Eyring law). Beside each solution stand the
Newtonian film formulas (Moes central and Dowson-Higginson minimum for a line contact,
Hamrock-Dowson for an elliptical one). The minimum film over the composite roughness is the
specific film thickness lambda; the EHL traction and a boundary friction coefficient, weighted
by the asperity load share of :mod:`asperity.gears.mixed`, give the friction coefficient, and
Blok's formula (:mod:`asperity.gears.thermal`) the flash temperature.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field, replace

import numpy as np

from .. import diagnostics
from ..ehl import formulas, solve_steady
from ..ehl.lubricant import Lubricant
from ..ehl.problem import FILM_ERROR, LineContact, PointContact
from ..errors import InputError
from ..materials import Material
from .geometry import GearPair
from .kinematics import Kinematics, kinematics
from .loading import hertz_along_path, load_jumps, load_sharing
from .mixed import asperity_share, mixed_friction
from .thermal import (
    LOW_PECLET_OVERESTIMATE,
    flash_temperature,
    low_peclet_overestimate,
    peclet_number,
    thermal_contact_coefficient,
)

__all__ = ["BOUNDARY_LUBRICATION_LAMBDA", "GEAR_FILM_MESH_ERROR", "GEAR_FILM_MESH_TARGET",
           "PLAUSIBLE_HERTZ_PRESSURE", "EHLMesh", "GearPathResult", "Thermal", "contact_problem",
           "film_mesh_error", "position_mesh", "solve_path"]

#: Largest Hertz pressure of a gear flank taken as plausible when neither body gives a
#: hardness, Pa: about the static (short-life) permissible contact stress of case-hardened
#: steel, sigma_Hlim 1500-1650 MPa (ISO 6336-5) times the static life factor 1.6 (ISO 6336-2);
#: above it a torque typed in the wrong unit is the likelier cause (docs/gears.md).
PLAUSIBLE_HERTZ_PRESSURE = 2.5e9

#: Estimated central-film discretisation error (:func:`film_mesh_error`) above which a path's
#: mesh is reported, and the estimate the suggested ``[ehl] nx`` aims at. Measured against
#: finer meshes (docs/gears.md) the estimate is 1.2-1.7 times the error at moderate loads and
#: about the error at high M: FZG pitch 12.7 % estimated, about 8 % measured (not reported);
#: a slow steel/bronze pair at B 16.5 %, 10 % (reported; its minimum film 13 % below
#: Dowson-Higginson); the crowned FZG example 19 %, about 18 %; a slow heavily loaded pair
#: (M 161) 49 %, 53 %. The limit was 25 %, which let the bronze pair and the crowned
#: example pass unreported.
GEAR_FILM_MESH_ERROR = 0.15
GEAR_FILM_MESH_TARGET = 0.10

#: Lambda below which a position is reported as in boundary lubrication: a smooth film of a
#: tenth of the composite roughness or less, an order of magnitude below the classical limit
#: of boundary lubrication, lambda = 1, where the friction rule of :mod:`asperity.gears.mixed`
#: already puts all the load on the asperities (Hamrock, Schmid & Jacobson, *Fundamentals of
#: Machine Elements*). There the smooth EHL film describes no real gap (docs/gears.md).
BOUNDARY_LUBRICATION_LAMBDA = 0.1


@dataclass(frozen=True)
class EHLMesh:
    """Mesh and solver options of the steady EHL solve at each path position.

    ``nx`` (and ``ny`` for a point contact) nodes on the finest of ``levels`` grids over
    ``x_min a .. x_max a`` (and ``y_min b .. y_max b``); ``tol``, ``max_sweeps`` and the
    oscillation ``damping`` as in :func:`asperity.ehl.solve_steady` (the point relaxation of a
    heavily loaded line contact oscillates without damping: on the FZG case 8 of 25 positions
    failed to converge in 40 000 sweeps undamped, none with 0.3).

    With ``adapt`` (the default) ``x_min`` is the shortest inlet of a line contact: where its
    fully flooded inlet lies farther upstream the domain is extended there at the same
    spacing (:func:`position_mesh`). Without it every position is solved on ``nx`` nodes over
    ``x_min a .. x_max a`` as given.
    """

    nx: int = 129
    ny: int = 33
    levels: int = 2
    x_min: float = -2.5
    x_max: float = 1.5
    y_min: float = -1.6
    y_max: float = 1.6
    tol: float = 1e-5
    max_sweeps: int = 20_000
    damping: float = 0.3
    adapt: bool = True


def position_mesh(problem, mesh: EHLMesh) -> tuple[float, int]:
    """Inlet (in Hertz semi-widths a) and node count along x of the solve at one position.

    The inlet is the farther upstream of ``mesh.x_min`` and the contact's fully flooded inlet
    (:meth:`asperity.ehl.LineContact.inlet_extent`: Hamrock & Dowson 1977, its inlet length
    counted 1.8 times), at the spacing of ``mesh`` (``nx - 1`` a multiple of
    ``2**(levels - 1)``). A thick film in Hertzian units needs a long inlet: a turbo pair's
    pitch point (M = 2.7) had 13 % less minimum film with the inlet at -2.5 a than at -6.5 a
    (docs/gears.md). An elliptical contact (crowned flanks) keeps ``mesh``: on a crowned
    z 17/43 pair the inlets at -3.1 and -4.2 a (145 and 169 nodes) at A and E made the point
    relaxation fail (a negative film at A, 5 min of retries) where -2.5 a converged in 750 and
    540 sweeps. The spacing is not refined (the point relaxation of the FZG example
    does not converge at 10 of 11 positions on 513 nodes); :func:`film_mesh_error` judges it.

    Parameters
    ----------
    problem : LineContact or PointContact
        The smooth contact at the position.
    mesh : EHLMesh
        The path's mesh options; without ``mesh.adapt`` (or for a point contact) its
        ``x_min`` and ``nx`` are returned.

    Returns
    -------
    (x_min, nx) : (float, int)
    """
    if not mesh.adapt or not isinstance(problem, LineContact):
        return mesh.x_min, mesh.nx
    x_min = min(mesh.x_min, -problem.inlet_extent())
    cells = (mesh.nx - 1) / (mesh.x_max - mesh.x_min)
    step = 2 ** (mesh.levels - 1)
    return x_min, step * math.ceil((mesh.x_max - x_min) * cells / step - 1e-9) + 1


def film_mesh_error(problem, spacing: float) -> float:
    """Estimated relative discretisation error of the central film on a mesh of ``spacing``
    (in a): ``FILM_ERROR dX^2 / H_c`` with ``H_c`` the Moes film in Hertzian units, the rule
    of the EHL default mesh (:meth:`asperity.ehl.LineContact.cells_per_a`, measured on point
    contacts; docs/ehl-robustness.md). On gear contacts at a/32, against finer meshes
    (Richardson-extrapolated from 129/257/513 nodes, docs/gears.md): 49 % where the central
    film was 53 % low (M = 161) and the minimum film 50 % below Dowson-Higginson; 19 % where
    it was about 18 % low (the crowned FZG example near B, an elliptical contact); 16.5 %
    where it was 10 % low (a slow steel/bronze pair at B); 12.7 % where it was about 8 % low
    (the FZG pitch, M = 45). It errs high at moderate loads, not at high ones."""
    return FILM_ERROR * spacing**2 / (problem.film_estimate() / problem.film_scale)


@dataclass(frozen=True)
class Thermal:
    """Thermal properties (k W/(m K), rho kg/m^3, c J/(kg K)) of both bodies, the bulk
    temperature (deg C) and the shape of the frictional heat source."""

    conductivity: tuple = (45.0, 45.0)
    density: tuple = (7850.0, 7850.0)
    specific_heat: tuple = (460.0, 460.0)
    bulk_temperature: float = 90.0
    profile: str = "semi-elliptic"

    def coefficients(self) -> tuple[float, float]:
        """Thermal contact coefficients B = sqrt(k rho c) of both bodies."""
        return tuple(thermal_contact_coefficient(k, r, c) for k, r, c in
                     zip(self.conductivity, self.density, self.specific_heat, strict=True))


@dataclass(frozen=True)
class GearPathResult:
    """Everything along the path (arrays over the positions), SI; temperatures in deg C / K.

    ``kin`` holds radii and speeds; ``share`` the load sharing factor X; ``load`` w' (N/m)
    or the point load (N); ``hertz_a``, ``hertz_b`` (NaN for a line), ``hertz_pressure``;
    ``central_film``, ``minimum_film`` from the solver and ``formula_*`` from the film
    formulas; ``specific_film`` lambda; ``ehl_friction``, ``asperity_share``, ``friction``;
    ``flash_temperature`` (K) and ``contact_temperature`` (deg C); ``converged`` and
    ``sweeps`` per solve (a solve whose minimum film is not positive counts as not converged),
    ``nodes`` the node count along x of each solve (0 where unloaded; :func:`position_mesh`),
    ``mesh_error`` the estimated relative error of its central film on that mesh
    (:func:`film_mesh_error`; 0 where unloaded).
    ``two_pair_side`` (where asked for) is the path result on the two-pair side of each
    load-sharing jump at B and D (:func:`~asperity.gears.loading.load_jumps`, in their
    order): the same radii and speeds, the two-pair load; None where not solved.
    With a Newtonian lubricant (no Eyring stress) ``ehl_friction`` is NaN, and so are
    ``friction`` and the temperatures wherever the film carries part of the load: a
    ``lubricant.tau0`` line among ``warnings``, or among ``notes`` where no loaded point's
    friction uses the EHL traction.
    """

    pair: GearPair
    kin: Kinematics
    share: np.ndarray
    load: np.ndarray
    hertz_a: np.ndarray
    hertz_b: np.ndarray
    hertz_pressure: np.ndarray
    max_pressure: np.ndarray
    central_film: np.ndarray
    minimum_film: np.ndarray
    formula_central: np.ndarray
    formula_minimum: np.ndarray
    formula_names: tuple
    composite_roughness: float
    specific_film: np.ndarray
    ehl_friction: np.ndarray
    asperity_share: np.ndarray
    friction: np.ndarray
    flash_temperature: np.ndarray
    contact_temperature: np.ndarray
    peclet: np.ndarray
    converged: np.ndarray
    sweeps: np.ndarray
    nodes: np.ndarray
    mesh_error: np.ndarray
    line: bool
    warnings: list = field(default_factory=list)
    notes: list = field(default_factory=list)
    two_pair_side: GearPathResult | None = None

    def critical(self) -> dict:
        """Index of the minimum lambda, maximum flash temperature and maximum Hertz pressure
        (ignoring unloaded positions); the flash temperature's is None when it is NaN at a
        loaded position (a Newtonian lubricant's traction left out)."""
        loaded = self.load > 0
        lam = np.where(loaded, self.specific_film, np.inf)
        flash = np.where(loaded, self.flash_temperature, -np.inf)
        # a loaded point without a flash temperature (a Newtonian film's traction left out)
        # leaves the maximum unknown: None rather than the largest of the others
        hottest = None if np.isnan(flash).any() else int(np.argmax(flash))
        return {"minimum_lambda": int(np.nanargmin(lam)),
                "maximum_flash_temperature": hottest,
                "maximum_hertz_pressure": int(np.argmax(self.hertz_pressure))}


def contact_problem(pair: GearPair, kin: Kinematics, index: int, load: float, body1: Material,
                    body2: Material, lubricant: Lubricant):
    """The smooth EHL contact at path position ``index``: a line contact of the reduced radius
    and load per length, or (crowned flanks) an elliptical one with ``ry`` from the crowning."""
    u1, u2 = float(kin.u1[index]), float(kin.u2[index])
    radius = float(kin.reduced_radius[index])
    if pair.crowned:
        return PointContact(radius, pair.crowning_radius, load, u1, u2, body1, body2, lubricant)
    return LineContact(radius, load, u1, u2, body1, body2, lubricant)


def _formulas(problem, lubricant):
    """(central, minimum, names) of the Newtonian film formulas of the contact."""
    args = (problem.mean_speed, lubricant.viscosity, lubricant.pressure_viscosity,
            problem.reduced_modulus)
    if isinstance(problem, LineContact):
        central = formulas.moes_line(problem.load_per_length, problem.radius, *args).central
        minimum = formulas.dowson_higginson_line(problem.load_per_length, problem.radius,
                                                 *args).minimum
        return central, minimum, ("Moes", "Dowson-Higginson")
    hd = formulas.hamrock_dowson_point(problem.load, problem.rx, problem.ry, *args)
    return hd.central, hd.minimum, ("Hamrock-Dowson", "Hamrock-Dowson")


def _solve(problem, mesh: EHLMesh):
    """One steady solve on the position's mesh (:func:`position_mesh`); a run that fails to
    converge is repeated with other oscillation damping: half the factor on a domain whose
    inlet lies one Hertz semi-width further upstream (same node count, so a slightly coarser
    spacing), then twice the factor, then none. The point relaxation of a line contact is
    fragile: on the FZG example (fixed 129 nodes) 3 of 25 positions needed the second try
    (their films are then 2-3 % off those of the original spacing), on the helical example
    the pure-rolling pitch point the third. Returns the solution and its node count."""
    line = isinstance(problem, LineContact)
    a = problem.a
    x_min, nx = position_mesh(problem, mesh)
    y_range = (0.0, 0.0) if line else (mesh.y_min * problem.b, mesh.y_max * problem.b)
    tries = dict.fromkeys(((mesh.damping, x_min), (0.5 * mesh.damping, x_min - 1.0),
                           (min(1.0, 2.0 * mesh.damping), x_min), (1.0, x_min)))
    res = None
    for damping, start in tries:
        res = solve_steady(problem, nx=nx, ny=1 if line else mesh.ny,
                           domain=((start * a, mesh.x_max * a), y_range), levels=mesh.levels,
                           tol=mesh.tol, max_iter=mesh.max_sweeps, damping=damping)
        if res.converged:
            break
    return res, nx


def _angles(kin: Kinematics, indices) -> str:
    """Pinion roll angles (deg) of path positions, listed."""
    return ", ".join(f"{math.degrees(kin.roll_angle[i]):.2f}" for i in indices)


def _mesh_notes(kin: Kinematics, error, film_units, mesh: EHLMesh) -> list[str]:
    """The ``ehl.nx`` line where the estimated central-film error of a position's mesh
    exceeds :data:`GEAR_FILM_MESH_ERROR`, with the nodes for :data:`GEAR_FILM_MESH_TARGET`."""
    coarse = np.flatnonzero(error > GEAR_FILM_MESH_ERROR)
    if not coarse.size:
        return []
    cells = math.sqrt(FILM_ERROR / (GEAR_FILM_MESH_TARGET * float(np.min(film_units))))
    step = 2 ** (mesh.levels - 1)
    need = step * math.ceil((mesh.x_max - mesh.x_min) * cells / step) + 1
    spacing = (mesh.x_max - mesh.x_min) / (mesh.nx - 1)
    return [f"ehl.nx: at {coarse.size} of {kin.rho1.size} path points (roll angles "
            f"{_angles(kin, coarse)} deg) the mesh dx = a/{1.0 / spacing:.3g} is too coarse "
            f"for the film (H_c = h_c R/a^2 down to {np.min(film_units):.3g}): the central "
            f"film's discretisation error is estimated at up to {np.max(error):.0%} "
            f"({FILM_ERROR:g} dx^2/H_c; a slow pair at M = 161 had half "
            "the central film on 129 nodes of that on 513), so films and lambda come out too low "
            f"there; raise [ehl] nx to {need} or more for about "
            f"{GEAR_FILM_MESH_TARGET:.0%}"]


def _boundary_notes(kin: Kinematics, lam, loaded, minimum_film,
                    boundary_friction: float) -> list[str]:
    """The ``lambda`` line where a loaded position's lambda lies below
    :data:`BOUNDARY_LUBRICATION_LAMBDA`: which numbers of the path then hold and which not."""
    low = np.flatnonzero(loaded & (lam < BOUNDARY_LUBRICATION_LAMBDA))
    if not low.size:
        return []
    return [f"lambda: down to {np.min(lam[low]):.3g} at {low.size} of {int(loaded.sum())} "
            f"loaded path points (roll angles {_angles(kin, low)} deg), below "
            f"{BOUNDARY_LUBRICATION_LAMBDA:g}, the limit of boundary lubrication taken here: "
            f"the smooth film (h_min down to {np.min(minimum_film[low]) * 1e9:.3g} nm) is a "
            "tenth of the composite roughness or less, so the asperities carry the load and "
            "that film, lambda and the EHL traction describe no real gap; the friction there is "
            f"the assumed [friction] boundary = {boundary_friction:g}, and the flash "
            "temperature follows from it (a nominal value; the asperity contacts run hotter). "
            "Geometry, load, Hertz pressure and sigma_H0 stand. Wear and scuffing are then set "
            "by the boundary films of the oil's additives, which asperity does not model; a "
            "larger lambda needs a more viscous oil or more speed (h ~ (eta0 u)^0.7) or "
            "smoother flanks"]


def _pressure_notes(p_hz, torque: float, body1: Material, body2: Material) -> list[str]:
    """The Hertz pressure against the bodies' hardness, or without one against
    :data:`PLAUSIBLE_HERTZ_PRESSURE`."""
    bodies = [("body1", body1), ("body2", body2)]
    if any(getattr(m, "hardness", None) is not None for _, m in bodies):
        return diagnostics.above_hardness(p_hz, bodies)
    p_max = float(np.max(p_hz))
    if not p_max > PLAUSIBLE_HERTZ_PRESSURE:
        return []
    return [f"operation.torque: the maximum Hertz pressure {p_max / 1e9:.3g} GPa at the "
            f"torque {torque:.6g} N m is above {PLAUSIBLE_HERTZ_PRESSURE / 1e9:g} GPa, more than "
            "case-hardened steel flanks carry (docs/gears.md); check the torque and its unit "
            "(kN m typed as N m?), or give body1/body2.hardness to judge the pressure by"]


def solve_path(pair: GearPair, rho1, *, pinion_speed: float, torque: float, body1: Material,
               body2: Material, lubricant: Lubricant, roughness: float,
               thermal: Thermal = Thermal(), mesh: EHLMesh = EHLMesh(),
               boundary_friction: float = 0.1, boundary_lambda: float = 1.0,
               full_film_lambda: float = 3.0, two_pair_sides: bool = False,
               progress=None) -> GearPathResult:
    """Solve the steady EHL contact at each position ``rho1`` and derive lambda, friction and
    flash temperature (module notes).

    Parameters
    ----------
    pair : GearPair
    rho1 : array_like
        Positions on the line of action (m from T1), e.g. ``pair.path(25)``.
    pinion_speed : float
        omega1, rad/s.
    torque : float
        Pinion torque T1, N m.
    body1, body2 : Material
        Pinion and wheel.
    lubricant : Lubricant
        With its viscosity at the bulk temperature.
    roughness : float
        Composite roughness sigma of :func:`asperity.gears.mixed.composite_roughness`, m.
    thermal : Thermal
    mesh : EHLMesh
    boundary_friction, boundary_lambda, full_film_lambda : float
        The mixed-friction rule of :mod:`asperity.gears.mixed`.
    two_pair_sides : bool
        Also solve the two-pair side of the load-sharing jumps at B and D where a position
        lies on them (:attr:`GearPathResult.two_pair_side`), so that the film, lambda,
        friction and temperature curves can step there as the load does.
    progress : callable, optional
        ``progress(done, total, description)`` after each solve.

    Returns
    -------
    GearPathResult
    """
    if not (isinstance(roughness, int | float) and math.isfinite(roughness)
            and roughness > 0):
        raise InputError("roughness", "a composite roughness > 0 in m", roughness)
    kin = kinematics(pair, rho1, pinion_speed)
    n = kin.rho1.size
    share = load_sharing(pair, kin.rho1)
    jumps = load_jumps(pair, kin.rho1) if two_pair_sides else []
    a, b, p_hz, load = hertz_along_path(pair, kin.rho1, torque, kin.reduced_radius, body1,
                                        body2)
    out = {key: np.full(n, np.nan) for key in (
        "hc", "hm", "fc", "fm", "mu", "pmax")}
    converged = np.ones(n, dtype=bool)
    sweeps = np.zeros(n, dtype=int)
    nodes = np.zeros(n, dtype=int)
    mesh_error = np.zeros(n)
    film_units = np.full(n, np.inf)
    names = ("", "")
    caught_lines = []
    for i in range(n):
        if load[i] > 0:
            problem = contact_problem(pair, kin, i, float(load[i]), body1, body2, lubricant)
            with warnings.catch_warnings(record=True) as caught:
                warnings.simplefilter("always")
                res, nodes[i] = _solve(problem, mesh)
            mesh_error[i] = film_mesh_error(problem, (res.x[1] - res.x[0]) / problem.a)
            film_units[i] = problem.film_estimate() / problem.film_scale
            caught_lines += [str(w.message) for w in caught]
            out["hc"][i], out["hm"][i] = res.central_film, res.minimum_film
            out["mu"][i], out["pmax"][i] = abs(res.friction_coefficient), res.max_pressure
            out["fc"][i], out["fm"][i], names = _formulas(problem, lubricant)
            converged[i], sweeps[i] = res.converged, res.total_sweeps
        if progress is not None:
            progress(i + 1, n + len(jumps), f"EHL at path point {i + 1} of {n}")
    loaded = load > 0
    # a film of zero or less is no solution of the smooth contact, whatever the residual says
    # (a torque typed in N m for kN m: p_H 43 GPa, h_min -1.3 nm, "converged")
    no_film = loaded & ~(np.isfinite(out["hm"]) & (out["hm"] > 0))
    solver_failed = loaded & ~converged & ~no_film
    converged &= ~no_film
    lam = out["hm"] / roughness
    f_asp = asperity_share(np.where(loaded, lam, np.inf), boundary_lambda, full_film_lambda)
    newtonian_mu = out["mu"].copy()
    if lubricant.newtonian:
        # eta du/h of a Newtonian film at the pressure-raised viscosity grows without bound
        # (1e4 .. 1e13 on gear flanks): no traction, so not reported as one (docs/gears.md)
        out["mu"][loaded] = np.nan
    # an unloaded position (the end of a relieved tip) has no friction coefficient: NaN, not
    # the 0 of its absent film; it makes no heat (flash temperature 0)
    mu = np.where(loaded, mixed_friction(np.where(loaded, out["mu"], 0.0), boundary_friction,
                                         f_asp), np.nan)
    b1, b2 = thermal.coefficients()
    heat = np.where(loaded, mu, 0.0) * 0.25 * math.pi * p_hz * np.abs(kin.sliding_speed)
    flash = flash_temperature(heat, a, kin.u1, kin.u2, b1, b2, thermal.profile)
    pe = np.minimum(*(peclet_number(u, a, k, r, c) for u, k, r, c in zip(
        (kin.u1, kin.u2), thermal.conductivity, thermal.density, thermal.specific_heat,
        strict=True)))
    notes = list(pair.design_warnings())
    notes += _pressure_notes(p_hz, torque, body1, body2)
    if caught_lines:
        notes.append(f"EHL solver ({len(caught_lines)} warning(s) along the path), first: "
                     f"{caught_lines[0]}")
    bad = np.flatnonzero(no_film)
    if bad.size:
        finite = out["hm"][bad][np.isfinite(out["hm"][bad])]
        depth = f"down to {finite.min() * 1e9:.3g} nm" if finite.size else "not finite"
        p_bad = float(np.max(p_hz[bad]))
        if p_bad > PLAUSIBLE_HERTZ_PRESSURE:
            advice = ("check operation.torque and its unit (the Hertz pressure there is up to "
                      f"{p_bad / 1e9:.3g} GPa, above {PLAUSIBLE_HERTZ_PRESSURE / 1e9:g} GPa), "
                      "then the lubricant")
        else:
            # a plausible load: the film is too thin for the mesh or the relaxation
            advice = (f"the Hertz pressure there (up to {p_bad / 1e9:.3g} GPa) is a plausible "
                      "load, so the film is thinner than the solve resolves: raise [ehl] nx "
                      "(and max_sweeps), or give [ehl] damping a smaller value")
        notes.append(f"EHL solve: the minimum film is zero or negative ({depth}) at "
                     f"{bad.size} of {n} path points "
                     f"(roll angles {_angles(kin, bad)} deg), so they are not converged "
                     f"solutions; {advice}")
    bad = np.flatnonzero(solver_failed)
    if bad.size:
        notes.append(f"EHL solve: {bad.size} of {n} path points did not converge (roll angles "
                     f"{_angles(kin, bad)} deg); refine [ehl] nx/levels or raise max_sweeps")
    notes += _mesh_notes(kin, mesh_error, film_units, mesh)
    notes += _boundary_notes(kin, lam, loaded & np.isfinite(lam), out["hm"], boundary_friction)
    left_out = loaded & (f_asp < 1.0)
    remarks = []
    if lubricant.newtonian and loaded.any() and not left_out.any():
        # the asperities carry all the load at every point: no result uses the EHL traction
        remarks.append(
            "Newtonian lubricant (no lubricant.tau0): the EHL traction is left out (NaN in "
            "result.nc), and no result here depends on it: at every loaded point lambda is "
            f"below [friction] boundary_lambda = {boundary_lambda:g}, where the asperities "
            "carry all the load and the friction is the boundary coefficient. A film that "
            "carries load needs lubricant.tau0 for its friction and temperatures.")
    elif lubricant.newtonian and left_out.any():
        raw = np.abs(newtonian_mu[loaded & np.isfinite(newtonian_mu)])
        size = f" (here a coefficient up to {raw.max():.3g})" if raw.size else ""
        notes.append(
            "lubricant.tau0: the lubricant has no Eyring stress, and a Newtonian film's shear "
            f"stress eta du/h grows without bound with the pressure-raised viscosity{size}, "
            "so it is no traction: "
            "the EHL friction is left out (NaN), and with it the friction and the flash and "
            f"contact temperatures at the {int(left_out.sum())} of {int(loaded.sum())} loaded "
            "points where the film carries load (lambda above [friction] boundary_lambda); "
            "set lubricant.tau0 (gear oils: about 5-10 MPa) for them")
    if pair.crowned and np.nanmax(b) * 2.0 > pair.face_width:
        notes.append(f"Hertz ellipse: length 2b up to {np.nanmax(b) * 2e3:.3g} mm exceeds the "
                     f"face width {pair.face_width * 1e3:.3g} mm, so the contact is cut by the "
                     "tooth ends (edge loading); increase the crowning")
    low_pe = (load > 0) & (heat > 0) & (pe < 5.0)
    if np.any(low_pe):
        over = LOW_PECLET_OVERESTIMATE[thermal.profile]
        lowest = float(pe[low_pe].min())
        worst = low_peclet_overestimate(thermal.profile, lowest)
        size = (f"more than {worst:.0%}" if lowest < min(over) else f"about {worst:.0%}")
        notes.append(f"flash temperature: Peclet number down to {lowest:.2g} < 5 at "
                     f"{int(low_pe.sum())} point(s); Blok's high-speed formula overestimates "
                     f"there, for the {thermal.profile} source by {size} at Pe = {lowest:.2g} "
                     f"({over[1.0]:.0%} at Pe = 1, {over[0.3]:.0%} at Pe = 0.3) against "
                     "Jaeger's exact moving band source, so treat those values as upper bounds")
    result = GearPathResult(
        pair=pair, kin=kin, share=share, load=load, hertz_a=a, hertz_b=b, hertz_pressure=p_hz,
        max_pressure=out["pmax"], central_film=out["hc"], minimum_film=out["hm"],
        formula_central=out["fc"], formula_minimum=out["fm"], formula_names=names,
        composite_roughness=float(roughness), specific_film=lam, ehl_friction=out["mu"],
        asperity_share=f_asp, friction=mu, flash_temperature=flash,
        contact_temperature=thermal.bulk_temperature + flash, peclet=pe, converged=converged,
        sweeps=sweeps, nodes=nodes, mesh_error=mesh_error, line=not pair.crowned, warnings=notes,
        notes=remarks,
    )
    if jumps:
        side = _two_pair_side(result, jumps, progress, pinion_speed=pinion_speed,
                              torque=torque, body1=body1, body2=body2, lubricant=lubricant,
                              roughness=roughness, thermal=thermal, mesh=mesh,
                              boundary_friction=boundary_friction,
                              boundary_lambda=boundary_lambda,
                              full_film_lambda=full_film_lambda)
        result = replace(result, two_pair_side=side)
    return result


def _two_pair_side(result: GearPathResult, jumps, progress, **inputs) -> GearPathResult:
    """The path result at the two-pair side of ``jumps`` (:func:`solve_path` with the same
    ``inputs``), a line among ``result.warnings`` for each side whose solve did not converge
    (its curves are drawn broken there)."""
    n = result.load.size
    report = None if progress is None else (
        lambda done, total, _: progress(n + done, n + total,
                                        f"EHL on the two-pair side of B/D ({done} of {total})"))
    side = solve_path(result.pair, [jump.rho for jump in jumps], progress=report, **inputs)
    for jump, converged in zip(jumps, side.converged, strict=True):
        if not converged:
            point = "B" if jump.side < 0 else "D"
            result.warnings.append(
                f"EHL solve on the two-pair side of {point} (load sharing {jump.outside:.3g}) "
                "did not converge: the film, lambda, friction and temperature curves are "
                "broken there; refine [ehl] nx/levels or raise max_sweeps")
    return side
