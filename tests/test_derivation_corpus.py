"""The typed derivations of tests/data/derivations, each run as a student runs it,
``derive check PROBLEM --derivation FILE``, and compared line by line with the
verdict a teacher gives it (tests/support/derivation_corpus.py).

A derivation is judged as a teacher judges it when every line's verdict agrees:
the first wrong line is where the teacher puts the slip, with the slip's name; a line
the teacher marks "again" is the checker's "the same mistake again"; carried lines are
carried; correct lines are correct; a line the teacher does not mark (``skip``) may be
skipped or found correct, never wrong. The pass rate is printed:

    PYTHONPATH=$PWD python -m pytest -q -n 0 -s tests/test_derivation_corpus.py

Each case is a test of its own; one the checker does not judge as the teacher does
yet is reported as xfail with the disagreements, so that the suite stays green
while the rate is measured.
"""

from __future__ import annotations

import json
import re

import pytest
from support.derivation_corpus import Case, load_cases

#: By problem: derivations of one problem run one after another share what the checker keeps for
#: it in memory (its solved systems), which made the corpus 270 -> 217 s of CPU (CI's time)
CASES = sorted(load_cases(), key=lambda c: (c.verdict.problem, c.name))
#: The verdicts of a line's relations, from the least to the most serious.
RANK = ("not read", "not checked", "error", "correct", "carried", "again", "wrong", "unit mismatch")
#: The checker's name of a slip its report gives in words (the rest are mistakes' names).
RESULTS: dict[str, list[str]] = {}
#: Per case: (lines the teacher marks that the checker judges as the teacher does, lines marked).
LINES: dict[str, tuple[int, int]] = {}


def checker_lines(cli, case: Case) -> dict[int, tuple[str, str]]:
    """line number -> (the teacher's word for the checker's status, the slip's name)."""
    r = cli("check", case.verdict.problem, "--derivation", str(case.path), "--format", "json")
    if not r.out.strip():
        return {0: ("unread", r.err.strip())}
    data = json.loads(r.out)
    out: dict[int, tuple[str, str]] = {}
    for item in data["items"]:
        if item["kind"] != "line" or not str(item["name"]).isdigit():
            continue
        status = item["status"]
        slip = item.get("slip") or ",".join(d["mistake"] for d in item.get("diagnosis", []))
        if status == "wrong" and item.get("again"):
            status = "again"
        n = int(item["name"])  # a line of several relations: its worst verdict
        if n not in out or RANK.index(status) > RANK.index(out[n][0]):
            out[n] = (status, slip)
    return out


def disagreements(case: Case, found: dict[int, tuple[str, str]]) -> list[str]:
    """Where the checker's verdict is not the teacher's, in words (empty when it agrees)."""
    if 0 in found:
        return [f"not read: {found[0][1]}"]
    v = case.verdict
    names = {s.line: s.name for s in v.slips}
    out = []
    for n, teacher in v.lines.items():
        status, slip = found.get(n, ("not read", ""))
        if teacher == "skip":
            if status not in ("not read", "not checked", "correct", "error"):
                out.append(f"line {n}: {status}, the teacher does not mark it")
        elif status != teacher:
            out.append(f"line {n}: {status}, the teacher: {teacher}")
        elif teacher == "wrong" and names[n] not in slip.split(","):
            out.append(f"line {n}: wrong as {slip or 'no name'}, the teacher: {names[n]}")
    for n, (status, _) in found.items():
        if n not in v.lines and status in ("wrong", "again", "carried"):
            out.append(f"line {n}: {status}, not a relation the teacher marks")
    return out


@pytest.mark.parametrize("case", CASES, ids=[c.name for c in CASES])
def test_judged_as_a_teacher_judges(cli, case: Case) -> None:
    problems = disagreements(case, checker_lines(cli, case))
    RESULTS[case.name] = problems
    lines_wrong = {int(p.split(":")[0].split()[1]) for p in problems if p.startswith("line ")}
    marked = len(case.verdict.lines)
    LINES[case.name] = (
        0 if problems and not lines_wrong else marked - len(lines_wrong & set(case.verdict.lines)),
        marked,
    )
    assert not any("internal error" in p for p in problems), problems[0]  # a report, never a traceback
    if problems:
        pytest.xfail("; ".join(problems[:4]))


def test_pass_rate_is_reported() -> None:
    """Runs last (pytest keeps file order): prints the rate of the cases run above."""
    if not RESULTS:
        pytest.skip("no corpus case ran")
    passed = sum(1 for p in RESULTS.values() if not p)
    print(f"\ncorpus: {passed} of {len(RESULTS)} derivations judged as the teacher judges them")
    agreed, marked = (sum(n[i] for n in LINES.values()) for i in (0, 1))
    print(f"lines: {agreed} of {marked} marked lines judged as the teacher judges them")
    batches: dict[str, list[int]] = {}
    for name, problems in RESULTS.items():
        tally = batches.setdefault(re.match(r"[a-z]+", name).group(), [0, 0, 0, 0])
        tally[0] += not problems
        tally[1] += 1
        tally[2] += LINES[name][0]
        tally[3] += LINES[name][1]
    print("by batch: " + ", ".join(f"{b} {p}/{n} ({a}/{m} lines)" for b, (p, n, a, m) in sorted(batches.items())))
    for name, problems in sorted(RESULTS.items()):
        if problems:
            print(f"  {name}: {'; '.join(problems[:3])}")
