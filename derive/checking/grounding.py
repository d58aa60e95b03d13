"""Names read as a teacher reads them: grounded on how they are first used, not on whatever
makes the most lines hold.

:mod:`.inference` picks what a student's names stand for by the relations that hold. A slip
early on followed by lines worked from it makes more lines hold under a reading the student
never meant (``x - y = eu`` for the restitution law, upside down: read with x and y "taken
positive the other way", the slip turns right and the momentum line before it turns wrong).
A teacher reads x and y as A's and B's velocities in the frame of the givens as written, and
leaves that reading only for one the student's first relation bears out. So: a reading with a
velocity's sign turned, or the two bodies swapped, is kept only where the first relation its
names stand in, on which the natural reading and it disagree, holds that way.
"""

from __future__ import annotations

import itertools
import re

import sympy

from derive.checking.context import Context
from derive.checking.frames import Pair, n_components, pairs
from derive.checking.naming import PREFIX
from derive.checking.numeric import number_of
from derive.checking.statementbodies import statement_bodies
from derive.problem.units import VELOCITY

Option = tuple[tuple[str, sympy.Expr], ...]  # for each name of a group: (what, its meaning)


def natural_of(combo: Option, options: list[Option], sign: int = 1) -> Option:
    """The natural reading of ``combo``: the same velocities, each positive in the frame
    (``sign``; not "taken the other way"), and two velocities at one time in the order A then B;
    ``combo`` itself where that reading is not among ``options``."""
    turned = [_signed(w, e, sign) for w, e in combo]
    if len(turned) == 2:
        first, second = (_name(e) for _w, e in turned)
        if "B" in first and first.replace("B", "A") == second:
            turned.reverse()  # x, y: A's then B's
    out = tuple(turned)
    return out if out in options else combo


def _signed(what: str, e: sympy.Expr, sign: int) -> tuple[str, sympy.Expr]:
    """A velocity candidate with the sign ``sign`` (others as they are)."""
    plain = (what[1:], -e) if what.startswith("-") and isinstance(-e, sympy.Symbol) else (what, e)
    if not plain[0].startswith("v_") or sign == 1:
        return plain
    return (f"-{plain[0]}", -plain[1])


def first_holds(
    found: list[list[Pair]],
    group: set[sympy.Symbol],
    ours: dict,
    theirs: dict,
    at: tuple[Context, dict, dict],
    turned: bool = False,
) -> tuple[int, bool]:
    """Which of two readings holds the first ``=`` the names of ``group`` stand in on which they
    disagree (+1 ``ours``, -1 ``theirs``, 0 where none differs), and whether that ``=`` is in
    the first relation the names stand in. Where the readings differ by every sign (``turned``),
    one name less another alone (``x - y = 0.8(3 + 2)``) tells them apart only as the impact
    rule's own slip (the difference the wrong way round) does: it is passed over."""
    ctx, pt, truth = at
    subs = [{k: ctx.in_unknowns(v).xreplace(pt).xreplace(truth) for k, v in m.items()} for m in (ours, theirs)]
    lines = 0
    for line in found:
        mine = [(tol, lr) for tol, lr, _moved in line if group & (lr[0].free_symbols | lr[1].free_symbols)]
        if turned and any(_relative_only(lr, group) for _tol, lr in mine):
            continue
        lines += bool(mine)
        for tol, (left, right) in mine:
            held = [_holds(left.xreplace(s), right.xreplace(s), tol) for s in subs]
            if held[0] != held[1]:
                return (1 if held[0] else -1), lines == 1
    return 0, False


def _holds(left: sympy.Expr, right: sympy.Expr, tol: float) -> bool:
    a, b = number_of(left), number_of(right)
    return a is not None and b is not None and abs(a - b) <= 2 * tol * max(abs(a), abs(b)) + 1e-12


def _name(e: sympy.Expr) -> str:
    e = -e if isinstance(-e, sympy.Symbol) else e
    return e.name if isinstance(e, sympy.Symbol) else ""


def grounded(
    best: Option, options: list[Option], group: list[sympy.Symbol], mapping: dict, found: list[list[Pair]], at: tuple
) -> Option:
    """The natural reading of ``best``'s velocities (:func:`natural_of`; ``at`` is the context,
    the point, the true values and the frame's sign), or another reading of them (``best``, or
    their other signs: ``-mx`` written for a rebound) that holds the first relation on which the
    two disagree. Every velocity turned at once (the after-values in another frame) is taken
    only where the first relation the names stand in says so (never from a later relation whose
    slip it would make right)."""
    ctx, pt, truth, sign = at

    def wins(a: Option, b: Option) -> bool:
        ours = {**mapping, **{p: c[1] for p, c in zip(group, a, strict=True)}}
        theirs = {**mapping, **{p: c[1] for p, c in zip(group, b, strict=True)}}
        every = all(x[1] == -y[1] for x, y in zip(a, b, strict=True))
        strict = every or (_swapped(a, b) and not _lettered(ctx, group, a))  # a law upside down reads as either
        won, first = first_holds(found, set(group), ours, theirs, (ctx, pt, truth), strict)
        return won > 0 and (first or not strict)

    natural = natural_of(best, options, sign)
    current = best if best != natural and wins(best, natural) else natural
    for other in _signs_of(current, options):
        if wins(other, current):
            current = other
    return current


