"""A line of numbers worked from values the student got wrong, with each put back as the true
value of the quantity it was stated for: where it still holds, it does not depend on the slip.

A teacher reads ``0.7776/2.16 = 36 %`` after ``KE_1 = m v_1² = 2.16`` and ``ΔKE = … = 0.7776``
(both without the ½) as the fraction of the energy lost, ΔKE/KE_1: the slip doubles both, and
the fraction is the true 0.3888/1.08 = 36 % all the same. The line is correct, not carried. A
line whose number the slip moves (``2.16 - 1.3824 = 0.7776``: the true 1.08 - 0.6912 is 0.3888)
is carried as before.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import TYPE_CHECKING

import sympy

from derive.checking.dependency import side_value
from derive.checking.numeric import number_of

if TYPE_CHECKING:
    from derive.checking.inference import Read
    from derive.checking.tracing import Trace

#: A number as written in a side (not a part of a name, a power of ten or another number).
_NUMBER = re.compile(r"(?<![\w.^])\d+(?:\.\d+)?(?![\w.])")
#: Where a side's mathematics may begin after words the reader left out (``… is lost, i.e. 0.77/2.16``).
_START = re.compile(r"(?:^|(?<=\s))[-(\d√]")


def _wrong_values(trace: Trace) -> dict[sympy.Rational, float]:
    """The numbers the student stated for quantities and got wrong, each with its true value."""
    out: dict[sympy.Rational, float] = {}
    stated = trace.stated_values().values  # type: ignore[attr-defined]  (Depending, not in the protocol)
    for q, x in {**stated, **trace.own}.items():
        if not x.is_number or not x.is_real:
            continue
        true = number_of(trace.ctx.in_unknowns(q).xreplace(trace.pts[0]).xreplace(trace.truth[0]))
        mine = number_of(x)
        if true is None or mine is None or abs(true.imag) > 1e-12 or abs(true.real - mine.real) <= 1e-9 * abs(true):
            continue
        out[sympy.Rational(str(mine.real))] = true.real
    return out


def _as_read(text: str, value: sympy.Expr) -> str | None:
    """The part of ``text`` the reader read as ``value`` (the side without the words before it)."""
    target = number_of(value)
    if target is None:
        return None
    for m in _START.finditer(text):
        v = side_value(text[m.start() :])
        if v is not None and abs(v - target.real) <= 1e-9 * max(abs(v), 1e-12):
            return text[m.start() :]
    return None


def independent(trace: Trace, line: Read) -> bool:
    """Whether ``line``, of numbers only, holds once each number the student got wrong in its
    working is put back as the true value of the quantity it stands for (see the module's words)."""
    wrong, exprs = _wrong_values(trace), line.exprs or ()
    if not wrong or len(exprs) < 2 or len(exprs) != len(line.sides) or any(x.free_symbols for x in exprs):
        return False
    put, changed = [], False
    for text, x in zip(line.sides[:-1], exprs[:-1], strict=True):
        side = _as_read(text, x)
        if side is None:
            return False
        fixed = _NUMBER.sub(
            lambda m: f"({wrong[r]!r})" if (r := sympy.Rational(m.group())) in wrong else m.group(), side
        )
        value = side_value(fixed) if fixed != side else number_of(x).real  # type: ignore[union-attr]
        if value is None:
            return False
        changed = changed or fixed != side
        put.append(sympy.Float(value, 20))
    if not changed:
        return False
    fixed_line = replace(line, exprs=(*put, exprs[-1]))
    return trace.holds(trace.pairs(fixed_line), trace.truth)
