"""Problem files that say what the instructor means (issue #27): units beside names of the
same spelling, units after expressions, angles in pi or degrees, a condition on an angle.

Each test writes a problem file as a user would and solves it through the CLI; every number
asserted comes from a hand calculation written beside it.
"""

from __future__ import annotations

import json
import math
import textwrap
from pathlib import Path

import pytest


def solve_json(cli, tmp_path: Path, text: str, name: str = "p.toml") -> dict:
    """Write ``text`` to a file, ``derive solve FILE -f json``; the JSON (exit code 0 asserted)."""
    path = tmp_path / name
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    res = cli("solve", str(path), "-f", "json")
    assert res.code == 0, res.err
    return json.loads(res.out)


def solve_error(cli, tmp_path: Path, text: str) -> str:
    """The one-line error of a file derive refuses (exit 2)."""
    path = tmp_path / "p.toml"
    path.write_text(textwrap.dedent(text), encoding="utf-8")
    res = cli("solve", str(path))
    assert res.code == 2, res.out[:300]
    assert len(res.err.strip().splitlines()) == 1
    return res.err


# ----------------------------------------------------------------- 1. names and units


def test_a_length_beside_a_mass_named_m_is_a_length(cli, tmp_path: Path) -> None:
    """``d = "m"`` is a length symbol although a mass is named m (it was read as that mass)."""
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "A length d beside a mass m"
        kind = "direct"
        [given]
        m = "kg"
        d = "m"
        m_A = "m"
        m_B = "2*m"
        e = 0.5
        v_A1 = "4 m/s"
        v_B1 = 0
        """,
    )
    assert out["givens"]["d"] == {"value": None, "unit": "m"}
    assert out["givens"]["m_A"]["unit"] == "kg"  # m_A = "m": the mass m (a length cannot be a mass)
    # hand: m_A = m, m_B = 2m, u = 4, e = 1/2: v_B2 = m u (1 + e)/(3m) = 4*1.5/3 = 2
    assert out["results"]["v_B2"]["value"] == pytest.approx(2.0)


def test_a_given_named_s_leaves_the_unit_m_per_s_alone(cli, tmp_path: Path) -> None:
    """``u = "m/s"`` is a velocity symbol beside a given mass m and a given length s (it was
    read as m divided by s: "expected a velocity, but the expression is M L^-1")."""
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "A distance named s"
        kind = "direct"
        [given]
        m = "kg"
        s = "0.5 m"
        u = "m/s"
        m_A = "m"
        m_B = "2*m"
        e = 0.5
        v_A1 = "u"
        v_B1 = 0
        """,
    )
    assert out["givens"]["u"] == {"value": None, "unit": "m/s"}
    # hand: v_B2 = u (1 + e)/3 = u/2; v_A2 = u (1 - 2e)/3 = 0
    assert out["results"]["v_B2"]["value_expr"] == "u/2"
    assert out["results"]["v_A2"]["value"] == 0


# ----------------------------------------------------------------- 2. units after expressions


def test_a_unit_after_any_constant_expression(cli, tmp_path: Path) -> None:
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "Units after expressions"
        kind = "direct"
        [given]
        m_A = "1/3 kg"
        m_B = "2 kg"
        e = 1
        v_A1 = "3*sqrt(2) m/s"
        v_B1 = "-sqrt(2) m/s"
        """,
    )
    r2 = math.sqrt(2)
    assert out["givens"]["m_A"]["value"] == pytest.approx(1 / 3)
    assert out["givens"]["v_B1"]["value"] == pytest.approx(-r2)
    # hand, e = 1: v_B2 = (2 m_A v_A1 + (m_B - m_A) v_B1)/(m_A + m_B)
    #   = (2/3 * 3√2 - 5/3 √2)/(7/3) = (6√2 - 5√2)/7 = √2/7
    assert out["results"]["v_B2"]["value"] == pytest.approx(r2 / 7)


def test_units_after_expressions_convert_in_a_us_problem(cli, tmp_path: Path) -> None:
    """``1/2 lb`` weight and ``3*sqrt(2) ft/s`` in a US problem stay in slugs and ft/s."""
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "US units after expressions"
        kind = "direct"
        units = "US"
        [given]
        W_A = "1/2 lb"
        W_B = "1/2 lb"
        e = 1
        v_A1 = "3*sqrt(2) ft/s"
        v_B1 = 0
        """,
    )
    # equal masses, e = 1: they exchange velocities, v_B2 = 3√2 ft/s
    assert out["results"]["v_B2"]["value"] == pytest.approx(3 * math.sqrt(2))
    assert out["results"]["v_B2"]["unit"] == "ft/s"


