"""A relation in two unknowns rearranged with its one term free of them carried across with its
sign kept (``v_A = v_B + 4`` from ``v_B − v_A = 4``): nothing was worked out in that step, so the
slip is ``algebra``, the step's, not the impact rule written the wrong way round that the line
also is, nor ``arithmetic``. Every number is worked by hand from the problem files' givens."""

from __future__ import annotations

from support.checked import worst_lines

#: AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward it, e = 0.8. By hand: momentum
#: 0.9 − 0.4 = 0.5 = 0.3 v_A + 0.2 v_B; restitution v_B − v_A = 0.8 × 5 = 4, so v_A = v_B − 4.
HEAD_ON = "aqa-m3-2007-spheres-approach-head-on"
#: CIE 9231 2018: A (5m) at u meets B (2m) at 2u, e symbolic. By hand: 5mu − 4mu = mu, so
#: 5 v_A + 2 v_B = u; restitution v_B − v_A = e(u + 2u) = 3eu, so v_A = v_B − 3eu.
FIVE_M = "cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u"


def test_a_number_carried_across_with_its_sign_is_algebra() -> None:
    # v_A = v_B + 4 is v_A − v_B = 4, the impact rule reversed as an equation; the student wrote
    # the rule right on the line before and moved the 4 across without its sign changed. Then
    # 0.3(v_B + 4) + 0.2 v_B = 0.5 gives 0.5 v_B = 0.5 − 1.2 = −0.7: right given the slip.
    work = (
        "Taking right as positive.\n"
        "0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\n"
        "v_B - v_A = 0.8(3 + 2) = 4\n"
        "v_A = v_B + 4\n"
        "0.3(v_B + 4) + 0.2 v_B = 0.5\n"
    )
    found = worst_lines(HEAD_ON, work)
    assert found[2][0] == found[3][0] == "correct", found
    assert found[4] == ("wrong", "algebra"), found
    assert found[5][0] == "carried", found


def test_a_term_in_the_symbolic_givens_carried_across_is_algebra() -> None:
    # The givens are letters (u, e, m): nothing is put in for them, so the step is still the
    # step. vA = vB + 3eu from vB - vA = 3eu: the 3eu kept its sign crossing over (phone-typed).
    work = "A's way +ve. after: vA, vB\n5mu - 2m(2u) = 5m vA + 2m vB\nvB - vA = e(u + 2u) = 3eu\nvA = vB + 3eu\n"
    found = worst_lines(FIVE_M, work)
    assert found[2][0] == found[3][0] == "correct", found
    assert found[4] == ("wrong", "algebra"), found


def test_in_latex_with_primes() -> None:
    # The same slip in LaTeX: v_B' - v_A' = 4 rearranged as v_A' = v_B' + 4.
    work = (
        "Right is positive.\n"
        "$$0.3(3) + 0.2(-2) = 0.3v_A' + 0.2v_B'$$\n"
        "$$v_B' - v_A' = 0.8\\,(3 - (-2)) = 4$$\n"
        "$$\\Rightarrow v_A' = v_B' + 4$$\n"
    )
    found = worst_lines(HEAD_ON, work)
    assert found[4] == ("wrong", "algebra"), found


def test_a_number_worked_out_with_its_sign_lost_stays_arithmetic() -> None:
    # 0.5 = 0.3 v_A + 0.2 v_B with v_B = v_A + 4: 0.5 = 0.5 v_A + 0.8, so 0.5 v_A = 0.5 − 0.8 =
    # −0.3; written 0.3, the number worked out from two has its sign lost: arithmetic.
    work = (
        "Taking right as positive.\n"
        "0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\n"
        "v_B - v_A = 0.8(3 + 2) = 4\n"
        "0.5 = 0.5 v_A + 0.8\n"
        "0.5 v_A = 0.3\n"
    )
    found = worst_lines(HEAD_ON, work)
    assert found[4][0] == "correct", found
    assert found[5] == ("wrong", "arithmetic"), found
