"""A slip in multiplying out a square of a bracket in letters, named as a teacher names it: algebra.

A teacher calls a slip in multiplying out a square of a bracket algebra: a term of it lost or
changed (``2(1 + e)² = 2 + 2e + 2e²``; ``(1 + e)² + (1 − e)² = 2 + 2e``; ``9(1 + e)² = 9 + 18e
+ e²``). Such a slip leaves the line false at the sample points of the givens, where the letters
have become numbers, so the checker's rules for a number worked wrongly would call it
arithmetic; these functions look at the letters themselves. Terms collected or a bracket
multiplied by a number with a number wrong (``2eu − 5eu = 3eu``; ``81e² + 9e² = 80e²``;
``3(v + 5eu) = 3v + 15eu`` written ``3v + 12eu``) stay arithmetic, as teachers mark them; a
bracket's factor taken to some of its terms only (``3(v + 5eu) = 3v + 5eu``) is algebra
(:mod:`.bracketfactors`).
"""

from __future__ import annotations

from dataclasses import replace

import sympy

from derive.checking import bracketfactors, denominators, misread, slipnames, termsigns
from derive.checking.worlds import Pair

#: The kinetic energies a line may name.
ENERGIES = ("T_1", "T_2", "T_lost")

#: The largest denominator of a factor a whole relation is multiplied or divided by.
SIMPLE_DENOMINATOR = 12


def plain(bad: Pair, ctx=None) -> str:
    """The slip of ``bad``, a false pair free of the unknowns: ``algebra`` where one side is a
    square of a bracket in letters multiplied out on the other and the two are not a number
    times each other (a term of the square changed), or where a term in letters was collected
    with its sign lost (:func:`.termsigns.sign_lost`), else ``arithmetic``."""
    left, right = bad.left, bad.right
    if not (left.free_symbols | right.free_symbols) or left == 0 or right == 0 or bad.raw is None:
        return "arithmetic"
    if ctx is not None and (termsigns.sign_lost(ctx, bad) or bracketfactors.partly_multiplied(ctx, bad)):
        return "algebra"
    if denominators.term_not_multiplied(bad):  # (11 − 7e)u/3 + 7eu written 11u/3
        return "algebra"
    if not (_squares(bad.raw[0]) ^ _squares(bad.raw[1])):  # one side the square, the other multiplied out
        return "arithmetic"
    ratio = _ratio(left, right)
    return "arithmetic" if ratio is not None and ratio.is_number else "algebra"


def unknowns_written(bad: Pair, U: tuple[sympy.Symbol, ...]) -> set[sympy.Symbol]:
    """The unknowns ``bad`` holds that its sides as written name (``T_lost = ½(m)(0.84)(36)`` names
    none, though T_lost is worked in the velocities after): the ones an expected line may be in."""
    written = set().union(*(x.free_symbols for x in bad.raw)) if bad.raw else set(U)
    return bad.difference.free_symbols & set(U) & written


def _squares(x: sympy.Expr) -> bool:
    """Whether ``x`` holds a power of a bracket in letters, ``(1 + e)²``."""
    return any(p.base.is_Add and p.base.free_symbols and p.exp.is_Integer and p.exp > 1 for p in x.atoms(sympy.Pow))


def in_letters(trace, bad: Pair, name: str) -> str:
    """``algebra`` for ``name`` ``arithmetic`` where ``bad`` multiplies out the square of a bracket
    in the relation just before it (which held) in the same unknowns and what changed is not its
    number: the number part (free of the unknowns) in letters changed beyond a factor, or the
    terms in the unknowns changed while the number part is that relation's up to a simple
    factor; ``name`` else."""
    if name != "arithmetic" or trace.previous is None:
        return name
    if bracketfactors.from_previous(trace, bad):  # a bracket multiplied out on some of its terms only
        return "algebra"
    U = tuple(trace.U)
    F = _polynomial(bad.difference, U)
    if F is None:
        return name
    names = bad.difference.free_symbols & set(U)
    for p in reversed(trace.previous[1]):
        if p.difference.free_symbols & set(U) != names:
            continue
        G = _polynomial(p.difference, U)
        squared = p.raw is not None and any(_squares(x) for x in p.raw)  # the relation before: a square
        if squared and G is not None and _letters_changed(F, G):
            return "algebra"
        return name
    return name


