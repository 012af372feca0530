"""Machined surfaces: process roughness ranges, kinematic feed marks, tool vibration in turning.

Seireg, *Friction and Lubrication in Mechanical Design* (1998), ch. 4: Table 4.1 (average
roughness of 24 manufacturing processes), eq. (4.1) (kinematic peak-to-valley roughness of
turning, ``R_max = f^2 / (8 r)`` for ``f <= 2 r sin(kappa_e)``), and the tool-vibration
simulation of Jang & Seireg summarised in Fig. 4.2.
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources

import numpy as np
import scipy.linalg
import scipy.signal

from ..errors import InputError, check_positive
from .parameters import roughness_parameters
from .topography import Profile, cell_centres

__all__ = [
    "MICROINCH",
    "ProcessRoughness",
    "PARABOLA_TOLERANCE",
    "TurnedSurface",
    "arc_peak_to_valley",
    "check_feed",
    "feed_limit",
    "feed_within_limit",
    "kinematic_peak_to_valley",
    "parabola_error",
    "parabola_feed_limit",
    "process_names",
    "process_roughness",
    "roughness_along",
    "turned_profile",
    "turned_profile_dynamic",
]

MICROINCH = 25.4e-9  # m


@dataclass(frozen=True)
class ProcessRoughness:
    """Range of the average roughness Ra a manufacturing process produces (Seireg Table 4.1)."""

    process: str
    ra_min_microinch: float
    ra_max_microinch: float

    @property
    def ra_min_um(self) -> float:
        return self.ra_min_microinch * MICROINCH * 1e6

    @property
    def ra_max_um(self) -> float:
        return self.ra_max_microinch * MICROINCH * 1e6

    @property
    def ra_range_m(self) -> tuple[float, float]:
        """(min, max) Ra in m."""
        return self.ra_min_microinch * MICROINCH, self.ra_max_microinch * MICROINCH


@lru_cache(maxsize=1)
def _table() -> tuple[ProcessRoughness, ...]:
    text = resources.files("asperity").joinpath("data", "process_roughness.csv").read_text()
    rows = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    return tuple(ProcessRoughness(r["process"], float(r["ra_min_microinch"]),
                                  float(r["ra_max_microinch"])) for r in rows)


def _key(name: str) -> str:
    return " ".join(str(name).lower().replace("-", " ").split())


def process_names() -> list[str]:
    """The 24 process names of Seireg Table 4.1, in the table's order."""
    return [p.process for p in _table()]


def process_roughness(name: str) -> ProcessRoughness:
    """Average roughness range of a manufacturing process (Seireg Table 4.1).

    Parameters
    ----------
    name : str
        A process name of :func:`process_names`, case-insensitive; a table entry that lists two
        processes ("Boring, turning") also answers to either ("turning").

    Raises
    ------
    InputError
        For an unknown process; the message lists the valid names.
    """
    key = _key(name)
    for entry in _table():
        full = _key(entry.process)
        if key == full or key in (_key(part) for part in entry.process.split(",")):
            return entry
    raise InputError("process", f"one of: {'; '.join(process_names())}", name)


#: Relative error of eq. (4.1)'s parabola against the arcs above which a turning result warns
#: (from f = 0.87 r on, :func:`parabola_feed_limit`): at f = 0.79 mm, r = 0.4 mm,
#: ``f^2/(8 r)`` = 195 um is 42 % below the arcs' 337 um.
PARABOLA_TOLERANCE = 0.05


def feed_limit(nose_radius, end_relief_angle=None) -> tuple[float, str]:
    """The largest feed whose marks the nose radius alone forms, and the rule in words.

    The arcs of radius r every f meet (and form the whole mark) up to ``f = 2 r``, or
    ``f = 2 r sin(kappa_e)`` when an end cutting-edge angle kappa_e is given (Seireg eq. 4.1).

    Parameters
    ----------
    nose_radius : float
        Tool nose radius r (m).
    end_relief_angle : float, optional
        End cutting-edge (relief) angle kappa_e (rad).

    Returns
    -------
    (float, str)
        The limit (m) and ``"2 r = 0.8 mm (r = 0.4 mm)"`` (with the angle where given).
    """
    r = check_positive("nose_radius", nose_radius)
    limit = 2.0 * r
    rule = f"2 r = {_mm(limit)} (r = {_mm(r)})"
    if end_relief_angle is not None:
        kappa = check_positive("end_relief_angle", end_relief_angle)
        limit *= math.sin(kappa)
        rule = (f"2 r sin(kappa_e) = {_mm(limit)} (r = {_mm(r)}, kappa_e = "
                f"{math.degrees(kappa):.4g} deg)")
    return limit, rule


