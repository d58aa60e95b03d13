"""The centre-of-mass (zero-momentum) frame: a name the habits read as a body's velocity
(``u_A``, ``u_B'``), set alone on a line, after the centre of mass's velocity is written, to
that body's velocity less the centre of mass's, is the velocity relative to the centre of mass
on every line (derive/checking/cmframe.py). Values worked by hand from the givens."""

from __future__ import annotations

from support.checked import worst_lines

#: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: V = (48 + 32)/12 = 20/3; relative to the centre
#: 16/3 and -8/3 before, -8/3 and 4/3 after (reversed, halved); back: 4 and 8 m/s
#: (momentum 16 + 64 = 80, separation 8 - 4 = 0.5 × 8).
BALLS = "byjus-4kg-ball-catches-8kg-ball"
#: 2m at 5u hits 3m at rest, coefficient e: V = 10mu/5m = 2u; relative 3u and -2u before,
#: -3eu and 2eu after; back: 2u - 3eu and 2u + 2eu = 2(1 + e)u, the problem's answers.
SPHERES = "edexcel-m2-2004-june-q5-2m-at-5u-hits-3m"


def test_numbers_relative_to_the_centre_and_back() -> None:
    work = (
        "v_cm = (4*12 + 8*4)/(4 + 8) = 20/3\n"
        "u_A = 12 - 20/3 = 16/3\n"
        "u_B = 4 - 20/3 = -8/3\n"
        "u_A' = -0.5*(16/3) = -8/3\n"
        "u_B' = -0.5*(-8/3) = 4/3\n"
        "v_A' = u_A' + v_cm = -8/3 + 20/3 = 4\n"
        "v_B' = u_B' + v_cm = 4/3 + 20/3 = 8\n"
    )
    found = worst_lines(BALLS, work)
    assert [found[n][0] for n in range(1, 8)] == ["correct"] * 7


def test_letters_in_the_frame_of_the_centre_of_mass() -> None:
    work = (
        "v_G = (2m(5u) + 3m(0))/(5m) = 2u\n"
        "u_A = 5u - v_G = 3u\n"
        "u_B = 0 - 2u = -2u\n"
        "u_A' = -e(3u) = -3eu\n"
        "u_B' = -e(-2u) = 2eu\n"
        "v_A' = u_A' + v_G = 2u - 3eu\n"
        "v_B' = u_B' + v_G = 2u(1 + e)\n"
    )
    found = worst_lines(SPHERES, work)
    assert [found[n][0] for n in range(1, 8)] == ["correct"] * 7


def test_a_velocity_not_reversed_in_the_frame_is_still_a_slip() -> None:
    # u_A' = +e(3u): neither A's velocity after (2u - 3eu) nor it less V (-3eu)
    work = "v_G = (2m(5u) + 3m(0))/(5m) = 2u\nu_A = 5u - 2u = 3u\nu_A' = e(3u) = 3eu\n"
    found = worst_lines(SPHERES, work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][0] == "wrong"


def test_a_velocity_before_written_after_the_centre_is_still_the_habit() -> None:
    # u_A = 12 is A's velocity before in the laboratory, as the habit reads it: correct
    found = worst_lines(BALLS, "v_cm = (4*12 + 8*4)/12 = 20/3\nu_A = 12\nu_B = 4\n")
    assert [found[n][0] for n in range(1, 4)] == ["correct"] * 3


def test_the_centre_named_by_a_letter_of_the_students_own() -> None:
    # V is no habit's name: it is the centre of mass's velocity by its value, 10mu/5m = 2u
    work = "V = (2m(5u) + 3m(0))/(5m) = 2u\nu_A = 5u - V = 3u\nu_B = 0 - V = -2u\nu_B' = -e(-2u) = 2eu\n"
    found = worst_lines(SPHERES, work)
    assert [found[n][0] for n in range(1, 5)] == ["correct"] * 4
