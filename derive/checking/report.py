"""The verdicts on a set of answers, equations and derivation lines, and their rendering.

A :class:`CheckReport` holds one :class:`Item` per thing checked; it renders as text
(for a terminal), Markdown or JSON. The report only words and lays out what the
checks found: it judges nothing.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from derive import escape
from derive.checking import words
from derive.errors import InputError

FORMATS = ("text", "md", "json")
#: Every status an item can have, in the order the summary counts them.
STATUSES = ("correct", "wrong", "unit mismatch", "carried", "not read", "not checked", "error")
_MARK = {
    "correct": "✓",
    "wrong": "✗",
    "unit mismatch": "✗",
    "carried": "↳",
    "not read": "?",
    "not checked": "·",
    "error": "!",
}


@dataclass(frozen=True)
class Diagnosis:
    """A common mistake (or two together) that reproduces a wrong answer, equation or line."""

    mistake: str
    title: str
    description: str
    where: str
    equations: tuple[int, ...] = ()
    value: str | None = None

    def as_dict(self) -> dict[str, Any]:
        """The diagnosis as plain data (the JSON report)."""
        return {
            "mistake": self.mistake,
            "title": self.title,
            "description": self.description,
            "where": self.where,
            "equations": list(self.equations),
            "value": self.value,
        }


@dataclass(frozen=True)
class Item:
    """The verdict on one answer, equation or line of a derivation.

    ``kind`` is "answer", "equation" or "line"; ``status`` is "correct", "wrong",
    "unit mismatch", "carried" (a line that is right given an earlier slip) or
    "error" (it could not be read; ``message`` says why); ``expected`` the value
    (or equation) expected, as shown; ``relative_error`` (written − expected) /
    |expected|; ``method`` how the verdict was reached; ``message`` says it in a
    sentence; ``diagnosis`` the mistakes that reproduce a wrong one.
    """

    kind: str
    name: str
    written: str
    status: str
    expected: str
    message: str
    method: str = ""
    relative_error: float | None = None
    value: float | None = None
    expected_value: float | None = None
    unit: str = ""
    unit_missing: bool = False
    notes: tuple[str, ...] = ()
    diagnosis: tuple[Diagnosis, ...] = ()
    slip: str = ""
    again: bool = False
    stage: str = ""  # a chain's stage the line is in ("Stage 1: …"), for its heading

    @property
    def correct(self) -> bool:
        """True when the answer or equation is right."""
        return self.status == "correct"

    @property
    def shown(self) -> str:
        """How the item is named in a report: ``v_B2n``, ``(3)``, ``line 7``."""
        if self.kind == "answer":
            return self.name
        if self.kind == "line":
            return f"line {self.name}"
        return f"({self.name})" if self.name else ""

    def as_dict(self) -> dict[str, Any]:
        """The item as plain data (the JSON report)."""
        return {
            "kind": self.kind,
            "name": self.name,
            "written": self.written,
            "status": self.status,
            "correct": self.correct,
            "value": self.value,
            "unit": self.unit,
            "unit_missing": self.unit_missing,
            "expected": self.expected,
            "expected_value": self.expected_value,
            "relative_error": self.relative_error,
            "method": self.method,
            "message": self.message,
            "notes": list(self.notes),
            "diagnosis": [d.as_dict() for d in self.diagnosis],
            "slip": self.slip,
            "again": self.again,
            "stage": self.stage,
        }


@dataclass(frozen=True)
class CheckReport:
    """The verdicts on a set of answers and equations for one problem."""

    problem: str
    title: str
    items: tuple[Item, ...]
    tolerance: float | None = None
    notes: tuple[str, ...] = ()  # how a derivation's names were read (derive's names)
    glossary: tuple[tuple[str, str], ...] = ()  # derive's names in words, for the student

    @property
    def names(self) -> list[str]:
        """The notes in the student's terms, one sentence a name (:func:`.words.notes_in_words`)."""
        return words.notes_in_words(self.notes, dict(self.glossary))

    @property
    def all_correct(self) -> bool:
        """True when every answer and equation is right (a line not read, or not checked in the
        time, is not judged)."""
        return all(i.correct or i.status in ("not read", "not checked") for i in self.items)

    @property
    def exit_code(self) -> int:
        """The CLI's exit code: 0 when everything is right, 1 when anything is wrong,
        2 when an item could not be read (bad input)."""
        if any(i.status == "error" for i in self.items):
            return 2
        return 0 if self.all_correct else 1

    def counts(self) -> dict[str, int]:
        """How many items have each status ("carried" and "error" only where there are any)."""
        out = {s: sum(1 for i in self.items if i.status == s) for s in STATUSES}
        return {s: n for s, n in out.items() if n or s in ("correct", "wrong", "unit mismatch")}

    def as_dict(self) -> dict[str, Any]:
        """The report as plain data (the JSON report)."""
        return {
            "problem": self.problem,
            "title": self.title,
            "all_correct": self.all_correct,
            "counts": self.counts(),
            "tolerance": self.tolerance,
            "notes": list(self.notes),
            "names": self.names,
            "items": [i.as_dict() for i in self.items],
        }

    def render(self, fmt: str = "text") -> str:
        """The report as "text" (a terminal), "md" (Markdown) or "json"."""
        writers = {"text": self.text, "md": self.markdown, "json": self.json}
        if fmt not in writers:
            raise InputError(f"unknown format {fmt!r} (expected one of: {', '.join(FORMATS)})", field="format")
        return writers[fmt]()

    def json(self) -> str:
        """The report as JSON text."""
        from derive.fileio import dumps_json

        return dumps_json(self.as_dict())  # strict: no NaN or Infinity

    def summary(self) -> str:
        """One sentence: how many are right, wrong, carried, unreadable (a derivation none of
        whose lines could be read is said so, not counted as "0 of 1")."""
        judged = [i for i in self.items if not _whole(i)]
        if not judged:
            return "Nothing was judged: no line could be read as a relation."
        c = CheckReport(self.problem, self.title, tuple(judged)).counts()
        parts = [f"{c['correct']} of {len(judged)} correct"]
        if c["wrong"]:
            parts.append(f"{c['wrong']} wrong")
        if c["unit mismatch"]:
            parts.append(f"{c['unit mismatch']} with a unit mismatch")
        if c.get("carried"):
            parts.append(f"{c['carried']} right given an earlier slip (carried)")
        if c.get("not read"):
            parts.append(f"{c['not read']} not read")
        if c.get("not checked"):
            parts.append(f"{c['not checked']} not checked (out of time)")
        if c.get("error"):
            parts.append(f"{c['error']} could not be read")
        return ", ".join(parts) + "."

    def text(self) -> str:
        """The report as aligned text with ✓ and ✗ (a derivation's lines: verdict, then the line)."""
        rows = []
        for i in self.items:
            expected = f"expected {i.expected}" if i.expected else ""
            err = percent(i.relative_error) if i.relative_error is not None else ""
            rows.append((_MARK[i.status], i.shown or "eq.", i.written, expected, err, i.status))
        checked = [r for i, r in zip(self.items, rows, strict=True) if i.kind != "line"] or [("",) * 6]
        widths = [max(len(r[c]) for r in checked) for c in range(6)]
        widths[2] = min(widths[2], 36)
        shown_width = max([len(r[1]) for r in rows] + [0])
        status_width = max([len(i.status) for i in self.items if i.kind == "line"] + [0])
        lines = [f"derive check: {self.title} ({self.problem})", ""]
        names = tuple(self.names)
        lines += [f"  {note}" for note in names] + ([""] if names else [])
        said: dict[str, str] = {}  # each mistake's paragraph once: mistake -> the line it was said at
        for i, row in zip(self.items, rows, strict=True):
            if i.kind == "line" and i.stage and i.stage != _stage_before(self.items, i):
                lines.append(f"  {i.stage}")
            if _whole(i):
                lines.append(f"  {row[0]}  the derivation could not be read")
            elif i.kind == "line":
                lines.append(
                    f"  {row[0]}  {row[1].ljust(shown_width)}  {i.status.ljust(status_width)}  {i.written}".rstrip()
                )
            else:
                cells = [row[c].ljust(widths[c]) for c in range(5)]
                lines.append(("  " + "  ".join(cells) + "  " + row[5]).rstrip())
            shown = details(i, said, names)
            if i.kind == "line" and i.expected:
                shown.insert(1, f"Expected: {i.expected}.")
            lines += ["        " + detail for detail in shown]
        lines += ["", self.summary()]
        return "\n".join(lines) + "\n"

    def markdown(self) -> str:
        """The report as a Markdown table and a list of details."""
        md = escape.markdown
        out = [f"## Check: {md(self.title)}", ""]
        names = tuple(self.names)
        out += [md(note) for note in names] + ([""] if names else [])
        out.append("| | | Written | Expected | Error | Verdict |")
        out.append("|---|---|---|---|---|---|")
        for i in self.items:
            err = percent(i.relative_error) if i.relative_error is not None else ""
            out.append(
                f"| {_MARK[i.status]} | {md(i.shown or 'equation')} | {md(i.written)} | {md(i.expected)} "
                f"| {md(err)} | {i.status} |"
            )
        out += ["", f"**{self.summary()}**", ""]
        said: dict[str, str] = {}
        for i in self.items:
            if i.kind == "line" and i.stage and i.stage != _stage_before(self.items, i):
                out += ([""] if out[-1] else []) + [f"**{md(i.stage)}**", ""]
            text = " ".join(details(i, said, names))
            out.append(f"- **{md(i.shown or 'equation')}** ({i.status}): " + md(text))
        return "\n".join(out) + "\n"


