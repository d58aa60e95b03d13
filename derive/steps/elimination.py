"""Stage 3 of the notes' layout: the elimination written out.

From (4) one unknown in terms of the other, substituted into (3) and back (Example
4.C.11); where (3) and (4) have equal coefficients, added and subtracted (Example
4.C.12); in an inverse problem, each equation with one unknown left, in turn.
"""

from __future__ import annotations

import sympy

from derive.numbers import tidy
from derive.physics.impact import root_rule
from derive.steps.kinetics import Kinetics
from derive.steps.model import Block, Degrees, Eqn, Math, Side, Text
from derive.steps.page import Page, as_float, nonzero, over, show

#: Why the root shown is the one kept, by the physics' rule.
ROOT_REASONS = {
    "e": "the root with 0 ≤ e ≤ 1 is the physical one.",
    "angle": "the root between -180° and 180° for which the bodies approach is the physical one.",
}


def elimination(page: Page, kin: Kinetics) -> list[Block]:
    """The unknowns from the collected equations, each step shown."""
    if page.imp.inverse:
        return _generic_solve(page, kin)
    if page.p.fixed_B:
        return [_against_surface(page)]
    x, y = page.nm.A2n, page.nm.B2n
    terms3, _ = kin.eq3
    a = sympy.expand(sympy.Add(*terms3)).coeff(x)
    b = sympy.expand(sympy.Add(*terms3)).coeff(y)
    if sympy.simplify(a - b) == 0:
        return _add_and_subtract(page, kin, sympy.simplify(a))
    return _substitute(page, kin, a, b)


def _against_surface(page: Page) -> Block:
    """A fixed B: (4) alone gives v_A2n = -e v_A1n."""
    x = page.nm.A2n
    form = -page.e * page.givens(page.nm.A1n)
    sides = [Side((x,)), Side((form,))]
    if page.has_values(form):
        sides.append(Side((form,), "values"))
    sides.append(Side((page.value_of(x),), "result"))
    return Block((f"From ({page.tags(4)}), with the {page.surface} at rest:",), (Eqn(tuple(sides), unit=page.unit_v),))


def _add_and_subtract(page: Page, kin: Kinetics, a1: sympy.Expr) -> list[Block]:
    """Equal coefficients in (3): add and subtract (3) and (4), as in Example 4.C.12.

    (4) reads v_B2n - v_A2n = k, so with a coefficient ``a1`` other than 1 in (3),
    (4) is taken ``a1`` times for a term to cancel."""
    x, y = page.nm.A2n, page.nm.B2n
    (_, c), k = kin.eq3, kin.eq4
    xv, yv = page.value_of(x), page.value_of(y)
    three, four = page.tags(3), page.tags(4)
    if a1 == 1:
        add: Text = (f"Add ({three}) and ({four}): ", Math(x), " cancels.")
        sub: Text = (f"Subtract ({four}) from ({three}): ", Math(y), " cancels.")
        ak = k
    else:
        add = (f"Multiply ({four}) by ", Math(as_float(a1)), f" and add it to ({three}): ", Math(x), " cancels.")
        sub = (f"Multiply ({four}) by ", Math(as_float(a1)), f" and subtract it from ({three}): ", Math(y), " cancels.")
        ak = a1 * k
    return [
        Block(add, _sum_lines(page, a1, y, (c, ak), yv, page.tags(5)), _sum_check(page, (c, ak))),
        Block(sub, _sum_lines(page, a1, x, (c, -ak), xv, page.tags(6)), _sum_check(page, (c, -ak))),
    ]


def _sum_lines(
    page: Page, a1: sympy.Expr, u: sympy.Symbol, terms: tuple[sympy.Expr, ...], value: sympy.Expr, tag: str
) -> tuple[Eqn, ...]:
    """``2 a1 u = c + a1 k`` then ``u = value``; one line ``u = c + a1 k = value`` when 2 a1 is 1."""
    if 2 * a1 == 1:
        sides = (Side((u,)), Side(terms, "numeric", optional=True), Side((value,), "result"))
        return (Eqn(sides, unit=page.unit_v, tag=tag),)
    return (
        Eqn((Side((sympy.Mul(2 * a1, u, evaluate=False),), "numeric"), Side(terms, "numeric"))),
        Eqn((Side((u,)), Side((value,), "result")), unit=page.unit_v, tag=tag, implies=True),
    )


