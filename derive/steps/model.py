"""A worked solution as data: stages of blocks of sentences and equation lines.

The physics fills these records; every renderer (Markdown, LaTeX, HTML, JSON)
turns the same records into its format. Nothing here is text for one format:
mathematics stays SymPy until a renderer prints it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any, Literal

import sympy

from derive.physics.results import Result
from derive.problem import ChainProblem, Problem

#: How a side of an equation line is printed:
#: 'symbolic' as it stands; 'values' with each given's number in place of its
#: symbol (the substitution line); 'numeric' with numbers evaluated, carried to
#: one figure more than the answer; 'result' evaluated at the answer's figures.
Mode = Literal["symbolic", "values", "numeric", "result"]


class Degrees(sympy.Symbol):
    """An angle's value in degrees in a numeric line (sin 71.57°): printed at the page's
    figures, which only the writer knows (an intermediate's, + one, at ``--digits``)."""

    degrees: sympy.Expr

    def __new__(cls, degrees: sympy.Expr) -> Degrees:
        obj = super().__new__(cls, f"deg:{sympy.srepr(degrees)}")
        obj.degrees = degrees
        return obj

    def __getnewargs_ex__(self) -> tuple[tuple[sympy.Expr], dict[str, object]]:
        return (self.degrees,), {}


@dataclass(frozen=True)
class Math:
    """Inline mathematics inside a sentence."""

    expr: sympy.Basic


#: A sentence: words and inline mathematics, in order.
Text = tuple["str | Math", ...]


@dataclass(frozen=True)
class Side:
    """One side of an equation: its terms in the order the notes write them.

    An ``optional`` side is a sum shown term by term before the total after it
    (v_B2n = -1.11 + 9.51 = 8.40): a renderer leaves it out where its terms, as
    printed, do not add up to the total as printed (v_B2n = 9.29, not
    -5.926 + 15.21 = 9.29).
    """

    terms: tuple[sympy.Expr, ...]
    mode: Mode = "symbolic"
    optional: bool = False


@dataclass(frozen=True)
class Eqn:
    """An equation line ``side = side = ...``, with the notes' decorations.

    ``tag`` is the equation number; ``cancel`` holds symbols shown struck out;
    ``unit`` follows the last side; ``implies`` starts the line with ⇒; an
    ``optional`` line (a sum shown term by term) may be left out where its numbers
    cannot be shown so that they add up at the solution's figures; ``mark`` puts the
    notes' "⟵ ANSWER" after the line.
    """

    sides: tuple[Side, ...]
    tag: str | None = None
    cancel: frozenset[sympy.Symbol] = frozenset()
    unit: str | None = None
    implies: bool = False
    boxed: bool = False
    optional: bool = False
    mark: bool = False


@dataclass(frozen=True)
class Block:
    """A sentence (optional) and the equation lines it introduces.

    ``sums`` records sums shown term by term, ``(terms, total)``: a renderer
    carries enough figures that the rounded terms add up to the rounded total,
    starting from the answer's figures where ``answer_figures`` (results, not
    intermediates).
    """

    text: Text | None
    lines: tuple[Eqn, ...] = ()
    sums: tuple[tuple[tuple[sympy.Expr, ...], sympy.Expr], ...] = ()
    answer_figures: bool = False


@dataclass(frozen=True)
class Stage:
    """A numbered stage: of the notes' layout (1 geometry, 2 kinetics, 3 solve, 4 answer),
    or of a chain, where an impact stage holds its own worked page in ``part``.

    ``figure`` asks for the figure of the impact, "before" or "after"; ``carried``
    lists what an impact stage hands on to the stages after it; ``values``, where
    set, are the numbers known at this stage of a chain (its substitution lines use
    these, not numbers a later stage finds).
    """

    number: int
    title: str
    blocks: tuple[Block, ...] = ()
    figure: str | None = None
    part: Solution | None = None
    carried: tuple[Eqn, ...] = ()
    kind: str = "step"
    values: dict[sympy.Symbol, sympy.Expr] | None = None


@dataclass(frozen=True)
class Answer:
    """A chain's final answer, the quantity ``name``: a boxed line, or a yes/no ``verdict``."""

    name: str
    line: Eqn | None = None
    verdict: str | None = None


@dataclass(frozen=True)
class Solution:
    """A solved problem or chain: its results and the worked stages that reach them.

    ``values`` maps each symbol with a number to its exact value, for substitution
    lines; ``angles`` are the symbols held in radians and shown in degrees;
    ``answers`` closes a chain; ``shown`` and ``ranges`` are the problem's "show that"
    results and ranges as the physics decided them; ``others`` the results of each other
    physical solution, where the data do not choose one.
    """

    problem: Problem | ChainProblem
    results: Mapping[str, Result]
    stages: tuple[Stage, ...]
    values: dict[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    angles: frozenset[sympy.Symbol] = frozenset()
    answers: tuple[Answer, ...] = ()
    shown: tuple[Any, ...] = ()
    ranges: tuple[Any, ...] = ()
    others: tuple[Mapping[str, Result], ...] = ()
    #: A chain's impact stage: its quantities by the chain's names (v_A1 -> u_B, v_A2 -> w_B),
    #: for the figure's labels (the steps are written in them already).
    names: Mapping[str, str] = field(default_factory=dict)

    @property
    def is_chain(self) -> bool:
        """True for a chain of stages (``kind = "chain"``)."""
        return isinstance(self.problem, ChainProblem)
