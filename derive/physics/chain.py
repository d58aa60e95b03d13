"""Chains: impacts in sequence, and the motion before and after an impact.

A chain file (``kind = "chain"``) has givens and a list of ``[[stage]]`` tables.
Each stage takes its inputs from the givens and from the results of the stages
before it, and names its own results for those after it. The notes' rule is kept:
energy methods before and after an impact, never across one; each impact uses
momentum and restitution (equations (1)-(4)).

Stage types: ``fall`` (speed from a height, energy), ``rise`` (height from a
speed), ``slide`` (distance to rest with kinetic friction), ``spring`` (greatest
compression), ``impact`` (a central impact, as in a problem file), ``bounces``
(a ball bouncing on a floor n times), ``again`` (will two bodies collide again?),
``define`` (a quantity from others) and ``solve`` (an unknown from a condition).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from typing import Any

import sympy

from derive.errors import ExpressionError, InputError, SolveError
from derive.problem import units
from derive.problem.expr import ParseError, parse
from derive.problem.reader import Given, _build, _Ctx, _givens, _infer_system, _text, _type
from derive.steps.model import Block, Eqn, Math, Result, Side, Solution, Text
from derive.symbols import symbol

STAGE_TYPES = ("fall", "rise", "slide", "spring", "impact", "bounces", "again", "define", "solve")
TOP = ("title", "kind", "source", "statement", "question", "digits", "units", "given", "stage", "find")
HALF = sympy.Rational(1, 2)


@dataclass(frozen=True)
class ChainStage:
    """One stage: its title, what it takes and gives, and its worked lines."""

    number: int
    type: str
    title: str
    blocks: tuple[Block, ...] = ()
    solution: Solution | None = None
    outputs: tuple[str, ...] = ()
    exports: tuple[tuple[str, str], ...] = ()  # (name for later stages, the impact's result)


@dataclass(frozen=True)
class ChainProblem:
    """A chain file, checked: its givens and its stage tables (solved by :func:`solve_chain`)."""

    path: str
    title: str
    givens: tuple[Given, ...]
    stages: tuple[dict[str, Any], ...]
    system: str
    digits: int | None = None
    source: str | None = None
    statement: str | None = None
    question: str | None = None
    find: tuple[str, ...] = ()
    name: str = ""
    ctx: Any = field(default=None, compare=False, repr=False)
    kind: str = "chain"

    def symbols(self) -> dict[str, sympy.Symbol]:
        return {g.name: g.symbol for g in self.givens}


@dataclass(frozen=True)
class ChainSolution:
    """A solved chain: each stage worked, and every named quantity's value."""

    problem: ChainProblem
    stages: tuple[ChainStage, ...]
    results: dict[str, Result]
    values: dict[sympy.Symbol, sympy.Expr]
    angles: frozenset[sympy.Symbol] = frozenset()

    def _repr_markdown_(self) -> str:
        from derive.writers.view import render

        return render(self, "md")  # type: ignore[arg-type]


def build_chain(data: dict[str, Any], ctx: _Ctx, name: str) -> ChainProblem:
    """Check a chain file's fields (the stages are checked as they are solved)."""
    for key in data:
        if key not in TOP:
            raise ctx.error(f"unknown field (expected one of: {', '.join(TOP)})", key=key)
    title = _text(data, "title", ctx, required=True)
    digits = data.get("digits")
    if digits is not None and (isinstance(digits, bool) or not isinstance(digits, int) or not 1 <= digits <= 10):
        raise ctx.error("expected a whole number of significant figures from 1 to 10", key="digits", value=digits)
    given_tbl = data.get("given", {})
    if not isinstance(given_tbl, dict):
        raise ctx.error(f"expected a table, not {_type(given_tbl)}", key="given")
    system = data.get("units") or _infer_system(given_tbl)
    if system not in units.SYSTEMS:
        raise ctx.error('expected "SI" or "US"', key="units", value=system)
    givens = _givens(given_tbl, ctx, True, system)
    stages = data.get("stage")
    if not isinstance(stages, list) or not stages or not all(isinstance(s, dict) for s in stages):
        raise ctx.error("is missing: a chain needs [[stage]] tables", key="stage")
    if len(stages) > 30:
        raise ctx.error("has too many stages (at most 30)", key="stage")
    for i, st in enumerate(stages, 1):
        if st.get("type") not in STAGE_TYPES:
            raise ctx.error(
                f"stage {i}: expected type one of {', '.join(STAGE_TYPES)}",
                section="stage",
                key="type",
                value=st.get("type"),
            )
    find = data.get("find", [])
    if not isinstance(find, list) or not all(isinstance(f, str) for f in find):
        raise ctx.error("expected a list of names", key="find", value=find)
    return ChainProblem(
        path=ctx.path,
        title=title or "",
        givens=tuple(givens),
        stages=tuple(stages),
        system=system,
        digits=digits,
        source=_text(data, "source", ctx),
        statement=_text(data, "statement", ctx),
        question=_text(data, "question", ctx),
        find=tuple(find),
        name=name,
        ctx=ctx,
    )