def _substitute(page: Page, kin: Kinetics, a: sympy.Expr, b: sympy.Expr) -> list[Block]:
    """From (4) v_B2n in terms of v_A2n, into (3), and back into (4), as in Example 4.C.11."""
    x, y = page.nm.A2n, page.nm.B2n
    (_, c), k = kin.eq3, kin.eq4
    xv, yv = page.value_of(x), page.value_of(y)
    sub = sympy.Add(x, as_float(k), evaluate=False)
    lhs = (a * x, sympy.Mul(b, sub, evaluate=False))
    coef = sympy.Add(a, b, evaluate=False)
    bk = sympy.Mul(as_float(-b), as_float(k), evaluate=False)
    fraction = show(
        _over_one_denominator((c, -b * k), a + b) or _fraction(sympy.Add(as_float(c), bk, evaluate=False), a + b)
    )
    return [
        Block((f"From ({page.tags(4)}):",), (Eqn((Side((y,)), Side((x, k), "numeric"))),)),
        Block(
            (f"Substitute into ({page.tags(3)}):",),
            (
                Eqn((Side(lhs, "numeric"), Side((c,), "numeric"))),
                Eqn((Side((sympy.Mul(coef, x, evaluate=False),), "numeric"), Side((c, bk), "numeric")), implies=True),
                Eqn((Side((x,)), Side((fraction,), "numeric"), Side((xv,), "result")), unit=page.unit_v, implies=True),
            ),
        ),
        Block(
            (f"Back into ({page.tags(4)}):",),
            (Eqn((Side((y,)), Side((xv, k), "numeric", optional=True), Side((yv,), "result")), unit=page.unit_v),),
            (((xv, k), yv),) if not ((xv.free_symbols | yv.free_symbols) - page.varied) else (),
        ),
    ]


def _fraction(num: sympy.Expr, den: sympy.Expr) -> sympy.Expr:
    return over(num, as_float(den))


def _over_one_denominator(terms: tuple[sympy.Expr, ...], den: sympy.Expr) -> sympy.Expr | None:
    """(4u - 4u/3)/3 written as the notes would, with no fraction inside the fraction: each
    term and the denominator times the terms' common denominator ((12u - 4u)/9). None where
    no term has a fraction of its own (nothing to clear) or a number is not exact."""
    exact = [t.as_coeff_Mul()[0] for t in terms] + [den]
    if any(not x.is_Rational for x in exact) or not any(t.free_symbols for t in terms):
        return None
    lcm = sympy.ilcm(*(x.q for x in exact[:-1]))
    if lcm == 1:
        return None
    num = sympy.Add(*(sympy.expand(lcm * t) for t in terms), evaluate=False)
    return _fraction(num, lcm * den)


def _generic_solve(page: Page, kin: Kinetics) -> list[Block]:
    """Inverse problems: take each equation with one unknown left, in turn."""
    blocks: list[Block] = []
    remaining = [u for u in page.unknowns if u not in kin.shown]
    eqs = dict(sorted(kin.open.items()))
    known: dict[sympy.Symbol, sympy.Expr] = {}
    while remaining:
        step = None
        for k, ex in eqs.items():
            us = [u for u in remaining if ex.xreplace(known).has(u)]
            if len(us) == 1:
                step = (k, us[0])
                break
        if step is None:
            lines = tuple(
                Eqn((Side((u,)), Side((page.value_of(u),), "result")), unit=page.unit_of(u)) for u in remaining
            )
            listed = " and ".join(f"({page.tags(k)})" for k in eqs)
            cases = _cases_note(page)
            blocks.append(Block((f"Solve {listed} together" + (f"; {cases}" if cases else ":"),), lines))
            break
        k, u = step
        sides = [Side((u,))]
        if u == page.e and k == 4:
            nm = page.nm
            sep = sympy.Add(*nonzero(tuple(page.givens(t) for t in (nm.B2n, -nm.A2n))), evaluate=False)
            app = sympy.Add(*nonzero(tuple(page.givens(t) for t in (nm.A1n, -nm.B1n))), evaluate=False)
            frac = over(sep, app)
            sides.append(Side((frac,)))
            put_in = _substituted(page, sep, known), _substituted(page, app, known)
            sides.append(Side((show(_cleared(*put_in) or _substituted(page, frac, known)),), "numeric"))
            sides.append(Side((page.notes(page.value_of(u)),), "result"))
        else:
            sides.append(Side((page.value_of(u),), "result"))
        why = _root_reason(page, u)
        text: Text = (f"From ({page.tags(k)}):" + (f" {why}" if why else ""),)
        lines = (Eqn(tuple(sides), unit=page.unit_of(u)),)
        if len(sides) == 2 and root_rule(page.imp, u) is not None:  # the equation in u first, then its root
            lines = (_in_one_unknown(eqs[k].xreplace(known), u), *lines)
        blocks.append(Block(text, lines))
        known[u] = page.value_of(u)
        remaining.remove(u)
        del eqs[k]
    return blocks


