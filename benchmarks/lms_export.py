"""The LMS exports of the bundled [vary] tables, timed: ``derive variants NAME --count N
--stack … --moodle …`` for each, the slowest printed first.

    python benchmarks/lms_export.py [--count 2] [--top 5] [--tree TREE] [NAMES...]

Each export runs in its own process (``python -m derive variants``, ``DERIVE_NO_CACHE=1``), one
after another; the wall time of the whole process is kept. ``--tree`` runs derive from another
source tree (a worktree of an older commit), for a before and after in the same session: the
machine is shared, so compare runs made together (the load average is printed).

A mistake's value is solved from the mistaken equations; with surds among a variant's numbers
(cos 30°) an exact solve factors over their number field: ocr-m3-2013's STACK export of two
variants took about a minute before such systems were solved in 30-digit decimals.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

from latency import against_env, run_once  # benchmarks/ is on the path when a script here runs

ROOT = Path(__file__).resolve().parent.parent


def tables() -> list[str]:
    """The bundled problems with a [vary] table."""
    folder = ROOT / "problems"
    return sorted(p.stem for p in folder.glob("*.toml") if "\n[vary]" in p.read_text(encoding="utf-8"))


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("names", nargs="*", help="bundled problems (default: every [vary] table)")
    ap.add_argument("--count", type=int, default=2)
    ap.add_argument("--top", type=int, default=5)
    ap.add_argument("--tree", type=Path, default=ROOT, help="the source tree to run derive from")
    a = ap.parse_args()
    env = {**against_env(str(a.tree)), "DERIVE_NO_CACHE": "1"}
    times = []
    with tempfile.TemporaryDirectory() as tmp:
        for name in a.names or tables():
            out = Path(tmp) / name
            argv = [sys.executable, "-m", "derive", "variants", name, "--count", str(a.count), "-o", str(out / "hw")]
            argv += ["--stack", str(out / "stack.xml"), "--moodle", str(out / "moodle.xml")]
            wall, cpu, code, _ = run_once(argv, tmp, env)
            times.append((wall, cpu, name, code))
    print(f"load average {os.getloadavg()[0]:.1f}; {len(times)} exports of {a.count} variants ({a.tree})")
    for wall, cpu, name, code in sorted(times, reverse=True)[: a.top]:
        print(f"  {wall:7.1f} s wall  {cpu:7.1f} s CPU  {name}" + (f"  (exit {code})" if code else ""))
    return 1 if any(code for *_, code in times) else 0


if __name__ == "__main__":
    sys.exit(main())
