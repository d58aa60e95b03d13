"""A relation in several unknowns worked on wrongly: its terms kept, its number not.

:func:`.slipnames.solving_slip` names a line solved from the relation just before it in one
unknown; a line that only tidies a relation in two unknowns (``0.3(3) + 0.2(-2) = 0.3 v_A +
0.2 v_B, so 0.3 v_A + 0.2 v_B = 0.6``: the momentum's number worked out) and gets that number
wrong is the same slip, an arithmetic one, whether the relation it works on is on the line
before or earlier on the same line. Without it such a line looks like a given copied wrongly
(a mass put in for another can make it hold within its rounding).
"""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.checking import letterslips, misread, slipnames
from derive.checking.dependency import GOES_ON
from derive.checking.slipnames import Holds, Previous, same_but_number
from derive.checking.worlds import Pair


def number_worked_wrongly(
    pairs: list[Pair], previous: Previous, at: tuple[tuple, dict], holds: Holds, values: dict | None = None
) -> str:
    """``arithmetic`` where the first failing relation of a line is one that holds (the line
    before's, or one earlier on the line) with the same terms in the same unknowns, up to a
    factor, and only its number changed; "" otherwise. ``at``: the unknowns and a sample point;
    ``values``: the student's values there (the line before's other unknowns put in: ``v_B2 -
    v_A2 = e(0.5)``, v_A2 found before, then ``0.35 = 0.5e`` for 0.325)."""
    U, pt = at
    unknowns = set(U)
    if any(not p.difference.free_symbols & unknowns and not holds(p) for p in pairs):
        return ""  # a side of numbers wrong is the arithmetic of that side, named elsewhere
    failing = next((p for p in pairs if p.difference.free_symbols & unknowns and not holds(p)), None)
    if failing is None:
        return ""
    own = pairs[: pairs.index(failing)]
    held = [p for p in (*(previous[1] if previous else ()), *own) if p.difference.free_symbols & unknowns]
    held = [p for p in held if holds(p)]
    names = failing.difference.free_symbols & unknowns
    for p in held:
        if p.difference.free_symbols & unknowns == names and same_but_number(failing.difference, p.difference, U, pt):
            return "arithmetic"
    numbers = failing.raw is not None and all(x.free_symbols <= unknowns for x in failing.raw)  # no letters given
    for p in held if values and numbers else ():  # the numbers put into a law in letters: its other unknowns as found
        other = (p.difference.free_symbols & unknowns) - names
        if not names or not other or not all(s in values for s in other):
            continue
        put = p.difference.xreplace(pt).xreplace({s: values[s] for s in other})
        if put.free_symbols & unknowns == names and same_but_number(failing.difference, put, U, pt):
            return "arithmetic"
    return ""


def wrong_energy_worked(trace, line, pairs: list[Pair]) -> bool:
    """A line that goes on ("= ...") from a wrong line and whose side of numbers is a kinetic
    energy by one of the wrong formulas (``KE lost = ½m(u − v)²``, then ``= 0.5 × 0.8 × (4 −
    1.2)²``: of the speeds): the wrong formula's working, carried, not a further slip."""
    if not trace.went_wrong or GOES_ON.match(line.written) is None:
        return False
    unknowns = set(trace.U)
    numbers = [(p, x) for p in pairs for x in (p.left, p.right) if not x.free_symbols & unknowns]
    world = trace.world if trace.world is not None else trace.truth
    for form in [*slipnames.wrong_energies(trace.ctx), *swapped_energies(trace.ctx)]:
        for value in form.values():
            energy = trace.ctx.in_unknowns(misread.with_copied(trace.ctx, value, trace.copied))  # 5 for 4 m/s
            if any(trace.holds([replace(p, left=energy, right=x, raw=None)], world) for p, x in numbers):
                return True
    return False


def works_from_slip(trace, line, slip_line: int) -> bool:
    """Whether ``line`` writes a number the slip at ``slip_line`` came to, or a line after it (not data):
    ``7.2 = -0.96 + 0.4v`` after ``momentum before = 0.8(6) + 0.4(6) = 7.2`` (B's sign lost)
    works from that line's number, a carried error, not the mistake made again."""
    stated = set().union(*(t for n, t in trace.stated.items() if slip_line <= n < line.number))  # and lines after it
    written = set(re.findall(r"\d+\.?\d*", " ".join(line.sides)))
    figures = [t for t in written & stated if "." in t.strip(".") or len(t.strip("0")) >= 2]  # not a 2 of ½
    return any(t.strip("0.") and sympy.Rational(t) not in trace.ctx.data for t in figures)


