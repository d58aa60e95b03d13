"""Two plane vectors with ``\\times`` between them (``\\mathbf{u}\\times\\mathbf{v}``, ``\\vec a
\\times \\vec b``) are their cross product, its one component across the plane: a_n b_t - a_t b_n
(the sine of the angle between them times their sizes), as ``\\cdot`` between them is their dot
product; ``\\times`` between numbers is still times.

Worked by hand for notes 4.C.11 (A at 5 m/s at 37.6 deg to n): v_A1 = (5 cos 37.6, 5 sin 37.6) =
(3.9619, 3.0505); (3) and (4) give v_A2n = -1.1092 and v_A2t = 3.0505, so
v_A1 x v_A2 = 3.9619(3.0505) - 3.0505(-1.1092) = 3.0505(5.0711) = 15.47.
"""

from __future__ import annotations

from support.checked import lines

from derive.mathtext.latex import latex_to_plain


def test_the_cross_product_of_two_vectors_in_components() -> None:
    assert latex_to_plain(r"\vec a \times \vec b") == "(a_n b_t - a_t b_n)"
    assert latex_to_plain(r"1.67 \times 10^{-27}") == "1.67 * 10^(-27)"


CROSS = r"""
$$\vec{v}_{A1} \times \vec{v}_{A2} = (3.962)(3.050) - (3.050)(-1.109) = 15.47$$
"""


def test_a_cross_product_worked_in_numbers() -> None:
    assert lines("notes-4c11-two-spheres", CROSS)[2][0] == "correct"


def test_a_cross_product_with_a_sign_slip_is_wrong() -> None:
    wrong = CROSS.replace("- (3.050)(-1.109) = 15.47", "+ (3.050)(-1.109) = 8.70")
    assert lines("notes-4c11-two-spheres", wrong)[2][0] == "wrong"
