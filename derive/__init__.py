"""The public API of derive: load, solve, render, check (and Problem, Solution).
May import: every package of derive (it is the top of the flow).

>>> import derive  # doctest: +SKIP
>>> solution = derive.solve(derive.load("notes-4c11-two-spheres"))  # doctest: +SKIP
>>> print(derive.render(solution, "md"))  # doctest: +SKIP

``import derive`` loads nothing heavy: each function imports what it needs when called.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from derive.errors import DeriveError, InputError, RenderError

if TYPE_CHECKING:
    from derive.checking.answers import CheckReport
    from derive.problem import ChainProblem, Problem
    from derive.steps.model import Solution

__version__ = "0.1.0"
__all__ = [
    "DeriveError",
    "InputError",
    "Problem",
    "RenderError",
    "Solution",
    "__version__",
    "check",
    "load",
    "render",
    "solve",
    "verify",
]


def load(path: str | Path) -> Problem | ChainProblem:
    """Read a problem: a path to a TOML file, or the name of a bundled problem.

    Raises :class:`InputError` with a one-line message on bad input.
    """
    from derive import problem

    return problem.load(path)


def solve(problem: Problem | ChainProblem) -> Solution:
    """Solve ``problem`` in closed form and write its worked solution as data.

    In Jupyter the solution shows itself as its worked solution.
    """
    from derive.display import displayed
    from derive.steps import solve as solve_steps

    return displayed(solve_steps(problem))


def render(solution: Solution, fmt: str = "md", **options: Any) -> str:
    """``solution`` as text in ``fmt``: 'md', 'tex' (a document), 'tex-fragment', 'html' or 'json'.

    ``options``: ``digits``, ``figures``, ``target`` (Markdown: 'github', 'jupyter', 'mkdocs' or
    'pandoc'), ``heading_level``, ``title`` and ``plot`` (the plot of the outcome against e after
    the answer); see :func:`derive.writers.view.render` and docs/interop.md.
    """
    from derive.writers.view import render as render_text

    return render_text(solution, fmt, **options)


def check(solution: Solution | Problem, answers: Any = None, **options: Any) -> CheckReport:
    """Check hand answers (and equations) against a solution; see :func:`derive.checking.answers.check`."""
    from derive.checking.answers import check as check_answers

    return check_answers(solution, answers, **options)


def verify(solution: Solution, fmt: str = "md", **options: Any) -> Any:
    """Check every line of ``solution``'s page in ``fmt``; returns a :class:`derive.verifier.VerifyReport`.

    Imported on first use, so that ``import derive`` stays light (see :mod:`derive.verifier`).
    """
    from derive.verifier import verify as check_page

    return check_page(solution, fmt, **options)


def __getattr__(name: str) -> Any:
    """``derive.Problem`` and ``derive.Solution``, imported on first use."""
    if name == "Problem":
        from derive.problem import Problem

        return Problem
    if name == "Solution":
        from derive.steps.model import Solution

        return Solution
    raise AttributeError(f"module 'derive' has no attribute {name!r}")
