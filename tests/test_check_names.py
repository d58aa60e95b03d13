"""What a student's names stand for (issue #31, names): a name set equal to a value with a mass,
impulse or energy unit, or declared in words as one, is that quantity, never a velocity; the
problem's own letters keep their meaning under a body's lead-in.

Values worked by hand. MSU bullet (0.020 kg at 300 m/s lodges in a 4.0 kg block at rest):
w = 0.020 x 300 / 4.020 = 6/4.02 = 1.4925 m/s; the impulse on the block 4.0 x 1.4925 = 5.970 N s;
KE before ½(0.020)(300²) = 900 J. OCR M3 Jan 2012 Q2 (2m at u, m at u opposite, each at alpha to
the line of centres, e = 0.5): along the line 2u cos a and -u cos a, V = u cos a / 3,
v_A = V - e(u cos a - V) = 0, v_B = V + e(V + u cos a) = u cos a.
"""

from __future__ import annotations

import pytest
from support.checked import lines

import derive
from derive.checking.valuenames import kinds
from derive.mathtext.reader import read_relations
from derive.problem.units import ENERGY, IMPULSE, MASS


def report(problem: str, work: str) -> derive.checking.report.CheckReport:
    return derive.check(derive.solve(derive.load(problem)), derivation=work)


def by_line(problem: str, work: str) -> dict[str, str]:
    out: dict[str, str] = {}
    for i in report(problem, work).items:
        if i.kind == "line" and i.name.isdigit():
            worst = ("wrong", "carried", "error", "correct")
            old = out.get(i.name)
            out[i.name] = i.status if old is None or worst.index(i.status) < worst.index(old) else old
    return out


BULLET = "msu-lectureonline-bullet-lodges-in-block"


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("m = 47/32.2 = 1.4596 slug", {"m": MASS}),
        ("$p = 0.150$ kg puck, $q = 70.0$ kg goalie", {"p": MASS, "q": MASS}),
        ("J = 1.4596 * 6.235 = 9.10 lb.s", {"J": IMPULSE}),
        (r"I = 4.0(1.49) = 5.97\ \mathrm{N\,s}", {"I": IMPULSE}),
        ("L = 0.5(4)(3^2) = 18 J", {"L": ENERGY}),
        ("impulse J on B along the line of centres: J = m vB", {"J": IMPULSE}),
        ("Let P be the impulse on the block. P = 3", {"P": IMPULSE}),
        ("x = 3.0 m/s, then y = 2g", {}),  # a velocity is no kind of its own; 2g is 2 times g
        ("x = 3 given", {}),
    ],
)
def test_the_kind_of_a_name_by_its_unit_or_words(text: str, expected: dict) -> None:
    found = kinds(tuple(read_relations(text)), text, set())
    assert {k: v for k, v in found.items() if v in (MASS, IMPULSE, ENERGY)} == expected


@pytest.mark.parametrize("masses", ["p = 0.020 kg bullet, q = 4.0 kg block", "p = 20 g bullet, q = 4.0 kg block"])
def test_names_set_to_a_mass_and_declared_an_impulse_are_not_velocities(masses: str) -> None:
    work = "\n".join(
        [
            masses,
            "Let P be the impulse on the block.",
            "p(300) = (p + q) w",
            "w = 6/4.02 = 1.49 m/s",
            "P = q w = 4.0(1.49) = 5.97 N s",
        ]
    )
    assert by_line(BULLET, work) == {"1": "correct", "3": "correct", "4": "correct", "5": "correct"}


def test_a_slip_in_an_impulse_named_in_words_is_wrong_on_its_line() -> None:
    work = "m = 0.020 kg, M = 4.0 kg\nJ is the impulse on the block\nw = 0.020(300)/4.02 = 1.49\nJ = M w = 4.0(1.49) = 5.79 N s"
    lines = by_line(BULLET, work)
    assert lines["3"] == "correct" and lines["4"] == "wrong"


def test_a_given_letter_under_a_bodys_lead_in_is_the_given() -> None:
    work = "\n".join(
        [
            "V = (2m u cos(alpha) - m u cos(alpha))/(3m) = u cos(alpha)/3",
            "A: v_A = V - e(u cos(alpha) - V) = 0",
            "B: v_B = V + e(V + u cos(alpha)) = u cos(alpha)",
        ]
    )
    lines = by_line("ocr-m3-2012-january-q2-opposite-directions-each-at-alpha", work)
    assert lines == {"1": "correct", "2": "correct", "3": "correct"}


def test_components_unprimed_beside_primed_ones_are_before_the_impact() -> None:
    # Pre-U specimen Q2 (equal balls, A at u at 30° to the line of centres, B at rest): before,
    # along u cos 30°, across u sin 30°; m u cos 30° = m v_A' + m v_B', v_B' - v_A' = e u cos 30°,
    # and A's component across is unchanged.
    work = "\n".join(
        [
            r"$v_{An} = u\cos 30^\circ$",
            r"$v_{At} = u\sin 30^\circ$",
            r"$m v_{An} = m v_A' + m v_B'$",
            r"$v_B' - v_A' = e v_{An}$",
            r"$v_{At}' = v_{At}$",
        ]
    )
    lines = by_line("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg", work)
    assert lines == {str(n): "correct" for n in range(1, 6)}


OCR_FM = "ocr-fm-2023-oblique-discs-60deg"


@pytest.mark.parametrize(
    "work",
    [
        # OCR FM 2023 (A 4 m/s at 60° to the line of centres): along 4 cos 60° = 2, across 4 sin 60° = 3.46
        "\\begin{align*}\n\\text{along l.o.c.:}\\quad u_1 &= 4\\cos 60^\\circ = 2\\\\\n"
        "\\text{perp.:}\\quad u_2 &= 4\\sin 60^\\circ = 3.46\n\\end{align*}\n",
        "u_1 = 4 cos 60° = 2 (along the line of centres)\nu_2 = 4 sin 60° = 3.46 (perpendicular to it)\n",
        "Along the line of centres: u_1 = 4 cos 60° = 2\nPerpendicular: u_2 = 4 sin 60° = 3.46\n",
        "∥ l.o.c.: u_1 = 4 cos 60° = 2\n⊥ l.o.c.: u_2 = 4 sin 60° = 3.46\n",
        "along the common normal: u_1 = 4 cos 60° = 2\ntangential: u_2 = 4 sin 60° = 3.46\n",
    ],
)
def test_names_labelled_with_an_axis_are_that_component_of_the_body_resolved(work: str) -> None:
    assert list(by_line(OCR_FM, work).values()) == ["correct", "correct"]


