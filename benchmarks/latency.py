"""Start-up latency of the derive CLI, as a ratio to ``python -c "import sympy"`` (issue #19).

    python benchmarks/latency.py [--runs 15] [--json] [--module] [--no-variants] [--strict] [--against TREE]

What it measures: the wall time of the whole process (start, imports, work, output, exit) of

    derive solve notes-4c11-two-spheres              (Markdown)
    derive solve notes-4c11-two-spheres -f json
    derive check notes-4c11-two-spheres --answer v_A2n=-1.11
    derive list

each run ``--runs`` times, alternating with the baseline B = ``python -c "import sympy"``
(B, solve, B, json, B, check, B, list, in a shuffled order each round), and prints the median of
each, its ratio to the median of B, the issue's target and PASS/FAIL. Then it runs
benchmarks/variants.py (in its own process) and prints its figures, checked against the issue's
targets (>= 100x the re-solve rate, flat peak memory).

Why ratios: this machine is shared and its speed changes from minute to minute; a time in seconds
means little from one run to the next, but B (the import that every solve must pay anyway) slows
down with it. Interleaving B with the commands makes both see the same noise. The children's CPU
time (user + system, from ``getrusage``) is shown too: it moves less than wall time when other
work competes for the cores.

Fairness: every process runs under the interpreter running this script (the venv's python).
``derive`` is the venv's console script, run as ``python .venv/bin/derive ...`` -- what the shebang
does when a user types ``derive`` -- or ``python -m derive ...`` with ``--module`` (runpy adds a
few ms). Children run in an empty temporary folder, so the working folder cannot shadow the
installed package. Before timing, derive's own bytecode is compiled (``compileall``, into the
package's __pycache__ folders, which git ignores): an installed wheel has it, but an editable
checkout on a machine with PYTHONDONTWRITEBYTECODE=1 never writes it, and would charge derive
about 0.1 s of CPU for compiling on every call, which users never pay.
``--no-compile`` measures the tree as it is. One untimed warm-up run of each command checks its
exit code and output and warms the file cache, as a user's first command does for every later
one. derive keeps nothing on disk between runs (issue #25): every run compiles its templates and
defines its records afresh.

``--against TREE`` also runs each command from another source tree (``PYTHONPATH=TREE``, e.g. a
worktree of the commit before a change), in the same rounds: a before and after measured under
the same load, which separate runs on a shared machine do not give.
"""

from __future__ import annotations

import argparse
import compileall
import importlib.util
import json
import os
import random
import re
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

PROBLEM = "notes-4c11-two-spheres"
BASELINE = ("-c", "import sympy")

#: name, arguments after ``derive``, target ratio to B (at or under).
COMMANDS: list[tuple[str, tuple[str, ...], float]] = [
    ("solve md", ("solve", PROBLEM), 1.8),  # issue #25: within 1.8x, with no tricks
    ("solve json", ("solve", PROBLEM, "-f", "json"), 1.8),
    ("check", ("check", PROBLEM, "--answer", "v_A2n=-1.11"), 1.8),
    ("list", ("list",), 0.3),
]

VARIANTS_RATIO_TARGET = 100  # worked Markdown variants/s over re-solved variants/s, at least
VARIANTS_MEMORY_SLACK = 1.25  # peak MiB for 400 variants over 100 variants, at most


def derive_prefix(module: bool) -> list[str]:
    """How to start derive under this interpreter: the console script beside it, or ``-m derive``."""
    script = Path(sys.executable).parent / "derive"
    if module or not script.is_file():
        return [sys.executable, "-m", "derive"]
    return [sys.executable, str(script)]


def compile_derive() -> str:
    """Compile the installed derive package's bytecode (without importing it); returns its folder."""
    spec = importlib.util.find_spec("derive")
    if spec is None or not spec.submodule_search_locations:
        sys.exit("derive is not installed in this interpreter's environment")
    folder = next(iter(spec.submodule_search_locations))
    compileall.compile_dir(folder, quiet=1)
    return folder


