"""A name the habits read as a quantity another name already stands for, defined by the student
as something else (derive/checking/ownnames.py, ``defined_anew``): a velocity relative to the
centre of mass, the common velocity at the greatest compression. A teacher judges each line with
the quantity the student's own defining line gives it. Each expected mark is worked by hand from
the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines

# 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: the centre of mass moves at 80/12 = 6.667 m/s.
# Relative to it A moves at 5.333 and B at -2.667; reversed and times e: -2.667 and 1.333; back in
# the ground's frame A at 4.0 and B at 8.0 (momentum 16 + 64 = 80; 8 - 4 = 0.5(12 - 4)).
CM_FRAME = """Centre of mass velocity: v_G = (4(12) + 8(4))/(4 + 8) = 6.667
u_A = v_A - v_G = 12 - 6.667 = 5.333
u_B = v_B - v_G = 4 - 6.667 = -2.667
u_A' = -0.5 u_A = -2.667
u_B' = -0.5 u_B = 1.333
v_A' = u_A' + v_G = -2.667 + 6.667 = {a}
v_B' = u_B' + v_G = 1.333 + 6.667 = 8.0
"""


def test_velocities_relative_to_the_centre_of_mass_are_the_students_own() -> None:
    got = worst_lines("byjus-4kg-ball-catches-8kg-ball", CM_FRAME.format(a="4.0"))
    assert [got[n][0] for n in range(1, 8)] == ["correct"] * 7


def test_a_slip_back_in_the_ground_frame_is_still_found() -> None:
    # -2.667 + 6.667 is 4.0, not 4.4: the line is the slip, B's line after it is right.
    got = worst_lines("byjus-4kg-ball-catches-8kg-ball", CM_FRAME.format(a="4.4"))
    assert [got[n][0] for n in range(1, 6)] == ["correct"] * 5
    assert got[6][0] == "wrong"


def test_the_common_velocity_and_the_impulses_of_the_two_phases() -> None:
    # 2 kg at 5 m/s hits 1 kg at rest and goes on at 2 m/s: B leaves at 6 m/s. At the greatest
    # compression both move at 10/3 = 3.333; B's impulse while compressing 1(3.333) = 3.333, in
    # all 1(6) = 6, while restoring 6 - 3.333 = 2.667; e = 2.667/3.333 = 0.8.
    # v_2 names B's velocity after: v, set to another value, is the student's own.
    work = """m_1 = 2, u_1 = 5, m_2 = 1, u_2 = 0, v_1 = 2, v_2 = 6
v = m_1 u_1/(m_1 + m_2) = 10/3 = 3.333
I_D = m_2 (v - u_2) = 3.333
I_R = m_2 (v_2 - v) = 2.667
e = I_R/I_D = 2.667/3.333 = 0.8
"""
    got = worst_lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert [got[n][0] for n in range(2, 6)] == ["correct"] * 4


# Cars couple: 150000(0.300) + 110000(-0.120) = 31800 kg m/s, shared by 260000 kg: V = 0.1223 m/s,
# and the kinetic energy after is p²/2M = 31800²/520000 = 1944.7 J (½(260000)(0.1223)² the same).
COUPLED = """150000(0.300) + 110000(-0.120) = 260000 V
V = 31800/260000 = 0.1223 m/s
KE after = {ke}
"""


def test_the_kinetic_energy_from_the_momentum_and_the_total_mass() -> None:
    got = worst_lines("openstax-cp-8-train-cars-couple", COUPLED.format(ke="P^2/(2M) = 31800^2/(2 × 260000) = 1945 J"))
    assert [got[n][0] for n in (1, 2, 3)] == ["correct"] * 3


def test_the_momentum_squared_over_the_mass_without_the_half_is_a_slip() -> None:
    # p²/M = 3889 J, twice the energy after: a wrong formula, not read as other quantities.
    got = worst_lines("openstax-cp-8-train-cars-couple", COUPLED.format(ke="p^2/M = 31800^2/260000 = 3889 J"))
    assert got[3][0] == "wrong"


def test_a_name_in_p_may_still_be_a_velocity() -> None:
    # 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: 80 = 4p + 8q and q - p = 0.5(8) = 4 give
    # p = 4 and q = 8: p and q are the velocities after, not momenta.
    work = """4(12) + 8(4) = 4p + 8q
q - p = 0.5(12 - 4)
12p = 80 - 32 = 48
p = 4
"""
    got = worst_lines("byjus-4kg-ball-catches-8kg-ball", work)
    assert [got[n][0] for n in (1, 2, 3, 4)] == ["correct"] * 4
