"""Building blocks of case files: quantities with units, strict models, error formatting.

A quantity field accepts a plain number (SI) or a string with a unit (``"2160 lbf"``); it is
converted once by :func:`asperity.units.to_si`. A count (:data:`Integer`) or a plain number
(:data:`Number`) takes a TOML number only: pydantic would read ``"128"`` as 128 and ``true`` as 1.
Models forbid unknown keys, so a misspelt key is reported instead of silently ignored, with
the key of its table that reads like it.
"""

from __future__ import annotations

import difflib
import typing
from typing import Annotated

from pydantic import (
    BaseModel,
    BeforeValidator,
    ConfigDict,
    Field,
    ValidationError,
    ValidationInfo,
    WrapValidator,
)
from pydantic_core import PydanticCustomError

from ..errors import InputError
from ..formatting import format_quantity
from ..units import DIMENSIONS, to_si
from .keys import case_keys

__all__ = [
    "CaseHeader",
    "CaseModel",
    "Quantity",
    "Integer",
    "Number",
    "Length",
    "PositiveLength",
    "Force",
    "Pressure",
    "PositivePressure",
    "Moment",
    "Speed",
    "OneOrList",
    "existing_file",
    "first_error",
]


class CaseModel(BaseModel):
    """Base of every case-file table: unknown keys are errors, instances are immutable.

    A field's docstring (the string under it) is its description, listed by ``asperity schema``
    and in ``docs/cases.md``.
    """

    model_config = ConfigDict(extra="forbid", frozen=True, validate_default=True,
                              use_attribute_docstrings=True)


class CaseHeader(CaseModel):
    """The keys every case file may start with: ``title``, ``description``, ``source`` (the
    book figure or paper table a built-in example reproduces)."""

    title: str = "asperity case"
    """Heading of the report."""
    description: str = ""
    """One or two sentences under the heading: what the case is."""
    source: str = ""
    """The book figure or paper table the case reproduces."""


def _converter(dimension: str):
    unit = DIMENSIONS[dimension]

    def convert(value):
        try:
            return to_si(value, dimension, "")
        except InputError as exc:
            raise ValueError(f"expected {exc.expected}") from None

    convert.__name__ = f"to_{dimension}"
    convert.__doc__ = f"Convert to {unit or 'a pure number'}."
    return convert


def Quantity(dimension: str, **constraints):  # noqa: N802 - reads as a type in annotations
    """An annotated float field measured in ``dimension`` (a key of ``units.DIMENSIONS``).

    Keyword constraints (``gt``, ``ge``, ``lt``, ``le``) apply to the SI value. The dimension is
    kept in the field's JSON-schema extra (``{"dimension": ...}``) for the key reference.
    """
    return Annotated[float, BeforeValidator(_converter(dimension)),
                     Field(json_schema_extra={"dimension": dimension}, **constraints)]


def _whole_number(value):
    """A count as TOML writes it: an integer, or a float without a fraction (``128.0``, ``1e4``
    are the same count); a string (``"128"``) or a bool is refused."""
    if isinstance(value, float) and value.is_integer():
        return int(value)
    if isinstance(value, bool) or not isinstance(value, int):
        raise ValueError("expected a whole number such as 128")
    return value


def _plain_number(value):
    """A pure number as TOML writes it (an integer or a float); a string or a bool is
    refused."""
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise ValueError("expected a number such as 0.5")
    return value


#: An integer field (mesh sizes, counts, seeds, steps, levels): a TOML integer, or a float
#: without a fraction; ``"128"`` and ``true`` are refused. Constrain it with
#: ``Annotated[Integer, Field(ge=..., le=...)]``.
Integer = Annotated[int, BeforeValidator(_whole_number)]

#: A pure-number field without a unit (a ratio, a tolerance, a coefficient): a TOML integer or
#: float; ``"0.5"`` and ``true`` are refused.
Number = Annotated[float, BeforeValidator(_plain_number)]

Length = Quantity("length")
PositiveLength = Quantity("length", gt=0)
Force = Quantity("force")
Pressure = Quantity("pressure")
PositivePressure = Quantity("pressure", gt=0)
Moment = Quantity("moment")
Speed = Quantity("speed")


def _one_or_list(value, handler):
    """Validate a list; a single value is validated as a list of one, and an error in it is
    reported at the key itself (``surface.profile``), not at an item the user did not write
    (``surface.profile[0]``)."""
    if isinstance(value, list | tuple):
        return handler(value)
    try:
        return handler([value])
    except ValidationError as exc:
        err = exc.errors(include_url=False)[0]
        if err["loc"][:1] != (0,):  # not the item's own error (e.g. a length bound)
            raise
        raise PydanticCustomError(err["type"], err["msg"].replace("{", "{{").replace("}", "}}"),
                                  err.get("ctx")) from None


