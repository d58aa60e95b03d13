"""A typed derivation of a chain problem, judged line by line against the chain's values.

A chain has no single set of equations (1)-(4) to solve again, so its lines are judged as
numbers: every given and every stage's result is known by its name (``u_A``, ``w_B``,
``e_floor``), and a name the student introduces with a value (``v1 = sqrt(2 x 9.8 x 2) =
6.26``) is known for the lines after it, both as it truly is and as the student worked it.
A line that holds is correct; the first that does not is the slip; a later line that holds
only with the student's own earlier numbers is carried.
"""

from __future__ import annotations

import re
from dataclasses import replace
from functools import partial

import sympy

from derive.checking import chainfit, chainletters, chainnames, chainsolve, mistakes, principles, substitutions, words
from derive.checking import ownquantities as own
from derive.checking.bodylists import written_out
from derive.checking.chaincarried import from_wrong
from derive.checking.chaindata import given_said, shadowed
from derive.checking.chainhabits import habit_names
from derive.checking.chainreadings import as_written
from derive.checking.chainstages import in_stages
from derive.checking.chainworld import own_world
from derive.checking.context import Context
from derive.checking.copiedagain import copied_again
from derive.checking.earlyworking import worked_early
from derive.checking.figures import literal_tolerance
from derive.checking.impulseword import impulse_said, impulse_sign
from derive.checking.naming import PREFIX, Open, declaration, read_side, rewrite
from derive.checking.naming import placeholders as _own  # the student's names not yet placed
from derive.checking.numeric import number_of
from derive.checking.report import Item, merged
from derive.checking.slipnames import COPIED, copied_into_working
from derive.checking.stageslips import (
    StageMistakes,
    named_arithmetic,
    numbers_written,
    own_root,
    own_sides,
    own_value,
    result_numbers,
    rule_named,
    stage_given,
    stage_mistakes,
    unnamed_number,
)
from derive.checking.stations import opening_letters
from derive.checking.termslips import halved, term_slip
from derive.checking.worlds import NUMBER_SIDE, number_at_figures
from derive.mathtext.notation import student
from derive.mathtext.reader import Relation, read_relations
from derive.problem.expr import ParseError


