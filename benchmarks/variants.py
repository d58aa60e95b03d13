"""Speed and memory of homework variants against the budget of issue #25: 200 worked variants
of Example 4.C.11 (each its page, its student's sheet and its row of the key) in 20 s, and 40
of a chain in 20 s, on a 2-core machine, under 300 MB.

    python benchmarks/variants.py [--count 200] [--chain-count 40] [--chain chain-aqa-m3-2007-collide-again]

Each run is ``derive variants`` as the command line makes it (:func:`write_variants`, which
uses every core), timed from the problem loaded to the folder written. Memory is the peak of
the proportional set size (PSS: shared pages counted once) summed over this process and its
workers, sampled every 50 ms; CPU is user + system time of this process and its workers.

Its last line reads ``variants: single=<s> s chain=<s> s peak=<MB> MB (budget 20 s, 20 s, 300 MB)``.
"""

from __future__ import annotations

import argparse
import os
import resource
import tempfile
import threading
import time
from pathlib import Path

import derive
from derive.homework.variants import write_variants

PROBLEM = "notes-4c11-two-spheres"
CHAIN = "chain-aqa-m3-2007-collide-again"


def _pss_kib(pid: int) -> int:
    try:
        for line in Path(f"/proc/{pid}/smaps_rollup").read_text().splitlines():
            if line.startswith("Pss:"):
                return int(line.split()[1])
    except OSError:
        pass
    return 0


def _tree(pid: int) -> list[int]:
    """``pid`` and its descendants (the pool's workers)."""
    out, todo = [], [pid]
    while todo:
        p = todo.pop()
        out.append(p)
        try:
            for task in Path(f"/proc/{p}/task").iterdir():
                todo += [int(c) for c in (task / "children").read_text().split()]
        except OSError:
            pass
    return out


class PeakMemory:
    """The peak PSS (MiB) of this process and its children while the block runs."""

    def __enter__(self) -> PeakMemory:
        self.peak, self.done = 0, threading.Event()
        self.thread = threading.Thread(target=self._watch, daemon=True)
        self.thread.start()
        return self

    def _watch(self) -> None:
        while not self.done.wait(0.05):
            self.peak = max(self.peak, sum(_pss_kib(p) for p in _tree(os.getpid())))

    def __exit__(self, *exc: object) -> None:
        self.done.set()
        self.thread.join()

    @property
    def mib(self) -> float:
        return self.peak / 1024


def _cpu() -> float:
    own, kids = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + kids.ru_utime + kids.ru_stime


def run(name: str, count: int) -> tuple[float, float, float]:
    """Wall seconds, CPU seconds and peak MiB of ``derive variants NAME --count COUNT`` (md)."""
    with tempfile.TemporaryDirectory() as out, PeakMemory() as memory:
        cpu, t0 = _cpu(), time.perf_counter()
        failures = write_variants(derive.load(name), str(Path(out) / "hw"), count=count, seed=1)
        wall = time.perf_counter() - t0
        assert not failures, failures
        written = len(list((Path(out) / "hw").glob("variant-*.md")))
        assert written == 2 * count, written
    return wall, _cpu() - cpu, memory.mib


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("--chain-count", type=int, default=40)
    parser.add_argument("--chain", default=CHAIN)
    args = parser.parse_args()

    derive.solve(derive.load(PROBLEM))  # SymPy and derive imported and warm, as in a session
    load = os.getloadavg()[0]
    single = run(PROBLEM, args.count)
    chain = run(args.chain, args.chain_count)
    print(f"cores: {os.cpu_count()}; load average before: {load:.1f}")
    for what, (wall, cpu, mib) in (
        (f"{PROBLEM} x {args.count}", single),
        (f"{args.chain} x {args.chain_count}", chain),
    ):
        print(f"{what}: {wall:.1f} s wall, {cpu:.1f} s CPU, peak {mib:.0f} MiB (PSS, workers included)")
    peak = max(single[2], chain[2])
    print(f"variants: single={single[0]:.1f} s chain={chain[0]:.1f} s peak={peak:.0f} MB (budget 20 s, 20 s, 300 MB)")


if __name__ == "__main__":
    main()
