"""The documentation's examples work: every complete problem in docs/ and README solves."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import derive
from derive.problem import loads

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "docs" / "problem-format.md", ROOT / "README.md"]


def examples() -> list[pytest.param]:
    out = []
    for doc in DOCS:
        blocks = re.findall(r"```toml\n(.*?)```", doc.read_text(encoding="utf-8"), flags=re.S)
        for i, block in enumerate(blocks):
            if block.lstrip().startswith("title"):
                out.append(pytest.param(block, id=f"{doc.name}-{i}"))
    return out


@pytest.mark.parametrize("text", examples())
def test_documented_problem_solves(text: str) -> None:
    solution = derive.solve(loads(text, path="example.toml"))
    assert "ANSWER" in derive.render(solution, "md")


def test_there_are_documented_examples() -> None:
    assert len(examples()) >= 3
