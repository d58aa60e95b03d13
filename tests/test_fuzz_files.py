"""The file fuzzer: 10,000 problem, chain and answers files broken the way users and attackers
break them (tests/support/fuzz_files.py, from the schema), each run through the real command line,
in this process (``derive.cli.main``).

For every file: no internal error (no traceback, no "internal error"), no run over its time
budget, valid strict JSON wherever JSON is written, no raw control character on standard
output or error, and an error is one line. The same seed gives the same files.

    .venv/bin/python -m pytest -m slow tests/test_fuzz_files.py          # the full run: 10,000 files, seed 18 (.ci/run: 6,000)
    DERIVE_FUZZ_FILES=200000 DERIVE_FUZZ_SEED=random \\
        .venv/bin/python -m pytest -m slow tests/test_fuzz_files.py      # a longer random campaign

``DERIVE_FUZZ_REPORT=fuzz.json`` writes the figures (files by kind, outcomes, errors by
class, the slowest runs); failing files are kept in pytest's temporary folder, named in
the failure message, to be run again by hand.
"""

from __future__ import annotations

import contextlib
import copy
import io
import json
import os
import random
import re
import time
from collections import Counter
from collections.abc import Callable
from pathlib import Path

import pytest
from support import fuzz_files

from derive.cli import main
from derive.errors import DeriveError

FILES = int(os.environ.get("DERIVE_FUZZ_FILES", "10000"))
_SEED = os.environ.get("DERIVE_FUZZ_SEED", "18")
SEED = random.SystemRandom().randrange(2**32) if _SEED == "random" else int(_SEED)
#: Each run's time budget: the command's default (solve and check 60 s, variants 600 s).
RAW = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
#: The figures of the last run (the summary line in conftest.py reads its record_property).
FUZZ_SUMMARY: dict[str, object] = {}


def _no_constants(name: str) -> float:
    raise ValueError(f"{name} is not JSON")


def argv(case: fuzz_files.Case, path: Path, problem: Path, out: Path) -> list[str]:
    if case.command == "check":
        return ["check", str(problem), "--answers", str(path), "--format", "json" if case.number % 2 else "text"]
    if case.command == "variants":
        return ["variants", str(path), "--count", "3", "-o", str(out), "-f", "json"]
    return ["solve", str(path), "-f", case.command.removeprefix("solve-")]


#: Encodings of standard output and error a run may meet (issue #29: a Windows console
#: redirected to a file is cp1252; an old locale, ASCII); one run in 13 meets one of them.
ENCODINGS = ("cp1252", "ascii", "latin-1")


