"""A direction line is right when it is the angle its words name, not merely when its
calculator step is right (``tan⁻¹(6.4/1.732) = 74.9° to XY`` is right arithmetic and the
wrong angle); a check word after a value is not part of it.

Hand values:
- OCR MEI 2024 Q12 (disc A stops; ocr-mei-fmm-2024-disc-a-stops): B after has 6.4 along XY
  and 2 sin 60° = √3 across it, so it makes tan⁻¹(√3/6.4) = 15.14° with XY (the mark scheme's
  deflection 60 - 15.1 = 44.9°); 74.86° is the angle with the perpendicular.
- OCR M3 Jan 2007 (ocr-m3-2007-oblique-sin-alpha-0p8): A after is -4.5 i + 12 j, at
  180 - tan⁻¹(12/4.5) = 110.56° from i; tan⁻¹(12/-4.5) = -69.44° is the wrong quadrant.
- FisicaLab Example 7 (d) (fisicalab-example-7-normal-at-20deg): A leaves at 100.326° from the
  x axis (the manual's answer); the common normal is at 20° from x, so 80.33° from n.
- OpenStax 8.5 (goalie and puck): 91.9 - 0.196 = 91.7 J.
"""

from __future__ import annotations

import pytest

import derive

_SOLVED: dict[str, derive.Solution] = {}


def verdicts(problem: str, text: str) -> dict[int, tuple[str, str]]:
    if problem not in _SOLVED:
        _SOLVED[problem] = derive.solve(derive.load(problem))
    report = derive.check(_SOLVED[problem], {}, derivation=text)
    return {int(i.name): (i.status, i.slip) for i in report.items if i.name.isdigit()}


@pytest.mark.parametrize(
    ("line", "status", "slip"),
    [
        ("tan^-1(6.4/1.732) = 74.9° to XY", "wrong", "angle_other_axis"),
        ("Direction: $\\tan^{-1}\\left(\\frac{6.4}{1.732}\\right) = 74.9^\\circ$ to XY", "wrong", "angle_other_axis"),
        ("tan^-1(1.732/6.4) = 15.1° to XY", "correct", ""),
        ("angle = 15.1° with the line of centres", "correct", ""),
        ("tan^-1(1.732/6.4) = 15.1° to the perpendicular", "correct", ""),  # no axis named: arithmetic
        ("tan^-1(1.732/6.4) = 15.1°", "correct", ""),
    ],
)
def test_an_angle_to_a_line_is_that_angle(line: str, status: str, slip: str) -> None:
    found = verdicts("ocr-mei-fmm-2024-disc-a-stops", "3 v_A1n + 5 = 5 v_B2n\n" + line + "\n")
    assert found[2] == (status, slip)


def test_a_direction_from_an_axis_in_the_wrong_quadrant() -> None:
    text = (
        "v_A2n = -4.5\n"
        "direction: tan^-1(12/-4.5) = -69.4° from i\n"
        "direction = 180 - 69.4 = 110.6° from i\n"
        "angle = 69.4° with the line of centres\n"
    )
    found = verdicts("ocr-m3-2007-oblique-sin-alpha-0p8", text)
    assert found[2] == ("wrong", "angle_quadrant")
    assert found[3][0] == "correct" and found[4][0] == "correct"


def test_the_quadrant_is_seen_in_the_lines_own_components() -> None:
    """-9i + 12j (the student's own, after a slip not read here) is at 126.9° from i, not -53.1°."""
    found = verdicts("ocr-m3-2007-oblique-sin-alpha-0p8", "direction: tan^-1(12/-9) = -53.1° from i\n")
    assert found[1] == ("wrong", "angle_quadrant")


def test_an_angle_from_the_x_axis_of_a_problem_with_one() -> None:
    text = "psi = 100.3° from the x axis\nangle = 80.3° from the x axis\nangle = 80.3° from n\n"
    found = verdicts("fisicalab-example-7-normal-at-20deg", text)
    assert found[1][0] == "correct"
    assert found[2][0] == "wrong"
    assert found[3][0] == "correct"


def test_a_direction_carried_from_an_earlier_slip_is_carried() -> None:
    """B's sign in restitution: v_B2n = 0.8(u + 1), with 3u + 5 = 5 v_B2n: 3u + 5 = 4u + 4, u = 1,
    v_B2n = 1.6; then B after is (1.6, √3) at tan⁻¹(1.732/1.6) = 47.3° to XY: right given the slip."""
    text = "3 v_A1n + 5 = 5 v_B2n\nv_B2n = 0.8(v_A1n + 1)\nv_A1n = 1, v_B2n = 1.6\ntan^-1(1.732/1.6) = 47.3° to XY\n"
    found = verdicts("ocr-mei-fmm-2024-disc-a-stops", text)
    assert found[2][0] == "wrong"
    assert found[4][0] == "carried"


