"""Rules ``figures``, ``zero`` and ``notation``: how each number is written.

- ``figures``: no number shows more significant figures than the solution's rule
  (the problem's ``digits``, else 3, or 4 when the leading digit is 1), one more
  for an intermediate; a given written as the file gave it is data, not a rounding.
- ``zero``: nothing is written 0.00 (a value rounded away: write it with a power of ten).
- ``notation``: no number is written out with more than a few zeros (0.00000167,
  2000000): below 1e-4 or from 1e6 up a textbook writes a power of ten.
"""

from __future__ import annotations

from collections.abc import Iterator
from decimal import Decimal

from derive.mathtext.tree import Num
from derive.verifier.evaluate import walk
from derive.verifier.judge import Claim, Judge, is_result
from derive.verifier.report import Failure

SMALL, LARGE = Decimal("1e-4"), Decimal("1e6")


def _numbers(claim: Claim) -> Iterator[tuple[Num, bool]]:
    """Each number of a claim, and whether it states a result (the last side of a result line)."""
    for relation in claim.relations:
        for i, side in enumerate(relation.sides):
            result = is_result(claim, relation, i)
            for node in walk(side.expr):
                if isinstance(node, Num):
                    yield node, result


def _figures(judge: Judge, claim: Claim, num: Num, result: bool) -> str | None:
    scopes = judge.chain_of(claim.line.scope)
    if num.value == 0 or (not result and judge.is_exact(num, scopes)):
        return None
    # a number just above a power of ten may be the rounding of one just below it, whose
    # leading digit is 1 (2.000 for 1.99992 shows 4 figures by the rule)
    rule = max(judge.rule_figures(num.value), judge.rule_figures(abs(num.value) - num.ulp / 2))
    allowed = rule if result else rule + 1
    if num.figures <= allowed:
        return None
    what = "a result" if result else "an intermediate"
    return f"{num.text} shows {num.figures} significant figures; {what} here shows at most {allowed}"


def _problems(judge: Judge, claim: Claim, num: Num, result: bool) -> Iterator[tuple[str, str]]:
    figures = _figures(judge, claim, num, result)
    if figures:
        yield "figures", figures
    if num.value == 0 and not num.integer:
        yield "zero", f"{num.text} shows a value rounded to zero: give it with a power of ten"
    if num.exponent == 0 and num.value != 0 and not SMALL <= abs(num.value) < LARGE:
        yield "notation", f"{num.text} is written out in full: use a power of ten"


def check(judge: Judge) -> Iterator[Failure]:
    """Too many figures, zeros shown for a value, numbers that need a power of ten (one failure
    per rule and line, naming each number)."""
    for claim in judge.claims:
        found: dict[str, list[str]] = {}
        for num, result in _numbers(claim):
            for rule, reason in _problems(judge, claim, num, result):
                if reason not in found.setdefault(rule, []):
                    found[rule].append(reason)
        for rule, reasons in found.items():
            line = claim.line
            yield Failure(line.number, line.latex, rule, "; ".join(reasons), line.scope)