def feed_within_limit(feed: float, limit: float) -> bool:
    """Whether ``feed`` is at most ``limit`` (:func:`feed_limit`): a feed of exactly 2 r typed
    in mm ("0.8 mm" for r = "0.4 mm") may land an ulp above it."""
    return feed <= limit * (1.0 + 1e-12)


def check_feed(feed, nose_radius, end_relief_angle=None, field: str = "feed") -> float:
    """Refuse a feed whose marks are not formed by the nose radius alone
    (:func:`feed_limit`); return the feed.

    Parameters
    ----------
    feed, nose_radius : float
        Feed per revolution f and tool nose radius r (m).
    end_relief_angle : float, optional
        End cutting-edge (relief) angle kappa_e (rad).
    field : str
        The name of the feed in the message (``surface.feed`` in a case file).

    Raises
    ------
    InputError
        For ``f > 2 r`` (``f > 2 r sin(kappa_e)``), saying the limit in mm.
    """
    f = check_positive(field, feed)
    limit, rule = feed_limit(nose_radius, end_relief_angle)
    if not feed_within_limit(f, limit):
        raise InputError(field, "", problem=f"expected at most {rule}, feed marks formed by "
                         f"the nose radius (Seireg eq. 4.1), got {_mm(f)}")
    return f


def _mm(length: float) -> str:
    """A length in mm as people read it (``0.8 mm``)."""
    return f"{length * 1e3:.4g} mm"


def kinematic_peak_to_valley(feed, nose_radius, end_relief_angle=None) -> float:
    """Kinematic peak-to-valley roughness of turning, ``f^2 / (8 r)`` (Seireg eq. 4.1).

    The parabola's approximation of the arcs' height :func:`arc_peak_to_valley`; it is low by
    :func:`parabola_error` (1.6 % at f = r / 2, 5 % at f = 0.87 r, 42 % at f = 1.975 r).

    Parameters
    ----------
    feed : float
        Feed per revolution f (m).
    nose_radius : float
        Tool nose radius r (m).
    end_relief_angle : float, optional
        End cutting-edge (relief) angle kappa_e (rad); when given, the validity condition
        ``f <= 2 r sin(kappa_e)`` of eq. (4.1) is checked (``f <= 2 r`` without it).

    Raises
    ------
    InputError
        For a feed above the limit (:func:`check_feed`).
    """
    f = check_feed(feed, nose_radius, end_relief_angle)
    return f * f / (8.0 * float(nose_radius))


def arc_peak_to_valley(feed, nose_radius) -> float:
    """Peak-to-valley height of circular feed marks, ``r - sqrt(r^2 - f^2/4)`` (m).

    The exact height of arcs of radius r every f (what :func:`turned_profile` cuts); r at
    ``f = 2 r``.

    Parameters
    ----------
    feed, nose_radius : float
        Feed per revolution f and tool nose radius r (m), ``f <= 2 r``.
    """
    f = check_feed(feed, nose_radius)
    r = float(nose_radius)
    return r - math.sqrt(max(r * r - f * f / 4.0, 0.0))


def parabola_error(feed, nose_radius) -> float:
    """How far eq. (4.1)'s ``f^2/(8 r)`` is below the arcs' height, relative to the arcs.

    ``1 - f^2/(8 r) / (r - sqrt(r^2 - f^2/4)) = (1 - sqrt(1 - f^2/(4 r^2))) / 2``, about
    ``f^2 / (16 r^2)`` for small feeds; 1/2 at ``f = 2 r``.

    Parameters
    ----------
    feed, nose_radius : float
        Feed per revolution f and tool nose radius r (m), ``f <= 2 r``.
    """
    f = check_feed(feed, nose_radius)
    ratio = min(f / (2.0 * float(nose_radius)), 1.0)
    return 0.5 * (1.0 - math.sqrt(1.0 - ratio * ratio))


