"""Vectors as US intro-physics homework types them (issue #31): components in angle brackets
(``<9, 12>``, ``⟨9, 12⟩``, LaTeX's ``\\langle 9, 12\\rangle``), in a before/after table (Markdown
or a LaTeX ``tabular`` whose cells are set apart by ``&``), a bold letter with its body after it
(``**u**_A``). Each is one relation per component, as ``(9, 12)`` is; an inequality stays one.

Values worked by hand: OCR M3 June 2007 Q4 (A 4 kg at 15 m/s at alpha to the line of centres,
sin alpha = 0.8; B 3 kg at 12 m/s toward A; e = 0.5). Along the line of centres A has
15(0.6) = 9, across it 15(0.8) = 12; 4(9) + 3(-12) = 0 = 4a + 3b, b - a = 0.5(9 + 12) = 10.5,
so a = -4.5, b = 6; A keeps 12 across, B none (mark scheme: a = -4.5, b = 6).
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "ocr-m3-2007-oblique-sin-alpha-0p8"


def sides(text: str) -> list[tuple[str, ...]]:
    return [r.sides for r in read_relations(text)]


@pytest.mark.parametrize(
    "text",
    [
        "u_A = <15(0.6), 15(0.8)> = <9, 12>",
        "u_A = ⟨15(0.6), 15(0.8)⟩ = ⟨9, 12⟩",
        r"$\vec u_A = \langle 15(0.6),\ 15(0.8)\rangle = \left\langle 9,\ 12\right\rangle$",
        "Before: **u**_A = <15(0.6), 15(0.8)> = <9, 12>",
    ],
)
def test_a_vector_in_angle_brackets_is_one_relation_per_component(text: str) -> None:
    assert sides(text) == [("u_An", "15(0.6)", "9"), ("u_At", "15(0.8)", "12")]


@pytest.mark.parametrize("text", ["0 < e < 1, so v_A > 0", "e < 1, v_B > 2", "A -> B, v_A < 3"])
def test_inequalities_are_no_vector(text: str) -> None:
    assert all(len(s) != 2 or "," not in "".join(s) for s in sides(text))
    assert ("v_An",) not in [s[:1] for s in sides(text)]


MARKDOWN = """x along the line of centres (A to B), y perpendicular to it.

| body | before | after |
|---|---|---|
| A | <15(0.6), 15(0.8)> = <9, 12> | <a, 12> |
| B | <-12, 0> | <b, 0> |

4(9) + 3(-12) = 4a + 3b
b - a = 0.5(9 + 12) = 10.5
a = -4.5, b = 6
v_A = <-4.5, 12> m/s, v_B = <6, 0> m/s
"""


def test_a_before_after_table_of_angle_bracket_vectors_is_read() -> None:
    found = worst_lines(PROBLEM, MARKDOWN)
    assert found[5] == ("correct", "")
    assert found[11][0] == "correct"


def test_a_wrong_component_in_the_table_is_wrong() -> None:
    found = worst_lines(PROBLEM, MARKDOWN.replace("<9, 12>", "<9, 21>"))
    assert found[5][0] == "wrong"


TABULAR = r"""$x$ along the line of centres from A to B, $y$ perpendicular.

\begin{tabular}{l|c|c}
 & before & after\\ \hline
A & $\langle 15\cos\alpha, 15\sin\alpha\rangle = \langle 9, 12\rangle$ & $\langle a, 12\rangle$\\
B & $\langle -12, 0\rangle$ & $\langle b, 0\rangle$
\end{tabular}
\begin{align*}
4(9) + 3(-12) &= 4a + 3b\\
b - a &= 0.5(9 + 12) = 10.5\\
a &= -4.5
\end{align*}
$\vec v_A = \left\langle -4.5,\ 12\right\rangle$ m/s
"""


def test_a_tabular_row_of_langle_vectors_is_read() -> None:
    found = worst_lines(PROBLEM, TABULAR)
    assert found[5] == ("correct", "")
    assert found[13][0] == "correct"


def test_a_wrong_component_after_in_langle_is_wrong() -> None:
    found = worst_lines(PROBLEM, TABULAR.replace(r"-4.5,\ 12\right", r"-4.5,\ 6\right"))
    assert found[13][0] == "wrong"
