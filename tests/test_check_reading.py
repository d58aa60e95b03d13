"""Reading a student's correct work as a teacher reads it (issue #31 items 1-3): vectors in i, j
(and ê_n, ê_t, component pairs), names of components by the body's letter, words around the
mathematics, a chain of lines whose middle side is words, conventions declared in prose.

Values worked by hand: OCR M3 June 2007 Q4 (mark scheme: a = -4.5, b = 6, speed of A 12.8 m/s at
111° anticlockwise from i): u_A = 15(0.6)i + 15(0.8)j = 9i + 12j, u_B = -12i; 4a + 3b = 0,
b - a = 0.5(9 + 12) = 10.5. OCR M3 2006 (A at 4 m/s across the line of centres, B at 4 m/s along
it toward A, masses 5 and 2, e = 0.75): 5a + 2b = -8, b - a = 3, a = -2, b = 1; A keeps 4 across,
|v_A| = sqrt(4 + 16) = 4.47, direction 180° - atan(4/2) = 116.6° from x. OCR M2 2014 (2m at 4,
3m at 2 toward each other, e = 0.4): mu = 6m^2/5m = 1.2m, loss = ½(1.2m)(1 - 0.16)(6^2) = 18.144m;
KE before ½(2m)16 + ½(3m)4 = 22m. The cushion (0.240 kg, 3.00 m/s in, 2.40 m/s out): e = 0.8.
"""

from __future__ import annotations

import pytest

import derive
from derive.mathtext.reader import read_relations
from derive.problem.expr import parse


def sides(text: str) -> list[tuple[str, ...]]:
    return [r.sides for r in read_relations(text)]


def report(problem: str, work: str) -> derive.checking.report.CheckReport:
    return derive.check(derive.solve(derive.load(problem)), derivation=work)


def statuses(problem: str, work: str) -> list[str]:
    return [i.status for i in report(problem, work).items]


# --- vectors ----------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("u_A = 15(0.6)i + 15(0.8)j = 9i + 12j", [("u_An", "15(0.6)", "9"), ("u_At", "15(0.8)", "12")]),
        (r"$\mathbf{u}_B = -12\mathbf{i}$", [("u_Bn", "-12"), ("u_Bt", "0")]),
        (r"$\vec v_{A2} = 3.05\,\hat e_t - 1.12\,\hat e_n$ (m/s).", [("v_A2n", "-1.12"), ("v_A2t", "3.05")]),
        (r"$v = 2\hat{\imath} - \hat{\jmath}$", [("v_n", "2"), ("v_t", "-1")]),
        ("After: v_A = ai + 12j", [("v_An", "a"), ("v_At", "12")]),
        ("w = 2.5 e_t − 0.75 e_n", [("w_n", "-0.75"), ("w_t", "2.5")]),  # Unicode's minus
        ("A after = -4.5 i + 12 j", [("A_n'", "-4.5"), ("A_t'", "12")]),
        (r"Before: $A = (0,\; 4)$", [("A_n", "0"), ("A_t", "4")]),
        ("A has components (4 cos 60°, 4 sin 60°) = (2, 2sqrt(3))", [("4 cos 60°", "2"), ("4 sin 60°", "2sqrt(3)")]),
    ],
)
def test_a_vector_relation_is_one_relation_per_component(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    "text",
    ["x = 2pi", "e = (v_B - v_A)/(u_A - u_B)", "theta = atan2(1.11, 3.05)", "5x + 3y = -8", "w = (a)(b)"],
)
def test_what_is_not_a_vector_stays_one_relation(text: str) -> None:
    assert len(sides(text)) == 1


def test_a_derivation_in_i_and_j_is_read_and_correct() -> None:
    work = (
        "i along the line of centres (A to B), j perpendicular.\n"
        "Before: u_A = 15(0.6)i + 15(0.8)j = 9i + 12j,  u_B = -12i\n"
        "After: v_A = ai + 12j, v_B = bi\n"
        "4(9) + 3(-12) = 4a + 3b\n"
        "b - a = 0.5(9 + 12) = 10.5\n"
        "a = -4.5, b = 6\n"
        "A after = -4.5 i + 12 j\n"
        "direction 180° - tan^-1(12/4.5) = 111° anticlockwise from i\n"
    )
    r = report("ocr-m3-2007-oblique-sin-alpha-0p8", work)
    assert [i.status for i in r.items] == ["correct"] * 7, r.text()


# --- names of components, speeds, directions --------------------------------------------
def test_components_named_by_the_body_letter_and_a_prime_for_after() -> None:
    work = (
        "Before: $A = (0, 4)$, $B = (-4, 0)$\n"
        "5(0) + 2(-4) = 5a + 2b\n"
        "b - a = 0.75(0 - (-4)) = 3\n"
        "a = -2, b = 1\n"
        "A_y' = 4\n"
        r"$|v_A| = \sqrt{(-2)^2 + 4^2} = 4.47$" + "\n"
        r"$\text{direction of } A = 180^\circ - \tan^{-1}(4/2) \approx 117^\circ \text{ from } x$" + "\n"
    )
    r = report("ocr-m3-2006-oblique-a-across-centres", work)
    assert [i.status for i in r.items] == ["correct"] * 7, r.text()
    slip = "A_y' = 0.75 * 4 = 3\n"  # e applied across the line of centres: a slip, not "not read"
    assert statuses("ocr-m3-2006-oblique-a-across-centres", slip) == ["wrong"]


def test_a_name_for_a_symbolic_given_is_inferred() -> None:
    # Example 4.C.12: v for the cue ball's speed before (the given v_A1), A_n its n component
    work = "A_n = v sin 45° = 0.7071v\nA_n' + B_n' = 0.7071v\nB_n' - A_n' = 0.9(0.7071v) = 0.6364v\n"
    r = report("notes-4c12-cue-ball", work)
    assert [i.status for i in r.items] == ["correct"] * 3, r.text()
    assert any("v is v_A1" in n for n in r.notes), r.notes


def test_degrees_and_an_inverse_function_add() -> None:
    deg = parse("180*deg - atan(12/4.5)", {"deg": (derive.checking.context.DEG, (0, 0, 0, 0))}).expr
    assert abs(float(deg.subs(derive.checking.context.DEG, 3.141592653589793 / 180)) - 1.92964) < 1e-4


# --- words around the mathematics -------------------------------------------------------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("x = 124° from x", ("x", "124°")),
        ("v = -1.04 m/s (reversed)", ("v", "-1.04")),
        ("fraction kept = 0.6912/1.08 = 0.64, i.e. 64 %", ("fraction kept", "0.6912/1.08", "0.64")),
        ("a = -69.4 degrees to i", ("a", "-69.4 degrees")),
        (r"$\text{angle with the line of centres} = \tan^{-1}(2/3) \approx 33.7^\circ$", ("atan(2/3)", "33.7°")),
        ("v = -0.3 x 4 = -1.2   (so speed 1.2 m/s)", ("v", "-0.3 x 4", "-1.2")),
    ],
)
def test_words_after_the_last_number_and_words_for_a_side(text: str, expected: tuple) -> None:
    assert sides(text) == [expected]


def test_a_speed_at_an_angle_is_two_relations() -> None:
    text = "|v_A| = sqrt(1.108^2 + 3.051^2) = 3.246 m/s at tan^-1(3.051/1.108) = 70.0° to the line of centres"
    assert sides(text) == [("|v_A|", "sqrt(1.108^2 + 3.051^2)", "3.246"), ("tan^-1(3.051/1.108)", "70.0°")]


def test_a_continued_line_after_a_side_in_words_is_judged_from_the_first_side() -> None:
    work = (
        "2vA + 3vB = 2\nvB - vA = 2.4\n"
        "loss = 1/2 mu (1 - e^2) (relative speed)^2\n"
        "     = 1/2 (1.2m)(1 - 0.16)(6^2)\n"
        "     = 18.144m\n"
    )
    r = report("ocr-m2-2014-particles-2m-3m-ke-lost", work)
    lines = {i.name: i.status for i in r.items}
    assert lines["4"] == "correct" and lines["5"] == "correct", r.text()
    assert lines.get("3", "not read") == "not read", r.text()


def test_a_wrong_energy_before_carries_into_the_loss() -> None:
    work = (
        "2vA + 3vB = 2\nvB - vA = 2.4\nvA = -1.04, vB = 1.36\n"
        "KE before = 1/2(2m)(4^2) + 1/2(3m)(2^2) = 16m + 12m = 28m\n"
        "Loss = 28m - 3.856m = 24.144m\n"
    )
    assert statuses("ocr-m2-2014-particles-2m-3m-ke-lost", work) == ["correct"] * 3 + ["wrong", "carried"]


# --- the sign convention declared in prose ----------------------------------------------
@pytest.mark.parametrize(
    ("words", "sign"),
    [
        ("I take the direction away from the wall as positive", -1),
        ("away from the cushion", -1),
        ("taking A's direction as +ve", 1),
        ("from A towards B", 1),
        ("down is positive", 0),
        ("LEFT as positive", 0),
    ],
)
def test_the_sign_a_phrase_states(words: str, sign: int) -> None:
    from derive.checking.naming import sign_of

    assert sign_of(words) == sign


def test_a_convention_in_prose_and_relations_on_the_same_line() -> None:
    work = "Positive = away from the cushion.  u = -3.00, v = +2.40\ne = -v/u = 0.800\n"
    assert statuses("openstax-cp-8-31-billiard-ball-cushion", work) == ["correct", "correct"]


# --- chains ----------------------------------------------------------------------------
# Dropped from 2 m onto the floor, rebounds to 1.4 m (OCR M2 2006): v_1 = sqrt(2 g 2) = 6.261,
# v_2 = sqrt(2 g 1.4) = 5.238, e = 0.8367, J = 0.3(6.261 + 5.238) = 3.450 N s upwards.
DROP = "chain-ocr-m2-2006-drop-rebound"


def test_a_chain_name_in_words_and_a_name_of_the_students_own_are_inferred() -> None:
    work = (
        "taking downwards as positive\n"
        "velocity after = -5.24 m/s (upwards)\n"
        "impulse = m(v - u) = 0.3(-5.24 - 6.26) = -3.45 N s\n"
        "0 = 5.24^2 - 2(9.8)h  =>  h = 1.40\n"
    )
    r = report(DROP, work)
    assert [i.status for i in r.items] == ["correct"] * 3, r.text()
    assert any("velocity after is u" in n and "impulse is -J" in n for n in r.notes), r.notes
    assert statuses(DROP, "velocity after = -5.24\nimpulse = 0.3(-5.24 - 6.26) = -3.15\n") == ["correct", "wrong"]


def test_a_chain_stage_e_and_a_relation_with_an_inequality_after_it() -> None:
    # AQA M3 2007: u_A = -0.6, u_B = 3.4 after the first impact; B meets the wall with e = 0.7
    work = "B hits the wall with e = 0.7\nw_B = -0.7 * 3.4 = -2.38\nw_B = -2.38 < 0 and u_A = -0.6 < 0\n"
    assert statuses("chain-aqa-m3-2007-collide-again", work) == ["correct"] * 3


