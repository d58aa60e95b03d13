"""The expression trees a displayed line is read into (see :mod:`derive.mathtext.parser`).

Numbers keep the text they were shown with, so that a rule can ask how many
figures a number shows and what rounding it may hide. The nodes compare by
identity: two equal numbers on a line are two numbers.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from decimal import Decimal


@dataclass(frozen=True, eq=False)
class Num:
    """A number as shown: ``mantissa`` digits, a power of ten, maybe a degree sign."""

    mantissa: str
    exponent: int = 0
    degrees: bool = False

    @property
    def value(self) -> Decimal:
        """The number as written (degrees not converted)."""
        return Decimal(self.mantissa).scaleb(self.exponent)

    @property
    def decimals(self) -> int:
        """Digits after the point in the mantissa."""
        return len(self.mantissa.split(".")[1]) if "." in self.mantissa else 0

    @property
    def ulp(self) -> Decimal:
        """One unit in the last place shown."""
        return Decimal(1).scaleb(self.exponent - self.decimals)

    @property
    def integer(self) -> bool:
        """True for a whole number written without a point or a power of ten."""
        return "." not in self.mantissa and self.exponent == 0

    @property
    def figures(self) -> int:
        """Significant figures shown (an integer's trailing zeros not counted)."""
        digits = self.mantissa.replace(".", "").lstrip("0")
        if self.integer:
            digits = digits.rstrip("0")
        return len(digits)

    @property
    def text(self) -> str:
        tail = rf" \times 10^{{{self.exponent}}}" if self.exponent else ""
        return self.mantissa + tail + (r"^\circ" if self.degrees else "")


@dataclass(frozen=True, eq=False)
class Sym:
    """A name (``v_A1n``); ``letters`` is set when an unbroken run of letters may be a product."""

    name: str
    cancelled: bool = False


@dataclass(frozen=True, eq=False)
class Vec:
    """A vector ``\\vec{v}_{A2}``: evaluated one component at a time."""

    name: str


@dataclass(frozen=True, eq=False)
class Hat:
    """A unit vector: axis 't', 'n', 'x' or 'y'."""

    axis: str


@dataclass(frozen=True, eq=False)
class Add:
    """A sum: (sign, term) pairs in the order shown."""

    terms: tuple[tuple[int, object], ...]


@dataclass(frozen=True, eq=False)
class Mul:
    """A product of factors in the order shown; ``gaps`` what stood between them where the
    reader kept it: "·" (``\\cdot``), "*" (``\\times``, ``*``), " " (a space) or ""."""

    factors: tuple[object, ...]
    gaps: tuple[str, ...] = ()


@dataclass(frozen=True, eq=False)
class Frac:
    num: object
    den: object


@dataclass(frozen=True, eq=False)
class Pow:
    base: object
    exp: object


@dataclass(frozen=True, eq=False)
class Func:
    """A function: sin, asin, sqrt, abs, atan2, ... of its arguments; "()": brackets as written (lenient)."""

    name: str
    args: tuple[object, ...]


@dataclass(frozen=True, eq=False)
class Deg:
    """An expression followed by a degree sign."""

    inner: object


@dataclass(frozen=True, eq=False)
class Text:
    """Words in the maths (``\\text{...}``): never evaluated."""

    text: str


@dataclass(frozen=True, eq=False)
class Unknown:
    """The ``?`` of an unknown given."""


@dataclass(frozen=True)
class Side:
    """One side of a relation and the unit shown after it (None: none shown)."""

    expr: object
    unit: str | None = None
    source: str = ""


@dataclass(frozen=True)
class ParsedRelation:
    """A relation read into trees, ``side op side op ...``; ``ops`` are '=', '<', '>', '<=', '>=', '!=', '~' (a
    relation of plain text, as the checker reads it, is :class:`derive.mathtext.reader.Relation`)."""

    sides: tuple[Side, ...]
    ops: tuple[str, ...]


@dataclass(frozen=True)
class Display:
    """A displayed line: its decorations and its relations."""

    implies: bool = False
    boxed: bool = False
    answer_marks: int = 0
    tag: str | None = None
    relations: tuple[ParsedRelation, ...] = ()
    text_only: bool = False
    body: str = field(default="", compare=False)
