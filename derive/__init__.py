"""derive: worked solutions of central-impact problems, in the layout of the course notes.

>>> import derive  # doctest: +SKIP
>>> solution = derive.solve(derive.load("notes-4c11-two-spheres"))  # doctest: +SKIP
>>> print(derive.render(solution, "md"))  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

from derive.checking.answers import check
from derive.errors import DeriveError, InputError, RenderError
from derive.problem import Problem
from derive.steps import solve
from derive.steps.model import Solution
from derive.writers.view import render

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
]


def load(path: str | Path) -> Problem:
    """Read a problem: a path to a TOML file, or the name of a bundled problem.

    Raises :class:`InputError` with a one-line message on bad input.
    """
    from derive import problem, resources

    p = Path(path)
    if not p.exists() and isinstance(path, str) and "/" not in path and not path.endswith(".toml"):
        bundled = resources.bundled()
        if path in bundled:
            return problem.load(bundled[path])
        raise InputError(
            f"no such file, and no bundled problem of that name (try 'derive list'); bundled: {', '.join(bundled)}",
            where=str(path),
        )
    return problem.load(p)
