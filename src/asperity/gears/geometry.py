"""Involute geometry of a spur or helical gear pair, external or internal, and its path of
contact (ISO 21771).

All lengths in m, angles in rad. Subscript 1 is the pinion (the driving gear), 2 the wheel.
The relations (ISO 21771:2007, clauses 4 and 5; the same as in any gear textbook)::

    alpha_t = atan(tan alpha_n / cos beta)              transverse pressure angle
    m_t = m_n / cos beta,  d = z m_t,  d_b = d cos alpha_t
    beta_b = asin(sin beta cos alpha_n)                 base helix angle
    inv alpha_wt = inv alpha_t + 2 tan alpha_n (x1 + x2) / (z1 + z2)   (no backlash)
    a_w = (d1 + d2) cos alpha_t / (2 cos alpha_wt)      centre distance from the shifts
    j_bn = 2 a_w (inv alpha_wt - inv alpha_wt0) cos alpha_wt cos beta_b
                                                        normal backlash at a given a_w
    d_a = d + 2 m_n (1 + x + k),  k = min(0, (a_w - a_0)/m_n - (x1 + x2))   tip alteration

The path of contact lies on the line of action T1-T2 (length ``a_w sin alpha_wt`` between the
points of tangency with the base circles). Positions on it are distances ``rho1`` from T1, which
are also the transverse radii of curvature of the pinion flank (``rho2 = T1T2 - rho1``)::

    A: rho1 = T1T2 - sqrt(r_a2^2 - r_b2^2)   start of contact (wheel tip)
    E: rho1 = sqrt(r_a1^2 - r_b1^2)          end of contact (pinion tip)
    C: rho1 = r_b1 tan alpha_wt               pitch point
    B = E - p_bt, D = A + p_bt   lowest and highest points of single contact on the pinion
    p_bt = pi m_t cos alpha_t = 2 pi r_b1 / z1   (transverse base pitch)
    eps_alpha = (E - A) / p_bt,  eps_beta = b sin beta / (pi m_n)

An internal pair (a planetary's planet and ring) is written as in ISO 21771: the wheel (the
ring) has a negative number of teeth ``z2 < 0``; diameters, radii and the centre distance are
positive (ISO 21771:2007, unlike DIN 3960's negative ones), and the profile shift keeps ISO's
sign: ``x2 > 0`` moves the ring's tip circle towards its axis (the KHK/JIS tables write the
opposite sign). With ``|z2|`` the ring's teeth and ``d2 = |z2| m_t``::

    inv alpha_wt = inv alpha_t + 2 tan alpha_n (x1 + x2) / (z1 + z2)   (z2 < 0; no backlash)
    a_w = (d2 - d1) cos alpha_t / (2 cos alpha_wt),  cos alpha_wt = (d_b2 - d_b1) / (2 a_w)
    j_bn = 2 a_w (inv alpha_wt0 - inv alpha_wt) cos alpha_wt cos beta_b
                                       (a longer centre distance takes backlash away)
    d_a2 = d2 - 2 m_n (1 + x2)          the ring's tip circle (no tip alteration)
    s_a2 = d_a2 (s2/d2 - inv alpha_t + inv alpha_a2)   ring tooth thickness at its tip

Both base circles touch the line of action on the same side of the contact, T2 beyond T1
(``T1T2 = a_w sin alpha_wt``), so the ring's flank is concave with the signed radius of
curvature ``rho2 = -(rho1 + T1T2)``; contact starts at the ring's tip,
``A: rho1 = sqrt(r_a2^2 - r_b2^2) - T1T2``, and ends at the pinion's, as above. The ring's
tip must not reach past T1 (``A > 0``), and the pinion's tip must clear the ring's tooth
tips as it leaves the mesh (no trochoid interference, SDP/SI *Elements of metric gear
technology*, eqs. 5-6 to 5-8, in transverse quantities)::

    (z1/|z2|) theta1 + inv alpha_wt - inv alpha_a2 >= theta2,
    theta1 = acos((r_a2^2 - r_a1^2 - a_w^2) / (2 a_w r_a1)) + inv alpha_a1 - inv alpha_wt,
    theta2 = acos((a_w^2 + r_a2^2 - r_a1^2) / (2 a_w r_a2)),

which a standard 20 deg pair meets from ``|z2| - z1 = 9`` (the reference's rule: 9 teeth
of difference or more); with fewer than 34 teeth a standard ring's tip circle lies inside
its base circle. The ring is not checked
for undercut (it is cut by a pinion-type cutter; the cutter's own interference limits are a
manufacturing matter).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError, check_positive
from .rack import (
    BASIC_RACK_CLEARANCE,
    BASIC_RACK_DEDENDUM,
    BASIC_RACK_ROOT_RADIUS,
    MIN_TIP_CLEARANCE,
    form_roll_distance,
    root_diameter,
    tip_for_clearance,
    tip_for_form,
)

__all__ = ["BACKLASH_FACTOR", "MAX_TIP_RELIEF", "MIN_CONTACT_RATIO", "MIN_TIP_THICKNESS",
           "GearPair", "involute", "inverse_involute", "minimum_backlash", "trochoid_clearance"]

#: Normal tooth thickness at the tip, in normal modules, below which a pair is warned about
#: (a common design minimum: a thinner tip chips, and a case-hardened one hardens through;
#: docs/gears.md). Only a tip of thickness 0 or less is refused.
MIN_TIP_THICKNESS = 0.2

#: Transverse contact ratio below which a pair whose overlap ratio is below 1 is warned about
#: (a common design minimum, 1.2-1.4 in gear design practice): one pair of teeth carries the
#: load over most of the path, with no margin for relief, deflection and tolerances.
MIN_CONTACT_RATIO = 1.2

#: Tip relief, in normal modules, above which it is warned about: reliefs are of the order of
#: the teeth's deflection under load, a few um to a few tens of um (about 0.01-0.02 m_n).
MAX_TIP_RELIEF = 0.05

#: A given centre distance whose normal backlash exceeds this many times the recommended
#: minimum of ISO/TR 10064-2 (:func:`minimum_backlash`) is warned about: more backlash than
#: tooth thickness tolerances give, so the profile shifts and the centre distance do not
#: belong to one design (docs/gears.md).
BACKLASH_FACTOR = 3.0


def minimum_backlash(centre_distance: float, normal_module: float) -> float:
    """Recommended minimum normal backlash of ISO/TR 10064-2 (also AGMA 2002),
    ``j_bn,min = (2/3) (0.06 + 0.0005 a + 0.03 m_n)`` in mm with ``a``, ``m_n`` in mm; here
    in m for ``a`` and ``m_n`` in m."""
    return (2.0 / 3.0) * (0.06e-3 + 0.0005 * centre_distance + 0.03 * normal_module)


def involute(angle):
    """The involute function inv(alpha) = tan(alpha) - alpha (ISO 21771, eq. 17)."""
    return np.tan(angle) - angle


def inverse_involute(value: float) -> float:
    """The angle alpha in [0, pi/2) with inv(alpha) = ``value`` >= 0 (Newton's method).

    Starts from the series inverse alpha ~ (3 v)^(1/3) and converges to machine precision in
    a few steps for the pressure angles of gears.
    """
    value = float(value)
    if not value >= 0.0:
        raise InputError("involute", "a value >= 0", value)
    if value == 0.0:
        return 0.0
    alpha = min((3.0 * value) ** (1.0 / 3.0), 1.5)
    for _ in range(60):
        step = (math.tan(alpha) - alpha - value) / math.tan(alpha) ** 2
        alpha = min(max(alpha - step, 0.5 * alpha), 0.5 * (alpha + 0.5 * math.pi))
        if abs(step) < 1e-15:
            break
    return alpha


def _check_undercut(name: str, z: int, x: float, alpha_t: float, cos_b: float):
    """Refuse undercut of an external gear, ``x < 1 - z sin^2(alpha_t) / (2 cos beta)`` (the
    basic rack's addendum 1)."""
    x_min = 1.0 - z * math.sin(alpha_t) ** 2 / (2.0 * cos_b)
    z_min = 2.0 * cos_b / math.sin(alpha_t) ** 2  # x_min = 0
    if x < x_min - 1e-9:
        raise InputError("profile_shift", (
            f"no undercut: the {name} shift x = {x:.4f} is below x_min = {x_min:.4f} = "
            f"1 - z sin^2(alpha_t) / (2 cos beta) for z = {z} (without shift a gear "
            f"needs z >= 2 cos beta / sin^2(alpha_t) = {z_min:.4g}"
            " teeth); raise the profile shift"))


def trochoid_clearance(z1: int, z2: int, ra, rb, aw: float, alpha_wt: float) -> float:
    """Margin against trochoid interference of an internal pair, rad (module notes; SDP/SI
    eqs. 5-6 to 5-8): ``(z1/z2) theta1 + inv alpha_wt - inv alpha_a2 - theta2``, negative
    where the pinion's tip cuts into the ring's tooth tips as it leaves the mesh.

    Parameters
    ----------
    z1, z2 : int
        Teeth of pinion and ring (``z2`` as a positive count).
    ra, rb : (float, float)
        Tip and base radii of pinion and ring, m (the ring's tip radius is its inner circle).
    aw : float
        Working centre distance, m.
    alpha_wt : float
        Working transverse pressure angle, rad.
    """
    (ra1, ra2), (rb1, rb2) = ra, rb
    cos1 = (ra2**2 - ra1**2 - aw**2) / (2.0 * aw * ra1)
    cos2 = (aw**2 + ra2**2 - ra1**2) / (2.0 * aw * ra2)
    if not (-1.0 <= cos1 <= 1.0 and -1.0 <= cos2 <= 1.0):
        return math.inf  # the tip circles do not cross: the pinion tip never meets the ring's
    theta1 = math.acos(cos1) + involute(math.acos(rb1 / ra1)) - involute(alpha_wt)
    theta2 = math.acos(cos2)
    return z1 / z2 * theta1 + involute(alpha_wt) - involute(math.acos(rb2 / ra2)) - theta2


def _rack_geometry(d, shifts, mn: float, alpha_n: float, alpha_t: float, internal: bool, da,
                   aw: float) -> dict:
    """Root diameters, root form distances and tip clearances of the pair, the external gears
    taken as generated by the ISO 53 profile A basic rack (:mod:`asperity.gears.rack`).

    Returns
    -------
    dict
        ``df`` and ``form_rho`` (pinion, wheel; NaN for a ring gear), m, and ``clearance``:
        each gear's tip to the mating root, ``a - r_a1 - r_f2`` and ``a - r_a2 - r_f1`` (a
        ring pair: NaN for the pinion's tip, ``r_a2 - a - r_f1`` for the ring's), m.
    """
    external = (True, not internal)
    df = tuple(root_diameter(d[i], mn, shifts[i]) if external[i] else math.nan
               for i in range(2))
    form_rho = tuple(form_roll_distance(d[i], mn, shifts[i], alpha_n, alpha_t) if external[i]
                     else math.nan for i in range(2))
    if internal:
        clearance = (math.nan, 0.5 * (da[1] - df[0]) - aw)
    else:
        clearance = (aw - 0.5 * (da[0] + df[1]), aw - 0.5 * (da[1] + df[0]))
    return {"df": df, "form_rho": form_rho, "clearance": clearance}


def _check_tip_clearance(rack: dict, da, aw: float, mn: float, internal: bool):
    """Refuse a tip that runs into the mating gear's root circle (a negative tip clearance of
    :func:`_rack_geometry`), naming the tip diameter that fits."""
    for i, name in enumerate(("pinion", "wheel")):
        c = rack["clearance"][i]
        if not c < -1e-9:
            continue
        mate = 1 - i
        root = rack["df"][mate]
        fits = tip_for_clearance(aw, root, 0.0, internal)
        standard = tip_for_clearance(aw, root, BASIC_RACK_CLEARANCE * mn, internal)
        owner, other = ("ring", "pinion") if internal else (name, ("pinion", "wheel")[mate])
        formula = ("r_a2 - a - r_f1" if internal else
                   f"a - r_a{i + 1} - r_f{mate + 1}")
        raise InputError("tip_diameter", (
            f"a {owner} tip diameter of {'at least' if internal else 'at most'} "
            f"{fits * 1e3:.4f} mm, the {'smallest' if internal else 'largest'} that clears the "
            f"{other}'s root circle: {da[i] * 1e3:.4f} mm leaves a tip clearance {formula} = "
            f"{c * 1e3:.4g} mm, against the {other}'s root diameter d_f{mate + 1} = "
            f"d{mate + 1} - 2 m_n ({BASIC_RACK_DEDENDUM:g} - x{mate + 1}) = {root * 1e3:.4f} mm "
            f"of the ISO 53 profile A basic rack (dedendum h_fP = {BASIC_RACK_DEDENDUM:g} m_n, "
            f"assumed: the case gives no cutter); {standard * 1e3:.4f} mm leaves the basic "
            f"rack's clearance {BASIC_RACK_CLEARANCE:g} m_n"),
            f"{da[i] * 1e3:.4f} mm")


def _contact_ratio_remedy(keys: list[str], internal: bool) -> str:
    """What to change for a larger contact ratio, for the ``[gear]`` keys the case gave."""
    if internal:
        steps = {"tip_diameter": "raise the pinion's tip diameter or lower the ring's (its tip "
                                 "circle nearer its axis)",
                 "centre_distance": "raise the centre distance towards the backlash-free one"}
    else:
        steps = {"tip_diameter": "raise the tip diameters",
                 "centre_distance": "reduce the centre distance towards the backlash-free one"}
    steps["profile_shift"] = ("lower the sum of the profile shifts, or give more teeth or a "
                              "smaller pressure angle")
    return " or ".join(steps[k] for k in keys)


def _pair(name: str, values, positive: bool = False) -> tuple[float, float]:
    try:
        first, second = (float(v) for v in values)
    except (TypeError, ValueError):
        raise InputError(name, "two numbers (pinion, wheel)", values) from None
    for v in (first, second):
        if not math.isfinite(v) or (positive and not v > 0):
            raise InputError(name, "finite values" + (" > 0" if positive else ""), values)
    return first, second


def _derived(name: str, doc: str) -> property:
    """A read-only property returning ``self.derived[name]``."""
    return property(lambda self: self.derived[name], doc=doc)


@dataclass(frozen=True)
class GearPair:
    """An involute gear pair, external or internal (spur for ``helix_angle = 0``).

    Parameters
    ----------
    teeth : (int, int)
        Numbers of teeth z1 (pinion), z2 (wheel); ``z2 < 0`` is an internal wheel (a ring
        gear, ISO 21771), which needs more teeth than the pinion, ``|z2| > z1``.
    normal_module : float
        m_n, m.
    pressure_angle : float
        Normal pressure angle alpha_n of the basic rack, rad.
    helix_angle : float
        Reference helix angle beta, rad (0: spur).
    profile_shift : (float, float)
        Profile shift coefficients x1, x2.
    face_width : float
        Common face width b, m.
    centre_distance : float, optional
        Working centre distance a_w, m; default the backlash-free distance of the shifts.
        A distance shorter than that (longer for an internal pair) is refused (the teeth
        would jam).
    tip_diameter : (float, float), optional
        d_a1, d_a2, m; default ISO 21771's standard tips with the tip alteration k (an
        internal pair's without it).
    tip_relief : (float, float)
        Amount of tip relief C_a of pinion and wheel, m (changes the load sharing).
    crowning : (float, float)
        Crowning heights C_b over the face width, m; the crowning radius is b^2/(8 C_b)
        and any crowning makes the contact elliptical (a point contact).

    Raises
    ------
    InputError
        Interference (the mating tip passes the point of tangency of a base circle, or an
        internal pair's trochoid interference), a pointed tip, a tip that runs into the
        mating gear's root circle (a negative tip clearance against the ISO 53 profile A
        roots, :mod:`asperity.gears.rack`), a transverse contact ratio below 1, undercut of
        the pinion or of an external wheel, tips below the base circle. The key named is
        the one the pair was given (``tip_diameter``, ``centre_distance``), else
        ``profile_shift``.
    """

    teeth: tuple
    normal_module: float
    pressure_angle: float
    helix_angle: float
    profile_shift: tuple
    face_width: float
    centre_distance: float | None = None
    tip_diameter: tuple | None = None
    tip_relief: tuple = (0.0, 0.0)
    crowning: tuple = (0.0, 0.0)
    derived: dict = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        try:
            z1, z2 = (int(z) for z in self.teeth)
        except (TypeError, ValueError):
            raise InputError("teeth", "two integers (pinion, wheel)", self.teeth) from None
        if any(isinstance(z, bool) or int(z) != z for z in self.teeth) or min(z1, abs(z2)) < 5:
            raise InputError("teeth", "two integers >= 5 (pinion, wheel; a negative wheel is a "
                             "ring gear)", self.teeth)
        if z2 < 0 and not -z2 > z1:
            raise InputError("teeth", f"a ring gear with more teeth than the pinion, |z2| > "
                             f"{z1}", self.teeth)
        mn = check_positive("normal_module", self.normal_module)
        alpha_n = check_positive("pressure_angle", self.pressure_angle)
        if not alpha_n < math.radians(45):
            raise InputError("pressure_angle", "an angle below 45 deg", math.degrees(alpha_n))
        beta = float(self.helix_angle)
        if not (math.isfinite(beta) and abs(beta) < math.radians(60)):
            raise InputError("helix_angle", "an angle of magnitude below 60 deg",
                             math.degrees(beta))
        x1, x2 = _pair("profile_shift", self.profile_shift)
        b = check_positive("face_width", self.face_width)
        ca = _pair("tip_relief", self.tip_relief)
        cb = _pair("crowning", self.crowning)
        if min(ca + cb) < 0:
            raise InputError("tip_relief, crowning", "values >= 0", (ca, cb))
        object.__setattr__(self, "teeth", (z1, z2))
        object.__setattr__(self, "profile_shift", (x1, x2))
        object.__setattr__(self, "tip_relief", ca)
        object.__setattr__(self, "crowning", cb)
        object.__setattr__(self, "derived", self._derive(z1, z2, mn, alpha_n, beta, x1, x2, b))

    def _derive(self, z1, z2, mn, alpha_n, beta, x1, x2, b) -> dict:
        """Every derived quantity of ISO 21771 the path of contact needs, checked (module
        notes; ``z2 < 0``: an internal pair, with the signs written there)."""
        internal = z2 < 0
        side = -1.0 if internal else 1.0  # the wheel's base circle across the line of action
        cos_b = math.cos(beta)
        alpha_t = math.atan(math.tan(alpha_n) / cos_b)
        mt = mn / cos_b
        d = (z1 * mt, abs(z2) * mt)
        db = tuple(di * math.cos(alpha_t) for di in d)
        beta_b = math.asin(abs(math.sin(beta)) * math.cos(alpha_n))
        a0 = 0.5 * (d[1] + side * d[0])
        inv_wt = involute(alpha_t) + 2.0 * math.tan(alpha_n) * (x1 + x2) / (z1 + z2)
        if not inv_wt > 0:
            raise InputError("profile_shift", "a sum x1 + x2 giving a positive working "
                             "pressure angle", (x1, x2))
        base = 0.5 * (db[1] + side * db[0])  # a_w cos alpha_wt
        tight = base / math.cos(inverse_involute(inv_wt))
        if self.centre_distance is None:
            aw = tight
        else:
            aw = check_positive("centre_distance", self.centre_distance)
            if side * (aw - tight) < -1e-6 * tight:
                raise InputError("centre_distance", (
                    f"{'<=' if internal else '>='} {tight * 1e3:.4f} mm, the distance at which "
                    "the shifted teeth mesh without backlash (they would jam)"),
                    f"{aw * 1e3:.4f} mm")
            if not aw > base:
                raise InputError("centre_distance", "more than the "
                                 + ("difference" if internal else "sum") + " of the base radii",
                                 aw)
        alpha_wt = math.acos(base / aw)
        # the working pitch circles' pitch less both tooth thicknesses there, 2 a_w (inv
        # alpha_wt - inv alpha_wt0) (the other sign for an internal pair), in the normal
        # direction
        backlash = (2.0 * side * aw * (involute(alpha_wt) - inv_wt) * math.cos(alpha_wt)
                    * math.cos(beta_b))
        if self.tip_diameter is None:
            k = 0.0 if internal else min(0.0, (aw - a0) / mn - (x1 + x2))
            da = (d[0] + 2.0 * mn * (1.0 + x1 + k), d[1] + 2.0 * side * mn * (1.0 + x2 + k))
        else:
            da = _pair("tip_diameter", self.tip_diameter, positive=True)
        if internal and self.tip_diameter is None and not da[1] > db[1]:
            z_min = math.ceil(2.0 * (1.0 + x2) * cos_b / (1.0 - math.cos(alpha_t)) - 1e-9)
            raise InputError("teeth", (
                f"a ring whose tip circle lies outside its base circle: its standard tip "
                f"diameter d2 - 2 m_n (1 + x2) = {da[1] * 1e3:.4f} mm is inside its base "
                f"circle {db[1] * 1e3:.4f} mm, where its involute begins; give the ring at "
                f"least {z_min} teeth at this shift, or lower its profile shift x2"))
        for i, name in enumerate(("pinion", "wheel")):
            if not da[i] > db[i]:
                raise InputError(f"tip_diameter ({name})", f"more than the base diameter "
                                 f"{db[i] * 1e3:.4f} mm", f"{da[i] * 1e3:.4f} mm")
        rb = (0.5 * db[0], 0.5 * db[1])
        ra = (0.5 * da[0], 0.5 * da[1])
        t1t2 = aw * math.sin(alpha_wt)
        rho_a = side * (t1t2 - math.sqrt(ra[1] ** 2 - rb[1] ** 2))
        rho_e = math.sqrt(ra[0] ** 2 - rb[0] ** 2)
        rho_c = rb[0] * math.tan(alpha_wt)
        pbt = math.pi * mt * math.cos(alpha_t)
        tip_thickness = []
        for i, (z, x, name) in enumerate(((z1, x1, "pinion"), (z2, x2, "wheel"))):
            if z > 0:
                _check_undercut(name, z, x, alpha_t, cos_b)
            s_ref = mt * (0.5 * math.pi + 2.0 * x * math.tan(alpha_n))
            alpha_a = math.acos(db[i] / da[i])
            s_tip = da[i] * (s_ref / d[i] + math.copysign(1.0, z)
                             * (involute(alpha_t) - involute(alpha_a)))
            tip_thickness.append(s_tip)
            if not s_tip > 0:
                raise InputError(self._tip_field(), (
                    f"no pointed tip: the {name} tooth thickness at the tip is "
                    f"{s_tip * 1e3:.4f} mm; reduce the tip diameter or the profile shift"
                    if z > 0 else
                    f"no pointed tip: the ring's tooth thickness at its tip is "
                    f"{s_tip * 1e3:.4f} mm; raise the ring's tip diameter or lower its "
                    "profile shift"))
        if not rho_a > 0:
            raise InputError(self._tip_field(), (
                f"no interference: the wheel tip reaches {-rho_a * 1e3:.3f} mm past T1, where "
                "the line of action touches the pinion's base circle; "
                + ("raise the ring's tip diameter or the pinion profile shift" if internal else
                   "reduce the wheel tip diameter or raise the pinion profile shift")))
        if not internal and not rho_e < t1t2:
            raise InputError(self._tip_field(), (
                "no interference: the pinion tip reaches past T2, where the line of action "
                "touches the wheel's base circle; reduce the pinion tip diameter or raise the "
                "wheel profile shift"))
        if internal:
            clearance = trochoid_clearance(z1, -z2, ra, rb, aw, alpha_wt)
            if not clearance >= 0:
                raise InputError("teeth", (
                    f"no trochoid interference: leaving the mesh, the pinion tip cuts into the "
                    f"ring's tooth tips (by {-math.degrees(clearance):.3f} deg of ring "
                    f"rotation); give the ring more teeth (a standard 20 deg pair needs "
                    f"{z1 + 9}), or a smaller pinion tip or a larger ring tip diameter"))
        rack = _rack_geometry(d, (x1, x2), mn, alpha_n, alpha_t, internal, da, aw)
        _check_tip_clearance(rack, da, aw, mn, internal)
        eps_alpha = (rho_e - rho_a) / pbt
        if not eps_alpha >= 1.0:
            keys = self._keys_set()
            raise InputError(", ".join(keys), (
                f"a transverse contact ratio >= 1 (it is {eps_alpha:.3f}: the mesh loses "
                f"contact); {_contact_ratio_remedy(keys, internal)}"))
        return {
            "alpha_t": alpha_t, "mt": mt, "d": d, "db": db, "rb": rb, "da": da, "ra": ra,
            "beta_b": beta_b, "a0": a0, "aw": aw, "alpha_wt": alpha_wt,
            "dw": (2.0 * aw * z1 / abs(z1 + z2), 2.0 * aw * abs(z2) / abs(z1 + z2)),
            "t1t2": t1t2, "pbt": pbt, "eps_alpha": eps_alpha,
            "eps_beta": b * abs(math.sin(beta)) / (math.pi * mn),
            "path": {"A": rho_a, "B": rho_e - pbt, "C": rho_c, "D": rho_a + pbt, "E": rho_e},
            "tip_thickness": tuple(tip_thickness),
            "tight_centre_distance": tight, "backlash": max(0.0, backlash),
            "df": rack["df"], "form_rho": rack["form_rho"],
            "tip_clearance": rack["clearance"],
        }

    def _tip_field(self) -> str:
        """The key a refusal about the tips names: ``tip_diameter`` where it was given, else
        ``profile_shift`` (the default tips follow the shifts)."""
        return "tip_diameter" if self.tip_diameter is not None else "profile_shift"

    def _keys_set(self) -> list[str]:
        """The ``[gear]`` keys among ``tip_diameter`` and ``centre_distance`` that were given,
        else ``["profile_shift"]`` (what sets the tips and the distance then): the keys a line
        about the contact ratio names."""
        keys = [k for k in ("tip_diameter", "centre_distance") if getattr(self, k) is not None]
        return keys or ["profile_shift"]

    # --- read-only views of the derived quantities -----------------------------------------

    alpha_t = _derived("alpha_t", "Transverse pressure angle, rad.")
    mt = _derived("mt", "Transverse module m_n / cos beta, m.")
    d = _derived("d", "Reference diameters (pinion, wheel), m.")
    db = _derived("db", "Base diameters, m.")
    rb = _derived("rb", "Base radii, m.")
    da = _derived("da", "Tip diameters (given or ISO 21771 standard), m.")
    ra = _derived("ra", "Tip radii, m.")
    dw = _derived("dw", "Working pitch diameters 2 a_w |z| / |z1 + z2|, m.")
    beta_b = _derived("beta_b", "Base helix angle, rad.")
    a0 = _derived("a0", "Reference centre distance (d1 + d2)/2 ((d2 - d1)/2 internal), m.")
    aw = _derived("aw", "Working centre distance, m.")
    alpha_wt = _derived("alpha_wt", "Working transverse pressure angle, rad.")
    t1t2 = _derived("t1t2", "Length T1T2 = a_w sin alpha_wt of the line of action, m.")
    pbt = _derived("pbt", "Transverse base pitch pi m_t cos alpha_t, m.")
    tip_thickness = _derived("tip_thickness", "Transverse tooth thickness at the tips, m.")
    df = _derived("df", "Root diameters d - 2 m_n (1.25 - x) of the ISO 53 profile A basic rack "
                  "(pinion, wheel; NaN for a ring gear), m.")
    tip_clearance = _derived(
        "tip_clearance", "Tip clearances a - r_a1 - r_f2 and a - r_a2 - r_f1 (a ring pair: NaN "
        "and r_a2 - a - r_f1), m, against the root diameters :attr:`df`.")

    @property
    def form_diameter(self) -> tuple[float, float]:
        """Root form diameters d_Ff = 2 sqrt(r_b^2 + rho_F^2) of the involutes generated by the
        ISO 53 profile A basic rack (:func:`asperity.gears.rack.form_roll_distance`; pinion,
        wheel; NaN for a ring gear), m."""
        return tuple(2.0 * math.hypot(rb, rho) for rb, rho in
                     zip(self.rb, self.derived["form_rho"], strict=True))
    tight_centre_distance = _derived(
        "tight_centre_distance", "Centre distance at which the shifted teeth mesh without "
        "backlash, m.")
    backlash = _derived(
        "backlash", "Normal backlash j_bn = 2 a_w (inv alpha_wt - inv alpha_wt0) cos alpha_wt "
        "cos beta_b of the working centre distance (0 without a given one), m; tooth "
        "thickness allowances are not modelled.")

    @property
    def normal_tip_thickness(self) -> tuple[float, float]:
        """Normal tooth thickness at the tips, s_an = s_at cos(beta_a) with
        tan(beta_a) = tan(beta) d_a / d (pinion, wheel), m."""
        tan_b = math.tan(self.helix_angle)
        return tuple(s * math.cos(math.atan(tan_b * da / d)) for s, da, d in
                     zip(self.tip_thickness, self.da, self.d, strict=True))

    def design_warnings(self) -> list[str]:
        """Lines about a valid but doubtful design: a nearly pointed tip (normal tip thickness
        below :data:`MIN_TIP_THICKNESS` m_n; the case keys named are ``gear.profile_shift`` and
        ``gear.tip_diameter``), a given centre distance whose backlash is more than
        :data:`BACKLASH_FACTOR` times ISO/TR 10064-2's recommended minimum
        (``gear.centre_distance``), a tip clearance below
        :data:`~asperity.gears.rack.MIN_TIP_CLEARANCE` m_n, a mating tip that meets a flank
        inside its root form circle (tip-to-fillet interference, ``d_Nf < d_Ff``; ISO 53
        profile A generation assumed), a transverse contact ratio below
        :data:`MIN_CONTACT_RATIO` with an overlap ratio below 1, and a tip relief above
        :data:`MAX_TIP_RELIEF` m_n (``gear.tip_relief``).

        Returns
        -------
        list of str
            One line per finding.
        """
        lines = []
        mn = self.normal_module
        limit = BACKLASH_FACTOR * minimum_backlash(self.aw, mn)
        if self.backlash > limit:
            z1, z2 = self.teeth
            alpha_n = self.pressure_angle
            shifts = ((involute(self.alpha_wt) - involute(self.alpha_t)) * (z1 + z2)
                      / (2.0 * math.tan(alpha_n)))
            lines.append(
                f"gear.centre_distance: {self.aw * 1e3:.4g} mm is "
                f"{abs(self.aw - self.tight_centre_distance) * 1e3:.4g} mm "
                f"{'less' if self.internal else 'more'} than the "
                f"{self.tight_centre_distance * 1e3:.6g} mm at which the profile shifts "
                f"(x1 + x2 = {sum(self.profile_shift):.4g}) mesh without backlash: a normal "
                f"backlash of {self.backlash * 1e3:.3g} mm = {self.backlash / mn:.3g} m_n, "
                f"{self.backlash / minimum_backlash(self.aw, mn):.3g} times ISO/TR 10064-2's "
                f"recommended minimum, and a transverse contact ratio of "
                f"{self.contact_ratio:.4g}; at this centre distance the teeth mesh without "
                f"backlash with x1 + x2 = {shifts:.4g}: check gear.centre_distance and "
                "gear.profile_shift")
        for name, s_an in zip(("pinion", "wheel"), self.normal_tip_thickness, strict=True):
            if s_an < MIN_TIP_THICKNESS * mn:
                lines.append(
                    f"gear.profile_shift / gear.tip_diameter: the {name} tip is nearly pointed: "
                    f"tooth thickness at the tip {s_an * 1e3:.4g} mm = {s_an / mn:.3g} m_n, "
                    f"below {MIN_TIP_THICKNESS:g} m_n (a common design minimum; a thinner tip "
                    "chips, and case-hardened it hardens through); reduce the "
                    f"{name} profile shift or tip diameter")
        return (lines + self._clearance_warnings() + self._fillet_warnings()
                + self._contact_ratio_warnings() + self._tip_relief_warnings())

    def _tip_key(self) -> str:
        """The key a line about the tips names: ``gear.tip_diameter`` where the case gave
        it, else ``gear.profile_shift / gear.tip_diameter`` (the default tips follow the
        shifts)."""
        return ("gear.tip_diameter" if self.tip_diameter is not None
                else "gear.profile_shift / gear.tip_diameter")

    def _clearance_warnings(self) -> list[str]:
        """A line per tip whose clearance to the mating root (:attr:`tip_clearance`) is below
        :data:`MIN_TIP_CLEARANCE` m_n (a negative one is refused)."""
        mn, lines = self.normal_module, []
        for i, c in enumerate(self.tip_clearance):
            if not c < MIN_TIP_CLEARANCE * mn:  # NaN: not judged (a ring pair's pinion tip)
                continue
            mate = 1 - i
            owner, other = ("ring", "pinion") if self.internal else (
                ("pinion", "wheel")[i], ("pinion", "wheel")[mate])
            better = tip_for_clearance(self.aw, self.df[mate], BASIC_RACK_CLEARANCE * mn,
                                       self.internal)
            lines.append(
                f"{self._tip_key()}: the {owner} tip clears the {other}'s root circle by "
                f"{c * 1e3:.4g} mm = {c / mn:.3g} m_n, below {MIN_TIP_CLEARANCE:g} m_n (design "
                f"software's usual minimum; ISO 53's basic rack gives {BASIC_RACK_CLEARANCE:g} "
                f"m_n): the {other}'s "
                f"root diameter {self.df[mate] * 1e3:.4f} mm is that of the ISO 53 profile A "
                f"basic rack (dedendum {BASIC_RACK_DEDENDUM:g} m_n; a deeper-cutting tool leaves "
                "more room), and "
                "tolerances, thermal growth and the oil squeezed from the root need the room; "
                f"a {owner} tip diameter of {better * 1e3:.4f} mm leaves "
                f"{BASIC_RACK_CLEARANCE:g} m_n")
        return lines

    def _fillet_warnings(self) -> list[str]:
        """A line per flank on which the mating tip's contact starts inside the root form
        circle (:attr:`form_diameter`): tip-to-fillet interference, the active root diameter
        ``d_Nf = 2 sqrt(r_b^2 + rho^2)`` at A (pinion) or E (wheel) below ``d_Ff``."""
        pts, rb, t1t2 = self.points, self.rb, self.t1t2
        reach = (pts["A"], math.nan if self.internal else t1t2 - pts["E"])
        lines = []
        for j, flank in enumerate(("pinion", "wheel")):
            rho_f = self.derived["form_rho"][j]
            if not reach[j] < rho_f - 1e-9:  # NaN: the ring's form circle is not known
                continue
            tip = 1 - j
            tipname = "ring" if self.internal else ("pinion", "wheel")[tip]
            limit = tip_for_form(rb[tip], t1t2, rho_f, self.internal)
            bound = "at least" if self.internal else "at most"
            lines.append(
                f"{self._tip_key()}: the {tipname} tip meets the {flank} flank inside its "
                f"root form circle (tip-to-fillet interference): contact starts at "
                f"d_Nf{j + 1} = {2e3 * math.hypot(rb[j], reach[j]):.4f} mm, below the form "
                f"diameter d_Ff{j + 1} = {self.form_diameter[j] * 1e3:.4f} mm where the "
                f"{flank}'s involute ends, assuming it was generated by the ISO 53 profile A "
                f"basic rack (h_fP = {BASIC_RACK_DEDENDUM:g} m_n, rho_fP = "
                f"{BASIC_RACK_ROOT_RADIUS:g} m_n; the case gives no cutter), so the tip runs "
                "onto the fillet, where the involute radii, speeds and loads of the path do "
                f"not hold; a {tipname} tip diameter of {bound} {limit * 1e3:.4f} mm keeps "
                "the contact on the involute")
        return lines

    def _contact_ratio_warnings(self) -> list[str]:
        """A line when the transverse contact ratio is below :data:`MIN_CONTACT_RATIO` and the
        overlap ratio below 1 (a helical pair with eps_beta >= 1 shares the load along its
        contact lines whatever eps_alpha)."""
        eps = self.contact_ratio
        if not (eps < MIN_CONTACT_RATIO and self.overlap_ratio < 1.0):
            return []
        keys = self._keys_set()
        single = min(1.0, (2.0 - eps) / eps)  # B-D over A-E: p_bt (2 - eps) / (eps p_bt)
        return [
            f"{', '.join(f'gear.{k}' for k in keys)}: the transverse contact ratio "
            f"{eps:.4g} is below {MIN_CONTACT_RATIO:g} (a common design minimum): one pair of "
            f"teeth carries the load over {single:.0%} of the path of contact (B-D), and the "
            "two-pair stretches at its ends are short, so there is no margin for tip relief, "
            "deflection under load and pitch or centre-distance tolerances, which shorten the "
            "path in service and can make the mesh lose contact (a shock at each change of "
            f"pair); {_contact_ratio_remedy(keys, self.internal)}"]

    def _tip_relief_warnings(self) -> list[str]:
        """A line per gear whose tip relief exceeds :data:`MAX_TIP_RELIEF` m_n."""
        mn, lines = self.normal_module, []
        for name, ca in zip(("pinion", "wheel"), self.tip_relief, strict=True):
            if ca > MAX_TIP_RELIEF * mn:
                lines.append(
                    f"gear.tip_relief: the {name}'s tip relief {ca * 1e6:.4g} um = "
                    f"{ca / mn:.3g} m_n is above {MAX_TIP_RELIEF:g} m_n: a tip relief C_a is of "
                    "the order of the teeth's deflection under load, a few um to a few tens of "
                    "um (about 0.01-0.02 m_n, rarely over 0.05 m_n); one this deep takes the "
                    "relieved tip out of contact and shortens the working path, which the load "
                    "sharing (X falls to 0 at a relieved tip whatever its amount) does not "
                    "model; check the value and its unit (\"20 um\")")
        return lines

    @property
    def ratio(self) -> float:
        """Gear ratio u = z2 / z1 (negative for an internal pair, as in ISO 6336)."""
        return self.teeth[1] / self.teeth[0]

    @property
    def overlap_ratio(self) -> float:
        """eps_beta = b sin|beta| / (pi m_n)."""
        return self.derived["eps_beta"]

    @property
    def contact_ratio(self) -> float:
        """Transverse contact ratio eps_alpha = g_alpha / p_bt."""
        return self.derived["eps_alpha"]

    @property
    def points(self) -> dict:
        """rho1 (m) of the points A, B, C, D, E of the path of contact."""
        return dict(self.derived["path"])

    @property
    def crowning_radii(self) -> tuple[float, float]:
        """Crowning radii b^2 / (8 C_b) of pinion and wheel, m (inf without crowning)."""
        b = self.face_width
        return tuple(b * b / (8.0 * c) if c > 0 else math.inf for c in self.crowning)

    @property
    def crowning_radius(self) -> float:
        """Relative crowning radius 1 / (1/R_c1 + 1/R_c2), m: the ``ry`` of the elliptical
        contact of a crowned pair (inf without crowning)."""
        curvature = sum(1.0 / r for r in self.crowning_radii)
        return 1.0 / curvature if curvature > 0 else math.inf

    @property
    def crowned(self) -> bool:
        """True when either flank is crowned: the contact is then elliptical."""
        return max(self.crowning) > 0

    @property
    def internal(self) -> bool:
        """True for an internal pair (a ring gear, ``z2 < 0``)."""
        return self.teeth[1] < 0

    def rho2(self, rho1):
        """Signed transverse radius of curvature of the wheel flank, m: T1T2 - rho1 (convex),
        or -(rho1 + T1T2) for a ring gear (concave, negative as in ISO 21771)."""
        rho1 = np.asarray(rho1, dtype=float)
        t1t2 = self.derived["t1t2"]
        return -(rho1 + t1t2) if self.internal else t1t2 - rho1

    def roll_angle(self, rho1):
        """Pinion roll angle rho1 / r_b1, rad (the tangent of the pressure angle there)."""
        return np.asarray(rho1, dtype=float) / self.derived["rb"][0]

    def rho1_at_roll_angle(self, angle: float) -> float:
        """rho1 (m) at a pinion roll angle (rad); it must lie on the path of contact A-E."""
        rho = float(angle) * self.derived["rb"][0]
        pts = self.derived["path"]
        if not pts["A"] - 1e-12 <= rho <= pts["E"] + 1e-12:
            lo, hi = (math.degrees(pts[k] / self.derived["rb"][0]) for k in "AE")
            raise InputError("roll_angle", f"an angle between {lo:.3f} and {hi:.3f} deg (A to E)",
                             f"{math.degrees(angle):.3f} deg")
        return rho

    @property
    def pitch_on_path(self) -> bool:
        """Whether the pitch point C lies on the path of contact A-E. Heavily shifted pairs
        (an internal pair with ``x2 = 0.8``, C 3.4 mm before A) mesh in recess or approach
        alone; their path has no pitch point."""
        pts = self.derived["path"]
        return pts["A"] <= pts["C"] <= pts["E"]

    def path(self, n: int) -> np.ndarray:
        """``n`` positions rho1 (m) spread evenly from A to E, with B, D and C (where it lies
        on the path, :attr:`pitch_on_path`) always among them: each takes the nearest
        interior node not yet taken, in that order. (Moving only a node within half a spacing
        lost C when B-D is short against the spacing: 5 points on a pair with contact ratio
        1.66 reported the "pitch" film 1.27 mm from C, and a maximum Hertz pressure 19 %
        low. A pitch point outside A-E had been taken as a node there, with its load sharing
        extrapolated: a pitch Hertz pressure of 85 MPa where the teeth do not touch.)"""
        if isinstance(n, bool) or not isinstance(n, int) or n < 5:
            raise InputError("points", "an integer >= 5", n)
        pts = self.derived["path"]
        rho = np.linspace(pts["A"], pts["E"], n)
        free = list(range(1, n - 1))
        for key in ("B", "C", "D") if self.pitch_on_path else ("B", "D"):
            i = min(free, key=lambda k: abs(rho[k] - pts[key]))
            rho[i] = pts[key]
            free.remove(i)
        return np.sort(rho)
