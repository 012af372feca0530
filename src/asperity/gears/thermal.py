"""Blok's flash temperature of a sliding contact (moving band heat source, high Peclet number).

A band heat source of half-width ``a`` moving over a semi-infinite body at speed V with
Peclet number ``Pe = V a / (2 kappa) >> 1`` heats each surface point like a one-dimensional
transient conduction problem (Jaeger 1942; Carslaw & Jaeger, *Conduction of Heat in Solids*,
sec. 10.7; Blok 1937)::

    theta(x) = 1 / (B sqrt(pi V)) * integral_{-a}^{x} q(s) / sqrt(x - s) ds,   B = sqrt(k rho c)

For a uniform flux q the maximum (at the trailing edge) is
``theta_max = (2/sqrt(pi)) q sqrt(2a/V) / B = 1.128 q sqrt(2a/V) / B``; for a semi-elliptic flux
of the same mean q (a Hertzian pressure times a constant friction coefficient and sliding speed)
the maximum is ``1.1115 q sqrt(2a/V) / B``, at x = 0.652 a: Blok's constant 1.11. With the
heat shared between the surfaces so that their maximum temperatures are equal (Blok's
postulate) the flash temperature is::

    theta_fl = C q sqrt(2a) / (B1 sqrt(V1) + B2 sqrt(V2)),   q = mu p_mean |v_s|

(Blok's formula ``theta_fl = 1.11 mu w' |v_s| / ((B1 sqrt V1 + B2 sqrt V2) sqrt(2 a))``
with ``q = mu w' |v_s| / (2a)``). The contact temperature is the bulk temperature plus the
flash temperature.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import InputError, check_positive

__all__ = ["FLASH_CONSTANTS", "LOW_PECLET_OVERESTIMATE", "flash_temperature",
           "low_peclet_overestimate", "peclet_number", "thermal_contact_coefficient"]

#: theta_max B sqrt(V) / (q_mean sqrt(2a)) of a band source at high Peclet number: uniform
#: 2/sqrt(pi); semi-elliptic the maximum over x of the integral in the module notes (computed
#: once by adaptive quadrature, 1.11153; Blok's 1.11).
FLASH_CONSTANTS = {"uniform": 2.0 / math.sqrt(math.pi), "semi-elliptic": 1.11153}

#: How much the high-Peclet formula exceeds the maximum of Jaeger's exact moving band source
#: (one body, the K0 kernel of Carslaw & Jaeger sec. 10.7, integrated numerically) at
#: Pe = 5 .. 0.01, per source profile: a slow pair's Pe of 0.05 is an 81 % overestimate
#: (semi-elliptic), where the values at Pe 1 and 0.3 alone said 6 % and 22 %.
LOW_PECLET_OVERESTIMATE = {
    "semi-elliptic": {5.0: 0.004, 2.0: 0.023, 1.0: 0.063, 0.5: 0.137, 0.3: 0.222, 0.2: 0.311,
                      0.1: 0.519, 0.05: 0.810, 0.02: 1.364, 0.01: 1.952},
    "uniform": {5.0: 0.041, 2.0: 0.083, 1.0: 0.138, 0.5: 0.224, 0.3: 0.315, 0.2: 0.408,
                0.1: 0.622, 0.05: 0.921, 0.02: 1.491, 0.01: 2.097},
}


def low_peclet_overestimate(profile: str, peclet: float) -> float:
    """Relative overestimate of Blok's high-Peclet formula at Peclet number ``peclet``
    against Jaeger's exact band source, interpolated linearly in log Pe in
    :data:`LOW_PECLET_OVERESTIMATE` (held at its ends: 0.01 and 5)."""
    table = LOW_PECLET_OVERESTIMATE[profile]
    pe = sorted(table)
    return float(np.interp(math.log(peclet), np.log(pe), [table[v] for v in pe]))


def thermal_contact_coefficient(conductivity: float, density: float,
                                specific_heat: float) -> float:
    """B = sqrt(k rho c), W s^0.5 / (m^2 K) (steel: about 12 700)."""
    return math.sqrt(check_positive("conductivity", conductivity)
                     * check_positive("density", density)
                     * check_positive("specific_heat", specific_heat))


def peclet_number(speed, half_width, conductivity, density, specific_heat):
    """Pe = V a / (2 kappa), kappa = k / (rho c); the band formulas need Pe >> 1 (say > 5)."""
    kappa = conductivity / (density * specific_heat)
    return np.abs(np.asarray(speed, dtype=float)) * np.asarray(half_width) / (2.0 * kappa)


def flash_temperature(mean_heat_flux, half_width, speed1, speed2, coefficient1, coefficient2,
                      profile: str = "semi-elliptic"):
    """Maximum flash temperature rise by Blok's formula (module notes), K.

    Parameters
    ----------
    mean_heat_flux : array_like
        Mean frictional heat flux over the band, q = mu p_mean |v_s|, W/m^2.
    half_width : array_like
        Half-width a of the band along the motion (the Hertz semi-axis), m.
    speed1, speed2 : array_like
        Speeds of the two surfaces relative to the heat source, m/s (magnitudes are used).
    coefficient1, coefficient2 : float
        Thermal contact coefficients B = sqrt(k rho c) of the surfaces.
    profile : {"semi-elliptic", "uniform"}
        Shape of the heat flux over the band.

    Returns
    -------
    ndarray
        theta_fl, K; 0 where the flux is 0, NaN where it is NaN (unknown friction).
    """
    if profile not in FLASH_CONSTANTS:
        raise InputError("profile", '"semi-elliptic" or "uniform"', profile)
    b1 = check_positive("coefficient1", coefficient1)
    b2 = check_positive("coefficient2", coefficient2)
    q = np.asarray(mean_heat_flux, dtype=float)
    a = np.asarray(half_width, dtype=float)
    denominator = b1 * np.sqrt(np.abs(speed1)) + b2 * np.sqrt(np.abs(speed2))
    with np.errstate(invalid="ignore", divide="ignore"):
        theta = FLASH_CONSTANTS[profile] * q * np.sqrt(2.0 * a) / denominator
    return np.where(np.isnan(q), np.nan, np.where(q > 0, theta, 0.0))
