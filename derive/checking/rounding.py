"""What a right method gives when its intermediates are rounded to 3 significant figures.

The notes round what they show to three figures and carry those numbers on: the
components before the impact (5 cos 37.6° = 3.96), the numbers of the collected
equations (3) and (4) (19.8 and 9.51), and the velocities after the impact that
the speeds, directions and energies are worked from. An answer worked that way
can miss the exact value by more than its last digit: :func:`rounded_values`
gives what each way of rounding those intermediates yields, so that such an
answer is recognised (and accepted) as the right method with rounded working.
"""

from __future__ import annotations

import itertools
import re
from decimal import Decimal
from typing import TYPE_CHECKING

import sympy

from derive.checking.context import Context
from derive.checking.figures import figures, round_figures
from derive.checking.numeric import listed, number_of
from derive.numbers import to_decimal
from derive.problem import Problem

if TYPE_CHECKING:  # a type only: the answers path must not import the mistakes' model
    from derive.checking.worlds import Pair

#: Significant figures the intermediates are rounded to (the notes' rule).
INTERMEDIATE_FIGURES = 3


def rounded_values(ctx: Context, name: str) -> list[sympy.Expr]:
    """The values of result ``name`` (working unit) when any of the three stages of
    intermediates is rounded: the components before the impact (with masses worked
    out from weights), the numbers of the collected equations, the velocities after
    the impact. Empty for an inverse problem or one with symbolic givens."""
    if ctx.chain or ctx.results[name].value is None:  # a chain: its stages' roundings are not modelled
        return []
    key = ("rounded", name)
    if key not in ctx.memo:  # worked once per result: every wrong answer of that result asks
        ctx.memo[key] = _rounded_values(ctx, name)
    return ctx.memo[key]


def _rounded_values(ctx: Context, name: str) -> list[sympy.Expr]:
    from derive.checking.mistakes.quantities import results_of  # the model: only for an answer not right

    m, p = ctx.model, ctx.problem
    if m.inverse:
        return []
    pre = {c: m.num(x) for c, x in m.pre.items()}
    masses = (m.num(m.m_A), m.num(m.m_B))
    if any(x.free_symbols for x in (*pre.values(), *masses)):
        return []
    # a velocity after the impact is the answer itself: rounding it is the answer's own rounding
    components = {"v_A2t", "v_A2n", "v_B2t", "v_B2n"} if p.oblique else {"v_A2", "v_B2"}
    out = []
    for first, second, third in itertools.product((False, True), repeat=3):
        if not (first or second or third) or (third and name in components):
            continue
        pre_r = {c: _rounded(x, ctx) for c, x in pre.items()} if first else pre
        masses_r = tuple(_round(x) if first and _derived(p, k) else x for k, x in zip("AB", masses, strict=True))
        post = _solve(ctx, pre_r, masses_r, round_constants=second)
        if post is None:
            continue
        if third:
            post = {c: _rounded(x, ctx) for c, x in post.items()}
        if p.fixed_B:
            masses_r = (masses_r[0], sympy.Integer(0))
        q = results_of(p, m.nm, pre_r, post, masses_r, {}, "atan2", m.num).get(name)
        if q is not None and q.value is not None:
            out.append(q.value)
    return out


def _rounded(x: sympy.Expr, ctx: Context) -> sympy.Expr:
    """``x`` at 3 significant figures, unless it is the problem's data as given."""
    return x if x.is_Rational and x in ctx.data else _round(x)


def _round(x: sympy.Expr) -> sympy.Expr:
    """``x`` at 3 significant figures (zero stays zero)."""
    return x if x == 0 else sympy.Rational(str(round_figures(to_decimal(x), INTERMEDIATE_FIGURES)))


def _derived(p: Problem, body: str) -> bool:
    """Whether the mass of ``body`` is worked out from other givens (m = W/g)."""
    try:
        return p.given(f"m_{body}").definition is not None
    except KeyError:
        return False