def parabola_feed_limit(nose_radius, tolerance=PARABOLA_TOLERANCE) -> float:
    """The feed at which :func:`parabola_error` reaches ``tolerance``: ``4 r sqrt(t (1 - t))``
    (0.87 r at 5 %).

    Parameters
    ----------
    nose_radius : float
        Tool nose radius r (m).
    tolerance : float
        Relative error t of eq. (4.1), 0 < t <= 1/2.
    """
    t = check_positive("tolerance", tolerance)
    if t > 0.5:
        raise InputError("tolerance", "at most 1/2 (the parabola's error at f = 2 r)", t)
    return 4.0 * check_positive("nose_radius", nose_radius) * math.sqrt(t * (1.0 - t))


def _feed_mark_envelope(x, first_pass, feed, radius, offsets):
    """Lowest point of the tool nose arcs: ``min_k [offsets_k + r - sqrt(r^2 - (x - c_k)^2)]``.

    Pass k has its nose centre at axial position ``c_k = first_pass + k feed`` and is displaced
    by ``offsets_k`` (away from the workpiece positive). Metal lies below the result.
    """
    base = np.floor((x - first_pass) / feed).astype(int)
    reach = int(math.ceil(radius / feed)) + 1
    z = np.full(x.shape, np.inf)
    for j in range(-reach, reach + 1):
        k = base + j
        valid = (k >= 0) & (k < offsets.size)
        d = x - (first_pass + k * feed)
        # the arc's ends included (to round-off): at f = 2 r the cusps are the ends of two
        # arcs, covered by none if the ends were left out (heights of inf)
        inside = valid & (np.abs(d) <= radius * (1.0 + 1e-9))
        kk = np.clip(k, 0, offsets.size - 1)
        arc = offsets[kk] + radius - np.sqrt(np.maximum(radius**2 - d**2, 0.0))
        z = np.where(inside, np.minimum(z, arc), z)
    return z


def _first_pass(feed, radius):
    """Axial position of the first pass: a multiple of the feed, one nose radius before x = 0."""
    return -math.ceil(radius / feed) * feed


def turned_profile(feed, nose_radius, length, spacing, *, end_relief_angle=None) -> Profile:
    """Kinematic feed-mark profile of turning: circular arcs of radius r every feed f.

    Its peak-to-valley height is ``r - sqrt(r^2 - f^2/4)``, which eq. (4.1) approximates by
    ``f^2/(8 r)`` (relative error about f^2 / (16 r^2)). The nose centres (valleys) lie at the
    multiples of the feed, x = k f. Heights have zero mean; the profile is periodic when its
    length is a whole number of feeds.

    Parameters
    ----------
    feed, nose_radius : float
        Feed per revolution and tool nose radius (m).
    length, spacing : float
        Profile length and grid spacing along the workpiece axis (m).
    end_relief_angle : float, optional
        See :func:`kinematic_peak_to_valley`.
    """
    kinematic_peak_to_valley(feed, nose_radius, end_relief_angle)
    length = check_positive("length", length)
    spacing = check_positive("spacing", spacing)
    n = int(round(length / spacing))
    if n < 4:
        raise InputError("length", "at least 4 grid spacings", length)
    x = cell_centres(n, spacing)
    first = _first_pass(feed, nose_radius)
    passes = int(math.ceil((n * spacing - 2 * first) / feed)) + 2
    z = _feed_mark_envelope(x, first, feed, nose_radius, np.zeros(passes))
    turns = n * spacing / feed
    return Profile(x, z - z.mean(), periodic=abs(turns - round(turns)) < 1e-9 * turns)


@dataclass(frozen=True)
class TurnedSurface:
    """A turned profile generated with tool vibration (:func:`turned_profile_dynamic`).

    Attributes
    ----------
    profile : Profile
        Heights along the workpiece axis (m), zero mean.
    pass_positions : ndarray
        Axial positions of the nose centre at each revolution (m).
    pass_displacements : ndarray
        Tool displacement away from the workpiece at each pass (m), static deflection included.
    kinematic_rt : float
        f^2 / (8 r), the rigid-machine peak-to-valley roughness (m).
    static_deflection : float
        Mean cutting force / stiffness (m).
    spindle_speed : float
        Workpiece revolutions per second.
    mean_force : float
        Mean thrust force (N).
    stiffness, mass : float
        Of the tool assembly (N/m, kg).
    time_step : float
        Integration step (s).
    seed : int or None
    """

    profile: Profile
    pass_positions: np.ndarray
    pass_displacements: np.ndarray
    kinematic_rt: float
    static_deflection: float
    spindle_speed: float
    mean_force: float
    stiffness: float
    mass: float
    time_step: float
    seed: int | None


