"""Case file of a gear pair: film, lambda, friction and flash temperature along the path of contact.

::

    analysis = "gear"
    [gear]
    teeth = [16, 24]                     # a ring gear negative: [27, -75] (ISO 21771)
    normal_module = "4.5 mm"
    pressure_angle = "20 deg"
    helix_angle = "0 deg"
    profile_shift = [0.1817, 0.1715]
    face_width = "14 mm"
    centre_distance = "91.5 mm"          # optional: default from the shifts
    tip_diameter = ["82.46 mm", "118.36 mm"]   # optional: default ISO 21771 with tip alteration
    tip_relief = ["0 um", "0 um"]        # optional
    crowning = ["0 um", "0 um"]          # optional crowning heights: elliptical contact
    [operation]
    torque = "302 N m"                   # pinion torque
    speed = "2170 rpm"                   # pinion speed ("rpm", "min^-1", "rev/s" or "rad/s")
    bulk_temperature = 90                # deg C (viscosity eta0 is taken at this temperature)
    [body1] / [body2]                    # E, nu (optional: steel)
    [lubricant]                          # eta0, alpha, ... tau0 (as for ehl-steady)
    [surface1] / [surface2]              # roughness of pinion and wheel flank (ground, builtin,
                                         # gaussian, file): lambda and the transient hand-off
    [roughness]
    parameter = "ra"                     # or "rq"
    combination = "rss"                  # or "mean" (ISO/TR 15144-1)
    [friction]
    boundary = 0.1                       # boundary friction coefficient
    boundary_lambda = 1.0                # all load on asperities below this lambda
    full_film_lambda = 3.0               # none above this
    [thermal]                            # k, rho, c of pinion and wheel (steel defaults;
                                         # a body that is not steel is warned without them)
    [ehl]                                # points along A-E and the steady mesh
    points = 25
    [handoff]                            # the point `asperity gear --emit-transient` writes
    at = "min-lambda"                    # "pitch", "min-lambda", "max-flash" or a roll angle
    [handoff.solver]                     # optional [solver] keys of the transient case (a line
                                         # contact gets max_sweeps = 2000 unless given)
"""

from __future__ import annotations

import math
import re
from typing import Annotated, Literal

import pint
from pydantic import BeforeValidator, Field, field_validator, model_validator

from ..errors import InputError
from ..gears.geometry import GearPair
from ..gears.path import EHLMesh, Thermal
from ..materials import Material
from ..units import is_bare, registry, to_si
from .bodies import MaterialSpec
from .doubts import BareNumbers
from .ehl import LubricantSpec
from .ehl_transient import MovingSurfaceSpec, TimeSpec, TransientSolverSpec
from .fields import CaseHeader, CaseModel, Integer, Number, Quantity

__all__ = ["GearCase", "GearSpec", "HandoffSpec", "OperationSpec"]

Angle = Quantity("angle")


def _mm(value: float) -> str:
    """A length in m written for a message ("20 m", "0.05 mm", "50 um")."""
    if value >= 1.0:
        return f"{value:g} m"
    return f"{value * 1e3:g} mm" if value >= 1e-5 else f"{value * 1e6:g} um"


def _bare_hint(value, low: float, high: float) -> str:
    """How to write a bare number too large in metres: with the unit ("mm", else "um") that
    brings it into ``low .. high``, else in mm."""
    number = float(value)
    for scale, unit in ((1e-3, "mm"), (1e-6, "um")):
        if low <= number * scale <= high:
            return f"{number:g} {unit}"
    return f"{number:g} mm"


