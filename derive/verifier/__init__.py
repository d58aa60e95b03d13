"""An independent check that every line of a worked solution is true.
May import: the leaf mathtext (the LaTeX reader); only its facts/ package reads derive's objects.

It reads the page as a reader does (the rendered Markdown or LaTeX, not the
objects that produced it), parses each displayed relation with the one reader of
typed mathematics (:mod:`derive.mathtext.parser`, which keeps the figures a number
shows), and checks it against its own facts about the problem (:mod:`.facts`,
the only part that touches derive's objects): each ``=`` holds to the precision
shown, the givens are the right ones, equation references exist and do what
they say, sums add up, numbers have the figures the rule allows, units match.

>>> import derive  # doctest: +SKIP
>>> report = derive.verify(derive.solve(derive.load("notes-4c11-two-spheres")))  # doctest: +SKIP
>>> report.ok  # doctest: +SKIP
"""

from __future__ import annotations

from typing import Any

from derive.verifier.facts import Facts, facts_of
from derive.verifier.judge import Judge
from derive.verifier.reader import read
from derive.verifier.report import Failure, VerifyReport
from derive.verifier.rules import RULES

__all__ = ["Failure", "VerifyReport", "verify", "verify_text"]


def verify_text(text: str, facts: Facts, fmt: str = "md") -> VerifyReport:
    """Check the page ``text`` (Markdown, or LaTeX for 'tex'/'tex-fragment') against ``facts``."""
    judge = Judge(facts, read(text, fmt))
    report = VerifyReport(lines=len(judge.claims))
    report.failures += [Failure(0, "", "physics", note) for note in facts.notes]
    for check in RULES.values():
        report.failures += list(check(judge))
    report.failures.sort(key=lambda f: (f.line, f.rule))
    report.relations = sum(len(c.relations) for c in judge.claims)
    report.unchecked = sorted(judge.unresolved)
    return report


def verify(
    solution: Any, fmt: str = "md", *, digits: int | None = None, text: str | None = None, source: str | None = None
) -> VerifyReport:
    """Render ``solution`` in ``fmt`` ('md' or 'tex') and check every line of it.

    ``text`` checks a page already rendered (a homework variant's) instead; ``source`` is
    the problem file's TOML when the problem was not loaded from a file on disk (else
    the verifier reads the file at the problem's path itself).
    """
    if text is None:
        from derive.writers.view import render

        text = render(solution, fmt, digits=digits, figures=False)
    return verify_text(text, facts_of(solution, digits, source), fmt)