def OneOrList(item, **constraints):  # noqa: N802 - reads as a type in annotations
    """A tuple field of ``item`` values that also takes one value (a list of one).

    Keyword constraints (``min_length``, ``max_length``) apply to the list. An error in a
    single value names the key as written, without the ``[0]`` of the list it became.
    """
    return Annotated[tuple[item, ...], Field(**constraints), WrapValidator(_one_or_list)]


def existing_file(cls, value, info: ValidationInfo):
    """Field validator of file paths (use as ``field_validator("path")(existing_file)``).

    The file must exist. A relative path is relative to the case file's folder, or for a case
    without a file (TOML text, a built-in example) to the working directory and failing that to
    the folder of the built-in examples (their shipped data).
    """
    from importlib import resources
    from pathlib import Path

    if value is None:
        return value
    path = Path(value)
    if not path.is_absolute():
        base = (info.context or {}).get("base_dir")
        if base is not None:
            path = Path(base) / path
        elif not path.is_file():
            shipped = resources.files("asperity.examples") / value
            path = Path(str(shipped)) if shipped.is_file() else path
    if not path.is_file():
        raise ValueError("expected an existing file")
    return str(path)


_PROBLEMS = {
    "missing": "missing (a value is required)",
    "extra_forbidden": "unknown key (check the spelling)",
}

_LENGTHS = {"too_short": ("at least", "min_length"), "too_long": ("at most", "max_length")}


#: pydantic's bound errors, in words
_BOUNDS = {"greater_than": "more than", "greater_than_equal": "at least",
           "less_than": "less than", "less_than_equal": "at most"}


def _bound_with_unit(err: dict, field: str, model: type[BaseModel] | None,
                     data) -> InputError | None:
    """A quantity's bound in a readable unit, and a bare number's reading in SI.

    pydantic states the bound of the SI value as a bare number: ``roughness.rms = 0.1``
    (meant in um, read in m) was told "expected a value less than or equal to 0.01, got 0.1",
    naming neither unit. Now: "expected at most 10 mm, got 0.1 (a bare number is in m:
    100 mm)". None where the error is no bound of a quantity whose key :func:`case_keys`
    lists (the caller's message stands).
    """
    words = _BOUNDS.get(err["type"])
    if words is None or model is None:
        return None
    key = ".".join(str(p) for p in err["loc"]
                   if isinstance(p, str) and not p.startswith("function-"))
    unit = next((k.unit for k in case_keys(model) if k.key == key and k.type == "quantity"),
                "")
    bound = next(iter(err.get("ctx", {}).values()), None)
    if not unit or not isinstance(bound, int | float):
        return None
    raw = _written_at(data, err["loc"])
    value = err.get("input")
    got = f"{raw!r}" if isinstance(raw, str) else f"{value:g}"
    if isinstance(raw, int | float) and not isinstance(raw, bool) and raw != 0:
        got += f" (a bare number is in {unit}: {format_quantity(float(raw), unit)})"
    return InputError(field, "", problem=f"expected {words} {format_quantity(bound, unit)}, "
                      f"got {got}")


def _key(part) -> str:
    """A key as written in a case file; odd keys (spaces, control characters) quoted."""
    text = str(part)
    return text if text.replace("_", "").replace("-", "").isalnum() else repr(text)


def _misspelling(missing: dict, errors: list[dict]) -> dict | None:
    """The unknown key beside a missing one that reads like it (``[laoding]`` for
    ``loading``), so that the error names the key the user wrote rather than only the one
    the case lacks; None where there is none."""
    if missing["type"] != "missing":
        return None
    *parent, wanted = missing["loc"]
    unknown = {str(e["loc"][-1]): e for e in errors
               if e["type"] == "extra_forbidden" and list(e["loc"][:-1]) == parent}
    close = difflib.get_close_matches(str(wanted), list(unknown), n=1, cutoff=0.75)
    return unknown[close[0]] if close else None


