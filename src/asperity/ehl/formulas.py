"""Closed-form (curve-fitted) EHL film thickness of smooth, isothermal, Newtonian contacts.

Notation (SI): load ``w`` (N) or ``w'`` (N/m), radii of relative curvature ``rx`` (entrainment
direction) and ``ry``, mean entrainment speed ``u = (u1 + u2)/2``, ambient viscosity ``eta0``,
pressure-viscosity coefficient ``alpha``, reduced modulus ``E' = 2 E*`` (use
``2 * contact_modulus(body1, body2)``).

Hamrock-Dowson groups:  U = eta0 u / (E' rx),  G = alpha E',  W = w / (E' rx^2)
(W' = w' / (E' rx) for a line),  k = b/a from the exact Hertz solution.

Moes groups, with 2U = eta0 (u1 + u2) / (E' rx):  L = G (2U)^(1/4),
M = W (2U)^(-3/4) (point) or M = W' (2U)^(-1/2) (line), and the film H = h / (rx sqrt(2U)).

References
----------
B. J. Hamrock and D. Dowson, "Isothermal elastohydrodynamic lubrication of point contacts,
part III", J. Lubr. Technol. 99 (1977) 264-276.
D. Dowson and G. R. Higginson, *Elasto-hydrodynamic Lubrication*, 2nd ed., Pergamon, 1977.
H. Moes, "Optimum similarity analysis with applications to elastohydrodynamic lubrication",
Wear 159 (1992) 57-66.
R. J. Chittenden, D. Dowson, J. F. Dunn and C. M. Taylor, "A theoretical analysis of the
isothermal elastohydrodynamic lubrication of concentrated contacts. II. General case, with
lubricant entrainment along either principal axis", Proc. R. Soc. Lond. A 397 (1985) 271-294.
G. Nijenbanning, C. H. Venner and H. Moes, "Film thickness in elastohydrodynamically lubricated
elliptic contacts", Wear 176 (1994) 217-229.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import brentq

from ..contact.hertz import hertz_point
from ..errors import InputError, check_positive
from ..materials import Material

__all__ = [
    "FilmThickness",
    "HamrockDowsonGroups",
    "MoesGroups",
    "hamrock_dowson_groups",
    "moes_groups",
    "hamrock_dowson_point",
    "chittenden_point",
    "hamrock_dowson_soft_point",
    "brewe_hamrock_taylor_point",
    "martin_line",
    "rigid_mean_pressure",
    "flooded_inlet_distance",
    "starved_film_ratio",
    "flooded_film",
    "dowson_higginson_line",
    "moes_line",
    "moes_line_film",
    "moes_line_parts",
    "nijenbanning_point",
    "nijenbanning_film",
    "nijenbanning_parts",
]


@dataclass(frozen=True)
class FilmThickness:
    """A film-thickness estimate; a formula that does not give a value leaves it None."""

    central: float | None
    """Central film thickness, m."""
    minimum: float | None
    """Minimum film thickness, m."""
    formula: str
    """Name of the formula."""
    dimensionless: Mapping[str, float] = field(default_factory=dict)
    """The dimensionless groups and films the formula used."""


@dataclass(frozen=True)
class HamrockDowsonGroups:
    """Hamrock-Dowson groups U (speed), G (material), W (load) and ellipticity k = b/a."""

    U: float
    G: float
    W: float
    k: float


@dataclass(frozen=True)
class MoesGroups:
    """Moes groups M (load) and L (lubricant), and the film scale rx sqrt(2U) in m."""

    M: float
    L: float
    film_scale: float


def _common(rx, mean_speed, eta0, alpha, reduced_modulus, *, alpha_zero_ok):
    rx = check_positive("rx", rx)
    u = check_positive("mean_speed", mean_speed)
    eta0 = check_positive("eta0", eta0)
    alpha = check_positive("alpha", alpha, allow_zero=alpha_zero_ok)
    e = check_positive("reduced_modulus", reduced_modulus)
    if not (np.isfinite(rx) and np.isfinite(e)):
        raise InputError("rx, reduced_modulus", "finite values")
    return rx, u, eta0, alpha, e


def hamrock_dowson_groups(load, rx, ry, mean_speed, eta0, alpha, reduced_modulus):
    """Hamrock-Dowson dimensionless groups of a point (elliptical) contact.

    U = eta0 u / (E' rx), G = alpha E', W = w / (E' rx^2); k = b/a, the ratio of the Hertz
    semi-axes across and along the entrainment direction, from the exact elliptic-integral
    solution (:func:`asperity.contact.hertz_point`), not the fit k = 1.03 (ry/rx)^0.64.

    Parameters
    ----------
    load : float
        Normal load w, N.
    rx, ry : float
        Radii of relative curvature along and across the entrainment direction, m.
    mean_speed : float
        Mean entrainment speed u = (u1 + u2)/2, m/s.
    eta0 : float
        Viscosity at ambient pressure, Pa s.
    alpha : float
        Pressure-viscosity coefficient, 1/Pa.
    reduced_modulus : float
        E' = 2 E*, Pa.

    Returns
    -------
    HamrockDowsonGroups
    """
    rx, u, eta0, alpha, e = _common(
        rx, mean_speed, eta0, alpha, reduced_modulus, alpha_zero_ok=True
    )
    w = check_positive("load", load)
    ry = check_positive("ry", ry)
    # k depends on rx/ry only; any modulus will do (E* = E'/2 against a rigid body)
    hz = hertz_point(w, rx, ry, Material(0.5 * e, 0.0), Material(np.inf, 0.0))
    return HamrockDowsonGroups(
        U=eta0 * u / (e * rx), G=alpha * e, W=w / (e * rx * rx), k=float(hz.b / hz.a)
    )


def moes_groups(load, rx, mean_speed, eta0, alpha, reduced_modulus, *, line=False):
    """Moes dimensionless groups M and L.

    With 2U = eta0 (u1 + u2) / (E' rx) = 2 eta0 u / (E' rx):
    L = alpha E' (2U)^(1/4);  M = [w / (E' rx^2)] (2U)^(-3/4) for a point contact, or
    M = [w' / (E' rx)] (2U)^(-1/2) for a line contact (``line=True``, load per unit length).
    These are the seed's "Moes and Bosma" groups, L = alpha E' (2 eta0 u / E' R)^(1/4) and
    M = (w / E' R^2) (E' R / 2 eta0 u)^(3/4).

    Returns
    -------
    MoesGroups
        M, L and the film scale rx sqrt(2U) (m) that turns a dimensionless film H into h.
    """
    rx, u, eta0, alpha, e = _common(
        rx, mean_speed, eta0, alpha, reduced_modulus, alpha_zero_ok=True
    )
    w = check_positive("load_per_length" if line else "load", load)
    two_u = 2.0 * eta0 * u / (e * rx)
    if line:
        m = w / (e * rx) * two_u**-0.5
    else:
        m = w / (e * rx * rx) * two_u**-0.75
    return MoesGroups(M=m, L=alpha * e * two_u**0.25, film_scale=rx * two_u**0.5)


def hamrock_dowson_point(load, rx, ry, mean_speed, eta0, alpha, reduced_modulus):
    """Hamrock-Dowson (1977) central and minimum film of an elliptical contact.

    Hc = hc/rx = 2.69 U^0.67 G^0.53 W^-0.067 (1 - 0.61 exp(-0.73 k)),
    Hmin = hmin/rx = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68 k)),
    groups from :func:`hamrock_dowson_groups`. Fitted to piezoviscous-elastic solutions for
    1 <= k <= 8 (entrainment along the minor axis, ``ry >= rx``).

    Parameters are those of :func:`hamrock_dowson_groups`; ``alpha`` must be > 0.

    Returns
    -------
    FilmThickness
        ``central`` and ``minimum`` in m.
    """
    check_positive("alpha", alpha)
    g = hamrock_dowson_groups(load, rx, ry, mean_speed, eta0, alpha, reduced_modulus)
    hc = 2.69 * g.U**0.67 * g.G**0.53 * g.W**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * g.k))
    hm = 3.63 * g.U**0.68 * g.G**0.49 * g.W**-0.073 * (1.0 - np.exp(-0.68 * g.k))
    rx = float(rx)
    return FilmThickness(
        central=float(hc * rx),
        minimum=float(hm * rx),
        formula="Hamrock-Dowson",
        dimensionless={"U": g.U, "G": g.G, "W": g.W, "k": g.k, "Hc": float(hc), "Hmin": float(hm)},
    )


def hamrock_dowson_soft_point(load, rx, ry, mean_speed, eta0, reduced_modulus):
    """Hamrock & Dowson's (1978) isoviscous-elastic ("soft EHL") central and minimum film of
    an elliptical contact of a material of low elastic modulus.

    Hc = hc/rx = 7.32 (1 - 0.72 exp(-0.28 k)) U^0.64 W^-0.22,
    Hmin = hmin/rx = 7.43 (1 - 0.85 exp(-0.31 k)) U^0.65 W^-0.21,
    groups from :func:`hamrock_dowson_groups` (the viscosity taken constant, so no G).
    Fitted to their solutions for 1 <= k <= 12 (entrainment along the minor axis) with
    E' of a few to tens of MPa; B. J. Hamrock and D. Dowson, "Elastohydrodynamic lubrication
    of elliptical contacts for materials of low elastic modulus I -- fully flooded
    conjunction", J. Lubr. Technol. 100 (1978) 236-245.

    Parameters are those of :func:`hamrock_dowson_groups` without ``alpha``.

    Returns
    -------
    FilmThickness
        ``central`` and ``minimum`` in m.
    """
    g = hamrock_dowson_groups(load, rx, ry, mean_speed, eta0, 0.0, reduced_modulus)
    hc = 7.32 * (1.0 - 0.72 * np.exp(-0.28 * g.k)) * g.U**0.64 * g.W**-0.22
    hm = 7.43 * (1.0 - 0.85 * np.exp(-0.31 * g.k)) * g.U**0.65 * g.W**-0.21
    rx = float(rx)
    return FilmThickness(
        central=float(hc * rx),
        minimum=float(hm * rx),
        formula="Hamrock-Dowson (soft EHL)",
        dimensionless={"U": g.U, "W": g.W, "k": g.k, "Hc": float(hc), "Hmin": float(hm)},
    )


def brewe_hamrock_taylor_point(load, rx, ry, mean_speed, eta0, reduced_modulus):
    """Brewe, Hamrock & Taylor's (1979) rigid-isoviscous minimum film of an elliptical contact
    (Reynolds exit condition; Kapitza's solution corrected to their numerical ones).

    Hmin = hmin/rx = 128 ar lam^2 [0.131 atan(ar/2) + 1.683]^2 (U/W)^2, with ``ar = ry/rx``,
    ``lam = 1/(1 + 2/(3 ar))`` and the groups of :func:`hamrock_dowson_groups`; a rigid
    contact's least film is its central one. Checked against a rigid ball's Reynolds
    equation solved here on square domains of half-width S = 8, 16, 32 times
    sqrt(2 rx h0) (its load falls short of the unbounded one as 1 - 1.6/S): the film
    extrapolated to an unbounded domain is 18.0 um where the formula gives 17.9 um
    (docs/ehl-robustness.md, "A nearly rigid contact"). B. J. Brewe, B. J. Hamrock and
    C. M. Taylor, "Effect of geometry on hydrodynamic film thickness", J. Lubr. Technol. 101
    (1979) 231-239.

    Parameters are those of :func:`hamrock_dowson_groups` without ``alpha``.

    Returns
    -------
    FilmThickness
        ``central`` and ``minimum`` (equal) in m.
    """
    g = hamrock_dowson_groups(load, rx, ry, mean_speed, eta0, 0.0, reduced_modulus)
    ar = float(ry) / float(rx)
    lam = 1.0 / (1.0 + 2.0 / (3.0 * ar))
    hm = 128.0 * ar * lam**2 * (0.131 * np.arctan(ar / 2.0) + 1.683) ** 2 * (g.U / g.W) ** 2
    h = float(hm * float(rx))
    return FilmThickness(central=h, minimum=h, formula="Brewe-Hamrock-Taylor",
                         dimensionless={"U": g.U, "W": g.W, "Hmin": float(hm)})


def rigid_mean_pressure(load, rx, film):
    """Pressure scale of a nearly rigid point contact, Pa: the load over the disc of radius
    ``l = sqrt(2 rx h)`` over which its pressure builds up, ``w / (2 pi rx h)``.

    The Hertz pressure does not measure such a contact: a glass ball in glycerol (R = 10 mm,
    0.5 N, 0.1 m/s) has p_h = 109 MPa and a film pressure of 0.46 MPa at its peak (the rigid
    ball's Reynolds equation solved in docs/ehl-robustness.md: ``p_max = 0.0707 x 12 eta u l /
    h^2``); this scale gives 0.72 MPa, above the peak, so that ``alpha`` times it is a safe
    test of whether the viscosity rises.

    Parameters
    ----------
    load : float
        Normal load w, N.
    rx : float
        Radius of relative curvature along the entrainment direction, m.
    film : float
        Film thickness h (e.g. Brewe, Hamrock & Taylor's, :func:`brewe_hamrock_taylor_point`), m.
    """
    return check_positive("load", load) / (
        2.0 * np.pi * check_positive("rx", rx) * check_positive("film", film))


def martin_line(load_per_length, radius, mean_speed, eta0):
    """Martin's (1916) rigid-isoviscous film of a line contact with the Reynolds (Swift-Stieber)
    exit condition: ``h0 = 4.895 eta0 u R / w'``, ``u`` the mean speed; the exit lies at
    ``x = 0.4751 sqrt(2 R h0)``. The constant is ``24 C`` with C the load integral of the
    Swift-Stieber pressure, integrated in tests/test_ehl_formulas.py
    (``test_moes_rigid_asymptotes_against_exact_rigid_line_solutions``). A rigid contact's
    least film is its central one.

    Returns
    -------
    FilmThickness
        ``central`` and ``minimum`` (equal) in m.
    """
    w = check_positive("load_per_length", load_per_length)
    h = 4.895 * check_positive("eta0", eta0) * check_positive("mean_speed", mean_speed) \
        * check_positive("radius", radius) / w
    return FilmThickness(central=float(h), minimum=float(h), formula="Martin")


def chittenden_point(load, rx, ry, mean_speed, eta0, alpha, reduced_modulus):
    """Chittenden, Dowson, Dunn & Taylor (1985) central and minimum film, either axis.

    Hc = hc/rx = 4.31 U^0.68 G^0.49 W^-0.073 [1 - exp(-1.23 (ry/rx)^(2/3))],
    Hmin = hmin/rx = 3.68 U^0.68 G^0.49 W^-0.073 [1 - exp(-0.67 (ry/rx)^(2/3))],
    with the Hamrock-Dowson groups on the radius ``rx`` along the entrainment direction
    (:func:`hamrock_dowson_groups`). Fitted to solutions with entrainment along either
    principal axis, ``ry/rx`` from about 1/50 to 50, so it covers ``k = b/a < 1`` (entrainment
    along the major axis), which Hamrock-Dowson does not. Transcribed from the secondary
    literature (Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film Lubrication*, 2004).
    Where both fits apply (``ry >= rx``) it agrees with Hamrock-Dowson's central film within
    5 % and its minimum film within 2 % on the gear case, ry/rx = 1 to 30 (1.4 % and 0.3 % at
    ry = rx); the central-film gap depends on U, G, W (the exponents differ): 5.5 % at
    W = 100 N, u = 0.5 m/s, ry = rx = 10 mm.

    Parameters are those of :func:`hamrock_dowson_groups`; ``alpha`` must be > 0.

    Returns
    -------
    FilmThickness
        ``central`` and ``minimum`` in m.
    """
    check_positive("alpha", alpha)
    g = hamrock_dowson_groups(load, rx, ry, mean_speed, eta0, alpha, reduced_modulus)
    ratio = (float(ry) / float(rx)) ** (2.0 / 3.0)
    base = g.U**0.68 * g.G**0.49 * g.W**-0.073
    hc = 4.31 * base * (1.0 - np.exp(-1.23 * ratio))
    hm = 3.68 * base * (1.0 - np.exp(-0.67 * ratio))
    return FilmThickness(
        central=float(hc * rx),
        minimum=float(hm * rx),
        formula="Chittenden et al.",
        dimensionless={"U": g.U, "G": g.G, "W": g.W, "k": g.k, "Hc": float(hc), "Hmin": float(hm)},
    )


def flooded_inlet_distance(film, stretch=1.0):
    """Hamrock & Dowson's (1977, part IV) fully flooded inlet distance of a point contact.

    ``m* = 1 + 3.06 H^0.58`` in Hertz semi-axes ``a`` upstream of the centre, with
    ``H = (Rx/a)^2 hc/Rx = hc Rx/a^2`` the central film in Hertzian units; an inlet at
    ``m < m*`` starves the film. ``stretch`` counts the inlet length ``m* - 1`` that many
    times: ``1 + stretch (m* - 1)``.
    """
    return 1.0 + stretch * 3.06 * film**0.58


def starved_film_ratio(film, m):
    """Hamrock & Dowson's (1977, part IV) starved over fully flooded central film of a point
    contact whose inlet meniscus lies ``m`` Hertz semi-axes upstream of the centre:
    ``((m - 1)/(m* - 1))^0.29`` for ``1 < m < m*``, 1 for ``m >= m*``, with ``m*`` the fully
    flooded inlet distance (:func:`flooded_inlet_distance`) of the fully flooded central
    ``film`` in Hertzian units ``H = hc Rx/a^2``.
    """
    m_star = flooded_inlet_distance(film)
    return 1.0 if m >= m_star else ((m - 1.0) / (m_star - 1.0)) ** 0.29


def flooded_film(starved, m):
    """The fully flooded central film ``H`` (Hertzian units ``hc Rx/a^2``) whose starved film
    at an inlet ``m`` semi-axes upstream is ``starved`` by Hamrock & Dowson's fit
    (:func:`starved_film_ratio`): the root of ``H ratio(H, m) = starved``.

    The fit's ``m*`` is that of the flooded film. A solve on a short inlet gives the starved
    one, and the ``m*`` of the starved film is the shorter: set into the fit, a 6206
    bearing's contact (Rx 3.9 mm, 450 N, inlet at -1.5 a) gave a loss of 4.6 % instead of
    5.5 % (the solver's own loss there is 9.6 % against -2.5 a, docs/ehl-robustness.md).
    ``H ratio(H, m)`` grows with ``H`` (as ``H^0.83`` below ``m*``), so the root is unique.
    """
    starved = check_positive("starved", starved)
    if not m > 1.0:
        raise InputError("m", "an inlet upstream of the Hertz zone, m > 1", m)
    hi = starved
    while hi * starved_film_ratio(hi, m) < starved:
        hi *= 2.0
    if hi == starved:
        return float(starved)
    return float(brentq(lambda h: h * starved_film_ratio(h, m) - starved, hi / 2.0, hi,
                        xtol=1e-12 * hi, rtol=1e-12))


def dowson_higginson_line(load_per_length, radius, mean_speed, eta0, alpha, reduced_modulus):
    """Dowson-Higginson (1977) minimum film of a line contact.

    Hmin = hmin/R = 2.65 U^0.70 G^0.54 W'^-0.13 with U = eta0 u/(E' R), G = alpha E',
    W' = w'/(E' R).

    Parameters
    ----------
    load_per_length : float
        w', N/m.
    radius : float
        Radius of relative curvature R along the entrainment direction, m.
    mean_speed, eta0, alpha, reduced_modulus : float
        As in :func:`hamrock_dowson_groups`; ``alpha`` > 0.

    Returns
    -------
    FilmThickness
        ``minimum`` in m (``central`` is None).
    """
    r, u, eta0, alpha, e = _common(
        radius, mean_speed, eta0, alpha, reduced_modulus, alpha_zero_ok=False
    )
    w = check_positive("load_per_length", load_per_length)
    U, G, W = eta0 * u / (e * r), alpha * e, w / (e * r)
    hm = 2.65 * U**0.70 * G**0.54 * W**-0.13
    return FilmThickness(
        central=None,
        minimum=float(hm * r),
        formula="Dowson-Higginson",
        dimensionless={"U": U, "G": G, "W": W, "Hmin": hm},
    )


def _power_mean(a, b, q):
    """(a^q + b^q)^(1/q) for a, b >= 0; for q < 0 a zero argument gives 0."""
    with np.errstate(divide="ignore"):
        return (a**q + b**q) ** (1.0 / q)


def moes_line_parts(M, L):
    """The isoviscous and piezoviscous parts of Moes' (1992) line-contact fit.

    Asymptotes (rigid-isoviscous, elastic-isoviscous, rigid-piezoviscous,
    elastic-piezoviscous)::

        H_RI = 3 M^-1,  H_EI = 2.621 M^-1/5,  H_RP = 1.287 L^2/3,  H_EP = 1.311 M^-1/8 L^3/4

    ``iso = (H_RI^7/3 + H_EI^7/3)^(3/7)``, ``piezo = (H_RP^-7/2 + H_EP^-7/2)^(-2/7)`` and the
    exponent ``s = (7 + 8 exp(-2 H_EI / H_RI)) / 5`` of ``H = (iso^s + piezo^s)^(1/s)``
    (:func:`moes_line_film`; Moes 1992, as quoted by Venner & Lubrecht, *Multilevel Methods
    in Lubrication*, 2000).

    Parameters
    ----------
    M, L : array_like
        Moes groups (M > 0, L >= 0).

    Returns
    -------
    tuple of ndarray
        ``(h_ri, h_ei, iso, piezo, s)``.
    """
    M = np.asarray(M, dtype=float)
    L = np.asarray(L, dtype=float)
    h_ri = 3.0 / M
    h_ei = 2.621 * M**-0.2
    h_rp = 1.287 * L ** (2.0 / 3.0)
    h_ep = 1.311 * M**-0.125 * L**0.75
    s = (7.0 + 8.0 * np.exp(-2.0 * h_ei / h_ri)) / 5.0
    return h_ri, h_ei, _power_mean(h_ri, h_ei, 7.0 / 3.0), _power_mean(h_rp, h_ep, -3.5), s


def moes_line_film(M, L):
    """Moes' central film H = hc / (R sqrt(2U)) of a line contact, from M and L.

    ``H = [(H_RI^7/3 + H_EI^7/3)^(3s/7) + (H_RP^-7/2 + H_EP^-7/2)^(-2s/7)]^(1/s)`` with the
    asymptotes and ``s`` of :func:`moes_line_parts`.

    Parameters
    ----------
    M, L : array_like
        As :func:`moes_line_parts`.

    Returns
    -------
    ndarray
        H.
    """
    _, _, iso, piezo, s = moes_line_parts(M, L)
    return (iso**s + piezo**s) ** (1.0 / s)


def moes_line(load_per_length, radius, mean_speed, eta0, alpha, reduced_modulus):
    """Central film of a line contact by Moes' formula (:func:`moes_line_film`).

    Parameters are those of :func:`dowson_higginson_line`; ``alpha`` may be 0 (isoviscous).

    Returns
    -------
    FilmThickness
        ``central`` in m, with M, L, H, the rigid- and elastic-isoviscous asymptotes ``H_RI``,
        ``H_EI`` and the fit's two parts ``H_iso``, ``H_piezo`` (:func:`moes_line_parts`).
    """
    g = moes_groups(load_per_length, radius, mean_speed, eta0, alpha, reduced_modulus, line=True)
    h = float(moes_line_film(g.M, g.L))
    h_ri, h_ei, iso, piezo, _ = moes_line_parts(g.M, g.L)
    return FilmThickness(
        central=h * g.film_scale,
        minimum=None,
        formula="Moes",
        dimensionless={"M": g.M, "L": g.L, "H": h, "H_RI": float(h_ri), "H_EI": float(h_ei),
                       "H_iso": float(iso), "H_piezo": float(piezo)},
    )


def nijenbanning_parts(M, L, D):
    """The isoviscous and piezoviscous parts of Nijenbanning, Venner & Moes' (1994) fit.

    With the curvature ratio D = rx/ry (0 < D <= 1) and c(D) = 1 + 0.006 ln D + 0.63 D^(4/7)::

        H_RI = 145 (1 + 0.796 D^(14/15))^(-15/7) D^-1 M^-2
        H_EI = 3.18 c^(-14/25) D^(-1/15) M^(-2/15)
        H_RP = 1.29 (1 + 0.691 D)^(-2/3) L^(2/3)
        H_EP = 1.48 c^(-7/20) D^(-1/24) M^(-1/12) L^(3/4)
        s = 1.5 (1 + exp(-1.2 H_EI / H_RI)),  H_00 = 1.8 D^-1
        iso = [H_RI^(3/2) + (H_EI^-4 + H_00^-4)^(-3/8)]^(2/3)
        piezo = (H_RP^-8 + H_EP^-8)^(-1/8)

    and the fit is ``H = (iso^s + piezo^s)^(1/s)`` (:func:`nijenbanning_film`). Where the two
    parts are of a size the sum exceeds either; the rigid-isoviscous term grows as 1/D, so a
    wide ellipse (D small) at low M has them so (docs/ehl-robustness.md, "Nijenbanning's fit
    where its two parts meet").

    Parameters
    ----------
    M, L : array_like
        Moes point-contact groups (:func:`moes_groups`).
    D : array_like
        rx / ry, in (0, 1].

    Returns
    -------
    tuple of ndarray
        ``(h_ri, h_ei00, iso, piezo, s)``: the rigid-isoviscous asymptote ``H_RI``, the
        elastic-isoviscous term ``H_EI00 = (H_EI^-4 + H_00^-4)^(-1/4)`` it is added to in
        ``iso = (H_RI^(3/2) + H_EI00^(3/2))^(2/3)``, the two parts and the exponent.
    """
    M = np.asarray(M, dtype=float)
    L = np.asarray(L, dtype=float)
    D = np.asarray(D, dtype=float)
    c = 1.0 + 0.006 * np.log(D) + 0.63 * D ** (4.0 / 7.0)
    h_ri = 145.0 * (1.0 + 0.796 * D ** (14.0 / 15.0)) ** (-15.0 / 7.0) / D * M**-2.0
    h_ei = 3.18 * c ** (-14.0 / 25.0) * D ** (-1.0 / 15.0) * M ** (-2.0 / 15.0)
    h_rp = 1.29 * (1.0 + 0.691 * D) ** (-2.0 / 3.0) * L ** (2.0 / 3.0)
    h_ep = 1.48 * c ** (-7.0 / 20.0) * D ** (-1.0 / 24.0) * M ** (-1.0 / 12.0) * L**0.75
    s = 1.5 * (1.0 + np.exp(-1.2 * h_ei / h_ri))
    h_ei00 = _power_mean(h_ei, 1.8 / D, -4.0)
    iso = _power_mean(h_ri, h_ei00, 1.5)
    piezo = _power_mean(h_rp, h_ep, -8.0)
    return h_ri, h_ei00, iso, piezo, s


def nijenbanning_film(M, L, D):
    """Nijenbanning, Venner & Moes (1994) central film H = hc / (rx sqrt(2U)), elliptic contact.

    ``H = { [H_RI^(3/2) + (H_EI^-4 + H_00^-4)^(-3/8)]^(2s/3) + (H_RP^-8 + H_EP^-8)^(-s/8) }^(1/s)``
    with the asymptotes and ``s`` of :func:`nijenbanning_parts`.

    The isoviscous bracket is raised to ``2s/3``, in the same pattern as Moes' line formula,
    so that H -> H_RI as M -> 0 at L = 0. The transcription in REFERENCE.md (inner powers
    ``3s/2``, ``-3s/8`` and outer ``2/(3s)``) gives H -> H_RI^(1/3) instead, i.e. it fails the
    rigid-isoviscous limit by orders of magnitude, and is not used.

    Parameters
    ----------
    M, L, D : array_like
        As :func:`nijenbanning_parts`: the Moes groups and rx / ry.

    Returns
    -------
    ndarray
        H.
    """
    _, _, iso, piezo, s = nijenbanning_parts(M, L, D)
    return (iso**s + piezo**s) ** (1.0 / s)


def nijenbanning_point(load, rx, ry, mean_speed, eta0, alpha, reduced_modulus):
    """Central film of an elliptical contact by Nijenbanning's formula (:func:`nijenbanning_film`).

    Parameters are those of :func:`hamrock_dowson_groups`, with ``ry >= rx`` (entrainment
    along the minor axis) and ``alpha`` >= 0.

    Returns
    -------
    FilmThickness
        ``central`` in m, with M, L, D, H, the rigid-isoviscous asymptote ``H_RI``, the
        elastic-isoviscous term ``H_EI00`` it is added to, and the fit's two parts ``H_iso``,
        ``H_piezo`` (:func:`nijenbanning_parts`).
    """
    rx = check_positive("rx", rx)
    ry = check_positive("ry", ry)
    if ry < rx:
        raise InputError("ry", f"ry >= rx = {rx} m (the fit covers D = rx/ry <= 1)", ry)
    g = moes_groups(load, rx, mean_speed, eta0, alpha, reduced_modulus)
    d = rx / ry
    h = float(nijenbanning_film(g.M, g.L, d))
    h_ri, h_ei00, iso, piezo, _ = nijenbanning_parts(g.M, g.L, d)
    return FilmThickness(
        central=h * g.film_scale,
        minimum=None,
        formula="Nijenbanning",
        dimensionless={"M": g.M, "L": g.L, "D": d, "H": h, "H_RI": float(h_ri),
                       "H_EI00": float(h_ei00),
                       "H_iso": float(iso), "H_piezo": float(piezo)},
    )
