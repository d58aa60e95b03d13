"""Rule ``letters``: a line of numbers leaves no letter for standard gravity.

A side where the givens are put in (it shows a decimal number) puts in g too when g has
a number: ``√2 √1.6 √g`` with the default g = 9.81 m/s² left g as a letter (issue #29).
Only g is judged: other letters may rightly stay (a symbolic given such as u, an unknown
found later on the page), which the facts do not yet tell apart.
"""

from __future__ import annotations

from collections.abc import Iterator

from derive.mathtext.tree import Num, Sym
from derive.verifier.evaluate import walk
from derive.verifier.judge import Judge
from derive.verifier.report import Failure

RULE = "letters"
#: The letters judged: standard gravity, whose number derive supplies when the file gives none.
JUDGED = frozenset({"g"})


def check(judge: Judge) -> Iterator[Failure]:
    """Each side with a decimal number in it and a judged letter that has a number."""
    for claim in judge.claims:
        scopes = judge.chain_of(claim.line.scope)
        for relation in claim.relations:
            for side in relation.sides[1:]:
                nodes = list(walk(side.expr))
                if not any(isinstance(n, Num) and "." in n.mantissa for n in nodes):
                    continue
                left = sorted(
                    {
                        n.name
                        for n in nodes
                        if isinstance(n, Sym)
                        and n.name in JUDGED
                        and (q := judge.quantity(n.name, scopes)) is not None
                        and q.value is not None
                    }
                )
                if left:
                    yield Failure(
                        claim.line.number,
                        claim.line.latex,
                        RULE,
                        f"{', '.join(left)} left as a letter in a line where the numbers are put in",
                        claim.line.scope,
                    )
                    break
