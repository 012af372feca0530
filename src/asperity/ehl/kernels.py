"""Compiled relaxation sweeps of the coupled (p, h) EHL equations (Holmes et al. 2003, Eq. 7).

All quantities are dimensionless (see :mod:`asperity.ehl.problem`). At an interior node P the
finite-difference Reynolds equation (docs/ehl.md) and the differential deflection equation read

    A0 p_P + B0 h_P = R^          (Reynolds, theta-scheme in time)
    C0 p_P + D0 h_P = E^          (Delta_h h = Delta_h phi + curvature + c sum f p)

with, for faces ``xi_e = (eps_P + eps_E)/(2 dX^2)`` etc. and second-order upwind weights
``(c0, c1, c2) = (3/2, 2, 1/2)`` (first order ``(1, 1, 0)`` next to the inlet boundary):

    A0 = -theta sum xi_nb
    B0 = -theta lam rho_P c0 / dX - mass rho_P
    R^ = -theta [sum xi_nb p_nb + lam (c1 (rho h)_W - c2 (rho h)_WW) / dX] - rhs_t
    C0 = -c f_00,  D0 = -2/dX^2 - 2/dY^2
    E^ = efar - (h_E + h_W)/dX^2 - (h_N + h_S)/dY^2

``mass = lam/dT`` and ``rhs_t = (1 - theta) L^n + mass (rho h)^n`` carry the time terms (zero
for a steady solve) and ``efar = Delta_h phi + curvature + c (sum f p)_lagged`` the far-field
deflection refreshed by FFT. A node whose coupled update gives p < 0 is cavitated (p = 0,
h from the deflection equation); one that gives h < 0 is in contact (h = 0, p from the
deflection equation, Holmes et al. Eq. 8).

Three sweeps are provided: the seed's point update (:func:`point_sweep`), a zebra x-line
update (:func:`line_sweep`, rows solved in parallel threads) that solves every ``y = const``
row of nodes at once, with the Reynolds x-couplings, the deflection Laplacian in x and the
``|k| <= K`` near-field pressure coefficients along x implicit, by block elimination of its
2 x 2 (p_i, h_i) blocks, and a y-line update (:func:`column_sweep`) that solves every
``x = const`` column with the y-couplings implicit, for cells that are not long across the
entrainment direction (docs/ehl-robustness.md, "Square cells").
:func:`damp_oscillations` damps a sweep's oscillating changes (and under-relaxes them all)
and :func:`far_field` evaluates ``efar`` at a far-field refresh.
"""

from __future__ import annotations

import os

# OpenMP threads of the parallel line sweep sleep instead of spinning when they wait: on a
# machine shared with other processes (a sweep of cases, a test run) spinning threads took
# 35 % longer than one thread; when the cores are free both policies give the same speed-up.
# Set before numba starts its threading layer; an explicit user setting wins.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")

import numba  # noqa: E402
import numpy as np

FLUID, CAVITATED, CONTACT = 0, 1, 2

# The helpers called at every node are inlined into their callers by numba
# (``inline="always"``): called as functions, they took their arrays with reference counts
# (atomic increments and decrements at every call), an eighth of the line sweep's time on
# 571 x 201 nodes (10.5 against 9.2 ms, one thread).


@numba.njit(cache=True, inline="always")
def _spacing(ny, dx, dy):
    """(dX^2, dY^2, 1/dY^2, D0) of the grid; a single row (line contact) has no y-terms."""
    if ny > 1:
        dy2 = dy * dy
        inv_dy2 = 1.0 / dy2
    else:
        dy2 = 1.0
        inv_dy2 = 0.0
    dx2 = dx * dx
    return dx2, dy2, inv_dy2, -2.0 / dx2 - 2.0 * inv_dy2


@numba.njit(cache=True, inline="always")
def _upwind(i):
    """Upwind weights (c0, c1, c2) of d(rho h)/dX at node i (first order next to the inlet)."""
    if i >= 2:
        return 1.5, 2.0, 0.5
    return 1.0, 1.0, 0.0


@numba.njit(cache=True, inline="always")
def _faces(eps_x, eps_y, i, j, dx2, dy2):
    """Face conductances xi_e, xi_w, xi_n, xi_s at node (i, j) (arithmetic face averages)."""
    ep = eps_x[i, j]
    xe = 0.5 * (ep + eps_x[i + 1, j]) / dx2
    xw = 0.5 * (ep + eps_x[i - 1, j]) / dx2
    if eps_y.shape[1] > 1:
        eq = eps_y[i, j]
        xn = 0.5 * (eq + eps_y[i, j + 1]) / dy2
        xs = 0.5 * (eq + eps_y[i, j - 1]) / dy2
    else:
        xn = 0.0
        xs = 0.0
    return xe, xw, xn, xs