def _cleared(num: sympy.Expr, den: sympy.Expr) -> sympy.Expr | None:
    """num/den with no fraction inside it, where a term of either has one of its own:
    (3u - 2u/3)/(2u + u) as (9u - 2u)/(6u + 3u), (λu + u/k - 0)/(u - λu) as
    (kλu + u - 0)/(ku - kλu): each term times the terms' common denominator. None where no
    term has a denominator, or a number in them is a decimal."""
    terms = [*sympy.Add.make_args(num), *sympy.Add.make_args(den)]
    if not any(t.free_symbols for t in terms):  # numbers only: 8.4 prints as a decimal, no fraction in it
        return None
    if any(isinstance(a, sympy.Float) for t in terms for a in sympy.preorder_traversal(t)):
        return None
    lcm = sympy.lcm_list([sympy.fraction(sympy.together(t))[1] for t in terms])
    if lcm == 1:
        return None

    def times(side: sympy.Expr) -> sympy.Expr:
        return sympy.Add(
            *(t if t.is_zero else sympy.expand(lcm * t) for t in sympy.Add.make_args(side)), evaluate=False
        )

    return over(times(num), times(den))


def _substituted(page: Page, expr: sympy.Expr, known: dict[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with every known quantity's number in its place, structure kept."""
    vals = {**page.numeric, **known}
    if isinstance(expr, sympy.Symbol):
        if expr in page.outcome.angles and expr in vals:  # an angle as the page shows angles: 30°
            return Degrees(tidy(vals[expr] * 180 / sympy.pi))  # 71.57°, not all the figures of atan(3)
        return as_float(vals[expr]) if expr in vals else expr
    if expr.is_Atom:
        return expr
    return expr.func(*(_substituted(page, a, known) for a in expr.args), evaluate=False)


def _root_reason(page: Page, u: sympy.Symbol) -> str:
    """Why the root shown is the one kept, where the equations have several."""
    if page.outcome.others:
        return _cases_note(page)
    rule = root_rule(page.imp, u)
    if rule == "sign":
        return f"the root with {u.name} ≥ 0 is the physical one."
    return ROOT_REASONS.get(rule, "") if rule else ""


def _in_one_unknown(ex: sympy.Expr, u: sympy.Symbol) -> Eqn:
    """``ex = 0`` as the terms in ``u`` = the rest (4 sin th = -2), before its root is taken."""
    terms = sympy.Add.make_args(sympy.expand(ex))
    left = sympy.Add(*(t for t in terms if t.has(u)))
    return Eqn((Side((left,), "numeric"), Side((-(ex - left),), "numeric")))


def _cases_note(page: Page) -> str:
    """Where several roots are physical: that the data do not choose, and what the page does."""
    if not page.outcome.others:
        return ""
    n = len(page.outcome.others) + 1
    other = "the other" if n == 2 else "the others"
    return f"{n} sets of roots are physical and the data do not choose between them: the steps follow the first, and the answer lists {other}."


def _sum_check(page: Page, terms: tuple[sympy.Expr, ...]) -> tuple[tuple[tuple[sympy.Expr, ...], sympy.Expr], ...]:
    """The sum claim for a line of numeric terms (none when a symbol remains)."""
    nums = tuple(page.num(t) for t in terms)
    if any(t.free_symbols - page.varied for t in nums):
        return ()
    return ((nums, sympy.Add(*nums)),)
