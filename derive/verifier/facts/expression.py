"""Expressions of a problem file (``2*m_A``, ``asin(75/123)``, ``sqrt(2*g*h_0)``), read here
apart from derive's own parser: a value (exact, SymPy) and a dimension.

The text is parsed with :mod:`ast` (a parser only: nothing is evaluated as Python)
and each node is worked out by hand; anything but numbers, known names, ``+ - * /
^ **``, parentheses, ``pi`` and the file format's ten functions is refused.
"""

from __future__ import annotations

import ast
from collections.abc import Callable, Mapping
from fractions import Fraction

import sympy

from derive.verifier import units

Named = Mapping[str, tuple[sympy.Expr, units.Dim]]


class Unread(ValueError):
    """An expression this reader does not read."""


def _root(d: units.Dim) -> units.Dim:
    if any(x % 2 for x in d):
        raise Unread("the square root of a dimension with an odd power")
    return (d[0] // 2, d[1] // 2, d[2] // 2, d[3] // 2)


#: name -> (function, arguments, dimension of the result from the first argument's)
FUNCTIONS: dict[str, tuple[Callable[..., sympy.Expr], int, Callable[[units.Dim], units.Dim]]] = {
    "sqrt": (sympy.sqrt, 1, _root),
    "sin": (sympy.sin, 1, lambda d: units.NONE),
    "cos": (sympy.cos, 1, lambda d: units.NONE),
    "tan": (sympy.tan, 1, lambda d: units.NONE),
    "asin": (sympy.asin, 1, lambda d: units.ANGLE),
    "acos": (sympy.acos, 1, lambda d: units.ANGLE),
    "atan": (sympy.atan, 1, lambda d: units.ANGLE),
    "atan2": (sympy.atan2, 2, lambda d: units.ANGLE),
    "exp": (sympy.exp, 1, lambda d: units.NONE),
    "log": (sympy.log, 1, lambda d: units.NONE),
}


def evaluate(text: str, names: Named) -> tuple[sympy.Expr, units.Dim]:
    """The value and dimension of ``text`` with ``names`` (name -> (value, dimension));
    raises :class:`Unread` for anything else."""
    if len(text) > 500:
        raise Unread("too long")
    try:
        tree = ast.parse(text.strip().replace("^", "**"), mode="eval")
        return _node(tree.body, names)
    except (SyntaxError, RecursionError, TypeError, ZeroDivisionError) as exc:
        raise Unread(str(exc)) from None


def _number(value: object) -> sympy.Expr:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise Unread(f"not a number: {value!r}")
    return sympy.Integer(value) if isinstance(value, int) else sympy.Rational(str(Fraction(repr(value))))


def _node(node: ast.AST, names: Named) -> tuple[sympy.Expr, units.Dim]:
    if isinstance(node, ast.Constant):
        return _number(node.value), units.NONE
    if isinstance(node, ast.Name):
        if node.id in names:
            return names[node.id]
        if node.id == "pi":
            return sympy.pi, units.NONE
        raise Unread(f"unknown name {node.id!r}")
    if isinstance(node, ast.UnaryOp) and isinstance(node.op, (ast.USub, ast.UAdd)):
        v, d = _node(node.operand, names)
        return (-v if isinstance(node.op, ast.USub) else v), d
    if isinstance(node, ast.BinOp):
        return _binary(node, names)
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in FUNCTIONS:
        fn, count, dim = FUNCTIONS[node.func.id]
        if len(node.args) != count or node.keywords:
            raise Unread(f"{node.func.id} takes {count} argument(s)")
        args = [_node(a, names) for a in node.args]
        return fn(*(v for v, _ in args)), dim(args[0][1])
    raise Unread(f"cannot read {type(node).__name__}")


def _binary(node: ast.BinOp, names: Named) -> tuple[sympy.Expr, units.Dim]:
    a, da = _node(node.left, names)
    b, db = _node(node.right, names)
    if isinstance(node.op, (ast.Add, ast.Sub)):
        return (a + b if isinstance(node.op, ast.Add) else a - b), (da if da != units.NONE else db)
    if isinstance(node.op, ast.Mult):
        return a * b, units.multiply(da, db)
    if isinstance(node.op, ast.Div):
        return a / b, units.multiply(da, db, -1)
    if isinstance(node.op, ast.Pow):
        if db != units.NONE:
            raise Unread("an exponent with a unit")
        if da == units.NONE:
            return a**b, units.NONE
        if not (b.is_Rational and b.q in (1, 2)):
            raise Unread("a quantity with a unit to a power that is not a whole number or a half")
        dim = units.multiply(units.NONE, da, int(b * 2))
        return a**b, _root(dim)
    raise Unread(f"cannot read the operator {type(node.op).__name__}")
