"""Student names read as a grammar (issue #31, names): a base letter with a body mark, a time
mark and a component mark, in any order and grouping (``v_{1i}``, ``v_{i,1}``, ``v1i``,
``v_1^i``; ``vAn'``, ``(v_A)_n'``; ``v_{x,f}``; ``p_i``; ``KE_f``), decided from the whole
derivation; givens restated in the student's names declare them.

Values worked by hand:

- byjus 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: momentum 48 + 32 = 80, approach 8,
  separation 4; 4 v1 + 8 (v1 + 4) = 80 gives v_1f = 4, v_2f = 8.
- OCR M3 Jan 2006 Q4 (5 kg A across the line of centres at 4 m/s, 2 kg B at 4 m/s toward A along
  it, e = 0.75): 5(0) + 2(-4) = -8 = 5a + 2b, b - a = 0.75(4) = 3, so a = -2, b = 1; the t
  components stay 4 and 0; A's speed after sqrt(4 + 16) = 4.47, B's 1.
- OCR M2 2012 particle (0.8 kg at 4 m/s into a wall, e = 0.3): back at 1.2 m/s; the impulse
  0.8 (1.2 + 4) = 4.16 N s.
- MSU bullet (0.020 kg at 300 m/s lodges in 4.0 kg at rest): p = 6.0, v' = 6.0/4.02 = 1.49;
  KE 0.5(0.020)(300²) = 900 J before, 0.5(4.02)(1.49²) = 4.46 J after, a change of -896 J.
- OCR M2 2006 spheres (2 kg at 5, 1 kg at -5, e = 0.8): total momentum 10 - 5 = 5 (15 adds B's
  momentum though it moves the other way).
"""

from __future__ import annotations

import pytest

import derive
from derive.mathtext.reader import read_relations


def statuses(problem: str, work: str) -> dict[int, str]:
    """Line -> its worst status (wrong before carried before not read before correct)."""
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    worst = ("wrong", "carried", "error", "not read", "not checked", "correct")
    out: dict[int, str] = {}
    for i in report.items:
        if i.kind == "line" and i.name.isdigit():
            n, old = int(i.name), out.get(int(i.name))
            out[n] = i.status if old is None or worst.index(i.status) < worst.index(old) else old
    return out


CATCHES = "byjus-4kg-ball-catches-8kg-ball"


@pytest.mark.parametrize(
    ("i1", "i2", "f1", "f2"),
    [
        ("v_{1i}", "v_{2i}", "v_{1f}", "v_{2f}"),
        ("v_{i,1}", "v_{i,2}", "v_{f,1}", "v_{f,2}"),
        ("v_1^i", "v_2^i", "v_1^f", "v_2^f"),
        ("v1i", "v2i", "v1f", "v2f"),
        ("v_{1,i}", "v_{2,i}", "v_{1,f}", "v_{2,f}"),
    ],
)
def test_digits_are_bodies_where_i_and_f_are_times(i1: str, i2: str, f1: str, f2: str) -> None:
    work = "\n".join(
        [
            f"Ball 1: $m_1 = 4$ kg, ${i1} = 12$ m/s; ball 2: $m_2 = 8$ kg, ${i2} = 4$ m/s",
            f"$m_1 {i1} + m_2 {i2} = m_1 {f1} + m_2 {f2}$",
            f"${f2} - {f1} = 0.5\\,({i1} - {i2})$",
            f"$4 {f1} + 8 {f2} = 80$",
            f"${f2} - {f1} = 4$",
            f"${f1} = 4$ m/s, ${f2} = 8$ m/s",
        ]
    )
    found = statuses(CATCHES, work)
    assert all(found.get(n) == "correct" for n in (2, 3, 4, 5, 6)), found


def test_a_slip_in_names_with_marks_is_found_at_its_line() -> None:
    work = "\n".join(
        [
            "$m_1 v_{1i} + m_2 v_{2i} = m_1 v_{1f} + m_2 v_{2f}$",
            r"$v_{1f} - v_{2f} = 0.5\,(v_{1i} - v_{2i})$",  # restitution the wrong way round
        ]
    )
    found = statuses(CATCHES, work)
    assert found == {1: "correct", 2: "wrong"}


def test_a_name_glued_to_its_mark_before_a_thin_space_is_no_unit_vector() -> None:
    (r,) = read_relations(r"$v_{1f} = \frac{m_1 - m_2}{m_1 + m_2}\,v_{1i}$")
    assert r.sides[-1].endswith("v_1i")


