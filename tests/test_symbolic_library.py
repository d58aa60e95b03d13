"""The symbolic / "show that" library (issue #14): derive's closed forms against the mark schemes.

Every bundled problem with an ``answers`` table holds a mark scheme's printed results.
For each, derive solves the problem and each result's closed form (``closed``, in the
problem's letters, with the givens that are numbers put in) is compared with the printed
expression by SymPy equivalence, the letters positive (``[assume]`` may say otherwise):

- the printed expression as the file states it (``answers``), parsed with derive's
  restricted parser, and as tests/support/symbolic_published.py states it (a fixed string of this
  test code, parsed with SymPy): the two must agree, and derive must agree with both;
- angles compare by tangent, and at sample values of the letters (so a direction
  reversed by 180 degrees does not pass); an angle printed in degrees also by its figures;
- a range (``range = { of = "e", where = "v_A2 < 0" }``) compares as a set of e within
  0 <= e <= 1 with the printed one (``"e > 1/3"``);
- a ``show`` is decided as holding, and the worked solution says "as required".

Skips: a problem whose file uses a part of the new syntax that derive does not accept yet
(``answers``, ``show``, ``equations``, ``range``, ``[assume]``, ``[define]``, ``e = "e"``)
is skipped, with derive's refusal as the reason; see tests/support/pending_syntax.py. The skip
ends by itself the moment derive accepts that part; from then on these tests run.
Defects of derive these problems found are strict expected failures (``DEFECTS``), which
fail once derive is fixed so that the entry goes with the fix.
The mark schemes' results are checked against equations (1)-(4) without derive in
tests/test_symbolic_library_by_hand.py, which always runs.
"""

from __future__ import annotations

import re
import tomllib
from functools import cache

import pytest
import sympy
from support.pending_syntax import UNSOLVED, skip_if_pending
from support.symbolic_published import (
    DEGREES,
    EXPR,
    PUBLISHED,
    RANGE,
    SHOWN,
    TAN,
    Row,
    same_angle,
    same_degrees,
    values_of_e,
)
from sympy.parsing.sympy_parser import parse_expr

import derive
from derive import resources
from derive.problem.expr import parse

#: Defects of derive these problems found, as strict expected failures: each test of the
#: listed kind ("result", "show", "answers") fails until derive is fixed, and then the
#: strict xfail fails too, so the entry is removed with the fix.
DEFECTS: dict[tuple[str, str], str] = {
    **{(stem, kind): reason for stem, reason in UNSOLVED.items() for kind in ("result", "show", "answers")},
}


def param(stem: str, kind: str, *values: object, id: str) -> object:
    """A test case, marked as a strict expected failure where DEFECTS lists it."""
    reason = DEFECTS.get((stem, kind))
    marks = [pytest.mark.xfail(strict=True, reason=reason)] if reason else []
    return pytest.param(stem, *values, id=id, marks=marks)


#: [assume] kinds and the SymPy assumptions a letter of that kind has.
KINDS = {
    "positive": {"positive": True},
    "acute": {"positive": True},
    "nonnegative": {"nonnegative": True},
    "real": {"real": True},
    "negative": {"negative": True},
}


def _file(stem: str) -> dict:
    with resources.bundled()[stem].open("rb") as f:
        return tomllib.load(f)


@cache
def solved(stem: str) -> derive.Solution:
    return derive.solve(derive.load(stem))


def solution_of(stem: str) -> derive.Solution:
    skip_if_pending(stem, unsolved=False)  # a known defect is a strict expected failure here
    return solved(stem)


def letters(stem: str, solution: derive.Solution) -> dict[str, sympy.Symbol]:
    """Each given's name -> a symbol with the assumptions the problem gives it (positive unless said)."""
    assume = _file(stem).get("assume", {})
    names = {g.name for g in solution.problem.givens} | {"e"}
    return {name: sympy.Symbol(name, **KINDS[assume.get(name, "positive")]) for name in names}


