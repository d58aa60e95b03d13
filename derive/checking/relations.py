"""Equations as ``lhs - rhs`` in the unknowns: compared up to a factor, solved with the
others, satisfied by a set of velocities, and shown the way the notes collect them.

Every comparison is made at sample points of the symbolic givens (one empty point
where every given has a number), with a relative tolerance for the decimals written.
"""

from __future__ import annotations

import functools

import mpmath
import sympy

from derive.checking.mistakes import Outcome
from derive.checking.numeric import coefficient, is_negative, number_of, plain
from derive.checking.polyroots import polynomial_roots

Point = dict[sympy.Symbol, sympy.Expr]
Values = dict[sympy.Symbol, sympy.Expr]


@functools.lru_cache(maxsize=4096)
def coefficients(expr: sympy.Expr, U: tuple[sympy.Symbol, ...]) -> dict[tuple[int, ...], complex] | None:
    """The numeric coefficient of each monomial of ``expr`` in ``U`` (None where not a polynomial).
    Cached: the mistakes' equations are compared with every wrong line (do not change the result)."""
    try:
        poly = sympy.Poly(sympy.expand(sympy.numer(sympy.together(expr))), *U)
    except (sympy.PolynomialError, sympy.GeneratorsError):
        return None
    out = {}
    for m, c in poly.terms():
        x = number_of(c)
        if x is None:
            return None
        out[m] = x
    return out


def cosine(a: dict, b: dict, keys: list) -> float:
    """|cos| of the angle between two coefficient vectors over the monomials ``keys``."""
    dot = sum(a.get(m, 0) * b.get(m, 0) for m in keys)
    na = sum(abs(a.get(m, 0)) ** 2 for m in keys) ** 0.5
    nb = sum(abs(b.get(m, 0)) ** 2 for m in keys) ** 0.5
    return abs(dot) / (na * nb) if na and nb else 0.0


def proportional(a: sympy.Expr, b: sympy.Expr, U: tuple[sympy.Symbol, ...], pts: list[Point], tol: float) -> bool:
    """Whether equations ``a = 0`` and ``b = 0`` are the same up to a nonzero factor (a function
    of an unknown, ``sin(alpha)`` where α is asked, compared as a letter of its own)."""
    a, b, U = functions_as_letters(a, b, U)
    for pt in pts:
        ca, cb = coefficients(a.xreplace(pt), U), coefficients(b.xreplace(pt), U)
        if not ca or not cb:
            return False
        key = max(cb, key=lambda m: abs(cb[m]))
        if abs(ca.get(key, 0)) == 0:
            return False
        c = ca[key] / cb[key]
        scale = abs(cb[key])
        for m in set(ca) | set(cb):
            if abs(ca.get(m, 0) - c * cb.get(m, 0)) > max(tol, 1e-12) * abs(c) * scale:
                return False
    return True


def functions_as_letters(
    a: sympy.Expr, b: sympy.Expr, U: tuple[sympy.Symbol, ...]
) -> tuple[sympy.Expr, sympy.Expr, tuple[sympy.Symbol, ...]]:
    """``a`` and ``b`` with each function of an unknown (``sin(alpha)``, ``cos(alpha)`` where α is
    asked) put as a letter of its own, the same in both, and the unknowns with those letters: the
    two are then polynomials to compare term by term (not a polynomial in α itself)."""
    unknown = set(U)
    found = {f for x in (a, b) for f in x.atoms(sympy.Function) if f.free_symbols & unknown}
    if not found:
        return a, b, U
    letters = {f: sympy.Symbol(f"<{f}>") for f in sorted(found, key=str)}
    return a.xreplace(letters), b.xreplace(letters), (*U, *letters.values())


#: The systems solved so far (a slip is solved in its rules' turn, the same system more than once).
_SOLVED: dict[tuple, list[list[Values]] | None] = {}


def solve_with(
    F: sympy.Expr, equations: dict[int, sympy.Expr], k: int, U: tuple[sympy.Symbol, ...], pts: list[Point]
) -> list[list[Values]] | None:
    """Solve ``equations`` with (k) replaced by ``F = 0``, at each point: the roots there (each
    system once: remembered for the rules that ask again; the roots are not to be changed)."""
    key = (F, tuple(sorted(equations.items())), k, tuple(U), tuple(tuple(sorted(p.items(), key=str)) for p in pts))
    if key not in _SOLVED:
        if len(_SOLVED) > 512:
            _SOLVED.clear()
        _SOLVED[key] = _solve_with(F, equations, k, U, pts)
    return _SOLVED[key]


