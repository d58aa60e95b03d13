"""Energy stages before and after an impact (never across one): ``fall`` (speed from a
height), ``rise`` (height from a speed), ``slide`` (distance to rest with kinetic
friction) and ``spring`` (greatest compression)."""

from __future__ import annotations

from dataclasses import dataclass

import sympy

from derive.errors import SolveError
from derive.physics.energy import HALF
from derive.physics.state import ChainState, StageOutcome
from derive.problem import Given, units
from derive.symbols import symbol


@dataclass(frozen=True)
class Balance:
    """An energy balance ``lhs terms = rhs terms`` solved for ``result``: ``solved`` is its
    value in the known quantities; ``cancel`` the symbols that cancel (the mass)."""

    lhs: tuple[sympy.Expr, ...]
    rhs: tuple[sympy.Expr, ...]
    solved: sympy.Expr
    result: Given
    cancel: frozenset[sympy.Symbol] = frozenset()
    friction: sympy.Expr | None = None  # slide: mu m g
    value: sympy.Expr | None = None  # ``solved`` with every number known now put in


@dataclass(frozen=True)
class Spring:
    """The spring's greatest compression: the balance (with gravity when ``vertical``)
    and its one positive root."""

    lhs: tuple[sympy.Expr, ...]
    rhs: tuple[sympy.Expr, ...]
    root: sympy.Expr
    result: Given
    vertical: bool


def fall(state: ChainState, i: int, st: dict) -> StageOutcome:
    """Speed after falling through ``height`` from ``speed`` (default 0): T1 + V1 = T2 + V2."""
    h = state.quantity(i, st, "height", units.LENGTH)
    v0 = state.quantity(i, st, "speed", units.VELOCITY, default="0")
    g = state.g_symbol()
    m = symbol("m", "positive")
    speed = sympy.sqrt(v0**2 + 2 * g * h)
    out = state.define(i, st.get("result", f"v_{i}"), speed, units.VELOCITY)
    lhs = (HALF * m * v0**2, m * g * h) if v0 != 0 else (m * g * h,)
    data = Balance(lhs, (HALF * m * out.symbol**2,), speed, out, frozenset({m}), value=state.value(speed))
    body = str(st.get("body", "the body"))  # "suitcase A": the first letter up, the rest as typed
    return StageOutcome(i, "fall", f"{body[:1].upper()}{body[1:]} falls through the height", data, (out.name,))


def rise(state: ChainState, i: int, st: dict) -> StageOutcome:
    """Height reached from ``speed``: 1/2 m v² = m g h."""
    v = state.quantity(i, st, "speed", units.VELOCITY)
    g = state.g_symbol()
    m = symbol("m", "positive")
    height = v**2 / (2 * g)
    out = state.define(i, st.get("result", f"h_{i}"), height, units.LENGTH)
    data = Balance((HALF * m * v**2,), (m * g * out.symbol,), height, out, frozenset({m}), value=state.value(height))
    return StageOutcome(i, "rise", "Rise after the impact", data, (out.name,))


def slide(state: ChainState, i: int, st: dict) -> StageOutcome:
    """Distance to rest from ``speed`` with kinetic friction ``mu``: 1/2 m v² - mu m g d = 0."""
    v = state.quantity(i, st, "speed", units.VELOCITY)
    mu = state.quantity(i, st, "mu", units.DIMENSIONLESS)
    if state.value(mu) == 0:
        raise state.err(i, "mu", "with mu = 0 no friction acts: the body never stops; give mu above 0", st.get("mu"))
    g = state.g_symbol()
    m = symbol("m", "positive")
    d = v**2 / (2 * mu * g)
    out = state.define(i, st.get("result", f"d_{i}"), d, units.LENGTH)
    lhs = (HALF * m * v**2, -mu * m * g * out.symbol)
    data = Balance(lhs, (sympy.Integer(0),), d, out, frozenset({m}), mu * m * g, state.value(d))
    return StageOutcome(i, "slide", "Sliding to rest after the impact", data, (out.name,))


def spring(state: ChainState, i: int, st: dict) -> StageOutcome:
    """Greatest compression of a spring ``k`` hit by ``mass`` at ``speed``; a vertical
    spring (``vertical = true``) starts from its ``static`` compression, gravity working."""
    v = state.quantity(i, st, "speed", units.VELOCITY)
    mass = state.quantity(i, st, "mass", units.MASS)
    k = state.quantity(i, st, "k", units.STIFFNESS)
    vertical = bool(st.get("vertical", False))
    x0 = state.quantity(i, st, "static", units.LENGTH, default="0") if vertical else sympy.Integer(0)
    x = sympy.Symbol("x", positive=True)
    name = st.get("result", f"x_{i}")
    if vertical:
        g = state.g_symbol()
        balance = sympy.Eq(HALF * mass * v**2 + mass * g * x, HALF * k * (x0 + x) ** 2 - HALF * k * x0**2)
    else:
        balance = sympy.Eq(HALF * mass * v**2, HALF * k * x**2)
    roots = [r for r in sympy.solve(balance, x) if state.positive(r)]
    if len(roots) != 1:
        raise SolveError(f"stage {i}: the spring's compression has no single positive root", where=state.chain.path)
    out = state.define(i, name, roots[0], units.LENGTH)
    X = out.symbol
    if vertical:
        lhs = (HALF * mass * v**2, mass * symbol("g", "positive") * X)
        rhs = (HALF * k * (x0 + X) ** 2, -HALF * k * x0**2)
    else:
        lhs, rhs = (HALF * mass * v**2,), (HALF * k * X**2,)
    return StageOutcome(
        i, "spring", "The spring after the impact", Spring(lhs, rhs, roots[0], out, vertical), (out.name,)
    )
