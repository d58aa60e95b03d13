"""A chain's derivation where the student introduces a quantity derive has no name for (a
friction force, a deceleration, a time, an angular frequency, an amplitude), relates it to the
givens, solves for it and uses it: the lines are judged by whether they hold given what the
quantity is, the lines before the one that solves for it too, and a value worked from rounded
numbers carries its rounding into the lines that use it. Every number is worked by hand from
the problem files' givens (in the comments), never from derive's output."""

from __future__ import annotations

import pytest

import derive


def statuses(report: derive.checking.report.CheckReport) -> dict[str, str]:
    return {i.name: i.status for i in report.items}


def lines(problem: str, work: str) -> dict[int, str]:
    """line number -> status of ``derive check PROBLEM --derivation``."""
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    rank = ("not read", "correct", "carried", "wrong")
    out: dict[int, str] = {}
    for i in report.items:
        if i.kind == "line" and i.name.isdigit():
            n = int(i.name)
            if n not in out or rank.index(i.status) > rank.index(out[n]):
                out[n] = i.status
    return out


def test_quantities_related_before_a_later_line_finds_them_are_judged_with_them() -> None:
    # The car (910 kg) and the SUV (2100 kg) skid 2.7 m together, mu = 0.80, g = 9.8:
    # F = 0.80(3010)(9.8) = 23598.4 N, a = F/3010 = 7.84 m/s^2 (F = 3010 a holds),
    # V = sqrt(2(7.84)(2.7)) = sqrt(42.336) = 6.5066; t = 6.507/7.84 = 0.82997 s and
    # V t/2 = 6.5066(0.82997)/2 = 2.7001, the skid (the 0.830 rounded, not a slip).
    work = (
        "Let F be the friction force on the wreck and a its deceleration.\n"
        "F = 3010 a\n"
        "F = 0.80(3010)(9.8) = 23598.4\n"
        "a = F/3010 = 7.84\n"
        "V = sqrt(2(7.84)(2.7)) = 6.507\n"
        "t = 6.507/7.84 = 0.830\n"
        "2.7 = V t/2\n"
    )
    found = lines("chain-car-rear-ends-suv-skid", work)
    assert [found[n] for n in (2, 3, 4, 5, 6, 7)] == ["correct"] * 6


def test_a_quantity_defined_by_its_square_is_known_for_the_lines_after() -> None:
    # The block (30 kg) strikes the pan (10 kg) at sqrt(2(9.81)(2)) = 6.2642 m/s; V = 4.6981;
    # k = 20000 N/m: w^2 = 20000/40 = 500. y_0 = 30(9.81)/20000 = 0.014715;
    # A^2 = 0.014715^2 + 4.698^2/500 = 0.00021653 + 0.044142 = 0.044359, A = 0.21062;
    # the lowest point 0.0147 + 0.2106 = 0.2253 m below the pan's first position.
    work = (
        "Let w be the angular frequency of the block and pan on the spring.\n"
        "w^2 = 20000/40 = 500\n"
        "Let A be the amplitude about the new equilibrium.\n"
        "A^2 = (30(9.81)/20000)^2 + 4.698^2/w^2\n"
        "A = 0.2106\n"
        "x = 0.0147 + A = 0.2253\n"
    )
    found = lines("chain-block-onto-spring-pan", work)
    assert [found[n] for n in (2, 4, 5, 6)] == ["correct"] * 4


def test_a_later_definition_does_not_make_an_earlier_false_line_wrong_or_right() -> None:
    # F = 0.80(3010)(9.8) = 23598.4 and a = 7.84, so F = 2100 a (the SUV's mass only) is false;
    # it stays not read (the later lines may have come from a slip), never a false 'correct'.
    work = "F = 2100 a\nF = 0.80(3010)(9.8) = 23598.4\na = F/3010 = 7.84\n"
    found = lines("chain-car-rear-ends-suv-skid", work)
    assert found[1] == "not read"
    assert found[2] == found[3] == "correct"