# --- names read from the lead-in, from a relation, from the shape of the equations -----------
# OCR FM 2023 (discs of 5 and 3 kg; A at 4 m/s at 60° to the line of centres, B at 6 m/s along it
# toward A; e = 3/4): A's components 4 cos 60° = 2 along, 2√3 across; 5x + 3y = -8, y - x = 6.
DISCS = "ocr-fm-2023-oblique-discs-60deg"


def test_a_bodys_lead_in_gives_its_names_the_body() -> None:
    work = "A: u_x = 4cos(60°) = 2, u_y = 4sin(60°) = 2sqrt(3); B: u_x = -6\nB before: along = -6\n"
    r = report(DISCS, work)
    assert [i.status for i in r.items] == ["correct", "correct"], r.text()
    assert statuses(DISCS, "B before: along = -5\n") == ["wrong"]


def test_a_name_set_equal_to_one_of_derives_stands_for_it() -> None:
    # Example 4.C.11 with one t velocity for both spheres (a slip): v_t is read, not "not read"
    work = "20(3.05) + 5(-9.15) = 25 v_t\nv_t = 0.61 = v_A2t = v_B2t\n"
    r = report("notes-4c11-two-spheres", work)
    assert "not read" not in [i.status for i in r.items], r.text()
    assert any("v_t is v_A2t" in n for n in r.notes), r.notes


def test_names_after_a_slip_are_read_by_the_shape_of_their_equations() -> None:
    # sin and cos swapped (A along = 4 sin 60° = 3.46): every x, y line after it is false for
    # the problem, yet 5x + 3y is (3) and y - x is (4) in shape, so x and y are A's and B's
    work = (
        "A before: along = 4 sin 60 = 3.46\n"
        "5(3.46) + 3(-6) = 5x + 3y, so 5x + 3y = -0.7\n"
        "y - x = 0.75(3.46 + 6) = 7.10\n"
        "8x = -0.7 - 21.3 = -22.0\n"
        "x = -2.75, y = 4.35\n"
    )
    r = report(DISCS, work)
    assert [i.status for i in r.items] == ["wrong"] + ["carried"] * 4, r.text()
    assert any("x is v_A2n, y is v_B2n" in n for n in r.notes), r.notes


# --- notation typed with a keyboard's own signs ------------------------------------------------
# Spheres meet head-on at 5 m/s each, 2 kg and 1 kg, e = 0.8: v_A = -1, v_B = 7; KE 37.5 J before,
# 25.5 J after, 12 J lost; the impulse on B is 1(7 + 5) = 12 N s.
MEET = "ocr-m2-2006-spheres-meet-at-5-ke-lost"


@pytest.mark.parametrize(
    "work",
    [
        "2(5) + 1(-5) = 2v₁ + v₂\nv₂ - v₁ = 0.8(5 - (-5)) = 8\n",  # Unicode subscripts
        "2(5) + 1(-5) = 2u_A' + u_B'\nu_A' = -1, u_B' = 7\n",  # primes: after
        "v_A = 5, v_B = -5\nv_B' - v_A' = 0.8(v_A - v_B) = 8\n",  # v_A and v_A': v_A is before
        "V_A = -1, V_B = 7\n",  # capital V after
        "KE lost = ½(2)(5²) + ½(1)(5²) − [½(2)(1²) + ½(1)(7²)] = 37.5 − 25.5 = 12 J\n",  # ½, [ ]
        "Loss in K.E. = 12 J\n",
        "Impulse on B = 1(7 - (-5)) = 12 Ns\nI = 12 N s\n",  # I for the impulse; "on B" is not a name
    ],
)
def test_keyboard_notation_is_read(work: str) -> None:
    r = report(MEET, work)
    assert r.items and all(i.status == "correct" for i in r.items), r.text()


def test_a_function_glued_to_its_angle_and_t_components_named_like_n() -> None:
    # Example 4.C.11 (the notes: 3.96, 3.05, -11.9, -9.15; -1.11 and 8.40 after along n)
    work = (
        "A: 5cos37.6° = 3.96 along n, 5sin37.6° = 3.05 along t\n"
        "20(3.96) + 5(-11.9) = 20v_An + 5v_Bn\n"
        "v_Bn - v_An = 0.6(3.96 + 11.9) = 9.52\n"
        "v_An = -1.11, v_Bn = 8.40\n"
        "v_At = 3.05, v_Bt = -9.15\n"
    )
    r = report("notes-4c11-two-spheres", work)
    assert [i.status for i in r.items] == ["correct"] * 5, r.text()
    assert any("v_At is v_A2t" in n or "v_At as v_A2t" in n for n in r.notes), r.notes  # inferred, or v's habit


# --- more names students give ------------------------------------------------------------------
def test_definitions_after_with_a_common_velocity_v_cm_and_a_as_after() -> None:
    # MEI FMM 2023 (0.5 kg at 6 m/s catches 2 kg at 2 m/s; A moves back at 0.2): v = 3.55,
    # e = 3.75/4 = 0.9375; KE lost = ½ (0.4)(1 - 0.9375²)(4²) = 0.388 J (reduced mass 1/2.5 = 0.4)
    work = (
        "A after = -0.2 m/s\n"
        "0.5(6) + 2(2) = 0.5(-0.2) + 2v  so  v = 3.55\n"
        "e = (3.55 - (-0.2))/(6 - 2) = 0.9375\n"
        "KE lost = 1/2 mu (1 - e^2) w^2 with mu = (0.5 x 2)/2.5 = 0.4 and w = 4 (closing speed)\n"
        "     = 0.2 x (1 - 0.9375^2) x 16 = 0.388 J\n"
    )
    r = report("ocr-mei-fmm-2023-a-speed-0p2-backward", work)
    assert [i.status for i in r.items] == ["correct"] * 5, r.text()
    # satellites 4000 kg at 0.250 m/s and 7500 kg at rest: V_cm = 1000/11500 = 0.08696
    cm = "V_{cm} = (4000(0.250) + 7500(0))/(4000 + 7500) = 0.08696\nv_1' = 2(0.08696) - 0.250 = -0.0761\n"
    assert statuses("openstax-cp-8-satellites-elastic", cm) == ["correct", "correct"]


def test_mu_is_m_times_u_where_m_and_u_are_given_and_a_slow_slip_is_bounded() -> None:
    # CIE 2014: m at u hits 9m at rest, half the KE lost: x + 9y = u, y - x = eu; (1 - 9e)² +
    # 9(1 + e)² = 50 (written 25, a slip): the report comes, in seconds, and x, y are read
    work = "mu = mx + 9my  =>  x + 9y = u\ny - x = eu\nx^2 + 9y^2 = u^2/2\n(1 - 9e)^2 + 9(1 + e)^2 = 25\n"
    r = report("cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost", work)
    assert [i.status for i in r.items] == ["correct"] * 3 + ["wrong"], r.text()


def test_words_after_a_unit_and_v_for_a_common_velocity_after() -> None:
    # goalie 70.0 kg catches a 0.150 kg puck at 35.0 m/s: v = 5.25/70.15 = 0.0748 m/s
    work = "0.150 x 35.0 = (0.150 + 70.0) V\nV = 0.0748 m/s\n91.9 - 0.196 = 91.7 J  ok\n"
    assert statuses("openstax-cp-8-5-goalie-catches-puck", work) == ["correct"] * 3


def test_a_power_of_a_function_is_read() -> None:
    from derive.mathtext.notation import student

    assert student("cos^2(alpha) + 9/16 sin^2 alpha") == "cos(alpha)^2+9/16*sin(alpha)^2"


def test_a_chain_name_no_value_fits_is_what_its_relation_solves_it_to_be() -> None:
    # Edexcel M2, three equal particles: A at 7 m/s hits B at rest; p, q after (no stage result
    # for p); B then hits C and C moves off at 4 m/s: u_B = 2√7 = 5.29 (the chain's values)
    work = "7m = mp + mq  =>  p + q = 7\nq - p = 7e\nq = 5.29\n"
    assert statuses("chain-edexcel-m2-three-particles", work) == ["correct"] * 3


def test_along_in_prose_before_the_mathematics_is_not_a_name() -> None:
    # OCR M3 2013: B at 0.6 m/s at 30° to the line of centres, toward A: -0.6 cos 30° = -0.520
    work = r"B before: along the line $-0.6\cos 30^\circ = -0.520$, across $0.6\sin 30^\circ = 0.3$" + "\n"
    assert statuses("ocr-m3-2013-b-turns-through-right-angle", work) == ["correct"]


def test_a_chain_side_not_read_in_the_middle_is_left_out() -> None:
    # OCR M2 2007: thrown down at 21 m/s from 40 m: v^2 = 21^2 + 2(9.8)(40) = 1225, v = 35 m/s
    work = "v^2 = u^2 + 2as = 21^2 + 2(9.8)(40) = 441 + 784 = 1225\nv = 35 m/s\n"
    assert statuses("chain-ocr-m2-2007-rebounds-to-start", work) == ["correct", "correct"]


# --- a body's quantities in words: possessives ------------------------------------------
@pytest.mark.parametrize(
    ("line", "status"),
    [
        # 4.C.11 (the notes): v_A2 = 3.05 e_t - 1.11 e_n, v_B2 = -9.15 e_t + 8.40 e_n (m/s), so
        # A's speed sqrt(3.05^2 + 1.11^2) = 3.25 and B's sqrt(9.15^2 + 8.40^2) = 12.4
        ("A's speed = 3.25 m/s", "correct"),
        ("B’s speed after = 12.4 m/s", "correct"),
        ("the final speed of B = 12.4 m/s", "correct"),
        ("B's speed = 8.40 m/s", "wrong"),  # B's n component, not its speed
    ],
)
def test_a_bodys_speed_in_words_is_read(line: str, status: str) -> None:
    assert statuses("notes-4c11-two-spheres", line) == [status]


def test_a_bodys_velocity_before_and_after_in_words_is_read(tmp_path) -> None:
    """2 kg at 6 m/s hits 4 kg at rest, e = 0.8: 12 = 2a + 4b, b - a = 4.8, so a = -1.2, b = 3.6."""
    problem = tmp_path / "carts.toml"
    problem.write_text(
        'title = "t"\nkind = "direct"\n[given]\nm_A = "2 kg"\nm_B = "4 kg"\ne = 0.8\nv_A1 = "6 m/s"\nv_B1 = 0\n'
    )
    work = "A's initial velocity = 6 m/s\nA's final velocity = -1.2 m/s\nB's velocity after = 3.6 m/s\n"
    assert statuses(str(problem), work) == ["correct"] * 3
    assert statuses(str(problem), "A's final velocity = 1.2 m/s") == ["wrong"]