def test_a_check_word_after_the_value_is_not_part_of_it() -> None:
    found = verdicts("openstax-cp-8-5-goalie-catches-puck", "91.9 - 0.196 = 91.7 J  ok\n91.9 - 0.196 = 91.7 ok\n")
    assert found[1][0] == "correct" and found[2][0] == "correct"


def test_a_rounded_value_equal_to_its_exact_form_holds_at_its_figures() -> None:
    """OCR M3 2013: B's speed after is 0.2√3 = 0.3464; 0.346 is it at three figures, 0.35 at two
    (0.36 too: ±1 in the last figure), 0.37 is not."""
    found = verdicts(
        "ocr-m3-2013-b-turns-through-right-angle", "0.346 = 0.2 sqrt(3)\n0.35 = 0.2sqrt(3)\n0.37 = 0.2sqrt(3)\n"
    )
    assert [found[n][0] for n in (1, 2, 3)] == ["correct", "correct", "wrong"]


def test_degrees_to_a_vector_axis_is_a_direction() -> None:
    """OCR M3 2007 typed as in the mark scheme's layout: "-69.4 degrees to i" is a direction."""
    found = verdicts("ocr-m3-2007-oblique-sin-alpha-0p8", "v_A2n = -4.5\ntan^-1(12 / -4.5) = -69.4 degrees to i\n")
    assert found[2] == ("wrong", "angle_quadrant")


def test_a_named_direction_worked_in_a_chain_names_its_mistake() -> None:
    """Example 4.C.12 (e = 0.9): θ_2 = tan⁻¹(v_A2n/v_A2t) = tan⁻¹((1 - e)/2) = tan⁻¹(0.05) = 2.862°;
    tan⁻¹(v_A2t/v_A2n) = tan⁻¹(20) = 87.14° is from the other axis."""
    text = "v_A2n = sqrt(2)/4*(1-e)*v_A1\n$$\\theta_2 = \\tan^{-1}\\frac{2}{1-e} = \\tan^{-1}(20) = 87.1^\\circ$$\n"
    found = verdicts("notes-4c12-cue-ball", text)
    assert found[2] == ("wrong", "angle_other_axis")
    assert (
        verdicts("notes-4c12-cue-ball", "v_A2n = sqrt(2)/4*(1-e)*v_A1\ntheta_2 = atan(0.05) = 2.86°\n")[2][0]
        == "correct"
    )


def test_the_words_may_come_before_the_angle() -> None:
    """OCR FM 2023 (ocr-fm-2023-oblique-discs-60deg): A leaves with -3.25 along the line of centres
    and 4 sin 60° = 2√3 across it, at tan⁻¹(2√3/3.25) = 46.83° to it; 43.17° is the other axis."""
    text = (
        "v_A2n = -3.25\n"
        "and the angle its path makes with the line of centres is\n"
        "\\[ \\theta = \\tan^{-1}\\left(\\frac{3.25}{2\\sqrt3}\\right) = 43.2^\\circ \\]\n"
        "the angle with the line of centres is tan^-1(3.464/3.25) = 46.8°\n"
    )
    found = verdicts("ocr-fm-2023-oblique-discs-60deg", text)
    assert found[3] == ("wrong", "angle_other_axis")
    assert found[4][0] == "correct"


def test_the_words_are_found_on_the_line_as_typed_where_the_side_has_lost_them() -> None:
    from derive.checking.angles import claim
    from derive.checking.inference import Read

    written = r"Direction: $\tan^{-1}\left(\frac{6.4}{1.732}\right) = 74.9^\circ$ to XY"
    c = claim(Read(15, written, ("atan(((6.4)/(1.732)) )", "74.9°"), "", None))
    assert c is not None and (c.value, c.axis, c.directed, c.ratio) == (74.9, "n", False, (6.4, 1.732))
    c = claim(Read(3, "a = 45.2° from n, b = 56.8° from n", ("a", "45.2°"), "", None))
    assert c is not None and (c.value, c.axis, c.directed) == (45.2, "n", True)
    assert claim(Read(1, "tan^-1(1.732/6.4) = 15.1°", ("atan(1.732/6.4)", "15.1°"), "", None)) is None


def test_a_direction_worked_from_the_sizes_of_its_components() -> None:
    """OCR M3 Jan 2006 (ocr-m3-2006-oblique-a-across-centres): A leaves with -2 along the line of
    centres and 4 across, at 180° - tan⁻¹(4/2) = 116.6° from x (its sizes in tan⁻¹, not its signs)."""
    text = "v_A2n = -2\ndirection of A = 180° - tan^-1(4/2) = 117° from x\n"
    assert verdicts("ocr-m3-2006-oblique-a-across-centres", text)[2][0] == "correct"