def test_a_component_labelled_with_an_axis_and_resolved_wrongly_is_wrong() -> None:
    work = "along l.o.c.: u_1 = 4 cos 60° = 2\nperp.: u_2 = 4 cos 60° = 2\n"
    assert by_line(OCR_FM, work) == {"1": "correct", "2": "wrong"}


def test_a_greek_letter_typed_is_the_problems_letter_for_it(tmp_path) -> None:
    # m at u catches 2m at λu (λ < 1, written lam in the file): u + 2λu = v_A + 2 v_B,
    # v_B - v_A = e(u - λu); the approach u - λu.
    problem = tmp_path / "lam.toml"
    problem.write_text(
        'title = "t"\nkind = "direct"\n[given]\nm = "kg"\nu = "m/s"\nlam = "lam"\ne = "e"\n'
        'm_A = "m"\nm_B = "2*m"\nv_A1 = "u"\nv_B1 = "lam*u"\n'
    )
    work = "mu + 2mλu = m v_A + 2m v_B\nu + 2λu = v_A + 2v_B\nv_B - v_A = e(u - λu)\nv_B - v_A = eu(1 + λ)\n"
    assert by_line(str(problem), work) == {"1": "correct", "2": "correct", "3": "correct", "4": "wrong"}


@pytest.mark.parametrize(
    ("words", "sign"),
    [("Let right be +ve (direction A moves)", 1), ("positive: the direction in which A travels", 1)],
)
def test_the_direction_a_body_moves_declared_positive(words: str, sign: int) -> None:
    from derive.checking.naming import sign_of

    assert sign_of(words) == sign


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Let the impulse be J.", {"J": IMPULSE}),
        ("the mass of A is M", {"M": MASS}),
        ("energy is conserved; the impulse on B acts along n", {}),
        ("the mass A moves at 4 m/s", {}),
    ],
)
def test_a_kind_declared_in_words_and_words_that_declare_none(text: str, expected: dict) -> None:
    assert kinds(tuple(read_relations(text)), text, set()) == expected


def test_with_e_zero_a_name_for_the_velocity_after_carries_a_slip_into_the_energy() -> None:
    # the bullet and block move off together at 6/4.02 = 1.4925 m/s; 1.94 is an arithmetic slip,
    # and ½(4.02)(1.94²) = 7.565 J is worked from it: carried
    work = "0.020(300) = 4.02 v'\nv' = 6/4.02 = 1.94\nKE after = ½(4.02)(1.94)^2 = 7.56 J\n"
    assert by_line(BULLET, work) == {"1": "correct", "2": "wrong", "3": "carried"}


def test_a_mass_letter_set_to_a_given_mass_without_a_unit_is_that_mass() -> None:
    # the bullet (0.020 kg) and block (4.0 kg): m1(300) = (m1 + m2) w, w = 6/4.02 = 1.49
    work = "m1 = 0.020, M = 4.0\nm1(300) = (m1 + M) w\nw = 6/4.02 = 1.49\nJ = M w = 5.97\n"
    assert by_line(BULLET, work) == {"1": "correct", "2": "correct", "3": "correct", "4": "correct"}


def test_a_sentence_after_the_last_number_is_not_part_of_it() -> None:
    # the wall (e = 0.4): "e = 0.4. The ball …" is e = 0.4, not 0.4 times a name
    work = "e = 0.4. The ball rebounds.\ne = 0.4. θ is the angle with the wall\n"
    assert by_line("edexcel-m2-ball-rebounds-from-wall", work) == {"1": "correct", "2": "correct"}


CAR = "web2calc-car-rear-ends-car-find-mass"
PUCKS = "young-freedman-8-96-pucks-find-mass"


@pytest.mark.parametrize("label", ["(a)", "(ii)", "b)", "Q3(b)", "part (c):", "(a)(i)"])
def test_a_part_label_before_a_relation_is_not_a_name(label: str) -> None:
    # the car (1200 kg at 10 m/s) locks onto a parked car, both move on at 6 m/s:
    # 12000 = 6(1200 + M), 6M = 4800, M = 800 kg; e = 0 (they move together)
    work = f"{label} 1200(10) = (1200 + M)(6)\n6M = 4800\n{label} M = 800\n{label} e = 0\n"
    assert by_line(CAR, work) == {"1": "correct", "2": "correct", "3": "correct", "4": "correct"}


def test_the_one_mass_to_find_written_m_is_that_mass_even_in_a_slip() -> None:
    # the pucks (e = 1): B leaves at 0.2 + 0.05 = 0.25 m/s; 0.04(0.2) = 0.04(0.05) + m(0.25),
    # 0.008 = 0.002 + 0.25 m, m = 0.024 kg. Writing 0.02 for 0.04 x 0.05 is a slip:
    # 0.25 m = -0.012, m = -0.048, carried
    work = "v = 0.05 + 0.2 = 0.25\n0.04(0.2) = 0.04(0.05) + m(0.25)\n0.008 = 0.02 + 0.25m\nm = -0.048\n"
    assert by_line(PUCKS, work) == {"1": "correct", "2": "correct", "3": "wrong", "4": "carried"}


