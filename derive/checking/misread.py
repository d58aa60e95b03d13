"""A given misread into a line of working in numbers: ``1200 x 12 = (1200 + M) x 6`` where the
car moves at 10 m/s, ``2(5) + 1(0) = 2(3) + 1 v_B`` where A goes on at 2 m/s.

A teacher reads the numbers first: when every number on the line is the problem's but one, and
that one is a given with a digit misread (12 for 10, 3 for 2, 0.6 for 0.4) such that the line,
with the given put back, is a true relation of the problem, the slip is the copy
(``copied_wrong``), even where a common mistake (the masses swapped, an inverse problem solved
the other way) happens to reproduce the student's numbers too. A common mistake writes the
problem's own numbers in the wrong places; it does not invent a number.
"""

from __future__ import annotations

import re
from dataclasses import replace
from decimal import Decimal
from typing import TYPE_CHECKING

import sympy

from derive.checking.mistakes import Variant
from derive.checking.numeric import number_of, shown
from derive.checking.tracing import Trace
from derive.checking.worlds import Pair, solve_world
from derive.mathtext.notation import student
from derive.problem.expr import ParseError, parse

if TYPE_CHECKING:
    from derive.checking.context import Context
    from derive.checking.inference import Read
    from derive.problem.records import Given


#: A slip named: the equation it takes the place of (None: the closest), its words, its name.
Found = tuple[int | None, str, str] | None

#: A number as written on a line (not a subscript's digit, not part of a name).
_WRITTEN = re.compile(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])")


def misread(trace: Trace, line: Read, bad: Pair, diags: tuple) -> Found:
    """``copied_wrong`` where the false ``bad`` (in the unknowns) holds once the one number
    written on ``line`` that is none of the problem's, and reads as a given with one digit
    changed, is put back as that given (a number it comes to scaled alike: 1200 x 12 read as
    14400); None otherwise. ``diags`` are what a common mistake said of the line: they give
    way to the copy, which needs no mistake."""
    if bad.raw is None:
        return None
    ctx = trace.ctx
    known = set(ctx.data) | _values(trace)
    written = {sympy.Rational(t) for side in line.sides if not _bare(side) for t in _WRITTEN.findall(side)}
    foreign = [c for c in written if c and c not in known]
    if len(foreign) != 1:
        return None  # one number misread; more is working of the student's own
    c = foreign[0]
    givens = [g for g in ctx.problem.givens if not g.unknown and g.value is not None and g.value.is_Rational]
    world = trace.world if trace.world is not None else trace.truth
    numbers = set().union(*(x.atoms(sympy.Number) for x in bad.raw)) - {sympy.Integer(0)}
    misread = [
        g
        for g in givens
        if g.value
        and _one_digit(c, abs(g.value))
        and any(_holds_put(trace, bad, a, g.value / c, world) for a in numbers)
    ]
    if not misread:
        return None
    if trace.world is None:  # the problem as the student copied it: the line holds there too
        found = next((g for g in misread if _copied_world(trace, bad, g, c)), None)  # 2 is m_A and v_A2
        if found is None:
            return None  # "4(12) + 3(0) = 7 v_t": 7 is no copy of A's 4 kg (the line is false with 7 kg)
        g = found
    else:
        g = misread[0]
    said = f"{g.name} = {shown(abs(g.value))}, not {shown(c)}"
    return None, f": a given is copied wrongly into it: the problem gives {said}.", "copied_wrong"


#: What joins a number to others on a side (a product, a sum, brackets), where a copy stands.
_JOINED = re.compile(r"[+*×·()\[\]]|\\times|\\cdot|\\frac|\d\s*[A-Za-z]|(?<=\s)x(?=\s)")


def _bare(side: str) -> bool:
    """A side that is one number, its unit after it (``1200 kg``, ``3``): a result worked out
    (``0.75 x 4 = 3``), never a given copied into working."""
    return len(_WRITTEN.findall(side)) <= 1 and not _JOINED.search(side)