def _solve(
    ctx: Context, pre: dict[sympy.Symbol, sympy.Expr], masses: tuple[sympy.Expr, ...], round_constants: bool
) -> dict[sympy.Symbol, sympy.Expr] | None:
    """The velocities after the impact from equations (1)-(4) with these numbers; with
    ``round_constants`` the number of each collected equation rounded first."""
    from derive.checking.mistakes.equations import APPROACH_A, APPROACH_B
    from derive.checking.mistakes.records import Variant

    m = ctx.model
    subs = {**pre, APPROACH_A: pre[m.nm.A1n], APPROACH_B: pre[m.nm.B1n], m.m_A: masses[0], m.m_B: masses[1]}
    eqs = []
    for x in m.equations(Variant()).values():
        eq = sympy.expand(m.num(x.xreplace(m.zeros).xreplace(subs)))
        if round_constants:
            eq = _collected(eq, m.unknowns, ctx)
        eqs.append(_numeric(eq))
    sol = sympy.solve(eqs, m.unknowns, dict=True)
    if len(sol) != 1 or set(sol[0]) != set(m.unknowns):
        return None
    return {**sol[0], **{c: v for c, v in m.zeros.items()}}


def _numeric(eq: sympy.Expr) -> sympy.Expr:
    """``eq`` with each irrational number (cos 37.6°, sqrt(2)) at 30 digits. SymPy would
    otherwise solve over the field of those numbers, finding their minimal polynomials: up to
    15 s for a direction in 4.C.11 (issue #19); the values serve to compare an answer with."""
    exact = [a for a in eq.atoms(sympy.Function, sympy.Pow, sympy.NumberSymbol) if not a.free_symbols]
    return eq.xreplace({a: a.evalf(30) for a in exact}) if exact else eq


def _collected(eq: sympy.Expr, unknowns: tuple[sympy.Symbol, ...], ctx: Context) -> sympy.Expr:
    """``eq`` as the notes collect it (one unknown: its coefficient 1), its number rounded."""
    terms = {u: eq.coeff(u) for u in unknowns if eq.coeff(u) != 0}
    const = eq.subs(dict.fromkeys(unknowns, 0))
    if len(terms) == 1:
        ((u, a),) = terms.items()
        return u + _rounded(const / a, ctx)
    return sum((a * u for u, a in terms.items()), sympy.Integer(0)) + _rounded(const, ctx)


def early_numbers(ctx: Context, sides: tuple[str, ...]) -> list[str]:
    """The numbers on a line's sides before the last that are rounded to two figures and are
    not the problem's data (``3.5`` for 4 sin 60 = 3.464)."""
    data = {abs(x) for x in ctx.data if x.is_Rational}
    exact = data | {a * b for a in data for b in data}  # 0.1 = 0.5 x 0.2 (m_A times A's speed): not rounded
    return [
        t
        for t in re.findall(r"(?<![\d.])\d*\.\d+|(?<![\w.])\d{2}(?![\w.])", " ".join(sides[:-1]))
        if figures(Decimal(t)) <= 2 and sympy.Rational(t) not in exact
    ]


def rounded_early(ctx: Context, sides: tuple[str, ...], bad: Pair, pt: dict, truth: dict) -> str:
    """ ": rounded too early …" where the line is worked from numbers the student rounded to
    two figures (not the data: on its sides before the last, the result's own figures are
    not working) and misses the value by more than its last figure, by at most 3 %."""
    early = early_numbers(ctx, sides)
    if not early:
        return ""
    left, right = (number_of(x.xreplace(pt).xreplace(truth)) for x in (bad.left, bad.right))
    if left is None or right is None or not right:
        return ""
    drift = abs(left - right) / max(abs(left), abs(right)) * 100
    if drift > 3 or not _rounding_of(bad.text, early, (left, right)):  # more than rounding explains
        return ""
    return f": rounded too early: worked from {listed(early[:3])}, rounded to 2 figures, it drifts by {drift:.1f} %."


def _rounding_of(text: str, early: list[str], values: tuple) -> bool:
    """Whether each side of ``text`` that is one of the ``early`` numbers alone is the other side's
    true value (``values``: left, right) rounded to its figures: ``78 = 4a + 8b`` where
    4a + 8b is 80 is a number worked wrongly, not 80 rounded (``3.1`` for 3.0505 is)."""
    parts = [t.strip() for t in text.split("=")]
    if len(parts) != 2:
        return True
    for i, t in enumerate(parts):
        other = values[1 - i]
        other = other.real if isinstance(other, complex) and not other.imag else other
        if t in early and isinstance(other, float | int):
            d = Decimal(t)
            unit = Decimal(1).scaleb(d.adjusted() - figures(d) + 1)
            if abs(round_figures(Decimal(str(other)), figures(d)) - d) > unit:
                return False
    return True