def test_names_declared_by_whose_velocity_they_are_and_by_ellipsis() -> None:
    # Edexcel M2 June 2004 Q5 (2m at 5u hits 3m at rest): 10u = 2p + 3q and q - p = 5eu give
    # p = (2 - 3e)u, q = 2(1 + e)u. The declaration names q by ellipsis ("q = B's")
    work = (
        "p = A's velocity after, q = B's, both the way A moved\n"
        "10mu = 2mp + 3mq\nq - p = 5eu\np = (2 - 3e)u\nq = 2(1 + e)u\n"
    )
    r = report("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)
    assert any(n.startswith("Declared:") and "q is v_B2" in n and "p is v_A2" in n for n in r.notes), r.notes
    lines = by_line("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)
    assert [lines[k] for k in "2345"] == ["correct"] * 4


AQA_30 = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"


@pytest.mark.parametrize(
    ("declared", "tangent"),
    [
        ("φ is the angle A's new path makes with the line of centres", False),
        ("A's path after the impact makes an angle φ with the line of centres", False),
        ("$\\phi$ = the angle that A's velocity after makes with the l.o.c.", False),
        ("φ is the angle A's path makes with the common tangent", True),
    ],
)
def test_an_angle_after_the_impact_declared_in_words(declared: str, tangent: bool) -> None:
    # identical balls, A at u at 30° to the line of centres, B at rest: along it p + q = u cos 30,
    # q - p = e u cos 30, p = sqrt(3) u (1 - e)/4; across A keeps u/2. So from the line of
    # centres tan φ = (u/2)/p = 2/(sqrt(3)(1 - e)); from the tangent tan φ = p/(u/2) = sqrt(3)(1 - e)/2
    last = "tan φ = sqrt(3)(1 - e)/2" if tangent else "tan φ = 2/(sqrt(3)(1 - e))"
    work = (
        "let p and q be the velocities of A and B along the line of centres after\n"
        "p = (sqrt(3)/4) u (1 - e)\n"
        f"{declared}\n{last}\n"
    )
    assert by_line(AQA_30, work).get("4") == "correct"


def test_an_angle_plus_a_bare_number_is_in_degrees() -> None:
    # the same impact: A's path after is at φ to the line of centres, tan φ = 2/(sqrt(3)(1 - e));
    # the deflection is φ - 30°, and tan(φ - 30°) = (tan φ - tan 30)/(1 + tan φ tan 30)
    work = (
        "let p and q be the velocities of A and B along the line of centres after\n"
        "A's path after makes an angle φ with the line of centres\n"
        "tan φ = 2/(sqrt(3)(1 - e))\nδ = φ - 30\n"
        "tan δ = (tan φ - tan 30)/(1 + tan φ tan 30)\n"
    )
    assert by_line(AQA_30, work).get("5") == "correct"


def test_a_greek_name_worked_out_to_a_given_angle_is_that_angle() -> None:
    # the same impact (line of centres at 30° to A's path): sin φ = 1/2 gives φ = 30°, the given
    # angle; then p + q = u cos 30, q - p = e u cos 30 and q = (1 + e) u cos 30/2
    work = (
        "let p and q be the velocities of A and B along the line of centres after\n"
        "sin φ = 1/2, so φ = 30°\np + q = u cos φ\nq - p = e u cos φ\nq = (1 + e) u cos(φ)/2\n"
    )
    assert by_line(AQA_30, work) == {"2": "correct", "3": "correct", "4": "correct", "5": "correct"}
    # at 40° φ is the student's own angle, not the given: u cos 40° is not the component along
    other = work.replace("sin φ = 1/2, so φ = 30°", "φ = 40°")
    assert by_line(AQA_30, other)["3"] == "wrong"


def test_a_name_said_in_words_is_a_declaration_not_a_relation() -> None:
    # the 2m at 5u on 3m problem: "p = A's velocity after, q = B's" says what p and q are; it is
    # neither judged nor read as a relation in the names "A's" and "B's"
    work = "p = A's velocity after, q = B's\n10mu = 2mp + 3mq\n"
    r = report("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)
    judged = {i.name for i in r.items if i.kind == "line"}
    assert "1" not in judged and "2" in judged
    assert not any("_ps" in n for n in r.notes), r.notes


@pytest.mark.parametrize(
    ("text", "sides"),
    [
        ("a = mu g = 0.3(9.8) = 2.94", ("a", "mu g", "0.3(9.8)", "2.94")),
        ("friction F = mu m g", ("F", "mu m g")),  # "friction": words before the name
        ("s = 4.5 m", ("s", "4.5")),
    ],
)
def test_a_letter_after_a_name_is_a_factor_not_a_unit(text: str, sides: tuple) -> None:
    # g, m, s, N end a side as a unit only after a number: mu g is μ times g
    assert [r.sides for r in read_relations(text)] == [sides]


@pytest.mark.parametrize("tag", ["...(1)", "…(1)", " .....(1)"])
def test_a_tag_after_dots_is_a_tag(tag: str) -> None:
    # a tag led by dots, as in a textbook: 2u = x + 2y ...(1) is the relation 2u = x + 2y
    assert [(r.sides, r.tag) for r in read_relations(f"2u = x + 2y   {tag}")] == [(("2u", "x + 2y"), "1")]


def test_delta_ke_typed_with_the_greek_capital_is_the_energy_lost() -> None:
    # MEI 2023, A (0.5 kg at 6) catches B (2 kg at 2), A moves on at 0.2: 3 + 4 = 0.1 + 2v, v = 3.45;
    # lost 13 - (0.01 + 11.9025) = 1.0875 J. ½m(u - v)² for each body is the wrong formula:
    # 8.41 + 2.1025 = 10.51, carried
    work = "3 + 4 = 0.1 + 2v, v = 3.45\nΔKE = ½(0.5)(6 − 0.2)² + ½(2)(3.45 − 2)²\n= 8.41 + 2.1025 = 10.51 J\n"
    assert by_line("ocr-mei-fmm-2023-a-speed-0p2-forward", work) == {"1": "correct", "2": "wrong", "3": "carried"}


def test_a_line_continued_with_approximately_equal_is_continued() -> None:
    # "  ≈ 7.5 J" under "= 7.51" continues the relation above it, as "  = 7.5" would
    got = [(r.line, r.sides, r.lead) for r in read_relations("T = 3 + 4.51\n  = 7.51\n  ≈ 7.5 J\n")]
    assert got[-1] == (3, ("7.51", "7.5"), "T")


@pytest.mark.parametrize(
    "declared", ["A is deflected through δ", "δ is the deflection of A", "δ = angle of deflection"]
)
def test_the_deflection_declared_in_words(declared: str) -> None:
    # the same impact: A's path after is at φ to the line of centres, tan φ = 2/(sqrt(3)(1 - e)),
    # and A came in at 30° on the same side, so it turns through δ = φ - 30°
    work = (
        f"{declared}\n"
        "A's path after makes an angle φ with the line of centres\n"
        "tan φ = 2/(sqrt(3)(1 - e))\ntan δ = (tan φ - tan 30)/(1 + tan φ tan 30)\n"
    )
    assert by_line(AQA_30, work).get("4") == "correct"


OCR_M3_ALPHA = "ocr-m3-2012-january-q2-opposite-directions-each-at-alpha"


@pytest.mark.parametrize(
    "said",
    [
        "(writing a for α, and x, y for the components of A and B along the line of centres after)",
        "Use a for alpha throughout.",
        "a stands for \\alpha; x and y are A's and B's components along the line of centres after",
        "a, k for α, u",
    ],
)
def test_a_short_letter_said_in_words_to_stand_for_the_problems_letter(said: str) -> None:
    # OCR M3 2012 Q2 (A 2m, B m, each at u at α to the line of centres, opposite ways, e = 1/2):
    # along: 2m u cos α - m u cos α = 2m x + m y, y - x = (1/2)(2 u cos α) -> x = 0, y = u cos α
    k = "k" if said.startswith("a, k") else "u"
    work = (
        f"{said}\n2m {k} cos a - m {k} cos a = 2m x + m y\ny - x = 0.5({k} cos a + {k} cos a)\nx = 0\ny = {k} cos a\n"
    )
    assert by_line(OCR_M3_ALPHA, work) == {str(n): "correct" for n in range(2, 6)}


def test_a_letter_said_to_stand_for_a_word_is_not_a_name() -> None:
    # "as for" and "so for" are English: nothing is declared, the line stays not read
    from derive.checking.context import Context
    from derive.checking.wordnames import in_words

    ctx = Context(derive.solve(derive.load(OCR_M3_ALPHA)), None)
    assert in_words("as for alpha, it is acute; so for u", ctx) == {}
    assert set(in_words("(a for alpha)", ctx)) == {"a"}


def test_a_quantity_the_file_defines_is_a_name_a_derivation_may_use() -> None:
    # Edexcel FM1 June 2023 Q7(a), the mark scheme's own lines: "V cos(beta) = U cos(alpha)",
    # "V sin(beta) = e_1 U sin(alpha)", "tan(beta) = e_1 tan(alpha)" (β the statement's angle after,
    # a [define] of the file; V the speed after, never declared)
    work = "V cos β = U cos α\nV sin β = e₁ U sin α\ntan β = e₁ tan α\n"
    assert by_line("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta", work) == {
        "1": "correct",
        "2": "correct",
        "3": "correct",
    }


def test_a_letter_with_a_digit_is_one_name_not_a_product() -> None:
    # OCR M3 2012 Q2: along the line, the approach speed is 2u cos α, the reduced mass 2m/3, so the
    # loss is (1/2)(2m/3)(1 - e^2)(2u cos α)^2 = (4/3) m u^2 cos^2 α (1 - e^2) = m u^2 cos^2 α
    # (e = 1/2); the student writes e1 for the one e: e1^2 is e squared, not e times 1^2
    work = "KE lost = 4/3 m u^2 cos^2 α (1 - e1^2)\n = m u^2 cos^2 α\n"
    assert by_line(OCR_M3_ALPHA, work) == {"1": "correct", "2": "correct"}


@pytest.mark.parametrize("across", ["u sin α", "-u sin α"])
def test_a_component_across_named_in_words_unsigned_is_its_size(across: str) -> None:
    # OCR M3 2012 Q2: B comes in at u at α to the line of centres from the other side (from -n
    # toward -t): along it B has -u cos α, across it u sin α in size, -u sin α in derive's t.
    # Unsigned, the student's direction across is their own; signed, derive's.
    sq = "-" if across.startswith("-") else ""
    work = (
        "Along the line of centres B has -u cos α = -u sqrt(1 - sin^2 α)\n"
        f"Across the line of centres B has {across} = {sq}u sqrt(1 - cos^2 α)\n"
    )
    assert by_line(OCR_M3_ALPHA, work) == {"1": "correct", "2": "correct"}


AQA_30_SPEED = "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b"


@pytest.mark.parametrize(
    "said",
    [
        "where V is A's speed after the collision",
        "Let V be the speed of A after the impact.",
        "Let the speed of A after the impact be V.",
        "A's speed is now V.",
        "The speed of sphere A afterwards = V",
        "A moves off with speed V.",
    ],
)
@pytest.mark.parametrize("slip", [False, True])
def test_a_speed_after_an_oblique_impact_named_in_words(said: str, slip: bool) -> None:
    # AQA M3 2007 Q6 (equal spheres, A at u at 30° to the line of centres, B at rest, e): A keeps
    # u sin 30° = u/2 across; along, A has sqrt(3) u (1 - e)/4, so V^2 = u^2/4 + 3u^2(1 - e)^2/16.
    # With 1 + e for 1 - e the line is wrong, never not read.
    sign = "+" if slip else "-"
    work = f"{said}\nV^2 = (u/2)^2 + 3u^2(1 {sign} e)^2/16\n"
    assert by_line(AQA_30_SPEED, work) == {"2": "wrong" if slip else "correct"}


@pytest.mark.parametrize(
    ("said", "name", "whose"),
    [
        ("A's component along the line of centres after the impact is p.", "p", "A"),
        ("Let p be A's component along the line of centres after the impact.", "p", "A"),
        ("The component of B's velocity along the line of centres after the collision is q.", "q", "B"),
        ("p, q = components of A, B along the line of centres after impact", "q", "B"),
        ("Along the line of centres, after: A has p, B has q.", "q", "B"),
        ("After the impact A has p along the line of centres and u/2 across it.", "p", "A"),
        ("B moves off along the line of centres with speed q", "q", "B"),
    ],
)
@pytest.mark.parametrize("slip", [False, True])
def test_a_component_after_named_in_words_is_judged_not_taken_as_defined(
    said: str, name: str, whose: str, slip: bool
) -> None:
    # AQA M3 2007 Q6 (equal spheres, A at u at 30° to the line of centres, B at rest, e): along,
    # A has sqrt(3) u (1 - e)/4 after and B sqrt(3) u (1 + e)/4 (B moves off along the line).
    # The other body's value is a slip: wrong, never "correct" as a definition of the name.
    right, other = ("1 - e", "1 + e") if whose == "A" else ("1 + e", "1 - e")
    work = f"{said}\n{name} = √3 u ({other if slip else right})/4\n"
    assert by_line(AQA_30_SPEED, work) == {"2": "wrong" if slip else "correct"}


@pytest.mark.parametrize(
    "said",
    [
        "Let $p$ and $q$ be the $n$ components after.",
        "Let p, q be the components along the line of centres after the impact.",
        "p and q are the normal components after",
        "let p and q be the n-components after impact",
    ],
)
@pytest.mark.parametrize("slip", [False, True])
def test_two_components_after_named_in_words_without_their_bodies_are_a_then_b(said: str, slip: bool) -> None:
    # AQA M3 2007 Q6: along the line of centres A has sqrt(3) u (1 - e)/4 after and B sqrt(3) u (1 + e)/4;
    # two names said without bodies are A's then B's, as a teacher reads them: the values swapped are wrong
    a, b = ("1 + e", "1 - e") if slip else ("1 - e", "1 + e")
    work = f"{said}\np = √3 u ({a})/4\nq = √3 u ({b})/4\n"
    verdict = "wrong" if slip else "correct"
    assert by_line(AQA_30_SPEED, work)["2"] == verdict


@pytest.mark.parametrize(
    "said",
    [
        "Let θ be the angle between A's new path and the line of centres",
        "θ is the angle between the line of centres and A's path after the impact",
    ],
)
def test_an_angle_after_declared_as_the_angle_between_a_path_and_the_line(said: str) -> None:
    # AQA M3 2007 Q6: after, A has u/2 across and sqrt(3) u (1 - e)/4 along the line of centres,
    # so tan θ = (u/2)/(sqrt(3) u (1 - e)/4) = 2/(sqrt(3)(1 - e)); with (1 + e) it is wrong
    work = f"{said}\ntan θ = 2/(√3 (1 - e))\ntan θ = 2/(√3 (1 + e))\n"
    assert by_line(AQA_30_SPEED, work) == {"2": "correct", "3": "wrong"}


@pytest.mark.parametrize(
    "work",
    [
        "B: along = -15 cos 37.6° = -11.88\nB: across = {sign}15 sin 37.6° = {sign}{value}\n",
        "along l.o.c.: u_B = -15 cos 37.6° = -11.88\nperp. to l.o.c.: w_B = {sign}15 sin 37.6° = {sign}{value}\n",
        "Along the line of impact B has -15 cos 37.6° = -11.88\nAcross it B has {sign}15 sin 37.6° = {sign}{value}\n",
    ],
)
@pytest.mark.parametrize(
    ("sign", "value", "second"), [("", "9.15", "correct"), ("-", "9.15", "correct"), ("", "9.51", "wrong")]
)
def test_a_component_across_written_as_a_size_beside_a_signed_one_along(
    work: str, sign: str, value: str, second: str
) -> None:
    # Notes Example 4.C.11: B at 15 m/s, at 37.6° to the line of impact, moving toward A: along
    # -15 cos 37.6° = -11.88 (n from A toward B), across 15 sin 37.6° = 9.15 in size (derive's t
    # has it negative). Unsigned it is a size, signed derive's; 9.51 is a slip either way.
    lines = by_line("notes-4c11-two-spheres", work.format(sign=sign, value=value))
    assert lines == {"1": "correct", "2": second}


@pytest.mark.parametrize(
    "said",
    [
        "A's component along the line of centres is a = {v}",
        "Let a be A's component along the line of centres before the impact: a = {v}",
        "The component of A's velocity along the line of centres before is a = {v}",
    ],
)
@pytest.mark.parametrize(("v", "verdict"), [("4 cos 60° = 2", "correct"), ("4 sin 60° = 3.46", "wrong")])
def test_a_component_named_in_words_and_valued_on_the_same_line(said: str, v: str, verdict: str) -> None:
    # OCR FM 2023 (A 4 m/s at 60° to the line of centres): along 4 cos 60° = 2; resolving with sin
    # is the wrong axis, wrong, never "correct" as the definition of a
    assert by_line(OCR_FM, said.format(v=v) + "\n") == {"1": verdict}


def test_a_letter_inside_the_value_after_has_is_not_a_name_declared() -> None:
    # "A has U cos 30°": U is a factor of the value, not the name of A's component
    from derive.checking.context import Context
    from derive.checking.wordnames import in_words

    ctx = Context(derive.solve(derive.load(AQA_30_SPEED)), None)
    assert "U" not in in_words("Along the line of centres A has U cos 30° = √3/2 U, across it U/2", ctx)
    assert set(in_words("Along the line of centres, after: A has p, B has q.", ctx)) == {"p", "q"}


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("mu = m v_A + 3m v_B\n", "correct"),
        ("mu = 3m v_A + m v_B\n", "wrong"),  # the masses swapped: m × u, never a name "mu" defined
        ("mu + 0 = 3m v_A + m v_B\n", "wrong"),
    ],
)
def test_mu_alone_on_the_left_is_m_times_u_even_when_the_momentum_is_wrong(tmp_path, work: str, expected: str) -> None:
    # m at u hits 3m at rest: the momentum m u = m v_A + 3m v_B (worked by hand); with the
    # masses swapped m u = 3m v_A + m v_B is false, a slip, not a definition of a name "mu".
    problem = tmp_path / "m3m.toml"
    problem.write_text(
        'title = "t"\nkind = "direct"\n[given]\nm = "kg"\nu = "m/s"\ne = "e"\n'
        'm_A = "m"\nm_B = "3*m"\nv_A1 = "u"\nv_B1 = "0 m/s"\n'
    )
    assert by_line(str(problem), work) == {"1": expected}
    if expected == "wrong":
        slip = next(i for i in report(str(problem), work).items if i.status == "wrong")
        assert "masses_swapped" in {d.mistake for d in slip.diagnosis}


#: CIE 9231 Nov 2014 Q1: A (2m) at 4u meets B (m) at 3u head on: the speeds before are 4u and 3u
#: (B's velocity along A's direction is -3u). OCR M3 2007: A at 15 m/s at alpha to the line of
#: centres (sin alpha = 0.8), B at 12 m/s along it: the speeds before are 15 and 12 m/s.
HEAD_ON = "cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses"


@pytest.mark.parametrize(
    "work",
    [
        "speed of A before = 4u\nspeed of B before = 3u",
        "initial speed of A = 4u\ninitial speed of B = 3u",
        "A's speed before = 4u\nB's initial speed = 3u",
        "Speed of A before $= 4u$, speed of B before $= 3u$.",
        "A initial speed = 4u\nB initial velocity = -3u",
        "initial velocity of A = 4u\nvelocity of B before = -3u",
    ],
)
def test_a_speed_before_said_in_words_is_the_size_of_the_velocity_before(work: str) -> None:
    assert set(by_line(HEAD_ON, work).values()) == {"correct"}


@pytest.mark.parametrize(
    "work",
    [
        "speed of A before = 4u\nspeed of B before = -3u",
        "A initial speed = 4u\nB initial velocity = 3u",
        "initial velocity of A = 4u\nvelocity of B before = 3u",
    ],
)
def test_a_speed_before_in_words_set_to_a_wrong_value_is_wrong_not_unread(work: str) -> None:
    assert by_line(HEAD_ON, work) == {"1": "correct", "2": "wrong"}


def test_a_speed_before_in_an_oblique_impact_is_the_speed_not_a_component() -> None:
    got = by_line("ocr-m3-2007-oblique-sin-alpha-0p8", "speed of A before = 15 m/s\nspeed of B before = 12 m/s")
    assert got == {"1": "correct", "2": "correct"}


#: Giancoli 7-18 (0.060 kg at 28 m/s, 45° to a wall, same speed back): the normal component
#: 28 cos 45° = 19.80 m/s reverses, so the ball's change of momentum along the normal is
#: 0.060(-19.80 - 19.80) = -2.376 kg m/s and the impulse on it has size 2.376 N s.
TENNIS = "giancoli-7-18-tennis-ball-wall-45deg"


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("Dp = 0.060(-19.80 - 19.80) = -2.376\nimpulse = 2.38 N s", ["correct", "correct"]),
        (
            "change in momentum = 0.060(-19.80 - 19.80) = -2.376\nso the impulse on the ball = 2.376 N s",
            ["correct"] * 2,
        ),
        ("impulse = change in momentum = 0.060(19.80 + 19.80) = 2.376 N s", ["correct"]),
        ("Δp = 0.060(-19.80 - 19.80) = -2.367\nimpulse exerted by the wall = 2.367 N s", ["wrong", "carried"]),
        ("dp = 0.060(-19.80 - 19.80) = -2.367\nJ = 2.367 N s", ["wrong", "carried"]),
        ("impulse = change in momentum = 0.060(19.80 - 19.80) = 0", ["wrong"]),
        ("the impulse = 3.1 N s", ["wrong"]),
    ],
)
def test_an_impulse_or_a_change_of_momentum_in_words_is_the_impulse(work: str, expected: list) -> None:
    got = by_line(TENNIS, work)
    assert [got.get(str(k + 1)) for k in range(len(expected))] == expected


