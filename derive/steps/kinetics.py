"""Stage 2 of the notes' layout: equations (1)-(4), each written symbolically, then
with the numbers in, then collected into unknown terms and a constant.

The blocks come back with what the solve stage needs (:class:`Kinetics`): the
collected (3) and (4), the equations still to be solved, and the unknowns found on
the way.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import sympy

from derive.numbers import as_written, tidy
from derive.physics.algebra import collect, common_factor
from derive.steps.model import Block, Eqn, Math, Side, Text
from derive.steps.page import Page, nonzero, over


def smooth(a: str, b: str) -> str:
    """Why (1) and (2) hold, for bodies the page calls ``a`` and ``b``."""
    return (
        "Linear momentum in the t-direction is conserved for each particle: "
        f"no impulsive force acts on {a} or on {b} along t (the surfaces are smooth)."
    )


def internal(a: str, b: str) -> str:
    """Why (3) holds."""
    return f"Linear momentum in the n-direction is conserved for the system {a} + {b}: the contact forces are internal to it."


#: A direction after the impact, by name: the components (y, x) whose ratio is its tangent.
DIRECTIONS = {
    "theta_A2": ("A2n", "A2t"),
    "theta_B2": ("B2n", "B2t"),
    "beta_A2": ("A2t", "A2n"),
    "beta_B2": ("B2t", "B2n"),
}
IMPACT_RULE = (
    "Impact rule: the coefficient of restitution relates the normal components only, separation over approach."
)


@dataclass(frozen=True)
class Kinetics:
    """The kinetics blocks and what the solve stage takes from them.

    ``eq3`` is (3) collected, (unknown terms, constant); ``eq4`` the constant of (4);
    ``open`` maps each equation still to be solved to its ``lhs - rhs`` with numbers
    in; ``shown`` holds the unknowns already found from (1) or (2).
    """

    blocks: tuple[Block, ...]
    eq3: tuple[tuple[sympy.Expr, ...], sympy.Expr] | None = None
    eq4: sympy.Expr | None = None
    open: dict[int, sympy.Expr] = field(default_factory=dict)
    shown: frozenset[sympy.Symbol] = frozenset()


def kinetics(page: Page) -> Kinetics:
    """Equations (1)-(4) as they apply to this impact."""
    blocks: list[Block] = []
    open_: dict[int, sympy.Expr] = {}
    shown: set[sympy.Symbol] = set()
    nm, p = page.nm, page.p
    if p.oblique:
        blocks.append(Block((smooth(page.a, page.b),)))
        for k, b, m, c1, c2 in ((1, "A", page.m_A, nm.A1t, nm.A2t), (2, "B", page.m_B, nm.B1t, nm.B2t)):
            if b == "B" and p.fixed_B:
                says = "the notes' t-momentum equation for it" if page.tags.own else "(2)"
                blocks.append(Block((f"{page.b}, the {page.surface}, does not move: {says} says nothing.",)))
                continue
            block, left = t_momentum(page, k, b, m, c1, c2)
            blocks.append(block)
            if left is None:
                shown.add(c2)
            else:
                open_[k] = left
    else:
        which = "the notes' t-momentum equations" if page.tags.own else "equations (1) and (2) of the notes"
        blocks.append(Block((f"The impact is direct: there are no t components, so {which} read 0 = 0.",)))
    eq3 = None
    if p.fixed_B:
        momentum = "the notes' momentum equation along n" if page.tags.own else "equation (3)"
        blocks.append(
            Block(
                (
                    f"Linear momentum along n is not conserved for {page.a} and the {page.surface}: its supports exert an "
                    f"impulsive reaction, so {momentum} does not apply. The impact rule alone gives the n component.",
                )
            )
        )
    else:
        block, eq3, open_[3] = momentum_n(page)
        blocks.append(block)
    block, eq4, open_[4] = restitution(page)
    blocks.append(block)
    for k, eq in page.imp.equations.items():
        if k >= 5:
            block, open_[k] = condition(page, k, eq)
            blocks.append(block)
    return Kinetics(tuple(blocks), eq3, eq4, open_, frozenset(shown))


def condition(page: Page, k: int, eq: sympy.Eq) -> tuple[Block, sympy.Expr]:
    """A condition of the problem beyond (1)-(4), as one more equation (5), (6), ..."""
    rel = page.p.asks.equations[k - 5]
    rhs = rel.rhs
    lhs, rhs_ = page.givens(eq.lhs), page.givens(eq.rhs)
    direction = DIRECTIONS.get(rel.lhs.name) if isinstance(rel.lhs, sympy.Symbol) else None
    if direction is not None and rhs.is_number:  # theta_A2 = 30°: v_A2n cos theta_A2 = v_A2t sin theta_A2
        rhs = sympy.Symbol(as_written(tidy(rhs)) + r"^\circ")
        y, x = (getattr(page.nm, c) for c in direction)
        lhs, rhs_ = y * sympy.cos(rel.lhs), x * sympy.sin(rel.lhs)
    unit = _unit_of_number(page, rel) if direction is None else None
    text: Text = ("The problem gives ", Math(sympy.Eq(rel.lhs, rhs, evaluate=False)), *((f" {unit}",) if unit else ()))
    text += (": one more equation.",)
    lines = [Eqn((Side((lhs,)), Side((rhs_,), "values" if unit else "symbolic")))]
    if page.has_values(lhs) or page.has_values(rhs_):
        lines.append(Eqn((Side((lhs,), "values"), Side((rhs_,), "values"))))
    lines[-1] = Eqn(lines[-1].sides, tag=page.tags(k), unit=unit)
    return Block(text, tuple(lines)), page.num(lhs - rhs_)


def _unit_of_number(page: Page, rel: Any) -> str | None:
    """The unit of ``name = number`` (v_A2t = -2 m/s), where the number has one."""
    if not (isinstance(rel.lhs, sympy.Symbol) and rel.rhs.is_number and rel.rhs != 0):
        return None
    r = page.results.get(rel.lhs.name)
    return (r.unit or None) if r is not None else page.unit_of(rel.lhs)


def t_momentum(
    page: Page, k: int, b: str, m: sympy.Symbol, c1: sympy.Symbol, c2: sympy.Symbol
) -> tuple[Block, sympy.Expr | None]:
    """(1) or (2): the mass cancels and the t component is unchanged. Returns the block
    and, when the line does not give ``c2`` outright, the equation left to solve."""
    pre = page.givens(c1)
    lines = [Eqn((Side((m * c1,)), Side((m * c2,))), cancel=frozenset({m}))]
    given_c2 = c2.name in {g.name for g in page.p.givens}
    left = None
    if not given_c2 and not (pre.free_symbols & set(page.unknowns)):
        lines.append(Eqn((Side((c2,)), Side((c1,))) + ((Side((pre,)),) if pre != c1 else ()), implies=True))
        if page.has_values(pre) and not pre.is_Symbol and pre != 0:
            lines.append(Eqn((Side((c2,)), Side((pre,), "values"))))
        lines.append(Eqn((Side((c2,)), Side((page.value_of(c2),), "result")), tag=page.tags(k), unit=page.unit_v))
    else:
        lines.append(Eqn((Side((pre,)), Side((c2,))), implies=True))
        lines.append(Eqn((Side((pre,), "values"), Side((c2,), "values")), tag=page.tags(k)))
        left = page.num(pre - c2)
    return Block((f"System {page.label(b)}: ", Math(sympy.Symbol(r"\Sigma F_t = 0")), ","), tuple(lines)), left


def collected(
    page: Page, lhs: sympy.Expr, rhs: sympy.Expr, order: tuple[sympy.Symbol, ...]
) -> tuple[tuple[sympy.Expr, ...], tuple[sympy.Expr, ...]]:
    """``lhs = rhs`` with numbers in, as unknown terms (in ``order``) = constant."""
    return collect(page.num(lhs), page.num(rhs), order, page.unknowns)


def _collected_line(page: Page, terms: tuple[sympy.Expr, ...], const: tuple[sympy.Expr, ...], number: int) -> Eqn:
    """(3) or (4) collected: unknown terms = constant; ``v_A2 = -1.6 m/s`` when one unknown is left."""
    unit = alone(page, terms, const)
    return Eqn(
        (Side(terms, "numeric"), Side(const, "result" if unit else "numeric")),
        tag=page.tags(number),
        implies=True,
        unit=unit,
    )


def _pure_letters(page: Page) -> set[sympy.Symbol]:
    """The pure-number givens kept as letters (e), and the chain's names they stand for (e_floor)."""
    out: set[sympy.Symbol] = set()
    for g in page.p.givens:
        if g.value is None and not g.unknown and not any(g.dim):
            out |= {g.symbol} | (g.definition.free_symbols if g.definition is not None else set())
    return out