def GearLength(low: float, high: float, *, inclusive_low: bool = True):  # noqa: N802
    """A length field of a gear (SI m) held to a plausible range ``low .. high``.

    A bare number is metres (``normal_module = 4`` is 4 m): a value outside the range is
    refused in one line that says so and how to write it (``"4 mm"``). The range stands in the
    field's constraints too (``ge``/``gt`` and ``le``).
    """
    if low > 0:
        span = f"from {_mm(low)} to {_mm(high)}"
    else:
        span = f"from 0 to {_mm(high)}" if inclusive_low else f"above 0, up to {_mm(high)}"

    def convert(value):
        try:
            si = to_si(value, "length", "")
        except InputError as exc:
            raise ValueError(f"expected {exc.expected}") from None
        inside = (si >= low if inclusive_low else si > low) and si <= high
        if not inside:
            hint = _bare_hint(value, low, high) if is_bare(value) and si > high else ""
            note = f' (a bare number is metres: write "{hint}")' if hint else ""
            raise ValueError(f"expected a length {span}{note}")
        return si

    convert.__name__ = "to_gear_length"
    bound = {"ge": low} if inclusive_low else {"gt": low}
    return Annotated[float, BeforeValidator(convert),
                     Field(json_schema_extra={"dimension": "length"}, le=high, **bound)]


#: Plausible ranges of the gear lengths (m): a slip of the unit (a bare number is metres) falls
#: outside them. Modules of 0.05 mm (watch gears) to 100 mm (mill drives); face widths, centre
#: distances and tip diameters of the largest girth gears; tip relief and crowning of a few um
#: to a few tens of um in practice.
MODULE_RANGE = (0.05e-3, 100e-3)
FACE_WIDTH_MAX = 2.0
CENTRE_DISTANCE_MAX = 20.0
TIP_DIAMETER_MAX = 20.0
MODIFICATION_MAX = 1e-3
_Modification = GearLength(0.0, MODIFICATION_MAX)
_Tip = GearLength(0.0, TIP_DIAMETER_MAX, inclusive_low=False)


#: ``[gear]`` keys of bevel, hypoid and crossed-axis pairs, refused as out of scope.
NON_PARALLEL_KEYS = frozenset({"shaft_angle", "axis_angle", "crossing_angle", "cone_angle",
                               "pitch_angle", "pitch_cone_angle", "offset", "hypoid_offset"})