def streams(case: fuzz_files.Case) -> tuple[io.TextIOBase, io.TextIOBase]:
    """Standard output and error for one run: text, or now and then bytes in a narrow encoding."""
    if case.number % 13:
        return io.StringIO(), io.StringIO()
    encoding = ENCODINGS[(case.number // 13) % len(ENCODINGS)]
    return tuple(io.TextIOWrapper(io.BytesIO(), encoding=encoding, errors="strict") for _ in range(2))  # type: ignore[return-value]


def text_of(stream: io.TextIOBase) -> str:
    """What a run wrote: a page sent to a narrow stream is UTF-8 (derive makes it so), a message
    keeps the stream's encoding, with escapes for what it cannot write (both read as UTF-8)."""
    if isinstance(stream, io.StringIO):
        return stream.getvalue()
    stream.flush()
    return stream.buffer.getvalue().decode("utf-8", "replace")  # type: ignore[attr-defined]


def problems_with(case: fuzz_files.Case, code: int, out: str, err: str, seconds: float) -> list[str]:
    """What is wrong with one run, in words (nothing: an empty list)."""
    found = []
    if "Traceback" in err or "internal error" in err:
        found.append("internal error")
    if "stopped after" in err:
        found.append(f"over its time budget ({seconds:.1f} s)")
    if RAW.search(out) or RAW.search(err):
        found.append("a raw control character on the terminal")
    if code not in (0, 1, 2):
        found.append(f"exit code {code}")
    if code == 2 and not (err.startswith("Error: ") and err.count("\n") == 1):
        found.append("an error that is not one line")
    if code == 0 and (case.command == "solve-json" or (case.command == "check" and case.number % 2)):
        try:
            json.loads(out, parse_constant=_no_constants)
        except ValueError as exc:
            found.append(f"invalid JSON ({exc})")
    return found


@pytest.mark.slow
def test_ten_thousand_hostile_files(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, record_property: Callable[[str, object], None]
) -> None:
    last_error: list[str] = []
    real_str = DeriveError.__str__

    def recorded(self: DeriveError) -> str:  # the class of the error the command line prints
        last_error.append(type(self).__name__)
        return real_str(self)

    monkeypatch.setattr(DeriveError, "__str__", recorded)
    problem = tmp_path / "carts.toml"
    problem.write_text(fuzz_files.to_toml(fuzz_files.FAST_DIRECT), encoding="utf-8")
    path, out_dir, keep = tmp_path / "fuzz.toml", tmp_path / "out", tmp_path / "failures"
    kinds, commands, outcomes, classes = Counter(), Counter(), Counter(), Counter()
    slowest: list[tuple[float, int, str, str]] = []
    failures: list[str] = []
    start = time.monotonic()
    for case in fuzz_files.cases(FILES, SEED):
        path.write_bytes(case.data)
        stdout, stderr = streams(case)
        last_error.clear()
        t0 = time.monotonic()
        with contextlib.redirect_stdout(stdout), contextlib.redirect_stderr(stderr):
            code = main(argv(case, path, problem, out_dir))
        seconds = time.monotonic() - t0
        stdout, stderr = text_of(stdout), text_of(stderr)
        kinds[case.kind] += 1
        commands[case.command] += 1
        outcomes[f"exit {code}"] += 1
        if code == 2 and last_error:
            classes[last_error[-1]] += 1
        slowest = sorted([*slowest, (seconds, case.number, case.kind, case.command)], reverse=True)[:5]
        wrong = problems_with(case, code, stdout, stderr, seconds)
        if wrong:
            keep.mkdir(exist_ok=True)
            saved = keep / f"case-{case.number}.toml"
            saved.write_bytes(case.data)
            failures.append(f"{saved} ({case.kind}, {case.command}; {', '.join(wrong)}): {stderr[-300:]!r}")
    total = time.monotonic() - start
    FUZZ_SUMMARY.update(
        files=FILES,
        seed=SEED,
        seconds=round(total, 1),
        kinds=dict(kinds),
        commands=dict(commands),
        outcomes=dict(outcomes),
        errors_by_class=dict(classes),
        slowest=[{"seconds": round(s, 2), "case": n, "kind": k, "command": c} for s, n, k, c in slowest],
        failures=len(failures),
    )
    record_property("fuzz_files", dict(FUZZ_SUMMARY))  # the summary line, from an xdist worker too
    if os.environ.get("DERIVE_FUZZ_REPORT"):
        Path(os.environ["DERIVE_FUZZ_REPORT"]).write_text(json.dumps(FUZZ_SUMMARY, indent=2) + "\n")
    assert not failures, f"{len(failures)} of {FILES} files (seed {SEED}) went wrong:\n" + "\n".join(failures[:20])
    assert sum(kinds.values()) == FILES >= 1
    assert outcomes["exit 0"] > FILES // 50, outcomes  # enough files are good enough to be worked out
    assert len(kinds) == 12, kinds  # problems, answers, and a chain with each of the nine stage types


def test_the_same_seed_writes_the_same_files() -> None:
    first = [c.data for c in fuzz_files.cases(60, 5)]
    assert first == [c.data for c in fuzz_files.cases(60, 5)]
    assert first != [c.data for c in fuzz_files.cases(60, 6)]


def test_every_field_of_every_table_is_broken() -> None:
    """In the first pass over the slots, every field of every table (each stage type's too) is set,
    deleted or joined by an unknown key at least once."""
    all_slots = fuzz_files.slots()
    fields = {(s.kind, s.stage_type, s.field.name if s.field else "?") for s in all_slots}
    names = {f"{s.kind}:{'.'.join(map(str, s.table)) or '-'}:{s.field.name if s.field else '?'}" for s in all_slots}
    seen = {case.broken[0] for case in fuzz_files.cases(len(all_slots) * 10, 1)}
    assert seen == names
    assert ("chain", "spring", "vertical") in fields and ("answers", "", "tolerance") in fields
    assert {s.stage_type for s in all_slots} >= set(fuzz_files.STAGE_EXAMPLES)


def test_the_fuzzer_finds_what_it_looks_for() -> None:
    """The checks can fail: a traceback, a raw ESC, Infinity in JSON and a time-out are each caught."""
    case = fuzz_files.Case(1, "problem", (), b"", "solve-json")
    assert problems_with(case, 1, "", "Error: internal error (KeyError: 'x'); run with --debug", 0.1)
    assert problems_with(case, 0, "\x1b[31m", "", 0.1)
    assert problems_with(case, 0, '{"value": Infinity}', "", 0.1)
    assert problems_with(case, 1, "", "Error: derive solve stopped after 60 s, its time budget", 60)
    assert problems_with(case, 2, "", "Error: a\nb\n", 0.1)
    assert problems_with(case, 0, '{"value": 1.5}', "", 0.1) == []


def test_a_broken_value_is_never_shared_between_files() -> None:
    """The fuzzer hands out a fresh value each time: a shared ``{}`` filled in by a later break
    once came to hold itself, and the generator (not derive) died of recursion after about 160,000
    files of the random campaign."""
    field = next(s.field for s in fuzz_files.slots() if s.field is not None and s.field.type == "table")
    before = copy.deepcopy(fuzz_files.WRONG_TYPES)
    rng = random.Random(3)
    for _ in range(3000):
        value = fuzz_files.value_for(field, rng)
        if isinstance(value, dict):
            value["filled"] = value
        elif isinstance(value, list):
            value.append(value)
    assert [repr(v) for v in fuzz_files.WRONG_TYPES] == [repr(v) for v in before]
