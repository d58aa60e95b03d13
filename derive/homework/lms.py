"""Homework variants for a learning-management system: Moodle XML and PrairieLearn.

Both exports ask for one result (``--result``) of each variant drawn by
:mod:`derive.variants`, graded by the significant-figure rule of ``derive check``:

* the right answer is the value as the answer key shows it (key.json ``shown``);
* the tolerance is 1.5 units in its last significant digit: half a unit, so that
  any answer that rounds to the shown value counts, plus the ±1 in the last digit
  that ``derive check`` allows for rounded intermediates. For v = 8.40 m/s it is
  0.015 m/s (8.385 to 8.415). The significant figures are those the value was
  rounded to, so the trailing zeros of a rounded whole number do not count:
  1045.81 J at three figures is shown as 1050 J, ± 15 J. An exact zero (shown
  ``0``) gets ±0.005.

Moodle: one numerical question per variant, all in one category (a random
question drawn from it gives each student a variant), with the worked solution as
general feedback and, where :mod:`derive.mistakes` predicts the value a common
mistake gives, that value as a wrong answer with the mistake's hint as feedback.
Moodle gives the feedback of the first answer whose range holds the response, so
the mistakes' ranges are cut where they would overlap the right answer's or each
other's (:func:`mistake_ranges`): a student gets the hint of the mistake nearest
to their value.

PrairieLearn: a question folder (``info.json``, ``question.html``, ``server.py``)
whose ``generate()`` picks one of the same variants by ``data["variant_seed"]``
and whose ``grade()`` gives a wrong answer the same mistake hints (in place of
pl-number-input's "does not have precision" message, which ``rtol="0"`` would give
every wrong answer).

Neither question text carries the problem's citation (its Source line): the
citations of the bundled problems quote their published answers.

Nothing here needs more than the standard library and derive itself.
"""

from __future__ import annotations

import copy
import hashlib
import html
import pprint
import re
import uuid
import xml.etree.ElementTree as ET
from dataclasses import dataclass, replace
from decimal import Decimal
from pathlib import Path

import sympy

from derive.checking import mistakes
from derive.errors import InputError
from derive.fileio import dumps_json
from derive.homework.variants import Compiled, Variant, answers, fill, statement_only
from derive.numbers import figures_for, format_number
from derive.problem import Problem
from derive.symbols import latex_name

#: The tolerance in units of the last digit shown: ½ (rounding) + 1 (the checker's allowance).
TOLERANCE_UNITS = Decimal("1.5")
#: The tolerance of an answer shown as an exact zero (it rounds to 0.00).
ZERO_TOLERANCE = Decimal("0.005")
#: PrairieLearn compares |x - c| <= atol in doubles, where 8.385 - 8.40 is 0.0150000000000006: its
#: atol is the tolerance widened by this fraction of the larger of |c| and the tolerance, so that the
#: ends of the range are right (Moodle widens its ranges the same way, by 1e-14).
EDGE = Decimal("1e-12")
#: Units a student may write instead of the one asked, with how many of them make one of it
#: (Moodle converts a response in one of these by its multiplier).
OTHER_UNITS: dict[str, tuple[tuple[str, Decimal], ...]] = {
    "m/s": (("km/h", Decimal("3.6")), ("ft/s", 1 / Decimal("0.3048")), ("cm/s", Decimal(100))),
    "ft/s": (("m/s", Decimal("0.3048")), ("mph", Decimal(3600) / 5280), ("in/s", Decimal(12))),
    "J": (("kJ", Decimal("0.001")),),
    "N·s": (("kg·m/s", Decimal(1)), ("kN·s", Decimal("0.001"))),
}
DEFAULT_GRADE = "1.0000000"
PENALTY = "0.3333333"
TOPIC = "Central impact"

_SOLUTION = "**Solution.**"
_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


# ---------------------------------------------------------------- Markdown to HTML


