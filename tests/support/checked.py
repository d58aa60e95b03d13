"""``derive check PROBLEM --derivation`` as the checker's tests read it: each line's verdict."""

from __future__ import annotations

import functools
from pathlib import Path

import derive


@functools.cache
def solution(problem: str) -> derive.Solution:
    """A bundled problem solved once per test session (the checker's tests check many lines on it)."""
    return derive.solve(derive.load(problem))


def line_statuses(problem: str, text: str) -> list[str]:
    """The status of every line item, in the report's order."""
    return [i.status for i in derive.check(solution(problem), derivation=text).items if i.kind == "line"]


def lines(problem: str, work: str) -> dict[int, tuple[str, str, bool]]:
    """line number -> (status, slip name, again)."""
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return {int(i.name): (i.status, i.slip, i.again) for i in report.items if i.kind == "line" and i.name.isdigit()}


def worst_lines(problem: str, work: str) -> dict[int, tuple[str, str]]:
    """line number -> (status, slip name): the worst status where a line has several relations."""
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    out: dict[int, tuple[str, str]] = {}
    rank = ("not read", "correct", "carried", "wrong")
    for i in report.items:
        if i.kind == "line" and i.name.isdigit():
            n = int(i.name)
            if n not in out or rank.index(i.status) > rank.index(out[n][0]):
                out[n] = (i.status, i.slip)
    return out


def solved_text(folder: Path, name: str, toml: str) -> derive.Solution:
    """A problem file written from ``toml`` into ``folder`` (a test's own problem), solved."""
    path = folder / name
    path.write_text(toml, encoding="utf-8")
    return derive.solve(derive.load(path))


def statuses_of(solution: derive.Solution, work: str) -> dict[int, str]:
    """line number -> status, on a solution already made (a test's own problem)."""
    report = derive.check(solution, derivation=work)
    return {int(i.name): i.status for i in report.items if i.kind == "line" and i.name.isdigit()}


#: A ball on a smooth wall at 30° to it (0.5 kg at 10 m/s, e = 0.5): a test's own oblique wall problem.
WALL_30 = """title = "A ball strikes a smooth wall at 30 degrees"
kind = "oblique"
statement = "A ball of mass 0.5 kg hits a smooth wall at 10 m/s at 30 degrees to the wall; e = 0.5."
question = "Find the velocity after the impact."

[given]
m_A = "0.5 kg"
e = 0.5
v_A1 = "10 m/s"
alpha = "30 deg"

[A]
angle = "alpha"
from = "+t"
toward = "+n"

[B]
fixed = true
name = "wall"
"""


def text_lines(folder: Path, toml: str, work: str) -> list[str]:
    """The statuses of ``work``'s lines, in order, against a test's own problem ``toml`` (written
    into ``folder``)."""
    sol = solved_text(folder, "problem.toml", toml)
    return [i.status for i in derive.check(sol, derivation=work).items if i.kind == "line"]


def wall_30_lines(folder: Path, work: str) -> list[str]:
    """:func:`text_lines` against :data:`WALL_30`."""
    return text_lines(folder, WALL_30, work)
