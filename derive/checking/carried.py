"""Where a line stands to a slip before it, beyond "it holds in the slip's world" (:mod:`.lines`): a line of numbers that
comes to the slip's value of a result (carried, though right arithmetic), and a line whose rule holds while a step of its
own working does not (an arithmetic slip inside the line, and what the student carries on)."""

from __future__ import annotations

import copy
import itertools
import re
from dataclasses import replace
from decimal import Decimal
from typing import TYPE_CHECKING

import sympy

from derive.checking import cofunctions, energyforms, misread, reworld, signslips, slipnames, slipworld, workedslips
from derive.checking.angles import in_degrees
from derive.checking.dependency import exact_in_world
from derive.checking.mistakes import REGISTRY, Mistake, Variant, phrase
from derive.checking.mistakes.pairs import merge
from derive.checking.naming import Open, read_side, rewrite
from derive.checking.numeric import decimals, number_of, shown
from derive.checking.report import Item
from derive.checking.slipbefore import as_slipped, writes_slips_number
from derive.checking.tracing import Trace
from derive.checking.worlds import NUMBER_SIDE, Pair, solve_world, written_right
from derive.mathtext.notation import student
from derive.problem.expr import ParseError

if TYPE_CHECKING:
    from derive.checking.inference import Read
    from derive.checking.relations import Values


#: A slip named: the equation it takes the place of, the words of the verdict, its name.
Found = tuple[int | None, str, str] | None
RESULTS = ("T_1", "T_2", "T_lost", "J_n", "v_A2", "v_B2")  # what a line of numbers may come to


def slips_result(trace: Trace, line: Read, pairs: list[Pair]) -> bool:
    """A line of numbers only, right as arithmetic, that comes to what the slip makes of a result and to no result of
    the problem (``½(2)(7²) + ½(1)(1²) = 49.5``: T_2 with the swapped masses' velocities): carried, not correct; so is a
    velocity stated so (:func:`~.reworld.nearer_the_slip`), or one worked from a number the student got wrong with the slip in
    place of the other equation (:func:`~.reworld.moved`: ``v1f = 0.160 - 35.0 = -34.84`` after
    ``v2f = 10.5/70.15 = 0.160``, near the true -34.85 too: the restitution kept); an angle in degrees so too."""
    U = set(trace.U)
    if trace.world is None or any(p.difference.free_symbols & U for p in pairs):
        wrote = bool(decimals(line.sides[:-1]) & trace.wrong_values) and trace.world is not None
        moved = wrote and reworld.moved(trace, pairs, written_wrong=True) and trace._moved(pairs)  # values it moves
        return reworld.nearer_the_slip(trace, line, pairs) or moved or exact_in_world(trace, pairs)
    m = NUMBER_SIDE.match(student(line.sides[-1].strip()))
    givens = {g.symbol for g in trace.ctx.problem.givens}
    if not m or m.group(3) == "rad" or any(x in givens for x in line.exprs or ()):  # "since e = 1": the data, stated
        return False
    written = Decimal(m.group(1) + m.group(2))
    d = trace.ctx.derived()
    exprs = in_degrees(d) if m.group(3) else [d[n][1] for n in RESULTS if n in d] + list(trace.U)

    def comes_to(values: Values, slipped: bool = False) -> bool:  # slipped: the values before as the slip has them
        for x in (as_slipped(trace, y) for y in exprs) if slipped else exprs:
            v = number_of(trace.ctx.in_unknowns(x).xreplace(trace.pts[0]).xreplace(values))
            if v is not None and abs(v.imag) < 1e-12 and written_right(written, sympy.Float(v.real, 15)):
                return True
        return False

    return (comes_to(trace.world[0]) or comes_to(trace.world[0], True)) and not comes_to(trace.truth[0])


def sides(trace: Trace, line: Read, i: int, k: int) -> Pair:
    """The pair of ``line``'s sides ``i`` and ``k``, as a relation of its own."""
    assert line.exprs is not None
    two = replace(line, sides=(line.sides[i], line.sides[k]), exprs=(line.exprs[i], line.exprs[k]))
    return trace.pairs(two)[0]


