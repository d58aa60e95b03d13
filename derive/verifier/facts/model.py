"""Plain facts about one problem: what each name on the page is worth, and its dimension.

A :class:`Scope` is what a reader knows at one part of the page: the givens
and solved values of a problem, or of one stage of a chain (a chain stage's
scope has the chain's own names as its parent). Values are numbers at 40
digits; a symbolic given (a mass ``m`` kept as a letter) is given a sample
value, the same everywhere on the page, so that a line true for every ``m``
is checked at one ``m``.
"""

from __future__ import annotations

import re
import zlib
from collections.abc import Mapping
from dataclasses import dataclass, field
from decimal import Decimal

import sympy

from derive.verifier import units
from derive.verifier.evaluate import CTX


@dataclass(frozen=True)
class Quantity:
    """One name: its value (radians for angles; None when it has none), dimension and role.

    The role says what the name is on the page: "given" (a datum), "param" (a letter kept
    symbolic), "unknown" (a quantity the equations determine, free when an elimination is
    checked) or "result" (one computed from those).
    """

    name: str
    value: object | None
    dim: units.Dim
    role: str = "given"


@dataclass(frozen=True)
class Scope:
    """What holds in one part of the page.

    ``key`` is ``""`` for a problem, ``"chain"`` for a chain's own names, ``"stage 2"``
    for a chain's second stage (``"chain 2"`` its parent: the chain's names as they
    stand at stage 2). ``exact`` holds the numbers a reader takes as exact (givens as
    written). ``asked`` names what the question asks; ``answers`` is False where an
    ANSWER mark does not belong (a chain's intermediate stage).
    """

    key: str
    quantities: Mapping[str, Quantity]
    vectors: Mapping[str, Mapping[str, object]] = field(default_factory=dict)
    system: str = "SI"
    parent: str | None = None
    exact: frozenset[Decimal] = frozenset()
    asked: frozenset[str] = frozenset()
    answers: bool = True

    def unknowns(self) -> frozenset[str]:
        """Names the equations of this scope determine."""
        return frozenset(n for n, q in self.quantities.items() if q.role == "unknown")


@dataclass(frozen=True)
class Facts:
    """Every scope of a page, the figures rule, and what the facts themselves found wrong.

    ``solved`` holds, for the parts of a chain before its ``solve`` stage, the same
    scopes with the unknowns at their solved values: a line that is false as it
    stands but true there shows a value before the unknown it needs is found.
    """

    scopes: Mapping[str, Scope]
    digits: int | None = None
    chain: bool = False
    notes: tuple[str, ...] = ()
    solved: Mapping[str, Scope] = field(default_factory=dict)


# ---------------------------------------------------------------- samples

_SAMPLE_BASE = {
    units.MASS: 1.7,
    units.VELOCITY: 2.9,
    units.LENGTH: 1.3,
    units.ANGLE: 0.61,
    units.NONE: 0.43,
    units.FORCE: 15.0,
    units.ENERGY: 7.0,
    units.ACCELERATION: 9.5,
}


def sample(name: str, dim: units.Dim) -> sympy.Rational:
    """A value for a letter kept symbolic: fixed by its name, of a size its kind has."""
    jitter = (zlib.crc32(name.encode()) % 97) / 400
    base = _SAMPLE_BASE.get(dim, 1.9)
    return sympy.Rational(str(round(base * (1 + jitter), 6)))


def number(expr: sympy.Expr | None, subs: Mapping[sympy.Symbol, sympy.Expr]) -> object | None:
    """An exact expression as a 40-digit number at the sample point (None: not a real number)."""
    if expr is None:
        return None
    x = sympy.sympify(expr).xreplace(dict(subs))
    if x.free_symbols:
        return None
    try:
        v = x.evalf(45)
    except (TypeError, ValueError, ZeroDivisionError):
        return None
    if v.has(sympy.zoo, sympy.nan, sympy.oo, -sympy.oo):
        return None
    re_, im_ = v.as_real_imag()
    if im_ != 0 and abs(im_) > 1e-30 * max(1, abs(re_)):
        return None
    return CTX.mpf(str(sympy.Float(re_, 45)))