def chain_items(ctx: Context, text: str) -> tuple[list[Item], list[str]]:
    """One item per relation of a chain's derivation, and what was read of its names."""
    values = {sympy.Symbol(str(k)): v for k, v in ctx.solution.values.items()}
    names = chainletters.chain_names(ctx, values)  # e for e_floor; m beside a letter (ma + mb)
    read = shadowed(ctx, as_written(_read(ctx, text, names), values, _givens(ctx)), values)  # vA = 1: theirs
    said, read = chainnames.declared_in(ctx, text, read)  # "p = A after, q = B after": names, not relations
    said, read = habit_names(ctx, read, said, partial(_holds_with, ctx, values=values))  # vA, vB: the impact's
    said |= (
        impulse := impulse_said(ctx, read, said)
    )  # "impulse = m(v - u) = …": the impact's J, not a name it defines
    read, notes = opening_letters(ctx, read, names, said, partial(_holds_with, ctx, subs={}, values=values))
    mapping, later = _infer(ctx, read, values, said), own.solved_somewhere(read)  # later: F = 3010 a, then F = …
    mapping |= own.paired(read, mapping, values, partial(_holds_with, ctx, values=values), later | _introduced(read))

    def reread(side: str) -> sympy.Expr:  # a side as written, in the chain's names ("KE just after" too)
        return chainnames.side_or_words(side, names).xreplace(mapping)

    true_defs = own.Defs({p: chainnames.at(x, values) for p, x in said.items()})
    own_defs: dict[sympy.Symbol, sympy.Expr] = dict(true_defs)
    pending: list[tuple[int, tuple, list]] = []  # lines not read for a name a later line defines
    items: list[Item] = []
    slips: list[str] = []
    alias = chainnames.aliases(said, values, _givens(ctx))  # x, A's velocity after, is the chain's u_A
    stages = chainnames.with_declared(stage_mistakes(ctx), alias)
    written: list[list[sympy.Expr]] = []  # the relations read so far, for the student's own values
    previous: list[sympy.Expr] = []  # the relation just before, where it held
    wrong: set[str] = set()  # the numbers the student got wrong: a line worked from them is carried
    for r, sides, exprs in substitutions.judged(read, values):  # not "(w = 7)", a general result's letter's value
        exprs = [x.xreplace(mapping) for x in exprs]
        left = exprs[0]
        name = own.defined(left, true_defs) if len(exprs) > 1 else None  # s = …, ω² = k/m: the student's own
        if name and not own.provisional(name, exprs, true_defs, later):
            own.define(ctx, name, (sides, exprs), (true_defs, own_defs), values, _number)
            exprs, sides = own.defined_rest(name[0], (exprs, sides), (true_defs, slips), _number, own.from_givens(ctx))
        sides, exprs = _known_sides(sides, exprs, set(true_defs))
        if stage_given(ctx, exprs) or given_said(ctx, (r, read), exprs, (true_defs, values)):  # e; a = -9.8, up +
            items.append(
                Item("line", str(r.line), r.written, "correct", "", "A given of a stage.", "the chain's values")
            )
            continue
        exprs = _of_the_stage(ctx, sides, exprs, values)
        chainsolve.said_in_own(said, true_defs, own_defs, values)  # KE lost from the student's wrong v_1
        item = _verdict(ctx, r, sides, exprs, values, true_defs, own_defs, slips)
        done, defs = (items, written, slips), (values, true_defs, own_defs, stages)
        item = own_world(ctx, item, (sides, exprs), done, defs, (partial(_holds, ctx, sides), reread))
        pending += [(len(items), sides, exprs)] if item.status == "not read" else []
        if item.status == "wrong" and len(slips) > 1 and numbers_written(sides, set()) & wrong:  # 8.92 = 39.44 h
            holds = partial(_holds, ctx, sides, subs=[true_defs, values])
            item = own.carried_on(item, sides, exprs, (true_defs, own_defs, values), holds, (slips, _carried, reread))
        if item.status == "correct" and from_wrong(ctx, (sides, exprs), (wrong, r.line, read, mapping), done, defs):
            item = replace(item, status="carried", message=_carried(slips))  # worked from a wrong number; V = 1.50
        if item.status == "carried":  # 0 = v2^2 - 2(9.8)(30): the given copied wrongly again
            at, names_in = partial(_holds, ctx, subs=[true_defs, values]), partial(_names_in, read)
            item = copied_again(ctx, item, sides, items, reread, at, names_in)
        if item.status == "wrong" and slips == [str(r.line)]:  # the first slip: a given copied wrongly?
            holds = partial(_holds, ctx, subs=[true_defs, values])
            item = chainnames.named_copied(ctx, item, sides, reread, holds, own_defs, said)
        if item.status == "wrong" and not item.again and not item.slip:
            defs = (values, true_defs, own_defs, stages)
            item = _slip_named(ctx, item, (sides, exprs, previous), defs, reread)
        if item.status in ("wrong", "carried"):
            wrong |= result_numbers(sides, ctx.data)  # y = 5 m/s: a number the student got wrong
        written.append(exprs)
        if item.status == "wrong" and said:  # the names declared in words, as the student's relations give them
            chainnames.own_solved(ctx, written, said, own_defs, (alias, values))
        previous = exprs if item.status == "correct" else []
        items.append(named_arithmetic(item, exprs))  # 441 + 784 = 1125: arithmetic; 6 = 4.0 V: algebra
        if item.status == "correct" and slips and len(exprs) == 2:
            own_root(exprs, values, own_defs, _givens(ctx))
        if item.status == "correct" and slips:  # the stage's names as the student's relations make them
            chainsolve.resolved(ctx, exprs, written[:-1], own_defs, values, (_givens(ctx), alias))
        if slips and item.status != "not read":  # a later stage's values, from the student's wrong ones
            chainsolve.downstream(ctx, own_defs, values, _givens(ctx), written)
        if item.status == "carried":  # 9(1 + e)²/4 = 4: the student's own e, for the lines after
            _keep_root(ctx, exprs, values, true_defs, own_defs)
        own_value(own_defs, left, (sides, exprs), item.status, _number)  # the student's value, carried on
    own.judged_later(items, pending, true_defs, partial(_holds, ctx, subs=[true_defs, values]), (wrong, slips))
    said = [f"{p.name[1:].replace('_', ' ')} is {_name(v, values)}" for p, v in (mapping | impulse).items()]
    notes += ["Inferred from the values: " + ", ".join(said) + "."] if said else []
    return merged(in_stages(ctx, items, (mapping, true_defs, values), read)), notes


