"""A chain's line after a slip that comes to the student's own value at the figures written,
not the problem's, is carried, though its rounded working (``6.0/4.0``) is loose enough to let
it pass as the problem's value (derive/checking/chaincarried.py). Every number is worked by hand
from problems/chain-msu-bullet-block-swings.toml (0.020 kg at 300 m/s into a 4.0 kg block,
g = 9.81): the true V = 6/4.02 = 1.49254, T_after = ½(4.02)(1.49254²) = 4.4776,
h_2 = 1.49254²/19.62 = 0.11354."""

from __future__ import annotations

from support.checked import lines

PROBLEM = "chain-msu-bullet-block-swings"


def test_a_coupled_mass_left_out_is_carried_into_both_stages_in_latex() -> None:
    # The bullet's mass left out after: 6.0 = 4.0 V, V = 1.5 (1.50; the problem's 1.49 at three
    # figures). KE after ½(4.02)(2.25) = 4.5225 (4.52; the problem's 4.48); the swing
    # h = 2.25/19.62 = 0.11468 (0.115; the problem's 0.114): each the slip's value.
    work = (
        "Bullet and block stick together, momentum conserved:\n\n"
        "$0.020 \\times 300 = 4.0\\,V$\n\n"
        "$V = 6.0/4.0 = 1.50$ m/s\n\n"
        "KE just after: $\\frac{1}{2}(4.02)(1.50)^2 = 4.52$ J\n\n"
        "Swing up: $h = V^2/(2g) = 1.50^2/19.62 = 0.115$ m\n"
    )
    found = lines(PROBLEM, work)
    assert found[3][0] == "wrong"
    assert [found[n][0] for n in (5, 7, 9)] == ["carried", "carried", "carried"]


def test_phone_typed_the_same_slip_carried_into_the_swing() -> None:
    # 0.02*300 = 4*v: v = 1.5 (1.50, the problem's 1.49); h = 1.50^2/(2*9.81) = 0.11468 (0.115).
    work = "0.02*300 = 4*V\nV = 6/4 = 1.50 m/s\nh = V^2/(2*9.81) = 1.50^2/19.62 = 0.115 m\n"
    found = lines(PROBLEM, work)
    assert found[1][0] == "wrong"
    assert [found[n][0] for n in (2, 3)] == ["carried", "carried"]


def test_a_value_put_right_after_the_slip_is_correct_not_carried() -> None:
    # After the same slip the student works V again with the bullet's mass: 6.0/4.02 = 1.4925
    # (1.49, the problem's value at three figures), and h = 1.493^2/19.62 = 2.2290/19.62 = 0.11361
    # (0.114, the problem's): right for the problem, not the slip's 1.50 and 0.115.
    work = "0.020 x 300 = 4.0 V\nV = 6.0/4.02 = 1.49 m/s\nh = 1.493^2/19.62 = 0.114 m\n"
    found = lines(PROBLEM, work)
    assert found[1][0] == "wrong"
    assert found[2][0] == "correct"
    assert found[3][0] == "correct"
