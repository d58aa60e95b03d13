"""A chain's numbered names counted from the student's own first station (derive/checking/stations.py):
"(1) thrown, (2) just before the ground, (3) just after" makes the student's v_2 the chain's v_1
(the landing speed) and v_3 the chain's v_2 (the rebound), where the student's numbers run past
the chain's and the relations hold so. Numbers worked by hand from the problem files' givens."""

from __future__ import annotations

from support.checked import lines

# OCR M2 2007: thrown down at 21 m/s from 40 m, g = 9.8: v_1^2 = 441 + 784 = 1225, v_1 = 35;
# it rebounds to the start: v_2^2 = 2(9.8)(40) = 784, v_2 = 28; e = 28/35 = 0.8.
REBOUNDS = "chain-ocr-m2-2007-rebounds-to-start"


def test_stations_from_the_throw_are_the_chains_instants() -> None:
    work = (
        "Stations: (1) thrown, (2) just before the ground, (3) just after, (4) back at the top.\n"
        "v_2^2 = v_1^2 + 2 g h_0 = 21^2 + 2(9.8)(40) = 1225\n"
        "v_2 = 35 m/s\n"
        "v_3^2 = 2 g h_0 = 2(9.8)(40) = 784\n"
        "v_3 = 28 m/s\n"
        "e = v_3/v_2 = 28/35 = 0.8\n"
    )
    found = lines(REBOUNDS, work)
    assert [found[n][0] for n in range(2, 7)] == ["correct"] * 5


def test_stations_from_release_at_rest_in_latex() -> None:
    # OCR M2 2006: dropped from 2 m: v^2 = 2(9.8)(2) = 39.2, 6.261; rebounds to 1.4 m:
    # 2(9.8)(1.4) = 27.44, 5.238; e = 5.238/6.261 = 0.8367. The student's v_1 is the release, 0.
    work = (
        "Points: 1 = released, 2 = just before the bounce, 3 = just after.\n\n"
        "$v_1 = 0$\n\n"
        "$v_2^2 = v_1^2 + 2(9.8)(2) = 39.2$, so $v_2 = 6.26$ m/s\n\n"
        "$v_3^2 = 2(9.8)(1.4) = 27.44$, so $v_3 = 5.24$ m/s\n\n"
        "$e = v_3 / v_2 = 5.24/6.26 = 0.837$\n"
    )
    found = lines("chain-ocr-m2-2006-drop-rebound", work)
    assert [found[n][0] for n in (3, 5, 7, 9)] == ["correct"] * 4


def test_a_slip_at_a_station_is_carried_in_the_stations_names() -> None:
    # 441 + 784 written 1215: v = sqrt(1215) = 34.86 (the slip); e = 28/34.86 = 0.8032, carried.
    work = (
        "(1) thrown (2) hits the ground (3) leaves it\n"
        "v2^2 = v1^2 + 2*9.8*40 = 441 + 784 = 1215\n"
        "v2 = 34.86\n"
        "v3 = sqrt(2*9.8*40) = 28\n"
        "e = v3/v2 = 28/34.86 = 0.803\n"
    )
    found = lines(REBOUNDS, work)
    assert found[2][:2] == ("wrong", "arithmetic")
    assert [found[n][0] for n in (3, 4, 5)] == ["carried", "correct", "carried"]


def test_a_third_name_of_the_students_own_beside_the_chains_is_not_shifted() -> None:
    # v_1 and v_2 the chain's (35 and 28); v_3 the student's own sum of speeds, 63: J = 0.2(63) = 12.6.
    work = (
        "v_1^2 = 21^2 + 2(9.8)(40) = 1225, v_1 = 35\n"
        "v_2^2 = 2(9.8)(40) = 784, v_2 = 28\n"
        "v_3 = v_1 + v_2 = 63\n"
        "J = 0.2 v_3 = 12.6\n"
    )
    found = lines(REBOUNDS, work)
    assert [found[n][0] for n in (1, 2, 4)] == ["correct"] * 3