class GearSpec(CaseModel):
    """``[gear]``: the involute pair (ISO 21771); lists are ``[pinion, wheel]``."""

    teeth: tuple[Annotated[Integer, Field(ge=5, le=1000)],
                 Annotated[Integer, Field(ge=-1000, le=1000)]]
    """Numbers of teeth [pinion, wheel]; a negative wheel is a ring gear (an internal pair,
    ISO 21771: ``[27, -75]`` is a planet in its ring), with more teeth than the pinion."""
    normal_module: GearLength(*MODULE_RANGE)
    """Normal module m_n, 0.05 mm to 100 mm ("4 mm"; a bare number is metres; a diametral
    pitch "8 1/in" is refused with the module it means, 1/P)."""
    pressure_angle: Quantity("angle", gt=0) = math.radians(20.0)
    """Normal pressure angle (e.g. "20 deg")."""
    helix_angle: Angle = 0.0
    """Helix angle at the reference circle (0: spur gears)."""
    profile_shift: tuple[Number, Number] = (0.0, 0.0)
    """Profile shift coefficients [pinion, wheel]."""
    face_width: GearLength(0.0, FACE_WIDTH_MAX, inclusive_low=False)
    """Face width, up to 2 m ("30 mm"; a bare number is metres)."""
    centre_distance: GearLength(0.0, CENTRE_DISTANCE_MAX, inclusive_low=False) | None = None
    """Centre distance, up to 20 m (default from the profile shifts)."""
    tip_diameter: tuple[_Tip, _Tip] | None = None
    """Tip diameters [pinion, wheel], up to 20 m (default ISO 21771 with tip alteration)."""
    tip_relief: tuple[_Modification, _Modification] = (0.0, 0.0)
    """Tip relief [pinion, wheel], 0 to 1 mm ("10 um")."""
    crowning: tuple[_Modification, _Modification] = (0.0, 0.0)
    """Crowning heights [pinion, wheel], 0 to 1 mm (nonzero: an elliptical contact)."""

    @model_validator(mode="before")
    @classmethod
    def _parallel_axes(cls, data):
        """Refuse the keys of a bevel or crossed-axis pair in words (they were "unknown key
        (check the spelling)"): only parallel-axis pairs are modelled."""
        if isinstance(data, dict):
            for key in data:
                if key in NON_PARALLEL_KEYS:
                    raise InputError(f"gear.{key}", "", problem=(
                        "only parallel-axis pairs (spur and helical, external or internal, "
                        "ISO 21771) are modelled; bevel, hypoid, worm and crossed-axis helical "
                        "gears are not (their contact and sliding differ from a cylindrical "
                        "pair's): give the pair's teeth, module and helix angle on parallel "
                        "shafts"))
        return data

    @field_validator("helix_angle", mode="before")
    @classmethod
    def _one_helix_angle(cls, value):
        """Refuse two helix angles: a parallel-axis pair has one, of opposite hand on the two
        gears; two angles that do not cancel are crossed axes (shaft angle beta1 + beta2)."""
        if isinstance(value, list | tuple):
            raise ValueError(
                "expected one helix angle, the reference-circle angle of both gears (on "
                "parallel shafts the wheel's is the same of opposite hand); two angles of a "
                "crossed-axis helical pair (shaft angle beta1 + beta2) are not modelled, "
                f"got {list(value)}")
        return value

    @field_validator("teeth", mode="before")
    @classmethod
    def _ring_second(cls, value):
        """Refuse in words a value that is not a pair (one count read "expected a valid
        tuple, got 25"), a negative pinion (the pinion of an internal pair is the external
        gear, the ring the wheel) and a ring of fewer than 5 teeth."""
        if not (isinstance(value, list | tuple) and len(value) == 2):
            raise ValueError("expected a pair [pinion, wheel] of tooth counts such as [25, 50]")
        if all(isinstance(z, int | float) and not isinstance(z, bool) for z in value):
            if value[0] < 0:
                raise ValueError(
                    "expected [pinion, wheel] with the pinion external (> 0): an internal pair "
                    "is written with the ring gear as the wheel, negative (ISO 21771), e.g. "
                    f"[{abs(value[0]):g}, {-abs(value[1]):g}], got {list(value)}")
            if -5 < value[1] < 5:
                raise ValueError("expected a wheel of at least 5 teeth (negative: a ring gear "
                                 f"of at least 5), got {list(value)}")
        return value

    @field_validator("normal_module", mode="before")
    @classmethod
    def _not_a_diametral_pitch(cls, value):
        """Refuse a diametral pitch ("8 1/in") given as the module with the module it means,
        m = 1 / P (25.4 mm / 8 = 3.175 mm); the unit check said only "expected a quantity
        convertible to m"."""
        if isinstance(value, str):
            try:
                per_metre = float(registry().Quantity(value.strip()).to("1/m").magnitude)
            except Exception:  # pint raises many kinds on odd text; the unit check decides
                return value
            if per_metre > 0:
                raise ValueError(
                    "expected a module (a length), not a diametral pitch P: the module is "
                    f"m = 1 / P, here normal_module = \"{1e3 / per_metre:.4g} mm\" (a normal "
                    "diametral pitch gives the normal module)")
        return value

    @model_validator(mode="after")
    def _valid(self):
        """Build the pair; its refusal names the ``[gear]`` keys it concerns
        (``gear.tip_diameter: expected ...``; it read ``gear: expected ... (centre_distance)``,
        a key the case need not have)."""
        try:
            self.pair()
        except InputError as exc:
            keys = ", ".join(f"gear.{key}" for key in exc.field.split(", "))
            raise InputError(keys, exc.expected, exc.got, problem=exc.problem) from None
        return self

    def pair(self) -> GearPair:
        """The :class:`~asperity.gears.GearPair` (raises InputError for invalid gear data)."""
        return GearPair(self.teeth, self.normal_module, self.pressure_angle, self.helix_angle,
                        self.profile_shift, self.face_width, self.centre_distance,
                        self.tip_diameter, self.tip_relief, self.crowning)


#: Per-minute speeds, revolutions as gear catalogues and DIN 1301 write them ("min^-1").
_PER_MINUTE = re.compile(r"\s*([-+0-9.eE]+)\s*(rpm|RPM|r/min|rev/min|U/min|1/min|/min|min\^-1|"
                         r"min\*\*-1|min-1)\s*")
