"""Problem files: read a TOML problem, check every field, and build a :class:`Problem`.

The format is documented in ``docs/problem-format.md``. Every error names the
file, the line where it can be found, the field and what was expected.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from typing import Any

import sympy

from derive.errors import ExpressionError, InputError, PhysicsError, UnitError
from derive.problem import units
from derive.problem.expr import NAME_RE, ParseError, parse
from derive.problem.source import Source, text_field, type_name
from derive.problem.symbolic import Asks, Relation, read_asks
from derive.problem.units import ANGLE, DIMENSIONLESS, MASS, VELOCITY, Dim, describe
from derive.symbols import kind_of, symbol

KINDS = ("direct", "oblique")
TOP_FIELDS = (
    "title",
    "kind",
    "source",
    "statement",
    "question",
    "find",
    "digits",
    "units",
    "given",
    "geometry",
    "answer_units",
    "answers",
    "assume",
    "define",
    "equations",
    "range",
    "show",
    "vary",
    "conditions",
    "A",
    "B",
)
GEOMETRY_FIELDS = ("n_angle", "offset", "centre_A", "centre_B")
BODY_FIELDS = ("angle", "from", "toward", "fixed", "name")
AXES = ("+n", "-n", "+t", "-t")
XY_AXES = ("+x", "-x", "+y", "-y")
MAX_GIVENS = 60

#: Names whose meaning (and so dimension) the notes fix.
RESERVED: dict[str, Dim] = {
    "m_A": MASS,
    "m_B": MASS,
    "e": DIMENSIONLESS,
    "v_A1": VELOCITY,
    "v_B1": VELOCITY,
    "v_A1n": VELOCITY,
    "v_A1t": VELOCITY,
    "v_B1n": VELOCITY,
    "v_B1t": VELOCITY,
    "v_A2": VELOCITY,
    "v_B2": VELOCITY,
    "v_A2n": VELOCITY,
    "v_A2t": VELOCITY,
    "v_B2n": VELOCITY,
    "v_B2t": VELOCITY,
    "W_A": units.FORCE,
    "W_B": units.FORCE,
    "g": units.ACCELERATION,
    "phi": ANGLE,
    "v_A1x": VELOCITY,
    "v_A1y": VELOCITY,
    "v_B1x": VELOCITY,
    "v_B1y": VELOCITY,
}
#: Standard gravity as textbooks use it, by unit system (for mass = W/g).
GRAVITY = {"SI": ("9.81", "m/s^2"), "US": ("32.2", "ft/s^2")}
#: Results a problem may ask for by name.
RESULT_NAMES = (
    "v_A2",
    "v_B2",
    "v_A2n",
    "v_A2t",
    "v_B2n",
    "v_B2t",
    "theta_A2",
    "theta_B2",
    "beta_A2",
    "beta_B2",
    "T_1",
    "T_2",
    "T_lost",
)
#: Names a file may not give: the results derive computes (the velocities after
#: the impact may be given, in an inverse problem).
COMPUTED = {"T_1", "T_2", "T_lost", "J_n"}
#: Velocities after the impact, by kind: given in an inverse problem, else unknown.
POST = {"direct": ("v_A2", "v_B2"), "oblique": ("v_A2t", "v_A2n", "v_B2t", "v_B2n")}

_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,2})?)\s*(.*?)\s*$")


@dataclass(frozen=True)
class Given:
    """One given: its symbol, dimension and exact value in the problem's working unit.

    ``value`` is None for a symbolic given. Angles are held in radians (shown in
    degrees); ``written`` is the text as the file gave it when it was converted.
    """

    name: str
    symbol: sympy.Symbol
    dim: Dim
    value: sympy.Expr | None
    unit: str
    written: str | None = None
    definition: sympy.Expr | None = None
    unknown: bool = False

    @property
    def decimal(self) -> bool:
        """True for a number that is not whole and was not written as an expression (0.6,
        37.6 deg, 22 g as 0.022 kg): where it meets letters the worked lines show decimals;
        exact data (integers, 3/5, sqrt(2)) stay exact."""
        if self.value is None or self.definition is not None:
            return False
        if self.unit == "deg":
            return not (self.value * 180 / sympy.pi).is_Integer
        return not self.value.is_Integer  # 0.6, and 22 g as 0.022 kg


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


@dataclass(frozen=True)
class Condition:
    """A condition every homework variant must meet, such as ``v_B2n > 0``."""

    text: str
    lhs: sympy.Expr
    op: str
    rhs: sympy.Expr


@dataclass(frozen=True)
class Problem:
    """A central-impact problem, checked and ready for the equations."""

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
    phi: sympy.Symbol | None = None
    answer_units: Mapping[str, str] = field(default_factory=dict)
    vary: Mapping[str, tuple[sympy.Expr, ...]] = field(default_factory=dict)
    conditions: tuple[Condition, ...] = ()
    extra: Mapping[str, Any] = field(default_factory=dict)
    assume: Mapping[str, str] = field(default_factory=dict)
    asks: Asks = field(default_factory=Asks)

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


def build_problem(data: dict[str, Any], ctx: Source, name: str, seed: Mapping[str, Given] | None = None) -> Problem:
    """A Problem from parsed TOML. ``seed`` holds givens known already (a chain's
    earlier results): the file's values may refer to them, and a required name the
    file leaves out (m_A, e, ...) is taken from them."""
    for key in data:
        if key not in TOP_FIELDS:
            raise ctx.error(f"unknown field (expected one of: {', '.join(TOP_FIELDS)})", key=key)
    title = text_field(data, "title", ctx, required=True)
    assert title is not None
    kind = data.get("kind")
    if kind not in KINDS:
        what = "is missing" if kind is None else "is not a kind of problem"
        raise ctx.error(f'{what}: expected "direct" or "oblique" (or "chain" for stages)', key="kind", value=kind)
    oblique = kind == "oblique"
    digits = data.get("digits")
    if digits is not None and (isinstance(digits, bool) or not isinstance(digits, int) or not 1 <= digits <= 10):
        raise ctx.error("expected a whole number of significant figures from 1 to 10", key="digits", value=digits)
    system = data.get("units")
    if system is not None and (not isinstance(system, str) or system not in units.SYSTEMS):
        raise ctx.error('expected "SI" or "US"', key="units", value=system)

    given_tbl = data.get("given")
    if given_tbl is None:
        raise ctx.error("is missing: give the masses, e and the velocities before the impact", section="given")
    if not isinstance(given_tbl, dict):
        raise ctx.error(f"expected a table, not {type_name(given_tbl)}", key="given")
    if len(given_tbl) > MAX_GIVENS:
        raise ctx.error(f"has too many entries ({len(given_tbl)}, at most {MAX_GIVENS})", section="given")
    if system is None:
        system = infer_system(given_tbl)
    assume = read_assume(data.get("assume"), given_tbl, ctx)
    after = {k: v for k, v in given_tbl.items() if k in AFTER}
    given_tbl = {k: v for k, v in given_tbl.items() if k not in AFTER}
    givens = build_givens(given_tbl, ctx, oblique, system, seed, assume)
    by_name = {g.name: g for g in givens}
    b_tbl = data.get("B")
    b_fixed = isinstance(b_tbl, dict) and b_tbl.get("fixed") is True
    needed = ("m_A", "e", "v_A1", "v_A1n", "v_A1t", "W_A")
    if not b_fixed:
        needed += ("m_B", "v_B1", "v_B1n", "v_B1t", "W_B")
    if any(w in given_tbl or w in (seed or {}) for w in ("W_A", "W_B")):
        needed += ("g",)
    for key, g in (seed or {}).items():
        if key in needed and key not in by_name:
            givens.append(g)
            by_name[key] = g

    body_tbls = {}
    for b in "AB":
        tbl = data.get(b, {})
        if not isinstance(tbl, dict):
            raise ctx.error(f"expected a table, not {type_name(tbl)}", key=b)
        for k in tbl:
            if k not in BODY_FIELDS:
                raise ctx.error(f"unknown field (expected one of: {', '.join(BODY_FIELDS)})", section=b, key=k)
        for k in ("fixed",):
            if k in tbl and not isinstance(tbl[k], bool):
                raise ctx.error("expected true or false", section=b, key=k, value=tbl[k])
        if "name" in tbl and (not isinstance(tbl["name"], str) or not 0 < len(tbl["name"]) <= 40):
            raise ctx.error('expected a short name such as "wall" or "floor"', section=b, key="name", value=tbl["name"])
        body_tbls[b] = tbl
    if body_tbls["A"].get("fixed"):
        raise ctx.error(
            "only B can be fixed: let A be the moving body and B the wall or floor", section="A", key="fixed"
        )
    fixed_B = bool(body_tbls["B"].get("fixed"))
    if fixed_B:
        for k in ("m_B", "W_B", "v_B1", "v_B1n", "v_B1t", "v_B2", "v_B2n", "v_B2t"):
            if k in by_name:
                raise ctx.error(
                    "B is fixed (a wall or floor: infinite mass, at rest), so it takes no mass or velocity",
                    section="given",
                    key=k,
                )
        for k in ("angle", "from", "toward"):
            if k in body_tbls["B"]:
                raise ctx.error("B is fixed: it has no velocity to give a direction to", section="B", key=k)

    for b in "AB":
        m, w = f"m_{b}", f"W_{b}"
        if b == "B" and fixed_B:
            continue
        if m in by_name and w in by_name:
            raise ctx.error(f"give the mass {m} or the weight {w}, not both", section="given", key=w)
        if m not in by_name and w in by_name:
            if "g" not in by_name:
                number, unit_text = GRAVITY[system]
                g_given = _quantity(
                    "g",
                    symbol("g", "positive"),
                    sympy.Rational(number),
                    units.parse_unit(unit_text),
                    units.ACCELERATION,
                    system,
                    None,
                )
                givens.append(g_given)
                by_name["g"] = g_given
            weight, grav = by_name[w], by_name["g"]
            definition = weight.symbol / grav.symbol
            value = None if weight.value is None or grav.value is None else weight.value / grav.value
            mass = Given(
                m,
                symbol(m, "positive"),
                MASS,
                value,
                units.working_unit(MASS, system).text,
                definition=definition,
                unknown=False,
            )
            givens.append(mass)
            by_name[m] = mass

    needs = ("m_A", "e") if fixed_B else ("m_A", "m_B", "e")
    for need in needs:
        if need not in by_name:
            what = {"e": "the coefficient of restitution e"}.get(
                need, f"the mass of {need[-1]} (or its weight W_{need[-1]})"
            )
            raise ctx.error(f"is missing: give {what}", section="given", key=need)
    post = POST[kind]
    for k in list(by_name):
        if k.startswith(("v_A2", "v_B2")) and k not in post:
            allowed = ", ".join(post)
            raise ctx.error(
                f"is not a velocity this kind of impact uses after the impact (use {allowed})", section="given", key=k
            )
    _check_ranges(by_name, given_tbl, ctx)

    phi = _geometry(data.get("geometry"), givens, by_name, ctx, oblique, system)
    motions = []
    for b in "AB":
        if b == "B" and fixed_B:
            motions.append(Motion("B", sympy.Integer(0), sympy.Integer(0)))
            continue
        motion, extra = _motion(b, body_tbls[b], by_name, ctx, oblique, phi)
        if extra is not None:
            givens.append(extra)
            by_name[extra.name] = extra
        motions.append(motion)

    asks = read_asks(
        data,
        {g.name: (g.symbol, g.dim) for g in givens},
        RESULT_DIMS,
        {g.name for g in givens if g.value is None and not g.unknown},
        system,
        ctx,
    )
    asks = replace(asks, equations=asks.equations + _known_after(after, by_name, ctx, oblique, system))
    extra = tuple(d.name for d in asks.defined) + (("v_A2x", "v_A2y", "v_B2x", "v_B2y") if phi is not None else ())
    find = _find(data.get("find"), ctx, oblique, tuple(g.name for g in givens if g.unknown), extra)
    problem = Problem(
        path=ctx.path,
        title=title,
        kind=kind,
        givens=tuple(givens),
        motion_A=motions[0],
        motion_B=motions[1],
        find=find,
        system=system,
        digits=digits,
        source=text_field(data, "source", ctx),
        statement=text_field(data, "statement", ctx),
        question=text_field(data, "question", ctx),
        name=name,
        fixed_B=fixed_B,
        name_B=body_tbls["B"].get("name"),
        phi=phi,
        answer_units=_answer_units(data.get("answer_units"), ctx),
        vary=_vary(data.get("vary"), by_name, ctx, oblique, system),
        conditions=_conditions(data.get("conditions"), by_name, ctx),
        assume=assume,
        asks=asks,
    )
    _check_approach(problem, ctx)
    return problem


def infer_system(tbl: Mapping[str, Any]) -> str:
    votes = {"SI": 0, "US": 0}
    for value in tbl.values():
        if isinstance(value, str):
            m = _QUANTITY.match(value)
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
    is the seeded given itself."""
    for key in tbl:
        if not NAME_RE.match(key):
            raise ctx.error(
                "is not a usable name: start with a letter; letters, digits and _ only", section="given", key=key
            )
        if key in COMPUTED:
            raise ctx.error("is what derive computes, so it cannot be given", section="given", key=key)
        if key in ("pi",) or key in ("sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "exp", "log"):
            raise ctx.error("is the name of a constant or function; choose another name", section="given", key=key)
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
        progressed = False
        for key in list(pending):
            raw = pending[key]
            deps = (_names_in(raw) & set(tbl)) - set(seed) - {key}  # e = "e" is a letter
            if deps - set(done):
                continue
            scope = {**done, **seed, **{k: _alias(g) for k, g in outer.items()}}
            done[key] = _outer(_given(key, raw, scope, ctx, oblique, system, assume), outer, ctx)
            del pending[key]
            progressed = True
        if not progressed:
            key = sorted(pending)[0]
            raise ctx.error(
                "is defined in a circle (it depends on itself through other givens)",
                section="given",
                key=key,
                value=pending[key],
            )
    return [done[k] for k in tbl]


#: What a file may assume of a letter -> the symbol's assumptions (an acute angle is
#: positive, and its range is used where a sign is decided).
ASSUMPTIONS = {
    "positive": "positive",
    "nonnegative": "nonnegative",
    "real": "real",
    "negative": "negative",
    "acute": "positive",
}


def read_assume(raw: Any, given_tbl: Mapping[str, Any], ctx: Source) -> dict[str, str]:
    """The [assume] table: what a letter is (letters are positive unless it says otherwise)."""
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise ctx.error(f'expected a table such as {{ alpha = "acute" }}, not {type_name(raw)}', key="assume")
    for name, word in raw.items():
        if name not in given_tbl:
            raise ctx.error("names no given: assume what a letter of [given] is", section="assume", key=name)
        if word not in ASSUMPTIONS:
            raise ctx.error(f"expected one of: {', '.join(ASSUMPTIONS)}", section="assume", key=name, value=word)
    return dict(raw)


#: Results after the impact a file may give as knowns (each becomes an equation).
AFTER = ("theta_A2", "theta_B2", "beta_A2", "beta_B2")


def _known_after(
    after: Mapping[str, Any], by_name: Mapping[str, Given], ctx: Source, oblique: bool, system: str
) -> tuple[Relation, ...]:
    """A direction after the impact given as a known: ``theta_A2 = "30 deg"`` is the
    equation theta_A2 = 30°, which fixes one more unknown."""
    out = []
    for name, raw in after.items():
        if not oblique:
            raise ctx.error('a direction after the impact needs kind = "oblique"', section="given", key=name)
        g = _given(name, raw, by_name, ctx, oblique, system)
        if g.dim != ANGLE or g.value is None:
            raise ctx.error('expected an angle such as "30 deg"', section="given", key=name, value=raw)
        out.append(Relation(f"{name} = {raw}", symbol(name), g.value * 180 / sympy.pi))
    return tuple(out)


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


def _names_in(raw: Any) -> set[str]:
    if not isinstance(raw, str):
        return set()
    return set(re.findall(r"[A-Za-z][A-Za-z0-9_]*", raw))


def _given(
    key: str,
    raw: Any,
    done: Mapping[str, Given],
    ctx: Source,
    oblique: bool,
    system: str,
    assume: Mapping[str, str] | None = None,
) -> Given:
    expected = RESERVED.get(key)
    assume = assume or {}
    sym = symbol(key, ASSUMPTIONS.get(assume.get(key, ""), kind_of(key, oblique)))
    # a new name kept as a letter (u, m) is positive unless [assume] says otherwise; the
    # notes' own names keep their meaning (v_A1n is signed, e is 0 to 1)
    natural = kind_of(key, oblique) if key in RESERVED else "positive"
    letter = symbol(key, ASSUMPTIONS.get(assume.get(key, ""), natural))
    err = lambda what, cls=InputError: ctx.error(what, section="given", key=key, value=raw, cls=cls)  # noqa: E731
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise err(f'expected a number or text such as "5 m/s", not {type_name(raw)}')
    if isinstance(raw, float) and not math.isfinite(raw):
        raise err("expected a finite number")
    if isinstance(raw, (int, float)):
        if abs(raw) > 1e30 or (raw != 0 and abs(raw) < 1e-30):
            raise err("is out of range (expected a magnitude between 1e-30 and 1e30)")
        value = sympy.Rational(str(raw)) if isinstance(raw, float) else sympy.Integer(raw)
        dim = expected if expected is not None else DIMENSIONLESS
        unit = units.working_unit(dim, system) if dim != ANGLE else units.parse_unit("deg")
        if dim == ANGLE:
            value = value * unit.factor
        return Given(key, sym, dim, value, unit.text)
    text = raw.strip()
    if text == key and key not in done:  # e = "e": a letter, of the dimension its name has
        dim = expected if expected is not None else DIMENSIONLESS
        work = units.parse_unit("deg") if dim == ANGLE else units.working_unit(dim, system)
        return Given(key, letter, dim, None, work.text if dim in units.SYSTEMS[system] or dim == ANGLE else "")
    if text == "?" or text.startswith("? "):
        unit_text = text[1:].strip()
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
    if text == "":
        raise err(
            'is empty: expected a number with a unit ("5 m/s"), a unit alone for a symbol ("m/s"), or an expression'
        )
    unit_problem: str | None = None
    m = _QUANTITY.match(text)
    if m and text not in done:
        number, unit_text = m.groups()
        try:
            unit = units.parse_unit(unit_text)
        except ValueError as exc:
            unit_problem = str(exc) if re.fullmatch(r"[A-Za-z°][A-Za-z°/*^·\d\s]*", unit_text) else None
        else:
            return _quantity(key, sym, sympy.Rational(number), unit, expected, system, err)
    elif re.fullmatch(r"[A-Za-z°][A-Za-z°/*^·\d\s]*", text) and not _names_in(text) <= set(done):
        # a unit alone: a symbolic given of that kind
        try:
            unit = units.parse_unit(text)
        except ValueError:
            unit = None
        if unit is not None:
            if expected is not None and unit.dim != expected:
                raise err(f"expected {describe(expected)}, but {text} is {describe(unit.dim)}", UnitError)
            work = units.working_unit(unit.dim, system) if unit.dim != ANGLE else units.parse_unit("deg")
            return Given(key, letter, unit.dim, None, work.text)
    names = {g.name: (g.symbol, g.dim) for g in done.values()}
    try:
        parsed = parse(text, names)
    except ParseError as exc:
        if unit_problem:
            raise err(unit_problem, UnitError) from None
        if re.fullmatch(r"[A-Za-z°][A-Za-z°/*^·\d\s]*", text) and not _names_in(text) <= set(done):
            raise err(f'{exc}; or, for a symbol, a known unit alone such as "m/s"', ExpressionError) from None
        raise err(str(exc), ExpressionError) from None
    if expected is not None and parsed.dim != expected:
        raise err(f"expected {describe(expected)}, but the expression is {describe(parsed.dim)}", UnitError)
    values = {g.symbol: g.value for g in done.values() if g.value is not None}
    defined: dict[sympy.Symbol, sympy.Expr] = {}
    for g in done.values():  # symbolic givens defined from others (r_A = r) resolved, so r/(r_A + r_B) = 1/2
        if g.value is None and g.definition is not None:
            defined[g.symbol] = g.definition.xreplace(defined)
    value = parsed.expr.xreplace(defined).xreplace(values)
    if value.free_symbols:
        value = None
    else:
        try:
            num = complex(value.evalf(30))
        except (TypeError, ValueError):
            raise err("does not evaluate to a number") from None
        if not math.isfinite(num.real) or abs(num.imag) > 1e-12 * max(1.0, abs(num.real)):
            raise err("does not evaluate to a finite real number")
    work = (
        units.working_unit(parsed.dim, system)
        if parsed.dim in units.SYSTEMS[system]
        else units.Unit("", sympy.Integer(1), parsed.dim)
    )
    return Given(key, sym, parsed.dim, value, work.text, definition=parsed.expr)


def _quantity(
    key: str, sym: sympy.Symbol, number: sympy.Expr, unit: units.Unit, expected: Dim | None, system: str, err
) -> Given:
    if expected is not None and unit.dim != expected:
        raise err(
            f"expected {describe(expected)}, but {unit.text or 'a bare number'} is {describe(unit.dim)}", UnitError
        )
    if abs(number) > 10**30 or (number != 0 and abs(number) < sympy.Rational(1, 10**30)):
        raise err("is out of range (expected a magnitude between 1e-30 and 1e30)")
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


def _check_ranges(by_name: Mapping[str, Given], raw: Mapping[str, Any], ctx: Source) -> None:
    e = by_name["e"].value
    if e is not None and not (0 <= e <= 1):
        raise ctx.error(
            "the coefficient of restitution must lie between 0 and 1",
            section="given",
            key="e",
            value=raw["e"],
            cls=PhysicsError,
        )
    for m in ("m_A", "m_B"):
        if m not in by_name:
            continue
        v = by_name[m].value
        if v is not None and not v > 0:
            raise ctx.error("a mass must be positive", section="given", key=m, value=raw.get(m), cls=PhysicsError)
    for s in ("v_A1", "v_B1"):
        g = by_name.get(s)
        if g is not None and g.value is not None and g.symbol.is_nonnegative and not g.value >= 0:
            raise ctx.error(
                "a speed cannot be negative (its direction is set by [A]/[B] angle, from and toward)",
                section="given",
                key=s,
                value=raw.get(s, None),
                cls=PhysicsError,
            )


def _num(value: sympy.Expr) -> str:
    from derive.numbers import format_number

    return format_number(value, 4)


def _geometry(
    geo: Any, givens: list[Given], by_name: dict[str, Given], ctx: Source, oblique: bool, system: str
) -> sympy.Symbol | None:
    """The line of impact in the problem's x-y axes: its angle phi from +x toward +y,
    given directly, from an offset between parallel paths (sin phi = d/(r_A + r_B)),
    or from the centres at contact. phi becomes a given, defined by that geometry."""
    if geo is None:
        return None
    if not isinstance(geo, dict):
        raise ctx.error(f"expected a table, not {type_name(geo)}", key="geometry")
    for k in geo:
        if k not in GEOMETRY_FIELDS:
            raise ctx.error(f"unknown field (expected one of: {', '.join(GEOMETRY_FIELDS)})", section="geometry", key=k)
    if not oblique:
        raise ctx.error('the line of impact from geometry needs kind = "oblique"', section="geometry")
    if "phi" in by_name:
        raise ctx.error(
            "phi is the angle derive gives the line of impact; rename this given", section="given", key="phi"
        )
    methods = [m for m in ("n_angle", "offset", "centre_A") if m in geo]
    if len(methods) != 1 or ("centre_A" in geo) != ("centre_B" in geo):
        raise ctx.error(
            "give exactly one of: n_angle; offset (with r_A and r_B given); centre_A and centre_B", section="geometry"
        )

    def add(name: str, raw: Any, field_: str) -> Given:
        if name in by_name:
            raise ctx.error(f"{name} is given already; [geometry] defines it", section="geometry", key=field_)
        try:
            g = _given(name, raw, by_name, ctx, oblique, system)
        except InputError as exc:
            raise ctx.error(exc.what, section="geometry", key=field_, value=raw, cls=type(exc)) from None
        givens.append(g)
        by_name[name] = g
        return g

    if "n_angle" in geo:
        raw = geo["n_angle"]
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            raw = f"{raw} deg"
        return add("phi", raw, "n_angle").symbol
    if "offset" in geo:
        for r in ("r_A", "r_B"):
            if r not in by_name or by_name[r].dim != units.LENGTH:
                raise ctx.error(f"an offset needs the radii: give {r} (a length)", section="given", key=r)
        raw = geo["offset"]
        d = by_name[raw.strip()] if isinstance(raw, str) and raw.strip() in by_name else add("d", raw, "offset")
        if d.dim != units.LENGTH:
            raise ctx.error("expected a length", section="geometry", key="offset", value=geo["offset"], cls=UnitError)
        return add("phi", f"asin({d.name}/(r_A + r_B))", "offset").symbol
    for b in "AB":
        raw = geo[f"centre_{b}"]
        if not isinstance(raw, list) or len(raw) != 2:
            raise ctx.error('expected two coordinates, such as ["0 m", "0.1 m"]', section="geometry", key=f"centre_{b}")
        for axis, value in zip("xy", raw, strict=True):
            g = add(f"{axis}_{b}", value, f"centre_{b}")
            if g.dim != units.LENGTH:
                raise ctx.error("expected lengths", section="geometry", key=f"centre_{b}", value=raw, cls=UnitError)
    return add("phi", "atan2(y_B - y_A, x_B - x_A)", "centre_B").symbol


def _motion(
    b: str,
    tbl: Mapping[str, Any],
    by_name: dict[str, Given],
    ctx: Source,
    oblique: bool,
    phi: sympy.Symbol | None = None,
) -> tuple[Motion, Given | None]:
    speed_name, n_name, t_name = f"v_{b}1", f"v_{b}1n", f"v_{b}1t"
    x_name, y_name = f"v_{b}1x", f"v_{b}1y"
    if (x_name in by_name or y_name in by_name) and phi is None:
        key = x_name if x_name in by_name else y_name
        raise ctx.error("x-y components need a [geometry] table that sets the line of impact", section="given", key=key)
    if phi is not None and (x_name in by_name or y_name in by_name):
        if n_name in by_name or t_name in by_name or speed_name in by_name:
            raise ctx.error(f"give the velocity of {b} one way only", section="given", key=x_name)
        missing = [k for k in (x_name, y_name) if k not in by_name]
        if missing:
            raise ctx.error(
                f"is missing: with components give both {x_name} and {y_name}", section="given", key=missing[0]
            )
        vx, vy = by_name[x_name].symbol, by_name[y_name].symbol
        n = vx * sympy.cos(phi) + vy * sympy.sin(phi)
        t = -vx * sympy.sin(phi) + vy * sympy.cos(phi)
        return Motion(b, n, t, x=vx, y=vy), None
    if not oblique:
        if n_name in by_name or t_name in by_name or {"angle", "from", "toward"} & set(tbl):
            key = n_name if n_name in by_name else t_name if t_name in by_name else None
            raise ctx.error(
                f"a direct impact has one velocity component: give {speed_name}, signed along +n (from A toward B)",
                section="given" if key else b,
                key=key,
            )
        if speed_name not in by_name:
            raise ctx.error(
                f"is missing: give the velocity of {b} before the impact, signed along +n",
                section="given",
                key=speed_name,
            )
        return Motion(b, by_name[speed_name].symbol, sympy.Integer(0)), None
    has_comp = n_name in by_name or t_name in by_name
    if has_comp and speed_name in by_name:
        raise ctx.error(
            f"give either {speed_name} (speed, with a direction) or {n_name} and {t_name}, not both",
            section="given",
            key=speed_name,
        )
    if has_comp:
        if {"angle", "from", "toward"} & set(tbl):
            raise ctx.error(f"the velocity of {b} is given by components, so [{b}] needs no angle", section=b)
        missing = [k for k in (n_name, t_name) if k not in by_name]
        if missing:
            raise ctx.error(
                f"is missing: with components give both {n_name} and {t_name}", section="given", key=missing[0]
            )
        return Motion(b, by_name[n_name].symbol, by_name[t_name].symbol), None
    if speed_name not in by_name:
        raise ctx.error(
            f"is missing: give the speed {speed_name} with [{b}] angle, from and toward, or the components {n_name} and {t_name}",
            section="given",
            key=speed_name,
        )
    speed = by_name[speed_name]
    if not {"angle", "from", "toward"} & set(tbl):
        if speed.value == 0:
            return Motion(b, sympy.Integer(0), sympy.Integer(0), speed=speed.symbol), None
        raise ctx.error(f"is missing: give the direction of {b}'s velocity (angle, from, toward)", section=b)
    for k in ("angle", "from", "toward"):
        if k not in tbl:
            raise ctx.error(f"is missing: the direction of {b} needs angle, from and toward", section=b, key=k)
    axis_from, toward = tbl["from"], tbl["toward"]
    allowed = AXES + (XY_AXES if phi is not None else ())
    for k, ax in (("from", axis_from), ("toward", toward)):
        if ax not in allowed:
            hint = "" if phi is not None else " (x-y axes need a [geometry] table)"
            raise ctx.error(f"expected one of {', '.join(allowed)}{hint}", section=b, key=k, value=ax)
    if (axis_from in XY_AXES) != (toward in XY_AXES):
        raise ctx.error("measure the angle between two x-y axes or two n-t axes", section=b, key="toward", value=toward)
    if axis_from[1] == toward[1]:
        raise ctx.error(
            f"the angle is measured from {axis_from} toward an axis at right angles to it (±n or ±t), not {toward}",
            section=b,
            key="toward",
            value=toward,
        )
    extra = None
    angle_raw = tbl["angle"]
    if isinstance(angle_raw, str) and angle_raw.strip() in by_name:
        angle = by_name[angle_raw.strip()]
        if angle.dim != ANGLE:
            raise ctx.error(
                f'{angle.name} is {describe(angle.dim)}, not an angle: give it with its unit, such as "30 deg"',
                section=b,
                key="angle",
                value=angle_raw,
                cls=UnitError,
            )
    else:
        name = f"theta_{b}1"
        if name in by_name:
            raise ctx.error(f'{name} is already given: write angle = "{name}"', section=b, key="angle", value=angle_raw)
        err = lambda what, cls=InputError: ctx.error(what, section=b, key="angle", value=angle_raw, cls=cls)  # noqa: E731
        if isinstance(angle_raw, bool) or not isinstance(angle_raw, (int, float, str)):
            raise err('expected an angle such as "30 deg" or the name of a given angle')
        if isinstance(angle_raw, (int, float)):
            if not math.isfinite(angle_raw):
                raise err("expected a finite angle")
            angle_raw = f"{angle_raw} deg"
        m = _QUANTITY.match(angle_raw)
        if not m:
            raise err('expected an angle such as "30 deg" or the name of a given angle')
        try:
            unit = units.parse_unit(m.group(2) or "deg")
        except ValueError as exc:
            raise err(str(exc), UnitError) from None
        if unit.dim != ANGLE:
            raise err(f"expected an angle, but {unit.text} is {describe(unit.dim)}", UnitError)
        angle = _quantity(name, symbol(name), sympy.Rational(m.group(1)), unit, ANGLE, "SI", err)
        extra = angle
    v, th = speed.symbol, angle.symbol
    comps = {axis_from: v * sympy.cos(th), toward: v * sympy.sin(th)}
    if axis_from in XY_AXES:
        assert phi is not None
        x = sympy.sympify(sum((c if ax == "+x" else -c) for ax, c in comps.items() if ax[1] == "x"))
        y = sympy.sympify(sum((c if ax == "+y" else -c) for ax, c in comps.items() if ax[1] == "y"))
        n = x * sympy.cos(phi) + y * sympy.sin(phi)
        t = -x * sympy.sin(phi) + y * sympy.cos(phi)
        motion = Motion(b, n, t, speed=v, angle=th, axis_from=axis_from, toward=toward, x=x, y=y)
        return motion, extra
    n = sum((c if ax == "+n" else -c) for ax, c in comps.items() if ax[1] == "n")
    t = sum((c if ax == "+t" else -c) for ax, c in comps.items() if ax[1] == "t")
    return Motion(b, sympy.sympify(n), sympy.sympify(t), speed=v, angle=th, axis_from=axis_from, toward=toward), extra


MAX_CHOICES = 100_000
_CONDITION = re.compile(r"^(.*?)(<=|>=|<|>)(.*)$")
#: Dimension of each result name, for conditions on results.
RESULT_DIMS: dict[str, Dim] = {
    **dict.fromkeys(("v_A2", "v_B2", "v_A2n", "v_A2t", "v_B2n", "v_B2t", "v_A2x", "v_A2y", "v_B2x", "v_B2y"), VELOCITY),
    **dict.fromkeys(("theta_A2", "theta_B2", "beta_A2", "beta_B2"), ANGLE),
    **dict.fromkeys(("T_1", "T_2", "T_lost"), units.ENERGY),
    "J_n": units.IMPULSE,
}


def _vary(
    raw: Any, by_name: dict[str, Given], ctx: Source, oblique: bool, system: str
) -> dict[str, tuple[sympy.Expr, ...]]:
    """Ranges or choices for homework variants: { m_A = { min = "2 kg", max = "10 kg", step = "0.5 kg" } }."""
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise ctx.error("expected a table of ranges or choices", key="vary")
    out: dict[str, tuple[sympy.Expr, ...]] = {}
    for name, spec in raw.items():
        g = by_name.get(name)
        if g is None or g.value is None or g.unknown or g.definition is not None:
            raise ctx.error("only a given with a plain number can vary", section="vary", key=name)
        if not isinstance(spec, dict) or not ({"choices"} == set(spec) or {"min", "max", "step"} == set(spec)):
            raise ctx.error(
                "expected { min = ..., max = ..., step = ... } or { choices = [...] }", section="vary", key=name
            )

        def value(v: Any, field_: str, name: str = name, g: Given = g) -> sympy.Expr:
            try:
                item = _given(name, v, {}, ctx, oblique, system)
            except InputError as exc:
                raise ctx.error(exc.what, section="vary", key=f"{name}.{field_}", value=v, cls=type(exc)) from None
            if item.dim != g.dim or item.value is None:
                raise ctx.error(f"expected {describe(g.dim)}", section="vary", key=f"{name}.{field_}", value=v)
            return item.value

        if "choices" in spec:
            if not isinstance(spec["choices"], list) or not spec["choices"]:
                raise ctx.error("expected a list of values", section="vary", key=name)
            values = tuple(value(v, "choices") for v in spec["choices"])
        else:
            lo, hi, step = (value(spec[k], k) for k in ("min", "max", "step"))
            if not step > 0 or hi < lo:
                raise ctx.error("expected min <= max and a positive step", section="vary", key=name)
            count = int(sympy.floor((hi - lo) / step)) + 1
            if count > MAX_CHOICES:
                raise ctx.error(f"gives {count} values (at most {MAX_CHOICES})", section="vary", key=name)
            values = tuple(lo + k * step for k in range(count))
        out[name] = tuple(dict.fromkeys(sympy.nsimplify(v) if v.is_Float else v for v in values))
    return out


def _conditions(raw: Any, by_name: Mapping[str, Given], ctx: Source) -> tuple[Condition, ...]:
    """Conditions on givens and results, each "lhs < rhs" (< <= > >=), parsed safely."""
    if raw is None:
        return ()
    if not isinstance(raw, list) or not all(isinstance(c, str) for c in raw):
        raise ctx.error('expected a list of conditions such as ["v_B2n > 0"]', key="conditions")
    names = {g.name: (g.symbol, g.dim) for g in by_name.values()}
    names.update({n: (symbol(n), d) for n, d in RESULT_DIMS.items()})
    out = []
    for text in raw:
        m = _CONDITION.match(text)
        if not m:
            raise ctx.error("expected a comparison with <, <=, > or >=", key="conditions", value=text)
        try:
            lhs, rhs = parse(m.group(1).strip(), names), parse(m.group(3).strip(), names)
        except ParseError as exc:
            raise ctx.error(str(exc), key="conditions", value=text, cls=ExpressionError) from None
        if lhs.dim != rhs.dim and lhs.expr.free_symbols and rhs.expr.free_symbols:
            raise ctx.error(f"compares {describe(lhs.dim)} with {describe(rhs.dim)}", key="conditions", value=text)
        out.append(Condition(text, lhs.expr, m.group(2), rhs.expr))
    return tuple(out)


def _answer_units(raw: Any, ctx: Source) -> dict[str, str]:
    """Results to show also in a unit of the user's choice: {v_A2 = "km/h"}."""
    if raw is None:
        return {}
    if not isinstance(raw, dict):
        raise ctx.error('expected a table such as { v_A2 = "km/h" }', key="answer_units")
    out = {}
    for name, text in raw.items():
        if not isinstance(text, str):
            raise ctx.error("expected a unit as text", section="answer_units", key=name, value=text)
        try:
            unit = units.parse_unit(text)
        except ValueError as exc:
            raise ctx.error(str(exc), section="answer_units", key=name, value=text, cls=UnitError) from None
        if unit.dim in (DIMENSIONLESS,):
            raise ctx.error("expected a unit", section="answer_units", key=name, value=text, cls=UnitError)
        out[name] = unit.text
    return out


def _find(
    raw: Any, ctx: Source, oblique: bool, unknown: tuple[str, ...] = (), extra: tuple[str, ...] = ()
) -> tuple[str, ...]:
    """The results asked for: by default the unknowns, else the velocities; ``extra``
    names more that may be asked (quantities defined from the results, x-y components)."""
    default = unknown or ("v_A2", "v_B2")
    if raw is None:
        return default
    if isinstance(raw, str):
        raw = [raw]
    if not isinstance(raw, list) or not raw or not all(isinstance(x, str) for x in raw):
        raise ctx.error("expected a list of result names", key="find", value=raw)
    allowed = (RESULT_NAMES if oblique else ("v_A2", "v_B2", "T_1", "T_2", "T_lost")) + ("J_n", *unknown, *extra)
    for x in raw:
        if x not in allowed:
            raise ctx.error(f"unknown result {x!r} (expected some of: {', '.join(allowed)})", key="find", value=raw)
    return tuple(dict.fromkeys(raw))


def _check_approach(problem: Problem, ctx: Source) -> None:
    approach = problem.motion_A.n - problem.motion_B.n
    value = approach.xreplace(problem.numeric())
    if value.free_symbols:
        if value.is_positive is False or (value.is_zero is True):
            raise ctx.error(
                "the bodies do not approach along n: v_A1n - v_B1n must be positive", section="given", cls=PhysicsError
            )
        return
    if not value > 0:
        from derive.numbers import format_number

        shown = format_number(value, 4)
        raise ctx.error(
            f"the bodies do not approach: v_A1n - v_B1n = {shown}, but it must be positive "
            "(n points from A's centre toward B's, so A must close on B along n)",
            section="given",
            cls=PhysicsError,
        )
