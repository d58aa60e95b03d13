"""The derivation read so far, as the verdicts on a false line see it: one protocol for
:class:`~.lines.Trace`, used by the modules it calls (they may not import lines).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Protocol

import sympy

from derive.checking.mistakes import Variant
from derive.checking.worlds import Pair

if TYPE_CHECKING:
    from derive.checking.context import Context
    from derive.checking.inference import Read
    from derive.checking.mistakes import Outcome
    from derive.checking.relations import Point, Values


class Trace(Protocol):
    """What of :class:`~.lines.Trace` (the derivation read so far) the verdicts of :mod:`.carried`,
    :mod:`.misread` and :mod:`.slipworld` use."""

    ctx: Context
    U: tuple[sympy.Symbol, ...]
    pts: list[Point]
    truth: list[Values]
    world: list[Values] | None
    equations: dict[int, sympy.Expr]
    copied: dict[sympy.Symbol, sympy.Expr]
    variant: Variant
    replaced: list[tuple[int, int]]
    held: list[Pair]
    named: dict[int, set[str]]
    stated: dict[int, set[str]]
    wrong_values: set[str]
    worked: tuple[Pair, ...]
    base: Outcome
    own: dict[sympy.Symbol, sympy.Expr]
    displaced: tuple[int, sympy.Expr] | None
    unrefined: tuple[int, list[Values]] | None

    def _closest(self, F: sympy.Expr) -> int | None: ...
    def _moved(self, pairs: list[Pair]) -> bool: ...
    def holds(self, pairs: list[Pair], values: list[Values]) -> bool: ...
    def pairs(self, line: Read) -> list[Pair]: ...
