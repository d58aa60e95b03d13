"""The records a problem file becomes: :class:`Given`, :class:`Motion`, :class:`Condition`, :class:`Problem`.

Each record checks itself where it is built (``__post_init__``) and raises a
:class:`RecordError` that names its field; the reader, which knows the file, adds the
file and the line (``file:7: [given] e = 1.3: …``) and raises it again.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import sympy

from derive.errors import InputError, PhysicsError
from derive.problem import units
from derive.problem.expr import NAME_RE
from derive.problem.schema.base import BAD_NAME
from derive.problem.symbolic import Asks
from derive.problem.units import Dim

KINDS = ("direct", "oblique")
AXES = ("+n", "-n", "+t", "-t")
XY_AXES = ("+x", "-x", "+y", "-y")
OPERATORS = ("<", "<=", ">", ">=")


class RecordError(InputError):
    """A record that does not hold together: ``section`` and ``key`` name its field, ``cls``
    the kind of error; the reader adds where it is in the file."""

    def __init__(
        self, what: str, *, section: str | None = None, key: str | None = None, cls: type[InputError] = InputError
    ) -> None:
        super().__init__(what, field=(f"[{section}] " if section else "") + (key or "") or None)
        self.section = section
        self.key = key
        self.cls = cls


@dataclass(frozen=True)
class Given:
    """One given: its symbol, dimension and exact value in the problem's working unit.

    ``value`` is None for a symbolic given. Angles are held in radians (shown in
    degrees); ``written`` is the text as the file gave it when it was converted;
    ``typed`` the number as the file typed it ("2.50" of "2.50 m/s"), for a statement
    to print a value with the places the file gave it.
    """

    name: str
    symbol: sympy.Symbol
    dim: Dim
    value: sympy.Expr | None
    unit: str
    written: str | None = None
    definition: sympy.Expr | None = None
    unknown: bool = False
    inexact: bool = False
    typed: str | None = None

    @property
    def decimal(self) -> bool:
        """True for a number that is not whole and was not written as an expression (0.6,
        37.6 deg, 22 g as 0.022 kg), or one worked out from such numbers (``inexact``: a
        chain's v_1 = sqrt(2 g h) with g = 9.8): where it meets letters the worked lines
        show decimals; exact data (integers, 3/5, sqrt(2)) stay exact."""
        if self.value is not None and self.inexact:
            return not self.value.is_Integer
        if self.value is None or self.definition is not None:
            return False
        if self.unit == "deg":
            return not (self.value * 180 / sympy.pi).is_Integer
        return not self.value.is_Integer  # 0.6, and 22 g as 0.022 kg

    def __post_init__(self) -> None:
        if not NAME_RE.match(self.name):
            raise RecordError(BAD_NAME, key=self.name)
        if len(self.dim) != 4 or not isinstance(self.unit, str):
            raise RecordError("has no dimension or unit", key=self.name)


@dataclass(frozen=True)
class Motion:
    """How a body moves before the impact: its n and t components in the givens.

    ``speed``/``angle``/``axis_from``/``toward`` are set when the file gave a
    speed and a direction (the geometry stage resolves them).
    """

    body: str
    n: sympy.Expr
    t: sympy.Expr
    speed: sympy.Symbol | None = None
    angle: sympy.Symbol | None = None
    axis_from: str | None = None
    toward: str | None = None
    x: sympy.Expr | None = None
    y: sympy.Expr | None = None

    def __post_init__(self) -> None:
        if self.body not in ("A", "B"):
            raise RecordError(f"a body is A or B, not {self.body!r}")
        for k in ("axis_from", "toward"):
            axis = getattr(self, k)
            if axis is not None and axis not in AXES + XY_AXES:
                raise RecordError(f"expected one of {', '.join(AXES + XY_AXES)}", section=self.body, key=k)


@dataclass(frozen=True)
class Condition:
    """A condition every homework variant must meet, such as ``v_B2n > 0``."""

    text: str
    lhs: sympy.Expr
    op: str
    rhs: sympy.Expr

    def __post_init__(self) -> None:
        if self.op not in OPERATORS:
            raise RecordError("expected a comparison with <, <=, > or >=", key="conditions")


@dataclass(frozen=True)
class Problem:
    """A central-impact problem, checked and ready for the equations.

    Building one checks the physics the givens must have: e between 0 and 1, masses
    positive, speeds not negative, and bodies that approach along n.
    """

    path: str
    title: str
    kind: str
    givens: tuple[Given, ...]
    motion_A: Motion
    motion_B: Motion
    find: tuple[str, ...]
    system: str = "SI"
    digits: int | None = None
    source: str | None = None
    statement: str | None = None
    question: str | None = None
    name: str = ""
    fixed_B: bool = False
    name_B: str | None = None
    #: The letters the page calls body A and body B by (a chain stage where sphere B
    #: strikes a wall: ("B", "W")); the physics and the JSON keep the notes' A and B.
    labels: tuple[str, str] = ("A", "B")
    phi: sympy.Symbol | None = None
    answer_units: Mapping[str, str] = field(default_factory=dict)
    vary: Mapping[str, tuple[sympy.Expr, ...]] = field(default_factory=dict)
    conditions: tuple[Condition, ...] = ()
    extra: Mapping[str, Any] = field(default_factory=dict)
    assume: Mapping[str, str] = field(default_factory=dict)
    asks: Asks = field(default_factory=Asks)
    #: The file it was read from (:class:`~derive.problem.source.Source`): its text, for a
    #: homework variant (the file with other numbers written in) and for messages.
    ctx: Any = field(default=None, compare=False, repr=False)
    #: A homework variant whose masses are drawn while its radii are the file's: a figure of
    #: it is schematic in size (B may come out denser than gold).
    sizes_schematic: bool = field(default=False, compare=False)

    def __post_init__(self) -> None:
        if self.kind not in KINDS:
            raise RecordError('expected "direct" or "oblique"', key="kind")
        if self.system not in units.SYSTEMS:
            raise RecordError('expected "SI" or "US"', key="units")
        if self.digits is not None and (isinstance(self.digits, bool) or not 1 <= self.digits <= 10):
            raise RecordError("expected a whole number of significant figures from 1 to 10", key="digits")
        check_ranges(self)
        check_approach(self)

    @property
    def oblique(self) -> bool:
        """True for an oblique impact (velocities with n and t components)."""
        return self.kind == "oblique"

    def given(self, name: str) -> Given:
        """The given called ``name``."""
        for g in self.givens:
            if g.name == name:
                return g
        raise KeyError(name)

    def unknowns(self) -> tuple[sympy.Symbol, ...]:
        """Givens marked "?", which the equations must determine (an inverse problem)."""
        return tuple(g.symbol for g in self.givens if g.unknown)

    def numeric(self) -> dict[sympy.Symbol, sympy.Expr]:
        """Symbol -> exact value for every given that has a number."""
        return {g.symbol: g.value for g in self.givens if g.value is not None}

    def symbols(self) -> dict[str, sympy.Symbol]:
        """Name -> symbol for every given."""
        return {g.name: g.symbol for g in self.givens}


def check_ranges(problem: Problem) -> None:
    """e in [0, 1], masses positive, speeds not negative (where they are numbers)."""
    by_name = {g.name: g for g in problem.givens}
    e = by_name["e"].value if "e" in by_name else None
    if e is not None and not (0 <= e <= 1):
        raise RecordError(
            "the coefficient of restitution must lie between 0 and 1", section="given", key="e", cls=PhysicsError
        )
    for m in ("m_A", "m_B"):
        v = by_name[m].value if m in by_name else None
        if v is not None and not v > 0:
            raise RecordError("a mass must be positive", section="given", key=m, cls=PhysicsError)
    for s in ("v_A1", "v_B1"):
        g = by_name.get(s)
        if g is not None and g.value is not None and g.symbol.is_nonnegative and not g.value >= 0:
            raise RecordError(
                "a speed cannot be negative (its direction is set by [A]/[B] angle, from and toward)",
                section="given",
                key=s,
                cls=PhysicsError,
            )


def check_approach(problem: Problem) -> None:
    """The bodies must approach along n: v_A1n - v_B1n > 0."""
    approach = problem.motion_A.n - problem.motion_B.n
    value = approach.xreplace(problem.numeric())
    if value.free_symbols:
        if value.is_positive is False or (value.is_zero is True):
            raise RecordError(
                "the bodies do not approach along n: v_A1n - v_B1n must be positive", section="given", cls=PhysicsError
            )
        return
    if not value > 0:
        from derive.numbers import format_number

        shown = format_number(value, 4)
        raise RecordError(
            f"the bodies do not approach: v_A1n - v_B1n = {shown}, but it must be positive "
            "(n points from A's centre toward B's, so A must close on B along n)",
            section="given",
            cls=PhysicsError,
        )
