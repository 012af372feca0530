"""Steady EHL problems: geometry, operating conditions, Hertz scales and dimensionless groups.

A problem is given in SI at the API and solved in Hertzian dimensionless variables
(Venner & Lubrecht 2000, ch. 4)::

    X = x/a, Y = y/a, P = p/p_h, H = h Rx/a^2, rho_bar = rho/rho0, eta_bar = eta/eta0

with ``a`` the Hertz half-width along x (the entrainment direction) and ``p_h`` the Hertz
maximum pressure. The film equation then reads
``H = H0 + X^2/2 + (Rx/Ry) Y^2/2 + c sum D P`` with ``c = 2 p_h Rx / (pi E' a)`` and the
Reynolds equation ``d/dX(eps_x dP/dX) + d/dY(eps_y dP/dY) - lam d(rho_bar H)/dX = 0`` with
``eps = sigma 12 eta0 Rx^3 / (rho0 a^6)`` and ``lam = 12 eta0 u_mean Rx^2 / (a^3 p_h)``.

Dimensionless groups follow Hamrock & Dowson (U, G, W) and Moes (M, L) with the mean speed
``u_mean = (u1 + u2)/2``: ``U = eta0 u_mean/(E' Rx)``, ``G = alpha E'``, ``W = w/(E' Rx^2)``
(point) or ``w'/(E' R)`` (line); point ``M = W (2U)^-3/4``, line ``M = W' (2U)^-1/2``,
``L = G (2U)^1/4``.

References
----------
C. H. Venner, A. A. Lubrecht, *Multilevel Methods in Lubrication*, Elsevier, 2000.
M. J. A. Holmes et al., J. Tribol. 127 (2005) 61-69 (the seed: Table 1, domain and mesh).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..contact.hertz import hertz_line, hertz_point
from ..errors import InputError, check_int, check_positive
from ..materials import Material, contact_modulus
from . import formulas
from .lubricant import Lubricant

__all__ = ["LineContact", "PointContact"]

#: Outlet of the default domain, in Hertz semi-axes a: the film exit and its cavitation
#: boundary lie within about 1.1 a.
OUTLET = 1.5

#: Inlet of the default domain at least this many a upstream of the centre (the seed's).
MIN_INLET = 2.5

#: Relative error of the central film, times ``H_c / dX^2``, of the discretisation on the
#: default mesh: 17 % at M = 1000, L = 10 (circular, H_c = 0.031) with dX = 1/32, 4 % with
#: 1/64 (second order); the default mesh keeps it near 2 % (docs/ehl-robustness.md).
FILM_ERROR = 5.0

#: Target relative discretisation error of the central film on the default mesh.
MESH_TARGET = 0.02

#: Side margin of the default domain beyond the Hertz contact, per unit of the fully flooded
#: inlet length (m* - 1) a (at least b): the inlet's pressure build-up spreads sideways as far
#: as it reaches upstream. With the sides at +-2 b, a circle at M = 10, L = 10 (inlet 5.8 a) had
#: its central film 2.8 % and its minimum film 4.3 % below those on +-4.4 b
#: (docs/ehl-robustness.md, "Side boundaries").
SIDE_PER_INLET = 0.5

#: Largest dY/dX of a default point-contact mesh: at 32-33 the x-line relaxation diverged for
#: the ellipses k = 5 at M = 1000 and 3000, L = 19 (Barus); at 16 and 22 it converged
#: (docs/ehl-robustness.md, "Compressible point contacts and long ellipses at large L").
MAX_CELL_ASPECT = 16.0

#: Least dY/dX of a default point-contact mesh: on nearly square cells the lagged y-couplings
#: of an Eyring oil's Poiseuille flow made the x-line relaxation diverge (docs/ehl-robustness.md,
#: "Why square cells failed").
MIN_CELL_ASPECT = 3.0


#: Farthest bound of a domain from the contact's centre, in Hertz semi-axes (the cases' limit,
#: ``cases.ehl.MAX_BOUND``; a rigid contact's default domain stops there too).
MAX_BOUND = 100.0

#: ``l = sqrt(2 Rx hc)`` (estimated film), in Hertz semi-axes a, from which a point contact's
#: default domain and mesh follow ``l`` rather than the Hertz zone: a glass ball on glass in
#: glycerol (l = 11 a, peak pressure 0.6 % of p_h) was given 1969 x 617 nodes of a/32 on
#: -60 a..1.5 a and refused (docs/ehl-robustness.md, "Rigid contacts: a default domain and
#: mesh on l").
RIGID_DEFAULT_LENGTH = 4.0

#: Largest ``alpha`` times a rigid contact's own pressure scale
#: (:func:`asperity.ehl.formulas.rigid_mean_pressure` of the estimated film) for its defaults
#: to follow ``l``: the isoviscous-rigid regime (the limit of the isoviscous comparison rows,
#: ``references.ISOVISCOUS``). A thick estimated film with a strongly piezoviscous oil (a
#: traction drive at alpha = 900 1/GPa, millimetres of film: a unit mistake, most likely)
#: keeps the EHL defaults and their refusal.
RIGID_ISOVISCOUS = 0.1

#: Largest ``alpha p_h`` (the Barus exponent at the Hertz pressure) at which a point contact
#: is also set beside Hamrock & Dowson's isoviscous-elastic (soft EHL) films
#: (:mod:`asperity.references`) and counts as soft (:attr:`PointContact.soft`): the viscosity
#: rises by at most 10.5 % there.
ISOVISCOUS = 0.1
#: Smallest Moes M at which Hamrock & Dowson's isoviscous-elastic films are shown: below it
#: the rigid-isoviscous limit takes over (Nijenbanning's asymptotes of a circle, H_RI = 41.3 M^-2
#: and H_EI = 2.42 M^-2/15, cross at M = 4.6). A steel ball at M = 0.8 was shown 1.26 um
#: against Nijenbanning's 21 um.
ELASTIC_M = 10.0

#: Inlet and sides of a rigid contact's default domain, in ``l`` (at most :data:`MAX_BOUND`
#: semi-axes): its film is about ``(1 - 1.6/S)^2`` of the unbounded one there (0.81 at 16 l).
RIGID_REACH_DEFAULT = 16.0

#: Outlet of a rigid contact's default domain, in ``l`` (an outlet at 0.5 l cost the film
#: 0.4 %, docs/ehl-robustness.md).
RIGID_OUTLET_DEFAULT = 1.0

#: Cells per ``l`` of a rigid contact's default mesh (square cells): against the rigid ball's
#: Reynolds equation solved independently the film was 5.8 % thin on l/4, 1.4 % on l/8 and
#: 0.25 % on l/16. l/12 of the estimated film keeps the solved film's spacing within l/8
#: (the glass ball's solved film on its domain is 0.63 of the estimate: 0.105 l).
RIGID_CELLS_PER_LENGTH = 12

#: Load gain per unit of the estimated film ``H_c`` (Hertzian units) of a rigid contact: the
#: solver's default 0.05, made for ``H_c`` of 0.03-1, moves the separation of a film at
#: ``H_c = 60`` by 1e-5 of it per sweep, and the glass ball's load error stalled near 0.9 %
#: after 5,000 sweeps on every mesh; with ``0.05 H_c`` it converged in 570-3,230 sweeps.
RIGID_GAIN_PER_FILM = 0.05


def _check_common(u1, u2, body1, body2, lubricant):
    u1 = float(u1)
    u2 = float(u2)
    if not (np.isfinite(u1) and np.isfinite(u2)):
        raise InputError("u1, u2", "finite surface speeds in m/s", (u1, u2))
    if not 0.5 * (u1 + u2) > 0:
        raise InputError(
            "u1, u2", "a positive mean entrainment speed (u1 + u2)/2 > 0 for a lubricated contact",
            (u1, u2),
        )
    if not isinstance(body1, Material) or not isinstance(body2, Material):
        raise InputError("body1, body2", "asperity.Material instances")
    if not isinstance(lubricant, Lubricant):
        raise InputError("lubricant", "an asperity.ehl.Lubricant")
    contact_modulus(body1, body2)
    return u1, u2


def _check_domain(domain, half_x, half_y):
    """Validate ((x0, x1), (y0, y1)) in m: finite, increasing, holding the Hertz area."""
    try:
        (x0, x1), (y0, y1) = domain
        x0, x1, y0, y1 = (float(v) for v in (x0, x1, y0, y1))
    except (TypeError, ValueError):
        raise InputError("domain", "((x_min, x_max), (y_min, y_max)) in m", domain) from None
    if not np.all(np.isfinite([x0, x1, y0, y1])):
        raise InputError("domain", "finite bounds", domain)
    if not (x0 < -half_x and x1 > half_x):
        raise InputError(
            "domain", f"x bounds enclosing the Hertz contact -a..a (a = {half_x:.4g} m)", domain
        )
    if half_y is not None and not (y0 < -half_y and y1 > half_y):
        raise InputError(
            "domain", f"y bounds enclosing the Hertz contact -b..b (b = {half_y:.4g} m)", domain
        )
    return (x0, x1), (y0, y1)


class _Contact:
    """Shared behaviour of point and line contacts (speeds, lubricant, scales).

    Subclasses set ``hertz`` (the dry Hertz solution) in ``__post_init__``.
    """

    @property
    def a(self) -> float:
        """Hertz semi-axis (point) or half-width (line) along x, m."""
        return self.hertz.a

    @property
    def p_hertz(self) -> float:
        """Hertz maximum pressure, Pa."""
        return self.hertz.p_max

    @property
    def mean_speed(self) -> float:
        """Entrainment (mean) speed (u1 + u2)/2, m/s."""
        return 0.5 * (self.u1 + self.u2)

    @property
    def sliding_speed(self) -> float:
        """Sliding speed u2 - u1, m/s (the sign enters the Eyring shear stress)."""
        return self.u2 - self.u1

    @property
    def slide_roll_ratio(self) -> float:
        """xi = (u1 - u2)/u_mean, so that u1 = u (1 + xi/2), u2 = u (1 - xi/2) (the seed)."""
        return (self.u1 - self.u2) / self.mean_speed

    @property
    def reduced_modulus(self) -> float:
        """E' = 2 E*, Pa."""
        return 2.0 * contact_modulus(self.body1, self.body2)

    @property
    def film_scale(self) -> float:
        """h = film_scale * H: a^2 / Rx, m."""
        return self.a**2 / self.rx

    @property
    def elastic_factor(self) -> float:
        """c = 2 p_h Rx / (pi E' a), the factor of the dimensionless deflection sum."""
        return 2.0 * self.p_hertz * self.rx / (np.pi * self.reduced_modulus * self.a)

    @property
    def lam(self) -> float:
        """Reynolds wedge factor lam = 12 eta0 u_mean Rx^2 / (a^3 p_h)."""
        eta0 = self.lubricant.viscosity
        return 12.0 * eta0 * self.mean_speed * self.rx**2 / (self.a**3 * self.p_hertz)

    @property
    def U(self) -> float:
        """Hamrock-Dowson speed parameter eta0 u_mean / (E' Rx)."""
        return self.lubricant.viscosity * self.mean_speed / (self.reduced_modulus * self.rx)

    @property
    def G(self) -> float:
        """Material parameter alpha E'."""
        return self.lubricant.pressure_viscosity * self.reduced_modulus

    @property
    def L(self) -> float:
        """Moes material parameter L = G (2U)^(1/4)."""
        return self.G * (2.0 * self.U) ** 0.25

    def inlet_extent(self) -> float:
        """Distance of the default inlet upstream of the centre, in a.

        The fully flooded inlet distance of Hamrock & Dowson (1977, part IV),
        ``m* = 1 + 3.06 [(Rx/a)^2 hc/Rx]^0.58 = 1 + 3.06 H^0.58`` with ``H = hc Rx/a^2`` the
        estimated central film in Hertzian units, with its inlet length ``m* - 1`` counted
        1.8 times: ``1 + 1.8 (m* - 1)``, and at least the seed's 2.5 a (which the gear case
        keeps). An inlet at ``m*`` starved the central film by 1.3 % (circular, M = 10,
        L = 10), one at ``1 + 1.5 (m* - 1)`` by 0.2 % (docs/ehl-robustness.md).
        """
        film = self.film_estimate() / self.film_scale
        return max(MIN_INLET, formulas.flooded_inlet_distance(film, 1.8))

    def load_gain(self) -> float | None:
        """Load gain for :func:`asperity.ehl.solve_steady`: None, the solver's default (a
        rigid point contact's own, :meth:`PointContact.load_gain`)."""
        return None

    def cells_per_a(self) -> int:
        """Default mesh spacing along x: dX = 1/n with n a power of two from 32 to 1024.

        The discretisation error of the central film grows like ``FILM_ERROR dX^2 / H_c``
        (second order, relative to the Hertzian-unit film ``H_c``, which shrinks with the load
        parameter M); ``n`` is the smallest power of two that keeps it below
        ``MESH_TARGET``.
        """
        film = self.film_estimate() / self.film_scale
        need = np.sqrt(FILM_ERROR / (MESH_TARGET * film))
        return int(2 ** np.clip(np.ceil(np.log2(need)), 5, 10))


