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


def test_a_chains_data_before_the_working_is_not_marked_in_the_students_own_names() -> None:
    # A at 3 m/s, B at 1.5 m/s toward A, after: A on at 2, B back at 2.9 (A's way positive):
    # u_B is the chain's name of B's velocity after, but here the student's B before, -1.5.
    # CLM: 3 m_A - 0.3 = 2 m_A + 0.58 -> m_A = 0.88 kg
    work = (
        "Take A's initial direction as positive.\n"
        "Before the collision: u_A = 3, u_B = -1.5. After it: v_A = 2, v_B = 2.9.\n"
        "3m_A + 0.2(-1.5) = 2m_A + 0.2(2.9)\nm_A = 0.88 kg\n"
    )
    assert _statuses("chain-ocr-m2-2011-find-e-mass-then-wall", work) == ["correct"] * 3


def test_a_chains_given_with_its_sign_lost_on_a_data_line_is_still_the_slip() -> None:
    # B moves toward A: with A's way positive B's velocity before is -1.5, not 1.5; and 2 is no B's
    for number in ("1.5", "2"):
        work = f"Take A's initial direction as positive.\nBefore the collision: u_A = 3, u_B = {number}.\n"
        assert _statuses("chain-ocr-m2-2011-find-e-mass-then-wall", work)[0] == "wrong", number


def test_a_law_quoted_after_a_label_and_colon_with_its_letters_is_not_marked() -> None:
    # dropped from 2 m: v^2 = 2(9.8)(2) = 39.2, v = 6.261; it rises to 1.4 m: u^2 = 2(9.8)(1.4) =
    # 27.44, u = 5.238, so 0 = 5.24^2 - 2(9.8)h gives h = 1.40 m
    work = (
        "Down +ve: u = 0, a = 9.8, s = 2\nv^2 = 0 + 2(9.8)(2) = 39.2\nv = 6.26 m/s\n"
        "Part (b) Up +ve: v^2 = u^2 + 2as where v = 0, u = 5.24, a = -9.8\n0 = 5.24^2 - 2(9.8)h\nh = 1.40 m\n"
    )
    assert _statuses("chain-ocr-m2-2006-drop-rebound", work) == ["correct"] * 5


def test_a_result_stated_first_at_a_givens_value_is_judged() -> None:
    # A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward A, e = 0.8: after, v_A = -0.6 and v_B = 3.4;
    # B's -2 is its velocity before, and v_B2 names B's after: a result, wrong, not the data
    work = "v_B2 = -2 m/s\n"
    assert _statuses("aqa-m3-2007-spheres-approach-head-on", work) == ["wrong"]
