"""Single-line mutants of a worked solution, ten kinds of error, for the verifier's mutation test.

Each mutant changes one line of a page as written (Markdown or LaTeX) in one way a
slip of the pen would: a number off, a sign, A and B swapped, a term dropped, a
unit swapped, an equation reference changed, the boxed answer, cos for sin, a
given, an intermediate rounded the wrong way. The lines are found in the text
itself (display blocks, Given items, sentences naming equations), not through the
verifier's reader, so a line the verifier does not read still gets mutants.

A mutant that leaves the line true is not made where that can be seen from the
text and the problem's values: a term dropped that is worth 0, A and B swapped where
the two names have the same value, cos for sin at 45°, a sign of a zero.
"""

from __future__ import annotations

import random
import re
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from decimal import Decimal

KINDS = (
    "number",
    "sign",
    "swap_ab",
    "drop_term",
    "unit",
    "reference",
    "boxed",
    "cos_sin",
    "given",
    "rounding",
)

#: A number as the pages write it (not inside a name's subscript or a \tag).
NUMBER = re.compile(r"(?<![_{\w.])(\d+\.\d+|\d+)(?![\w.])")
UNIT = re.compile(r"\\mathrm\{([^{}]+)\}")
UNIT_SWAPS = {
    "m/s": "m",
    "m": "m/s",
    "kg": "g",
    "g": "kg",
    "J": "N",
    "N": "J",
    "N s": "J",
    "N\\,s": "J",
    "mm": "m/s",
    "cm": "kg",
    "km/h": "m/s",
    "ft/s": "ft",
    "ft": "ft/s",
    "slug": "lb",
    "lb": "slug",
    "ft lb": "lb",
    "ft\\,lb": "lb",
    "lb s": "ft\\,lb",
    "lb\\,s": "ft\\,lb",
    "m/s^2": "m/s",
    "ft/s^2": "ft/s",
    "N/m": "N",
    "s": "m",
}
REFERENCE = re.compile(
    r"^(?:\\noindent\s*)?(?:From|Substitute into|Back into|Add|Subtract|Solve|Multiply)\b.*?\((\d+)\)", re.M
)
Values = Callable[[str], object | None]


@dataclass(frozen=True)
class Mutant:
    kind: str
    line: int  # 1-based line of the page
    before: str
    after: str

    def apply(self, text: str) -> str:
        lines = text.split("\n")
        assert lines[self.line - 1] == self.before
        lines[self.line - 1] = self.after
        return "\n".join(lines)


@dataclass(frozen=True)
class PageLine:
    number: int
    text: str
    role: str  # "display", "given", "sentence"
    boxed: bool = False


def page_lines(text: str, fmt: str) -> list[PageLine]:
    """The lines a mutant may change: displayed mathematics, Given items, sentences naming equations."""
    out: list[PageLine] = []
    inside = False
    for i, line in enumerate(text.split("\n"), 1):
        s = line.strip()
        if fmt == "md":
            if s == "$$":
                inside = not inside
                continue
        elif s in (r"\begin{equation*}", r"\[") or s.startswith(r"\begin{align"):
            inside = True
            continue
        elif s in (r"\end{equation*}", r"\]") or s.startswith(r"\end{align"):
            inside = False
            continue
        if inside and s:
            out.append(PageLine(i, line, "display", r"\boxed" in line))
        elif re.match(r"^(?:- |\\item )\$[^$]+\$\s*$", s):
            out.append(PageLine(i, line, "given"))
        elif REFERENCE.search(s) and "of the notes" not in s:
            out.append(PageLine(i, line, "sentence"))
    return out


def _numbers(text: str) -> list[re.Match[str]]:
    """Numbers of a line outside \\tag{...}, \\mathrm{...} and exponents of units."""
    masked = re.sub(r"\\(tag|mathrm|text|operatorname)\{[^{}]*\}", lambda m: " " * len(m[0]), text)
    return [m for m in NUMBER.finditer(masked)]


def _bump(digits: str, up: bool) -> str | None:
    """The number with its last figure one up or down (None when it would lose its form)."""
    d = Decimal(digits)
    ulp = Decimal(1).scaleb(d.as_tuple().exponent)
    new = d + ulp if up or d == 0 else d - ulp
    if new < 0:
        return None
    out = f"{new:f}"
    return out


def _number_off(line: PageLine, rng: random.Random) -> Iterator[str]:
    for m in _numbers(line.text):
        new = _bump(m[1], rng.random() < 0.5)
        if new is not None and new != m[1]:
            yield line.text[: m.start(1)] + new + line.text[m.end(1) :]


def _rounded_wrongly(line: PageLine, rng: random.Random) -> Iterator[str]:
    """A decimal with its last figure dropped and rounded the wrong way (79.23 -> 79.3)."""
    for m in _numbers(line.text):
        digits = m[1]
        if "." not in digits or len(digits.split(".")[1]) < 2 or digits.endswith(("5", "0")):
            continue
        d = Decimal(digits)
        places = len(digits.split(".")[1]) - 1
        right = d.quantize(Decimal(1).scaleb(-places))
        ulp = Decimal(1).scaleb(-places)
        wrong = right - ulp if d > right else right + ulp
        if wrong >= 0:
            yield line.text[: m.start(1)] + f"{wrong:f}" + line.text[m.end(1) :]


