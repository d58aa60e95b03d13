"""How much of each command's time its imports alone take, as ratios to ``python -c "import sympy"`` (issue #19).

    python benchmarks/floor.py [--runs 15]

For each command of benchmarks/latency.py (solve md, solve json, check, list) it first runs the
command once and records every module the process imported, in order. Then it times, interleaved
with B = ``python -c "import sympy"`` (a shuffled order each round, as latency.py does):

- ``B + first Add``: import sympy, then ``x + y``. SymPy's ``Add.flatten`` imports
  ``sympy.tensor.tensor`` (and with it ``sympy.combinatorics``) on the first sum of a process,
  which every command that does algebra pays and B does not;
- ``B + first Add + jinja2``: what a Markdown, LaTeX or HTML page needs before derive's own code;
- ``B, gc.freeze() at exit``: B without the interpreter's last collections over SymPy's objects,
  which derive's console script skips the same way (derive.cli.run);
- ``B as derive runs it``: B with the collector off while SymPy is imported and SymPy's objects
  frozen, as derive.cli.run does, and frozen at exit: the last column gives each row's ratio
  to it, a command's cost against a baseline that starts and exits as derive does;
- ``imports of CMD``: a process that imports the command's modules, in the command's order (with
  sympy.tensor where the command made a sum), with the collector off, does nothing else and
  exits as derive's console script does;
- ``CMD``: the command itself (the console script, as latency.py runs it).

The difference between the last two is the command's work (read, solve, write); the imports alone
show what is left of a target once the modules are loaded. Medians of wall and CPU time.
"""

from __future__ import annotations

import argparse
import os
import random
import statistics
import subprocess
import sys
import tempfile

from latency import BASELINE, COMMANDS, compile_derive, derive_prefix, run_once

FIRST_ADD = "import sympy; x, y = sympy.symbols('x y'); x + y"

#: Run in a child: the command, then the names of the modules it imported, one a line, in order.
RECORD = """
import contextlib, io, sys
import derive.cli
with contextlib.redirect_stdout(io.StringIO()):
    derive.cli.main(sys.argv[1:])
print("\\n".join(sys.modules))
"""

#: Run in a child: the modules in the file named by argv[1], in order (sympy.tensor among them where
#: the command made a sum, as SymPy imports it then), and nothing else; it exits as derive.cli.run does.
IMPORT = """
import gc, importlib, sys
gc.disable()  # as derive.cli.run imports SymPy
for name in open(sys.argv[1]).read().split():
    try:
        importlib.import_module(name)
    except Exception:  # a module that cannot be imported on its own (a platform's, a test's)
        pass
gc.freeze()
gc.enable()
gc.freeze()
"""

#: B as derive's console script would run it (derive.cli.run): the collector off while SymPy is
#: imported, SymPy's objects frozen, and frozen again at exit. The like-for-like baseline.
B_AS_DERIVE = "import gc; gc.disable(); import sympy; gc.freeze(); gc.enable(); gc.freeze()"


def module_list(args: tuple[str, ...], cwd: str, number: int) -> str:
    """The file listing the modules that ``derive ARGS`` imports, in the order it imports them."""
    out = subprocess.run([sys.executable, "-c", RECORD, *args], cwd=cwd, capture_output=True, text=True, check=True)
    path = os.path.join(cwd, f"modules-{number}.txt")
    with open(path, "w") as f:
        f.write(out.stdout)
    return path


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=15, help="timed runs of each process")
    parser.add_argument("--seed", type=int, default=19, help="seed of the order within a round")
    opts = parser.parse_args()
    compile_derive()
    prefix = derive_prefix(module=False)
    with tempfile.TemporaryDirectory(prefix="derive-floor-") as cwd:
        processes: list[tuple[str, list[str]]] = [
            ("B, gc.freeze() at exit", [sys.executable, "-c", "import sympy, gc; gc.freeze()"]),
            ("B as derive runs it", [sys.executable, "-c", B_AS_DERIVE]),
            ("B + first Add", [sys.executable, "-c", FIRST_ADD]),
            ("B + first Add + jinja2", [sys.executable, "-c", FIRST_ADD + "; import jinja2"]),
        ]
        for number, (name, args, _) in enumerate(COMMANDS):
            modules = module_list(args, cwd, number)
            processes.append((f"imports of {name}", [sys.executable, "-c", IMPORT, modules]))
            processes.append((name, [*prefix, *args]))
        base = [sys.executable, *BASELINE]
        walls: dict[str, list[float]] = {"B": [], **{name: [] for name, _ in processes}}
        cpus: dict[str, list[float]] = {key: [] for key in walls}
        load_start = os.getloadavg()
        rng = random.Random(opts.seed)
        for _ in range(opts.runs):
            rng.shuffle(processes)
            for name, argv in processes:
                for key, cmd in (("B", base), (name, argv)):
                    wall, cpu, code, _ = run_once(cmd, cwd)
                    if code != 0:
                        sys.exit(f"{key}: exit code {code}")
                    walls[key].append(wall)
                    cpus[key].append(cpu)
    start, end = ([round(x, 2) for x in load] for load in (load_start, os.getloadavg()))
    print(f"runs: {opts.runs}; load average at start {start}, at end {end}; cores: {os.cpu_count()}")
    b, b_cpu = statistics.median(walls["B"]), statistics.median(cpus["B"])
    same = statistics.median(walls["B as derive runs it"])
    print(f"{'':26s} {'median':>8s} {'ratio':>6s} {'cpu':>8s} {'cpu ratio':>9s} {'like for like':>13s}")
    rows = ["B", "B, gc.freeze() at exit", "B as derive runs it", "B + first Add", "B + first Add + jinja2"]
    rows += [key for name, _, _ in COMMANDS for key in (f"imports of {name}", name)]
    for key in rows:
        w, c = statistics.median(walls[key]), statistics.median(cpus[key])
        print(f"{key:26s} {w:6.3f} s {w / b:5.2f}x {c:6.3f} s {c / b_cpu:8.2f}x {w / same:12.2f}x")
    return 0


if __name__ == "__main__":
    sys.exit(main())
