"""A kinetic energy labelled in words before a colon and worked in numbers (``KE before: ½ ×
0.150 × 35.0 = 2.63 J``) is judged as the energy its label names, not as arithmetic only: a
speed not squared is the slip (fixC, eighth session). Every number here is worked by hand from
the problem files' givens (in the comments), never from derive's output."""

from __future__ import annotations

import pytest

import derive


def lines(problem: str, work: str) -> dict[int, tuple[str, str]]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return {int(i.name): (i.status, i.slip) for i in report.items if i.kind == "line" and i.name.isdigit()}


# Goalie (OpenStax 8.5): V = 5.25/70.15 = 0.0748; KE before ½(0.150)(35.0²) = 91.875, not
# ½(0.150)(35.0) = 2.625 (2.63); KE after ½(70.15)(0.0748²) = 0.196; the loss from the student's
# 2.63 is 2.63 - 0.196 = 2.434 (2.43): carried.
GOALIE = "openstax-cp-8-5-goalie-catches-puck"


def test_a_labelled_energy_with_its_speed_not_squared_is_the_slip_and_the_loss_carried() -> None:
    work = (
        "0.150 x 35.0 = 70.15 V\nV = 0.0748 m/s\n"
        "KE before: ½ × 0.150 × 35.0 = 2.63 J\n"
        "KE after: ½ × 70.15 × 0.0748² = 0.196 J\n"
        "KE lost: 2.63 - 0.196 = 2.43 J\n"
    )
    found = lines(GOALIE, work)
    # a speed put in unsquared is arithmetic, as the corpus's teachers name it (docs/checking.md)
    assert found[3] == ("wrong", "arithmetic")
    assert found[4][0] == "correct"
    assert found[5][0] == "carried"


# OCR M2 2012: 0.8 kg at 4 m/s into a wall, e = 0.3; the rebound 1.2 m/s.
# KE before ½(0.8)(4²) = 6.4 J (½(0.8)(4) = 1.6 is not it); after ½(0.8)(1.2²) = 0.576 J.
WALL = "ocr-m2-2012-particle-hits-wall"


@pytest.mark.parametrize(
    "said",
    ["Kinetic energy before: 1/2 (0.8)(4) = 1.6 J", "initial KE: 0.5 x 0.8 x 4 = 1.6 J"],
)
def test_a_labelled_energy_before_not_squared_is_wrong(said: str) -> None:
    assert lines(WALL, said + "\n")[1][0] == "wrong"


@pytest.mark.parametrize(
    "said",
    ["KE before: 1/2 (0.8)(4^2) = 6.4 J", "KE after: 0.5 x 0.8 x 1.2^2 = 0.576 J", "KE lost: 6.4 - 0.576 = 5.824 J"],
)
def test_a_labelled_energy_worked_rightly_is_correct(said: str) -> None:
    assert lines(WALL, said + "\n")[1][0] == "correct"


def test_an_instant_alone_under_a_kinetic_energy_heading_is_that_energy() -> None:
    # "## Kinetic energy" then "* before: ½ × 0.150 × 35.0 = 2.63": KE before is 91.875, so the slip;
    # "* after: ½ × 70.15 × 0.0748² = 0.196" is right.
    work = (
        "0.150 x 35.0 = 70.15 V\nV = 0.0748 m/s\n\n## Kinetic energy\n\n"
        "* before: ½ × 0.150 × 35.0 = 2.63 J\n* after: ½ × 70.15 × 0.0748² = 0.196 J\n"
    )
    found = lines(GOALIE, work)
    assert found[6][0] == "wrong"
    assert found[7][0] == "correct"


def test_an_instant_alone_under_a_momentum_heading_is_not_an_energy() -> None:
    # "**Momentum**" then "- before: 0.150 × 35.0 = 5.25": arithmetic, right (0.150 x 35.0 = 5.25).
    work = "**Momentum**\n\n- before: 0.150 × 35.0 = 5.25\n- after: 70.15 × 0.0748 = 5.25\n"
    found = lines(GOALIE, work)
    assert found[3][0] == found[4][0] == "correct"


def test_a_name_of_its_own_after_an_energy_label_is_not_that_energy() -> None:
    # "KE lost by the reduced mass: M = (0.150)(70.0)/(70.15)": M is the reduced mass,
    # 10.5/70.15 = 0.14968 (0.150), not the energy lost.
    work = "KE lost by the reduced mass: M = (0.150)(70.0)/(70.15) = 0.150 kg\n"
    assert lines(GOALIE, work)[1][0] == "correct"
