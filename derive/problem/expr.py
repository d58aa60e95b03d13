"""A restricted expression parser: arithmetic, a problem's names and a few functions.

Problem and answer files come from other people. ``sympify`` and ``parse_expr``
evaluate Python, so they never see that text: this recursive-descent parser
admits only numbers, the names it is given, ``+ - * / ^`` (``**`` too),
parentheses and the functions in :data:`FUNCTIONS`, and builds the SymPy
expression itself. It also tracks the dimension of every subexpression, so
``v_A1 + m_A`` is an error, not a number.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass

import sympy

from derive.problem import units
from derive.problem.schema.base import NAME_PATTERN
from derive.problem.unit_tokens import is_unit_name, unit_text
from derive.problem.units import ANGLE, DIMENSIONLESS, Dim, describe

MAX_LENGTH = 500
MAX_DEPTH = 40
MAX_TOKENS = 300
MAX_BITS = 4096  # largest exact power computed: about 1,200 decimal digits
MAX_EXPONENT = 64
MAX_DECIMAL_EXPONENT = 30
MAX_DEGREE = 128  # highest total power of the names in an expression (x^64 * y^64)
MAX_MAGNITUDE = 1e300  # largest computed value of a function or irrational power of numbers
MAX_FUNCTION_NESTING = 4  # sin(sin(sin(sin(x)))): SymPy's simplification grows exponentially with more

#: function name -> (SymPy function, number of arguments)
FUNCTIONS = {
    "sqrt": (sympy.sqrt, 1),
    "sin": (sympy.sin, 1),
    "cos": (sympy.cos, 1),
    "tan": (sympy.tan, 1),
    "asin": (sympy.asin, 1),
    "acos": (sympy.acos, 1),
    "atan": (sympy.atan, 1),
    "atan2": (sympy.atan2, 2),
    "exp": (sympy.exp, 1),
    "log": (sympy.log, 1),
}
CONSTANTS = {"pi": sympy.pi}

_TOKEN = re.compile(
    r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)"
    r"|(?P<name>[A-Za-z][A-Za-z0-9_]*|°)"
    r"|(?P<op>\*\*|[-+*/^(),]))"
)
NAME_RE = re.compile(NAME_PATTERN)
_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


class ParseError(ValueError):
    """The text is not an expression of the admitted grammar (message says why)."""


@dataclass(frozen=True)
class Parsed:
    """A parsed expression and its dimension."""

    expr: sympy.Expr
    dim: Dim


def _tokens(text: str) -> list[tuple[str, str]]:
    if len(text) > MAX_LENGTH:
        raise ParseError(f"the expression is too long ({len(text)} characters, at most {MAX_LENGTH})")
    out: list[tuple[str, str]] = []
    pos = 0
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if not m:
            bad = text[pos:].lstrip()[:1]
            raise ParseError(f"unexpected character {bad!r} at position {len(text) - len(text[pos:].lstrip()) + 1}")
        pos = m.end()
        kind = m.lastgroup or "op"
        out.append((kind, m.group(kind)))
        if len(out) > MAX_TOKENS:
            raise ParseError(f"the expression has too many parts (at most {MAX_TOKENS})")
    return out


class _Parser:
    def __init__(self, text: str, names: Mapping[str, tuple[sympy.Symbol, Dim]], system: str | None = None) -> None:
        self.toks = _tokens(text)
        self.i = 0
        self.names = names
        self.system = system
        self.depth = 0
        self.calls = 0

    def peek(self) -> str | None:
        return self.toks[self.i][1] if self.i < len(self.toks) else None

    def take(self) -> tuple[str, str]:
        if self.i >= len(self.toks):
            raise ParseError("the expression ends too early")
        tok = self.toks[self.i]
        self.i += 1
        return tok

    def expect(self, op: str) -> None:
        _kind, val = self.take()
        if val != op:
            raise ParseError(f"expected {op!r} but found {val!r}")

    def enter(self) -> None:
        self.depth += 1
        if self.depth > MAX_DEPTH:
            raise ParseError(f"the expression is nested too deeply (at most {MAX_DEPTH} levels)")

    def parse(self) -> Parsed:
        if not self.toks:
            raise ParseError("the expression is empty")
        out = self.sum()
        if self.i != len(self.toks):
            raise ParseError(f"unexpected {self.toks[self.i][1]!r} after the expression")
        return out

    def sum(self) -> Parsed:
        self.enter()
        left = self.product()
        while self.peek() in ("+", "-"):
            op = self.take()[1]
            right = self.product()
            if left.dim != right.dim:
                left, right = _radians(left, right)
            left = Parsed(left.expr + right.expr if op == "+" else left.expr - right.expr, left.dim)
            _check_size(left.expr)
        self.depth -= 1
        return left

    def product(self) -> Parsed:
        left = self.unary()
        while self.peek() in ("*", "/"):
            op = self.take()[1]
            right = self.unary()
            if op == "*":
                dim = tuple(a + b for a, b in zip(left.dim, right.dim, strict=False))
                left = Parsed(left.expr * right.expr, dim)  # type: ignore[arg-type]
            else:
                if right.expr == 0:
                    raise ParseError("division by zero")
                dim = tuple(a - b for a, b in zip(left.dim, right.dim, strict=False))
                left = Parsed(left.expr / right.expr, dim)  # type: ignore[arg-type]
            _check_size(left.expr)
        if self.i < len(self.toks) and self.toks[self.i][0] == "name":
            return self.with_unit(left)
        return left

    def with_unit(self, left: Parsed) -> Parsed:
        """A unit after a term (``1/3 kg``, ``0.0625 m^2/s^2``): always a unit, whatever givens
        share its name. The term is a pure number; the value in ``system``'s working unit."""
        try:
            text, self.i = unit_text(self.toks, self.i)
            unit = units.parse_unit(text)
        except ValueError as exc:
            raise ParseError(str(exc)) from None
        if left.expr.free_symbols or left.dim != DIMENSIONLESS:
            raise ParseError(
                f"a unit ({text}) may follow only a number or an expression of numbers, such as "
                f'"1/3 kg" or "-sqrt(2) m/s"; a given with a unit is multiplied with *'
            )
        value = left.expr * unit.factor / units.working_factor(unit.dim, self.system)
        _check_size(value)
        return Parsed(value, unit.dim)

    def unary(self) -> Parsed:
        if self.peek() in ("+", "-"):
            op = self.take()[1]
            self.enter()
            inner = self.unary()
            self.depth -= 1
            return Parsed(-inner.expr if op == "-" else inner.expr, inner.dim)
        return self.power()

    def power(self) -> Parsed:
        base = self.atom()
        if self.peek() in ("^", "**"):
            self.take()
            self.enter()
            exp = self.unary()
            self.depth -= 1
            if exp.dim != DIMENSIONLESS:
                raise ParseError(f"an exponent must be a pure number, not {describe(exp.dim)}")
            return _power(base, exp.expr)
        return base

    def atom(self) -> Parsed:
        kind, val = self.take()
        if kind == "num":
            return Parsed(number(val), DIMENSIONLESS)
        if kind == "name":
            if self.peek() == "(":
                return self.call(val)
            if val in CONSTANTS:
                return Parsed(CONSTANTS[val], DIMENSIONLESS)
            if val in self.names:
                sym, dim = self.names[val]
                return Parsed(sym, dim)
            if val in FUNCTIONS:
                raise ParseError(f"the function {val} needs its argument in parentheses")
            if is_unit_name(val):
                raise ParseError(
                    f"{val!r} is a unit: write it after the number it belongs to, with a space "
                    f'("sqrt(2) kg", "120 deg")'
                )
            raise ParseError(f"unknown name {val!r}" + _known(self.names))
        if val == "(":
            inner = self.sum()
            self.expect(")")
            return inner
        raise ParseError(f"unexpected {val!r}")

    def call(self, name: str) -> Parsed:
        if name not in FUNCTIONS:
            allowed = ", ".join(sorted(FUNCTIONS))
            raise ParseError(f"unknown function {name!r} (allowed: {allowed})")
        func, nargs = FUNCTIONS[name]
        self.expect("(")
        self.calls += name != "sqrt"
        if self.calls > MAX_FUNCTION_NESTING:
            raise ParseError(f"functions are nested too deeply (at most {MAX_FUNCTION_NESTING} levels)")
        args = [self.sum()]
        while self.peek() == ",":
            self.take()
            args.append(self.sum())
        self.expect(")")
        self.calls -= name != "sqrt"
        if len(args) != nargs:
            raise ParseError(f"{name} takes {nargs} argument{'s' if nargs > 1 else ''}, not {len(args)}")
        return _apply(name, func, args)


