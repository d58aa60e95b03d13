"""The fields of a problem that ask for results or set up homework: ``find``,
``answer_units``, ``[vary]`` and ``conditions``.

Their types were checked against the schema when the file was read; here each is
checked against the problem (a result it can ask for, a given that can vary, a
condition whose sides are of one kind) and built.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

import sympy

from derive.errors import ExpressionError, InputError, UnitError
from derive.problem import units
from derive.problem.expr import ParseError, parse
from derive.problem.givens import given_value
from derive.problem.records import Condition, Given
from derive.problem.source import Source
from derive.problem.units import ANGLE, DIMENSIONLESS, VELOCITY, Dim, describe
from derive.symbols import symbol

#: Results a problem may ask for by name.
RESULT_NAMES = (
    *("v_A2", "v_B2", "v_A2n", "v_A2t", "v_B2n", "v_B2t"),
    *("theta_A2", "theta_B2", "beta_A2", "beta_B2"),
    *("alpha_A2", "alpha_B2", "gamma_A2", "gamma_B2", "delta_A", "delta_B"),
    *("T_1", "T_2", "T_lost"),
)
#: Dimension of each result name, for conditions on results.
RESULT_DIMS: dict[str, Dim] = {
    **dict.fromkeys(("v_A2", "v_B2", "v_A2n", "v_A2t", "v_B2n", "v_B2t", "v_A2x", "v_A2y", "v_B2x", "v_B2y"), VELOCITY),
    **dict.fromkeys(("theta_A2", "theta_B2", "beta_A2", "beta_B2"), ANGLE),
    **dict.fromkeys(("alpha_A2", "alpha_B2", "gamma_A2", "gamma_B2", "delta_A", "delta_B"), ANGLE),
    **dict.fromkeys(("T_1", "T_2", "T_lost"), units.ENERGY),
    "J_n": units.IMPULSE,
}


def result_dims(oblique: bool, fixed_B: bool = False, xy: bool = False) -> dict[str, Dim]:
    """The results an impact of this kind has, with their dimensions: a direct impact has no
    components, directions or x-y velocities, a fixed B no velocity after; a field that
    names one of those names no result (it is an unknown name, never a free letter)."""
    names = ["v_A2", "v_B2", "T_1", "T_2", "T_lost", "J_n"]
    if oblique:
        names += ["v_A2n", "v_A2t", "v_B2n", "v_B2t", "theta_A2", "theta_B2", "beta_A2", "beta_B2"]
        if xy:
            names += ["v_A2x", "v_A2y", "v_B2x", "v_B2y"]
    if fixed_B:
        names = [n for n in names if not n.startswith(("v_B2", "theta_B2", "beta_B2"))]
    return {n: RESULT_DIMS[n] for n in names}


MAX_CHOICES = 100_000
#: A condition's form: "lhs op rhs".
CONDITION = re.compile(r"^(.*?)(<=|>=|<|>)(.*)$")


def find(
    raw: Any, ctx: Source, oblique: bool, unknown: tuple[str, ...] = (), extra: tuple[str, ...] = ()
) -> tuple[str, ...]:
    """The results to box in the answer (default: the unknowns, else the velocities after);
    ``extra`` names more that may be asked (quantities defined from the results, x-y components)."""
    default = unknown or ("v_A2", "v_B2")
    if raw is None:
        return default
    if isinstance(raw, str):
        raw = [raw]
    if not raw:
        raise ctx.error("expected a list of result names", key="find", value=raw)
    allowed = (RESULT_NAMES if oblique else ("v_A2", "v_B2", "T_1", "T_2", "T_lost")) + ("J_n", *unknown, *extra)
    for x in raw:
        if x not in allowed:
            raise ctx.error(f"unknown result {x!r} (expected some of: {', '.join(allowed)})", key="find", value=raw)
    return tuple(dict.fromkeys(raw))


def answer_units(raw: Mapping[str, str] | None, ctx: Source) -> dict[str, str]:
    """Results to show also in a unit of the user's choice: {v_A2 = "km/h"}."""
    out = {}
    for name, text in (raw or {}).items():
        try:
            unit = units.parse_unit(text)
        except ValueError as exc:
            raise ctx.error(str(exc), section="answer_units", key=name, value=text, cls=UnitError) from None
        if unit.dim in (DIMENSIONLESS,):
            raise ctx.error("expected a unit", section="answer_units", key=name, value=text, cls=UnitError)
        out[name] = unit.text
    return out


