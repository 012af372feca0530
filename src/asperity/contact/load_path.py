"""Tangential loading histories: compliance curves, slip progression, Masing hysteresis.

Friction makes the contact history-dependent: each step is solved from the traction of the
previous one (``solve_tangential(..., previous=...)``, Coulomb's law on the slip increment), so
unloading and reverse loading follow Masing's rule (Johnson 1985, sec. 7.2(c); Mindlin &
Deresiewicz 1953) instead of retracing the loading curve. The work of the applied loads over a
closed cycle is the energy dissipated by microslip (fretting).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from ..materials import Material
from ..solution import renamed_attribute, renamed_keywords
from .tangential import TangentialResult, solve_tangential

__all__ = ["LoadPathResult", "proportional_path", "tangential_load_path"]


@dataclass(frozen=True)
class LoadPathResult:
    """Result of :func:`tangential_load_path`; arrays have one row per solved load step."""

    loads: np.ndarray
    """Applied (Fx, Fy, M) per step, (k, 3), N and N m."""
    shift: np.ndarray
    """Rigid shift of body 1 relative to body 2, (k, 2), m."""
    rotation: np.ndarray
    """Rigid rotation, (k,), rad."""
    centre_of_rotation: np.ndarray
    """(k, 2), m (NaN where the motion has no rotation)."""
    region_force: np.ndarray
    """Force carried by each connected patch, (k, n_regions, 2), N."""
    region_moment: np.ndarray
    """Moment carried by each patch about the centre, (k, n_regions), N m."""
    reaction_moment: np.ndarray
    """Moment supplied by the fixture when rotation is fixed, (k,), N m (zeros when free)."""
    stick_fraction: np.ndarray
    """Stuck share of the contact area, (k,)."""
    stick: np.ndarray
    """Stick maps, (k, nx, ny) bool: the progression of slip."""
    work: np.ndarray
    """Cumulative work of the applied loads, int F.d(delta) + M d(omega), (k,), J."""
    dissipated_energy: float
    """Work over the closed loop from the first visit of the last load to the end, J (the
    energy dissipated per cycle); NaN when the last load was not visited before."""
    gross_slip_step: int
    """Index of the step that reached gross slip (the path stops there), -1 if none."""
    iterations: int
    """Iterations summed over the steps."""
    converged: bool
    """Every step converged."""
    final: TangentialResult
    """The full result of the last step."""

    center_of_rotation = renamed_attribute("center_of_rotation", "centre_of_rotation")


def proportional_path(force=(0.0, 0.0), moment=0.0, steps=10, *, cycle=False, unload=False):
    """Load points from zero to (F, M) in ``steps`` equal increments.

    With ``cycle=True`` the path continues to -(F, M) and back to (F, M) (a full fretting
    cycle after the first loading), ``2 steps`` increments each way. With ``unload=True`` it
    ends with a return to zero load in ``steps`` increments.
    """
    if int(steps) < 1:
        raise InputError("steps", "an integer >= 1", steps)
    peak = np.array([*np.asarray(force, dtype=float), float(moment)])
    s = np.linspace(0.0, 1.0, int(steps) + 1)[1:]
    path = [s]
    if cycle:
        down = np.linspace(1.0, -1.0, 2 * int(steps) + 1)[1:]
        path += [down, -down]
    if unload:
        path.append(1.0 - s)
    return np.concatenate(path)[:, None] * peak[None, :]


@renamed_keywords(center="centre")
def tangential_load_path(pressure, x, y, mu, body1: Material, body2: Material, loads, *,
                         centre=None, tol=1e-8, callback=None,
                         rotation="free") -> LoadPathResult:
    """Solve a sequence of tangential loads, each from the state left by the previous one.

    Parameters
    ----------
    pressure, x, y, mu, body1, body2, centre, tol, rotation
        As for :func:`asperity.contact.solve_tangential` (the pressure is held fixed;
        ``center`` is accepted with a DeprecationWarning).
    loads : array_like (k, 3)
        Successive applied loads (Fx, Fy, Mz), N and N m, starting from the unloaded state;
        see :func:`proportional_path`. Any path is allowed (force first, then moment, ...).
    callback : callable, optional
        ``callback(step, result)`` after each step.

    Returns
    -------
    LoadPathResult
        The path stops at the first step in gross slip (history beyond is undefined).
    """
    loads = np.atleast_2d(np.asarray(loads, dtype=float))
    if loads.ndim != 2 or loads.shape[1] != 3 or not np.all(np.isfinite(loads)):
        raise InputError("loads", "an array of finite (Fx, Fy, M) rows", loads.shape)
    results: list[TangentialResult] = []
    previous = None
    gross = -1
    for k, load in enumerate(loads):
        res = solve_tangential(pressure, x, y, mu, body1, body2, force=load[:2],
                               moment=load[2], centre=centre, tol=tol, previous=previous,
                               rotation=rotation)
        results.append(res)
        if callback is not None:
            callback(k, res)
        if res.gross_slip:
            gross = k
            break
        previous = res
    done = loads[: len(results)]
    shift = np.array([r.shift for r in results])
    rotation = np.array([r.rotation for r in results])
    motion = np.column_stack([shift, rotation])
    # trapezoidal work from the unloaded origin
    states = np.vstack([np.zeros(3), done])
    motions = np.vstack([np.zeros(3), motion])
    increments = 0.5 * np.sum((states[1:] + states[:-1]) * np.diff(motions, axis=0), axis=1)
    work = np.cumsum(increments)
    # a closed loop: the last load was visited before (e.g. the peak of a fretting cycle)
    scale = np.abs(done).max(axis=0) + 1e-300
    same = np.all(np.abs(done[:-1] - done[-1]) <= 1e-9 * scale, axis=1)
    dissipated = float("nan")
    if gross < 0 and same.any():
        dissipated = float(work[-1] - work[int(np.argmax(same))])
    return LoadPathResult(
        loads=done, shift=shift, rotation=rotation,
        centre_of_rotation=np.array([r.centre_of_rotation for r in results]),
        region_force=np.array([[reg.force for reg in r.regions] for r in results]),
        region_moment=np.array([[reg.moment for reg in r.regions] for r in results]),
        reaction_moment=np.array([r.reaction_moment for r in results]),
        stick_fraction=np.array([r.stick.sum() / max((r.labels > 0).sum(), 1)
                                 for r in results]),
        stick=np.array([r.stick for r in results]), work=work, dissipated_energy=dissipated,
        gross_slip_step=gross, iterations=int(sum(r.iterations for r in results)),
        converged=all(r.converged for r in results), final=results[-1])
