"""A chain's velocities written as vectors along its one line (``-35 j``, ``3.4 i``): every impact of
a chain is direct, so a relation whose vectors are all along one unit vector is the relation of their
components along it, as on a head-on impact (derive/checking/chainlines.py, ``_read``). Worked by
hand from the problem files' givens."""

from __future__ import annotations

from support.checked import lines


def test_velocities_along_i_in_the_momentum_and_after_the_wall() -> None:
    # chain-aqa-m3-2007-collide-again: A 0.3 kg at 3 m/s (i), B 0.2 kg at 2 m/s toward it, e = 0.8,
    # the wall's e 0.7. 0.9 i - 0.4 i = 0.5 i; v_B - v_A = 0.8(5) = 4; v_A = -0.6 i, v_B = 3.4 i;
    # off the wall B has -0.7(3.4) = -2.38 i.
    work = (
        "i is to the right (A moves right at first)\n"
        "momentum: 0.3(3 i) + 0.2(-2 i) = 0.5 i = 0.3 v_A + 0.2 v_B\n"
        "NEL: v_B - v_A = 0.8(3 - (-2)) = 4\n"
        "v_A = -0.6 i m/s, v_B = 3.4 i m/s\n"
        "wall: w_B = -0.7(3.4 i) = -2.38 i m/s\n"
    )
    found = lines("chain-aqa-m3-2007-collide-again", work)
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4


def test_an_impulse_in_j_after_a_slip_in_the_fall_is_carried() -> None:
    # chain-ocr-m2-2007-rebounds-to-start: 0.2 kg thrown down at 21 m/s from 40 m, back up to 40 m.
    # The slip: 441 + 784 written 1125 (it is 1225), v1 = 33.5 (true 35); v2 = sqrt(784) = 28.
    # J = 0.2(28 j - (-33.5 j)) = 0.2(61.5) j = 12.3 j: the slip's (0.2(28 + 33.541) = 12.31; true 12.6).
    work = (
        "j up positive\n"
        "v1^2 = 21^2 + 2(9.8)(40) = 441 + 784 = 1125, v1 = 33.5\n"
        "v2^2 = 2(9.8)(40) = 784, v2 = 28\n"
        "J = m(v_after - v_before) = 0.2(28 j - (-33.5 j))\n"
        "J = 0.2(61.5) j = 12.3 j N s\n"
    )
    found = lines("chain-ocr-m2-2007-rebounds-to-start", work)
    assert found[2][0] == "wrong"
    assert [found[n][0] for n in (4, 5)] == ["carried", "carried"]
