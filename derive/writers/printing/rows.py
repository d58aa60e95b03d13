"""Equation lines in LaTeX: the sides joined, an optional side kept where it adds up, a
line too wide set on rows, and the style of a block whose sums must add up."""

from __future__ import annotations

from dataclasses import dataclass, replace

from derive.numbers import floatify, places_that_add_up, to_decimal
from derive.steps.model import Block, Eqn
from derive.writers.printing.expressions import side_terms
from derive.writers.printing.numerals import adds_up
from derive.writers.printing.printer import join_terms
from derive.writers.printing.style import Style
from derive.writers.printing.units import line_unit, struck, unit_latex
from derive.writers.width import width_pt


def _printed_sides(eqn: Eqn, style: Style, extra: int) -> list[list[tuple[str, str]]]:
    """Each side's printed terms; a side printed the same as the one before it is shown once
    (v_2 = -u, not v_2 = -u = -u). An optional side whose terms do not add up to the total
    after it is left out."""
    texts = [side_terms(side, style, extra, struck(eqn, style)) for side in eqn.sides]
    printed: list[list[tuple[str, str]]] = []
    for side, terms in zip(eqn.sides, texts, strict=True):
        if side.optional and not adds_up(join_terms(terms), join_terms(texts[-1])):
            continue
        if not printed or join_terms(terms) != join_terms(printed[-1]):
            printed.append(terms)
    return printed


def latex_eqn(eqn: Eqn, style: Style, extra: int = 1) -> tuple[str, str | None]:
    """The line's LaTeX (without delimiters) and its tag."""
    printed = _printed_sides(eqn, style, extra)
    texts = [join_terms(terms) for terms in printed]
    if _bracketed(eqn, style, printed):
        texts[-1] = r"\left(" + texts[-1] + r"\right)"
    body = " = ".join(texts) + unit_latex(eqn, style)
    if eqn.boxed:
        body = r"\boxed{" + body + "}"
    if eqn.implies:
        body = IMPLIES + body
    return body, eqn.tag


def _bracketed(eqn: Eqn, style: Style, printed: list[list[tuple[str, str]]]) -> bool:
    """Whether the last side goes in brackets before its unit: a sum, however it came to be
    printed as one ((1.88 + 1.88 e_floor) N·s, never 1.88 + 1.88 e_floor N·s)."""
    return bool(unit_latex(eqn, style)) and (line_unit(eqn, style)[1] or len(printed[-1]) > 1)


IMPLIES = r"\Rightarrow\quad "
_RELATION_PT = 13.33  # '=' with its spaces (Computer Modern, 10 pt)
_CONTINUED_PT = 10.0 + 12.22  # '\quad +' at the start of a continued row
_BOX_PT = 6.8  # what \boxed adds


@dataclass(frozen=True)
class Row:
    """One row of an equation line too wide for the page: ``lhs rel rhs``.

    The first row holds the left side (``lhs``) and ``=``; each later side starts a
    row of its own (``lhs`` empty, ``rel`` "="); a side still too wide goes on in
    rows that start with its next sign (``rel`` "+" or "-", ``continued``).
    """

    lhs: str
    rel: str
    rhs: str
    continued: bool = False


def latex_rows(eqn: Eqn, style: Style, width: float, extra: int = 1, reserve: float = 0.0) -> tuple[Row, ...]:
    """The line set on rows that each fit ``width`` pt (10 pt type, display style), as
    :func:`derive.writers.width.width_pt` estimates it; ``reserve`` pt more go beside it
    (the ANSWER mark). Empty when the line fits on one row, or has one side only.

    One side per row after the first (``T_2 = a``, ``= b``, ``= c``); a side still too
    wide is broken before one of its own terms' signs, never inside a term.
    """
    sides = _printed_sides(eqn, style, extra)
    if len(sides) < 2:
        return ()
    unit = unit_latex(eqn, style)
    bracket = _bracketed(eqn, style, sides)
    if unit:
        sign, text = sides[-1][-1]
        sides[-1][-1] = (sign, text + (")" if bracket else "") + unit)
    room = width - reserve - (_BOX_PT if eqn.boxed else 0.0)
    lhs = (IMPLIES if eqn.implies else "") + join_terms(sides[0])
    if width_pt(lhs + " = " + " = ".join(join_terms(t) for t in sides[1:])) <= room:
        return ()
    left = width_pt(lhs)
    rows: list[Row] = []
    for terms in sides[1:]:
        chunks = [terms[:1]]
        for term in terms[1:]:
            trial = [*chunks[-1], term]
            lead = _RELATION_PT if len(chunks) == 1 else _CONTINUED_PT
            if term[0] in "+-" and left + lead + width_pt(_continued(trial)) > room:
                chunks.append([term])
            else:
                chunks[-1] = trial
        opening = "(" if bracket and terms is sides[-1] else ""
        rows.append(Row(lhs if not rows else "", "=", opening + join_terms(chunks[0])))
        rows.extend(Row("", chunk[0][0], _continued(chunk), continued=True) for chunk in chunks[1:])
    return tuple(rows)


def _continued(terms: list[tuple[str, str]]) -> str:
    """Terms joined, the first without its sign (the row's ``rel`` shows it)."""
    return join_terms([("+", terms[0][1]), *terms[1:]])


def block_style(block: Block, style: Style) -> Style:
    """The style for one block: where it shows a sum term by term, every
    intermediate gets the same places after the point, enough that the rounded
    terms add up to the rounded total (79.23 - 59.42 = 19.81)."""
    if block.answer_figures:
        style = replace(style, extra=0)
    if not block.sums:
        return style
    sums = [
        ([to_decimal(floatify(t, False)) for t in terms], to_decimal(floatify(total, False)))
        for terms, total in block.sums
    ]
    places = places_that_add_up(sums, style.digits, style.extra, each=block.answer_figures)
    # no places at which the rounded terms add up: leave out the line that shows them
    return replace(style, decimals=places, hide_optional=places is None)
