"""Simultaneous equations solved with matrices (Cramer's rule, a matrix equation), as students
type them in LaTeX: a matrix equation is its equations, a determinant its value in its entries,
and a relation on the line after a matrix equation ending with a comma is judged on its own line.

Values worked by hand: OCR M3 June 2007 Q4 (A 4 kg, 15 m/s at alpha to the line of centres with
sin alpha = 0.8: along it 9; B 3 kg, 12 m/s toward A; e = 0.5), a and b along the line of centres
after: 4(9) + 3(-12) = 0 = 4a + 3b, b - a = 0.5(9 + 12) = 10.5; the matrix [[4, 3], [-1, 1]] has
determinant 4(1) - 3(-1) = 7; a = (0(1) - 3(10.5))/7 = -31.5/7 = -4.5, b = (4(10.5) - 0(-1))/7 = 6.
"""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.matrices import determinants, matrix_equations

PROBLEM = "ocr-m3-2007-oblique-sin-alpha-0p8"
WORK = r"""Along the line of centres, $a$ and $b$ for A and B after, from A to B:
$$4a + 3b = 0, \qquad b - a = 10.5$$
$$\left[\begin{matrix} 4 & 3 \\ -1 & 1 \end{matrix}\right]\left[\begin{matrix} a \\ b \end{matrix}\right] = \left[\begin{matrix} 0 \\ 10.5 \end{matrix}\right]$$
\begin{align*}
a &= \frac{\det\begin{bmatrix} 0 & 3 \\ 10.5 & 1 \end{bmatrix}}{7} = \frac{-31.5}{7} = -4.5 \\
b &= \frac{1}{7}\left|\begin{matrix} 4 & 0 \\ -1 & 10.5 \end{matrix}\right| = \frac{42}{7} = 6
\end{align*}
"""


def test_a_determinant_is_its_value() -> None:
    assert determinants(r"\begin{vmatrix} p & q \\ r & s \end{vmatrix}").strip() == "((p)(s) - (q)(r))"
    three = determinants(r"\begin{vmatrix} 1 & 2 & 3 \\ 0 & 1 & 4 \\ 5 & 6 & 0 \end{vmatrix}")
    # 1(0 - 24) - 2(0 - 20) + 3(0 - 5) = -24 + 40 - 15 = 1
    assert eval(three.replace(")(", ")*(")) == 1


def test_a_matrix_in_round_brackets_is_not_a_determinant() -> None:
    text = r"\begin{pmatrix} 4 & 3 \\ -1 & 1 \end{pmatrix}"
    assert determinants(text) == text


def test_a_matrix_equation_is_its_equations() -> None:
    text = r"\begin{pmatrix} 4 & 3 \\ -1 & 1 \end{pmatrix}\begin{pmatrix} a \\ b \end{pmatrix} = \begin{pmatrix} 0 \\ 10.5 \end{pmatrix}"
    assert matrix_equations(text) == r"(4)(a) + (3)(b) = 0 \\ (-1)(a) + (1)(b) = 10.5"


def test_a_product_of_shapes_that_do_not_agree_is_left() -> None:
    text = r"\begin{pmatrix} 4 & 3 \\ -1 & 1 \end{pmatrix}\begin{pmatrix} a \\ b \\ c \end{pmatrix} = \begin{pmatrix} 0 \\ 10.5 \end{pmatrix}"
    assert matrix_equations(text) == text


def test_cramers_rule_is_read_and_judged() -> None:
    found = worst_lines(PROBLEM, WORK)
    assert {n: found.get(n, ("missing", ""))[0] for n in (2, 3, 5, 6)} == dict.fromkeys((2, 3, 5, 6), "correct")


def test_a_wrong_matrix_row_is_wrong() -> None:
    found = worst_lines(PROBLEM, WORK.replace(r"-1 & 1 \end{matrix}\right]\left[", r"1 & 1 \end{matrix}\right]\left["))
    assert found[3][0] == "wrong"


def test_a_determinant_worked_wrongly_is_wrong() -> None:
    found = worst_lines(PROBLEM, WORK.replace(r"\frac{42}{7} = 6", r"\frac{-42}{7} = -6"))
    assert found[6][0] == "wrong"


def test_a_relation_after_a_matrix_equation_and_its_comma_has_its_own_line() -> None:
    work = r"""Along the line of centres, $a$ and $b$ for A and B after, from A to B:
\[
\begin{pmatrix} 4 & 3 \\ -1 & 1 \end{pmatrix}\begin{pmatrix} a \\ b \end{pmatrix} = \begin{pmatrix} 0 \\ 10.5 \end{pmatrix},
\qquad D = 4 \cdot 1 - 3 \cdot (-2) = 7.
\]
"""
    found = worst_lines(PROBLEM, work)
    assert found[3][0] == "correct"
    assert found[4][0] == "wrong"
