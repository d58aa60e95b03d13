"""A line of the problem's data before the working, with no "Given:" header (datalines.py): a
name set to a given's exact value, in the student's own sign convention, is not working and is
not marked, whatever instant or component the checker reads the name as; a number that is no
given's value of that body, or the value with its sign turned against the student's declared way,
is still the slip. Expected marks worked by hand from each problem's givens."""

from __future__ import annotations

import derive
from derive.mathtext.splitting import split_relations


def _statuses(problem: str, work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return [i.status for i in report.items]


def test_a_given_velocity_after_restated_in_words_of_before_is_not_marked() -> None:
    # A 2 kg at 5 m/s hits B 1 kg at rest and goes on at 2 m/s: "initially" on the line made
    # v_A read as A's velocity before (5), and the restated 2 a given copied wrongly.
    # 2(5) + 0 = 2(2) + v_B -> v_B = 6 (exactly).
    work = "+ve: the way A was going initially. A keeps going so v_A = 2\n2(5) + 1(0) = 2(2) + 1(v_B)\nv_B = 6\n"
    assert _statuses("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work) == ["correct"] * 3


def test_a_rebound_restated_with_the_students_sign_is_not_marked() -> None:
    # the ball at 3.00 m/s into the cushion, straight back at 2.40 m/s: with the ball's first way
    # positive it is -2.40; e = 2.40/3.00 = 0.8
    work = "Positive along the ball's initial direction. It comes straight back so vA = -2.40\ne = 2.40/3.00 = 0.8\n"
    assert _statuses("openstax-cp-8-31-billiard-ball-cushion", work) == ["correct", "correct"]


def test_a_given_with_its_sign_turned_or_another_number_is_still_the_slip() -> None:
    # A carries on at +2 in the student's own (A's) way: -2 and 3 are no given of A's
    for number in ("-2", "3"):
        work = f"+ve: the way A was going initially. A keeps going so v_A = {number}\n"
        assert _statuses("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)[0] == "wrong", number


def test_a_component_set_to_a_speed_is_still_the_slip() -> None:
    # Example 4.C.11: A at 5 m/s, B at 15 m/s, each at 37.6 deg to the line of centres; their n
    # components are 5 cos 37.6 = 3.961 and -15 cos 37.6 = -11.88, not the speeds
    work = "u_{An} = 5 m/s, u_{Bn} = -15 m/s\n20(3.961) + 5(-11.88) = 20 v_{An} + 5 v_{Bn}\n"
    assert _statuses("notes-4c11-two-spheres", work)[0] == "wrong"


def test_a_speed_restated_as_the_givens_letter_is_not_marked() -> None:
    # the ball's speed before is the problem's U: "(u)_1 = U" states it, whatever (u)_1 is read as
    work = "Let the speed before be (u)_1 = U.\n"
    assert _statuses("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta", work) == ["correct"]


def test_givens_typed_tight_a_space_apart_are_separate_relations() -> None:
    # "mA=2 mB=1 e=0.5": three givens, not mB = 1e = 0.5; a product typed together stays one
    assert [p.strip() for p in split_relations("masses mA=2 mB=1 e=0.5")] == ["masses mA=2", "mB=1", "e=0.5"]
    assert split_relations("v=2u=8") == ["v=2u=8"]

