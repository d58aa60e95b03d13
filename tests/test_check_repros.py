"""The grading holes of ``derive check`` found by the hostile inputs of round 2
(tests/data/repros2/, copied from shared/repros/input2/), each run as its first
line says and each ending as issue #31 (item 8) asks.

The true values are the notes' (Example 4.C.11: v_A2n = -1.109 m/s, T_lost = 321.4 J,
v_A2t = 3.051 m/s, v_B2t = -9.152 m/s, J_n = 101.4 N·s) and, for the equal elastic spheres
of check-angle-180-wrong.toml, a hand calculation: with e = 1 and equal masses the n
components exchange, so A keeps only v_A1t = -3 m/s: v_A2n = 0 exactly and A moves along
-t, theta_A2 = 180° (from +t toward +n), the same direction as -180°.
"""

from __future__ import annotations

import shutil
import time
from pathlib import Path

import pytest

HERE = Path(__file__).parent / "data" / "repros2"
#: CPU seconds a report may take (issue #31: under 10 s; it used to run to the 60 s budget).
BOUND = 10.0


@pytest.fixture
def here(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    for f in HERE.iterdir():
        shutil.copy(f, tmp_path / f.name)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def verdicts(out: str) -> dict[str, list[str]]:
    """name -> the statuses of its rows in a text report."""
    found: dict[str, list[str]] = {}
    for line in out.splitlines():
        parts = line.split()
        if parts and parts[0] in ("✓", "✗", "↳", "?"):
            found.setdefault(parts[1], []).append(parts[-1])
    return found


def test_exponent_answers_are_judged_at_the_values_magnitude(cli, here: Path) -> None:
    r = cli("check", "notes-4c11-two-spheres", "--answers", "check-exponent-answers-all-correct.toml")
    assert r.code == 1, r.out
    v = verdicts(r.out)
    for name in ("v_A2n", "T_lost", "v_A2t", "v_B2t", "J_n"):
        assert v[name] == ["wrong"], (name, r.out)
    assert "5 wrong" in r.out


@pytest.mark.parametrize(
    ("answer", "right"),
    [
        ("v_A2n=-1e0", True),  # -1.109 at one figure is -1
        ("v_A2n=-1e1", False),
        ("T_lost=3e2", True),  # 321.4 at one figure
        ("T_lost=1e3", False),
        ("v_B2n=8.5", True),  # two figures, ±1 in the second (docs/checking.md)
        ("v_B2n=8.6", False),
        ("v_A2t=0", False),  # 3.05 is not 0 at the units
        ("v_A2t=0e9", False),
    ],
)
def test_figures_relative_to_the_value(cli, answer: str, right: bool) -> None:
    r = cli("check", "notes-4c11-two-spheres", "--answer", answer)
    assert r.code == (0 if right else 1), r.out


def test_angles_are_the_same_direction_modulo_a_turn(cli, here: Path) -> None:
    r = cli("check", "check-angle-180-wrong.toml", "--answer", "theta_A2=-180", "--answer", "theta_A2=540")
    assert r.code == 0, r.out
    assert "wrong sign" not in r.out


def test_an_exact_zero_answered_one_is_wrong(cli, here: Path) -> None:
    r = cli("check", "check-angle-180-wrong.toml", "--answer", "v_A2n=1")
    assert r.code == 1, r.out
    assert "rounded intermediates" not in r.out
    assert cli("check", "check-angle-180-wrong.toml", "--answer", "v_A2n=0").code == 0


@pytest.mark.parametrize(
    ("option", "name", "count"),
    [
        ("--derivation", "dos-derivation-wrong-lines.txt", 150),
        ("--answers", "dos-answers-wrong-equations.toml", 100),
    ],
)
def test_many_wrong_items_give_their_report_in_time(cli, here: Path, option: str, name: str, count: int) -> None:
    start = time.process_time()
    r = cli("check", "notes-4c11-two-spheres", option, name)
    seconds = time.process_time() - start
    assert seconds < BOUND, f"{name} took {seconds:.1f} s"
    assert r.code == 1, r.err
    rows = sum(len(v) for v in verdicts(r.out).values())
    assert rows == count, r.out[-500:]
    assert "time budget" not in r.err
