"""Case file of a surface analysis: which surface (``[surface]``) and how to evaluate it.

``analysis = "surface"`` characterises one or more profiles or a topography: ISO roughness
parameters, the power spectrum, the waviness/roughness split of the ISO 16610-21 Gaussian
filter, and for turned surfaces the kinematic feed-mark roughness (Seireg eq. 4.1) and the
roughness along the workpiece under tool vibration (Seireg Fig. 4.2).

Every key of ``[surface]`` belongs to some kinds; a key given for a kind that does not use it
is an error naming that key, as is a required key left out. Generated surfaces are bounded in
size (:data:`MAX_POINTS`, :data:`MAX_STEPS`) so that a case always runs in seconds.
"""

from __future__ import annotations

import math
from typing import Annotated, Literal

from pydantic import Field, ValidationError, field_validator, model_validator
from pydantic_core import InitErrorDetails, PydanticCustomError

from ..surfaces.machining import feed_limit, feed_within_limit
from .fields import CaseHeader, CaseModel, Integer, Number, OneOrList, Quantity
from .roughness import MeasuredFile, SurfaceKeys

__all__ = ["EvaluationSpec", "SurfaceCase", "SurfaceSpec", "MAX_POINTS", "MAX_STEPS"]

#: Most points of a surface (profile or topography).
MAX_POINTS = 2**20
#: Most time steps of the tool-vibration simulations of a case (:meth:`SurfaceSpec.simulated_steps`
#: each).
MAX_STEPS = 5_000_000
#: Fastest spindle of the tool-vibration model, rev/s (60 000 rpm).
MAX_SPINDLE = 1000.0
#: Default cells per feed of a turned profile (odd, so that the cusps fall on grid points).
CELLS_PER_FEED = 201
#: Default number of feeds of a turned profile.
FEEDS = 20

_BUILTIN = {"length": 5e-3, "spacing": 0.5e-6}  # defaults of asperity.surfaces.builtin_profile

#: kind -> (required keys, optional keys) of [surface]
KEYS = {
    "gaussian": ({"length", "spacing", "rms", "correlation_length"},
                 {"width", "acf", "seed"}),
    "self-affine": ({"length", "spacing", "hurst"},
                    {"width", "rms", "rms_slope", "rolloff_wavelength", "short_cutoff", "seed"}),
    "ground": ({"length", "spacing", "ra"}, {"correlation_length", "run_in", "seed"}),
    "builtin": ({"profile"}, {"length", "spacing"}),
    "file": ({"path"}, {"spacing", *MeasuredFile.model_fields}),
    "turned": ({"feed", "nose_radius"}, {"length", "spacing", "end_relief_angle"}),
}
#: Keys of the tool-vibration model of a turned surface: all required with natural_frequency.
DYNAMIC_REQUIRED = ("natural_frequency", "depth_of_cut", "cutting_speed", "workpiece_diameter",
                    "mass")
DYNAMIC_OPTIONAL = ("damping_ratio", "seed")

Frequency = Quantity("frequency", gt=0)


def _key_error(key: str | tuple, message: str, value=None) -> ValidationError:
    """A validation error located at ``key`` (a name or a path), so that its line names it."""
    loc = key if isinstance(key, tuple) else (key,)
    if message == "missing":
        detail = InitErrorDetails(type="missing", loc=loc, input=None)
    else:
        detail = InitErrorDetails(type=PydanticCustomError("value_error", message), loc=loc,
                                  input=value)
    return ValidationError.from_exception_data("case", [detail])


