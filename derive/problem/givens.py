"""The ``[given]`` table: each entry a number with a unit, a symbol, an unknown "?" or an
expression of other givens, built as a :class:`~derive.problem.records.Given` in the
problem's working units.

Every value is bounded before it is worked out: the expression parser limits its size,
nesting and exponents, and a value computed from other givens must be a finite real
number of a magnitude between 1e-30 and 1e30, as a number written in the file must.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Mapping
from dataclasses import replace
from typing import Any

import sympy

from derive.errors import ExpressionError, InputError, UnitError
from derive.problem import units
from derive.problem.expr import FUNCTIONS, MAX_FUNCTION_NESTING, NAME_RE, ParseError, function_nesting, parse
from derive.problem.records import Given, RecordError
from derive.problem.schema import ASSUMPTIONS
from derive.problem.schema.base import BAD_NAME
from derive.problem.source import Source, type_name
from derive.problem.units import ANGLE, DIMENSIONLESS, MASS, VELOCITY, Dim, describe
from derive.symbols import kind_of, symbol

#: Names whose meaning (and so dimension) the notes fix.
RESERVED: dict[str, Dim] = {
    **dict.fromkeys(("m_A", "m_B"), MASS),
    "e": DIMENSIONLESS,
    **dict.fromkeys(
        (
            *("v_A1", "v_B1", "v_A1n", "v_A1t", "v_B1n", "v_B1t"),
            *("v_A2", "v_B2", "v_A2n", "v_A2t", "v_B2n", "v_B2t"),
            *("v_A1x", "v_A1y", "v_B1x", "v_B1y"),
        ),
        VELOCITY,
    ),
    "W_A": units.FORCE,
    "W_B": units.FORCE,
    "g": units.ACCELERATION,
    "phi": ANGLE,
}
#: Velocities before the impact that, kept as letters, are positive (a speed along +n).
SPEEDS = ("v_A1", "v_B1")
#: A number typed as a plain decimal before its unit ("2.50 m/s", "-0.120 m/s", "37.6 deg").
_TYPED = re.compile(r"([-+]?(?:\d+\.?\d*|\.\d+))(?:\s+\S.*|°)?$")
#: Standard gravity as textbooks use it, by unit system (for mass = W/g).
GRAVITY = {"SI": ("9.81", "m/s^2"), "US": ("32.2", "ft/s^2")}
#: Names a file may not give: the results derive computes (the velocities after
#: the impact may be given, in an inverse problem).
COMPUTED = {"T_1", "T_2", "T_lost", "J_n"}
#: The magnitude of every given's value (written or computed), when not 0.
MAGNITUDE = (sympy.Rational(1, 10**30), sympy.Integer(10**30))
OUT_OF_RANGE = "is out of range (expected a magnitude between 1e-30 and 1e30)"

QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,2})?)\s*(.*?)\s*$")
_UNIT_ALONE = re.compile(r"[A-Za-z°][A-Za-z°/*^·\d\s]*")

Err = Callable[..., InputError]


def infer_system(tbl: Mapping[str, Any]) -> str:
    """ "US" when more givens are in US customary units than in SI, else "SI"."""
    votes = {"SI": 0, "US": 0}
    for value in tbl.values():
        if isinstance(value, str):
            m = QUANTITY.match(value)
            unit_text = m.group(2) if m else value
            try:
                sys_ = units.parse_unit(unit_text).system
            except ValueError:
                continue
            if sys_:
                votes[sys_] += 1
    return "US" if votes["US"] > votes["SI"] else "SI"


def build_givens(
    tbl: Mapping[str, Any],
    ctx: Source,
    oblique: bool,
    system: str,
    seed: Mapping[str, Given] | None = None,
    assume: Mapping[str, str] | None = None,
) -> list[Given]:
    """Build the givens in dependency order (a given may be defined from others).

    ``seed`` givens may be referred to; a key whose value is its own name (e = "e")
    is the seeded given itself. ``assume`` says what a letter is (``[assume]``)."""
    for key in tbl:
        _check_name(key, ctx)
    seed = dict(seed or {})
    done: dict[str, Given] = {}
    pending = dict(tbl)
    for key, raw in tbl.items():
        if isinstance(raw, str) and raw.strip() == key and key in seed:
            done[key] = seed[key]
            del pending[key]
    # In a chain's stage, a name on the right refers to the chain's quantity, even
    # where the stage defines the same name for itself (m_A = "m_B", m_B = "m_C").
    outer = {k: g for k, g in seed.items() if k in pending}
    while pending:
        ready = [k for k in pending if not ((names_in(pending[k]) & set(tbl)) - set(seed) - {k}) - set(done)]
        if not ready:
            key = sorted(pending)[0]
            raise ctx.error(
                "is defined in a circle (it depends on itself through other givens)",
                section="given",
                key=key,
                value=pending[key],
            )
        for key in ready:
            scope = {**done, **seed, **{k: _alias(g) for k, g in outer.items()}}
            done[key] = _outer(given_value(key, pending.pop(key), scope, ctx, oblique, system, assume), outer, ctx)
    return [done[k] for k in tbl]


def read_assume(raw: Mapping[str, str] | None, given_tbl: Mapping[str, Any], ctx: Source) -> dict[str, str]:
    """The [assume] table: what a letter is (letters are positive unless it says otherwise).
    Its words were checked against the schema; here each must name a given."""
    for name in raw or {}:
        if name not in given_tbl:
            raise ctx.error("names no given: assume what a letter of [given] is", section="assume", key=name)
    return dict(raw or {})


def _alias(g: Given) -> Given:
    """A chain's quantity that a stage shadows, under a symbol of its own while parsed."""
    return replace(g, symbol=sympy.Symbol(g.name + "__outer", **g.symbol.assumptions0))


