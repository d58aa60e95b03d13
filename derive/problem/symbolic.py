"""What a problem asks beyond the velocities: results to show, ranges, extra equations,
quantities defined from the results, and the published answers (for tests and keys).

Each field is an expression (or relation) in the problem's names, the givens and the
results derive computes, parsed by the restricted parser; nothing here solves anything.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import sympy

from derive.errors import ExpressionError, UnitError
from derive.problem import units
from derive.problem.expr import FUNCTIONS, NAME_RE, Parsed, ParseError, parse
from derive.problem.source import Source, type_name
from derive.problem.units import ANGLE, DIMENSIONLESS, Dim, describe
from derive.symbols import symbol

_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,2})?)\s*([A-Za-z°].*?)\s*$")
_INEQUALITY = re.compile(r"^(.*?)(<=|>=|<|>)(.*)$")
MAX_ITEMS = 20


@dataclass(frozen=True)
class Relation:
    """``lhs = rhs`` as the file wrote it (``text``), in the problem's names."""

    text: str
    lhs: sympy.Expr
    rhs: sympy.Expr


@dataclass(frozen=True)
class Range:
    """The values of the letter ``of`` for which ``lhs op rhs`` holds."""

    text: str
    of: sympy.Symbol
    lhs: sympy.Expr
    op: str
    rhs: sympy.Expr


@dataclass(frozen=True)
class Defined:
    """A quantity defined from the results (``F_avg = J_n/dt``), found like a result."""

    name: str
    symbol: sympy.Symbol
    expr: sympy.Expr
    dim: Dim
    unit: str
    #: The expression as the file wrote it, and where (``file:line``), for messages.
    text: str = ""
    where: str = ""


@dataclass(frozen=True)
class Asks:
    """Everything a problem asks besides equations (1)-(4)."""

    show: tuple[Relation, ...] = ()
    ranges: tuple[Range, ...] = ()
    equations: tuple[Relation, ...] = ()
    defined: tuple[Defined, ...] = ()
    answers: Mapping[str, sympy.Expr] = field(default_factory=dict)


def read_asks(
    data: Mapping[str, Any],
    names: Mapping[str, tuple[sympy.Symbol, Dim]],
    result_dims: Mapping[str, Dim],
    letters: set[str],
    system: str,
    ctx: Source,
) -> Asks:
    """The fields ``define``, ``show``, ``range``, ``equations`` and ``answers``, checked."""
    scope = dict(names)
    scope.update({n: (symbol(n), d) for n, d in result_dims.items() if n not in scope})
    defined = _defined(data.get("define"), scope, system, ctx)
    scope.update({d.name: (d.symbol, d.dim) for d in defined})
    return Asks(
        show=_relations(data.get("show"), scope, ctx, "show"),
        ranges=_ranges(data.get("range"), scope, letters, ctx),
        equations=_relations(data.get("equations"), scope, ctx, "equations", system),
        defined=defined,
        answers=_answers(data.get("answers"), scope, system, ctx),
    )


def _listed(raw: Any, key: str, ctx: Source) -> list[str]:
    if raw is None:
        return []
    if isinstance(raw, str):
        raw = [raw]
    if not isinstance(raw, list) or not all(isinstance(x, str) for x in raw):
        raise ctx.error('expected a relation such as "v_B2 = 2/5*(1 + e)*u", or a list of them', key=key, value=raw)
    if len(raw) > MAX_ITEMS:
        raise ctx.error(f"has too many entries ({len(raw)}, at most {MAX_ITEMS})", key=key)
    return raw


def _side(
    text: str, scope: Mapping[str, tuple[sympy.Symbol, Dim]], ctx: Source, key: str, whole: str, system: str = ""
) -> Parsed:
    """One side of a relation: an expression in the problem's names or, with ``system``,
    also a number with its unit ("-2 m/s", "5 ft"), in the working unit."""
    m = _QUANTITY.match(text) if system else None
    if m and m.group(2).strip() not in scope:
        try:
            unit = units.parse_unit(m.group(2))
        except ValueError as exc:
            raise ctx.error(str(exc), key=key, value=whole, cls=UnitError) from None
        if unit.dim == ANGLE:
            raise ctx.error(
                'an angle here has no unit; give a direction after the impact in [given] (theta_A2 = "10 deg")',
                key=key,
                value=whole,
                cls=UnitError,
            )
        value = sympy.Rational(m.group(1))
        if unit.dim != DIMENSIONLESS:
            value = units.convert(value, unit, units.working_unit(unit.dim, system))
        return Parsed(value, unit.dim)
    try:
        return parse(text.strip(), scope)
    except ParseError as exc:
        raise ctx.error(str(exc), key=key, value=whole, cls=ExpressionError) from None