# --- notation students type: Greek letters, LaTeX sizing, units, colons, remarks ------------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("APB = 90° so θ + φ = 90°, φ = 90° − θ", [("θ + φ", "90°"), ("φ", "90° − θ")]),  # three points: words
        ("Substituting y = x + 2: 5x + 6 = -4", [("Substituting y", "x + 2"), ("5x + 6", "-4")]),
        ("A: 3cos30 = 2.6,   B: -4", [("3cos30", "2.6")]),  # a body's lead-in after a comma
        ("v_P = -u/3 (v_P = u is before the collision)", [("v_P", "-u/3")]),  # a root turned down
        ("x = 3 or x = -1 (rejected)", [("x", "3")]),  # two roots: the one kept is read, not the rejected one
        ("v_B = 2(1 + e)u (M1 A1)", [("v_B", "2(1 + e)u")]),  # a mark scheme's marks: not a name A1
        ("v = 0.75(4) = 3 (A1ft)(B1)", [("v", "0.75(4)", "3")]),
        ("e^2 = 4/9  =>  e = 2/3   (e > 0)", [("e^2", "4/9"), ("e", "2/3")]),  # a condition after it: a remark
        (r"$b - a = \tfrac25\Bigl(7 - \bigl(-3\bigr)\Bigr) = 4$", [("b - a", "(2/5) (7 - (-3))", "4")]),
    ],
)
def test_greek_letters_colons_labels_remarks_and_sizing_are_read(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    "text",
    [
        "v_B = 3 m s⁻¹",
        "v_B = 3 ms-1",
        "v_B = 3 m s^(-1)",
        "v_B = 3 ms^-1",
        "v_B = 3 m·s⁻¹",
        r"$v_B = 3\ \text{m\,s}^{-1}$",
        r"$v_B = 3\ \mathrm{m\,s^{-1}}$",
        r"$v_B = 3\,\mathrm{m}\cdot\mathrm{s}^{-1}$",
        "v_B = 3 kg m/s",
        "v_B = 3 N·s",
        "v_B = 3 m s−1",  # a Unicode minus
        "v_B = 3 m s -1",
        "v_B = 3 m/sec",
    ],
)
def test_a_unit_typed_any_way_after_a_number_is_taken_off(text: str) -> None:
    assert sides(text) == [("v_B", "3")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("m1 = 22 g, u1 = 3.5 m/s", [("m1", "0.022"), ("u1", "3.5")]),
        (r"$m_A = 20\ \mathrm{Mg} = 20\,000$ kg", [("m_A", "20*1000", "20000")]),
        ("u = 54 km/h", [("u", "54*5/18")]),
        ("u = 54 km h⁻¹", [("u", "54*5/18")]),
    ],
)
def test_a_number_in_a_multiple_of_an_si_unit_is_read_in_the_si_unit(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_masses_in_grams_restated_are_right() -> None:
    # uoguelph superballs (22 g and 27 g): the masses restated in grams are the givens
    assert statuses("uoguelph-8-34-superballs-grams", "m_A = 22 g, m_B = 27 g\n") == ["correct"]
    assert statuses("uoguelph-8-34-superballs-grams", "m_A = 27 g\n") == ["wrong"]


def test_letters_after_a_number_that_are_no_unit_stay() -> None:
    assert sides("v^2 = 2 g h") == [("v^2", "2 g h")]
    assert sides("x = 2s-1") == [("x", "2s-1")]


def test_latex_sizing_bars_and_a_unit_in_text_are_read() -> None:
    # OCR M2 2014: 2m at 4 m/s, 3m at 2 m/s toward it, e = 0.4: 2a + 3b = 2, b - a = 2.4,
    # so 5a = 2 - 7.2, a = -1.04, b = 1.36; A's speed 1.04 m/s
    work = (
        "$2(4) + 3(-2) = 2a + 3b$\n"
        r"$b - a = 0.4\bigl(4 - (-2)\bigr) = 2.4$" + "\n"
        r"$\Rightarrow\ 5a = 2 - 7.2$, so $a = -1.04$, $b = 1.36$" + "\n"
        r"$\lvert a \rvert = 1.04\ \text{m\,s}^{-1}$" + "\n"
    )
    assert statuses("ocr-m2-2014-particles-2m-3m-ke-lost", work) == ["correct"] * 4


def test_an_angle_name_worked_out_to_another_value_is_the_students_own() -> None:
    # 4.C.12 (e = 0.9, θ1 = 45° given as theta_1, equal masses, B at rest): v_A2t = v cos 45°,
    # v_A2n = v sin 45° (1 - e)/2 = 0.05 v sin 45°, so tan θ2 = 0.05 and θ2 = 2.86° from the
    # plane of contact: the student's theta is that angle, not the given 45°
    work = (
        "v_A2t = v_A1 cos 45°\n"
        "v_A2n + v_B2n = v_A1 sin 45°\n"
        "v_B2n - v_A2n = 0.9 v_A1 sin 45°\n"
        "v_A2n = 0.05 v_A1 sin 45°\n"
        "tan theta = v_A2n / v_A2t = 0.05 tan 45° = 0.05\n"
        "θ = 2.86° to the plane of contact\n"
    )
    assert statuses("notes-4c12-cue-ball", work) == ["correct"] * 6


def test_the_same_letter_under_before_and_after_is_two_quantities() -> None:
    # Giancoli 7-18: 28 m/s at 45° to the normal, e = 1: the normal part reverses, the other stays
    work = "Before: x = 28 cos 45°, y = 28 sin 45°\nAfter: x = -28 cos 45°, y = 28 sin 45°\n"
    assert statuses("giancoli-7-18-tennis-ball-wall-45deg", work) == ["correct", "correct"]


# --- names the student introduces ------------------------------------------------------------
def _inverse_carts(tmp_path, given: str) -> str:
    problem = tmp_path / "carts.toml"
    problem.write_text(f'title = "t"\nkind = "direct"\n[given]\n{given}')
    return str(problem)


def test_v_alone_is_the_one_velocity_after_not_given_and_words_are_not_bad_input(tmp_path) -> None:
    # 2 kg at 6 m/s hits 4 kg at rest, B moves off at 3.6 m/s: 12 = 2v + 14.4, v = -1.2; the
    # student works 4(3.6) as 1.44 (a slip): v = (12 - 1.44)/2 = 5.28, carried
    problem = _inverse_carts(
        tmp_path, 'm_A = "2 kg"\nm_B = "4 kg"\ne = "?"\nv_A1 = "6 m/s"\nv_B1 = 0\nv_B2 = "3.6 m/s"\n'
    )
    work = "momentum before = momentum after\n2(6) + 4(0) = 2v + 4(3.6)\n12 = 2v + 1.44\nv = 5.28 m/s\n"
    assert statuses(problem, work) == ["correct", "correct", "wrong", "carried"]  # the principle in words: right


def test_m_alone_is_the_one_unknown_mass(tmp_path) -> None:
    # 1500 kg at 8 m/s into a car at rest; they move on together at 5 m/s: 12000 = 5(1500 + M),
    # M = 900 kg; 1500 copied as 1050: 12000 = 5250 + 5M, M = 1350, carried
    given = 'm_A = "1500 kg"\nm_B = "? kg"\ne = "?"\nv_A1 = "8 m/s"\nv_B1 = 0\nv_A2 = "5 m/s"\nv_B2 = "5 m/s"\n'
    work = "Let M be the mass of the second car.\n1500 × 8 = (1050 + M) × 5\n12000 = 5250 + 5M\nM = 1350 kg\n"
    assert statuses(_inverse_carts(tmp_path, given), work) == ["wrong", "carried", "carried"]


def test_a_mass_times_a_students_own_name_and_v_names_after_the_impact() -> None:
    # Edexcel M2 2003: 2m at u hits m at rest: 2u = 2v_P + v_Q holds for the velocities after;
    # kinetic energy conserved (e is 1/3, not 1) is the slip, though the velocities before
    # (v_P = u, v_Q = 0) satisfy both lines: v_P and v_Q are after (v after, as u is before)
    work = (
        "CLM: 2mu = 2mv_P + mv_Q  =>  2u = 2v_P + v_Q\n"
        "KE conserved: ½(2m)u² = ½(2m)v_P² + ½ m v_Q²  =>  2u² = 2v_P² + v_Q²\n"
    )
    r = report("edexcel-m2-2003-january-q6-2m-hits-m-e-one-third", work)
    assert [i.status for i in r.items] == ["correct", "wrong"], r.text()
    assert any("v_P is v_A2" in n for n in r.notes), r.notes


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (r"$v_Q = \frac{2u}{3} \quad (v_Q = 0 \text{ is the initial velocity})$", [("v_Q", "(2u)/3")]),
        ("lost = 37.5 - 49.5 = -12 J ???", [("lost", "37.5 - 49.5", "-12")]),  # the doubt is not the value
    ],
)
def test_a_root_turned_down_in_latex_words_and_a_doubt_after_a_value(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_a_chain_product_with_a_name_of_the_students_own_and_its_own_value_carried() -> None:
    # OCR M2 2007: thrown down at 21 m/s from 40 m: v = 35; e = 0.8, so it rebounds at 28 and
    # rises 28²/19.6 = 40 m. 0.8 × 35 worked as 26 (a slip): ½ v_2² = gh holds for the problem,
    # and with the student's 26 gives h = 26²/19.6 = 34.5: carried, not a further slip
    work = "v^2 = 21^2 + 2(9.8)(40) = 1225, v = 35\nv_2 = 0.8 × 35 = 26\n½ v_2^2 = gh\nh = 26^2/(2 × 9.8) = 34.5 m\n"
    assert statuses("chain-ocr-m2-2007-rebounds-to-start", work) == ["correct", "wrong", "correct", "carried"]


def test_a_size_is_judged_where_the_files_conditions_hold(tmp_path) -> None:
    # m at u hits 3m at rest: u = v_A + 3v_B, v_B - v_A = eu, so v_A = u(1 - 3e)/4, and A
    # reverses when e > 1/3: its speed is then u(3e - 1)/4
    head = 'title = "t"\nkind = "direct"\n'
    given = '[given]\nm = "kg"\nu = "m/s"\ne = "e"\nm_A = "m"\nm_B = "3*m"\nv_A1 = "u"\nv_B1 = 0\n'
    problem = tmp_path / "reverses.toml"
    problem.write_text(head + 'conditions = ["e > 1/3"]\n' + given)
    assert statuses(str(problem), r"$\lvert v_A \rvert = \frac{u(3e - 1)}{4}$" + "\n") == ["correct"]
    assert statuses(str(problem), "|v_A| = u(1 - 3e)/4\n") == ["wrong"]


def test_a_number_glued_to_a_name_after_a_slash_is_one_divisor() -> None:
    # OCR M2 2014 (2m at 4, 3m at 2 toward it, e = 0.4): reduced mass 2m·3m/(5m) = 1.2m; loss
    # ½(1.2m)(1 - 0.16)(6²) = 18.144m (KE 22m before, 1.0816m + 2.7744m = 3.856m after)
    work = (
        "speed of approach = 4 + 2 = 6\n"
        "speed of separation = 0.4 × 6 = 2.4\n"
        "KE lost = ½ μ (1 − e²) w² with μ = 2m·3m/5m = 1.2m and w = 6\n"
        "= 0.6m × 0.84 × 36 = 18.144m J\n"
    )
    assert statuses("ocr-m2-2014-particles-2m-3m-ke-lost", work) == ["correct"] * 4
    assert statuses("ocr-m2-2014-particles-2m-3m-ke-lost", "μ = 2m·3m/5m = 1.5m\n") == ["wrong"]


@pytest.mark.parametrize(
    ("line", "status"),
    [
        # 4.C.11 (the notes): A's speed after sqrt(3.05² + 1.11²) = 3.25, B's sqrt(9.15² + 8.40²) = 12.4
        (r"$\text{Speed of A after} = 3.25\ \text{m/s}$", "correct"),
        (r"$\text{B's final speed} = 12.4$", "correct"),
        (r"$\text{speed of B} = 8.40$", "wrong"),  # B's n component, not its speed
    ],
)
def test_a_bodys_quantity_in_latex_text_is_read(line: str, status: str) -> None:
    assert statuses("notes-4c11-two-spheres", line + "\n") == [status]


def test_a_value_with_the_direction_opposite_to_the_positive_one_is_negative() -> None:
    # OCR M2 2014 (2m at 4, 3m at 2 toward it, e = 0.4): A moves back at 1.04, B on at 1.36
    work = (
        "Taking right as positive.\n2(4) + 3(-2) = 2v_A + 3v_B\nv_B - v_A = 0.4(4 + 2) = 2.4\n"
        "v_A = 1.04 m/s to the left\nv_B = 1.36 m/s to the right\n"
    )
    assert statuses("ocr-m2-2014-particles-2m-3m-ke-lost", work) == ["correct"] * 4
    wrong = "Taking right as positive.\n2(4) + 3(-2) = 2v_A + 3v_B\nv_A = 1.04 m/s to the right\n"
    assert statuses("ocr-m2-2014-particles-2m-3m-ke-lost", wrong)[-1] == "wrong"


def test_v_a_as_the_magnitude_of_its_components_is_the_speed_in_an_oblique_impact() -> None:
    # OCR M3 June 2007 (mark scheme: a = -4.5, b = 6, speed of A 12.8): along the line of
    # centres v_A, v_B are the n components; A keeps 12 across it, so v_A = sqrt(4.5^2 + 12^2)
    # = sqrt(164.25) = 12.8 is A's speed. sqrt(4.5^2 + 6^2) = 7.5 is not A's speed.
    work = "4(9) + 3(-12) = 4 v_A + 3 v_B\nv_B - v_A = 0.5(9 + 12) = 10.5\nv_A = -4.5, v_B = 6\n"
    assert statuses("ocr-m3-2007-oblique-sin-alpha-0p8", work + "v_A = sqrt(4.5^2 + 12^2) = 12.8\n") == ["correct"] * 4
    assert statuses("ocr-m3-2007-oblique-sin-alpha-0p8", work + "v_A = sqrt(4.5^2 + 6^2) = 7.5\n")[-1] == "wrong"


@pytest.mark.parametrize(
    ("line", "declared"),
    [
        ("Let $p$, $q$ be the speeds of P and Q after the impact.", "p is v_A2, q is v_B2"),
        ("p = velocity of Q after, q = velocity of P after", "p is v_B2, q is v_A2"),
        ("a and b are the velocities of the m and the 3m particle after", "a is v_B2, b is v_A2"),
        ("Let s and r denote the velocities of A and B before the collision", "s is v_A1, r is v_B1"),
    ],
)
def test_names_declared_in_words(line: str, declared: str) -> None:
    # CIE 2012: A has mass 3m, B mass m (a direct impact); the words name each body by its
    # letter, P and Q, or its mass.
    notes = report("cie-9231-p2-2012-june-q2-impulse-4mu-show-ke-lost", line + "\nm_A = 3m\n").notes
    assert f"Declared: {declared}." in notes


def test_a_direction_in_words_after_a_number_gives_its_sign() -> None:
    # OCR M2 2014: 2m at 4 m/s meets 3m at 2 m/s, e = 0.4: 2a + 3b = 2, b - a = 2.4, so
    # a = -1.04 (A goes back, to the left: A came from the left) and b = 1.36 (to the right).
    lead = "2m(4) - 3m(2) = 2m a + 3m b\nb - a = 0.4(6) = 2.4\n"
    problem = "ocr-m2-2014-particles-2m-3m-ke-lost"
    assert statuses(problem, lead + "v_A = 1.04 m/s to the left\nv_B = 1.36 m/s to the right\n") == ["correct"] * 4
    assert statuses(problem, lead + "v_A = 1.04 m/s to the right\n")[-1] == "wrong"
    assert statuses(problem, "v_A2 = 1.04 m/s in the opposite direction\n") == ["correct"]
    assert statuses(problem, "v_B2 = 1.36 m/s (to the left)\n") == ["wrong"]


def test_names_solved_for_in_a_find_the_speeds_before_problem_are_the_speeds_before() -> None:
    # Edexcel M2 Jan 2017 (mark scheme: u_P = 8v, u_Q = 4.5v): P (2m) at x, Q (3m) at y toward it;
    # after, P at -v and Q at 3v/2. 2x - 3y = -2v + 4.5v = 2.5v; 2.5v = (x + y)/5, x + y = 12.5v;
    # 5x = 40v. x and y are solved for, and here the velocities before are the unknowns.
    work = (
        "2m x - 3m y = 2m(-v) + 3m(3v/2)\n2x - 3y = 2.5v\n3v/2 + v = 1/5 (x + y)\nx + y = 12.5v\n"
        "5x = 40v\nx = 8v, y = 4.5v\n"
    )
    assert statuses("edexcel-m2-2017-january-q5-both-reverse-find-speeds-before", work) == ["correct"] * 6


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a numbered line's "1)" opens no bracket: the remark in brackets after the value is dropped
        ("1) speed after: v = 0.3 x 4 = 1.2 m/s (away from the wall)", [("v", "0.3 x 4", "1.2")]),
        # an aside whose opening bracket went with the words before it
        ("so (the angle with the normal = 90 - 1.27 = 88.7°)", [("the normal", "90 - 1.27", "88.7°")]),
        # a sentence in brackets after the relation's full stop is the student's remark
        ("Speed of B = u(1 - e)/4. (The question has (sqrt3/4)u(1 + e): why?)", [("Speed of B", "u(1 - e)/4")]),
        ("x = (a) + (b)", [("x", "(a) + (b)")]),
    ],
)
def test_a_label_bracket_is_not_an_aside_bracket(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_v_and_big_v_with_bodies_moving_off_together_are_two_quantities() -> None:
    # MSU bullet: 0.020 kg at v = 300 m/s lodges in 4.0 kg (e = 0): V = 6/4.02 = 1.49 m/s. The
    # student's v is the bullet's speed before, V the common velocity after.
    work = "v = 300\n0.020 v = 4.02 V\nV = 1.49\n"
    r = report("msu-lectureonline-bullet-lodges-in-block", work)
    assert [i.status for i in r.items] == ["correct"] * 3, r.text()


# --- what is written around a relation (issue #31: the q/r batches) ---------------------------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # a unit after LaTeX spacing, in any spelling, then words
        (r"$v = 35\ \text{m s}^{-1}\text{ just before impact}$", [("v", "35")]),
        (r"$w = 28~\mathrm{m\,s^{-1}}$", [("w", "28")]),
        (r"$v = 4.2\;\text{m}\,\text{s}^{-1}$", [("v", "4.2")]),
        (r"$u = 6\,\frac{\text{m}}{\text{s}}$", [("u", "6")]),
        ("w = 2.5 m s^-1", [("w", "2.5")]),
        # the unrounded value in brackets; a remark in square brackets; a tick then words
        ("V = 2.47 m/s   (2.4688)", [("V", "2.47")]),
        ("v_B = 0.333 (0.3333...)", [("v_B", "0.333")]),
        ("0.5 = 0.1(v + 3)    [v up, 3 down]", [("0.5", "0.1(v + 3)")]),
        ("v = 3u - 2u = u   ✓ that is B's speed", [("v", "3u - 2u", "u")]),
        ("v_A = u(1 - 2e), in the direction it came from", [("v_A", "u(1 - 2e)")]),
        # a product in brackets is not a note
        ("w = m g (20)", [("w", "m g (20)")]),
        ("J = 0.2 (28)", [("J", "0.2 (28)")]),
        # relations inside prose: a sentence after a unit, words before a name, bold
        ("Common velocity V = 9/3 = 3 m/s. In that frame A moves at 2", [("V", "9/3", "3")]),
        (r"so $\phi = \alpha + 45^\circ$ and", [("phi", "alpha + 45°")]),
        ("**CLM:** 3a + b = 4", [("3a + b", "4")]),
        ("energy      a^2 + b^2 = 10", [("a^2 + b^2", "10")]),
    ],
)
def test_notes_units_and_prose_around_a_relation_are_not_read_into_it(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("text", "tag"),
    [("3x + y = 14   ...(1)", "1"), ("y - x = 2e  --(2)", "2"), ("a + b = 7 [3]", "3"), ("a = 2b  …(4)", "4")],
)
def test_an_equations_tag_after_it_in_any_form(text: str, tag: str) -> None:
    (r,) = read_relations(text)
    assert r.tag == tag and "(" not in r.sides[-1] and "[" not in r.sides[-1], r


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        # withdrawn working: never marked
        ("v = 2.4 - 0.6 = 1.8   <-- wrong, sign", []),
        ("v = 1.8 (crossed out)", []),
        ("2v ... no wait, (1) + (2):  3v = 9", [("3v", "9")]),
        ("~~v = 1.8~~ v = 3.0", [("v", "3.0")]),
        # a root rejected in words, to the end of its sentence
        ("if v = 7u/4 then w = 2u - 7u/4 = u/4 < v, not possible", []),
        ("v = 2u would mean B is slower than A, which can't happen. So v = u", [("v", "u")]),
        ("Since e cannot be negative, e = 0.5", [("e", "0.5")]),  # what follows the words stands
        ("v = 7u/4 is impossible as w < v, so v = u/2", [("v", "u/2")]),
        # a goal is not a claim
        ("Q3 - show that v = u(1 + e)/2", []),
        ("Hence show e = 1/2. Then v = 3", [("v", "3")]),
        # equations combined lead in; a sum of products does not
        ("(1) - 2(2): 5y = 6", [("5y", "6")]),
        ("4500(3) + 3000(6) = 7500 V", [("4500(3) + 3000(6)", "7500 V")]),
    ],
)
def test_what_a_teacher_does_not_mark_is_not_read(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_latex_environments_students_use() -> None:
    aligned = "\\[\n\\begin{aligned}\na + b &= 3 \\\\\nb &= 1\n\\end{aligned}\n\\]\n"
    assert [(r.line, r.sides) for r in read_relations(aligned)] == [(3, ("a + b", "3")), (4, ("b", "1"))]
    note = "\\begin{align*}\nm u &= m a + m b && \\text{(CLM along } \\mathbf{i})\\\\\nb - a &= e u && b = 2\n\\end{align*}"
    assert sides(note) == [("m u", "m a + m b"), ("b - a", "e u"), ("b", "2")]
    continued = "\\begin{align*}\nK &= \\tfrac12 (2)(3)^2 \\\\\n  &\\approx 9.0\\ \\text{J}\n\\end{align*}"
    assert sides(continued) == [("K", "(1/2) (2)(3)^2"), ("(1/2) (2)(3)^2", "9.0")]


def test_a_greek_letter_before_a_latin_one_is_two_factors() -> None:
    from derive.mathtext.notation import student

    assert student("u + kλu") == "u+k*lambda*u" and student("μu^2") == "mu*u^2"


# OCR M2 2014 (2m at 4, 3m at 2 toward it, e = 0.4): 2vA + 3vB = 8 - 6 = 2, vB - vA = 0.4(6) = 2.4,
# 5vB = 2 + 4.8 = 6.8, vB = 1.36, vA = -1.04 (worked by hand).
def test_notes_withdrawn_lines_and_rejected_cases_in_a_derivation() -> None:
    work = (
        "2vA + 3vB = 2        ...(1)\n"
        "vB - vA = 2.4        ...(2)\n"
        "vA = 2.4 - 1.36 = 1.04   <- no, wrong sign\n"
        "(1) + 2(2): 5vB = 6.8\n"
        "vB = 1.36 m/s   (1.360)\n"
        "if vA = 1.36 then vB = 2.4 + 1.36 = 3.76 and 2(1.36) + 3(3.76) = 13.96, impossible.\n"
        "vA = 1.36 - 2.4 = -1.04 m/s     [A goes back]\n"
    )
    r = report("ocr-m2-2014-particles-2m-3m-ke-lost", work)
    lines = {i.name: i.status for i in r.items}
    assert lines == {"1": "correct", "2": "correct", "4": "correct", "5": "correct", "7": "correct"}, r.text()


def test_a_unit_after_latex_spacing_then_words_is_not_a_power() -> None:
    work = (
        "\\begin{align*}\n2v_A + 3v_B &= 2 \\\\\nv_B - v_A &= 2.4 \\\\\n"
        "v_B &= 1.36\\ \\text{m s}^{-1} \\text{ after the impact}\n\\end{align*}\n"
    )
    assert statuses("ocr-m2-2014-particles-2m-3m-ke-lost", work) == ["correct"] * 3


@pytest.mark.parametrize(
    ("typed", "read"),
    [
        ("h = v^2/2g", "h=v^2/(2*g)"),  # over the product, as a teacher reads it
        ("V = (2m u + m w)/3m", "V=(2*m*u+m*w)/(3*m)"),
        ("V = u cos α/3", "V=u*cos(alpha)/3"),  # (u cos α)/3
        ("s = √(u²cos²α + u²sin²α)", "s=sqrt(u^2*cos(alpha)^2+u^2*sin(alpha)^2)"),
        ("f = 36%", "f=(36/100)"),
        ("m = 3.2 × 10⁻³", "m=3.2e-3"),  # any superscript, not only ² and ³; standard form is one number
        ("T = 1.23 x 10^(3) + 4·10^2", "T=1.23e3+4e2"),  # at the mantissa's figures
        ("y = 2^3 × 10^2", "y=2^3*10^2"),  # a power times 10^2: not a number in standard form
        ("w = ⅔u + ⅛", "w=(2/3)*u+(1/8)"),  # any vulgar fraction
    ],
)
def test_students_notation_as_a_teacher_reads_it(typed: str, read: str) -> None:
    from derive.mathtext.notation import student

    assert student(typed) == read


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Energy lost, using ΔT = ½ m u² (1 − e²):", [("Delta T", "½ m u² (1 − e²)")]),
        ("Using NEL, v_B - v_A = 2", [("v_B - v_A", "2")]),
        ("(that's 0.25/0.50 = 50% lost, i.e. 50% kept)", [("0.25/0.50", "50%")]),
        ("I = 0.5 * 4.2 = 2.1 lb.s", [("I", "0.5 * 4.2", "2.1")]),
        ("I = 2.1 lbf s", [("I", "2.1")]),
        ("Loss in K.E. = 12 J", [("Loss in K.E", "12")]),
    ],
)
def test_lead_in_clauses_percentages_and_impulse_units(text: str, expected: list) -> None:
    assert sides(text) == expected


