"""A typed derivation judged line by line: true, the first slip, carried, or a further slip.

Each relation is put to the problem's true values: true lines are correct. The first false line
is the slip; the mistake that explains it is named (the rules of :mod:`.equation`, or the number
judge for ``v_A2n = -1.11``), and the equations are solved again with that line in place of the
one it stands for. A later line false for the problem but true in that world is carried; one
false in both is a further slip, which joins the first in the world. A slip with no unknowns
(``79.2 - 59.5 = 29.7``) carries its wrong number instead.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

import sympy

from derive.checking import (
    axisdefined,
    carried,
    cofunctions,
    eliminated,
    energyshown,
    firstwritten,
    freshslips,
    labelled,
    letterslips,
    misread,
    mistakes,
    recopied,
    reworld,
    roundedworld,
    rounding,
    sidepairs,
    slipnames,
    slipquantity,
    slipworld,
    termslips,
    twobefore,
    words,
    workedslips,
)
from derive.checking.bodywords import as_typed, body_words
from derive.checking.carrying import Carrying, together
from derive.checking.context import DEG, Context
from derive.checking.equation import judge, relation
from derive.checking.inference import Read, read_lines
from derive.checking.number import line_answer
from derive.checking.numeric import decimals, listed
from derive.checking.relations import Point, Values, shown
from derive.checking.report import Diagnosis, Item, merged
from derive.checking.speedwords import looks_like_prose
from derive.checking.words import sides_unequal
from derive.checking.worlds import NUMBER_SIDE, Pair, closest, holds_at, in_letters, solve_world, three_figures
from derive.errors import InputError
from derive.mathtext.notation import student

TRUE = "substituting the correct values"
SOLVING = termslips.SOLVING  # algebra, arithmetic: a line worked wrongly from the one before
WORKING = termslips.WORKING  # a line whose rule holds but whose working does not come to what it claims
COPIED = slipnames.COPIED
KEPT = 0  # the slip is in a result worked from the velocities, not in the equations: none is replaced

MAX_LINES = 200  # the most relations of one derivation that are judged (the rest are not checked)
MAX_SEARCHED = 12  # the slips searched for a common mistake (the rest are named as further slips)
Line = Read


def derivation_items(ctx: Context, text: str) -> tuple[list[Item], list[str]]:
    """One item per relation of the derivation ``text``, and what was inferred of its names."""
    trace = Trace(ctx)
    trace.typed = text.splitlines()  # the lines as typed: a label's heading (KE, then "- before: …")
    said = body_words(text, ctx)
    lines, notes = read_lines(ctx, said, trace.pts[0], trace.truth[0], tuple(trace.base.equations.values()))
    lines = [as_typed(line, text, said) for line in lines]
    if not any(line.exprs is not None or line.error.startswith("unknown name") for line in lines):
        first = lines[0] if lines else None
        why = f" (line {first.number}: {words.not_read(first.error, first.sides, first.written)})" if first else ""
        why = why or " (no line with '=')"
        return [Item("line", "", "", "error", "", f"The derivation has no relation that could be read{why}.")], notes
    from derive.checking.budget import lines_judged  # angles as their words name them; in the time

    items = lines_judged(trace, lines[:MAX_LINES], text)
    if len(lines) > MAX_LINES:
        rest = f"{len(lines) - MAX_LINES} more relations, from line {lines[MAX_LINES].number}, were not checked"
        items.append(Item("line", str(lines[MAX_LINES].number), "", "error", "", f"{rest} (at most {MAX_LINES})."))
    return merged([i for i in firstwritten.moved_back(trace, lines, items) if i is not None]), notes


class Trace(Carrying):
    """The state of a derivation read so far: the student's equations and their solution."""

    def __init__(self, ctx: Context) -> None:
        base = mistakes.correct(ctx.solution)
        if base is None:
            raise InputError("this problem's equations cannot be set up for checking", field="--derivation")
        self.ctx, self.base, self.U = ctx, base, base.unknowns
        syms = set().union(*(x.free_symbols for x in (*base.post.values(), *base.equations.values()))) - set(self.U)
        self.pts: list[Point] = ctx.sampler().points(syms, 3) if syms else [{}]
        self.truth = [{u: base.post[u].xreplace(pt) for u in self.U} for pt in self.pts]
        self.equations = dict(base.equations)
        self.world: list[Values] | None = None
        self.slips: list[int] = []  # the line numbers of the slips
        self.named: dict[int, set[str]] = {}  # the mistakes named at each slip
        self.replaced: list[tuple[int, int]] = []  # (line number, the equation it took the place of)
        self.wrong_number: tuple[str, sympy.Expr] | None = None
        self.held: list[Pair] = []  # the right relations in the unknowns, so far
        self.early: int | None = None  # the line where rounding too early was named
        self.wrong_values: set[str] = set()  # numbers the student wrote on wrong or carried lines
        self.wrong_numbers: set[str] = set()  # and their integers too
        self.stated: dict[int, set[str]] = {}  # the numbers each wrong or carried line came to
        self.right_terms: dict[str, sympy.Expr] = {}  # values in letters worked wrongly: "3m" -> 2m
        self.wrong_amounts: list[float] = []  # the values wrong or carried lines of numbers came to
        self.wrong_terms: set[str] = set()  # values in the symbolic givens written wrong (5u for 3u)
        self.own: dict[sympy.Symbol, sympy.Expr] = {}  # the student's own values of names got wrong
        self.previous: slipnames.Previous = None  # the relation just before, if it held
        self.copied: dict[sympy.Symbol, sympy.Expr] = {}  # the givens copied wrongly, as copied
        self.partial = ""  # a mistake of the values before, so far made on one body's only
        self.variant = mistakes.Variant()  # the common mistake (or given copied) the world is made with

    # one line ----------------------------------------------------------------
    def item(self, line: Line) -> Item | None:
        """The verdict on ``line`` (None for prose that merely has an "=" in it)."""
        out = self._judge(line)
        if out is not None and line.exprs is not None and not line.defines:
            self._note(line, out.status)
        return out

    def _judge(self, line: Line) -> Item | None:
        if line.exprs is None:
            if looks_like_prose(" = ".join(line.sides)):
                return None  # prose with an "=" in it
            return self._item(
                line, "not read", f"Not read: {words.not_read(line.error, line.sides, line.written)}.", ""
            )
        if line.defines and (comp := axisdefined.of_trace(self, line)) is not None:  # v_perp = u cos θ: sin for cos
            return self._carried(line) if reworld.in_world(self, [comp]) else self._slip(line, [comp], None)
        if line.defines and line.exprs and len(line.exprs) >= 3:  # J = m(u + v) = 0.8(5.2) = 4.16: the working
            return self.item(replace(line, sides=line.sides[-len(line.exprs) + 1 :], exprs=line.exprs[1:], defines=""))
        if line.defines:
            return self._item(line, "correct", f"Defines {line.defines} for the lines after it.", "a definition")
        pairs = carried.pairs_of(self, line)
        answer = self._answer(line)
        if (answer is not None and answer.correct) or (answer is None and self.holds(pairs, self.truth)):
            total = labelled.of_trace(self, line)  # a total, a component or an energy labelled in words
            if total is not None:  # "p before = 150000 x 0.300 + 110000 x 0.120 = 58200": B's sign
                self._wrote_wrong(line)  # right with the student's own values (their v_B): carried
                own = reworld.in_world(self, [total])
                return self._carried(line) if own else self._slip(line, [total, *pairs], answer)
            if self.slips and (
                self._continues(line)
                or self._uses_wrong_numbers(line, pairs)
                or carried.slips_result(self, line, pairs)
            ):
                self._wrote_wrong(line)
                return self._carried(line)
            return self._correct(line, pairs, answer)
        if reworld.in_world(self, pairs):
            self._wrote_wrong(line)
            own = [p for p in pairs if not self.holds([p], self.truth) and p.difference.free_symbols & set(self.U)]
            if own:  # the student's own equation, at the figures written, takes its place in the world
                slipworld.refine(self, own[0])
            return self._carried(line)
        if self.wrong_number is not None and self._carries_number(line):
            self._replace(line, next(p for p in pairs if not self.holds([p], self.truth)), slip=False)
            return self._carried(line)
        self._wrote_wrong(line)
        if self._with_own_values(line) or self._with_terms_put_right(line) or self._with_slips_results(line, pairs):
            return carried.again_item(self, line, pairs) or self._carried(line)  # resolved afresh: again
        if workedslips.wrong_energy_worked(self, line, pairs):  # = 0.5(0.8)(4 - 1.2)²: the wrong formula's working
            return self._carried(line)
        self._own_value(line)
        return self._slip(line, pairs, answer)

    def pairs(self, line: Line) -> list[Pair]:
        """Each ``=`` of the line, in the unknowns."""
        raw = [misread.with_copied(self.ctx, x, self.copied) for x in line.exprs or ()]  # as the student has it
        sides, exprs = line.sides, [self.ctx.in_unknowns(x) for x in raw]
        out = []
        # a chain that ends in a number as written: each side is compared with that number
        ends = len(sides) >= 3 and NUMBER_SIDE.match(student(sides[-1].strip())) is not None
        worked = three_figures(sides, self.ctx.data) if ends else ""  # the student's own, at 3 figures
        for i in range(len(sides) - 1):
            k = len(sides) - 1 if ends else i + 1
            text = f"{sides[i]} = {sides[k]}"
            tol = max(self._tolerance(sides, raw, (i, k), worked), 1e-9)
            out.append(Pair(text, exprs[i], exprs[k], tol, (raw[i], raw[k]), worked=ends))
        return out[:-1] + sidepairs.adjacent(self, sides, exprs, raw) + out[-1:] if ends else out  # last stays last

    def holds(self, pairs: list[Pair], values: list[Values]) -> bool:
        """Whether every pair holds for ``values`` (at each sample point), within the
        precision of the decimals written."""
        return all(holds_at(p, values, self.pts, self.U) for p in pairs)

    # verdicts ----------------------------------------------------------------
    def _correct(self, line: Line, pairs: list[Pair], answer: Item | None) -> Item:
        self.held += [p for p in pairs if p.difference.free_symbols & set(self.U)]
        follows = self.world is None or self.holds(pairs, self.world) or in_letters(pairs)  # a law in names
        notes = () if follows else (f"It is right for the problem, but it does not follow from {self._slips_named()}.",)
        if not follows:
            workedslips.into_world(self, line, pairs)
        if answer is not None:
            return self._item(line, "correct", answer.message, answer.method, notes=notes, expected=answer.expected)
        arithmetic = not any(p.difference.free_symbols & set(self.U) for p in pairs) and not line.own_names
        said = "Its arithmetic is right." if arithmetic else "True for this problem."
        return self._item(line, "correct", said, TRUE, notes=notes)

    def _carried(self, line: Line) -> Item:
        if line.sides and line.number not in self.stated:  # its numbers wrong: tan⁻¹(1/11.09) = 5.15°, 60° − 5.15°
            self._wrote_wrong(line)
        replaced = [f"line {n} in place of ({j})" for n, j in self.replaced]
        how = f"solving again with {listed(replaced)}" if replaced else "with the wrong number carried"
        msg = f"Right given {self._slips_named()}: a carried error, not a new mistake."
        return self._item(line, "carried", msg, how)

    def _slip(self, line: Line, pairs: list[Pair], answer: Item | None) -> Item:
        world = self.world if self.world is not None else self.truth
        failing = [p for p in pairs if not self.holds([p], world)]
        plain = [p for p in failing if not p.difference.free_symbols & set(self.U)]  # arithmetic first,
        bad = next((p for p in plain if p.raw and any(x.has(DEG) for x in p.raw)), None)  # an angle's first
        bad = bad or next(iter(plain), None)
        bad = bad or next(iter(failing), None)
        bad = bad or next((p for p in pairs if not self.holds([p], self.truth)), pairs[0])
        bad, (diags, j, detail, name) = freshslips.explained(self, line, bad, pairs, answer)  # e_on_t, not again
        if detail in (WORKING, termslips.SIGN_PUT_IN) or workedslips.worked_on(self, pairs, name, world):  # carried on
            bad = next((p for p in carried.carried_on(self, line) if not self.holds([p], world)), bad)
        if not bad.difference.free_symbols & set(self.U) and len(pairs) > 1:
            ends = replace(pairs[0], right=pairs[-1].right, raw=None)  # what the student carries on: first = last
            if ends.difference.free_symbols & set(self.U):
                self._replace(line, ends, slip=False)
        made = {d.mistake for d in diags} | ({name} if name in (*cofunctions.NAMES, "ke_formula") else set())
        again = [n for n, names in self.named.items() if slipnames.same_mistake(names, made)]
        if again:
            lead = f"False: the same mistake as in line {again[0]}, made again"
        elif self.slips:
            lead = f"False, and not explained by {self._slips_named()}: a further slip"
        else:
            lead = "The first line that is false for this problem"
        self.named[line.number] = made
        self._replace(line, bad, j, slip=not again)  # the same mistake again is not a further slip
        if again and workedslips.works_from_slip(self, line, again[0]):  # 7.2 = -0.96 + 0.4v: its number
            del self.named[line.number]
            return self._carried(line)
        expected = answer.expected if answer is not None else ""
        used = letterslips.unknowns_written(bad, self.U)  # expected only in the unknowns the line writes
        if not expected and j and used and used <= self.base.equations[j].free_symbols:
            nm = self.ctx.model.nm
            expected = shown(self.base.equations[j], self.U, (nm.B2n, nm.A2n) if j == 4 else ())
        if line.own_names or name in SOLVING:  # not the student's names, or not the line they meant
            expected = ""
        arithmetic = not bad.difference.free_symbols & set(self.U)
        early = "rounded too early" in detail
        named = "rounded_too_early" if early else letterslips.plain(bad, self.ctx) if arithmetic else ""
        named = name or named
        slip = ",".join(d.mistake for d in diags) or named
        item = self._item(line, "wrong", f"{lead}{detail}", TRUE, diagnosis=diags, expected=expected)
        return replace(item, slip=slip, again=bool(again))

    def _explain(
        self, line: Line, bad: Pair, answer: Item | None
    ) -> tuple[tuple[Diagnosis, ...], int | None, str, str]:
        """The mistakes explaining the slip ``bad``, its equation, the verdict's words, the slip's name."""
        if len(set(self.slips)) >= MAX_SEARCHED:  # bounded: a long list of slips is not searched further
            return (), None, f" (not searched for a common mistake: more than {MAX_SEARCHED} slips).", ""
        if not bad.difference.free_symbols & set(self.U):
            diags = self._before(bad) or self._in_results(bad, line)
            if diags:
                said = " / ".join(mistakes.phrase(d.mistake) or d.title for d in diags)
                return diags, None, f": it {said}.", ""
            named = cofunctions.plain(
                self.ctx, bad, lambda p: self.holds([p], self.world or self.truth), line.exprs or ()
            )
            if named is not None:  # the kinetic energy's formula, an angle from the other axis
                if named[1] in cofunctions.NAMES:  # its number, written wrong, is carried on
                    self._number_wrong(bad)
                return (), None, *named
            given = carried.plain_named(self, line, bad, self.world or self.truth)
            if given is not None:  # a body's speed for its component, a given copied wrongly
                return (), None, *given
            text = " = ".join(line.sides)
            if slipnames.copied_wrong(self.ctx, bad, lambda p: self.holds([p], self.world or self.truth), text):
                return (), None, f": {COPIED}", "copied_wrong"
            self._number_wrong(bad)  # its number, carried on; 8cos30 = 8 x .87: a decimal rounded to 2 figures
            early = self._rounded_early(line, bad) if decimals(rounding.early_numbers(self.ctx, line.sides)) else ""
            return (), None, early or ": " + sides_unequal(bad.text, bad.left, bad.right, self.pts[0]), ""
        label = labelled.notes_number(line.tag, bad.difference, self.base.equations, self.U, self.pts[0])
        v = judge(self.ctx, relation(self.ctx, bad.text, label, bad.difference))
        if (named := termslips.renamed(self, line, bad, v)) is not None:  # I = m(v - u), v a speed; algebra
            return (), *named
        if not (answer is not None and answer.diagnosis) and (kf := letterslips.ke_formula(self, bad)):  # not a rule
            return (), KEPT, f": {slipnames.ENERGY_WORDS[kf]}", kf
        diags = answer.diagnosis if answer is not None and answer.diagnosis else v.mistakes
        before = set().union(*self.named.values()) if self.named else set()
        fresh = tuple(d for d in diags if d.mistake not in before)  # one made again with a new one: the new one
        diags = fresh if fresh and len(fresh) < len(diags) else diags
        pinned = workedslips.pinned(self, bad)  # its unknowns stated right already: no mistake's world
        diags = () if pinned else diags
        if v.rule in ("mistaken_equation", "solves_as_mistake", "no_match") and (
            copied := slipworld.number_copied(self, bad, v.rule)
        ):
            return (), KEPT, copied, "copied_wrong"  # in one unknown: a number for a given, not a mistake's value
        together = v.together if not (answer is not None and answer.diagnosis) else "together" in answer.message
        j = v.equation if v.equation is not None and not pinned else self._closest(bad.difference)
        if (combined := misread.misread(self, line, bad, diags) or carried.combined(self, bad, diags)) is not None:
            return ((), *combined)
        if not diags:  # a result's mistake keeps the velocities stated right: pinned or not
            diags = self._in_results(bad, line) or (() if pinned else self._in_mistake_world(bad) or self._before(bad))
            if diags:  # a result worked wrongly, or the mistake's world is now the student's
                said = " / ".join(mistakes.phrase(d.mistake) or d.title for d in diags)
                return diags, KEPT, f": it {said}.", ""
        if not diags:
            if (first := recopied.named_first(self, line, bad)) is not None:  # masses swapped, a number copied
                return (), *first
            early = self._rounded_early(line, bad)
            if early:
                return diags, j, early, ""
            further = carried.world_mistake(self, bad)  # a common mistake made on the student's equations
            if further is not None:
                return self.ctx.diagnosis(further[0]), further[1], f": it {further[0].phrase}.", ""
            world = self.world if self.world is not None else self.truth
            at, held = (self.U, self.pts[0]), lambda p: self.holds([p], world)
            name = slipnames.solving_slip(line.sides, self.pairs(line), self.previous, at, held)
            name = name or workedslips.number_worked_wrongly(self.pairs(line), self.previous, at, held, world[0])
            name = workedslips.sign_over_number(self, bad, name, held)
            if not name and carried.worked_wrongly(self, line, world):
                why, name = termslips.working_slip(self, line, world, WORKING)  # a sign put in: algebra
                if name == "arithmetic":
                    name = workedslips.sign_over_number(self, bad, name, held)  # a sign lost in letters
                    why = WORKING if name == "arithmetic" else slipnames.FLIPPED[name]
                return diags, None, why, name
            found = slipquantity.unnamed(self, line, bad, world, j, name)
            if found is not None:  # a given copied wrongly, a velocity's sign or a term's lost
                return (diags, *found)
            return diags, j, *eliminated.named(self, bad, name)  # or the step from two relations combined
        said = (" and " if together else " / ").join(mistakes.phrase(d.mistake) or d.title for d in diags)
        if j is None or answer is not None:
            return diags, j, f": it {said}.", ""
        return diags, j, f": it is {words.EQUATION_WORDS[j]}, but it {said}.", ""

    def _in_mistake_world(self, bad: Pair) -> tuple[Diagnosis, ...]:
        """The mistake whose equations, in place of those it changes (the student's slips kept),
        give velocities ``bad`` holds for (``20(3.05) + 5(-9.15) = 25 v_t``: the system's t
        momentum; ``e = (3.55 - 0.2)/(6 + 2)``: B's sign lost). They become the student's."""
        own = {j for _n, j in self.replaced}
        current = self.world if self.world is not None else self.truth
        for o in self.ctx.singles():
            if o.mistake is None:
                continue
            changed = [j for j in o.mistake.enters if j in o.equations and j in self.equations and j not in own]
            if not changed:
                continue
            equations = {**self.equations, **{j: o.equations[j] for j in changed}}
            world = solve_world(equations, self.U, self.pts, current)
            if world is not None and self.holds([bad], world) and not self.holds([bad], current):
                self.world, self.equations = world, equations
                return self.ctx.diagnosis(o.mistake)
        return ()

    def _in_results(self, bad: Pair, line: Line | None = None) -> tuple[Diagnosis, ...]:
        """The mistakes whose value of a result named in ``bad`` (T_1, θ_A2) makes it hold."""
        world = self.world if self.world is not None else self.truth
        found = slipnames.under_results(self.ctx, bad, lambda p: self.holds([p], world))
        found = energyshown.shown(self.ctx, bad, found, lambda p: self.holds([p], world), line.sides if line else bad)
        return tuple(d for m in found for d in self.ctx.diagnosis(m))

    def _with_slips_results(self, line: Line, pairs: list[Pair]) -> bool:
        """Whether the line, worked from numbers the student got wrong, holds with the results
        as the mistakes named so far give them (``T_lost = 2898 - 1843`` after T_1 and T_2
        worked with the weights as masses); a line that works the mistake afresh is "again"."""
        if not self.named or not set(re.findall(r"\d+\.?\d*", " ".join(line.sides[:-1]))) & self.wrong_numbers:
            return False
        world = self.world if self.world is not None else self.truth
        named = set().union(*self.named.values())
        return slipnames.carried_by_results(self.ctx, pairs, named, lambda q: self.holds([q], world))

    def _before(self, bad: Pair) -> tuple[Diagnosis, ...]:
        """The mistakes in the values before the impact (sin and cos swapped, B's sign, radians,
        masses) that make ``bad`` hold; the velocities they give become the slip's world."""
        found = slipnames.before_impact(self.ctx, bad, lambda p: self.holds([p], self.truth))
        if not found:
            return ()
        out = next((o for o in self.ctx.singles() if o.mistake is not None and o.mistake.name == found[0].name), None)
        variant = found[0].build(self.ctx.model)
        one = mistakes.of_one_body(self.ctx.model, variant, set().union(*(x.free_symbols for x in bad.raw or ())))
        widen = self.partial == found[0].name and self.world is not None and one != self.variant
        if one is not None and not widen:  # A's velocity resolved wrongly, B's not (yet): the mistake on A's only
            out, variant, self.partial = self.ctx.model.outcome(one, found[0]) or out, one, found[0].name
        if out is not None and widen:  # then B's resolved the same wrong way: the mistake on both
            self.world, self.partial = None, ""
        if out is not None and self.world is None:  # the student's equations are now the mistake's
            self.world = [{u: out.post[u].xreplace(pt) for u in self.U} for pt in self.pts]
            self.equations = {j: F for j, F in out.equations.items() if j in self.equations}
            self.variant = variant or self.variant
        elif not widen:  # a further slip in the values before, on the other body: both in the world
            twobefore.with_both(self, variant, found[0])
        return tuple(d for m in found for d in self.ctx.diagnosis(slipnames.as_named(self.ctx, m)))

    def _rounded_early(self, line: Line, bad: Pair) -> str:
        """ ": rounded too early …" (once) where the line is worked from numbers rounded early."""
        if self.early is not None:
            return ""
        words = rounding.rounded_early(self.ctx, line.sides, bad, self.pts[0], self.truth[0])
        if words:  # named once: the lines after, worked from the same numbers, are carried
            self.early = line.number
            roundedworld.adopt(self)  # in the world of the components before as the student rounded them
            self.wrong_values |= decimals(rounding.early_numbers(self.ctx, line.sides))
        return words

    # the world of the slips ------------------------------------------------
    def _replace(self, line: Line, bad: Pair, j: int | None = None, slip: bool = True) -> None:
        """Record ``bad`` of ``line`` (a slip, or a line that carries a wrong number on):
        in place of (j) when it has unknowns, and solve the equations again."""
        F = bad.difference
        if F.free_symbols & set(self.U) and j != KEPT:
            j = j if j is not None else self._closest(F)
            if j is not None:
                self.displaced, self.equations[j] = (j, self.equations[j]), F
                self.replaced.append((line.number, j))
                world = solve_world(self.equations, self.U, self.pts, self.world or self.truth)
                world = carried.kept_world(self, F, j, world)
                if world is not None:
                    self.world = world
        if slip:
            self.slips.append(line.number)

    def _closest(self, F: sympy.Expr) -> int | None:
        """The equation ``F`` most likely stands for (:func:`~.worlds.closest`); a value of one unknown
        (``v' = 0.0784``) never for "they move off together" (e = 0: one name for both velocities)."""
        j = closest(F, self.equations, self.U, self.pts[0], self.truth[0], [*self.held[-12:], *self.worked[-8:]])
        if j is None or len(F.free_symbols & set(self.U)) != 1 or not together(self.equations[j], self.U):
            return j
        for k in self.equations:  # the first other equation whose place it can take
            if k != j and solve_world({**self.equations, k: F}, self.U, self.pts[:1], self.truth[:1]) is not None:
                return k
        return j

    def _slips_named(self) -> str:
        numbers = [str(n) for n in dict.fromkeys(self.slips)]
        return f"the slip in line {numbers[0]}" if len(numbers) == 1 else f"the slips in lines {listed(numbers)}"

    # answers -----------------------------------------------------------------
    def _answer(self, line: Line) -> Item | None:
        """``v_A2n = -1.11``: judged as an answer is (:func:`~.number.line_answer`)."""
        return line_answer(self.ctx, line.sides, line.exprs, line.written)

    def _item(self, line: Line, status: str, message: str, method: str, **kw: Any) -> Item:
        """The line's item; ``kw``: its ``notes``, ``diagnosis`` and ``expected`` value, if any."""
        expected = kw.pop("expected", "")
        return Item("line", str(line.number), line.written, status, expected, message, method, **kw)