def _tables(annotation) -> list[type[BaseModel]]:
    """The models a field's annotation holds (a table, a list of tables, a union of them)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    return [m for arg in typing.get_args(annotation) for m in _tables(arg)]


def _table_keys(model: type[BaseModel], loc) -> list[str]:
    """The keys of the table at ``loc`` (a pydantic error location below ``model``): list
    items are skipped, a part that names no key (a union member's tag) keeps the tables."""
    tables = [model]
    for part in loc:
        fields = {info.alias or name: info for table in tables
                  for name, info in table.model_fields.items()}
        if isinstance(part, str) and part in fields:
            tables = _tables(fields[part].annotation)
    return list(dict.fromkeys(info.alias or name for table in tables
                              for name, info in table.model_fields.items()))


def _written_at(data, loc):
    """The value the user wrote at ``loc`` (keys and list indices) of the case's ``data``,
    or None where there is none."""
    for part in loc:
        try:
            data = data[part]
        except (KeyError, IndexError, TypeError):
            return None
    return data


def _given_keys(data, loc) -> set[str]:
    """The keys the user wrote in the table at ``loc`` of the case's ``data``."""
    table = _written_at(data, loc)
    return set(table) if isinstance(table, dict) else set()


def _unknown_key(err: dict, model: type[BaseModel] | None, data) -> str:
    """The problem of an unknown key: the key of its table that reads like it, if any, and
    is not written already (``rxx`` beside ``rx`` is no misspelt ``rx``)."""
    *parent, wrong = err["loc"]
    keys = _table_keys(model, parent) if model is not None else []
    keys = [k for k in keys if k not in _given_keys(data, parent)]
    close = difflib.get_close_matches(str(wrong), keys, n=1, cutoff=0.7)
    return f"unknown key; did you mean '{close[0]}'?" if close else _PROBLEMS[err["type"]]


def first_error(exc: ValidationError, prefix: str = "", model: type[BaseModel] | None = None,
                data: dict | None = None) -> InputError:
    """Turn pydantic's first validation error into one :class:`InputError` line.

    An :class:`InputError` raised by a validator (one that checks a key against the rest of the
    case, such as a domain bound against the Hertz semi-axes) keeps the key it names. Given the
    validated ``model`` and its input ``data``, an unknown key is answered with the key of its
    table that reads like it and was not written (``loading.lod``: did you mean 'load'?).

    Parameters
    ----------
    exc : pydantic.ValidationError
        The error of validating a case (or a table of one).
    prefix : str
        Dotted path put before the key the error names.
    model : type of pydantic.BaseModel, optional
        The model validated, whose tables' keys an unknown key is matched against.
    data : dict, optional
        The input validated, whose keys are not offered for an unknown one.

    Returns
    -------
    InputError
        One line naming the key.
    """
    errors = exc.errors(include_url=False)
    err = errors[0]
    misspelt = _misspelling(err, errors)
    if misspelt is not None:
        *parent, wrong = misspelt["loc"]
        name = ".".join(p for p in (prefix, *map(_key, parent), _key(wrong)) if p)
        return InputError(name, "", problem=f"unknown key; did you mean '{_key(err['loc'][-1])}'"
                          f" (which is missing)?")
    raised = err.get("ctx", {}).get("error")
    if isinstance(raised, InputError):
        field = ".".join(p for p in (prefix, raised.field) if p)
        return InputError(field, raised.expected, raised.got, problem=raised.problem)
    loc = ""
    for part in err["loc"]:
        if str(part).startswith("function-"):
            continue
        if isinstance(part, int):  # a list's item as the case file's readers write it
            loc += f"[{part}]"
        else:
            loc += ("." if loc else "") + _key(part)
    field = ".".join(p for p in (prefix, loc) if p) or "case"
    if err["type"] == "extra_forbidden":
        return InputError(field, "", problem=_unknown_key(err, model, data))
    if err["type"] in _PROBLEMS:
        return InputError(field, "", problem=_PROBLEMS[err["type"]])
    if err["type"] in _LENGTHS:
        bound, key = _LENGTHS[err["type"]]
        ctx = err["ctx"]
        expected = f"a list of {bound} {ctx[key]} item{'s' * (ctx[key] != 1)}"
        return InputError(field, expected, problem=f"expected {expected}, got "
                          f"{ctx['actual_length']}")
    bounded = _bound_with_unit(err, field, model, data)
    if bounded is not None:
        return bounded
    msg = err["msg"]
    for lead in ("Value error, ", "Assertion failed, "):
        msg = msg.removeprefix(lead)
    msg = msg.split(", unable to")[0].split(", got a number with")[0]
    msg = msg.removeprefix("expected ").removeprefix("Input should be ")
    if msg.startswith(("greater", "less")):
        msg = "a value " + msg
    got = err.get("input")  # a list as written ([10, 20] for a load); a table left out
    return InputError(field, msg, None if isinstance(got, dict) else got)
