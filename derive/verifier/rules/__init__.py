"""The rules, one module each, in the order a report lists them.
May import: the rest of the verifier only.

Each rule is a function ``check(judge) -> Iterator[Failure]``; a new rule is a
new module added to :data:`RULES`.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from derive.verifier.judge import Judge
from derive.verifier.report import Failure
from derive.verifier.rules import (
    answers,
    coefficients,
    consistent,
    dimensions,
    equals,
    figures,
    givens,
    letters,
    references,
    sums,
    work,
)

#: rule name -> check
RULES: dict[str, Callable[[Judge], Iterator[Failure]]] = {
    equals.RULE: equals.check,
    "coefficients": coefficients.check,
    "figures": figures.check,
    "units": dimensions.check,
    references.RULE: references.check,
    sums.RULE: sums.check,
    consistent.RULE: consistent.check,
    givens.RULE: givens.check,
    answers.RULE: answers.check,
    letters.RULE: letters.check,
    "work": work.check,
}
