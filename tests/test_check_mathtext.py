"""derive/mathtext: the one reader of typed mathematics (issue #25 item 5, issue #31 item 3),
and the reading of a derivation in the student's own names (issue #31 items 1-2).

Values are worked by hand: Spheres meet head-on (2 kg and 1 kg at 5 m/s each, e = 0.8):
2(5) - 5 = 5 = 2x + y and y - x = 8, so x = -1, y = 7; the wall (2 kg at 4 m/s, e = 0.4):
it rebounds at 1.6 m/s.
"""

from __future__ import annotations

import pytest

import derive
from derive.mathtext.latex import latex_to_plain
from derive.mathtext.notation import student
from derive.mathtext.reader import read_relations


def sides(text: str) -> list[tuple[int, tuple[str, ...]]]:
    return [(r.line, r.sides) for r in read_relations(text)]


def test_two_relations_on_a_line_and_so() -> None:
    assert sides("v_B1n = -6 m/s, v_B1t = 0\n3x = -3  so x = -1, y = 7") == [
        (1, ("v_B1n", "-6")),
        (1, ("v_B1t", "0")),
        (2, ("3x", "-3")),
        (2, ("x", "-1")),
        (2, ("y", "7")),
    ]


def test_a_bracket_call_with_a_comma_is_one_relation() -> None:
    assert sides("theta = atan2(1.11, 3.05)") == [(1, ("theta", "atan2(1.11, 3.05)"))]


def test_comments_headings_and_prose_are_skipped() -> None:
    text = "# Heading\n<!-- KE lost = initial - final -->\nI take left as positive.\n% e = 5 in a TeX comment\nx = 2\n"
    assert sides(text) == [(5, ("x", "2"))]


def test_align_rows_keep_their_lines_and_a_display_spans_lines() -> None:
    text = "\\begin{align*}\na &= 1 \\\\\nb &= 2\n\\end{align*}\n$$c\n= 3$$\n"
    assert sides(text) == [(2, ("a", "1")), (3, ("b", "2")), (5, ("c", "3"))]


def test_a_line_that_starts_with_equals_continues_the_one_above() -> None:
    assert sides("KE = 0.5 x 4^2\n    = 8") == [(1, ("KE", "0.5 x 4^2")), (2, ("0.5 x 4^2", "8"))]


def test_columns_say_where_a_line_starts() -> None:
    (r,) = read_relations("   x = 2")
    assert (r.line, r.column) == (1, 3)


@pytest.mark.parametrize(
    ("tex", "plain"),
    [
        (r"v = -e\,u", "v = -e u"),
        (r"a \; b \quad c", "a b c"),
        (r"\tan^{-1}(0.5)", "atan(0.5)"),
        (r"x \approx 2", "x = 2"),
        (r"\frac{45\,000}{2}", "45000/2"),
        (r"T_{\text{lost}} = 3", "T_lost = 3"),
    ],
)
def test_latex_notation(tex: str, plain: str) -> None:
    assert latex_to_plain(tex) == plain


def test_inverse_functions_typed_in_plain_text() -> None:
    assert student("tan^-1(1.11/3.05)") == "atan(1.11/3.05)"
    assert student("tan^(-1)(2)") == "atan(2)"


def test_x_and_y_are_inferred_and_said() -> None:
    work = "2(5) + 1(-5) = 2x + y\ny - x = 0.8(5 + 5) = 8\nx = -1, y = 7\n"
    report = derive.check(derive.solve(derive.load("ocr-m2-2006-spheres-meet-at-5-ke-lost")), derivation=work)
    assert report.all_correct, report.text()
    assert any("x is v_A2" in n and "y is v_B2" in n for n in report.notes), report.notes


def test_the_sign_convention_is_inferred_from_the_values() -> None:
    work = "u = -4\nv = -0.4 * u = 1.6\n"
    report = derive.check(derive.solve(derive.load("edexcel-m2-ball-rebounds-from-wall")), derivation=work)
    assert report.all_correct, report.text()
    assert any("opposite to derive's n" in n for n in report.notes), report.notes


def test_a_declared_convention_is_not_overruled() -> None:
    # positive toward the wall (derive's n): u = -4 is then the wrong sign, a slip
    work = "positive: from A toward B\nu = -4\n"
    report = derive.check(derive.solve(derive.load("edexcel-m2-ball-rebounds-from-wall")), derivation=work)
    assert [i.status for i in report.items] == ["wrong"], report.text()


def test_a_name_the_student_introduces() -> None:
    work = "u_A = 12, u_B = 4\nG = (m_A u_A + m_B u_B)/(m_A + m_B)\nG = 6.667\nv_A = G - e(u_A - G) = 4.00\n"
    report = derive.check(derive.solve(derive.load("byjus-4kg-ball-catches-8kg-ball")), derivation=work)
    assert report.all_correct, report.text()
    assert "Defines G" in report.items[1].message


def test_divided_by_a_fraction_is_divided_by_the_whole_fraction() -> None:
    # \div then \frac{2u}{9}: the quotient is (3u/11)/(2u/9) = 27/22 (corpus e13), not
    # (3u/11)/(2u) then /9; 6 ÷ ½ is 12.
    assert latex_to_plain(r"\frac{3u}{11} \div \frac{2u}{9} = \frac{27}{22}") == "(3u)/11 / ((2u)/9) = 27/22"
    assert latex_to_plain(r"x = 6 \div \tfrac{1}{2}") == "x = 6 / (1/2)"
