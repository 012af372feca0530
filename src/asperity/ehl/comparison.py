"""Centre line of a rough point contact against the equivalent rough line contact (seed Fig. 10).

Holmes, Evans & Snidle (J. Tribol. 127 (2005) 61, "Behavior in the Center of the Contact",
Fig. 10) compare, at one timestep, the film and pressure on the centre line ``y = 0`` of the
elliptical contact with those of the equivalent line contact, both with the same rough surfaces
moving at the same speeds: "the film thickness behavior is identical between the two methods
and the minor differences in pressure are no greater than inevitably exist in the comparison
of these equivalent smooth surface solutions". :func:`compare_centre_lines` measures both
statements on two :class:`~asperity.ehl.TransientResult` runs, and the smooth difference on
the two :class:`~asperity.ehl.SteadyResult` starts when given.

Metrics, over the Hertz width ``|x| <= a`` of the point contact (``a`` along x)::

    film_max_difference     = max |h_line - h_point| / h_c
    film_rms_difference     = rms(h_line - h_point) / h_c
    pressure_rms_difference = rms(p_line - p_point) / p_h

with ``h_c`` the central film of the point contact's smooth steady solution and ``p_h`` its
Hertz pressure; the same three for the smooth steady centre lines.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import InputError
from .problem import LineContact, PointContact
from .solver import SteadyResult
from .transient import TransientResult

__all__ = ["CentreLineComparison", "compare_centre_lines"]


@dataclass(frozen=True)
class CentreLineComparison:
    """Centre-line film and pressure of a rough point and line contact at common timesteps.

    Attributes
    ----------
    x : ndarray
        Node coordinates along x shared by both runs, m.
    a : float
        Hertz semi-axis of the point contact along x, m: the window ``|x| <= a`` of the
        metrics and the length unit of the figures.
    p_hertz : float
        Hertz pressure of the point contact, Pa.
    central_film : float
        Central film of the point contact's smooth steady solution, m.
    steps : ndarray of int
        Snapshot steps recorded, and completed, by both runs.
    point_film, line_film, point_pressure, line_pressure : ndarray
        h (m) and p (Pa) on y = 0, shape ``(steps.size, x.size)``.
    surface1, surface2 : ndarray
        Heights z1, z2 (m) on y = 0 at those steps (the same in both runs).
    film_max_difference, film_rms_difference : ndarray
        Per step: max and RMS over ``|x| <= a`` of ``h_line - h_point``, over
        ``central_film``.
    pressure_rms_difference : ndarray
        Per step: RMS over ``|x| <= a`` of ``p_line - p_point``, over ``p_hertz``.
    film_rms_deviation : ndarray
        Per step: RMS over ``|x| <= a`` of the rough point film minus the smooth steady point
        film, over ``central_film`` (how far the roughness moves the film; the scale against
        which ``film_rms_difference`` is small). NaN without the smooth solutions.
    smooth_film_max_difference, smooth_film_rms_difference, smooth_pressure_rms_difference
        The same metrics for the two smooth steady solutions (the difference the seed calls
        inevitable); NaN without them.
    converged : bool
        Both transient runs, and both steady solutions when given, converged.
    """

    x: np.ndarray
    a: float
    p_hertz: float
    central_film: float
    steps: np.ndarray
    point_film: np.ndarray
    line_film: np.ndarray
    point_pressure: np.ndarray
    line_pressure: np.ndarray
    surface1: np.ndarray
    surface2: np.ndarray
    film_max_difference: np.ndarray
    film_rms_difference: np.ndarray
    pressure_rms_difference: np.ndarray
    film_rms_deviation: np.ndarray
    smooth_film_max_difference: float
    smooth_film_rms_difference: float
    smooth_pressure_rms_difference: float
    converged: bool


def _check_steady(steady, x, field, line):
    if not isinstance(steady, SteadyResult):
        raise InputError(field, "an asperity.ehl.SteadyResult or None", type(steady).__name__)
    if (steady.x.shape != x.shape or not np.allclose(steady.x, x, rtol=0.0,
                                                     atol=1e-9 * np.ptp(x))
            or (steady.y.size == 1) != line or not steady.y[0] <= 0.0 <= steady.y[-1]):
        raise InputError(field, "the smooth steady solution of the same contact on the "
                                "transient runs' x grid")
    _, p, h = steady.centre_line()
    return h, p


def _metrics(inside, h_ref, p_ref, film_a, film_b, pressure_a, pressure_b):
    """(max |dh|, rms dh) / h_ref and rms dp / p_ref over the columns ``inside``."""
    dh = (np.asarray(film_b) - film_a)[..., inside]
    dp = (np.asarray(pressure_b) - pressure_a)[..., inside]
    return (np.abs(dh).max(axis=-1) / h_ref, np.sqrt(np.mean(dh**2, axis=-1)) / h_ref,
            np.sqrt(np.mean(dp**2, axis=-1)) / p_ref)


def compare_centre_lines(point_result, line_result, point_problem, line_problem,
                         point_steady=None, line_steady=None) -> CentreLineComparison:
    """Compare the centre line of a rough point contact with the equivalent line contact.

    The seed's Fig. 10 check (Holmes, Evans & Snidle, J. Tribol. 127 (2005) 61, "Behavior in
    the Center of the Contact"): at the same timestep, with the same rough surfaces at the same
    places, the line contact's film should follow the point contact's film on y = 0 and its
    pressure differ no more than the two smooth solutions do. Metrics are taken over the point
    contact's Hertz width ``|x| <= a`` (module docstring).

    Parameters
    ----------
    point_result, line_result : TransientResult
        Runs of :func:`asperity.ehl.solve_transient` on the same x grid in metres (same nodes
        and domain: pass an explicit ``domain`` to both, since the Hertz widths differ), with
        the same timestep and at least one common snapshot step.
    point_problem : PointContact
        The point contact of ``point_result``.
    line_problem : LineContact
        The line contact of ``line_result``; same surface speeds ``u1``, ``u2``.
    point_steady, line_steady : SteadyResult, optional
        The smooth steady solutions of the two contacts on the same x grid (typically the
        ``steady`` starts of the runs); give both for the smooth metrics and
        ``film_rms_deviation``.

    Returns
    -------
    CentreLineComparison

    Raises
    ------
    InputError
        Wrong types; x grids, timesteps, surface speeds or recorded surface heights that
        differ; no common completed snapshot step; only one steady solution, or one on
        another grid.
    """
    for value, field in ((point_result, "point_result"), (line_result, "line_result")):
        if not isinstance(value, TransientResult):
            raise InputError(field, "an asperity.ehl.TransientResult", type(value).__name__)
    if not isinstance(point_problem, PointContact):
        raise InputError("point_problem", "a PointContact", type(point_problem).__name__)
    if not isinstance(line_problem, LineContact):
        raise InputError("line_problem", "a LineContact", type(line_problem).__name__)
    x = point_result.x
    if point_result.y.size < 2:
        raise InputError("point_result", "a point-contact run (more than one node along y)")
    if line_result.y.size != 1:
        raise InputError("line_result", "a line-contact run (one node along y)")
    tol_x = 1e-9 * np.ptp(x)
    if line_result.x.shape != x.shape or not np.allclose(line_result.x, x, rtol=0.0,
                                                         atol=tol_x):
        raise InputError("x", "the same x nodes (m) in both runs: pass the same nx and an "
                              "explicit domain in m to solve_transient",
                         (f"{x.size} nodes on [{x[0]:.6g}, {x[-1]:.6g}]",
                          f"{line_result.x.size} nodes on "
                          f"[{line_result.x[0]:.6g}, {line_result.x[-1]:.6g}]"))
    if not np.isclose(line_result.dt, point_result.dt, rtol=1e-9, atol=0.0):
        raise InputError("dt", "the same timestep in both runs", (point_result.dt,
                                                                  line_result.dt))
    speeds_p = (point_problem.u1, point_problem.u2)
    speeds_l = (line_problem.u1, line_problem.u2)
    if not np.allclose(speeds_l, speeds_p, rtol=1e-9, atol=0.0):
        raise InputError("u1, u2", "the same surface speeds in both problems",
                         (speeds_p, speeds_l))
    last = min(point_result.steps_done, line_result.steps_done)
    steps = np.intersect1d(point_result.snapshot_steps, line_result.snapshot_steps)
    steps = steps[steps <= last]
    if steps.size == 0:
        raise InputError("snapshot_steps", "at least one snapshot step recorded and completed "
                                           "by both runs",
                         (point_result.snapshot_steps.tolist(),
                          line_result.snapshot_steps.tolist()))
    ip = np.searchsorted(point_result.snapshot_steps, steps)
    il = np.searchsorted(line_result.snapshot_steps, steps)
    for name in ("centre_surface1", "centre_surface2"):
        zp = getattr(point_result, name)[ip]
        zl = getattr(line_result, name)[il]
        scale = max(float(np.max(np.abs(zp))), float(np.max(np.abs(zl))), 1e-300)
        if not np.allclose(zl, zp, rtol=0.0, atol=1e-9 * scale):
            raise InputError(name, "the same surface heights in both runs at the common steps "
                                   "(same roughness, speeds and inlet)")

    a = point_problem.a
    p_h = point_problem.p_hertz
    h_c = float(point_result.steady_central_film)
    inside = np.abs(x) <= a
    film_p, film_l = point_result.centre_film[ip], line_result.centre_film[il]
    pres_p, pres_l = point_result.centre_pressure[ip], line_result.centre_pressure[il]
    film_max, film_rms, pres_rms = _metrics(inside, h_c, p_h, film_p, film_l, pres_p, pres_l)

    converged = bool(point_result.converged and line_result.converged)
    if (point_steady is None) != (line_steady is None):
        raise InputError("point_steady, line_steady", "both smooth steady solutions or neither")
    if point_steady is None:
        smooth = (np.nan, np.nan, np.nan)
        deviation = np.full(steps.size, np.nan)
    else:
        hp, pp = _check_steady(point_steady, x, "point_steady", line=False)
        hl, pl = _check_steady(line_steady, x, "line_steady", line=True)
        smooth = tuple(float(v) for v in _metrics(inside, h_c, p_h, hp, hl, pp, pl))
        deviation = _metrics(inside, h_c, p_h, hp, film_p, pp, pres_p)[1]
        converged = converged and bool(point_steady.converged and line_steady.converged)

    return CentreLineComparison(
        x=x, a=float(a), p_hertz=float(p_h), central_film=h_c, steps=steps,
        point_film=film_p, line_film=film_l, point_pressure=pres_p, line_pressure=pres_l,
        surface1=point_result.centre_surface1[ip], surface2=point_result.centre_surface2[ip],
        film_max_difference=film_max, film_rms_difference=film_rms,
        pressure_rms_difference=pres_rms, film_rms_deviation=deviation,
        smooth_film_max_difference=smooth[0], smooth_film_rms_difference=smooth[1],
        smooth_pressure_rms_difference=smooth[2], converged=converged)