def _name(v: sympy.Expr, values: dict) -> str:
    return f"-{(-v).name}" if isinstance(-v, sympy.Symbol) else str(v)


def _slip_named(ctx: Context, item: Item, line: tuple, defs: tuple, reread) -> Item:
    """A wrong line not yet named, named by what a teacher sees in it: the impulse's rebound with
    its sign lost, a line before halved but for one term, a stage's mistake, a rule written wrongly, a given copied into the working, a value worked wrongly from the line before, or its
    one wrong term (a sign lost, a ½ dropped, e's ratio upside down). ``line``: its sides, its
    expressions and the relation before it; ``defs``: the chain's values, the student's names'
    true and own values, the stages' mistakes."""
    sides, exprs, previous = line
    values, true_defs, own_defs, stages = defs
    at = partial(_holds, ctx, sides, subs=[true_defs, values])
    item = impulse_sign(ctx, item, sides, exprs, at)  # 0.2(35 - 28): the rebound's sign lost
    if not item.slip:
        item = halved(item, exprs, previous) or _named(ctx, item, sides, exprs, values, true_defs, own_defs, stages)
    item = rule_named(ctx, item, (sides, exprs), reread, at)
    if not item.slip and copied_into_working(ctx, sides, exprs, at):
        item = replace(item, slip="copied_wrong", message=f"{item.message.split(': ')[0]}: {COPIED}")
    if not item.slip and (_solved_wrongly(exprs, previous, sides) or chainsolve.number_worked(exprs, previous)):
        item = replace(item, slip="arithmetic", message=f"{item.message[:-1]}{ARITHMETIC}")
    flip, why = ("", "") if item.slip else term_slip(exprs, at, item.message, sides)
    if flip:
        item = replace(item, slip=flip, message=f"{item.message.split(': ')[0]}{why}")
    return item


def _names_in(read: list, line: str) -> set[sympy.Symbol]:
    """The names (the chain's and the student's own) in the relations of line ``line``."""
    return {p for r, _sides, exprs in read if str(r.line) == line for x in exprs for p in x.free_symbols}


#: The slip named where a value is worked wrongly from the relation just before it.
ARITHMETIC = ": it does not follow from the line before (an arithmetic slip: a number worked wrongly)."


def _carried(slips: list[str]) -> str:
    return f"Right given the slip in line {slips[0]}: a carried error, not a new mistake."


def _solved_wrongly(exprs: list[sympy.Expr], previous: list[sympy.Expr], sides: tuple[str, ...]) -> bool:
    """``v1 = 6.16`` after ``v1^2 = 39.2`` (which held): a name's value worked wrongly from the
    relation just before it, the one name it is in (an arithmetic slip)."""
    if len(exprs) != 2 or not exprs[0].is_Symbol or not _number(sides[-1]) or not previous:
        return False
    names = set().union(*(x.free_symbols for x in previous))
    return names == {exprs[0]}