@numba.njit(cache=True, inline="always")
def _newton(p, deps_x, deps_y, i, j, dx2, dy2, theta):
    """Stabilising part of the Newton derivative of the Poiseuille flux at node (i, j).

    The face conductances hold half the node's own ``eps``; with ``eps = eps(p_P)`` the flux
    ``theta sum xi_nb (p_nb - p_P)`` has the extra derivative
    ``theta/2 [eps_x'(p_E + p_W - 2 p_P)/dX^2 + eps_y'(p_N + p_S - 2 p_P)/dY^2]`` with respect
    to ``p_P``. Where it is negative (``eps`` falls with pressure and the node lies below its
    neighbours, e.g. a roughness valley at high pressure) it is added to the diagonal ``A0``
    (and ``times p_P`` to the right-hand side), so the change vanishes at convergence; where it
    is positive it is left out, so ``A0`` never loses diagonal weight.
    """
    pp = p[i, j]
    g = deps_x[i, j] * (p[i + 1, j] + p[i - 1, j] - 2.0 * pp) / dx2
    if p.shape[1] > 1:
        g += deps_y[i, j] * (p[i, j + 1] + p[i, j - 1] - 2.0 * pp) / dy2
    g *= 0.5 * theta
    return g if g < 0.0 else 0.0


#: Exponent k of the film in the flow factors' Newton term, ``d eps/dh = k eps/h``: 2, the
#: Eyring film sheared at the sliding speed (``eps -> rho h^2 |du| / (12 tau0)``, where
#: ``eps`` no longer falls with the pressure), the smaller of that and a Newtonian film's 3.
FILM_EXPONENT = 2.0


@numba.njit(cache=True, inline="always")
def _film_newton(p, h, eps_x, eps_y, i, j, dx2, dy2, theta):
    """Stabilising part of the Newton derivative of the Poiseuille flux at node (i, j) with
    respect to the node's film, for the coefficient of ``h_P`` in its Reynolds row.

    With ``eps = eps(h_P)``, ``d eps/dh = k eps / h`` (``k`` = :data:`FILM_EXPONENT`), the
    flux ``theta sum xi_nb (p_nb - p_P)`` has the derivative
    ``theta k/2 [eps_x (p_E + p_W - 2 p_P)/dX^2 + eps_y (p_N + p_S - 2 p_P)/dY^2] / h_P``.
    Where it is negative (the node at or above its neighbours' pressure: a pressure crest)
    it has the sign of the wedge's coefficient ``B0`` and is added to it (``times h_P`` to the
    right-hand side, so the fixed point is unchanged); elsewhere it is left out. A user's
    cam-nose line contact with a 4 MPa Eyring oil at slide/roll 0.1 (M = 44, L = 6.1), whose
    Hertz zone keeps flow factors of 0.6 % of the inlet's, drifted to a micrometre-thick
    branch without it (docs/ehl-robustness.md, "Not in the table").
    """
    hh = h[i, j]
    if hh <= 0.0:
        return 0.0
    g = eps_x[i, j] * (p[i + 1, j] + p[i - 1, j] - 2.0 * p[i, j]) / dx2
    if p.shape[1] > 1:
        g += eps_y[i, j] * (p[i, j + 1] + p[i, j - 1] - 2.0 * p[i, j]) / dy2
    g *= 0.5 * theta * FILM_EXPONENT / hh
    return g if g < 0.0 else 0.0


@numba.njit(cache=True, inline="always")
def _density_newton(h, drho, i, j, lam, dx, theta, mass, k):
    """Newton derivative of node (i, j)'s Reynolds wedge and time terms with respect to the
    pressure of node ``i - k`` (k = 0, 1, 2) through the density, at the current film.

    The wedge ``-theta lam (c0 (rho h)_i - c1 (rho h)_{i-1} + c2 (rho h)_{i-2}) / dX`` and the
    time term ``-mass (rho h)_i`` with ``rho = rho(p)``: the derivative with respect to
    ``p_{i-k}`` is ``-theta lam c_k' h_{i-k} rho'_{i-k} / dX`` (``c_0' = c0``, ``c_1' = -c1``,
    ``c_2' = c2``) plus ``-mass h_i rho'_i`` for k = 0. The sweeps add it to the coefficient
    of ``p_{i-k}`` (and times ``p_{i-k}`` to the right-hand side), so that a compressible
    lubricant's density follows the pressure within the update instead of lagging one sweep
    behind; the fixed point is unchanged.
    """
    c0, c1, c2 = _upwind(i)
    c = (c0, -c1, c2)[k]
    d = -theta * lam * c * h[i - k, j] * drho[i - k, j] / dx
    if k == 0:
        d -= mass * h[i, j] * drho[i, j]
    return d


