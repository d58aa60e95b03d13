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


@pytest.mark.parametrize(
    ("work", "wrong"),
    [
        ("v_A2 = -4 m/s\nv_B2 = -8 m/s", {"1", "2"}),  # no words, no given: the answers alone never turn the frame
        ("Momentum: 4(12) + 8(4) = 80\n80 = 4(-4) + 8(-8)\nv_A2 = -4 m/s\nv_B2 = -8 m/s", {"2", "3", "4"}),
        ("v_A1 = 12, v_B1 = 4\nv_A2 = -4\nv_B2 = -8", {"2", "3"}),  # A's +12 fixes derive's frame
        ("v_A1 = -12, v_B1 = 4\nv_A2 = -4\nv_B2 = -8", {"1", "2", "3"}),  # the givens disagree: derive's frame
    ],
)
def test_the_answers_alone_never_choose_a_reversed_frame(work: str, wrong: set) -> None:
    # true: v_A2 = 4, v_B2 = 8 along the way both move (12a = 48 above)
    seen = by_line(CATCH, work)
    assert {k for k, v in seen.items() if v == "wrong"} == wrong, seen


def test_a_given_written_reversed_turns_derives_names() -> None:
    all_correct(CATCH, "v_A1 = -12, v_B1 = -4\nv_A2 = -4\nv_B2 = -8")


# ------------------------------------------------- names never seen, read from the relations


@pytest.mark.parametrize(
    ("work", "said"),
    [
        ("4(12) + 8(4) = 4P + 8Q\nQ - P = 0.5(12 - 4)\nQ = P + 4\n80 = 12P + 32\nP = 4\nQ = 8", "P is v_A2"),
        ("4(12) + 8(4) = 4V1 + 8V2\nV2 - V1 = 0.5(12 - 4) = 4\nV1 = 4, V2 = 8", "V_1 is v_A2"),
        ("4(12) + 8(4) = 4w1 + 8w2\nw2 - w1 = 0.5(12 - 4) = 4\nw1 = 4\nw2 = 8", "w_1 is v_A2"),
        ("4(12) + 8(4) = 4α + 8β\nβ − α = 0.5(12 − 4)\nα = 4 m/s\nβ = 8 m/s", "alpha is v_A2"),
        ("4(12) + 8(4) = 4 s + 8 q\nq - s = 4\ns = 4, q = 8", "s is v_A2"),
    ],
)
def test_two_names_of_the_students_own_read_as_the_velocities_after(work: str, said: str) -> None:
    report = derive.check(derive.solve(derive.load(CATCH)), derivation=work)
    assert any(said in n for n in report.notes), report.notes
    all_correct(CATCH, work)


@pytest.mark.parametrize(
    "work",
    [
        "P = 4\nQ = -e P = -1.6",  # P before, Q after: not A's and B's (there is no B to move)
        "Taking the direction towards the wall as positive, V1 = 4 and V2 = -e V1 = -1.6 m/s",
        "w = 0.4 × 4 = 1.6 m/s\nKE lost = ½(2)(4²) − ½(2)(1.6²) = 16 − 2.56 = 13.44 J",
        "Q = 0.4(4) = 1.6\nloss = 0.5(2)(16) - 0.5(2)(Q^2) = 13.44",
    ],
)
def test_names_at_a_wall_are_the_balls_before_and_after(work: str) -> None:
    all_correct(WALL, work)


@pytest.mark.parametrize(
    ("problem", "work"),
    [
        (WALL, "vel_after = -1.6\nKE_lost = 0.5(2)(4^2 - vel_after^2) = 13.44"),
        (WALL, "velA_after = -0.4(4) = -1.6"),
        (WALL, "v_rebound = 0.4 * 4 = 1.6\nloss = 0.5*2*4^2 - 0.5*2*v_rebound^2 = 13.44"),
        (
            CATCH,
            "momentum: 4*12 + 8*4 = 4*vel_after_A + 8*vel_after_B\n"
            "restitution: vel_after_B - vel_after_A = 0.5*(12 - 4)\nvel_after_A = 4\nvel_after_B = 8",
        ),
    ],
)
def test_names_in_words_joined_by_underscores(problem: str, work: str) -> None:
    all_correct(problem, work)


