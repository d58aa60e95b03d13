"""A bare name the student declares a speed (``v_A = sqrt(1.109^2 + 3.051^2) = 3.246``) is that speed on
the later lines that do not work in components (an energy ``½ m v_A²``), though the habit reads a bare
``v_A`` in an oblique impact as A's n component after (docs/checking.md, "Habits").

Example 4.C.11 by hand (m_A = 20, m_B = 5, e = 0.6, A at 5 m/s and B at 15 m/s, each 37.6° from the
line of impact, cos 37.6° = 0.7923, sin 37.6° = 0.6102): before, A n = 3.962, t = 3.051; B n = -11.88,
t = -9.152. Momentum 20(3.962) + 5(-11.88) = 19.81; separation 0.6(3.962 + 11.88) = 9.507; so
25 v_A2n = 19.81 - 5(9.507) gives v_A2n = -1.109, v_B2n = 8.398. Speeds after: A √(1.109² + 3.051²) =
3.246, B √(8.398² + 9.152²) = 12.42. Energies after: A ½(20)(3.246²) = 105.4, B ½(5)(12.42²) = 385.6,
together 491.0. With v_A the n component, ½(20)(1.109²) = 12.30 and ½(5)(8.398²) = 176.3: not these."""

from __future__ import annotations

from support.checked import worst_lines

PROBLEM = "notes-4c11-two-spheres"

LATEX = r"""$20(3.962) + 5(-11.88) = 20v_A + 5v_B$
$v_B - v_A = 0.6(3.962 + 11.88)$
$v_A = -1.109$, $v_B = 8.398$
$v_A = \sqrt{1.109^2 + 3.051^2} = 3.246$
$KE_A = \tfrac12 (20) v_A^2 = 105.4$
"""

PLAIN = """20*3.962 + 5*(-11.88) = 20*vA + 5*vB
vB - vA = 0.6*(3.962 + 11.88)
vA = -1.109, vB = 8.398
vA = sqrt(1.109^2 + 3.051^2) = 3.246
vB = sqrt(8.398^2 + 9.152^2) = 12.42
KE after = 0.5*20*vA^2 + 0.5*5*vB^2 = 491
"""


def test_an_energy_after_a_declared_speed_is_judged_with_the_speed() -> None:
    assert worst_lines(PROBLEM, LATEX)[5][0] == "correct"


def test_both_speeds_declared_in_plain_text() -> None:
    assert worst_lines(PROBLEM, PLAIN)[6][0] == "correct"


def test_an_energy_with_the_n_component_is_wrong_after_the_declaration() -> None:
    work = LATEX.replace("105.4", "12.30")
    assert worst_lines(PROBLEM, work)[5][0] == "wrong"


def test_momentum_checked_again_keeps_the_components() -> None:
    """A sum of the bare names to the first power is (3) again: 20(-1.109) + 5(8.398) = 19.81."""
    assert worst_lines(PROBLEM, PLAIN + "20*vA + 5*vB = 19.81\n")[7][0] == "correct"


#: AQA M3 2007 Q6(a) by hand: A at speed u, 30° from the line of centres, hits an identical B at rest.
#: Along n A has u cos 30° = (√3/2)u, across u sin 30° = u/2. Equal masses: v_A + v_B = (√3/2)u and
#: v_B - v_A = e(√3/2)u, so B's speed after is (√3/4)(1 + e)u. A letter the student sets a bare
#: velocity before equal to (``u_A = U``, ``v_1 = c``) is A's speed, u: the components are U cos 30°
#: and U sin 30°. Read as the n component (the habit's bare u_A), U cos 30° would be (3/4)u.
SHOW = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"

LETTER_LATEX = r"""Let $u_A = U$.
$u_{An} = U\cos 30^\circ = \tfrac{\sqrt3}{2}U$, $u_{At} = U\sin 30^\circ = \tfrac12 U$
$v_{An} + v_{Bn} = \tfrac{\sqrt3}{2}U$
$v_{Bn} - v_{An} = e\tfrac{\sqrt3}{2}U$
$v_{Bn} = \tfrac{\sqrt3}{4}(1 + e)U$
"""

LETTER_PLAIN = """A: uA = c
uAn = c cos 30 = 0.866c
uAt = c sin 30 = 0.5c
"""


def test_a_letter_set_equal_to_a_bare_velocity_before_is_the_speed() -> None:
    got = worst_lines(SHOW, LETTER_LATEX)
    assert [got[k][0] for k in (2, 3, 4, 5)] == ["correct"] * 4


def test_a_letter_set_equal_phone_typed() -> None:
    got = worst_lines(SHOW, LETTER_PLAIN)
    assert got[2][0] == "correct" and got[3][0] == "correct"


def test_the_components_swapped_are_still_the_slip() -> None:
    """U sin 30° along the line of centres: sin and cos swapped, found at its line."""
    work = LETTER_LATEX.replace(r"U\cos 30^\circ = \tfrac{\sqrt3}{2}U", r"U\sin 30^\circ = \tfrac12 U")
    assert worst_lines(SHOW, work)[2][0] == "wrong"