# OCR M2 June 2012 Q1 (0.8 kg at 4 m/s into a wall, e = 0.3): KE lost = ½(0.8)(16)(1 - 0.09) = 5.824 J
# (mark scheme 5.82 J), by the general formula in the problem's letters.
def test_a_general_formula_line_in_the_problems_letters_is_judged() -> None:
    work = "m = 0.8, u = 4, e = 0.3\nEnergy lost, using ΔKE = ½ m u² (1 − e²):\nΔKE = 6.4 × (1 − 0.09) = 5.824 J\n"
    r = report("ocr-m2-2012-particle-hits-wall", work)
    assert {i.name: i.status for i in r.items}.get("2") == "correct", r.text()
    assert {i.name: i.status for i in r.items}.get("3") == "correct", r.text()


def test_markdown_code_marks_a_blockquote_and_latex_intertext_are_layout() -> None:
    assert sides("`v_B = 2.4`\n> v_A = -1.04\n") == [("v_B", "2.4"), ("v_A", "-1.04")]
    text = "\\begin{align*}\na &= 2 \\\\\n\\intertext{so}\nb &= 3\n\\end{align*}"
    assert [(r.line, r.sides) for r in read_relations(text)] == [(2, ("a", "2")), (4, ("b", "3"))]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("v = 3.46 (3 s.f.)", [("v", "3.46")]),
        ("e = 0.8 (to 1 d.p.)", [("e", "0.8")]),
        ("v = 3.464 m/s (3sf)", [("v", "3.464")]),
        ("v = 2 m/s (2 d.p.) <- answer", [("v", "2")]),
        ("x = 3 (from (1))", [("x", "3")]),
        ("(a) v = 3", [("v", "3")]),
        ("(ii) v = 3", [("v", "3")]),
        ("b) v = 3", [("v", "3")]),
        ("Q1(b): e = 0.5", [("e", "0.5")]),
        ("So, v = 3.", [("v", "3")]),
        (r"$v_A = \SI{3}{\metre\per\second}$", [("v_A", "3")]),
        (r"$v = \qty{3.5}{m/s}$", [("v", "3.5")]),
        # what stays: a rejected root, a direction, a product
        ("x = 5u/6 (rejected)", []),
        ("x = 2(a + b)", [("x", "2(a + b)")]),
    ],
)
def test_figures_part_labels_pointers_and_siunitx(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_a_direction_in_brackets_after_a_note_is_kept() -> None:
    (r,) = read_relations("v = 4 ms^-1 (to the left)")
    assert r.sides == ("v", "4") and r.direction == -1


def test_latex_formatting_of_the_words_around_the_mathematics() -> None:
    assert sides(r"\textbf{Stage 2.} Now $w = 1.5$") == [("w", "1.5")]
    assert sides(r"\section*{Q2} \textbf{CLM:} $3a + b = 4$") == [("3a + b", "4")]
    assert sides(r"\item $v = 3$") == [("v", "3")]


def test_a_bodys_quantity_in_words_by_the_exams_letters_p_and_q() -> None:
    # OCR M2 2014 (2m at 4, 3m at 2 toward it, e = 0.4): v_A = -1.04, v_B = 1.36 (worked above)
    work = (
        "2vA + 3vB = 2\nvB - vA = 2.4\nSpeed of Q after = 1.36\n**Answer:** velocity of P after $= -1.04$, reversed.\n"
    )
    r = report("ocr-m2-2014-particles-2m-3m-ke-lost", work)
    lines = {i.name: (i.status, i.written) for i in r.items}
    assert lines["3"] == ("correct", "Speed of Q after = 1.36"), r.text()
    assert lines["4"][0] == "correct" and "velocity of P after" in lines["4"][1], r.text()


def test_a_wide_gap_before_a_note_is_read_in_bounded_time() -> None:
    """The notes' patterns look at a line's end: a gap of thousands of spaces (hostile input) is
    read at once, not in time growing as a power of its length."""
    import time

    start = time.process_time()
    assert [tuple(" ".join(x.split()) for x in r) for r in sides("x = 1" + " " * 5000 + "(1.5")] == [("x", "1 (1.5")]
    assert len(sides("v = 2 m" + " " * 5000 + "x")) == 1
    assert time.process_time() - start < 5


def test_many_goals_and_text_pieces_are_read_in_time_growing_linearly() -> None:
    # against 400 of each measured in the same run (an absolute limit fails on a busy machine)
    from support.growth import grows_about_linearly

    grows_about_linearly(lambda n: sides("show that " * n + "x = 1"), 400, 4000)
    grows_about_linearly(lambda n: sides("$x = " + "\\text{a}" * n + "$"), 400, 4000)


def test_a_long_relation_in_inline_maths_and_a_run_of_dollars_are_read_in_bounded_time() -> None:
    """Two patterns that backtracked as a power of a line's length (hostile input): prose after a
    whole relation in inline maths (``$a…a=a…a=$ into (1):``, 10,000 letters: over 60 s before) and
    a line going on from the one above behind a run of ``$`` (40 of them: minutes before)."""
    import time

    from derive.checking.carrying import GOES_ON

    start = time.process_time()
    assert len(sides("$" + "a" * 4990 + "=" + "a" * 4990 + "=$ into (1):")) <= 1
    assert GOES_ON.match("$" * 40 + "x") is None and GOES_ON.match("$$= 3") is not None
    assert time.process_time() - start < 5


# --- notation breadth (tests/test_check_notation_breadth.py measures it on four problems) ----------
# OCR M2 2012, a particle of 0.8 kg at 4 m/s into a wall, e = 0.3: v_A2 = -0.3(4) = -1.2 (rebound
# speed 1.2), KE before ½(0.8)(16) = 6.4 J, after ½(0.8)(1.44) = 0.576 J, lost 5.824 J.
WALL_2012 = "ocr-m2-2012-particle-hits-wall"


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("rebound speed = 0.3 × 4 = 1.2 m/s", ["correct"]),  # a wall's rebound speed in words
        ("speed after = 1.2 m s^-1", ["correct"]),
        ("rebound speed = 1.6 m/s", ["wrong"]),
        (r"$KE_{before} = \tfrac12(0.8)(4)^2 = 6.4\,\mathrm{J}$", ["correct"]),  # KE with its subscript
        (r"$KE_{lost} = 5.82\ \text{J}$", ["correct"]),
        (r"$KE_{lost} = 6.4\ \text{J}$", ["wrong"]),
        ("KE after = 5.76 × 10^-1 J", ["correct"]),  # standard form at the mantissa's figures
        (r"$KE_{after} = 5.8 \times 10^{-1}\,\mathrm{J}$", ["correct"]),
        ("KE after = 6.5 x 10^-1 J", ["wrong"]),
        ("$v_{A2} = -1.2 m/s$", ["correct"]),  # a unit typed bare inside $…$
        ("$v_{A2} = -1.6 m/s$", ["wrong"]),  # once "not read" (m and s taken for names)
        (r"$v_{A2} = -1.6\,ms^{-1}$", ["wrong"]),
        ("v_{A2} = -1.2", ["correct"]),  # LaTeX's braces typed in plain text
        ("v_{A2} = -1.6", ["wrong"]),
        ("v_A2 = -1.2 m/s   // it bounces back", ["correct"]),  # a code comment after the value
        ("v_A2 = -1.6 m/s   # it bounces back", ["wrong"]),
        ("v_A1 = 4 m/s & v_A2 = -1.2 m/s", ["correct"]),  # & for "and" in plain text
        ("v_A1 = 4 m/s & v_A2 = -1.6 m/s", ["wrong"]),
        (r"v_A2 = -\frac{6}{5} = -1.2", ["correct"]),  # LaTeX typed with no $
        (r"v_{A2} = -\dfrac{8}{5}", ["wrong"]),
        ("e = rebound speed / approach speed = 1.2/4 = 0.3", ["correct"]),
        ("v'_A = -1.2 m/s", ["correct"]),  # a prime before the subscript
        (r"$v_{A}^{\prime} = -1.6$", ["wrong"]),  # a prime as a power
        ("v_(A2) = -1.2", ["correct"]),  # a subscript in brackets, or with a comma
        ("v_{A,2} = -1.6", ["wrong"]),
        ("rebound speed = 1 1/5 m/s", ["correct"]),  # a mixed number
        ("rebound speed = 1 3/5 m/s", ["wrong"]),
        ("KE before = 6.4E0 J", ["correct"]),  # standard form with a capital E
        ("KE before = 7.4E0 J", ["wrong"]),
        ("KE lost ~ 5.8 J", ["correct"]),  # ~ and ≃ for "about"
        ("KE lost ≃ 6.4 J", ["wrong"]),
        ("KE before = 0.5 x 0.8 x 4^2 = 6.4 J", ["correct"]),  # x for times between numbers
        ("KE before = 0.5 x 0.8 x 4^2 = 7.2 J", ["wrong"]),
        ("KE lost = 6.4 J − 0.576 J = 5.824 J", ["correct"]),  # a unit after each number
        ("KE lost = 6.4 J − 0.576 J = 6.976 J", ["wrong"]),
    ],
)
def test_a_wall_problem_typed_in_many_notations(work: str, expected: list[str]) -> None:
    assert statuses(WALL_2012, work) == expected