def _read(ctx: Context, text: str, names: Open) -> list[tuple[Relation, tuple[str, ...], list[sympy.Expr]]]:
    """Each relation read: its sides and their expressions (a first side in words, ``velocity
    after = -5.24``, is a name of the student's own; ``After: B w1, C w2 = 4``: w2 = 4)."""
    out, lines = [], text.split("\n")
    for r in read_relations(written_out(ctx, text), None, True):  # a chain is on one line: 4.97 j along it
        r = replace(r, written=lines[r.line - 1].strip()) if r.written not in lines[r.line - 1] else r
        if declaration(r.written):
            continue
        exprs = []
        try:
            for i, s in enumerate(r.sides):
                try:
                    exprs.append(read_side(rewrite(s, set(names.known)), names, i == 0, i == len(r.sides) - 1))
                except ParseError:
                    words = re.fullmatch(r"\s*([A-Za-z]{2,}(?:\s+[A-Za-z]{2,}){0,5})\s*", s)
                    if 0 < i < len(r.sides) - 1 and not words:
                        exprs.append(None)  # "v^2 = u^2 + 2as = 21^2 + …": a middle side not read is left out
                        continue
                    if i == 0 and not words and len(r.sides) >= 3 and re.fullmatch(r"[A-Za-z\s'’,-]+", s):
                        exprs.append(None)  # "energy lost in the bounce = ½(0.2)(…) = 2.87": words, then working
                        continue
                    if not words or i == len(r.sides) - 1:
                        raise
                    exprs.append(sympy.Symbol(PREFIX + "_".join(words.group(1).split())))
        except (ParseError, ValueError, TypeError):
            continue
        sides = tuple(sd for sd, x in zip(r.sides, exprs, strict=True) if x is not None)
        if len(sides) >= 2:
            out.append((r, sides, [x for x in exprs if x is not None]))
    return out


def _infer(ctx: Context, read: list, values: dict, said: dict) -> dict[sympy.Symbol, sympy.Expr]:
    """A name of the student's own (``h``, ``velocity after``) stands for the chain's value, of
    either sign, that makes the most relations hold where it is the only unknown; a name no
    value fits is what the first such relation solves it to be (``p + q = 7``: p = 7 - q).
    A name declared in words (``said``) is known, not inferred."""
    found: dict[sympy.Symbol, sympy.Expr] = dict(said)
    given = _givens(ctx)  # where a given and a result have one value (h_0 = h_2), the result first
    quantities = {s: v for s, v in values.items() if s not in chainnames.yes_no(ctx)}  # "again" = 1: no velocity
    cands = [
        c for s, v in sorted(quantities.items(), key=lambda sv: sv[0] in given) if v.is_number and v for c in (s, -s)
    ]
    defined = _introduced(read) - _answers(read, values, given)
    for _r, _sides, exprs in read + read:  # twice: a name found later leaves one unknown (p + q = 7)
        for p in sorted(set().union(*(_own(x) for x in exprs)) - set(found) - defined, key=str):
            alone = [a for a in (_only(sd, ex, p, found) for _r2, sd, ex in read) if a is not None]
            score = {c: sum(bool(_holds_with(ctx, sd, ex, {**found, p: c}, values)) for sd, ex in alone) for c in cands}
            kinds = chainfit.of_kind(p, cands, ctx, score)  # (v_B)_3: a speed where one fits
            best = chainfit.nearest(kinds, score, alone, (found, p), (values, ctx.unit_subs()))
            letter = [v for v in values if chainfit.of_the_letter(v, p)]
            mine = chainfit.of_letter(p, kinds, letter)  # "h": h_0 or h_2, never e = 0.7 that 0.702 rounds to
            near = chainfit.nearest(mine, score, alone, (found, p), (values, ctx.unit_subs())) if mine else None
            if near is not None and score[near]:
                found[p] = near
            elif mine and (result := chainfit.one_result(letter, given)) is not None:
                found[p] = result
            elif best is not None and score[best]:
                found[p] = best
            elif len(letter) == 1 and "_" not in p.name and letter[0].name != p.name[1:]:
                found[p] = letter[0]  # "d" where the chain has one d (d_B): the result the student works out
            elif len(exprs) == 2 and set().union(*(_own(x.xreplace(found)) for x in exprs)) == {p} and p not in exprs:
                roots = _solved(exprs[0].xreplace(found) - exprs[1].xreplace(found), p)
                if roots is not None:
                    found[p] = roots
    return {p: x for p, x in found.items() if p not in said}