def _solve_with(
    F: sympy.Expr, equations: dict[int, sympy.Expr], k: int, U: tuple[sympy.Symbol, ...], pts: list[Point]
) -> list[list[Values]] | None:
    out = []
    for pt in pts:
        fast = linear_roots([x.xreplace(pt) for j, x in equations.items() if j != k] + [F.xreplace(pt)], U)
        if fast == []:  # singular: no single root
            return None
        if fast is not None:
            out.append(fast)
            continue
        taken = _taken_apart([x.xreplace(pt) for j, x in equations.items() if j != k] + [F.xreplace(pt)], U)
        if taken is not None:  # elimination in floating point, not SymPy's Gröbner basis
            if not taken:
                return None
            out.append(taken)
            continue
        cf = coefficients(F.xreplace(pt), U)
        if cf is None or any(sum(m) > 2 for m in cf):  # beyond a quadratic: not an equation of this impact
            return None
        # exact rationals: a polynomial system in floats sends SymPy's solver down paths that
        # take minutes (e unknown: the impact rule is bilinear in e and the velocities)
        eqs = [_rational(x.xreplace(pt)) for j, x in equations.items() if j != k]
        eqs.append(_rational(sympy.numer(sympy.together(F.xreplace(pt)))))
        try:
            roots = sympy.solve(eqs, list(U), dict=True)
        except (NotImplementedError, ValueError, TypeError):
            return None
        roots = [r for r in roots if set(r) == set(U)]
        if not roots:
            return None
        out.append(roots)
    return out


def _rational(x: sympy.Expr) -> sympy.Expr:
    """``x`` with its numbers as exact rationals (at 30 digits)."""
    return sympy.nsimplify(sympy.N(x, 30), rational=True)


def linear_roots(eqs: list[sympy.Expr], U: tuple[sympy.Symbol, ...]) -> list[Values] | None:
    """The one root of a square linear system with numeric coefficients, by elimination in
    floating point (SymPy's solver takes a hundred times longer); [] where it is singular
    (no single root); None where it is not square or not linear (the caller then asks SymPy)."""
    rows = []
    for eq in eqs:
        cf = coefficients(eq, U)
        if cf is None or any(sum(m) > 1 for m in cf) or len(eqs) != len(U):
            return None
        rows.append([cf.get(tuple(int(i == j) for i in range(len(U))), 0) for j in range(len(U))])
        rows[-1].append(-cf.get((0,) * len(U), 0))
    n = len(U)
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(rows[r][c]))
        if abs(rows[p][c]) < 1e-12 * max(1.0, max(abs(x) for x in rows[p][:n])):
            return []
        rows[c], rows[p] = rows[p], rows[c]
        for r in range(n):
            if r != c:
                f = rows[r][c] / rows[c][c]
                rows[r] = [a - f * b for a, b in zip(rows[r], rows[c], strict=True)]
    return [{u: _real(rows[i][n] / rows[i][i]) for i, u in enumerate(U)}]


def _real(z: complex) -> sympy.Expr:
    return (
        sympy.Float(z.real, 20) if abs(z.imag) <= 1e-12 * max(1.0, abs(z)) else sympy.Float(z.real) + sympy.I * z.imag
    )


def matches(
    roots: list[list[Values]], outcome: Outcome, U: tuple[sympy.Symbol, ...], pts: list[Point], tol: float
) -> bool:
    """Whether, at every point, one of ``roots`` is ``outcome``'s velocities."""
    slack = max(5 * tol, 1e-8)
    for found, pt in zip(roots, pts, strict=True):
        target = {}
        for u in U:
            x = number_of(outcome.post[u].xreplace(pt))
            if x is None:
                return False
            target[u] = x
        # each unknown within the slack of its own size (a tenth of the largest at least): a
        # small component is not hidden by a large one (23.7 for 19.8 in (3) moved v_A2n by 14 %)
        big = max([abs(v) for v in target.values()] + [1e-12])
        scales = {u: slack * max(abs(target[u]), 0.1 * big) for u in U}
        if not any(_same(r, target, U, scales) for r in found):
            return False
    return True


def _same(
    root: Values, target: dict[sympy.Symbol, complex], U: tuple[sympy.Symbol, ...], slack: dict[sympy.Symbol, float]
) -> bool:
    vals = [number_of(root[u]) for u in U]
    if any(v is None for v in vals):
        return False
    return all(abs(v - target[u]) <= slack[u] for v, u in zip(vals, U, strict=True))


