"""The verifier's failing lines over the corpus of tests/test_every_line.py, grouped by rule.

    PYTHONPATH=. python benchmarks/false_lines.py [--generated N] [--variants N] [--only variants|generated]

Prints, for each rule, how many lines fail on how many pages, and each distinct reason
with one example line. The corpus is the slow tests' own (200 variants of each [vary]
table in Markdown and LaTeX; N generated problems, one in five also in LaTeX).
"""

from __future__ import annotations

import argparse
import os
import sys
from collections import defaultdict
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

import test_every_line as t
from support import verify_corpus


def _variants(name: str, text: str, count: int) -> t.Tally:
    import derive
    from derive.homework import variants
    from derive.problem import loads
    from derive.verifier import verify_text
    from derive.verifier.facts import facts_of

    problem = loads(text, path=f"{name}.toml", name=name)
    tally = t.Tally()
    for fmt in ("md", "tex"):
        compiled = variants.compile_problem(problem)
        for v in variants.draw(compiled, count, seed=1):
            page = variants.fill(compiled, v, fmt)
            mine = t._with_values(problem, v.values)
            facts = facts_of(derive.solve(mine) if any(g.unknown for g in mine.givens) else mine)
            tally.add(f"{name} variant {v.number:03d}", fmt, verify_text(page, facts, fmt))
    return tally


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--generated", type=int, default=2000)
    ap.add_argument("--variants", type=int, default=200)
    ap.add_argument("--only", choices=["variants", "generated"])
    ap.add_argument("--examples", type=int, default=2)
    args = ap.parse_args()
    total = t.Tally()
    with ProcessPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        futures = []
        if args.only != "generated":
            for name, text in t._variant_cases():
                futures.append(pool.submit(_variants, name, text, args.variants))
        if args.only != "variants":
            cases = list(verify_corpus.cases(args.generated))
            for i, c in enumerate(cases):
                fmts = ("md", "tex") if i % 5 == 0 else ("md",)
                futures.append(pool.submit(t._check_text, c.name, c.text, fmts))
        for f in futures:
            total.merge(f.result())
    by_rule: dict[str, list] = defaultdict(list)
    for name, fmt, f in total.failures:
        by_rule[f.rule].append((name, fmt, f))
    print(f"{len(total.failures)} failing lines of {total.lines} checked ({total.pages} pages)")
    for rule, items in sorted(by_rule.items(), key=lambda kv: -len(kv[1])):
        pages = {(n, fmt) for n, fmt, _ in items}
        print(f"{rule}: {len(items)} lines on {len(pages)} pages")
        by_reason: dict[str, list] = defaultdict(list)
        for n, fmt, f in items:
            key = "".join("#" if ch.isdigit() else ch for ch in f.reason)[:90]
            by_reason[key].append((n, fmt, f))
        for key, its in sorted(by_reason.items(), key=lambda kv: -len(kv[1])):
            print(f"  {len(its):4d} x {key}")
            for n, fmt, f in its[: args.examples]:
                print(f"         {n} [{fmt}] line {f.line}: {f.reason}\n           {f.text[:200]}")


if __name__ == "__main__":
    main()