# A name declared for a body's SPEED with words that say it moves backwards ("(A bounces back)",
# "A moving backwards") is the mark scheme's v: minus the velocity along derive's +n, the
# convention unchanged for everything else. 2 kg at 5 m/s hits 3 kg at rest, e = 0.8, by hand:
# 10 = 2a + 3b, b - a = 4 -> a = -0.4, b = 3.6: A bounces back at s = 0.4.
def test_a_speed_declared_backwards_is_minus_the_velocity(tmp_path) -> None:
    problem = tmp_path / "back.toml"
    problem.write_text(
        'title = "t"\nkind = "direct"\n[given]\nm_A = "2 kg"\nm_B = "3 kg"\nv_A1 = "5 m/s"\nv_B1 = "0 m/s"\ne = "0.8"\n'
    )
    work = (
        "Let s be the speed of A after the impact (A bounces back).\n"
        "2(5) + 3(0) = -2s + 3v_B\nv_B + s = 0.8(5)\nv_B = 4 - s\n10 = -2s + 12 - 3s\n5s = 2\ns = 0.4 m/s\n"
    )
    assert set(by_line(str(problem), work).values()) == {"correct"}


def test_a_speed_declared_backwards_in_letters_is_said_so_not_as_the_convention_turned() -> None:
    # CAIE 9231 Nov 2014 Q1 (2m at 4u, m at 3u toward it): 8mu - 3mu = -2ms + mw and
    # w + s = 7eu give 3s = 7eu - 5u, s = u(7e - 5)/3 = -v_A2 (mark scheme v_A = (5 - 7e)u/3).
    work = (
        "Let s be the speed of A after the impact, A moving backwards, and w the velocity of B.\n"
        "2m(4u) - m(3u) = -2ms + mw\nw + s = 7eu\n3s = 7eu - 5u\ns = u(7e - 5)/3\n"
    )
    r = report("cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses", work)
    assert {i.status for i in r.items if i.kind == "line"} == {"correct"}
    said = " ".join(r.notes)
    assert "s is -v_A2" in said
    assert "positive direction is opposite" not in said  # not derive's n turned for every name


