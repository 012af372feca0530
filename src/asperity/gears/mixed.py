"""Specific film thickness lambda and the friction of a partly boundary-lubricated contact.

``lambda = h_min / sigma`` with the composite roughness ``sigma = sqrt(s1^2 + s2^2)`` of the
two surfaces' Rq (or Ra) values ("rss"), or their mean ``(s1 + s2)/2`` as in ISO/TR 15144-1
("mean", with Ra).

Friction: the load share carried by asperity contact, ``f``, falls linearly from 1 at
``lambda <= lambda_b`` to 0 at ``lambda >= lambda_f`` (defaults 1 and 3, the classical limits of
boundary and full-film lubrication, e.g. Hamrock, Schmid & Jacobson, *Fundamentals of Machine
Elements*, ch. 8); the friction coefficient is ``mu = (1 - f) mu_EHL + f mu_b`` with mu_EHL the
smooth EHL traction (Eyring) and mu_b a boundary friction coefficient. This load-sharing rule
is an engineering assumption stated as such, not a model of the asperity contacts.
"""

from __future__ import annotations

import numpy as np

from ..errors import InputError, check_positive

__all__ = ["asperity_share", "composite_roughness", "mixed_friction"]


def composite_roughness(s1: float, s2: float, rule: str = "rss") -> float:
    """Composite roughness of two surfaces: "rss" sqrt(s1^2 + s2^2) or "mean" (s1 + s2)/2, m."""
    s1 = check_positive("roughness1", s1, allow_zero=True)
    s2 = check_positive("roughness2", s2, allow_zero=True)
    if rule == "rss":
        return float(np.hypot(s1, s2))
    if rule == "mean":
        return 0.5 * (s1 + s2)
    raise InputError("combination", '"rss" or "mean"', rule)


def asperity_share(specific_film, boundary_lambda: float = 1.0, full_film_lambda: float = 3.0):
    """Share f of the load carried by asperities: 1 below ``boundary_lambda``, 0 above
    ``full_film_lambda``, linear in lambda between."""
    lo = check_positive("boundary_lambda", boundary_lambda, allow_zero=True)
    hi = check_positive("full_film_lambda", full_film_lambda)
    if not hi > lo:
        raise InputError("full_film_lambda", f"a value above boundary_lambda = {lo}", hi)
    lam = np.asarray(specific_film, dtype=float)
    return np.clip((hi - lam) / (hi - lo), 0.0, 1.0)


def mixed_friction(ehl_friction, boundary_friction: float, share):
    """mu = (1 - f) mu_EHL + f mu_b.

    Parameters
    ----------
    ehl_friction : array_like
        EHL traction coefficient mu_EHL; NaN where it is unknown (a Newtonian film).
    boundary_friction : float
        Boundary friction coefficient mu_b.
    share : array_like
        Asperity load share f in [0, 1].

    Returns
    -------
    ndarray
        mu; where f = 1 it is mu_b even if mu_EHL is NaN (the film carries nothing there),
        elsewhere NaN with mu_EHL.
    """
    mu_b = check_positive("boundary_friction", boundary_friction, allow_zero=True)
    f = np.asarray(share, dtype=float)
    mixed = (1.0 - f) * np.asarray(ehl_friction, dtype=float) + f * mu_b
    return np.where(f >= 1.0, mu_b, mixed)