def worked_wrongly(trace: Trace, line: Read, world: list[Values]) -> bool:
    """``v_B = v_A + eu = (5 + 4e)u/3`` (its rule right, the working from it wrong) or
    ``4v + 8(v + 4) = 12v + 4 = 80`` (its claim right, a step of its working wrong): an
    arithmetic slip inside the line."""
    if len(line.sides) < 3 or line.exprs is None or len(line.exprs) != len(line.sides):
        return False
    if not (trace.holds([sides(trace, line, 0, 1)], world) or trace.holds([sides(trace, line, 0, -1)], world)):
        return False
    steps = [sides(trace, line, i, i + 1) for i in range(len(line.sides) - 1)]
    return not all(trace.holds([p], world) for p in steps)


def carried_on(trace: Trace, line: Read) -> tuple[Pair, Pair]:
    """What a line with a slip in its working carries on: its first side = its last (``v_B = (5 + 4e)u/3``), else its
    last step (``12v + 4 = 80``)."""
    return sides(trace, line, 0, -1), sides(trace, line, -2, -1)


def given_copied(trace: Trace, bad: Pair) -> str:
    """``e = 0.6`` where the problem gives e = 0.4: a given replaced by another number (not the same with its sign
    turned: the student's own axis). The slip's world is then the problem solved with the number as copied (the lines
    after, right with it, are carried); the words of the verdict ("" where it is not such a line)."""
    if bad.raw is None or not isinstance(bad.raw[0], sympy.Symbol) or not bad.raw[1].is_Rational:
        return ""
    g = next((g for g in trace.ctx.problem.givens if g.symbol == bad.raw[0] and not g.unknown), None)
    if (
        g is None
        or g.value is None
        or not g.value.is_Rational
        or abs(g.value) == abs(bad.raw[1])
        or trace.world is not None
    ):
        return ""
    out = trace.ctx.model.outcome(Variant(values={g.symbol: bad.raw[1]}))
    if out is None:
        return ""
    trace.copied[g.symbol] = bad.raw[1]
    trace.variant = Variant(values={g.symbol: bad.raw[1]})
    trace.world = [{u: out.post[u].xreplace(pt) for u in trace.U} for pt in trace.pts]
    if any(x.unknown for x in trace.ctx.problem.givens):  # its outcome keeps the true unknowns: solved so
        trace.world = slipworld.solved_with(trace, trace.variant) or trace.world
    trace.equations = {j: F for j, F in out.equations.items() if j in trace.equations}
    written = bad.text.split(" = ")[-1].strip()
    return f": a given is copied wrongly: the problem gives {g.name} = {shown(g.value)}, not {written}."


def unnamed(trace: Trace, line: Read, bad: Pair, world: list[Values], j: int | None) -> Found:
    """The slip ``bad`` (of ``line``) no common mistake names, named by what makes it
    hold: a given copied wrongly (``copied_wrong``), a given velocity taken the other way
    (``b_sign``: the problem solved with it so, no equation replaced), one term's sign
    (``algebra``, or ``b_sign`` for a mass times a velocity: in place of the equation the
    line is with that sign right); the equation replaced, the words, the name; None otherwise."""

    def holds(p: Pair) -> bool:
        return trace.holds([p], world)

    if speed_for_component(trace, line, world):
        return 4, SPEEDS, "e_speeds"
    if (swapped := misread.swapped_words(trace, line, bad)) is not None:
        return swapped  # 0.0954 for 0.0945
    if (copied := slipworld.number_copied(trace, bad)) or slipnames.copied_wrong(
        trace.ctx, bad, holds, " = ".join(line.sides)
    ):
        return (0, copied, "copied_wrong") if copied else (j, f": {slipnames.COPIED}", "copied_wrong")
    if given_negated(trace, bad):
        return 0, slipnames.FLIPPED["b_sign"], "b_sign"  # 0: no equation replaced
    if (one := signslips.negated_in_one(trace, bad)) is not None:  # in the restitution line alone
        return one, slipnames.FLIPPED["b_sign"], "b_sign"
    flip, right = slipnames.sign_flipped(trace.ctx, bad, trace.U, holds)
    prefer = workedslips.substituted_factors(trace.held, bad, trace.U)
    if not flip and (energy := energyforms.masses_put_right(trace.ctx, bad, holds)) is not None:
        return trace._closest(energy), f": {slipnames.KE_FORMULA}", "ke_formula"  # ½ m v_B² for ½(9m) v_B²
    if not flip and (scaled := workedslips.term_scaled(trace.ctx, bad, holds, prefer)) is not None:
        return trace._closest(scaled), workedslips.SCALED, "algebra"  # a factor lost in substituting
    if not flip:
        return cofunctions.asked_angle(trace, line, bad, holds)  # α from the wall resolved as from the normal
    if right is not None and right.free_symbols & set(trace.U):
        j = trace._closest(right)
    return j, slipnames.FLIPPED[flip], flip


