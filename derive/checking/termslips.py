"""A line named by its one wrong term: a sign lost, a squared term's ½, a value's sign put in.

A chain's lines are judged as numbers (:mod:`.chainlines`); a line that holds once one of its
terms is put right names the slip: a sign (:func:`~.slipnames.sign_of_a_term`), or the factor
2 of a square: the ½ of ½ m v² dropped is the kinetic energy's formula (``ke_formula``), a
½ lost from v² once the masses cancelled is a slip in rearranging (``algebra``). A line's
own working that puts a value in with its sign lost is ``algebra`` too; a wall's impulse line
with the rebound speed put in as the velocity after is ``b_sign`` (a velocity the wrong way).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING, Protocol

import sympy

from derive.checking import stepslips
from derive.checking.carried import Trace, sides
from derive.checking.chainnames import energy_key
from derive.checking.naming import PREFIX
from derive.checking.rearranging import FACTORS
from derive.checking.slipnames import FLIPPED, Previous, sign_of_a_term, solving_slip
from derive.checking.stepslips import halved  # noqa: F401  (chainlines' import)
from derive.checking.worlds import Pair

if TYPE_CHECKING:
    from derive.checking.context import Context
    from derive.checking.equation import Verdict
    from derive.checking.inference import Read
    from derive.checking.relations import Values

#: A line whose rule holds but whose working does not come to what it claims.
WORKING = (
    ": a step of its working does not follow from the one before it (an arithmetic slip: an expression worked wrongly)."
)


class Solving(Trace, Protocol):
    """A :class:`~.carried.Trace` that keeps the relation just before the line, if it held."""

    previous: Previous


#: What a report says of a coefficient of restitution worked as the ratio upside down.
UPSIDE_DOWN = ": it is the ratio upside down: e = separation / approach (speed after over speed before)."

#: What a report says of a line worked wrongly from the relation just before it, by the slip's name.
SOLVING = {
    "algebra": ": it does not follow from the line before (a slip in rearranging it: a sign, a factor or a letter lost).",
    "arithmetic": ": it does not follow from the line before (an arithmetic slip: a number worked wrongly).",
}
#: What a report says of a chain's line that holds with a squared term's factor of 2 put right.
HALVED = {
    "ke_formula": ": the kinetic energy is worked without its half (T = ½ m v²).",
    "algebra": ": it holds with a factor of 2 put back (a slip in rearranging: a factor lost).",
}


def term_slip(
    exprs: list[sympy.Expr], holds: Callable[[list], bool | None], said: str = "", written: tuple[str, ...] = ()
) -> tuple[str, str]:
    """A chain's line named by the one term that is wrong, with the words for it: a sign lost
    (:func:`~.slipnames.sign_of_a_term`), else a squared term's factor of 2 lost or doubled:
    ``ke_formula`` where the square has a mass with it (``0.3(9.8)(2) = 0.3 v1²``: the ½ of
    ½ m v² dropped), ``algebra`` where it stands alone (``v1² = 9.8(2)`` from ½(0.3) v1² =
    0.3(9.8)(2): the masses cancelled and the ½ lost); ``restitution_reversed`` where a
    coefficient of restitution is worked as the ratio upside down (``e = 6.26/5.24``: approach
    over separation); else the one step of its working that does not follow
    (:func:`~.stepslips.working_step`, ``written``: its sides as written); ("", "") otherwise.
    ``said``: the verdict's words (a line they call an arithmetic slip is one, but for e's
    ratio upside down)."""
    e = exprs[0] if exprs and isinstance(exprs[0], sympy.Symbol) else None
    if e is not None and (e.name == "e" or e.name.startswith("e_")) and holds([1 / e, *exprs[1:]]):
        return "restitution_reversed", UPSIDE_DOWN
    if said.endswith("(an arithmetic slip)."):
        return "", ""
    flip = sign_of_a_term(exprs, holds)
    if flip:
        return flip, FLIPPED[flip]
    found = set()
    for i, side in enumerate(exprs):
        for t in sympy.Add.make_args(side):
            squares = [p for p in t.atoms(sympy.Pow) if p.exp == 2 and p.base.free_symbols]
            if len(squares) != 1:
                continue
            for k in FACTORS:
                if holds([*exprs[:i], side + (k - 1) * t, *exprs[i + 1 :]]):
                    found.add("algebra" if abs(t / squares[0]) == 1 else "ke_formula")
    if len(found) != 1:
        name, why = stepslips.working_step(exprs, written, holds) if written else ("", "")
        return (
            ("ke_formula", HALVED["ke_formula"]) if name == "algebra" and exprs and _energy(exprs[0]) else (name, why)
        )
    name = found.pop()
    return name, HALVED[name]


def _energy(x: sympy.Expr) -> bool:
    """Whether ``x`` is a name the student gives an impact's kinetic energy (``K'``, ``KE after``):
    a factor of 2 lost in its own formula is the ½ of ½ m v² dropped, ``ke_formula``."""
    return isinstance(x, sympy.Symbol) and energy_key(x.name.removeprefix(PREFIX)) is not None


#: What a report says of a line whose working puts a value in with its sign lost.
SIGN_PUT_IN = (
    ": a step of its working puts a value in with its sign lost (a negative velocity written as positive):"
    " a slip in the algebra, not in the numbers."
)


def working_slip(trace: Trace, line: Read, world: list[Values], worked: str) -> tuple[str, str]:
    """The words and name of a slip inside a line's working (:func:`~.carried.worked_wrongly`):
    ``algebra`` where the step from letters to numbers holds with one unknown's value put in
    with its sign lost (``3 v_B2 = 2 - 2 v_A2 = 2 - 2.08`` with v_A2 = -1.04),
    else ``worked`` and ``arithmetic`` (an expression worked wrongly)."""
    unknowns = set(trace.U)
    for i in range(len(line.sides) - 1):
        p = sides(trace, line, i, i + 1)
        if trace.holds([p], world) or p.right.free_symbols & unknowns or not p.left.free_symbols & unknowns:
            continue
        for u in p.left.free_symbols & unknowns:
            if trace.holds([p], [{**w, u: -w[u]} for w in world]):
                return SIGN_PUT_IN, "algebra"
    return worked, "arithmetic"


def rebound_speed(ctx: Context, bad: Pair, v: Verdict) -> tuple[str, str] | None:
    """The words and name (``b_sign``) of a wall's impulse or momentum line (its mass or impulse
    written) that holds with the rebound speed put in as the velocity after (``I = m(v - u)`` with
    v = e u > 0, toward the wall): the line is not the impact rule, so its slip is not the rule's
    differences reversed but a velocity taken in the wrong direction; None otherwise."""
    if not ctx.problem.fixed_B or bad.raw is None or [d.mistake for d in v.mistakes] != ["restitution_reversed"]:
        return None
    written = set().union(*(x.free_symbols for x in bad.raw))
    impulse = {ctx.model.m_A} | {sym for name, (sym, _x) in ctx.derived().items() if name.startswith("J")}
    return (FLIPPED["b_sign"], "b_sign") if written & impulse else None


def renamed(trace: Solving, line: Read, bad: Pair, v: Verdict) -> tuple[int | None, str, str] | None:
    """The equation it takes the place of, the words and the name of a slip a teacher names
    otherwise than the common mistake the judge found: a wall's impulse line with the rebound
    speed in it (:func:`rebound_speed`), or a value solved wrongly from the relation just
    before it (which held), whose value happens to be a mistake's (``v_A2 = u(1 + e)`` from ``u = v_A2 + eu``: a sign lost, not the impact rule
    reversed, which the line does not state); None otherwise."""
    wall = rebound_speed(trace.ctx, bad, v)
    if wall is not None:
        return (v.equation, *wall)
    if v.rule != "solves_as_mistake" or trace.previous is None:
        return None
    world = trace.world if trace.world is not None else trace.truth
    numeric = {g.symbol for g in trace.ctx.problem.givens if g.value is not None and g.value.is_number}
    if any(x.free_symbols & numeric for p in trace.previous[1] for x in p.raw or ()):
        return None  # the line puts numbers in a formula (the masses swapped in it): not a rearrangement
    at = (trace.U, trace.pts[0])
    name = solving_slip(line.sides, trace.pairs(line), trace.previous, at, lambda p: trace.holds([p], world))
    return (None, SOLVING[name], name) if name else None  # in place of the closest: not the mistake's equation