#: Units that say what turns: pint converts them to rad/s as they are.
_TURNING = {"radian", "degree", "turn", "revolution", "revolutions_per_minute"}
_SPEED_EXAMPLES = "'1500 rpm', '1500 min^-1', '25 rev/s' or '157 rad/s'"


_BARE_SPEED = (f"expected a rotational speed with its unit: {_SPEED_EXAMPLES} (a bare number "
               "may be rpm or rad/s, a factor 9.55)")


def _celsius(value):
    """A temperature in deg C: a plain number is deg C already; a string is read with its unit
    by pint's offset-aware conversion ("353.15 K" and "176 degF" are 80 deg C); a bool is no
    temperature (pydantic would read true as 1 deg C)."""
    expected = "expected a temperature such as 80 or \"80 degC\""
    if isinstance(value, bool):
        raise ValueError(expected)
    if not isinstance(value, str) or is_bare(value):
        return value
    match = re.fullmatch(r"\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)\s*", value)
    if match is None:
        raise ValueError(expected)
    ureg = registry()
    try:  # number and unit apart: pint refuses "80 degC" as a product with an offset unit
        quantity = ureg.Quantity(float(match[1]), match[2])
    except (pint.errors.PintError, ValueError, AttributeError, TypeError):
        raise ValueError(expected) from None
    if quantity.dimensionality != ureg.kelvin.dimensionality:
        raise ValueError(expected)
    return float(quantity.to("degC").magnitude)


def _rotational_speed(value):
    """The pinion speed in rad/s.

    Per-minute units ("2170 rpm", "2170 1/min", "2170 min^-1") count revolutions; units with a
    turn or an angle ("25 rev/s", "227 rad/s") convert as such. A bare number ("1450") and a
    per-second unit that names no turn ("25 Hz", "227 1/s") are refused: the one may be rpm or
    rad/s (a bare 1450 meant in rpm was read as 1450 rad/s, 9.55 times too fast), the other
    revolutions or radians (a factor 2 pi; "25 Hz" was read as 25 rad/s).
    """
    if not isinstance(value, str):
        if isinstance(value, int | float) and not isinstance(value, bool):
            raise ValueError(_BARE_SPEED)
        raise ValueError(f"expected a rotational speed such as {_SPEED_EXAMPLES}")
    try:
        float(value)
    except ValueError:
        pass
    else:  # "1450": a bare number in a string
        raise ValueError(_BARE_SPEED)
    match = _PER_MINUTE.fullmatch(value)
    if match:
        try:
            return float(match.group(1)) * 2.0 * math.pi / 60.0
        except ValueError:
            raise ValueError("expected a speed like \"2170 rpm\"") from None
    text = re.sub(r"\brev\b|\br\b|\brps\b", "turn", value.replace("rps", "turn/s"))
    try:
        q = registry().Quantity(text.strip())
        turning = bool(_TURNING & {name for name, _ in q.unit_items()})
        rad_per_s = float(q.to("rad/s").magnitude)
    except Exception:  # pint raises many kinds on odd text
        raise ValueError(f"expected a rotational speed such as {_SPEED_EXAMPLES}") from None
    if not turning:
        raise ValueError(f"expected a unit that says what turns: {_SPEED_EXAMPLES} (a bare "
                         "per-second unit such as '25 Hz' may count revolutions or radians)")
    return rad_per_s


def _power(value) -> float | None:
    """``value`` in W where it is a text quantity of power ("50 kW", "30 hp"), else None."""
    if not isinstance(value, str):
        return None
    try:
        q = registry().Quantity(value.strip())
        return float(q.to("W").magnitude)
    except Exception:  # pint raises many kinds on odd text; not a power: the unit check decides
        return None


#: Bulk temperature of the teeth, deg C, from which it is doubted: gear teeth run at about
#: 40-150 deg C (sump or jet oil plus 10-30 K), and mineral and synthetic gear oils oxidise
#: fast and approach their flash points above about 200 deg C; a bare number this large is
#: most often kelvin (400 K = 126.85 deg C).
HOT_BULK_TEMPERATURE = 200.0