def _swapped(a: Option, b: Option) -> bool:
    """Whether two readings give the same velocities to the two names the other way round (x as
    B's and y as A's): with one less the other in the impact rule that swap is the law written
    upside down, and from it on the later lines hold either way; only the first relation the
    names stand in (apart from that difference) may ground it, as a teacher reads x then y."""
    return len(a) == 2 and a[0] != a[1] and (a[0], a[1]) in ((b[1], b[0]), (_turn(b[1]), _turn(b[0])))


def _turn(c: tuple[str, sympy.Expr]) -> tuple[str, sympy.Expr]:
    """A name's reading taken positive the other way (x as -B's too: swapped and turned at once)."""
    return (c[0][1:] if c[0].startswith("-") else f"-{c[0]}", -c[1])


def _lettered(ctx: Context, group: list[sympy.Symbol], reading: Option) -> bool:
    """Whether each name of ``group`` carries a body's letter (``v_Q``, ``v_P``: the statement's Q
    is derive's A) and ``reading`` gives it that body's velocity: the letters decide, not the order."""
    marks = {"A": "A", "B": "B", **statement_bodies(ctx)}
    for p, (what, _e) in zip(group, reading, strict=True):
        letters = re.findall(r"[A-Z]", p.name.removeprefix(PREFIX))
        body = what.lstrip("-")[2:3] if what.lstrip("-").startswith("v_") else ""
        if len(letters) != 1 or marks.get(letters[0]) != body:
            return False
    return True


def _signs_of(combo: Option, options: list[Option]) -> list[Option]:
    """The readings of ``combo``'s velocities in its order with other signs (those among
    ``options``), the fewest turned first."""
    ways = [[(w, e), (w[1:], -e) if w.startswith("-") else (f"-{w}", -e)] for w, e in combo]
    out = sorted(itertools.product(*ways), key=lambda c: sum(x != y for x, y in zip(c, combo, strict=True)))
    return [c for c in out if c != combo and c in options]


def grounded_frame(ctx: Context, ways: dict[int, list], found: dict[int, dict], at: tuple[dict, dict]) -> int | None:
    """The frame (+1 derive's n, -1 reversed) the givens as written ground, where the student's
    own names are read both ways: the first relation that holds in either (an answer such as
    ``v_A = -4`` never counts) decides where it holds one way only; where it holds either way
    (``0 = x + 2y``, an energy), derive's. None where no relation holds, or the first one read
    is false either way (a slip: the relations that hold choose, as before). ``ways`` are the
    relations read in each frame, ``found`` each frame's mapping; a later relation never turns
    the frame (a restitution law upside down would otherwise make it)."""
    pt, truth = at
    if set(ways) != {1, -1}:
        return None
    sides = {sg: pairs(ctx, ways[sg], pt, truth) for sg in ways}
    subs = {sg: {k: ctx.in_unknowns(v).xreplace(pt).xreplace(truth) for k, v in found[sg].items()} for sg in ways}
    before = {c for c in (ctx.model.nm.A1n, ctx.model.nm.B1n) if isinstance(c, sympy.Symbol)}
    turned = {p for p in found[1] if found[-1].get(p) != found[1][p]}  # what the frame moves
    for k, r in enumerate(ways[1]):
        if r.exprs is None or _answer(r.exprs, found[1], before):
            continue
        if r.exprs == ways[-1][k].exprs and not any(turned & x.free_symbols for x in r.exprs):
            continue  # nothing in it the frame moves (``m = 2``, a size)
        held = {
            sg: [
                _holds(a.xreplace(subs[sg]), b.xreplace(subs[sg]), tol) for tol, (a, b), moved in sides[sg][k] if moved
            ]
            for sg in (1, -1)
        }
        for mine, other in zip(held[1], held[-1], strict=False):
            if mine != other:
                return 1 if mine or not _turned_written(ctx, ways[1], at) else -1
        if any(held[1]):
            if _moves(ctx, r.exprs, turned, found[1], at):
                return 1  # it holds either way: derive's
            continue  # ``(v_A)_1n = 0``: true in either
        if any(_evaluated(a, b, subs) for _t, (a, b), moved in sides[1][k] if moved):
            return None  # false either way (a slip): the relations that hold choose
    return None


