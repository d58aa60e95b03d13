"""What a solution's numbers print as: the :class:`Style` of a page."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

import sympy


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
    hide_optional: bool = False
    strike: bool = True
    decimal: frozenset[sympy.Symbol] = frozenset()
    letters: frozenset[sympy.Symbol] = frozenset()
    letter_units: Mapping[sympy.Symbol, str] = field(default_factory=dict)
    labels: tuple[str, str] = ("A", "B")
    derived: frozenset[sympy.Symbol] = frozenset()