def md_to_html(md: str) -> str:
    """derive's Markdown as simple HTML: headings, paragraphs, lists, **bold**, *italics*,
    inline math as ``\\( \\)`` and display math (``$$ … $$``) as ``\\[ \\]`` for MathJax.

    Text is HTML-escaped; raw HTML in the Markdown (a figure) is left out.
    """
    out: list[str] = []
    para: list[str] = []
    items: list[str] = []

    def flush() -> None:
        if para:
            out.append(f"<p>{_inline(' '.join(para))}</p>")
            para.clear()
        if items:
            out.append("<ul>" + "".join(f"<li>{_inline(x)}</li>" for x in items) + "</ul>")
            items.clear()

    lines = md.splitlines()
    i = 0
    while i < len(lines):
        s = lines[i].strip()
        i += 1
        if not s:
            flush()
            continue
        if s.startswith("$$"):
            flush()
            rest = s[2:]
            body: list[str] = []
            while not rest.rstrip().endswith("$$"):
                body.append(rest)
                if i >= len(lines):
                    rest = "$$"
                    break
                rest = lines[i]
                i += 1
            body.append(rest.rstrip()[:-2])
            tex = "\n".join(x for x in body if x.strip()).strip()
            if tex:
                out.append(f"<p>\\[ {_esc(tex)} \\]</p>")
            continue
        heading = re.match(r"(#{1,6})\s+(.*)", s)
        if heading:
            flush()
            level = min(6, len(heading.group(1)) + 2)
            out.append(f"<h{level}>{_inline(heading.group(2))}</h{level}>")
            continue
        if s.startswith("<"):  # raw HTML (a figure): not carried over
            flush()
            continue
        if s.startswith(("- ", "* ")):
            if para:
                flush()
            items.append(s[2:])
            continue
        if items:
            flush()
        para.append(s)
    flush()
    return "\n".join(out)


def _esc(text: str) -> str:
    return html.escape(text, quote=False)


#: Classes MathJax 3 (PrairieLearn, Moodle 4.5+) and MathJax 2 (older Moodle) skip.
_NO_MATH = "mathjax_ignore tex2jax_ignore"


def _words(text: str) -> str:
    """A file's text (a title, a statement's words) as HTML that never turns into math:
    ``$`` and ``\\`` as character references, so a filter reading the HTML source (Moodle's
    TeX filter) finds no delimiter, and inside a span MathJax is told to skip, so the
    decoded text (``$5 or $10``, ``\\(x\\)``) is not typeset either."""
    out = _esc(text)
    if "$" not in out and "\\" not in out:
        return out
    out = out.replace("$", "&#36;").replace("\\", "&#92;")
    return f'<span class="{_NO_MATH}">{out}</span>'


def _inline(text: str) -> str:
    """One line of Markdown text: escapes undone, math kept as TeX, bold and italics."""
    out: list[str] = []
    run: list[str] = []
    open_tags: list[str] = []

    def flush_run() -> None:
        if run:
            out.append(_words(html.unescape("".join(run))))
            run.clear()

    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch == "\\" and i + 1 < n:
            run.append(text[i + 1])
            i += 2
            continue
        if ch == "$":
            end = text.find("$", i + 1)
            if end > i + 1:
                flush_run()
                out.append(f"\\({_esc(text[i + 1 : end])}\\)")
                i = end + 1
                continue
        if ch == "*":
            tag = "strong" if text.startswith("**", i) else "em"
            flush_run()
            if open_tags and open_tags[-1] == tag:
                open_tags.pop()
                out.append(f"</{tag}>")
            else:
                open_tags.append(tag)
                out.append(f"<{tag}>")
            i += 2 if tag == "strong" else 1
            continue
        run.append(ch)
        i += 1
    flush_run()
    out.extend(f"</{tag}>" for tag in reversed(open_tags))
    return "".join(out)


def _statement_html(md: str) -> str:
    """A statement page (heading, source, Given, Find) as HTML, without its title heading
    and without the Source paragraph (citations quote the published answers)."""
    lines = md.splitlines()
    while lines and (not lines[0].strip() or re.match(r"#\s", lines[0])):
        lines.pop(0)
    kept: list[str] = []
    in_source = False
    for line in lines:
        if line.startswith("*Source:"):
            in_source = True
        if in_source:
            in_source = bool(line.strip())
            continue
        kept.append(line)
    return md_to_html("\n".join(kept))