def _check_number(text: str) -> None:
    if len(text) > 30:
        raise ParseError(f"the number {text[:20]}… is too long")
    if "e" in text.lower() and abs(int(text.lower().split("e")[1][:6] or "0")) > MAX_DECIMAL_EXPONENT:
        raise ParseError(
            f"the number {text[:30]} is out of range (exponents from -{MAX_DECIMAL_EXPONENT} to {MAX_DECIMAL_EXPONENT})"
        )


def number(text: str) -> sympy.Rational:
    """A decimal number written in a file, exactly; its length and exponent are checked before
    it is built (``1e99999999`` would take for ever)."""
    if not _NUMBER.fullmatch(text.strip()):
        raise ParseError(f"{text[:30]!r} is not a number")
    _check_number(text.strip())
    return sympy.Rational(text.strip())


_NUMBER_UNIT = re.compile(r"^\s*([-+]?[\d.]+(?:[eE][-+]?\d+)?)\s*([A-Za-z].*)$")


def number_with_unit(text: str) -> tuple[sympy.Rational, str] | None:
    """``"40 m"`` -> (40, "m"); None when ``text`` is not a number followed by a unit.
    Raises :class:`ParseError` for a malformed or out-of-range number (``1.2.3 m``, ``1e999 m``)."""
    m = _NUMBER_UNIT.match(text)
    if not m:
        return None
    return number(m.group(1)), m.group(2).strip()