ACROSS = "ocr-m3-2006-oblique-a-across-centres"


@pytest.mark.parametrize(
    ("an", "bn", "at", "a_", "b_"),
    [
        ("vAn'", "vBn'", "vAt'", "vA'", "vB'"),
        ("(v_A)_n'", "(v_B)_n'", "(v_A)_t'", "v_A'", "v_B'"),
        ("v_{An}'", "v_{Bn}'", "v_{At}'", "v_{A}'", "v_{B}'"),
    ],
)
def test_glued_and_bracketed_primes_are_after(an: str, bn: str, at: str, a_: str, b_: str) -> None:
    plain = "v" in an[:1] and "{" not in an
    lines = [
        "vAn = 0, vAt = 4" if plain else "$(v_A)_n = 0$, $(v_A)_t = 4$",
        f"$5(0) + 2(-4) = 5{an} + 2{bn}$",
        f"${bn} - {an} = 0.75(0 + 4) = 3$",
        f"${an} = -2$, ${bn} = 1$",
        f"${at} = 4$",
        f"${a_} = \\sqrt{{2^2 + 4^2}} = 4.47$ m/s",
        f"${b_} = 1$ m/s",
    ]
    found = statuses(ACROSS, "\n".join(lines))
    assert all(found.get(n) == "correct" for n in range(2, 8)), found


WALL = "ocr-m2-2012-particle-hits-wall"


def test_givens_restated_declare_the_names_and_x_may_point_out_of_the_wall() -> None:
    work = "\n".join(
        [
            "Given: $m = 0.8$ kg, $v = 4$ m/s, e = 0.3",
            "x away from the wall:",
            "$v_{x,i} = -v = -4$ m/s",
            "$v_{x,f} = 0.3 v = 1.2$ m/s",
            "$J_x = m(v_{x,f} - v_{x,i}) = 0.8(1.2 + 4) = 4.16$ N s",
        ]
    )
    found = statuses(WALL, work)
    assert found.get(1) in ("correct", "not read", None)
    assert all(found.get(n) == "correct" for n in (3, 4, 5)), found


BULLET = "msu-lectureonline-bullet-lodges-in-block"


def test_momentum_and_energy_by_time_marks_and_a_negative_change() -> None:
    work = "\n".join(
        [
            "p_i = p_f",
            "p_i = 0.020(300) + 4.0(0) = 6.0 kg m/s",
            "p_f = (0.020 + 4.0) v' = 4.02 v'",
            "v' = 6.0/4.02 = 1.49 m/s",
            "KE_i = 0.5(0.020)(300)^2 = 900 J",
            "KE_f = 0.5(4.02)(1.49)^2 = 4.46 J",
            "ΔKE = 4.46 - 900 = -896 J",
        ]
    )
    found = statuses(BULLET, work)
    assert all(found.get(n) == "correct" for n in range(1, 8)), found


def test_the_total_momentum_before_is_worked_with_both_signs() -> None:
    work = "\n".join(
        [
            "p_i = p_f",
            "p_i = 2(5) + 1(5) = 15",  # B moves the other way: 2(5) + 1(-5) = 5
        ]
    )
    found = statuses("ocr-m2-2006-spheres-meet-at-5-ke-lost", work)
    assert found.get(2) == "wrong", found


def test_primes_before_the_subscript_and_energies_by_time() -> None:
    # byjus: KE 0.5(4)(144) + 0.5(8)(16) = 288 + 64 = 352 J before; 0.5(4)(16) + 0.5(8)(64) = 32 + 256
    # = 288 J after; the change 288 - 352 = -64 J; A's alone after 32 J.
    work = "\n".join(
        [
            "$m_1 v_1 + m_2 v_2 = m_1 v'_1 + m_2 v'_2$",
            "$4(12) + 8(4) = 4 v'_1 + 8 v'_2$",
            "$v'_2 - v'_1 = 0.5(12 - 4) = 4$",
            "$v'_1 = 4$, $v'_2 = 8$",
            r"$K_i = \frac12 (4)(12)^2 + \frac12 (8)(4)^2 = 352$ J",
            r"$K_f = \frac12 (4)(4)^2 + \frac12 (8)(8)^2 = 288$ J",
            r"$\Delta K = 288 - 352 = -64$ J",
            r"$K_{1f} = \frac12 (4)(4^2) = 32$ J",
        ]
    )
    found = statuses(CATCHES, work)
    assert all(found.get(n) == "correct" for n in range(1, 9)), found
    assert statuses(CATCHES, r"$K_{1f} = \frac12 (4)(8^2) = 128$ J") == {1: "wrong"}  # B's speed in A's energy