def _sign(line: PageLine, rng: random.Random) -> Iterator[str]:
    text = line.text
    for m in re.finditer(r"(?<=[\w}\)]) ([+-]) (?!0(?![.\d]))", text):
        flip = "-" if m[1] == "+" else "+"
        yield text[: m.start(1)] + flip + text[m.end(1) :]
    for m in re.finditer(r"= (-?)(\d)", text):
        if m[2] == "0" and not re.match(r"0\.\d*[1-9]", text[m.start(2) :]):
            continue
        yield text[: m.start(1)] + ("" if m[1] else "-") + text[m.end(1) :]


def _swap_ab(line: PageLine, rng: random.Random, value: Values) -> Iterator[str]:
    for m in re.finditer(r"([a-zA-Z]+)_\{([AB])([^{}]*)\}", line.text):
        other = "B" if m[2] == "A" else "A"
        a, b = f"{m[1]}_{m[2]}{m[3]}", f"{m[1]}_{other}{m[3]}"
        va, vb = value(a), value(b)
        if va is not None and vb is not None and abs(va - vb) <= 1e-12 * max(1, abs(va)):
            continue  # equal values: the line stays true
        yield line.text[: m.start(2)] + other + line.text[m.end(2) :]


def _drop_term(line: PageLine, rng: random.Random, term_value: Callable[[str], object | None]) -> Iterator[str]:
    """A term ``+ x`` or ``- x`` of a sum at the top level of a side, dropped."""
    text = line.text
    for m in re.finditer(r" [+-] ", text):
        end = _term_end(text, m.end())
        term = text[m.end() : end]
        if not term.strip() or term.strip() in ("0",) or re.fullmatch(r"0(?:\.0+)?", term.strip()):
            continue
        v = term_value(term)
        if v is not None and abs(v) < 1e-12:
            continue
        yield text[: m.start()] + text[end:]


def _term_end(text: str, start: int) -> int:
    depth = 0
    i = start
    while i < len(text):
        c = text[i]
        if c in "({[":
            depth += 1
        elif c in ")}]":
            if depth == 0:
                return i
            depth -= 1
        elif (depth == 0 and (text.startswith((" + ", " - ", " = "), i) or text.startswith(r"\ \mathrm", i))) or (
            depth == 0 and text.startswith((r"\tag", r"\quad"), i)
        ):
            return i
        i += 1
    return i


def _unit(line: PageLine, rng: random.Random) -> Iterator[str]:
    for m in UNIT.finditer(line.text):
        new = UNIT_SWAPS.get(m[1])
        if new is not None and line.text[max(0, m.start() - 2) : m.start()] == "\\ ":
            yield line.text[: m.start(1)] + new + line.text[m.end(1) :]


def _reference(line: PageLine, rng: random.Random, tags: list[int]) -> Iterator[str]:
    for m in re.finditer(r"\((\d+)\)", line.text):
        n = int(m[1])
        others = [t for t in tags if t != n and abs(t - n) <= 3] or [t for t in tags if t != n]
        if others:
            new = rng.choice(others)
            yield line.text[: m.start(1)] + str(new) + line.text[m.end(1) :]


def _cos_sin(line: PageLine, rng: random.Random, term_value: Callable[[str], object | None]) -> Iterator[str]:
    for m in re.finditer(r"\\(cos|sin)(\^\{\d\})?\s*(\{(?:[^{}]|\{[^{}]*\})*\})?", line.text):
        rest = line.text[m.end(2) if m[2] else m.end(1) :][:20]
        if re.match(r"\s*\{?\s*(?:45|-45|135)(?:\^\\circ|°)", rest):
            continue
        if m[3]:
            a, b = term_value(rf"\cos {m[3]}"), term_value(rf"\sin {m[3]}")
            if a is not None and b is not None and abs(a - b) < 1e-12:
                continue  # at 45°: cos and sin agree
        new = "sin" if m[1] == "cos" else "cos"
        yield line.text[: m.start(1)] + new + line.text[m.end(1) :]


def mutants(
    text: str,
    fmt: str,
    rng: random.Random,
    value: Values,
    term_value: Callable[[str], object | None],
    per_kind: int | None = 3,
    equivalent: Callable[[str, str], bool] = lambda before, after: False,
) -> list[Mutant]:
    """Up to ``per_kind`` mutants of each kind for one page (all of them for None).
    ``equivalent(before, after)``: the changed line has every side worth what it was."""
    lines = page_lines(text, fmt)
    tags = sorted({int(t) for t in re.findall(r"\\tag\{(\d+)\}", text)})
    pools: dict[str, list[Mutant]] = {k: [] for k in KINDS}

    def add(kind: str, line: PageLine, news: Iterator[str]) -> None:
        for new in news:
            if new != line.text and not equivalent(line.text, new):
                pools[kind].append(Mutant(kind, line.number, line.text, new))

    for line in lines:
        if line.role == "sentence":
            add("reference", line, _reference(line, rng, tags))
            continue
        if line.role == "given":
            add("given", line, _number_off(line, rng))
            continue
        if line.boxed:
            add("boxed", line, _number_off(line, rng))
        else:
            add("number", line, _number_off(line, rng))
            add("rounding", line, _rounded_wrongly(line, rng))
        add("sign", line, _sign(line, rng))
        add("swap_ab", line, _swap_ab(line, rng, value))
        add("drop_term", line, _drop_term(line, rng, term_value))
        add("unit", line, _unit(line, rng))
        add("cos_sin", line, _cos_sin(line, rng, term_value))
    out: list[Mutant] = []
    for kind in KINDS:
        pool = pools[kind]
        out += pool if per_kind is None or len(pool) <= per_kind else rng.sample(pool, per_kind)
    return out
