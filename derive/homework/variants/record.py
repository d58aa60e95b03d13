"""A drawn variant: what every kind of compiled problem (one impact, a chain) prints."""

from __future__ import annotations

from dataclasses import dataclass

import sympy


@dataclass(frozen=True)
class Variant:
    """One drawn variant: its number (1, 2, ...) and the varied givens' exact values."""

    number: int
    values: dict[str, sympy.Expr]