def test_time_words_in_subscripts_and_in_brackets() -> None:
    work = "\n".join(
        [
            r"$m_A v_{A,\text{before}} + m_B v_{B,\text{before}} = m_A v_{A,\text{after}} + m_B v_{B,\text{after}}$",
            "$v_{B,after} - v_{A,after} = 0.5 (v_{A,before} - v_{B,before})$",
            "$p_{A,i} = 4(12) = 48$",
            "$p_{B,f} = 8(8) = 64$",
        ]
    )
    found = statuses(CATCHES, work)
    assert all(found.get(n) == "correct" for n in range(1, 5)), found
    assert statuses(CATCHES, "$p_{B,f} = 8(4) = 32$") == {1: "wrong"}  # B's momentum before, not after


PUCK = "openstax-cp-8-30-puck-bounces-off-goalie"


@pytest.mark.parametrize(("a", "b"), [("puck", "goalie"), ("p", "g")])
def test_the_statement_s_words_for_the_bodies_are_body_marks(a: str, b: str) -> None:
    # OpenStax 8.30 (0.150 kg puck at 35.0 m/s, 70.0 kg goalie at rest, elastic): the relative
    # velocity reverses, v_g' - v_p' = 35.0; momentum m_p v_p = m_p v_p' + m_g v_g'.
    work = "\n".join(
        [
            f"$m_{{{a}}} v_{{{a},i}} = m_{{{a}}} v_{{{a},f}} + m_{{{b}}} v_{{{b},f}}$",
            f"$v_{{{b},f}} - v_{{{a},f}} = v_{{{a},i}}$",
        ]
    )
    assert statuses(PUCK, work) == {1: "correct", 2: "correct"}
    swapped = f"$v_{{{a},f}} - v_{{{b},f}} = v_{{{a},i}}$"
    assert statuses(PUCK, swapped) == {1: "wrong"}


DISCS = "ocr-fm-2023-oblique-discs-60deg"


def test_digits_with_a_component_and_a_time_are_bodies_in_an_oblique_impact() -> None:
    # OCR FM 2023 (5 kg A at 4 m/s, 60° to the line of centres; 3 kg B at 6 m/s toward A; e = 3/4;
    # mark scheme v_Ax = -13/4, v_Bx = 11/4): along x 5(2) + 3(-6) = -8 = 5a + 3b, b - a = 0.75(8) = 6,
    # so a = -3.25, b = 2.75; across 4 sin 60° = 3.46 unchanged.
    work = "\n".join(
        [
            r"$v_{1x,i} = 4\cos 60° = 2$, $v_{1y,i} = 4\sin 60° = 3.46$, $v_{2x,i} = -6$",
            "$5 v_{1x,i} + 3 v_{2x,i} = 5 v_{1x,f} + 3 v_{2x,f}$",
            "$v_{2x,f} - v_{1x,f} = 0.75(2 + 6) = 6$",
            "$v_{1x,f} = -3.25$, $v_{2x,f} = 2.75$",
            "$v_{1y,f} = v_{1y,i} = 3.46$",
        ]
    )
    found = statuses(DISCS, work)
    assert all(found.get(n) == "correct" for n in range(1, 6)), found
    slip = "$5(2) + 3(6) = 28 = 5 v_{1x,f} + 3 v_{2x,f}$\n$v_{2x,f} - v_{1x,f} = 0.75(2 + 6) = 6$"  # B's sign
    assert statuses(DISCS, slip) == {1: "wrong", 2: "correct"}
    reversed_ = (
        "$v_{1x,f} - v_{2x,f} = 0.75(v_{1x,i} - v_{2x,i})$"  # the names alone say whose: not A's and B's swapped
    )
    assert statuses(DISCS, reversed_) == {1: "wrong"}


def test_givens_glued_to_their_units_on_one_line_declare_the_names_used_after() -> None:
    # MSU bullet: 0.020 x 300 = 6.0 = 4.020 V, V = 1.49 m/s.
    work = "\n".join(
        [
            "bullet m_b = 0.020kg u=300 m/s, block M = 4.0kg at rest",
            "m_b u = (m_b + M)V",
            "V = 6.0/4.02 = 1.49 m/s",
        ]
    )
    assert statuses(BULLET, work) == {1: "correct", 2: "correct", 3: "correct"}
    assert statuses(BULLET, work.replace("(m_b + M)V", "M V"))[2] == "wrong"  # the bullet's mass left out