class SurfaceSpec(SurfaceKeys):
    """The surface to analyse: ``kind`` and the keys of that kind (others must be left out).

    - ``gaussian``: ``length``, ``spacing``, ``rms``, ``correlation_length`` (lag where the
      autocorrelation falls to 0.2); optional ``acf`` ("gaussian" or "exponential"), ``seed``,
      and ``width`` (with ``correlation_length_y``) for a topography instead of a profile.
    - ``self-affine``: ``length``, ``spacing``, ``hurst`` and exactly one of ``rms`` or
      ``rms_slope``; optional ``rolloff_wavelength``, ``short_cutoff``, ``width``, ``seed``.
    - ``ground``: transverse-ground profile, ``length``, ``spacing``, ``ra``; optional
      ``correlation_length`` (default 15 um), ``run_in`` (0 fresh .. <1 strongly run-in),
      ``seed``.
    - ``builtin``: ``profile`` "A", "B", "C" or a list of them (synthetic stand-ins of the
      mixed-EHL seed's Fig. 1 traces); optional ``length`` (5 mm), ``spacing`` (0.5 um).
    - ``file``: ``path`` (text, npy, npz, or an instrument format), relative to the case file,
      or ``builtin:NAME`` for data shipped with asperity; ``spacing`` if the file has no
      coordinates; ``unit``/``x_unit``/``z_unit``, ``missing`` and ``resample`` as in
      :class:`~asperity.cases.roughness.MeasuredFile`.
    - ``turned``: feed marks of a tool of ``nose_radius`` at ``feed`` per revolution, optional
      ``end_relief_angle`` (checks f <= 2 r sin(kappa_e), Seireg eq. 4.1), ``length`` (default
      20 feeds, rounded to whole feeds) and ``spacing`` (default feed/201, reduced to an odd
      fraction of the feed so that the cusps fall on grid points). With ``natural_frequency``
      (one value or a list to compare) the tool vibrates (Jang & Seireg's model, see
      :func:`asperity.surfaces.turned_profile_dynamic`), which needs ``depth_of_cut``,
      ``cutting_speed``, ``workpiece_diameter``, ``mass`` and takes ``damping_ratio`` (0.05)
      and ``seed``.

    The surface keys are those of :class:`~asperity.cases.roughness.SurfaceKeys`; ``profile``
    here also takes a list.
    """

    kind: Literal["gaussian", "self-affine", "ground", "builtin", "file", "turned"]
    """Which surface: "gaussian", "self-affine", "ground", "builtin", "file" or "turned" (each takes
    its own keys; others must be left out)."""
    length: Quantity("length", gt=0) | None = None
    """Length of a generated surface along x."""
    width: Quantity("length", gt=0) | None = None
    """Width along y of a generated topography (absent: a profile)."""
    profile: OneOrList(Literal["A", "B", "C"], min_length=1) | None = None
    """Built-in profile "A", "B", "C", or a list of them to compare."""
    feed: Quantity("length", gt=0, le=0.01) | None = None
    """Feed per revolution of a turning tool."""
    nose_radius: Quantity("length", gt=0, le=0.1) | None = None
    """Nose radius of the turning tool."""
    end_relief_angle: Quantity("angle", gt=0, le=math.pi / 2) | None = None
    """End-relief angle of the tool (checks f <= 2 r sin(kappa_e), Seireg eq. 4.1)."""
    natural_frequency: OneOrList(Frequency, min_length=1, max_length=8) | None = None
    """Natural frequency of the tool (one value or a list to compare); turns on the tool-vibration
    model."""
    depth_of_cut: Quantity("length", gt=0, le=0.1) | None = None
    """Depth of cut (tool-vibration model)."""
    cutting_speed: Quantity("speed", gt=0, le=100) | None = None
    """Cutting speed (tool-vibration model)."""
    workpiece_diameter: Quantity("length", gt=0, le=10) | None = None
    """Workpiece diameter (tool-vibration model)."""
    damping_ratio: Annotated[Number, Field(gt=0, lt=1)] | None = None
    """Damping ratio of the tool (tool-vibration model; default 0.05)."""
    mass: Quantity("mass", ge=1e-6, le=1e6) | None = None
    """Effective mass of the tool (tool-vibration model)."""

    @model_validator(mode="before")
    @classmethod
    def _form_degree_elsewhere(cls, data):
        """``form_degree`` belongs to ``[evaluation]`` here (a contact's ``[roughness]`` takes
        it itself): say so rather than "unknown key"."""
        if isinstance(data, dict) and "form_degree" in data:
            raise _key_error("form_degree", "expected it under [evaluation] in a surface "
                             "analysis (evaluation.form_degree)", data["form_degree"])
        return data

    @field_validator("profile", "natural_frequency")
    @classmethod
    def _distinct(cls, value):
        if value is not None and len(set(value)) != len(value):
            raise ValueError("expected distinct values")
        return value

    @model_validator(mode="after")
    def _keys_of_kind(self):
        required, optional = KEYS[self.kind]
        allowed = required | optional | {"kind"}
        if self.kind == "turned" and self.natural_frequency is not None:
            allowed |= set(DYNAMIC_REQUIRED) | set(DYNAMIC_OPTIONAL)
            required = required | set(DYNAMIC_REQUIRED)
        if self.kind == "gaussian" and self.width is not None:
            allowed |= {"correlation_length_y"}
        for key in type(self).model_fields:  # in declaration order: the first bad key is reported
            if key in self.model_fields_set and key not in allowed:
                value = getattr(self, key)
                if key in DYNAMIC_REQUIRED + DYNAMIC_OPTIONAL and self.kind == "turned":
                    raise _key_error(key, "expected natural_frequency too (the tool-vibration "
                                          "model); leave it out for kinematic turning", value)
                if key == "correlation_length_y" and self.kind == "gaussian":
                    raise _key_error(key, "expected width too (a topography)", value)
                raise _key_error(key, f"expected no {key} for kind = \"{self.kind}\"", value)
        for key in sorted(required):
            if getattr(self, key) is None:
                raise _key_error(key, "missing")
        if self.kind == "self-affine" and (self.rms is None) == (self.rms_slope is None):
            raise _key_error("rms", "expected exactly one of rms or rms_slope", self.rms)
        if self.kind == "turned":
            self._check_turning()
        self._check_size()
        return self

    def _check_turning(self):
        """Eq. (4.1)'s validity and a spacing that resolves the feed marks."""
        limit, rule = feed_limit(self.nose_radius, self.end_relief_angle)
        if not feed_within_limit(self.feed, limit):  # in mm, the angle only where given
            raise _key_error("feed", f"f <= {rule}, a feed mark formed by the nose radius "
                             f"(Seireg eq. 4.1); got {self.feed * 1e3:.4g} mm")
        if self.natural_frequency is not None:
            spindle = self.cutting_speed / (math.pi * self.workpiece_diameter)
            if spindle > MAX_SPINDLE:
                raise _key_error("cutting_speed", f"a spindle speed V / (pi D) of at most "
                                 f"{MAX_SPINDLE:g} rev/s (got {spindle:.3g})",
                                 self.cutting_speed)
        if self.spacing is not None and self.spacing > self.feed / 10:
            raise _key_error("spacing", f"at most feed / 10 = {self.feed / 10:.4g} m, to "
                                        "resolve the feed marks", self.spacing)

    def _check_size(self):
        length, spacing = self.profile_length(), self.profile_spacing()
        if length is None:
            return
        n = length / spacing
        if n < 8:
            raise _key_error("length", f"at least 8 spacings ({8 * spacing:.4g} m)", self.length)
        shape = "profile" if self.width is None else "topography"
        points = n if self.width is None else n * self.width / spacing
        if self.width is not None and self.width / spacing < 8:
            raise _key_error("width", f"at least 8 spacings ({8 * spacing:.4g} m)", self.width)
        if points > MAX_POINTS:
            raise _key_error("length" if self.width is None else "width",
                             f"at most {MAX_POINTS} points in the {shape} (got "
                             f"{points:.3g}); raise spacing or shorten it",
                             self.length if self.width is None else self.width)
        if self.kind == "turned":
            # The feed-mark envelope visits about 2 r / f + 3 arcs at every point.
            arcs = 2.0 * math.ceil(self.nose_radius / self.feed) + 3
            if n * arcs > 5e7:
                raise _key_error("length", "at most 5e7 evaluations of nose arcs (got "
                                           f"{n:.3g} points x {arcs:.0f} arcs); shorten it",
                                 self.length)
            if self.natural_frequency is not None:
                steps = self.simulated_steps() * len(self.natural_frequency)
                if steps > MAX_STEPS:
                    raise _key_error("length", f"at most {MAX_STEPS} time steps over all "
                                     f"natural frequencies (got {steps:.3g}); shorten it or "
                                     "raise cutting_speed", self.length)

    def profile_spacing(self) -> float | None:
        """Grid spacing (m) of a generated surface; None for a file (taken from the file)."""
        if self.kind == "file":
            return None
        if self.kind == "builtin":
            return self.spacing or _BUILTIN["spacing"]
        if self.kind == "turned":
            cells = CELLS_PER_FEED if self.spacing is None else self.feed / self.spacing
            return self.feed / (2 * math.ceil((cells - 1) / 2) + 1)
        return self.spacing

    def profile_length(self) -> float | None:
        """Length (m) of a generated surface along x; None for a file."""
        if self.kind == "file":
            return None
        if self.kind == "builtin":
            return self.length or _BUILTIN["length"]
        if self.kind == "turned":
            feeds = FEEDS if self.length is None else max(1, round(self.length / self.feed))
            return feeds * self.feed
        return self.length

    def simulated_steps(self) -> float:
        """Time steps of one tool-vibration simulation, by the step rule of
        :func:`~asperity.surfaces.turned_profile_dynamic`: at least 40 steps per natural period
        and 2 per correlation time of its default 1 kHz force noise, over every revolution."""
        period = math.pi * self.workpiece_diameter / self.cutting_speed
        revolutions = self.profile_length() / self.feed + 2 * self.nose_radius / self.feed + 2
        rate = max(40.0 * max(self.natural_frequency), 2.0 * 1000.0)
        return revolutions * math.ceil(period * rate)

    def labels(self) -> list[str]:
        """Names of the surfaces this spec makes, in order (the first is analysed in full)."""
        if self.kind == "builtin":
            return list(self.profile)
        if self.kind == "turned":
            dynamic = [f"{fn:g} Hz" for fn in self.natural_frequency or ()]
            return [*dynamic, "kinematic"]
        return [self.kind]


