"""A value the student rounded at a stage's end, carried into the next stage, is not a slip
(derive/checking/chainsteps.py, ``rounded_on``): the next stage's line is right when its rule
holds with the chain's value put back for the student's rounded one and its working holds as
written. A wrong rule worked from the same rounded value stays a slip. Numbers by hand."""

from __future__ import annotations

from support.checked import lines


def test_a_common_velocity_from_a_rounded_impact_speed() -> None:
    # Block onto a pan: v1 = sqrt(2(9.81)(2)) = 6.2642 (6.26); V = 30 v1/40 = 4.6981, from 6.26:
    # 30(6.26)/40 = 4.695; T = ½(40)(4.695²) = 440.87 (the chain's ½(40)(4.6981²) = 441.45).
    work = "v1 = sqrt(2 x 9.81 x 2) = 6.26 m/s\nV = 30(6.26)/40 = 4.695 m/s\nT = 1/2 (40)(4.695)^2 = 440.9 J\n"
    found = lines("chain-block-onto-spring-pan", work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_a_slide_from_a_speed_rounded_twice() -> None:
    # Hibbeler 15-58: u_B = 15.3325 (9.437 + 5.898 = 15.335, written 15.34); the slide
    # d = u_B^2/(2 mu g) = 15.3325^2/25.76 = 9.126, from 15.34: 235.3/25.76 = 9.135.
    work = (
        "v_1 = sqrt(2(32.2)(6)) = 19.66 ft/s\n"
        "u_A = 9.437 ft/s\n"
        "u_B = 9.437 + 5.898 = 15.34 ft/s\n"
        "d_B = 15.34^2/(2(0.4)(32.2)) = 9.135 ft\n"
    )
    found = lines("chain-hibbeler-15-58-suitcases", work)
    assert found[4][0] == "correct"


def test_a_factor_lost_from_the_rounded_speed_stays_a_slip() -> None:
    # d = 15.34^2/(0.4 x 32.2) = 18.27: with 15.3325 put back, 235.09/12.88 = 18.25, not 9.126.
    work = "u_B = 9.437 + 5.898 = 15.34 ft/s\nd_B = 15.34^2/(0.4 x 32.2) = 18.27 ft\n"
    found = lines("chain-hibbeler-15-58-suitcases", work)
    assert found[2][0] == "wrong"