def test_mu_before_a_chain_that_ends_in_letters_is_m_times_u_not_a_mass() -> None:
    # Edexcel M2 June 2024 Q5 (m at u hits 2m at rest, P reverses), x P's speed back, y Q's
    # velocity: mu = -mx + 2my, y + x = eu -> mu = 2meu - 3mx, x = u(2e - 1)/3 (= -v_A2). The
    # chain's last side starts with a digit (2meu): it is no mass's number, mu stays m × u.
    work = "mu = -mx + 2my\ny + x = eu\nmu = -mx + 2m(eu - x) = 2meu - 3mx\nx = u(2e - 1)/3\n"
    assert set(by_line("edexcel-m2-2024-june-q5-m-hits-2m-speed-of-p", work).values()) == {"correct"}


def test_v_beside_v_primed_is_the_velocity_before_where_the_bodies_move_off_together() -> None:
    # OpenStax's v and v′: MSU bullet (0.020 kg at 300 m/s into 4.0 kg, they move together), by
    # hand: v′ = 0.020(300)/4.02 = 6/4.02 = 1.4925; KE before ½(0.020)(300²) = 900 J. v is the
    # bullet's velocity before (v′ the one after), not the common velocity.
    work = (
        "Bullet m = 0.020 kg at 300 m/s, block M = 4.0 kg at rest.\n"
        "v' = m v/(m + M) = 0.020(300)/4.02 = 6/4.02 = 1.49 m/s\n"
        "KE before = 1/2 m v^2 = 0.5(0.020)(300)^2 = 900 J\n"
    )
    assert by_line(BULLET, work) == {"1": "correct", "2": "correct", "3": "correct"}


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("impulse = 2(4 + 1.6) = 11.2 N s", "correct"),
        ("impulse = 2(-1.6 - 4) = -11.2 N s", "correct"),  # in the student's own sense
        ("impulse = 2(4 - 1.6) = 4.8 N s", "wrong"),  # right arithmetic, the rebound's sign lost
        ("impulse = -4.8 N s", "wrong"),
    ],
)
def test_the_word_impulse_alone_is_the_impulse_in_either_sense(line: str, expected: str) -> None:
    # Edexcel M2 wall (2 kg at 4 m/s, e = 0.4), by hand: rebound 1.6 m/s, impulse 2(4 + 1.6) = 11.2
    # N s. "impulse" on its own names it (as "the magnitude of the impulse" does), its sign the
    # student's: -11.2 is right, 4.8 (and -4.8) is not.
    assert by_line("edexcel-m2-ball-rebounds-from-wall", line) == {"1": expected}