def test_a_name_nothing_settles_is_not_read_never_wrong() -> None:
    assert by_line(WALL, "rebound_speed = 1.6") == {"1": "not read"}


@pytest.mark.parametrize(
    "work",
    [
        "Left positive.\nu1 = -12, u2 = -4\n-48 - 32 = 4 v1 + 8 v2\nv2 - v1 = -0.5(-4 + 12) = -4\nv1 = -4, v2 = -8",
        "Taking the direction from B to A along the line of centres as positive:\nu_A = -12, u_B = -4\n"
        "4(-12) + 8(-4) = 4x + 8y\ny - x = -0.5(-4 - (-12))\nx = -4\ny = -8",
    ],
)
def test_habitual_and_own_names_in_a_reversed_frame(work: str) -> None:
    all_correct(CATCH, work)


def test_speed_of_approach_in_words_is_not_a_speed_of_a() -> None:
    # "speed of approach" once read as "speed of A" + "pproach"
    all_correct(WALL, "v = -1.6 m/s\ne = speed of separation / speed of approach = 1.6/4 = 0.4")


# ------------------------------------------------- axes placed in words

CUSHION = "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta"  # U at α to the cushion, e₁: tan β = e₁ tan α


@pytest.mark.parametrize(
    "axes",
    [
        "Take i along the cushion and j away from the cushion.",
        r"Unit vectors: $\hat{\imath}$ parallel to DC (the cushion), $\hat{\jmath}$ pointing out of the cushion.",
        r"$\mathbf{i}$ along the cushion; $\mathbf{j}$ perpendicular to it, away from the cushion.",
    ],
)
def test_unit_vectors_placed_in_words_at_a_cushion(axes: str) -> None:
    # i along the cushion (derive's t), j away from it (-n): u = U cos α i - U sin α j,
    # v = U cos α i + e₁ U sin α j (the part across reversed and times e₁)
    work = "\n".join(
        [
            axes,
            r"$$\mathbf{u} = U\cos\alpha\,\mathbf{i} - U\sin\alpha\,\mathbf{j}$$",
            r"$$\mathbf{v} = U\cos\alpha\,\mathbf{i} + e_1 U\sin\alpha\,\mathbf{j}$$",
            r"$$\tan\beta = \frac{e_1 U\sin\alpha}{U\cos\alpha} = e_1\tan\alpha$$",
        ]
    )
    report = derive.check(derive.solve(derive.load(CUSHION)), derivation=work)
    assert any("axes" in n for n in report.notes), report.notes
    all_correct(CUSHION, work)


def test_unit_vectors_placed_in_words_and_a_slip_across() -> None:
    # j away from the cushion: after the impact the j part is +e₁ U sin α; -e₁ U sin α is a slip
    work = "Take i along the cushion and j away from the cushion.\nu = U cos α i - U sin α j\nv = U cos α i - e_1 U sin α j"
    seen = by_line(CUSHION, work)
    assert seen["2"] == "correct" and seen["3"] == "wrong", seen


@pytest.mark.parametrize(
    ("text", "axes"),
    [
        ("Wall along i, j pointing away from the wall.", {"n": ("t", 1), "t": ("n", -1)}),
        ("x-axis parallel to the cushion, y-axis into the cushion", {"n": ("t", 1), "t": ("n", 1)}),
        ("I take the y axis along the line of centres", {"t": ("n", 1), "n": ("t", 1)}),
        ("i along the line of centres, j perpendicular to it", {}),  # derive's own
        ("v = 3i + 4j", {}),
        # a letter not named as an axis: x for "times", a part (i)
        ("v_x = 1 x 19.8 = 19.8 m/s, so the ball moves away from the wall", {}),
        ("(i) The ball bounces away from the wall:", {}),
        ("v = 0.5 x 6 = 3, away from the cushion", {}),
        ("Take x along the wall, y out of the wall.", {"n": ("t", 1), "t": ("n", -1)}),
        ("x direction parallel to the cushion; y direction away from the cushion", {"n": ("t", 1), "t": ("n", -1)}),
    ],
)
def test_axes_placed_in_words(text: str, axes: dict) -> None:
    from derive.checking.frames import declared_axes

    assert declared_axes(text) == axes


