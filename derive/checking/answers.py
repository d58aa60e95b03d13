"""Hand answers to check: the answers file, and ``derive check`` on the command line.

An answers file is TOML with a table ``[answers]`` (result name -> value), an
optional table ``[equations]`` (label -> equation) and an optional relative
``tolerance``. :func:`run` is what ``derive check`` does: read the options and
files, solve the problem, check, render.

This module is also the checking package's public face: it re-exports the
records and :func:`check` (``from derive.checking.answers import Item, check``).
"""

from __future__ import annotations

from pathlib import Path

from derive.checking.check import check
from derive.checking.entries import Answers, Entry, answer_option, equation_option, parse_tolerance
from derive.checking.report import CheckReport, Diagnosis, Item
from derive.errors import InputError


def load_answers(path: str | Path) -> Answers:
    """Read an answers file (TOML: ``[answers]``, optional ``[equations]`` and ``tolerance``)."""
    from derive.fileio import read_user_text

    shown = str(path)
    text = read_user_text(path, "an answers file")
    return loads_answers(text, path=shown)


def loads_answers(text: str, *, path: str = "<answers>") -> Answers:
    """Read answers given as TOML text (``path`` only names it in messages); the file is
    checked against the answers table of :mod:`derive.problem.schema` first."""
    from derive.problem import Source, parse_toml, validate
    from derive.problem.schema import ANSWERS
    from derive.problem.source import printable

    data = parse_toml(text, path)
    lines = Source(path, text)
    validate.check(data, ANSWERS, lines)
    out_a, out_e = [], []
    for section, out in (("answers", out_a), ("equations", out_e)):
        for key, value in data.get(section, {}).items():
            where = lines.where(lines.line_of(section, key))
            out.append(Entry(str(key), value, where=where, field=f"[{section}] {printable(key)}"))
    if not out_a and not out_e:
        raise InputError("has nothing to check: give an [answers] table (or [equations])", where=path)
    return Answers(tuple(out_a), tuple(out_e), data.get("tolerance"))


def run(
    problem: str,
    answers: list[str] | None = None,
    answers_file: str | None = None,
    equations: list[str] | None = None,
    tolerance: str | None = None,
    fmt: str = "text",
    derivation: str | None = None,
) -> tuple[CheckReport, str]:
    """What ``derive check`` does: load, solve, check; returns the report and its rendering.

    ``derivation`` is the path of a typed derivation (``.md``, ``.tex`` or plain lines).
    """
    from derive.fileio import read_user_text
    from derive.problem import load
    from derive.steps import solve

    given = Answers()
    if answers_file:
        given = load_answers(answers_file)
    extra = Answers(
        tuple(answer_option(a) for a in answers or ()),
        tuple(equation_option(x) for x in equations or ()),
    )
    given = given.merged(extra)
    tol = parse_tolerance(tolerance) if tolerance is not None else given.tolerance
    work = read_user_text(derivation, "a derivation") if derivation else None
    if not given.answers and not given.equations and work is None:
        raise InputError(
            "nothing to check: give answers with --answer NAME=VALUE or --answers FILE, or --derivation FILE",
            where="usage",
        )
    solution = solve(load(problem), steps=False)  # the results alone: no worked steps
    report = check(solution, given, tolerance=tol, derivation=work)
    return report, report.render(fmt)


__all__ = [
    "Answers",
    "CheckReport",
    "Diagnosis",
    "Entry",
    "Item",
    "answer_option",
    "check",
    "equation_option",
    "load_answers",
    "loads_answers",
    "parse_tolerance",
    "run",
]
