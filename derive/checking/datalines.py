"""The problem's data stated before the working, with no header (``Before: u_A = 3, u_B = -1.5``,
``$m_1 = 4$ kg, $v_1 = 80$ m/s at $45^\\circ$``, ``A rebounds so vA = -0.2``, ``Ball speed before
$(v)_1 = U$``). The rule a teacher follows: a line that only states the problem's data, each
number at a given's exact value in the student's own sign convention, is not working and is not
marked, whatever instant or component the checker reads its names as; a number that is no given's
value of that body and kind, or the value with its sign turned against the student's way
(``positive: from A toward B``, then ``u = -4``), is a slip (a given copied wrongly, a sign lost)
and is judged as any line is.

"The student's own sign convention" is the sign the name is read with: a name read as minus a
velocity (the student's positive the other way) compares the givens turned round too. A name
written with a component's mark (``u_{Bn}``, ``vAx``) in an oblique impact is compared with the
components the problem gives, never with a speed (``u_{Bn} = 3`` for B at 3 m/s toward A is the
sign slip). "Before the working": every relation on the lines before it states a value too. A name read as an
unknown of the problem (``v_B2 = 4 m/s`` first, where B's 4 m/s is its speed before) states a
result, not the data, and is judged.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from typing import Any

import sympy

from derive.checking.restated import written_number
from derive.problem.units import VELOCITY

#: A mark of time in words inside a name's subscript (``v_{final}``): not a component's n or t.
_TIME_WORDS = re.compile(r"initial|init|final|fin|before|after|in", re.I)
#: A body's letter in derive's name of a quantity (``v_A1n``, ``m_B``, ``theta_A1``).
_BODY = re.compile(r"_([AB])")


def data_line(ctx: Any, line: Any, lines: Sequence[Any]) -> bool:
    """Whether ``line`` is on a line of data before the working: each relation on its line and on
    every line before it sets names to a number or to a given's letter, and nothing else."""
    return all(_states(ctx, r) for r in lines if r.number <= line.number and r.exprs is not None)


def _states(ctx: Any, r: Any) -> bool:
    if r.defines or r.exprs is None or len(r.exprs) < 2:
        return False
    if not all(_named(x) is not None for x in r.exprs[:-1]):
        return False
    last = r.exprs[-1]
    return bool(last.is_number) or last in {g.symbol for g in ctx.problem.givens}


def _named(x: sympy.Expr) -> tuple[int, sympy.Symbol, bool] | None:
    """``x`` as (its sign, the name's symbol, whether a size): ``-v_A1`` -> (-1, v_A1, False)."""
    size = isinstance(x, sympy.Abs)
    x = x.args[0] if size else x
    coeff, rest = x.as_coeff_Mul()
    if isinstance(rest, sympy.Symbol) and coeff in (1, -1):
        return int(coeff), rest, size
    return None


def exact_given(ctx: Any, r: Any, unknowns: set) -> bool:
    """Whether the relation's value is a given's, exactly (to the figures written), of the same
    kind and body as each name is read, in the sign the name is read with. A name read as one of
    the problem's ``unknowns`` (``v_B2 = 4`` where B's 4 m/s is before) claims a result: judged."""
    last = r.exprs[-1]
    if not last.is_number:  # a given's letter: of the names' kind
        return all(kind_of(ctx, _named(x)[1]) == kind_of(ctx, last) is not None for x in r.exprs[:-1])
    if any(_named(x)[1] in unknowns for x in r.exprs[:-1]):
        return False
    written = written_number(r.sides[-1].strip())
    value, half = written if written is not None else (float(last), 1e-9)
    return all(_matches(ctx, x, r.sides[i], value, half) for i, x in enumerate(r.exprs[:-1]))


def _matches(ctx: Any, x: sympy.Expr, side: str, value: float, half: float) -> bool:
    sign, sym, size = _named(x)
    kind, body = kind_of(ctx, sym), _body(sym)
    if kind is None:
        return False
    component = ctx.problem.oblique and _axis_marked(side)
    for g in ctx.problem.givens:
        if g.value is None or not getattr(g.value, "is_number", False) or getattr(g, "dim", None) != kind:
            continue
        if _body(g.symbol) not in (body, None) or (component and not re.search(r"\d[nt]$", g.symbol.name)):
            continue
        given = abs(float(g.value)) if size else sign * float(g.value)
        if abs(value - given) <= half:
            return True
    return False


def _body(sym: sympy.Symbol) -> str | None:
    m = _BODY.search(sym.name)
    return m.group(1) if m else None


def _axis_marked(side: str) -> bool:
    """Whether the name as written (the last name of the side) carries a component's mark: n, t,
    x, y among its subscript's letters (``u_{Bn}``, ``vAx``, ``(v_t)_1``)."""
    names = re.findall(r"\(?[A-Za-z][\w{}(),'\\]*", side)
    if not names:
        return False
    name = re.sub(r"\\[A-Za-z]+", "", names[-1]).lstrip("(")
    marks = _TIME_WORDS.sub("", name[1:])
    return re.search(r"[ntxy]", marks) is not None


def kind_of(ctx: Any, x: sympy.Expr) -> Any:
    """The kind (dimension) of the quantity ``x`` is read as: a given's own, a velocity's."""
    if not isinstance(x, sympy.Symbol):
        return None
    for g in ctx.problem.givens:
        if g.symbol == x:
            return getattr(g, "dim", None)
    return VELOCITY if re.fullmatch(r"v_[AB][12][nt]?|u_[AB]|v_[AB]", x.name) else None
