"""One recipe -> surface function: the kind dispatch of every surface a case or the CLI makes.

A :class:`SurfaceRecipe` names a surface by its ``kind`` and the parameters of that kind, in SI
units, with no reference to a case file; :func:`build_surface` makes it on a grid of a given
length and spacing. The case tables ``[roughness]``, ``[surface1]``/``[surface2]`` (transient
EHL, gears) and ``[surface]`` (surface analysis), and ``asperity surface generate``, all describe
their surface as a recipe (:func:`asperity.cases.roughness.surface_recipe`) and build it here.

Kinds and the parameters they use:

- ``smooth``: no roughness (zero heights, periodic; a waviness may still be added)
- ``gaussian``: ``rms``, ``correlation_length`` (``correlation_length_y`` of a topography),
  ``acf``, ``seed`` (:func:`~.generate.gaussian_profile`, :func:`~.generate.gaussian_topography`)
- ``self-affine``: ``hurst``, ``rms`` or ``rms_slope``, ``rolloff_wavelength``,
  ``short_cutoff``, ``seed`` (:func:`~.generate.self_affine_profile`,
  :func:`~.generate.self_affine_topography`)
- ``ground``: ``ra``, ``correlation_length`` (default 15 um), ``run_in``, ``seed``
  (:func:`~.ground.transverse_ground_profile`)
- ``builtin``: ``profile`` "A", "B" or "C" (:func:`~.ground.builtin_profile`)
- ``file``: ``path``, ``file_spacing`` (a file without coordinates; refused for a file that
  gives its own positions), ``read_options`` (:func:`~.io.read_measured`) and ``form_degree``
  (the least-squares polynomial of that degree removed after reading,
  :func:`~.form.remove_form`: 1 the mean line or plane, 0 the mean only; None keeps the heights
  as read)
- ``feature``: ``feature`` "dent", "bump", "ridge" or "groove", ``amplitude``, ``half_width``,
  ``position``
  (:func:`~.features.feature_surface`)
- ``turned``: ``feed``, ``nose_radius``, ``end_relief_angle`` (:func:`~.machining.turned_profile`);
  with ``natural_frequency`` the tool vibrates (:func:`~.machining.turned_profile_dynamic`:
  ``depth_of_cut``, ``cutting_speed``, ``workpiece_diameter``, ``mass``, ``damping_ratio``,
  ``seed``)

:func:`build_surface_record` also returns what was read and removed (a
:class:`SurfaceBuild`), for the notes of a run.

Every kind then takes, in this order: ``lowpass_wavelength`` (the cut-off of an ISO 16610-21
Gaussian filter applied to a profile, or along x to each row of a topography), ``scale`` (a
factor on the heights) and ``waviness`` (a sinusoid added to the scaled heights).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from ..errors import InputError
from .areal import form_left_in
from .features import feature_surface
from .filters import gaussian_filter
from .form import remove_form
from .generate import (
    add_waviness,
    gaussian_profile,
    gaussian_topography,
    self_affine_profile,
    self_affine_topography,
)
from .ground import builtin_profile, transverse_ground_profile
from .io import Reading, read_measured
from .machining import turned_profile, turned_profile_dynamic
from .parameters import rms_gradient
from .topography import Profile, Topography, cell_centres

__all__ = ["KINDS", "FormRemoval", "SurfaceBuild", "SurfaceRecipe", "Waviness", "build_surface",
           "build_surface_record", "level"]

#: The kinds of surface :func:`build_surface` makes.
KINDS = ("smooth", "gaussian", "self-affine", "ground", "builtin", "file", "feature", "turned")


@dataclass(frozen=True)
class Waviness:
    """A sinusoid of ``wavelength`` and ``amplitude`` (m) varying along ``direction``."""

    wavelength: float
    amplitude: float
    direction: str = "y"


@dataclass(frozen=True)
class SurfaceRecipe:
    """A surface by its kind and that kind's parameters (SI units; module docstring).

    Parameters left at None take the defaults of the generator that uses them.
    """

    kind: str
    rms: float | None = None
    rms_slope: float | None = None
    ra: float | None = None
    correlation_length: float | None = None
    correlation_length_y: float | None = None
    acf: str = "gaussian"
    hurst: float | None = None
    rolloff_wavelength: float | None = None
    short_cutoff: float | None = None
    run_in: float = 0.0
    profile: str | None = None
    path: str | None = None
    file_spacing: float | None = None
    read_options: dict = field(default_factory=dict)
    form_degree: int | None = None
    feature: str | None = None
    amplitude: float | None = None
    half_width: float | None = None
    position: float | None = None
    feed: float | None = None
    nose_radius: float | None = None
    end_relief_angle: float | None = None
    natural_frequency: float | None = None
    depth_of_cut: float | None = None
    cutting_speed: float | None = None
    workpiece_diameter: float | None = None
    mass: float | None = None
    damping_ratio: float = 0.05
    seed: int = 0
    lowpass_wavelength: float | None = None
    scale: float = 1.0
    waviness: Waviness | None = None

    def __post_init__(self):
        if self.kind not in KINDS:
            raise ValueError(f"unknown surface kind {self.kind!r}; expected one of {KINDS}")


@dataclass(frozen=True)
class FormRemoval:
    """The least-squares form removed from a measured surface (:func:`level`), SI units.

    Attributes
    ----------
    degree : int
        Degree of the polynomial removed (0: the mean only).
    offset : float
        Mean height of the surface as read, m (always removed).
    tilt : tuple of float
        Slope of the least-squares line (a profile: along x) or plane (along x, along y) of
        the heights as read, rad; removed when ``degree >= 1`` and the surface is not periodic.
    form_height : float
        Peak-to-valley height of the removed form, m.
    periodic : bool
        A periodic surface has no form: only its mean is removed.
    left_in : str or None
        The start of a warning when a map still holds form (a cylinder under a plane:
        :func:`~asperity.surfaces.areal.form_left_in`), for :meth:`SurfaceBuild.file_report`
        to end with the case's key.
    """

    degree: int
    offset: float
    tilt: tuple[float, ...]
    form_height: float
    periodic: bool = False
    left_in: str | None = None

    def describe(self) -> str:
        """What was removed, in words (heights in um to 0.1 nm, tilts in mrad to 0.1 urad)."""
        tilts = " and ".join(f"{round(t * 1e3, 4) + 0.0:.3g} mrad along {axis}"
                             for t, axis in zip(self.tilt, "xy", strict=False))
        offset = f"offset {round(self.offset * 1e6, 4) + 0.0:.4g} um"
        if self.periodic:
            return (f"its mean height was removed ({offset}; a periodic file has no form, so "
                    f"its tilt of {tilts} is kept)")
        if self.degree == 0:
            return (f"its mean height was removed (form_degree = 0: {offset}); its tilt of "
                    f"{tilts} is kept")
        if self.degree == 1:
            shape = "line" if len(self.tilt) == 1 else "plane"
            return (f"its least-squares mean {shape} was removed (form_degree = 1): {offset}, "
                    f"tilt {tilts}")
        return (f"its least-squares polynomial of degree {self.degree} was removed "
                f"(form_degree = {self.degree}): {offset}, tilt {tilts}, form "
                f"{self.form_height * 1e6:.4g} um peak-to-valley")


@dataclass(frozen=True)
class SurfaceBuild:
    """A built surface with what was read and removed on the way (:func:`build_surface_record`).

    Attributes
    ----------
    surface : Profile or Topography
        The surface, as :func:`build_surface` returns it.
    reading : Reading or None
        A measured file's reading (its notes and warnings); None for other kinds.
    form : FormRemoval or None
        The form removed from a measured file; None when none was (other kinds, or
        ``form_degree`` None).
    """

    surface: Profile | Topography
    reading: Reading | None = None
    form: FormRemoval | None = None

    @cached_property
    def rms_slope(self) -> tuple[str, float]:
        """Rdq or Sdq of the built heights (:func:`~asperity.surfaces.rms_gradient`), once."""
        return rms_gradient(self.surface)

    def file_report(self, key: str, name: str) -> tuple[tuple[str, ...], tuple[str, ...]]:
        """Notes and warnings of a measured file for a case, each naming ``key`` (the case's
        ``path`` key, e.g. ``"surface2.path"``): the reader's notes (the units read and where
        from) and the form removed, under ``"key (name)"``; the reader's warnings and its doubt
        on the units when the rms slope (:func:`~asperity.surfaces.rms_gradient` of the
        built heights) is implausible (:meth:`Reading.slope_warnings`): heights in nm read as
        um give slopes a thousand times too steep, which a contact solver takes without
        complaint. Both empty for a surface that was not read from a file."""
        if self.reading is None:
            return (), ()
        notes = [f"{key} ({name}): {note}" for note in self.reading.notes]
        if self.form is not None:
            notes.append(f"{key} ({name}): {self.form.describe()}")
        doubts = self.reading.slope_warnings(*self.rms_slope)
        if self.form is not None and self.form.left_in:
            table = key.removesuffix(".path")
            doubts = (*doubts, self.form.left_in + (
                "and the contact takes it as part of the gap, on top of the bodies' radii; "
                "remove the measured curvature when the case's radius already gives it: "
                f"{table}.form_degree = {self.form.degree + 1}; waviness as long as the map "
                "belongs to the gap and stays"))
        return tuple(notes), tuple(f"{key}: {w}" for w in (*self.reading.warnings, *doubts))


def _tilt(surface) -> tuple[float, ...]:
    """Slopes of the least-squares line or plane of the heights (on a full grid the x and y
    terms are orthogonal, so each is the slope of the mean heights along its axis)."""
    z = np.asarray(surface.z, dtype=float)
    coords = (surface.x,) if isinstance(surface, Profile) else (surface.x, surface.y)
    slopes = []
    for axis, coord in enumerate(coords):
        c = np.asarray(coord, dtype=float) - np.mean(coord)
        mean = z if z.ndim == 1 else z.mean(axis=1 - axis)
        slopes.append(float(c @ mean / (c @ c)))
    return tuple(slopes)


def level(surface, degree: int) -> tuple[Profile | Topography, FormRemoval]:
    """A measured surface referred to its least-squares form, and what was removed.

    Parameters
    ----------
    surface : Profile or Topography
    degree : int
        Degree of the form (:func:`~.form.remove_form`): 0 the mean, 1 the mean line or plane.

    Returns
    -------
    (Profile or Topography, FormRemoval)
    """
    levelled = remove_form(surface, degree)
    z = np.asarray(surface.z, dtype=float)
    form = z - np.asarray(levelled.z)
    left_in = (form_left_in(levelled, degree, advice="")
               if isinstance(surface, Topography) and not surface.periodic else None)
    return levelled, FormRemoval(degree, float(z.mean()), _tilt(surface), float(np.ptp(form)),
                                 bool(surface.periodic), left_in)


def _measured(recipe: SurfaceRecipe) -> SurfaceBuild:
    """The recipe's file, read, checked against ``file_spacing`` and levelled."""
    reading = read_measured(recipe.path, recipe.file_spacing, **recipe.read_options)
    surface = reading.surface
    if recipe.file_spacing is not None:
        own = np.atleast_1d(surface.spacing)
        if not np.allclose(own, np.broadcast_to(recipe.file_spacing, own.shape), rtol=1e-6):
            apart = " by ".join(f"{h * 1e6:.4g} um" for h in own)
            raise InputError("spacing", f"no spacing for a file that gives its own positions "
                             f"(its points are {apart} apart); leave spacing out",
                             recipe.file_spacing)
    if recipe.form_degree is None:
        return SurfaceBuild(surface, reading)
    levelled, form = level(surface, recipe.form_degree)
    return SurfaceBuild(levelled, reading, form)


