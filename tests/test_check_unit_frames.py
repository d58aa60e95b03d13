"""Vectors in the student's own unit vectors (docs/checking.md, "Vectors"): a unit vector along
the line of centres declared in the student's i and j (``n̂ = cos 30° i − sin 30° j``, ``\\hat n =
(\\cos 20°, \\sin 20°)``) is the student's frame: a vector in i and j is, on derive's n and t, its
dot products with n̂ and t̂ (t̂ as declared, or n̂ turned a quarter turn counter-clockwise); a dot
product with a unit vector (``u_A · n̂``, ``\\vec u_A \\cdot \\hat n``, ``u_A · î``) is the component;
Unicode's hats (``3î + 4ĵ``) are unit vectors.

Values worked by hand from the problems' givens:
- mcasco-glancing-disks-us: A at 8 ft/s at 30° to the line of centres, B at rest, equal disks,
  e = 0.8. With i along A's path (j a quarter turn from it), n̂ = cos 30° i − sin 30° j and
  t̂ = sin 30° i + cos 30° j; u_A = 8 i, so u_A · n̂ = 8 cos 30° = 6.928 and u_A · t̂ = 8 sin 30° = 4.
  After: v_An = 6.928 (1 − 0.8)/2 = 0.6928, v_At = 4.
- fisicalab-example-7-normal-at-20deg: A 80 m/s at 45° from x, B 110 m/s at 120°, the normal at
  20°: u_A = (56.57, 56.57), u_B = (−55.00, 95.26); u_A · n̂ = 80 cos 25° = 72.50, u_B · n̂ =
  110 cos 100° = −19.10, u_B · t̂ = 110 sin 100° = 108.3.
- ocr-m3-2007-oblique-sin-alpha-0p8: i along the line of centres, u_A = 15(0.6 i + 0.8 j) = 9i + 12j.
- notes-4c11-two-spheres: cos 37.6° = 0.7923, sin 37.6° = 0.6101: u_A = 3.96 i + 3.05 j,
  u_B = −11.88 i − 9.15 j.
"""

from __future__ import annotations

from support.checked import line_statuses as statuses

from derive.checking.frames import declared_axes
from derive.mathtext.reader import read_relations

DISKS = "mcasco-glancing-disks-us"
FISICALAB = "fisicalab-example-7-normal-at-20deg"
OCR = "ocr-m3-2007-oblique-sin-alpha-0p8"
SPHERES = "notes-4c11-two-spheres"

ALONG_A = """Take i along A's path and j perpendicular to it.
The line of centres: n̂ = cos 30° i − sin 30° j, and t̂ = sin 30° i + cos 30° j.
u_A = 8 i ft/s
u_A · n̂ = 8 cos 30° = 6.928 ft/s
u_A · t̂ = 8 sin 30° = 4 ft/s
v_A = 0.6928 n̂ + 4 t̂
"""


def test_a_frame_declared_in_i_and_j_turns_the_vectors_written_in_them() -> None:
    assert statuses(DISKS, ALONG_A) == ["correct"] * 4


def test_a_dot_product_with_the_wrong_function_is_wrong_in_the_students_frame() -> None:
    work = ALONG_A.replace("u_A · n̂ = 8 cos 30° = 6.928", "u_A · n̂ = 8 sin 30° = 4")
    assert statuses(DISKS, work)[1] == "wrong"


LATEX = r"""$\hat n = (\cos 20^\circ, \sin 20^\circ)$ in the question's axes.

$\vec u_A = 80(\cos 45^\circ, \sin 45^\circ) = (56.57, 56.57)$

$\vec u_B = 110(\cos 120^\circ, \sin 120^\circ) = (-55.00, 95.26)$

$\vec u_A \cdot \hat n = 80\cos 25^\circ = 72.50$

$\vec u_B \bullet \hat n = 110\cos 100^\circ = -19.10$

$\vec u_B \cdot \hat t = 110\sin 100^\circ = 108.3$
"""


def test_pairs_in_the_questions_axes_and_dot_products_typed_in_latex() -> None:
    assert statuses(FISICALAB, LATEX) == ["correct"] * 5


def test_a_component_of_the_wrong_sign_in_the_questions_axes_is_wrong() -> None:
    work = LATEX.replace("(-55.00, 95.26)", "(55.00, 95.26)")
    assert statuses(FISICALAB, work)[1] == "wrong"


