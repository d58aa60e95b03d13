"""A reading the student did not declare must not make a wrong line right. Values by hand.

- An axis laid along the line of centres "from A towards B" declares the student's positive:
  a B moving toward A at 3 m/s written ``u_Bx = 3`` is B's sign lost, not a frame turned round
  (which the values, A's being wrong too, would otherwise infer).
- Two slips in the values before, one on each body (A's sin and cos swapped, B's sign lost): the
  lines after are right given both (carried), not the first made again; ``since e = 1`` there
  states the given as the problem has it (correct).
- The statement's letters for the bodies (spheres S and T) name the velocities before, u_S and u_T,
  where one letter is placed by its mass and the other is the other body: ``u_T = -λu`` for a T
  moving the same way as S is a slip, not a name of the student's own defined there.
"""

from __future__ import annotations

from support.checked import worst_lines

#: Gramoll's two balls: equal masses, e = 1; A at 4 m/s at 30° to the line of impact, B at 3 m/s
#: along it toward A. True (n from A to B): A (4 cos 30, 4 sin 30) = (3.464, 2), B -3.
#: Slips: A's as (2, 3.464), B's +3: 2 + 3 = 5 = a + b, b - a = 1(2 - 3) = -1: a = 3, b = 2.
BALLS = "gramoll-ecourses-two-balls-elastic"
#: Edexcel M2 Q5: S (m) at u catches T (km) at λu, S brought to rest. True: mu + kmλu = kmv,
#: v = u(1 + kλ)/k, and v = e(u - λu). T's taken -λu: v = u(1 - kλ)/k.
ST = "edexcel-m2-undated-q5-s-brought-to-rest-show-e"


def test_an_axis_laid_from_a_to_b_declares_the_positive_way() -> None:
    work = (
        "x along the line of impact, pointing from A towards B; y along the contact plane.\n"
        "u_Ax = 4 sin 30 = 2, u_Ay = 4 cos 30 = 3.46\n"
        "u_Bx = 3, u_By = 0\n"
        "m(2) + m(3) = m v_Ax + m v_Bx\n"
        "v_Bx - v_Ax = 1(2 - 3) = -1\n"
        "v_Ax = 3, v_Bx = 2\n"
        "KE is kept, since e = 1\n"
    )
    found = worst_lines(BALLS, work)
    assert found[2] == ("wrong", "sin_cos_swapped")
    assert found[3] == ("wrong", "b_sign")
    assert [found[n][0] for n in (4, 5, 6)] == ["carried"] * 3
    assert found[7][0] == "correct"


def test_the_statements_letters_name_the_velocities_before() -> None:
    wrong = "Taking the direction S moves in as positive.\nu_T = -λu\nmu + km(-λu) = km v_T\nv_T = u(1 - kλ)/k\n"
    found = worst_lines(ST, wrong)
    assert found[2] == ("wrong", "b_sign")
    assert found[3][0] == found[4][0] == "carried"
    right = "Taking the direction S moves in as positive.\nu_S = u, u_T = λu\nmu + kmλu = km v_T\nv_T = u(1 + kλ)/k\n"
    assert [s for s, _ in worst_lines(ST, right).values()] == ["correct"] * 3