def _holds_put(trace: Trace, bad: Pair, a: sympy.Expr, k: sympy.Expr, world: list) -> bool:
    """Whether ``bad`` holds with the number ``a`` scaled by ``k`` (the given put back)."""
    assert bad.raw is not None
    sides = [trace.ctx.in_unknowns(x.xreplace({a: a * abs(k)})) for x in bad.raw]
    return trace.holds([replace(bad, left=sides[0], right=sides[1])], world)


def _copied_world(trace: Trace, bad: Pair, g: Given, copy: sympy.Rational) -> bool:
    """Make the slip's world the problem solved with the given ``g`` as the student copied it
    (the lines after, right with it, are carried), where ``bad`` holds in it; whether it does
    (after an earlier slip the world stays as it is)."""
    if trace.world is not None:
        return False
    assert g.value is not None
    variant = Variant(values={g.symbol: copy if g.value > 0 else -copy})
    equations = {j: F for j, F in trace.ctx.model.numbered(variant).items() if j in trace.equations}
    world = solve_world(equations, trace.U, trace.pts, trace.truth)  # an inverse problem's too
    if world is None or not trace.holds([bad], world):
        return False
    trace.variant, trace.world, trace.equations = variant, world, equations
    trace.copied[g.symbol] = variant.values[g.symbol]  # the student's v_A2 is the number copied
    return True


