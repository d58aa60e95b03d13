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
from derive.checking.report import Diagnosis, Item, Report
from derive.errors import InputError


def load_answers(path: str | Path) -> Answers:
    """Read an answers file (TOML: ``[answers]``, optional ``[equations]`` and ``tolerance``)."""
    from derive.fileio import read_user_text

    shown = str(path)
    text = read_user_text(path, "an answers file")
    return loads_answers(text, path=shown)


def loads_answers(text: str, *, path: str = "<answers>") -> Answers:
    """Read answers given as TOML text (``path`` only names it in messages)."""
    from derive.problem import Source, parse_toml

    data = parse_toml(text, path)
    lines = Source(path, text)

    def where(section: str | None, key: str | None) -> str:
        n = lines.line_of(section, key)
        return f"{path}:{n}" if n else path

    for key in data:
        if key not in ("answers", "equations", "tolerance"):
            raise InputError(
                "unknown field (expected [answers], [equations] or tolerance)", where=where(None, key), field=key
            )
    out_a, out_e = [], []
    for section, out in (("answers", out_a), ("equations", out_e)):
        tbl = data.get(section, {})
        if not isinstance(tbl, dict):
            raise InputError('expected a table such as [answers] v_B2n = "8.40 m/s"', where=path, field=section)
        for key, value in tbl.items():
            fld = f"[{section}] {key}"
            if isinstance(value, bool) or not isinstance(value, (str, int, float)):
                raise InputError('expected a number or text such as "8.40 m/s"', where=where(section, key), field=fld)
            if section == "equations" and not isinstance(value, str):
                raise InputError(
                    'expected an equation as text, such as "v_B2n - v_A2n = 9.5"', where=where(section, key), field=fld
                )
            out.append(Entry(str(key), value, where=where(section, key), field=fld))
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
) -> tuple[Report, str]:
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
    solution = solve(load(problem))
    report = check(solution, given, tolerance=tol, derivation=work)
    return report, report.render(fmt)


__all__ = [
    "Answers",
    "Diagnosis",
    "Entry",
    "Item",
    "Report",
    "answer_option",
    "check",
    "equation_option",
    "load_answers",
    "loads_answers",
    "parse_tolerance",
    "run",
]
