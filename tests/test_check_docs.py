"""docs/checking.md: every example derivation (a fenced block with ``check=PROBLEM``) is
judged as the text beside it says: each line with a relation correct, but for those its
``expect="LINE:VERDICT …"`` names (issue #31: the header, and every notation shown)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import derive

DOCS = Path(__file__).resolve().parent.parent / "docs" / "checking.md"
BLOCK = re.compile(r'```(\w+) check=(\S+)(?: expect="([^"]*)")?\n(.*?)```', re.S)
VERDICT = {"wrong": "wrong", "again": "wrong", "carried": "carried", "correct": "correct"}


def examples() -> list:
    text = DOCS.read_text(encoding="utf-8")
    found = enumerate(BLOCK.finditer(text))
    return [pytest.param(m.group(2), m.group(3) or "", m.group(4), id=f"{m.group(1)}-{i}") for i, m in found]


def test_every_notation_has_an_example() -> None:
    shown = "".join(work for _p, _e, work in (e.values for e in examples()))
    notations = ("let x", "positive:", "6eu", r"\,", r"\;", r"\quad", "align*", "&", r"\\", "tan^-1(", r"\tan^{-1}")
    notations += (", y = 7", r"\approx", "<!--", "## ", "I take the direction")  # two on a line, prose, heading
    notations += (r"\mathbf{i}", r"\hat\imath", "A = (0, 4)", "A_y'", "|v_A|", "direction of A", "A after:")  # vectors
    notations += ("velocity after =", "(m/s)", "anticlockwise from")  # names in words, words after a number
    notations += ("v_{1i}", "v_{2,i}", "v'_1", "p_i", "K_i")  # names as a grammar
    notations += ("(M1 A1)", " or x = ", "Reject.", "(0 < e < 1)", "From CLM,")  # mark-scheme habits
    for notation in notations:
        assert notation in shown, notation
    assert len(examples()) >= 10


@pytest.mark.parametrize(("problem", "expect", "work"), examples())
def test_documented_derivation(problem: str, expect: str, work: str) -> None:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    wanted = dict(pair.split(":") for pair in expect.split())
    lines = {int(i.name): i for i in report.items if i.kind == "line"}
    relation_lines = [n for n, text in enumerate(work.splitlines(), 1) if re.search(r"=|\\approx", text)]
    for n in relation_lines:
        if re.match(r"\s*(let |positive:)", work.splitlines()[n - 1]):
            assert n not in lines, f"line {n}: a declaration is not judged"
            continue
        assert n in lines, (n, report.text())
        item = lines[n]
        verdict, _, slip = wanted.get(str(n), "correct").partition("/")  # "wrong/algebra": the slip's name
        assert item.status == VERDICT[verdict], (n, report.text())
        assert not slip or item.slip == slip, (n, item.slip, report.text())
        assert item.again == (verdict == "again"), (n, report.text())
    assert report.exit_code == (1 if wanted else 0), report.text()
