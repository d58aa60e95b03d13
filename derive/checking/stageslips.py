"""A chain's stages as single impacts for the checker: each impact stage's common mistakes as
the chain's values they give, and a stage's own givens (the wall's e), so that a slip in a
stage is named as in a single impact."""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.checking import mistakes
from derive.checking.context import Context
from derive.checking.figures import EARLY
from derive.checking.numeric import number_of
from derive.checking.report import Item
from derive.checking.worlds import NUMBER_SIDE
from derive.errors import InputError
from derive.mathtext.notation import student
from derive.problem.expr import ParseError
from derive.problem.units import FORCE

#: A stage's mistakes: the chain's names of its results -> the results' names in the stage,
#: and the stage's common mistakes solved (each with its values by those names).
StageMistakes = list[tuple[str, dict[sympy.Symbol, sympy.Expr]]]


def stage_mistakes(ctx: Context) -> StageMistakes:
    """Each impact stage's common mistakes, as the chain's values they give (``w_B`` = +2.38
    with the wall's restitution reversed): a slip in a stage is named as in a single impact."""
    out: StageMistakes = []
    for st in getattr(ctx.solution, "stages", ()):
        part = getattr(st, "part", None)
        if part is None:
            continue
        names = {}
        for eqn in getattr(st, "carried", ()):
            outer, inner = (eqn.sides[0].terms[0], eqn.sides[1].terms[0])
            if isinstance(outer, sympy.Symbol) and isinstance(inner, sympy.Symbol):
                names[sympy.Symbol(outer.name)] = inner.name  # the chain's values are plain symbols
        for inner_name, outer_name in getattr(part, "names", {}).items():  # a wall stage writes w_B for v_B2
            names.setdefault(sympy.Symbol(outer_name), inner_name)
        chain = {str(k) for k in ctx.solution.values}
        for g in part.problem.givens:  # the stage's unknowns (e and m_A found): the chain's by their names
            if g.unknown and g.name in chain:
                names.setdefault(sympy.Symbol(g.name), g.name)
        inner_ctx = Context(part, None)
        try:
            found = [*inner_ctx.singles(), *(o for o in inner_ctx.forms() if o.post)]
        except (InputError, ValueError, TypeError, ArithmeticError):
            continue
        for o in found:
            if o.mistake is None:
                continue
            post = {u.name: x for u, x in o.post.items()}
            given = {}
            for outer, inner in names.items():
                q = o.results.get(inner)
                x = q.value if q is not None and q.value is not None else post.get(inner)
                if x is not None:
                    given[outer] = x * 180 / sympy.pi if q is not None and q.value is None else x
            given.update(_energies_after(part, names, post, given))
            if given:
                out.append((o.mistake.name, given))
    return out


def _energies_after(part, names: dict, post: dict, given: dict) -> dict:
    """The kinetic energy after an impact (the chain's name of its T_2) that a mistake's
    velocities give where the mistake states only those (kinetic energy kept with the bodies
    moving together: V = 21.2, so T_after = ½(m_A + m_B)V² = 900), for the lines worked from it."""
    outer = next((k for k, v in names.items() if v == "T_2" and k not in given), None)
    masses = {g.name: g.value for g in part.problem.givens if g.name in ("m_A", "m_B") and g.value is not None}
    if outer is None or len(masses) != 2 or not all(f"v_{b}2" in post for b in "AB"):
        return {}
    return {outer: sum(masses[f"m_{b}"] * post[f"v_{b}2"] ** 2 for b in "AB") / 2}


def stage_given(ctx: Context, exprs) -> bool:
    """``e = 0.7`` where a stage's own given of that name (the wall's e) has that value."""
    if len(exprs) != 2 or not isinstance(exprs[0], sympy.Symbol) or exprs[1].free_symbols:
        return False
    for st in getattr(ctx.solution, "stages", ()):
        part = getattr(st, "part", None)
        g = next((g for g in part.problem.givens if g.name == exprs[0].name), None) if part is not None else None
        if g is not None and g.value is not None and not g.value.free_symbols and g.value == exprs[1]:
            return True
    return False


