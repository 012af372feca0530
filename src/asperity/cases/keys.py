"""Every key of a case file, read from the pydantic models: type, unit, default, meaning.

The reference behind ``asperity schema`` and ``docs/cases.md``. The unit of a quantity comes
from its :func:`~asperity.cases.fields.Quantity` dimension, the meaning from the field's
description (its docstring in the model), the default from the field itself.
"""

from __future__ import annotations

import functools
import operator
import types
import typing
from dataclasses import dataclass

from pydantic import BaseModel
from pydantic.fields import FieldInfo

from ..units import DIMENSIONS

__all__ = ["CaseKey", "case_keys"]

_NAMES = {str: "text", int: "integer", float: "number", bool: "true/false"}


@dataclass(frozen=True)
class CaseKey:
    """One key of a case file.

    Attributes
    ----------
    key : str
        Dotted path as written in TOML (``body1.youngs_modulus``; ``[[pressure.regions]]``
        entries as ``pressure.regions[].size``).
    type : str
        What the value is: ``quantity``, ``number``, ``integer``, ``text``, ``true/false``, a
        list of choices, ``table``, ``list of tables``, ``pair of quantities`` ...
    unit : str
        SI unit of a quantity (any unit of the same dimension is accepted as a string); empty
        for pure numbers and text.
    default : str
        The default as TOML would write it; ``required`` when there is none; ``-`` when the key
        is optional with no value (the analysis chooses or the table is absent).
    meaning : str
        The field's description.
    """

    key: str
    type: str
    unit: str
    default: str
    meaning: str


def _strip_optional(annotation):
    """The annotation without ``None``."""
    if typing.get_origin(annotation) in (typing.Union, types.UnionType):
        args = [a for a in typing.get_args(annotation) if a is not type(None)]
        if len(args) < len(typing.get_args(annotation)):
            return functools.reduce(operator.or_, args)
    return annotation


def _extra(annotation, info: FieldInfo | None = None) -> dict:
    """The JSON-schema extra of a field or of its Annotated metadata (``dimension``, and a
    ``type`` text where the value is more than a quantity; or the ``unit`` a plain number is
    given in, such as a temperature in deg C)."""
    extras = [info.json_schema_extra] if info is not None else []
    if typing.get_origin(annotation) is typing.Annotated:
        extras += [m.json_schema_extra for m in typing.get_args(annotation)[1:]
                   if isinstance(m, FieldInfo)]
    return next((e for e in extras if isinstance(e, dict) and ("dimension" in e or "unit" in e)),
                {})


def _dimension(annotation, info: FieldInfo | None = None) -> str | None:
    """The Quantity dimension of a (possibly Annotated) float annotation."""
    dimension = _extra(annotation, info).get("dimension")
    return None if dimension is None else str(dimension)


def _models(annotation) -> list[type[BaseModel]]:
    """The case models an annotation holds (a table, a list of tables, a union of tables)."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return [annotation]
    found = [m for arg in typing.get_args(annotation) for m in _models(arg)]
    return list(dict.fromkeys(found))


def _describe_type(annotation, info: FieldInfo | None) -> tuple[str, str]:
    """(type text, SI unit) of a field annotation; a plain number's ``unit`` extra is its
    unit."""
    number_unit = _extra(annotation, info).get("unit")
    if number_unit is not None:
        base = typing.get_args(annotation)[0] \
            if typing.get_origin(annotation) is typing.Annotated else annotation
        kind = _extra(annotation, info).get("type") or _describe_type(base, None)[0]
        return kind, number_unit
    dimension = _dimension(annotation, info)
    if dimension is not None:
        unit = DIMENSIONS[dimension]
        return _extra(annotation, info).get("type", "quantity" if unit else "number"), unit
    origin, args = typing.get_origin(annotation), typing.get_args(annotation)
    if origin is typing.Annotated:
        return _describe_type(args[0], None)
    if origin is typing.Literal:
        return "one of " + ", ".join(f'"{a}"' if isinstance(a, str) else str(a)
                                      for a in args), ""
    if origin in (tuple, list):
        items = [a for a in args if a is not Ellipsis]
        inner, unit = _describe_type(items[0], None) if items else ("value", "")
        plural = {"quantity": "quantities"}.get(inner, inner + "s")
        if inner.startswith("one of"):
            plural = f"values ({inner})"
        if origin is tuple and len(items) == 2 and Ellipsis not in args:
            return f"pair of {plural}", unit
        return f"list of {plural}", unit
    if origin in (typing.Union, types.UnionType):
        parts = [_describe_type(a, None) for a in args]
        units = {u for _, u in parts if u}
        return " or ".join(dict.fromkeys(t for t, _ in parts)), units.pop() if len(
            units) == 1 else ""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return "table", ""
    return _NAMES.get(annotation, getattr(annotation, "__name__", str(annotation))), ""


def _default(info: FieldInfo) -> str:
    if info.is_required():
        return "required"
    value = info.get_default(call_default_factory=True)
    if value is None:
        return "-"
    if isinstance(value, BaseModel):
        return "(table)"
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, float):
        return f"{value:.6g}"
    if isinstance(value, tuple | list):
        return "[" + ", ".join(f"{v:.6g}" if isinstance(v, float) else str(v)
                               for v in value) + "]"
    return str(value)


def _meaning(model: type[BaseModel], name: str) -> str:
    """The field's description, or that of the base class field it overrides."""
    for cls in model.__mro__:
        info = getattr(cls, "model_fields", {}).get(name)
        if info is not None and info.description:
            return " ".join(info.description.split())
    return ""


def case_keys(model: type[BaseModel], prefix: str = "") -> list[CaseKey]:
    """Every key of a case model and its tables, depth first, in the order of the model.

    Parameters
    ----------
    model : type of pydantic.BaseModel
        A case model (``asperity.cases.ANALYSES[name]``) or one of its tables.
    prefix : str
        Dotted path of the table (for recursion).

    Returns
    -------
    list of CaseKey
    """
    keys = []
    for name, info in model.model_fields.items():
        key = prefix + (info.alias or name)
        annotation = _strip_optional(info.annotation)
        kind, unit = _describe_type(annotation, info)
        tables = _models(annotation)
        is_list = typing.get_origin(annotation) in (list, tuple)
        if tables:
            kind = "list of tables" if is_list else "table"
        keys.append(CaseKey(key, kind, unit, _default(info),
                            _meaning(model, name)))
        for table in tables:
            keys += case_keys(table, key + ("[]." if is_list else "."))
    unique = {k.key: k for k in keys}  # a table reached through two unions once
    return list(unique.values())