def again_item(trace: Trace, line: Read, pairs: list[Pair]) -> Item | None:
    """The verdict on a line that makes a slip of the values before the impact again
    (:func:`made_again`); None where it does not."""
    fresh = not writes_slips_number(trace, line.sides)  # 5(0.99509): the slip's number carried, not resolved again
    again = (made_again(trace, pairs) if fresh else None) or made_again_in_results(trace, line, pairs)
    if again is None:
        return None
    said = f"False: the same mistake as in line {again[0]}, made again: it {phrase(again[1])}."
    item = Item("line", str(line.number), line.written, "wrong", "", said, "substituting the correct values")
    return replace(item, slip=again[1], again=True)


def made_again_in_results(trace: Trace, line: Read, pairs: list[Pair]) -> tuple[int, str] | None:
    """The mistake in the masses named at an earlier line that a line of a result works afresh
    (``T_2 = ½(15)(8.256)² + ½(10)(14.153)²`` after ``T_1 = ½(15)(19.657)² = 2898``: the
    weights as masses again, with velocities an earlier slip gave): the line writes the
    mistake's own values (the weights 15 and 10; not 7500, a total worked on an earlier line),
    its false pairs hold with them, and it uses none of the numbers that line came to (a line
    worked from 2898 carries it); None otherwise."""
    world = trace.world or trace.truth
    false = [p for p in pairs if not trace.holds([p], world)]
    working = set(re.findall(r"\d+\.?\d*", " ".join(line.sides[:-1])))
    if not false:
        return None
    for n, names in sorted(trace.named.items()):
        for name in sorted(names):
            m = REGISTRY.get(name)
            v = m.build(trace.ctx.model) if m is not None else None
            if v is None or working & trace.stated.get(n, set()) or not _writes(trace, working, v):
                continue
            if all(
                slipnames.with_mistakes_values(trace.ctx, p, {name}, lambda q: trace.holds([q], world)) for p in false
            ):
                return n, name
    return None


def _writes(trace: Trace, working: set[str], v: Variant) -> bool:
    """Whether the numbers ``working`` has one of the masses the mistake ``v`` puts in (its
    values, or the problem's masses where it exchanges them)."""
    model = trace.ctx.model
    put = list(v.values.values()) if v.values else []
    put += [trace.ctx.in_unknowns(x).xreplace(trace.pts[0]) for x in (model.m_A, model.m_B)] if v.masses else []
    numbers = {number_of(x) for x in put if x.is_number}
    return any(number_of(sympy.Rational(t)) in numbers for t in working)


def made_again(trace: Trace, pairs: list[Pair]) -> tuple[int, str] | None:
    """The slip (its line, its name) a line makes again: a velocity before the impact resolved
    afresh the same wrong way (``u_2 = u cos 30°`` under ``u_1 = u sin 30°``: the t component
    with sin and cos swapped too) is that mistake again, not a carried error; None otherwise."""
    named = {name: n for n, names in trace.named.items() for name in names}
    pre, own = set(trace.ctx.model.pre), trace.own  # vA1t = (rt3/2)u as stated wrongly before: said again, carried
    false = [p for p in pairs if not trace.holds([p], trace.truth) and not (p.raw and own.get(p.raw[0]) == p.raw[1])]
    if not named or not false:
        return None
    for p in false:
        if p.raw is None or not set().union(*(x.free_symbols for x in p.raw)) & pre:
            return None  # not a velocity before the impact resolved
        if p.difference.free_symbols & set(trace.U):
            return None
    found = [slipnames.before_impact(trace.ctx, p, lambda q: trace.holds([q], trace.truth)) for p in false]
    for m in found[0]:
        name = slipnames.as_named(trace.ctx, m).name
        if name in named and all(name in {slipnames.as_named(trace.ctx, x).name for x in f} for f in found):
            return named[name], name
    return None


