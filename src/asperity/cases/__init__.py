"""Case files: one TOML schema for every analysis, validated with pydantic.

``analysis`` selects the table layout (``"normal"``, ``"tangential"``, ``"ehl-steady"``,
``"ehl-transient"``, ``"surface"``, ``"gear"``). :func:`load_case` turns a file, a TOML string
or a dict into a validated, immutable case whose quantities are SI floats; any error becomes one
:class:`asperity.InputError` line naming the key path.
"""

from __future__ import annotations

import re
import sys
from pathlib import Path
from typing import Any

from pydantic import ValidationError

from ..errors import InputError
from .ehl import EHLSteadyCase
from .ehl_transient import EHLTransientCase
from .fields import first_error
from .gear import GearCase
from .normal import NormalCase
from .surface import SurfaceCase
from .tangential import TangentialCase

if sys.version_info >= (3, 11):
    import tomllib
else:  # pragma: no cover
    import tomli as tomllib

__all__ = ["ANALYSES", "load_case", "parse_toml"]

#: Case models by the value of their ``analysis`` key.
ANALYSES = {
    "normal": NormalCase,
    "surface": SurfaceCase,
    "ehl-steady": EHLSteadyCase,
    "ehl-transient": EHLTransientCase,
    "tangential": TangentialCase,
    "gear": GearCase,
}

def parse_toml(text: str, origin: str = "case") -> dict[str, Any]:
    """Parse TOML text; a syntax error becomes an :class:`InputError` naming the line.

    A leading byte-order mark (Windows editors save UTF-8 with one) is not part of the text:
    TOML refused it as an invalid statement at line 1.
    """
    try:
        return tomllib.loads(text.removeprefix("\ufeff"))
    except tomllib.TOMLDecodeError as exc:
        raise InputError(origin, f"valid TOML ({exc})") from None


def load_case(source: str | Path | dict) -> Any:
    """Validate a case given as a path to a TOML file, TOML text, a dict, or an example's name.

    ``load_case("gear-dry-hertz")`` loads the built-in example of that name (``asperity
    examples`` lists them).

    Returns
    -------
    pydantic model
        The analysis' case model (e.g. :class:`~asperity.cases.normal.NormalCase`).

    Raises
    ------
    InputError
        Unknown or misspelt keys, missing values, wrong types, out-of-range values, unknown
        units; the message names the key path.
    """
    if isinstance(source, Path) or (isinstance(source, str) and source.endswith(".toml")
                                     and "\n" not in source):
        path = Path(source)
        if not path.is_file():
            raise InputError("case", "an existing TOML file", str(path))
        data = parse_toml(path.read_text(encoding="utf-8"), str(path))
        base_dir = str(path.resolve().parent)
    elif isinstance(source, str) and re.fullmatch(r"[A-Za-z0-9][A-Za-z0-9_.-]*", source.strip()):
        from ..examples import example_text

        data, base_dir = parse_toml(example_text(source.strip()), source), None
    elif isinstance(source, str):
        data, base_dir = parse_toml(source), None
    elif isinstance(source, dict):
        data, base_dir = source, None
    else:
        raise InputError("case", "a TOML file path, TOML text or a dict", type(source).__name__)
    analysis = data.get("analysis")
    if not isinstance(analysis, str) or analysis not in ANALYSES:
        raise InputError("analysis", "one of " + ", ".join(f'"{a}"' for a in ANALYSES),
                         analysis)
    model = ANALYSES[analysis]
    try:
        return model.model_validate(data, context={"base_dir": base_dir})
    except ValidationError as exc:
        raise first_error(exc, model=model, data=data) from None
