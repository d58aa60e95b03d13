"""HTML's character references in a Markdown derivation (``&nbsp;``, ``&minus;``, ``&times;``), as
a Markdown page shows them: a space, −, ×. A line with them is read and judged as the same
line typed with the characters; a bare ``&`` (LaTeX's column) is left alone.

BYJU'S (A 4 kg at 12 m/s catches B 8 kg at 4 m/s, e = 0.5), by hand: 4(12) + 8(4) = 80 =
4a + 8b; b - a = 0.5(12 - 4) = 4; so 12a = 80 - 32 = 48, a = 4 and b = 8 m/s."""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.entities import decoded

PROBLEM = "byjus-4kg-ball-catches-8kg-ball"
WORK = """Momentum:&nbsp;$4(12) + 8(4) = 4a + 8b$
NEL:&nbsp;&nbsp;$b &minus; a = 0.5(12 &minus; 4) = {nel}$
$12a = 80 &minus; 8&times;4 = 48$&nbsp;&nbsp;so $a = 4$&nbsp;m/s, $b = 8$&nbsp;m/s
"""


def test_references_are_their_characters() -> None:
    assert decoded("a&nbsp;=&nbsp;3&#160;m/s &times; 2 &#x221A;3") == "a = 3 m/s × 2 √3"
    assert decoded(r"v_A &= 3 && \text{(1)} \\ & = 4") == r"v_A &= 3 && \text{(1)} \\ & = 4"


def test_a_line_with_html_spaces_and_signs_is_judged() -> None:
    found = worst_lines(PROBLEM, WORK.format(nel="4"))
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3, found


@pytest.mark.parametrize("nel", ["5", "6"])
def test_a_wrong_line_with_html_spaces_is_wrong(nel: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(nel=nel))[2][0] == "wrong"
