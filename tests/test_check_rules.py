"""The checker's parts: the equation rules, two mistakes together, rounded intermediates,
students' notation in formulas, and a report that keeps its other items when one is bad.

Numbers come from the notes (Example 4.C.11: m_A = 20 kg, m_B = 5 kg, e = 0.6,
v_A = 5 m/s, v_B = 15 m/s at θ = 37.6°; v_A2t = 3.05, v_B2t = −9.15, v_A2n = −1.11,
v_B2n = 8.40 m/s; equations (3) 20 v_A2n + 5 v_B2n = 19.8 and (4) v_B2n − v_A2n = 9.5)
or are worked here by hand from them with ``math``; never pasted from derive.
"""

from __future__ import annotations

import json
import math

import pytest

import derive
from derive.checking import mistakes
from derive.checking.context import Context
from derive.checking.entries import Entry
from derive.checking.equation import RULES, judge, read_equation

C11 = "notes-4c11-two-spheres"
OCR = "ocr-fm-2023-oblique-discs-60deg"
DEG = math.pi / 180
mA, mB, e, vA, vB, th = 20.0, 5.0, 0.6, 5.0, 15.0, 37.6 * DEG
# 4.C.11 by hand: n along A's velocity's n component, B moving toward A
A1n, A1t, B1n, B1t = vA * math.cos(th), vA * math.sin(th), -vB * math.cos(th), -vB * math.sin(th)
COS = math.cos(th)
_SOLVED: dict[str, derive.Solution] = {}


def solved(name: str) -> derive.Solution:
    if name not in _SOLVED:
        _SOLVED[name] = derive.solve(derive.load(name))
    return _SOLVED[name]


def one(problem: str, name: str, value: str, **kw) -> derive.checking.report.Item:
    report = derive.check(solved(problem), {name: value}, **kw)
    assert len(report.items) == 1
    return report.items[0]


def n_solve(c3: float, c4: float) -> tuple[float, float]:
    """(3) 20 a + 5 b = c3 and (4) b - a = c4, solved by hand."""
    a = (c3 - mB * c4) / (mA + mB)
    return a, a + c4


def sig(x: float, n: int) -> str:
    return f"{x:#.{n}g}".rstrip(".")


# ------------------------------------------------------------------ the rules table


def verdict(label: str, text: str, problem: str = C11):
    ctx = Context(solved(problem), None)
    return judge(ctx, read_equation(ctx, Entry(label, text)))


def test_the_rules_table_is_in_the_documented_order() -> None:
    names = [r.__name__ for r in RULES]
    assert names[:5] == ["same_equation", "mistaken_equation", "relabelled", "solves_correctly", "solves_as_mistake"]
    assert "consistent" in names
    assert all(r.__doc__ for r in RULES)


# the constant of the masses-swapped (3), 5 v_A1n + 20 v_B1n, and its velocities with the correct (4)
_SWAP_C3 = mB * A1n + mA * B1n
_SEP = e * (A1n - B1n)
_SWAP_A2N = (_SWAP_C3 - mA * _SEP) / (mA + mB)


@pytest.mark.parametrize(
    ("label", "text", "rule", "correct", "equation", "mistake"),
    [
        ("3", "20*v_A2n + 5*v_B2n = 19.8", "same_equation", True, 3, None),  # the notes' (3)
        ("4", "v_B2n - v_A2n = 9.5", "same_equation", True, 4, None),  # the notes' (4)
        ("4", "v_A2n - v_B2n = 9.5", "mistaken_equation", False, 4, "restitution_reversed"),
        ("4", "20*v_A2n + 5*v_B2n = 19.8", "relabelled", True, 3, None),
        ("5", "25*v_A2n = 19.8 - 5*9.5", "solves_correctly", True, 3, None),  # the notes' elimination
        ("3", f"25*v_A2n = {_SWAP_C3 - mA * _SEP:.4f}", "solves_as_mistake", False, 3, "masses_swapped"),
        ("1", "25*v_A2n = 19.8 - 5*9.5", "consistent", True, None, None),  # an n equation labelled (1)
        ("3", "5*v_A2n + 20*v_B2n = 19.8", "mistaken_equation", False, 3, "masses_swapped"),  # after only
        ("3", "20*v_A2n + 7*v_B2n = 19.8", "no_match", False, 3, None),
    ],
    ids=[
        "same-3",
        "same-4",
        "mistaken",
        "relabelled",
        "solves",
        "solves-as-mistake",
        "consistent",
        "masses-one-side",
        "no-match",
    ],
)
def test_each_rule_gives_its_verdict(
    label: str, text: str, rule: str, correct: bool, equation: int | None, mistake: str | None
) -> None:
    v = verdict(label, text)
    assert v.rule == rule
    assert v.correct is correct
    assert v.equation == equation
    assert [d.mistake for d in v.mistakes] == ([mistake] if mistake else [])