@dataclass(frozen=True)
class PointContact(_Contact):
    """Smooth elliptical (point) EHL contact, entrainment along x.

    Parameters
    ----------
    rx, ry : float
        Radii of relative curvature along x (entrainment) and y, m.
    load : float
        Normal load w, N.
    u1, u2 : float
        Surface speeds along x, m/s; their mean must be positive.
    body1, body2 : Material
        The two elastic bodies.
    lubricant : Lubricant
        The lubricant (viscosity, density and Eyring laws).
    """

    rx: float
    ry: float
    load: float
    u1: float
    u2: float
    body1: Material
    body2: Material
    lubricant: Lubricant

    def __post_init__(self):
        object.__setattr__(self, "rx", check_positive("rx", self.rx))
        object.__setattr__(self, "ry", check_positive("ry", self.ry))
        if not np.isfinite(self.ry):
            raise InputError("ry", "a finite radius (use LineContact for a line contact)")
        object.__setattr__(self, "load", check_positive("load", self.load))
        u1, u2 = _check_common(self.u1, self.u2, self.body1, self.body2, self.lubricant)
        object.__setattr__(self, "u1", u1)
        object.__setattr__(self, "u2", u2)
        object.__setattr__(
            self, "hertz", hertz_point(self.load, self.rx, self.ry, self.body1, self.body2)
        )

    @property
    def b(self) -> float:
        """Hertz semi-axis along y, m."""
        return self.hertz.b

    @property
    def curvature(self) -> float:
        """Dimensionless Laplacian of the undeformed gap, 1 + Rx/Ry."""
        return 1.0 + self.rx / self.ry

    @property
    def load_integral(self) -> float:
        """Target of the dimensionless load: integral of P dX dY = 2 pi b / (3 a)."""
        return 2.0 * np.pi * self.b / (3.0 * self.a)

    @property
    def W(self) -> float:
        """Hamrock-Dowson load parameter w / (E' Rx^2)."""
        return self.load / (self.reduced_modulus * self.rx**2)

    @property
    def M(self) -> float:
        """Moes load parameter M = W (2U)^(-3/4)."""
        return self.W * (2.0 * self.U) ** -0.75

    def film_estimate(self) -> float:
        """Central film from Nijenbanning, Venner & Moes (1994), m (``ry >= rx``; for
        ``ry < rx`` evaluated at ``ry = rx``: an estimate for the domain and the mesh)."""
        lub = self.lubricant
        return formulas.nijenbanning_point(
            self.load, self.rx, max(self.ry, self.rx), self.mean_speed, lub.viscosity,
            lub.pressure_viscosity, self.reduced_modulus).central

    def rigid_length(self) -> float:
        """``l = sqrt(2 Rx hc)`` of the estimated central film (:meth:`film_estimate`), m: the
        length over which a nearly rigid contact's pressure builds up and falls off."""
        return math.sqrt(2.0 * self.rx * self.film_estimate())

    @property
    def rigid(self) -> bool:
        """Whether the default domain and mesh follow :meth:`rigid_length` (at least
        :data:`RIGID_DEFAULT_LENGTH` a, and ``alpha`` times the pressure scale
        ``w / (2 pi Rx h)`` at most :data:`RIGID_ISOVISCOUS`): an isoviscous hydrodynamic
        rather than an elastohydrodynamic contact, whose pressure spreads far beyond the
        Hertz zone."""
        film = self.film_estimate()
        pressure = formulas.rigid_mean_pressure(self.load, self.rx, film)
        return (self.rigid_length() >= RIGID_DEFAULT_LENGTH * self.a
                and self.lubricant.pressure_viscosity * pressure <= RIGID_ISOVISCOUS)

    @property
    def soft(self) -> bool:
        """Whether the contact is isoviscous and elastic (soft EHL: ``alpha p_h <=``
        :data:`ISOVISCOUS`, Moes ``M >=`` :data:`ELASTIC_M`; a PDMS ball on glass), whose
        steady relaxation needs its own fallback (:data:`asperity.ehl.solver.SOFT_RETRY_REFRESH`)
        and mesh advice (:func:`asperity.runners.ehl_steady.relaxed_cells`)."""
        return (self.M >= ELASTIC_M
                and self.lubricant.pressure_viscosity * self.p_hertz <= ISOVISCOUS)

    def load_gain(self) -> float | None:
        """Load gain for :func:`asperity.ehl.solve_steady` (None: the solver's default).

        A rigid contact's (:attr:`rigid`) film in Hertzian units is large (``H_c`` = 60 for a
        glass ball in glycerol) and the solver's default shift of the separation per unit
        load error, 0.05, too small for it: ``RIGID_GAIN_PER_FILM H_c``, the shift Newton's
        step would take with the rigid film's ``h ~ w^-2`` (``dH = -2 H_c dw/w``) times 0.025.
        """
        if not self.rigid:
            return None
        return RIGID_GAIN_PER_FILM * self.film_estimate() / self.film_scale

    def rigid_domain(self):
        """The default domain of a rigid contact (:attr:`rigid`), m: inlet and sides
        ``RIGID_REACH_DEFAULT l`` from the centre, outlet ``RIGID_OUTLET_DEFAULT l`` (at
        least 1.5 a), each within :data:`MAX_BOUND` semi-axes (``l`` =
        :meth:`rigid_length`). A rigid ball's film on a square domain of half-width S l is
        about ``(1 - 1.6/S)^2`` of the unbounded one: 0.81 at 16 l; the run's domain line
        says how much its domain keeps, and the comparison rows give Brewe, Hamrock &
        Taylor's unbounded film."""
        length = self.rigid_length()
        reach = RIGID_REACH_DEFAULT * length
        x0 = -min(reach, MAX_BOUND * self.a)
        x1 = min(max(RIGID_OUTLET_DEFAULT * length, OUTLET * self.a), MAX_BOUND * self.a)
        half_y = min(reach, MAX_BOUND * self.b)
        return (x0, x1), (-half_y, half_y)

    def default_domain(self):
        """-m a < x < 1.5 a, -w < y < w (m) with ``m`` = :meth:`inlet_extent` and
        ``w = max(b + max(b, SIDE_PER_INLET (m - 1) min(a, b)), a)`` rounded up to a multiple
        of 0.4 b.

        The seed's domain (-2.5a..1.5a, -2b..2b) for the gear case and any other contact
        whose fully flooded inlet lies within 2.5 a; the transverse half-width keeps at least
        one a for ellipses entrained along their major axis (b < a). A long inlet (thick
        films, low M) widens the sides with it: a margin of half the inlet length beyond the
        contact, for circular contacts at M = 10-50 (an ellipse with b > a keeps 2 b while b
        exceeds half its inlet length (m - 1) a / 2).

        A rigid contact (:attr:`rigid`) takes :meth:`rigid_domain` instead.
        """
        if self.rigid:
            return self.rigid_domain()
        inlet = self.inlet_extent()
        margin = max(self.b, SIDE_PER_INLET * (inlet - 1.0) * min(self.a, self.b))
        half_y = max(self.b + margin, self.a)
        # whole blocks of 8 cells of b/10, so that the default mesh keeps dY = b/10 where
        # dY >= 3 dX allows it (+-2.24 b gave the slow ball 40 cells of b/8.9)
        block = 0.4 * self.b
        half_y = block * math.ceil(half_y / block - 1e-9)
        return (-inlet * self.a, OUTLET * self.a), (-half_y, half_y)

    def default_nodes(self, domain=None, *, max_dx: float | None = None,
                      max_dy: float | None = None) -> tuple[int, int]:
        """Default mesh (nx, ny) on ``domain`` (default :meth:`default_domain`).

        Across ``dY = b/10`` (40 cells on the default domain of an ellipse with ``k >= 1/2``),
        coarser where needed to keep ``dY >= MIN_CELL_ASPECT dX`` (16 cells at least): with
        cells nearly square the lagged y-couplings of an Eyring lubricant's Poiseuille flow
        made the x-line relaxation diverge (docs/ehl-robustness.md); finer where needed to keep
        ``dY <= MAX_CELL_ASPECT dX``: on cells 32 times longer than wide the relaxation
        diverged for long ellipses at large Moes L (k = 5, M = 1000 and 3000, L = 19).
        Along x ``dX = 1/n`` with ``n`` the power of two of :meth:`cells_per_a`, refined to
        ``dX <= b/30`` when ``b < a`` so that both hold. ``nx - 1`` is a multiple of 8, and
        ``ny - 1`` too where one fits between ``dY <= b/10`` and ``dY >= 3 dX``, else a
        multiple of 4 or 2 (the mesh check, :func:`asperity.diagnostics.ehl_mesh`, wants
        ``b/dY >= 10``).

        ``max_dx`` and ``max_dy`` (m) are spacings a surface feature asks for (a transient
        run's dent, bump or waviness: :meth:`asperity.cases.EHLTransientCase.feature_spacing`):
        ``n`` is raised to ``dX <= max_dx`` and to ``MIN_CELL_ASPECT dX <= max_dy``, and
        ``dY <= max_dy`` (the transient relaxation needs the same cell shape: a bump through
        a ball-on-disc contact failed on cells with ``dY = 2 dX`` at ``a/64``,
        docs/ehl-transient.md, "The default mesh of a transient case").
        """
        (x0, x1), (y0, y1) = _check_domain(
            self.default_domain() if domain is None else domain, self.a, self.b)
        if self.rigid and not (max_dx or max_dy):
            return self.rigid_nodes(((x0, x1), (y0, y1)))
        need = max(self.cells_per_a(), 30.0 * self.a / self.b,
                   self.a / max_dx if max_dx else 1.0,
                   MIN_CELL_ASPECT * self.a / max_dy if max_dy else 1.0)
        dx = self.a / int(2 ** np.ceil(np.log2(need)))
        nx = 8 * int(np.ceil((x1 - x0) / (8 * dx))) + 1
        dy = min(0.1 * self.b, max_dy) if max_dy else 0.1 * self.b
        widest = (y1 - y0) / (MIN_CELL_ASPECT * dx)  # most cells with dY >= 3 dX
        # a multiple of 8 (grid sequencing) with dY <= dy where one fits under that bound,
        # else of 4 or 2: a 5.2 b wide domain at dX = b/32 has room for 52-55 cells only, and
        # the 48 taken before gave b/dy = 9.2, which the mesh check then warned about
        cells = next((m * np.ceil((y1 - y0) / (m * dy)) for m in (8, 4, 2)
                      if m * np.ceil((y1 - y0) / (m * dy)) <= widest),
                     8 * np.floor(widest / 8))
        cells = max(cells, 8 * np.ceil((y1 - y0) / (8 * MAX_CELL_ASPECT * dx)))
        return nx, int(max(cells, 16)) + 1

    def rigid_nodes(self, domain) -> tuple[int, int]:
        """Default mesh (nx, ny) of a rigid contact (:attr:`rigid`) on ``domain`` (m): square
        cells of at most ``l / RIGID_CELLS_PER_LENGTH`` (``l`` = :meth:`rigid_length`), the
        pressure varying over ``l`` and not over the Hertz zone; ``nx - 1`` and ``ny - 1``
        multiples of 8 (grid sequencing). The glass ball in glycerol: 129 x 225 nodes on
        -100 a..10.9 a, +-100 b, against 1969 x 617 of a/32 before."""
        (x0, x1), (y0, y1) = domain
        step = self.rigid_length() / RIGID_CELLS_PER_LENGTH
        return tuple(8 * math.ceil((hi - lo) / (8 * step) - 1e-9) + 1
                     for lo, hi in ((x0, x1), (y0, y1)))

    def grid(self, nx: int, ny: int, domain=None):
        """Node (cell-centre) coordinates ``x``, ``y`` in m on ``domain`` (default
        :meth:`default_domain`).

        The end nodes lie on the domain bounds; the seed's mesh dx = a/200, dy = b/50 is
        ``nx, ny = 801, 201`` on the seed's domain -2.5a..1.5a, -2b..2b.
        """
        (x0, x1), (y0, y1) = _check_domain(
            self.default_domain() if domain is None else domain, self.a, self.b
        )
        nx, ny = _check_nodes(nx, "nx"), _check_nodes(ny, "ny")
        return np.linspace(x0, x1, nx), np.linspace(y0, y1, ny)


