"""Case file of a transient mixed-EHL run: rough surfaces moving through the contact.

Reuses the contact, speed and lubricant tables of :mod:`asperity.cases.ehl` and adds one table
per surface, the time stepping and the per-step solver options of
:func:`asperity.ehl.solve_transient`::

    analysis = "ehl-transient"
    reduced_modulus = "227 GPa"
    [contact]   ...   [speeds]  u = "25 m/s", xi = 0.25   [lubricant] ...
    [grid]
    nx = 129
    ny = 65
    [surface1]
    kind = "builtin"    # smooth | builtin | ground | gaussian | self-affine | file | feature
    profile = "C"
    [surface2]
    kind = "builtin"
    profile = "C"
    [surface2.waviness] # transverse waviness (varies along y), as in the seed's Fig. 15
    wavelength = "420 um"
    amplitude = "0.1 um"
    [time]
    counting_steps = 200
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Annotated, Literal

import numpy as np
from pydantic import Field, ValidationError, model_validator
from pydantic_core import InitErrorDetails, PydanticCustomError

from ..ehl.transient import (
    FEATURE_CELLS_ACROSS,
    FEATURE_CELLS_ALONG,
    ROUGHNESS_CELLS,
    default_warmup_steps,
)
from ..errors import InputError
from ..surfaces.features import STRAIGHT_FEATURES
from ..surfaces.recipe import SurfaceBuild, build_surface_record
from ..surfaces.topography import Topography
from .ehl import EHLCaseBase, EHLGridSpec, check_node_count
from .fields import CaseModel, Integer, Number, Quantity
from .roughness import (
    KIND_KEYS,
    FormKeys,
    SurfaceKeys,
    WavinessSpec,
    named_in_table,
    refuse_implausible_file,
    surface_recipe,
)

__all__ = ["FEATURE_KEYS", "MAX_FEATURE_SLOPE", "MAX_LEAD_HALF_WIDTHS", "EHLTransientCase",
           "MovingSurfaceSpec", "TimeSpec", "TransientSolverSpec"]

#: Largest slope of a single feature's flank, ``pi A / (2 w)`` for the cosine-squared cap of
#: amplitude A and half-width w (:mod:`asperity.surfaces.features`), that a case takes: the
#: half-space's influence coefficients assume small surface slopes, and the dents, bumps and
#: ridges of the transient EHL literature slope by 0.001-0.1 (Kaneta's dents about 1.5 um deep
#: and 30 um in half-width: 0.08). A user's amplitude written as a bare number (0.25, read as
#: 0.25 m, meant 0.25 um) sloped by 2.6e4 and was taken without a word.
MAX_FEATURE_SLOPE = 0.25

#: The keys of a single feature (``kind = "feature"``), refused on the other kinds: a user's
#: ``amplitude`` on a smooth surface, or ``rms`` on a feature one, were taken without a word
#: (the report's table showed the unused ``surface1.rms``).
FEATURE_KEYS = ("feature", "amplitude", "half_width", "lead")

#: Farthest a feature's ``lead`` may place it upstream of the inlet, in half-widths: the
#: default puts it one half-width plus the warm-up's travel away (a few to tens of them); a
#: user's ``lead = "1 m"`` for a 30 um dent scheduled 1.2 million steps without a word.
MAX_LEAD_HALF_WIDTHS = 200.0


class MovingSurfaceSpec(FormKeys, SurfaceKeys):
    """``[surface1]``/``[surface2]``: the roughness a surface carries into the contact.

    ``kind``: ``smooth``; ``builtin`` (``profile`` "A", "B" or "C": the synthetic stand-ins of
    the seed's transverse-ground profiles); ``ground`` (``ra``, ``correlation_length``,
    ``run_in``, ``seed``); ``gaussian`` (``rms``, ``correlation_length``, ``acf``, ``seed``);
    ``self-affine`` (``hurst``, ``rms`` or ``rms_slope``, ``rolloff_wavelength``,
    ``short_cutoff``, ``seed``); ``file`` (a measured profile, or a map whose middle is placed on
    the contact's centre line across y: ``path``, ``spacing`` when the file has no x column,
    the reading keys ``unit``, ``x_unit``, ``z_unit``, ``missing``, ``resample``, and
    ``form_degree``: the least-squares form removed, default 1, its mean line, as in a
    contact case's ``[roughness]``, so that the scan's offset and tilt do not enter the
    inlet); ``feature`` (one ``feature`` "dent", "bump", "ridge" or "groove" of
    ``amplitude`` and ``half_width`` on a smooth surface, its centre ``lead`` upstream of the
    inlet at the start: the probes of Venner & Lubrecht, Kaneta, Ai & Cheng;
    :mod:`asperity.surfaces.features`). Profiles vary
    along x (the rolling direction) and are extruded across y; a gaussian or self-affine
    surface of a point contact is a topography over the mesh's rows (isotropic, or with
    ``correlation_length_y`` along y: a long one gives ridges across the rolling direction),
    a profile for a line contact. ``scale`` multiplies the
    heights (the seed's sqrt(2) x C); ``lowpass`` removes wavelengths shorter than that many
    mesh spacings (ISO Gaussian filter) when the mesh cannot resolve them; ``waviness`` adds a
    sinusoid along y (transverse waviness) or x. The surface keys are those of
    :class:`~asperity.cases.roughness.SurfaceKeys` and
    :class:`~asperity.cases.roughness.FormKeys`.
    """

    kind: Literal["smooth", "builtin", "ground", "gaussian", "self-affine", "file",
                  "feature"] = "smooth"
    """Roughness the surface carries: "smooth", "builtin", "ground", "gaussian", "self-affine",
    "file" or "feature" (a single dent, bump, ridge or groove)."""
    scale: Annotated[Number, Field(ge=0, le=100)] = 1.0
    """Factor on the heights (the seed's sqrt(2) x C)."""
    lowpass: Annotated[Number, Field(ge=0, le=100)] = 0.0
    """Remove wavelengths shorter than this many mesh spacings (ISO Gaussian filter; 0: off)."""
    waviness: WavinessSpec | None = None
    """A sinusoidal waviness along y (transverse) or x."""
    feature: Literal["dent", "bump", "ridge", "groove"] | None = None
    """Single feature (kind = "feature"): a circular "dent" or "bump" centred on y = 0, or a
    straight "ridge" or "groove" across the rolling direction."""
    amplitude: Quantity("length", gt=0) | None = None
    """Depth of the dent or groove, height of the bump or ridge (kind = "feature")."""
    half_width: Quantity("length", gt=0) | None = None
    """Radius of the dent or bump, half-width along x of the ridge or groove (kind =
    "feature")."""
    lead: Quantity("length", ge=0) | None = None
    """Distance of the feature's centre upstream of the inlet at the start of the run (default:
    its half-width plus the distance the surface travels in the warm-up, so that it enters
    when counting starts)."""

    @model_validator(mode="after")
    def _required(self):
        self.check_kind({"builtin": ("profile",), "ground": ("ra",), "self-affine": ("hurst",),
                         "gaussian": ("rms", "correlation_length"), "file": ("path",),
                         "feature": ("feature", "amplitude", "half_width")},
                        {**KIND_KEYS, "feature": set(), "smooth": set()})
        if self.kind != "feature":
            for key in FEATURE_KEYS:
                if getattr(self, key) is not None:
                    message = (f"expected no {key} for kind = \"{self.kind}\" (it is a single "
                               "feature's: kind = \"feature\")")
                    detail = InitErrorDetails(type=PydanticCustomError("value_error", message),
                                              loc=(key,), input=getattr(self, key))
                    raise ValidationError.from_exception_data("case", [detail])
        if self.kind == "feature":
            slope = 0.5 * np.pi * self.amplitude / self.half_width
            if slope > MAX_FEATURE_SLOPE:
                message = (f"expected a feature whose flank slopes by at most "
                           f"{MAX_FEATURE_SLOPE:g} (pi amplitude / (2 half_width); limit of the "
                           f"half-space's small slopes): {self.amplitude:.4g} m over "
                           f"{self.half_width * 1e6:.4g} um slopes by {slope:.3g}; check the "
                           "amplitude's unit (a bare number is metres: write \"0.25 um\")")
                detail = InitErrorDetails(type=PydanticCustomError("value_error", message),
                                          loc=("amplitude",), input=self.amplitude)
                raise ValidationError.from_exception_data("case", [detail])
            if self.lead is not None and self.lead > MAX_LEAD_HALF_WIDTHS * self.half_width:
                message = (f"expected a lead of at most {MAX_LEAD_HALF_WIDTHS:g} half-widths "
                           f"({MAX_LEAD_HALF_WIDTHS * self.half_width * 1e3:.4g} mm): the run "
                           "lasts until the feature has crossed the contact, and "
                           f"{self.lead * 1e3:.4g} mm upstream that is many thousands of steps "
                           "of smooth film; leave lead out (the feature then enters as counting "
                           "starts) or check its unit (a bare number is metres)")
                detail = InitErrorDetails(type=PydanticCustomError("value_error", message),
                                          loc=("lead",), input=self.lead)
                raise ValidationError.from_exception_data("case", [detail])
        return self

    def feature_lead(self, warmup_travel: float = 0.0) -> float:
        """Distance (m) of the feature's centre upstream of the inlet at the start of the run:
        ``lead``, or by default the half-width plus ``warmup_travel``, the distance the surface
        moves in the warm-up."""
        return self.half_width + warmup_travel if self.lead is None else self.lead

    def build(self, length: float, spacing: float, y: np.ndarray, dx: float,
              warmup_travel: float = 0.0):
        """The surface (Profile, Topography or None), at least ``length`` m long along x: the
        surface of :meth:`build_record`."""
        built = self.build_record(length, spacing, y, dx, warmup_travel)
        return None if built is None else built.surface

    def build_record(self, length: float, spacing: float, y: np.ndarray, dx: float,
                     warmup_travel: float = 0.0) -> SurfaceBuild | None:
        """The surface with what a measured file's reading said and the form removed from it
        (:class:`~asperity.surfaces.recipe.SurfaceBuild`), or None for a smooth surface without
        waviness.

        Built by :func:`asperity.surfaces.recipe.build_surface_record` on cells of ``spacing``
        m, at least ``length`` m long along x (a file has its own length); ``dx`` is the mesh
        spacing (of ``lowpass``), ``y`` the mesh's cell centres across x (of a dent, a bump, a
        transverse waviness, and the rows of a gaussian or self-affine topography, which has
        the mesh's spacing across). A feature is placed by :meth:`feature_lead` of
        ``warmup_travel`` (m).
        """
        if self.kind == "smooth" and self.waviness is None:
            return None
        changes = {"lowpass_wavelength": self.lowpass * dx if self.lowpass > 0 else None}
        if self.kind == "feature":
            # the surface enters the inlet end first: its last cell centre arrives at t = 0
            end = (np.ceil(length / spacing) - 0.5) * spacing
            changes["position"] = max(end - self.feature_lead(warmup_travel), 0.0)
        recipe = surface_recipe(self, **changes)
        if self.kind in ("gaussian", "self-affine") and y.size > 1:
            # a topography over the mesh's rows, periodic across the domain's width
            dy = float(y[1] - y[0])
            if self.short_cutoff is not None and self.short_cutoff < 2.0 * dy:
                raise InputError("short_cutoff", "at least two of the mesh's row spacings "
                                 f"across y ({2.0 * dy:.4g} m), where a point contact's "
                                 "self-affine topography is generated; or more rows (grid.ny)",
                                 self.short_cutoff)
            return build_surface_record(recipe, length, (spacing, dy), width=y.size * dy,
                                        y=y)
        return build_surface_record(recipe, length, spacing, y=y)


def _centred_across(key: str, path: str, built: SurfaceBuild, y: np.ndarray) -> SurfaceBuild:
    """A measured map placed across y with its middle on the domain's middle (the contact's
    centre line), as a map of the track under the contact is meant; its own y, which a text
    export or an instrument gives from 0, would leave the rows y < 0 of the domain without
    heights. Along x the map is fed in from the inlet as it is.

    Raises
    ------
    InputError
        A map narrower than the domain across y (naming ``key`` with the width needed and
        ``grid.y_min``, ``grid.y_max``), or a map for a line contact, before the steady start
        rather than after it.
    """
    surface = built.surface
    if y.size == 1:
        raise InputError(key, f"a profile (one trace along x) for a line contact "
                         f"({Path(path).name} is a map of {surface.y.size} rows across y)")
    have = float(surface.y[-1] - surface.y[0])
    need = float(y[-1] - y[0])
    if have < need * (1.0 - 1e-9):
        raise InputError(key, f"a map at least {need * 1e3:.4g} mm wide across y, the domain's "
                         f"width, since the map is centred on the contact ({Path(path).name} "
                         f"is {have * 1e3:.4g} mm wide): a wider map, or a narrower domain "
                         "(grid.y_min, grid.y_max)")
    shift = 0.5 * (y[0] + y[-1]) - 0.5 * (surface.y[0] + surface.y[-1])
    return replace(built, surface=Topography(surface.x, surface.y + shift, surface.z,
                                             periodic=surface.periodic))


def _backwards_error(speeds, k: int, u: float) -> ValidationError:
    """The error of a rough surface ``k`` whose speed ``u`` (m/s) is not positive, located at
    the key that set it: ``speeds.xi`` (``u_k = u (1 -+ xi/2)``, so ``|xi| < 2``) or
    ``speeds.u1``/``speeds.u2``. The solver feeds a surface's heights in from the inlet
    (x_min) and has none to feed from the outlet; a smooth surface may move backwards, since
    the Reynolds equation sees only the mean speed and the sliding speed
    (tests/test_ehl_features.py, a groove at xi = 2.5)."""
    if speeds.xi is not None:
        key, value = "xi", speeds.xi
        message = (f"expected a slide/roll ratio with |xi| < 2 while surface{k} carries "
                   f"roughness: xi = {speeds.xi:g} moves surface {k} backwards "
                   f"(u{k} = {u:.4g} m/s), and rough surfaces enter from the inlet only; "
                   f"or a smooth surface{k}")
    else:
        key, value = f"u{k}", u
        message = (f"expected a positive speed of surface {k} while surface{k} carries "
                   f"roughness (u{k} = {u:.4g} m/s moves it backwards, and rough surfaces "
                   f"enter from the inlet only); or a smooth surface{k}")
    detail = InitErrorDetails(type=PydanticCustomError("value_error", message),
                              loc=("speeds", key), input=value)
    return ValidationError.from_exception_data("case", [detail])


def _check_trace_length(key: str, path: str, surface, travel: float, warmup: int,
                        counting: int):
    """Refuse a measured trace or map shorter than the ``travel`` (m) its surface makes in the
    run: the solver feeds the surface in from the inlet and has no heights for the rest."""
    have = float(surface.x[-1] - surface.x[0])
    what = "map" if np.ndim(surface.z) == 2 else "trace"
    if travel > have:
        raise InputError(key, f"a {what} at least {travel * 1e3:.4g} mm long along x, as far "
                         f"as its surface travels in the run's {warmup} warm-up and {counting} "
                         f"counting steps ({Path(path).name} is {have * 1e3:.4g} mm): measure "
                         f"a longer {what}, or shorten the run (time.warmup_steps, "
                         "time.counting_steps)")


class TimeSpec(CaseModel):
    """``[time]``: ``counting_steps`` after ``warmup_steps``; ``dt`` (default the seed's
    dx / (2 u_max)); ``snapshots`` centre-line snapshots spread over the counting period
    (Figs. 3, 10).

    The defaults follow the surfaces (:meth:`EHLTransientCase.steps`): rough surfaces warm up
    until the slower one has crossed the domain (the seed) and count 200 steps; a single
    feature (dent, bump, ridge, groove) enters when counting starts and is counted until it, and the
    film change it makes, have crossed the domain.
    """

    counting_steps: Annotated[Integer, Field(ge=1, le=100_000)] | None = None
    """Time steps over which contacts and films are counted (default 200, or with a feature
    the steps of its passage through the domain)."""
    warmup_steps: Annotated[Integer, Field(ge=0, le=100_000)] | None = None
    """Steps before counting (default: until the slower rough surface has crossed the domain;
    a feature does not count as rough here)."""
    dt: Quantity("time", gt=0) | None = None
    """Time step (default the seed's dx / (2 u_max))."""
    snapshots: Annotated[Integer, Field(ge=1, le=50)] = 4
    """Centre-line snapshots spread over the counting period (with a single feature, over its
    passage through the Hertz zone)."""


class TransientSolverSpec(CaseModel):
    """``[solver]``: per-step options of :func:`asperity.ehl.solve_transient`: tolerance and
    sweep limit per step, far-field refresh interval, the memory of the Anderson acceleration
    of the refresh cycles (0: off; default 3 with line relaxation, off with the point update),
    relaxation method, time-scheme weight ``theta``, the oscillation ``damping`` of the nodal
    update, the ``load_gain``, the film below which a node counts as in contact
    (``contact_film``; default the tolerance times the central film) and the checkpoint
    interval."""

    tolerance: Annotated[Number, Field(gt=0, lt=1)] = 1e-4
    """Relative convergence tolerance per time step."""
    max_sweeps: Annotated[Integer, Field(ge=1, le=100_000)] = 400
    """Sweep limit per time step."""
    refresh: Annotated[Integer, Field(ge=1, le=1000)] | None = None
    """Sweeps between refreshes of the far-field deflection at the start of a timestep (every
    sweep once the step's residual is below 0.3); default 3, 1 for the row solve of a line
    contact."""
    acceleration: Annotated[Integer, Field(ge=0, le=20)] | None = None
    """Memory of the Anderson acceleration of the refresh cycles (0: off; default 3 with line
    relaxation)."""
    method: Literal["line", "point"] | None = None
    """Relaxation: "line" or "point" (default by contact type)."""
    theta: Annotated[Number, Field(ge=0.5, le=1.0)] = 0.5
    """Weight of the time scheme (0.5 Crank-Nicolson, 1 implicit Euler)."""
    damping: Annotated[Number, Field(gt=0, le=1.0)] = 0.7
    """Oscillation damping of the nodal update."""
    load_gain: Annotated[Number, Field(gt=0, le=10.0)] | None = None
    """Separation shift per sweep per relative load error (default 0.15 min(1, b/a) for a point
    contact, 0.03 for a line contact); halved for a step that does not converge with a refresh
    at every sweep and the density's pressure derivative."""
    contact_film: Quantity("length", ge=0) | None = None
    """Film below which a node counts as in contact (default the tolerance times the central film).
    """
    checkpoint_every: Annotated[Integer, Field(ge=1, le=100_000)] = 50
    """Steps between checkpoints (a stopped run resumes with --resume)."""


class EHLTransientCase(EHLCaseBase):
    """``analysis = "ehl-transient"``: rough surfaces through a point or line contact."""

    analysis: Literal["ehl-transient"]
    """Selects the transient mixed-EHL analysis."""
    title: str = "Transient mixed EHL"
    long_running: bool = False
    """Marks a case that runs for many minutes (listed as such by asperity examples)."""
    grid: EHLGridSpec = EHLGridSpec()
    """Mesh and domain (in Hertz semi-axes). Bounds the table does not set follow the contact
    (inlet from Hamrock-Dowson's fully flooded distance) and without node counts the mesh
    follows the film and the surfaces' features (:meth:`mesh`)."""
    surface1: MovingSurfaceSpec = MovingSurfaceSpec()
    """Roughness of surface 1."""
    surface2: MovingSurfaceSpec = MovingSurfaceSpec()
    """Roughness of surface 2."""
    time: TimeSpec = TimeSpec()
    """Time stepping and counting."""
    solver: TransientSolverSpec = TransientSolverSpec()
    """Solver options per time step."""
    paper_contact_time_percent: Annotated[Number, Field(ge=0, le=100)] | None = None
    """Published percentage of time with contact, compared in the report."""

    def feature_spacing(self) -> tuple[float | None, float | None]:
        """Largest mesh spacing (m) along x and across y that the surfaces' features ask for
        (None: no feature): a feature's half-width over
        :data:`~asperity.ehl.transient.FEATURE_CELLS_ALONG` along x and (dent, bump)
        :data:`~asperity.ehl.transient.FEATURE_CELLS_ACROSS` across; a waviness's wavelength
        over twice ``FEATURE_CELLS_ALONG`` along its direction; a gaussian topography's
        correlation lengths over :data:`~asperity.ehl.transient.ROUGHNESS_CELLS` along x and
        across y, a self-affine topography's ``short_cutoff`` over it across y (their heights
        are generated on the mesh's rows)."""
        along, across = [], []
        for spec in (self.surface1, self.surface2):
            if spec.kind == "gaussian":
                along.append(spec.correlation_length / ROUGHNESS_CELLS)
                if not self.contact.line:
                    across.append((spec.correlation_length_y or spec.correlation_length)
                                  / ROUGHNESS_CELLS)
            if spec.kind == "self-affine" and spec.short_cutoff is not None \
                    and not self.contact.line:
                across.append(spec.short_cutoff / ROUGHNESS_CELLS)
            if spec.kind == "feature":
                along.append(spec.half_width / FEATURE_CELLS_ALONG)
                if spec.feature not in STRAIGHT_FEATURES:
                    across.append(spec.half_width / FEATURE_CELLS_ACROSS)
            if spec.waviness is not None:
                wave = spec.waviness
                (along if wave.direction == "x" else across).append(
                    wave.wavelength / (2 * FEATURE_CELLS_ALONG))
        return min(along, default=None), min(across, default=None)

    def mesh(self, problem) -> tuple[int, int, tuple]:
        """``(nx, ny, domain)`` of the run, domain in m.

        The domain is the [grid] table's bounds, and where it sets none the problem's
        :meth:`~asperity.ehl.PointContact.default_domain`. The nodes are the table's, or
        without ``nx``/``ny`` the problem's
        :meth:`~asperity.ehl.PointContact.default_nodes` with the spacing the features ask
        for (:meth:`feature_spacing`): the steady default mesh where there is no feature.
        """
        domain = self.grid.domain(problem)
        if self.grid.nodes_given:
            nx, ny = self.grid.nodes(problem)
        else:
            max_dx, max_dy = self.feature_spacing()
            nx, ny = problem.default_nodes(domain, max_dx=max_dx, max_dy=max_dy)
        return nx, ny, domain

    def timestep(self, problem, x: np.ndarray) -> float:
        """The time step (s) on the mesh ``x`` (m): ``time.dt``, or the seed's
        ``dx / (2 u_max)``."""
        if self.time.dt is not None:
            return self.time.dt
        return 0.5 * (x[1] - x[0]) / max(abs(problem.u1), abs(problem.u2))

    def steps(self, problem, x: np.ndarray, dt: float) -> tuple[int, int]:
        """``(warmup_steps, counting_steps)`` on the mesh ``x`` (m) with timestep ``dt`` (s).

        Given values are kept. By default the warm-up lasts until the slower surface with
        roughness (not a single feature) has crossed the domain
        (:func:`asperity.ehl.transient.default_warmup_steps`; 0 without one), and counting
        lasts 200 steps, or with a feature until the slowest feature and the film change it
        makes have crossed the domain: its trailing edge over the length of the domain plus
        its distance upstream at the start of counting, at the lesser of its surface's speed
        and the mean speed (with sliding the film change travels at the mean speed;
        tests/test_ehl_features.py).
        """
        warmup = self.time.warmup_steps
        if warmup is None:
            rough = [u for spec, u in ((self.surface1, problem.u1), (self.surface2, problem.u2))
                     if spec.kind not in ("smooth", "feature") or spec.waviness is not None]
            warmup = default_warmup_steps(x, rough, dt)
        counting = self.time.counting_steps
        if counting is None:
            passages = []
            for _, spec, start, step in self.feature_tracks(problem, x, dt, warmup):
                # from the centre's place when counting starts until the trailing edge has left
                distance = x[-1] + spec.half_width - (start + warmup * step)
                passages.append(int(np.ceil(distance / (min(step / dt, problem.mean_speed)
                                                        * dt))))
            counting = max(passages, default=200)
        return warmup, counting

    def snapshot_steps(self, problem, x: np.ndarray, dt: float, warmup: int,
                       total: int) -> np.ndarray:
        """Steps of the centre-line snapshots: ``time.snapshots`` spread evenly over the
        counting period, or with single features over their passage through the Hertz zone,
        from the first feature's centre at x = -a until every feature's centre, and the film
        change it makes at the mean speed (Venner & Lubrecht), have reached x = +a (within the
        counting period, and only where it holds that many steps; else as without). A feature
        enters the inlet when counting starts and is counted until it has left the domain, so
        the counting period's first and last steps show the smooth contact: a dent run's
        five snapshots showed it at two (session 38)."""
        first, last = warmup + 1, total
        tracks = self.feature_tracks(problem, x, dt, warmup)
        if tracks:
            a = problem.a
            enter = [(-a - start) / step for _, _, start, step in tracks]
            leave = [max((a - start) / step, (-a - start) / step
                         + 2.0 * a / (problem.mean_speed * dt))
                     for _, _, start, step in tracks]
            inside = max(first, int(np.ceil(min(enter)))), min(last, int(np.floor(max(leave))))
            if inside[1] - inside[0] + 1 >= self.time.snapshots:
                first, last = inside
        return np.unique(np.linspace(first, last, self.time.snapshots).round().astype(int))

    def feature_tracks(self, problem, x: np.ndarray, dt: float, warmup: int) -> list:
        """``(label, spec, start, step)`` per single-feature surface: its centre's position
        (m) at the start of the run and the distance (m) it moves per step, placed as
        :meth:`surfaces` places it (the centre at step k is ``start + k step``)."""
        tracks = []
        for k, (spec, u) in enumerate(((self.surface1, problem.u1), (self.surface2, problem.u2)),
                                      start=1):
            if spec.kind == "feature":
                tracks.append((f"surface{k}", spec,
                               x[0] - spec.feature_lead(u * warmup * dt), u * dt))
        return tracks

    def surfaces(self, problem, x: np.ndarray, y: np.ndarray, warmup: int, total: int,
                 dt: float):
        """The two surfaces (Profile, Topography or None) of :meth:`surface_records`."""
        return [None if built is None else built.surface
                for built in self.surface_records(problem, x, y, warmup, total, dt)]

    def surface_records(self, problem, x: np.ndarray, y: np.ndarray, warmup: int, total: int,
                        dt: float) -> list[SurfaceBuild | None]:
        """The two surfaces of a run of ``total`` steps of ``dt`` s on the mesh ``x``, ``y``
        (m), with what a measured file's reading said (:meth:`MovingSurfaceSpec.build_record`):
        long enough to feed the whole run (at least the built-in profiles' own 5 mm, so that
        short runs use the standard realisation) and sampled at a quarter of the mesh spacing
        (0.5 um at most); a feature placed by :meth:`MovingSurfaceSpec.feature_lead` to enter
        when counting starts after ``warmup`` steps.

        Raises
        ------
        InputError
            A measured file, not periodic, shorter than its surface travels in the run (naming
            ``surfaceK.path``, with the length needed and what to change).
        """
        dx = x[1] - x[0]
        spacing = min(0.5e-6, dx / 4)
        out = []
        for k, (spec, u) in enumerate(((self.surface1, problem.u1),
                                       (self.surface2, problem.u2)), start=1):
            length = max(5e-3, abs(u) * dt * total + (x[-1] - x[0]) + 20 * dx)
            travel = abs(u) * dt * warmup
            if spec.kind == "feature":
                length = max(length, spec.feature_lead(travel) + 2 * spec.half_width)
            try:
                built = spec.build_record(length, spacing, y, dx, warmup_travel=travel)
            except InputError as exc:  # the generator's key, named in the case's table
                raise named_in_table(exc, f"surface{k}", spec) from None
            if built is not None and spec.kind == "file":
                refuse_implausible_file(built, f"surface{k}.path ({Path(spec.path).name})",
                                        f"surface{k}")
            if built is not None and spec.kind == "file" and not built.surface.periodic:
                _check_trace_length(f"surface{k}.path", spec.path, built.surface,
                                    abs(u) * dt * total, warmup, total - warmup)
                if isinstance(built.surface, Topography):
                    built = _centred_across(f"surface{k}.path", spec.path, built, y)
            out.append(built)
        return out

    @model_validator(mode="after")
    def _consistent(self):
        line = self.contact.line
        if line and "ny" in self.grid.model_fields_set and self.grid.ny != 1:
            raise ValueError("expected grid.ny = 1 (or no ny) for a line contact")
        try:
            problem = self.problem()
        except InputError as exc:
            raise ValueError(f"expected {exc.expected} ({exc.field})") from None
        nx, ny, _ = self.mesh(problem)
        check_node_count(nx, ny, not self.grid.nodes_given)
        u1, u2 = self.speeds.surface_speeds()
        for k, (spec, u) in enumerate(((self.surface1, u1), (self.surface2, u2)), start=1):
            rough = spec.kind != "smooth" or spec.waviness is not None
            if rough and not u > 0:
                raise _backwards_error(self.speeds, k, u)
            if line and spec.kind == "feature" and spec.feature not in STRAIGHT_FEATURES:
                raise ValueError(f"expected feature = \"ridge\" or \"groove\" on surface{k} "
                                 "of a line contact (a dent or a bump needs a point contact)")
            if line and spec.waviness is not None and spec.waviness.direction == "y":
                raise ValueError(f"expected no transverse waviness on surface{k} of a line "
                                 "contact")
        return self