def test_the_solved_as_mistake_equation_is_that_mistakes_velocity() -> None:
    # by hand: 5 a + 20 b = 5 v_A1n + 20 v_B1n with b - a = e (v_A1n - v_B1n)
    assert round(_SWAP_A2N, 2) == -16.32


# ------------------------------------------------------------------ two mistakes together


def test_two_mistakes_together_are_named() -> None:
    # the system's t momentum, with e applied to it: one t velocity e (m_A v_A1t + m_B v_B1t)/(m_A + m_B)
    both = e * (mA * A1t + mB * B1t) / (mA + mB)
    assert both == pytest.approx(0.366, abs=1e-3)
    for name in ("v_A2t", "v_B2t"):
        item = one(C11, name, sig(both, 3))
        assert item.status == "wrong"
        assert {"system_t", "e_on_t"} <= {d.mistake for d in item.diagnosis}, item.message
        assert "together" in item.message
        for d in item.diagnosis:
            assert d.title == mistakes.REGISTRY[d.mistake].title and d.where


def test_two_mistakes_together_on_another_problem() -> None:
    # OCR FM 2023: A 5 kg at 4 m/s at 60° to n, B 3 kg moving along n (no t component), e = 3/4
    both = 0.75 * 5 * 4 * math.sin(60 * DEG) / (5 + 3)
    item = one(OCR, "v_A2t", sig(both, 4))
    assert {"system_t", "e_on_t"} <= {d.mistake for d in item.diagnosis}, item.message


def test_a_single_mistake_is_still_preferred_to_a_pair() -> None:
    item = one(C11, "v_A2t", sig(e * A1t, 3))  # e on t alone: 1.83
    assert [d.mistake for d in item.diagnosis] == ["e_on_t"]
    assert "together" not in item.message