def _made(recipe: SurfaceRecipe, length: float, spacing, width, y):
    """The surface of the recipe's kind, before low-pass, scale and waviness."""
    h = spacing[0] if isinstance(spacing, tuple) else spacing
    kind = recipe.kind
    if kind == "gaussian":
        if width is None:
            return gaussian_profile(length, h, recipe.rms, recipe.correlation_length,
                                    acf=recipe.acf, seed=recipe.seed)
        ell = (recipe.correlation_length,
               recipe.correlation_length_y or recipe.correlation_length)
        return _on_rows(gaussian_topography((length, width), spacing, recipe.rms, ell,
                                            acf=recipe.acf, seed=recipe.seed), y)
    if kind == "self-affine":
        options = {"rms_height": recipe.rms, "rms_slope": recipe.rms_slope,
                   "rolloff_wavelength": recipe.rolloff_wavelength,
                   "short_cutoff": recipe.short_cutoff, "seed": recipe.seed}
        if width is None:
            return self_affine_profile(length, h, recipe.hurst, **options)
        return _on_rows(self_affine_topography((length, width), spacing, recipe.hurst,
                                               **options), y)
    if kind == "ground":
        ell = {} if recipe.correlation_length is None else {
            "correlation_length": recipe.correlation_length}
        return transverse_ground_profile(length, h, recipe.ra, run_in=recipe.run_in,
                                         seed=recipe.seed, **ell)
    if kind == "builtin":
        return builtin_profile(recipe.profile, length=length, spacing=h)
    if kind == "feature":
        return feature_surface(recipe.feature, length, h, amplitude=recipe.amplitude,
                               half_width=recipe.half_width, position=recipe.position, y=y)
    if kind == "turned":
        if recipe.natural_frequency is None:
            return turned_profile(recipe.feed, recipe.nose_radius, length, h,
                                  end_relief_angle=recipe.end_relief_angle)
        return turned_profile_dynamic(
            recipe.feed, recipe.nose_radius, recipe.depth_of_cut, recipe.cutting_speed,
            recipe.workpiece_diameter, length, h, recipe.natural_frequency,
            damping_ratio=recipe.damping_ratio, mass=recipe.mass, seed=recipe.seed).profile
    n = int(np.ceil(length / h))
    return Profile(cell_centres(n, h), np.zeros(n), periodic=True)


