"""Rule ``givens``: the values in the Given list and in each substitution line are this
problem's (or this stage's) givens, not another stage's or another body's.

- A Given line ``m_A = ... = 3 kg`` states the value of m_A here; when it is
  wrong, the reason names whose value it is (m_B of this stage, m_C of the chain).
- A substitution line (the numbers put in for the letters of the line above
  it) is matched term by term with the line above: in each term the numbers
  must be the values of the letters they replace.
"""

from __future__ import annotations

from collections.abc import Iterator

from derive.verifier.evaluate import DEGREE, mpf
from derive.verifier.judge import Claim, Judge, lone_number, signed_value
from derive.verifier.report import Failure
from derive.verifier.tree import Add, Frac, Func, Mul, Num, Pow, Sym

RULE = "givens"


def _whose(judge: Judge, value: object, h: object, skip: str, here: str) -> str | None:
    """Which given has this value: of this part of the page first, then of any other."""
    near = [s.key for s in judge.chain_of(here)]
    order = near + [k for k in judge.facts.scopes if k not in near]
    for key in order:
        scope = judge.facts.scopes[key]
        for q in scope.quantities.values():
            if q.role in ("given",) and q.name != skip and q.value is not None and abs(q.value - value) <= h:
                where = "this problem" if key == "" else ("the chain" if key.startswith("chain") else key)
                where = "this stage" if key == here and key else where
                return f"{q.name} of {where}"
    return None


def _given_line(judge: Judge, claim: Claim) -> str | None:
    rel = claim.relations[0] if claim.relations else None
    if rel is None or len(rel.sides) < 2 or not isinstance(rel.sides[0].expr, Sym):
        return None
    name = rel.sides[0].expr.name
    scopes = judge.chain_of(claim.line.scope)
    q = judge.quantity(name, scopes)
    last, num = rel.sides[-1], lone_number(rel.sides[-1])
    if q is None or q.value is None or num is None or num.degrees:
        return None
    try:
        shown = judge.value(last, scopes)
    except (ArithmeticError, LookupError):
        return None
    h = judge.halfwidth(num, scopes) + mpf("1e-20") * max(1, abs(q.value))
    if abs(shown.center - q.value) <= h:
        return None
    other = _whose(judge, shown.center, h, name, claim.line.scope)
    where = f"; {signed_value(last)} is {other}" if other else ""
    return f"{name} here is {float(q.value):.6g}{where}"


def _leaves(node: object, power: int = 1) -> Iterator[tuple[object, int]]:
    if isinstance(node, Mul):
        for f in node.factors:
            yield from _leaves(f, power)
    elif isinstance(node, Frac):
        yield from _leaves(node.num, power)
        yield from _leaves(node.den, -power)
    elif isinstance(node, Pow) and isinstance(node.exp, Num) and node.exp.integer:
        yield from _leaves(node.base, power * int(node.exp.mantissa))
    else:
        yield node, power


def _terms(node: object) -> list[object]:
    return [t for _, t in node.terms] if isinstance(node, Add) else [node]


def _compare(judge: Judge, scopes: list, sym: object, num: object) -> Iterator[str]:
    """Term by term: the numbers of ``num`` are the values of the letters of ``sym``."""
    a_terms, b_terms = _terms(sym), _terms(num)
    if len(a_terms) != len(b_terms):
        return
    for ta, tb in zip(a_terms, b_terms, strict=True):
        la, lb = list(_leaves(ta)), list(_leaves(tb))
        if len(la) != len(lb):
            continue
        want, have = [], []
        for (x, px), (y, py) in zip(la, lb, strict=True):
            if isinstance(x, Func) and isinstance(y, Func) and x.name == y.name and len(x.args) == len(y.args):
                for ax, ay in zip(x.args, y.args, strict=True):
                    yield from _compare(judge, scopes, ax, ay)
                continue
            if isinstance(x, Add) and isinstance(y, Add):
                yield from _compare(judge, scopes, x, y)
                continue
            q = judge.quantity(x.name, scopes) if isinstance(x, Sym) else None
            if isinstance(x, Num):
                want.append((mpf(x.value), px, x.text))
            elif q is not None and q.role == "given" and q.value is not None:
                want.append((q.value, px, x.name))
            if isinstance(y, Num):
                have.append((mpf(y.value) * (DEGREE if y.degrees else 1), py, y))
        yield from _match(judge, scopes, want, have)