#: A line that says which way is positive ("going up, with up positive", "take up as +ve").
_CONVENTION = re.compile(r"\bpositive\b|\+\s?ve\b|\bas\s+\+|\+\s*(?:is\s+)?(?:up|down)", re.I)


def given_turned(ctx: Context, written: str, exprs, subs: tuple[dict, dict]) -> bool:
    """``a = -9.8`` on a line that takes another way as positive ("going up, with up positive"):
    a name standing for a given (g, as suvat's a or the student's own ``a = g``) restated in the
    convention that line takes, its sign turned; a teacher reads it as the next leg's given, not
    as a slip in the earlier one. ``subs``: the student's names' true values, the chain's."""
    if len(exprs) != 2 or not isinstance(exprs[0], sympy.Symbol) or exprs[1].free_symbols:
        return False
    if not _CONVENTION.search(written):
        return False
    defs, values = subs
    x, y = (number_of(e.xreplace(defs).xreplace(values).xreplace(ctx.unit_subs())) for e in exprs)
    given = {number_of(values[sympy.Symbol(g.name)]) for g in ctx.problem.givens if sympy.Symbol(g.name) in values}
    if x is None or y is None or abs(x) < 1e-12 or abs(x + y) > 1e-3 * abs(x):
        return False
    return any(v is not None and abs(abs(v) - abs(x)) <= 1e-9 * abs(x) for v in given)


def named_arithmetic(item: Item, exprs: list[sympy.Expr] = ()) -> Item:
    """A stage's line found false with no mistake named, where a side of numbers is not what the
    student wrote it comes to (``441 + 784 = 1125``): an arithmetic slip, named so. Where its sides
    are unequal and a name stands in working (``(0.020)(300) = (4.0) V``, ``2y = 7 + e``), not only
    alone on the left set to a number: an algebra slip, a term or factor lost in the relation
    (``exprs``: its sides read)."""
    if item.status != "wrong" or item.slip or item.again:
        return item
    if item.message.endswith("(an arithmetic slip)."):
        return replace(item, slip="arithmetic")
    worked = [x for k, x in enumerate(exprs) if k or not x.is_Symbol]
    if item.message.endswith("(an arithmetic or algebra slip).") and any(x.free_symbols for x in worked):
        return replace(item, slip="algebra")
    return item


def own_value(own: dict, left: sympy.Expr, line: tuple, status: str, number: Callable[[str], bool]) -> None:
    """The student's value of a chain's name on the left of a line, for the lines after: the
    number written last, or on a wrong or carried line the expression in the unknowns it comes
    to (``u_B = 9(1 + e)/2``, with 9 copied for 7)."""
    sides, exprs = line
    if left.is_Pow and left.exp == 2 and left.base.is_Symbol and status in ("wrong", "carried") and number(sides[-1]):
        own[left.base] = sympy.sqrt(sympy.Rational(sides[-1].strip()))  # V² = 21.17 after a slip: V = √21.17
        return
    if not left.is_Symbol or len(exprs) < 2:
        return
    if number(sides[-1]):
        own[left] = sympy.Rational(sides[-1].strip())
    elif status in ("wrong", "carried") and exprs[-1].free_symbols and left not in exprs[-1].free_symbols:
        own[left] = exprs[-1].xreplace(own)


def own_sides(exprs: list[sympy.Expr], own: dict) -> list[sympy.Expr]:
    """The sides of a line that are the student's own value of a name in the unknowns, put
    back as that name (``9(1 + e)²/4 = 4`` with the student's u_C = 9(1 + e)²/4: u_C = 4)."""
    out = []
    for x in exprs:
        same = (k for k, v in own.items() if x.free_symbols and v.free_symbols and sympy.expand(x - v) == 0)
        out.append(next(same, x))
    return out