def _solution_md(page: str) -> str:
    cut = page.find(_SOLUTION)
    return page[cut:] if cut >= 0 else page


# ---------------------------------------------------------------- the asked result


@dataclass(frozen=True)
class Answer:
    """A variant's answer to the asked result: shown text, value, unit and tolerance."""

    name: str
    shown: str
    value: Decimal
    unit: str
    tolerance: Decimal
    figures: int  # the significant figures ``shown`` was rounded to


def significant_figures(shown: str) -> int:
    """The significant figures of a number as written, when nothing else is known: every
    digit from the first non-zero one, except the trailing zeros of a whole number."""
    d = Decimal(shown)
    if d == 0:
        return 1
    digits = "".join(map(str, d.as_tuple().digits)).lstrip("0")
    exp = d.as_tuple().exponent
    assert isinstance(exp, int)
    return len(digits.rstrip("0")) if exp >= 0 else len(digits)


def tolerance(shown: str, figures: int | None = None) -> Decimal:
    """The tolerance of an answer shown as ``shown``, rounded to ``figures`` significant
    figures: 1.5 units in its last significant digit (``figures`` None: counted by
    :func:`significant_figures`)."""
    d = Decimal(shown)
    if d == 0:
        return ZERO_TOLERANCE
    figs = significant_figures(shown) if figures is None else figures
    return TOLERANCE_UNITS.scaleb(d.adjusted() - figs + 1)


def _figures(value: float, digits: int | None) -> int:
    """The figures ``format_number(value, digits)`` rounds to (as the key shows numbers)."""
    return figures_for(Decimal(repr(float(value))), digits)


def _answer(name: str, row: dict, digits: int | None) -> Answer:
    shown = row["shown"]
    figs = _figures(row["value"], digits)
    return Answer(name, shown, Decimal(shown), row["unit"], tolerance(shown, figs), figs)


def default_result(compiled: Compiled, variants: list[Variant], digits: int | None = None) -> str:
    """The first of the problem's ``find`` results with a number in every variant (else the first result)."""
    common = _numeric_results(compiled, variants, digits)
    for name in compiled.problem.find:
        if name in common:
            return name
    if not common:
        raise InputError("no result has a number in the variants (a symbolic given remains)", field="--result")
    return common[0]


def _numeric_results(compiled: Compiled, variants: list[Variant], digits: int | None) -> list[str]:
    names: list[str] | None = None
    for v in variants:
        have = list(answers(compiled, v, digits))
        names = have if names is None else [n for n in names if n in have]
    return names or []


def resolve_result(compiled: Compiled, variants: list[Variant], result: str | None, digits: int | None = None) -> str:
    """``result`` checked (a result with a number in every variant), or the default."""
    if "md" not in compiled.templates:
        raise ValueError(
            "the LMS exports need the problem compiled for Markdown: compile_problem(problem, digits, 'md')"
        )
    if result is None:
        return default_result(compiled, variants, digits)
    have = _numeric_results(compiled, variants, digits)
    if result not in have:
        raise InputError(
            f"no such result with a number in every variant (expected one of: {', '.join(have)})",
            field=f"--result {result}",
        )
    return result


# ---------------------------------------------------------------- common mistakes


@dataclass(frozen=True)
class Wrong:
    """A wrong value that common mistakes predict, shown as the key shows numbers, and their hints."""

    shown: str
    tolerance: Decimal
    mistakes: tuple[str, ...]
    hints: tuple[str, ...]


