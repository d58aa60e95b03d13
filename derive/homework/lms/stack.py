"""STACK questions (Moodle XML, ``<question type="stack">``): one question per asked result,
holding all the variants; the format of STACK 4.11.1 (``questiontype.php``, export_to_xml and
import_from_xml, stackversion 2026010500).

A STACK question draws its variant from the seed the quiz deploys. Its question variables,
plain Maxima, index derive's variants by ``n1:mod(stack_seed-1,N)+1``: the deployed seeds
1..N are derive's variants 1..N, and every number the question needs is a list with one
entry per variant (the varied givens, the right answer and its tolerance, each mistake
node's value and range, the statement's numbers as derive prints them: STACK's own display
of a float drops its trailing zeros). The question text is the student's sheet with those
numbers and one input; the worked solution of each variant is the general feedback, in an
``[[if]]``/``[[elif]]`` branch per variant; the potential response tree is
:mod:`~derive.homework.lms.stack_tree`'s. Text from derive is always inside
``[[escape]]...[[/escape]]``, so that ``{@``, ``{#``, ``[[`` in it are never CASText.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from decimal import Decimal

from derive.errors import InputError
from derive.homework.lms.grading import resolve_result
from derive.homework.lms.markup import esc, result_html, solution_html, statement_html, words
from derive.homework.lms.mistake_model import MistakeModel
from derive.homework.lms.moodle import PENALTY, problem_name, quiz_element, text_element, xml_document
from derive.homework.lms.stack_tree import MistakeNode, Tree, build_tree
from derive.homework.variants import Compiled, Variant, fill_view, setup_figure
from derive.symbols import latex_name

#: The STACK version whose format this follows (STACK 4.11.1, ``$plugin->version``).
STACK_VERSION = "2026010500"
#: How many variants a STACK question holds by default, and at most: each attempt sends the
#: question's variables and text, with every variant's worked solution, to Maxima.
DEFAULT_COUNT = 20
MAX_COUNT = 50
#: derive's units that STACK's units (SI with prefixes) know, as Maxima writes them; a
#: result in another unit (ft/s, degrees, lb) has a numerical input, its unit after the box.
STACK_UNITS = {
    "m/s": "m/s",
    "m/s²": "m/s^2",
    "J": "J",
    "kJ": "kJ",
    "N": "N",
    "N·s": "N*s",
    "kg·m/s": "kg*m/s",
    "kg": "kg",
    "m": "m",
    "s": "s",
    "W": "W",
    "N·m": "N*m",
}
INPUT = "ans1"
PRT = "prt1"
RIGHT_NOTE = "right"


def maxima_number(d: Decimal | float) -> str:
    """A number as a Maxima float: plain digits with a point (``8.40``, ``-0.0015``, ``1050.0``)."""
    text = format(Decimal(str(d)) if isinstance(d, float) else d, "f")
    return text if "." in text else text + ".0"


def maxima_string(text: str) -> str:
    """A Maxima string literal."""
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def escaped(text: str) -> str:
    """Text from derive as CASText that is never parsed: inside ``[[escape]]`` (whose end,
    ``[[/escape]]``, it cannot contain: ``[[/`` is written ``[&#91;/``)."""
    if not text:
        return ""
    return "[[escape]]" + text.replace("[[/", "[&#91;/") + "[[/escape]]"


def per_variant(bodies: list[str]) -> str:
    """One branch per variant, ``[[if test="is(n1=1)"]]...[[elif test="is(n1=2)"]]...[[/if]]``,
    each body escaped."""
    parts = []
    for k, body in enumerate(bodies, 1):
        parts.append(f'[[{"if" if k == 1 else "elif"} test="is(n1={k})"]]{escaped(body)}')
    return "".join(parts) + "[[/if]]" if parts else ""


def _name(prefix: str, name: str) -> str:
    return prefix + re.sub(r"\W", "_", name, flags=re.ASCII)


def _list(items: list[str]) -> str:
    return "[" + ",".join(items) + "]"


class _Question:
    """One STACK question (one asked result) being built."""

    def __init__(self, compiled: Compiled, variants: list[Variant], tree: Tree, digits: int | None) -> None:
        self.c, self.variants, self.tree, self.digits = compiled, variants, tree, digits
        self.unit = tree.rights[0].unit if tree.rights else ""
        self.stack_unit = STACK_UNITS.get(self.unit, "")
        self.pages = [fill_view(compiled, v, digits) for v in variants]

    def with_unit(self, number: str) -> str:
        """A Maxima expression of ``number`` in the asked unit (the input's kind of answer)."""
        return f"{number}*{self.stack_unit}" if self.stack_unit else number

    def variables(self) -> str:
        """The question variables: the index, then the lists, then the teacher's answer."""
        c, t, n = self.c, self.tree, len(self.variants)
        lines = [
            f"/* derive: {problem_name(c)}, {n} variants; seed k is derive's variant k */",
            f"n1:mod(stack_seed-1,{n})+1;",
        ]
        for g in self.variants[0].values if self.variants else ():
            values = [maxima_number(float(v.values[g])) for v in self.variants]
            lines.append(f"{_name('dg_', g)}:{_list(values)};")
        lines.append(f"dans:{_list([maxima_number(r.value) for r in t.rights])};")
        lines.append(f"ds_ans:{_list([maxima_string(r.shown) for r in t.rights])};")
        lines.append(f"dtol:{_list([maxima_number(r.tolerance) for r in t.rights])};")
        figs = [f"{r.figures} significant figure{'s' if r.figures != 1 else ''}" for r in t.rights]
        lines.append(f"dfig:{_list([maxima_string(f) for f in figs])};")
        lines.append(f"dnote:{_list([maxima_string(self.note(k)) for k in range(n)])};")
        for i, node in enumerate(t.nodes, 1):
            lines.append(f"/* node {i + 1}: {node.name} */")
            lines.append(
                f"dw{i}:{_list([maxima_number(Decimal(s.shown) if s.live else s.center) for s in node.spans])};"
            )
            lines.append(f"dc{i}:{_list([maxima_number(s.center) for s in node.spans])};")
            lines.append(f"dh{i}:{_list([maxima_number(s.half) for s in node.spans])};")
        lines.append(f"ta1:{self.with_unit('dans[n1]')};")
        return "\n".join(lines)

    def note(self, k: int) -> str:
        """The question note of variant k+1: its number, varied givens and answer (unique per variant)."""
        v, right = self.variants[k], self.tree.rights[k]
        givens = ", ".join(f"{g} = {float(v.values[g]):g}" for g in sorted(v.values))
        unit = f" {right.unit}" if right.unit else ""
        return f"derive variant {v.number}: {givens}; {self.tree.result} = {right.shown}{unit}"

    def statement(self) -> str:
        """The student's sheet: each variant's statement (a variant is its own problem, written
        as any page is), one branch per variant."""
        return per_variant([statement_html(p) for p in self.pages])

    def question_text(self) -> str:
        """Statement, set-up figure (inline SVG, per variant), what to enter, the input."""
        c, result = self.c, self.tree.result
        figures = [setup_figure(c, v, "md") for v in self.variants]
        figure = per_variant([f'<div class="derive-figure">{f}</div>' for f in figures]) if any(figures) else ""
        unit_words = "degrees" if self.unit == "deg" else self.unit
        where = f", in {esc(unit_words)}" if unit_words else ""
        symbol = latex_name(result)
        ask = escaped(f"<p>Enter \\({symbol}\\), {result_html(c, result)}{where}, to ") + "{@dfig[n1]@}."
        if self.stack_unit:
            how = f"with its unit (for example <code>{esc(self.example())}</code>)"
        else:
            how = f"a number{where}" if unit_words else "a number"
        box = escaped(f"<p>\\({symbol} =\\) ") + f"[[input:{INPUT}]] " + escaped(f"({how})</p>")
        return "\n".join(
            p for p in (self.statement(), figure, ask + escaped("</p>"), box, f"[[validation:{INPUT}]]") if p
        )

    def example(self) -> str:
        shown = self.tree.rights[0].shown if self.tree.rights else "1"
        return f"{shown}*{self.stack_unit}"

    def general_feedback(self) -> str:
        """Each variant's worked solution (derive's HTML), in its own branch."""
        return per_variant([solution_html(p) for p in self.pages])


def _fields(parent: ET.Element, **fields: str) -> None:
    for tag, text in fields.items():
        ET.SubElement(parent, tag).text = text


def _options(q: ET.Element) -> None:
    """The question's options, as STACK's default (``stack_options``) sets them."""
    _fields(q, questionsimplify="1", assumepositive="0", assumereal="0")
    text_element(q, "prtcorrect", "<p>Correct answer, well done.</p>", format="html")
    text_element(q, "prtpartiallycorrect", "<p>Your answer is partially correct.</p>", format="html")
    text_element(q, "prtincorrect", "<p>Incorrect answer.</p>", format="html")
    _fields(
        q,
        decimals=".",
        scientificnotation="*10",
        multiplicationsign="dot",
        sqrtsign="1",
        complexno="i",
        inversetrig="cos-1",
        logicsymbol="lang",
        matrixparens="[",
        isbroken="0",
        variantsselectionseed="",
    )


def _input(q: ET.Element, question: _Question) -> None:
    """One input: ``units`` where STACK knows the unit, else ``numerical`` (floats allowed)."""
    el = ET.SubElement(q, "input")
    _fields(
        el,
        name=INPUT,
        type="units" if question.stack_unit else "numerical",
        tans="ta1",
        boxsize="15",
        strictsyntax="1",
        insertstars="4" if question.stack_unit else "0",  # "8.40 m/s": a space is a product
        syntaxhint="",
        syntaxattribute="0",
        forbidwords="",
        allowwords="",
        forbidfloat="0",
        requirelowestterms="0",
        checkanswertype="0",
        mustverify="1",
        showvalidation="1",
        options="",
    )


def _node(prt: ET.Element, i: int, test: str, tans: str, opt: str, true: tuple[str, str, str], last: bool) -> None:
    """Node ``i`` (0-based): ``test`` of the input against ``tans`` with option ``opt``; when
    true: ``true`` = (score, answer note, feedback), end; when false: the next node."""
    node = ET.SubElement(prt, "node")
    score, note, feedback = true
    _fields(node, name=str(i), description="", answertest=test, sans=INPUT, tans=tans, testoptions=opt, quiet="0")
    _fields(node, truescoremode="=", truescore=score, truepenalty="", truenextnode="-1", trueanswernote=note)
    text_element(node, "truefeedback", feedback, format="html")
    _fields(
        node,
        falsescoremode="=",
        falsescore="0.0000000",
        falsepenalty="",
        falsenextnode="-1" if last else str(i + 1),
        falseanswernote=f"{PRT}-{i + 1}-F",
    )
    text_element(node, "falsefeedback", "", format="html")


def _mistake_feedback(node: MistakeNode, model: MistakeModel) -> str:
    """The node's feedback: its mistake's hint, and the hints of mistakes it holds in some variants."""
    shared = node.shared()
    lead = "<p>A common mistake gives this value.</p>"
    if shared:
        ks = sorted({k for v in shared.values() for k in v})
        lead = (
            f'[[if test="member(n1,{_list([str(k) for k in ks])})"]]'
            + escaped("<p>Common mistakes give this value.</p>")
            + "[[else]]"
            + escaped(lead)
            + "[[/if]]"
        )
    else:
        lead = escaped(lead)
    out = lead + escaped(f"<p>{esc(node.hint)}</p>")
    for other, ks in shared.items():
        hint = f"<p>{esc(model.registry[other].description)}</p>"
        out += f'[[if test="member(n1,{_list([str(k) for k in ks])})"]]' + escaped(hint) + "[[/if]]"
    return out


def _prt(q: ET.Element, question: _Question, model: MistakeModel) -> None:
    """The potential response tree: node 1 the right answer at derive's tolerance, then one node per mistake."""
    test = "UnitsAbsolute" if question.stack_unit else "NumAbsolute"
    prt = ET.SubElement(q, "prt")
    _fields(prt, name=PRT, value="1.0000000", autosimplify="1", feedbackstyle="1")
    text_element(prt, "feedbackvariables", "")
    nodes = question.tree.nodes
    symbol = latex_name(question.tree.result)
    unit = "°" if question.unit == "deg" else (f" {question.unit}" if question.unit else "")
    right = escaped(f"<p>Right: \\({symbol}\\) is ") + "{@ds_ans[n1]@}" + escaped(f"{esc(unit)}.</p>")
    _node(prt, 0, test, question.with_unit("dans[n1]"), "dtol[n1]", ("1.0000000", RIGHT_NOTE, right), not nodes)
    for i, node in enumerate(nodes, 1):
        feedback = _mistake_feedback(node, model)
        tans, opt = question.with_unit(f"dc{i}[n1]"), f"dh{i}[n1]"
        _node(prt, i, test, tans, opt, ("0.0000000", node.name, feedback), i == len(nodes))


def _qtests(q: ET.Element, question: _Question) -> None:
    """Question tests, run by STACK on every deployed variant: the right answer as the key shows
    it scores 1; the value of each mistake whose node is on in every variant reaches its note."""
    cases = [("The right answer, as derive's key shows it", "dans[n1]", "1.0000000", "0.0000000", RIGHT_NOTE)]
    for i, node in enumerate(question.tree.nodes, 1):
        if node.always_live():
            cases.append((f"The value the mistake {node.name} gives", f"dw{i}[n1]", "0.0000000", PENALTY, node.name))
    for n, (description, value, score, penalty, note) in enumerate(cases, 1):
        t = ET.SubElement(q, "qtest")
        _fields(t, testcase=str(n), description=description)
        _fields(ET.SubElement(t, "testinput"), name=INPUT, value=question.with_unit(value))
        e = ET.SubElement(t, "expected")
        _fields(e, name=PRT, expectedscore=score, expectedpenalty=penalty, expectedanswernote=note)


def stack_question(
    compiled: Compiled, variants: list[Variant], result: str, digits: int | None, model: MistakeModel
) -> ET.Element:
    """One ``<question type="stack">`` asking for ``result`` in every variant."""
    tree = build_tree(compiled, variants, result, digits, model)
    question = _Question(compiled, variants, tree, digits)
    q = ET.Element("question", {"type": "stack"})
    text_element(q, "name", f"{compiled.problem.title} ({result})")
    text_element(q, "questiontext", question.question_text(), format="html")
    text_element(q, "generalfeedback", question.general_feedback(), format="html")
    _fields(q, defaultgrade="1", penalty=PENALTY, hidden="0", idnumber="")
    text_element(q, "stackversion", STACK_VERSION)
    text_element(q, "questionvariables", question.variables())
    text_element(q, "specificfeedback", f"[[feedback:{PRT}]]", format="html")
    text_element(q, "questionnote", "{@dnote[n1]@}", format="html")
    text_element(
        q,
        "questiondescription",
        escaped(f"<p>Written by derive from {words(problem_name(compiled))}.</p>"),
        format="html",
    )
    _options(q)
    _input(q, question)
    _prt(q, question, model)
    for k in range(1, len(variants) + 1):
        ET.SubElement(q, "deployedseed").text = str(k)
    _qtests(q, question)
    return q


def stack_results(compiled: Compiled, variants: list[Variant], result: str | None, digits: int | None) -> list[str]:
    """The results to ask: ``result``, else each of the problem's ``find`` results with a number
    in every variant (else the default one)."""
    if result is not None:
        return [resolve_result(compiled, variants, result, digits)]
    default = resolve_result(compiled, variants, None, digits)
    out = []
    for name in compiled.problem.find:
        try:
            out.append(resolve_result(compiled, variants, name, digits))
        except InputError:  # a find result without a number in some variant is left out
            continue
    return out or [default]


def stack_xml(
    compiled: Compiled,
    variants: list[Variant],
    *,
    result: str | None = None,
    digits: int | None = None,
    model: MistakeModel | None = None,
) -> str:
    """The variants as Moodle XML for STACK: a category, then one STACK question per asked
    result (``result``, else each of the problem's ``find`` results with a number)."""
    if not 1 <= len(variants) <= MAX_COUNT:
        raise ValueError(f"a STACK question holds 1 to {MAX_COUNT} variants, not {len(variants)}")
    results = stack_results(compiled, variants, result, digits)
    model = MistakeModel(compiled) if model is None else model
    quiz = quiz_element(compiled, None, "STACK questions by derive.")
    for r in results:
        quiz.append(stack_question(compiled, variants, r, digits, model))
    return xml_document(quiz)