class OperationSpec(BareNumbers):
    """``[operation]``: pinion ``torque``, pinion ``speed`` (with its unit: rpm, rad/s), the
    ``bulk_temperature`` of the teeth in deg C (the lubricant's eta0 is taken at it)."""

    torque: Quantity("moment", gt=0)
    """Pinion torque ("318 N m", "2800 lbf in"); a power ("50 kW") is refused with the torque
    it means at the pinion speed."""
    speed: Annotated[float, Field(gt=0, json_schema_extra={"unit": "rad/s",
                                                           "type": "quantity"})]
    """Pinion speed with its unit: "2170 rpm", "2170 min^-1", "36 rev/s" or "227 rad/s"; a
    bare number (rpm or rad/s?), "25 Hz" and "227 1/s" (revolutions or radians?) are
    refused."""
    bulk_temperature: Annotated[float, Field(gt=-100, lt=1000,
                                             json_schema_extra={"unit": "°C",
                                                                "type": "number or temperature"})
                                ] = 90.0
    """Bulk temperature of the teeth: a number in deg C, or with its unit ("80 degC",
    "353.15 K", "176 degF"); the lubricant's eta0 is taken at it. From 200 deg C it is warned
    (a bare 400 with its kelvin reading, 126.85 deg C)."""

    def unit_doubts(self, key: str) -> list[str]:
        """A line when the bulk temperature is at least :data:`HOT_BULK_TEMPERATURE`: written
        bare (read in deg C) with its reading in kelvin, else as hotter than gear teeth run.

        Parameters
        ----------
        key : str
            The table's name, ``"operation"``.

        Returns
        -------
        list of str
            One line, or none.
        """
        celsius = self.bulk_temperature
        if celsius < HOT_BULK_TEMPERATURE:
            return []
        hot = ("hotter than gear teeth run (about 40-150 deg C; gear oils oxidise fast and "
               f"near their flash points from about {HOT_BULK_TEMPERATURE:g} deg C), and the "
               "contact temperatures add the flash temperature to it")
        raw = self.bare("bulk_temperature")
        if raw is None:
            return [f"{key}.bulk_temperature: {celsius:.4g} deg C is {hot}; check the value"]
        return [f"{key}.bulk_temperature: the bare number {raw:g} is read in deg C, {hot}; "
                f"read in kelvin it is {raw - 273.15:.4g} deg C: write \"{raw:g} K\" if kelvin "
                "was meant"]

    _speed = field_validator("speed", mode="before")(lambda cls, v: _rotational_speed(v))
    _bulk_temperature = field_validator("bulk_temperature", mode="before")(
        lambda cls, v: _celsius(v))

    @model_validator(mode="before")
    @classmethod
    def _not_a_power(cls, data):
        """A power given as the torque ("50 kW", "30 hp") is refused with the torque it means
        at the pinion speed, T = P / omega (the unit check named only the dimension:
        "expected a quantity convertible to N*m, got '50 kW'"), and so is a ``power`` key in
        place of the torque (it read "operation.torque: missing")."""
        if not isinstance(data, dict):
            return data
        key = "torque" if "torque" in data or "power" not in data else "power"
        watts = _power(data.get(key))
        if watts is None:
            return data
        try:
            omega = _rotational_speed(data.get("speed"))
        except ValueError:
            give = "T = P / omega (P in W, omega in rad/s)"
        else:
            give = (f"\"{watts / omega:.4g} N m\" (T = P / omega at the pinion speed "
                    f"{data['speed']})")
        raise ValueError(f"a torque in operation.torque, not the power {data[key]!r} "
                         f"({watts / 1e3:.4g} kW): give torque = {give}")