def test_pairs_are_bounded() -> None:
    pairs = mistakes.pair_outcomes(solved(C11))
    singles = mistakes.outcomes(solved(C11))
    assert 0 < len(pairs) <= min(mistakes.MAX_PAIRS, len(singles) * (len(singles) - 1) // 2)
    assert all(o.mistake is not None and o.mistake.name.count("+") == 1 for o in pairs)


def test_a_pair_equation_is_named_together() -> None:
    # (1) as the pair writes it: the system's t momentum, with e applied to the t components
    v = verdict("1", "0.6*(20*v_A1t + 5*v_B1t) = 20*v_A2t + 5*v_B2t")
    assert not v.correct and v.together
    assert {"system_t", "e_on_t"} <= {d.mistake for d in v.mistakes}


# ------------------------------------------------------------------ rounded intermediates


def r3(x: float) -> float:
    return float(f"{x:.3g}")


def test_answers_from_components_rounded_to_3_figures_are_accepted_and_said_so() -> None:
    a1, b1 = r3(A1n), r3(B1n)  # 3.96 and -11.9
    assert (a1, b1) == (3.96, -11.9)
    v_A2n, v_B2n = n_solve(mA * a1 + mB * b1, e * (a1 - b1))
    for name, value in (("v_A2n", v_A2n), ("v_B2n", v_B2n)):
        written = sig(value, 4)  # -1.115, 8.401: off by more than the last digit
        item = one(C11, name, written)
        assert item.status == "correct", (written, item.message)
        assert "rounded intermediates" in item.message and "3 significant figures" in item.message
        assert "3-figure intermediates" in item.method


def test_answers_from_the_notes_numbers_of_3_and_4_are_accepted() -> None:
    _, v_B2n = n_solve(19.8, 9.51)  # (3) and (4) with 3-figure numbers
    item = one(C11, "v_B2n", f"{v_B2n:.3f}")  # 8.400
    assert item.status == "correct" and "rounded intermediates" in item.message
    # the direction from the notes' 3.05 and -1.11
    theta = math.degrees(math.atan2(-1.11, 3.05))
    assert one(C11, "theta_A2", f"{theta:.2f}").status == "correct"


def test_the_rounding_band_is_narrow_and_a_near_miss_gets_a_word_about_rounding() -> None:
    exact = {"v_B2n": 53 / 5 * COS, "v_A2n": -7 / 5 * COS}  # the notes' example solved by hand
    for name, written in (("v_B2n", "8.396"), ("v_B2n", "8.42"), ("v_A2n", "-1.107"), ("v_A2n", "-1.13")):
        item = one(C11, name, written)
        assert item.status == "wrong", (written, item.message)
        near = abs(float(written) - exact[name]) <= 0.01 * abs(exact[name])
        assert ("within 1 % of the exact value" in item.message) is near, item.message
        assert ("3-figure intermediates give" in item.message) is near


def test_no_rounding_band_with_a_tolerance() -> None:
    a1, b1 = r3(A1n), r3(B1n)
    v_A2n, _ = n_solve(mA * a1 + mB * b1, e * (a1 - b1))
    assert one(C11, "v_A2n", sig(v_A2n, 4), tolerance="0.1%").status == "wrong"


def test_rounded_intermediates_in_a_direct_impact_with_weights() -> None:
    # Hibbeler 15-58: 15 lb at 19.657 ft/s onto 10 lb at rest, e = 0.3: masses W/g rounded to 0.466 and 0.311
    m1, m2 = r3(15 / 32.2), r3(10 / 32.2)
    v_B2 = (m1 * 19.657 + m1 * 0.3 * 19.657) / (m1 + m2)
    exact = (15 * 19.657 + 15 * 0.3 * 19.657) / 25
    assert abs(v_B2 - exact) > 0.0015  # off by more than the last digit at 4 figures
    item = one("hibbeler-15-58-suitcases", "v_B2", f"{v_B2:.3f} ft/s")
    assert item.status == "correct" and "rounded intermediates" in item.message, item.message


# ------------------------------------------------------------------ students' notation


@pytest.mark.parametrize(
    "written",
    ["5*sin(37.6 deg)", "5*sin(37.6°)", "5 sin 37.6°", "5 sin(37.6 deg)", "5·sin(37.6°)"],
)
def test_degree_marks_in_a_formula(written: str) -> None:
    item = one(C11, "v_A2t", written)
    assert item.status == "correct", item.message  # 5 sin 37.6°, the notes' (1)


def test_degree_marks_and_implicit_products_in_equations() -> None:
    report = derive.check(
        solved(C11),
        None,
        equations=["3: 20 v_A2n + 5 v_B2n = 19.8", "4: 0.6(5 cos 37.6° + 15 cos 37.6°) = v_B2n − v_A2n"],
    )
    assert [i.status for i in report.items] == ["correct", "correct"], report.text()


def test_a_bad_formula_still_names_what_was_written() -> None:
    with pytest.raises(derive.InputError, match=r"\[answers\] v_A2t|answers\[v_A2t\]"):
        one(C11, "v_A2t", "5*sin(37.6 dg)")


# ------------------------------------------------------------------ one bad item


def test_one_bad_item_does_not_lose_the_report() -> None:
    report = derive.check(solved(C11), {"v_A2n": "-1.11", "v_A2t": "5*sin(37.6 dg)", "v_B2n": "8.40 m/s"})
    assert [i.status for i in report.items] == ["correct", "error", "correct"]
    bad = report.items[1]
    assert "v_A2t" in bad.message and "dg" in bad.message
    assert report.exit_code == 2 and not report.all_correct
    data = json.loads(report.render("json"))
    assert data["counts"] == {"correct": 2, "wrong": 0, "unit mismatch": 0, "error": 1}
    assert "1 could not be read" in report.render("text")


def test_a_bad_equation_among_good_answers() -> None:
    report = derive.check(solved(C11), {"v_A2n": "-1.11"}, equations={"3": "20*v_A2n + 5*v_B2n"})
    assert [i.status for i in report.items] == ["correct", "error"]
    assert "exactly one '='" in report.items[1].message


def test_cli_prints_the_report_and_names_the_bad_item(cli) -> None:
    r = cli("check", C11, "--answer", "v_A2n=-1.11", "--answer", "v_A2t=5*sin(37.6 dg)")
    assert r.code == 2
    assert "✓" in r.out and "could not be read" in r.out
    assert r.err.startswith("Error: --answer v_A2t: ") and r.err.count("\n") == 1


def test_everything_bad_is_still_an_input_error(cli) -> None:
    r = cli("check", C11, "--answer", "v_A2t=5*sin(37.6 dg)")
    assert r.code == 2 and r.out == "" and r.err.startswith("Error: --answer v_A2t")


# ------------------------------------------------------------------ the mistakes' registry


def test_the_registry_is_a_table_of_kinds_in_report_order() -> None:
    assert list(mistakes.REGISTRY) == [m.name for m in mistakes.KINDS]
    assert list(mistakes.REGISTRY)[:3] == ["b_sign", "restitution_reversed", "e_speeds"]
    assert mistakes.phrase("e_on_t+system_t") == (
        mistakes.REGISTRY["e_on_t"].phrase + " and " + mistakes.REGISTRY["system_t"].phrase
    )


def test_a_mistake_built_on_another() -> None:
    # B's velocity negated after sin and cos are swapped: v_B1n = +15 sin 37.6°
    model = mistakes.model(solved(C11))
    both = mistakes.combine(mistakes.REGISTRY["sin_cos_swapped"], mistakes.REGISTRY["b_sign"])
    out = model.outcome(both.build(model), both)
    sA, sB = vA * math.sin(th), vB * math.sin(th)  # the swapped n components, B's sign flipped
    a, b = n_solve(mA * sA + mB * sB, e * (sA - sB))
    assert float(out.results["v_A2n"].value) == pytest.approx(a, rel=1e-12)
    assert float(out.results["v_B2n"].value) == pytest.approx(b, rel=1e-12)


def test_a_new_kind_of_mistake_is_one_decorated_function() -> None:
    # BYJU'S: 4 kg at 12 m/s behind 8 kg at 4 m/s, e = 0.5; with e halved, by hand
    v_A2 = (4 * 12 + 8 * 4 - 8 * 0.25 * (12 - 4)) / 12
    try:

        @mistakes.mistake("e_halved", "e halved", "e was taken as half its value.", (4,), "the impact rule", "halves e")
        def e_halved(model: mistakes.Model) -> mistakes.Variant:
            return mistakes.Variant(e=model.e / 2)

        assert list(mistakes.REGISTRY)[-1] == "e_halved"
        solution = derive.solve(derive.load("byjus-4kg-ball-catches-8kg-ball"))  # its own cache
        item = derive.check(solution, {"v_A2": sig(v_A2, 4)}).items[0]
        assert item.status == "wrong" and "e_halved" in [d.mistake for d in item.diagnosis], item.message
    finally:
        mistakes.REGISTRY.pop("e_halved", None)


def test_a_files_own_condition_is_kept_by_the_mistakes(problem_from) -> None:
    # 2 kg at 3 m/s onto 1 kg at rest, e unknown, a quarter of the energy lost: by hand
    # 2a + b = 6 and a^2 + b^2/2 = 3/4 * 9 give (a, b) = (1.5, 3) with e = 0.5, or (2.5, 1):
    # the root of the reversed impact rule 3e = a - b, with e = 0.5 again
    problem = problem_from(
        """
        title = "A quarter of the energy lost"
        kind = "direct"
        equations = ["T_2 = 3/4*T_1"]
        [given]
        m_A = "2 kg"
        m_B = "1 kg"
        v_A1 = "3 m/s"
        v_B1 = 0
        e = "?"
        """
    )
    solution = derive.solve(problem)
    report = derive.check(solution, {"e": "0.5", "v_A2": "1.5", "v_B2": "1.0"}, equations={"3": "2 v_A2 + v_B2 = 6"})
    assert [i.status for i in report.items] == ["correct", "correct", "wrong", "correct"], report.text()
    assert [d.mistake for d in report.items[2].diagnosis] == ["restitution_reversed"]
