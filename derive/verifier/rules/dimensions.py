"""Rules ``unit`` and ``angle``: each displayed quantity carries a unit of its dimension.

- ``unit``: the unit shown after a quantity is of the quantity's dimension (no
  ``T_1 = 18.00 m``); a quantity shown as a value (numbers, and letters kept
  symbolic) carries a unit unless the letters already give its dimension
  (``v_A2 = 0.889 u`` needs none, ``T_1 = 22.0 m`` with m a mass does).
- ``angle``: an angle with a degree sign is in degrees (no radian value with a
  degree sign: ``beta = 14.036° = 0.245°``), and an angle in degrees has its sign
  (no ``cos {30}`` for cos 30°).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from fractions import Fraction

from derive.mathtext.tree import Add, Deg, Frac, Func, Hat, Mul, Num, ParsedRelation, Pow, Side, Sym, Vec
from derive.verifier import units
from derive.verifier.evaluate import DEGREE, mpf, walk
from derive.verifier.judge import Claim, Judge, lone_number
from derive.verifier.report import Failure

FDim = tuple[Fraction, Fraction, Fraction, Fraction]
NONE: FDim = (Fraction(0),) * 4  # type: ignore[assignment]
ANGLE: FDim = (Fraction(0), Fraction(0), Fraction(0), Fraction(1))


def _scale(d: FDim, k: Fraction) -> FDim:
    return (d[0] * k, d[1] * k, d[2] * k, d[3] * k)


def _plus(a: FDim, b: FDim, sign: int = 1) -> FDim:
    return (a[0] + sign * b[0], a[1] + sign * b[1], a[2] + sign * b[2], a[3] + sign * b[3])


def _exponent(node: object) -> Fraction | None:
    if isinstance(node, Num):
        return Fraction(node.value)
    if isinstance(node, Add) and len(node.terms) == 1 and isinstance(node.terms[0][1], Num):
        return node.terms[0][0] * Fraction(node.terms[0][1].value)
    if isinstance(node, Frac):
        a, b = _exponent(node.num), _exponent(node.den)
        return None if a is None or not b else a / b
    return None


def dimension(node: object, dim_of: Callable[[str], units.Dim | None]) -> FDim | None:
    """The dimension of a tree (None when a name is unknown or the terms disagree)."""
    if isinstance(node, Num):
        return ANGLE if node.degrees else NONE
    if isinstance(node, (Sym, Vec)):
        d = dim_of(node.name)
        return None if d is None else tuple(Fraction(x) for x in d)  # type: ignore[return-value]
    if isinstance(node, (Hat, Deg)):
        return ANGLE if isinstance(node, Deg) else NONE
    if isinstance(node, Add):
        dims = [dimension(t, dim_of) for _, t in node.terms]
        known = {d[:3] for d in dims if d is not None}
        return None if len(known) != 1 or None in dims else dims[0]
    if isinstance(node, (Mul, Frac)):
        parts = node.factors if isinstance(node, Mul) else (node.num, node.den)
        out = NONE
        for k, p in enumerate(parts):
            d = dimension(p, dim_of)
            if d is None:
                return None
            out = _plus(out, d, -1 if isinstance(node, Frac) and k == 1 else 1)
        return out
    if isinstance(node, Pow):
        base, k = dimension(node.base, dim_of), _exponent(node.exp)
        return None if base is None or k is None else _scale(base, k)
    if isinstance(node, Func):
        if node.name == "sqrt":
            d = dimension(node.args[0], dim_of)
            return None if d is None else _scale(d, Fraction(1, 2))
        if node.name == "abs":
            return dimension(node.args[0], dim_of)
        return ANGLE if node.name in ("asin", "acos", "atan", "atan2") else NONE
    return None


def _dims(judge: Judge, claim: Claim, i: int):
    scopes = judge.side_scopes(claim, i)

    def dim_of(name: str) -> units.Dim | None:
        q = judge.quantity(name, scopes)
        return None if q is None else q.dim

    return dim_of, scopes


def _unit_dim(side: Side, system: str) -> FDim | None:
    if side.unit is None:
        num = lone_number(side)
        return ANGLE if num is not None and num.degrees else None
    try:
        _, dim, degrees = units.to_working(side.unit, system)
    except units.UnknownUnit:
        return None
    return ANGLE if degrees else tuple(Fraction(x) for x in dim)  # type: ignore[return-value]


def _name(d: FDim) -> str:
    return units.words(tuple(int(x) if x.denominator == 1 else x for x in d))  # type: ignore[arg-type]


def _unit_reasons(judge: Judge, claim: Claim, relation: ParsedRelation) -> Iterator[str]:
    dim_of, scopes = _dims(judge, claim, 0)
    head = dimension(relation.sides[0].expr, dim_of)
    if head is None:
        return
    label = relation.sides[0].source
    for k, side in enumerate(relation.sides[1:], 1):
        shown = _unit_dim(side, scopes[0].system)
        if shown is not None and side.unit is not None:  # 22.0 m J/kg is an energy when m is a mass
            own = dimension(side.expr, _dims(judge, claim, k)[0])
            shown = _plus(shown, own) if own is not None else shown
        if shown is not None and shown != head and not (head == NONE and side.unit == "%"):
            unit = side.unit or "°"
            yield f"{label} is {_name(head)}, but {unit} is {_name(shown)}"
            return
    last = relation.sides[-1]
    if not isinstance(relation.sides[0].expr, (Sym, Vec)) or head == NONE or last.unit is not None:
        return
    if _unit_dim(last, scopes[0].system) is not None or not value_form(last.expr):
        return
    dim_of_last, scopes_last = _dims(judge, claim, len(relation.sides) - 1)
    if any(_solved_here(judge, n, scopes_last) for n in judge.names(last.expr)):
        return  # an equation in the unknowns, not a value (a chain's unknown before its solve stage is a letter)
    num = lone_number(last)
    if num is not None and num.value == 0:
        return
    have = dimension(last.expr, dim_of_last)
    if have is not None and have != head:
        yield f"{label} is {_name(head)}; {last.source} shows no unit"


def _solved_here(judge: Judge, name: str, scopes: list) -> bool:
    """An unknown the equations of this part of the page determine (not a chain's pure-number
    unknown, e, that only a later ``solve`` stage finds: until then it is a letter, and
    v_A2 = -35 e_floor is a value that needs its m/s)."""
    for s in scopes:
        q = s.quantities.get(name)
        if q is not None:
            return q.role == "unknown" and (s.key not in judge.facts.solved or q.dim != units.NONE)
    return False


def value_form(node: object) -> bool:
    """A value as a result shows it: a number, or numbers times letters (3.50 + 3.50 e, 22.0 m)."""
    if isinstance(node, Num):
        return True
    if isinstance(node, Add):
        return all(value_form(t) for _, t in node.terms)
    if isinstance(node, Mul):
        return all(isinstance(f, (Num, Sym)) or (isinstance(f, Pow) and isinstance(f.base, Sym)) for f in node.factors)
    return isinstance(node, Sym)


def _bare_degrees(judge: Judge, claim: Claim, relation: ParsedRelation) -> Iterator[str]:
    """An angle in degrees put into sin, cos or tan without its degree sign (cos {30})."""
    angles = [q.value / DEGREE for q in _angles(judge, claim)]
    for side in relation.sides:
        for node in walk(side.expr):
            if not (isinstance(node, Func) and node.name in ("sin", "cos", "tan") and isinstance(node.args[0], Num)):
                continue
            num = node.args[0]
            if not num.degrees and any(abs(mpf(num.value) - a) <= mpf("1e-9") * max(1, abs(a)) for a in angles):
                yield f"{node.name} {{{num.text}}} takes an angle in degrees without its degree sign"
                return


def _angles(judge: Judge, claim: Claim) -> list:
    return [
        q
        for s in judge.chain_of(claim.line.scope)
        for q in s.quantities.values()
        if q.dim == units.ANGLE and q.value is not None and q.value
    ]


def _angle_reasons(judge: Judge, claim: Claim, relation: ParsedRelation) -> Iterator[str]:
    yield from _bare_degrees(judge, claim, relation)
    first = relation.sides[0].expr
    if not isinstance(first, Sym):
        return
    scopes = judge.side_scopes(claim, 0)
    q = judge.quantity(first.name, scopes)
    if q is None or q.dim != units.ANGLE or q.value is None:
        return
    for side in relation.sides[1:]:
        num = lone_number(side)
        if num is None or not num.degrees:
            continue
        shown = mpf(num.value) * (-1 if isinstance(side.expr, Add) else 1)
        h = judge.halfwidth(num, scopes, True) + mpf("1e-20")
        if abs(shown - q.value) <= h and abs(shown * DEGREE - q.value) > h * DEGREE:
            yield f"{side.source} is {first.name} in radians, shown with a degree sign"


def check(judge: Judge) -> Iterator[Failure]:
    """Units of the wrong dimension, values without a unit, radians shown as degrees."""
    for claim in judge.claims:
        for relation in claim.relations:
            if len(relation.sides) < 2:
                continue
            line = claim.line
            for rule, reasons in (("unit", _unit_reasons), ("angle", _angle_reasons)):
                for reason in reasons(judge, claim, relation):
                    yield Failure(line.number, line.latex, rule, reason, line.scope)
                    break