def own_root(exprs: list[sympy.Expr], values: dict, own_defs: dict, given: set) -> None:
    """``½V² = gh`` after a slip in V: right for the problem, and with the student's own V it
    gives the student's own value of the chain's latest name in it (h), carried on to the lines
    after (``h = 1.52²/(2 × 9.81) = 0.118`` is then carried, not a further slip)."""
    d = exprs[0] - exprs[1]
    own = d.xreplace(own_defs)
    order = list(values)
    open_ = sorted(
        (x for x in own.free_symbols if x in values and x not in own_defs and x not in given), key=order.index
    )
    if own == d or not open_:
        return  # none of the student's own values in it
    x = open_[-1]
    eq = own.xreplace({k: v for k, v in values.items() if k != x})
    if eq.free_symbols != {x} or not eq.is_polynomial(x) or sympy.degree(eq, x) not in (1, 2):
        return
    roots = [r for r in sympy.solve(eq, x) if r.is_real]
    if roots:
        own_defs[x] = min(roots, key=lambda r: abs(r - values[x]))


#: A side that is a number alone, perhaps with its unit (``5 m/s``): a line's result.
RESULT = re.compile(r"\s*[-+]?\d+(?:\.\d+)?\s*(?:[A-Za-z/ ]|\^\s*-?\d|[²³⁻¹])*")  # a unit with its powers: m^2/s^2


def numbers_written(
    sides: tuple[str, ...] | list[str], data: set, working: bool = False, small: bool = False
) -> set[str]:
    """The decimals written in ``sides`` and the whole numbers of two figures or more
    (``1125`` in ``sqrt(1125)``), as written, but the problem's ``data``: a number a wrong line
    came to, and a later line worked from it. ``working``: of the sides but a last one that is
    a number alone (the line's result; ``3010 × 4.601`` is working). ``small``: the whole numbers
    2 to 9 too (``y = 5`` worked wrongly, then ``0.7 × 5``)."""
    if working and sides and RESULT.fullmatch(sides[-1]):
        sides = sides[:-1]
    found = re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])", " ".join(sides))
    short = {str(k) for k in range(2, 10)} if small else set()
    return {t for t in found if ("." in t or len(t.strip("0")) >= 2 or t in short) and sympy.Rational(t) not in data}


def result_numbers(sides: tuple[str, ...], data: set) -> set[str]:
    """The numbers a line came to: its last side, and every side before it that is a number alone,
    perhaps with a unit (``y = 5 m/s``; ``v = 6.378 = 6.38``: both, the value to more figures and
    rounded), as :func:`numbers_written` has them (small whole numbers too; none of the problem's
    ``data``)."""
    alone = [s for s in sides[1:] if RESULT.fullmatch(s) or NUMBER_SIDE.match(student(s.strip()))]
    return numbers_written(alone, data, small=True)


def unnamed_number(ctx: Context, exprs: list, sides: tuple) -> bool:
    """Whether what is left of a line is a number alone that a name of the student's own was set
    to (``w = 3.1``), not 0 and no stage's given (``e = 0``, ``e = 0.7`` restated in a name)."""
    if len(exprs) >= 2 or len(sides) != 1 or not NUMBER_SIDE.match(student(sides[0].strip())) or exprs[0] == 0:
        return False
    givens = [
        g
        for st in getattr(ctx.solution, "stages", ())
        for g in getattr(getattr(st, "part", None), "problem", ctx.problem).givens
    ]
    return all(g.value != exprs[0] for g in [*givens, *ctx.problem.givens])


def rule_named(ctx: Context, item: Item, line: tuple, reread: Callable[[str], sympy.Expr], holds: Callable) -> Item:
    """A chain's slip named by the rule it breaks: a weight used as the mass, or a rule of motion
    with a factor 2 lost, or worked from a number rounded to two figures (``line``: the sides as
    written and as read)."""
    sides, exprs = line
    lead = item.message.split(": ")[0]
    if not item.slip and weight_as_mass(ctx, sides, reread, holds):
        item = replace(item, slip="weight_as_mass", message=f"{lead}: it {mistakes.phrase('weight_as_mass')}.")
    if not item.slip and factor_lost(ctx, exprs, holds):
        item = replace(item, slip="algebra", message=f"{lead}{FACTOR_LOST}")
    if not item.slip and (early := ctx.memo.get((EARLY, tuple(sides)))):  # J = 0.3(5.24 + 6.3) = 3.46
        said = f"{lead}: rounded too early: worked from {', '.join(early[:3])}, rounded to 2 figures."
        item = replace(item, slip="rounded_too_early", message=said)
    return item