# An angle the student names by its tangent (``tan α = …``) is defined by it for the lines after,
# as ``v_G = …`` is. Example 4.C.11: v_A2n = -1.109, v_A2t = 3.051, so tan α = 1.109/3.051 =
# 0.3635 (α = 19.98°), β = 90° - α = 70.02°, tan β = 1/tan α = 3.051/1.109 = 2.751.
ANGLE_BY_TANGENT = "$\\tan\\alpha = \\frac{1.109}{3.051}$\n$\\beta = 90^\\circ - \\alpha$\n$\\tan\\beta = \\frac{1}{\\tan\\alpha} = {}$"


@pytest.mark.parametrize(("last", "expected"), [("2.75", "correct"), ("0.3635", "wrong")])
def test_an_angle_named_by_its_tangent_is_defined_for_the_lines_after(last: str, expected: str) -> None:
    work = ANGLE_BY_TANGENT.replace("{}", last)
    assert statuses("notes-4c11-two-spheres", work) == ["correct", "correct", expected]


# A letter written without its body where the problem gives both bodies the same value: the disks
# weigh 47 lb each (M. Casco), so W is W_A = W_B and m = 47/32.2 = 1.4596 slug.
@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("Each disk weighs W = 47 lb, so m = W/32.2 = 1.460 slug", ["correct"]),
        ("W = 74 lb", ["wrong"]),
        ("W = 47 lb\nm = W/32.2 = 1.62 slug", ["correct", "wrong"]),
    ],
)
def test_one_letter_for_a_given_both_bodies_share(work: str, expected: list[str]) -> None:
    assert statuses("mcasco-glancing-disks-us", work) == expected