class RoughnessSpec(CaseModel):
    """``[roughness]``: which parameter of the surfaces' profiles enters lambda (``ra`` or
    ``rq``) and how the two combine (``rss`` sqrt(s1^2 + s2^2) or ``mean``)."""

    parameter: Literal["ra", "rq"] = "ra"
    """Profile parameter of the flanks that enters lambda: "ra" or "rq"."""
    combination: Literal["rss", "mean"] = "rss"
    """How the two flanks' roughness combine: "rss" sqrt(s1^2 + s2^2) or "mean" (ISO/TR 15144-1)."""


class FrictionSpec(CaseModel):
    """``[friction]``: boundary friction coefficient and the lambda range of mixed friction."""

    boundary: Annotated[Number, Field(ge=0, le=1)] = 0.1
    """Boundary friction coefficient."""
    boundary_lambda: Annotated[Number, Field(ge=0)] = 1.0
    """Lambda below which the asperities carry all the load."""
    full_film_lambda: Annotated[Number, Field(gt=0)] = 3.0
    """Lambda above which the film carries all the load."""

    @model_validator(mode="after")
    def _order(self):
        if not self.full_film_lambda > self.boundary_lambda:
            raise ValueError("expected full_film_lambda > boundary_lambda")
        return self


#: A positive value of pinion and wheel.
_Pair = tuple[Annotated[Number, Field(gt=0)], Annotated[Number, Field(gt=0)]]


#: Young's moduli read as steel's where ``[thermal]`` is left at its steel defaults, Pa
#: (carbon, alloy and case-hardening steels 200-215 GPa; cast irons, bronzes, titanium and
#: polymers lie below it).
STEEL_MODULUS_RANGE = (190e9, 220e9)

#: The ``[thermal]`` keys whose defaults are steel's.
THERMAL_KEYS = ("conductivity", "density", "specific_heat")


class ThermalSpec(CaseModel):
    """``[thermal]``: conductivity (W/(m K)), density (kg/m^3) and specific heat (J/(kg K)) of
    pinion and wheel (default steel: 45, 7850, 460; a body whose Young's modulus is not
    steel's, 190-220 GPa, is warned where a key is left at that default), and the heat-source
    ``profile``."""

    conductivity: _Pair = Field((45, 45), json_schema_extra={"unit": "W/(m*K)"})
    """Thermal conductivity [pinion, wheel] in W/(m K)."""
    density: _Pair = Field((7850, 7850), json_schema_extra={"unit": "kg/m^3"})
    """Density [pinion, wheel] in kg/m^3."""
    specific_heat: _Pair = Field((460, 460), json_schema_extra={"unit": "J/(kg*K)"})
    """Specific heat [pinion, wheel] in J/(kg K)."""
    profile: Literal["semi-elliptic", "uniform"] = "semi-elliptic"
    """Heat-source profile of the flash temperature: "semi-elliptic" or "uniform"."""

    @field_validator(*THERMAL_KEYS, mode="before")
    @classmethod
    def _plain_pair(cls, value, info):
        """A pair [pinion, wheel] of plain SI numbers: a single number or a quantity with its
        unit is refused in words (it read "expected a valid tuple, got 45" and "expected a
        valid number, got '45 W/(m K)'"; units are not read for thermal properties)."""
        spec = cls.model_fields[info.field_name]
        unit = spec.json_schema_extra["unit"]
        if not isinstance(value, list | tuple) or len(value) != 2:
            raise ValueError(f"expected a pair [pinion, wheel] of plain numbers in {unit}, "
                             f"e.g. {list(spec.default)} for steel on steel")
        if any(isinstance(v, str) for v in value):
            raise ValueError(f"expected plain numbers in {unit} (the unit is not read for "
                             "thermal properties: write the SI value)")
        return value