def test_a_name_with_max_or_min_as_its_subscript_in_latex_is_read() -> None:
    # The bullet (0.020 kg at 300 m/s) lodges in the 4.0 kg block: V = 6/4.02 = 1.49254 m/s;
    # the rise V^2/(2g) = 2.22767/19.62 = 0.11354 m (g = 9.81).
    for name in (r"h_{\max}", r"h_\max", r"h_{\text{max}}"):
        work = f"\\[ {name} = \\frac{{V^2}}{{2g}} = \\frac{{1.4925^2}}{{2(9.81)}} = 0.1135\\ \\text{{m}} \\]\n"
        assert lines("chain-msu-bullet-block-swings", work).get(1) == "correct", name


def test_a_chains_kinetic_energies_named_by_the_student_are_the_impacts() -> None:
    # Suitcase A (15 lb) slides down 6 ft: v = sqrt(2(32.2)(6)) = 19.657 ft/s, so its KE before
    # is 15(6) = 90 ft lb; after the impact (e = 0.3): 15 v = 15 a + 10 b, b - a = 0.3 v gives
    # a = 9.4354, b = 15.3325, and KE after = ½(15/32.2)(9.435²) + ½(10/32.2)(15.33²) = 57.23.
    # With the weights for the masses the 'KE after' is 1842.7: a slip, not a name's definition.
    right = "KE before = (1/2)(15/32.2)(19.66)^2 = 90.0\nKE after = (1/2)(15/32.2)(9.435)^2 + (1/2)(10/32.2)(15.33)^2 = 57.23\n"
    found = lines("chain-hibbeler-15-58-suitcases", right)
    assert found[1] == found[2] == "correct"
    slip = "KE_after = (1/2)(15)(9.435)^2 + (1/2)(10)(15.33)^2 = 1842.7\n"
    assert lines("chain-hibbeler-15-58-suitcases", slip)[1] == "wrong"


def test_two_names_met_only_together_are_the_givens_of_their_letters_that_make_it_hold() -> None:
    # The car (910 kg) locks onto the SUV (2100 kg) and they skid 2.7 m (mu = 0.80, g = 9.8):
    # V = sqrt(42.336) = 6.5066 and the car's speed 3010 V/910 = 21.52 m/s; so m v = (m + 2100) V
    # holds with m the car's mass and v its speed (no other pair of the chain's values does).
    # (Neither m nor v is met alone on another line, so neither is inferred one at a time.)
    work = "m v = (m + 2100) V\nV = sqrt(2(0.80)(9.8)(2.7)) = 6.507\n"
    found = lines("chain-car-rear-ends-suv-skid", work)
    assert [found[n] for n in (1, 2)] == ["correct"] * 2


def test_an_equation_for_the_next_result_from_a_wrong_number_is_carried() -> None:
    # The bullet (0.020 kg at 300 m/s) in the 4.0 kg block: V = 6/4.02 = 1.4925, written 1.39.
    # Then ½(4.02)(1.39²) = 3.8835 = 4.02(9.81) h = 39.44 h holds for the student's h = 0.09847:
    # worked from the wrong 1.39, carried, as is h = 0.0985 (the true rise is 0.11354 m).
    work = "V = 6/4.02 = 1.39\n(1/2)(4.02)(1.39)^2 = 4.02(9.81)h = 39.44h\nh = 3.884/39.44 = 0.0985\n"
    found = lines("chain-msu-bullet-block-swings", work)
    assert found[1] == "wrong"
    assert found[2] == found[3] == "carried"