# A name in brackets with its marks after them, as the engineering textbooks write it (Hibbeler,
# Beer & Johnston): ``(v_A)_2``, ``(v_A)'``, ``(v_B)_{2x}``, ``(v_A)_n'``, and in ASCII ``(vA)1``
# beside ``mA``. The brackets hold the name together; a factor before them stays a factor. A
# number typed with its thousands spaced (``20 000``) is one number, as a teacher reads it.
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("20 (v_A)' + 35(0.3) = 10", [("20 v_A' + 35(0.3)", "10")]),
        ("e = [(v_B)' - (v_A)'] / [(v_A) - (v_B)]", [("e", "[v_B' - v_A'] / [(v_A) - (v_B)]")]),
        ("mA(vA)1 + mB(vB)1 = 9.16", [("m_A v_A1 + m_B v_B1", "9.16")]),
        (r"$m(v_A)_{2x} + m(v_B)_{2x} = 6.928$", [("m v_A2x + m v_B2x", "6.928")]),
        (r"$2(v_B)_n' = 12.47$", [("2 v_Bn'", "12.47")]),
        ("(v_A - v_B)_2 = 3", [("(v_A - v_B)_2", "3")]),  # not a name in the brackets: as written
        ("T_1 = 1/2 (20 000)(0.5)^2 = 2500 J", [("T_1", "1/2 (20000)(0.5)^2", "2500")]),
        ("v = 2 125.5", [("v", "2 125.5")]),  # not three figures after the space: not one number
        ("p = 4,500(3) - 3,000(6) = -4,500", [("p", "4500(3) - 3000(6)", "-4500")]),
        ("W = 3,000 lb, v = 6 ft/s", [("W", "3000"), ("v", "6")]),
        ("A = (3,4)", [("A_n", "3"), ("A_t", "4")]),  # a pair, not a number
    ],
)
def test_names_in_brackets_and_spaced_thousands_are_read_as_written(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_a_derivation_in_bracketed_names_is_judged_line_by_line() -> None:
    """byjus 4 kg at 12 onto 8 kg at 4, e = 0.5: 80 = 4 v_A2 + 8 v_B2, v_B2 - v_A2 = 4 -> v_A2 = 4,
    v_B2 = 8 (by hand); the third line drops the 0.5 (a slip: 8, not 4)."""
    work = "4(12) + 8(4) = 4(vA)2 + 8(vB)2\n(v_B)_2 - (v_A)_2 = 0.5[(v_A)_1 - (v_B)_1]\n(vB)2 = (vA)2 + 8\n"
    assert statuses("byjus-4kg-ball-catches-8kg-ball", work) == ["correct", "correct", "wrong"]


# A doubt after a value ("?? can't be right", "?!") is no withdrawal: the line stands and is marked,
# right or wrong. byjus: KE before 288 + 64 = 352 J, after 32 + 256 = 288 J, lost 64 J (by hand).
@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("KE lost = 352 - 288 = 64 J ?? seems a lot, can't be right but I can't see why", ["correct"]),
        ("Loss $= 352 - 280 = 72$ J ?! that can't be right", ["wrong"]),
        ("v_A2 = -4, which cannot be, so v_A2 = 4", ["correct"]),  # a case turned down: not marked
    ],
)
def test_a_doubt_after_a_value_is_not_a_withdrawal(line: str, expected: list[str]) -> None:
    assert statuses("byjus-4kg-ball-catches-8kg-ball", line) == expected


# Two vectors with a dot between them are their dot product, the sum of the products of their
# components (a perpendicular path by a zero dot product). Example 4.C.11 by hand: v_A1 = (3.9614,
# 3.0507) and v_A2 = (-1.1092, 3.0507) on (n, t): v_A1 . v_A2 = -4.3940 + 9.3068 = 4.913, not the
# product of the speeds 5(3.246) = 16.23.
@pytest.mark.parametrize(
    ("line", "expected"),
    [
        (r"$\vec{v}_{A1} \cdot \vec{v}_{A2} = 4.913$", ["correct"]),
        (r"$(-\mathbf{v}_{A1})\cdot\mathbf{v}_{A2} = -4.91$", ["correct"]),
        (r"$\mathbf{v}_{A1}\cdot\mathbf{v}_{A2} = 16.23$", ["wrong"]),  # the speeds multiplied
    ],
)
def test_a_dot_product_of_two_vectors_is_read(line: str, expected: list[str]) -> None:
    assert statuses("notes-4c11-two-spheres", line) == expected


def test_a_dot_between_numbers_is_a_product() -> None:
    assert sides(r"$4\cdot 12 + 8 \cdot 4 = 80$") == [("4 * 12 + 8 * 4", "80")]
    assert sides(r"$(-\mathbf{p})\cdot\mathbf{q} = 0$") == [("-(p_n q_n + p_t q_t)", "0")]


# An arrow after a value, where its relation ends, is the direction it points, as "to the left"
# says it (derive's +n points right, from A toward B); an arrow between two relations is still
# "so". Edexcel M2 wall (2 kg at 4 m/s toward the wall, e = 0.4), by hand: v_A2 = -1.6 m/s.
@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("v_A2 = 1.6 m/s ←", ["correct"]),
        ("v_A2 = 1.6 m/s (←)", ["correct"]),
        ("v_A2 = 1.6 m/s <-", ["correct"]),
        ("v_A2 = -1.6 m/s (←)", ["correct"]),  # signed already: the arrow says the same
        (r"$v_{A2} = 1.6\ \text{m/s} \leftarrow$", ["correct"]),
        ("v_A2 = 1.6 m/s (→)", ["wrong"]),
        ("v_A2 = 1.6 m/s ->", ["wrong"]),
    ],
)
def test_an_arrow_after_a_value_is_its_direction(line: str, expected: list[str]) -> None:
    assert statuses("edexcel-m2-ball-rebounds-from-wall", line) == expected


# The arrow is read where the student declares the positive way in words too (an arrow
# against it makes the value negative, as "to the left" does), and where the answer is
# marked after it ("← **Ans.**", "<- (Ans.)"). Same wall, by hand: v_A2 = -1.6 m/s.
@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("Taking right as positive.\nv_A2 = 1.6 m/s ←", ["correct"]),
        ("Positive to the right.\n$v_{A2} = 1.6$ m/s $\\leftarrow$, \\quad $e = 0.4$", ["correct"]),
        ("Positive to the right.\nv_A2 = 1.6 m/s → Ans.", ["wrong"]),
        ("v_A2 = 1.6 m/s ← **Ans.**", ["correct"]),
        ("v_A2 = 1.6 m/s <- (Ans.)", ["correct"]),
        ("v_A2 = 1.6 m/s -> Ans", ["wrong"]),
    ],
)
def test_an_arrow_after_a_value_is_read_with_a_convention_in_words_and_an_answer_mark(
    work: str, expected: list[str]
) -> None:
    got = [i.status for i in report("edexcel-m2-ball-rebounds-from-wall", work).items if i.kind == "line"]
    assert got == expected


def test_a_relation_after_a_comma_that_ends_words_split_off_at_at_is_its_own() -> None:
    # "m = 0.150 kg at 35.0 m/s, goalie M = 70.0 kg": split at "at", then "35.0 m/s" has no "=":
    # the comma ends it, and "M = 70.0" is a relation of its own (not "35.0 m/s, M = 70.0").
    assert sides("Trolley m = 2.0 kg at 3.0 m/s, second trolley M = 5.0 kg at rest") == [("m", "2.0"), ("M", "5.0")]
    assert sides("x = 1, 2") == [("x", "1, 2")]