@pytest.mark.parametrize(("answer", "expected"), [("1000", "correct"), ("1500", "wrong")])
def test_the_mass_asked_for_named_in_words_is_the_students_m(tmp_path, answer: str, expected: str) -> None:
    # A 1500 kg van at 5 m/s runs into a parked car (mass M); they move on together at 3 m/s.
    # By hand: 7500 = 3(1500 + M) -> M = 1000 kg. "mass of the parked car" names the one mass to find.
    problem = tmp_path / "van.toml"
    problem.write_text(
        'title = "t"\nkind = "direct"\n[given]\nm_A = "1500 kg"\nm_B = "? kg"\ne = "?"\n'
        'v_A1 = "5 m/s"\nv_B1 = 0\nv_A2 = "3 m/s"\nv_B2 = "3 m/s"\n'
    )
    work = f"1500(5) = (1500 + M)(3)\n7500 = 4500 + 3M\nAnswer: mass of the parked car = {answer} kg\n"
    assert by_line(str(problem), work) == {"1": "correct", "2": "correct", "3": expected}


@pytest.mark.parametrize(
    ("problem", "work", "status"),
    [
        # BYJU'S (4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5): v_A2 = 4, v_B2 = 8, so the impulse on A
        # is 4(4 - 12) = -32 N s and on B 8(8 - 4) = +32 N s along the way they move
        ("byjus-4kg-ball-catches-8kg-ball", "impulse on A = 32 N s", "wrong"),
        ("byjus-4kg-ball-catches-8kg-ball", "impulse on A = -32 N s", "correct"),
        ("byjus-4kg-ball-catches-8kg-ball", "impulse on B = 32 N s", "correct"),
        ("byjus-4kg-ball-catches-8kg-ball", "change in momentum of B = -32 N s", "wrong"),
        # MSU bullet (0.020 kg at 300 m/s into 4.0 kg at rest): w = 6/4.02 = 1.4925 m/s; the impulse on
        # the block (B) is 4.0(1.4925) = +5.97 N s, on the bullet (A) 0.020(1.4925 - 300) = -5.97 N s
        (BULLET, "impulse on A = 5.97 N s", "wrong"),
        (BULLET, "impulse on A = -5.97 N s", "correct"),
        (BULLET, "impulse on B = 5.97 N s", "correct"),
    ],
)
def test_an_impulse_on_a_body_named_is_that_bodys(problem: str, work: str, status: str) -> None:
    assert by_line(problem, work) == {"1": status}


