"""Moodle XML: a category, then one numerical question per variant, with the worked solution
as general feedback and the common mistakes' values as wrong answers with their hints."""

from __future__ import annotations

import base64
import xml.etree.ElementTree as ET
from decimal import Decimal
from pathlib import Path

from derive.homework.lms.grading import Answer, asked_answer, resolve_result
from derive.homework.lms.markup import clean_xml, esc, result_html, solution_html, statement_html, words
from derive.homework.lms.mistake_model import MistakeModel, mistake_ranges
from derive.homework.variants import Compiled, Variant, answers, fill_view, setup_figure
from derive.symbols import latex_name

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


def _plain(d: Decimal) -> str:
    text = format(d, "f")
    return "0" if text.strip("-0.") == "" else text


def text_element(parent: ET.Element, tag: str, text: str, **attrs: str) -> ET.Element:
    """A ``<tag>`` in ``parent`` whose ``<text>`` holds ``text`` (made safe for XML)."""
    el = ET.SubElement(parent, tag, attrs)
    ET.SubElement(el, "text").text = clean_xml(text)
    return el


#: The set-up figure's file inside a question (Moodle's importer stores each ``<file>`` of a
#: text, base64, and the text reaches it as ``@@PLUGINFILE@@/<name>``).
FIGURE_FILE = "setup.svg"


def _question_text(q: ET.Element, compiled: Compiled, v: Variant, statement: str, ask: str) -> None:
    """The question text: the variant's statement, its figure before the impact (an SVG file
    of the question, drawn to the variant's speeds) and what to enter."""
    figure = setup_figure(compiled, v, "md")
    shown = f'<p><img src="@@PLUGINFILE@@/{FIGURE_FILE}" alt="The set-up before the impact" /></p>\n' if figure else ""
    el = text_element(q, "questiontext", statement + "\n" + shown + ask, format="html")
    if figure:
        f = ET.SubElement(el, "file", {"name": FIGURE_FILE, "path": "/", "encoding": "base64"})
        f.text = base64.b64encode(figure.encode("utf-8")).decode("ascii")


def _ask(compiled: Compiled, answer: Answer) -> str:
    """The sentence that says what to enter, as HTML."""
    unit = "degrees" if answer.unit == "deg" else answer.unit
    where = f", in {esc(unit)}" if unit else ""
    figs = answer.figures
    return (
        f"<p>Enter \\({latex_name(answer.name)}\\), {result_html(compiled, answer.name)}{where}, "
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


def problem_name(compiled: Compiled) -> str:
    """The problem's name (else its file's stem) for categories, tags and uuids."""
    p = compiled.problem
    return p.name or Path(p.path).stem or "problem"


def moodle_xml(
    compiled: Compiled,
    variants: list[Variant],
    *,
    result: str | None = None,
    digits: int | None = None,
    category: str | None = None,
    model: MistakeModel | None = None,
) -> str:
    """The variants as Moodle XML: a category, then one numerical question per variant.

    ``category`` defaults to ``$course$/derive/<problem name>``; ``result`` to
    :func:`default_result`. Each question also has the values
    common mistakes give, as wrong answers whose feedback is the mistake's hint, in
    the ranges of :func:`mistake_ranges` (``model``: a :class:`MistakeModel` to share).
    """
    result = resolve_result(compiled, variants, result, digits)
    p = compiled.problem
    d = digits if digits is not None else p.digits
    if model is None:
        model = MistakeModel(compiled)
    quiz = quiz_element(compiled, category, f"{len(variants)} variants drawn by derive.")
    width = max(2, len(str(len(variants))))
    symbol = latex_name(result)
    for v in variants:
        page = fill_view(compiled, v, digits)
        right = asked_answer(result, answers(compiled, v, digits)[result], d)
        q = ET.SubElement(quiz, "question", {"type": "numerical"})
        text_element(q, "name", f"{p.title} — variant {v.number:0{width}d} ({result})")
        _question_text(q, compiled, v, statement_html(page), _ask(compiled, right))
        text_element(q, "generalfeedback", solution_html(page), format="html")
        ET.SubElement(q, "defaultgrade").text = DEFAULT_GRADE
        ET.SubElement(q, "penalty").text = PENALTY
        ET.SubElement(q, "hidden").text = "0"
        unit = f" {right.unit}" if right.unit and right.unit != "deg" else ("°" if right.unit else "")
        a = ET.SubElement(q, "answer", {"fraction": "100", "format": "moodle_auto_format"})
        ET.SubElement(a, "text").text = _plain(right.value)
        text_element(a, "feedback", f"<p>Right: \\({symbol} = {esc(right.shown)}\\){esc(unit)}.</p>", format="html")
        ET.SubElement(a, "tolerance").text = _plain(right.tolerance)
        for r in mistake_ranges(right, model.wrong(v, right, digits)):
            a = ET.SubElement(q, "answer", {"fraction": "0", "format": "moodle_auto_format"})
            ET.SubElement(a, "text").text = _plain(r.center)
            lead = (
                "A common mistake gives this value." if len(r.wrong.hints) == 1 else "Common mistakes give this value."
            )
            body = "".join(f"<p>{esc(h)}</p>" for h in r.wrong.hints)
            text_element(a, "feedback", f"<p>{lead}</p>{body}", format="html")
            ET.SubElement(a, "tolerance").text = _plain(r.half_width)
        _units(q, right.unit)
    return xml_document(quiz)


def quiz_element(compiled: Compiled, category: str | None, info: str) -> ET.Element:
    """A Moodle quiz whose first question sets its category (``category``, by default
    ``$course$/derive/<problem name>``) and says ``info`` about what follows."""
    quiz = ET.Element("quiz")
    cat = ET.SubElement(quiz, "question", {"type": "category"})
    text_element(cat, "category", f"$course$/derive/{problem_name(compiled)}" if category is None else category)
    text_element(cat, "info", f"<p>{words(compiled.problem.title)}: {info}</p>", format="html")
    return quiz


def xml_document(quiz: ET.Element) -> str:
    """``quiz`` as the text of an XML file, indented."""
    ET.indent(quiz, space="  ")
    return '<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(quiz, encoding="unicode") + "\n"