def given_negated(trace: Trace, bad: Pair) -> bool:
    """Whether the first slip ``bad`` holds with one of the problem's given velocities taken the
    other way (``0.5(0.2)`` for an A that moves back at 0.2 m/s; ``2mv`` for a P that reverses
    at speed v): a velocity's sign lost. The slip's world is then the problem solved with that
    velocity so (no equation replaced), and the lines right with it are carried."""
    if trace.world is not None:
        return False
    model = trace.ctx.model
    for g in trace.ctx.problem.givens:
        value = g.value if g.value is not None else g.definition
        if g.unknown or value is None or value == 0 or g.name[:1] not in "uvw" or g.symbol is None:
            continue
        variant = Variant(values={g.symbol: -value})
        turned = copy.copy(model)  # a velocity after given (A moves back): among the known components
        turned.zeros = {k: (-x if x == value else x) for k, x in model.zeros.items()}
        turned.ind = {k: (-x if x == value else x) for k, x in model.ind.items()}
        equations = {j: F for j, F in turned.numbered(variant).items() if j in trace.equations}
        if equations == trace.equations:
            continue
        world = solve_world(equations, trace.U, trace.pts, trace.truth)
        held = world is not None and (trace.holds([bad], world) or _named_negated(trace, bad, g.symbol, -value, world))
        if held and signslips.keeps_own(trace, world, g.symbol):
            trace.variant, trace.world, trace.equations = variant, world, equations
            return True
    return False


def _named_negated(trace: Trace, bad: Pair, symbol: sympy.Symbol, value: sympy.Expr, world: list[Values]) -> bool:
    """Whether ``bad``, free of the unknowns, holds with a given velocity taken the other way in
    a quantity it names (``p after = 0.8(1.2) + 0.4v`` for an A that moves back at 1.2 m/s)."""
    if bad.raw is None or bad.difference.free_symbols & set(trace.U):
        return False
    raw = tuple(misread.with_copied(trace.ctx, x, {symbol: value}) for x in bad.raw)
    if raw == bad.raw:
        return False
    left, right = (trace.ctx.in_unknowns(x) for x in raw)
    return trace.holds([replace(bad, left=left, right=right, raw=raw)], world)


def kept_world(trace: Trace, F: sympy.Expr, j: int, world: list[Values] | None) -> list[Values] | None:
    """The slip's world where the slip ``F`` (in place of (j)) gives one unknown from others the
    student has right so far (``v = 3eu - w``, sign lost, after ``w = u(1 + e)``): those others
    as the student found them (a right relation of theirs in place of another equation), not as
    the equations with the slip give them; ``world`` where that is not so."""
    current = trace.world or trace.truth
    others = F.free_symbols & set(trace.U)
    if not others or world is None:
        return world

    def same(a: list[Values], kept: set) -> bool:
        return all(
            abs(complex((x[u] - y[u]).evalf())) <= 1e-9 * max(1.0, abs(complex(y[u].evalf())))
            for x, y in zip(a, current, strict=True)
            for u in kept
        )

    for h in [*reversed(trace.worked[-12:]), *reversed(trace.held[-12:])]:  # the student's own, latest first
        kept = h.difference.free_symbols & set(trace.U)
        if len(kept) != 1 or not others - kept or h.difference.has(sympy.Float) or same(world, kept):
            continue  # a value found (w = u(1 + e)), not rounded decimals, that the slip's world changes
        try:
            if sympy.degree(sympy.expand(h.difference), next(iter(kept))) != 1:
                continue
        except sympy.PolynomialError:
            continue  # |v_B2| written: not a polynomial in it, no value found by it
        nm = trace.ctx.model.nm
        found_first = not kept & {nm.A2n, nm.B2n, nm.A2t, nm.B2t}  # e or a mass: from the problem's condition
        for k in sorted(trace.equations, key=lambda k: (k <= 4, k)) if found_first else trace.equations:
            if k == j:
                continue
            equations = {**trace.equations, k: h.difference}
            trial = solve_world(equations, trace.U, trace.pts, current)
            if trial is not None and same(trial, kept):
                trace.equations = equations
                return trial
    return world