class EvaluationSpec(CaseModel):
    """How to evaluate profiles (all optional).

    - ``cutoff``: the ISO 16610-21 Gaussian filter's cut-off wavelength lambda_c; the
      parameters are then those of the roughness profile (profile minus the filter's mean line,
      the waviness), evaluated without half a cut-off at each end of a non-periodic profile.
    - ``sampling_length``: parameters are computed in consecutive sampling lengths and averaged
      (ISO 4287; Rz is the mean of the peak-to-valley heights); otherwise over the whole
      evaluation length.
    - ``window``: length of the windows of the roughness along a turned workpiece (Seireg
      Fig. 4.2); default about a twentieth of the length, in whole feeds.
    - ``form_degree``: degree of the least-squares polynomial removed as form before the
      parameters (default 1, a line or plane; 2 for a cylinder or ball).
    """

    cutoff: Quantity("length", gt=0) | None = None
    """Cut-off wavelength lambda_c of the ISO 16610-21 Gaussian filter; parameters are then those of
    the roughness profile."""
    sampling_length: Quantity("length", gt=0) | None = None
    """Sampling length: parameters computed in consecutive sampling lengths and averaged (ISO 4287).
    """
    window: Quantity("length", gt=0) | None = None
    """Window length of the roughness along a turned workpiece (Seireg Fig. 4.2; default about a
    twentieth of the length)."""
    form_degree: Annotated[Integer, Field(ge=0, le=9)] | None = None
    """Degree of the least-squares polynomial removed as form (default 1, a line or plane; 2 for
    a cylinder or ball)."""


class SurfaceCase(CaseHeader):
    """``analysis = "surface"``: roughness parameters, spectrum, filtering, turning models."""

    analysis: Literal["surface"]
    """Selects the surface analysis."""
    title: str = "Surface analysis"
    surface: SurfaceSpec
    """The surface to analyse."""
    evaluation: EvaluationSpec = EvaluationSpec()
    """How to evaluate it (filter cut-off, sampling length, window)."""

    @model_validator(mode="after")
    def _window_for_turning(self):
        if self.evaluation.window is not None and self.surface.natural_frequency is None:
            raise _key_error(("evaluation", "window"), "expected no window without "
                             "surface.natural_frequency (the windows of the roughness along a "
                             "vibrating turned workpiece)", self.evaluation.window)
        return self