# ------------------------------------------------- conventions said in words


@pytest.mark.parametrize(
    ("words", "sign"),
    [
        ("taking the initial direction of motion of A as positive", 1),
        ("taking the original direction of the ball as positive", 1),
        ("taking the direction of approach as positive", 1),
        ("positive towards B", 1),
        ("positive: towards A", -1),
        ("positive in the direction the ball rebounds", -1),
        ("positive direction: from the wall", -1),
        ("out from the wall is positive", -1),
        ("I take the direction towards the wall as positive, so after the rebound v = -1.6", 1),
        ("positive towards a wall", 0),  # "a", not the body A: left to the values
        ("to the left (B's original direction) as positive", -1),
        ("A’s original direction is positive", 1),
        ("to the left (Q's original direction) as positive", 0),  # a letter of the exam's: left to the values
        # the way the clause makes positive, not any word in it
        ("Taking the ball's direction before the rebound as positive.", 1),
        ("positive towards the wall until it bounces back", 1),
        ("taking the sphere's direction of motion before the impact as positive", 1),
        ("taking the direction of B before the collision as positive", -1),
        ("positive in the original direction of motion of B", -1),
        ("positive is to A's right", 0),  # A's right: left or right, to the values
        ("left is positive (from the ground)", 0),  # a point of view, not away from the ground
        ("right is positive as seen from the bank", 0),
        # the way a body was going, in any tense
        ("positive in the direction A was moving", 1),
        ("positive = direction A was heading", 1),
        ("the direction in which B was travelling is positive", -1),
        ("taking the way B moves as +ve", -1),
        ("positive in the direction a ball was moving", 0),  # "a", not the body A
    ],
)
def test_a_convention_said_in_words(words: str, sign: int) -> None:
    from derive.checking.conventions import sign_of

    assert sign_of(words) == sign


@pytest.mark.parametrize(
    "work",
    [
        "positive: the direction of the rebound\nv_A1 = -4\nv_A2 = 1.6",
        "I take the original direction of the ball as positive, so after the rebound v_A2 = -0.4(4) = -1.6",
        # the way before the rebound is the first way: after it the ball moves at -0.4(4)
        "Taking the ball's direction before the rebound as positive.\nu = 4 m/s\nv = -0.4 x 4 = -1.6 m/s",
        "Positive: the way the ball moves before it hits the wall.\nv_A1 = 4\nv_A2 = -0.4(4) = -1.6",
    ],
)
def test_derives_names_with_a_convention_said_in_words(work: str) -> None:
    all_correct(WALL, work)


def test_another_bodys_original_direction_is_not_the_first_bodys() -> None:
    # CIE 9231 Nov 2014 (2m at 4u meets m at 3u head-on). Left (B's way) positive: before -4u and
    # +3u; -5u = 2x + y and x - y = 7eu give x = -(5 - 7e)u/3, y = -(5 + 14e)u/3, which are
    # (5 - 7e)u/3 and (5 + 14e)u/3 to the right, the mark scheme's v_A and v_B.
    lead = (
        "to the left (B's original direction) as positive. Let x and y be A's and B's velocities after, to the left.\n"
    )
    work = "2m(-4u) + m(3u) = 2mx + my\n-5u = 2x + y\nx - y = e(3u - (-4u)) = 7eu\n3x = 7eu - 5u\nx = -(5 - 7e)u/3\n"
    all_correct(
        "cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses",
        lead.replace("to the", "I take the direction to the") + work,
    )