def test_a_solve_condition_with_a_unit_after_an_expression_and_powers(cli, tmp_path: Path) -> None:
    """``s2 = 3*sqrt(2) m/s`` and ``b2 = 0.0625 m^2/s^2`` (a power of units) as conditions of
    solve stages."""
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "Find e from a speed after"
        kind = "chain"
        find = ["e", "k"]
        [given]
        m = "1 kg"
        u = "6 m/s"
        e = "?"
        k = "?"
        [[stage]]
        type = "impact"
        kind = "direct"
        given = { m_A = "m", m_B = "m", e = "e", v_A1 = "u", v_B1 = 0 }
        results = { v_B2 = "s2" }
        [[stage]]
        type = "solve"
        condition = "s2 = 3*sqrt(2) m/s"
        for = "e"
        [[stage]]
        type = "define"
        expr = "k*s2^2"
        result = "b2"
        [[stage]]
        type = "solve"
        condition = "b2 = 0.0625 m^2/s^2"
        for = "k"
        """,
    )
    # hand: equal masses, B at rest: v_B2 = u (1 + e)/2 = 3(1 + e) = 3√2 -> e = √2 - 1
    assert out["results"]["e"]["value"] == pytest.approx(math.sqrt(2) - 1)
    # k (3√2)^2 = 18 k = 1/16 -> k = 1/288
    assert out["results"]["k"]["value"] == pytest.approx(1 / 288)


def test_a_unit_in_place_of_a_name_says_where_it_goes(cli, tmp_path: Path) -> None:
    err = solve_error(
        cli,
        tmp_path,
        """
        title = "x"
        kind = "direct"
        [given]
        m_A = "sqrt(2)*kg"
        m_B = "3 kg"
        e = 0.8
        v_A1 = "4 m/s"
        v_B1 = 0
        """,
    )
    assert "'kg' is a unit: write it after the number" in err


def test_a_unit_after_an_expression_in_the_givens_is_refused_with_why(cli, tmp_path: Path) -> None:
    err = solve_error(
        cli,
        tmp_path,
        """
        title = "x"
        kind = "direct"
        [given]
        u = "m/s"
        m_A = "2 kg"
        m_B = "3 kg"
        e = 0.8
        v_A1 = "2*u m/s"
        v_B1 = 0
        """,
    )
    assert "may follow only a number or an expression of numbers" in err


# ----------------------------------------------------------------- 3. angles


def test_angles_in_pi_and_in_degrees_beside_an_angle_given(cli, tmp_path: Path) -> None:
    """``pi - pi/3 - leave`` and ``120 deg - leave`` (refused before: "cannot add a pure
    number and an angle")."""
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "Angles"
        kind = "oblique"
        find = ["theta_A2"]
        [given]
        m_A = "1 kg"
        m_B = "1 kg"
        e = 1
        leave = "20 deg"
        a = "pi - pi/3 - leave"
        b = "120 deg - leave"
        v_A1 = "2 m/s"
        v_B1 = 0
        [A]
        angle = "b"
        from = "+t"
        toward = "+n"
        [define]
        diff = "a - b"
        """,
    )
    # both are 180 - 60 - 20 = 100 degrees
    assert out["givens"]["a"]["value"] == pytest.approx(100)
    assert out["givens"]["b"]["value"] == pytest.approx(100)
    assert out["results"]["diff"]["value"] == pytest.approx(0, abs=1e-12)
    # 100 deg from +t toward +n: v_A1n = 2 sin 100 > 0, v_A1t = 2 cos 100; equal masses, e = 1:
    # A keeps only its t component, which points along -t: theta_A2 = 180 deg
    assert out["results"]["v_A2n"]["value"] == pytest.approx(0, abs=1e-12)
    assert out["results"]["v_A2t"]["value"] == pytest.approx(2 * math.cos(math.radians(100)))


def test_a_plain_number_added_to_an_angle_asks_for_its_unit(cli, tmp_path: Path) -> None:
    err = solve_error(
        cli,
        tmp_path,
        """
        title = "x"
        kind = "oblique"
        [given]
        m_A = "1 kg"
        m_B = "1 kg"
        e = 1
        leave = "20 deg"
        a = "120 - leave"
        v_A1 = "2 m/s"
        v_B1 = 0
        [A]
        angle = "a"
        from = "+t"
        toward = "+n"
        """,
    )
    assert "give the number its unit (120 deg)" in err


WALL_SOLVE = """
title = "A sphere meets a wall at 60 degrees to it and leaves at 30 degrees: find e"
kind = "chain"
find = ["e"]
[given]
m = "kg"
u = "m/s"
e = "?"
[[stage]]
type = "impact"
kind = "oblique"
given = { m_A = "m", e = "e", v_A1 = "u", theta = "60 deg" }
A = { angle = "theta", from = "+t", toward = "+n" }
B = { fixed = true, name = "wall" }
results = { theta_A2 = "leave" }
[[stage]]
type = "solve"
condition = "leave = CONDITION"
for = "e"
"""


@pytest.mark.parametrize("condition", ["-30 deg", "-30°", "-pi/6", "-30"])
def test_a_solve_stage_on_an_angle_after_a_wall(cli, tmp_path: Path, condition: str) -> None:
    """The angle after the wall (from the wall, toward +n: leaving, so -30 deg) fixes e. Before,
    "-30 deg" was compared with radians: "0 admissible values of e"."""
    out = solve_json(cli, tmp_path, WALL_SOLVE.replace("CONDITION", condition))
    # hand: along the wall u cos 60 stays; off it e u sin 60: tan 30 = e tan 60, e = 1/3
    assert out["results"]["e"]["value"] == pytest.approx(1 / 3)


def test_a_solve_stage_with_no_root_says_so(cli, tmp_path: Path) -> None:
    path = tmp_path / "p.toml"
    path.write_text(WALL_SOLVE.replace("CONDITION", "30 deg"), encoding="utf-8")
    res = cli("solve", str(path))
    assert res.code != 0
    assert "0 admissible values of e (it has no root" in res.err


# ----------------------------------------------------------------- 4. letters

AGAIN = """
title = "A strikes B, B rebounds from a wall: for which e do they collide again?"
kind = "chain"
find = FIND
[given]
m = "kg"
SPEED
e = "e"
[[stage]]
type = "impact"
kind = "direct"
given = { m_A = "m", m_B = "3*m", e = "e", v_A1 = "LETTER", v_B1 = 0 }
results = { v_A2 = "u_A", v_B2 = "u_B" }
[[stage]]
type = "impact"
kind = "direct"
given = { m_A = "3*m", e = "1/3", v_A1 = "u_B" }
A = { label = "B" }
B = { fixed = true, name = "wall" }
results = { v_A2 = "w_B" }
[[stage]]
type = "again"
behind = "u_A"
ahead = "w_B"
range_of = "e"
"""


def _again(find: str, speed: str, letter: str) -> str:
    return AGAIN.replace("FIND", find).replace("SPEED", speed).replace("LETTER", letter)


def test_a_range_whose_bound_holds_a_speed_letter_uses_that_it_is_positive(cli, tmp_path: Path) -> None:
    """``v_A1 = "m/s"``: a speed kept as a letter is positive, so the range of e is worked out
    (it said "the range depends on other letters"). Hand: u_A = u(1 - 3e)/4, u_B = u(1 + e)/4,
    w_B = -u_B/3; u_A - w_B = u(3 - 9e + 1 + e)/12 = u(1 - 2e)/3 > 0 for e < 1/2."""
    out = solve_json(cli, tmp_path, _again('["again"]', 'v_A1 = "m/s"', "v_A1"))
    assert out["results"]["again"]["expr"] == "e < 1/2"


def test_again_can_be_named_in_find_and_its_range_is_in_the_json(cli, tmp_path: Path) -> None:
    out = solve_json(cli, tmp_path, _again('["u_A", "w_B", "again"]', 'u = "m/s"', "u"))
    assert out["results"]["again"]["value"] is None
    assert out["results"]["again"]["expr"] == "e < 1/2"  # hand, above


def test_a_range_in_a_direct_problem_with_a_speed_letter(cli, tmp_path: Path) -> None:
    """Hand: m strikes 3m at rest, v_A2 = v_A1 (1 - 3e)/4 < 0 for e > 1/3 (v_A1 > 0)."""
    path = tmp_path / "p.toml"
    path.write_text(
        textwrap.dedent(
            """
            title = "A reverses for which e?"
            kind = "direct"
            range = { of = "e", where = "v_A2 < 0" }
            [given]
            m = "kg"
            m_A = "m"
            m_B = "3*m"
            e = "e"
            v_A1 = "m/s"
            v_B1 = 0
            """
        ),
        encoding="utf-8",
    )
    res = cli("solve", str(path))
    assert res.code == 0, res.err
    assert r"that is for $\frac{1}{3} < e$ and $e \leq 1$" in res.out


def test_a_stage_show_names_the_chain_givens(cli, tmp_path: Path) -> None:
    path = tmp_path / "p.toml"
    path.write_text(
        textwrap.dedent(
            """
            title = "A stage's show uses the chain's givens"
            kind = "chain"
            find = ["w"]
            [given]
            m = "kg"
            u = "m/s"
            e = "e"
            [[stage]]
            type = "impact"
            kind = "direct"
            given = { m_A = "m", m_B = "2*m", e = "e", v_A1 = "u", v_B1 = 0 }
            show = "v_B2 = u*(1 + e)/3"
            results = { v_B2 = "w" }
            """
        ),
        encoding="utf-8",
    )
    res = cli("solve", str(path))
    assert res.code == 0, res.err
    # hand: m at u strikes 2m at rest: v_B2 = m u (1 + e)/(3m)
    assert "it follows, as required" in res.out


def test_weights_carried_through_chain_names(cli, tmp_path: Path) -> None:
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "Weights through chain names"
        kind = "chain"
        find = ["w_A", "w_B", "T"]
        [given]
        W_bag = "20 lb"
        W_case = "30 lb"
        v = "10 ft/s"
        [[stage]]
        type = "impact"
        kind = "direct"
        given = { W_A = "W_bag", W_B = "W_case", e = 0.5, v_A1 = "v", v_B1 = 0 }
        results = { v_A2 = "w_A", v_B2 = "w_B", T_lost = "T" }
        """,
    )
    # hand, masses in the ratio 20 : 30: v_A2 = (20*10 - 30*0.5*10)/50 = 1 ft/s,
    # v_B2 = (20*10 + 20*0.5*10)/50 = 6 ft/s; T_lost = 1/2 (m_A m_B/(m_A + m_B)) (1 - e^2) v^2
    # = 1/2 (12/32.2)(0.75)(100) = 450/32.2 ft*lb (US: g = 32.2 ft/s^2)
    assert out["results"]["w_A"]["value"] == pytest.approx(1.0)
    assert out["results"]["w_B"]["value"] == pytest.approx(6.0)
    assert out["results"]["T"]["value"] == pytest.approx(450 / 32.2)


def test_a_closed_form_drops_a_velocity_given_as_zero(cli, tmp_path: Path) -> None:
    out = solve_json(
        cli,
        tmp_path,
        """
        title = "m at u strikes 2m at rest"
        kind = "direct"
        [given]
        m = "kg"
        u = "m/s"
        m_A = "m"
        m_B = "2*m"
        e = "e"
        v_A1 = "u"
        v_B1 = 0
        """,
    )
    for name in ("v_A2", "v_B2", "T_1", "T_lost"):
        assert "v_B1" not in out["results"][name]["expr"], name
    # hand: v_B2 = u (1 + e)/3
    assert out["results"]["v_B2"]["expr"] == "u*(e + 1)/3"