def _givens(ctx: Context) -> set[sympy.Symbol]:
    return {sympy.Symbol(g.name) for g in getattr(ctx.problem, "givens", ())}


def _introduced(read: list) -> set[sympy.Symbol]:
    """The names of the student's own first met alone on the left of a relation whose next side
    is in the chain's names (``δ_0 = m_pan g/k = …``): defined there, not inferred."""
    seen: set[sympy.Symbol] = set()
    out: set[sympy.Symbol] = set()
    for _r, _sides, exprs in read:
        left = exprs[0]
        if left.is_Symbol and left in _own(left) and left not in seen and len(exprs) > 2 and not _own(exprs[1]):
            out.add(left)
        seen |= set().union(*(_own(x) for x in exprs))
    return out


def _answers(read: list, values: dict, given: set) -> set[sympy.Symbol]:
    """The student's own names worked out once and used nowhere else, each of the letter of one
    of the chain's results (``h = 1.49^2/9.81 = 0.227`` where the chain finds h_2): the answer,
    judged as that result, not a quantity of the student's own."""
    uses = [p for _r, _sides, exprs in read for p in set().union(*(_own(x) for x in exprs))]
    one = {p for p in uses if uses.count(p) == 1 and "_" not in p.name}
    return {p for p in one if len([v for v in values if chainfit.of_the_letter(v, p)]) == 1} - {
        p for p in one for v in given if chainfit.of_the_letter(v, p)
    }


def _only(sides, exprs: list, p: sympy.Symbol, found: dict) -> tuple | None:
    """The sides of a relation where ``p`` is the only unknown (two at least, one with p)."""
    keep = [k for k, x in enumerate(exprs) if _own(x.xreplace(found)) <= {p}]
    if len(keep) < 2 or not any(p in _own(exprs[k].xreplace(found)) for k in keep):
        return None
    return tuple(sides[k] for k in keep), [exprs[k] for k in keep]


def _holds_with(ctx: Context, sides, exprs, subs: dict, values: dict) -> bool | None:
    return _holds(ctx, *_known_sides(sides, [x.xreplace(subs) for x in exprs], set()), [{}, values])


def _solved(difference: sympy.Expr, p: sympy.Symbol) -> sympy.Expr | None:
    """The one root of a relation linear in ``p`` (None where it is not)."""
    a, b = difference.diff(p), difference.subs(p, 0)
    return None if a.has(p) or a == 0 else -b / a


def _known_sides(sides, exprs: list[sympy.Expr], defined: set) -> tuple[tuple[str, ...], list[sympy.Expr]]:
    """The sides without a name of the student's own not yet known (``impulse = m(v - u) =
    0.3(-5.24 - 6.26) = -3.45``: ``m(v - u)`` is left out), where two sides remain."""
    keep = [k for k, x in enumerate(exprs) if not (_own(x) - defined)]
    if len(keep) < 2 or len(keep) == len(exprs):
        return tuple(sides), exprs
    return tuple(sides[k] for k in keep), [exprs[k] for k in keep]


def _of_the_stage(ctx: Context, sides, exprs: list[sympy.Expr], values: dict) -> list[sympy.Expr]:
    """``e = 0.7`` (``e = 0.5/2.9 = 0.172``) where the chain's e is 0.8 and its e_wall 0.7: the
    student's e is the stage's (a given's name with a stage's suffix)."""
    left = exprs[0]
    if len(exprs) < 2 or left not in values or _holds(ctx, sides, exprs, [{}, values]) is not False:
        return exprs
    for sym in values:
        if sym.name.startswith(left.name + "_") and _holds(ctx, sides, [sym, *exprs[1:]], [{}, values]):
            return [sym, *exprs[1:]]
    return exprs