@numba.njit(cache=True, inline="always")
def _nodal_coefficients(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el,
                        f_near, i, j):
    """(A0, B0, R^, E^) of the coupled nodal update at interior node (i, j) (module docstring).

    At the current iterate, without the Newton term; the implicit x-neighbour pressure terms
    ``c f_{k,0} p_{i+k}``, ``1 <= |k| <= K``, are moved to ``E^`` (none when ``f_near`` holds
    only ``f_00``). ``C0 = -c f_00`` and ``D0 = -2/dX^2 - 2/dY^2`` complete the 2 x 2 system.
    """
    nx, ny = p.shape
    two_d = ny > 1
    dx2, dy2, inv_dy2, _ = _spacing(ny, dx, dy)
    xe, xw, xn, xs = _faces(eps_x, eps_y, i, j, dx2, dy2)
    c0, c1, c2 = _upwind(i)
    nb = xe * p[i + 1, j] + xw * p[i - 1, j]
    hy = 0.0
    if two_d:
        nb += xn * p[i, j + 1] + xs * p[i, j - 1]
        hy = (h[i, j + 1] + h[i, j - 1]) * inv_dy2
    rho_ww_h = rho[i - 2, j] * h[i - 2, j] if i >= 2 else 0.0
    a0 = -theta * (xe + xw + xn + xs)
    b0 = -theta * lam * rho[i, j] * c0 / dx - mass * rho[i, j]
    r = -theta * (nb + lam * (c1 * rho[i - 1, j] * h[i - 1, j] - c2 * rho_ww_h) / dx)
    r -= rhs_t[i, j]
    e = efar[i, j] - (h[i + 1, j] + h[i - 1, j]) / dx2 - hy
    kn = f_near.size - 1
    for k in range(-kn, kn + 1):
        if k != 0 and 0 < i + k < nx - 1:
            e += c_el * f_near[abs(k)] * p[i + k, j]
    return a0, b0, r, e


@numba.njit(cache=True)
def point_sweep(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el, f_near,
                deps_x, deps_y):
    """One lexicographic Gauss-Seidel sweep of the coupled nodal update (Holmes et al. Eq. 7-8).

    Rows j in turn, nodes along each row in the entrainment direction (+x). Updates ``p``
    and ``h`` in place on interior nodes and returns the largest change of p and of h. The
    nodal 2 x 2 system carries the stabilising Newton terms of the flow factors in the node's
    pressure (:func:`_newton`) and film (:func:`_film_newton`).
    ``C0 = -c_el f_near[0] > 0`` (the seed's update has ``f_near = [f_00]``; ``efar`` must
    exclude the coefficients in ``f_near``). With one row (``ny == 1``) it is the
    line-contact sweep.
    """
    nx, ny = p.shape
    two_d = ny > 1
    dx2, dy2, inv_dy2, d0 = _spacing(ny, dx, dy)
    c_self = -c_el * f_near[0]
    j0, j1 = (1, ny - 1) if two_d else (0, 1)
    dp_max = 0.0
    dh_max = 0.0
    for j in range(j0, j1):
        for i in range(1, nx - 1):
            a0, b0, r, e = _nodal_coefficients(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx,
                                               dy, theta, mass, c_el, f_near, i, j)
            newton = _newton(p, deps_x, deps_y, i, j, dx2, dy2, theta)
            a0 += newton
            r += newton * p[i, j]
            film = _film_newton(p, h, eps_x, eps_y, i, j, dx2, dy2, theta)
            b0 += film
            r += film * h[i, j]
            det = a0 * d0 - b0 * c_self
            pn = (r * d0 - b0 * e) / det
            hn = (a0 * e - c_self * r) / det
            if pn < 0.0:
                pn = 0.0
                hn = e / d0
            if hn < 0.0:
                hn = 0.0
                pn = max(e / c_self, 0.0)
            dp_max = max(dp_max, abs(pn - p[i, j]))
            dh_max = max(dh_max, abs(hn - h[i, j]))
            p[i, j] = pn
            h[i, j] = hn
    return dp_max, dh_max


