"""A line carried by what it depends on: the values the student stated for quantities on their
own lines, put in for those quantities in a later line of any kind.

A teacher reads ``v_B = 3.45`` (right given the slip before it) and then ``e = (v_B - v_A)/(u_A -
u_B) = (3.45 + 0.2)/4 = 0.9125`` as carried: it holds once the student's own 3.45 stands for
v_B and the given v_A is as the problem has it, whatever the slip's world makes of v_A in the
equations the student did not write wrongly; the e it comes to is then the student's own. So
is ``tan θ = √3(1 + e)/(1 - 3e)`` said again after a chain of ``=`` lines, worked from a wrong
formula for tan θ, came to it: the chain's head (tan θ) has the value its last line came to.

:func:`note` keeps, for each line judged, the value its head comes to (its first side, or the
head of the chain of lines it goes on from); :func:`holds_with_own` puts those in. A line that
finds a quantity (its first side a name not stated yet) is carried when the rest of it holds
with the student's values put in and its first step is a law: true for the problem as written
in names (``e = (v_B - v_A)/(u_A - u_B)``), or, in numbers, true once each number the student
stated for a quantity is that quantity's value for the problem (``(3.45 + 0.2)/4`` is
``(3.55 + 0.2)/4`` for v_B = 3.55).
"""

from __future__ import annotations

import functools
import re
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import sympy

from derive.checking.naming import Open, read_side, rewrite
from derive.checking.numeric import number_of
from derive.checking.roundedworld import keep
from derive.checking.slipbefore import holds_as_slipped
from derive.checking.worlds import NUMBER_SIDE
from derive.mathtext.notation import student
from derive.problem.expr import ParseError

if TYPE_CHECKING:
    from derive.checking.inference import Read
    from derive.checking.tracing import Trace
    from derive.checking.worlds import Pair

#: A line that goes on from the one above: "=" first, after any markup that opens it (a list's
#: bullet, a quote's ``>``, ``$``, ``\(``, ``\[``, an ``align`` row's ``&``, TeX spacing), or
#: after words of what the step does up to a colon (``times rt3(1-e) top and bottom: = …``).
GOES_ON = re.compile(
    r"(?:[^=:\n]{1,80}:(?!=))?\s*(?:(?:[*>+$&-]|\\[(\[]|\\q?quad\b|\\[,;:!])\s*)*(?:=|≈|\\approx\b|~=)"
)  # one $ a step: no backtracking


@functools.lru_cache(maxsize=4096)
def side_value(text: str) -> float | None:
    """The value of a side of numbers only, read again (None where it does not read); kept,
    as a line's pairs are made again at each verdict."""
    try:
        x = read_side(rewrite(text, set()), Open({}), True, True)
    except (ParseError, ValueError, TypeError, RecursionError):
        return None
    v = number_of(x) if not x.free_symbols else None
    return v.real if v is not None and abs(v.imag) < 1e-12 else None


#: The most quantities kept (a derivation states a handful; putting them in stays cheap).
MAX_KEPT = 40


class Stated:
    """The student's own values of quantities, as their lines last stated them."""

    def __init__(self) -> None:
        self.values: dict[sympy.Expr, sympy.Expr] = {}
        self.written: dict[sympy.Expr, str] = {}  # a value stated as a number: the number as written
        self.head: sympy.Expr | None = None  # the head of the chain of "=" lines read last
        self.moved = False  # whether a wrong or carried line has stated a value yet
        self.before: dict[sympy.Symbol, sympy.Expr] = {}  # the components before, as last stated (A_n ≈ 73)


def _quantity(trace: Trace, x: sympy.Expr) -> bool:
    """Whether ``x`` names a quantity the derivation finds: a name or a function of names
    (``v_B``, ``tan θ``, ``v²``) whose value depends on the unknowns."""
    if x.is_number or not (x.is_Symbol or x.is_Function or x.is_Pow):
        return False
    return bool(trace.ctx.in_unknowns(x).free_symbols & set(trace.U))


def _in_unknowns(trace: Trace, x: sympy.Expr) -> bool:
    return bool(trace.ctx.in_unknowns(x).free_symbols & set(trace.U))


def note(trace: Trace, stated: Stated, line: Read, status: str | None) -> None:
    """What ``line``, judged ``status``, states: its head's value, where it comes to one."""
    exprs = line.exprs or ()
    if status not in ("correct", "carried", "wrong") or len(exprs) < 2:
        stated.head = None
        return
    keep(trace, stated, line)  # A_n = 80 cos 25 = 72.50 ≈ 73: the world of a slip of rounding
    goes_on = GOES_ON.match(line.written) is not None and stated.head is not None
    head = stated.head if goes_on else exprs[0]
    if head is None or not _quantity(trace, head):
        stated.head = None
        return
    stated.head = head
    last = exprs[-1]
    if _in_unknowns(trace, last) or last.has(sympy.zoo, sympy.nan):
        return
    if head not in stated.values and len(stated.values) >= MAX_KEPT:
        return
    stated.moved = stated.moved or status != "correct"
    stated.values[head] = last
    m = NUMBER_SIDE.match(student(line.sides[-1].strip())) if line.sides else None
    if m and not m.group(3) and last.is_number:
        stated.written[head] = m.group(2)
    else:
        stated.written.pop(head, None)