class MistakeModel:
    """The common mistakes of :mod:`derive.mistakes` for every variant of a compiled problem.

    The mistakes' equations are set up once, on the problem with its varied givens
    symbolic; a variant only puts its numbers in (no new solve of the problem), so
    a variant costs about a tenth of a second.
    """

    def __init__(self, compiled: Compiled) -> None:
        self.compiled = compiled
        self.base = mistakes.Model(compiled.solution)
        self.registry = mistakes.REGISTRY
        self._wrong: dict[tuple, list[Wrong]] = {}

    def model(self, variant: Variant) -> mistakes.Model:
        """The mistakes' model with this variant's numbers in."""
        base, c = self.base, self.compiled
        values = {c.givens[n].symbol: variant.values[n] for n in c.names}
        numeric = {**base.numeric, **values}
        givens = []
        for g in base.problem.givens:
            if g.name in variant.values:
                g = replace(g, value=variant.values[g.name])
            elif g.value is None and g.definition is not None and not g.unknown:
                value = base.num(g.definition, values)
                if not value.free_symbols:
                    g = replace(g, value=value)
                    numeric[g.symbol] = value
            givens.append(g)
        m = copy.copy(base)  # shares the solved forms of the equations, which hold no numbers
        m.numeric = numeric
        m.problem = replace(base.problem, givens=tuple(givens))
        return m

    def values(self, variant: Variant, result: str) -> list[tuple[str, float]]:
        """(mistake name, the value of ``result`` it gives) for each mistake that applies."""
        m = self.model(variant)
        out = []
        for mk in self.registry.values():
            built = mk.build(m)
            if built is None:
                continue
            outcome = m.outcome(built, mk)
            q = outcome.results.get(result) if outcome is not None else None
            if q is None or q.value is None:
                continue
            try:
                x = complex(sympy.sympify(q.value).evalf(30))
            except (TypeError, ValueError):
                continue
            if abs(x.imag) > 1e-9 * max(1.0, abs(x.real)) or x.real != x.real or abs(x.real) == float("inf"):
                continue
            out.append((mk.name, x.real))
        return out

    def wrong(self, variant: Variant, right: Answer, digits: int | None) -> list[Wrong]:
        """The mistakes' values for ``right.name`` that a student would not get right anyway,
        one per value shown (mistakes that give the same value share it), in order of value."""
        d = digits if digits is not None else self.compiled.problem.digits
        key = (variant.number, tuple(sorted((k, str(x)) for k, x in variant.values.items())), right, d)
        if key in self._wrong:
            return self._wrong[key]
        found: dict[str, list[str]] = {}
        figs: dict[str, int] = {}
        for name, x in self.values(variant, right.name):
            shown = format_number(Decimal(repr(x)), d)
            if abs(Decimal(shown) - right.value) <= right.tolerance:
                continue  # within the right answer's tolerance: it grades as right
            found.setdefault(shown, []).append(name)
            figs.setdefault(shown, _figures(x, d))
        out = [
            Wrong(
                shown, tolerance(shown, figs[shown]), tuple(names), tuple(self.registry[n].description for n in names)
            )
            for shown, names in sorted(found.items(), key=lambda item: Decimal(item[0]))
        ]
        self._wrong[key] = out
        return out


@dataclass(frozen=True)
class Range:
    """Where a response gets a wrong answer's feedback: center ± half_width."""

    center: Decimal
    half_width: Decimal
    wrong: Wrong

    @property
    def low(self) -> Decimal:
        return self.center - self.half_width

    @property
    def high(self) -> Decimal:
        return self.center + self.half_width


def mistake_ranges(right: Answer, wrongs: list[Wrong]) -> list[Range]:
    """The ranges of the mistakes' answers, so that a response gets the feedback of the
    mistake nearest to it whichever answer an LMS tries first.

    A mistake's range is its own tolerance about its value, cut where it meets the
    right answer's range (which wins) and halfway to the next mistake's value. Each
    mistake's first range is centred on its value (the widest that fits); what is
    left on the wider side follows as a second range with the same feedback.
    """
    ordered = sorted(wrongs, key=lambda w: Decimal(w.shown))
    right_low, right_high = right.value - right.tolerance, right.value + right.tolerance
    out: list[Range] = []
    for i, w in enumerate(ordered):
        v = Decimal(w.shown)
        low, high = v - w.tolerance, v + w.tolerance
        if i > 0:
            low = max(low, (Decimal(ordered[i - 1].shown) + v) / 2)
        if i + 1 < len(ordered):
            high = min(high, (v + Decimal(ordered[i + 1].shown)) / 2)
        if v > right.value:
            low = max(low, right_high)
        else:
            high = min(high, right_low)
        half = min(v - low, high - v)
        if half <= 0:
            continue
        out.append(Range(v, half, w))
        rest_low, rest_high = (v + half, high) if high - v > half else (low, v - half)
        if rest_high > rest_low:
            out.append(Range((rest_low + rest_high) / 2, (rest_high - rest_low) / 2, w))
    return out


