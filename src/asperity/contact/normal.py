"""Frictionless (dry) normal contact of two elastic half-spaces with an arbitrary gap.

The pressure ``p >= 0`` and the deformed gap ``g = gap0 + u(p) - approach >= 0`` satisfy
``p g = 0`` everywhere, with ``u = K p`` the combined normal displacement
(:func:`asperity.elastic.normal_operator`). The discrete problem is solved by the constrained
conjugate-gradient method (CCG) of Polonsky & Keer (1999): conjugate directions restricted to
the current contact set, projection onto ``p >= 0``, and re-admission of overlapping points.

- Load control: the mean gap on the contact set is removed at every iteration (its value is the
  rigid approach, the Lagrange multiplier of the load), search directions have zero sum on the
  contact set, and the pressure is rescaled to the load after each step (PK steps 2-10).
- Approach control: the same iteration on the bound-constrained quadratic
  ``1/2 p.K p + p.(gap0 - approach)`` with no load constraint (no mean removal, no rescaling).

Two departures from the paper, both measured on the benchmarks (``benchmarks/``):

- PK restart the conjugacy (steepest descent) whenever points re-enter the contact. Here the
  conjugacy is kept and reset only when the direction is not a descent direction; on rough
  surfaces this needs 2-3 times fewer iterations for the same residual.
- The step length uses ``t.K t`` by Parseval's theorem on the spectrum of ``t``, and the spectrum
  of the new pressure follows by linearity, ``P' = s (P - tau T)``; it is transformed afresh only
  when the projection or the overlap rule moved ``p`` off that line. An iteration therefore
  costs two real FFTs (forward ``t``, inverse ``K P``), three when the contact set changed,
  against four for two convolutions. Non-periodic transforms skip the zero rows of the padding.

References
----------
I. A. Polonsky, L. M. Keer, A numerical method for solving rough contact problems based on the
multi-level multi-summation and conjugate gradient techniques, Wear 231 (1999) 206-219.
"""

from __future__ import annotations

from dataclasses import dataclass

import numba
import numpy as np

from ..elastic import grid_spacing, normal_influence, normal_operator
from ..errors import InputError, check_positive
from ..materials import Material, contact_modulus
from ..solution import SolverResult, renamed_keywords
from ..surfaces import Topography
from .gap import surface_gap

__all__ = ["NormalContactResult", "solve_normal"]


@dataclass(frozen=True, repr=False)
class NormalContactResult(SolverResult):
    """Result of :func:`solve_normal` (SI units, arrays indexed ``[ix, iy]``).

    The result protocol of :class:`asperity.solution.SolverResult`: ``converged``,
    ``iterations``, ``residual``, ``message``, ``warnings``, ``to_dataset()``.
    """

    VARIABLES = {"pressure": ("Pa", "contact pressure"), "gap": ("m", "deformed gap"),
                 "displacement": ("m", "combined normal displacement"),
                 "contact": ("1", "contact indicator")}

    pressure: np.ndarray
    """Contact pressure, Pa."""
    gap: np.ndarray
    """Deformed gap ``gap0 + displacement - approach``, m (zero in contact, to ``tol``)."""
    displacement: np.ndarray
    """Combined normal displacement of the two surfaces, m (zero-mean when periodic)."""
    contact: np.ndarray
    """Boolean contact mask (``pressure > 0``)."""
    contact_area: float
    """Real contact area, m^2."""
    approach: float
    """Rigid approach of the bodies, m: the shift of the undeformed gap (periodic: the shift of
    the mean gap, ``mean(gap0) - mean(gap)``)."""
    load: float
    """Normal load, N."""
    iterations: int
    converged: bool
    residual: float
    """Final convergence measure (see :func:`solve_normal`)."""
    ffts: int
    """Number of 2-D real FFTs used (forward or inverse; a convolution costs two)."""
    x: np.ndarray
    y: np.ndarray
    periodic: bool

    @property
    def contact_fraction(self) -> float:
        """Contact area over the area of the grid."""
        return float(np.count_nonzero(self.contact)) / self.contact.size

    @property
    def max_pressure(self) -> float:
        """Largest pressure, Pa."""
        return float(self.pressure.max())


# The kernels below work on flattened (1-D) views of the [ix, iy] arrays; a point is in the
# contact set when its pressure is > 0.