def test_a_sign_slip_under_a_convention_said_in_words() -> None:
    # rebound direction positive: the ball arrives at -4 and leaves at +1.6; -1.6 is a slip
    seen = by_line(WALL, "positive: the direction of the rebound\nv_A1 = -4\nv_A2 = -1.6")
    assert seen == {"2": "correct", "3": "wrong"}, seen


@pytest.mark.parametrize(
    "after",
    [
        "(i) Away from the wall:\nv_x = -1(19.8) = -19.8 m/s",  # x toward the wall: -19.8 after
        "v_x = 1 x 19.8 = 19.8 m/s, so the ball moves away from the wall",  # a size with its way in words
    ],
)
def test_a_times_x_or_a_part_label_places_no_axis(after: str) -> None:
    # Giancoli 7-18: 28 m/s at 45° to the normal, e = 1: 28 cos 45 = 28 sin 45 = 19.8 m/s each way,
    # the part across reversed (19.8 toward the wall before, 19.8 away after), the part along kept
    work = f"u_x = 28 cos 45 = 19.8 m/s\nu_y = 28 sin 45 = 19.8 m/s\n{after}"
    seen = by_line("giancoli-7-18-tennis-ball-wall-45deg", work)
    assert "wrong" not in seen.values() and seen[max(seen, key=int)] == "correct", seen


def test_components_named_on_axes_placed_in_words() -> None:
    # x along the cushion (derive's t), y away from it (-n): u_y = -U sin α before, v_y = +e₁ U sin α after
    lead = "Take x along the cushion and y away from the cushion.\nu_x = U cos α, u_y = -U sin α\n"
    all_correct(CUSHION, lead + "v_x = U cos α, v_y = e_1 U sin α\ntan β = v_y/v_x = e_1 tan α")
    report = derive.check(derive.solve(derive.load(CUSHION)), derivation=lead)
    assert any("u_y as -v_A1n" in n for n in report.notes), report.notes
    seen = by_line(CUSHION, lead + "v_x = U cos α, v_y = -e_1 U sin α")
    assert seen == {"2": "correct", "3": "wrong"}, seen


# ------------------------------------------------- a slip stays a slip: the reading is grounded
# on the givens as written and the natural order of names, never on what makes a slip vanish.
# Worked by hand:
# - BYJU'S (above): 4(12) + 8(4) = 80 = 4a + 8b, b - a = 0.5(12 - 4) = 4: a = 4, b = 8. With the
#   law upside down (a - b = 4): 80 = 4(b + 4) + 8b, b = 16/3 = 5.33, a = 9.33.
# - Edexcel M2 2004 (2m at 5u hits 3m at rest): 10u = 2p + 3q, q - p = 5eu: q = 2(1 + e)u,
#   p = (2 - 3e)u. Upside down (p - q = 5eu): 10u = 5q + 10eu, q = 2u(1 - e), p = (2 + 3e)u.
# - Edexcel M2 2011 (m at 4u hits 3m at rest): 4u = v_A + 3v_B, v_B - v_A = 4eu; with x the
#   speed A rebounds at (x = -v_A): 4u = -x + 3y and y + x = 4eu.
# - CIE 2019 (2m at 2u meets 4m at u head-on): momentum 0 = 2x + 4y, y - x = 3eu: y = eu,
#   x = -2eu. Upside down: x - y = 3eu, -3y = 3eu, y = -eu, x = 2eu.

