"""An arrow after a value with LaTeX's spacing and an answer mark after it (``3.5 \\text{ m/s}
\\leftarrow \\qquad \\textbf{Ans.}``, as engineering texts box a result): the arrow is the value's
direction (derive/mathtext/arrows.py). Before, the side did not read and the line had no verdict.
Each expected mark is worked by hand from the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.arrows import arrows_said


def test_the_arrow_before_latex_spacing_and_an_answer_mark_is_a_direction() -> None:
    assert arrows_said(r"v = 3.5 \text{ m/s} \leftarrow \qquad \textbf{Ans.}").startswith(
        r"v = 3.5 \text{ m/s} to the left "
    )
    assert "to the right" in arrows_said(r"v = 2 \rightarrow \; \text{Ans}")
    assert arrows_said("x = 2 -> y = 3") == "x = 2 -> y = 3"  # between two relations: "so"


def test_a_speed_after_with_its_arrow_and_ans_is_judged_as_the_signed_velocity() -> None:
    # OCR M2 2006: A (2 kg) at 5 m/s meets B (1 kg) at 5 m/s head on, e = 0.8 (→ positive):
    # 2(5) - 1(5) = 2x + y, y - x = 0.8(10) = 8 -> x = -1, y = 7. A's 1 m/s to the left is
    # right; B's 7 m/s to the left is wrong (it moves to the right).
    work = r"""$$(v_A)_2 = 1 \text{ m/s} \leftarrow \qquad \textbf{Ans.}$$

$$(v_B)_2 = 7 \text{ m/s} \longleftarrow \quad \textbf{Ans.}$$
"""
    got = worst_lines("ocr-m2-2006-spheres-meet-at-5-ke-lost", work)
    assert got[1][0] == "correct"
    assert got[3][0] == "wrong"