@numba.njit(cache=True)
def _gap_sums(u, h, p, shift):
    """Contact count, sum of g = u + h - shift on the contact set, min of g off it, range of u."""
    n = 0
    total = 0.0
    lowest = np.inf
    umin = np.inf
    umax = -np.inf
    for i in range(u.size):
        g = u[i] + h[i] - shift
        umin = min(umin, u[i])
        umax = max(umax, u[i])
        if p[i] > 0.0:
            n += 1
            total += g
        else:
            lowest = min(lowest, g)
    return n, total, lowest, umax - umin


@numba.njit(cache=True)
def _gap_on_contact(u, h, p, shift, g):
    """Write g = u + h - shift; return the sum of g^2 over the contact set."""
    total = 0.0
    for i in range(u.size):
        gi = u[i] + h[i] - shift
        g[i] = gi
        if p[i] > 0.0:
            total += gi * gi
    return total


@numba.njit(cache=True)
def _direction(g, p, t, beta):
    """Conjugate direction t = g + beta t on the contact set, zero off it (PK step 4).

    Returns the sums over the contact set of t, g t and g.
    """
    t_sum = 0.0
    gt_sum = 0.0
    g_sum = 0.0
    for i in range(g.size):
        if p[i] > 0.0:
            ti = g[i] + beta * t[i]
            t[i] = ti
            t_sum += ti
            gt_sum += g[i] * ti
            g_sum += g[i]
        else:
            t[i] = 0.0
    return t_sum, gt_sum, g_sum


def _direction_with_load(g, p, t, beta, n, load_control):
    """Set the direction t (zero sum on the contact set under load control); return g.t."""
    t_sum, g_dot_t, g_sum = _direction(g, p, t, beta)
    if load_control:  # keep the load: shift t to zero sum on the n contact points
        _shift_on_contact(t, p, -t_sum / n)
        g_dot_t -= g_sum * t_sum / n
    return g_dot_t


@numba.njit(cache=True)
def _shift_on_contact(t, p, c):
    """t += c on the contact set."""
    for i in range(t.size):
        if p[i] > 0.0:
            t[i] += c


@numba.njit(cache=True)
def _energy(spectrum, weight):
    """sum weight |spectrum|^2: the quadratic form t.K t by Parseval's theorem."""
    total = 0.0
    for i in range(spectrum.shape[0]):
        for j in range(spectrum.shape[1]):
            z = spectrum[i, j]
            total += weight[i, j] * (z.real * z.real + z.imag * z.imag)
    return total


@numba.njit(cache=True)
def _spectral_step(load_spectrum, direction_spectrum, tau, factor):
    """P <- factor (P - tau T) in place: the transform of the updated pressure by linearity."""
    for i in range(load_spectrum.shape[0]):
        for j in range(load_spectrum.shape[1]):
            load_spectrum[i, j] = factor * (load_spectrum[i, j] - tau * direction_spectrum[i, j])


@numba.njit(cache=True)
def _update(p, g, t, tau):
    """Polonsky-Keer steps 7-9: p <- max(p - tau t, 0); overlaps (p == 0, g < 0) get -tau g.

    Returns (sum of p, number of points moved off the line p - tau t).
    """
    total = 0.0
    corrected = 0
    for i in range(p.size):
        pi = p[i] - tau * t[i]
        if pi <= 0.0:
            if pi < 0.0:
                corrected += 1
            pi = 0.0
            if g[i] < 0.0:
                pi = -tau * g[i]
                corrected += 1
        p[i] = pi
        total += pi
    return total, corrected


