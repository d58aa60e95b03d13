"""LaTeX's layout around a display's rows (issue #31): a row's end with extra space after it
(``\\\\[4pt]``, ``\\\\ [1ex]``, ``\\\\[\\baselineskip]``) or its no-break star (``\\\\*``) ends the row;
the space asked for is no part of the next row's mathematics, and that row is judged on its own line.

Values worked by hand: OCR M3 June 2007 Q4 (A 4 kg, 15 m/s at alpha to the line of centres with
sin alpha = 0.8: along it 9; B 3 kg, 12 m/s toward A; e = 0.5): 4(9) + 3(-12) = 4a + 3b,
b - a = 0.5(9 + 12) = 10.5, so 4a + 3(a + 10.5) = 0, 7a = -31.5, a = -4.5, b = 6.
"""

from __future__ import annotations

from support.checked import worst_lines

PROBLEM = "ocr-m3-2007-oblique-sin-alpha-0p8"
WORK = r"""Along the line of centres, $x$ from A to B:
\begin{align*}
4(9) + 3(-12) &= 4a + 3b \\[4pt]
b - a &= 0.5(9 + 12) = 10.5 \\ [1ex]
7a &= -31.5 \\*
a &= -4.5 \\[\baselineskip]
b &= -4.5 + 10.5 = 6
\end{align*}
"""


def test_rows_after_extra_space_are_read_on_their_own_lines() -> None:
    found = worst_lines(PROBLEM, WORK)
    assert {n: found.get(n, ("missing", ""))[0] for n in (3, 4, 5, 6, 7)} == dict.fromkeys((3, 4, 5, 6, 7), "correct")


def test_a_wrong_row_after_extra_space_is_wrong() -> None:
    found = worst_lines(PROBLEM, WORK.replace("0.5(9 + 12) = 10.5", "0.5(9 - 12) = -1.5"))
    assert found[4][0] == "wrong"