class GearEHLSpec(CaseModel):
    """``[ehl]``: ``points`` along A-E and the steady mesh (:class:`asperity.gears.EHLMesh`)."""

    points: Annotated[Integer, Field(ge=5, le=400)] = 25
    """Points along the path of contact A-E."""
    nx: Annotated[Integer, Field(ge=17, le=4097)] = 129
    """Nodes along x of each steady EHL solve."""
    ny: Annotated[Integer, Field(ge=9, le=1025)] = 33
    """Nodes along y of each steady EHL solve."""
    levels: Annotated[Integer, Field(ge=1, le=5)] = 2
    """Grids in the multilevel sequence."""
    x_min: Annotated[Number, Field(lt=-1.0, ge=-20.0)] = -2.5
    """Inlet end of the domain in Hertz semi-axes a."""
    x_max: Annotated[Number, Field(gt=1.0, le=20.0)] = 1.5
    """Outlet end of the domain in Hertz semi-axes a."""
    tolerance: Annotated[Number, Field(gt=0, lt=1)] = 1e-5
    """Relative convergence tolerance of each steady solve."""
    max_sweeps: Annotated[Integer, Field(ge=100, le=200_000)] = 20_000
    """Sweep limit of each steady solve."""
    damping: Annotated[Number, Field(gt=0, le=1)] = 0.3
    """Relaxation damping of the steady solves."""
    adapt: bool = True
    """Move the inlet of a line contact upstream to Hamrock & Dowson's fully flooded distance
    where it lies beyond x_min, at the same spacing (docs/gears.md); false: nx nodes over
    x_min..x_max everywhere."""

    @model_validator(mode="after")
    def _levels(self):
        step = 2 ** (self.levels - 1)
        if (self.nx - 1) % step or (self.nx - 1) // step < 8:
            raise ValueError(f"expected nx = {step} m + 1 with m >= 8 for levels = "
                             f"{self.levels}")
        return self

    def mesh(self, ny: int | None = None) -> EHLMesh:
        """The :class:`~asperity.gears.path.EHLMesh`."""
        return EHLMesh(nx=self.nx, ny=self.ny if ny is None else ny, levels=self.levels,
                       x_min=self.x_min, x_max=self.x_max, tol=self.tolerance,
                       max_sweeps=self.max_sweeps, damping=self.damping, adapt=self.adapt)


class HandoffSpec(CaseModel):
    """``[handoff]``: the point whose transient mixed-EHL case ``asperity gear
    --emit-transient`` writes: ``at`` = ``"pitch"``, ``"min-lambda"``, ``"max-flash"`` or a
    pinion roll angle (``"24 deg"``), with the transient mesh, time stepping and solver keys."""

    at: str = "min-lambda"
    """Point of the transient hand-off: "pitch", "min-lambda", "max-flash" or a pinion roll angle
    ("24 deg")."""
    nx: Annotated[Integer, Field(ge=9, le=8193)] = 129
    """Nodes along x of the transient case (default 129, dx = a/32: at the FZG example's
    start of contact the steady line-contact start does not converge on finer meshes); raised
    to 32 m + 1 nodes where the spacing would exceed the surfaces' autocorrelation length / 3.5
    (docs/gears.md)."""
    ny: Annotated[Integer, Field(ge=1, le=4097)] = 65
    """Nodes along y of the transient case."""
    x_min: Annotated[Number, Field(lt=-1.0, ge=-100.0)] = -2.5
    """Inlet end of the transient domain in Hertz semi-axes a."""
    x_max: Annotated[Number, Field(gt=1.0, le=100.0)] = 1.5
    """Outlet end of the transient domain in Hertz semi-axes a."""
    time: TimeSpec = TimeSpec()
    """Time stepping of the transient case."""
    solver: TransientSolverSpec | None = None
    """Per-step solver keys of the transient case (the keys given are written; a line contact
    gets max_sweeps = 2000 unless given)."""

    @field_validator("at")
    @classmethod
    def _point(cls, value):
        if value in ("pitch", "min-lambda", "max-flash"):
            return value
        try:
            to_si(value, "angle", "at")
        except InputError:
            raise ValueError('expected "pitch", "min-lambda", "max-flash" or a roll angle '
                             'such as "24 deg"') from None
        return value

    def roll_angle(self) -> float | None:
        """The roll angle (rad) when ``at`` names one, else None."""
        if self.at in ("pitch", "min-lambda", "max-flash"):
            return None
        return to_si(self.at, "angle", "at")


