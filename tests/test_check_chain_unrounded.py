"""A number the student got wrong, written again to more figures (the unrounded value noted in
brackets, ``v = 7.53 m/s (7.5253)``, then ``0.7 x 7.5253``), is that wrong number: the line worked
from it is carried (derive/checking/chainroots.py, ``more_figures``). Numbers by hand from
problems/chain-ocr-m2-2015-thrown-down-bounce.toml: 0.2 kg thrown down at 5 m/s from 1.6 m,
e = 0.7, g = 9.8: v_1^2 = 25 + 31.36 = 56.36, v_1 = 7.5073; v_2 = 0.7 v_1 = 5.2551."""

from __future__ import annotations

from support.checked import lines

from derive.checking.chainroots import more_figures

PROBLEM = "chain-ocr-m2-2015-thrown-down-bounce"


def test_more_figures_of_a_number_of_three_figures() -> None:
    assert more_figures("7.5253", "7.53") and more_figures("0.012345", "0.0123")
    assert not more_figures("7.5073", "7.53")  # another number
    assert not more_figures("7.46", "7.5")  # two figures say too little to tell


def test_the_unrounded_wrong_value_in_an_unnamed_line_is_carried() -> None:
    # 25 + 31.36 written 56.63 (a slip): v = sqrt(56.63) = 7.5253 (7.53); 0.7 x 7.5253 = 5.268.
    work = (
        "down +ve: v^2 = u^2 + 2as = 5^2 + 2(9.8)(1.6) = 25 + 31.36 = 56.63\n"
        "v = 7.53 m/s (7.5253)\n"
        "rebound speed = 0.7 x 7.5253 = 5.268 m/s\n"
    )
    found = lines(PROBLEM, work)
    assert [found[n][0] for n in (1, 2, 3)] == ["wrong", "carried", "carried"]


def test_the_true_value_to_more_figures_after_the_slip_is_correct() -> None:
    # The student starts again from the true 7.5073: 0.7 x 7.5073 = 5.2551 (5.255), right.
    work = (
        "down +ve: v^2 = u^2 + 2as = 5^2 + 2(9.8)(1.6) = 25 + 31.36 = 56.63\n"
        "v = 7.53 m/s (7.5253)\n"
        "rebound speed = 0.7 x 7.5073 = 5.255 m/s\n"
    )
    found = lines(PROBLEM, work)
    assert found[3][0] == "correct"
