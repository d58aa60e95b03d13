"""Givens restated in the student's names: ``Given: m = 0.060 kg, v = 28 m/s``, ``Puck: v_{1i} =
35.0 m/s``, ``v=35.0 m/s`` on the first lines. A line before the working whose relations are all
a name set to a number, where a number is the problem's value of exactly one given velocity (to
the figures written, either sign: the student's positive may be derive's negative), declares that
name as that given: it is never a slip, and ``v`` there is the speed before, not the habit's
velocity after. Written without a sign, it is the given's size (``v = 4`` where the student's
positive points out of the wall: ``v_{x,i} = -v``); with one, the velocity. A zero says too
little (B at rest, a velocity after that vanishes) and declares nothing.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context
from derive.checking.numeric import number_of
from derive.checking.valuenames import unit_of
from derive.mathtext.notation import student
from derive.mathtext.reader import Relation
from derive.problem.expr import ParseError, parse
from derive.problem.units import VELOCITY

_NAME = re.compile(r"[A-Za-z]\w{0,6}['′]{0,2}")  # e' for the wall's e too
_NUMBER = re.compile(r"\s*[-+]?\s*(\d+)\.?(\d*)\s*")


def written_number(side: str) -> tuple[float, float] | None:
    """The number a side is (its value and half its last written figure), None where it is none."""
    m = _NUMBER.fullmatch(side)
    if m is None:
        return None
    try:
        value = number_of(parse(student(side), {}).expr)
    except ParseError:
        return None
    if value is None or abs(value.imag) > 1e-12:
        return None
    return float(value.real), 0.5 * 10 ** -len(m.group(2)) + 1e-12


def stated(sides: tuple[str, ...]) -> bool:
    """Whether the sides state a value: a name set to a number (``v = 28``)."""
    return len(sides) == 2 and _NAME.fullmatch(sides[0].strip()) is not None and written_number(sides[1]) is not None


def _stated(r: Relation) -> bool:
    return stated(r.sides)


def _mass_or_weight(r: Relation) -> bool:
    """A mass or a weight (or g) given in a line of givens as it is worked out or written
    (``m_A = 4500/32.2 = 139.8``, ``m_1 = 1.50 × 10^5``, ``masses from the weights, m = W/g``):
    not the working that a velocity stated after it would be a result of."""
    words = r.sides[0].split()
    return bool(words) and re.fullmatch(r"[mMWg](?:_?\{?\w{1,3}\}?)?", words[-1]) is not None


def restated(ctx: Context, relations: tuple[Relation, ...], reserved: set[str]) -> dict[str, sympy.Expr]:
    """The names set to a given velocity's value on a line of givens -> that given."""
    givens = [
        (g.symbol, abs(float(g.value)))
        for g in ctx.problem.givens
        if g.dim == VELOCITY and not g.unknown and g.value is not None and g.value.is_number and g.value != 0
    ]
    lines: dict[int, list[Relation]] = {}
    for r in relations:
        lines.setdefault(r.line, []).append(r)
    out: dict[str, sympy.Expr] = {}
    seen: set[str] = set()
    worked = [n for n, rs in lines.items() if not all(_stated(x) or _mass_or_weight(x) for x in rs)]
    for r in relations:
        if worked and r.line >= min(worked):
            break  # the givens come before the working ("v = 5 m/s" after it is a result)
        name = r.sides[0].strip()
        if len(r.sides) != 2 or not _NAME.fullmatch(name) or name in reserved or name in seen or r.lead:
            seen.add(name)
            continue
        seen.add(name)
        unit = unit_of(r)
        if re.match(r"[mMWEKTJIpPe]", name) or (unit is not None and unit[0] != VELOCITY):
            continue  # a mass, a weight, an energy, an impulse, a momentum, e: not a velocity
        value, half = written_number(r.sides[1])
        hits = [s for s, v in givens if abs(abs(value) - v) <= half]
        if len(hits) == 1:
            typed = " ".join(x.written for x in relations)
            for spelled in _spellings(name, reserved | seen, typed):  # v1 on the line of givens is v_1 in $m_1 v_1$
                signed = value < 0 or r.direction < 0 or ctx.problem.oblique  # "0.120 m/s the other way": signed
                out[spelled] = hits[0] if signed else sympy.Abs(hits[0])  # "v = 4": a size
    return out


def _spellings(name: str, taken: set[str], typed: str) -> list[str]:
    """``name`` and its other spelling, with or without the underscore (``v1``, ``v_1``), where
    the student types both (``v1`` in a line of givens, ``$m_1 v_1$`` later) or the reading
    writes ``v1`` as ``v_1``, and that one is not a name of its own already."""
    m = re.fullmatch(r"([A-Za-z])_?(\w+)", name)
    if m is None:
        return [name]
    other = f"{m[1]}{m[2]}" if "_" in name else f"{m[1]}_{m[2]}"
    spelled = rf"(?<![\w\\]){m[1]}_\{{?{m[2]}\}}?(?!\w)" if "_" not in name else rf"(?<![\w\\]){m[1]}{m[2]}(?!\w)"
    rewritten = re.fullmatch(r"[uvVw][AB12]\d?[nt]?", name)  # v1 is read as v_1 (naming.rewrite)
    return [name, other] if other not in taken and (rewritten or re.search(spelled, typed)) else [name]


def is_size(ctx: Context, e: sympy.Expr) -> bool:
    """Whether ``e`` is a size, the same in any sign convention: a speed of an oblique impact (a
    given ``v_A1``, a result ``v_A2``), a given restated without its sign."""
    if isinstance(e, sympy.Abs):
        return True  # a given restated as a number without its sign (restated)
    if not ctx.problem.oblique or not isinstance(e, sympy.Symbol):
        return False
    speeds = [g.symbol for g in ctx.problem.givens if g.dim == VELOCITY and not g.name.endswith(("n", "t"))]
    return e in speeds or any(s == e for n, (s, _x) in ctx.derived().items() if re.fullmatch(r"v_[AB]2", n))