class GearCase(CaseHeader):
    """``analysis = "gear"``: a gear pair along its path of contact (module notes)."""

    analysis: Literal["gear"]
    """Selects the gear-pair analysis."""
    title: str = "Gear pair along the path of contact"
    gear: GearSpec
    """The involute gear pair."""
    operation: OperationSpec
    """Torque, speed and temperature."""
    body1: MaterialSpec = MaterialSpec(youngs_modulus=206e9, poisson_ratio=0.3)
    """Pinion material (default steel)."""
    body2: MaterialSpec = MaterialSpec(youngs_modulus=206e9, poisson_ratio=0.3)
    """Wheel material (default steel)."""
    lubricant: LubricantSpec
    """Lubricant properties (as for ehl-steady)."""
    surface1: MovingSurfaceSpec
    """Roughness of the pinion flank."""
    surface2: MovingSurfaceSpec
    """Roughness of the wheel flank."""
    roughness: RoughnessSpec = RoughnessSpec()
    """How the flank roughness enters lambda."""
    friction: FrictionSpec = FrictionSpec()
    """Mixed-friction model."""
    thermal: ThermalSpec = ThermalSpec()
    """Thermal properties for the flash temperature."""
    ehl: GearEHLSpec = GearEHLSpec()
    """Points along A-E and the steady EHL mesh."""
    handoff: HandoffSpec = HandoffSpec()
    """The transient mixed-EHL case written by asperity gear --emit-transient."""

    @model_validator(mode="after")
    def _rough(self):
        for k, spec in enumerate((self.surface1, self.surface2), start=1):
            if spec.kind == "smooth" and spec.waviness is None:
                raise ValueError(f"expected a rough surface{k} (lambda needs its roughness)")
        return self

    def pair(self) -> GearPair:
        """The gear pair."""
        return self.gear.pair()

    def bodies(self) -> tuple[Material, Material]:
        """Pinion and wheel."""
        return self.body1.material(), self.body2.material()

    def thermal_notes(self) -> list[str]:
        """A ``thermal`` line for each body whose Young's modulus lies outside
        :data:`STEEL_MODULUS_RANGE` while a ``[thermal]`` key it needs was left at the steel
        default: its thermal contact coefficient B = sqrt(k rho c), and with it Blok's flash
        temperature (:mod:`asperity.gears.thermal`), would be steel's. A steel pinion on a
        bronze wheel ran as steel on steel without a word, and a steel pinion on a PA66 wheel
        (B 696 against 12 750 W s^0.5/(m^2 K)) had flash temperatures 1.6-3.3 times too low
        (docs/gears.md)."""
        missing = [f"thermal.{key}" for key in THERMAL_KEYS
                   if key not in self.thermal.model_fields_set]
        if not missing:
            return []
        low, high = STEEL_MODULUS_RANGE
        lines = []
        for k, (role, spec) in enumerate((("pinion", self.body1), ("wheel", self.body2))):
            if low <= spec.youngs_modulus <= high:
                continue
            name = "" if spec.name == "material" else f", {spec.name!r}"
            lines.append(
                f"thermal: the {role} (body{k + 1}{name}) has E = "
                f"{spec.youngs_modulus / 1e9:.4g} GPa, outside steel's {low / 1e9:g}-"
                f"{high / 1e9:g} GPa (the limit of the steel defaults), but "
                f"{', '.join(missing)} {'was' if len(missing) == 1 else 'were'} left at "
                "steel's (45 W/(m K), 7850 kg/m^3, 460 J/(kg K)), so the flash and contact "
                f"temperatures assume a steel {role}; give its values as the "
                f"{('first', 'second')[k]} of each pair (a polymer's B = sqrt(k rho c) is "
                "about 1/18 of steel's: a steel pinion on a PA66 wheel has 1.6-3.3 times the "
                "flash temperature of a steel wheel)")
        return lines

    def thermal_model(self) -> Thermal:
        """The :class:`~asperity.gears.path.Thermal` of the case."""
        t = self.thermal
        return Thermal(conductivity=t.conductivity, density=t.density,
                       specific_heat=t.specific_heat,
                       bulk_temperature=self.operation.bulk_temperature, profile=t.profile)
