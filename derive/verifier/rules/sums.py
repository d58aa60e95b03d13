"""Rule ``sums``: the terms shown in a sum add up to the total shown.

A reader adds the numbers as written: ``79.23 - 59.42`` must give the 19.81
shown (on the same line, or as the total of the next line, as in ``79.23 -
59.42 = 20 v_A2n + 5 v_B2n`` then ``20 v_A2n + 5 v_B2n = 19.81``), and
``T_lost = T_1 - T_2 = 321 J`` must agree with the 813 J and 491 J shown for
T_1 and T_2: the sum of the terms as shown, rounded as the total is, is the total.
"""

from __future__ import annotations

from collections.abc import Iterator
from decimal import Decimal

from derive.mathtext.tree import Add, Num, ParsedRelation, Side, Sym
from derive.verifier.judge import Claim, Judge, is_result, lone_number, signed_value
from derive.verifier.report import Failure

RULE = "sums"


def _term(node: object, shown: dict[str, Decimal]) -> Decimal | None:
    """A term's value as written: a number, or a name whose value is shown above (a product
    of rounded numbers is left to the rule ``equals``, which allows for its rounding)."""
    if isinstance(node, Num) and not node.degrees:
        return node.value
    if isinstance(node, Sym):
        return shown.get(node.name)
    return None


def numeric_sum(side: Side, shown: dict[str, Decimal]) -> tuple[Decimal, int] | None:
    """The sum of a side of two or more terms, each known as written; and how many were names."""
    expr = side.expr
    if not isinstance(expr, Add) or len(expr.terms) < 2:
        return None
    total, names = Decimal(0), 0
    for sign, term in expr.terms:
        v = _term(term, shown)
        if v is None:
            return None
        total += sign * v
        names += isinstance(term, Sym)
    return total, names


def _mismatch(judge: Judge, claim: Claim, total: Decimal, side: Side, result: bool) -> str | None:
    num = lone_number(side)
    value = signed_value(side)
    if num is None or value is None:
        return None
    h = judge.halfwidth(num, judge.chain_of(claim.line.scope), result)
    if abs(total - value) <= Decimal(str(h)) * Decimal("1.000001"):
        return None
    shown = f"{total.normalize():f}" if total == 0 or Decimal("1e-4") <= abs(total) < Decimal("1e6") else f"{total:.4g}"
    return f"the terms add up to {shown}, not {num.text}"


def _shown_values(judge: Judge) -> dict[int, dict[str, Decimal]]:
    """For each line, the value last shown above it for each name (x = ... = number)."""
    out: dict[int, dict[str, Decimal]] = {}
    current: dict[str, dict[str, Decimal]] = {}
    for claim in judge.claims:
        scope = claim.line.scope
        out[id(claim)] = dict(current.get(scope, {}))
        for rel in claim.relations:
            first, last = rel.sides[0], rel.sides[-1]
            value = signed_value(last)
            if len(rel.sides) >= 2 and isinstance(first.expr, Sym) and value is not None:
                current.setdefault(scope, {})[first.expr.name] = value
    return out


def _same_line(judge: Judge, claim: Claim, rel: ParsedRelation, shown: dict[str, Decimal]) -> Iterator[str]:
    """A sum and a total on one line. Names stand for the values shown for them above,
    unless the line writes their numbers out itself (T_1 - T_2 = 812.5 - 491.1 = 321)."""
    written = any(numeric_sum(side, {}) is not None for side in rel.sides)
    for i, side in enumerate(rel.sides):
        found = numeric_sum(side, {} if written else shown)
        if found is None:
            continue
        for j, other in enumerate(rel.sides):
            if j != i and lone_number(other) is not None:
                reason = _mismatch(judge, claim, found[0], other, is_result(claim, rel, j))
                if reason:
                    yield reason
                return


def _next_line(judge: Judge, claim: Claim, nxt: Claim | None) -> Iterator[str]:
    if nxt is None or nxt.line.block != claim.line.block or not nxt.relations or not claim.relations:
        return
    rel, follow = claim.relations[0], nxt.relations[0]
    if len(rel.sides) != 2 or len(follow.sides) < 2:
        return
    for i in (0, 1):
        found = numeric_sum(rel.sides[i], {})
        other = rel.sides[1 - i]
        if found is not None and follow.sides[0].source == other.source:
            reason = _mismatch(judge, nxt, found[0], follow.sides[-1], is_result(nxt, follow, len(follow.sides) - 1))
            if reason:
                yield reason


def check(judge: Judge) -> Iterator[Failure]:
    """Sums on a line and sums carried to the next line's total."""
    shown = _shown_values(judge)
    claims = judge.claims
    for k, claim in enumerate(claims):
        reasons = [r for rel in claim.relations for r in _same_line(judge, claim, rel, shown[id(claim)])]
        reasons += list(_next_line(judge, claim, claims[k + 1] if k + 1 < len(claims) else None))
        if reasons:
            line = claim.line
            yield Failure(line.number, line.latex, RULE, reasons[0], line.scope)
