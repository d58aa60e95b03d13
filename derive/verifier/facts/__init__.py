"""From derive's objects to plain facts: the only part of the verifier that touches them.
May import: steps, physics, problem and the leaves (the only part of the verifier that does).

:func:`facts_of` reads a Solution (or a chain's solution) and returns a
:class:`Facts`: for each part of the page, each name's value as a number, its
dimension and its role. It reads the problem's data from the problem file itself
(:mod:`.source`: its own reading of the TOML, units and angles), works the physics
out again (:mod:`.physics`), and notes where derive's loaded problem or its results
differ; nothing here prints or parses a page.
"""

from __future__ import annotations

from typing import Any

from derive.verifier.facts.model import Facts, Quantity, Scope, Table
from derive.verifier.facts.problem import impact
from derive.verifier.facts.source import load as load_source

__all__ = ["Facts", "Quantity", "Scope", "facts_of"]


def facts_of(solution: Any, digits: int | None = None, source: str | None = None) -> Facts:
    """The facts of a solved problem or chain (or of a problem, when it has no unknowns to
    find); ``digits`` overrides the problem's figures. The givens are read from the
    problem's file (``source``: its TOML text, when it is not on disk); a problem built
    in memory (a homework variant's) has only derive's reading."""
    problem = getattr(solution, "problem", solution)
    read = load_source(problem, source)
    if getattr(problem, "kind", None) == "chain":
        from derive.verifier.facts.chain import chain_facts

        facts = chain_facts(solution, read)
    else:
        table = Table()
        notes = impact(table, solution, read=read)
        table.relabel(getattr(problem, "labels", ("A", "B")))
        asked = frozenset(problem.find) | frozenset(g.name for g in problem.givens if g.unknown)
        scope = table.scope("", system=problem.system, asked=asked)
        facts = Facts({"": scope}, problem.digits, False, tuple(notes))
    if read is not None:  # the figures the file asks for, and derive's reading of them
        mine = read.data.get("digits")
        mine = mine if isinstance(mine, int) and not isinstance(mine, bool) else None
        notes = facts.notes
        if mine != facts.digits:
            notes += (f"digits: the file gives {mine}, derive read {facts.digits}",)
        facts = Facts(facts.scopes, mine, facts.chain, notes, facts.solved)
    if digits is not None:
        facts = Facts(facts.scopes, digits, facts.chain, facts.notes, facts.solved)
    return facts
