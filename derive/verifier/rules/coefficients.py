"""Rule ``equals`` for a closed form in letters: each coefficient shown is the rounding of
the exact coefficient, not only the whole side at one sample value of the letters.

``T_lost = m_A v_A1^2 (e + 1)(1 - e)/2 = (123 - 123 e^2) J`` holds at one value of e
within the rounding of both 123s together, and so would ``123 - 122 e^2``. Here the
side in letters (a polynomial: each term a number times a product of letters kept
symbolic) is compared with an exact side of the same line that writes the same
letters out: the exact side is valued at as many points of the letters as the
polynomial has terms, which gives its exact coefficients, and a point more checks
that it is that polynomial. Each number must then be its coefficient rounded, as a
value shown alone would be (a coefficient exactly half way may be rounded either way:
derive writes 11.0 e^2 for 11.05 e^2 on some variant pages).
"""

from __future__ import annotations

from collections.abc import Iterator

from derive.mathtext.tree import Add, Mul, Num, ParsedRelation, Pow, Side, Sym
from derive.verifier import units
from derive.verifier.evaluate import CTX, Undefined, Unresolved, mpf, walk
from derive.verifier.judge import Claim, Judge
from derive.verifier.report import Failure

RULE = "equals"
#: factors that move each letter away from its sample value, one point after another
_STEPS = (0.71, 1.37, 0.53, 1.91, 0.87, 1.23, 0.61, 1.53, 0.97, 1.71)

Term = tuple[int, Num | None, tuple[tuple[str, int], ...]]


def _poly(expr: object) -> list[Term] | None:
    """The terms ``sign, number, letters`` of a polynomial side (None for any other form)."""
    out: list[Term] = []
    for sign, term in expr.terms if isinstance(expr, Add) else ((1, expr),):
        num: Num | None = None
        powers: dict[str, int] = {}
        for f in term.factors if isinstance(term, Mul) else (term,):
            if isinstance(f, Num) and not f.degrees and num is None:
                num = f
            elif isinstance(f, Sym):
                powers[f.name] = powers.get(f.name, 0) + 1
            elif isinstance(f, Pow) and isinstance(f.base, Sym) and isinstance(f.exp, Num) and f.exp.integer:
                powers[f.base.name] = powers.get(f.base.name, 0) + int(f.exp.mantissa)
            else:
                return None
        out.append((sign, num, tuple(sorted(powers.items()))))
    return out


def _is_letter(judge: Judge, name: str, scopes: list) -> bool:
    """A name kept symbolic here: a letter, or a chain's unknown before its ``solve`` stage."""
    for s in scopes:
        q = s.quantities.get(name)
        if q is not None:
            return q.value is not None and (q.role == "param" or (q.role == "unknown" and s.key in judge.facts.solved))
    return False


def _constant(judge: Judge, name: str, scopes: list, solved: list | None) -> bool:
    """A given whose value does not hang on the letters (the same once a chain's unknown is found)."""
    q = judge.quantity(name, scopes)
    if q is None or q.role != "given" or q.value is None:
        return name == "pi"
    other = judge.quantity(name, solved) if solved else None
    return other is None or other.value == q.value


def _exact_side(judge: Judge, relation: ParsedRelation, k: int, letters: set[str], scopes: list) -> Side | None:
    """A side other than ``k`` that writes the letters out over constant givens, with no rounding."""
    view = judge.solved_view()
    solved = view.chain_of(scopes[0].key) if view is not None else None
    for j, side in enumerate(relation.sides):
        if j == k:
            continue
        names = {n.name for n in walk(side.expr) if isinstance(n, Sym)}
        if not letters <= names:
            continue
        if all(n in letters or _constant(judge, n, scopes, solved) for n in names):
            try:
                if not judge.value(side, scopes).radius:
                    return side
            except (Unresolved, Undefined, ArithmeticError, ValueError, units.UnknownUnit):
                continue
    return None


def _coefficients(judge: Judge, side: Side, terms: list[Term], scopes: list) -> list | None:
    """The exact side's coefficient of each term's letters (None: it is not that polynomial)."""
    letters = sorted({n for _, _, mono in terms for n, _ in mono})
    base = {n: judge.quantity(n, scopes).value for n in letters}
    rows, values = [], []
    for i in range(len(terms) + 1):
        point = {n: base[n] * mpf(_STEPS[(i + 3 * a) % len(_STEPS)]) for a, n in enumerate(letters)}
        rows.append([CTX.fprod(point[n] ** p for n, p in mono) for _, _, mono in terms])
        try:
            values.append(judge.value(side, scopes, overrides=point).center)
        except (Unresolved, Undefined, ArithmeticError, ValueError):
            return None
    try:
        coef = CTX.lu_solve(CTX.matrix(rows[:-1]), CTX.matrix(values[:-1]))
    except ZeroDivisionError:
        return None
    check = CTX.fsum(c * x for c, x in zip(coef, rows[-1], strict=True))
    if abs(check - values[-1]) > CTX.mpf(10) ** -25 * max(1, abs(values[-1])):
        return None
    return list(coef)


def _closed_form(judge: Judge, claim: Claim, relation: ParsedRelation) -> str | None:
    scopes = judge.chain_of(claim.line.scope)
    for k, side in enumerate(relation.sides):
        terms = _poly(side.expr)
        if not terms or all(num is None for _, num, _ in terms) or len({m for _, _, m in terms}) < len(terms):
            continue
        letters = {n for _, _, mono in terms for n, _ in mono}
        if not letters or not all(_is_letter(judge, n, scopes) for n in letters):
            continue
        exact = _exact_side(judge, relation, k, letters, scopes)
        coef = _coefficients(judge, exact, terms, scopes) if exact is not None else None
        if coef is None:
            continue
        factor = 1
        if side.unit is not None:
            factor = mpf(units.to_working(side.unit, scopes[0].system)[0])
        for (sign, num, mono), c in zip(terms, coef, strict=True):
            if num is None:
                continue
            shown = sign * mpf(num.value) * factor
            half = max(judge.halfwidth(num, scopes, True), mpf(num.ulp) / 2) * abs(factor)
            slack = CTX.mpf(10) ** -20 * max(1, abs(c))
            if abs(c - shown) > half + slack:
                what = " ".join(f"{n}^{p}" if p > 1 else n for n, p in mono) or "the constant term"
                return f"the coefficient of {what} is {float(c / factor):.6g}, which does not round to {num.text}"
    return None


def check(judge: Judge) -> Iterator[Failure]:
    """Every closed form in letters on a displayed line, coefficient by coefficient."""
    for claim in judge.claims:
        if claim.line.kind != "display":
            continue
        for relation in claim.relations:
            if len(relation.sides) < 2 or set(relation.ops) != {"="} or judge.axes(relation) != [None]:
                continue
            reason = _closed_form(judge, claim, relation)
            if reason:
                yield Failure(claim.line.number, claim.line.latex, RULE, reason, claim.line.scope)
                break