ED04 = "edexcel-m2-2004-june-q5-2m-at-5u-hits-3m"
ED11 = "edexcel-m2-2011-june-q2-m-at-4u-hits-3m-show-e-gt-third"
ZERO = "cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u"
HEAD_ON = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(("a", "b"), [("x", "y"), ("p", "q"), ("a", "b"), ("V_1", "V_2"), ("v_A", "v_B"), ("v1", "v2")])
def test_a_restitution_law_upside_down_stays_wrong_whatever_the_names(a: str, b: str) -> None:
    work = f"4(12) + 8(4) = 4{a} + 8{b}\n{a} - {b} = 0.5(12 - 4)\n{a} = {b} + 4\n80 = 4({b} + 4) + 8{b}\n"
    work += f"64 = 12{b}\n{b} = 5.33, {a} = 9.33"
    seen = by_line(CATCH, work)
    assert seen["1"] == "correct" and seen["2"] == "wrong", seen
    assert "correct" not in {seen[k] for k in "3456"}, seen


@pytest.mark.parametrize(
    ("momentum", "statuses"),
    [
        ("0.3(3) - 0.2(2) = 0.3x + 0.2y", ["wrong", "correct"]),  # the givens' frame: the law is the slip
        ("0.3(-3) + 0.2(2) = 0.3x + 0.2y", ["correct", "correct"]),  # left positive throughout
    ],
)
def test_a_restitution_law_written_first_grounds_no_frame_the_momentum_after_it_does(momentum, statuses) -> None:
    # AQA M3 2007 (0.3 kg at 3 m/s, 0.2 kg at 2 m/s toward it, e = 0.8): right positive, 0.5 =
    # 0.3x + 0.2y and y - x = 0.8(3 + 2) = 4 give x = -0.6, y = 3.4 (the mark scheme's). The law
    # written first as x - y = 4 is upside down in the givens' frame, which the momentum after it
    # writes (A's +3, B's -2): then 0.5 = 0.3x + 0.2(x - 4), 0.5x = 1.3, x = 2.6, y = -1.4, carried. With left positive (A's -3, B's +2) the same law is right and x = 0.6,
    # y = -3.4 (-0.5 = 0.5x - 0.8).
    left = momentum.startswith("0.3(-3)")
    rest = (
        "-0.5 = 0.3x + 0.2(x - 4)\n0.5x = 0.3\nx = 0.6\ny = -3.4"
        if left
        else ("0.5 = 0.3x + 0.2(x - 4)\n0.5x = 1.3\nx = 2.6\ny = -1.4")
    )
    seen = by_line(HEAD_ON, f"x - y = 0.8(3 + 2) = 4\n{momentum}\n{rest}")
    assert [seen["1"], seen["2"]] == statuses, seen
    later = "correct" if left else "carried"
    assert [seen[k] for k in "3456"] == [later] * 4, seen


def test_a_restitution_law_upside_down_in_letters() -> None:
    work = "10mu = 2mp + 3mq\np - q = 5eu\np = q + 5eu\n10u = 5q + 10eu\nq = 2u(1 - e)\np = 2u - 2eu + 5eu = (2 + 3e)u"
    seen = by_line(ED04, work)
    assert seen == {"1": "correct", "2": "wrong", "3": "carried", "4": "carried", "5": "carried", "6": "carried"}


@pytest.mark.parametrize("lead", ["", "A: 2u ->, B: u <-, -> is +ve. x (A), y (B) after.\n"])
def test_zero_momentum_does_not_turn_the_frame_for_a_slip_after_it(lead: str) -> None:
    # 0 = 2x + 4y holds in either frame: the restitution law after it may not choose one
    work = lead + "2m(2u) - 4mu = 2mx + 4my\n0 = x + 2y\nx - y = 3eu\n-3y = 3eu\ny = -eu\nx = 2eu"
    seen = by_line(ZERO, work)
    k = 1 if lead else 0
    assert [seen[str(i + k)] for i in range(1, 7)] == ["correct", "correct", "wrong"] + ["carried"] * 3, seen


def test_habitual_names_keep_the_frame_of_the_givens_written() -> None:
    work = "4(12) + 8(4) = 4v_A + 8v_B\nv_A - v_B = 0.5(12 - 4)\nv_A = v_B + 4\n80 = 12v_B + 16\nv_B = 5.33\nv_A = 9.33"
    report = derive.check(derive.solve(derive.load(CATCH)), derivation=work)
    assert not any("opposite to derive" in n for n in report.notes), report.notes
    seen = by_line(CATCH, work)
    assert seen["1"] == "correct" and seen["2"] == "wrong", seen