def test_an_arrow_between_relations_still_splits_them() -> None:
    assert sides("x = 2 → y = 3") == [("x", "2"), ("y", "3")]
    assert [r.direction for r in read_relations("v_A2 = 1.6 m/s ←, v_B2 = 2 m/s →")] == [-1, 1]


# An up or down arrow after a value (``\downarrow``, ``↑``) is its direction in words, as
# "downwards" says it, not an unread mark. OCR M2 June 2006 Q2 (dropped from 2 m, rebounds to
# 1.4 m, g = 9.8), by hand: v_1 = sqrt(2(9.8)(2)) = sqrt(39.2) = 6.26; v_2 = sqrt(27.44) = 5.24.
@pytest.mark.parametrize(
    "line",
    [
        r"$v_1 = \sqrt{2(9.8)(2)} = 6.26\ \text{m/s} \downarrow$",
        "v_1 = 6.26 m/s ↓",
        "v_1 = 6.26 m/s (↓)",
        r"$v_2 = \sqrt{2(9.8)(1.4)} = 5.24 \text{ m/s} \uparrow$",
    ],
)
def test_a_vertical_arrow_after_a_value_is_its_direction(line: str) -> None:
    assert statuses("chain-ocr-m2-2006-drop-rebound", line) == ["correct"]


# A length rounded and said again in a smaller unit (``≈ 114 mm``) keeps the figures written:
# 114 mm is 0.114 m at three figures, not the exact 114/1000. MSU bullet and block (20 g at
# 300 m/s into 4.0 kg, g = 9.81), by hand: V = 6/4.02 = 1.49254, h = V²/19.62 = 0.11354 m.
@pytest.mark.parametrize(
    ("line", "expected"),
    [
        (r"$h_2 = 0.1135\ \text{m} \approx 114\ \text{mm}$", ["correct"]),
        ("h_2 = 0.1135 m = 11.4 cm", ["correct"]),
        ("h_2 = 114 mm", ["correct"]),
        ("h_2 = 120 mm", ["wrong"]),
    ],
)
def test_a_length_in_millimetres_keeps_its_figures(line: str, expected: list[str]) -> None:
    assert statuses("chain-msu-bullet-block-swings", line) == expected


# An energy balance stated in symbols before a chain's stage is worked (T_1 + V_1 = T_2 + V_2,
# KE_i + PE_i = KE_f + PE_f, T_1 + ΣU_{1-2} = T_2) is the principle a teacher marks right, not a
# line of unknown names. MSU bullet and block (20 g at 300 m/s into 4.0 kg, g = 9.81), by hand:
# V = 6/4.02 = 1.4925; ½(4.02)(1.4925)² = 4.4776 = 4.02(9.81)h = 39.436 h, h = 0.11354 m.
@pytest.mark.parametrize(
    "balance",
    [
        "T_1 + V_1 = T_2 + V_2",
        r"$KE_i + PE_i = KE_f + PE_f$",
        r"$T_1 + \Sigma U_{1-2} = T_2$",
        "K_A + U_A = K_B + U_B",
    ],
)
def test_an_energy_balance_in_symbols_is_the_stage_principle(balance: str) -> None:
    work = "V = 0.020(300)/4.020 = 1.4925\n" + balance + "\n½(4.02)(1.4925)^2 + 0 = 0 + 4.02(9.81)h\nh = 0.1135"
    assert statuses("chain-msu-bullet-block-swings", work) == ["correct"] * 4


def test_a_velocity_equation_is_no_energy_balance() -> None:
    from derive.checking.principles import energy_balance

    assert not energy_balance(("V_1", "V_2"))
    assert not energy_balance(("T_1", "T_2"))  # kinetic energy kept: a claim to judge, not a principle
    assert not energy_balance(("m_A u_A + m_B u_B", "m_A v_A + m_B v_B"))


# A rebound's angle named in words by the body's verb ("let the ball leave the cushion at an angle
# φ to the cushion") is the acute angle of its path after, its size (derive's angle from the
# cushion is negative after the bounce), and "its speed be U before and w after" names the speed
# after. Edexcel FM1 June 2023 Q7a (mark scheme): U cos α = w cos φ, e₁U sin α = w sin φ, so
# tan φ = e₁ tan α.
@pytest.mark.parametrize(
    "prose",
    [
        r"Let its speed be $U$ before and $w$ after, and let the ball leave the cushion at an angle $\phi$ to the cushion.",
        r"Speeds $U$ and $w$ before and after; the ball rebounds at an angle $\phi$ with the cushion.",
    ],
)
def test_a_rebound_angle_and_speed_named_in_words(prose: str) -> None:
    work = prose + "\n" + r"$U\cos\alpha = w\cos\phi$" + "\n" + r"$e_1 U\sin\alpha = w\sin\phi$"
    work += "\n" + r"$\tan\phi = e_1\tan\alpha$"
    assert statuses("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta", work) == ["correct"] * 3


# The engineering texts' names typed plain, the component before the instant (``(vA)n1``,
# ``(vB)t2``), and two relations set side by side on a line with a wide gap between them.
# OCR M3 2007 (masses 4 and 3, A at 15 m/s with sin α = 0.8, B at 12 m/s toward it, e = 0.5),
# by hand: 36 - 36 = 4a + 3b, b - a = 0.5(9 + 12) = 10.5, so a = -4.5, b = 6; A keeps 12 across.
def test_component_then_instant_names_and_relations_side_by_side() -> None:
    work = (
        "(vA)n1 = 15(0.6) = 9 m/s      (vA)t1 = 15(0.8) = 12 m/s\n"
        "(vB)n1 = -12\n"
        "4(9) + 3(-12) = 4(vA)n2 + 3(vB)n2\n"
        "(vB)n2 - (vA)n2 = 0.5(9 + 12) = 10.5\n"
        "(vA)n2 = -4.5      (vB)n2 = 6\n"
        "(vA)t2 = (vA)t1 = 12\n"
    )
    r = report("ocr-m3-2007-oblique-sin-alpha-0p8", work)
    assert [i.status for i in r.items] == ["correct"] * 6, r.text()
    assert sides("x = 2      y = 3") == [("x", "2"), ("y", "3")]
    assert sides("x = 2 + y = 3") == [("x", "2 + y", "3")]  # no gap: one chain, as written


# A line of givens in plain names (v1, v2) is the same names typed later in LaTeX ($v_1$), and a
# speed given "the other way" is the velocity with its sign. AQA M3 2007 (0.3 kg at 3 m/s, 0.2 kg
# at 2 m/s toward it, e = 0.8), by hand: 0.9 - 0.4 = 0.5 = 0.3a + 0.2b.
@pytest.mark.parametrize("other_way", ["the other way", "in the opposite direction"])
def test_givens_restated_in_plain_names_are_the_latex_names(other_way: str) -> None:
    work = (
        f"m1 = 0.3 kg, v1 = 3 m/s; m2 = 0.2 kg, v2 = 2 m/s {other_way}.\n"
        "$$m_1 v_1 + m_2 v_2 = m_1 a + m_2 b$$\n"
        "$$0.3(3) + 0.2(-2) = 0.3a + 0.2b$$\n"
    )
    assert statuses("aqa-m3-2007-spheres-approach-head-on", work) == ["correct"] * 3


# A label in \text{} and then a term with a minus (``\text{CLM:}\quad -0.2(2) + …``): the minus is
# the term's sign, not a list's dash dropped. AQA M3 2007 (0.3 kg at 3 m/s, 0.2 kg at 2 m/s toward
# it), by hand: -0.4 + 0.9 = 0.5 (as 0.4 + 0.9 = 1.3 it would be wrong).
@pytest.mark.parametrize("label", [r"\text{CLM:}\quad", r"\text{Momentum:}\ "])
def test_a_minus_after_a_label_in_text_is_kept(label: str) -> None:
    line = rf"$${label} -0.2(2) + 0.3(3) = 0.3 v_A + 0.2 v_B$$"
    assert statuses("aqa-m3-2007-spheres-approach-head-on", line) == ["correct"]


# A given velocity written without its sign (B's 1.5 m/s toward A) is still the problem's data,
# exact: no rounding slack hides an arithmetic slip worked from it. OCR M2 2011 (B: 0.2 kg at
# 1.5 m/s toward A), by hand: ½(0.2)(1.5)² = 0.225 J, so 0.235 is a slip.
def test_a_given_written_without_its_sign_is_exact_data() -> None:
    assert statuses("ocr-m2-2011-spheres-find-e-and-mass", "½(0.2)(1.5)^2 = 0.225") == ["correct"]
    assert statuses("ocr-m2-2011-spheres-find-e-and-mass", "½(0.2)(1.5)^2 = 0.235") == ["wrong"]


# --- prose around a relation typed in inline mathematics --------------------------------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("From (2), $v_B = v_A + 7eu$. Put into (1):", [("v_B", "v_A + 7eu")]),
        ("Sub $v_B = v_A + 7eu$ into (1):", [("v_B", "v_A + 7eu")]),
        ("Using (1) and (2), $v_B = v_A + 7eu$, then substitute in (1)", [("v_B", "v_A + 7eu")]),
        (r"Substituting \(v_B = v_A + 7eu\) in eqn 1 gives", [("v_B", "v_A + 7eu")]),
        ("$v_B = 1.2$ m/s to the left", [("v_B", "1.2")]),
        ("Speed of B after $= 6.5v$, which is less", [("Speed of B after", "6.5v")]),
    ],
)
def test_words_around_a_whole_relation_in_inline_maths_are_not_its_sides(text: str, expected: list) -> None:
    assert sides(text) == expected


#: CIE 9231 Nov 2014 Q1 (A 2m at 4u, B m at 3u toward it): CLM 2m(4u) - m(3u) = 2m v_A + m v_B,
#: so 5u = 2v_A + v_B; NEL v_B - v_A = e(4u + 3u) = 7eu; then 5u = 3v_A + 7eu, v_A = (5 - 7e)u/3.
HEAD_ON = "cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses"


def test_a_relation_announced_in_words_before_a_substitution_is_judged() -> None:
    work = (
        "$5u = 2v_A + v_B$ (1)\n\n$v_B - v_A = 7eu$ (2)\n\nFrom (2), $v_B = v_A + 7eu$. Put into (1):\n\n"
        "$5u = 3v_A + 7eu$\n\nSub $v_A = (5 - 7e)u/3$ into (2) for B.\n"
    )
    got = {i.name: i.status for i in report(HEAD_ON, work).items if i.kind == "line"}
    assert got == {"1": "correct", "3": "correct", "5": "correct", "7": "correct", "9": "correct"}


def test_a_wrong_relation_announced_in_words_is_wrong_not_unread() -> None:
    work = "$5u = 2v_A + v_B$ (1)\n\nSub $v_B = v_A + 5eu$ into (1):\n"
    got = {i.name: i.status for i in report(HEAD_ON, work).items if i.kind == "line"}
    assert got == {"1": "correct", "3": "wrong"}


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        (r"\textbf{Q5} \quad $m = 0.2$ kg, $u = 5$ m/s", [("m", "0.2"), ("u", "5")]),
        ("Q3 v = 2.4", [("v", "2.4")]),
        ("Question 7: e = 0.5", [("e", "0.5")]),
        ("Q12a  x = 3", [("x", "3")]),
        ("Q5 = 3", [("Q5", "3")]),  # a name, not a question's number
    ],
)
def test_a_questions_number_before_a_relation_is_not_its_name(text: str, expected: list) -> None:
    assert sides(text) == expected


