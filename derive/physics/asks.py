""" "Show that" results and ranges of a letter, decided from the closed forms.

A relation to show holds when its two sides, with every result put in by its closed
form, are equal for all values the letters may take; where SymPy cannot simplify the
difference to zero, it is evaluated at many points of the assumed ranges, and a point
where the sides differ is a counterexample. A range is the set of values of one letter
(e in [0, 1], another letter positive) for which an inequality between results holds.
"""

from __future__ import annotations

import math
import random
from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from derive.physics.results import Result
from derive.problem import Problem
from derive.problem.symbolic import Range, Relation

POINTS = 24


@dataclass(frozen=True)
class Shown:
    """A relation to show, decided: ``lhs``/``rhs`` in the letters; ``holds``; ``how`` it
    was decided ("exactly" or "at N points"); a ``counterexample`` where it fails."""

    relation: Relation
    lhs: sympy.Expr
    rhs: sympy.Expr
    holds: bool
    how: str
    counterexample: dict[sympy.Symbol, float] | None = None
    #: right side minus left, where it was found exactly not to be 0 (a rational function)
    difference: sympy.Expr | None = None


@dataclass(frozen=True)
class Found:
    """A range: ``expr op 0`` in the letter, ``reduced`` once positive factors are
    dropped, and the ``interval`` of the letter where it holds (None if undecided)."""

    range: Range
    expr: sympy.Expr
    reduced: sympy.Expr
    interval: sympy.Set | None
    dropped: tuple[sympy.Expr, ...] = ()
    #: why the interval is None, where the letters are not the cause (too many intervals)
    reason: str = ""


def in_letters(expr: sympy.Expr, problem: Problem, results: Mapping[str, Result]) -> sympy.Expr:
    """``expr`` (in result and given names) in the letters alone: each result by its closed
    form, each direction's tangent as its ratio of components, every number put in."""
    comps = {"theta": ("n", "t"), "beta": ("t", "n")}
    for name, r in results.items():
        kind, _, body = name.partition("_")
        if kind in comps and body in ("A2", "B2"):
            y, x = (results[f"v_{body}{c}"].closed for c in comps[kind])
            speed = sympy.sqrt(y**2 + x**2)
            s = r.symbol
            expr = expr.replace(sympy.tan(s), y / x).replace(sympy.sin(s), y / speed).replace(sympy.cos(s), x / speed)
    subs = {r.symbol: r.closed for r in results.values()}
    for g in problem.givens:  # an unknown given (e = "?") is its result, found by name
        if g.unknown and g.name in results:
            subs.setdefault(g.symbol, results[g.name].closed)
    for g in problem.givens:
        if g.value is None and g.definition is not None:
            subs.setdefault(g.symbol, g.definition)
    out = expr.xreplace(subs)
    for _ in range(4):  # definitions that name other givens
        out = out.xreplace(
            {g.symbol: g.definition for g in problem.givens if g.value is None and g.definition is not None}
        )
    out = out.xreplace(problem.numeric())
    # a letter the closed forms name by its component symbol (v_A1) is the given's letter, with
    # what the given says of it (a speed kept as a letter is positive)
    letters = {g.name: g.symbol for g in problem.givens if g.value is None}
    return out.xreplace({s: letters[s.name] for s in out.free_symbols if s.name in letters})


def decide(rel: Relation, problem: Problem, results: Mapping[str, Result]) -> Shown:
    """Whether ``rel`` follows from the closed forms, for every value of the letters.

    Decided exactly where it can be: the difference of the sides simplifies to 0, or is a
    rational function of the letters, which is identically 0 only if it cancels to 0 (a
    ``+ 1e-30 u`` term never does). Otherwise the sides are compared at points of the letters'
    ranges to 50 digits, and ``how`` says so: a page states that it was not proved.
    """
    lhs, rhs = in_letters(rel.lhs, problem, results), in_letters(rel.rhs, problem, results)
    difference = sympy.simplify(lhs - rhs)
    lhs = sympy.factor(sympy.simplify(lhs))
    if difference == 0:
        return Shown(rel, lhs, rhs, True, "exactly")
    letters = difference.free_symbols
    points = sample(problem, letters)
    if difference.is_rational_function(*letters):
        reduced = sympy.cancel(sympy.together(difference))
        if reduced == 0:
            return Shown(rel, lhs, rhs, True, "exactly")
        point = next((pt for pt in points if _differ(reduced, pt)), points[0] if points else {})
        return Shown(rel, lhs, rhs, False, "exactly", dict(point), sympy.factor(-reduced))
    for point in points:
        if _differ(difference, point):
            return Shown(rel, lhs, rhs, False, f"at {len(points)} points", dict(point))
    return Shown(rel, lhs, rhs, True, f"at {len(points)} points")


