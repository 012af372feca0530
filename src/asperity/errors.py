"""Exceptions that asperity raises for bad input and failed solves.

Every error caused by the user's input is an :class:`InputError` (a ``ValueError``) whose
message names the offending field and what was expected, so that the command line can print it
as one line and exit with status 2.
"""

from __future__ import annotations

import numbers

__all__ = ["InputError", "check_finite", "check_int", "check_positive"]


class InputError(ValueError):
    """Invalid input: the message names the field and what was expected.

    Parameters
    ----------
    field : str
        Dotted path of the offending field (``"load"``, ``"body1.youngs_modulus"``).
    expected : str
        What a valid value looks like, in words.
    got : object, optional
        The value received, shown in the message when given.
    problem : str, optional
        A statement of what is wrong used instead of "expected ..." (e.g. "unknown key").
    """

    def __init__(self, field: str, expected: str, got: object = None, *, problem: str = ""):
        self.field = field
        self.expected = expected
        self.got = got
        self.problem = problem
        msg = f"{field}: {problem or 'expected ' + expected}"
        if got is not None:
            msg += f", got {_short(got)}"
        super().__init__(" ".join(msg.splitlines()))  # always one line


def _short(value: object, limit: int = 60) -> str:
    """The value as the case file writes it (``true``, not Python's ``True``), cut short."""
    text = str(value).lower() if isinstance(value, bool) else repr(value)
    return text if len(text) <= limit else text[: limit - 3] + "..."


def check_finite(field: str, value):
    """Raise :class:`InputError` unless every element of ``value`` is finite; return it."""
    import numpy as np

    arr = np.asarray(value, dtype=float)
    if not np.all(np.isfinite(arr)):
        raise InputError(field, "finite numbers (no NaN or infinity)")
    return value


def check_positive(field: str, value: float, *, allow_zero: bool = False) -> float:
    """Raise :class:`InputError` unless ``value`` is a finite number > 0 (or >= 0)."""
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise InputError(field, "a number", value) from None
    import math

    if not math.isfinite(v) or v < 0 or (v == 0 and not allow_zero):
        expected = "a finite number >= 0" if allow_zero else "a finite number > 0"
        raise InputError(field, expected, value)
    return v


def check_int(field: str, value, minimum: int, expected: str | None = None) -> int:
    """Raise :class:`InputError` unless ``value`` is an integer (not a bool) >= ``minimum``."""
    if isinstance(value, bool) or not isinstance(value, numbers.Integral) or value < minimum:
        raise InputError(field, expected or f"an integer >= {minimum}", value)
    return int(value)