#: AQA M3 June 2016 Q6(a): A (speed u) moves at 60° to the line of centres, B at rest: along the
#: line A's component is u cos 60° = u/2, across it u sin 60° = (√3/2)u (unchanged by the impact).
ALONG_WALL = "aqa-m3-2016-june-q6a-path-along-wall-line-at-60deg-show-speed-of-b"


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("along l.o.c: u cos60 = u/2\nperp to l.o.c: u sin60 = (root3/2)u, unchanged by the impact", ["correct"] * 2),
        (
            "along the line of centres: A has u sin60 = (root3/2)u\n"
            "perpendicular to the line of centres: u cos60 = u/2, unchanged",
            ["wrong", "wrong"],
        ),
        ("along loc: u sin 60 = (root3/2)u", ["wrong"]),
    ],
)
def test_a_symbolic_component_labelled_by_its_axis_in_words_is_that_component(work: str, expected: list) -> None:
    items = [i for i in report(ALONG_WALL, work).items if i.kind == "line"]
    assert [i.status for i in items] == expected
    assert all(i.slip == "sin_cos_swapped" for i in items if i.status == "wrong")


# --- a bracket whose only words are Greek letters' or functions' names is mathematics ------
@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("w - 0 = e (u - lambda u)", ("w - 0", "e (u - lambda u)")),
        ("v = e (U sin alpha)", ("v", "e (U sin alpha)")),
        ("x = m (u cos theta + omega t)", ("x", "m (u cos theta + omega t)")),
        ("v = 2 (reversed)", ("v", "2")),  # a word: a remark
        ("v = 3 (sine rule, with theta)", ("v", "3")),
    ],
)
def test_a_bracket_of_greek_names_after_a_space_is_a_factor(text: str, expected: tuple) -> None:
    assert sides(text)[0] == expected


def test_a_factor_in_brackets_with_greek_words_is_judged() -> None:
    # Edexcel FM1 2023 Q7: V cos(beta) = U cos(alpha) along the cushion, V sin(beta) = e_1 U sin(alpha)
    # across it, so tan(beta) = e_1 tan(alpha) (the mark scheme's answer), LaTeX's \, read as a space.
    work = "V cos beta = U cos alpha\nV sin beta = e_1 (U sin alpha)\n$\\tan\\beta = e_1\\,(\\tan\\alpha)$\n"
    assert statuses("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta", work) == ["correct"] * 3


# --- a lead-in naming its axis in brackets; a body's letter said to be after in words --------
@pytest.mark.parametrize(
    ("text", "label", "expected"),
    [
        ("CLM (i): ma + mb = 3m", "CLM (i)", ("ma + mb", "3m")),
        ("Momentum (x): 2(6) + 4(0) = 2v + 4(2.5)", "Momentum (x)", ("2(6) + 4(0)", "2v + 4(2.5)")),
        ("NLR(along l.o.c.): b - a = 2", "NLR(along l.o.c.)", ("b - a", "2")),
    ],
)
def test_a_lead_in_with_its_axis_in_brackets_is_a_label(text: str, label: str, expected: tuple) -> None:
    (r,) = read_relations(text)
    assert (r.label, r.sides) == (label, expected)


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("so after the impact B = (w, 2.5)", [("B_n'", "w"), ("B_t'", "2.5")]),
        (
            "After the collision A = (a, 12) and B = (b, 0)",
            [("A_n'", "a"), ("A_t'", "12"), ("B_n'", "b"), ("B_t'", "0")],
        ),
        ("Afterwards: A = 3i + 2j", [("A_n'", "3"), ("A_t'", "2")]),
        ("Before: A = (6, 0), B = (0, 2.5)", [("A_n", "6"), ("A_t", "0"), ("B_n", "0"), ("B_t", "2.5")]),
        ("after the impact V = 3", [("V", "3")]),  # a speed's own letter, not a body's
    ],
)
def test_a_bodys_letter_said_to_be_after_in_words_is_after(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_velocities_as_pairs_before_and_after_in_words_are_judged() -> None:
    # OCR MEI 2021 (A 2 kg at 6 along the line of centres, B 4 kg at 2.5 across it, B leaves at 45°):
    # B keeps 2.5 across, so its component along is 2.5/tan 45° = 2.5; 12 = 2v + 10 -> v = 1;
    # e = (2.5 - 1)/6 = 0.25. The same letters A, B before and after, told apart by the words.
    work = (
        "Take x along the line of centres and y across it.\n\n"
        "Before: A = (6, 0), B = (0, 2.5).\n\n"
        "After the collision A = (v, 0) and B = (w, 2.5), and B moves at 45° to the line of centres, so w = 2.5.\n\n"
        "CLM (x): 2(6) = 2v + 4w\n\nv = 1\n\nNEL (x): w - v = e(6 - 0)\n\ne = 0.25\n"
    )
    assert statuses("ocr-mei-fmm-2021-b-at-45deg-find-e", work) == ["correct"] * 6


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("**Ex. 3.12** the red ball $m_r = 0.2$ kg", ("m_r", "0.2")),
        ("13.13 railroad car m = 20", ("m", "20")),
        ("P8.96a blue puck M_b = 0.04", ("M_b", "0.04")),
    ],
)
def test_an_exercises_number_and_words_before_a_name_are_not_its_name(text: str, expected: tuple) -> None:
    assert sides(text)[0] == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("alpha = 73.0° (72.98°)", ("alpha", "73.0°")),  # 72.98 rounds up to 73.0
        ("$\\theta = 40^\\circ \\quad (39.8^\\circ)$", ("theta", "40°")),
        ("p = 35% (34.7%)", ("p", "35%")),
        ("v = 3.1 (2.96)", ("v", "3.1 (2.96)")),  # not the value to more figures: a product
    ],
)
def test_an_angle_to_more_figures_in_brackets_is_no_factor(text: str, expected: tuple) -> None:
    assert sides(text)[0] == expected


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("speed after = e x 4 = 1.2 m/s", ["correct"]),  # OCR M2 2012: 0.3 x 4 = 1.2 m/s back from the wall
        ("u_A x 2 = 8", ["correct"]),  # u_A = 4 before: a name with a subscript times 2
    ],
)
def test_x_for_times_after_a_letter_is_times(line: str, expected: list) -> None:
    assert statuses("ocr-m2-2012-particle-hits-wall", line) == expected


def test_a_display_line_that_starts_with_an_arrow_is_read_on_its_own_line() -> None:
    text = "\\[\nx = 2 + 3\n\\quad\\Longrightarrow\\quad y = 5\n\\]\n$$\na = 1\n\\implies b = 2\n$$"
    assert [(r.line, r.sides) for r in read_relations(text)] == [
        (2, ("x", "2 + 3")),
        (3, ("y", "5")),
        (6, ("a", "1")),
        (7, ("b", "2")),
    ]


def test_the_result_after_an_arrow_on_the_next_line_of_a_display_is_judged() -> None:
    # Edexcel M4 June 2005 Q3: Q keeps u sin(alpha) across the line of centres and has
    # u cos(alpha)(1 - e)/2 along it after, so tan(beta) = 2 tan(alpha)/(1 - e), the printed result.
    work = (
        "\\[\n\\tan\\beta = \\frac{u\\sin\\alpha}{\\tfrac12 u\\cos\\alpha(1-e)}\n"
        "\\;\\Rightarrow\\; (1-e)\\tan\\beta = 2\\tan\\alpha\n\\]\n"
    )
    r = report("edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta", work)
    assert [(i.name, i.status) for i in r.items if i.kind == "line"] == [("2", "correct"), ("3", "correct")]


def test_a_subscripted_letter_glued_to_a_capital_is_a_product() -> None:
    # Edexcel FM1 2023 Q7: V sin(beta) = e_1 U sin(alpha), LaTeX's e_1U typed without a space.
    work = "$V\\sin\\beta = e_1U\\sin\\alpha$\n$V\\cos\\beta = U\\cos\\alpha$\n"
    assert statuses("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta", work) == ["correct", "correct"]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("A has 15(0.6) i + 15(0.8) j = 9 i + 12 j, and B has -12 i", [("15(0.6)", "9"), ("15(0.8)", "12")]),
        ("P's velocity has components (3, 4) = (3, 2 + 2)", [("3", "3"), ("4", "2 + 2")]),
        ("A has u = 3", [("u", "3")]),
    ],
)
def test_a_body_that_has_a_velocity_leads_in_and_the_other_bodys_clause_is_no_side(text: str, expected: list) -> None:
    assert sides(text) == expected


def test_velocities_said_with_has_are_judged() -> None:
    # OCR M3 June 2007 Q4: sin(alpha) = 0.8, so A's 15 m/s is 15(0.6) = 9 along the line of centres
    # and 15(0.8) = 12 across it; B has 12 toward A.
    work = "Initially A has 15(0.6) i + 15(0.8) j = 9 i + 12 j, and B has -12 i.\n"
    assert statuses("ocr-m3-2007-oblique-sin-alpha-0p8", work) == ["correct"]


def test_a_velocity_with_its_number_and_time_in_the_subscript_stays_one_name() -> None:
    # BYJU'S: 4 kg at 12 m/s and 8 kg at 4 m/s: 4(12) + 8(4) = 80. v_{1i}: ball 1's velocity initially.
    assert statuses("byjus-4kg-ball-catches-8kg-ball", "$4 v_{1i} + 8 v_{2i} = 80$\n") == ["correct"]


# --- a direction in words after a side in letters --------------------------------------------
@pytest.mark.parametrize(
    "tail",
    [
        r"\tfrac89 m u, backwards.",
        r"\frac{8mu}{9} (backwards)",
        "(8/9)mu in the opposite direction",
        "m(8u/9) backwards",
        r"\dfrac{8}{9}mu to the left.",
    ],
)
def test_a_direction_in_words_after_a_side_in_letters_is_not_part_of_it(tail: str) -> None:
    # Edexcel M2 2003: P (2m) at u hits Q (m) at rest, e = 1/3: v_P = 5u/9, so the impulse on P
    # is 2m(5u/9 - u) = -8mu/9: its size 8mu/9, "backwards" (the words give the sign). The
    # working 2m(u - 5u/9) = 8mu/9 is right; the direction words are not a factor of the side.
    work = f"Impulse on P = 2m(u - 5u/9) = {tail}\n"
    assert statuses("edexcel-m2-2003-january-q6-2m-hits-m-e-one-third", work) == ["correct"]
    # a slip in the working is still one (4mu/9 for 8mu/9), whatever the words after it
    work = f"Impulse on P = 2m(u - 5u/9) = {tail.replace('8', '4')}\n"
    assert statuses("edexcel-m2-2003-january-q6-2m-hits-m-e-one-third", work) == ["wrong"]
    assert not any(w in sides(f"J = {tail}")[0][1] for w in ("back", "opposite", "left"))  # words left off
