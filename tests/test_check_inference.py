"""The student's frame and names, inferred where nothing declares them (issue #31, conventions).

Values worked by hand from the problems' givens, never from derive's output:

- Edexcel M2 ball and wall (2 kg at 4 m/s into a wall, e = 0.4): rebound speed 0.4 x 4 = 1.6 m/s;
  away from the wall as positive, the velocity before is -4 and after +1.6.
- BYJU'S (A 4 kg at 12 m/s catches B 8 kg at 4 m/s, e = 0.5): 4(12) + 8(4) = 80 = 4a + 8b,
  b - a = 0.5(12 - 4) = 4, so 12a = 48: a = 4, b = 8 m/s, both still moving on. Taking the way
  they move as negative: before -12 and -4, after -4 and -8.
- Notes 4c11 is not used here: its numbers are the corpus's.
"""

from __future__ import annotations

import pytest

import derive

WALL = "edexcel-m2-ball-rebounds-from-wall"
CATCH = "byjus-4kg-ball-catches-8kg-ball"


def by_line(problem: str, work: str) -> dict[str, str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    out: dict[str, str] = {}
    for i in report.items:
        if i.kind == "line" and i.name.isdigit():
            worst = ("wrong", "carried", "error", "correct")
            old = out.get(i.name)
            out[i.name] = i.status if old is None or worst.index(i.status) < worst.index(old) else old
    return out


def all_correct(problem: str, work: str) -> None:
    seen = by_line(problem, work)
    assert seen and set(seen.values()) == {"correct"}, seen


# ------------------------------------------------- derive's names in the student's own frame


@pytest.mark.parametrize(
    "work",
    [
        "Taking away from the wall as positive.\nv_A1 = -4 m/s\nv_A2 = -e v_A1 = -0.4(-4) = 1.6 m/s",
        "positive: away from the wall\n$v_{A1} = -4$\n$v_{A2} = 1.6$ m/s",
        "v_A1 = -4\nv_A2 = -0.4 x (-4) = 1.6",  # nothing said: the values written say it
        "(v_A)_1 = -4 m/s, so (v_A)_2 = -e(v_A)_1 = +1.6 m/s",
    ],
)
def test_derives_names_in_a_frame_away_from_the_wall(work: str) -> None:
    all_correct(WALL, work)


def test_a_sign_slip_in_the_students_own_frame_is_still_wrong() -> None:
    work = "Taking away from the wall as positive.\nv_A1 = -4 m/s\nv_A2 = -1.6 m/s"
    assert by_line(WALL, work) == {"2": "correct", "3": "wrong"}


def test_derives_names_with_the_way_both_move_taken_as_negative() -> None:
    work = "\n".join(
        [
            "I take left as positive; both balls roll to the right.",
            "v_A1 = -12, v_B1 = -4",
            "4 v_A1 + 8 v_B1 = 4 v_A2 + 8 v_B2",
            "4(-12) + 8(-4) = -80 = 4 v_A2 + 8 v_B2",
            "v_B2 - v_A2 = -0.5(v_B1 - v_A1) = -0.5(-4 + 12) = -4",
            "12 v_A2 = -80 + 32 = -48",
            "v_A2 = -4 m/s, v_B2 = -8 m/s",
        ]
    )
    all_correct(CATCH, work)


def test_derives_names_in_derives_frame_with_one_sign_slip_stay_in_derives_frame() -> None:
    # v_B2 written with the wrong sign once: that is a slip, not a reversed frame
    work = "v_A1 = 12, v_B1 = 4\n4(12) + 8(4) = 4 v_A2 + 8 v_B2\nv_B2 - v_A2 = 0.5(12 - 4)\nv_A2 = 4\nv_B2 = -8"
    seen = by_line(CATCH, work)
    assert seen["5"] == "wrong" and seen["4"] == "correct" and seen["1"] == "correct", seen