# A 0.3 kg at 3 m/s meets B 0.2 kg at 2 m/s head on, e = 0.8 (AQA M3 2007): the total momentum
# 0.3(3) - 0.2(2) = 0.5; after, 0.3a + 0.2b = 0.5 and b - a = 0.8(5) = 4 give a = -0.6, b = 3.4;
# KE before ½(0.3)(9) + ½(0.2)(4) = 1.75, after ½(0.3)(0.36) + ½(0.2)(11.56) = 1.21: 0.54 lost.
HEAD_ON = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(("before", "after"), [("p_i", "p_f"), ("P_before", "P_after"), ("p_initial", "p_final")])
def test_the_total_momentum_named_before_and_after_is_the_momentum_of_both(before: str, after: str) -> None:
    work = f"{before} = {after}\n{before} = 0.3(3) + 0.2(-2) = 0.5\n{after} = 0.3(-0.6) + 0.2(3.4) = 0.5\n"
    found = statuses(derive.check(derive.solve(derive.load(HEAD_ON)), derivation=work))
    assert [found[n] for n in ("1", "2", "3")] == ["correct"] * 3
    slip = f"{before} = 0.3(3) + 0.2(2) = 1.3\n"  # B's velocity with the wrong sign: not p_i's definition
    assert statuses(derive.check(derive.solve(derive.load(HEAD_ON)), derivation=slip))["1"] == "wrong"


@pytest.mark.parametrize("line", ["ΔKE = 1.21 - 1.75 = -0.54", "ΔKE = 1.75 - 1.21 = 0.54", r"\Delta KE = -0.54 J"])
def test_a_change_in_kinetic_energy_is_read_with_the_sign_it_is_worked_with(line: str) -> None:
    found = statuses(derive.check(derive.solve(derive.load(HEAD_ON)), derivation=line + "\n"))
    assert found["1"] == "correct", line
    wrong = line.replace("0.54", "0.45")
    assert statuses(derive.check(derive.solve(derive.load(HEAD_ON)), derivation=wrong + "\n"))["1"] == "wrong"


def test_a_chains_velocities_named_by_the_habit_are_its_impacts() -> None:
    # The car (910 kg) at 21.52 m/s locks onto the stopped SUV (2100 kg): 910(21.52) = 19583 =
    # 3010 V with V = 6.5066 (the skid), so A and B both move at V after. vB - vA = 0.8(21.52)
    # takes mu for e (e = 0 here): wrong; the rest is worked from it: 19583 = 3010 vA + 36162,
    # vA = -16579/3010 = -5.508, carried. vA and vB are A's and B's velocities after the impact.
    work = (
        "910(21.52) + 0 = 910 vA + 2100 vB\n"
        "vB - vA = 0.8(21.52 - 0) = 17.22\n"
        "19583 = 910 vA + 2100(vA + 17.22) = 3010 vA + 36162\n"
        "vA = -16579/3010 = -5.508\n"
    )
    found = lines("chain-car-rear-ends-suv-skid", work)
    assert [found[n] for n in (1, 2, 3, 4)] == ["correct", "wrong", "carried", "carried"]


def test_a_side_of_names_and_a_wrong_number_is_carried_where_the_number_put_right_holds() -> None:
    # V = 6/4.02 = 1.4925 written 1.39; ½(4.02)(1.39²) - 4.02(9.81)h = 0 is the energy rule
    # right, worked from 1.39 (with 1.4925 it holds at the true rise 0.11354 m): carried.
    work = "V = 6/4.02 = 1.39\n(1/2)(4.02)(1.39)^2 - 4.02(9.81)h = 0\n"
    found = lines("chain-msu-bullet-block-swings", work)
    assert found[1] == "wrong"
    assert found[2] == "carried"


def test_an_energy_named_initial_for_a_later_stage_is_not_taken_for_the_impacts() -> None:
    # The spring stage's energy balance starts just after the impact: KE_i = ½(40)(4.698²) =
    # 441.4 J there (the impact's KE before is ½(30)(6.264²) = 588.6): the student's own name.
    found = lines("chain-block-onto-spring-pan", "KE_i = (1/2)(40)(4.698)^2 = 441.4\n")
    assert found[1] == "correct"
