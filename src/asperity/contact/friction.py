"""Coulomb friction on a given pressure: the set-up shared by the tangential solvers.

The FFT solver (:mod:`asperity.contact.tangential`) and Seireg's linear programming
(:mod:`asperity.contact.tangential_lp`) solve the same problem: tractions ``q`` bounded by
Coulomb's discs ``|q_i| <= mu_i p_i`` that balance an applied tangential force and twisting
moment (equilibrium ``B q = b``, with the moment about a reference point, by default the centre
of the normal load). This module holds what both need: the validated problem
(:func:`friction_problem`), the equilibrium operator (:class:`Constraints`), the friction
capacity in gross slip (:func:`gross_slip_capacity`, :func:`friction_capacity`) and the
result (:class:`TangentialResult`, :func:`make_result`, :func:`gross_slip_result`).

The gross-slip capacity is, by convex duality, ``t = min over rigid motions y with b.y = 1 of
sum_i mu_i p_i A |W_i(y)|`` (for a pure moment the minimum over centres of rotation of
``int mu p |r - c| dA``); the load is carried by friction when ``t > 1``.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy import ndimage, optimize

from ..elastic import grid_spacing
from ..errors import InputError, check_finite
from ..solution import SolverResult, renamed_attribute, renamed_keywords

__all__ = [
    "FIXED",
    "FREE",
    "Constraints",
    "FrictionProblem",
    "RegionLoad",
    "TRANSLATION_BELOW",
    "TangentialResult",
    "contact_regions",
    "friction_capacity",
    "friction_problem",
    "gross_slip_capacity",
    "gross_slip_result",
    "load_centroid",
    "make_result",
    "rotation_centre",
]


@dataclass(frozen=True)
class RegionLoad:
    """Load carried by one connected contact patch."""

    label: int
    """Label in :attr:`TangentialResult.labels` (1, 2, ...)."""
    area: float
    """Contact area, m^2."""
    force: np.ndarray
    """Tangential force (Fx, Fy) carried, N."""
    moment: float
    """Twisting moment carried about the solve's ``centre``, N m."""
    capacity: float
    """Friction capacity int mu p dA, N."""
    stick_fraction: float
    """Share of the patch's area that sticks."""

    @property
    def full_slip(self) -> bool:
        """True when no cell of the patch sticks."""
        return self.stick_fraction == 0.0


@dataclass(frozen=True, repr=False)
class TangentialResult(SolverResult):
    """Result of :func:`solve_tangential` (SI units, arrays indexed ``[ix, iy]``).

    The result protocol of :class:`asperity.solution.SolverResult`: ``converged``,
    ``iterations``, ``residual``, ``message``, ``warnings``, ``to_dataset()``.
    """

    VARIABLES = {"traction": ("Pa", "tangential traction on body 2"),
                 "stick": ("1", "stick indicator"),
                 "slip": ("m", "slip of body 1 vs body 2"),
                 "region": ("1", "connected contact region (0 outside the contact)", ("x", "y"),
                            "labels")}

    traction: np.ndarray
    """Traction q transmitted by body 1 to body 2, shape (2, nx, ny), Pa."""
    stick: np.ndarray
    """Cells of the contact that stick (|q| < mu p), bool (nx, ny)."""
    slip: np.ndarray
    """Relative slip of body 1 against body 2 (during this load step when solved from a
    ``previous`` state), (2, nx, ny), m; in gross slip the unit
    direction of the instantaneous sliding motion (its magnitude is indeterminate)."""
    shift: np.ndarray
    """Rigid shift (2,) of body 1 relative to body 2, m (NaN in gross slip; periodic: measured
    from the mean displacement)."""
    rotation: float
    """Rigid rotation of body 1 relative to body 2 about z, rad (NaN in gross slip)."""
    centre_of_rotation: np.ndarray
    """Point (2,) where the rigid motion vanishes, m (NaN when it does not rotate)."""
    gross_slip: bool
    """True when friction cannot carry the applied load."""
    load_capacity: float
    """Factor t: t (F, M) is the gross-slip load along the applied load's direction."""
    excess: np.ndarray
    """(Fx, Fy, M) not carried, N and N m: (1 - t) times the load in gross slip, else zero."""
    force: np.ndarray
    """Tangential force (2,) carried, N."""
    moment: float
    """Twisting moment carried about ``centre``, N m."""
    centre: np.ndarray
    """Reference point (2,) of the moment, m."""
    labels: np.ndarray
    """Connected contact patches, int (nx, ny), 0 outside the contact."""
    regions: tuple
    """One :class:`RegionLoad` per patch."""
    reaction_moment: float
    """Moment supplied by the constraint that prevents rotation (``rotation="fixed"``): the
    traction's moment about ``centre`` minus the applied moment, N m; 0 when rotation is free."""
    iterations: int
    converged: bool
    residual: float
    """``fft``: relative duality gap sum g|s| - q.s over sum g|W| (zero iff Coulomb's law
    holds); ``lp``: the largest unbalanced load component over the applied."""
    convolutions: int
    """Number of block convolutions used."""
    method: str
    x: np.ndarray | None = None
    """Cell-centre coordinates along x, m."""
    y: np.ndarray | None = None
    """Cell-centre coordinates along y, m."""
    reason: str = ""
    """Why the solve did not converge, in words, when the method can tell (``"lp"``: no trial
    motion balances the load with predetermined directions); empty otherwise."""

    center = renamed_attribute("center", "centre")
    center_of_rotation = renamed_attribute("center_of_rotation", "centre_of_rotation")

    @property
    def warnings(self) -> tuple[str, ...]:
        """The solver's own reason for not converging when it gives one, else the generic line."""
        if self.reason and not self.converged:
            return (self.reason,)
        return SolverResult.warnings.fget(self)


