"""A worked solution as data: stages of blocks of sentences and equation lines.

The physics fills these records; every renderer (Markdown, LaTeX, HTML, JSON)
turns the same records into its format. Nothing here is text for one format:
mathematics stays SymPy until a renderer prints it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Literal

import sympy

from derive.problem.reader import Problem

#: How a side of an equation line is printed:
#: 'symbolic' as it stands; 'values' with each given's number in place of its
#: symbol (the substitution line); 'numeric' with numbers evaluated, carried to
#: one figure more than the answer; 'result' evaluated at the answer's figures.
Mode = Literal["symbolic", "values", "numeric", "result"]


@dataclass(frozen=True)
class Math:
    """Inline mathematics inside a sentence."""

    expr: sympy.Basic


#: A sentence: words and inline mathematics, in order.
Text = tuple["str | Math", ...]


@dataclass(frozen=True)
class Side:
    """One side of an equation: its terms in the order the notes write them."""

    terms: tuple[sympy.Expr, ...]
    mode: Mode = "symbolic"


@dataclass(frozen=True)
class Eqn:
    """An equation line ``side = side = ...``, with the notes' decorations.

    ``tag`` is the equation number; ``cancel`` holds symbols shown struck out;
    ``unit`` follows the last side; ``implies`` starts the line with ⇒.
    """

    sides: tuple[Side, ...]
    tag: str | None = None
    cancel: frozenset[sympy.Symbol] = frozenset()
    unit: str | None = None
    implies: bool = False
    boxed: bool = False


@dataclass(frozen=True)
class Block:
    """A sentence (optional) and the equation lines it introduces.

    ``sums`` records sums shown term by term, ``(terms, total)``: a renderer
    carries enough figures that the rounded terms add up to the rounded total.
    """

    text: Text | None
    lines: tuple[Eqn, ...] = ()
    sums: tuple[tuple[tuple[sympy.Expr, ...], sympy.Expr], ...] = ()


@dataclass(frozen=True)
class Stage:
    """A numbered stage of the notes' layout (1 geometry, 2 kinetics, 3 solve, 4 answer)."""

    number: int
    title: str
    blocks: tuple[Block, ...]


@dataclass(frozen=True)
class Result:
    """A computed quantity.

    ``closed`` is its closed form in the givens' symbols; ``value`` its exact
    value in the problem's working unit (degrees for angles), or None when it
    depends on a symbolic given, in which case ``partial`` holds the numbers
    substituted and the symbols kept.
    """

    name: str
    symbol: sympy.Symbol
    closed: sympy.Expr
    value: sympy.Expr | None
    partial: sympy.Expr
    unit: str
    description: str


@dataclass(frozen=True)
class Solution:
    """A solved problem: its results and the worked stages that reach them."""

    problem: Problem
    results: dict[str, Result]
    stages: tuple[Stage, ...]
    values: dict[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    angles: frozenset[sympy.Symbol] = frozenset()

    def _repr_markdown_(self) -> str:
        from derive.writers.view import render

        return render(self, "md")

    def _repr_latex_(self) -> str:
        """The boxed answers as display math (for front ends that show LaTeX, not Markdown)."""
        from derive.writers.view import view

        stages = view(self)["stages"]
        lines = [ln["latex"] for st in stages for b in st["blocks"] for ln in b["lines"] if ln["boxed"]]
        return "\n".join(f"$${ln}$$" for ln in lines)
