"""Transverse-ground profiles, fresh and run-in, and the built-in profiles A, B, C.

A ground finish is modelled as a Gaussian random profile along the rolling direction x (grinding
marks run across it, along y; use :meth:`Profile.extrude` for the surface). As-ground surfaces
have a near-Gaussian height distribution; running-in flattens and rounds the asperity tips,
which skews the height distribution negatively (mixed-EHL seed, "Analysis of Mixed Lubrication
Effects in Simulated Gear Tooth Contacts", Holmes, Evans & Snidle, J. Tribol. 2005).
Running-in is modelled by a smooth truncation of the peaks::

    z_run_in = c - w log(1 + exp((c - z) / w))

(a soft minimum of z and the plateau level c, with rounding width w = 0.25 Rq), where c is the
height exceeded by the fraction ``run_in`` of the fresh profile. The profile is then shifted to
zero mean and scaled so that its Ra about the mean -- as
:func:`~asperity.surfaces.roughness_parameters` computes it for the periodic profile -- equals
the target exactly.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError, check_positive
from .generate import gaussian_profile
from .topography import Profile

__all__ = ["BUILTIN_PROFILES", "GROUND_CORRELATION_LENGTH", "builtin_profile",
           "transverse_ground_profile"]

#: Rounding width of the run-in truncation, in units of the fresh profile's Rq.
ROUNDING = 0.25

#: Default autocorrelation length of a transverse-ground profile, m.
GROUND_CORRELATION_LENGTH = 15e-6


def transverse_ground_profile(length, spacing, ra,
                              correlation_length=GROUND_CORRELATION_LENGTH, *, run_in=0.0,
                              seed=0) -> Profile:
    """Synthetic transverse-ground profile with an exact Ra, optionally run-in.

    Parameters
    ----------
    length, spacing : float
        Profile length and grid spacing (m).
    ra : float
        Target arithmetic mean roughness Ra (m), met exactly.
    correlation_length : float
        Lag (m) at which the autocorrelation of the fresh profile (Gaussian ACF) falls to 0.2.
    run_in : float
        Fraction 0 <= run_in < 1 of the fresh profile lying above the plateau level; 0 gives
        the fresh (Gaussian) ground profile, larger values flatter, more negatively skewed
        profiles with rounded tips.
    seed : int or None
        Seed of ``numpy.random.default_rng``.

    Returns
    -------
    Profile
        Periodic profile on cell centres starting at ``spacing / 2``.
    """
    ra = check_positive("ra", ra)
    run_in = float(run_in)
    if not 0.0 <= run_in < 1.0:
        raise InputError("run_in", "a fraction 0 <= run_in < 1", run_in)
    fresh = gaussian_profile(length, spacing, 1.0, correlation_length, seed=seed)
    z = fresh.z
    if run_in > 0.0:
        width = ROUNDING * np.sqrt(np.mean(z**2))
        level = np.quantile(z, 1.0 - run_in)
        z = level - width * np.logaddexp(0.0, (level - z) / width)
    z = z - z.mean()
    z *= ra / np.mean(np.abs(z))
    return fresh.with_heights(z)


#: Synthetic stand-ins for the measured traces A, B, C of the mixed-EHL seed (Holmes, Evans &
#: Snidle 2005, Fig. 1), which are not public: Ra from the paper; correlation length and run-in
#: chosen so that C has the sharpest asperities (largest rms slope), A is the most run-in
#: (smallest slopes, most negative skew) and B lies between. Fixed seeds.
BUILTIN_PROFILES = {
    "A": {"ra": 0.32e-6, "correlation_length": 25e-6, "run_in": 0.5, "seed": 101},
    "B": {"ra": 0.22e-6, "correlation_length": 12e-6, "run_in": 0.3, "seed": 102},
    "C": {"ra": 0.31e-6, "correlation_length": 6e-6, "run_in": 0.1, "seed": 103},
}


def builtin_profile(name: str, length=5e-3, spacing=0.5e-6) -> Profile:
    """One of the built-in transverse-ground profiles "A", "B", "C".

    These are SYNTHETIC stand-ins for the measured profiles of the mixed-EHL seed (the traces
    are not published as data): Ra 0.32, 0.22 and 0.31 um; A a well run-in transverse-ground
    disk (smallest slopes, most negative skew), B and C run-in gear profiles with larger
    asperities, C the most aggressive (sharpest asperities, largest rms slope). Each is
    reproducible: the realisation depends only on (name, length, spacing).

    Parameters
    ----------
    name : {"A", "B", "C"}
    length, spacing : float
        Profile length and grid spacing (m); defaults 5 mm and 0.5 um.
    """
    key = str(name).strip().upper()
    if key not in BUILTIN_PROFILES:
        raise InputError("name", f"one of {', '.join(BUILTIN_PROFILES)}", name)
    return transverse_ground_profile(length, spacing, **BUILTIN_PROFILES[key])
