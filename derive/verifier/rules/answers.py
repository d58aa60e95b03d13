"""Rule ``answers``: one ANSWER mark per answer, on what the question asks.

- An answer section (a problem's "Answer", a chain's final "Answer") has at most
  one mark, but for the velocity vectors of the two bodies, which the notes mark
  together (Example 4.C.11); a line has at most one.
- The marked line is about a quantity the question asks for (a vector: one of its
  components asked is enough).
- A chain's intermediate stages carry no mark: their results are steps, not answers.
"""

from __future__ import annotations

from collections.abc import Iterator

from derive.mathtext.tree import Sym, Vec
from derive.verifier.judge import Judge
from derive.verifier.report import Failure

RULE = "answers"


def check(judge: Judge) -> Iterator[Failure]:
    """Marks in stages, several marks in one answer, marks on what was not asked."""
    marks: dict[tuple[str, str], list[bool]] = {}  # by answer: whether each marked line is a vector
    for claim in judge.claims:
        d = claim.display
        if d is None or not d.answer_marks:
            continue
        line = claim.line
        scope = judge.scope(line.scope)
        reasons = []
        if d.answer_marks > 1:
            reasons.append("the line has two ANSWER marks")
        if not scope.answers:
            reasons.append("an intermediate result of a stage is marked ANSWER; the chain's answer is at its end")
        first = claim.relations[0].sides[0].expr if claim.relations else None
        kinds = marks.setdefault((line.scope, line.section), [])
        kinds.append(isinstance(first, Vec))
        if len(kinds) >= 2 and not (len(kinds) == 2 and all(kinds)):
            reasons.append("a second ANSWER mark in one answer")
        asked = scope.asked | {n[:-1] for n in scope.asked if n[-1:] in ("n", "t")}
        if isinstance(first, (Sym, Vec)) and scope.asked and first.name not in asked:
            reasons.append(f"{first.name} is marked ANSWER, but the question asks for {', '.join(sorted(scope.asked))}")
        if reasons:
            yield Failure(line.number, line.latex, RULE, "; ".join(reasons), line.scope)
