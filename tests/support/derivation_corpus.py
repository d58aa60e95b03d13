"""The corpus of typed derivations with a teacher's verdicts (tests/data/derivations).

Each case is a derivation typed the way students type it (Markdown, LaTeX or plain
text) and the verdict a teacher gives it, line by line: which lines are correct, which
line is the slip (and its name), which later lines are carried, which are not relations
to mark. The verdicts were written by hand from the problem's givens, independently of
derive's checker; see tests/data/derivations/README.md for the schema.

    from support.derivation_corpus import load_cases, check_corpus
    for case in load_cases():
        case.path, case.text, case.verdict.lines, case.verdict.slips

`check_corpus()` returns the list of problems with the corpus itself (a file without a
verdict, a line number past the end of its file, a category short of its count).
"""

from __future__ import annotations

import re
import tomllib
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import pytest

CORPUS = Path(__file__).resolve().parents[1] / "data" / "derivations"
VERDICTS = CORPUS / "verdicts.toml"
PROBLEMS = Path(__file__).resolve().parents[2] / "problems"

FORMATS = {"md": ".md", "tex": ".tex", "txt": ".txt"}
STATUSES = ("correct", "wrong", "again", "carried", "skip")
CATEGORIES = ("correct", "baseline", "one_slip", "two_slips", "chain")
# The least each category must hold (the "Done when" of issue 31).
MINIMUM = {"correct": 12, "baseline": 3, "one_slip": 20, "two_slips": 5, "chain": 3}
MINIMUM_TOTAL = 40
# The checker's names of the common mistakes (docs/checking.md) and the teacher's own.
CHECKER_MISTAKES = frozenset(
    {
        "b_sign",
        "restitution_reversed",
        "e_speeds",
        "e_on_t",
        "energy_conserved",
        "system_t",
        "sin_cos_swapped",
        "angle_other_axis",
        "angle_quadrant",
        "degrees_as_radians",
        "masses_swapped",
        "weight_as_mass",
    }
)
OTHER_SLIPS = frozenset({"arithmetic", "algebra", "rounded_too_early", "copied_wrong", "ke_formula"})
SLIP_NAMES = CHECKER_MISTAKES | OTHER_SLIPS

# A line holds a relation when it has one of these (outside the checks of what it says).
RELATION = re.compile(r"=|\\approx|≈")


@dataclass(frozen=True)
class Slip:
    """One slip: its line, its name, and what the teacher writes beside it."""

    line: int
    name: str
    words: str


@dataclass(frozen=True)
class Verdict:
    """A teacher's verdict on one derivation."""

    problem: str
    format: str
    category: str
    method: str
    summary: str
    lines: dict[int, str]
    slips: tuple[Slip, ...]
    values: dict[str, float | str] = field(default_factory=dict)
    slip_values: dict[str, float | str] = field(default_factory=dict)
    stages: dict[str, list[int]] = field(default_factory=dict)

    def with_status(self, status: str) -> list[int]:
        """The line numbers with this status, in order."""
        return sorted(n for n, s in self.lines.items() if s == status)

    @property
    def first_wrong(self) -> int | None:
        """The line of the first slip (None for a correct derivation)."""
        return min((s.line for s in self.slips), default=None)

    @property
    def wrong_count(self) -> int:
        """How many new mistakes the teacher counts (the slips; "again" lines are not new)."""
        return len(self.slips)


@dataclass(frozen=True)
class Case:
    """One typed derivation and its verdict."""

    name: str
    path: Path
    text: str
    verdict: Verdict

    @property
    def file_lines(self) -> list[str]:
        """The file's lines as typed (line n is file_lines[n - 1])."""
        return self.text.splitlines()


def _verdict(entry: dict) -> Verdict:
    """A Verdict from one [[case]] table of verdicts.toml."""
    lines: dict[int, str] = {}
    for status in STATUSES:
        for number in entry.get(status, []):
            if number in lines:
                raise ValueError(f"{entry['file']}: line {number} is both {lines[number]} and {status}")
            lines[int(number)] = status
    slips = tuple(Slip(int(s["line"]), str(s["name"]), str(s["words"])) for s in entry.get("slips", []))
    return Verdict(
        problem=entry["problem"],
        format=entry["format"],
        category=entry["category"],
        method=entry["method"],
        summary=entry["summary"],
        lines=dict(sorted(lines.items())),
        slips=slips,
        values=dict(entry.get("values", {})),
        slip_values=dict(entry.get("slip_values", {})),
        stages={str(k): [int(n) for n in v] for k, v in entry.get("stages", {}).items()},
    )