def _outer(g: Given, outer: Mapping[str, Given], ctx: Source) -> Given:
    """``g`` with every shadowed chain quantity it names put in by its value (or definition)."""
    if g.definition is None or not outer:
        return g
    subs = {}
    for name, o in outer.items():
        alias = _alias(o).symbol
        if not g.definition.has(alias):
            continue
        if o.value is None and o.definition is None:
            raise ctx.error(
                f"refers to the chain's {name}, which this stage also defines: rename one of them",
                section="given",
                key=g.name,
            )
        subs[alias] = o.value if o.value is not None else o.definition
    if not subs:
        return g
    definition = g.definition.xreplace(subs)
    return replace(g, definition=definition if definition.free_symbols else None)


def _check_name(key: str, ctx: Source) -> None:
    if not isinstance(key, str) or not NAME_RE.match(key):
        raise ctx.error(BAD_NAME, section="given", key=key)
    if key in COMPUTED:
        raise ctx.error("is what derive computes, so it cannot be given", section="given", key=key)
    if key == "pi" or key in FUNCTIONS:
        raise ctx.error("is the name of a constant or function; choose another name", section="given", key=key)


def names_in(raw: Any) -> set[str]:
    """The names a given's text mentions (its possible dependencies)."""
    if not isinstance(raw, str):
        return set()
    return set(re.findall(r"[A-Za-z][A-Za-z0-9_]*", raw))


def given_value(
    key: str,
    raw: Any,
    done: Mapping[str, Given],
    ctx: Source,
    oblique: bool,
    system: str,
    assume: Mapping[str, str] | None = None,
) -> Given:
    """One given from its file value: a number, "?" (an unknown), its own name (a letter),
    a number with a unit, a unit alone (a letter of that kind) or an expression of the
    givens in ``done``."""

    def err(what: str, cls: type[InputError] = InputError) -> InputError:
        return ctx.error(what, section="given", key=key, value=raw, cls=cls)

    said = ASSUMPTIONS.get((assume or {}).get(key, ""))
    sym = symbol(key, said or kind_of(key, oblique))
    # a new name kept as a letter (u, m) is positive unless [assume] says otherwise; the
    # notes' own names keep their meaning (v_A1n is signed, e is 0 to 1)
    # a speed before the impact kept as a letter (v_A1 = "m/s") is positive too: +n, as written
    letter = symbol(key, said or (kind_of(key, oblique) if key in RESERVED and key not in SPEEDS else "positive"))
    try:
        if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
            raise err(f'expected a number or text such as "5 m/s", found {type_name(raw)}')
        if isinstance(raw, (int, float)):
            return _from_number(key, sym, raw, system, err)
        text = raw.strip()
        if text == key and key not in done:  # e = "e": a letter, of the dimension its name has
            return _letter(key, letter, system)
        if text == "?" or text.startswith("? "):
            return _unknown(key, sym, text[1:].strip(), system, err)
        if text == "":
            raise err(
                'is empty: expected a number with a unit ("5 m/s"), a unit alone for a symbol ("m/s"), or an expression'
            )
        given = _from_text(key, sym, letter, text, done, system, err)
        typed = _TYPED.match(text)
        if typed and given.value is not None and given.definition is None:
            return replace(given, typed=typed.group(1))
        return given
    except RecordError as exc:
        raise err(exc.what, exc.cls) from exc


