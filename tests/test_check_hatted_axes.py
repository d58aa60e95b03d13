"""Axes named by hatted letters typed as Unicode (``x̂`` with a combining hat, ``ŷ``) are the
student's unit vectors x and y, placed by the words after them; and a short word before a
given's name in prose (``multiplied by e = 1/2``) is a word, not a name ``b_y`` times e.
Values worked by hand from the givens."""

from __future__ import annotations

from support.checked import worst_lines

#: Identical balls, B at rest, A at u at 30° to the line of centres: A's component along the
#: line of centres before is u cos 30° = 0.866u, along the tangent u sin 30° = 0.5u.
THIRTY = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"
#: Spheres 2m and m at u in opposite directions, each at α to the line of centres; e = 1/2.
OPPOSITE = "ocr-m3-2012-january-q2-opposite-directions-each-at-alpha"


def test_hatted_y_along_the_line_of_centres() -> None:
    work = (
        "x̂ along the common tangent, ŷ along the line of centres.\nu_Ay = u cos 30° = 0.866u\nu_Ax = u sin 30° = 0.5u\n"
    )
    found = worst_lines(THIRTY, work)
    assert found[2][0] == found[3][0] == "correct"


def test_hatted_axes_named_y_first() -> None:
    work = "ŷ along the line of centres and x̂ along the tangent.\nu_Ay = u cos 30° = 0.866u\nu_Ax = u sin 30° = 0.5u\n"
    found = worst_lines(THIRTY, work)
    assert found[2][0] == found[3][0] == "correct"


def test_multiplied_by_e_is_prose() -> None:
    # e = 1/2 is the given; "by" is the word, not B's y component before
    work = (
        "Take x along the line of centres from A to B.\n"
        "v_By' = -u sin α\n"
        "Along x the speed of separation is the speed of approach multiplied by e = 1/2.\n"
    )
    found = worst_lines(OPPOSITE, work)
    assert found[2][0] == "correct"
    assert found[3][0] in ("correct", "not read")