def with_copied(ctx: Context, x: sympy.Expr, copied: dict[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``x`` with the givens copied wrongly as the student has them, in the results worked from
    them too (``KE before`` is ½ m u² with the bullet's 0.2 kg, where 20 g was copied so)."""
    if not copied:
        return x
    derived = {s: e for s, e in ctx.derived().values() if s in x.free_symbols and e.free_symbols & set(copied)}
    return x.xreplace(derived).xreplace(copied)


def _values(trace: Trace) -> set[sympy.Rational]:
    """The problem's values worked out (a velocity after, a mass asked for), as the numbers a
    student may write for them: these are no misread givens."""
    out: set[sympy.Rational] = set()
    for v in trace.truth[0].values() if trace.truth else ():
        x = number_of(v)
        if x is not None and abs(x.imag) < 1e-12:
            out |= {sympy.Rational(str(round(abs(x.real), 6)))}
    return out


def _one_digit(a: sympy.Rational, g: sympy.Rational) -> bool:
    """``a`` written for ``g`` with one digit misread: the same digits in the same places but
    one (12 for 10, 0.6 for 0.4, 3 for 2)."""
    if a == g:
        return False
    x, y = (format(Decimal(str(sympy.Float(v, 15))).normalize(), "f") for v in (a, g))
    return len(x) == len(y) and sum(p != q for p, q in zip(x, y, strict=True)) == 1


#: A decimal written with three significant figures or more (``0.0954``, ``19.567``).
_DECIMAL = re.compile(r"(?<![\w.])\d*\.\d+(?![\w.])")


def transposed(trace: Trace, line: Read, pairs: list[Pair]) -> list[Pair]:
    """``pairs``, judged at the figures of a number on ``line`` whose digits are those of the
    value the line needs there in another order (``0.077 = 0.049 v_1 + 0.0954`` where
    0.027 × 3.5 = 0.0945): the line holds only at the looser figures of its other numbers, but a
    teacher sees the two digits swapped, a slip. The pairs as they are otherwise."""
    if not pairs or not trace.holds(pairs, trace.truth):
        return pairs
    found = _swapped(trace, line, pairs)
    if found is None:
        return pairs
    k, token, _shown = found
    half = 0.5 * 10.0 ** -len(token.split(".")[1]) / float(abs(sympy.Rational(token)))  # its own last figure
    p = pairs[k]
    return [*pairs[:k], replace(p, tol=min(p.tol, half), own_figures=True), *pairs[k + 1 :]]


def swapped_words(trace: Trace, line: Read, bad: Pair) -> Found:
    """The slip of a line :func:`transposed` judged at a number's own figures: ``arithmetic``,
    the number and the value the line needs there in words; None for any other line."""
    found = _swapped(trace, line, [bad]) if bad.own_figures else None
    if found is None:
        return None
    _k, token, needed = found
    return (
        None,
        f": {token} has its digits in the wrong order: the line needs {needed} there (an arithmetic slip).",
        "arithmetic",
    )


def _swapped(trace: Trace, line: Read, pairs: list[Pair]) -> tuple[int, str, str] | None:
    """(the pair, the number written, the value it needs at its places) for a decimal of
    ``line`` whose digits are the needed value's in another order; None where there is none."""
    for token in _DECIMAL.findall(" = ".join(line.sides)):
        digits = token.replace(".", "").lstrip("0")
        d = sympy.Rational(token)
        if len(digits) < 3 or len(set(digits)) < 2 or d in trace.ctx.data:
            continue
        places = len(token.split(".")[1])
        for k, p in enumerate(pairs):
            need = _needed(trace, p, d)
            at = f"{abs(need):.{places}f}" if need is not None else token
            if at != token and sorted(at.replace(".", "").lstrip("0")) == sorted(digits):
                return k, token, at
    return None


def _needed(trace: Trace, p: Pair, d: sympy.Rational) -> float | None:
    """The value the number ``d`` of the pair ``p`` would need for ``p`` to hold exactly at the
    problem's true values (None: ``d`` is not one of its numbers, or the pair is not linear in it)."""
    if p.raw is None or not any(d in x.atoms(sympy.Number) for x in p.raw):
        return None
    x = sympy.Symbol("_put")
    sides = [trace.ctx.in_unknowns(s.xreplace({d: x})) for s in p.raw]
    F = (sides[0] - sides[1]).xreplace(trace.pts[0]).xreplace(trace.truth[0])
    if F.free_symbols != {x}:
        return None
    a, b = F.diff(x), F.subs(x, 0)
    if not a.is_number or a == 0 or not (F - a * x - b).equals(0):
        return None
    value = number_of(-b / a)
    return None if value is None or abs(value.imag) > 1e-12 else value.real


#: Numbers in working that are no data: a power (``^2``), the half of a kinetic energy.
_NOT_DATA = re.compile(r"\^\s*\(?\d+\)?|(?<![\w.])1\s*/\s*2(?![\w.])|½")


def in_working(trace: Trace, line: Read, bad: Pair) -> str:
    """``speed after = e x speed before = 0.4 x 5`` where the ball moves at 4 m/s: a line of
    numbers (no unknown) whose working writes one number that is none of the problem's, a given
    with one digit misread, and that is right with the given put back; the verdict's words
    ("" where it is not such a line). The slip's world is the problem as the student copied it,
    where the line holds there (the lines worked from it are carried)."""
    if bad.raw is None or bad.difference.free_symbols & set(trace.U):
        return ""
    ctx = trace.ctx
    known = set(ctx.data) | _values(trace)
    plain = [_NOT_DATA.sub(" ", side) for side in line.sides if not _bare(side)]  # no squares, no halves
    foreign = list({sympy.Rational(t) for side in plain for t in _WRITTEN.findall(side)} - known - {0})
    if len(foreign) != 1:
        return ""
    c = foreign[0]
    world = trace.world if trace.world is not None else trace.truth
    first = (line.exprs or (None,))[0]
    token = re.compile(rf"(?<![\w.]){re.escape(str(line_number(c)))}(?![\w.])")
    found = []
    for g in ctx.problem.givens:
        if g.unknown or g.value is None or not g.value.is_Rational or not g.value or not _one_digit(c, abs(g.value)):
            continue
        sides = [side for side in line.sides[1:] if token.search(side)]
        put = [_number(token.sub(str(line_number(abs(g.value))), side)) for side in sides]  # the given put back
        if first is None or not any(
            x is not None and trace.holds([_against(trace, bad, first, x)], world) for x in put
        ):
            continue
        copy = c if g.value > 0 else -c
        as_copied = with_copied(ctx, first, {g.symbol: copy})  # the line as written, in the problem as copied
        found.append(
            (
                not any(
                    x is not None and trace.holds([_against(trace, bad, as_copied, x)], world)
                    for x in map(_number, sides)
                ),
                g,
                copy,
            )
        )
    if not found:
        return ""
    _apart, g, copy = min(found, key=lambda f: f[0])
    if trace.world is None:
        _as_copied(trace, g, copy)
    return f": a given is copied wrongly into it: the problem gives {g.name} = {shown(abs(g.value))}, not {shown(c)}."


def line_number(x: sympy.Rational) -> str:
    """``x`` as a student writes it (``5``, ``2.9``, ``0.25``)."""
    return format(Decimal(str(sympy.Float(x, 15))).normalize(), "f")


def _number(side: str) -> sympy.Expr | None:
    """The number a side of numbers comes to (None where it has a name or does not read)."""
    try:
        x = parse(student(side), {}).expr
    except ParseError:
        return None
    return x if not x.free_symbols else None


def _against(trace: Trace, bad: Pair, first: sympy.Expr, x: sympy.Expr) -> Pair:
    """``bad`` as the line's first side against the number ``x``."""
    return replace(bad, left=trace.ctx.in_unknowns(first), right=x, raw=(first, x))


def _as_copied(trace: Trace, g: Given, copy: sympy.Rational) -> None:
    """Make the slip's world the problem solved with the given ``g`` as the student copied it."""
    variant = Variant(values={g.symbol: copy})
    out = trace.ctx.model.outcome(variant)
    if out is None:
        return
    trace.copied[g.symbol] = copy
    trace.variant, trace.world = variant, [{u: out.post[u].xreplace(pt) for u in trace.U} for pt in trace.pts]
    trace.equations = {j: F for j, F in out.equations.items() if j in trace.equations}


def total_copied(trace: Trace, line: Read, bad: Pair) -> str:
    """``8000/11050 (0.250)`` where the masses are 4000 and 7500 kg: a line of numbers whose
    working writes one number that is none of the problem's nor a sum or product of two of its
    numbers (8000 = 2 x 4000), but such a total with its digits in another order or one digit
    misread (11500 = 4000 + 7500), and that is right with the total put back; the verdict's
    words ("" where it is not such a line)."""
    if bad.raw is None or bad.difference.free_symbols & set(trace.U):
        return ""
    data = sorted({abs(x) for x in trace.ctx.data if x and x.is_Rational})
    totals = {a + b for a in data for b in data} | {a * b for a in data for b in data}
    known = set(data) | totals | _values(trace)
    plain = [_NOT_DATA.sub(" ", side) for side in line.sides if not _bare(side)]
    foreign = list({sympy.Rational(t) for side in plain for t in _WRITTEN.findall(side)} - known - {0})
    if len(foreign) != 1:
        return ""
    c = foreign[0]
    world = trace.world if trace.world is not None else trace.truth
    token = re.compile(rf"(?<![\w.]){re.escape(line_number(c))}(?![\w.])")
    sides = [side for side in line.sides[1:] if token.search(side)]
    for v in sorted(totals - set(data)):
        digits = [re.sub(r"\D", "", line_number(x)) for x in (c, v)]
        if not (_one_digit(c, v) or (len(digits[1]) >= 3 and sorted(digits[0]) == sorted(digits[1]))):
            continue
        put = [_number(token.sub(line_number(v), side)) for side in sides]
        if any(x is not None and trace.holds([replace(bad, right=x, raw=(bad.raw[0], x))], world) for x in put):
            return f": a number is copied wrongly into it: {shown(v)}, not {shown(c)}."
    return ""


#: For the modules that read a line's numbers as this one does (recopied.py): a side that is one
#: number, a side of numbers' value, a pair of the line's first side against a number.
bare, side_number, against = _bare, _number, _against