@pytest.mark.parametrize(
    ("work", "seen"),
    [
        ("4mu = -mx + 3my\ny + x = 4eu", {"1": "correct", "2": "correct"}),  # x: the speed A rebounds at
        ("4mu = -mx + 3my\ny - x = 4eu", {"1": "correct", "2": "wrong"}),  # then the law with x's sign lost
    ],
)
def test_a_name_for_a_rebound_speed_is_read_from_its_first_relation(work: str, seen: dict) -> None:
    assert by_line(ED11, work) == seen


@pytest.mark.parametrize(
    ("work", "seen"),
    [
        (
            "4(-12) + 8(-4) = 4x + 8y\ny - x = 0.5(-12 - (-4))\nx = -4, y = -8",
            {"1": "correct", "2": "correct", "3": "correct"},
        ),
        ("4(-12) + 8(-4) = 4x + 8y\nx - y = 0.5(-12 - (-4))", {"1": "correct", "2": "wrong"}),
        ("4(12) + 8(4) = 8x + 4y\ny - x = 0.5(12 - 4)", {"1": "wrong", "2": "correct"}),  # masses swapped: not x for B
    ],
)
def test_the_givens_written_ground_the_frame_of_names_never_seen(work: str, seen: dict) -> None:
    # before written as -12 and -4: left is positive; after -4 and -8 in that frame
    assert by_line(CATCH, work) == seen


@pytest.mark.parametrize("who", ["Q", "B"])
def test_a_convention_in_the_way_a_body_was_going_with_zero_momentum(who: str) -> None:
    # CIE 2019 (above) with B's way positive: before -2u and +u, after x = 2eu and y = -eu; the
    # momentum is 0 either way, so only the words can say the frame
    work = (
        f"Take the direction {who} was moving as positive; x and y are the velocities of A and B after.\n"
        "-2m(2u) + 4mu = 2mx + 4my\n0 = x + 2y\ny - x = e(-2u - u) = -3eu\n3y = -3eu\ny = -eu\nx = 2eu"
    )
    assert set(by_line(ZERO, work).values()) == {"correct"}, by_line(ZERO, work)


@pytest.mark.parametrize(
    ("way", "work", "seen"),
    [
        # CIE 2019 (above) in B's way: before -2u and u, after x = 2eu, y = -eu
        (
            "Q",
            "-2m(2u) + 4mu = 2mx + 4my\n0 = x + 2y\ny - x = e(-2u - u) = -3eu\n3y = -3eu\ny = -eu\nx = 2eu",
            "cccccc",
        ),
        ("P", "2m(2u) - 4mu = 2mx + 4my\n0 = x + 2y\ny - x = 3eu\n3y = 3eu\ny = eu\nx = -2eu", "cccccc"),
        ("P", "2m(2u) - 4mu = 2mx + 4my\n0 = x + 2y\nx - y = 3eu\n-3y = 3eu\ny = -eu\nx = 2eu", "ccwkkk"),
    ],
)
def test_names_declared_in_the_way_a_body_was_moving(way: str, work: str, seen: str) -> None:
    lead = f"x and y are the velocities of P and Q after, both in the direction {way} was moving.\n"
    status = {"c": "correct", "w": "wrong", "k": "carried"}
    assert by_line(ZERO, lead + work) == {str(i + 2): status[s] for i, s in enumerate(seen)}


# AQA M3 2007 Q6(a) (identical balls, B at rest, A at u at 30° to the line of centres), by hand:
# along the line of centres A has u cos 30° = (√3/2)u. x + y = (√3/2)u and y - x = e(√3/2)u give
# y = (√3/4)u(1 + e). The law upside down (x - y = e(√3/2)u): (1) - (2) gives 2y = (√3/2)u(1 - e),
# y = (√3/4)u(1 - e). With equal masses the momentum holds whichever name is A's, and the law
# upside down holds with the names swapped: only the order the names are met in grounds them.
EQUAL = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"