@numba.njit(cache=True)
def _block_band_solve(m, b, bl, bu, x=None, start=0):
    """Solve the block-banded system of a row (:func:`_assemble_row`) by block elimination,
    from block row ``start``.

    ``m[i, j - i + bl]`` holds the 2 x 2 block A[i, j] for ``-bl <= j - i <= bu`` and
    ``b[i]`` the right-hand side of block row i; the solution goes to ``x`` (to ``b`` without
    ``x``). Block LU without interchanges between block rows keeps the band, so it needs no
    fill-in storage; each diagonal block is inverted directly. ``m`` and ``b`` are eliminated
    in place: block row k then holds the inverse of its pivot, its unchanged blocks right of
    it and (with ``x``) its eliminated right-hand side. A row of the coupled (p, h) system
    has a nonsingular diagonal block at every node (``det = A0 D0 - B0 C0 > 0`` at a fluid
    node, ``D0`` cavitated, ``-C0`` in contact) and is dominated by it, which is what
    elimination without pivoting needs; it costs about a third of a scalar band elimination
    with partial pivoting (LAPACK ``gbsv``) of the same rows.

    The h-columns of the blocks right of the diagonal are those of the deflection Laplacian:
    ``(0, 1/dX^2)`` in A[k, k + 1] (zero at a boundary node) and zero further right. The
    elimination keeps them (their updates only involve h-columns further right), so the
    products with these zeros are left out; the other products are those of a full block
    elimination, in the same order.

    With ``start > 0`` rows ``< start`` must hold their elimination by an earlier call with
    ``x`` and rows ``>= start`` the (new) system: only the rows from ``start`` on are
    eliminated, in the same operations as a solve from row 0, so the solution is the same to
    the bit.
    """
    _eliminate(m, b, bl, bu, start)
    if x is None:
        _back_substitute(m, b, b, bl, bu)
    else:
        _back_substitute(m, b, x, bl, bu)


@numba.njit(cache=True)
def _eliminate(m, b, bl, bu, start):
    """The block elimination of :func:`_block_band_solve`, from block row ``start``."""
    n = b.shape[0]
    for k in range(max(0, start - bl), n):
        if k >= start:
            _invert_pivot(m, k, bl)
        i00 = m[k, bl, 0, 0]
        i01 = m[k, bl, 0, 1]
        i10 = m[k, bl, 1, 0]
        i11 = m[k, bl, 1, 1]
        b0 = b[k, 0]
        b1 = b[k, 1]
        for i in range(max(k + 1, start), min(k + bl, n - 1) + 1):
            a = k - i + bl
            a00 = m[i, a, 0, 0]
            a01 = m[i, a, 0, 1]
            a10 = m[i, a, 1, 0]
            a11 = m[i, a, 1, 1]
            if a00 == 0.0 and a01 == 0.0 and a10 == 0.0 and a11 == 0.0:
                continue
            l00 = a00 * i00 + a01 * i10
            l01 = a00 * i01 + a01 * i11
            l10 = a10 * i00 + a11 * i10
            l11 = a10 * i01 + a11 * i11
            # h-column of block (k, k + 1): (0, 1/dX^2); right of it the h-column is zero
            u11 = m[k, bl + 1, 1, 1]
            m[i, bl + k + 1 - i, 0, 1] -= l01 * u11
            m[i, bl + k + 1 - i, 1, 1] -= l11 * u11
            for j in range(k + 1, min(k + bu, n - 1) + 1):
                u = j - k + bl
                c = j - i + bl
                u00 = m[k, u, 0, 0]
                u10 = m[k, u, 1, 0]
                m[i, c, 0, 0] -= l00 * u00 + l01 * u10
                m[i, c, 1, 0] -= l10 * u00 + l11 * u10
            b[i, 0] -= l00 * b0 + l01 * b1
            b[i, 1] -= l10 * b0 + l11 * b1


@numba.njit(cache=True)
def _back_substitute(m, b, x, bl, bu):
    """Back substitution of :func:`_block_band_solve` into ``x`` (which may be ``b``: each row
    of ``b`` is read before it is overwritten)."""
    n = b.shape[0]
    for k in range(n - 1, -1, -1):
        s0 = b[k, 0]
        s1 = b[k, 1]
        for j in range(k + 1, min(k + bu, n - 1) + 1):
            u = j - k + bl
            s0 -= m[k, u, 0, 0] * x[j, 0]
            if j == k + 1:
                s1 -= m[k, u, 1, 0] * x[j, 0] + m[k, u, 1, 1] * x[j, 1]
            else:
                s1 -= m[k, u, 1, 0] * x[j, 0]
        x[k, 0] = m[k, bl, 0, 0] * s0 + m[k, bl, 0, 1] * s1
        x[k, 1] = m[k, bl, 1, 0] * s0 + m[k, bl, 1, 1] * s1