def details(i: Item, said: dict[str, str] | None = None, notes: tuple[str, ...] = ()) -> list[str]:
    """The sentences shown under an item: its message, notes and diagnosis. For a line of a
    derivation, the student's names on a wrong line are said again as they were read
    (``notes``), and the mistake in words; a mistake already described (``said``: mistake ->
    the line it was described at) is named, not described again."""
    lines = [i.message]
    lines += list(i.notes)
    if i.kind == "line" and i.status == "wrong":
        lines += _names_read(i.written, notes)
    for d in i.diagnosis:
        value = f" (it gives {d.value})" if d.value else ""
        if said is not None and d.mistake in said:
            lines.append(f"Mistake: {d.title}{value}, as in {said[d.mistake]}.")
            continue
        if said is not None:
            said[d.mistake] = i.shown or "the answers"
        if i.kind == "line":
            lines.append(
                f"Mistake: {d.title}{value}. {d.description} It enters through {words.equations_in_words(d.where)}."
            )
        else:
            lines.append(f"Mistake: {d.title}{value}. {d.description} It enters in {d.where}.")
    return lines


def _names_read(written: str, notes: tuple[str, ...]) -> list[str]:
    """The notes on how the names written on a line were read ("θ: read as …")."""
    out = []
    for note in notes:
        name = words.names_on(note)
        if name and words.on_line(name, written):
            out.append(words.reminder(note))
    return out


