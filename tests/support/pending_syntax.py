"""Which parts of the new problem-file syntax of issue #14 derive accepts yet.

The symbolic library (problems with ``answers``, ``show``, ``equations``, ``range``,
``[assume]``, ``[define]``, and pure numbers kept as letters such as ``e = "e"``) was written
before derive reads that syntax. A problem that uses a part derive does not accept yet is
*pending*: tests that load every bundled problem skip it (saying why) instead of failing,
and run it for real as soon as the part lands.

Each part has a probe: the smallest problem that uses it (and nothing else new). A part is
pending while derive refuses its probe with an input error; anything else a probe raises
is a bug and is raised. Which parts a file uses is read from the file with ``tomllib``.

A problem that derive reads but cannot solve because of a known defect is listed in
``UNSOLVED`` with the defect: the tests over every bundled problem skip it, and
tests/test_symbolic_library.py holds it as a strict expected failure, which fails as soon
as derive is fixed, so that the entry is then removed.
"""

from __future__ import annotations

import tomllib
from functools import cache
from pathlib import Path

import pytest

import derive
from derive import resources
from derive.errors import DeriveError
from derive.problem import loads

_NUMBERS = """title = "probe"
kind = "direct"
{top}
[given]
m_A = "1 kg"
m_B = "1 kg"
e = {e}
v_A1 = "2 m/s"
v_B1 = 0
{tables}"""

_WALL = """title = "probe"
kind = "oblique"
[given]
m = "kg"
U = "m/s"
m_A = "m"
e = 0.5
v_A1 = "U"
alpha = "deg"
[assume]
alpha = "acute"
[A]
angle = "alpha"
from = "+t"
toward = "+n"
[B]
fixed = true
name = "wall"
"""

#: part -> the smallest problem that uses it (e = 1/2 gives v_A2 = 1/2, v_B2 = 3/2, T_2 = 5/8 T_1).
PROBES: dict[str, str] = {
    "answers": _NUMBERS.format(top='answers = { v_B2 = "3/2" }', e=0.5, tables=""),
    "show": _NUMBERS.format(top='show = "v_B2 = 3/4*v_A1"', e=0.5, tables=""),
    "equations": _NUMBERS.format(top='equations = ["T_2 = 5/8*T_1"]', e='"?"', tables=""),
    "letter": _NUMBERS.format(top="", e='"e"', tables=""),
    "define": _NUMBERS.format(top="", e=0.5, tables='[define]\nfraction = "T_2/T_1"\n'),
    "range": _NUMBERS.format(top='range = { of = "e", where = "v_A2 < 0" }', e='"e"', tables=""),
    "assume": _WALL,
}


#: Bundled problem -> the derive defect that stops it being solved (see the module docstring).
UNSOLVED: dict[str, str] = {}


@cache
def refused(part: str) -> str | None:
    """derive's message refusing the probe of ``part``, or None once derive accepts it."""
    try:
        derive.solve(loads(PROBES[part], path=f"probe-{part}.toml"))
    except DeriveError as exc:
        return str(exc)
    return None


def parts_used(path: Path) -> set[str]:
    """The new parts of the syntax a problem file uses."""
    with path.open("rb") as f:
        data = tomllib.load(f)
    used = {key for key in ("answers", "show", "equations", "range", "assume", "define") if key in data}
    givens = data.get("given", {})
    if any(isinstance(value, str) and value.strip() == name for name, value in givens.items()):
        used.add("letter")  # a pure number kept as a letter: e = "e"
    return used


def pending_reason(name_or_path: str | Path, unsolved: bool = True) -> str | None:
    """Why a bundled problem (stem) or problem file cannot be solved yet, or None if it can.

    ``unsolved=False`` leaves out the known defects (``UNSOLVED``): only the syntax counts.
    """
    path = Path(name_or_path) if isinstance(name_or_path, Path) else resources.bundled()[name_or_path]
    if unsolved and path.stem in UNSOLVED:
        return f"{path.name}: a known defect of derive stops it being solved ({UNSOLVED[path.stem]})"
    for part in sorted(parts_used(path)):
        message = refused(part)
        if message is not None:
            return f"{path.name} uses '{part}' of the issue #14 syntax, not implemented yet ({message})"
    return None


def skip_if_pending(name_or_path: str | Path, unsolved: bool = True) -> None:
    reason = pending_reason(name_or_path, unsolved)
    if reason is not None:
        pytest.skip(reason)
