"""The world of a slip of rounding too early: the values before the impact as the student rounded them.

A student who rounds the components before the impact to two figures (``A_n = 80 cos 25 = 72.50 ≈
73``, ``B_t = 110 sin 100 = 108.33 ≈ 110``) is right on each line that rounds (it says the value),
and makes the slip where the rounding first moves a result (``4(73) + 3(-19) = 235``:
``rounded_too_early``). The rule a teacher follows after it: every later line worked from those
numbers is judged by them. ``b - a = 0.7(73 - (-19)) = 64.4``, the velocities solved from it and the
speeds from the rounded t components (``sqrt(5.971^2 + 34^2) = 34.52``) are carried, not further
slips, though 64.4 is not the restitution of the problem's components. So where the slip is named
``rounded_too_early``, its world is the problem solved again with each component before as the
student last stated it (:func:`adopt`), not the true equations with the one slipped line put in.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

import sympy

from derive.checking.mistakes import Variant
from derive.checking.numeric import number_of

if TYPE_CHECKING:
    from derive.checking.inference import Read
    from derive.checking.tracing import Trace


def keep(trace: Trace, stated: Any, line: Read) -> None:
    """``A_n = 80 cos 25 = 72.50 ≈ 73``: the number a component before the impact comes to on the
    student's line, kept for :func:`adopt` in ``stated`` (:class:`~.dependency.Stated`)."""
    exprs = line.exprs or ()
    pre = trace.ctx.model.pre
    if len(exprs) < 2 or not isinstance(exprs[0], sympy.Symbol) or exprs[0] not in pre:
        return
    value = number_of(exprs[-1]) if not exprs[-1].free_symbols else None
    if value is not None and abs(value.imag) < 1e-12:
        stated.before[exprs[0]] = sympy.Rational(str(value.real))


def adopt(trace: Trace) -> None:
    """The slip's world, where it is the first slip: the problem solved with the components
    before as the student stated them, where one of them is not the problem's value."""
    model, before = trace.ctx.model, trace.stated_values().before
    if trace.world is not None or not before:
        return
    own = {}
    for k, x in before.items():
        true = number_of(model.num(model.pre[k])) if not model.num(model.pre[k]).free_symbols else None
        if true is not None and abs(complex(x) - true) > 1e-9 * max(abs(true), 1.0):
            own[k] = x
    if not own:
        return
    variant = Variant(pre={**model.pre, **own})
    out = model.outcome(variant)
    if out is None:
        return
    trace.world = [{u: out.post[u].xreplace(pt) for u in trace.U} for pt in trace.pts]
    trace.equations = {j: F for j, F in out.equations.items() if j in trace.equations}
    trace.variant = variant