def test_an_impulse_on_a_body_is_said_as_written() -> None:
    from derive.checking.words import glossary, notes_in_words

    solution = derive.solve(derive.load("byjus-4kg-ball-catches-8kg-ball"))
    notes = derive.check(solution, derivation="impulse on A = -32 N s").notes
    said = " ".join(notes_in_words(notes, glossary(solution, ["J_n"])))
    assert "impulse on A: read as the impulse on A along" in said, said


def test_a_reversed_frame_said_turns_both_impulses() -> None:
    # B toward A positive (the givens written -12 and -4): the impulse on A is +32, on B -32
    work = "v_A1 = -12, v_B1 = -4\nimpulse on A = 32 N s\nimpulse on B = -32 N s"
    assert set(by_line("byjus-4kg-ball-catches-8kg-ball", work).values()) == {"correct"}


# --- the statement's letters for the bodies, and names declared by them in words ----------------
@pytest.mark.parametrize(
    ("problem", "expected"),
    [
        # "A smooth sphere P lies at rest ... a second identical sphere Q, moving on the plane, collides
        # with P": derive's moving body A is Q, the one at rest (v_B1 = 0) is P.
        ("edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta", {"P": "B", "Q": "A"}),
        # "sphere P of mass 2m moves at speed u ... strikes ... sphere Q of mass m that is at rest"
        ("edexcel-m2-2003-january-q6-2m-hits-m-e-one-third", {"P": "A", "Q": "B"}),
    ],
)
def test_the_statements_letters_are_matched_to_the_bodies_by_which_is_at_rest(problem: str, expected: dict) -> None:
    from derive.checking.context import Context
    from derive.checking.statementbodies import statement_bodies

    assert statement_bodies(Context(derive.solve(derive.load(problem)), None)) == expected


M4_2005 = "edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta"


def test_names_declared_by_the_statements_letters_are_those_bodies() -> None:
    # Q (mass m, speed u at alpha to the line of centres) hits P at rest: along the line of centres
    # p + q = u cos a, q - p = e u cos a -> p = u cos a (1 - e)/2; Q keeps u sin a across, so
    # tan(beta) = u sin a / p = 2 tan a/(1 - e), the printed result.
    work = (
        "Let p = Q after, q = P after, both along the line of centres.\n"
        "m u cos α = m p + m q\nq - p = e u cos α\np = (1/2) u cos α (1 - e)\n"
        "tan β = u sin α / p = 2 tan α / (1 - e)\n"
    )
    assert by_line(M4_2005, work) == {"2": "correct", "3": "correct", "4": "correct", "5": "correct"}


def test_nel_the_wrong_way_round_in_the_statements_letters_is_wrong() -> None:
    # With p for Q (A) and q for P (B), separation is q - p: p - q = e u cos a reverses it.
    work = "Let p = Q after, q = P after, both along the line of centres.\nm u cos α = m p + m q\np - q = e u cos α\n"
    r = report(M4_2005, work)
    (line3,) = [i for i in r.items if i.kind == "line" and i.name == "3"]
    assert line3.status == "wrong"
    assert "restitution_reversed" in [d.mistake for d in line3.diagnosis]