def _number(text: str) -> bool:
    try:
        sympy.Rational(text.strip())
    except (TypeError, ValueError):
        return False
    return True


def _holds(ctx: Context, sides, exprs, subs: list[dict]) -> bool | None:
    """Whether each ``=`` holds, within the decimals written; where the line ends in a number as written
    (``d = 1175/4 = 294``), each side is compared with it, at its figures (rounded working between)."""
    ends = len(exprs) >= 3 and NUMBER_SIDE.match(student(sides[-1].strip())) is not None
    for i in range(len(exprs) - 1):
        k = len(exprs) - 1 if ends else i + 1
        tol = max(literal_tolerance(f"{sides[i]} = {sides[k]}", ctx.data), 1e-9)
        tol += own.slack_of(subs[0], exprs[i].free_symbols | exprs[k].free_symbols)  # s found from rounded numbers
        terms = [[_value(ctx, t, subs) for t in sympy.Add.make_args(x)] for x in (exprs[i], exprs[k])]
        a, b = (_value(ctx, x, subs) for x in (exprs[i], exprs[k]))
        if a is None or b is None:
            return None
        largest = max((abs(t) for side in terms for t in side if t is not None), default=0.0)
        far = abs(a - b) > 2 * tol * max(abs(a), abs(b), largest) + 1e-12  # 0 = 5.26^2 - 2(9.8)h: at 27.7
        if far and not (number_at_figures(sides[k], a) or number_at_figures(sides[i], b)):
            return False
    return not (ends and worked_early(sides, exprs, ctx, partial(_value, ctx, subs=subs)))  # 6.3 worked on


def _value(ctx: Context, x: sympy.Expr, subs: list[dict]) -> complex | None:
    return number_of(x.xreplace(subs[0]).xreplace(subs[1]).xreplace(ctx.unit_subs()))


def _verdict(ctx, r: Relation, sides, exprs, values, true_defs, own_defs, slips: list[str]) -> Item:
    def item(status: str, message: str) -> Item:
        return Item("line", str(r.line), r.written, status, "", message, "the chain's values")

    if unnamed_number(ctx, exprs, sides):  # w = 3.1: a name no value fits, set to a number
        said = f"Not read: {words.student_text(r.sides[0].strip())} is no quantity I can name."
        return item("carried", _carried(slips)) if slips else item("not read", said)  # after a slip: its own
    if len(exprs) < 2 or principles.energy_balance(sides):  # T_1 + V_1 = T_2 + V_2: the stage's principle
        return item("correct", principles.energy_balance(sides) or "Defines a name for the lines after it.")
    truly = _holds(ctx, sides, exprs, [true_defs, values])
    if truly is None:
        unknown = sorted({x.name[len(PREFIX) :] for e in exprs for x in _own(e) if x not in true_defs})
        if not unknown:
            return item("not read", "Not read: a name in it is not the chain's.")
        return item("not read", f"Not read: {words.not_read('unknown name ' + ', '.join(unknown), sides, r.written)}.")
    if truly:
        return item("correct", "True for this problem.")
    carried = _carried(slips) if slips else ""
    if slips and _holds(ctx, sides, exprs[:1] + [x.xreplace(own_defs) for x in exprs[1:]], [own_defs, values]):
        return item("carried", carried)
    if slips and _holds(ctx, sides, own_sides(exprs, own_defs), [true_defs, values]):  # 9(1 + e)²/4 = 4: u_C = 4
        return item("carried", carried)
    # ``h_2 = V^2/(2g) = 22.9``: the formula right, and the rest worked from the student's V
    formula = slips and exprs[0].is_Symbol and len(exprs) > 2
    if formula and _holds(ctx, sides[:2], exprs[:2], [true_defs, values]):
        own = [x.xreplace(own_defs) for x in exprs[1:]]
        if _holds(ctx, sides[1:], own, [own_defs, values]):
            return item("carried", carried)
    if slips and exprs[0].is_Symbol and len(exprs) > 2 and _holds(ctx, sides[1:], exprs[1:], [true_defs, values]):
        truth = {**values, **{k: v.xreplace(values) for k, v in true_defs.items()}}  # a name of their own (x) too
        fixed = chainnames.put_right(sides[1], own_defs, truth)  # ``v_2 = 0.7(7.53) = 5.27``, 7.53 the student's v_1
        if fixed is not None and _holds(ctx, sides[:2], [exprs[0], fixed], [true_defs, values]):
            return item("carried", carried)
    first = not slips
    slips.append(str(r.line))
    lead = "The first line that is false for this problem" if first else "False: a further slip"
    return item("wrong", f"{lead}: {_why(ctx, sides, exprs, [true_defs, values])}")


