"""The slowest typed derivations to check: ``derive check PROBLEM --derivation FILE`` of every
derivation in tests/data/derivations, timed (issue #31, item 8: every report in under 10 s).

    python benchmarks/derivations.py [--top 8] [--limit 10] [--by wall|cpu] [--tree TREE] [--json] [NAMES...]
    python benchmarks/derivations.py --against OLDTREE [--runs 3] [NAMES...]

Each derivation is checked in its own process (``python -m derive check PROBLEM --derivation
FILE --format json``, ``DERIVE_NO_CACHE=1``), one after another, and the wall time and CPU
seconds of the whole process are kept (start, imports, solving, checking, writing). NAMES
(file-name prefixes such as ``n18``) limit the run to those derivations. It prints the slowest
``--top``, and exits 1 when any takes longer than ``--limit`` seconds or gives no report (a
report is JSON on stdout; a check stopped by its time budget prints none).

The machine is shared: a wall time is a time under load. The load average is printed with the
figures; on a busy machine compare CPU seconds (``--by cpu``). ``--tree`` runs derive from
another source tree (a worktree of an older commit), for a before and after.

``--against OLDTREE`` is that before and after in one run: each derivation is checked
``--runs`` times from each tree, the two trees alternating (so that both see the same load),
and the range of CPU seconds of each is printed with whether the two JSON reports are the
same, word for word (a speed-up must not change a verdict), then the sums over the
derivations timed. It exits 1 when a report differs.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import tomllib
from pathlib import Path

from latency import against_env, run_once  # benchmarks/ is on the path when a script here runs

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "tests" / "data" / "derivations"


def time_one(problem: str, path: Path, tree: Path, report: list | None = None) -> tuple[float, float, bool]:
    """One ``derive check`` process: wall seconds, CPU seconds, whether a report came back
    (appended to ``report`` when it is given)."""
    env = {**against_env(str(tree)), "DERIVE_NO_CACHE": "1"}
    argv = [sys.executable, "-m", "derive", "check", problem, "--derivation", str(path), "--format", "json"]
    wall, cpu, _, out = run_once(argv, str(tree), env)
    if report is not None:
        report.append(out)
    try:
        reported = "items" in json.loads(out)
    except ValueError:
        reported = False
    return wall, cpu, reported


def before_after(cases: list[dict], tree: Path, old: Path, runs: int) -> int:
    """Each case checked ``runs`` times from ``old`` and from ``tree`` in turn: CPU ranges, and
    whether the reports are the same; 1 when one differs."""
    print(f"{len(cases)} derivations, {runs} runs each from {old} (before) and {tree} (after), alternating")
    print("  before CPU s    after CPU s     same report  file")
    sums = {"before": 0.0, "after": 0.0}
    differ = 0
    for case in cases:
        path = CORPUS / case["file"]
        cpus: dict[str, list[float]] = {"before": [], "after": []}
        reports: dict[str, list] = {"before": [], "after": []}
        for _ in range(runs):
            for key, src in (("before", old), ("after", tree)):
                cpus[key].append(time_one(case["problem"], path, src, reports[key])[1])
        same = len(set(reports["before"] + reports["after"])) == 1
        differ += not same
        if not same:  # kept to compare (a time budget run out under load differs too)
            for key, outs in reports.items():
                for k, out in enumerate(outs):
                    Path(tempfile.gettempdir(), f"{case['file']}.{key}{k}.json").write_bytes(out)
        for key in sums:
            sums[key] += min(cpus[key])
        b, a = cpus["before"], cpus["after"]
        print(
            f"  {min(b):5.2f}-{max(b):5.2f}   {min(a):5.2f}-{max(a):5.2f}    {'yes' if same else 'NO':11}  {case['file']}"
        )
    load = os.getloadavg()[0]
    print(f"sum of the least CPU seconds: before {sums['before']:.1f}, after {sums['after']:.1f}; load {load:.1f}")
    return 1 if differ else 0


def main(argv: list[str] | None = None) -> int:
    """Time every derivation of the corpus (or those NAMES start); print the slowest."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("names", nargs="*", help="file-name prefixes (n18, c05-4c11): only those derivations")
    parser.add_argument("--top", type=int, default=8)
    parser.add_argument("--limit", type=float, default=10.0)
    parser.add_argument("--tree", type=Path, default=ROOT, help="the source tree to run derive from")
    parser.add_argument("--by", choices=("wall", "cpu"), default="wall", help="the time --limit applies to")
    parser.add_argument("--json", action="store_true", help="every time, as JSON")
    parser.add_argument("--against", type=Path, help="an older source tree: a before and after, reports compared")
    parser.add_argument("--runs", type=int, default=3, help="runs of each tree with --against")
    args = parser.parse_args(argv)
    tree = args.tree.resolve()
    cases = tomllib.loads((CORPUS / "verdicts.toml").read_text(encoding="utf-8"))["case"]
    cases = [c for c in cases if not args.names or any(c["file"].startswith(n) for n in args.names)]
    if args.against is not None:
        return before_after(cases, tree, args.against.resolve(), args.runs)
    rows = []
    for case in cases:
        wall, cpu, reported = time_one(case["problem"], CORPUS / case["file"], tree)
        rows.append({"file": case["file"], "wall": round(wall, 2), "cpu": round(cpu, 2), "report": reported})
    rows.sort(key=lambda row: -row[args.by])
    load = os.getloadavg()[0]
    if args.json:
        print(json.dumps({"load_average": round(load, 2), "cores": os.cpu_count(), "rows": rows}, indent=1))
    else:
        print(f"{len(rows)} derivations, tree {tree}, load average {load:.1f} on {os.cpu_count()} cores;")
        print(f"the slowest {args.top} by {args.by} time:")
        for row in rows[: args.top]:
            said = "report" if row["report"] else "NO REPORT"
            print(f"  {row['wall']:6.2f} s wall  {row['cpu']:6.2f} s CPU  {said:9}  {row['file']}")
    bad = [row for row in rows if row[args.by] > args.limit or not row["report"]]
    for row in bad:
        print(
            f"over {args.limit:g} s ({args.by}) or no report: {row['file']} ({row['wall']} s wall, {row['cpu']} s CPU)",
            file=sys.stderr,
        )
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