@numba.njit(cache=True, inline="always")
def _invert_pivot(m, k, bl):
    """Replace the diagonal 2 x 2 block ``m[k, bl]`` by its inverse."""
    d00 = m[k, bl, 0, 0]
    d01 = m[k, bl, 0, 1]
    d10 = m[k, bl, 1, 0]
    d11 = m[k, bl, 1, 1]
    inv = 1.0 / (d00 * d11 - d01 * d10)
    m[k, bl, 0, 0] = d11 * inv
    m[k, bl, 0, 1] = -d01 * inv
    m[k, bl, 1, 0] = -d10 * inv
    m[k, bl, 1, 1] = d00 * inv


@numba.njit(cache=True)
def _assemble_row(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el,
                  f_near, j, kind, m, b, bl, deps_x, deps_y, drho, start=0):
    """Assemble block rows ``start..nx-1`` of the block-banded system of row j: block i holds
    (p_i, h_i); ``m[i, k + bl]`` couples node i to node i + k (layout of
    :func:`_block_band_solve`)."""
    nx, ny = p.shape
    two_d = ny > 1
    dx2, dy2, inv_dy2, d0 = _spacing(ny, dx, dy)
    kn = f_near.size - 1
    m[start:] = 0.0
    for i in range(start, nx):
        if i == 0 or i == nx - 1:
            m[i, bl, 0, 0] = 1.0
            b[i, 0] = 0.0
            m[i, bl, 1, 1] = 1.0
            b[i, 1] = h[i, j]
            continue
        # deflection row: (h_E + h_W)/dX^2 + D0 h_P - c sum_|k|<=K f_k p_{i+k} = E^
        hy = (h[i, j + 1] + h[i, j - 1]) * inv_dy2 if two_d else 0.0
        m[i, bl, 1, 1] = d0
        m[i, bl + 1, 1, 1] = 1.0 / dx2
        m[i, bl - 1, 1, 1] = 1.0 / dx2
        for k in range(-kn, kn + 1):
            if 0 < i + k < nx - 1:
                m[i, bl + k, 1, 0] -= c_el * f_near[abs(k)]
        b[i, 1] = efar[i, j] - hy
        if kind[i] == CAVITATED:
            m[i, bl, 0, 0] = 1.0
            b[i, 0] = 0.0
            continue
        if kind[i] == CONTACT:
            m[i, bl, 0, 1] = 1.0
            b[i, 0] = 0.0
            continue
        xe, xw, xn, xs = _faces(eps_x, eps_y, i, j, dx2, dy2)
        c0, c1, c2 = _upwind(i)
        newton = _newton(p, deps_x, deps_y, i, j, dx2, dy2, theta)
        m[i, bl, 0, 0] = -theta * (xe + xw + xn + xs) + newton
        m[i, bl + 1, 0, 0] = theta * xe
        m[i, bl - 1, 0, 0] = theta * xw
        m[i, bl, 0, 1] = -theta * lam * rho[i, j] * c0 / dx - mass * rho[i, j]
        m[i, bl - 1, 0, 1] = theta * lam * c1 * rho[i - 1, j] / dx
        if i >= 2:
            m[i, bl - 2, 0, 1] = -theta * lam * c2 * rho[i - 2, j] / dx
        nb = 0.0
        if two_d:
            nb = xn * p[i, j + 1] + xs * p[i, j - 1]
        b[i, 0] = -theta * nb - rhs_t[i, j] + newton * p[i, j]
        if drho is not None:
            for k in range(min(i, 2) + 1):  # d(rho h)/dp of nodes i, i - 1, i - 2
                dr = _density_newton(h, drho, i, j, lam, dx, theta, mass, k)
                m[i, bl - k, 0, 0] += dr
                b[i, 0] += dr * p[i - k, j]


