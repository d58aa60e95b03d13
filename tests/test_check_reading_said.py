"""Lines of older batches' habits read as a teacher reads them (issue #31, fifth session, fixH):
the equation a relation comes from written before it, a way in words after a mass or a weight,
braceless fractions of letters, lines a teacher does not mark.

Values worked by hand. OCR M2 2006 (2 kg at 5 m/s, 1 kg at 5 m/s toward it, e = 0.8):
2(5) + 1(-5) = 5 = 2x + y, y - x = 0.8(10) = 8, so y = x + 8, 3x + 8 = 5, x = -1, y = 7.
Edexcel M2 2003 (P 2m at u hits Q m at rest, e = 1/3): 2x + y = 2u, y - x = eu = u/3.
AQA M3 2007 (A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward A).
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses, lines

SPHERES = "ocr-m2-2006-spheres-meet-at-5-ke-lost"
TWO_M = "edexcel-m2-2003-january-q6-2m-hits-m-e-one-third"


# --- the equation a relation comes from, before it ------------------------------------------
@pytest.mark.parametrize(
    "line",
    ["From (2) y = x + 8, sub into (1)", "using eqn 2 y = x + 8", "from (ii) y = x + 8", "by (2): y = x + 8"],
)
def test_the_equation_a_relation_comes_from_is_no_factor_of_it(line: str) -> None:
    # "(2) y" is not 2 times y: read so, y = x + 8 was a false algebra slip
    work = f"2(5) + 1(-5) = 2x + y   ...(1)\ny - x = 0.8(5 + 5) = 8   ...(2)\n{line}\n3x + 8 = 5\nx = -1, y = 7\n"
    assert line_statuses(SPHERES, work) == ["correct"] * 5


def test_a_roman_tag_after_into_is_where_the_relation_goes() -> None:
    work = "2x + y = 2u   ...(i)\ny - x = eu   ...(ii)\nfrom (ii) x = y - eu, into (i):\n"
    assert line_statuses(TWO_M, work) == ["correct"] * 3


# --- a way in words after a mass or a weight ---------------------------------------------------
@pytest.mark.parametrize(
    "line",
    [
        "Given: m_A = 0.3 kg moving right at 3 m/s, m_B = 0.2 kg moving left at 2 m/s",
        "m_B = 0.2 kg travelling to the left",
    ],
)
def test_a_way_said_after_a_mass_is_the_bodys_velocitys_not_the_masss(line: str) -> None:
    # "m_B = 0.2 kg moving left": the mass is 0.2 kg, not -0.2 (was a false arithmetic slip)
    assert "wrong" not in line_statuses("aqa-m3-2007-spheres-approach-head-on", line + "\n")


# --- a given's velocity restated with the convention's sign, in a name a chain has for another ---
@pytest.mark.parametrize(
    "line",
    ["(a) Taking A's way as positive: u_B = -2", "Take right as positive, u_B = -2, u_A = 3", "u_B = -2 (A's way +ve)"],
)
def test_a_given_restated_with_the_conventions_sign_is_not_judged(line: str) -> None:
    # AQA M3 2007 as a chain: B at 2 m/s toward A, so -2 with A's way positive (the student's u_B,
    # B's velocity before); the chain's u_B is B's velocity after the first impact (3.4, mark
    # scheme). A teacher does not mark the restated given: never a slip.
    assert "wrong" not in line_statuses("chain-aqa-m3-2007-collide-again", line + "\n")


# --- a speed said in a sentence, with the same speed in another unit after it ----------------
BULLET = "chain-msu-bullet-block-swings"  # 0.020 kg at 300 m/s into 4.0 kg: V = 6/4.02 = 1.4925 m/s


@pytest.mark.parametrize(
    "line",
    [
        "so the block is moving at about 1.49 m/s (≈ 5.37 km/h) just after",
        "Therefore the block was travelling at 1.49 m/s (= 5.4 km/h).",
        r"so the block was doing about $1.49$ m/s ($\approx 5.4$ km/h)",
    ],
)
def test_a_speed_said_by_a_verb_of_motion_is_judged_as_that_speed(line: str) -> None:
    work = f"0.020(300) = 4.02 V\nV = 1.493 m/s\n{line}\n"
    assert line_statuses(BULLET, work) == ["correct"] * 3
    # after a slip (V doubled: 2.985), the same sentence with the student's number is carried
    work = f"0.020(300) = 4.02 V\nV = 2.985 m/s\n{line.replace('1.49', '2.99')}\n"
    assert line_statuses(BULLET, work)[2] == "carried"


def test_a_speed_said_in_a_sentence_without_a_relations_sign_is_prose() -> None:
    # "(~5.4 km/h)": no = and no ≈ on the line, a teacher does not mark it; never a slip
    work = "0.020(300) = 4.02 V\nV = 2.985 m/s\nso the block was moving at 2.99 m/s (~10.7 km/h)\n"
    assert len(line_statuses(BULLET, work)) == 2


# --- the momentum before or after said in words, as a side of its own -------------------------
@pytest.mark.parametrize("said", ["momentum", "Total momentum", "system momentum"])
def test_the_momentum_after_in_words_is_the_two_bodies_momentum(said: str) -> None:
    # AQA M3 2007: 0.3(3) + 0.2(-2) = 0.5 before; after, A at -0.6 (mark scheme) and B at v:
    # -0.18 + 0.2v = 0.5, v = 3.4. The line after, in letters, is true whatever v is found to be.
    work = (
        f"{said} before = 0.3(3) + 0.2(-2) = 0.5\n{said} after = 0.3(-0.6) + 0.2v\n0.5 = -0.18 + 0.2v\nv = 3.4\n"
        f"{said} before = {said} after\n"
    )
    assert line_statuses("aqa-m3-2007-spheres-approach-head-on", work) == ["correct"] * 5


def test_the_momentum_after_in_words_with_a_wrong_sign_is_wrong() -> None:
    # A's -0.6 taken as +0.6: 0.18 + 0.68 = 0.86, not the 0.5 there is after (its arithmetic is right)
    work = "momentum after = 0.3(0.6) + 0.2(3.4) = 0.86\n"
    assert line_statuses("aqa-m3-2007-spheres-approach-head-on", work) == ["wrong"]


# --- a value in letters said again in brackets, rounded -------------------------------------
@pytest.mark.parametrize("again", ["(18.1m J)", "(≈ 18.1m J)", "(18.14m J)"])
def test_a_value_in_letters_said_again_rounded_is_no_factor(again: str) -> None:
    # OCR M2 2014 (2m at 4, 3m at 2 toward it, e = 0.4): a = -1.04, b = 1.36; KE before 16m + 6m = 22m,
    # after m(1.0816) + 1.5m(1.8496) = 3.856m, lost 18.144m (the reduced mass: ½(1.2m)(0.84)(36)).
    work = f"KE before = 1/2(2m)(4^2) + 1/2(3m)(2^2) = 22m\nKE lost = 22m - 3.856m = 18.144m J  {again}\n"
    assert line_statuses("ocr-m2-2014-particles-2m-3m-ke-lost", work) == ["correct", "correct"]


# --- a body said before a side in numbers, after a label ----------------------------------------
def test_a_body_said_before_its_working_is_no_name() -> None:
    # AQA M3 2007: v_A = -0.6, v_B = 3.4 (mark scheme); the impulse on B 0.2(3.4 + 2) = 1.08 N s,
    # on A 0.3(3 + 0.6) = 1.08 N s: equal and opposite, the student's check
    work = r"Check with the impulses: on B $0.2 \times 5.4 = 1.08$ N s, on A $0.3 \times 3.6 = 1.08$ N s ✓" + "\n"
    assert set(line_statuses("aqa-m3-2007-spheres-approach-head-on", work)) == {"correct"}


# --- a remark in brackets that starts with "with" ----------------------------------------------
@pytest.mark.parametrize("remark", ["(with v_A = -0.6 it is the same)", "(with v_B = 3.40 it's 1.21 J again)"])
def test_a_bracketed_remark_with_a_value_leaves_the_relation_whole(remark: str) -> None:
    # AQA M3 2007: v_A = -0.6, v_B = 3.4; KE after = ½(0.3)(0.36) + ½(0.2)(11.56) = 0.054 + 1.156 = 1.21 J
    work = f"KE after = 1/2(0.3)(0.6)^2 + 1/2(0.2)(3.4)^2 = 1.21 J  {remark}\n"
    assert set(line_statuses("aqa-m3-2007-spheres-approach-head-on", work)) == {"correct"}


# --- the conservation of momentum stated as sums, before the working --------------------------
@pytest.mark.parametrize(
    "law",
    [r"$\sum m u = \sum m v$", "Σmv_i = Σmv_f", r"\[ \Sigma p_1 = \Sigma p_2 \]", "sum m v_before = sum m v_after"],
)
def test_the_momentum_principle_stated_as_sums_is_right(law: str) -> None:
    # the method a teacher marks right, then the working: AQA M3 2007, 0.3(3) + 0.2(-2) = 0.5
    work = f"{law}\n0.3(3) + 0.2(-2) = 0.3 v_A + 0.2 v_B\n"
    assert line_statuses("aqa-m3-2007-spheres-approach-head-on", work) == ["correct", "correct"]


# --- a component across labelled in words, and a remark after a dash ------------------------
OFFSET = "ocr-mei-fmm-2022-offset-spheres-symbolic"  # A along x, B's centre r off A's path, centres 2r apart


@pytest.mark.parametrize("tail", [" — unchanged by the impact", ", unchanged (smooth)", " – constant"])
def test_a_component_across_with_sin_and_cos_swapped_is_named(tail: str) -> None:
    # sin θ = r/2r: θ = 30° between A's path and the line of centres; along it U cos 30° = (√3/2)U,
    # across it U sin 30° = U/2 (derive's t points the other way: -U/2, the student's a size).
    work = f"along the line of centres: $U\\cos30° = \\tfrac{{\\sqrt3}}{{2}}U$\nperpendicular: $U\\sin30° = \\tfrac12 U${tail}\n"
    assert line_statuses(OFFSET, work) == ["correct", "correct"]
    work = f"along the line of centres: $U\\cos30° = \\tfrac{{\\sqrt3}}{{2}}U$\nperpendicular: $U\\cos30° = \\tfrac{{\\sqrt3}}{{2}}U${tail}\n"
    assert lines(OFFSET, work)[2][:2] == ("wrong", "sin_cos_swapped")


# --- an angle after declared by its verb, and a number added to it in degrees -------------------
AQA_30 = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"  # equal spheres, B at rest, 30°


@pytest.mark.parametrize("verb", ["A now moves", "A then travels", "The sphere A then goes"])
def test_an_angle_after_declared_by_a_verb_of_motion_and_a_sum_in_degrees(verb: str) -> None:
    # along the line of centres after: x = (√3/4)u(1 - e) (mark scheme); across, u sin 30° = u/2
    # unchanged; tan b = (u/2)/x = 2/(√3(1 - e)); A turns through d = b - 30°, tan d = tan(b - 30°)
    work = (
        f"x = (sqrt3/4) u (1 - e)\n{verb} at angle b to the line of centres, where\n"
        "tan b = (u/2)/x = 2/(sqrt3 (1 - e))\nA is deflected through d = b - 30\n"
        "tan d = (tan b - tan 30)/(1 + tan b tan 30)\n"
    )
    assert line_statuses(AQA_30, work) == ["correct"] * 4
    assert line_statuses(AQA_30, work.replace("b - tan 30)/(1 +", "b + tan 30)/(1 -"))[-1] == "wrong"


@pytest.mark.parametrize(("worked", "verdict"), [("2m", "correct"), ("3m", "wrong")])
def test_the_momentum_law_as_sums_with_its_value_after_is_judged(worked: str, verdict: str) -> None:
    # OCR M2 2014: 2m at 4, 3m at -2. Σmu = 2m(4) + 3m(-2) = 2m; after, 2m(-1.04) + 3m(1.36) = 2m too.
    work = f"8m - 6m = 2m v_A2 + 3m v_B2\nΣmu = Σmv = {worked}\n"
    assert line_statuses("ocr-m2-2014-particles-2m-3m-ke-lost", work)[-1] == verdict


def test_a_given_restated_with_another_bodys_speed_is_judged() -> None:
    # AQA M3 2007: B moves at 2 m/s (A at 3 m/s). "u_B = -3" restates no speed of B's: it is A's 3 m/s
    # copied for B, a slip a teacher marks, not a restated given left unjudged.
    found = line_statuses("chain-aqa-m3-2007-collide-again", "Taking right as positive: u_B = -3\n")
    assert found == ["wrong"]