def satisfied(F: sympy.Expr, post: Values, U: tuple[sympy.Symbol, ...], pts: list[Point], tol: float) -> bool:
    """Whether the velocities ``post`` satisfy ``F = 0`` at every point, within ``tol``
    of the largest term."""
    for pt in pts:
        G = sympy.expand(sympy.numer(sympy.together(F.xreplace(pt))))
        sol = {u: post[u].xreplace(pt) for u in U}
        terms = G.args if isinstance(G, sympy.Add) else (G,)
        vals = [number_of(t.xreplace(sol)) for t in terms]
        if any(v is None for v in vals):
            return False
        scale = max(abs(v) for v in vals) if vals else 0
        if scale == 0:
            return False
        if abs(sum(vals)) > max(tol, 1e-9) * scale * 2 * (1 - 1e-9):  # exactly two units off is not within
            return False
    return True


def shown(expr: sympy.Expr, U: tuple[sympy.Symbol, ...], first: tuple[sympy.Symbol, ...] = ()) -> str:
    """``expr = 0`` collected as the notes write it: ``20 v_A2n + 5 v_B2n = 19.81``
    (the unknowns in ``first`` leading; one unknown solved for)."""
    U = list(first) + [u for u in U if u not in first]
    try:
        poly = sympy.Poly(sympy.expand(sympy.numer(sympy.together(expr))), *U)
    except sympy.PolynomialError:
        return plain(expr) + " = 0"
    terms = [(m, c) for m, c in poly.terms() if any(m)]
    const = poly.coeff_monomial(1)
    if not terms:
        return plain(expr) + " = 0"
    terms.sort(key=lambda mc: (-sum(mc[0]), [-x for x in mc[0]]))
    sign = -1 if is_negative(terms[0][1]) else 1
    if len(terms) == 1:  # one unknown: solved for it
        sign = sympy.Integer(1) / terms[0][1]
    out = ""
    for i, (m, c) in enumerate(terms):
        c = sign * c
        mono = "*".join(u.name + (f"^{p}" if p > 1 else "") for u, p in zip(U, m, strict=True) if p)
        neg = is_negative(c)
        mag = -c if neg else c
        piece = f"{'' if mag == 1 else coefficient(mag) + ' '}{mono}"
        if i == 0:
            out = ("-" if neg else "") + piece
        else:
            out += (" - " if neg else " + ") + piece
    return f"{out} = {coefficient(-sign * const) if const != 0 else '0'}"


def nonlinear_roots(eqs: list[sympy.Expr], U: tuple[sympy.Symbol, ...]) -> list[Values]:
    """The roots of ``eqs = 0`` (numbers in, 30 digits) that fix every unknown: by elimination in
    floating point (:mod:`.polyroots`), or where that cannot take the system apart, SymPy's ``solve``
    (a Gröbner basis over floats: seconds, where elimination takes milliseconds)."""
    return [dict(root) for root in _nonlinear_roots(tuple(eqs), tuple(U))]


@functools.lru_cache(maxsize=256)
def _nonlinear_roots(
    eqs: tuple[sympy.Expr, ...], U: tuple[sympy.Symbol, ...]
) -> tuple[tuple[tuple[sympy.Symbol, sympy.Expr], ...], ...]:
    """:func:`nonlinear_roots`, kept for the process (a world of the same equations at the same
    point is solved again for each line, rule and mistake that asks; SymPy's solve is seconds)."""
    found = polynomial_roots(list(eqs), U)
    if found is not None:
        return tuple(tuple((u, _real(z)) for u, z in r.items()) for r in found)
    try:
        roots = sympy.solve(list(eqs), list(U), dict=True, rational=False)
    except (NotImplementedError, ValueError, TypeError, mpmath.libmp.NoConvergence):  # 10^22 as a speed: none
        return ()
    return tuple(tuple(r.items()) for r in roots if set(r) == set(U))


def _taken_apart(eqs: list[sympy.Expr], U: tuple[sympy.Symbol, ...]) -> list[Values] | None:
    """The roots of the impact's equations with the student's last (no more than a quadratic)
    by elimination (:mod:`.polyroots`); None where it cannot take them apart."""
    cf = coefficients(eqs[-1], U)
    if cf is None or any(sum(m) > 2 for m in cf):
        return None
    found = polynomial_roots([sympy.N(sympy.numer(sympy.together(x)), 30) for x in eqs], U)
    return None if found is None else [{u: _real(z) for u, z in r.items()} for r in found]
