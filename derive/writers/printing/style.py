"""What a solution's numbers print as: the :class:`Style` of a page, and the open numbers
(slots) of a solution compiled for many variants."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy


@dataclass(frozen=True)
class Slot:
    """A number left open when a solution is compiled for many variants: ``expr`` in
    the varied givens, printed as ``kind`` says at ``digits``(+``extra``) figures or
    with its block's places after the point."""

    expr: sympy.Expr
    kind: str  # given | number | result | lead | signed | leadcoef | signedcoef
    digits: int | None
    extra: int
    block: int | None


class SlotBook:
    """Collects the open numbers of a compiled solution; each prints as a token."""

    def __init__(self) -> None:
        self.slots: list[Slot] = []
        self.claims: dict[int, list[tuple[tuple[sympy.Expr, ...], sympy.Expr]]] = {}

    def token(self, expr: sympy.Expr, kind: str, digits: int | None, extra: int, block: int | None) -> str:
        self.slots.append(Slot(expr, kind, digits, extra, block))
        return f"DRVSLOT{len(self.slots) - 1}X"


@dataclass(frozen=True)
class Style:
    """How numbers print: the answer's figures (None: textbook rule) and the extra
    figures intermediates carry; ``values`` and ``angles`` feed substitution lines;
    ``strike`` False prints a cancelled symbol without its stroke (for converters
    that have no ``\\cancel``); ``derived`` symbols have numbers worked out, not
    written in the file (a chain's carried values), rounded where long."""

    digits: int | None
    extra: int = 1
    values: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    angles: frozenset[sympy.Symbol] = frozenset()
    decimals: int | None = None
    varied: frozenset[sympy.Symbol] = frozenset()
    slots: SlotBook | None = field(default=None, compare=False)
    block: int | None = None
    hide_optional: bool = False
    strike: bool = True
    decimal: frozenset[sympy.Symbol] = frozenset()
    letters: frozenset[sympy.Symbol] = frozenset()
    letter_units: Mapping[sympy.Symbol, str] = field(default_factory=dict)
    labels: tuple[str, str] = ("A", "B")
    derived: frozenset[sympy.Symbol] = frozenset()