def _relations(
    raw: Any, scope: Mapping[str, tuple[sympy.Symbol, Dim]], ctx: Source, key: str, system: str = ""
) -> tuple[Relation, ...]:
    out = []
    for text in _listed(raw, key, ctx):
        if text.count("=") != 1 or re.search(r"[<>]", text):
            raise ctx.error('expected one equation such as "T_2 = 3/4*T_1"', key=key, value=text)
        left, right = text.split("=")
        lhs, rhs = _side(left, scope, ctx, key, text, system), _side(right, scope, ctx, key, text, system)
        _same_dim(lhs, rhs, ctx, key, text)
        out.append(Relation(text, lhs.expr, rhs.expr))
    return tuple(out)


def _same_dim(lhs: Any, rhs: Any, ctx: Source, key: str, text: str) -> None:
    if lhs.dim != rhs.dim and lhs.expr != 0 and rhs.expr != 0:
        raise ctx.error(f"compares {describe(lhs.dim)} with {describe(rhs.dim)}", key=key, value=text, cls=UnitError)


def _ranges(
    raw: Any, scope: Mapping[str, tuple[sympy.Symbol, Dim]], letters: set[str], ctx: Source
) -> tuple[Range, ...]:
    if raw is None:
        return ()
    items = raw if isinstance(raw, list) else [raw]
    out = []
    for item in items:
        if not isinstance(item, dict) or set(item) != {"of", "where"}:
            raise ctx.error('expected { of = "e", where = "v_A2 < 0" }', key="range", value=item)
        of, where = item["of"], item["where"]
        if not isinstance(of, str) or of not in letters:
            raise ctx.error("expected a given kept as a letter (such as e)", section="range", key="of", value=of)
        m = _INEQUALITY.match(where) if isinstance(where, str) else None
        if not m:
            raise ctx.error("expected a comparison with <, <=, > or >=", section="range", key="where", value=where)
        lhs, rhs = _side(m.group(1), scope, ctx, "range", where), _side(m.group(3), scope, ctx, "range", where)
        _same_dim(lhs, rhs, ctx, "range", where)
        out.append(Range(where, scope[of][0], lhs.expr, m.group(2), rhs.expr))
    return tuple(out)


def _defined(raw: Any, scope: dict[str, tuple[sympy.Symbol, Dim]], system: str, ctx: Source) -> tuple[Defined, ...]:
    if raw is None:
        return ()
    if not isinstance(raw, dict):
        raise ctx.error(f'expected a table such as {{ F_avg = "J_n/dt" }}, not {type_name(raw)}', key="define")
    out = []
    for name, text in raw.items():
        if not NAME_RE.match(name) or name in scope:
            raise ctx.error("expected a new name (letters, digits and _)", section="define", key=name)
        if name == "pi" or name in FUNCTIONS:
            raise ctx.error("is the name of a constant or function; choose another name", section="define", key=name)
        if not isinstance(text, str):
            raise ctx.error("expected an expression of the givens and results", section="define", key=name, value=text)
        try:
            parsed = parse(text.strip(), scope)
        except ParseError as exc:
            raise ctx.error(str(exc), section="define", key=name, value=text, cls=ExpressionError) from None
        if parsed.dim == ANGLE:
            unit = "deg"
        elif parsed.dim in units.SYSTEMS[system]:
            unit = units.working_unit(parsed.dim, system).text
        else:
            unit = ""
        d = Defined(name, symbol(name), parsed.expr, parsed.dim, unit, text, ctx.where(ctx.line_of("define", name)))
        scope[name] = (d.symbol, d.dim)
        out.append(d)
    return tuple(out)


def _answers(
    raw: Any, scope: Mapping[str, tuple[sympy.Symbol, Dim]], system: str, ctx: Source
) -> dict[str, sympy.Expr]:
    """Published answers: a number with its unit (converted to the working unit; angles
    in degrees) or an expression in the problem's names."""
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise ctx.error('expected a table such as { v_B2 = "2/5*(1 + e)*u" }', key="answers")
    out: dict[str, sympy.Expr] = {}
    for name, text in raw.items():
        if name not in scope:
            raise ctx.error("is not a result or given of this problem", section="answers", key=name)
        if isinstance(text, (int, float)) and not isinstance(text, bool):
            text = repr(text)
        if not isinstance(text, str):
            raise ctx.error("expected a number with its unit or an expression", section="answers", key=name, value=text)
        m = _QUANTITY.match(text)
        if m:
            try:
                unit = units.parse_unit(m.group(2))
            except ValueError as exc:
                raise ctx.error(str(exc), section="answers", key=name, value=text, cls=UnitError) from None
            value = sympy.Rational(m.group(1))
            if unit.dim == ANGLE:
                out[name] = value * unit.factor * 180 / sympy.pi
            elif unit.dim == DIMENSIONLESS:
                out[name] = value
            else:
                out[name] = units.convert(value, unit, units.working_unit(unit.dim, system))
            continue
        out[name] = _side(text, scope, ctx, "answers", text).expr
    return out