def _on_rows(topography: Topography, y) -> Topography:
    """A generated topography with its rows at the cell centres ``y`` (m) instead of from 0:
    the rows of the grid it was generated for (``width = y.size dy``, its period across)."""
    if y is None:
        return topography
    return Topography(topography.x, np.asarray(y, dtype=float), topography.z,
                      periodic=topography.periodic)


def _finished(recipe: SurfaceRecipe, surf, y):
    """The low-pass filter (along x), scale and waviness of the recipe applied to ``surf``."""
    z = np.asarray(surf.z)
    if recipe.lowpass_wavelength:  # along x (axis 0), every row of a topography
        z = gaussian_filter(z, surf.x, recipe.lowpass_wavelength, periodic=surf.periodic)
    if recipe.scale != 1.0 or recipe.lowpass_wavelength:
        surf = surf.with_heights(recipe.scale * z)
    if recipe.waviness is not None:
        w = recipe.waviness
        if isinstance(surf, Profile) and w.direction == "y" and y is not None:
            surf = surf.extrude(y)
        surf = add_waviness(surf, w.wavelength, w.amplitude, direction=w.direction)
    return surf


def build_surface_record(recipe: SurfaceRecipe, length: float, spacing, *,
                         width: float | None = None, y=None) -> SurfaceBuild:
    """The surface a recipe describes (:func:`build_surface`), with a measured file's reading
    and the form removed from it.

    Parameters
    ----------
    recipe : SurfaceRecipe
    length, spacing, width, y
        As :func:`build_surface`.

    Returns
    -------
    SurfaceBuild
    """
    if recipe.kind == "file":
        made = _measured(recipe)
    else:
        made = SurfaceBuild(_made(recipe, length, spacing, width, y))
    return SurfaceBuild(_finished(recipe, made.surface, y), made.reading, made.form)


def build_surface(recipe: SurfaceRecipe, length: float, spacing, *, width: float | None = None,
                  y=None) -> Profile | Topography:
    """The surface a recipe describes.

    Parameters
    ----------
    recipe : SurfaceRecipe
    length : float
        Length along x (m) of a generated surface (a file has its own).
    spacing : float or (float, float)
        Grid spacing (m); a pair ``(dx, dy)`` for a gaussian or self-affine topography.
    width : float, optional
        Width along y (m): a gaussian or self-affine kind then makes a topography instead of a
        profile. Profile kinds (ground, builtin, turned) ignore it.
    y : array_like, optional
        Cell-centre coordinates across x: the grid of a dent or bump, the ``y`` over which a
        profile is extruded when a waviness varies along y (without it, such a waviness is an
        error), and the rows of a gaussian or self-affine topography (with ``width`` its
        ``y.size`` times its spacing across).

    Returns
    -------
    Profile or Topography
        Profiles vary along x; the caller extrudes them where it needs a topography.
    """
    return build_surface_record(recipe, length, spacing, width=width, y=y).surface
