"""Whether a film regression applies to a contact: the contact's parameters against those of
the numerical solutions the formula was fitted to.

Line contacts (a gear flank, a roller): Dowson & Higginson's minimum film and the materials
parameter G. Point contacts (a ball bearing's race, a crowned roller): Hamrock & Dowson's
(1977) central and minimum films and the ellipticity parameter k.

Dowson & Higginson fitted their line-contact minimum film, ``H_min = 2.65 U^0.70 G^0.54
W'^-0.13``, to numerical EHL solutions for two materials parameters, G = alpha E' = 2500
(bronze on steel, mineral oil) and 5000 (steel on steel) (D. Dowson & G. R. Higginson,
*Elasto-Hydrodynamic Lubrication*, SI ed., Pergamon 1977). A polymer flank is far outside:
a steel pinion on a PA66 wheel (E 3 GPa, nu 0.4) with a 15 1/GPa oil has G = 105, and there
the converged solver with the formula's own oil model (Newtonian, Barus, incompressible)
lies 38 % above the formula at the pitch point (docs/gears.md). Moes' central-film formula,
whose material parameter L spans the isoviscous limit, is not judged here.

Hamrock & Dowson fitted their point-contact films to 34 solutions with the ellipticity
parameter ``k = b/a`` (which they approximated by ``1.03 (Ry/Rx)^0.64``) from 1 (a ball on a
plate) to 8 (B. J. Hamrock & D.
Dowson, J. Lubr. Technol. 99 (1977) 264). The inner-race contact of a deep-groove ball
bearing has k = 9-11 (a 6208: Rx = 3.3 mm, Ry = 103 mm, k = 9.08), where the rows were shown
with no word that they extrapolate. Nijenbanning's formula, whose asymptotes span the circle
to the line contact, is not judged here.
"""

from __future__ import annotations

__all__ = ["DOWSON_HIGGINSON_G", "FORMULA_G_FACTOR", "HAMROCK_DOWSON_K",
           "dowson_higginson_range_note", "hamrock_dowson_range_note"]

#: Materials parameters G = alpha E' of the solutions Dowson & Higginson's minimum film was
#: fitted to (1977): bronze on steel and steel on steel.
DOWSON_HIGGINSON_G = (2500.0, 5000.0)

#: Factor beyond those values past which the formula is said not to apply: asperity's choice,
#: which keeps the usual gear metals and oils (G about 1500-7000) and marks polymer flanks.
FORMULA_G_FACTOR = 2.0

#: Ellipticity parameters k = b/a of the solutions Hamrock & Dowson's (1977)
#: point-contact films were fitted to.
HAMROCK_DOWSON_K = (1.0, 8.0)


def dowson_higginson_range_note(materials_parameter: float) -> str:
    """The comparison row's note where ``G = alpha E'`` lies more than
    :data:`FORMULA_G_FACTOR` beyond :data:`DOWSON_HIGGINSON_G`, else ``""``.

    Parameters
    ----------
    materials_parameter : float
        G = alpha E' of the contact (E' = 2 E*, the Hamrock-Dowson convention).

    Returns
    -------
    str
        One sentence naming G and the fit's values, saying the formula does not apply.
    """
    low, high = DOWSON_HIGGINSON_G
    g = float(materials_parameter)
    if low / FORMULA_G_FACTOR <= g <= high * FORMULA_G_FACTOR:
        return ""
    side = "below" if g < low else "above"
    return (f"outside its range, not a check: the materials parameter G = alpha E' = {g:.3g} "
            f"is far {side} the G = {low:g}-{high:g} of the solutions the formula was fitted "
            "to (Dowson & Higginson 1977), so the difference measures the formula's "
            "extrapolation, not the solver")


def hamrock_dowson_range_note(ellipticity: float) -> str:
    """The note of a Hamrock-Dowson (1977) row where the ellipticity parameter lies outside
    :data:`HAMROCK_DOWSON_K`, else ``""``.

    Parameters
    ----------
    ellipticity : float
        The contact's ``k = b/a``, the Hertz semi-axis across the entrainment over the one
        along it.

    Returns
    -------
    str
        One sentence naming k and the fit's range: the row extrapolates the formula.
    """
    low, high = HAMROCK_DOWSON_K
    k = float(ellipticity)
    if low <= k <= high:
        return ""
    side = "below" if k < low else "above"
    return (f"outside its range: the ellipticity parameter k = b/a = {k:.3g} "
            f"lies {side} the k = {low:g}-{high:g} of the solutions the formula was fitted to "
            "(Hamrock & Dowson 1977), so the row extrapolates it")