# --- equilibrium constraints --------------------------------------------------------------


@dataclass(frozen=True)
class Constraints:
    """B q = (sum qx, sum qy, sum (X qy - Y qx)/L) and B^T y = (y0 - y2 Y/L, y1 + y2 X/L)."""

    X: np.ndarray
    Y: np.ndarray
    L: float

    def apply(self, q):
        return np.array([q[0].sum(), q[1].sum(), (self.X * q[1] - self.Y * q[0]).sum() / self.L])

    def adjoint(self, yv):
        return np.stack([yv[0] - yv[2] * self.Y / self.L, yv[1] + yv[2] * self.X / self.L])

    def basis(self):
        """The three fields B^T e_k."""
        one, zero = np.ones_like(self.X), np.zeros_like(self.X)
        return [np.stack([one, zero]), np.stack([zero, one]),
                np.stack([-self.Y / self.L, self.X / self.L])]


#: Equilibrium rows imposed: force and moment (rotation free) or the force only (fixed).
FREE, FIXED = (0, 1, 2), (0, 1)


# --- friction capacity (gross slip) ---------------------------------------------------------


def gross_slip_capacity(g, cons: Constraints, target, rows=FREE):
    """t = min over y with target.y = 1 of sum g |B^T y|, and the minimising y (convex).

    Rotation fixed (y2 = 0): a uniform shift along the force, t = sum g / |target[:2]|.
    """
    if rows == FIXED:
        f = np.hypot(target[0], target[1])
        return float(g.sum() / f), np.array([target[0] / f**2, target[1] / f**2, 0.0])
    tn = target / (target @ target)
    # orthonormal basis of the plane target.y = 0
    _, _, vt = np.linalg.svd(target[None, :])
    N = vt[1:].T

    def fun(zz):
        yv = tn + N @ zz
        W = cons.adjoint(yv)
        n = np.hypot(W[0], W[1])
        nn = np.where(n > 0, n, 1.0)
        grad_field = g * W / nn
        return float(np.sum(g * n)), N.T @ cons.apply(grad_field)

    best = optimize.minimize(fun, np.zeros(2), jac=True, method="BFGS",
                             options={"gtol": 1e-12 * fun(np.zeros(2))[0]})
    polish = optimize.minimize(lambda zz: fun(zz)[0], best.x, method="Nelder-Mead",
                               options={"xatol": 1e-10, "fatol": 1e-14 * best.fun})
    zz = polish.x if polish.fun < best.fun else best.x
    yv = tn + N @ zz
    return fun(zz)[0], yv


@renamed_keywords(center="centre")
def friction_capacity(pressure, x, y, mu, *, force=(0.0, 0.0), moment=0.0, centre=None,
                      rotation="free"):
    """Gross-slip limit along the direction of an applied load.

    With ``rotation="fixed"`` (twist prevented) only the force counts: ``mu P / |F|``. The
    moment is about ``centre``, by default the centre of the normal load (as in
    :func:`asperity.contact.solve_tangential`; ``center`` is accepted with a
    DeprecationWarning).

    Returns
    -------
    load_factor : float
        t such that t (Fx, Fy, M) is the largest load of that direction that friction carries.
    centre_of_rotation : ndarray
        Instantaneous centre (2,) of the full-slip motion (NaN for pure translation), m.
    """
    prob = friction_problem(pressure, x, y, mu, force, moment, centre, rotation)
    if not np.any(prob.target[list(prob.rows)]):
        return float("inf"), np.full(2, np.nan)
    t, yv = gross_slip_capacity(prob.g, prob.cons, prob.target, prob.rows)
    return t, rotation_centre(yv, prob)