def _whole(i: Item) -> bool:
    """The item of a derivation none of whose lines could be read (it is no line of the file)."""
    return i.kind == "line" and not i.name and i.status == "error"


def _stage_before(items: tuple[Item, ...], item: Item) -> str:
    """The stage of the line before ``item`` ("" for the first)."""
    before = ""
    for i in items:
        if i is item:
            return before
        if i.kind == "line":
            before = i.stage
    return before


def percent(x: float) -> str:
    """A relative error as a signed percentage with two or three significant digits."""
    p = x * 100
    if p == 0:
        return "0 %"
    if abs(p) >= 1:
        return f"{p:+.1f} %"
    if abs(p) < 0.001:
        return "< 0.001 %"
    return f"{p:+.2g} %"


#: A line's verdicts, least serious first: a line of several relations shows its worst once.
RANK = ("correct", "not read", "not checked", "carried", "wrong", "error")


def merged(items: list[Item]) -> list[Item]:
    """One item per line of the file (``a = 1, b = 2`` and ``… ⇒ …`` are one line): its worst verdict."""
    out: list[Item] = []
    for item in items:
        if out and out[-1].name == item.name and item.name:
            if RANK.index(item.status) > RANK.index(out[-1].status):
                out[-1] = item
            continue
        out.append(item)
    return out
