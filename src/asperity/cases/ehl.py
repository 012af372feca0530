"""Case files of lubricated (EHL) contacts: lubricant, contact, speeds, grid and solver tables.

The tables :class:`LubricantSpec`, :class:`ContactSpec` and :class:`SpeedSpec`, and the base
:class:`EHLCaseBase` that combines them with the bodies into a
:class:`~asperity.ehl.PointContact` or :class:`~asperity.ehl.LineContact`, are shared by every
EHL analysis; :class:`EHLSteadyCase` (``analysis = "ehl-steady"``) adds the mesh and the solver
options of :func:`asperity.ehl.solve_steady`.

Example (the smooth gear-disk contact of Holmes et al. 2005, Table 1)::

    analysis = "ehl-steady"
    reduced_modulus = "227 GPa"

    [contact]
    type = "point"
    rx = "19.1 mm"
    ry = "151 mm"
    load = "962 N"

    [speeds]
    u = "25 m/s"        # mean entrainment speed (u1 + u2)/2
    xi = 0.25           # slide/roll ratio (u1 - u2)/u

    [lubricant]
    eta0 = "0.005 Pa s"
    alpha = "11.1 1/GPa"
    tau0 = "10 MPa"

    [grid]
    nx = 257            # or cells_per_a = 64 (dx = a/64)
    ny = 129            # or cells_per_b = 32

    [solver]
    levels = 3
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import BeforeValidator, Field, field_validator, model_validator

from ..ehl.lubricant import DH_GAMMA, DH_LAMBDA, ROELANDS_CHI, ROELANDS_KAPPA, Lubricant
from ..ehl.problem import MAX_BOUND as PROBLEM_MAX_BOUND
from ..ehl.problem import LineContact, PointContact
from ..errors import InputError
from ..formatting import format_quantity
from ..materials import Material
from ..units import to_si
from .bodies import MaterialSpec
from .doubts import BARE_VISCOSITY, BareNumbers, CurvedBody
from .fields import CaseHeader, CaseModel, Integer, Number, Quantity

__all__ = [
    "ALPHA_MAX",
    "BARE_LINE_LOAD",
    "ELLIPTICITY_FIT",
    "ELLIPTICITY_POWER",
    "MAX_NODES",
    "MAX_NX",
    "MAX_NY",
    "ContactSpec",
    "EHLCaseBase",
    "EHLGridSpec",
    "EHLSteadyCase",
    "LubricantSpec",
    "SWAPPED_ELLIPTICITY",
    "SolverSpec",
    "SpeedSpec",
    "check_node_count",
]


#: Most nodes of an EHL case's mesh (four times the seed's 801 x 201).
MAX_NODES = 801 * 201 * 4
#: Most nodes along x and across y of an EHL case's mesh.
MAX_NX, MAX_NY = 8193, 4097


def check_node_count(nx: int, ny: int, chosen: bool, domain=None):
    """Refuse a mesh of more than :data:`MAX_NODES` nodes (as a validator's ValueError);
    ``chosen``: the default mesh the contact's film and features asked for, which says which
    keys to set. A steady case whose bare ``alpha = 28`` (1/Pa) made a 1.4 m film estimate
    asked for 542,009 x 42,345 nodes and ran out of memory without a word.

    ``domain``: the default domain that mesh is on, in Hertz semi-axes
    ``((x_min, x_max), (y_min, y_max))`` (y None for a line contact), named in the line: a
    [grid] table that sets only grid.nx and grid.ny keeps it."""
    if nx * ny > MAX_NODES:
        where = ""
        if domain is not None:
            (x0, x1), y_bounds = domain
            where = f", on its domain x = {x0:.3g} a..{x1:.3g} a" + (
                "" if y_bounds is None else f", y = {y_bounds[0]:.3g} b..{y_bounds[1]:.3g} b")
        shrink = math.sqrt(MAX_NODES / (nx * ny))
        fit_nx, fit_ny = (max(3, 2 * math.floor((n - 1) * shrink / 2) + 1) for n in (nx, ny))
        why = "" if not chosen else (
            f" (the default mesh {nx} x {ny} for the contact's film and the surfaces' "
            f"features{where}; check the lubricant's and the contact's units, or set grid.nx "
            f"and grid.ny: at most {fit_nx} x {fit_ny} in the same proportions, the finer the "
            "better)")
        raise ValueError(f"expected at most {MAX_NODES} nodes, got {nx * ny}{why}")


#: Largest pressure-viscosity coefficient a case takes, 1/Pa (1000 1/GPa, twenty times that
#: of a traction fluid): above it a bare number in 1/Pa was meant in 1/GPa.
ALPHA_MAX = 1e-6

#: Largest limit density ratio ``gamma / lambda`` of the Dowson-Higginson law a case takes
#: (the law's own constants: 1.35; liquids compress by some 20-35 % at 1-3 GPa): above it a
#: constant was mistyped (``gamma = "2270 1/GPa"`` made a 5.2 nm film of a 128 nm one).
DH_LIMIT_RATIO_MAX = 2.0

#: Largest Dowson-Higginson ``lambda`` a case takes, 1/Pa (100 1/GPa: half the compression
#: reached by 10 MPa; the law's own 1.68 1/GPa).
DH_LAMBDA_MAX = 1e-7


class LubricantSpec(BareNumbers):
    """``[lubricant]``: viscosity and density laws and the Eyring stress (seed Eqs. 3-4).

    ``eta0`` ambient viscosity, ``alpha`` pressure-viscosity coefficient (``"11.1 1/GPa"``),
    ``viscosity_model`` ``"roelands"`` (constants ``kappa``, ``chi``) or ``"barus"``,
    ``density_model`` ``"dowson-higginson"`` (constants ``gamma``, ``lambda``) or
    ``"incompressible"``, ``tau0`` the Eyring stress (``"none"`` or absent: Newtonian).
    """

    name: str = "lubricant"
    """Name of the lubricant, shown in reports."""
    eta0: Quantity("viscosity", gt=0)
    """Viscosity at ambient pressure."""
    alpha: Quantity("inverse_pressure", ge=0)
    """Pressure-viscosity coefficient, at most 1000 1/GPa (e.g. "11.1 1/GPa"; a bare number
    is 1/Pa)."""
    viscosity_model: Literal["roelands", "barus"] = "roelands"
    """Viscosity law: "roelands" (constants kappa, chi) or "barus"."""
    kappa: Quantity("viscosity", gt=0) = ROELANDS_KAPPA
    """Roelands constant kappa (the viscosity limit at infinite pressure)."""
    chi: Quantity("inverse_pressure", gt=0) = ROELANDS_CHI
    """Roelands constant chi (the pressure scale)."""
    density_model: Literal["dowson-higginson", "incompressible"] = "dowson-higginson"
    """Density law: "dowson-higginson" (constants gamma, lambda) or "incompressible"."""
    rho0: Quantity("density", gt=0) = 850.0
    """Density at ambient pressure."""
    gamma: Quantity("inverse_pressure", ge=0) = DH_GAMMA
    """Dowson-Higginson constant gamma."""
    lambda_: Quantity("inverse_pressure", ge=0) = Field(DH_LAMBDA, alias="lambda")
    """Dowson-Higginson constant lambda."""
    tau0: Quantity("pressure", gt=0) | None = None
    """Eyring stress (absent or "none": Newtonian)."""

    @field_validator("alpha")
    @classmethod
    def _plausible_alpha(cls, value):
        # mineral and synthetic oils lie at 5-40 1/GPa, traction fluids up to ~50; a bare
        # "alpha = 28" is 28 1/Pa, whose film estimate of 1.4 m made a default mesh of 542,009
        # x 42,345 nodes that ran out of memory without a word
        if value > ALPHA_MAX:
            raise ValueError(f"expected a pressure-viscosity coefficient of at most "
                             f"{ALPHA_MAX * 1e9:g} 1/GPa (oils: 5-50 1/GPa; a bare number is "
                             "in 1/Pa: write \"20 1/GPa\")")
        return value

    @field_validator("tau0", mode="before")
    @classmethod
    def _none_word(cls, value):
        if isinstance(value, str) and value.strip().lower() == "none":
            return None
        return value

    @model_validator(mode="after")
    def _roelands_range(self):
        if self.viscosity_model == "roelands" and not self.eta0 > self.kappa:
            raise ValueError(f"expected eta0 > kappa = {self.kappa:g} Pa s for the Roelands law "
                             '(or viscosity_model = "barus")')
        return self

    @model_validator(mode="after")
    def _density_constants(self):
        """rho/rho0 = (1 + gamma p) / (1 + lambda p) rises with p to gamma/lambda only for
        gamma >= lambda; a swapped pair or gamma = 0 made a density that falls (films 15-28 %
        too thick, converged without a word)."""
        if self.density_model != "dowson-higginson":
            return self
        gamma, lam = self.gamma, self.lambda_
        if lam > DH_LAMBDA_MAX:
            raise ValueError(f"expected a Dowson-Higginson lambda of at most "
                             f"{DH_LAMBDA_MAX * 1e9:g} 1/GPa (the law's: {DH_LAMBDA * 1e9:g} "
                             f"1/GPa; a bare number is in 1/Pa), got {lam * 1e9:g} 1/GPa")
        if gamma < lam:
            raise ValueError(
                f"expected gamma >= lambda for the Dowson-Higginson density (1 + gamma p) / "
                f"(1 + lambda p), got gamma = {gamma * 1e9:g} and lambda = {lam * 1e9:g} 1/GPa: "
                "the density would fall with pressure (the law's constants: gamma = "
                f"{DH_GAMMA * 1e9:g}, lambda = {DH_LAMBDA * 1e9:g} 1/GPa; for no compression "
                'write density_model = "incompressible")')
        if gamma > DH_LIMIT_RATIO_MAX * lam:
            ratio = "unbounded" if lam == 0 else f"{gamma / lam:.3g}"
            raise ValueError(
                f"expected gamma at most {DH_LIMIT_RATIO_MAX:g} lambda (the density's limit "
                f"ratio gamma/lambda; the law's own {DH_GAMMA / DH_LAMBDA:.3g}), got "
                f"gamma = {gamma * 1e9:g} and lambda = {lam * 1e9:g} 1/GPa ({ratio})")
        return self

    def unit_doubts(self, key: str) -> list[str]:
        """The doubt of this table, named ``key`` (:func:`asperity.cases.doubts.unit_doubts`):
        a line when ``eta0`` was a bare number of at least
        :data:`~asperity.cases.doubts.BARE_VISCOSITY` Pa s; ``eta0 = 100`` is 100 Pa s, a
        bitumen's, where 100 mPa s (cP) was meant."""
        value = self.bare("eta0")
        if value is None or value < BARE_VISCOSITY:
            return []
        return [f"{key}.eta0: the bare number {value:g} is read in Pa s, "
                f"{format_quantity(value, 'Pa*s')}, more viscous than lubricants are (a bare "
                f'number is in Pa s); if mPa s (cP) were meant write "{value:g} mPa s", else '
                f'"{value:g} Pa s" to confirm']

    def unused_defaults(self, key: str = "lubricant") -> dict:
        """The defaults of this table (named ``key``) that its laws do not use, as ``{key:
        None}`` (:attr:`asperity.results.Outcome.chosen`: left out of the report's
        parameters): Roelands' constants under Barus, Dowson-Higginson's for an
        incompressible lubricant. Constants the case file sets stay listed."""
        unused = []
        if self.viscosity_model == "barus":
            unused += ["kappa", "chi"]
        if self.density_model == "incompressible":
            unused += ["gamma", "lambda_"]
        fields = type(self).model_fields
        return {f"{key}.{fields[name].alias or name}": None for name in unused
                if name not in self.model_fields_set}

    def lubricant(self) -> Lubricant:
        """The :class:`asperity.ehl.Lubricant` this table describes."""
        return Lubricant(
            viscosity=self.eta0, pressure_viscosity=self.alpha,
            viscosity_model=self.viscosity_model, roelands_kappa=self.kappa,
            roelands_chi=self.chi, density=self.rho0,
            compressible=self.density_model == "dowson-higginson", dh_gamma=self.gamma,
            dh_lambda=self.lambda_, eyring_stress=self.tau0, name=self.name,
        )


#: Hamrock & Brewe's (1983) fit of the Hertz ellipticity, ``b/a = 1.0339 (ry/rx)^0.636``,
#: and the b/a below which a point contact's radii are doubted as swapped: a ball across its
#: groove (the issue's robustness table spans b/a = 0.25-8; a user's swapped rx, ry gave
#: 0.105 and a collapsed film after 148 s).
ELLIPTICITY_FIT, ELLIPTICITY_POWER = 1.0339, 0.636
SWAPPED_ELLIPTICITY = 0.25

#: Load per length (N/m) below which a bare ``load_per_length`` is doubted: 10 N/mm, the
#: lightest rolling-element line load (an unloaded-zone roller; gear and cam contacts carry
#: 100-2000 N/mm); a bare number is N/m, and N/mm is how such loads are written.
BARE_LINE_LOAD = 1e4


class ContactSpec(CurvedBody):
    """``[contact]``: shape and load.

    ``type = "point"``: radii of relative curvature ``rx`` (entrainment direction) and ``ry``,
    normal ``load`` (N). ``type = "line"``: ``radius`` (or ``rx``) and ``load_per_length``
    (``"527 kN/m"``).
    """

    type: Literal["point", "line"] = "point"
    """"point" (rx, ry, load) or "line" (radius or rx, load_per_length)."""
    rx: Quantity("length") | None = None
    """Radius of relative curvature along x, the entrainment direction."""
    ry: Quantity("length") | None = None
    """Radius of relative curvature along y (point contact)."""
    radius: Quantity("length") | None = None
    """Radius of relative curvature of a line contact (or give rx)."""
    load: Quantity("force", gt=0) | None = None
    """Normal load of a point contact."""
    load_per_length: Quantity("force_per_length", gt=0) | None = None
    """Load per unit length of a line contact (e.g. "527 kN/m")."""

    @field_validator("rx", "ry", "radius")
    @classmethod
    def _relative_radius(cls, value):
        """A radius of relative curvature > 0, saying how a concave surface enters it: a
        ball's groove (ry = -6.24 mm) was refused as "expected more than 0 m"."""
        if value is not None and not value > 0:
            raise ValueError(
                "expected a radius of relative curvature > 0: the two surfaces' curvatures "
                "combine, 1/R = 1/r1 + 1/r2, a concave one (a groove, an outer race) with its "
                "radius negative; e.g. a 6 mm ball in a 6.24 mm groove: ry = 1/(1/6 - 1/6.24) "
                "mm = 156 mm")
        return value

    @model_validator(mode="after")
    def _complete(self):
        if self.type == "point":
            for key in ("rx", "ry", "load"):
                if getattr(self, key) is None:
                    raise ValueError(f"expected {key} for a point contact")
            for key in ("radius", "load_per_length"):
                if getattr(self, key) is not None:
                    raise ValueError(f'expected no {key} for a point contact (type = "line"?)')
        else:
            if (self.rx is None) == (self.radius is None):
                raise ValueError("expected exactly one of radius or rx for a line contact")
            if self.load_per_length is None:
                raise ValueError("expected load_per_length (N/m) for a line contact")
            for key in ("ry", "load"):
                if getattr(self, key) is not None:
                    raise ValueError(f"expected no {key} for a line contact")
        return self

    @property
    def line(self) -> bool:
        """True for a line contact."""
        return self.type == "line"

    def unit_doubts(self, key: str) -> list[str]:
        """The radii's doubts (:meth:`CurvedBody.unit_doubts`) and a line where
        ``load_per_length`` was written as a bare number below :data:`BARE_LINE_LOAD` N/m:
        a bearing user's ``load_per_length = 1000``, meant in N/mm, ran as 1 N/mm without a
        word, where the radius and eta0 beside it were doubted."""
        lines = super().unit_doubts(key)
        if self.type == "point" and self.rx and self.ry:
            k = ELLIPTICITY_FIT * (self.ry / self.rx) ** ELLIPTICITY_POWER
            if k < SWAPPED_ELLIPTICITY:
                lines.append(
                    f"{key}.rx, {key}.ry: the contact ellipse is about {1 / k:.3g} times longer "
                    f"along the entrainment (x) than across it (b/a = {k:.2g}, ry < rx), as "
                    "few rolling contacts are; rx is the radius along the rolling direction, "
                    "ry across it (a ball in its groove: ry from the groove, the larger one): "
                    "check that they are not swapped")
        value = self.bare("load_per_length")
        if value is not None and value < BARE_LINE_LOAD:
            lines.append(
                f"{key}.load_per_length: the bare number {value:g} is read in N/m, "
                f"{format_quantity(value * 1e-3, 'N')}/mm, a light line load (a bare number is "
                f'in the key\'s SI unit); if N/mm were meant write "{value:g} N/mm", else '
                f'"{value:g} N/m" to confirm')
        return lines


class SpeedSpec(CaseModel):
    """``[speeds]``: mean speed ``u`` and slide/roll ratio ``xi``, or both surface speeds.

    With ``u`` and ``xi`` (default 0, pure rolling): ``u1 = u (1 + xi/2)``,
    ``u2 = u (1 - xi/2)``, i.e. ``xi = (u1 - u2)/u``. The mean speed must be positive: a
    lubricated contact needs entrainment.
    """

    u: Quantity("speed") | None = None
    """Mean entrainment speed (u1 + u2)/2 (with xi)."""
    xi: Quantity("dimensionless") | None = None
    """Slide/roll ratio (u1 - u2)/u (default 0, pure rolling)."""
    u1: Quantity("speed") | None = None
    """Surface speed of body 1 (with u2, instead of u and xi)."""
    u2: Quantity("speed") | None = None
    """Surface speed of body 2 (with u1, instead of u and xi)."""

    @model_validator(mode="after")
    def _one_form(self):
        mean_form = self.u is not None or self.xi is not None
        surface_form = self.u1 is not None or self.u2 is not None
        if mean_form == surface_form:
            raise ValueError("expected either u (and xi) or u1 and u2")
        if surface_form and (self.u1 is None or self.u2 is None):
            raise ValueError("expected both u1 and u2")
        if mean_form and self.u is None:
            raise ValueError("expected u, the mean entrainment speed, with xi")
        if not sum(self.surface_speeds()) > 0:
            raise ValueError("expected a positive mean entrainment speed (u1 + u2)/2 > 0: a "
                             "lubricated contact needs entrainment (for a dry contact use "
                             'analysis = "normal")')
        return self

    def unit_doubts(self, key: str) -> list[str]:
        """The doubt of this table, named ``key`` (:func:`asperity.cases.doubts.unit_doubts`):
        a line when the slide/roll ratio ``xi`` is beyond 2. The surfaces then move in
        opposite directions, which rigs seldom run and a ratio meant in percent (``xi = 25``
        for 25 %) gives without a word (u1 = 13.5 m/s, u2 = -11.5 m/s at u = 1 m/s)."""
        if self.xi is None or abs(self.xi) <= 2.0:
            return []
        u1, u2 = self.surface_speeds()
        return [f"{key}.xi: the slide/roll ratio {self.xi:g} is beyond 2 (limit: at most 2 "
                f"either way), so the surfaces move in opposite directions (u1 = "
                f"{format_quantity(u1, 'm/s')}, u2 = {format_quantity(u2, 'm/s')}); a ratio "
                f'in percent is written "{self.xi:g} %" (xi = {self.xi / 100:g}), and '
                "opposite surface speeds are clearer as u1 and u2"]

    def surface_speeds(self) -> tuple[float, float]:
        """(u1, u2) in m/s."""
        if self.u1 is not None:
            return self.u1, self.u2
        xi = 0.0 if self.xi is None else self.xi
        return self.u * (1.0 + 0.5 * xi), self.u * (1.0 - 0.5 * xi)


class EHLCaseBase(CaseHeader):
    """Tables shared by the EHL analyses: bodies (or ``reduced_modulus``), contact, speeds and
    lubricant; :meth:`problem` builds the contact problem."""

    title: str = "EHL contact"
    reduced_modulus: Quantity("pressure", gt=0) | None = None
    """Reduced modulus E' (instead of [body1] and [body2])."""
    body1: MaterialSpec | None = None
    """First elastic body (or give reduced_modulus)."""
    body2: MaterialSpec | None = None
    """Second elastic body (or give reduced_modulus)."""
    contact: ContactSpec
    """Contact shape and load."""
    speeds: SpeedSpec
    """Surface speeds."""
    lubricant: LubricantSpec
    """Lubricant properties."""

    @model_validator(mode="after")
    def _bodies(self):
        bodies = (self.body1 is not None, self.body2 is not None)
        if self.reduced_modulus is None and bodies != (True, True):
            raise ValueError("expected [body1] and [body2], or reduced_modulus (E')")
        if self.reduced_modulus is not None and any(bodies):
            raise ValueError("expected either reduced_modulus or [body1]/[body2], not both")
        return self

    def bodies(self) -> tuple[Material, Material]:
        """The two bodies; ``reduced_modulus`` E' gives two equal bodies with E = E', nu = 0."""
        if self.reduced_modulus is not None:
            m = Material(self.reduced_modulus, 0.0, f"E' = {self.reduced_modulus:.4g} Pa")
            return m, m
        return self.body1.material(), self.body2.material()

    def problem(self) -> PointContact | LineContact:
        """The :class:`~asperity.ehl.PointContact` or :class:`~asperity.ehl.LineContact`."""
        u1, u2 = self.speeds.surface_speeds()
        body1, body2 = self.bodies()
        lub = self.lubricant.lubricant()
        c = self.contact
        if c.line:
            radius = c.radius if c.radius is not None else c.rx
            return LineContact(radius, c.load_per_length, u1, u2, body1, body2, lub)
        return PointContact(c.rx, c.ry, c.load, u1, u2, body1, body2, lub)


def _domain_bound(lo: float, hi: float):
    """Validator of a domain bound: a number in Hertz semi-axes within [lo, hi] (strictly
    outside the contact), or a length (``"-1.2 mm"``) kept as written and converted by
    :meth:`EHLGridSpec.domain` once the semi-axes are known."""

    def check(value):
        try:
            number = float(value)
        except (TypeError, ValueError):
            if not isinstance(value, str):
                raise ValueError("expected a number (Hertz semi-axes) or a length") from None
            try:
                to_si(value, "length", "")
            except InputError as exc:
                raise ValueError(f"expected a number (Hertz semi-axes) or {exc.expected}") from None
            return value
        if isinstance(value, bool) or not (lo <= number <= hi and abs(number) > 1.0):
            raise ValueError(f"expected a number from {lo:g} to {hi:g} (Hertz semi-axes, outside "
                             "the contact) or a length")
        return number

    return Annotated[float | str, BeforeValidator(check),
                     Field(json_schema_extra={"dimension": "length",
                                              "type": "number or quantity"})]


#: Farthest domain bound from the contact's centre, in Hertz semi-axes (a number or a length).
MAX_BOUND = PROBLEM_MAX_BOUND

LowerBound = _domain_bound(-MAX_BOUND, -1.0)
UpperBound = _domain_bound(1.0, MAX_BOUND)


class EHLGridSpec(CaseModel):
    """``[grid]``: nodes and domain of an EHL solve, in units of the Hertz semi-axes.

    The domain is ``x_min a < x < x_max a``, ``y_min b < y < y_max b`` (y is unused for a line
    contact) and must hold the Hertz contact. A bound may also be a length
    (``x_min = "-1.2 mm"``), taken as it is. A bound the table does not set is the contact's
    own (:meth:`asperity.ehl.PointContact.default_domain`: the seed's -2.5a..1.5a, -2b..2b for
    the gear case, a longer inlet and wider sides for a thick film), the domain a case without
    a [grid] table is solved on.
    The mesh is ``nx`` x ``ny`` nodes with end nodes on the bounds, or a spacing
    ``cells_per_a`` (dx = a/cells_per_a) and ``cells_per_b`` over the domain; the seed's mesh
    a/200 x b/50 on -2.5a..1.5a, -2b..2b is ``nx = 801``, ``ny = 201``. A line contact has
    ``ny = 1``.
    """

    nx: Annotated[Integer, Field(ge=9, le=MAX_NX)] = 129
    """Nodes along x. A steady case that sets neither nx, ny nor a spacing gets the mesh its
    regime asks for on the domain instead of 129 x 65."""
    ny: Annotated[Integer, Field(ge=1, le=MAX_NY)] = 65
    """Nodes along y; 1 for a line contact."""
    cells_per_a: Annotated[Number, Field(gt=0, le=MAX_NX)] | None = None
    """Cells per Hertz semi-axis a along x (dx = a/cells_per_a), instead of nx."""
    cells_per_b: Annotated[Number, Field(gt=0, le=MAX_NY)] | None = None
    """Cells per Hertz semi-axis b along y (dy = b/cells_per_b), instead of ny."""
    x_min: LowerBound | None = None
    """Inlet end of the domain in Hertz semi-axes a (a number) or as a length (e.g. "-1.2 mm");
    default the contact's own inlet (-2.5 a for the seed's gear case)."""
    x_max: UpperBound | None = None
    """Outlet end of the domain in Hertz semi-axes a (a number) or as a length; default the
    contact's own (1.5 a; further for a nearly rigid contact)."""
    y_min: LowerBound | None = None
    """Lower side of the domain in Hertz semi-axes b (a number) or as a length; default the
    contact's own (-2 b for the seed's gear case)."""
    y_max: UpperBound | None = None
    """Upper side of the domain in Hertz semi-axes b (a number) or as a length; default the
    contact's own (2 b for the seed's gear case)."""

    @model_validator(mode="after")
    def _nodes_or_spacing(self):
        for cells_key, nodes_key in (("cells_per_a", "nx"), ("cells_per_b", "ny")):
            if getattr(self, cells_key) is not None and nodes_key in self.model_fields_set:
                raise ValueError(f"expected either {nodes_key} or {cells_key}, not both")
        return self

    @property
    def nodes_given(self) -> bool:
        """True when the table sets the mesh (``nx``, ``ny``, ``cells_per_a`` or
        ``cells_per_b``); otherwise the analysis chooses it for the contact."""
        return bool({"nx", "ny", "cells_per_a", "cells_per_b"} & self.model_fields_set)

    def nodes(self, problem: PointContact | LineContact) -> tuple[int, int]:
        """(nx, ny) of the solve of ``problem`` on :meth:`domain`: the table's node counts, or
        ``span / semi-axis * cells + 1`` nodes for a spacing; ny = 1 for a line contact.

        Raises
        ------
        ValueError
            Where a spacing asks for fewer or more nodes than ``nx`` or ``ny`` may have.
        """
        (x0, x1), (y0, y1) = self.domain(problem)
        nx = self._spaced("cells_per_a", "nx", x1 - x0, problem.a, MAX_NX)
        if isinstance(problem, LineContact):
            return nx, 1
        return nx, self._spaced("cells_per_b", "ny", y1 - y0, problem.b, MAX_NY)

    def _spaced(self, cells_key: str, nodes_key: str, span: float, semi: float,
                most: int) -> int:
        cells = getattr(self, cells_key)
        if cells is None:
            return getattr(self, nodes_key)
        nodes = round(span / semi * cells) + 1
        least = 9 if nodes_key == "nx" else 2
        if not least <= nodes <= most:
            raise ValueError(f"expected grid.{cells_key} giving {least} to {most} nodes over "
                             f"the domain's {span / semi:.4g} semi-axes; got {cells:g}, "
                             f"{nodes} nodes")
        return nodes

    def domain(self, problem: PointContact | LineContact):
        """((x0, x1), (y0, y1)) in m of the solve of ``problem`` (y0 = y1 = 0 for a line
        contact): the table's bounds in the Hertz semi-axes, and where it sets none the
        contact's own (:meth:`asperity.ehl.PointContact.default_domain`). A bound given as a
        length is taken as it is; it must lie outside the Hertz contact.
        """
        (x0, x1), (y0, y1) = problem.default_domain()
        x = (self._bound("x_min", problem.a, x0), self._bound("x_max", problem.a, x1))
        if isinstance(problem, LineContact):
            return x, (0.0, 0.0)
        return x, (self._bound("y_min", problem.b, y0), self._bound("y_max", problem.b, y1))

    def _bound(self, key: str, semi_axis: float, default: float) -> float:
        value = getattr(self, key)
        if value is None:
            return default
        if not isinstance(value, str):
            return value * semi_axis
        metres = to_si(value, "length", f"grid.{key}")
        lower = key.endswith("_min")
        if not abs(metres) > semi_axis or (metres < 0) != lower:
            edge = -semi_axis if lower else semi_axis
            raise InputError(f"grid.{key}", f"a bound outside the Hertz contact, "
                             f"{'below' if lower else 'above'} {edge:.4g} m", value)
        if abs(metres) > MAX_BOUND * semi_axis:  # as for a bound given in semi-axes
            raise InputError(f"grid.{key}", f"a bound within {MAX_BOUND:g} Hertz semi-axes "
                             f"({MAX_BOUND * semi_axis:.4g} m) of the centre", value)
        return metres


class SolverSpec(CaseModel):
    """``[solver]``: options of :func:`asperity.ehl.solve_steady`.

    ``levels`` grids in the sequence (node counts ``2^(levels-1) m + 1``), ``tolerance``,
    ``max_sweeps`` per grid (default 5000 for a point contact and 40000 for a line contact,
    whose point relaxation needs many sweeps), ``method`` ``"line"``/``"point"`` (default by
    contact type) and the ``boundary_friction`` coefficient of dry nodes.
    """

    levels: Annotated[Integer, Field(ge=1, le=6)] = 1
    """Grids in the multilevel sequence (node counts 2^(levels-1) m + 1); without levels,
    chosen with the mesh, the default one or the [grid] table's: up to 4 grids, each halved
    while the coarsest keeps 33 nodes along x and 17 across."""
    tolerance: Annotated[Number, Field(gt=0, lt=1)] = 1e-5
    """Relative convergence tolerance."""
    max_sweeps: Annotated[Integer, Field(ge=1, le=200_000)] | None = None
    """Sweep limit per grid (default 5000 for a point contact, 40000 for a line contact)."""
    method: Literal["line", "point"] | None = None
    """Relaxation: "line" or "point" (default by contact type)."""
    boundary_friction: Annotated[Number, Field(ge=0, le=10)] = 0.1
    """Friction coefficient of dry (contact) nodes."""

    def sweep_limit(self, line: bool) -> int:
        """``max_sweeps``, or its default for the contact type."""
        if self.max_sweeps is not None:
            return self.max_sweeps
        return 40_000 if line else 5_000


class ReferenceSpec(CaseModel):
    """``[reference]``: published numbers for this case, compared in the report."""

    source: str
    """Where the published numbers come from."""
    central_film: Quantity("length", gt=0) | None = None
    """Published central film thickness."""
    minimum_film_centreline: Quantity("length", gt=0) | None = None
    """Published minimum film thickness on the centre line."""
    minimum_film: Quantity("length", gt=0) | None = None
    """Published minimum film thickness."""
    max_pressure: Quantity("pressure", gt=0) | None = None
    """Published maximum pressure."""
    tolerance: Quantity("dimensionless", gt=0, lt=1) = 0.05
    """Relative tolerance of the comparison (0.05 or "5 %")."""


class EHLSteadyCase(EHLCaseBase):
    """``analysis = "ehl-steady"``: smooth steady EHL of a point or line contact."""

    analysis: Literal["ehl-steady"]
    """Selects the steady smooth EHL analysis."""
    title: str = "Steady EHL contact"
    grid: EHLGridSpec = EHLGridSpec()
    """Mesh and domain (in Hertz semi-axes). Without a [grid] table both follow the contact:
    inlet from Hamrock-Dowson's fully flooded distance, spacing from the estimated film,
    grid sequencing (docs/ehl-robustness.md); bounds a [grid] table does not set follow it
    too."""
    solver: SolverSpec = SolverSpec()
    """Solver options."""
    reference: ReferenceSpec | None = None
    """Published numbers to compare with."""

    @property
    def regime_mesh(self) -> bool:
        """True when the case has no [grid] table: domain, mesh and (unless ``solver.levels``
        is given) grid sequencing are the problem's defaults
        (:meth:`asperity.ehl.PointContact.default_nodes`)."""
        return "grid" not in self.model_fields_set

    @property
    def regime_nodes(self) -> bool:
        """True when no node count is given (no [grid] table, or one that sets only the
        domain): the mesh is the problem's default mesh on the domain, not 129 x 65 nodes."""
        return not self.grid.nodes_given

    def solve_options(self, problem) -> dict:
        """``nx``, ``ny``, ``domain`` and ``levels`` for :func:`asperity.ehl.solve_steady`
        (None where the solver chooses: the mesh from the regime, see :attr:`regime_mesh`, and
        the grid sequence unless ``solver.levels`` is given)."""
        levels = self.solver.levels if "levels" in self.solver.model_fields_set else None
        if self.regime_mesh:
            return {"nx": None, "ny": None, "domain": None, "levels": levels}
        nx, ny = (None, None) if self.regime_nodes else self.grid.nodes(problem)
        return {"nx": nx, "ny": ny, "levels": levels, "domain": self.grid.domain(problem)}

    @model_validator(mode="after")
    def _mesh(self):
        line = self.contact.line
        if line and "ny" in self.grid.model_fields_set and self.grid.ny != 1:
            raise ValueError("expected grid.ny = 1 (or no ny) for a line contact")
        try:
            problem = self.problem()
            options = self.solve_options(problem)
        except InputError as exc:
            raise ValueError(f"expected {exc.expected} ({exc.field})") from None
        step = 2 ** (self.solver.levels - 1)
        given = [] if self.regime_nodes else zip(("nx", "ny"), (options["nx"], options["ny"]),
                                                 strict=True)
        for key, n in given:
            if key == "ny" and line:
                continue
            if (n - 1) % step or (n - 1) // step + 1 < 9:
                raise ValueError(
                    f"expected grid.{key} = {step} m + 1 with m >= 8 for solver.levels = "
                    f"{self.solver.levels} (e.g. {8 * step + 1}, {16 * step + 1}, "
                    f"{32 * step + 1}); got {n}")
        nx, ny = (options["nx"], options["ny"]) if options["nx"] is not None else \
            problem.default_nodes(options["domain"])
        domain = None
        if self.regime_mesh:
            (x0, x1), (y0, y1) = problem.default_domain()
            domain = ((x0 / problem.a, x1 / problem.a),
                      None if line else (y0 / problem.b, y1 / problem.b))
        check_node_count(nx, ny if not line else 1, self.regime_nodes, domain)
        return self