# --- problem set-up --------------------------------------------------------------------------


@dataclass(frozen=True)
class FrictionProblem:
    """A validated frictional-contact problem on the grid (see :func:`friction_problem`)."""

    g: np.ndarray
    """Friction bound mu p per cell, Pa (zero outside the contact)."""
    cons: Constraints
    """Equilibrium operator, coordinates relative to ``centre``."""
    target: np.ndarray
    """Equilibrium right-hand side (Fx, Fy, M / L) / A, Pa."""
    area: float
    """Cell area A, m^2."""
    centre: np.ndarray
    """Reference point (2,) of the moment, m."""
    load: np.ndarray
    """Applied (Fx, Fy, M), N and N m."""
    rows: tuple = FREE
    """Equilibrium rows imposed (:data:`FREE` or :data:`FIXED`)."""


def friction_problem(pressure, x, y, mu, force, moment, centre,
                     rotation="free") -> FrictionProblem:
    """Validate the inputs of a frictional-contact solve and set up its equilibrium.

    Parameters
    ----------
    pressure : ndarray (nx, ny)
        Normal pressure, Pa (>= 0).
    x, y : ndarray
        Uniformly spaced cell-centre coordinates, m.
    mu : float or ndarray (nx, ny)
        Coefficient(s) of friction, > 0.
    force : (float, float)
        Applied tangential force, N.
    moment : float
        Applied twisting moment about ``centre``, N m.
    centre : (float, float) or None
        Reference point of the moment, m; None: the centre of the normal load
        (:func:`load_centroid`).
    rotation : {"free", "fixed"}
        Whether the moment equation is imposed (free) or dropped (fixed).

    Returns
    -------
    FrictionProblem

    Raises
    ------
    InputError
        Naming the offending argument.
    """
    dx, dy = grid_spacing(x, "x"), grid_spacing(y, "y")
    x, y = np.asarray(x, float), np.asarray(y, float)
    p = np.asarray(pressure, dtype=float)
    if p.shape != (x.size, y.size):
        raise InputError("pressure", f"an array of shape (len(x), len(y)) = {(x.size, y.size)}",
                         p.shape)
    check_finite("pressure", p)
    if np.any(p < 0):
        raise InputError("pressure", "non-negative values (Pa)")
    mu_arr = np.asarray(mu, dtype=float)
    if mu_arr.ndim not in (0, 2) or (mu_arr.ndim == 2 and mu_arr.shape != p.shape):
        raise InputError("mu", "a number or an array of the pressure's shape", mu_arr.shape)
    if not np.all(np.isfinite(mu_arr)) or np.any(mu_arr <= 0):
        raise InputError("mu", "a coefficient of friction > 0", mu)
    f = np.asarray(force, dtype=float)
    if f.shape != (2,) or not np.all(np.isfinite(f)):
        raise InputError("force", "two finite numbers (Fx, Fy) in N", force)
    if not np.isfinite(float(moment)):
        raise InputError("moment", "a finite number in N m", moment)
    if rotation not in ("free", "fixed"):
        raise InputError("rotation", "'free' or 'fixed'", rotation)
    c = load_centroid(p, x, y) if centre is None else np.asarray(centre, dtype=float)
    if c.shape != (2,) or not np.all(np.isfinite(c)):
        raise InputError("centre", "two finite coordinates (m)", centre)
    X, Y = np.meshgrid(x - c[0], y - c[1], indexing="ij")
    g = mu_arr * p
    contact = g > 0
    L = float(np.sqrt(np.max(np.where(contact, X * X + Y * Y, 0.0)))) if contact.any() else 1.0
    L = L if L > 0 else max(dx, dy)
    area = dx * dy
    load = np.array([f[0], f[1], float(moment)])
    target = np.array([f[0], f[1], float(moment) / L]) / area
    return FrictionProblem(g, Constraints(X, Y, L), target, area, c, load,
                           FREE if rotation == "free" else FIXED)


def load_centroid(pressure, x, y) -> np.ndarray:
    """Centre of the normal load, sum p r / sum p over the cells (m); the origin without load.

    The default reference point of the twisting moment: about it a tangential force through
    the centre of the normal load carries no moment, wherever the grid lies.
    """
    p = np.asarray(pressure, dtype=float)
    total = p.sum()
    if not total > 0:
        return np.zeros(2)
    return np.array([np.dot(p.sum(axis=1), x), np.dot(p.sum(axis=0), y)]) / total


