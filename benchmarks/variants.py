"""Speed of homework variants: worked Markdown and JSON variants per second, against
re-solving each variant with SymPy, and peak memory as the count grows.

    python benchmarks/variants.py [--count 1000] [--resolve 20]

Both sides write the same page: a variant's worked solution in Markdown with its figures
before and after the impact (``variants.fill`` draws each variant's own; the re-solve
baseline is ``derive.render(derive.solve(...), "md")`` of the problem file with the
variant's numbers written in, figures on, as a re-solved variant's page is).

Its last line reads ``variants/s: md=<n> json=<n> resolve=<n> ratio=<md/resolve>``.
"""

from __future__ import annotations

import argparse
import json
import re
import tempfile
import time
import tracemalloc
from decimal import Decimal

import derive
from derive.homework import variants
from derive.problem import loads
from derive.resources import bundled

PROBLEM = "notes-4c11-two-spheres"
UNITS = {"m_A": "kg", "m_B": "kg", "v_A1": "m/s", "v_B1": "m/s", "e": ""}


def resolve_text(base: str, values: dict) -> str:
    """The problem file with a variant's numbers written in: what re-solving starts from."""
    text = base
    for name, value in values.items():
        shown = format(Decimal(str(float(value))).normalize(), "f")
        new = f'"{shown} {UNITS[name]}"' if UNITS[name] else shown
        text = re.sub(rf"^{name} = .*$", f"{name} = {new}", text, count=1, flags=re.M)
    return text


def peak_memory(problem: derive.Problem, count: int) -> float:
    """Peak traced memory (MiB) while writing ``count`` variants to disk."""
    with tempfile.TemporaryDirectory() as out:
        tracemalloc.start()
        variants.write_variants(problem, out, count=count, seed=3)
        peak = tracemalloc.get_traced_memory()[1]
        tracemalloc.stop()
    return peak / 2**20


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--count", type=int, default=1000)
    parser.add_argument("--resolve", type=int, default=20, help="variants re-solved with SymPy for the ratio")
    args = parser.parse_args()

    problem = derive.load(PROBLEM)
    t0 = time.perf_counter()
    compiled = variants.compile_problem(problem)
    t_compile = time.perf_counter() - t0
    chosen = variants.draw(compiled, args.count, seed=1)
    t_draw = time.perf_counter() - t0 - t_compile

    t0 = time.perf_counter()
    pages = [variants.fill(compiled, v) for v in chosen]
    t_md = time.perf_counter() - t0
    t0 = time.perf_counter()
    keys = [json.dumps(variants.answers(compiled, v)) for v in chosen]
    t_json = time.perf_counter() - t0
    assert len(pages) == len(keys) == args.count

    base = bundled()[PROBLEM].read_text(encoding="utf-8")
    t0 = time.perf_counter()
    for v in chosen[: args.resolve]:
        derive.render(derive.solve(loads(resolve_text(base, v.values), path="v.toml")), "md")
    t_resolve = time.perf_counter() - t0

    md_rate = args.count / t_md
    json_rate = args.count / t_json
    resolve_rate = args.resolve / t_resolve
    small, large = peak_memory(problem, 100), peak_memory(problem, 400)
    print(f"problem: {PROBLEM}; start-up: compile {t_compile:.2f} s, draw {args.count} variants {t_draw:.2f} s")
    print(f"worked Markdown: {args.count} variants in {t_md:.3f} s")
    print(f"JSON answer keys: {args.count} variants in {t_json:.3f} s")
    print(f"re-solved with SymPy: {args.resolve} variants in {t_resolve:.2f} s")
    print(f"peak memory writing 100 variants: {small:.1f} MiB; 400 variants: {large:.1f} MiB")
    print(
        f"variants/s: md={md_rate:.0f} json={json_rate:.0f} resolve={resolve_rate:.1f} ratio={md_rate / resolve_rate:.0f}"
    )


if __name__ == "__main__":
    main()
