"""Problem files: read a TOML problem or chain, check every field, and build its record.

The format is documented in ``docs/problem-format.md``. Every error names the file,
the line where it can be found, the field and what was expected.
"""

from __future__ import annotations

from pathlib import Path

from derive.problem.chain import ChainProblem
from derive.problem.reader import Condition, Given, Motion, Problem, build_problem
from derive.problem.source import Source, parse_toml

__all__ = ["ChainProblem", "Condition", "Given", "Motion", "Problem", "Source", "build_problem", "load", "loads"]


def load(path: str | Path, *, name: str | None = None) -> Problem | ChainProblem:
    """Read and check the problem file at ``path``.

    Raises :class:`~derive.errors.InputError` (one line: file, field, what was
    expected) on anything that is not a well-posed central-impact problem.
    """
    from derive.fileio import read_user_text

    path = Path(path)
    text = read_user_text(path, "a problem file")
    return loads(text, path=str(path), name=name or path.stem)


def loads(text: str, *, path: str = "<string>", name: str = "") -> Problem | ChainProblem:
    """Check a problem given as TOML text (``path`` only names it in messages)."""
    from derive.problem.chain import build_chain

    source = Source(path, text)
    data = parse_toml(text, path)
    if isinstance(data, dict) and data.get("kind") == "chain":
        return build_chain(data, source, name)
    return build_problem(data, source, name)