#: Rotation, as the displacement ``|w| L`` it gives over the contact size, relative to the
#: shift, below which a motion is a translation: its centre of rotation would lie more than a
#: million contact sizes away, where the round-off rotation of a solve without a moment puts
#: it (7e-14 rad against a 14 nm shift put it 2e5 m away and hid the shift in the summary).
TRANSLATION_BELOW = 1e-6


def rotation_centre(yv, prob: FrictionProblem):
    """Zero of W = (y0 - w Y, y1 + w X), w = y2 / L, in absolute coordinates; NaN for a
    translation (``|w| L <= TRANSLATION_BELOW |(y0, y1)|``)."""
    w = yv[2] / prob.cons.L
    if abs(w) * prob.cons.L <= TRANSLATION_BELOW * np.hypot(yv[0], yv[1]) or w == 0.0:
        return np.full(2, np.nan)
    return prob.centre + np.array([-yv[1] / w, yv[0] / w])


def contact_regions(q, stick, prob: FrictionProblem):
    """Connected contact patches (labels) and the load each carries (:class:`RegionLoad`)."""
    labels, n = ndimage.label(prob.g > 0)
    X, Y = prob.cons.X, prob.cons.Y

    def per_patch(field):  # sums over each patch in one pass (a rough contact has thousands)
        return np.bincount(labels.ravel(), weights=np.ravel(field), minlength=n + 1)[1:]

    cells = np.bincount(labels.ravel(), minlength=n + 1)[1:]
    fx, fy = per_patch(q[0]), per_patch(q[1])
    moment, capacity = per_patch(X * q[1] - Y * q[0]), per_patch(prob.g)
    stuck = per_patch(stick)
    out = tuple(RegionLoad(
        label=k + 1,
        area=float(cells[k] * prob.area),
        force=np.array([fx[k], fy[k]]) * prob.area,
        moment=float(moment[k] * prob.area),
        capacity=float(capacity[k] * prob.area),
        stick_fraction=float(stuck[k] / cells[k]),
    ) for k in range(n))
    return labels, out


def make_result(q, stick, slip, yv, prob, *, gross, t, iterations, converged, residual, conv,
                method) -> TangentialResult:
    """Assemble the :class:`TangentialResult` of a solve.

    ``q``, ``stick``, ``slip`` are the fields on the grid, ``yv`` the rigid motion in the
    scaled form of :class:`Constraints` (shift, rotation times L), ``t`` the capacity factor;
    carried loads, patches and the fixture's reaction moment are computed here.
    """
    labels, regions = contact_regions(q, stick, prob)
    carried = prob.cons.apply(q) * prob.area
    if gross:
        shift, rot = np.full(2, np.nan), float("nan")
    else:
        shift, rot = np.array(yv[:2], dtype=float), float(yv[2] / prob.cons.L)
    moment = float(carried[2] * prob.cons.L)
    fixed = prob.rows == FIXED
    reaction = moment - prob.load[2] if fixed else 0.0
    excess = (1.0 - t) * prob.load * ([1.0, 1.0, 0.0] if fixed else 1.0) if gross else \
        np.zeros(3)
    return TangentialResult(
        traction=q, stick=stick, slip=slip, shift=shift, rotation=rot,
        centre_of_rotation=rotation_centre(yv, prob), gross_slip=bool(gross),
        load_capacity=float(t), excess=excess,
        force=carried[:2], moment=moment, centre=prob.centre, reaction_moment=float(reaction),
        labels=labels, regions=regions, iterations=int(iterations), converged=bool(converged),
        residual=float(residual), convolutions=int(conv), method=method,
        x=prob.cons.X[:, 0] + prob.centre[0], y=prob.cons.Y[0, :] + prob.centre[1])


def gross_slip_result(prob: FrictionProblem, t, yv, method) -> TangentialResult:
    """Full-slip traction mu p along the sliding motion ``yv`` of the capacity problem."""
    W = prob.cons.adjoint(yv)
    n = np.hypot(W[0], W[1])
    direction = np.where(prob.g > 0, W / np.where(n > 0, n, 1.0), 0.0)
    q = prob.g * direction
    stick = np.zeros(prob.g.shape, dtype=bool)
    return make_result(q, stick, direction, yv, prob, gross=True, t=t, iterations=0,
                       converged=True, residual=0.0, conv=0, method=method)
