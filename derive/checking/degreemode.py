"""A plain number beside an angle is a number of degrees: a calculator in degree mode.

The rule a teacher follows: a student's angle is in degrees unless they write ``rad``. A trig
function of a bare number is of degrees (``5cos(37.6)``), the sides that are plain numbers of a
line that ends in degrees are degrees (``90 - 1.27 = 88.7°``), and so is a plain number set equal to
an inverse trig function (``tan⁻¹(0.05) = 2.86``): the value a calculator in degree mode shows. The
same number in radians (``θ = tan⁻¹(0.05) = 0.04996``, then ``θ ≈ 0.0500°``) is a calculator in
radian mode, ``degrees_as_radians``, never right because the line's two sides also agree in radians.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import DEG

#: The inverse trig functions: their value is an angle.
INVERSE = (sympy.atan, sympy.asin, sympy.acos, sympy.atan2, sympy.acot)


def in_degrees(sides: tuple[str, ...], exprs: tuple[sympy.Expr, ...]) -> tuple[tuple[str, ...], tuple[sympy.Expr, ...]]:
    """``sides`` and ``exprs``, a relation's sides as written and read, with each side that is a
    plain number made degrees where the last side is a number of degrees (``90 - 1.27 = 88.7°``: the
    student marks the answer's unit only) or where another side is an angle worked by an inverse trig
    function with no degree mark (``tan⁻¹(0.05) = 2.86``, then written ``2.86°``: its figures are
    judged in degrees too); a number of radians is written ``rad``, read as such elsewhere."""
    last = exprs[-1] if exprs else None
    if last is None:
        return sides, exprs
    marked = last.free_symbols == {DEG} and (last / DEG).is_number
    aligned = len(sides) == len(exprs)  # each side as written beside its expression
    angles = [aligned and _inverse_angle(sides[i], x) for i, x in enumerate(exprs)]
    if not marked and not any(angles):
        return sides, exprs
    plain = [
        x.is_number and x != 0 and not x.atoms(sympy.Function) and not a for x, a in zip(exprs, angles, strict=True)
    ]
    if marked:
        plain[-1] = False
    elif aligned:
        sides = tuple(f"{s.strip()}°" if p and _NUMBER.match(s) else s for s, p in zip(sides, plain, strict=True))
    return sides, tuple(x * DEG if p else x for x, p in zip(exprs, plain, strict=True))


#: A side that is a number as typed, with no unit (``0.04996``, ``-2.86``).
_NUMBER = re.compile(r"^\s*[-+−]?\(?\d*\.?\d+\)?\s*$")


def _inverse_angle(side: str, x: sympy.Expr) -> bool:
    """Whether ``x`` (``side`` as written) is an angle worked by inverse trig functions of numbers
    alone, in no unit of its own (``tan⁻¹(0.05)``, ``2 sin⁻¹(0.3)``, ``sin⁻¹(0.5)`` read as π/6):
    an inverse function typed in it, every function in it inverse trig, no name, no degree mark."""
    if not _TYPED_INVERSE.search(side) or not x.is_number or x.free_symbols:
        return False
    return all(isinstance(f, INVERSE) for f in x.atoms(sympy.Function))


#: An inverse trig function as a side's plain text has it (``atan(…)``, ``tan^-1``, ``cos⁻¹``, ``arcsin``).
_TYPED_INVERSE = re.compile(r"\b(?:a|arc)(?:sin|cos|tan)\b|(?:sin|cos|tan)\s*(?:\^\s*\(?\{?\s*[-−]\s*1|⁻¹)")
