"""The same derivation gives the same report in every run: the notes on how names were read come
in the order the student first wrote the names, not in the order of a set (which changes from one
process to the next with Python's string hashing, PYTHONHASHSEED).

BYJU'S 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5. By hand: 4(12) + 8(4) = 80 = 4 v_1 + 8 v_2,
v_2 - v_1 = 0.5(12 - 4) = 4, so 12 v_1 = 48: v_1 = 4 m/s, v_2 = 8 m/s (the source's answer).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

WORK = """p_i = m_1 u_1 + m_2 u_2 = 4(12) + 8(4) = 80
p_f = m_1 v_1 + m_2 v_2
v_2 - v_1 = 0.5(u_1 - u_2) = 4
4 v_1 + 8(v_1 + 4) = 80
v_1 = 4 m/s, v_2 = 8 m/s
"""


def _report(tmp_path: Path, seed: int) -> str:
    work = tmp_path / "work.txt"
    work.write_text(WORK, encoding="utf-8")
    env = {**os.environ, "PYTHONHASHSEED": str(seed)}
    args = [sys.executable, "-m", "derive", "check", "byjus-4kg-ball-catches-8kg-ball", "--derivation", str(work)]
    done = subprocess.run(args, capture_output=True, text=True, env=env, cwd=tmp_path, check=False)
    assert done.returncode == 0, done.stderr
    return done.stdout


def test_the_report_is_the_same_whatever_the_hash_seed(tmp_path: Path) -> None:
    reports = {_report(tmp_path, seed) for seed in (0, 1, 2, 3)}
    assert len(reports) == 1
    (report,) = reports
    assert "✗" not in report and report.count("✓") == 5


def test_the_names_are_noted_in_the_order_first_written(tmp_path: Path) -> None:
    noted = re.findall(r"^\s+(\w+): read as", _report(tmp_path, 7), flags=re.M)
    assert len(noted) >= 6
    first = {n: re.search(rf"\b{n}\b", WORK).start() for n in noted}
    assert noted == sorted(noted, key=first.get)