def world_mistake(trace: Trace, bad: Pair) -> tuple[Mistake, int] | None:
    """A further slip that is a common mistake made on the student's own equations so far (``e = (0.4475
    - 0.3)/0.5`` after v_A2 = 0.4475: restitution reversed), the first whose equations, in place of those
    the student has not written, make ``bad`` hold; with the first equation it changes."""
    if not bad.difference.free_symbols & set(trace.U):
        return None
    model, own = trace.ctx.model, {j for _n, j in trace.replaced}
    if trace.world is None:  # a first slip: a form no outcome solves (e = approach/separation), not a step
        return None if workedslips.works_on_previous(trace, bad) else _in_forms(trace, bad, own)
    for m in REGISTRY.values():
        v = m.build(model.under(trace.variant))
        both = merge(trace.variant, v) if v is not None else None
        if both is None:
            continue
        at = _made(trace, m, model.numbered(both), own, bad)
        if at is not None:
            return m, at
    return _in_forms(trace, bad, own)


def _made(trace: Trace, m: Mistake, eqs: dict, own: set[int], bad: Pair) -> int | None:
    """The first equation ``m`` changes (to ``eqs``'s) where the student's equations so far with
    that change make ``bad`` hold (None where none is changed or it does not hold)."""
    changed = {j: eqs[j] for j in m.enters if j in eqs and j in trace.equations and j not in own}
    if not changed or all(trace.equations[j] == F for j, F in changed.items()):
        return None
    world = solve_world({**trace.equations, **changed}, trace.U, trace.pts, trace.world or trace.truth)
    return min(changed) if world is not None and trace.holds([bad], world) else None


def _in_forms(trace: Trace, bad: Pair, own: set[int]) -> tuple[Mistake, int] | None:
    """A further slip that is one of a mistake's other forms (:data:`~.mistakes.registry.FORMS`:
    e as approach over separation) made on the student's equations so far, the values before the
    impact as the student has them (a given copied wrongly kept) or as they are."""
    from derive.checking.mistakes.registry import FORMS

    model = trace.ctx.model
    for name, form in FORMS.items():
        m = REGISTRY.get(name)
        for under in (model.under(trace.variant), model) if m is not None else ():
            for eqs in form(under, trace.variant):
                at = _made(trace, m, eqs, own, bad)
                if at is not None:
                    return m, at
    return None


def pairs_of(trace: Trace, line: Read) -> list[Pair]:
    """The line's pairs (:meth:`~.lines.Trace.pairs`); a law in names alone, no decimal in it
    (``m_A (v_A)_1 + m_B (v_B)_1 = m_A (v_A)_2 + m_B (v_B)_2``) after a given copied wrongly,
    that holds with the given as the problem has it, is the law, true: it writes no number
    copied, so it is correct, not carried (the lines that put the number in are carried)."""
    pairs = misread.transposed(trace, line, trace.pairs(line))  # 0.0954 for 0.0945: at its own figures
    names = set().union(*(x.free_symbols for x in line.exprs or ()))
    if not trace.copied or not names & set(trace.copied) or any(re.search(r"\d\s*\.\s*\d", x) for x in line.sides):
        return pairs
    kept = trace.copied
    trace.copied = {}
    try:
        law = trace.pairs(line)
    finally:
        trace.copied = kept
    return law if trace.holds(law, trace.truth) else pairs


