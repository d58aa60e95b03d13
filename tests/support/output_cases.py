"""Problems for the output-validity tests: the bundled ones, plus one written here.

The extra problem is a direct impact (the bundled ones are oblique) whose text is
full of characters that mean something in Markdown, LaTeX or HTML, so that the
escaping of user text is checked by KaTeX and by TeX as well.
"""

from __future__ import annotations

import os
import re
from functools import cache
from pathlib import Path

import pytest

import derive
from derive import resources
from support.pending_syntax import pending_reason

HOSTILE_DIRECT = r"""
title = "Direct impact: $5 & 100% of #1 {x} \\input{/etc/passwd} a_b ^ ~ <b> | `code` *bold* [l](u) café θ → ≈ ½ Ω ∞ re\u0301gle\u0301e"
kind = "direct"
source = "Made up: \\$ costs $3 and $4; \\(not math\\) $$ not display $$"
statement = "Ball A (2 kg, 3 m/s) hits ball B (1.5 kg, -2 m/s) head-on; e = 0.5. 50% off, x_1 & y_2, 10^3 ~ 1e3, \\section{x} \\\\ \\end{document}."
question = "Find the velocities after the impact, and T_lost."
find = ["v_A2", "v_B2", "T_lost"]

[given]
m_A = "2 kg"
m_B = "1.5 kg"
e = 0.5
v_A1 = "3 m/s"
v_B1 = "-2 m/s"
"""


def in_ci() -> bool:
    """True when the CI environment variable says we run in CI (CI=true)."""
    return os.environ.get("CI", "").strip().lower() in ("true", "1", "yes")


def missing_tool(reason: str) -> None:
    """Fail in CI (a missing tool must not pass silently there); skip elsewhere, saying why."""
    if in_ci():
        pytest.fail(f"{reason} (CI=true: a missing tool is a failure, not a skip)", pytrace=False)
    pytest.skip(reason)


def bundled_names() -> list[str]:
    """Names of the bundled problems (the test ids).

    Problems written in the issue #14 syntax before derive reads it are left out until it
    does (tests/support/pending_syntax.py; test_symbolic_library.py reports them as skipped).
    """
    return [name for name in resources.bundled() if pending_reason(name) is None]


@cache
def solution(name: str) -> derive.Solution:
    """The solution of a bundled problem, solved once per test session."""
    return derive.solve(derive.load(name))


def hostile_problem(tmp_dir: Path) -> Path:
    """Write the problem with hostile text into ``tmp_dir``; its path."""
    path = tmp_dir / "hostile-direct.toml"
    path.write_text(HOSTILE_DIRECT, encoding="utf-8")
    return path


_VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source", "track", "wbr"}


def html_text(page: str) -> str:
    """An HTML page's text content, checked to be well formed on the way (every element
    closed, in order), without its figures (SVG coordinates are numbers too), its scripts,
    its styles and KaTeX's copies of the TeX (``<annotation>``); minus signs as ``-``, next to their number."""
    from html.parser import HTMLParser

    class Reader(HTMLParser):
        def __init__(self) -> None:
            super().__init__(convert_charrefs=True)
            self.stack: list[str] = []
            self.text: list[str] = []

        def handle_starttag(self, tag: str, attrs: list) -> None:
            if tag not in _VOID:
                self.stack.append(tag)

        def handle_endtag(self, tag: str) -> None:
            assert self.stack and self.stack[-1] == tag, f"</{tag}> closes <{self.stack[-1:]}>"
            self.stack.pop()

        def handle_data(self, data: str) -> None:
            if not {"svg", "script", "style", "annotation"} & set(self.stack):
                self.text.append(data)

    reader = Reader()
    reader.feed(page)
    reader.close()
    assert reader.stack == [], f"unclosed: {reader.stack}"
    text = " ".join(reader.text).replace("\u2212", "-")  # KaTeX's minus sign
    return re.sub(r"-\s+(?=\d)", "-", text)  # MathML's "- 9.15" as printed: -9.15