class _Solver:
    """Works a chain stage by stage, keeping every named quantity as a Given."""

    def __init__(self, chain: ChainProblem) -> None:
        self.chain = chain
        self.ctx = chain.ctx
        self.known: dict[str, Given] = {g.name: g for g in chain.givens}
        self.unknowns = [g.symbol for g in chain.givens if g.unknown]
        self.solved: dict[sympy.Symbol, sympy.Expr] = {}
        self.tag = 0
        self.stages: list[ChainStage] = []
        self.approaches: list[sympy.Expr] = []  # each impact's v_A1n - v_B1n, in the chain's names

    # helpers ---------------------------------------------------------------
    def err(
        self, i: int, key: str | None, what: str, value: Any = None, cls: type[InputError] = InputError
    ) -> InputError:
        return self.ctx.error(f"stage {i}: {what}", section="stage", key=key, value=value, cls=cls)

    def quantity(self, i: int, st: dict, key: str, dim: units.Dim | None, default: Any = None) -> sympy.Expr:
        """A stage field: a name or an expression of known quantities, as an exact expression."""
        raw = st.get(key, default)
        if raw is None:
            raise self.err(i, key, "is missing")
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            raw = repr(raw)
        if not isinstance(raw, str):
            raise self.err(i, key, "expected a name or an expression", raw)
        names = {n: (g.symbol, g.dim) for n, g in self.known.items()}
        try:
            parsed = parse(raw, names)
        except ParseError as exc:
            raise self.err(i, key, str(exc), raw, ExpressionError) from None
        if dim is not None and parsed.dim != dim and not (parsed.expr == 0):
            raise self.err(i, key, f"expected {units.describe(dim)}, not {units.describe(parsed.dim)}", raw)
        return parsed.expr

    def value(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` in the givens' numbers (symbols without numbers, unknowns, stay)."""
        vals = {g.symbol: g.value for g in self.known.values() if g.value is not None}
        defs = {g.symbol: g.definition for g in self.known.values() if g.value is None and g.definition is not None}
        return _resolve(expr, defs).xreplace(vals).xreplace(self.solved)

    def in_givens(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` with every earlier result replaced by its definition, down to the givens."""
        given = {g.name for g in self.chain.givens}
        return _resolve(
            expr, {g.symbol: g.definition for n, g in self.known.items() if g.definition is not None and n not in given}
        )

    def define(self, i: int, name: str, expr: sympy.Expr, dim: units.Dim, unit: str | None = None) -> Given:
        if not isinstance(name, str) or not name.isidentifier() or name in self.known:
            raise self.err(i, "result", f"{name!r} is not a new name (letters, digits and _)", name)
        val = self.value(expr)
        value = None if val.free_symbols else val
        if unit is None:
            unit = units.working_unit(dim, self.chain.system).text if dim in units.SYSTEMS[self.chain.system] else ""
        g = Given(name, symbol(name), dim, value, unit, definition=expr)
        self.known[name] = g
        return g

    def next_tag(self) -> str:
        self.tag += 1
        return str(self.tag)

    def g_symbol(self) -> sympy.Symbol:
        g = self.known.get("g")
        if g is None:
            number, unit_text = {"SI": ("9.81", "m/s^2"), "US": ("32.2", "ft/s^2")}[self.chain.system]
            g = Given("g", symbol("g", "positive"), units.ACCELERATION, sympy.Rational(number), unit_text)
            self.known["g"] = g
        return g.symbol

    # stages ----------------------------------------------------------------
    def run(self) -> ChainSolution:
        for i, st in enumerate(self.chain.stages, 1):
            method = getattr(self, "stage_" + st["type"])
            self.stages.append(method(i, st))
        results = {}
        outputs = {n for st in self.stages for n in st.outputs}
        roots = dict(self.solved)
        for name, g in self.known.items():
            if g.definition is None and not g.unknown and name not in outputs:
                continue
            closed = g.definition if g.definition is not None else roots.get(g.symbol, g.symbol)
            closed = self.in_givens(closed).xreplace(roots)  # in the chain's givens; unknowns by their solutions
            val = self.value(g.symbol if g.unknown else closed)
            number = None if val.free_symbols else val
            if g.unit == "deg" and number is not None:
                number = number * 180 / sympy.pi
            results[name] = Result(name, g.symbol, closed, number, val, g.unit, g.name)
        values = {g.symbol: g.value for g in self.known.values() if g.value is not None}
        values.update(self.solved)
        angles = frozenset(g.symbol for g in self.known.values() if g.unit == "deg")
        return ChainSolution(self.chain, tuple(self.stages), results, values, angles)

    def energy_lines(
        self, form: tuple, solved: sympy.Expr, result: Given, cancel: frozenset = frozenset()
    ) -> tuple[Eqn, ...]:
        """Energy conservation written out: the balance, then the result with numbers."""
        lines = [Eqn((Side(form[0]), Side(form[1])), cancel=cancel)]
        lines.append(
            Eqn(
                (Side((result.symbol,)), Side((solved,)), Side((solved,), "values"), Side((solved,), "result")),
                unit=result.unit,
                implies=True,
                tag=self.next_tag(),
            )
        )
        return tuple(lines)

    def stage_fall(self, i: int, st: dict) -> ChainStage:
        h = self.quantity(i, st, "height", units.LENGTH)
        v0 = self.quantity(i, st, "speed", units.VELOCITY, default="0")
        g = self.g_symbol()
        m = symbol("m", "positive")
        speed = sympy.sqrt(v0**2 + 2 * g * h)
        out = self.define(i, st.get("result", f"v_{i}"), speed, units.VELOCITY)
        form = ((HALF * m * v0**2, m * g * h) if v0 != 0 else (m * g * h,), (HALF * m * out.symbol**2,))
        text: Text = (
            "Before the impact no impulsive force acts: mechanical energy is conserved (datum at the lowest point), ",
            Math(sympy.Eq(symbol("T_1") + symbol("V_1"), symbol("T_2") + symbol("V_2"))),
            ". The mass cancels.",
        )
        lines = self.energy_lines(form, speed, out, frozenset({m}))
        body = st.get("body", "the body")
        return ChainStage(
            i, "fall", f"{str(body).capitalize()} falls through the height", (Block(text, lines),), outputs=(out.name,)
        )

    def stage_rise(self, i: int, st: dict) -> ChainStage:
        v = self.quantity(i, st, "speed", units.VELOCITY)
        g = self.g_symbol()
        m = symbol("m", "positive")
        height = v**2 / (2 * g)
        out = self.define(i, st.get("result", f"h_{i}"), height, units.LENGTH)
        form = ((HALF * m * v**2,), (m * g * out.symbol,))
        text: Text = ("After the impact, mechanical energy is conserved again up to the highest point: ",)
        lines = self.energy_lines(form, height, out, frozenset({m}))
        return ChainStage(i, "rise", "Rise after the impact", (Block(text, lines),), outputs=(out.name,))

    def stage_slide(self, i: int, st: dict) -> ChainStage:
        v = self.quantity(i, st, "speed", units.VELOCITY)
        mu = self.quantity(i, st, "mu", units.DIMENSIONLESS)
        g = self.g_symbol()
        m = symbol("m", "positive")
        d = v**2 / (2 * mu * g)
        out = self.define(i, st.get("result", f"d_{i}"), d, units.LENGTH)
        form = ((HALF * m * v**2, -mu * m * g * out.symbol), (sympy.Integer(0),))
        text: Text = (
            "After the impact, work and energy: kinetic friction ",
            Math(sympy.Eq(symbol("F"), mu * m * g)),
            " does the work that stops the body.",
        )
        lines = self.energy_lines(form, d, out, frozenset({m}))
        return ChainStage(i, "slide", "Sliding to rest after the impact", (Block(text, lines),), outputs=(out.name,))

    def stage_spring(self, i: int, st: dict) -> ChainStage:
        v = self.quantity(i, st, "speed", units.VELOCITY)
        mass = self.quantity(i, st, "mass", units.MASS)
        k = self.quantity(i, st, "k", units.STIFFNESS)
        vertical = bool(st.get("vertical", False))
        x0 = self.quantity(i, st, "static", units.LENGTH, default="0") if vertical else sympy.Integer(0)
        x = sympy.Symbol("x", positive=True)
        name = st.get("result", f"x_{i}")
        if vertical:
            g = self.g_symbol()
            balance = sympy.Eq(HALF * mass * v**2 + mass * g * x, HALF * k * (x0 + x) ** 2 - HALF * k * x0**2)
        else:
            balance = sympy.Eq(HALF * mass * v**2, HALF * k * x**2)
        roots = [r for r in sympy.solve(balance, x) if self._positive(r)]
        if len(roots) != 1:
            raise SolveError(f"stage {i}: the spring's compression has no single positive root", where=self.chain.path)
        out = self.define(i, name, roots[0], units.LENGTH)
        X = out.symbol
        if vertical:
            form = (
                (HALF * mass * v**2, mass * symbol("g", "positive") * X),
                (HALF * k * (x0 + X) ** 2, -HALF * k * x0**2),
            )
            text: Text = (
                "After the impact, energy is conserved while the spring compresses by a further ",
                Math(X),
                " below the equilibrium position (gravity does work too):",
            )
        else:
            form = ((HALF * mass * v**2,), (HALF * k * X**2,))
            text = (
                "After the impact, energy is conserved while the spring compresses: kinetic energy becomes spring energy.",
            )
        lines = [Eqn((Side(form[0]), Side(form[1])))]
        lines.append(Eqn((Side((X,)), Side((roots[0],), "result")), unit=out.unit, implies=True, tag=self.next_tag()))
        return ChainStage(i, "spring", "The spring after the impact", (Block(text, tuple(lines)),), outputs=(out.name,))

    def _positive(self, r: sympy.Expr) -> bool:
        v = self.value(r)
        if v.free_symbols:
            return bool(v.is_positive)
        c = complex(sympy.N(v))
        return abs(c.imag) < 1e-12 and c.real > 0

    def stage_impact(self, i: int, st: dict) -> ChainStage:
        table = {k: v for k, v in st.items() if k not in ("type", "results", "title")}
        data = {"title": st.get("title", "An impact"), **table}
        data.setdefault("given", {})
        # a chain's unknowns are symbols inside the stage: a later stage finds them
        seed = {n: (replace(g, unknown=False) if g.unknown else g) for n, g in self.known.items()}
        try:
            problem = _build(data, self.ctx, f"stage-{i}", seed=seed)
        except InputError as exc:
            raise InputError(f"stage {i}: {exc.what}", where=exc.where, field=exc.field) from None
        from derive.steps.impact import solve

        solution = _renumber(solve(problem), self.tag)
        self.tag = max((int(t) for t in _tags(solution)), default=self.tag)
        results = st.get("results", {})
        if not isinstance(results, dict):
            raise self.err(i, "results", 'expected a table such as { v_A2 = "u_A" }', results)
        from derive.physics.impact import independent_map

        # into the chain's names: a stage given defined from them by its definition,
        # one written in the stage as a number by that number
        own = {
            g.symbol: (g.definition if g.definition is not None else g.value)
            for g in problem.givens
            if seed.get(g.name) is not g and (g.definition is not None or g.value is not None)
        }
        ind = independent_map(problem)
        self.approaches.append((problem.motion_A.n - problem.motion_B.n).xreplace(ind).xreplace(own))
        outputs = []
        exports: list[tuple[str, str]] = []
        for rname, new in results.items():
            r = solution.results.get(rname)
            if r is None or not isinstance(new, str):
                raise self.err(i, "results", f"{rname!r} is not a result of this impact", rname)
            dim = _dim_of(rname, r.unit)
            expr = r.closed.xreplace(ind).xreplace(own)
            if rname.startswith(("theta", "beta")):
                expr = r.partial * sympy.pi / 180 if r.value is None else r.value * sympy.pi / 180
            g = self.define(i, new, expr, dim, "deg" if dim == units.ANGLE else None)
            outputs.append(g.name)
            exports.append((g.name, rname))
        for g in problem.givens:  # unknowns found by this impact become known to later stages
            if g.unknown and g.name not in self.known:
                r = solution.results[g.name]
                self.define(i, g.name, r.closed.xreplace(ind).xreplace(own), g.dim, g.unit)
                outputs.append(g.name)
        return ChainStage(i, "impact", data["title"], solution=solution, outputs=tuple(outputs), exports=tuple(exports))

    def stage_define(self, i: int, st: dict) -> ChainStage:
        raw = st.get("expr")
        expr = self.quantity(i, st, "expr", None)
        names = {n: (g.symbol, g.dim) for n, g in self.known.items()}
        dim = parse(str(raw), names).dim
        out = self.define(i, st.get("result", f"q_{i}"), expr, dim)
        line = Eqn(
            (Side((out.symbol,)), Side((expr,)), Side((expr,), "values"), Side((self.value(expr),), "result")),
            unit=out.unit or None,
            tag=self.next_tag(),
        )
        text: Text = (str(st.get("text", "Then:")),)
        return ChainStage(i, "define", st.get("title", "Then"), (Block(text, (line,)),), outputs=(out.name,))

    def stage_solve(self, i: int, st: dict) -> ChainStage:
        raw = st.get("condition")
        if not isinstance(raw, str) or raw.count("=") != 1:
            raise self.err(i, "condition", 'expected one equation such as "h_2 = 40 m"', raw)
        left, right = raw.split("=")
        names = {n: (g.symbol, g.dim) for n, g in self.known.items()}
        try:
            lhs = parse(left.strip(), names)
            rhs_text = right.strip()
            m = re.match(r"^\s*([-+]?[\d.]+(?:[eE][-+]?\d+)?)\s*([A-Za-z].*)$", rhs_text)
            if m:  # a number with a unit
                u = units.parse_unit(m.group(2))
                rhs_expr = sympy.Rational(m.group(1)) * u.factor / units.working_unit(u.dim, self.chain.system).factor
            else:
                rhs_expr = parse(rhs_text, names).expr
        except (ParseError, ValueError) as exc:
            raise self.err(i, "condition", str(exc), raw, ExpressionError) from None
        target = st.get("for")
        unknown = [u for u in self.unknowns if u not in self.solved and (target is None or u.name == target)]
        if len(unknown) != 1:
            raise self.err(i, "for", 'expected exactly one unknown (a given marked "?") to solve for', target)
        u = unknown[0]
        equation = self.value(lhs.expr) - rhs_expr
        roots = [r for r in sympy.solve(equation, u) if self._admissible(u, r)]
        if len(roots) != 1:
            raise SolveError(
                f"stage {i}: {raw} gives {len(roots)} admissible values of {u.name}", where=self.chain.path
            )
        self.solved[u] = roots[0]
        g = self.known[u.name]
        lines = (
            Eqn((Side((lhs.expr,)), Side((rhs_expr,), "result")), unit=g.unit if lhs.dim == g.dim else None),
            Eqn((Side((u,)), Side((roots[0],), "result")), unit=g.unit or None, implies=True, tag=self.next_tag()),
        )
        text: Text = ("The condition ", Math(sympy.Eq(lhs.expr, rhs_expr)), " fixes the unknown ", Math(u), ":")
        return ChainStage(i, "solve", f"Solve for {u.name}", (Block(text, lines),), outputs=(u.name,))

    def _admissible(self, u: sympy.Symbol, r: sympy.Expr) -> bool:
        """A root is admissible when real, e in [0, 1], a speed not negative, and every
        impact of the chain still has its bodies approaching."""
        for approach in self.approaches:
            a = self.value(approach).xreplace({u: r})
            if not a.free_symbols and not complex(sympy.N(a)).real > 0:
                return False
        v = self.value(r)
        if v.free_symbols:
            return True
        c = complex(sympy.N(v))
        if abs(c.imag) > 1e-12:
            return False
        if u.name.startswith("e") and not (-1e-12 <= c.real <= 1 + 1e-12):
            return False
        return not ((u.is_positive or u.is_nonnegative) and c.real < 0)

    def stage_bounces(self, i: int, st: dict) -> ChainStage:
        h0 = self.quantity(i, st, "height", units.LENGTH)
        e = self.quantity(i, st, "e", units.DIMENSIONLESS)
        n = st.get("count", 3)
        if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= 50:
            raise self.err(i, "count", "expected a whole number of bounces from 1 to 50", n)
        g = self.g_symbol()
        v0 = sympy.sqrt(2 * g * h0)
        lines = [
            Eqn(
                (Side((symbol("v_0"),)), Side((sympy.sqrt(2 * g * h0),)), Side((v0,), "result")),
                unit=units.working_unit(units.VELOCITY, self.chain.system).text,
                tag=self.next_tag(),
            )
        ]
        outputs = []
        for k in range(1, n + 1):
            vk = self.define(i, f"v_b{k}", e**k * v0, units.VELOCITY)
            hk = self.define(i, f"h_b{k}", e ** (2 * k) * h0, units.LENGTH)
            lines.append(
                Eqn((Side((vk.symbol,)), Side((e**k * symbol("v_0"),)), Side((vk.definition,), "result")), unit=vk.unit)
            )
            lines.append(
                Eqn(
                    (Side((hk.symbol,)), Side((hk.definition,), "values"), Side((hk.definition,), "result")),
                    unit=hk.unit,
                )
            )
            outputs += [vk.name, hk.name]
        total = self.define(i, "s_total", h0 * (1 + e**2) / (1 - e**2), units.LENGTH)
        lines.append(
            Eqn(
                (
                    Side((total.symbol,)),
                    Side((total.definition,)),
                    Side((total.definition,), "values"),
                    Side((total.definition,), "result"),
                ),
                unit=total.unit,
                tag=self.next_tag(),
            )
        )
        text: Text = (
            "Each bounce is an impact with the floor (a fixed body): the rebound speed is e times the impact speed, "
            "and between bounces energy is conserved, so the height after bounce k is ",
            Math(sympy.Eq(symbol("h_k"), e ** (2 * symbol("k")) * symbol("h_0"))),
            ". The distance travelled before the ball comes to rest is the sum of a geometric series.",
        )
        return ChainStage(
            i, "bounces", f"{n} bounces on the floor", (Block(text, tuple(lines)),), outputs=(*outputs, total.name)
        )

    def stage_again(self, i: int, st: dict) -> ChainStage:
        """Will A (behind, at smaller n) and B collide again? Yes when A moves faster along +n."""
        va = self.quantity(i, st, "behind", units.VELOCITY)
        vb = self.quantity(i, st, "ahead", units.VELOCITY)
        a, b = self.value(va), self.value(vb)
        diff = a - b
        text: Text = (
            "They collide again if the one behind moves faster along +n than the one ahead: ",
            Math(sympy.StrictGreaterThan(va, vb)),
            ".",
        )
        lines = [
            Eqn(
                (Side((va, -vb)), Side((diff,), "result")),
                unit=units.working_unit(units.VELOCITY, self.chain.system).text,
            )
        ]
        blocks = [Block(text, tuple(lines))]
        outputs = []
        if not diff.free_symbols:
            verdict = bool(diff > 0)
            flag = sympy.Integer(int(verdict))
            g = Given(
                st.get("result", "again"),
                symbol(st.get("result", "again")),
                units.DIMENSIONLESS,
                flag,
                "",
                definition=flag,
            )
            self.known[g.name] = g
            outputs.append(g.name)
            blocks.append(Block(("Yes: they collide again." if verdict else "No: they do not collide again.",)))
        param = st.get("range_of")
        if param is not None:
            p = self.known.get(param)
            if p is None or p.dim != units.DIMENSIONLESS:
                raise self.err(i, "range_of", "expected the name of a known coefficient such as e", param)
            defs = {g.symbol: g.definition for g in self.known.values() if g.definition is not None and g.name != param}
            general = _resolve(va - vb, defs)
            keep = {g.symbol: g.value for n, g in self.known.items() if g.value is not None and n != param}
            general = sympy.simplify(general.xreplace(keep).xreplace(self.solved))
            rng = sympy.solve_univariate_inequality(general > 0, p.symbol, relational=False).intersect(
                sympy.Interval(0, 1)
            )
            from derive.writers.printing import floatify

            blocks.append(
                Block(
                    (
                        "For other values of ",
                        Math(p.symbol),
                        ": they collide again when ",
                        Math(sympy.StrictGreaterThan(floatify(general, keep_integers=False), 0)),
                        ", that is for ",
                        Math(_float_interval(rng)),
                        ".",
                    )
                )
            )
        return ChainStage(
            i, "again", st.get("title", "Will they collide again?"), tuple(blocks), outputs=tuple(outputs)
        )


def _resolve(expr: sympy.Expr, defs: dict[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
    """``expr`` with ``defs`` put in until none is left (definitions refer to earlier ones)."""
    for _ in range(len(defs) + 1):
        new = expr.xreplace(defs)
        if new == expr:
            break
        expr = new
    return expr


def _dim_of(name: str, unit: str) -> units.Dim:
    if name.startswith(("theta", "beta")):
        return units.ANGLE
    if name.startswith("T_"):
        return units.ENERGY
    if name == "J_n":
        return units.IMPULSE
    if name in ("e",):
        return units.DIMENSIONLESS
    if name.startswith("m_"):
        return units.MASS
    return units.VELOCITY


def _tags(solution: Solution) -> list[str]:
    return [ln.tag for st in solution.stages for b in st.blocks for ln in b.lines if ln.tag]


def _renumber(solution: Solution, offset: int) -> Solution:
    """An impact's equation numbers continued from the chain's: (1)-(4) become (5)-(8)."""
    if offset == 0:
        return solution
    import re
    from dataclasses import replace as dc_replace

    def tag(t: str | None) -> str | None:
        return None if t is None else str(int(t) + offset)

    ref = re.compile(r"\b(From|Add|Subtract|into|and|Solve) \((\d+)\)")

    def text(parts: Text | None) -> Text | None:
        # only references to the stage's own equations move ("From (4):"); the notes'
        # equation numbers in sentences ("(3) does not apply") are the notes' own
        if parts is None:
            return None
        out = []
        for p in parts:
            if isinstance(p, str) and not re.search(r"notes|equation \(", p):
                p = ref.sub(lambda m: f"{m.group(1)} ({int(m.group(2)) + offset})", p)
                p = re.sub(r"\((\d+)\)(?= (and|together))", lambda m: f"({int(m.group(1)) + offset})", p)
            out.append(p)
        return tuple(out)

    stages = tuple(
        dc_replace(
            st,
            blocks=tuple(
                dc_replace(b, text=text(b.text), lines=tuple(dc_replace(ln, tag=tag(ln.tag)) for ln in b.lines))
                for b in st.blocks
            ),
        )
        for st in solution.stages
    )
    return dc_replace(solution, stages=stages)


def solve_chain(chain: ChainProblem) -> ChainSolution:
    """Work the chain stage by stage."""
    return _Solver(chain).run()


def _float_interval(rng: sympy.Set) -> sympy.Set:
    """An interval with its ends as decimals, for printing."""
    if isinstance(rng, sympy.Interval):
        return sympy.Interval(sympy.Float(rng.start, 4), sympy.Float(rng.end, 4), rng.left_open, rng.right_open)
    return rng