def holds_with_own(trace: Trace, stated: Stated, line: Read) -> bool:
    """Whether ``line`` holds once the student's own values stand for the quantities they
    stated, in the slip's world or for the problem (see the module's words)."""
    exprs = line.exprs or ()
    if not stated.moved or len(exprs) < 2:
        return False
    first = exprs[0]
    finds = len(exprs) >= 3 and _quantity(trace, first) and first not in stated.values
    put = tuple(x.xreplace(stated.values) for x in exprs)
    worlds = [w for w in (trace.world, trace.truth) if w is not None]
    if not finds:
        pairs = trace.pairs(replace(line, exprs=put))
        return put != exprs and any(trace.holds(pairs, w) for w in worlds)
    rest = replace(line, sides=line.sides[1:], exprs=put[1:])  # each step after the first side
    if not any(trace.holds(trace.pairs(rest), w) for w in worlds):
        return False
    if exprs[1].free_symbols:  # in names: the law as written, the student's values put in after it
        step = replace(line, sides=line.sides[:2], exprs=exprs[:2])
        return put[1:] != exprs[1:] and any(trace.holds(trace.pairs(step), w) for w in worlds)
    return _law(trace, stated, line)


def _law(trace: Trace, stated: Stated, line: Read) -> bool:
    """Whether the first step of ``line`` (the quantity found = its working in numbers) is a
    law: true for the problem once each number the student stated for a quantity is put back
    as that quantity's value for the problem."""
    exprs, sides = line.exprs or (), line.sides
    text, pt, truth = sides[1], trace.pts[0], trace.truth[0]
    for q, written in stated.written.items():
        v = number_of(trace.ctx.in_unknowns(q).xreplace(pt).xreplace(truth))
        if v is None or abs(v.imag) > 1e-12:
            continue
        text = re.sub(rf"(?<![\w.]){re.escape(written)}(?![\w.]|\d)", f"({v.real!r})", text)
    if text == sides[1]:
        return False
    value = side_value(text)
    if value is None:
        return False
    fixed = replace(line, sides=(sides[0], text), exprs=(exprs[0], sympy.Float(value, 20)))
    return trace.holds(trace.pairs(fixed), trace.truth)


def exact_in_world(trace: Trace, pairs: list[Pair]) -> bool:
    """Whether ``pairs``, right for the problem only within the figures written, are exactly
    true in the slip's world (``v = 5.25/70.0``, then ``v = 0.075``, after the puck's mass left
    out of the momentum after: 0.075 is 0.07484 at two figures, but it is 5.25/70 exactly):
    the student's own value, carried, not the problem's."""
    if trace.world is None:
        return False
    U, found = set(trace.U), False
    for p in pairs:
        if not trace.ctx.in_unknowns(p.difference).free_symbols & U:
            continue
        exact = [_exact(p, trace.pts[0], values[0]) for values in (trace.world, trace.truth)]
        if exact[0] is None or exact[1] is None or not exact[0]:
            return False
        found = found or not exact[1]
    return found


def _exact(p: Pair, pt: dict, values: dict) -> bool | None:
    left, right = (number_of(x.xreplace(pt).xreplace(values)) for x in (p.left, p.right))
    if left is None or right is None:
        return None
    return abs(left - right) <= 1e-12 * max(abs(left), abs(right), 1e-9)


class Depending:
    """The part of the trace that keeps what the student stated (:class:`Stated`) and asks
    whether a line holds with it put in."""

    def stated_values(self) -> Stated:
        """What the student stated so far for quantities (made when first asked)."""
        found = self.__dict__.get("_stated_values")
        if found is None:
            found = self.__dict__["_stated_values"] = Stated()
        return found

    def _note_stated(self, line: Read, status: str) -> None:
        trace: Any = self
        note(trace, self.stated_values(), line, status)

    def _holds_with_stated(self, line: Read) -> bool:
        """Whether ``line``, false for the problem, holds with the student's values put in (a
        line true for the problem that the slip does not move, ``v_A = sqrt(4.5^2 + 12^2)``
        after the restitution reversed made -4.5 into 4.5, is correct)."""
        trace: Any = self
        if not line.exprs or trace.holds(trace.pairs(line), trace.truth):
            return False
        return holds_with_own(trace, self.stated_values(), line) or holds_as_slipped(trace, line)
