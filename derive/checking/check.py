"""``derive.check``: judge hand answers, equations and a typed derivation against a solution.

Each answer, equation and line becomes an :class:`~.report.Item`; one that cannot
be read becomes an item with status "error" (and its message), so that the other
items are still reported. Only when nothing at all can be read is the input error
raised instead.
"""

from __future__ import annotations

import math
import re
from typing import Any

from derive.checking import words
from derive.checking.context import NUMBER, Context
from derive.checking.entries import Entry, as_answers, parse_tolerance
from derive.checking.number import number_item
from derive.checking.report import CheckReport, Item
from derive.errors import InputError
from derive.problem import Problem, units
from derive.steps.model import Solution


def check(
    solution: Solution | Problem,
    answers: Any = None,
    *,
    equations: Any = None,
    tolerance: Any = None,
    derivation: str | None = None,
) -> CheckReport:
    """Check hand answers (and equations, and a typed derivation) against ``solution``.

    ``answers`` maps result names to values (``{"v_B2n": "8.40 m/s", "v_A2n": -1.11}``),
    or is a list of ``"NAME=VALUE"`` strings, or what :func:`~.answers.load_answers` read;
    ``equations`` maps labels ("3", "4") to equations (``"20*v_A2n + 5*v_B2n = 19.8"``);
    ``derivation`` is the text of a typed derivation (plain lines, Markdown or LaTeX),
    judged line by line (:mod:`.lines`); ``tolerance`` is relative (0.01 or "1%"):
    without it numbers are judged at the precision they are written with. An item that
    cannot be read is reported with status "error"; raises
    :class:`~derive.errors.InputError` when nothing can be read.
    ``report.exit_code`` is 0 when everything is right, 1 when anything is wrong.

    >>> import derive  # doctest: +SKIP
    >>> derive.check(derive.solve(derive.load("notes-4c11-two-spheres")), {"v_B2n": "8.40 m/s"}).all_correct  # doctest: +SKIP
    True
    """
    if isinstance(solution, Problem):
        from derive.steps import solve

        solution = solve(solution, steps=False)
    given = as_answers(answers, equations)
    tol = parse_tolerance(tolerance if tolerance is not None else given.tolerance, "tolerance")
    if not given.answers and not given.equations and derivation is None:
        raise InputError("nothing to check: give answers (--answer NAME=VALUE or --answers FILE)", field="answers")
    ctx = Context(solution, tol)
    if ctx.chain and given.equations:
        raise InputError(
            "equations are checked for a single impact; a chain's answers are checked as numbers, "
            "and its derivation line by line against its stages' values",
            field="equations",
        )
    items: list[Item] = []
    errors: list[InputError] = []
    for judge, entries in ((answer_item, given.answers), (_equation_item, given.equations)):
        for e in entries:
            try:
                items.append(judge(ctx, e))
            except InputError as exc:
                errors.append(exc)
                items.append(error_item("answer" if judge is answer_item else "equation", e, exc))
    notes: list[str] = []
    known: dict[str, str] = {}
    if derivation is not None:
        if ctx.chain:
            from derive.checking.chainlines import chain_items as derivation_items
        else:
            from derive.checking.lines import derivation_items
            from derive.checking.putvalues import put_values

            ctx.fixed = put_values(ctx, derivation)  # "putting m = 1": that given drawn as 1
        # every line end Python knows ("\r", "\r\n", U+2028, form feed) as "\n": the reader and
        # each module that counts lines then count the same lines, as the student's editor shows them
        lines, notes = derivation_items(ctx, "\n".join(derivation.splitlines()))
        items += lines
        known = words.glossary(solution, () if ctx.chain else ctx.equation_names())
    if errors and len(errors) == len(items):
        raise errors[0]
    p = solution.problem
    tol_value = float(tol) if tol is not None else None
    return CheckReport(p.name or p.path, p.title, tuple(items), tol_value, tuple(notes), tuple(known.items()))


def answer_item(ctx: Context, e: Entry) -> Item:
    """The verdict on one answer: a number (with its unit) or a formula."""
    r = ctx.result(e)
    text = _text(e)
    m = NUMBER.match(text)
    unit_problem = None
    if m:
        number, unit_text = m.groups()
        if not unit_text:
            return number_item(ctx, e, r, text, number, None)
        try:
            unit = units.parse_unit(unit_text)
        except ValueError as exc:
            unit_problem = str(exc) if _looks_like_unit(unit_text) else None
        else:
            return number_item(ctx, e, r, text, number, unit)
    if ctx.chain:
        raise e.error(f"a chain's answers are checked as numbers with their units, such as {e.name}=-2.38 m/s")
    from derive.checking.expression import expression_item  # a formula's judges: imported when one is given

    return expression_item(ctx, e, r, text, unit_problem)


def _equation_item(ctx: Context, e: Entry) -> Item:
    """The verdict on one equation (its judges, and the mistakes' model, imported when one is given)."""
    from derive.checking.equation import equation_item

    return equation_item(ctx, e)


def error_item(kind: str, e: Entry, exc: InputError) -> Item:
    """An item that could not be read: its message is the input error's."""
    written = e.raw if isinstance(e.raw, str) else repr(e.raw)
    return Item(kind, e.name, written, "error", "", str(exc))


def _text(e: Entry) -> str:
    raw = e.raw
    if isinstance(raw, bool) or not isinstance(raw, (str, int, float)):
        raise e.error('expected a number or text such as "8.40 m/s"')
    if isinstance(raw, float) and not math.isfinite(raw):
        raise e.error("expected a finite number")
    text = (repr(raw) if isinstance(raw, float) else str(raw)).replace("−", "-").strip()
    if not text:
        raise e.error('is empty: expected a number with a unit ("8.40 m/s") or an expression')
    if len(text) > 500:
        raise e.error("is too long (at most 500 characters)")
    return text


def _looks_like_unit(text: str) -> bool:
    return re.fullmatch(r"[A-Za-z°][A-Za-z°/*^·\d\s]*", text) is not None