@numba.njit(cache=True)
def _update_active_set(row_kind, x):
    """Move the interior nodes of a row whose solution ``x = (p, h)`` leaves their state:
    fluid with p < 0 to cavitated, fluid or cavitated with h < 0 to contact, contact with
    p < 0 to cavitated. Returns the first node moved (``len(x)`` if none)."""
    n = x.shape[0]
    first = n
    for i in range(1, n - 1):
        old = row_kind[i]
        if old == FLUID and x[i, 0] < 0.0:
            row_kind[i] = CAVITATED
        elif old != CONTACT and x[i, 1] < 0.0:
            row_kind[i] = CONTACT
        elif old == CONTACT and x[i, 0] < 0.0:
            row_kind[i] = CAVITATED
        if row_kind[i] != old and first == n:
            first = i
    return first


@numba.njit(cache=True, inline="always")
def _released(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el, f_near,
              i, j, state, d0, c_self):
    """The state of a cavitated or contact node (i, j) after the release test of the line
    updates: fluid where the point update of Eq. 7 at the current iterate gives p > 0
    (cavitated) or h > 0 (contact), else unchanged."""
    a0, b0, r, e = _nodal_coefficients(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy,
                                       theta, mass, c_el, f_near, i, j)
    det = a0 * d0 - b0 * c_self
    if state == CAVITATED and (r * d0 - b0 * e) / det > 0.0:
        return FLUID
    if state == CONTACT and (a0 * e - c_self * r) / det > 0.0:
        return FLUID
    return state


@numba.njit(cache=True, inline="always")
def _store(p, h, i, j, x, k):
    """Write block k of a line solution ``x`` (p, h; negative values as 0) into node (i, j);
    return the changes |dp|, |dh|."""
    pn = max(x[k, 0], 0.0)
    hn = max(x[k, 1], 0.0)
    dp = abs(pn - p[i, j])
    dh = abs(hn - h[i, j])
    p[i, j] = pn
    h[i, j] = hn
    return dp, dh


@numba.njit(cache=True)
def _relax_row(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el, f_near,
               kind, deps_x, deps_y, drho, j):
    """Solve row j for all its (p, h) at once with an active set (see :func:`line_sweep`).

    Updates row j of ``p``, ``h`` and ``kind`` in place (reading only rows j - 1 and j + 1
    of the others) and returns its largest change of p and of h.
    """
    nx, ny = p.shape
    kn = f_near.size - 1
    bl = max(2, kn)  # h_{i-2} in the upwind wedge; p_{i-K} in the near field
    bu = max(1, kn)
    m = np.empty((nx, bl + bu + 1, 2, 2))
    b = np.empty((nx, 2))
    x = np.empty((nx, 2))
    d0 = _spacing(ny, dx, dy)[3]
    c_self = -c_el * f_near[0]
    row_kind = kind[:, j]
    for i in range(1, nx - 1):
        if row_kind[i] != FLUID:
            row_kind[i] = _released(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta,
                                    mass, c_el, f_near, i, j, row_kind[i], d0, c_self)
    start = 0
    for _ in range(4):
        _assemble_row(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el,
                      f_near, j, row_kind, m, b, bl, deps_x, deps_y, drho, start)
        _block_band_solve(m, b, bl, bu, x, start)
        start = _update_active_set(row_kind, x)
        if start == nx:
            break
    dp_max = 0.0
    dh_max = 0.0
    for i in range(1, nx - 1):
        dp, dh = _store(p, h, i, j, x, i)
        dp_max = max(dp_max, dp)
        dh_max = max(dh_max, dh)
    return dp_max, dh_max


