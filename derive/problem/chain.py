"""Chain files (``kind = "chain"``): givens and a list of ``[[stage]]`` tables, checked.

Every stage is checked against its type's table in the schema when the file is read:
its fields' types, the syntax of its expressions, and the names it gives its results
(new names only: a stage may not overwrite a given or an earlier result). What its
expressions mean is known only when the earlier stages are solved, so the stages are
solved by :mod:`derive.physics.chain`; an impact stage is read as a problem of its own
(:func:`derive.problem.reader.build_problem`) once the quantities it names are known.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import sympy

from derive.errors import ExpressionError
from derive.problem import fields
from derive.problem.expr import FUNCTIONS, ParseError, number_with_unit, parse, scan
from derive.problem.givens import build_givens, infer_system
from derive.problem.records import Given, RecordError
from derive.problem.schema import CHAIN, STAGES
from derive.problem.source import Source
from derive.problem.units import DIMENSIONLESS
from derive.problem.validate import check
from derive.symbols import symbol

STAGE_TYPES = tuple(STAGES)


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
    #: Homework variants: the values each varied given may take (``[vary]``), and the
    #: conditions every variant meets, as typed (their names are checked; their dimensions
    #: are known once the chain is solved).
    vary: Mapping[str, tuple[sympy.Expr, ...]] = field(default_factory=dict)
    conditions: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        if self.digits is not None and (isinstance(self.digits, bool) or not 1 <= self.digits <= 10):
            raise RecordError("expected a whole number of significant figures from 1 to 10", key="digits")
        if not self.stages or any(st.get("type") not in STAGE_TYPES for st in self.stages):
            raise RecordError(f"expected stages of the types {', '.join(STAGE_TYPES)}", key="stage")

    def symbols(self) -> dict[str, sympy.Symbol]:
        """Name -> symbol for every given."""
        return {g.name: g.symbol for g in self.givens}

    def stage_source(self, i: int) -> Source:
        """Where stage ``i`` (from 1) is in the file, for its messages: ``file:line: [stage i] key``."""
        return self.ctx.within("stage", i - 1, label=f"stage {i}")


def build_chain(data: dict[str, Any], ctx: Source, name: str) -> ChainProblem:
    """Check a chain file: its fields, and each stage's fields, expressions and result names."""
    check(data, CHAIN, ctx)
    given_tbl = data.get("given", {})
    system = data.get("units") or infer_system(given_tbl)
    givens = build_givens(given_tbl, ctx, True, system)
    used = {g.name for g in givens}
    for i, st in enumerate(data["stage"], 1):
        stage_ctx = ctx.within("stage", i - 1, label=f"stage {i}")
        _check_condition(st, stage_ctx)
        for key, new in stage_results(i, st):
            if new == "pi" or new in FUNCTIONS:  # a later stage would read it as SymPy's (pi = 3.14159)
                raise stage_ctx.error(
                    f"{new!r} is the name of a constant or function: choose another name", key=key, value=new
                )
            if new in used:
                raise stage_ctx.error(
                    f"{new!r} is used already (a given or an earlier stage's result): choose a new name",
                    key=key,
                    value=new,
                )
            used.add(new)
        if st["type"] == "impact":  # an unknown an impact finds (m_A = "? kg") is known after it
            stage_given = st.get("given", {})
            used |= {k for k, v in stage_given.items() if isinstance(v, str) and v.strip().startswith("?")}
    return ChainProblem(
        path=ctx.path,
        title=data["title"],
        givens=tuple(givens),
        stages=tuple(data["stage"]),
        system=system,
        digits=data.get("digits"),
        source=data.get("source"),
        statement=data.get("statement"),
        question=data.get("question"),
        find=tuple(data.get("find", [])),
        name=name,
        ctx=ctx,
        vary=fields.vary(data.get("vary"), {g.name: g for g in givens}, ctx, False, system),
        conditions=_conditions(data.get("conditions"), used | {"g"}, ctx),
    )


def _conditions(raw: list[str] | None, names: set[str], ctx: Source) -> tuple[str, ...]:
    """A chain's conditions, as typed: each a comparison of expressions in its givens and
    its stages' results (checked here: the form and the names)."""
    known = {n: (symbol(n), DIMENSIONLESS) for n in names}
    for text in raw or ():
        m = fields.CONDITION.match(text)
        if not m:
            raise ctx.error("expected a comparison with <, <=, > or >=", key="conditions", value=text)
        try:
            parse(m.group(1).strip(), known)
            parse(m.group(3).strip(), known)
        except ParseError as exc:
            raise ctx.error(str(exc), key="conditions", value=text, cls=ExpressionError) from None
    return tuple(raw or ())


def stage_results(i: int, st: dict[str, Any]) -> list[tuple[str, str]]:
    """(field, name) of each name stage ``i`` gives its results (defaults from the schema)."""
    kind = st["type"]
    if kind == "impact":
        return [(f"results.{k}", v) for k, v in st.get("results", {}).items()]
    if kind == "bounces":
        n = st.get("count", 3)
        return [("count", f"{x}_b{k}") for k in range(1, n + 1) for x in "vh"] + [("count", "s_total")]
    f = STAGES[kind].get("result")
    if f is None:
        return []
    return [("result", st.get("result", f.default.replace("<stage>", str(i))))]


def _check_condition(st: dict[str, Any], ctx: Source) -> None:
    """A solve stage's condition: one equation, each side a well-formed expression (or a
    number with its unit), its numbers in range."""
    text = st.get("condition")
    if st["type"] != "solve" or text is None:
        return
    if text.count("=") != 1:
        raise ctx.error('expected one equation such as "h_2 = 40 m"', key="condition", value=text)
    left, right = text.split("=")
    try:
        scan(left)
        if number_with_unit(right) is None:
            scan(right)
    except ParseError as exc:
        raise ctx.error(str(exc), key="condition", value=text) from None