def load_cases(verdicts: Path = VERDICTS) -> list[Case]:
    """Every derivation of the corpus with its verdict, in the order of verdicts.toml."""
    with verdicts.open("rb") as handle:
        data = tomllib.load(handle)
    cases = []
    for entry in data["case"]:
        path = verdicts.parent / entry["file"]
        cases.append(Case(entry["file"], path, path.read_text(encoding="utf-8"), _verdict(entry)))
    return cases


def _case_problems(case: Case) -> list[str]:
    """What is wrong with one case's verdict, in words (empty when nothing is)."""
    v, problems = case.verdict, []
    where = case.name
    if v.format not in FORMATS or case.path.suffix != FORMATS[v.format]:
        problems.append(f"{where}: format {v.format!r} does not match the file's extension")
    if v.category not in CATEGORIES:
        problems.append(f"{where}: unknown category {v.category!r}")
    if not (PROBLEMS / f"{v.problem}.toml").is_file():
        problems.append(f"{where}: no bundled problem {v.problem!r}")
    text_lines = case.file_lines
    for number, status in v.lines.items():
        if not 1 <= number <= len(text_lines):
            problems.append(f"{where}: line {number} is past the end ({len(text_lines)} lines)")
        elif status != "skip" and not RELATION.search(text_lines[number - 1]):
            problems.append(f"{where}: line {number} ({status}) holds no relation: {text_lines[number - 1]!r}")
    for number, text in enumerate(text_lines, start=1):
        if RELATION.search(text) and number not in v.lines:
            problems.append(f"{where}: line {number} holds a relation but has no verdict: {text!r}")
    problems += [
        f"{where}: stage {title!r} line {n} has no verdict"
        for title, numbers in v.stages.items()
        for n in numbers
        if n not in v.lines or v.lines[n] == "skip"
    ]
    if v.category == "chain" and not v.stages:
        problems.append(f"{where}: a chain without its stages")
    wrong = v.with_status("wrong")
    if sorted(s.line for s in v.slips) != wrong:
        problems.append(f"{where}: the slips' lines {[s.line for s in v.slips]} are not the wrong lines {wrong}")
    problems += [f"{where}: slip name {s.name!r} is not in the vocabulary" for s in v.slips if s.name not in SLIP_NAMES]
    first_bad = min(wrong, default=None)
    late = [n for n in v.with_status("carried") + v.with_status("again") if first_bad is None or n < first_bad]
    if late:
        problems.append(f"{where}: lines {late} are carried/again before any slip")
    expected = {"correct": 0, "baseline": 0, "one_slip": 1, "two_slips": 2}.get(v.category)
    if expected is not None and len(v.slips) != expected:
        problems.append(f"{where}: category {v.category} but {len(v.slips)} slips")
    if expected == 0 and any(s in v.lines.values() for s in ("wrong", "again", "carried")):
        problems.append(f"{where}: a correct derivation has lines marked wrong or carried")
    return problems


def counts(cases: list[Case]) -> tuple[Counter, Counter]:
    """The number of cases by category and by format."""
    return Counter(c.verdict.category for c in cases), Counter(c.verdict.format for c in cases)


def check_corpus(cases: list[Case] | None = None) -> list[str]:
    """Everything wrong with the corpus itself, in words (empty when it is consistent)."""
    cases = load_cases() if cases is None else cases
    problems = [p for case in cases for p in _case_problems(case)]
    listed = {c.name for c in cases}
    on_disk = {p.name for p in CORPUS.iterdir() if p.suffix in FORMATS.values() and p.name != "README.md"}
    problems += [f"{name}: a derivation without a verdict" for name in sorted(on_disk - listed)]
    problems += [f"{name}: listed twice" for name, n in Counter(c.name for c in cases).items() if n > 1]
    by_category, by_format = counts(cases)
    for category, least in MINIMUM.items():
        if by_category[category] < least:
            problems.append(f"{by_category[category]} {category} derivations, fewer than {least}")
    if len(cases) < MINIMUM_TOTAL:
        problems.append(f"{len(cases)} derivations, fewer than {MINIMUM_TOTAL}")
    for fmt in FORMATS:
        if 3 * by_format[fmt] < len(cases) - 2:
            problems.append(f"only {by_format[fmt]} of {len(cases)} derivations are {fmt}")
    return problems


def agree(recorded: dict, truth: dict, name: str) -> None:
    """Each value a case records equals the one worked again by hand from the givens (to 2e-4)."""
    for key, value in recorded.items():
        assert value == pytest.approx(truth[key], rel=2e-4, abs=2e-4), f"{name}: {key}"
