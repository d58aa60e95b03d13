"""A line's sides compared with each other, not only each with the number it ends in (fixC,
eighth session): ``KE lost = ½ m_A (v_A1 − V)² = 91.5 J`` is a wrong formula whose value is
near the energy lost (91.68 J), and the number's figures alone cannot tell them apart. The
name and the formula, the formula and its working, must be equal for the problem in the
student's own names. A result then worked from the wrong value (``KE after = KE before − KE
lost``) is carried. Every number here is worked by hand from the problem files' givens (in
the comments), never from derive's output."""

from __future__ import annotations

import pytest

import derive


def lines(problem: str, work: str) -> dict[int, tuple[str, str]]:
    """line number -> (status, slip name) of ``derive check PROBLEM --derivation``."""
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return {int(i.name): (i.status, i.slip) for i in report.items if i.kind == "line" and i.name.isdigit()}


# Goalie (OpenStax 8.5): puck 0.150 kg at 35.0 m/s, goalie 70.0 kg at rest, they move off together.
# V = 5.25/70.15 = 0.074840; KE before = 0.075(1225) = 91.875; KE after = 35.075(0.074840²) = 0.19645;
# lost 91.678. The puck's ½ m (u − V)² alone: 0.075(34.92516²) = 0.075(1219.767) = 91.483 (91.5).
GOALIE = "openstax-cp-8-5-goalie-catches-puck"
RECOIL = "0.150 x 35.0 = 70.15 V\nV = 0.0748 m/s\n"


@pytest.mark.parametrize(
    "said",
    [
        "KE_lost = 1/2 m_A (v_A1 - V)^2 = 91.5 J",  # letters, then the number
        "KE lost = 1/2 m_A (v_A1 - V)^2 = 1/2 x 0.150 x (35.0 - 0.0748)^2 = 91.5 J",  # its working too
        "T_lost = 1/2 m_A (v_A1 - V)^2 = 1/2 (0.150)(35.0 - 0.0748)^2 = 91.5 J",  # both
    ],
)
def test_a_wrong_energy_formula_near_the_true_value_is_the_slip(said: str) -> None:
    found = lines(GOALIE, RECOIL + said + "\n")
    assert found[1][0] == found[2][0] == "correct"
    assert found[3] == ("wrong", "ke_formula")


def test_the_energy_after_worked_from_the_wrong_loss_is_carried() -> None:
    # KE after = 91.9 - 91.5 = 0.4 (the student's), not 0.196: carried from the loss.
    work = RECOIL + (
        "KE_lost = 1/2 m_A (v_A1 - V)^2 = 91.5 J\n"
        "KE_before = 1/2 (0.150)(35.0^2) = 91.9 J\n"
        "KE_after = KE_before - KE_lost = 91.9 - 91.5 = 0.4 J\n"
    )
    found = lines(GOALIE, work)
    assert found[3] == ("wrong", "ke_formula")
    assert found[4][0] == "correct"
    assert found[5][0] == "carried"


def test_the_energy_lost_by_the_right_formula_is_still_correct() -> None:
    # 91.875 - ½(70.15)(0.0748²) = 91.875 - 0.19624 = 91.679 (91.7)
    work = RECOIL + "KE lost = 1/2 (0.150)(35.0)^2 - 1/2 (70.15)(0.0748)^2 = 91.7 J\n"
    assert lines(GOALIE, work)[3][0] == "correct"


# Bullet (MSU): 0.020 kg at 300 m/s into a 4.0 kg block at rest, it lodges. V = 6/4.02 = 1.4925;
# T_1 = 0.01(90000) = 900; T_2 = 2.01(1.4925²) = 4.478; lost 895.52. The bullet's ½ m (u − V)²:
# 0.01(298.51²) = 891.07; at two figures 8.9 x 10^2 either way, so only the formula tells them apart.
BULLET = "msu-lectureonline-bullet-lodges-in-block"


def test_a_wrong_formula_at_two_figures_is_the_slip_and_the_rest_carried() -> None:
    work = (
        "0.020(300) = 4.02 V\nV = 1.49 m/s\nT_1 = 1/2 (0.020)(300^2) = 900 J\n"
        "T_lost = 1/2 m_A (v_A1 - V)^2 = 8.9 x 10^2 J\n"
        "T_2 = T_1 - T_lost = 900 - 890 = 10 J\n"  # the student's own 10 J, from the wrong loss
    )
    found = lines(BULLET, work)
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4] == ("wrong", "ke_formula")
    assert found[5][0] == "carried"


# Train cars (OpenStax 8): 150000 kg at 0.300 m/s, 110000 kg at -0.120 m/s, they couple.
# V = (45000 - 13200)/260000 = 0.12231 (0.122). The energy in the centre of mass's frame,
# ½ m_A (u_A − V)² + ½ m_B (u_B − V)², is all lost where e = 0: 75000(0.178²) + 55000(0.242²)
# = 2376.3 + 3221.0 = 5597.3, and T_1 − T_2 = 7542 − 130000(0.12231²) = 7542 − 1944.7 = 5597.3.
def test_the_energy_in_the_centre_of_mass_frame_is_still_correct() -> None:
    work = (
        "150000(0.300) + 110000(-0.120) = 260000 V\nV = 0.122 m/s\n"
        "KE lost = 1/2 m_A (u_A - V)^2 + 1/2 m_B (u_B - V)^2"
        " = 1/2 (150000)(0.300 - 0.122)^2 + 1/2 (110000)(-0.120 - 0.122)^2 = 5597 J\n"
    )
    assert lines("openstax-cp-8-train-cars-couple", work)[3][0] == "correct"
