"""The slowest bundled problems to solve: ``derive solve NAME`` of every bundled problem, timed (issue #27).

    python benchmarks/slowest.py [--top 5] [--limit 3] [--by wall|cpu] [--tree TREE] [--json] [FILES...]

Each problem is solved in its own process (``python -m derive solve NAME``, Markdown to a pipe,
``DERIVE_NO_CACHE=1``: nothing carried over from an earlier run), one after another, and the wall
time of the whole process is kept: start, imports, solving, writing. FILES (problem files of your
own) are timed too. It prints the slowest ``--top`` with their times and CPU seconds, and exits 1
when any takes longer than ``--limit`` seconds (the issue's target: every bundled problem under 3 s)
or exits with an error (``--by cpu``: the limit on CPU seconds instead of wall seconds).
``--tree`` runs derive from another source tree (a worktree of an older commit), for a before
and after.

The machine is shared, so a wall time is a time under load: the load average is printed with
the figures; on a busy machine (load above the number of cores) compare CPU seconds, or run it
when the machine is quiet, and compare trees in the same session.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path

from latency import against_env, run_once  # benchmarks/ is on the path when a script here runs

ROOT = Path(__file__).resolve().parent.parent


def time_one(target: str, tree: Path, cwd: str) -> tuple[float, float, int]:
    """One ``derive solve`` process: wall seconds, CPU seconds, exit code."""
    env = {**against_env(str(tree)), "DERIVE_NO_CACHE": "1"}
    wall, cpu, code, _ = run_once([sys.executable, "-m", "derive", "solve", target, "--timeout", "120"], cwd, env)
    return wall, cpu, code


def main(argv: list[str] | None = None) -> int:
    """Time every bundled problem (and FILES); print the slowest; 1 when one is over the limit."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="*", help="problem files of your own, timed too")
    parser.add_argument("--top", type=int, default=5)
    parser.add_argument("--limit", type=float, default=3.0)
    parser.add_argument("--tree", type=Path, default=ROOT, help="the source tree to run derive from")
    parser.add_argument("--by", choices=("wall", "cpu"), default="wall", help="the time --limit applies to")
    parser.add_argument("--json", action="store_true", help="every time, as JSON")
    args = parser.parse_args(argv)
    tree = args.tree.resolve()
    targets = [p.stem for p in sorted((tree / "problems").glob("*.toml"))]
    targets += [str(Path(f).resolve()) for f in args.files]
    rows = []
    with tempfile.TemporaryDirectory() as cwd:
        for target in targets:
            wall, cpu, code = time_one(target, tree, cwd)
            rows.append({"problem": Path(target).stem, "wall": round(wall, 2), "cpu": round(cpu, 2), "exit": code})
    rows.sort(key=lambda row: -row[args.by])
    load = os.getloadavg()[0]
    if args.json:
        print(json.dumps({"load_average": round(load, 2), "cores": os.cpu_count(), "rows": rows}, indent=1))
    else:
        print(f"{len(rows)} problems, tree {tree}, load average {load:.1f} on {os.cpu_count()} cores;")
        print(f"the slowest {args.top} by {args.by} time:")
        for row in rows[: args.top]:
            print(f"  {row['wall']:6.2f} s wall  {row['cpu']:6.2f} s CPU  exit {row['exit']}  {row['problem']}")
    bad = [row for row in rows if row[args.by] > args.limit or row["exit"] != 0]
    for row in bad:
        print(
            f"over {args.limit:g} s ({args.by}) or failed: {row['problem']} "
            f"({row['wall']} s wall, {row['cpu']} s CPU, exit {row['exit']})",
            file=sys.stderr,
        )
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
