"""The verifier catches what a slip of the pen does to a page (issue #26): a mutation test.

Each bundled page, in Markdown and LaTeX, is changed one line at a time in ten ways
(tests/support/verify_mutants.py: a number off, a sign, A and B swapped, a term dropped, a
unit swapped, an equation reference changed, the boxed answer, cos for sin, a given,
an intermediate rounded the wrong way), and the verifier is run on each mutant
against the facts of the page's own problem. The page itself holds (no failing
line), so any failing line is the mutant caught.

Default run: a small sample (the notes' two examples, Markdown, one mutant of each
kind per page). Slow (``-m slow``): every bundled problem and chain in both formats,
up to DERIVE_MUTANTS_PER_KIND (default 3) mutants of each kind per page. Both need
at least 99 % of all mutants caught and 97 % of each kind (the issue's target), but
for the kinds in FLOORS, which do not reach it yet and are held at the figure
measured; the rates are printed in the run's summary (conftest.py) and kept as the
user property ``verify_mutants``.
"""

from __future__ import annotations

import os
import random
import re
from collections import Counter, defaultdict
from typing import Any

import pytest
from support import verify_mutants

import derive
from derive.resources import bundled
from derive.verifier import verify_text
from derive.verifier.evaluate import Env, value
from derive.verifier.facts import Facts, facts_of
from derive.verifier.judge import Judge, read_display
from derive.verifier.reader import read
from derive.writers.view import render

SEED = 26
PER_KIND = int(os.environ.get("DERIVE_MUTANTS_PER_KIND", "3"))
OVERALL, EACH = 0.99, 0.97
#: Kinds below the issue's 97 %, each held at the floor measured (a guard against going back).
#: None since the substitutions are checked number by number (givens) and a closed form's
#: coefficients one by one (coefficients): a number off is caught 431/444 (97.1 %).
FLOORS: dict[str, float] = {}
#: Kinds the small sample does not hold to a rate (two mutants a kind: one miss is half of them);
#: the full run measures them. The sample's number mutant on 4.C.12's
#: ``2 v_A2n = 0.7071 v_A1 - 0.6364 v_A1`` (0.7072) is one of the 11 the full run misses.
SAMPLE_LOOSE = {"number"}


def _oracles(facts: Facts):
    """A name's value anywhere on the page, and a term's value (None where not known)."""

    def scalar(name: str) -> object | None:
        for scope in facts.scopes.values():
            q = scope.quantities.get(name)
            if q is not None and q.value is not None:
                return q.value
        return None

    def term(latex: str) -> object | None:
        try:
            expr = read_display(latex).relations[0].sides[0].expr
            return value(expr, Env(scalar))
        except Exception:  # a term the reader does not take alone: keep the mutant
            return None

    return scalar, term


def _row(line: str) -> str:
    """A line as the reader keeps it: an aligned row without its ``&``, ``\\quad`` and ``\\\\``."""
    return re.sub(r"^&\s*(?:\\quad)?\s*", "", line.strip().removesuffix("\\\\").strip()).strip()


def _equivalence(facts: Facts, text: str, fmt: str):
    """Whether a changed line keeps the value of every side (then it is still true, and
    no mutant): each side valued in the line's own part of the page, as the verifier would."""
    judge = Judge(facts, read(text, fmt))
    by_text = {}
    for claim in judge.claims:
        by_text.setdefault(claim.line.latex.strip(), claim)

    def sides(claim, display) -> list | None:
        out = []
        for relation in display.relations:
            for axis in judge.axes(relation):
                for i, side in enumerate(relation.sides):
                    try:
                        v = judge.value(side, judge.side_scopes(claim, i), axis)
                        out.append((v.center, v.unit_dim))
                    except Exception:
                        return None
        return out

    def equivalent(before: str, after: str) -> bool:
        core = _row(before)
        claim = by_text.get(core) or next((c for c in judge.claims if core and core in c.line.latex), None)
        if claim is None or claim.display is None:
            return False
        try:
            changed_core = _row(after)
            new = read_display(claim.line.latex.replace(core, changed_core, 1))
        except Exception:
            return False
        old, changed = sides(claim, claim.display), sides(claim, new)
        if old is None or changed is None or len(old) != len(changed):
            return False
        pairs = zip(old, changed, strict=True)
        return all(da == db and abs(a - b) <= 1e-12 * max(1, abs(a)) for (a, da), (b, db) in pairs)

    return equivalent


