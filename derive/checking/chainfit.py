"""Which of a chain's values a student's name stands for, where several fit the same relations.

A number written without decimals is read to its figures (``3`` is 2.5 to 3.5), so ``(v_A)_1 = 3``
holds for A's 3 m/s and for B's 2.9 m/s after the impact alike, and ``2`` for 2 and for 1.5. A
teacher reads the name as the value the number is, not one it rounds to: among the values that
make the most relations hold, the nearest to what the relations say is taken."""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

import sympy

from derive.checking.numeric import number_of
from derive.errors import InputError
from derive.problem.units import VELOCITY, parse_unit


def nearest(
    cands: Sequence[sympy.Expr],
    score: dict[sympy.Expr, int],
    alone: Sequence[tuple[tuple[str, ...], list[sympy.Expr]]],
    name: tuple[dict, sympy.Symbol],
    values: tuple[dict, dict],
) -> sympy.Expr | None:
    """The candidate of the highest score (the first, as ``max``), and among those of that score
    the one whose relations (``alone``: the name the only unknown) are nearest to holding;
    ``name`` is (the names found so far, the name), ``values`` the chain's values and the units'."""
    best = max(cands, key=lambda c: score[c], default=None)
    if best is None or not score[best]:
        return best
    tied = [c for c in cands if score[c] == score[best]]
    found, p = name

    def at(x: sympy.Expr, c: sympy.Expr) -> sympy.Expr:
        return x.xreplace({**found, p: c}).xreplace(values[0]).xreplace(values[1])

    return min(tied, key=lambda c: _gap(alone, at, c)) if len(tied) > 1 else best


def _gap(alone, at: Callable[[sympy.Expr, sympy.Expr], sympy.Expr], c: sympy.Expr) -> float:
    """How far the relations are from holding with the name as ``c``: the spread of each one's
    sides, relative to their size, summed."""
    total = 0.0
    for _sides, exprs in alone:
        xs = [number_of(at(x, c)) for x in exprs]
        if any(x is None for x in xs):
            continue
        xs = [abs(x) if abs(x.imag) > 1e-12 else x.real for x in xs]
        total += (max(xs) - min(xs)) / max(max(abs(x) for x in xs), 1e-12)
    return total


def of_letter(p: sympy.Symbol, cands: Sequence[sympy.Expr], letter: Sequence[sympy.Symbol]) -> list[sympy.Expr]:
    """The candidates (either sign) among the chain's values of the letter a name of the
    student's own is (``h``: h_0 and h_2): a teacher reads ``h`` as a height, never as another
    value (e = 0.7) that a slipped height happens to round to."""
    if "_" in p.name:
        return []
    return [c for c in cands if (c if c.is_Symbol else -c) in letter]


def one_result(letter: Sequence[sympy.Symbol], given: set[sympy.Symbol]) -> sympy.Symbol | None:
    """The one value of that letter the chain works out (h_2 beside the given h_0), where no
    value of it makes a relation hold: the result the student is working out, wrongly."""
    results = [v for v in letter if v not in given]
    return results[0] if len(results) == 1 else None


#: A velocity's letter, alone or with a body's or an instant's marks after it (``w``, ``v_B3``,
#: ``(v_B)_3`` read as ``v_B3``, ``V``, ``u2``); never a word (``vel``) nor another quantity's letter.
_VELOCITY_NAME = re.compile(r"^[vuwVUW](?:_?\{?[A-Za-z]?\d{0,2}'?\}?)?$")


def of_kind(p: sympy.Symbol, cands: Sequence[sympy.Expr], ctx, score: dict[sympy.Expr, int]) -> list[sympy.Expr]:
    """The candidates a name may stand for by its kind: a velocity's letter (``w``, ``v_B3``) a
    velocity of the chain (a speed's unit) where one makes a relation hold (``score``), never an
    impulse or a ratio that a slipped number happens to round to (``(v_B)_3 = -0.7`` for the wall's
    0.68 N s, where B's velocity after the wall makes the impulse's relation hold); other names, and
    a velocity's letter no speed fits, all of them."""
    if not _VELOCITY_NAME.match(p.name[1:]):
        return list(cands)
    speeds = {sympy.Symbol(g.name) for g in getattr(ctx.problem, "givens", ()) if g.dim == VELOCITY}
    speeds |= {sympy.Symbol(k) for k, r in ctx.solution.results.items() if _is_speed(r.unit)}
    kinds = [c for c in cands if (c if c.is_Symbol else -c) in speeds]
    return kinds if any(score.get(c) for c in kinds) else list(cands)


def _is_speed(unit: str) -> bool:
    try:
        return bool(unit) and parse_unit(unit).dim == VELOCITY
    except (InputError, ValueError, KeyError):
        return False


#: Letters a teacher reads as one quantity's: the impulse is I (OCR, Edexcel) or J (the notes).
_SAME = {"I": ("I", "J"), "J": ("I", "J")}


def of_the_letter(v: sympy.Symbol, p: sympy.Symbol) -> bool:
    """Whether the chain's value ``v`` is of the letter the student's own name ``p`` is (``h``: h_0,
    h_2); the impulse's letters are one (``I`` where the chain has J)."""
    mine = p.name[1:]
    return v.name.partition("_")[0] in _SAME.get(mine, (mine,))
