"""Homework variants for a learning-management system: Moodle XML and PrairieLearn.

Both exports ask for one result (``--result``) of each variant drawn by
:mod:`derive.variants`, graded by the significant-figure rule of ``derive check``:

* the right answer is the value as the answer key shows it (key.json ``shown``);
* the tolerance is 1.5 units in its last digit: half a unit, so that any answer
  that rounds to the shown value counts, plus the ±1 in the last digit that
  ``derive check`` allows for rounded intermediates. For v = 8.40 m/s it is
  0.015 m/s (8.385 to 8.415). An exact zero (shown ``0``) gets ±0.005.

Moodle: one numerical question per variant, all in one category (a random
question drawn from it gives each student a variant), with the worked solution as
general feedback and, where :mod:`derive.mistakes` predicts the value a common
mistake gives, that value as a wrong answer with the mistake's hint as feedback.

PrairieLearn: a question folder (``info.json``, ``question.html``, ``server.py``)
whose ``generate()`` picks one of the same variants by ``data["variant_seed"]``.

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
from derive.problem import Problem
from derive.symbols import latex_name

#: The tolerance in units of the last digit shown: ½ (rounding) + 1 (the checker's allowance).
TOLERANCE_UNITS = Decimal("1.5")
#: The tolerance of an answer shown as an exact zero (it rounds to 0.00).
ZERO_TOLERANCE = Decimal("0.005")
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


def _inline(text: str) -> str:
    """One line of Markdown text: escapes undone, math kept as TeX, bold and italics."""
    out: list[str] = []
    run: list[str] = []
    open_tags: list[str] = []

    def flush_run() -> None:
        if run:
            out.append(_esc(html.unescape("".join(run))))
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
    """A statement page (heading, source, Given, Find) as HTML, without its title heading."""
    lines = md.splitlines()
    while lines and (not lines[0].strip() or re.match(r"#\s", lines[0])):
        lines.pop(0)
    return md_to_html("\n".join(lines))


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

    @property
    def figures(self) -> int:
        return len(self.value.as_tuple().digits) if self.value != 0 else 1


def tolerance(shown: str) -> Decimal:
    """The tolerance of an answer shown as ``shown``: 1.5 units in its last digit."""
    d = Decimal(shown)
    if d == 0:
        return ZERO_TOLERANCE
    exp = d.as_tuple().exponent
    assert isinstance(exp, int)
    return TOLERANCE_UNITS.scaleb(exp)


def _answer(name: str, row: dict) -> Answer:
    shown = row["shown"]
    return Answer(name, shown, Decimal(shown), row["unit"], tolerance(shown))


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
        one per value shown (mistakes that give the same value share it)."""
        from derive.numbers import format_number

        d = digits if digits is not None else self.compiled.problem.digits
        found: dict[str, list[str]] = {}
        for name, x in self.values(variant, right.name):
            shown = format_number(Decimal(repr(x)), d)
            if abs(Decimal(shown) - right.value) <= right.tolerance:
                continue  # within the right answer's tolerance: it grades as right
            found.setdefault(shown, []).append(name)
        return [
            Wrong(shown, tolerance(shown), tuple(names), tuple(self.registry[n].description for n in names))
            for shown, names in found.items()
        ]


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
    """Units optional (``showunits`` 0, ``unitgradingtype`` 0): a unit, if typed, must be this one."""
    ET.SubElement(question, "unitgradingtype").text = "0"
    ET.SubElement(question, "unitpenalty").text = "0.1000000"
    ET.SubElement(question, "showunits").text = "0" if unit else "3"
    ET.SubElement(question, "unitsleft").text = "0"
    if not unit:
        return
    units = ET.SubElement(question, "units")
    for name in [unit, "°"] if unit == "deg" else [unit]:
        u = ET.SubElement(units, "unit")
        ET.SubElement(u, "multiplier").text = "1"
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
) -> str:
    """The variants as Moodle XML: a category, then one numerical question per variant.

    ``category`` defaults to ``$course$/derive/<problem name>``; ``result`` to
    :func:`default_result`. With ``with_mistakes`` each question also has the values
    common mistakes give, as wrong answers whose feedback is the mistake's hint.
    """
    result = resolve_result(compiled, variants, result, digits)
    p = compiled.problem
    name = _problem_name(compiled)
    if category is None:
        category = f"$course$/derive/{name}"
    model = MistakeModel(compiled) if with_mistakes else None
    quiz = ET.Element("quiz")
    cat = ET.SubElement(quiz, "question", {"type": "category"})
    _text(cat, "category", category)
    _text(cat, "info", f"<p>{_esc(p.title)}: {len(variants)} variants drawn by derive.</p>", format="html")
    width = max(2, len(str(len(variants))))
    symbol = latex_name(result)
    for v in variants:
        page = fill(compiled, v, "md", digits)
        right = _answer(result, answers(compiled, v, digits)[result])
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
        for wrong in model.wrong(v, right, digits) if model is not None else []:
            a = ET.SubElement(q, "answer", {"fraction": "0", "format": "moodle_auto_format"})
            ET.SubElement(a, "text").text = _plain(Decimal(wrong.shown))
            lead = "A common mistake gives this value." if len(wrong.hints) == 1 else "Common mistakes give this value."
            body = "".join(f"<p>{_esc(h)}</p>" for h in wrong.hints)
            _text(a, "feedback", f"<p>{lead}</p>{body}", format="html")
            ET.SubElement(a, "tolerance").text = _plain(wrong.tolerance)
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
'''


def prairielearn_files(
    compiled: Compiled,
    variants: list[Variant],
    *,
    result: str | None = None,
    digits: int | None = None,
    seed: int | None = None,
) -> dict[str, str]:
    """The files of a PrairieLearn question (name -> text): info.json, question.html, server.py."""
    result = resolve_result(compiled, variants, result, digits)
    p = compiled.problem
    template = _statement_template(compiled)
    rows = []
    for v in variants:
        page = fill(compiled, v, "md", digits)
        right = _answer(result, answers(compiled, v, digits)[result])
        if template is not None:
            params = _params(compiled, v, template[1], digits)
        else:
            params = {"derive_statement": _statement_html(statement_only(page))}
        params.update(
            {
                "derive_variant": v.number,
                "derive_figures": right.figures,
                "derive_atol": float(right.tolerance),
                "derive_solution": md_to_html(_solution_md(page)),
            }
        )
        rows.append({"number": v.number, "params": params, "answer": float(right.value)})
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
                raise InputError("exists and is not a folder", where=str(folder), field="--prairielearn")
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
        parent = Path(moodle).parent
        if not parent.is_dir():
            raise InputError("the folder for the output does not exist", where=moodle, field="--moodle")
    if prairielearn and Path(prairielearn).exists() and not Path(prairielearn).is_dir():
        raise InputError("exists and is not a folder", where=prairielearn, field="--prairielearn")
    compiled = compile_problem(problem, digits, "md")
    chosen = draw(compiled, count, seed)
    result = resolve_result(compiled, chosen, result, digits)
    out = Exports([], [])
    if moodle:
        out.files.append((Path(moodle), moodle_xml(compiled, chosen, result=result, digits=digits)))
    if prairielearn:
        pl = _folder(prairielearn, prairielearn_files(compiled, chosen, result=result, digits=digits, seed=seed))
        out.files += pl.files
        out.folders += pl.folders
    return out