def into_world(trace, line, pairs: list[Pair]) -> None:
    """A relation right for the problem after a slip whose world it does not hold in (B's sign
    lost in the momentum, then ``v_B - v_A = 0.8(3 + 2)`` right: the mistake changed the
    approach too, the student did not): the student's world takes it in place of the equation
    it stands for, so the lines worked from both are carried, not further slips."""
    if trace.world is None or not re.search(r"\d", " ".join(line.sides)):
        return  # a law in names (the givens as the problem has them) is not the student's numbers
    givens = {g.symbol for g in trace.ctx.problem.givens if not g.unknown}
    own = [p for p in pairs if p.difference.free_symbols & set(trace.U) and not trace.holds([p], trace.world)]
    if len(own) == 1 and not set().union(*(x.free_symbols for x in own[0].raw or ())) & givens:
        trace._replace(line, own[0], slip=False)


#: What a report says of a line that holds with one term's factor changed.
SCALED = ": it holds with one term's factor changed (a slip in substituting or rearranging: a factor lost or doubled)."
#: The factors a term is found with: dropped, or a whole number's factor (a coefficient of the
#: name substituted: 7y = 7(x + 4eu)) lost or put in.
_FACTORS = (sympy.Integer(0), *(f for k in range(2, 13) for f in (sympy.Integer(k), sympy.Rational(1, k))))


def term_scaled(ctx, bad: Pair, holds: Holds, prefer: frozenset = frozenset()) -> sympy.Expr | None:
    """The relation ``bad`` stands for where it holds with exactly one of its terms in letters
    dropped or scaled by a whole number or its inverse (``u = x + 2x + eu`` from ``u = x + 2y``,
    ``y = x + eu``: the eu not doubled); None otherwise. Lines of three terms or more, as a
    sign lost (:func:`.slipnames.sign_flipped`); a term of numbers only is arithmetic. Where
    several such changes make it hold (``4u = 4x + 5x + u/2`` holds with the u/2 taken five
    times, the 4u halved or the 4x taken four times), the one change by a factor in ``prefer``
    (:func:`substituted_factors`: the coefficient of a name put in for) is what was done."""
    if bad.raw is None:
        return None
    terms = [sympy.Add.make_args(x) for x in bad.raw]
    if sum(len(t) for t in terms) < 3:
        return None
    found = []
    for i, side in enumerate(bad.raw):
        for term in terms[i]:
            if not term.free_symbols:
                continue
            for k in _FACTORS:
                raw = list(bad.raw)
                raw[i] = side + (k - 1) * term
                left, right = (ctx.in_unknowns(x) for x in raw)
                if holds(replace(bad, left=left, right=right, raw=(raw[0], raw[1]))):
                    found.append((k, left - right))
    if len(found) > 1:
        found = [f for f in found if f[0] in prefer]
    return found[0][1] if len(found) == 1 else None


def substituted_factors(held: list[Pair], bad: Pair, U: tuple) -> frozenset:
    """The factors a slip in putting a name in for another takes one term by: the coefficient
    (and its inverse) of each unknown of the last relations held that ``bad`` no longer has,
    the name substituted away (5 for ``y`` in ``4u = 4x + 5y``, ``y = x + u/2``)."""
    gone = set().union(*(p.difference.free_symbols for p in held[-4:])) & set(U)
    gone -= bad.difference.free_symbols
    out = set()
    for p in held[-4:]:
        F = sympy.expand(p.difference)
        for y in gone:
            c = abs(F.coeff(y, 1))
            if c.is_Rational and c not in (0, 1):
                out |= {c, 1 / c}
    return frozenset(out)


def speed_of_reversed(trace, pairs: list[Pair]) -> bool:
    """After a slip, ``|x| = ⅓u(e − 1)`` where the student's x is ⅓u(1 − e): the speed of a body
    the student says reverses, written as −x from the student's own x (its sign as the problem
    has it, not as the slip leaves it): the line holds in the slip's world with |x| as −x."""
    if trace.world is None or not any(p.difference.has(sympy.Abs) for p in pairs):
        return False

    def negated(x: sympy.Expr) -> sympy.Expr:
        return x.replace(
            lambda a: isinstance(a, sympy.Abs) and bool(a.free_symbols & set(trace.U)), lambda a: -a.args[0]
        )

    turned = [replace(p, left=negated(p.left), right=negated(p.right), raw=None) for p in pairs]
    return turned != pairs and trace.holds(turned, trace.world)