def run_once(argv: list[str], cwd: str, env: dict[str, str] | None = None) -> tuple[float, float, int, bytes]:
    """One process: wall seconds, CPU seconds (user + system), exit code, standard output."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.perf_counter()
    proc = subprocess.run(argv, cwd=cwd, env=env, stdin=subprocess.DEVNULL, capture_output=True, check=False)
    wall = time.perf_counter() - t0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return wall, cpu, proc.returncode, proc.stdout


def warm_up(argv: list[str], cwd: str, name: str, output: bool = True, env: dict[str, str] | None = None) -> None:
    """Run once, untimed: the command must succeed and (unless ``output`` is false) print something."""
    _, _, code, out = run_once(argv, cwd, env)
    if code != 0 or (output and not out.strip()):
        sys.exit(f"{name}: exit code {code}, {len(out)} bytes of output: {' '.join(argv)}")


def against_env(tree: str) -> dict[str, str]:
    """The environment that runs derive from another source tree (its bytecode compiled first)."""
    compileall.compile_dir(str(Path(tree) / "derive"), quiet=1)
    return {**os.environ, "PYTHONPATH": str(Path(tree).resolve())}


def measure(runs: int, prefix: list[str], cwd: str, seed: int, against: str | None = None) -> dict:
    """Interleaved timings: per round, B before each command, the commands in a shuffled order
    (with ``against``, each command also run from that source tree, in the same rounds)."""
    base = [sys.executable, *BASELINE]
    warm_up(base, cwd, "baseline", output=False)
    trees: list[tuple[str, dict[str, str] | None]] = [("", None)]
    if against is not None:
        trees.append((" (against)", against_env(against)))
    order = [(name + suffix, args, env) for name, args, _ in COMMANDS for suffix, env in trees]
    for name, args, env in order:
        warm_up([*prefix, *args], cwd, name, env=env)
    rng = random.Random(seed)
    walls: dict[str, list[float]] = {"B": [], **{name: [] for name, _, _ in order}}
    cpus: dict[str, list[float]] = {key: [] for key in walls}
    for _ in range(runs):
        rng.shuffle(order)
        for name, args, env in order:
            for key, argv, child_env in (("B", base, None), (name, [*prefix, *args], env)):
                wall, cpu, code, _ = run_once(argv, cwd, child_env)
                if code != 0:
                    sys.exit(f"{key}: exit code {code}: {' '.join(argv)}")
                walls[key].append(wall)
                cpus[key].append(cpu)
    b = statistics.median(walls["B"])
    b_cpu = statistics.median(cpus["B"])
    rows = []
    for name, args, target in [(n + suffix, a, t) for n, a, t in COMMANDS for suffix, _ in trees]:
        median = statistics.median(walls[name])
        ratio = median / b
        rows.append(
            {
                "name": name,
                "argv": ["derive", *args],
                "median_s": round(median, 4),
                "cpu_median_s": round(statistics.median(cpus[name]), 4),
                "ratio": round(ratio, 3),
                "cpu_ratio": round(statistics.median(cpus[name]) / b_cpu, 3),
                "target": target,
                "pass": ratio <= target,
                "against": name.endswith(" (against)"),
                "wall_s": [round(t, 4) for t in walls[name]],
            }
        )
    baseline = {
        "argv": ["python", *BASELINE],
        "median_s": round(b, 4),
        "cpu_median_s": round(b_cpu, 4),
        "wall_s": [round(t, 4) for t in walls["B"]],
    }
    return {"baseline": baseline, "commands": rows}


def variants_figures(cwd: str) -> dict:
    """Run benchmarks/variants.py in its own process and read its figures."""
    script = Path(__file__).with_name("variants.py")
    proc = subprocess.run([sys.executable, str(script)], cwd=cwd, capture_output=True, text=True, check=False)
    if proc.returncode != 0:
        return {"error": proc.stderr.strip().splitlines()[-1:] or [f"exit code {proc.returncode}"], "text": ""}
    text = proc.stdout
    last = re.search(r"variants/s: md=(\S+) json=(\S+) resolve=(\S+) ratio=(\S+)", text)
    memory = re.search(r"100 variants: ([\d.]+) MiB; 400 variants: ([\d.]+) MiB", text)
    out: dict = {"text": text}
    if last:
        md, js, resolve, ratio = (float(x) for x in last.groups())
        out.update(md_per_s=md, json_per_s=js, resolve_per_s=resolve, ratio=ratio)
        out["ratio_pass"] = ratio >= VARIANTS_RATIO_TARGET
    if memory:
        small, large = (float(x) for x in memory.groups())
        out.update(peak_mib_100=small, peak_mib_400=large)
        out["memory_pass"] = large <= small * VARIANTS_MEMORY_SLACK
    return out


def verdict(ok: bool) -> str:
    return "PASS" if ok else "FAIL"


def print_report(result: dict) -> None:
    b = result["baseline"]
    print(f"python {result['python_version']} ({result['python']}), runs: {result['runs']} of each, interleaved with B")
    print(f"derive run as: {' '.join(result['derive'])} ...; bytecode compiled first: {result['compiled']}")
    print(f"load average at start {result['load_start']}, at end {result['load_end']}; cores: {os.cpu_count()}")
    print()
    line = "{:21s} {:>8s} {:>7s} {:>7s} {:>5s} {:>8s} {:>9s}"
    print(line.format("", "median", "ratio", "target", "", "cpu", "cpu ratio"))
    print(line.format("B: import sympy", f"{b['median_s']:.3f} s", "1.00x", "", "", f"{b['cpu_median_s']:.3f} s", ""))
    for row in result["commands"]:
        cells = (f"{row['median_s']:.3f} s", f"{row['ratio']:.2f}x", f"<={row['target']:.1f}x", verdict(row["pass"]))
        print(line.format(row["name"], *cells, f"{row['cpu_median_s']:.3f} s", f"{row['cpu_ratio']:.2f}x"))
    var = result.get("variants")
    if var is not None:
        print()
        if var.get("error"):
            print(f"benchmarks/variants.py failed: {var['error']}")
            return
        print("benchmarks/variants.py:")
        print("  " + var["text"].rstrip().replace("\n", "\n  "))
        if "ratio" in var:
            print(f"  ratio {var['ratio']:.0f} >= {VARIANTS_RATIO_TARGET}: {verdict(var['ratio_pass'])}")
        if "peak_mib_400" in var:
            print(
                f"  peak memory 400 variants <= {VARIANTS_MEMORY_SLACK} x 100 variants: {verdict(var['memory_pass'])}"
            )


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15, help="timed runs of each command and of B per command")
    parser.add_argument("--json", action="store_true", help="print one JSON object (with every sample)")
    parser.add_argument("--module", action="store_true", help="run 'python -m derive' instead of the console script")
    parser.add_argument("--no-compile", action="store_true", help="do not compile derive's bytecode first")
    parser.add_argument("--no-variants", action="store_true", help="leave out benchmarks/variants.py")
    parser.add_argument("--seed", type=int, default=19, help="seed of the order of commands within a round")
    parser.add_argument("--strict", action="store_true", help="exit 1 when a figure misses its target")
    parser.add_argument(
        "--against",
        metavar="TREE",
        help="also run each command from this source tree (a folder with derive/, e.g. a worktree of an "
        "earlier commit), interleaved in the same rounds: a before/after in one run",
    )
    args = parser.parse_args()
    if args.runs < 1:
        parser.error("--runs must be at least 1")

    compiled = not args.no_compile
    if compiled:
        compile_derive()
    prefix = derive_prefix(args.module)
    with tempfile.TemporaryDirectory(prefix="derive-latency-") as cwd:
        load_start = os.getloadavg()
        result = {
            "python": sys.executable,
            "python_version": sys.version.split()[0],
            "derive": ["python", *prefix[1:]],
            "compiled": compiled,
            "runs": args.runs,
            **measure(args.runs, prefix, cwd, args.seed, args.against),
        }
        result["load_start"] = [round(x, 2) for x in load_start]
        result["load_end"] = [round(x, 2) for x in os.getloadavg()]
        if not args.no_variants:
            result["variants"] = variants_figures(cwd)
    ok = all(row["pass"] for row in result["commands"] if not row["against"])
    var = result.get("variants")
    if var is not None:
        ok = ok and not var.get("error") and var.get("ratio_pass", False) and var.get("memory_pass", False)
    result["pass"] = ok
    if args.json:
        print(json.dumps(result, indent=2))
    else:
        print_report(result)
    return 1 if args.strict and not ok else 0


if __name__ == "__main__":
    sys.exit(main())
