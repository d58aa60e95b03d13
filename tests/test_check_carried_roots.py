"""After a slip, the world a later slip is worked into: an unknown that cannot be negative (e, a
mass) is the student's positive root, and a slip in one unknown takes the place of the equation
that leaves the student's own carried relations standing. Every number is worked by hand from
the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines

# Edexcel M2 2013 Q5: P (2m) at u hits Q (m) at rest; after, the kinetic energy is ¾mu².
# True: 2u = 2x + y, y - x = eu: x = (2 - e)u/3, y = 2(1 + e)u/3; x² + y²/2 = ¾u² gives
# (6 + 3e²)/9 = ¾, e² = ¼, e = ½ (x = u/2, y = u). Restitution reversed (x - y = eu):
# x = (2 + e)u/3, y = 2(1 - e)u/3, and the same 6 + 3e² = 27/4 (e = -½ would give the true
# velocities back). A second slip, 27/4 - 6 = 3/4 taken as 1: 3e² = 1, e = 0.577, and with the
# student's own x = (2 + e)u/3: (2 + 0.577)u/3 = 0.859u.
PROBLEM = "edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters"


def test_e_from_a_slipped_energy_equation_is_the_positive_root_and_carried() -> None:
    work = (
        "2mu = 2mx + my\n"
        "x - y = eu\n"
        "x = (2 + e)u/3, y = 2(1 - e)u/3\n"
        "1/2 (2m) x^2 + 1/2 m y^2 = 3/4 m u^2\n"
        "6 + 3e^2 = 27/4\n"
        "3e^2 = 1\n"
        "e = 0.577\n"
        "x = (2 + 0.577)u/3 = 0.859u\n"
    )
    found = worst_lines(PROBLEM, work)
    assert found[2][:2] == ("wrong", "restitution_reversed")
    assert found[6][0] == "wrong"
    assert found[7][0] == "carried"
    assert found[8][0] == "carried"


def test_a_velocity_from_the_students_own_formula_after_the_second_slip_is_carried() -> None:
    # The same, typed otherwise: e² worked as 1/3 in one step, then Q's velocity from the
    # student's y = 2(1 - e)u/3: 2(1 - 0.577)/3 = 0.282, so y = 0.282u.
    work = (
        "2 m u = 2 m v_P + m v_Q\n"
        "v_P - v_Q = e u\n"
        "v_P = u(2 + e)/3\n"
        "v_Q = 2u(1 - e)/3\n"
        "m v_P^2 + 1/2 m v_Q^2 = 3/4 m u^2\n"
        "e^2 = 1/3\n"
        "e = 0.577\n"
        "v_Q = 2u(1 - 0.577)/3 = 0.282u\n"
    )
    found = worst_lines(PROBLEM, work)
    assert found[2][:2] == ("wrong", "restitution_reversed")
    assert found[6][0] == "wrong"
    assert found[7][0] == "carried"
    assert found[8][0] == "carried"
