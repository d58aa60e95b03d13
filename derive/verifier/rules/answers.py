"""Rule ``answers``: an ANSWER mark on each result asked for, and on nothing else.

- A marked line is about a quantity the question asks for (a vector: one of its
  components asked is enough); a line has at most one mark, and a result is marked
  once in one answer (a vector and its components are one result).
- An answer marks one line at least where it boxes a result asked for; a chain's
  final "Answer" lists the results asked for, boxed, and marks each of them.
- A chain's intermediate stages carry no mark: their results are steps, not answers.

Whether a marked value is right is the other rules' business (a boxed line is
checked as any line is).
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass, field

from derive.mathtext.tree import Sym, Vec
from derive.verifier.judge import Claim, Judge
from derive.verifier.reader import PageLine
from derive.verifier.report import Failure

RULE = "answers"

#: A velocity's component (v_A2n, v_B2x): the same result as the vector v_A2.
_COMPONENT = re.compile(r"(v_[A-Za-z]+\d)[ntxy]")


@dataclass
class _Answer:
    """One answer section: what it marks and what it boxes without a mark."""

    marked: dict[str, int] = field(default_factory=dict)  # result -> line of its first mark
    unmarked: list[Claim] = field(default_factory=list)  # boxed lines of asked results, not marked


def check(judge: Judge) -> Iterator[Failure]:
    """Marks in stages, a line or a result marked twice, marks on what was not asked, marks missing."""
    answers: dict[tuple[str, str], _Answer] = {}
    for claim in judge.claims:
        d = claim.display
        if d is None:
            continue
        line = claim.line
        scope = judge.scope(line.scope)
        name = _result(claim)
        asked = _asked(name, scope.asked)
        if not d.answer_marks:
            if d.boxed and scope.answers and (asked or _chain_answer(line)):
                answers.setdefault((line.scope, line.section), _Answer()).unmarked.append(claim)
            continue
        answer = answers.setdefault((line.scope, line.section), _Answer())
        reasons = []
        if d.answer_marks > 1:
            reasons.append("the line has two ANSWER marks")
        if not scope.answers:
            reasons.append("an intermediate result of a stage is marked ANSWER; the chain's answer is at its end")
        key = _COMPONENT.sub(r"\1", name) if name else line.latex
        if key in answer.marked:
            reasons.append(f"a second ANSWER mark on {name or 'the same result'} in one answer")
        answer.marked.setdefault(key, line.number)
        if name and scope.asked and not asked:
            reasons.append(f"{name} is marked ANSWER, but the question asks for {', '.join(sorted(scope.asked))}")
        if reasons:
            yield Failure(line.number, line.latex, RULE, "; ".join(reasons), line.scope)
    for (scope_key, _), answer in answers.items():
        yield from _missing(answer, scope_key)


def _missing(answer: _Answer, scope: str) -> Iterator[Failure]:
    """A chain's answer: each boxed result unmarked; a problem's: an answer that marks none."""
    if scope == "chain":
        for claim in answer.unmarked:
            line = claim.line
            why = "a result the chain's answer boxes (one asked for) is not marked ANSWER"
            yield Failure(line.number, line.latex, RULE, why, line.scope)
    elif answer.unmarked and not answer.marked:
        line = answer.unmarked[-1].line
        why = "the answer boxes what the question asks for but marks no line ANSWER"
        yield Failure(line.number, line.latex, RULE, why, line.scope)


def _result(claim: Claim) -> str:
    """The name a line states (its first side), or '' where it is not a name (tan β = ..., a verdict in words)."""
    first = claim.relations[0].sides[0].expr if claim.relations else None
    return first.name if isinstance(first, (Sym, Vec)) else ""


def _asked(name: str, asked: frozenset[str]) -> bool:
    """Whether ``name`` is asked for: itself, or a vector one of whose components is."""
    return bool(name) and (name in asked or any(n[:-1] == name for n in asked if n[-1:] in ("n", "t", "x", "y")))


def _chain_answer(line: PageLine) -> bool:
    """A line of a chain's final "Answer" (every result there is one asked for)."""
    return line.scope == "chain" and line.section == "Answer"