def _differ(difference: sympy.Expr, point: Mapping[sympy.Symbol, float]) -> bool:
    """True where ``difference`` is a real number other than 0 at ``point`` (to 50 digits)."""
    exact = {s: sympy.Rational(repr(v)) for s, v in point.items()}
    try:
        value = complex(sympy.N(difference.xreplace(exact), 50))
    except (TypeError, ValueError, ZeroDivisionError):
        return False
    if not (math.isfinite(value.real) and math.isfinite(value.imag)):
        return False
    scale = 1 + sum(abs(float(v)) for v in exact.values())
    return abs(value) > 1e-40 * scale


def sample(problem: Problem, letters: set[sympy.Symbol], n: int = POINTS) -> list[dict[sympy.Symbol, float]]:
    """Points of the letters' assumed ranges: e in (0, 1), an acute angle in (0°, 90°),
    another letter positive (or any sign where assumed real), reproducibly."""
    rng = random.Random(7)
    words = {g.symbol: problem.assume.get(g.name, "") for g in problem.givens}
    angles = {g.symbol for g in problem.givens if g.unit == "deg"}
    out = []
    for _ in range(n):
        point = {}
        for s in sorted(letters, key=str):
            word = words.get(s, "")
            if s.name == "e":
                point[s] = rng.uniform(0.05, 0.95)
            elif word == "acute" or s in angles:
                point[s] = rng.uniform(0.1, 1.4)  # radians, within (0°, 90°)
            elif word in ("real",):
                point[s] = rng.uniform(-3, 3)
            elif word == "negative":
                point[s] = -rng.uniform(0.3, 3)
            else:
                point[s] = rng.uniform(0.3, 3)
        out.append(point)
    return out


#: The SymPy relation of each operator a range may use.
RELATIONS = {"<": sympy.StrictLessThan, "<=": sympy.LessThan, ">": sympy.StrictGreaterThan, ">=": sympy.GreaterThan}
#: The most intervals a range lists (a periodic inequality over [0, 1] may have more).
MAX_INTERVALS = 50
#: Points of the domain at which a range found is checked against the inequality itself.
CHECK_POINTS = 400


def solve_range(rng: Range, problem: Problem, results: Mapping[str, Result]) -> Found:
    """The values of ``rng.of`` (e within [0, 1], another letter positive) where the
    inequality holds, the other letters taken positive. A periodic inequality is solved
    over one period and repeated over the domain (``sin(100 e) > 0``: 16 intervals in
    [0, 1]); every set found is checked at points of the domain, and one that disagrees
    with the inequality is not printed (``reason`` says why)."""
    expr = sympy.factor(in_letters(rng.lhs, problem, results) - in_letters(rng.rhs, problem, results))
    x = rng.of
    reduced, dropped = drop_positive(expr, x)
    domain = sympy.Interval(0, 1) if x.name == "e" else sympy.Interval.open(0, sympy.oo)
    if reduced.free_symbols - {x}:
        return Found(rng, expr, reduced, None, dropped)
    reduced, signless, why = _without_signless(reduced, x, domain)
    dropped += signless
    if why:
        return Found(rng, expr, reduced, None, dropped, why)
    holds = RELATIONS[rng.op](reduced, 0)
    try:
        period = sympy.periodicity(reduced, x) if reduced.has(sympy.sin, sympy.cos, sympy.tan) else None
        if period is not None and period != 0:
            found, reason = _periodic(holds, x, period, domain)
        else:
            found = sympy.solve_univariate_inequality(holds, x, relational=False).intersect(domain)
            reason = ""
    except (NotImplementedError, ValueError, TypeError):
        return Found(rng, expr, reduced, None, dropped, "derive could not work out this set")
    if found is not None and not _agrees(found, rng.op, reduced, x, domain):
        found, reason = None, "derive could not work out this set exactly"
    return Found(rng, expr, reduced, found, dropped, reason)


#: The highest degree of a polynomial factor with roots in the domain that a range solves.
MAX_DEGREE = 4


def _without_signless(
    reduced: sympy.Expr, x: sympy.Symbol, domain: sympy.Interval
) -> tuple[sympy.Expr, tuple[sympy.Expr, ...], str]:
    """``reduced`` without its polynomial factors of high degree that have no root in the domain
    (their sign, constant there, is kept as ±1): decided exactly by counting roots (Sturm),
    where solving them would take SymPy minutes (``v_A2^63 < v_B2^63``). A factor of high degree
    with a root in the domain is not solved: the reason says so. Returns the rest, the factors
    dropped (each made positive), and the reason."""
    factors = reduced.args if isinstance(reduced, sympy.Mul) else (reduced,)
    kept: list[sympy.Expr] = []
    dropped: list[sympy.Expr] = []
    for f in factors:
        base, power = f.as_base_exp()
        if not base.is_polynomial(x) or not base.has(x) or not power.is_Integer:
            kept.append(f)
            continue
        poly = sympy.Poly(base, x)
        if poly.degree() <= MAX_DEGREE:
            kept.append(f)
            continue
        hi = None if domain.sup == sympy.oo else domain.sup
        if poly.count_roots(domain.inf, hi) > 0:
            return (
                reduced,
                (),
                (
                    f"it has a factor of degree {poly.degree()} in {x} with a root in the range, which derive does not solve"
                ),
            )
        middle = domain.inf + 1 if hi is None else (domain.inf + hi) / 2
        sign = sympy.Integer(1 if poly.eval(middle) > 0 else -1) ** power
        kept.append(sign)
        dropped.append(sign * f)
    return sympy.Mul(*kept), tuple(dropped), ""


