"""Hostile-input repros of the second round (tests/data/repros2/, from the shared
repros' input2 folder), each run as its first line says and ending as its README asks."""

from __future__ import annotations

import csv
import math
import shutil
from pathlib import Path

import pytest

REPROS = Path(__file__).parent / "data" / "repros2"


@pytest.fixture
def here(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A scratch folder holding the repro files, as the current folder (their commands use bare names)."""
    for f in REPROS.glob("*.toml"):
        shutil.copy(f, tmp_path / f.name)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_a_drawn_choice_is_printed_in_the_unit_typed_unrounded(cli, here: Path) -> None:
    """vary-choice-unit-rounded.toml: the choices "4 m/s", "4 km/h", "4 mph" are printed as
    typed in the statement and the Given list ("at 4 km/h", not "at 1.1111 m/s"), and solved at
    their exact values: 4 km/h = 4000/3600 m/s, 4 mph = 4 x 1609.344/3600 m/s."""
    r = cli("variants", "vary-choice-unit-rounded.toml", "--count", "3", "-o", "hw")
    assert r.code == 0, r.err
    with (here / "hw" / "key.csv").open(encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    said = {}
    for row in rows:
        n = int(row["variant"])
        for page in (f"variant-0{n}-problem.md", f"variant-0{n}.md"):
            text = (here / "hw" / page).read_text(encoding="utf-8")
            line = next(ln for ln in text.splitlines() if ln.startswith("**Given.**"))
            said[n] = line.removeprefix("**Given.** ")
            assert "1.11" not in line and "1.78" not in line, line
        speed = float(row["v_A1 [m/s]"])
        # e = 0.8, m_A = 2 kg, m_B = 3 kg, B at rest: v_A2 = (m_A - e m_B) v / (m_A + m_B) = -0.08 v
        assert math.isclose(float(row["v_A2 [m/s]"]), -0.08 * speed, rel_tol=2e-3), row
        typed = {4.0: "A 2 kg at 4 m/s", 4 / 3.6: "A 2 kg at 4 km/h", 4 * 1609.344 / 3600: "A 2 kg at 4 mi/h"}
        want = next(text for value, text in typed.items() if math.isclose(speed, value, rel_tol=1e-12))
        assert said[n] == want, (said[n], want)
    assert sorted(said.values()) == ["A 2 kg at 4 km/h", "A 2 kg at 4 m/s", "A 2 kg at 4 mi/h"]