@pytest.mark.parametrize(("a", "b"), [("x", "y"), ("p", "q"), ("a", "b"), ("v_1", "v_2")])
def test_equal_masses_a_law_upside_down_does_not_swap_the_names(a: str, b: str) -> None:
    work = (
        f"m u cos 30° = m{a} + m{b} ⟹ {a} + {b} = (√3/2)u  (1)\n{a} - {b} = e(√3/2)u  (2)\n"
        f"(1) - (2): 2{b} = (√3/2)u - e(√3/2)u\n{b} = (√3/4)u(1 - e)"
    )
    assert by_line(EQUAL, work) == {"1": "correct", "2": "wrong", "3": "carried", "4": "carried"}


@pytest.mark.parametrize(("a", "b"), [("x", "y"), ("a", "b")])
def test_equal_masses_the_law_the_right_way_round_is_correct(a: str, b: str) -> None:
    work = (
        f"m u cos 30° = m{a} + m{b} ⟹ {a} + {b} = (√3/2)u  (1)\n{b} - {a} = e(√3/2)u  (2)\n"
        f"(1) + (2): 2{b} = (√3/2)u + e(√3/2)u\n{b} = (√3/4)u(1 + e)"
    )
    assert set(by_line(EQUAL, work).values()) == {"correct"}, by_line(EQUAL, work)


# OpenStax satellites (A 4000 kg at 0.250 m/s hits B 7500 kg at rest, e = 1), by hand:
# v_A = (4000 - 7500)/11500 x 0.250 = -0.0761 m/s, v_B = 2(4000)/11500 x 0.250 = 0.174 m/s.
# The masses swapped in v_A's formula, (7500 - 4000)/11500 (0.250) = +0.0761, holds only with u
# taken as -0.250, which the student never wrote: the slip, not a frame the other way. With
# -0.250 written for u the frame is the other way, and both lines hold in it.
SATELLITES = "openstax-cp-8-satellites-elastic"
V_B = "v_B = 2m_A/(m_A + m_B) u = 2(4000)/11500 ({u}) = {v} m/s"


@pytest.mark.parametrize(
    ("v_a", "u", "v", "seen"),
    [
        ("(7500 - 4000)/11500 (0.250) = 0.0761", "0.250", "0.174", {"1": "wrong", "2": "correct"}),
        ("(4000 - 7500)/11500 (0.250) = -0.0761", "0.250", "0.174", {"1": "correct", "2": "correct"}),
        ("(4000 - 7500)/11500 (-0.250) = 0.0761", "-0.250", "-0.174", {"1": "correct", "2": "correct"}),
    ],
)
def test_a_frame_the_other_way_only_where_a_velocity_before_is_written_turned(v_a, u, v, seen) -> None:
    work = f"v_A = (m_A - m_B)/(m_A + m_B) u = {v_a} m/s\n" + V_B.format(u=u, v=v)
    assert by_line(SATELLITES, work) == seen


@pytest.mark.parametrize("momentum", ["-0.3(3) + 0.2(2)", "0.2(2) - 0.3 × 3", "-(0.3)(3) + 0.2 × 2"])
def test_a_frame_the_other_way_written_with_a_minus_before_a_product(momentum: str) -> None:
    # AQA M3 2007 (above) with left positive: A's -3 and B's +2 before; after x = 0.6, y = -3.4
    # (the mark scheme's -0.6 and 3.4 turned): -0.9 + 0.4 = -0.5 = 0.18 - 0.68, y - x = 0.8(-3 - 2) = -4
    work = f"{momentum} = 0.3x + 0.2y\ny - x = 0.8(-3 - 2) = -4\nx = 0.6, y = -3.4"
    assert set(by_line(HEAD_ON, work).values()) == {"correct"}, by_line(HEAD_ON, work)