def _hint_text(wrong: Wrong) -> str:
    lead = "A common mistake gives this value." if len(wrong.hints) == 1 else "Common mistakes give this value."
    return " ".join([lead, *wrong.hints])


# ---------------------------------------------------------------- Moodle XML


def _clean(text: str) -> str:
    """Text that XML 1.0 can hold (control characters dropped)."""
    return _XML_BAD.sub("", text)


def _plain(d: Decimal) -> str:
    text = format(d, "f")
    return "0" if text.strip("-0.") == "" else text


def _text(parent: ET.Element, tag: str, text: str, **attrs: str) -> ET.Element:
    el = ET.SubElement(parent, tag, attrs)
    ET.SubElement(el, "text").text = _clean(text)
    return el


def _ask(compiled: Compiled, answer: Answer) -> str:
    """The sentence that says what to enter, as HTML."""
    r = compiled.solution.results[answer.name]
    unit = "degrees" if answer.unit == "deg" else answer.unit
    where = f", in {_esc(unit)}" if unit else ""
    figs = answer.figures
    return (
        f"<p>Enter \\({latex_name(answer.name)}\\), the {_esc(r.description)}{where}, "
        f"to {figs} significant figure{'s' if figs != 1 else ''}.</p>"
    )


def _units(question: ET.Element, unit: str) -> None:
    """Units optional (``showunits`` 0, ``unitgradingtype`` 0): the asked unit, or one of
    :data:`OTHER_UNITS` that Moodle converts by its multiplier (units per asked unit)."""
    ET.SubElement(question, "unitgradingtype").text = "0"
    ET.SubElement(question, "unitpenalty").text = "0.1000000"
    ET.SubElement(question, "showunits").text = "0" if unit else "3"
    ET.SubElement(question, "unitsleft").text = "0"
    if not unit:
        return
    units = ET.SubElement(question, "units")
    names = [(unit, Decimal(1)), ("°", Decimal(1))] if unit == "deg" else [(unit, Decimal(1))]
    for name, multiplier in [*names, *OTHER_UNITS.get(unit, ())]:
        u = ET.SubElement(units, "unit")
        ET.SubElement(u, "multiplier").text = (
            _plain(multiplier.normalize()) if multiplier == 1 else f"{multiplier:.15g}"
        )
        ET.SubElement(u, "unit_name").text = name


def _problem_name(compiled: Compiled) -> str:
    p = compiled.problem
    return p.name or Path(p.path).stem or "problem"


