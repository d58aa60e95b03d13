"""Rules ``derived``, ``repeated`` and ``read``: the working shows how each value comes.

- ``derived``: a line "⇒ x = value" follows lines that contain x (no
  ``h_2 = 1.40 ⇒ e = 0.837`` with e nowhere before it); a value carried to the
  next stage of a chain is worked out in its stage first.
- ``repeated``: no side is written twice in a row (``v_2 = -u = -u``).
- ``read``: a line the verifier cannot read, or one with a side it cannot value (a
  name with no value, an unknown unit), is reported, not skipped: no line counts as
  true unchecked.
"""

from __future__ import annotations

import itertools
from collections.abc import Iterator

from derive.mathtext.tree import Sym
from derive.verifier.judge import Claim, Judge
from derive.verifier.report import Failure


def _derived(judge: Judge, claim: Claim, before: list[Claim]) -> str | None:
    d = claim.display
    if d is None or not d.implies or not claim.relations:
        return None
    first = claim.relations[0].sides[0].expr
    if not isinstance(first, Sym):
        return None
    q = judge.quantity(first.name, judge.chain_of(claim.line.scope))
    if q is None or q.role != "unknown":
        return None
    seen = {n for c in before for rel in c.relations for s in rel.sides for n in judge.names(s.expr)}
    if first.name in seen:
        return None
    return f"{first.name} is stated, not worked out: no line above it in this step contains {first.name}"


def _carried(judge: Judge, claim: Claim) -> str | None:
    if claim.line.kind != "carried" or not claim.relations or len(claim.relations[0].sides) < 2:
        return None
    source = claim.relations[0].sides[1].expr
    if not isinstance(source, Sym):
        return None
    shown = any(
        source.name in set(judge.names(s.expr))
        for c in judge.claims
        if c.line.scope == claim.line.scope and c.line.kind == "display"
        for rel in c.relations
        for s in rel.sides
    )
    return None if shown else f"{source.name} is carried on but never worked out in this stage"


def check(judge: Judge) -> Iterator[Failure]:
    """Values stated without working, sides written twice, lines that cannot be read."""
    block: list[Claim] = []
    for claim in judge.claims:
        line = claim.line
        if block and block[-1].line.block != line.block:
            block = []
        found = []
        if claim.error is not None and line.kind == "display":
            found.append(("read", f"the verifier cannot read this line ({claim.error})"))
        elif line.number in judge.unvalued:
            found.append(("read", f"the verifier cannot check this line: {judge.unvalued[line.number]}"))
        reason = _derived(judge, claim, block) or _carried(judge, claim)
        if reason:
            found.append(("derived", reason))
        for rel in claim.relations:
            sources = [s.source for s in rel.sides]
            if any(a == b and a for a, b in itertools.pairwise(sources)):
                found.append(("repeated", "a side is written twice in a row"))
                break
        for rule, why in found:
            yield Failure(line.number, line.latex, rule, why, line.scope)
        block.append(claim)