def scan(text: str) -> None:
    """Check ``text``'s syntax without knowing its names: characters, length, numbers,
    parentheses. A file's stage fields are scanned when it is read; the names they use
    are known only when the chain is solved."""
    depth = calls = 0
    stack: list[bool] = []
    toks = _tokens(text)
    if not toks:
        raise ParseError("the expression is empty")
    for i, (kind, val) in enumerate(toks):
        if kind == "num":
            _check_number(val)
        elif val == "(":
            call = i > 0 and toks[i - 1][0] == "name" and toks[i - 1][1] in FUNCTIONS and toks[i - 1][1] != "sqrt"
            stack.append(call)
            calls += call
            depth = max(depth, len(stack))
            if depth > MAX_DEPTH:
                raise ParseError(f"the expression is nested too deeply (at most {MAX_DEPTH} levels)")
            if calls > MAX_FUNCTION_NESTING:
                raise ParseError(f"functions are nested too deeply (at most {MAX_FUNCTION_NESTING} levels)")
        elif val == ")":
            if not stack:
                raise ParseError("a ')' has no '(' before it")
            calls -= stack.pop()
    if stack:
        raise ParseError("a '(' is not closed")


def function_nesting(expr: sympy.Basic) -> int:
    """How deeply functions (sin, exp, atan2, ...) nest in ``expr``; powers and sqrt do not count."""
    if not expr.args:
        return 0
    inner = max(function_nesting(a) for a in expr.args)
    return inner + 1 if isinstance(expr, sympy.Function) else inner


def _radians(left: Parsed, right: Parsed) -> tuple[Parsed, Parsed]:
    """An angle added to a pure number in pi or ``deg`` (``pi - pi/3``, ``180*deg - atan(2)``):
    the number is read in radians. Any other sum of different kinds is an error."""
    if {left.dim, right.dim} != {ANGLE, DIMENSIONLESS}:
        raise ParseError(f"cannot add {describe(left.dim)} and {describe(right.dim)}")
    pure = (left if left.dim == DIMENSIONLESS else right).expr
    if {str(s) for s in pure.free_symbols} <= {"deg", "rad"} and pure.has(sympy.pi, *pure.free_symbols):
        return Parsed(left.expr, ANGLE), Parsed(right.expr, ANGLE)
    raise ParseError(
        "cannot add a pure number and an angle: give the number its unit (120 deg), or write it in pi (2*pi/3)"
    )


def _known(names: Mapping[str, object]) -> str:
    if not names:
        return ""
    return " (known: " + ", ".join(sorted(names)) + ")"


def _power(base: Parsed, exp: sympy.Expr) -> Parsed:
    if not exp.is_number:
        # A given in an exponent is evaluated only when its value is put in
        # (x^x with x = 1e30 has 10^31 digits): exponents must be numbers.
        if base.dim != DIMENSIONLESS:
            raise ParseError("a quantity with a unit can only be raised to a number")
        raise ParseError("an exponent must be a number, not an expression in the givens")
    _check_no_exp(base.expr, "raised to a power")
    if exp.is_Rational and abs(exp) > MAX_EXPONENT:
        raise ParseError(f"the exponent {exp} is too large (at most {MAX_EXPONENT})")
    if not exp.is_Rational:
        try:
            approx = complex(exp.evalf(15))  # (-1)^0.5 is i: not an exponent
        except (TypeError, ValueError):
            raise ParseError("the exponent is not a number") from None
        if approx.imag != 0 or not math.isfinite(approx.real):
            raise ParseError("the exponent is not a real number")
        if abs(approx.real) > MAX_EXPONENT:
            raise ParseError(f"the exponent is too large (at most {MAX_EXPONENT})")
    if base.expr.is_Rational and exp.is_Rational:
        b = base.expr
        bits = max(abs(b.p).bit_length(), abs(b.q).bit_length())
        if bits * abs(exp) > MAX_BITS:
            raise ParseError("the power is too large to compute")
    dim = base.dim
    if dim != DIMENSIONLESS:
        if not exp.is_Rational:
            raise ParseError("a quantity with a unit can only be raised to a rational power")
        new = [d * exp for d in dim]
        if any(not x.is_integer for x in new):
            raise ParseError(f"{describe(dim)} to the power {exp} has no unit")
        dim = tuple(int(x) for x in new)  # type: ignore[assignment]
    out = sympy.Pow(base.expr, exp)
    _check_size(out)
    return Parsed(out, dim)


