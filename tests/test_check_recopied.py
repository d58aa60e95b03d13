"""A number worked out on a line above and copied into a later line's working wrongly (digits
in another order, one digit changed) is ``copied_wrong``; worked out wrongly on its own line it
stays ``arithmetic`` (derive/checking/recopied.py). Expected values by hand."""

from __future__ import annotations

from support.checked import lines

#: Young & Freedman 8.96: A 0.0400 kg at 0.200 m/s, on at 0.050 m/s after an elastic impact with B
#: at rest: v_B = 0.200 + 0.050 = 0.250 m/s, 0.0400(0.200) = 0.0400(0.050) + m_B(0.250), m_B = 0.0240 kg.
PUCKS = "young-freedman-8-96-pucks-find-mass"
#: OpenStax 8.5: 0.150 kg at 35.0 m/s caught by 70.0 kg: V = 5.25/70.15 = 0.07484 m/s,
#: T_2 = ½(70.15)(0.07484)² = 0.1965 J.
GOALIE = "openstax-cp-8-5-goalie-catches-puck"


def test_velocity_copied_with_digits_swapped_into_the_momentum() -> None:
    work = (
        "v_B2 - v_A2 = 0.200 - 0 = 0.200\n"
        "v_B2 = 0.200 + 0.050 = 0.250 m/s\n"
        "0.0400(0.200) + 0 = 0.0400(0.050) + m_B(0.205)\n"  # 0.250 copied as 0.205
        "m_B = 0.00600/0.205 = 0.0293 kg\n"
    )
    found = lines(PUCKS, work)
    assert found[3][:2] == ("wrong", "copied_wrong")
    assert found[4][0] == "carried"


def test_common_speed_copied_into_the_energy_latex() -> None:
    work = (
        "\\[ (0.150)(35.0) = (70.15)V \\]\n"
        "\\[ V = 0.0748 \\text{ m/s} \\]\n"
        "\\[ KE_{after} = \\tfrac12 (70.15)(0.0784)^2 = 0.216 \\text{ J} \\]\n"  # 0.0748 copied as 0.0784
    )
    assert lines(GOALIE, work)[3][:2] == ("wrong", "copied_wrong")


def test_a_result_worked_wrongly_on_its_line_stays_arithmetic() -> None:
    work = "v_B2 - v_A2 = 0.200\nv_B2 = 0.050 + 0.200 = 0.205 m/s\n"  # 0.250 worked, not copied
    assert lines(PUCKS, work)[2][:2] == ("wrong", "arithmetic")
