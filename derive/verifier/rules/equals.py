"""Rule ``equals``: each ``=`` of a line holds, to the precision shown.

Each side is valued under the facts of its part of the page. A side with no
rounded number in it is exact; every other side must agree with it within the
rounding its own numbers may hide (a rounded number must be the rounding of
the exact value at the figures shown). Without an exact side, neighbouring
sides must agree within their roundings. ``<`` and ``>`` must hold too.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

from derive.mathtext.tree import ParsedRelation
from derive.verifier.judge import Claim, Judge, Value, lone_number, tolerance
from derive.verifier.report import Failure

RULE = "equals"


def show(x: object) -> str:
    """A value for a reason: 6 significant figures."""
    return f"{float(x):.6g}"


def _agree(a: Value, b: Value) -> bool:
    return abs(a.center - b.center) <= a.radius + b.radius + tolerance(a, b)


def _side_text(relation: ParsedRelation, i: int) -> str:
    s = relation.sides[i].source
    return s if len(s) <= 60 else s[:57] + "..."


def _reason(relation: ParsedRelation, i: int, j: int, a: Value, b: Value, axis: str | None) -> str:
    comp = f" ({axis} component)" if axis else ""
    num = lone_number(relation.sides[j])
    if num is not None and not a.radius:
        return f"{_side_text(relation, i)} is {show(a.center)}{comp}, which does not round to {num.text}"
    return (
        f"{_side_text(relation, i)} = {_side_text(relation, j)} does not hold{comp}: "
        f"{show(a.center)} against {show(b.center)}"
    )


def check_relation(judge: Judge, claim: Claim, relation: ParsedRelation) -> Iterator[str]:
    """Reasons why ``relation`` is false (nothing when it holds or cannot be valued)."""
    for axis in judge.axes(relation):
        vals = judge.values(claim, relation, axis)
        known = [(i, v) for i, v in enumerate(vals) if v is not None]
        if len(known) < 2:
            continue
        if any(op in ("<", ">", "<=", ">=") for op in relation.ops):
            yield from _inequalities(relation, vals)
            continue
        exact = [(i, v) for i, v in known if not v.radius]
        if exact:
            i0, ref = exact[0]
            for i, v in known:
                if i != i0 and not _agree(ref, v):
                    yield _reason(relation, i0, i, ref, v, axis)
                    break
            continue
        for (i, a), (j, b) in itertools.pairwise(known):
            if not _agree(a, b):
                yield _reason(relation, i, j, a, b, axis)
                break


def _inequalities(relation: ParsedRelation, vals: list[Value | None]) -> Iterator[str]:
    for k, op in enumerate(relation.ops):
        a, b = vals[k], vals[k + 1]
        if a is None or b is None or op not in ("<", ">", "<=", ">="):
            continue
        slack = a.radius + b.radius
        holds = {
            "<": a.center < b.center + slack,
            ">": a.center > b.center - slack,
            "<=": a.center <= b.center + slack,
            ">=": a.center >= b.center - slack,
        }[op]
        if not holds:
            yield f"{_side_text(relation, k)} {op} {_side_text(relation, k + 1)} is false: {show(a.center)}, {show(b.center)}"


def check(judge: Judge) -> Iterator[Failure]:
    """Every relation of every line; a line true only once a later unknown is known is ``order``."""
    solved = judge.solved_view()
    rounded = judge.rounded_view()
    for claim in judge.claims:
        for relation in claim.relations:
            if len(relation.sides) < 2:
                continue
            for reason in check_relation(judge, claim, relation):
                if claim.line.kind != "given" and next(check_relation(rounded, claim, relation), None) is None:
                    break  # a rounded intermediate whose digits happen to be a given's
                rule = RULE
                if solved is not None and next(check_relation(solved, claim, relation), None) is None:
                    rule = "order"
                    reason = f"{reason}; it holds only with a value found later on the page: shown before it is known"
                yield Failure(claim.line.number, claim.line.latex, rule, reason, claim.line.scope)
                break
