"""Names a derivation never declares, placed by their values (derive/checking/byvalue.py).

A teacher reads an undeclared name as the quantity its value is, judges the line in that
reading, and keeps the reading on the lines after it. Each expected mark below is worked by hand
from the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines


def test_names_met_together_are_the_velocities_after_and_a_reversed_rule_is_the_slip() -> None:
    # 2m at 2u hits m at rest, e = 2/3: 4u = 2p + q, q - p = 4u/3 -> p = 8u/9, q = 20u/9.
    # The student writes p - q = 4c/3 (reversed): then 3p = 16c/3, p = 16c/9, q = 4c/9 (carried).
    # B at rest: its velocity before is 0, which no name is read as (any product of it is 0).
    work = """2m(2c) = 2m p + m q
4c = 2p + q
p - q = (2/3)(2c)
3p = 4c + 4c/3 = 16c/3
p = 16c/9
q = 4c - 2p = 4c - 32c/9 = 4c/9
"""
    got = worst_lines("aqa-m3-2014-symbolic-2m-hits-m", work)
    assert [got[n][0] for n in (1, 2)] == ["correct", "correct"]
    assert got[3] == ("wrong", "restitution_reversed")
    assert [got[n][0] for n in (4, 5, 6)] == ["carried"] * 3


def test_a_mass_name_is_read_as_the_mass_its_working_holds_for() -> None:
    # Cars couple: V = (45000 - 13200)/260000 = 0.1223 m/s; T after = ½(260000)(0.1223)² = 1944 J.
    # M V² without the ½ (3889 J) is the kinetic energy's wrong formula, M the total mass.
    work = """150000(0.300) + 110000(-0.120) = 260000 V
V = 31800/260000 = 0.1223 m/s
KE after = 1/2 M V^2 = 0.5(260000)(0.1223)^2 = 1944 J
KE after = M V^2 = 260000(0.1223)^2 = 3889 J
"""
    got = worst_lines("openstax-cp-8-train-cars-couple", work)
    assert got[3][0] == "correct"
    assert got[4] == ("wrong", "ke_formula")


def test_a_name_placed_by_a_later_line_shows_the_earlier_slip() -> None:
    # A (2 kg, 5 m/s) hits B (1 kg) at rest, A goes on at 2 m/s: 10 = 4 + v_B2, v_B2 = 6, e = 4/5.
    # The student copies A's 2 as 3: 10 = 6 + k, k = 4 (carried); k - 2 = 5e holds for the problem
    # with k as B's velocity after (it places k), and e = 2/5 is carried.
    work = """2(5) + 0 = 2(3) + k
k = 4
k - 2 = 5e
e = (4 - 2)/5 = 0.4
"""
    got = worst_lines("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", work)
    assert got[1] == ("wrong", "copied_wrong")
    assert [got[n][0] for n in (2, 3, 4)] == ["carried", "correct", "carried"]


def test_a_name_no_quantity_has_the_value_of_stays_not_read() -> None:
    # 0.3 kg at 3 m/s meets 0.2 kg at -2 m/s (e = 0.8): the total momentum is 0.5, so 0.7z = 0.5
    # gives z = 0.714, which is no quantity of the problem (v_A2 = -0.6, v_B2 = 3.4, the common
    # velocity 1.0, T lost 0.54 J, J 1.08 N s): nothing places z.
    work = "0.3(3) + 0.2(-2) = 0.7 z\n"
    got = worst_lines("aqa-m3-2007-spheres-approach-head-on", work)
    assert got[1][0] == "not read"


def test_a_name_inside_sin_or_cos_is_read_as_the_angle_given() -> None:
    # psi = 30 deg between A's path and the line of centres: sin 30° = 0.5, cos 30° = 0.866;
    # tan 30° = 0.577, not 0.5: q can only be the angle given, and the line is false in it.
    work = """sin q = 0.5
u cos q = 0.866u
tan q = 0.5
"""
    got = worst_lines("edexcel-m4-undated-q3-deflected-through-theta-line-at-30deg", work)
    assert [got[n][0] for n in (1, 2, 3)] == ["correct", "correct", "wrong"]


def test_givens_typed_together_on_the_left_are_their_product() -> None:
    # 2m at 2u meets m at -u: 3u = 2x + y and y - x = e(2u + u) = 3eu, so eu = (y - x)/3 holds
    # (x = u(1 - e), y = u(1 + 2e)); "eu" on the left is e times u, not a word nor a name of the
    # student's own; (y + x)/3 = u(2 + e)/3 is not eu.
    work = """3u = 2x + y
eu = (y - x)/3
ue = (y + x)/3
"""
    got = worst_lines("edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u", work)
    assert [got[n][0] for n in (1, 2, 3)] == ["correct", "correct", "wrong"]