def _letter(key: str, letter: sympy.Symbol, system: str) -> Given:
    expected = RESERVED.get(key)
    dim = expected if expected is not None else DIMENSIONLESS
    work = units.parse_unit("deg") if dim == ANGLE else units.working_unit(dim, system)
    return Given(key, letter, dim, None, work.text if dim in units.SYSTEMS[system] or dim == ANGLE else "")


def _from_number(key: str, sym: sympy.Symbol, raw: int | float, system: str, err: Err) -> Given:
    if isinstance(raw, float) and not math.isfinite(raw):
        raise err("expected a finite number")
    if abs(raw) > 1e30 or (raw != 0 and abs(raw) < 1e-30):
        raise err(OUT_OF_RANGE)
    value = sympy.Rational(str(raw)) if isinstance(raw, float) else sympy.Integer(raw)
    expected = RESERVED.get(key)
    dim = expected if expected is not None else DIMENSIONLESS
    unit = units.working_unit(dim, system) if dim != ANGLE else units.parse_unit("deg")
    if dim == ANGLE:
        value = value * unit.factor
    return Given(key, sym, dim, value, unit.text)


def _unknown(key: str, sym: sympy.Symbol, unit_text: str, system: str, err: Err) -> Given:
    expected = RESERVED.get(key)
    try:
        unit = units.parse_unit(unit_text) if unit_text else None
    except ValueError as exc:
        raise err(str(exc), UnitError) from None
    dim = unit.dim if unit is not None else (expected if expected is not None else DIMENSIONLESS)
    if expected is not None and dim != expected:
        raise err(f"expected {describe(expected)}, but {unit_text} is {describe(dim)}", UnitError)
    if dim == ANGLE:
        work_text = "deg"
    elif dim in units.SYSTEMS[system]:
        work_text = units.working_unit(dim, system).text
    else:
        raise err(f"{describe(dim)} cannot be an unknown here", UnitError)
    return Given(key, sym, dim, None, work_text, unknown=True)


def _from_text(
    key: str, sym: sympy.Symbol, letter: sympy.Symbol, text: str, done: Mapping[str, Given], system: str, err: Err
) -> Given:
    expected = RESERVED.get(key)
    unit_problem: str | None = None
    m = QUANTITY.match(text)
    looks_like_unit = bool(_UNIT_ALONE.fullmatch(text)) and _reads_as_unit(text, expected, done, system)
    if m and text not in done:
        number, unit_text = m.groups()
        try:
            unit = units.parse_unit(unit_text)
        except ValueError as exc:
            unit_problem = str(exc) if _UNIT_ALONE.fullmatch(unit_text) else None
        else:
            return quantity(key, sym, sympy.Rational(number), unit, expected, system, err)
    elif looks_like_unit:  # a unit alone: a symbolic given of that kind
        try:
            unit = units.parse_unit(text)
        except ValueError:
            unit = None
        if unit is not None:
            if expected is not None and unit.dim != expected:
                raise err(f"expected {describe(expected)}, but {text} is {describe(unit.dim)}", UnitError)
            work = units.working_unit(unit.dim, system) if unit.dim != ANGLE else units.parse_unit("deg")
            return Given(key, letter, unit.dim, None, work.text)
    return _from_expression(key, sym, text, done, system, err, unit_problem, looks_like_unit)


_TRAILING_UNIT = re.compile(r"^(.*\S)\s+([A-Za-z°][A-Za-z0-9_/^*·°-]*)\s*$")


def _unit_after_expression(what: str, key: str, text: str) -> str:
    """A unit after an expression ("1/3 kg") where only a plain number may take one: say so,
    and show the form that gives it (a helper given with the unit)."""
    m = _TRAILING_UNIT.match(text) if what.startswith("unexpected") else None
    if not m:
        return what
    try:
        unit = units.parse_unit(m.group(2))
    except ValueError:
        return what
    return (
        f'a unit may follow only a plain number ("2.5 {unit.text}"); for {m.group(1)} {unit.text} give the unit '
        f'to a helper given, u_1 = "1 {unit.text}", and write {key} = "({m.group(1)})*u_1"'
    )


def _reads_as_unit(text: str, expected: Dim | None, done: Mapping[str, Given], system: str) -> bool:
    """Whether a text that could be a unit alone ("m", "m/s") is one. A unit is a unit: ``d = "m"``
    is a length even beside a given mass ``m``, and ``u = "m/s"`` a velocity beside a given ``s``.
    Only where the name's kind is fixed (``m_A`` is a mass) and the unit is of another kind while
    the givens it names are of the right one is it those givens (``m_A = "m"``, the mass m)."""
    if not names_in(text) <= set(done):
        return True  # names no given: a unit, or an unknown name
    try:
        unit = units.parse_unit(text)
    except ValueError:
        return False  # the givens' expression
    if expected is None or unit.dim == expected:
        return True
    names = {g.name: (g.symbol, g.dim) for g in done.values()}
    try:
        as_givens = parse(text, names, system).dim
    except ParseError:
        return True
    return as_givens != expected


