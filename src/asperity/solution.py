"""The result protocol shared by every solver's result, and renamed keywords.

Every solver returns a frozen dataclass that mixes in :class:`SolverResult`:

- ``converged``, ``iterations``, ``residual`` (fields or properties of the result);
- ``message``: one line saying whether and how the solve converged;
- ``warnings``: a tuple of lines, each a reason the answer may not be trusted (empty when
  none);
- ``to_dataset()``: the fields on their grid as an :class:`xarray.Dataset` with ``units`` and
  ``long_name`` on every variable and coordinate, the names the command line writes to
  ``result.nc``;
- a compact ``repr``: the class, the grid, the scalars and the convergence, not whole arrays.

A result class names its variables in ``VARIABLES``: variable name -> ``(units, long_name)``,
``(units, long_name, dims)`` or ``(units, long_name, dims, field)`` when the field has another
name; dims default to ``("x", "y")``, and a field of shape ``(2, nx, ny)`` is split into
``<name>_x`` and ``<name>_y``. Coordinates other than ``x`` and ``y`` come from extending
:meth:`SolverResult.coordinates`.

:func:`renamed_keywords` accepts a keyword's old spelling with a :class:`DeprecationWarning`
(``max_iterations`` and ``max_sweeps`` -> ``max_iter``, ``center`` -> ``centre``);
:func:`renamed_attribute` keeps a result field's old spelling as a read-only property that warns
(``center_of_rotation`` -> ``centre_of_rotation``).
"""

from __future__ import annotations

import dataclasses
import functools
import warnings

import numpy as np
import xarray as xr

__all__ = ["SolverResult", "renamed_attribute", "renamed_keywords"]

_COORDINATES = {"x": ("m", "x (first in-plane direction)"),
                "y": ("m", "y (second in-plane direction)")}


class SolverResult:
    """Mixin of the solvers' result dataclasses: message, warnings, Dataset, compact repr."""

    VARIABLES: dict = {}

    @property
    def message(self) -> str:
        """One line: converged or not, after how many iterations, with which residual."""
        state = "converged" if self.converged else "did not converge"
        return (f"{type(self).__name__}: {state} after {int(self.iterations)} iterations "
                f"(residual {float(self.residual):.3g})")

    @property
    def warnings(self) -> tuple[str, ...]:
        """Reasons the answer may not be trusted, one line each (empty when there are none)."""
        if self.converged:
            return ()
        return (f"the solve did not converge in {int(self.iterations)} iterations (residual "
                f"{float(self.residual):.3g}): do not trust the result",)

    def to_dataset(self) -> xr.Dataset:
        """The result's fields as an xarray Dataset with units and long names.

        Returns
        -------
        xarray.Dataset
            The variables of ``VARIABLES`` on coordinates ``x``, ``y`` (m) where the result
            has them; the scalar fields, ``converged``, ``message`` and the warnings as
            attributes.
        """
        coords = {name: xr.Variable(name, np.asarray(value), {"units": units,
                                                               "long_name": long_name})
                  for name, (value, units, long_name) in self.coordinates().items()}
        data = {}
        for name, spec in self.VARIABLES.items():
            units, long_name, dims, attribute = (*spec, ("x", "y"), name, name)[:4] \
                if len(spec) == 2 else (*spec, name)[:4]
            value = np.asarray(getattr(self, attribute))
            if value.dtype == bool:
                value = value.astype("i1")
            if value.ndim == len(dims) + 1 and value.shape[0] == 2:
                for axis, component in zip("xy", value, strict=True):
                    data[f"{name}_{axis}"] = xr.Variable(
                        dims, component, {"units": units, "long_name": f"{long_name}, {axis}"})
            else:
                data[name] = xr.Variable(dims, value, {"units": units, "long_name": long_name})
        attrs = {"solver_result": type(self).__name__, "converged": int(bool(self.converged)),
                 "message": self.message, "warnings": "\n".join(self.warnings)}
        attrs.update({k: v for k, v in self._scalars().items() if k not in attrs})
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def coordinates(self) -> dict:
        """Dataset coordinates: name -> (values, units, long_name); ``x``, ``y`` when present."""
        return {name: (getattr(self, name), units, long_name)
                for name, (units, long_name) in _COORDINATES.items()
                if getattr(self, name, None) is not None}

    def _scalars(self) -> dict:
        """Fields that are numbers, strings or flags (netCDF attribute types)."""
        out = {}
        for f in dataclasses.fields(self):
            value = getattr(self, f.name)
            if isinstance(value, bool | np.bool_):
                out[f.name] = int(value)
            elif isinstance(value, int | float | str | np.integer | np.floating):
                out[f.name] = value.item() if isinstance(value, np.generic) else value
        return out

    def __repr__(self) -> str:
        parts = []
        x, y = getattr(self, "x", None), getattr(self, "y", None)
        if x is not None and y is not None:
            parts.append(f"grid {np.size(x)} x {np.size(y)}")
        for key in self._scalars():
            if key in ("converged", "iterations", "residual"):
                continue
            value = getattr(self, key)
            parts.append(f"{key}={value:.4g}" if isinstance(value, float | np.floating)
                         and not isinstance(value, bool) else f"{key}={value!r}")
        parts.append(self.message.split(": ", 1)[1])
        return f"<{type(self).__name__} " + ", ".join(parts) + ">"


def renamed_keywords(**renames):
    """Decorator: accept each keyword's old spelling (``old="new"``) with a DeprecationWarning.

    Examples
    --------
    >>> @renamed_keywords(max_iterations="max_iter")
    ... def solve(*, max_iter=10):
    ...     return max_iter
    """

    def decorate(fn):
        @functools.wraps(fn)
        def wrapper(*args, **kwargs):
            for old, new in renames.items():
                if old in kwargs:
                    if new in kwargs:
                        raise TypeError(f"{fn.__name__}() got both {old!r} and {new!r}")
                    warnings.warn(f"{fn.__name__}: {old!r} is deprecated, use {new!r}",
                                          DeprecationWarning, stacklevel=2)
                    kwargs[new] = kwargs.pop(old)
            return fn(*args, **kwargs)

        return wrapper

    return decorate


def renamed_attribute(old: str, new: str) -> property:
    """A read-only property under an attribute's old spelling that warns (DeprecationWarning).

    Parameters
    ----------
    old, new : str
        The old spelling (the name the property is bound to) and the attribute it reads.

    Returns
    -------
    property
        Reading it warns and returns ``getattr(self, new)``.

    Examples
    --------
    >>> from dataclasses import dataclass
    >>> @dataclass(frozen=True)
    ... class Result:
    ...     centre: float
    ...     center = renamed_attribute("center", "centre")
    """

    def get(self):
        warnings.warn(f"{type(self).__name__}.{old} is deprecated, use {new!r}",
                      DeprecationWarning, stacklevel=2)
        return getattr(self, new)

    return property(get, doc=f"Deprecated spelling of ``{new}`` (read-only; warns).")
