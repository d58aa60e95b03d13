"""Numbers for the expression trees of :mod:`derive.mathtext.parser`, with the rounding they may hide.

Values are mpmath numbers at 40 digits, in a context of their own (the global
mpmath precision, which SymPy uses, is never touched). A rounded number shown
on the page stands for any value within half a unit of its last figure, so a
side's value comes with a radius: how far it may move when each rounded number
moves within its half unit (each number moved both ways, the effects added).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass, field

import mpmath

from derive.mathtext.tree import Add, Deg, Frac, Func, Hat, Mul, Num, Pow, Sym, Text, Unknown, Vec

CTX = mpmath.MPContext()
CTX.dps = 40
ZERO = CTX.mpf(0)
ONE = CTX.mpf(1)
DEGREE = CTX.pi / 180


class Unresolved(LookupError):
    """A name the facts give no value for: the relation cannot be checked."""


class Undefined(ArithmeticError):
    """No real value: a division by zero, the root of a negative number, words."""


@dataclass
class Env:
    """How to value the leaves of a tree.

    ``scalar(name)`` and ``vector(name, axis)`` give a name's value (None if
    unknown); ``axis`` is the component being evaluated (for ê and vectors);
    ``shift`` moves chosen numbers (by identity) for the radius.
    """

    scalar: Callable[[str], object | None]
    vector: Callable[[str, str], object | None] = lambda name, axis: None
    axis: str | None = None
    shift: dict[int, object] = field(default_factory=dict)


def mpf(x: object) -> object:
    """A number (Decimal, Fraction, int, str) in the verifier's precision."""
    if hasattr(x, "numerator") and hasattr(x, "denominator") and not isinstance(x, int):
        return CTX.mpf(x.numerator) / x.denominator
    return CTX.mpf(str(x))


def number(num: Num, env: Env) -> object:
    x = mpf(num.value) + env.shift.get(id(num), ZERO)
    return x * DEGREE if num.degrees else x


def value(node: object, env: Env) -> object:
    """The value of ``node`` (radians for angles); raises Unresolved or Undefined."""
    handler = _HANDLERS.get(type(node))
    if handler is None:
        raise Undefined(f"cannot evaluate {type(node).__name__}")
    return handler(node, env)


def _sym(node: Sym, env: Env) -> object:
    v = env.scalar(node.name)
    if v is not None:
        return v
    if node.cancelled:  # struck out on both sides: any value will do
        return CTX.mpf("1.37")
    base, _, sub = node.name.partition("_")
    if len(base) > 1 and base.isalpha():  # "th" may be t times h
        out = ONE
        for i, ch in enumerate(base):
            part = env.scalar(ch + ("_" + sub if sub and i == len(base) - 1 else ""))
            if part is None:
                raise Unresolved(node.name)
            out *= part
        return out
    raise Unresolved(node.name)


def _vec(node: Vec, env: Env) -> object:
    if env.axis is None:
        raise Undefined("a vector outside a component")
    v = env.vector(node.name, env.axis)
    if v is None:
        raise Unresolved(node.name)
    return v


def _hat(node: Hat, env: Env) -> object:
    if env.axis is None:
        raise Undefined("a unit vector outside a component")
    return ONE if node.axis == env.axis else ZERO


def _add(node: Add, env: Env) -> object:
    total = ZERO
    for sign, term in node.terms:
        total += sign * value(term, env)
    return total


def _mul(node: Mul, env: Env) -> object:
    out = ONE
    for f in node.factors:
        out *= value(f, env)
    return out


def _frac(node: Frac, env: Env) -> object:
    den = value(node.den, env)
    if den == 0:
        raise Undefined("division by zero")
    return value(node.num, env) / den


def _pow(node: Pow, env: Env) -> object:
    base, exp = value(node.base, env), value(node.exp, env)
    if base < 0 and exp != int(exp):
        raise Undefined("a fractional power of a negative number")
    if base == 0 and exp < 0:
        raise Undefined("division by zero")
    return _real(base**exp)


def _real(x: object) -> object:
    if isinstance(x, mpmath.ctx_mp_python.mpc):
        if abs(x.imag) > CTX.mpf(10) ** -30 * max(ONE, abs(x.real)):
            raise Undefined("not a real number")
        return x.real
    return x