def combined(trace: Trace, bad: Pair, diags: tuple) -> Found:
    """``2v_A = u + eu`` from ``(1) − (2)`` after ``u = v_A + v_B`` and ``v_B − v_A = eu``, both
    right: a line solved for one unknown, which a common mistake reproduces (restitution reversed)
    only in a world the student's own right relations deny, and which holds with one term's sign
    changed, is a slip in combining them (``algebra``), not that mistake; None otherwise."""
    unknowns = set(trace.U)
    if not diags or not trace.held or len(bad.difference.free_symbols & unknowns) != 1:
        return None
    names = {d.mistake for d in diags}
    outcomes = [o for o in trace.ctx.singles() if o.mistake is not None and o.mistake.name in names]
    if not outcomes:
        return None
    changed: list[int] = []
    for o in outcomes:
        changed = [j for j in o.mistake.enters if j in o.equations and j in trace.equations]
        world = solve_world(
            {**trace.equations, **{j: o.equations[j] for j in changed}}, trace.U, trace.pts, trace.truth
        )
        if not changed or world is None or all(trace.holds([p], world) for p in trace.held):
            return None
    current = trace.world if trace.world is not None else trace.truth
    expanded = replace(bad, raw=tuple(sympy.expand(x) for x in bad.raw)) if bad.raw is not None else bad
    for pair in (bad, expanded):  # 2v_1 = u cos 30°(1 + e): its bracket's terms, for (1 − e)
        flip, _right = slipnames.sign_flipped(trace.ctx, pair, trace.U, lambda p: trace.holds([p], current))
        if flip == "algebra":
            return changed[0], slipnames.FLIPPED[flip], flip  # in place of the equation the mistake seemed to change
    return None


#: The words of a body's speed put in the impact rule for its component along the line of centres.
SPEEDS = (
    ": it has a body's speed in the impact rule, where its component along the line of centres"
    " belongs (restitution relates the normal components only)."
)


def speed_for_component(trace: Trace, line: Read, world: list[Values]) -> bool:
    """Whether ``line`` (``e = (3.536 - 1)/(6 - 0)``) holds once a decimal that is a body's
    speed, before or after the impact, in an oblique impact (√(2.5² + 2.5²) = 3.536) is put
    back as that body's n component (2.5): the speed used for the component, ``e_speeds``."""
    nm, exprs = trace.ctx.model.nm, line.exprs or ()
    if len(exprs) < 2:
        return False

    def value(x: sympy.Expr | None) -> float | None:
        v = number_of(trace.ctx.in_unknowns(x).xreplace(trace.pts[0]).xreplace(world[0])) if x is not None else None
        return None if v is None or abs(v.imag) > 1e-9 else v.real

    for n, t in ((nm.A1n, nm.A1t), (nm.B1n, nm.B1t), (nm.A2n, nm.A2t), (nm.B2n, nm.B2t)):
        vn, vt = value(n), value(t)
        if vn is None or vt is None or abs(vt) < 1e-9:
            continue
        speed = (vn**2 + vt**2) ** 0.5
        for d in decimals(line.sides):
            if abs(float(d) - speed) > 0.6 * 10.0 ** -len(d.split(".")[1]):
                continue
            for k, x in itertools.product(range(1, len(exprs)), {vn, abs(vn)}):  # "+ 4.75" for "- (-3.25)"
                text = re.sub(rf"(?<![\d.]){re.escape(d)}(?![\d])", f"{x:.6g}", line.sides[k])
                if text == line.sides[k] or exprs[k].free_symbols:
                    continue
                try:
                    put = read_side(rewrite(text, set()), Open({}), False, False)
                except ParseError:
                    continue
                raw = (exprs[0], put)
                left, right = (trace.ctx.in_unknowns(x) for x in raw)
                if not put.free_symbols and trace.holds(
                    [Pair(f"{line.sides[0]} = {text}", left, right, 1e-3, raw)], world
                ):
                    return True
    return False


def plain_named(trace: Trace, line: Read, bad: Pair, world: list[Values]) -> tuple[str, str] | None:
    """The words and name of a slip in a line of numbers: a body's speed for its component
    (``e_speeds``), a given copied wrongly (``copied_wrong``); None for neither."""
    if speed_for_component(trace, line, world):
        return SPEEDS, "e_speeds"
    if given_negated(trace, bad):  # p after = 0.8(1.2) + 0.4v, A moving back: a velocity's sign lost
        return slipnames.FLIPPED["b_sign"], "b_sign"
    given = given_copied(trace, bad) or misread.in_working(trace, line, bad) or misread.total_copied(trace, line, bad)
    return (given, "copied_wrong") if given else None