def weight_as_mass(
    ctx: Context, sides, reread: Callable[[str], sympy.Expr], holds: Callable[[list], bool | None]
) -> bool:
    """Whether the line holds once a weight written in it (``½(10)(15.33)^2`` for B's 10 lb) is
    put back as the mass, W/g: in every side, or in one side only (the friction ``0.4(10)``
    on the other is a force, rightly the weight). ``reread`` reads a side as written."""
    g = next((v for k, v in ctx.solution.values.items() if str(k) == "g"), None)
    weights = [x.value for x in ctx.problem.givens if x.dim == FORCE and x.value is not None]
    if g is None or not weights:
        return False
    for w in (w for w in weights if w.is_Rational and w != 0):
        at = re.compile(rf"(?<![\w.]){re.escape(str(w))}(?![\w.]|\.\d)")
        for k in (None, *range(len(sides))):
            mass = [at.sub(f"({w}/({g}))", t) if k in (None, i) else t for i, t in enumerate(sides)]
            if mass == list(sides):
                continue
            try:
                exprs = [reread(t) for t in mass]
            except (ParseError, ValueError, TypeError):
                continue
            if holds(exprs):
                return True
    return False


#: The words for a rule of motion written with a factor 2 lost or put in (v² = gh for 2gh).
FACTOR_LOST = ": the rule is written with a factor of 2 lost or put in (an algebra slip: v² = 2gh, h = v²/(2g))."
#: The units of the speeds and lengths a rule of motion (v² = u² + 2as) relates.
_MOTION = {"m/s", "ft/s", "km/h", "mi/h", "m", "ft", "cm", "km", "in"}


def _with_a_mass(side: sympy.Expr) -> bool:
    """Whether a squared speed in ``side`` has a coefficient that is neither a small number nor
    made of g (``0.3 v1²``: a mass with it, an energy whose ½ is :mod:`.termslips`' ke_formula;
    ``V²/9.8`` and ``v²/2`` are rules of motion)."""
    for t in sympy.Add.make_args(side):
        squares = [p for p in t.atoms(sympy.Pow) if p.exp == 2 and p.base.free_symbols]
        if len(squares) != 1 or not (c := abs(t / squares[0])).is_number:
            continue
        c = float(c)
        near = (1, 2, 0.5, 4, 0.25, *(g * k for g in (9.8, 9.81, 32.2, 32.174) for k in (1, 2, 0.5)))
        if not any(abs(c - x) < 1e-6 * x or abs(c * x - 1) < 1e-6 for x in near):
            return True
    return False


def factor_lost(ctx: Context, exprs: list[sympy.Expr], holds: Callable[[list], bool | None]) -> bool:
    """Whether a line of a rule of motion in the chain's speeds and heights holds once its sides
    in those names are halved or doubled (``v2^2 = 9.8 × 1.4 = 13.72`` for v² = 2gh): a factor
    2 dropped in the rule, which a teacher marks as algebra. A line in an energy, an impulse or
    e is left to the other names."""
    results = ctx.solution.results
    found = [{s for s in x.free_symbols if s.name in results} for x in exprs]
    units = {str(getattr(results[s.name], "unit", "") or "") for named in found for s in named}
    named = [i for i, n in enumerate(found) if n]
    if not named or len(named) == len(exprs) or not units <= _MOTION or any(_with_a_mass(exprs[i]) for i in named):
        return False
    for f in (sympy.Rational(1, 2), sympy.Integer(2)):  # every side in the names, or one alone (h = V²/g)
        for scaled in (named, *([i] for i in named if len(named) > 1)):
            if holds([x * f if i in scaled else x for i, x in enumerate(exprs)]):
                return True
    return False