class _Transforms:
    """The operator's transforms (:meth:`Convolution.spectrum_of`, :meth:`Convolution.inverse`,
    pruned for the zero-padded case) with the kernel's real spectrum, the energy weights of
    Parseval's sum and a kept buffer for the kernel product."""

    def __init__(self, op):
        self.op = op
        self.kernel = op.even_spectrum  # Love's coefficients are even in x and y
        if self.kernel is None:
            raise ValueError("the normal contact solver needs an even kernel (a real spectrum)")
        fx, fy = op.fft_shape
        # Parseval in rfft layout: columns 1 .. (fy - 1) // 2 stand for two conjugate columns
        weight = np.full(fy // 2 + 1, 2.0)
        weight[0] = 1.0
        if fy % 2 == 0:
            weight[-1] = 1.0
        self.energy_weight = self.kernel * (weight / (fx * fy))[None, :]
        self._product = np.empty(self.kernel.shape, dtype=complex)

    def forward(self, a):
        return self.op.spectrum_of(a)

    def displacement(self, load_spectrum):
        """K p on the grid (C-contiguous) from the spectrum of p."""
        product = np.multiply(load_spectrum, self.kernel, out=self._product)
        return np.ascontiguousarray(self.op.inverse(product))


def _validate(gap0, x, y, load, approach):
    x = np.asarray(x, dtype=float)
    y = np.asarray(y, dtype=float)
    dx, dy = grid_spacing(x, "x"), grid_spacing(y, "y")
    h = np.asarray(gap0, dtype=float)
    if h.shape != (x.size, y.size):
        raise InputError("gap0", f"an array of shape (len(x), len(y)) = {(x.size, y.size)}",
                         h.shape)
    if not np.all(np.isfinite(h)):
        raise InputError("gap0", "finite gap heights (no NaN or infinity)")
    if (load is None) == (approach is None):
        raise InputError("load, approach", "exactly one of load (N) or approach (m)")
    if load is not None:
        load = check_positive("load", load)
    else:
        approach = float(approach)
        if not np.isfinite(approach):
            raise InputError("approach", "a finite number in m", approach)
    return np.ascontiguousarray(h), x, y, dx, dy, load, approach


@renamed_keywords(max_iterations="max_iter")
def solve_normal(
    gap0,
    x=None,
    y=None,
    body1: Material | None = None,
    body2: Material | None = None,
    *,
    load=None,
    approach=None,
    periodic: bool | None = None,
    tol: float = 1e-8,
    max_iter: int = 2000,
    callback=None,
) -> NormalContactResult:
    """Frictionless normal contact by constrained conjugate gradients (Polonsky & Keer 1999).

    Parameters
    ----------
    gap0 : array_like, shape (len(x), len(y)), or Topography
        Undeformed gap between the surfaces, m, indexed ``[ix, iy]``
        (:func:`asperity.contact.ellipsoid_gap` builds one for an ellipsoid with roughness). A
        :class:`~asperity.surfaces.Topography` is a rough surface on a rigid flat: its gap is
        ``max(z) - z`` on its own grid (:func:`asperity.contact.surface_gap`); call
        ``solve_normal(topography, body1, body2, load=...)``.
    x, y : array_like
        Uniformly spaced cell-centre coordinates, m (not with a Topography).
    body1, body2 : Material
        The two elastic bodies (only E* enters).
    load : float, optional
        Normal load, N (load control).
    approach : float, optional
        Rigid approach, m (approach control): the undeformed gap is lowered by ``approach``.
        Exactly one of ``load`` and ``approach`` must be given. When periodic, the displacement
        has zero mean and the approach must be below ``mean(gap0)`` (the mean gap stays
        positive; full contact is reached only under load control).
    periodic : bool, optional
        Periodic contact (a representative patch of a rough interface, continuum kernel
        2/(E*|q|)) or an isolated contact on half-spaces (Love's cell coefficients, DC-FFT).
        Default: the Topography's periodicity, else False.
    tol : float
        Tolerance on :attr:`NormalContactResult.residual`.
    max_iter : int
        Iteration limit; the result says ``converged=False`` when it is reached (the old
        spelling ``max_iterations`` is accepted with a DeprecationWarning).
    callback : callable, optional
        ``callback(iteration, residual)``, called once per iteration.

    Returns
    -------
    NormalContactResult

    Notes
    -----
    The residual is the largest of (i) the rms gap on the contact set, (ii) the largest
    penetration off the contact set, both divided by the larger of the range of the
    displacement and the displacement of a cell's centre under the mean contact pressure on
    that cell (Love's coefficient, about ``1.12 mean(p) dx / E*`` on square cells; it keeps the
    measure finite when the displacement is flat, as in the full contact of a flat gap, and
    bounds the pressure error by about ``tol mean(p)`` there), and (iii) the relative load
    error (load control; the pressure is rescaled to the load at every step,
    Polonsky & Keer step 10). Pressure is zero off the contact set by construction, so (i) and
    (ii) measure the complementarity ``p >= 0, g >= 0, p g = 0``.
    """
    if isinstance(gap0, Topography):
        if isinstance(x, Material):  # solve_normal(topography, body1, body2, ...)
            x, y, body1, body2 = None, None, x, y
        if x is not None or y is not None:
            raise InputError("x, y", "no coordinates with a Topography (it has its own)")
        x, y = gap0.x, gap0.y
        periodic = gap0.periodic if periodic is None else periodic
        gap0 = surface_gap(gap0)
    if x is None or y is None or body1 is None or body2 is None:
        raise InputError("gap0, x, y, body1, body2", "a gap with its coordinates x, y (or a "
                                                     "Topography) and the two bodies")
    periodic = bool(periodic)
    h, x, y, dx, dy, load, approach = _validate(gap0, x, y, load, approach)
    max_iter = int(max_iter)
    if max_iter < 1:
        raise InputError("max_iter", "an integer >= 1", max_iter)
    tol = check_positive("tol", tol)
    cell = dx * dy
    op = normal_operator(x, y, body1, body2, periodic)
    cell_compliance = float(normal_influence(0.0, 0.0, dx, dy, body1, body2))
    load_control = load is not None

    shape = h.shape
    h = h.ravel()
    if load_control:
        p = np.full(h.size, load / (cell * h.size))
        shift = 0.0
    else:
        if periodic and approach >= h.mean():
            raise InputError(
                "approach", f"less than the mean undeformed gap {h.mean():.6g} m for a "
                "periodic contact (full contact needs load control)", approach)
        # initial guess: the overlap times the stiffness of one cell, ~ E* / cell size
        stiffness = contact_modulus(body1, body2) / np.sqrt(cell)
        p = np.clip(approach - h, 0.0, None) * stiffness
        shift = approach

    fft = _Transforms(op)

    def transform(field):
        return fft.forward(field.reshape(shape))

    h_range = float(h.max() - h.min())
    g = np.empty_like(h)
    t = np.zeros_like(h)
    spectrum = transform(p)
    u = fft.displacement(spectrum).ravel()
    ffts = 2
    exact = True  # the pressure spectrum was transformed afresh, not updated by linearity
    g_old = 1.0
    residual = np.inf
    converged = False
    iteration = 0
    while True:
        n, total, lowest, u_range = _gap_sums(u, h, p, 0.0 if load_control else shift)
        if n == 0:  # no contact: only possible under approach control
            converged, residual = True, 0.0
            break
        if load_control:  # the mean gap on the contact set is the approach (PK step 2)
            shift = total / n
            lowest -= shift
        gsq = _gap_on_contact(u, h, p, shift, g)
        # gap errors relative to the range of the displacement, but never below the
        # displacement of one cell under the mean contact pressure, which stays finite when
        # u is flat (a flat gap in full contact: u_range -> 0 although p is exact)
        scale = max(u_range, np.sum(p) / n * cell_compliance) or h_range or 1.0
        residual = max(np.sqrt(gsq / n), -lowest) / scale
        if load_control:
            residual = max(residual, abs(p.sum() * cell - load) / load)
        if residual < tol:
            if exact:
                converged = True
                break
            spectrum = transform(p)  # verify with a fresh transform
            u = fft.displacement(spectrum).ravel()
            ffts += 2
            exact = True
            continue
        if iteration >= max_iter:
            break
        iteration += 1
        if callback is not None:
            callback(iteration, residual)

        beta = 0.0 if iteration == 1 else gsq / g_old
        g_old = gsq
        g_dot_t = _direction_with_load(g, p, t, beta, n, load_control)
        if beta and not g_dot_t > 0.0:  # not a descent direction: restart (steepest descent)
            g_dot_t = _direction_with_load(g, p, t, 0.0, n, load_control)
        t_spectrum = transform(t)
        ffts += 1
        t_k_t = _energy(t_spectrum, fft.energy_weight)  # = sum (K t) t (PK step 6)
        if not t_k_t > 0.0:
            break  # no descent direction left (the operator is singular on the contact set)
        tau = g_dot_t / t_k_t
        total, corrected = _update(p, g, t, tau)
        factor = 1.0
        if load_control and not total > 0.0:
            break  # the step left no pressure to scale (a contact far below one cell)
        if load_control:  # PK step 10
            factor = load / (total * cell)
            p *= factor
        exact = bool(corrected)
        if exact:
            spectrum = transform(p)
            ffts += 1
        else:
            _spectral_step(spectrum, t_spectrum, tau, factor)
        u = fft.displacement(spectrum).ravel()
        ffts += 1

    contact = (p > 0.0).reshape(shape)
    return NormalContactResult(
        pressure=p.reshape(shape),
        gap=(u + h - shift).reshape(shape),
        displacement=u.reshape(shape),
        contact=contact,
        contact_area=float(np.count_nonzero(contact)) * cell,
        approach=float(shift),
        load=float(p.sum() * cell),
        iterations=iteration,
        converged=bool(converged),
        residual=float(residual),
        ffts=ffts,
        x=x,
        y=y,
        periodic=bool(periodic),
    )