def _match(judge: Judge, scopes: list, want: list, have: list) -> Iterator[str]:
    if len(want) != len(have) or not want:
        return
    left = list(have)
    for value, power, label in want:
        hit = next(
            (
                h
                for h in left
                if h[1] == power and abs(abs(h[0]) - abs(value)) <= judge.halfwidth(h[2], scopes) + mpf("1e-20")
            ),
            None,
        )
        if hit is None:
            bare = [h for h in left if not h[2].degrees and abs(h[0] * DEGREE - abs(value)) <= mpf("1e-12")]
            if bare and label not in ("",) and not label[0].isdigit():
                yield f"{label} is {bare[0][2].text}° here: the line shows {bare[0][2].text} without its degree sign"
                return
            shown = ", ".join(h[2].text for h in left) or "nothing"
            yield f"{label} is {float(value):.6g} here, but the line shows {shown}"
            return
        left.remove(hit)


def check(judge: Judge) -> Iterator[Failure]:
    """Given lines with another given's value; substitution lines with the wrong numbers."""
    prev: Claim | None = None
    for claim in judge.claims:
        line = claim.line
        reason = None
        if line.kind == "given":
            reason = _given_line(judge, claim)
        elif prev is not None and prev.line.block == line.block and claim.relations and prev.relations:
            reason = _substitution(judge, prev, claim)
        if reason:
            yield Failure(line.number, line.latex, RULE, reason, line.scope)
        prev = claim if line.kind == "display" else None


def _substitution(judge: Judge, prev: Claim, claim: Claim) -> str | None:
    """A line that puts numbers in for the givens of the line above it (the same
    shape, each given letter replaced by a number), checked term by term."""
    a, b = prev.relations[0], claim.relations[0]
    if claim.display is None or claim.display.implies or len(a.sides) < 2 or len(b.sides) < 2:
        return None
    scopes = judge.chain_of(claim.line.scope)
    pairs = [(a.sides[0], b.sides[0]), (a.sides[-1], b.sides[-1])]
    if "given" not in judge.roles(Add(tuple((1, s.expr) for s, _ in pairs)), scopes):
        return None
    if "given" in judge.roles(Add(tuple((1, t.expr) for _, t in pairs)), scopes):
        return None
    if any(_shape(judge, s.expr, scopes) != _shape(judge, t.expr, scopes) for s, t in pairs):
        return None
    for sa, sb in pairs:
        for reason in _compare(judge, scopes, sa.expr, sb.expr):
            return reason
    return None


def _shape(judge: Judge, node: object, scopes: list) -> object:
    """A tree's shape with numbers and given letters as blanks (products in any order)."""
    if isinstance(node, Num):
        return "#"
    if isinstance(node, Sym):
        q = judge.quantity(node.name, scopes)
        return "#" if q is not None and q.role == "given" else node.name
    if isinstance(node, Add):
        return ("+", tuple((s, _shape(judge, t, scopes)) for s, t in node.terms))
    if isinstance(node, Mul):
        return ("*", tuple(sorted(repr(_shape(judge, f, scopes)) for f in node.factors)))
    if isinstance(node, Frac):
        return ("/", _shape(judge, node.num, scopes), _shape(judge, node.den, scopes))
    if isinstance(node, Pow):
        exp = node.exp.text if isinstance(node.exp, Num) else repr(_shape(judge, node.exp, scopes))
        return ("^", _shape(judge, node.base, scopes), exp)
    if isinstance(node, Func):
        return (node.name, tuple(_shape(judge, x, scopes) for x in node.args))
    return type(node).__name__