def run(pages: list[tuple[str, str]], per_kind: int | None) -> tuple[Counter, Counter, list[str]]:
    """Mutants of each page: (made, caught) by kind, and a few that passed."""
    made: Counter[str] = Counter()
    caught: Counter[str] = Counter()
    missed: list[str] = []
    solutions: dict[str, Any] = {}
    for name, fmt in pages:
        solution = solutions.setdefault(name, derive.solve(derive.load(name)))
        text = render(solution, fmt, figures=False)
        facts = facts_of(solution)
        base = verify_text(text, facts, fmt)
        assert base.ok, f"{name} [{fmt}] fails before any mutation:\n{base.format()}"
        rng = random.Random(f"{SEED}:{name}:{fmt}")
        scalar, term = _oracles(facts)
        same = _equivalence(facts, text, fmt)
        for m in verify_mutants.mutants(text, fmt, rng, scalar, term, per_kind, same):
            made[m.kind] += 1
            if verify_text(m.apply(text), facts, fmt).ok:
                missed.append(f"{m.kind}: {name} [{fmt}] line {m.line}:\n    {m.before.strip()}\n -> {m.after.strip()}")
            else:
                caught[m.kind] += 1
    return made, caught, missed


def _judge(made: Counter, caught: Counter, missed: list[str], record: Any, label: str, sample: bool = False) -> None:
    """The rates by kind against the issue's figures; a small sample (two mutants a kind) holds
    the kinds below 97 % (FLOORS) to nothing, as one miss is half of them: the full run measures them."""
    rates = {k: (caught[k], made[k]) for k in verify_mutants.KINDS if made[k]}
    record("verify_mutants", (label, rates))
    total, hit = sum(made.values()), sum(caught.values())
    assert total > 0
    loose = set(FLOORS) | (SAMPLE_LOOSE if sample else set())
    weak = [k for k, (c, n) in rates.items() if c < (0 if sample and k in loose else FLOORS.get(k, EACH)) * n]
    if sample:
        total -= sum(made[k] for k in loose)
        hit -= sum(caught[k] for k in loose)
    report = os.environ.get("DERIVE_MUTANTS_REPORT")
    if report:  # every mutant that passed, for a closer look
        with open(report, "w", encoding="utf-8") as out:
            out.write("\n".join(missed) + "\n")
    shown = "\n".join(missed[:25])
    assert hit >= OVERALL * total and not weak, (
        f"{hit}/{total} mutants caught; below {EACH:.0%}: {weak}\n{rates}\nmissed (first 25):\n{shown}"
    )


def test_mutants_of_the_notes_examples(record_property: Any) -> None:
    """A fast sample: one mutant of each kind on each of the notes' two examples."""
    pages = [("notes-4c11-two-spheres", "md"), ("notes-4c12-cue-ball", "md")]
    made, caught, missed = run(pages, 1)
    _judge(made, caught, missed, record_property, "sample", sample=True)


@pytest.mark.slow
def test_mutants_of_every_bundled_page(record_property: Any) -> None:
    pages = [(name, fmt) for name in bundled() for fmt in ("md", "tex")]
    made, caught, missed = run(pages, PER_KIND)
    _judge(made, caught, missed, record_property, "bundled")


def summary_line(reports: list[tuple[str, dict]]) -> list[str]:
    """The mutation figures for the end of the run (conftest.py)."""
    out = []
    merged: dict[str, dict[str, list[int]]] = defaultdict(lambda: defaultdict(lambda: [0, 0]))
    for label, rates in reports:
        for kind, (c, n) in rates.items():
            merged[label][kind][0] += c
            merged[label][kind][1] += n
    for label, rates in merged.items():
        c = sum(v[0] for v in rates.values())
        n = sum(v[1] for v in rates.values())
        parts = ", ".join(f"{k} {v[0]}/{v[1]}" for k, v in rates.items())
        out.append(f"verify mutants ({label}): {c}/{n} caught ({100 * c / n:.1f} %); {parts}")
    return out