def moodle_xml(
    compiled: Compiled,
    variants: list[Variant],
    *,
    result: str | None = None,
    digits: int | None = None,
    category: str | None = None,
    with_mistakes: bool = True,
    model: MistakeModel | None = None,
) -> str:
    """The variants as Moodle XML: a category, then one numerical question per variant.

    ``category`` defaults to ``$course$/derive/<problem name>``; ``result`` to
    :func:`default_result`. With ``with_mistakes`` each question also has the values
    common mistakes give, as wrong answers whose feedback is the mistake's hint, in
    the ranges of :func:`mistake_ranges` (``model``: a :class:`MistakeModel` to share).
    """
    result = resolve_result(compiled, variants, result, digits)
    p = compiled.problem
    d = digits if digits is not None else p.digits
    name = _problem_name(compiled)
    if category is None:
        category = f"$course$/derive/{name}"
    if not with_mistakes:
        model = None
    elif model is None:
        model = MistakeModel(compiled)
    quiz = ET.Element("quiz")
    cat = ET.SubElement(quiz, "question", {"type": "category"})
    _text(cat, "category", category)
    _text(cat, "info", f"<p>{_words(p.title)}: {len(variants)} variants drawn by derive.</p>", format="html")
    width = max(2, len(str(len(variants))))
    symbol = latex_name(result)
    for v in variants:
        page = fill(compiled, v, "md", digits)
        right = _answer(result, answers(compiled, v, digits)[result], d)
        q = ET.SubElement(quiz, "question", {"type": "numerical"})
        _text(q, "name", f"{p.title} — variant {v.number:0{width}d} ({result})")
        _text(q, "questiontext", _statement_html(statement_only(page)) + "\n" + _ask(compiled, right), format="html")
        _text(q, "generalfeedback", md_to_html(_solution_md(page)), format="html")
        ET.SubElement(q, "defaultgrade").text = DEFAULT_GRADE
        ET.SubElement(q, "penalty").text = PENALTY
        ET.SubElement(q, "hidden").text = "0"
        unit = f" {right.unit}" if right.unit and right.unit != "deg" else ("°" if right.unit else "")
        a = ET.SubElement(q, "answer", {"fraction": "100", "format": "moodle_auto_format"})
        ET.SubElement(a, "text").text = _plain(right.value)
        _text(a, "feedback", f"<p>Right: \\({symbol} = {_esc(right.shown)}\\){_esc(unit)}.</p>", format="html")
        ET.SubElement(a, "tolerance").text = _plain(right.tolerance)
        for r in mistake_ranges(right, model.wrong(v, right, digits)) if model is not None else []:
            a = ET.SubElement(q, "answer", {"fraction": "0", "format": "moodle_auto_format"})
            ET.SubElement(a, "text").text = _plain(r.center)
            lead = (
                "A common mistake gives this value." if len(r.wrong.hints) == 1 else "Common mistakes give this value."
            )
            body = "".join(f"<p>{_esc(h)}</p>" for h in r.wrong.hints)
            _text(a, "feedback", f"<p>{lead}</p>{body}", format="html")
            ET.SubElement(a, "tolerance").text = _plain(r.half_width)
        _units(q, right.unit)
    ET.indent(quiz, space="  ")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(quiz, encoding="unicode") + "\n"


# ---------------------------------------------------------------- PrairieLearn

_PARAM = "DRVPARAM{}X"


def _statement_template(compiled: Compiled) -> tuple[str, dict[str, tuple[str, str]]] | None:
    """The statement as HTML with ``{{params.NAME}}`` where each varied given's number
    goes, and what each parameter is (given name, slot kind); None when the statement
    holds a number that is not a varied given's."""
    parts = compiled.templates.get("md")
    if parts is None:
        return None
    by_symbol = {compiled.givens[n].symbol: n for n in compiled.names}
    keys: dict[str, tuple[str, str]] = {}
    out: list[str] = []
    for part in parts:
        if isinstance(part, str):
            cut = part.find(_SOLUTION)
            out.append(part if cut < 0 else part[:cut])
            if cut >= 0:
                break
            continue
        slot = compiled.book.slots[part]
        given = by_symbol.get(slot.expr)
        if given is None or slot.kind not in ("given", "text"):
            return None
        key = given if slot.kind == "text" else f"derive_given_{given}"
        keys[key] = (given, slot.kind)
        out.append(_PARAM.format(list(keys).index(key)))
    page = _statement_html("".join(out))
    page = re.sub(r"\{(?=\{)", "{ ", page)  # literal {{ in TeX is not Mustache
    page = re.sub(r"\}(?=\})", "} ", page)
    for i, key in enumerate(keys):
        page = page.replace(_PARAM.format(i), "{{params." + key + "}}")
    return page, keys


def _params(compiled: Compiled, variant: Variant, keys: dict[str, tuple[str, str]], digits: int | None) -> dict:
    from derive.homework.variants import given_text

    d = digits if digits is not None else compiled.problem.digits
    out = {}
    for key, (name, kind) in keys.items():
        text = given_text(compiled.givens[name], variant.values[name], d)
        out[key] = rf"\left({text}\right)" if kind == "given" and text.startswith("-") else text
    return out


