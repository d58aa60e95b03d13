"""A PrairieLearn question folder (``info.json``, ``question.html``, ``server.py``) whose
``generate()`` picks one of derive's variants and whose ``grade()`` gives the mistakes' hints."""

from __future__ import annotations

import hashlib
import html
import pprint
import uuid
from pathlib import Path

from derive.fileio import dumps_json
from derive.homework.lms.files import folder_exports
from derive.homework.lms.grading import EDGE, asked_answer, resolve_result
from derive.homework.lms.markup import clean_xml, esc, result_html, solution_html, statement_html
from derive.homework.lms.mistake_model import MistakeModel, hint_text, mistake_ranges
from derive.homework.lms.moodle import problem_name
from derive.homework.variants import Compiled, Variant, answers, fill_view, given_values, setup_figure
from derive.symbols import latex_name

TOPIC = "Central impact"


def _uuid(compiled: Compiled, result: str, seed: int | None, variants: list[Variant]) -> str:
    if seed is None:  # the variants themselves stand for the seed
        seed_text = hashlib.sha256(
            repr([sorted((k, str(x)) for k, x in v.values.items()) for v in variants]).encode()
        ).hexdigest()
    else:
        seed_text = str(seed)
    return str(uuid.uuid5(uuid.NAMESPACE_URL, f"derive:{problem_name(compiled)}:seed={seed_text}:result={result}"))


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
    model: MistakeModel | None = None,
) -> dict[str, str]:
    """The files of a PrairieLearn question (name -> text): info.json, question.html, server.py.

    pl-number-input grades with ``rtol="0"`` and ``atol`` the tolerance, widened by
    :data:`EDGE` so that the ends of the range are right in floating point; server.py's
    ``grade()`` gives the mistakes' hints in the ranges Moodle uses."""
    result = resolve_result(compiled, variants, result, digits)
    p = compiled.problem
    model = MistakeModel(compiled) if model is None else model
    rows = [_row(compiled, v, result, digits, model) for v in variants]
    # each variant's statement whole: a variant is its own problem, written as any page is
    question = _question_html(compiled, variants, result, digits, "{{{params.derive_statement}}}")
    info = {
        "uuid": _uuid(compiled, result, seed, variants),
        "title": f"{p.title} ({result})",
        "topic": TOPIC,
        "tags": ["derive", p.kind, problem_name(compiled)],
        "type": "v3",
    }
    server = _SERVER.format(
        title=repr(p.title), result=repr(result), variants=pprint.pformat(rows, width=100, sort_dicts=False)
    )
    return {"info.json": dumps_json(info), "question.html": clean_xml(question), "server.py": server}


def _row(compiled: Compiled, v: Variant, result: str, digits: int | None, model: MistakeModel) -> dict:
    """One variant as server.py's VARIANTS hold it: parameters, answer, mistakes' ranges."""
    page = fill_view(compiled, v, digits)
    d = digits if digits is not None else compiled.problem.digits
    right = asked_answer(result, answers(compiled, v, digits)[result], d)
    ranges = mistake_ranges(right, model.wrong(v, right, digits))
    # each varied given's number (the file's units, angles in degrees), for a course's own use
    params: dict = {name: given["value"] for name, given in given_values(compiled, v).items()}
    params["derive_statement"] = statement_html(page)
    params.update(
        {
            "derive_variant": v.number,
            "derive_figures": right.figures,
            "derive_atol": float(right.tolerance + EDGE * max(abs(right.value), right.tolerance)),
            "derive_solution": solution_html(page),
            "derive_figure": setup_figure(compiled, v, "md"),  # the set-up before the impact, SVG
        }
    )
    mistake_rows = [[float(r.low), float(r.high), hint_text(r.wrong)] for r in ranges]
    return {"number": v.number, "params": params, "answer": float(right.value), "mistakes": mistake_rows}


def _question_html(compiled: Compiled, variants: list[Variant], result: str, digits: int | None, statement: str) -> str:
    """question.html: the statement, what to enter, the number input and the solution panel."""
    unit = answers(compiled, variants[0], digits)[result]["unit"] if variants else ""
    unit_words = "degrees" if unit == "deg" else unit
    where = f", in {esc(unit_words)}" if unit_words else ""
    symbol = latex_name(result)
    suffix = f' suffix="{html.escape("°" if unit == "deg" else unit)}"' if unit else ""
    return (
        "<pl-question-panel>\n"
        f"{statement}\n"
        '<div class="derive-figure">{{{params.derive_figure}}}</div>\n'
        f"<p>Enter \\({symbol}\\), {result_html(compiled, result)}{where}, "
        "to {{params.derive_figures}} significant figures.</p>\n"
        "</pl-question-panel>\n\n"
        f'<pl-number-input answers-name="{html.escape(result)}" label="\\({symbol} =\\)"{suffix} '
        'comparison="relabs" rtol="0" atol="{{params.derive_atol}}"></pl-number-input>\n\n'
        "<pl-answer-panel>\n{{{params.derive_solution}}}\n</pl-answer-panel>\n"
    )


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
    folder_exports(folder, prairielearn_files(compiled, variants, result=result, digits=digits, seed=seed)).write()