def _apply(name: str, func, args: list[Parsed]) -> Parsed:
    for a in args:
        _check_no_exp(a.expr, f"inside {name}()")
    out = _apply_checked(name, func, args)
    _check_size(out.expr)
    return out


def _check_no_exp(expr: sympy.Expr, where: str) -> None:
    """exp() of a given may not go inside a function or power: sin(exp(x)) at x = 1e30 never ends."""
    if expr.free_symbols and any(f.free_symbols for f in expr.atoms(sympy.exp)):
        raise ParseError(f"exp() of an expression in the givens cannot be {where}")


def _degree(expr: sympy.Expr) -> sympy.Expr:
    """The total power of the names in ``expr`` (x^64*y^2 -> 66); a function of names counts 1."""
    if not expr.free_symbols:
        return sympy.Integer(0)
    if expr.is_Symbol:
        return sympy.Integer(1)
    if expr.is_Add:
        return max(_degree(a) for a in expr.args)
    if expr.is_Mul:
        return sum((_degree(a) for a in expr.args), sympy.Integer(0))
    if expr.is_Pow and expr.exp.is_number:
        return _degree(expr.base) * abs(expr.exp)
    return sympy.Integer(1)


def _check_size(expr: sympy.Expr) -> None:
    """Refuse what would take too long to evaluate: huge numbers, huge powers of the names.

    Every part of ``expr`` was checked when it was built, so evaluating it here is quick.
    """
    for r in expr.atoms(sympy.Rational):
        if max(abs(r.p).bit_length(), r.q.bit_length()) > MAX_BITS:
            raise ParseError("a number in the expression is too large (over about 1,200 digits)")
    if expr.free_symbols:
        if _degree(expr) > MAX_DEGREE:
            raise ParseError(f"the power of the givens is too large (at most {MAX_DEGREE} in all)")
        return
    if expr.is_Rational or not expr.is_number:
        return
    try:
        size = abs(complex(expr.evalf(15)))
    except OverflowError:
        size = math.inf
    except (TypeError, ValueError):
        return  # not a number (zoo, nan): reported where the value is used
    if not size <= MAX_MAGNITUDE:
        raise ParseError("the value is too large to compute (it is over 1e300)")


def _apply_checked(name: str, func, args: list[Parsed]) -> Parsed:
    if name in ("sin", "cos", "tan"):
        if args[0].dim not in (ANGLE, DIMENSIONLESS):
            raise ParseError(f"{name} takes an angle, not {describe(args[0].dim)}")
        return Parsed(func(args[0].expr), DIMENSIONLESS)
    if name in ("asin", "acos", "atan"):
        if args[0].dim != DIMENSIONLESS:
            raise ParseError(f"{name} takes a pure number, not {describe(args[0].dim)}")
        return Parsed(func(args[0].expr), ANGLE)
    if name == "atan2":
        if args[0].dim != args[1].dim:
            raise ParseError("atan2 takes two quantities of the same kind")
        return Parsed(func(args[0].expr, args[1].expr), ANGLE)
    if name == "sqrt":
        return _power(args[0], sympy.Rational(1, 2))
    if args[0].dim != DIMENSIONLESS:
        raise ParseError(f"{name} takes a pure number, not {describe(args[0].dim)}")
    return Parsed(func(args[0].expr), DIMENSIONLESS)


def parse(text: str, names: Mapping[str, tuple[sympy.Symbol, Dim]] | None = None, system: str | None = None) -> Parsed:
    """Parse ``text`` with the admitted grammar; ``names`` maps each name to (symbol, dimension);
    a number with a unit (``1/3 kg``) is put in the working unit of ``system`` (None: SI).

    Raises :class:`ParseError` with a sentence on anything else.

    >>> parse("2*x^2 + 1", {"x": (sympy.Symbol("x"), (0, 0, 0, 0))}).expr
    2*x**2 + 1
    """
    if not isinstance(text, str):
        raise ParseError(f"expected an expression as text, not {type(text).__name__}")
    return _Parser(text, names or {}, system).parse()
