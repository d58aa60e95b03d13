"""Facts of a chain: each stage worked again from the chain file's own tables.

Each stage's inputs are read from its table (``given = { m_A = "m_B" }``, ``speed
= "v_1"``) in the names the chain knows at that stage, never from the stage as
derive built it, so that a name captured by the wrong body shows. The motion
between impacts is energy (fall, rise, slide, spring); an impact is
:mod:`derive.verifier.facts.problem` with the stage's givens put in. An unknown of
the chain ("?") stays a letter (a sample value) until the ``solve`` stage that
finds it: a line before that must hold for every value of it.
"""

from __future__ import annotations

import contextlib
import re
from dataclasses import dataclass, field
from typing import Any

import sympy

from derive.verifier import units
from derive.verifier.facts import source
from derive.verifier.facts.expression import Unread, evaluate
from derive.verifier.facts.model import Facts, Quantity, Scope, Table, number
from derive.verifier.facts.problem import dim_of, file_value, impact, misread

_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*([A-Za-z°][A-Za-z°/*^·\d\s]*)$")
HALF = sympy.Rational(1, 2)
SEED_NAMES = ("m_A", "m_B", "e", "v_A1", "v_B1", "v_A1n", "v_A1t", "v_B1n", "v_B1t", "W_A", "W_B", "g")
GRAVITY = {"SI": "9.81", "US": "32.2"}


@dataclass
class _Stage:
    """One stage worked: its own table (an impact's names) and the chain names it adds."""

    number: int
    kind: str
    own: Table | None = None
    extra: dict[str, tuple[sympy.Expr, units.Dim]] = field(default_factory=dict)


class _Chain:
    """The chain worked once, at one point: ``fixed`` holds the unknowns found by then."""

    def __init__(self, solution: Any, fixed: dict[str, sympy.Expr], read: source.Read | None = None) -> None:
        self.sol = solution
        self.chain = solution.problem
        self.read = read
        self.raw_stages = list(read.data.get("stage") or []) if read is not None else list(self.chain.stages)
        if len(self.raw_stages) != len(self.chain.stages):
            self.raw_stages = list(self.chain.stages)
        self.system = read.system if read is not None else self.chain.system
        self.table = Table(fixed=dict(fixed))
        self.defined_at: dict[str, int] = {}
        self.stages: list[_Stage] = []
        self.notes: list[str] = []

    # reading a stage's fields -------------------------------------------
    def quantity(self, raw: object, default: object = None) -> tuple[sympy.Expr, units.Dim]:
        """A stage field (a number, "8 m/s", a name or an expression) in the chain's names."""
        raw = default if raw is None else raw
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            return sympy.Rational(repr(raw)), units.NONE
        text = str(raw)
        m = _QUANTITY.match(text)
        if m:
            factor, dim, degrees = units.to_working(m.group(2), self.system)
            value = sympy.Rational(m.group(1)) * sympy.Rational(factor.numerator, factor.denominator)
            return (value * sympy.pi / 180, units.ANGLE) if degrees else (value, dim)
        names = {n: (sympy.Symbol(n), self.table.dims.get(n, units.NONE)) for n in self.table.exprs}
        value, dim = evaluate(text, names)
        return self.table.resolve(value), dim

    def define(self, i: int, name: str, expr: sympy.Expr, dim: units.Dim, role: str = "result") -> None:
        self.table.put(name, expr, dim, role)
        self.defined_at.setdefault(name, i)

    # the stages -----------------------------------------------------------
    def run(self) -> _Chain:
        self.chain_givens()
        for i, (raw, st) in enumerate(zip(self.raw_stages, self.sol.stages, strict=True), 1):
            kind = raw["type"]
            stage = _Stage(i, kind)
            getattr(self, "stage_" + kind)(i, raw, st, stage)
            self.stages.append(stage)
        return self

    def chain_givens(self) -> None:
        read = self.read
        for g in sorted(self.chain.givens, key=lambda g: g.unknown):  # the unknowns' roots need the rest
            dim = dim_of(g)
            mine = file_value(self.table, read, g.name)
            if g.unknown:
                self.table.param(g.name, dim, role="unknown")
            elif mine is not None:
                self.table.put(g.name, mine, dim, "given")
                self.table.note_exact(mine, dim == units.ANGLE)
            elif g.value is not None:
                self.table.put(g.name, g.value, dim, "given")
                self.table.note_exact(g.value, g.unit == "deg")
            elif g.definition is not None:
                self.table.put(g.name, self.table.resolve(g.definition), dim, "given")
            else:
                self.table.param(g.name, dim)
            if g.written and read is None:
                self.table.note_exact(sympy.Rational(g.written.split()[0]))
            self.defined_at[g.name] = 0
        if read is not None:
            for typed in read.typed:
                self.table.note_exact(typed)
            self.notes += misread(self.table, self.chain, read)
        if "g" not in self.table.exprs:
            self.define(0, "g", sympy.Rational(GRAVITY.get(self.system, "9.81")), units.ACCELERATION, "given")

    def stage_fall(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        h, _ = self.quantity(raw.get("height"))
        v0, _ = self.quantity(raw.get("speed"), "0")
        self.define(i, raw.get("result", f"v_{i}"), sympy.sqrt(v0**2 + 2 * self.table.exprs["g"] * h), units.VELOCITY)

    def stage_rise(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        v, _ = self.quantity(raw.get("speed"))
        self.define(i, raw.get("result", f"h_{i}"), v**2 / (2 * self.table.exprs["g"]), units.LENGTH)

    def stage_slide(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        v, _ = self.quantity(raw.get("speed"))
        mu, _ = self.quantity(raw.get("mu"))
        self.define(i, raw.get("result", f"d_{i}"), v**2 / (2 * mu * self.table.exprs["g"]), units.LENGTH)

    def stage_spring(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        """Greatest compression: 1/2 M v^2 = 1/2 k x^2, or, hanging on a spring already
        compressed by x0, 1/2 M v^2 + M g x = 1/2 k (x0 + x)^2 - 1/2 k x0^2 (positive root)."""
        v, _ = self.quantity(raw.get("speed"))
        mass, _ = self.quantity(raw.get("mass"))
        k, _ = self.quantity(raw.get("k"))
        if raw.get("vertical"):
            x0, _ = self.quantity(raw.get("static"), "0")
            b = k * x0 - mass * self.table.exprs["g"]
            x = (-b + sympy.sqrt(b**2 + k * mass * v**2)) / k
        else:
            x = v * sympy.sqrt(mass / k)
        self.define(i, raw.get("result", f"x_{i}"), x, units.LENGTH)

    def stage_impact(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        problem = st.part.problem
        table = Table(fixed=self.table.fixed)
        raw_given = raw.get("given", {}) or {}
        values = {}
        for g in problem.givens:
            if g.name in raw_given and not str(raw_given[g.name]).strip().startswith("?"):
                values[g.name] = self.quantity(raw_given[g.name])[0]
            elif g.name in SEED_NAMES and g.name in self.table.exprs:
                values[g.name] = self.table.exprs[g.name]
        read = self.stage_read(raw, values) if self.read is not None else None
        self.notes += impact(table, st.part, values, label=f"stage {i}: ", read=read)
        stage.own = table
        for rname, new in (raw.get("results") or {}).items():
            if rname in table.exprs:
                self.define(i, new, table.exprs[rname], table.dims.get(rname, units.NONE))
        for g in problem.givens:
            if g.unknown and g.name not in self.table.exprs:
                self.define(i, g.name, table.exprs[g.name], dim_of(g))
        _own_names(table, raw, self.table)
        table.relabel(stage_letters(raw))  # the page's letters for the stage's bodies, as the file names them

    def stage_read(self, raw: dict, values: dict[str, sympy.Expr]) -> source.Read:
        """An impact stage's givens and velocities as the chain file gives them."""
        read = source.Read(system=self.system, data=raw)
        given = raw.get("given") or {}
        for name, value in values.items():
            read.values[name] = value
            read.dims[name] = self.table.dims.get(name, source.RESERVED.get(name, units.NONE))
            if name in given:  # its unit as the stage writes it ("36.87 deg": an angle)
                with contextlib.suppress(Unread, units.UnknownUnit, ValueError, TypeError):
                    read.dims[name] = self.quantity(given[name])[1]
        for name, text in (raw.get("given") or {}).items():
            if name not in read.values and not str(text).strip().startswith("?"):
                try:
                    read.values[name], read.dims[name] = self.quantity(text)
                except (Unread, units.UnknownUnit):
                    read.unread.append(name)
        source.read_impact(read, raw)
        return read

    def stage_bounces(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        h0, _ = self.quantity(raw.get("height"))
        e, _ = self.quantity(raw.get("e"))
        v0 = sympy.sqrt(2 * self.table.exprs["g"] * h0)
        stage.extra["v_0"] = (v0, units.VELOCITY)
        for k in range(1, int(raw.get("count", 3)) + 1):
            self.define(i, f"v_b{k}", e**k * v0, units.VELOCITY)
            self.define(i, f"h_b{k}", e ** (2 * k) * h0, units.LENGTH)
        self.define(i, "s_total", h0 * (1 + e**2) / (1 - e**2), units.LENGTH)

    def stage_again(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        behind, _ = self.quantity(raw.get("behind"))
        ahead, _ = self.quantity(raw.get("ahead"))
        gap = number(behind - ahead, {})
        if gap is not None:
            self.define(i, raw.get("result", "again"), sympy.Integer(int(gap > 0)), units.NONE)

    def stage_define(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        expr, dim = self.quantity(raw.get("expr"))
        self.define(i, raw.get("result", f"q_{i}"), expr, dim)

    def stage_solve(self, i: int, raw: dict, st: Any, stage: _Stage) -> None:
        """The unknown's value is derive's root: put back into the condition, it must hold."""
        name = _target(self.chain, i)
        if name is None or name not in self.table.fixed:
            return
        left, _, right = str(raw.get("condition", "")).partition("=")
        lhs, _ = self.quantity(left.strip())
        rhs, _ = self.quantity(right.strip())
        gap, size = number(lhs - rhs, {}), number(rhs, {})
        if gap is not None and abs(gap) > 1e-15 * max(1, abs(size or 1)):
            self.notes.append(f"stage {i}: derive's {name} does not meet the condition {raw.get('condition')}")

    # scopes ---------------------------------------------------------------
    def chain_scope(self, key: str, stage: int, **kw: object) -> Scope:
        """The chain's own names, as far as stage ``stage`` has defined them."""
        names = [n for n, at in self.defined_at.items() if at <= stage]
        return self.table.scope(key, names, system=self.system, **kw)

    def stage_scopes(self, i: int) -> dict[str, Scope]:
        """Stage ``i``: an impact's own names (the chain's as parent), or the chain's names."""
        stage = self.stages[i - 1]
        if stage.own is not None:
            stage.own.exact |= self.table.exact
            own = stage.own.scope(f"stage {i}", system=self.system, parent=f"chain {i}", answers=False)
            return {f"chain {i}": self.chain_scope(f"chain {i}", i), f"stage {i}": own}
        scope = self.chain_scope(f"stage {i}", i, answers=False)
        quantities = dict(scope.quantities)
        for n, (expr, dim) in stage.extra.items():
            quantities[n] = Quantity(n, number(expr, {}), dim, "result")
        return {f"stage {i}": Scope(scope.key, quantities, {}, self.system, None, scope.exact, answers=False)}


def _target(chain: Any, index: int) -> str | None:
    """The unknown a ``solve`` stage finds: its ``for``, else the first one not found before."""
    found: list[str] = []
    unknowns = [g.name for g in chain.givens if g.unknown]
    for i, raw in enumerate(chain.stages, 1):
        if raw.get("type") != "solve":
            continue
        name = raw.get("for") or next((u for u in unknowns if u not in found), None)
        if i == index:
            return name
        found.append(name)
    return None


def chain_facts(solution: Any, read: source.Read | None = None) -> Facts:
    """The facts of every stage of a solved chain.

    The chain is worked once for each set of unknowns the page has found so far:
    a stage before a ``solve`` stage sees its unknown as a letter (a sample
    value); the stages from there on, and the chain's answer, see its root.
    """
    chain = solution.problem
    solved_at = {_target(chain, i): i for i, raw in enumerate(chain.stages, 1) if raw.get("type") == "solve"}
    solved_at.pop(None, None)
    roots = {getattr(s, "name", ""): v for s, v in solution.values.items()}
    last = len(chain.stages)

    def state(i: int) -> frozenset[str]:
        return frozenset(n for n, at in solved_at.items() if at <= i and n in roots)

    runs = {s: _Chain(solution, {n: roots[n] for n in s}, read).run() for s in {state(i) for i in range(last + 1)}}
    full = runs[state(last)]
    asked = frozenset(chain.find) or frozenset(a.name for a in solution.answers)
    scopes = {"chain": full.chain_scope("chain", last, asked=asked)}
    solved: dict[str, Scope] = {}
    for i in range(1, last + 1):
        scopes.update(runs[state(i)].stage_scopes(i))
        if state(i) != state(last):
            solved.update(full.stage_scopes(i))
    return Facts(scopes, chain.digits, True, tuple(full.notes), solved)


def stage_letters(raw: dict) -> tuple[str, str]:
    """The letters a chain's impact stage calls its bodies by, read from the file: A's
    ``label`` (else A); B's ``label``, else, B being a wall or the ground, the initial of
    its name (W, G): a fixed body is never called B in a chain, where B may be a sphere."""
    a = str((raw.get("A") or {}).get("label") or "A")
    b_table = raw.get("B") or {}
    if b_table.get("label"):
        return a, str(b_table["label"])
    if not b_table.get("fixed"):
        return a, "B"
    initial = str(b_table.get("name") or "wall")[:1].upper()
    return a, initial if re.fullmatch(r"[A-Z]", initial) and initial != a else "W"


def _own_names(table: Table, raw: dict, chain: Table) -> None:
    """A wall or floor stage's quantities under the chain's names too, as the file gives them
    (v_A1 = "u_B", results v_A2 = "w_B"): its page writes u_B and w_B in their places. A
    letter of the chain (e_wall, still unknown here) stays the chain's letter."""
    if not (raw.get("B") or {}).get("fixed"):
        return
    pairs = [(slot, str(text).strip()) for slot, text in (raw.get("given") or {}).items()]
    pairs += [(slot, str(name)) for slot, name in (raw.get("results") or {}).items()]
    for slot, name in pairs:
        letter = chain.roles.get(name) in ("unknown", "param")
        if re.fullmatch(r"[A-Za-z]\w*", name) and slot in table.exprs and name not in table.exprs and not letter:
            table.put(name, table.exprs[slot], table.dims.get(slot, units.NONE), table.roles.get(slot, "result"))