def _uuid(compiled: Compiled, result: str, seed: int | None, variants: list[Variant]) -> str:
    if seed is None:  # the variants themselves stand for the seed
        seed_text = hashlib.sha256(
            repr([sorted((k, str(x)) for k, x in v.values.items()) for v in variants]).encode()
        ).hexdigest()
    else:
        seed_text = str(seed)
    return str(uuid.uuid5(uuid.NAMESPACE_URL, f"derive:{_problem_name(compiled)}:seed={seed_text}:result={result}"))


_SERVER = '''"""PrairieLearn question server, written by derive (derive variants --prairielearn).

generate() gives each PrairieLearn variant one of the homework variants drawn by
derive, by data["variant_seed"] modulo their number: the same numbers, answers and
worked solutions as the answer key. Regenerate it with derive rather than edit it.
"""

TITLE = {title}
RESULT = {result}
VARIANTS = {variants}


def generate(data):
    variant = VARIANTS[int(data.get("variant_seed", 0)) % len(VARIANTS)]
    data.setdefault("params", {{}}).update(variant["params"])
    data.setdefault("correct_answers", {{}})[RESULT] = variant["answer"]


def grade(data):
    """A wrong answer near a value a common mistake gives gets that mistake's hint, in place
    of pl-number-input's "does not have precision" message (which rtol="0" gives every
    wrong answer); the score stays the element's."""
    part = data.get("partial_scores", {{}}).get(RESULT)
    if not part or part.get("score", 0) >= 1:
        return
    variant = VARIANTS[int(data.get("variant_seed", 0)) % len(VARIANTS)]
    hint = None
    try:
        x = float(data["submitted_answers"][RESULT])
    except (KeyError, TypeError, ValueError):
        x = None
    if x is not None:
        for low, high, text in variant["mistakes"]:
            if low <= x <= high:
                hint = text
                break
    part["feedback"] = hint
'''


def prairielearn_files(
    compiled: Compiled,
    variants: list[Variant],
    *,
    result: str | None = None,
    digits: int | None = None,
    seed: int | None = None,
    with_mistakes: bool = True,
    model: MistakeModel | None = None,
) -> dict[str, str]:
    """The files of a PrairieLearn question (name -> text): info.json, question.html, server.py.

    pl-number-input grades with ``rtol="0"`` and ``atol`` the tolerance, widened by
    :data:`EDGE` so that the ends of the range are right in floating point; server.py's
    ``grade()`` gives the mistakes' hints in the ranges Moodle uses."""
    result = resolve_result(compiled, variants, result, digits)
    p = compiled.problem
    d = digits if digits is not None else p.digits
    if not with_mistakes:
        model = None
    elif model is None:
        model = MistakeModel(compiled)
    template = _statement_template(compiled)
    rows = []
    for v in variants:
        page = fill(compiled, v, "md", digits)
        right = _answer(result, answers(compiled, v, digits)[result], d)
        ranges = mistake_ranges(right, model.wrong(v, right, digits)) if model is not None else []
        if template is not None:
            params = _params(compiled, v, template[1], digits)
        else:
            params = {"derive_statement": _statement_html(statement_only(page))}
        params.update(
            {
                "derive_variant": v.number,
                "derive_figures": right.figures,
                "derive_atol": float(right.tolerance + EDGE * max(abs(right.value), right.tolerance)),
                "derive_solution": md_to_html(_solution_md(page)),
            }
        )
        mistake_rows = [[float(r.low), float(r.high), _hint_text(r.wrong)] for r in ranges]
        rows.append({"number": v.number, "params": params, "answer": float(right.value), "mistakes": mistake_rows})
    statement = template[0] if template is not None else "{{{params.derive_statement}}}"
    r = compiled.solution.results[result]
    unit = answers(compiled, variants[0], digits)[result]["unit"] if variants else ""
    unit_words = "degrees" if unit == "deg" else unit
    where = f", in {_esc(unit_words)}" if unit_words else ""
    symbol = latex_name(result)
    suffix = f' suffix="{html.escape("°" if unit == "deg" else unit)}"' if unit else ""
    question = (
        "<pl-question-panel>\n"
        f"{statement}\n"
        f"<p>Enter \\({symbol}\\), the {_esc(r.description)}{where}, "
        "to {{params.derive_figures}} significant figures.</p>\n"
        "</pl-question-panel>\n\n"
        f'<pl-number-input answers-name="{html.escape(result)}" label="\\({symbol} =\\)"{suffix} '
        'comparison="relabs" rtol="0" atol="{{params.derive_atol}}"></pl-number-input>\n\n'
        "<pl-answer-panel>\n{{{params.derive_solution}}}\n</pl-answer-panel>\n"
    )
    info = {
        "uuid": _uuid(compiled, result, seed, variants),
        "title": f"{p.title} ({result})",
        "topic": TOPIC,
        "tags": ["derive", p.kind, _problem_name(compiled)],
        "type": "v3",
    }
    server = _SERVER.format(
        title=repr(p.title),
        result=repr(result),
        variants=pprint.pformat(rows, width=100, sort_dicts=False),
    )
    return {
        "info.json": dumps_json(info),
        "question.html": _clean(question),
        "server.py": server,
    }