def exact_decimal(value: sympy.Expr | None) -> Decimal | None:
    """A given's exact value as a terminating decimal (None when it does not terminate)."""
    if value is None or not getattr(value, "is_Rational", False):
        return None
    q = int(value.q)
    for f in (2, 5):
        while q % f == 0:
            q //= f
    if q != 1:
        return None
    return (Decimal(int(value.p)) / Decimal(int(value.q))).normalize()


#: A body's quantity in the notes' names (v_A1n, m_B, theta_A2).
_BODY = re.compile(r"((?:v|m|W|r|theta|beta)_)([AB])([12]?[nt]?[xy]?)")


@dataclass
class Table:
    """Names collected at one sample point, each as a 45-digit number (a SymPy Float).

    ``fixed`` gives letters their value at this point (a chain's unknown: its
    root once the page has found it); any other letter kept symbolic gets its
    :func:`sample`. Working with numbers from the start keeps the derived
    quantities cheap: nothing is built as a long formula and evaluated late.
    """

    exprs: dict[str, sympy.Expr] = field(default_factory=dict)
    dims: dict[str, units.Dim] = field(default_factory=dict)
    roles: dict[str, str] = field(default_factory=dict)
    vectors: dict[str, dict[str, sympy.Expr]] = field(default_factory=dict)
    exact: set[Decimal] = field(default_factory=set)
    fixed: dict[str, sympy.Expr] = field(default_factory=dict)

    def put(self, name: str, expr: sympy.Expr, dim: units.Dim, role: str = "result") -> None:
        self.exprs[name] = numeric(expr)
        self.dims[name] = dim
        self.roles[name] = role

    def param(self, name: str, dim: units.Dim, role: str = "param") -> sympy.Expr:
        """A letter kept symbolic on the page: its value at this point."""
        value = self.fixed.get(name)
        self.put(name, sample(name, dim) if value is None else self.resolve(value), dim, role)
        return self.exprs[name]

    def resolve(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` (in derive's symbols) with each name replaced by its value here."""
        expr = sympy.sympify(expr)
        subs = {s: self.exprs[s.name] for s in expr.free_symbols if s.name in self.exprs}
        return numeric(expr.xreplace(subs))

    def note_exact(self, value: sympy.Expr | None, degrees: bool = False) -> None:
        d = exact_decimal(value * 180 / sympy.pi if degrees and value is not None else value)
        if d is not None:
            self.exact.add(d)
            self.exact.add(-d)

    def relabel(self, labels: tuple[str, str]) -> None:
        """Rename the bodies' quantities to the letters the page calls A and B by
        (``v_A1`` is read as ``v_B1`` on a page where sphere B strikes a wall)."""
        if tuple(labels) == ("A", "B"):
            return

        def new(name: str) -> str:
            m = _BODY.fullmatch(name)
            return name if m is None else m[1] + labels["AB".index(m[2])] + m[3]

        for book in (self.exprs, self.dims, self.roles, self.vectors):
            moved = {new(k): v for k, v in book.items()}
            book.clear()
            book.update(moved)

    def scope(self, key: str, names: list[str] | None = None, **kw: object) -> Scope:
        """The names (all, or those listed) as a :class:`Scope`."""
        keep = list(self.exprs) if names is None else names
        quantities = {
            n: Quantity(n, number(self.exprs[n], {}), self.dims.get(n, units.NONE), self.roles.get(n, "result"))
            for n in keep
        }
        vectors = {n: {ax: number(e, {}) for ax, e in comps.items()} for n, comps in self.vectors.items()}
        return Scope(key, quantities, vectors, exact=frozenset(self.exact), **kw)  # type: ignore[arg-type]


def numeric(expr: object) -> sympy.Expr:
    """A number as a 45-digit Float (an expression with letters is left as it is)."""
    expr = sympy.sympify(expr)
    if expr.free_symbols or isinstance(expr, sympy.Float):
        return expr
    try:
        value = expr.evalf(45)
    except (TypeError, ValueError, ZeroDivisionError):
        return expr
    return value if isinstance(value, sympy.Float) else expr