def _func(node: Func, env: Env) -> object:
    args = [value(a, env) for a in node.args]
    name = node.name
    if name == "atan2" and len(args) == 2:
        return CTX.atan2(args[0], args[1])
    if len(args) != 1:
        raise Undefined(f"{name} of {len(args)} arguments")
    x = args[0]
    if name == "sqrt":
        if x < 0:
            raise Undefined("the root of a negative number")
        return CTX.sqrt(x)
    if name == "abs":
        return abs(x)
    if name in ("asin", "acos") and abs(x) > 1:
        raise Undefined(f"{name} of a number beyond 1")
    if name in ("ln", "log") and x <= 0:
        raise Undefined("the logarithm of a number not positive")
    fn = _FUNCS.get(name)
    if fn is None:
        raise Undefined(f"unknown function {name}")
    return _real(fn(x))


_FUNCS = {
    "sin": CTX.sin,
    "cos": CTX.cos,
    "tan": CTX.tan,
    "cot": CTX.cot,
    "sec": CTX.sec,
    "csc": CTX.csc,
    "asin": CTX.asin,
    "acos": CTX.acos,
    "atan": CTX.atan,
    "sinh": CTX.sinh,
    "cosh": CTX.cosh,
    "tanh": CTX.tanh,
    "ln": CTX.ln,
    "log": CTX.ln,
    "exp": CTX.exp,
}


def _undefined(node: object, env: Env) -> object:
    raise Undefined("words or an unknown are not numbers")


_HANDLERS: dict[type, Callable[[object, Env], object]] = {
    Num: number,
    Sym: _sym,
    Vec: _vec,
    Hat: _hat,
    Add: _add,
    Mul: _mul,
    Frac: _frac,
    Pow: _pow,
    Func: _func,
    Deg: lambda node, env: value(node.inner, env) * DEGREE,
    Text: _undefined,
    Unknown: _undefined,
}


def walk(node: object) -> Iterator[object]:
    """Every node of the tree, parents first."""
    yield node
    if isinstance(node, Add):
        for _, t in node.terms:
            yield from walk(t)
    elif isinstance(node, Mul):
        for f in node.factors:
            yield from walk(f)
    elif isinstance(node, Frac):
        yield from walk(node.num)
        yield from walk(node.den)
    elif isinstance(node, Pow):
        yield from walk(node.base)
        yield from walk(node.exp)
    elif isinstance(node, Func):
        for a in node.args:
            yield from walk(a)
    elif isinstance(node, Deg):
        yield from walk(node.inner)


def measure(node: object, env: Env, halfwidth: Callable[[Num], object]) -> tuple[object, object, object]:
    """``node``'s value, how far it may move with the rounding of its numbers, and its
    scale (the size of its terms: a difference of large numbers is only as exact as they are)."""
    center = value(node, env)
    scale = abs(center)
    if isinstance(node, Add):
        scale = max(scale, sum((abs(value(t, env)) for _, t in node.terms), ZERO))
    radius = ZERO
    for num in (n for n in walk(node) if isinstance(n, Num)):
        h = halfwidth(num)
        if not h:
            continue
        worst = ZERO
        for step in (h, -h):
            shifted = Env(env.scalar, env.vector, env.axis, {**env.shift, id(num): step})
            try:
                worst = max(worst, abs(value(node, shifted) - center))
            except Undefined:
                continue
        radius += worst
    return center, radius * (1 + CTX.mpf(10) ** -6), scale


def substitute(node: object, mapping: dict[str, object]) -> object:
    """``node`` with each name in ``mapping`` replaced by the tree it maps to."""
    return rebuild(node, lambda n: mapping.get(n.name) if isinstance(n, Sym) else None)


def rebuild(node: object, replace: Callable[[object], object | None]) -> object:
    """``node`` with every sub-tree for which ``replace`` gives a tree put in its place,
    at any depth (inside powers, functions and degrees too)."""
    new = replace(node)
    if new is not None:
        return new
    if isinstance(node, Add):
        return Add(tuple((s, rebuild(t, replace)) for s, t in node.terms))
    if isinstance(node, Mul):
        return Mul(tuple(rebuild(f, replace) for f in node.factors))
    if isinstance(node, Frac):
        return Frac(rebuild(node.num, replace), rebuild(node.den, replace))
    if isinstance(node, Pow):
        return Pow(rebuild(node.base, replace), rebuild(node.exp, replace))
    if isinstance(node, Func):
        return Func(node.name, tuple(rebuild(a, replace) for a in node.args))
    if isinstance(node, Deg):
        return Deg(rebuild(node.inner, replace))
    return node