def _sdof_response(force, dt, omega, zeta, mass):
    """Displacement of ``m u'' + 2 zeta omega m u' + m omega^2 u = F`` from rest.

    Exact for a force held constant over each step (zero-order hold): the state transition
    ``exp(A dt)`` and input matrix ``int_0^dt exp(A s) ds B`` come from one matrix exponential
    of the augmented system; the recursion runs as the equivalent second-order IIR filter.
    """
    a = np.array([[0.0, 1.0], [-(omega**2), -2.0 * zeta * omega]])
    b = np.array([[0.0], [1.0 / mass]])
    aug = np.zeros((3, 3))
    aug[:2, :2], aug[:2, 2:] = a * dt, b * dt
    e = scipy.linalg.expm(aug)
    phi, gamma = e[:2, :2], e[:2, 2:]
    num, den = scipy.signal.ss2tf(phi, gamma, np.array([[1.0, 0.0]]), np.zeros((1, 1)))
    return scipy.signal.lfilter(num[0], den, force)


def turned_profile_dynamic(feed, nose_radius, depth_of_cut, cutting_speed, workpiece_diameter,
                           length, spacing, natural_frequency, *, damping_ratio=0.05, mass=None,
                           stiffness=None, specific_force=1.0e9, force_variation=0.2,
                           force_bandwidth=1000.0, seed=0) -> TurnedSurface:
    """Turned profile with feed marks displaced by tool vibration (after Jang & Seireg).

    What is modelled. The tool assembly is a damped single-degree-of-freedom oscillator in the
    direction normal to the machined surface, ``m u'' + c u' + k u = F(t)`` with natural
    frequency ``omega = 2 pi natural_frequency`` and damping ratio zeta; u > 0 moves the tool
    away from the workpiece. The thrust force is ``F = specific_force * feed * depth_of_cut *
    (1 + e(t))``: a mean proportional to the chip area plus a random part e(t), Gaussian with
    standard deviation ``force_variation``, held constant over intervals of
    ``1 / (2 force_bandwidth)`` (band-limited white noise). The cut starts at t = 0 with the
    tool at rest. The response is integrated exactly for the piecewise-constant force (see
    :func:`_sdof_response`), with at least 40 steps per natural period. The workpiece turns at
    ``cutting_speed / (pi workpiece_diameter)`` rev/s; along one generatrix, pass k leaves the
    arc of the nose radius centred at ``x_0 + k * feed`` (x_0 the multiple of the feed one nose
    radius before x = 0, where the tool starts), displaced by the tool position u(t_k) at
    that revolution, and the surface is the lowest envelope of all arcs (material removed by
    any pass stays removed). This is Seireg's description of Fig. 4.2: the tool edge displaced
    by the relative vibration, added to the kinematic roughness.

    What is assumed (the book gives no equations). Only the tool assembly vibrates (rigid
    workpiece and spindle); the force does not depend on the vibration (no regenerative chatter,
    no dependence on cutting speed); only the motion normal to the surface matters; the tool
    nose is a perfect arc and its flanks never cut. With fixed mass, a stiff, high-frequency
    tool barely moves and the kinematic feed-mark profile is recovered; the book reports this
    above about 150 Hz. ``specific_force`` (thrust force per chip area, default 1 GPa),
    ``force_variation`` and ``force_bandwidth`` are illustrative defaults, not fitted values.

    Parameters
    ----------
    feed, nose_radius, depth_of_cut : float
        Feed per revolution, tool nose radius, depth of cut (m).
    cutting_speed : float
        Surface speed of the workpiece (m/s), e.g. 61 m/min = 1.017 m/s in Fig. 4.2.
    workpiece_diameter : float
        Workpiece diameter (m), which sets the spindle speed.
    length, spacing : float
        Generated length along the workpiece axis and its grid spacing (m).
    natural_frequency : float
        Natural frequency of the tool assembly (Hz).
    damping_ratio : float
        Viscous damping ratio zeta (0 < zeta < 1).
    mass, stiffness : float
        Give exactly one: the modal mass (kg) or stiffness (N/m); the other follows from
        ``k = m omega^2``.
    specific_force, force_variation, force_bandwidth : float
        Thrust force per unit chip area (Pa), relative rms of the random force, its
        bandwidth (Hz).
    seed : int or None
        Seed of ``numpy.random.default_rng`` for the random force.
    """
    kinematic_rt = kinematic_peak_to_valley(feed, nose_radius)
    depth = check_positive("depth_of_cut", depth_of_cut)
    speed = check_positive("cutting_speed", cutting_speed)
    diameter = check_positive("workpiece_diameter", workpiece_diameter)
    length = check_positive("length", length)
    spacing = check_positive("spacing", spacing)
    fn = check_positive("natural_frequency", natural_frequency)
    zeta = check_positive("damping_ratio", damping_ratio)
    if zeta >= 1.0:
        raise InputError("damping_ratio", "an underdamped ratio 0 < zeta < 1", zeta)
    if (mass is None) == (stiffness is None):
        raise InputError("mass", "exactly one of mass and stiffness")
    omega = 2.0 * np.pi * fn
    if mass is not None:
        mass = check_positive("mass", mass)
        stiffness = mass * omega**2
    else:
        stiffness = check_positive("stiffness", stiffness)
        mass = stiffness / omega**2
    specific_force = check_positive("specific_force", specific_force)
    variation = check_positive("force_variation", force_variation, allow_zero=True)
    bandwidth = check_positive("force_bandwidth", force_bandwidth)
    n = int(round(length / spacing))
    if n < 4:
        raise InputError("length", "at least 4 grid spacings", length)

    revs_per_s = speed / (np.pi * diameter)
    period = 1.0 / revs_per_s
    first = _first_pass(feed, nose_radius)
    passes = int(math.ceil((n * spacing - 2 * first) / feed)) + 2
    steps_per_rev = int(math.ceil(period * max(40.0 * fn, 2.0 * bandwidth)))
    dt = period / steps_per_rev
    hold = max(1, int(round(1.0 / (2.0 * bandwidth * dt))))
    total = (passes - 1) * steps_per_rev + 1
    rng = np.random.default_rng(seed)
    noise = rng.standard_normal(-(-total // hold))[np.arange(total) // hold]  # held values
    mean_force = specific_force * feed * depth
    u = _sdof_response(mean_force * (1.0 + variation * noise), dt, omega, zeta, mass)
    offsets = u[:: steps_per_rev]

    x = cell_centres(n, spacing)
    z = _feed_mark_envelope(x, first, feed, nose_radius, offsets)
    return TurnedSurface(
        profile=Profile(x, z - z.mean()),
        pass_positions=first + feed * np.arange(offsets.size),
        pass_displacements=offsets,
        kinematic_rt=kinematic_rt,
        static_deflection=mean_force / stiffness,
        spindle_speed=revs_per_s,
        mean_force=mean_force,
        stiffness=stiffness,
        mass=mass,
        time_step=dt,
        seed=seed,
    )


def roughness_along(profile: Profile, window, parameter="Rt") -> tuple[np.ndarray, np.ndarray]:
    """A roughness parameter in consecutive windows along a profile (the curve of Fig. 4.2).

    Each window is referenced to its own mean, without removing a tilt: a least-squares line
    through a few feed marks cut at an arbitrary phase would tilt and inflate Rt.

    Parameters
    ----------
    profile : Profile
    window : float
        Window length (m), e.g. a few feeds; a trailing partial window is dropped.
    parameter : str
        A key of :func:`roughness_parameters` for a profile ("Ra", "Rt", "Rz", ...).

    Returns
    -------
    centres, values : ndarray
        Window centres (m) and the parameter in each window.
    """
    window = check_positive("window", window)
    per = int(round(window / profile.spacing))
    if per < 3 or per > profile.x.size:
        raise InputError("window", f"between 3 spacings and the profile length "
                                   f"({profile.length:.4g} m)", window)
    count = profile.x.size // per
    segments = profile.z[: count * per].reshape(count, per)
    xs = profile.x[: count * per].reshape(count, per)
    params = [roughness_parameters(s, periodic=True) for s in segments]
    if parameter not in params[0]:
        raise InputError("parameter", f"one of {', '.join(params[0])}", parameter)
    return xs.mean(axis=1), np.array([p[parameter] for p in params])