def _polynomial(expr: sympy.Expr, U: tuple) -> dict | None:
    """``expr`` (= 0) as its coefficients (in the givens' letters) of each monomial in ``U``."""
    try:
        poly = sympy.Poly(sympy.expand(sympy.numer(sympy.together(expr))), *U)
    except (sympy.PolynomialError, sympy.GeneratorsError):
        return None
    return dict(poly.terms())


def _letters_changed(F: dict, G: dict) -> bool:
    """Whether ``F`` is ``G`` with its terms in letters changed, not its number (see
    :func:`in_letters`)."""
    constant = (0,) * len(next(iter(G)))
    terms = (set(F) | set(G)) - {constant}
    if not terms or set(F) - {constant} != set(G) - {constant}:
        return False
    factors = {_ratio(F[m], G[m]) for m in terms}
    f0, g0 = F.get(constant, 0), G.get(constant, 0)
    if len(factors) != 1 or None in factors or not f0 or not g0:
        return False
    c = next(iter(factors))
    if not c.is_number:  # ``k v`` for ``k m v``: the number part must have lost the m too
        c0 = _ratio(f0, g0)
        return c0 is not None and not (c0 / c).is_number
    c0 = _ratio(f0, g0)  # the number as it was (or simply scaled), the terms in the unknowns not
    if c0 is None or not c0.is_number or abs(c) == abs(c0):
        return False
    return abs(c0) == 1 or (not _simple(c) and _simple(c0))


def _ratio(a: sympy.Expr, b: sympy.Expr) -> sympy.Expr | None:
    try:
        return sympy.nsimplify(sympy.cancel(sympy.nsimplify(a) / sympy.nsimplify(b)))
    except (ZeroDivisionError, TypeError, ValueError, sympy.PolynomialError):
        return None


def _simple(c: sympy.Expr) -> bool:
    """A factor a student multiplies or divides a whole relation by (2, ½, 10, ⅓, −1)."""
    return bool(c.is_Rational and c != 0 and c.q <= SIMPLE_DENOMINATOR and abs(c.p) <= 100)


def ke_formula(trace, bad: Pair) -> str:
    """The name (:func:`.slipnames.ke_formula`) where ``bad`` holds in the student's world (the
    velocities as the slips so far left them) with a kinetic energy it names worked by a wrong
    formula: tried before the impact rules' mistakes, which a line about an energy is never."""
    world = trace.world if trace.world is not None else trace.truth
    holds = lambda p: trace.holds([p], world)  # noqa: E731
    return slipnames.ke_formula(trace.ctx, bad, holds) or ("ke_formula" if _copied_energy(trace, bad, holds) else "")


def _copied_energy(trace, bad: Pair, holds) -> bool:
    """Whether ``bad`` names a kinetic energy worked out from a given the student copied wrongly
    (``KE lost = ½m(u − v)²`` after 5 m/s for 4: the energy's side is in that given, no longer
    its name) and holds with that energy by a wrong formula, the given as copied."""
    ctx, copied = trace.ctx, trace.copied
    if not copied or bad.raw is None:
        return False
    derived = ctx.derived()
    sides = {sympy.expand(misread.with_copied(ctx, derived[n][0], copied)): n for n in ENERGIES if n in derived}
    for i, x in enumerate(bad.raw):
        n = sides.get(sympy.expand(x))
        for form in slipnames.wrong_energies(ctx) if n else ():
            if n not in form:
                continue
            put = misread.with_copied(ctx, form[n], copied)
            raw = (put, bad.raw[1]) if i == 0 else (bad.raw[0], put)
            left, right = (ctx.in_unknowns(y) for y in raw)
            if holds(replace(bad, left=left, right=right, raw=raw)):
                return True
    return False
