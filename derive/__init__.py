"""derive: worked solutions of central-impact problems, in the layout of the course notes.

>>> import derive  # doctest: +SKIP
>>> solution = derive.solve(derive.load("notes-4c11-two-spheres"))  # doctest: +SKIP
>>> print(derive.render(solution, "md"))  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path

from derive.check import check
from derive.errors import DeriveError, InputError, RenderError
from derive.problem import Problem
from derive.render import render
from derive.solution import Solution
from derive.solve import solve

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


def verify(solution: Solution, fmt: str = "md", **options: object) -> object:
    """Check every line of ``solution``'s page in ``fmt``; returns a :class:`derive.verify.Report`.

    Imported on first use, so that ``import derive`` stays light (see :mod:`derive.verify`).
    """
    from derive.verify import verify as check_page

    return check_page(solution, fmt, **options)
