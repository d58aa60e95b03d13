"""The theory page of a handout: the notes' three systems and equations (1)-(4), as data.

The page is made of the records a solution is made of (:class:`Block`, :class:`Eqn`,
:class:`Math`) and printed by the same printer, so its notation is the worked
solutions' notation: ``v_A1n`` is the n component of the velocity of A before (1)
the impact. The equations are those of :mod:`derive.impact`::

    (1) v_A2t = v_A1t                                      t-momentum of A
    (2) v_B2t = v_B1t                                      t-momentum of B
    (3) m_A v_A1n + m_B v_B1n = m_A v_A2n + m_B v_B2n      n-momentum of A+B
    (4) e = (v_B2n - v_A2n) / (v_A1n - v_B1n)              restitution, n only

(The notes' direct-impact system equation reads ``M_B V_Bn2`` twice on its right;
(3) is the corrected form.)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import sympy

from derive.steps.model import Block, Eqn, Math, Side, Text
from derive.steps.page import over
from derive.symbols import kind_of, symbol
from derive.writers.printing import Style, latex_eqn, latex_inline

TITLE = "Central impact: the equations"


def _s(name: str) -> sympy.Symbol:
    return symbol(name, kind_of(name, oblique=True))


def _text(*parts: str | Math | sympy.Basic) -> Text:
    """Words with formulas: a string stays words, an expression is set as inline maths."""
    return tuple(p if isinstance(p, (str, Math)) else Math(p) for p in parts)


def _listed(*exprs: sympy.Basic) -> list[sympy.Basic | str]:
    """``a, b, c``: the expressions with commas between them."""
    return [part for x in exprs for part in (", ", x)][1:]


def _raw(tex: str) -> Math:
    """Inline LaTeX that is not an expression (a statement about forces)."""
    return Math(sympy.Symbol(tex))


m_A, m_B, e = _s("m_A"), _s("m_B"), _s("e")
v = {k: _s(f"v_{k}") for k in ("A1n", "A1t", "A2n", "A2t", "B1n", "B1t", "B2n", "B2t")}

_SEPARATION = sympy.Add(v["B2n"], -v["A2n"], evaluate=False)
_APPROACH = sympy.Add(v["A1n"], -v["B1n"], evaluate=False)

#: Equations (1)-(4), as the lines that print them.
EQUATION_LINES: dict[int, Eqn] = {
    1: Eqn((Side((v["A2t"],)), Side((v["A1t"],))), tag="1"),
    2: Eqn((Side((v["B2t"],)), Side((v["B1t"],))), tag="2"),
    3: Eqn((Side((m_A * v["A1n"], m_B * v["B1n"])), Side((m_A * v["A2n"], m_B * v["B2n"]))), tag="3"),
    4: Eqn((Side((e,)), Side((over(_SEPARATION, _APPROACH),))), tag="4"),
}


def equation(number: int) -> sympy.Eq:
    """Equation (``number``) as a SymPy equation, both sides summed."""
    line = EQUATION_LINES[number]
    return sympy.Eq(sympy.Add(*line.sides[0].terms), sympy.Add(*line.sides[1].terms))


@dataclass(frozen=True)
class Section:
    """A part of the page: a heading, a table (header row first), blocks set side by side
    (``columns``), blocks, then bullet points."""

    title: str
    blocks: tuple[Block, ...] = ()
    table: tuple[tuple[Text, ...], ...] = ()
    columns: tuple[Block, ...] = ()
    items: tuple[Text, ...] = ()


def _one_body(body: str, force: str, m: sympy.Symbol, before: sympy.Symbol, after: sympy.Symbol, tag: str) -> Block:
    """A body alone: the impulsive contact force acts along n only, so momentum is conserved along t."""
    return Block(
        (f"System {body} alone: ", _raw(rf"\Sigma F_n = {force} \neq 0"), ", ", _raw(r"\Sigma F_t = 0"), ":"),
        (
            Eqn((Side((m * before,)), Side((m * after,))), cancel=frozenset({m})),
            Eqn((Side((after,)), Side((before,))), tag=tag, implies=True),
        ),
    )


def sections() -> tuple[Section, ...]:
    """The page, in the order of the notes."""
    return (_impact(), _three_systems(), _restitution(), _summary(), _remarks())


def _impact() -> Section:
    """The opening: impact, the plane of contact, the line of impact, the axes."""
    return Section(
        "",
        (
            Block(
                _text(
                    "An impact is a collision with large contact forces acting over a very short time. The plane "
                    "of contact is tangent to the contact surfaces of A and B; the line of impact is normal to it; "
                    "in a central impact it passes through the mass centres of both bodies. Axes: ",
                    symbol("n"),
                    " along the line of impact, positive from the centre of A toward the centre of B; ",
                    symbol("t"),
                    " in the plane of contact. Index 1 means immediately before the impact, 2 immediately after (",
                    v["A1n"],
                    ": the n component of the velocity of A before the impact).",
                )
            ),
        ),
    )


def _three_systems() -> Section:
    """The three systems (A, B, A and B together) and what each conserves."""
    return Section(
        "Three systems: A alone, B alone, A and B together",
        table=(
            (("System",), ("along n",), ("along t",)),
            (("A alone",), ("not conserved: ", _raw(r"\Sigma F_n = F_{AB}")), ("conserved: (1)",)),
            (("B alone",), ("not conserved: ", _raw(r"\Sigma F_n = -F_{AB}")), ("conserved: (2)",)),
            (("A + B together",), ("conserved: (3)",), ("conserved, the sum of (1) and (2)",)),
        ),
        columns=(
            _one_body("A", r"F_{AB}", m_A, v["A1t"], v["A2t"], "1"),
            _one_body("B", r"-F_{AB}", m_B, v["B1t"], v["B2t"], "2"),
        ),
        blocks=(
            Block(
                ("System A + B: ", _raw(r"\Sigma F_n = 0"), " (the contact forces are internal to it):"),
                (EQUATION_LINES[3],),
            ),
        ),
    )


def _restitution() -> Section:
    """The coefficient of restitution, equation (4)."""
    return Section(
        "Coefficient of restitution",
        (
            Block(
                _text(
                    "Equation (3) has two unknowns, ",
                    v["A2n"],
                    " and ",
                    v["B2n"],
                    ". The coefficient of restitution ",
                    e,
                    ", the ratio of the restoration impulse to the deformation impulse, gives the other: the "
                    "relative velocity of separation over that of approach,",
                ),
                (EQUATION_LINES[4],),
            ),
            Block(
                _text(
                    _raw(r"0 \le e \le 1"),
                    ": ",
                    sympy.Eq(e, 1),
                    " perfectly elastic, ",
                    sympy.Eq(e, 0),
                    " perfectly plastic (the bodies move on together). An impact needs approach: ",
                    sympy.StrictGreaterThan(_APPROACH, 0),
                    ".",
                )
            ),
        ),
    )


def _summary() -> Section:
    """The four equations for the four unknowns."""
    return Section(
        "Summary: central impact",
        (
            Block(
                _text("Four equations for the four unknowns ", *_listed(v["A2t"], v["B2t"], v["A2n"], v["B2n"]), ":"),
                tuple(EQUATION_LINES[k] for k in (1, 2, 3, 4)),
            ),
        ),
    )


def _remarks() -> Section:
    """The remarks at the end of the notes."""
    return Section(
        "Remarks",
        items=(
            (
                "Impulsive forces are large in magnitude and short in duration. Reaction forces (of a wall, a "
                "floor, a support) can be impulsive; spring and gravitational forces are not.",
            ),
            ("Define the n–t axes clearly at the beginning of every solution.",),
            ("The restitution equation (4) is valid only for the velocity components along the line of impact.",),
            _text(
                "Mechanical energy is not conserved during an impact (unless ",
                sympy.Eq(e, 1),
                "): do not use the work–energy equation across an impact.",
            ),
            _text(
                "Direct impact: the velocities lie along n, and (1), (2) drop out. Oblique impact: resolve each "
                "velocity into n and t first; after the impact, ",
                sympy.Eq(_s("theta_A2"), sympy.atan(v["A2n"] / v["A2t"]), evaluate=False),
                " from the plane of contact.",
            ),
            _text(
                "A fixed surface (a wall, the floor) is a body B of infinite mass at rest: (4) gives ",
                sympy.Eq(v["A2n"], sympy.Mul(-1, e, v["A1n"], evaluate=False), evaluate=False),
                ", and (3) does not apply.",
            ),
        ),
    )


def _parts(text: Text, style: Style) -> list[tuple[str, str]]:
    return [("math", latex_inline(p.expr, style)) if isinstance(p, Math) else ("text", p) for p in text]


def _blocks(blocks: tuple[Block, ...], style: Style) -> list[dict[str, Any]]:
    out = []
    for block in blocks:
        lines = []
        for eqn in block.lines:
            body, tag = latex_eqn(eqn, style)
            lines.append({"latex": body, "tag": tag, "boxed": eqn.boxed})
        out.append({"text": _parts(block.text, style) if block.text else None, "lines": lines})
    return out


def view() -> dict[str, Any]:
    """The page as a template needs it: every formula printed as LaTeX."""
    style = Style(None)
    sections_ = [
        {
            "title": sec.title,
            "table": [[_parts(cell, style) for cell in row] for row in sec.table],
            "columns": _blocks(sec.columns, style),
            "blocks": _blocks(sec.blocks, style),
            "bullets": [_parts(item, style) for item in sec.items],
        }
        for sec in sections()
    ]
    return {"title": TITLE, "sections": sections_}