def _turned_written(ctx: Context, reads: list, at: tuple[dict, dict]) -> bool:
    """Whether a frame the other way is written: in a direct impact of two free bodies whose
    velocities before are given as numbers, a student taking the other way positive writes a
    velocity before that is positive in derive's frame (A's 3.5 m/s) with a minus sign (``-3.5``,
    ``- 0.3(3.5)``) somewhere. Where no such number is written, a relation that holds only the other way holds by a slip that turns a sign
    (the masses swapped in ``(m_A - m_B)/(m_A + m_B) u = (27 - 22)/49 (3.5)``), not by the frame."""
    givens = ctx.problem.givens
    if (
        ctx.problem.oblique
        or ctx.problem.fixed_B
        or any(g.value is None and not g.unknown and g.dim == VELOCITY for g in givens)
    ):
        return True  # components, letters, or a wall (its rebound written as a speed): numbers do not show it
    pt, truth = at
    before = [ctx.model.nm.A1n, ctx.model.nm.B1n]
    values = [number_of(ctx.in_unknowns(c).xreplace(pt).xreplace(truth)) for c in before if c is not None]
    positive = [v.real for v in values if v is not None and abs(v.imag) < 1e-12 and v.real > 1e-9]
    if not positive:
        return True
    written = [float(n) for r in reads for term in _minus_terms(r.written) for n in _NUMBER.findall(term)]
    return any(abs(w - v) <= 1e-6 + 5e-3 * v for w in written for v in positive)


_NUMBER = re.compile(r"\d+(?:\.\d+)?")


def _minus_terms(text: str) -> list[str]:
    """Each term a minus sign is put before (``-3.5``, ``- 0.3(3)``, ``-(0.3 × 3)``): the text
    after the sign up to the next sign or ``=`` outside brackets, or a bracket it is inside
    closing (``{27-22}``: only 22)."""
    out = []
    for m in re.finditer(r"[-−]", text):
        depth, k = 0, m.end()
        while k < len(text):
            c = text[k]
            depth += 1 if c in "({[" else -1 if c in ")}]" else 0
            if depth < 0 or (depth == 0 and c in "+-−=,;"):
                break
            k += 1
        out.append(text[m.end() : k])
    return out


def _relative_only(exprs: tuple[sympy.Expr, ...], turned: set) -> bool:
    """Whether a relation's first ``=`` has of the names ``turned`` only one less another
    (``x - y = 0.8(3 + 2)``): turning both signs only turns that difference round, the impact
    rule's own slip, so it grounds no reading (the momentum, with the givens' signs, does)."""
    if len(exprs) < 2:
        return False
    d = sympy.expand(exprs[0] - exprs[1])
    names = d.free_symbols & turned
    if len(names) != 2 or not d.is_polynomial(*names) or sympy.Poly(d, *names).total_degree() != 1:
        return False
    a, b = (d.coeff(n) for n in names)
    return a != 0 and sympy.simplify(a + b) == 0


def _evaluated(left: sympy.Expr, right: sympy.Expr, subs: dict) -> bool:
    """Whether a pair has a number on each side in both frames (no name left unread)."""
    return all(number_of(x.xreplace(subs[sg])) is not None for sg in (1, -1) for x in (left, right))


def _answer(exprs: tuple[sympy.Expr, ...], mapping: dict, before: set[sympy.Symbol]) -> bool:
    """``v_A = -4``, ``x = 9.33``: one name and a number, not a velocity before (after-values
    alone never set a frame; ``u_A = -12`` does)."""
    if len(exprs) != 2 or not exprs[0].is_Symbol or exprs[1].free_symbols:
        return False
    return not (sympy.sympify(mapping.get(exprs[0], exprs[0])).free_symbols & before)


def the_speed(ctx: Context, group: list[sympy.Symbol], options: list[Option]) -> Option | None:
    """A speed's letter of the student's own (U, W) that no reading makes hold (``U sin 30° = ½U`` is
    true whatever U is): the problem's one speed given as a letter (``speed U``, derive's v_A1),
    as a student renames it; None where the problem gives no such speed or more than one."""
    given = [g.symbol for g in ctx.problem.givens if g.value is None and not g.unknown and g.dim == VELOCITY]
    if len(group) != 1 or len({ctx.in_unknowns(g) for g in given}) != 1:
        return None
    if not re.fullmatch(re.escape(PREFIX) + "[uUwW]", group[0].name):  # a letter for a speed, not an angle's
        return None
    return next((o for o in options if o[0][1] in given), None)


def _moves(ctx: Context, exprs: tuple, turned: set, mapping: dict, at: tuple[dict, dict]) -> bool:
    """Whether a relation has something the frame turns that is not zero (``(v_A)_1n = 0`` holds
    in either frame and says nothing of it; ``0 = x + 2y`` with x, y not zero does)."""
    pt, truth = at
    ns = set(n_components(ctx))
    for s in set().union(*(x.free_symbols for x in exprs)) & (turned | ns):
        value = number_of(ctx.in_unknowns(mapping.get(s, s)).xreplace(pt).xreplace(truth))
        if value is None or abs(value) > 1e-12:
            return True
    return False