@numba.njit(cache=True, parallel=True)
def line_sweep(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el, f_near,
               kind, deps_x, deps_y, drho=None):
    """One zebra sweep of x-line relaxation: rows j = const, odd rows then even rows.

    Each row is solved for all its (p, h) at once with an active set: nodes are fluid,
    cavitated (p = 0) or in contact (h = 0). Fluid nodes that come out with p < 0 (h < 0)
    become cavitated (in contact) and the row is solved again from the first node that changed
    (the elimination of the nodes before it is kept); cavitated or contact nodes are
    released when the point update of Eq. 7 at the current iterate gives p > 0 (h > 0).
    ``kind`` (int8, shape p.shape) persists the active set between sweeps. ``f_near[k]`` are
    the implicit coefficients f_{k,0}, k = 0..K; ``efar`` must exclude them.

    Rows of one colour couple only to rows of the other, so each half-sweep solves its rows
    in parallel (numba threads); the result does not depend on the number of threads.
    Returns the largest change of p and of h.
    """
    nx, ny = p.shape
    j0, j1 = (1, ny - 1) if ny > 1 else (0, 1)
    dp_row = np.zeros(ny)
    dh_row = np.zeros(ny)
    for colour in range(2):
        first = j0 + colour
        count = max(0, (j1 - first + 1) // 2)
        for t in numba.prange(count):
            j = first + 2 * t
            dp_row[j], dh_row[j] = _relax_row(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx,
                                              dy, theta, mass, c_el, f_near, kind, deps_x,
                                              deps_y, drho, j)
    return dp_row.max(), dh_row.max()


@numba.njit(cache=True, parallel=True)
def damp_oscillations(p, h, p_before, h_before, last_change, damping, has_last, relaxation):
    """Scale by ``damping`` the change of a sweep at nodes where p moves against its last
    change, and by ``relaxation`` the change at every node.

    ``p, h`` hold the sweep's result and ``p_before, h_before`` the iterate it started from;
    p and h are moved back to ``before + factor * (new - before)`` with ``factor =
    relaxation``, times ``damping`` where ``(p - p_before) * last_change < 0`` (and
    ``has_last``). ``last_change`` becomes this sweep's change of p as scaled. All arrays
    share one shape and are updated in place.
    """
    nx, ny = p.shape
    for j in numba.prange(ny):  # x-fastest fields (asperity.ehl.solver.EHLState)
        for i in range(nx):
            change = p[i, j] - p_before[i, j]
            factor = relaxation
            if has_last and change * last_change[i, j] < 0.0:
                factor *= damping
            if factor != 1.0:
                change *= factor
                p[i, j] = p_before[i, j] + change
                h[i, j] = h_before[i, j] + factor * (h[i, j] - h_before[i, j])
            last_change[i, j] = change


@numba.njit(cache=True)
def _laplacian_column(w, j, dx2, dy2, two_d, out):
    """Column j of the 5-point Laplacian of ``w`` into ``out[:, j]``:
    ``(w_E - 2 w_P + w_W)/dX^2 [+ (w_N - 2 w_P + w_S)/dY^2]``, the y-part only when
    ``two_d``; zero on the edges (i = 0, nx - 1 and, when ``two_d``, j = 0, ny - 1)."""
    nx, ny = w.shape
    out[0, j] = 0.0
    out[nx - 1, j] = 0.0
    if two_d and (j == 0 or j == ny - 1):
        out[1:nx - 1, j] = 0.0
        return
    for i in range(1, nx - 1):
        lap = (w[i + 1, j] - 2.0 * w[i, j] + w[i - 1, j]) / dx2
        if two_d:
            lap += (w[i, j + 1] - 2.0 * w[i, j] + w[i, j - 1]) / dy2
        out[i, j] = lap


@numba.njit(cache=True, parallel=True)
def five_point_laplacian(w, dx2, dy2, two_d, out):
    """The 5-point Laplacian of the nodal field ``w`` into ``out`` (:func:`_laplacian_column`;
    ``dx2, dy2`` the squared spacings)."""
    for j in numba.prange(w.shape[1]):
        _laplacian_column(w, j, dx2, dy2, two_d, out)


@numba.njit(cache=True, parallel=True)
def far_field(w, p, source, c_el, f_near, dx2, dy2, two_d, efar):
    """The far-field term ``efar = source + c (Delta_h w - sum_{|k|<=K} f_k p_{i+k})`` of the
    deflection equation at every node, into ``efar``.

    ``w = D * p`` is the deflection sum, ``Delta_h`` its 5-point Laplacian
    (:func:`_laplacian_column`, zero on the edges) and ``f_near[k]`` the coefficients f_{k,0}
    kept implicit by the sweeps, summed over the x-neighbours inside the grid. Fastest with
    all fields x-fastest (like those of :class:`asperity.ehl.solver.EHLState`).
    """
    nx, ny = p.shape
    kn = f_near.size - 1
    for j in numba.prange(ny):
        _laplacian_column(w, j, dx2, dy2, two_d, efar)
        for i in range(nx):
            near = f_near[0] * p[i, j]
            for k in range(1, kn + 1):
                if i >= k:
                    near += f_near[k] * p[i - k, j]
                if i + k < nx:
                    near += f_near[k] * p[i + k, j]
            efar[i, j] = source[i, j] + c_el * (efar[i, j] - near)


@numba.njit(cache=True)
def _assemble_column(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el,
                     f_near, i, kind, m, b, deps_x, deps_y, start=0):
    """Assemble block rows ``start..ny-1`` of the block-tridiagonal system of column i (the
    nodes ``(i, j)``, j = 0..ny-1; layout of :func:`_block_band_solve` with one block either
    side): the Reynolds y-couplings and the deflection Laplacian in y implicit, the x-terms
    (the upwind wedge, the Reynolds and Laplacian x-neighbours and the near-field
    coefficients ``f_{k,0}``, ``k != 0``) at the current iterate as in :func:`point_sweep`."""
    nx, ny = p.shape
    dx2, dy2, inv_dy2, d0 = _spacing(ny, dx, dy)
    c_self = -c_el * f_near[0]
    m[start:] = 0.0
    for j in range(start, ny):
        if j == 0 or j == ny - 1:
            m[j, 1, 0, 0] = 1.0
            b[j, 0] = 0.0
            m[j, 1, 1, 1] = 1.0
            b[j, 1] = h[i, j]
            continue
        a0, b0, r, e = _nodal_coefficients(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy,
                                           theta, mass, c_el, f_near, i, j)
        # deflection row: (h_N + h_S)/dY^2 + D0 h_P + C0 p_P = E^ + (h_N + h_S)/dY^2
        m[j, 1, 1, 1] = d0
        m[j, 2, 1, 1] = inv_dy2
        m[j, 0, 1, 1] = inv_dy2
        m[j, 1, 1, 0] = c_self
        b[j, 1] = e + (h[i, j + 1] + h[i, j - 1]) * inv_dy2
        if kind[i, j] == CAVITATED:
            m[j, 1, 0, 0] = 1.0
            b[j, 0] = 0.0
            continue
        if kind[i, j] == CONTACT:
            m[j, 1, 0, 1] = 1.0
            b[j, 0] = 0.0
            continue
        xe, xw, xn, xs = _faces(eps_x, eps_y, i, j, dx2, dy2)
        newton = _newton(p, deps_x, deps_y, i, j, dx2, dy2, theta)
        m[j, 1, 0, 0] = a0 + newton
        m[j, 2, 0, 0] = theta * xn
        m[j, 0, 0, 0] = theta * xs
        m[j, 1, 0, 1] = b0
        b[j, 0] = r + theta * (xn * p[i, j + 1] + xs * p[i, j - 1]) + newton * p[i, j]


@numba.njit(cache=True)
def _relax_column(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el,
                  f_near, kind, deps_x, deps_y, i):
    """Solve column i for all its (p, h) at once with an active set, as :func:`_relax_row`
    does a row; returns its largest change of p and of h."""
    nx, ny = p.shape
    m = np.empty((ny, 3, 2, 2))
    b = np.empty((ny, 2))
    x = np.empty((ny, 2))
    d0 = _spacing(ny, dx, dy)[3]
    c_self = -c_el * f_near[0]
    col_kind = kind[i, :]
    for j in range(1, ny - 1):
        if col_kind[j] != FLUID:
            col_kind[j] = _released(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta,
                                    mass, c_el, f_near, i, j, col_kind[j], d0, c_self)
    start = 0
    for _ in range(4):
        _assemble_column(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el,
                         f_near, i, kind, m, b, deps_x, deps_y, start)
        _block_band_solve(m, b, 1, 1, x, start)
        start = _update_active_set(col_kind, x)
        if start == ny:
            break
    dp_max = 0.0
    dh_max = 0.0
    for j in range(1, ny - 1):
        dp, dh = _store(p, h, i, j, x, j)
        dp_max = max(dp_max, dp)
        dh_max = max(dh_max, dh)
    return dp_max, dh_max


@numba.njit(cache=True, parallel=True)
def column_sweep(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx, dy, theta, mass, c_el, f_near,
                 kind, deps_x, deps_y):
    """One sweep of y-line relaxation: columns i = const in ``max(3, K + 1)`` colours
    (``K = f_near.size - 1``), each solved for all its (p, h) at once with an active set
    (:func:`_relax_column`).

    A column reads the columns up to two nodes upstream (the second-order upwind wedge) and
    ``K`` either side (``f_near``), so the columns of one colour are independent and are
    solved in parallel; the result does not depend on the number of threads. Returns the
    largest change of p and of h.
    """
    nx, ny = p.shape
    colours = max(3, f_near.size)
    dp_col = np.zeros(nx)
    dh_col = np.zeros(nx)
    for colour in range(colours):
        first = 1 + colour
        count = max(0, (nx - 2 - first) // colours + 1)
        for t in numba.prange(count):
            i = first + colours * t
            dp_col[i], dh_col[i] = _relax_column(p, h, eps_x, eps_y, rho, efar, rhs_t, lam, dx,
                                                 dy, theta, mass, c_el, f_near, kind, deps_x,
                                                 deps_y, i)
    return dp_col.max(), dh_col.max()