def alone(page: Page, terms: tuple[sympy.Expr, ...], const: tuple[sympy.Expr, ...]) -> str | None:
    """The unit of a collected line that reads ``unknown = number`` (v_A2 = -1.6 m/s), or a number
    times pure-number letters (v_A2 = -35 e_floor m/s: a chain's e before a later stage finds it),
    else None."""
    if len(terms) != 1 or not isinstance(terms[0], sympy.Symbol):
        return None
    if any(c.free_symbols - page.varied - _pure_letters(page) for c in const):
        return None
    r = page.results.get(terms[0].name)
    return r.unit if r is not None and r.unit != "deg" else None


def momentum_n(page: Page) -> tuple[Block, tuple[tuple[sympy.Expr, ...], sympy.Expr], sympy.Expr]:
    """(3): n-momentum of A + B, written out and collected; a shared mass cancels."""
    nm, m_A, m_B = page.nm, page.m_A, page.m_B
    lhs_terms = (m_A * nm.A1n, m_B * nm.B1n)
    rhs_terms = (m_A * nm.A2n, m_B * nm.B2n)
    lines = [Eqn((Side(lhs_terms), Side(rhs_terms)))]
    g_lhs = nonzero(tuple(page.givens(t) for t in lhs_terms))
    g_rhs = tuple(page.givens(t) for t in rhs_terms)
    if g_lhs != lhs_terms or g_rhs != rhs_terms:
        lines.append(Eqn((Side(g_lhs), Side(g_rhs)), implies=True))
    common = common_factor(g_lhs + g_rhs, set(page.numeric), page.unknowns)
    if common is not None:
        lines[-1] = Eqn(lines[-1].sides, cancel=frozenset({common}), implies=lines[-1].implies)
        g_lhs = nonzero(tuple(sympy.cancel(t / common) for t in g_lhs))
        g_rhs = tuple(sympy.cancel(t / common) for t in g_rhs)
        lines.append(Eqn((Side(g_lhs), Side(g_rhs)), implies=True))
    sums = []
    if any(page.has_values(t) for t in g_lhs + g_rhs):
        lines.append(Eqn((Side(g_lhs, "values"), Side(g_rhs, "values"))))
        lhs_num = nonzero(tuple(page.num(t) for t in g_lhs))
        if len(lhs_num) > 1 and all(not (t.free_symbols - page.varied) for t in lhs_num):
            lines.append(Eqn((Side(lhs_num, "numeric"), Side(g_rhs, "values")), optional=True))
            sums.append((lhs_num, sympy.Add(*lhs_num)))
    terms, const = collected(page, sympy.Add(*g_rhs), sympy.Add(*g_lhs), (nm.A2n, nm.B2n))
    lines.append(_collected_line(page, terms, const, 3))
    block = Block((internal(page.a, page.b),), tuple(lines), tuple(sums))
    return block, (terms, const[0]), page.num(sympy.Add(*g_rhs) - sympy.Add(*g_lhs))