def _why(ctx: Context, sides, exprs: list[sympy.Expr], subs: list[dict]) -> str:
    """Why a chain's line is false, in the student's names: the true value of the name on its
    left (``V is 1.493, not 1.52``), or of a side of numbers (:func:`.words.unequal`)."""
    for i in range(len(exprs) - 1):
        if _holds(ctx, sides[i : i + 2], exprs[i : i + 2], subs):
            continue
        left, right = (_value(ctx, x, subs) for x in exprs[i : i + 2])
        if left is None or right is None:
            break
        if exprs[i].free_symbols and not words.numbers_only(sides[i]) and not exprs[i].is_Symbol:
            break  # a formula in names: its value is none the student wrote
        return words.unequal(words.student_text(sides[i].strip()), left.real, sides[i + 1], right.real)
    return "its two sides are not equal (an arithmetic or algebra slip)."


def _named(ctx, item: Item, sides, exprs, values, true_defs, own_defs, stages: StageMistakes) -> Item:
    """The first slip named by the stage's mistake whose values make it hold (and those values
    kept as the student's, for the lines after); else, a line in one result name unknown to
    the student is solved for it (``½(0.020)(300²) = ½(4.02) V²``) and its root kept."""
    for name, given in stages:
        if _holds(ctx, sides, exprs, [{**true_defs, **given}, values]):
            own_defs.update({k: v for k, v in given.items() if own_defs.get(k, true_defs.get(k)) == true_defs.get(k)})
            phrase = mistakes.phrase(name) or name
            lead = item.message.split(": ")[0]
            return replace(item, slip=name, message=f"{lead}: it {phrase}.")
    _keep_root(ctx, exprs, values, true_defs, own_defs)
    return item


def _keep_root(ctx, exprs, values, true_defs, own_defs) -> None:
    left = [x for x in exprs if x.free_symbols]
    names = set().union(*(x.free_symbols for x in exprs)) - set(true_defs) - set(own_defs)
    names = {s for s in names if s in values and ctx.solution.results.get(s.name) is not None}
    if len(names) == 1 and left and (exprs[0].free_symbols | exprs[-1].free_symbols) & names:
        (u,) = names  # the first side = the last: what the student carries on (v_1^2 = … = 36.36)
        root = _root(ctx, exprs[0] - exprs[-1], u, values)
        if root is not None:
            own_defs[u] = root


def _root(ctx: Context, F: sympy.Expr, u: sympy.Symbol, values) -> sympy.Expr | None:
    """The real root of ``F = 0`` in ``u`` (everything else known) nearest ``u``'s true value."""
    G = F.xreplace({k: v for k, v in values.items() if k != u}).xreplace(ctx.unit_subs())
    if G.free_symbols != {u}:
        return None
    try:
        roots = [r for r in sympy.solve(sympy.nsimplify(G, rational=True), u) if r.is_real]
    except (NotImplementedError, ValueError, TypeError):
        return None
    true = number_of(values[u])
    if not roots or true is None:
        return None
    return min(roots, key=lambda r: abs((number_of(r) or 0) - true.real))