def _periodic(holds: sympy.Basic, x: sympy.Symbol, period: sympy.Expr, domain: sympy.Interval):
    """The set where a periodic inequality ``holds`` within ``domain``: one period solved, then
    repeated; (None, why) where the domain holds more periods than a page lists."""
    if domain.sup == sympy.oo:
        return None, f"it holds on intervals that repeat every {period} without end, which derive does not list"
    count = int(sympy.ceiling((domain.sup - domain.inf) / period))
    one = sympy.solve_univariate_inequality(holds, x, relational=False, domain=sympy.Interval.Ropen(0, period))
    per = len(one.args) if isinstance(one, sympy.Union) else 1
    if count * per > MAX_INTERVALS + 2 * per:
        return None, (
            f"it holds on about {count * per} separate intervals (it repeats every {period}), "
            f"more than derive lists ({MAX_INTERVALS})"
        )
    pieces = [_shift(one, k * period) for k in range(int(sympy.floor(domain.inf / period)), count + 1)]
    return sympy.Union(*pieces).intersect(domain), ""


def _shift(found: sympy.Set, d: sympy.Expr) -> sympy.Set:
    """``found`` moved by ``d``."""
    if isinstance(found, sympy.Interval):
        return sympy.Interval(found.start + d, found.end + d, found.left_open, found.right_open)
    if isinstance(found, sympy.Union):
        return sympy.Union(*(_shift(a, d) for a in found.args))
    if isinstance(found, sympy.FiniteSet):
        return sympy.FiniteSet(*(a + d for a in found.args))
    return found


def _agrees(found: sympy.Set, op: str, reduced: sympy.Expr, x: sympy.Symbol, domain: sympy.Interval) -> bool:
    """Whether ``found`` is the set where ``reduced op 0`` at points spread over the domain
    (points where ``reduced`` is about 0, on a boundary, are not judged)."""
    test = {"<": float.__lt__, "<=": float.__le__, ">": float.__gt__, ">=": float.__ge__}[op]
    pieces = _pieces(found)
    if pieces is None:
        return False
    top = 1.0 if domain.sup != sympy.oo else 50.0
    low = float(domain.inf)
    for k in range(CHECK_POINTS):
        point = low + (top - low) * (k + 0.5 + 0.1234567 * math.sin(k)) / CHECK_POINTS
        try:
            value = complex(sympy.N(reduced.xreplace({x: sympy.Float(point, 30)}), 20))
        except (TypeError, ValueError, ZeroDivisionError):
            continue
        if not math.isfinite(value.real) or abs(value.imag) > 1e-9 or abs(value.real) < 1e-9:
            continue
        if _inside(pieces, point) != test(value.real, 0.0):
            return False
    return True


def _pieces(found: sympy.Set) -> list[tuple[float, float, bool, bool]] | None:
    """``found`` as intervals of floats (start, end, open at start, open at end); None if it is
    not a union of intervals and points."""
    out = []
    for part in found.args if isinstance(found, sympy.Union) else (found,):
        if isinstance(part, sympy.Interval):
            out.append((float(part.start), float(part.end), bool(part.left_open), bool(part.right_open)))
        elif isinstance(part, sympy.FiniteSet):
            out += [(float(a), float(a), False, False) for a in part.args]
        elif part is not sympy.S.EmptySet:
            return None
    return out


def _inside(pieces: list[tuple[float, float, bool, bool]], point: float) -> bool:
    return any(a < point < b or (point == a and not lo) or (point == b and not hi) for a, b, lo, hi in pieces)


def drop_positive(expr: sympy.Expr, x: sympy.Symbol) -> tuple[sympy.Expr, tuple[sympy.Expr, ...]]:
    """``expr`` without the factors known to be positive (u, m, 3, u^2): the sign is kept."""
    if not isinstance(expr, sympy.Mul):
        return expr, ()
    kept, dropped = [], []
    for f in expr.args:
        if not f.has(x) and f.is_positive:
            dropped.append(f)
        else:
            kept.append(f)
    return sympy.Mul(*kept), tuple(dropped)
