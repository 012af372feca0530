"""Doubts about what a bare number in a case file meant.

A bare TOML number is read in the key's SI unit, which is what it means most of the time and
silently wrong when the user wrote it in the unit they think in: ``rx = 9.525`` for a 3/4 in
ball is a 9.5 m radius, ``youngs_modulus = 30e6`` for a steel in psi is 30 MPa. The run
cannot know, so it says both readings and what to write, first among its warnings, for the
values whose bare reading is implausible for what the key holds
(:meth:`asperity.cases.bodies.MaterialSpec.unit_doubts`, :class:`CurvedBody`,
:meth:`asperity.cases.ehl.LubricantSpec.unit_doubts`). A value with
its unit is not doubted, except a slide/roll ratio beyond 2 however written
(:meth:`asperity.cases.ehl.SpeedSpec.unit_doubts`: ``xi = 25`` meant as 25 %).
"""

from __future__ import annotations

from pydantic import PrivateAttr, model_validator

from ..formatting import format_quantity
from .fields import CaseModel

__all__ = ["BARE_RADIUS", "BARE_VISCOSITY", "BareNumbers", "CurvedBody", "unit_doubts"]

#: A radius of relative curvature given as a bare number (metres) at least this large is
#: doubted: the contacts asperity models have radii of millimetres to centimetres (a crowned
#: roller's or a rail's transverse radius a few tenths of a metre), and a radius of metres
#: written bare is most often millimetres.
BARE_RADIUS = 1.0

#: An ambient viscosity given as a bare number (Pa s) at least this large is doubted:
#: lubricants lie between about 1 mPa s and 2 Pa s (glycerol 1.4 Pa s), and a bare 100 is
#: most often 100 mPa s (cP) meant.
BARE_VISCOSITY = 10.0

#: The radius keys of :class:`CurvedBody` tables.
RADIUS_KEYS = ("rx", "ry", "radius")


class BareNumbers(CaseModel):
    """A table that remembers which of its values were written as bare numbers (read in the
    key's SI unit), for the ``unit_doubts(key)`` of a subclass."""

    _bare: dict = PrivateAttr(default_factory=dict)

    @model_validator(mode="wrap")
    @classmethod
    def _record_bare(cls, data, handler):
        """Record the bare numbers of ``data`` (the table as written)."""
        spec = handler(data)
        if isinstance(data, dict):
            spec._bare = {k: float(v) for k, v in data.items()
                          if isinstance(v, int | float) and not isinstance(v, bool)}
        return spec

    def bare(self, name: str) -> float | None:
        """The value of ``name`` if it was written as a bare number, else None."""
        return self._bare.get(name)


class CurvedBody(BareNumbers):
    """A table with radii of relative curvature (``rx``, ``ry``, ``radius``), whose radii
    written as bare numbers of at least :data:`BARE_RADIUS` metres are doubted."""

    def unit_doubts(self, key: str) -> list[str]:
        """One line per radius written as a bare number of at least :data:`BARE_RADIUS`.

        Parameters
        ----------
        key : str
            The table's name in the case (``"contact"``, ``"geometry"``, ``"pressure"``).

        Returns
        -------
        list of str
            ``contact.rx: the bare number 9.525 is read in m, 9.525 m; ...``.
        """
        return [f"{key}.{name}: the bare number {value:g} is read in m, "
                f"{format_quantity(value, 'm')}, as a radius of relative curvature larger than "
                "most contacts have (a bare number is in the key's SI unit); if millimetres "
                f'were meant write "{value:g} mm", else "{value:g} m" to confirm'
                for name in RADIUS_KEYS
                if (value := self.bare(name)) is not None and value >= BARE_RADIUS]


def unit_doubts(case) -> list[str]:
    """The doubts of every table of ``case`` that has them (``unit_doubts(key)``: the bodies'
    moduli, the radii of a :class:`CurvedBody`), in the order of the case's keys: the first
    lines of every runner's warnings.

    Parameters
    ----------
    case : CaseModel
        A validated case.

    Returns
    -------
    list of str
    """
    lines = []
    for key in type(case).model_fields:
        table = getattr(case, key, None)
        if hasattr(table, "unit_doubts"):
            lines += table.unit_doubts(key)
    return lines
