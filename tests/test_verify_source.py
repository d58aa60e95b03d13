"""The verifier reads the problem file itself (issue #26): a loader bug cannot hide.

derive's loader turns the TOML into a Problem; the verifier reads the same file with
its own TOML reading, unit table, angle reading and expression reader
(derive/verifier/facts/source.py), so a given misread after loading makes
``derive solve --verify`` fail, in Markdown and in LaTeX.
"""

from __future__ import annotations

import ast
import math
from dataclasses import replace
from pathlib import Path

import pytest
import sympy

import derive
import derive.problem.reader as loader
from derive.verifier import verify
from derive.verifier.facts import source

VERIFIER = Path(derive.__file__).parent / "verifier"


def _plant(monkeypatch: pytest.MonkeyPatch, change) -> None:
    """derive's loader with a bug: each top-level problem it builds is changed by ``change``."""
    build = loader.build_problem

    def buggy(data, ctx, name, seed=None):
        problem = build(data, ctx, name, seed)
        return change(problem) if seed is None else problem

    monkeypatch.setattr(loader, "build_problem", buggy)


def _scale_given(name: str, factor: sympy.Expr):
    def change(problem):
        givens = tuple(replace(g, value=g.value * factor) if g.name == name else g for g in problem.givens)
        return replace(problem, givens=givens)

    return change


@pytest.mark.parametrize("fmt", ["md", "tex"])
def test_a_misread_e_fails_verify(cli, monkeypatch: pytest.MonkeyPatch, tmp_path: Path, fmt: str) -> None:
    """The loaded e multiplied by 1.1 (0.66 for the file's 0.6): the page agrees with itself,
    but not with the file, and --verify fails."""
    _plant(monkeypatch, _scale_given("e", sympy.Rational(11, 10)))
    out = tmp_path / f"page.{fmt}"
    result = cli("solve", "notes-4c11-two-spheres", "-f", fmt, "-o", str(out), "--verify")
    assert result.code == 1, result.err
    assert "[given] e: the file gives 0.6, derive read 0.66" in result.err
    assert "givens" in result.err  # the Given line e = 0.66 is not the file's e


@pytest.mark.parametrize("fmt", ["md", "tex"])
def test_without_the_bug_the_same_page_holds(cli, tmp_path: Path, fmt: str) -> None:
    out = tmp_path / f"page.{fmt}"
    result = cli("solve", "notes-4c11-two-spheres", "-f", fmt, "-o", str(out), "--verify")
    assert result.code == 0, result.err


@pytest.mark.parametrize(
    "name,change,said",
    [
        # grams read as kilograms: 22 g as 22 kg
        ("uoguelph-8-34-superballs-grams", _scale_given("m_A", 1000), "[given] m_A"),
        # a US weight read with g = 9.81: m_A = W/g off by 32.2/9.81
        ("hibbeler-15-58-suitcases", _scale_given("m_A", sympy.Rational("32.2") / sympy.Rational("9.81")), "m_A"),
        # an angle's direction read the other way: v_A1t = -v_A1 sin(theta)
        (
            "notes-4c11-two-spheres",
            lambda p: replace(p, motion_A=replace(p.motion_A, t=-p.motion_A.t)),
            "v_A1t",
        ),
    ],
)
def test_other_loader_bugs_fail(cli, monkeypatch: pytest.MonkeyPatch, name: str, change, said: str) -> None:
    _plant(monkeypatch, change)
    result = cli("solve", name, "--verify")
    assert result.code == 1, result.err
    assert said in result.err


def test_a_misread_chain_given_fails(monkeypatch: pytest.MonkeyPatch) -> None:
    """A chain's given misread (h_0 of the thrown-down sphere, 1.1 times the file's)."""
    import derive.problem.chain as chain_loader

    build = chain_loader.build_chain

    def buggy(data, ctx, name):
        chain = build(data, ctx, name)
        return replace(chain, givens=tuple(_scale(g, "h_0") for g in chain.givens))

    monkeypatch.setattr(chain_loader, "build_chain", buggy)
    report = verify(derive.solve(derive.load("chain-ocr-m2-2015-thrown-down-bounce")))
    assert not report.ok
    assert any("h_0" in f.reason for f in report.failures)


def _scale(g, name: str):
    return replace(g, value=g.value * sympy.Rational(11, 10)) if g.name == name else g


def test_the_verifier_reads_the_file_on_its_own() -> None:
    """No module of the verifier imports derive's loader or its units."""
    for path in VERIFIER.rglob("*.py"):
        tree = ast.parse(path.read_text(encoding="utf-8"))
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module] + [f"{node.module}.{a.name}" for a in node.names]
            bad = [n for n in names if n.startswith(("derive.problem", "derive.units"))]
            assert not bad, f"{path.name} imports {bad}"


def test_its_reading_of_numbers_units_and_angles() -> None:
    """Values worked by hand from the definitions (1 ft = 0.3048 m, 1 mi = 5280 ft,
    1 lbf = 0.45359237 kg x 9.80665 m/s^2)."""
    text = """
title = "t"
kind = "oblique"
[given]
m_A = "22 g"
m_B = "m_A*2"
e = 0.6
v_A1 = "36 km/h"
v_B1 = 0
theta = "30 deg"
[A]
angle = "theta"
from = "+n"
toward = "-t"
"""
    read = source.load(None, text)
    assert read is not None and not read.unread
    assert read.values["m_A"] == sympy.Rational(22, 1000)
    assert read.values["m_B"] == sympy.Rational(44, 1000)
    assert read.values["e"] == sympy.Rational(3, 5)
    assert read.values["v_A1"] == 10
    n, t = read.motions["A"]
    assert math.isclose(float(n), 10 * math.sqrt(3) / 2) and math.isclose(float(t), -5.0)
    us = source.load(
        None,
        'title = "t"\nkind = "direct"\n[given]\nW_A = "15 lb"\nm_B = "1 slug"\ne = 1\nv_A1 = "60 mi/h"\nv_B1 = 0\n',
    )
    assert us is not None and us.system == "US"
    assert us.values["v_A1"] == 88  # 60 mi/h = 88 ft/s
    assert us.values["m_A"] == sympy.Rational(15) / sympy.Rational("32.2")


def test_every_bundled_file_is_read_whole() -> None:
    from derive.resources import bundled

    for name, path in bundled().items():
        read = source.load(None, path.read_text(encoding="utf-8"))
        assert read is not None and not read.unread, (name, read and read.unread)