def vary(
    raw: Mapping[str, Any] | None, by_name: Mapping[str, Given], ctx: Source, oblique: bool, system: str
) -> dict[str, tuple[sympy.Expr, ...]]:
    """Ranges or choices for homework variants: { m_A = { min = "2 kg", max = "10 kg", step = "0.5 kg" } }."""
    out: dict[str, tuple[sympy.Expr, ...]] = {}
    for name, spec in (raw or {}).items():
        g = by_name.get(name)
        if g is None or g.value is None or g.unknown or g.definition is not None:
            raise ctx.error("only a given with a plain number can vary", section="vary", key=name)
        if "choices" in spec:
            values = tuple(_vary_value(name, g, v, "choices", ctx, oblique, system) for v in spec["choices"])
        else:
            lo, hi, step = (_vary_value(name, g, spec[k], k, ctx, oblique, system) for k in ("min", "max", "step"))
            if not step > 0 or hi < lo:
                raise ctx.error("expected min <= max and a positive step", section="vary", key=name)
            count = int(sympy.floor((hi - lo) / step)) + 1
            if count > MAX_CHOICES:
                raise ctx.error(f"gives {count} values (at most {MAX_CHOICES})", section="vary", key=name)
            values = tuple(lo + k * step for k in range(count))
        out[name] = tuple(dict.fromkeys(sympy.nsimplify(v) if v.is_Float else v for v in values))
    return out


def _vary_value(name: str, g: Given, v: Any, field_: str, ctx: Source, oblique: bool, system: str) -> sympy.Expr:
    try:
        item = given_value(name, v, {}, ctx, oblique, system)
    except InputError as exc:
        raise ctx.error(exc.what, section="vary", key=f"{name}.{field_}", value=v, cls=type(exc)) from None
    if item.dim != g.dim or item.value is None:
        raise ctx.error(f"expected {describe(g.dim)}", section="vary", key=f"{name}.{field_}", value=v)
    return item.value


def conditions(
    raw: list[str] | None,
    by_name: Mapping[str, Given],
    ctx: Source,
    results: Mapping[str, tuple[sympy.Symbol, Dim]] | None = None,
    system: str | None = None,
) -> tuple[Condition, ...]:
    """Conditions on givens and results, each "lhs < rhs" (< <= > >=), parsed safely.
    ``results``: the results a condition may name, with their dimensions (default: an
    impact's, :data:`RESULT_DIMS`; a chain's are known once it is solved). A number with
    a unit ("5 J") is put in ``system``'s working unit."""
    names = {g.name: (g.symbol, g.dim) for g in by_name.values()}
    if results is None:
        names.update({n: (symbol(n), d) for n, d in RESULT_DIMS.items()})
    else:
        names.update(results)
    out = []
    for text in raw or ():
        m = CONDITION.match(text)
        if not m:
            raise ctx.error("expected a comparison with <, <=, > or >=", key="conditions", value=text)
        try:
            lhs, rhs = parse(m.group(1).strip(), names, system), parse(m.group(3).strip(), names, system)
        except ParseError as exc:
            raise ctx.error(str(exc), key="conditions", value=text, cls=ExpressionError) from None
        if lhs.dim != rhs.dim and lhs.expr.free_symbols and rhs.expr.free_symbols:
            raise ctx.error(f"compares {describe(lhs.dim)} with {describe(rhs.dim)}", key="conditions", value=text)
        out.append(Condition(text, lhs.expr, m.group(2), rhs.expr))
    return tuple(out)
