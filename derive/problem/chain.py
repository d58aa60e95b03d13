"""Chain files (``kind = "chain"``): givens and a list of ``[[stage]]`` tables, checked.

The stages are solved by :mod:`derive.physics.chain`; an impact stage is read as a
problem of its own (:func:`derive.problem.reader.build_problem`) once the earlier
stages have given the quantities it names.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import sympy

from derive.problem import units
from derive.problem.reader import Given, build_givens, infer_system
from derive.problem.source import Source, text_field, type_name

STAGE_TYPES = ("fall", "rise", "slide", "spring", "impact", "bounces", "again", "define", "solve")


CHAIN_FIELDS = ("title", "kind", "source", "statement", "question", "digits", "units", "given", "stage", "find")


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


def build_chain(data: dict[str, Any], ctx: Source, name: str) -> ChainProblem:
    """Check a chain file's fields (the stages are checked as they are solved)."""
    for key in data:
        if key not in CHAIN_FIELDS:
            raise ctx.error(f"unknown field (expected one of: {', '.join(CHAIN_FIELDS)})", key=key)
    title = text_field(data, "title", ctx, required=True)
    digits = data.get("digits")
    if digits is not None and (isinstance(digits, bool) or not isinstance(digits, int) or not 1 <= digits <= 10):
        raise ctx.error("expected a whole number of significant figures from 1 to 10", key="digits", value=digits)
    given_tbl = data.get("given", {})
    if not isinstance(given_tbl, dict):
        raise ctx.error(f"expected a table, not {type_name(given_tbl)}", key="given")
    system = data.get("units") or infer_system(given_tbl)
    if system not in units.SYSTEMS:
        raise ctx.error('expected "SI" or "US"', key="units", value=system)
    givens = build_givens(given_tbl, ctx, True, system)
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
        source=text_field(data, "source", ctx),
        statement=text_field(data, "statement", ctx),
        question=text_field(data, "question", ctx),
        find=tuple(find),
        name=name,
        ctx=ctx,
    )
