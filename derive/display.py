"""A solution as notebooks and the REPL show it: its worked solution in Markdown, its
boxed answers as LaTeX, and a short plain-text line of its title and answers.

This sits above the writers, so the data (:class:`~derive.steps.model.Solution`)
never renders itself.
"""

from __future__ import annotations

from dataclasses import dataclass, fields

from derive.steps.model import Solution


@dataclass(frozen=True, repr=False)
class DisplayedSolution(Solution):
    """A :class:`Solution` with the display hooks of Jupyter and of the REPL."""

    def _repr_markdown_(self) -> str:
        """The worked solution as Markdown for notebooks (``\\require{cancel}`` where MathJax 2 needs it)."""
        from derive.writers.view import render

        return render(self, "md", target="jupyter")

    def _repr_latex_(self) -> str:
        """The boxed answers as display math (for front ends that show LaTeX, not Markdown)."""
        from derive.writers.view import boxed_lines

        return "\n".join(f"$${ln}$$" for ln in boxed_lines(self))

    def __repr__(self) -> str:
        from derive.writers.view import plain_answers

        answers = "; ".join(plain_answers(self))
        return f"<Solution {self.problem.title!r}: {answers}>" if answers else f"<Solution {self.problem.title!r}>"


def displayed(solution: Solution) -> DisplayedSolution:
    """``solution`` with its display hooks."""
    return DisplayedSolution(**{f.name: getattr(solution, f.name) for f in fields(solution)})