def test_a_prime_between_the_letter_and_the_body_is_after() -> None:
    # Beer & Johnston 13.13 (20 Mg at 0.5 m/s hits 35 Mg at rest, B leaves at 0.3 m/s): the engineers'
    # v'A, v'B are after, so vA, vB are before: 20(0.5) = 20 v'A + 35(0.3) -> v'A = -0.025 m/s;
    # e = (0.3 + 0.025)/0.5 = 0.65.
    work = (
        "vA = 0.5 m/s, vB = 0, v'B = 0.3 m/s\n20(0.5) = 20 v'A + 35(0.3)\nv'A = -0.025 m/s\n"
        "e = (v'B - v'A)/(vA - vB) = 0.65\n"
    )
    assert set(by_line("beer-johnston-13-13-railroad-cars-find-e", work).values()) == {"correct"}


def test_the_angle_of_a_moving_bodys_velocity_not_said_after_is_its_angle_before() -> None:
    # OCR M3 2007 Q4: A at 15 m/s at alpha to the line of centres, sin alpha = 0.8, so cos alpha = 0.6
    # and its component along is 15(0.6) = 9. Nothing says "after": theta is the angle A comes in at.
    work = (
        "Let θ be the angle between A's velocity and the line of centres.\n"
        "sin θ = 0.8, so cos θ = 0.6\nalong the line of centres A has 15 cos θ = 9\n"
    )
    assert by_line("ocr-m3-2007-oblique-sin-alpha-0p8", work) == {"2": "correct", "3": "correct"}


def test_m_glued_to_a_name_of_the_students_own_is_the_mass_times_it() -> None:
    # OCR MEI 2022 Q11 (equal masses m, A at speed U at 30° to the line of centres, e = 1/2): along the
    # line of centres a + b = (√3/2)U and b - a = (1/2)(√3/2)U -> b = 3√3U/8, a = √3U/8. "ma + mb"
    # is m a + m b, as "mx + my" is where m is a given.
    work = (
        "let U = v_A1\n"
        "Momentum along the line of centres: ma + mb = m(√3/2)U\n"
        "NEL: b − a = ½ (√3/2)U\nb = 3√3U/8, a = √3U/8\n"
    )
    found = by_line("ocr-mei-fmm-2022-offset-spheres-symbolic", work)
    assert [found.get(n) for n in ("2", "3", "4")] == ["correct"] * 3


def test_names_declared_with_be_and_a_possessive_are_declared() -> None:
    # "Let x be A's velocity after and y be B's velocity after": read as declared, not guessed from
    # the relations (a slip in them cannot move what the words said). BYJU'S: 4 kg at 12 m/s catches
    # 8 kg at 4 m/s, e = 0.5: 4(12) + 8(4) = 4x + 8y, y - x = 0.5(12 - 4) -> x = 4, y = 8.
    work = (
        "Let x be A's velocity after and y be B's velocity after, both in A's direction.\n"
        "CLM: 4(12) + 8(4) = 4x + 8y\nNEL: y - x = 0.5(12 - 4)\nx = 4, y = 8\n"
    )
    r = report("byjus-4kg-ball-catches-8kg-ball", work)
    assert "x: A's velocity after the impact (as you declared)." in r.names
    assert "y: B's velocity after the impact (as you declared)." in r.names
    assert set(by_line("byjus-4kg-ball-catches-8kg-ball", work).values()) == {"correct"}


def test_the_statements_letters_name_the_bodies_by_the_masses_it_gives_them() -> None:
    # Edexcel M2 June 2013 Q5: "Particles P (mass 2m) and Q (mass m)", Q at rest, P at u; after,
    # x for P and y for Q: 2mu = 2mx + my; x = u/2, y = u (KE after ¼mu² + ½mu² = ¾mu²).
    # (v_P)_2 and (v_Q)_2 are P's and Q's velocities after, derive's A and B by their masses.
    head = "$m_P = 2m$, $m_Q = m$\n$(v_P)_2 = x$, $(v_Q)_2 = y$\n"
    right = lines("edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters", head + "$2mu = 2mx + my$\n$x = u/2$\n")
    assert [right[n][0] for n in (2, 3, 4)] == ["correct"] * 3
    swapped = lines("edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters", head + "$2mu = 2my + mx$\n")
    assert swapped[3][0] == "wrong"


def test_velocity_names_typed_without_underscores_and_the_unmarked_one_after() -> None:
    # OCR M3 Jan 2006: A (5 kg) at 4 across the line of centres, B (2 kg) at 4 along it toward A,
    # e = 0.75. Along x: 5(0) + 2(-4) = -8 = 5 vAx + 2 vBx; vBx - vAx = 0.75(0 + 4) = 3, so
    # 7 vAx = -8 - 6 = -14, vAx = -2, vBx = 1. "vAx1" is A's before, so "vAx" (no mark) is after;
    # "2 vBx" is 2 times a name, not the number 2 and words.
    work = (
        "x along the line of centres, y along the common tangent\n5 vAx1 + 2 vBx1 = 5 vAx + 2 vBx\n"
        "-8 = 5 vAx + 2 vBx\nvBx - vAx = 0.75(vAx1 - vBx1) = 3\n7 vAx = -14\n"
    )
    found = lines("ocr-m3-2006-oblique-a-across-centres", work + "vAx = -2, vBx = 1\n")
    assert [found[n][0] for n in (2, 3, 4, 5, 6)] == ["correct"] * 5
    assert lines("ocr-m3-2006-oblique-a-across-centres", work + "vAx = 2\n")[6][0] == "wrong"


def test_a_greek_name_set_equal_to_masses_alone_is_the_students_own_name() -> None:
    # Edexcel M2 June 2013 Q5: P (2m), Q (m). The reduced mass μ = (2m)(m)/(3m) = 2m/3, typed "mu":
    # not m times u (a momentum is never a mass alone); 3m/2 is worked wrongly. "2mu" in the
    # momentum is still 2 m u: 2mu = 2m v_A2 + m v_B2 holds (u/2 and u).
    problem = "edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters"
    assert lines(problem, "mu = (2m)(m)/(3m) = 2m/3\n")[1][0] == "correct"
    assert lines(problem, "mu = (2m)(m)/(3m) = 3m/2\n")[1][0] == "wrong"
    assert lines(problem, "2mu = 2m v_A2 + m v_B2\n")[1][0] == "correct"