def pinned(trace, bad: Pair) -> bool:
    """Whether each unknown of ``bad`` has been stated by a line that held, alone in it
    (``v_B = ⅓u(1 + e)``), with no slip yet: a common mistake gives that unknown another value,
    so it is not what went wrong in ``bad`` (``v_A = u − 2v_B = ⅓u(1 + 2e)``: a sign lost in
    working it, not the impact rule reversed)."""
    unknowns = bad.difference.free_symbols & set(trace.U)
    if trace.slips or trace.world is not None or not unknowns:
        return False
    if any(x.is_Symbol for x in (bad.left, bad.right)):
        return False  # ``v_1f = (27 - 22)/49 (3.5)``: the value itself worked afresh, the masses swapped in it
    alone = {next(iter(s)) for p in trace.held if len(s := p.difference.free_symbols & set(trace.U)) == 1}
    return unknowns <= alone


def sign_over_number(trace, bad: Pair, name: str, holds: Holds) -> str:
    """``arithmetic`` (a line's part free of the unknowns changed) where that part is in letters
    and the line holds with one of its terms' sign changed: a sign lost in the algebra
    (``u − 2v_B = ⅓u(1 + 2e)`` for ⅓u(1 − 2e)), ``algebra``; ``name`` otherwise."""
    if name != "arithmetic":
        return name
    if bad.raw is None or not trace.pts[0]:  # a term of the unknowns' changed, not a number
        return letterslips.in_letters(trace, bad, name)
    expanded = replace(bad, raw=(sympy.expand(bad.raw[0]), sympy.expand(bad.raw[1])))  # ⅓u(1 + 2e): two terms
    flip, _right = slipnames.sign_flipped(trace.ctx, expanded, trace.U, holds)
    return "algebra" if flip == "algebra" else letterslips.in_letters(trace, bad, name)


#: What a report says of a kinetic energy worked with the masses exchanged.
SWAPPED = ": it works the kinetic energy with the two masses exchanged (each body's mass with the other's velocity)."


def swapped_energies(ctx) -> list[dict[str, sympy.Expr]]:
    """The kinetic energies (by result name) with the masses exchanged, ½m_B v_A² + ½m_A v_B²,
    in the components; none at a wall or for equal masses."""
    model, p = ctx.model, ctx.problem
    if p.fixed_B or sympy.simplify(model.m_A - model.m_B) == 0:
        return []
    nm, half = model.nm, sympy.Rational(1, 2)

    def square(b: str, k: str) -> sympy.Expr:
        t = getattr(nm, f"{b}{k}t") if p.oblique else None
        return getattr(nm, f"{b}{k}n") ** 2 + (t**2 if t is not None else 0)

    t1, t2 = (half * model.m_B * square("A", k) + half * model.m_A * square("B", k) for k in "12")
    return [{"T_1": t1, "T_2": t2, "T_lost": t1 - t2}]


def energy_masses_swapped(trace, bad: Pair, holds: Holds) -> bool:
    """Whether ``bad`` holds with a kinetic energy it names (``KE after``, T_2) worked with the
    masses exchanged (``½(6m)v_A² + ½(3m)v_B²`` where A is 3m)."""
    if bad.raw is None:
        return False
    derived = trace.ctx.derived()
    syms = set().union(*(x.free_symbols for x in bad.raw))
    named = {n: derived[n][0] for n in ("T_1", "T_2", "T_lost") if n in derived and derived[n][0] in syms}
    for form in swapped_energies(trace.ctx) if named else ():
        sides = [trace.ctx.in_unknowns(x.xreplace({s: form[n] for n, s in named.items()})) for x in bad.raw]
        if holds(replace(bad, left=sides[0], right=sides[1])):
            return True
    return False


def worked_on(trace, pairs: list[Pair], name: str, world: list) -> bool:
    """Whether a line that states a rule and works it through (``x = y + 4eu = (3u - eu + 4eu)/2 =
    u(3 + 3e)/2``) has its slip in the working: its first relation holds in the slips' ``world`` and
    the slip ``name`` is one of solving (arithmetic or algebra). What the student carries on is then
    its first side = its last (``x = u(3 + 3e)/2``), the other unknowns as they had them, as a
    teacher marks the lines after it."""
    return name in ("arithmetic", "algebra") and len(pairs) > 1 and trace.holds([pairs[0]], world)


def works_on_previous(trace, bad: Pair) -> bool:
    """Whether ``bad`` is in the unknowns of the relation just before it, which held (``x = u/3 −
    y`` after ``y − x = u/3``): a step from it, named by that step, not by a mistake's other form."""
    if trace.previous is None:
        return False
    unknowns = set(trace.U)
    before = set().union(*(p.difference.free_symbols for p in trace.previous[1])) & unknowns
    return bool(before) and before == bad.difference.free_symbols & unknowns
