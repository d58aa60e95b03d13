"""Rule ``givens``: the values in the Given list and in each substitution line are this
problem's (or this stage's) givens, not another stage's or another body's.

- A Given line ``m_A = ... = 3 kg`` states the value of m_A here; when it is
  wrong, the reason names whose value it is (m_B of this stage, m_C of the chain).
- A substitution line (the numbers put in for the letters of the line above
  it) is matched term by term with the line above: in each term the numbers
  must be the values of the letters they replace.
- So is a side that puts numbers in for the names of the side before it on
  the same line (``v_A1x cos(phi) + v_A1y sin(phi) = 56.5685 cos(20°) + 56.5685 sin(20°)``):
  each number must be the rounding, at the figures shown, of the value of the name it
  replaces (a given, a value worked out above, a root found), not only make the side's
  total come out within the rounding of all its numbers together.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

from derive.mathtext.tree import Add, Frac, Func, Mul, Num, Pow, Side, Sym
from derive.verifier import units
from derive.verifier.evaluate import DEGREE, mpf, walk
from derive.verifier.judge import Claim, Judge, lone_number, signed_value
from derive.verifier.report import Failure

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


def _negated(node: object) -> Num | None:
    """The number of ``-x`` written as a factor or a term: ``\\left(-19.1013\\right)``."""
    if isinstance(node, Add) and len(node.terms) == 1 and node.terms[0][0] == -1 and isinstance(node.terms[0][1], Num):
        return node.terms[0][1]
    return None


def _known(judge: Judge, name: str, scopes: list, wide: bool) -> object | None:
    """The value a name stands for in a substitution: a given's (``wide``: also a value
    worked out or a root found; never a letter's sample value, a chain's unknown before
    its ``solve`` stage included)."""
    for s in scopes:
        q = s.quantities.get(name)
        if q is None:
            continue
        if q.value is None or q.role == "param" or (q.role != "given" and not wide):
            return None
        if q.role == "unknown" and s.key in judge.facts.solved:
            return None
        return q.value
    return None


def _leaves(node: object, power: int = 1) -> Iterator[tuple[object, int]]:
    if _negated(node) is not None:
        yield _negated(node), power
    elif isinstance(node, Mul):
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


def _compare(judge: Judge, scopes: list, sym: object, num: object, wide: bool = False) -> Iterator[str]:
    """Term by term: the numbers of ``num`` are the values of the letters of ``sym``."""
    a_terms, b_terms = _terms(sym), _terms(num)
    if len(a_terms) != len(b_terms):
        return
    for ta, tb in zip(a_terms, b_terms, strict=True):
        la, lb = list(_leaves(ta)), list(_leaves(tb))
        if len(la) != len(lb):
            continue
        want, have = [], []
        kept = {y.name for y, _ in lb if isinstance(y, Sym)}
        for (x, px), (y, py) in zip(la, lb, strict=True):
            if isinstance(x, Func) and isinstance(y, Func) and x.name == y.name and len(x.args) == len(y.args):
                for ax, ay in zip(x.args, y.args, strict=True):
                    yield from _compare(judge, scopes, ax, ay, wide)
                continue
            if isinstance(x, Add) and isinstance(y, Add):
                if _fits(judge, x, y, scopes, wide):
                    yield from _compare(judge, scopes, x, y, wide)
                continue
            known = _known(judge, x.name, scopes, wide) if isinstance(x, Sym) and x.name not in kept else None
            if isinstance(x, Num):
                want.append((mpf(x.value) * (DEGREE if x.degrees else 1), px, x.text))
            elif known is not None:
                want.append((known, px, x.name))
            if isinstance(y, Num):
                have.append((mpf(y.value) * (DEGREE if y.degrees else 1), py, y))
        yield from _match(judge, scopes, want, have, wide)


def _room(judge: Judge, num: Num, scopes: list, wide: bool) -> object:
    """The rounding a number put in for a name may hide (``wide``: a decimal is always
    a rounding there, even one whose digits are a given's)."""
    h = judge.halfwidth(num, scopes)
    if wide and not num.integer:
        h = max(h, mpf(num.ulp) / 2 * (DEGREE if num.degrees else 1))
    return h + mpf("1e-20")


def _match(judge: Judge, scopes: list, want: list, have: list, wide: bool = False) -> Iterator[str]:
    if len(want) != len(have) or not want:
        return
    left = list(have)
    for value, power, label in want:
        # the nearest number that may be this value's rounding (0.4658 for m_A, not 0.5 beside it)
        near = [h for h in left if h[1] == power and abs(abs(h[0]) - abs(value)) <= _room(judge, h[2], scopes, wide)]
        hit = min(near, key=lambda h: abs(abs(h[0]) - abs(value)), default=None)
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
        if reason is None and line.kind == "display":
            reason = _within(judge, claim)
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
    for wide in (False, True):
        if not all(_fits(judge, s.expr, t.expr, scopes, wide) for s, t in pairs):
            continue
        for sa, sb in pairs:
            for reason in _compare(judge, scopes, sa.expr, sb.expr, wide):
                return reason
    return None


def _within(judge: Judge, claim: Claim) -> str | None:
    """A side that puts numbers in for the names of the side before it on the same
    line (the same shape, each name with a value replaced by a number)."""
    scopes = judge.chain_of(claim.line.scope)
    for relation in claim.relations:
        if judge.axes(relation) != [None]:
            continue
        for s, t in itertools.pairwise(relation.sides):
            if isinstance(s.expr, (Sym, Num)) or not _substitutes(judge, s, t, scopes):
                continue
            if not _fits(judge, s.expr, t.expr, scopes, True):
                continue
            for reason in _compare(judge, scopes, s.expr, t.expr, True):
                return reason
    return None


def _substitutes(judge: Judge, s: Side, t: Side, scopes: list) -> bool:
    """``t`` may be ``s`` with numbers put in: ``s`` names a value, ``t`` names none, shows
    a number, and its unit (if any) is the working unit the values are in."""

    def valued(side: Side) -> bool:
        return any(isinstance(n, Sym) and _known(judge, n.name, scopes, True) is not None for n in walk(side.expr))

    if not valued(s) or valued(t) or not any(isinstance(n, Num) for n in walk(t.expr)):
        return False
    if t.unit is None:
        return True
    try:
        factor, _, _ = units.to_working(t.unit, scopes[0].system)
    except units.UnknownUnit:
        return False
    return factor == 1


def _fits(judge: Judge, x: object, y: object, scopes: list, wide: bool = False) -> bool:
    """``y`` is ``x`` with numbers put in for its numbers and its names with a value (given
    letters; ``wide``: every name with a value), other names kept, products in any order;
    signs are not compared (rule ``equals`` does)."""
    if isinstance(y, Num) or _negated(y) is not None:
        return (
            isinstance(x, Num)
            or _negated(x) is not None
            or (isinstance(x, Sym) and _known(judge, x.name, scopes, wide) is not None)
        )
    if isinstance(x, Sym) or isinstance(y, Sym):
        return isinstance(x, Sym) and isinstance(y, Sym) and x.name == y.name
    if type(x) is not type(y):
        return False
    if isinstance(x, Add):
        return len(x.terms) == len(y.terms) and all(
            _fits(judge, a, b, scopes, wide) for (_, a), (_, b) in zip(x.terms, y.terms, strict=True)
        )
    if isinstance(x, Mul):
        left = list(y.factors)
        for f in x.factors:
            hit = next((g for g in left if _fits(judge, f, g, scopes, wide)), None)
            if hit is None and wide:  # a sum worked out another way (8 cos 30° for v_A1n): not compared
                hit = next((g for g in left if _sum_alike(f, g)), None)
            if hit is None:
                return False
            left.remove(hit)
        return not left
    if isinstance(x, Frac):
        return _fits(judge, x.num, y.num, scopes, wide) and _fits(judge, x.den, y.den, scopes, wide)
    if isinstance(x, Pow):
        if isinstance(x.exp, Num) or isinstance(y.exp, Num):
            same = isinstance(x.exp, Num) and isinstance(y.exp, Num) and x.exp.text == y.exp.text
            return same and _fits(judge, x.base, y.base, scopes, wide)
        return _fits(judge, x.base, y.base, scopes, wide) and _fits(judge, x.exp, y.exp, scopes, wide)
    if isinstance(x, Func):
        return (
            x.name == y.name
            and len(x.args) == len(y.args)
            and all(_fits(judge, a, b, scopes, wide) for a, b in zip(x.args, y.args, strict=True))
        )
    return False


def _sum_alike(x: object, y: object) -> bool:
    """Two factors that are both a sum in brackets (perhaps to the same power)."""
    if isinstance(x, Pow) and isinstance(y, Pow) and isinstance(x.exp, Num) and isinstance(y.exp, Num):
        return x.exp.text == y.exp.text and _sum_alike(x.base, y.base)
    return isinstance(x, Add) and isinstance(y, Add) and _negated(x) is None and _negated(y) is None
