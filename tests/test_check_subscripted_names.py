"""Names as engineering students type them (issue #31): Unicode's subscripts after a bracketed
name (``(v_B)ₓ₂``, ``(v_A)₁``) and a velocity's letter alone in brackets, its component and
instant glued after (``(v)n1``, ``(v)t2``). Each is the name it spells in ASCII.

Values worked by hand. OCR M3 2006 (A 5 kg moving across the line of centres, B 2 kg at 4 m/s
along it toward A, e = 0.75): along the line of centres 5(0) + 2(-4) = -8 = 5a + 2b and
b - a = 0.75(0 + 4) = 3, so 7a = -14, a = -2, b = 1. Giancoli 7-18 (0.060 kg ball at 28 m/s,
45° to the normal of a smooth wall, e = 1): into the wall 28 cos 45° = 19.80, along it
28 sin 45° = 19.80; after, along it 19.80 still, into it -1(19.80) = -19.80.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.subscripted import ascii_subscripts

DISCS = "ocr-m3-2006-oblique-a-across-centres"
DISC_WORK = """x along the line of centres from A to B.
(v_B)ₓ₁ = −4 m/s
5(0) + 2(−4) = 5(v_A)ₓ₂ + 2(v_B)ₓ₂
(v_B)ₓ₂ − (v_A)ₓ₂ = 0.75(0 + 4) = 3
7(v_A)ₓ₂ = −14, (v_A)ₓ₂ = −2
(v_B)ₓ₂ = −2 + 3 = 1 m/s
"""
WALL = "giancoli-7-18-tennis-ball-wall-45deg"
WALL_WORK = """n = normal into the wall, t = along the wall.
(v)n1 = 28 cos 45° = 19.80 m/s
(v)t1 = 28 sin 45° = 19.80 m/s
(v)t2 = (v)t1 = 19.80 m/s
(v)n2 = -e (v)n1 = -19.80 m/s
"""


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("(v_B)ₓ₂ − (v_A)ᵧ₁", "(v_B)_x2 − (v_A)_y1"),
        ("v₁ + v_A₂", "v_1 + v_A2"),
        ("(v)n2 = -e (v)_n1", "v_n2 = -e v_n1"),
        ("(a) v = 3", "(a) v = 3"),
    ],
)
def test_marks_in_ascii(text: str, expected: str) -> None:
    assert ascii_subscripts(text) == expected


def test_unicode_subscripts_after_a_bracketed_name_are_read() -> None:
    found = worst_lines(DISCS, DISC_WORK)
    assert {n: found.get(n, ("missing", ""))[0] for n in (2, 3, 4, 5, 6)} == dict.fromkeys((2, 3, 4, 5, 6), "correct")


def test_a_slip_in_unicode_subscripted_names_is_wrong() -> None:
    found = worst_lines(DISCS, DISC_WORK.replace("= 0.75(0 + 4) = 3", "= 0.75(0 - 4) = -3"))
    assert found[4][0] == "wrong"


def test_a_bare_bracketed_letter_with_component_and_instant_is_read() -> None:
    found = worst_lines(WALL, WALL_WORK)
    assert {n: found.get(n, ("missing", ""))[0] for n in (2, 3, 4, 5)} == dict.fromkeys((2, 3, 4, 5), "correct")


def test_a_slip_in_bare_bracketed_names_is_wrong() -> None:
    found = worst_lines(WALL, WALL_WORK.replace("-e (v)n1 = -19.80", "-e (v)n1 = -9.90"))
    assert found[5][0] == "wrong"


@pytest.mark.parametrize(("name", "spelled"), [("θ2", "θ_2"), ("θ₂", "θ_2"), ("theta2", "theta_2"), ("φ1", "φ_1")])
def test_an_angles_letter_with_its_instant_glued_on_is_read(name: str, spelled: str) -> None:
    # Giancoli 7-18: the ball leaves at 45° to the normal, on the other side of it (e = 1).
    for angle in ("45°", "30°"):  # read as the name with its underscore is, whatever the value
        found = worst_lines(WALL, f"{name} = {angle}\n")
        assert found == worst_lines(WALL, f"{spelled} = {angle}\n")
        assert found[1][0] != "not read"
    assert worst_lines(WALL, "θ2 = 45°\n")[1][0] == "correct"