def _from_expression(
    key: str,
    sym: sympy.Symbol,
    text: str,
    done: Mapping[str, Given],
    system: str,
    err: Err,
    unit_problem: str | None,
    looks_like_unit: bool,
) -> Given:
    expected = RESERVED.get(key)
    names = {g.name: (g.symbol, g.dim) for g in done.values()}
    try:
        parsed = parse(text, names, system)
    except ParseError as exc:
        if unit_problem:
            raise err(unit_problem, UnitError) from None
        if looks_like_unit:
            raise err(f'{exc}; or, for a symbol, a known unit alone such as "m/s"', ExpressionError) from None
        raise err(_unit_after_expression(str(exc), key, text), ExpressionError) from None
    if expected is not None and parsed.dim != expected:
        raise err(f"expected {describe(expected)}, but the expression is {describe(parsed.dim)}", UnitError)
    values = {g.symbol: g.value for g in done.values() if g.value is not None}
    defined: dict[sympy.Symbol, sympy.Expr] = {}
    for g in done.values():  # symbolic givens defined from others (r_A = r) resolved, so r/(r_A + r_B) = 1/2
        if g.value is None and g.definition is not None:
            defined[g.symbol] = g.definition.xreplace(defined)
    full = parsed.expr.xreplace(defined)
    if function_nesting(full.xreplace(values)) > MAX_FUNCTION_NESTING:
        raise err(
            f"functions are nested too deeply once the givens it uses are put in (at most {MAX_FUNCTION_NESTING} levels)",
            ExpressionError,
        )
    value = full.xreplace(values)
    value = None if value.free_symbols else _checked_value(value, err)
    work = (
        units.working_unit(parsed.dim, system)
        if parsed.dim in units.SYSTEMS[system]
        else units.Unit("", sympy.Integer(1), parsed.dim)
    )
    inexact = any(g.inexact for g in done.values() if g.symbol in parsed.expr.free_symbols)
    return Given(key, sym, parsed.dim, value, work.text, definition=parsed.expr, inexact=inexact)


def _checked_value(value: sympy.Expr, err: Err) -> sympy.Expr:
    """A computed value: a finite real number within the range a written number must keep."""
    try:
        num = complex(value.evalf(30))
    except (TypeError, ValueError, OverflowError):
        raise err("does not evaluate to a number") from None
    if not math.isfinite(num.real) or abs(num.imag) > 1e-12 * max(1.0, abs(num.real)):
        raise err("does not evaluate to a finite real number")
    size = abs(num.real)
    if size > 1e30 * (1 + 1e-12) or (value != 0 and 0 < size < 1e-30 * (1 - 1e-12)):
        raise err(f"{OUT_OF_RANGE}; it works out at {num.real:.3g}")
    return value


def quantity(
    key: str, sym: sympy.Symbol, number: sympy.Expr, unit: units.Unit, expected: Dim | None, system: str, err: Err
) -> Given:
    """A number with its unit as a given in the working unit (an angle in radians)."""
    if expected is not None and unit.dim != expected:
        raise err(
            f"expected {describe(expected)}, but {unit.text or 'a bare number'} is {describe(unit.dim)}", UnitError
        )
    if abs(number) > MAGNITUDE[1] or (number != 0 and abs(number) < MAGNITUDE[0]):
        raise err(OUT_OF_RANGE)
    if unit.dim == ANGLE:
        return Given(
            key,
            sym,
            ANGLE,
            number * unit.factor,
            "deg",
            written=None if unit.text in ("deg", "°") else f"{number} {unit.text}",
        )
    if unit.dim not in units.SYSTEMS[system]:
        raise err(f"{unit.text} is {describe(unit.dim)}, which derive does not use in a given", UnitError)
    work = units.working_unit(unit.dim, system)
    if unit.dim == units.FORCE and expected == MASS:
        raise err("a weight is not a mass", UnitError)
    if unit.text == work.text or unit.dim == DIMENSIONLESS:
        return Given(key, sym, unit.dim, number, work.text)
    value = units.convert(number, unit, work)
    return Given(key, sym, unit.dim, value, work.text, written=f"{number} {unit.text}")