def restitution(page: Page) -> tuple[Block, sympy.Expr, sympy.Expr]:
    """(4): the impact rule, separation over approach along n, written out and collected."""
    nm, e = page.nm, page.e
    sep = sympy.Add(nm.B2n, -nm.A2n, evaluate=False)
    app = sympy.Add(nm.A1n, -nm.B1n, evaluate=False)
    lines = [
        Eqn((Side((e,)), Side((over(sep, app),)))),
        Eqn((Side((sympy.Mul(e, app, evaluate=False),)), Side((nm.B2n, -nm.A2n))), implies=True),
    ]
    g_app = nonzero(tuple(page.givens(t) for t in (nm.A1n, -nm.B1n)))
    g_sep = nonzero(tuple(page.givens(t) for t in (nm.B2n, -nm.A2n)))
    g_app_expr = sympy.Add(*g_app, evaluate=False) if len(g_app) > 1 else g_app[0]
    g_lhs = sympy.Mul(e, g_app_expr, evaluate=False)
    if g_app != (nm.A1n, -nm.B1n) or g_sep != (nm.B2n, -nm.A2n):
        lines.append(Eqn((Side((g_lhs,)), Side(g_sep)), implies=True))
    if page.has_values(g_lhs) or any(page.has_values(t) for t in g_sep):
        lines.append(Eqn((Side((g_lhs,), "values"), Side(g_sep, "values"))))
    order = (nm.A2n,) if page.p.fixed_B else (nm.B2n, nm.A2n)
    terms, const = collected(page, sympy.Add(*g_sep), e * sympy.Add(*g_app), order)
    lines.append(_collected_line(page, terms, const, 4))
    text: Text = (IMPACT_RULE,)
    ev = page.numeric.get(e)
    if ev == 1:
        text += (" Here ", Math(sympy.Eq(e, 1)), ": the impact is perfectly elastic.")
    elif ev == 0:
        text += (" Here ", Math(sympy.Eq(e, 0)), ": the impact is perfectly plastic.")
    return Block(text, tuple(lines)), const[0], page.num(sympy.Add(*g_sep) - e * sympy.Add(*g_app))
