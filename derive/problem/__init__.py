"""Problem files: read a TOML problem or chain, check every field, and build its record.
May import: the leaves only (errors, symbols, numbers, escape, resources, fileio).

The format is documented in ``docs/problem-format.md`` and declared in
:mod:`derive.problem.schema`. Every error names the file, the line where it can be
found, the field and what was expected.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

from derive.errors import InputError
from derive.problem.source import Source, parse_toml

if TYPE_CHECKING:
    from derive.problem.chain import ChainProblem
    from derive.problem.reader import build_problem
    from derive.problem.records import Condition, Given, Motion, Problem

#: Names imported on first use: the records need SymPy, the schema and the TOML reader do not.
_LAZY = {
    "ChainProblem": "derive.problem.chain",
    "build_problem": "derive.problem.reader",
    "Condition": "derive.problem.records",
    "Given": "derive.problem.records",
    "Motion": "derive.problem.records",
    "Problem": "derive.problem.records",
}

__all__ = [
    "ChainProblem",
    "Condition",
    "Given",
    "Motion",
    "Problem",
    "Source",
    "build_problem",
    "find",
    "load",
    "loads",
    "parse_toml",
    "title",
]


def load(path: str | Path, *, name: str | None = None) -> Problem | ChainProblem:
    """Read and check a problem: a path to a TOML file, or the name of a bundled problem.

    Raises :class:`~derive.errors.InputError` (one line: file, field, what was
    expected) on anything that is not a well-posed central-impact problem.
    """
    from derive.fileio import read_user_text

    path = find(path)
    text = read_user_text(path, "a problem file")
    return loads(text, path=str(path), name=name or path.stem)


def find(path: str | Path) -> Path:
    """The file a problem argument names: a path, or the name (file stem) of a bundled problem."""
    from derive import resources

    p = Path(path)
    if not p.exists() and isinstance(path, str) and "/" not in path and not path.endswith(".toml"):
        bundled = resources.bundled()
        if path in bundled:
            return bundled[path]
        import difflib

        close = difflib.get_close_matches(path, list(bundled), n=3, cutoff=0.6)
        hint = f"did you mean {' or '.join(close)}?" if close else "'derive list' names them"
        raise InputError(f"no such file, and no bundled problem of that name; {hint}", where=str(path))
    return p


def loads(text: str, *, path: str = "<string>", name: str = "") -> Problem | ChainProblem:
    """Check a problem given as TOML text (``path`` only names it in messages)."""
    from derive.problem.chain import build_chain
    from derive.problem.reader import build_problem

    source = Source(path, text)
    data = parse_toml(text, path)
    if data.get("kind") == "chain":
        return build_chain(data, source, name)
    return build_problem(data, source, name)


def __getattr__(name: str) -> Any:
    """The records and the builder, imported when first asked for (they import SymPy)."""
    if name in _LAZY:
        import importlib

        return getattr(importlib.import_module(_LAZY[name]), name)
    raise AttributeError(f"module 'derive.problem' has no attribute {name!r}")


def title(path: str | Path) -> str:
    """A problem file's title, read and checked against the schema's ``title`` field
    without building the rest (for ``derive list``: no SymPy)."""
    from derive.fileio import read_user_text
    from derive.problem.schema import PROBLEM
    from derive.problem.validate import check_value, missing

    path = Path(path)
    text = read_user_text(path, "a problem file")
    source = Source(str(path), text)
    data = parse_toml(text, str(path))
    field = PROBLEM.get("title")
    assert field is not None
    if "title" not in data:
        raise missing(field, source)
    check_value(data["title"], field, source, ("title",))
    return data["title"]
