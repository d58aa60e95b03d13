"""Rule ``consistent``: a value shown twice is shown the same way.

Where a sentence names an equation ("Substitute into (3)"), the numbers of
that equation, or of an equation above it, that the lines under it use again
must be written as the equation wrote them, or rounded from it: (3) shown with
84.8 and then substituted as 84.77 reads as two different numbers, and 5.8971
of (4) put in as 5.896 is not its rounding. A result rounded for the answer (-1.11 m/s) and
carried on with one more figure (-1.109) is the textbook way, and not flagged;
nor is a value with letters at the end of a line (``-6.261 e = -6.26 e``).
"""

from __future__ import annotations

from collections.abc import Iterator
from decimal import Decimal

from derive.mathtext.tree import Num, Sym
from derive.verifier.evaluate import walk
from derive.verifier.judge import Claim, Judge, is_result
from derive.verifier.report import Failure
from derive.verifier.rules.dimensions import value_form
from derive.verifier.rules.references import steps

RULE = "consistent"


def _intermediates(judge: Judge, claim: Claim) -> Iterator[Num]:
    """The rounded numbers of a line that are not its stated result."""
    scopes = judge.chain_of(claim.line.scope)
    for rel in claim.relations:
        for i, side in enumerate(rel.sides):
            last = i == len(rel.sides) - 1 and i > 0
            if is_result(claim, rel, i) or (last and value_form(side.expr) and _has_letter(side.expr)):
                continue
            for node in walk(side.expr):
                if not isinstance(node, Num) or node.integer or node.value == 0:  # 0.00 is rule zero's
                    continue
                if not judge.is_exact(node, scopes):
                    yield node


def _has_letter(node: object) -> bool:
    return any(isinstance(n, Sym) for n in walk(node))


def check(judge: Judge) -> Iterator[Failure]:
    """Numbers of a named equation written again differently under it."""
    tagged = {c.display.tag: c for c in judge.claims if c.display is not None and c.display.tag}
    for step in steps(judge):
        sources = [tagged[t] for t in step.tags if t in tagged]
        if not sources:
            continue
        scopes = judge.chain_of(step.claim.line.scope)
        here = step.claim.line
        above = [c for c in tagged.values() if c.line.number < here.number and c.line.scope == here.scope]
        named = {id(c) for c in sources}
        theirs = [
            (n, s.display.tag, id(s) in named)
            for s in {id(c): c for c in sources + above}.values()
            for n in _intermediates(judge, s)
        ]
        # a number written exactly as another equation wrote it is that equation's (1.25 of (4)
        # under "Substitute into (3)", beside a 1.2 of (3))
        anywhere = {n.mantissa for c in tagged.values() for n in _intermediates(judge, c)}
        for claim in judge.claims:
            if claim.line.block != step.claim.line.block:
                continue
            own = {n.mantissa for n in _intermediates(judge, claim)}
            for mine in _intermediates(judge, claim):
                if mine.degrees or mine.mantissa in anywhere:
                    continue
                # an equation above but not named counts only for a number it shows with more
                # figures (5.8971 of (4) put in as 5.896): a shorter one may be another quantity
                near = [
                    (abs(mine.value - o.value), o, tag, is_named)
                    for o, tag, is_named in theirs
                    if not o.degrees and (is_named or (o.decimals > mine.decimals and mine.figures >= 3))
                ]
                if not near:
                    continue
                gap, other, tag, is_named = min(near, key=lambda x: x[0])
                if other.mantissa in own:  # the line writes that number as it was: mine is another
                    continue
                h = max(judge.halfwidth(mine, scopes), judge.halfwidth(other, scopes))
                if mine.decimals < other.decimals and abs(other.value - mine.value) <= mine.ulp / 2:
                    continue  # the textbook way: a number above carried on rounded (9.157 as 9.16)
                if gap <= (1 if is_named else 3) * Decimal(str(h)) and mine.mantissa != other.mantissa:
                    line = claim.line
                    reason = f"({tag}) shows {other.text}; this line writes it {mine.text}"
                    yield Failure(line.number, line.latex, RULE, reason, line.scope)
                    break