def prairielearn(
    compiled: Compiled,
    variants: list[Variant],
    folder: str | Path,
    *,
    result: str | None = None,
    digits: int | None = None,
    seed: int | None = None,
) -> None:
    """Write a PrairieLearn question folder for the variants (each file atomically)."""
    _folder(folder, prairielearn_files(compiled, variants, result=result, digits=digits, seed=seed)).write()


# ---------------------------------------------------------------- the CLI's exports


@dataclass
class Exports:
    """Export files built in memory (path, text), and the folders they need."""

    files: list[tuple[Path, str]]
    folders: list[Path]

    def write(self, inputs: tuple[Path, ...] = ()) -> None:
        """Create the folders, then write each file atomically (never over one of ``inputs``)."""
        from derive.fileio import write_atomic

        for folder in self.folders:
            if folder.exists() and not folder.is_dir():
                raise InputError("exists and is not a folder", where=str(folder))
            folder.mkdir(parents=True, exist_ok=True)
        for path, text in self.files:
            write_atomic(path, text, inputs=inputs)


def _folder(folder: str | Path, files: dict[str, str]) -> Exports:
    return Exports([(Path(folder) / name, text) for name, text in files.items()], [Path(folder)])


def build_exports(
    problem: Problem,
    *,
    count: int,
    seed: int,
    digits: int | None = None,
    result: str | None = None,
    moodle: str | None = None,
    prairielearn: str | None = None,
) -> Exports:
    """What ``derive variants --moodle/--prairielearn`` writes, built in memory first so
    that a bad ``--result`` writes nothing. The variants are those ``write_variants``
    draws for the same file and seed."""
    from derive.homework.variants import compile_problem, draw

    if moodle:
        # the folder is made when the files are written (it may be the -o folder, not made yet)
        parent = Path(moodle).parent
        for folder in (parent, *parent.parents):
            if folder.exists() and not folder.is_dir():
                raise InputError("a folder on the way is a file", where=str(folder), field="--moodle")
        if Path(moodle).is_dir():
            raise InputError("is a folder, not a file", where=moodle, field="--moodle")
    if prairielearn and Path(prairielearn).exists() and not Path(prairielearn).is_dir():
        raise InputError("exists and is not a folder", where=prairielearn, field="--prairielearn")
    compiled = compile_problem(problem, digits, "md")
    chosen = draw(compiled, count, seed)
    result = resolve_result(compiled, chosen, result, digits)
    model = MistakeModel(compiled)  # shared: each variant's mistakes are worked out once
    out = Exports([], [])
    if moodle:
        out.files.append((Path(moodle), moodle_xml(compiled, chosen, result=result, digits=digits, model=model)))
        out.folders.append(Path(moodle).parent)
    if prairielearn:
        files = prairielearn_files(compiled, chosen, result=result, digits=digits, seed=seed, model=model)
        pl = _folder(prairielearn, files)
        out.files += pl.files
        out.folders += pl.folders
    return out
