"""A value worked by the right rule from a step the student got wrong is carried, not a further
slip (derive/checking/chainworld.py, ``_from_wrong_step``): ``2 g h = 3.92`` (a slip) then
``v_1 = sqrt(3.92) = 1.98``. A wrong rule after the slip stays a slip. Numbers by hand."""

from __future__ import annotations

from support.checked import lines


def test_a_fall_worked_from_a_wrong_2gh_is_carried() -> None:
    # OCR M2 2006: dropped from 2 m, g = 9.8: 2gh = 39.2, written 3.92 (a slip);
    # v_1 = sqrt(3.92) = 1.980 (the true sqrt(39.2) = 6.261): the rule right, the step carried.
    work = "u = 0, so v^2 = 2gh\n2 x 9.8 x 2 = 3.92\nv_1 = sqrt(3.92) = 1.98 m/s\n"
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert found[2][0] == "wrong"
    assert found[3][0] == "carried"


def test_a_us_fall_with_the_product_slipped_then_the_root_taken() -> None:
    # Hibbeler 15-58: 2(32.2)(6) = 386.4, written 38.64 (a slip); v_1 = sqrt(38.64) = 6.216 ft/s,
    # (true sqrt(386.4) = 19.657): carried.
    work = "2 g h = 2 x 32.2 x 6 = 38.64\nv_1 = sqrt(38.64) = 6.216 ft/s\n"
    found = lines("chain-hibbeler-15-58-suitcases", work)
    assert found[1][0] == "wrong"
    assert found[2][0] == "carried"


def test_a_wrong_rule_after_the_wrong_step_stays_a_slip() -> None:
    # v_1 = 3.92/2 = 1.96: with 39.2 put back, 39.2/2 = 19.6 is not v_1 = 6.261: a rule wrong too.
    work = "2gh = 2(9.8)(2) = 3.92\nv_1 = 3.92/2 = 1.96 m/s\n"
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert found[1][0] == "wrong"
    assert found[2][0] == "wrong"