@dataclass(frozen=True)
class LineContact(_Contact):
    """Smooth line (infinitely long cylinder) EHL contact, entrainment along x.

    Parameters
    ----------
    radius : float
        Radius of relative curvature along x, m.
    load_per_length : float
        Load per unit length w', N/m.
    u1, u2, body1, body2, lubricant
        As for :class:`PointContact`.
    """

    radius: float
    load_per_length: float
    u1: float
    u2: float
    body1: Material
    body2: Material
    lubricant: Lubricant

    def __post_init__(self):
        object.__setattr__(self, "radius", check_positive("radius", self.radius))
        object.__setattr__(
            self, "load_per_length", check_positive("load_per_length", self.load_per_length)
        )
        u1, u2 = _check_common(self.u1, self.u2, self.body1, self.body2, self.lubricant)
        object.__setattr__(self, "u1", u1)
        object.__setattr__(self, "u2", u2)
        object.__setattr__(
            self,
            "hertz",
            hertz_line(self.load_per_length, self.radius, self.body1, self.body2),
        )

    @property
    def rx(self) -> float:
        """Radius along x, m (the ``radius``)."""
        return self.radius

    @property
    def curvature(self) -> float:
        """Dimensionless second derivative of the undeformed gap, 1."""
        return 1.0

    @property
    def load_integral(self) -> float:
        """Target of the dimensionless load: integral of P dX = pi/2."""
        return 0.5 * np.pi

    @property
    def W(self) -> float:
        """Load parameter w' / (E' R)."""
        return self.load_per_length / (self.reduced_modulus * self.radius)

    @property
    def M(self) -> float:
        """Moes load parameter M = W' (2U)^(-1/2)."""
        return self.W * (2.0 * self.U) ** -0.5

    def film_estimate(self) -> float:
        """Central film from Moes (1992), m (for the domain and the mesh)."""
        lub = self.lubricant
        return formulas.moes_line(self.load_per_length, self.radius, self.mean_speed,
                                  lub.viscosity, lub.pressure_viscosity,
                                  self.reduced_modulus).central

    def default_domain(self):
        """-m a < x < 1.5 a with ``m`` = :meth:`inlet_extent` (the y bounds are unused), m;
        the seed's -2.5a..1.5a when the fully flooded inlet lies within 2.5 a."""
        return (-self.inlet_extent() * self.a, OUTLET * self.a), (0.0, 0.0)

    def default_nodes(self, domain=None, *, max_dx: float | None = None,
                      max_dy: float | None = None) -> tuple[int, int]:
        """Default mesh (nx, 1) on ``domain``: ``dX = 1/``:meth:`cells_per_a`, refined by
        powers of two to ``dx <= max_dx`` (m; a ridge's, as for a point contact), ``nx - 1``
        a multiple of 8; ``max_dy`` is not used."""
        (x0, x1), _ = _check_domain(
            self.default_domain() if domain is None else domain, self.a, None)
        need = max(self.cells_per_a(), self.a / max_dx if max_dx else 1.0)
        dx = self.a / int(2 ** np.ceil(np.log2(need)))
        return 8 * int(np.ceil((x1 - x0) / (8 * dx))) + 1, 1

    def grid(self, nx: int, ny: int = 1, domain=None):
        """Node coordinates ``x`` (m) on the x-range of ``domain``; ``y = [0.]``."""
        if ny != 1:
            raise InputError("ny", "1 for a line contact", ny)
        (x0, x1), _ = _check_domain(
            self.default_domain() if domain is None else domain, self.a, None
        )
        return np.linspace(x0, x1, _check_nodes(nx, "nx")), np.zeros(1)


def _check_nodes(n, field):
    return check_int(field, n, 9, "an integer number of nodes >= 9")