def test_the_frame_declaration_is_not_a_relation_and_places_no_axes_in_words() -> None:
    text = "Unit vector along the line of centres n̂ = cos 20° i + sin 20° j\nu_A = 3 i"
    assert [r.sides for r in read_relations(text)] == [
        ("u_An", "(3)*(cos 20°)"),
        ("u_At", "(3)*(-(sin 20°))"),
    ]
    assert declared_axes("i along +x. Along the line of centres n̂ = cos 20° i + sin 20° j") == {}


def test_a_dot_product_with_i_or_j_where_i_is_the_line_of_centres() -> None:
    work = "i along the line of centres (A to B), j perpendicular.\nu_A = 15(0.6 i + 0.8 j) = 9i + 12j\nu_A · î = 9\nu_A · ĵ = 12\n"
    assert statuses(OCR, work) == ["correct"] * 3
    assert statuses(OCR, work.replace("u_A · ĵ = 12", "u_A · ĵ = 9"))[-1] == "wrong"


def test_unicode_hats_are_unit_vectors() -> None:
    work = (
        "î along the line of impact from A to B, ĵ across it.\n"
        "u_A = 5 cos 37.6° î + 5 sin 37.6° ĵ = 3.96î + 3.05ĵ\n"
        "u_B = −15 cos 37.6° î − 15 sin 37.6° ĵ = −11.9î − 9.15ĵ\n"
    )
    assert statuses(SPHERES, work) == ["correct", "correct"]
    assert statuses(SPHERES, work.replace("= −11.9î", "= 11.9î"))[-1] == "wrong"


CARRIED = """i along x, j along y. n̂ = cos 20° i + sin 20° j, t̂ = −sin 20° i + cos 20° j.
u_A = 80(cos 45° i + sin 45° j) = 56.57 i + 56.57 j
u_B = 110(cos 120° i + sin 120° j) = 55.00 i + 95.26 j
u_A · n̂ = 56.57 cos 20° + 56.57 sin 20° = 72.50
u_B · n̂ = 55.00 cos 20° + 95.26 sin 20° = 84.26
4a + 3b = 4(72.50) + 3(84.26) = 542.8
"""


def test_a_dot_product_of_a_vector_written_wrong_is_carried() -> None:
    # B's x component is -55.00 (110 cos 120°); written +55.00, u_B · n̂ = 55.00(0.9397) + 95.26(0.3420)
    # = 51.68 + 32.58 = 84.26 follows from it (the right one is -19.10): carried, as the momentum after it
    assert statuses(FISICALAB, CARRIED) == ["correct", "wrong", "correct", "carried", "carried"]
    said_again = CARRIED.replace("u_B · n̂ = 55.00 cos 20° + 95.26 sin 20° = 84.26", "u_B · n̂ = 84.26")
    assert statuses(FISICALAB, said_again) == ["correct", "wrong", "correct", "carried", "carried"]


BOLD = """Take **i** along the line of centres from A to B and **j** perpendicular.

**u**_A = 15(0.6**i** + 0.8**j**) = 9**i** + 12**j**, **u**_B = −12**i**

After: **v**_A = a**i** + 12**j**, **v**_B = b**i**

4(9**i** + 12**j**) + 3(−12**i**) = 4(a**i** + 12**j**) + 3b**i**

b − a = 0.5(9 + 12) = 10.5
"""


def test_markdown_bold_vectors_glued_and_a_number_times_a_letter_before_i() -> None:
    # OCR M3 2007: 4(9) + 3(-12) = 0 = 4a + 3b along i, 4(12) = 4(12) across; b - a = 0.5(9 + 12)
    assert statuses(OCR, BOLD) == ["correct"] * 4
    assert statuses(OCR, BOLD.replace("3(−12**i**) =", "3(12**i**) ="))[2] == "wrong"


HEAD_ON = "aqa-m3-2007-spheres-approach-head-on"


def test_a_side_in_names_beside_vectors_on_the_one_axis_of_a_head_on_impact() -> None:
    # m_B = 0.2 kg, u_B = -2, v_B = 3.4 (m/s along i): the impulse on B is 0.2(3.4 - (-2)) = 1.08 along i
    assert statuses(HEAD_ON, "J = m_B(v_B - u_B) = 0.2(3.4 i - (-2 i)) = 1.08 i") == ["correct"]
    assert statuses(HEAD_ON, "J = m_B(v_B - u_B) = 0.2(3.4 i - (-2 i)) = 0.28 i") == ["wrong"]