def in_letters(stem: str, solution: derive.Solution, expr: sympy.Basic) -> sympy.Basic:
    """``expr`` with the numbers of the givens put in and every letter as :func:`letters` makes it."""
    numbers = {g.symbol: g.value for g in solution.problem.givens if g.value is not None and not g.unknown}
    expr = expr.xreplace(numbers)
    named = letters(stem, solution)
    return expr.xreplace({s: named[s.name] for s in expr.free_symbols if s.name in named})


def from_file(stem: str, solution: derive.Solution, text: str) -> sympy.Basic:
    """An ``answers`` string of the file, read with derive's restricted parser."""
    names = {g.name: (g.symbol, g.dim) for g in solution.problem.givens}
    return in_letters(stem, solution, parse(text, names).expr)


def from_test(stem: str, solution: derive.Solution, text: str) -> sympy.Basic:
    """A fixed string of tests/support/symbolic_published.py, with the problem's letters."""
    return parse_expr(text.replace("^", "**"), local_dict=dict(letters(stem, solution)))


def agree(rule: str, actual: sympy.Basic, expected: sympy.Basic) -> bool:
    if rule == EXPR:
        return sympy.simplify(actual - expected) == 0
    if rule == TAN:
        return same_angle(actual, expected)
    raise AssertionError(f"unknown rule {rule}")


ROWS = [
    param(stem, "result", row, id=f"{stem}:{row.name}:{row.rule}") for stem, rows in PUBLISHED.items() for row in rows
]


@pytest.mark.parametrize(("stem", "row"), ROWS)
def test_derive_gives_the_published_result(stem: str, row: Row) -> None:
    solution = solution_of(stem)
    if row.rule == RANGE:
        found = [f for f in solution.ranges if re.sub(r"\s+", "", f.range.text) == re.sub(r"\s+", "", row.name)]
        assert len(found) == 1, f"{stem}: no range where {row.name} ({[f.range.text for f in solution.ranges]})"
        assert found[0].interval is not None, f"{stem}: derive left the range where {row.name} undecided"
        printed = from_test(stem, solution, row.published)
        assert values_of_e(found[0].interval) == values_of_e(printed), f"{stem}: {found[0].interval}, printed {printed}"
        return
    assert row.name in solution.results, f"{stem}: derive computes no {row.name} ({sorted(solution.results)})"
    actual = in_letters(stem, solution, solution.results[row.name].closed)
    if row.rule == DEGREES:
        assert same_degrees(actual, row.published), f"{row.name} = {actual}, published {row.published} deg"
        return
    printed = from_test(stem, solution, row.published)
    stated = from_file(stem, solution, _file(stem)["answers"][row.name])
    assert agree(row.rule, stated, printed), f"{stem}: the file states {stated}, the mark scheme {printed}"
    assert agree(row.rule, actual, printed), f"{stem}: {row.name} = {actual}, the mark scheme prints {printed}"


@pytest.mark.parametrize("stem", [param(stem, "show", id=stem) for stem in sorted(SHOWN)])
def test_each_show_that_holds_and_ends_as_required(stem: str) -> None:
    solution = solution_of(stem)
    assert len(solution.shown) == len(SHOWN[stem])
    for shown in solution.shown:
        assert shown.holds, f"{stem}: derive says {shown.relation.text} does not follow ({shown.counterexample})"
    md = derive.render(solution, "md")
    assert md.count("as required") >= len(SHOWN[stem]), f"{stem}: a shown result does not end 'as required'"
    assert "does not follow" not in md


@pytest.mark.parametrize("stem", [param(stem, "answers", id=stem) for stem in sorted(PUBLISHED)])
def test_every_answer_of_the_file_is_checked(stem: str) -> None:
    """The file's answers are exactly the rows checked above (its answer key holds nothing unchecked)."""
    solution = solution_of(stem)
    checked = {row.name for row in PUBLISHED[stem] if row.in_answers}
    assert set(_file(stem)["answers"]) == checked
    assert checked <= set(solution.results)
