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
