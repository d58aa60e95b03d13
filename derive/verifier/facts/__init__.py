"""From derive's objects to plain facts: the only part of the verifier that touches them.
May import: steps, physics, problem and the leaves (the only part of the verifier that does).

:func:`facts_of` reads a Solution (or a chain's solution) and returns a
:class:`Facts`: for each part of the page, each name's value as a number, its
dimension and its role. It reads the problem's data from derive's Problem, but
works the physics out again (:mod:`.physics`), and notes where derive's own
results differ; nothing here prints or parses a page.
"""

from __future__ import annotations

from typing import Any

from derive.verifier.facts.model import Facts, Quantity, Scope, Table
from derive.verifier.facts.problem import impact

__all__ = ["Facts", "Quantity", "Scope", "facts_of"]


def facts_of(solution: Any, digits: int | None = None) -> Facts:
    """The facts of a solved problem or chain (or of a problem, when it has no unknowns to
    find); ``digits`` overrides the problem's figures."""
    problem = getattr(solution, "problem", solution)
    if getattr(problem, "kind", None) == "chain":
        from derive.verifier.facts.chain import chain_facts

        facts = chain_facts(solution)
    else:
        table = Table()
        notes = impact(table, solution)
        table.relabel(getattr(problem, "labels", ("A", "B")))
        asked = frozenset(problem.find) | frozenset(g.name for g in problem.givens if g.unknown)
        scope = table.scope("", system=problem.system, asked=asked)
        facts = Facts({"": scope}, problem.digits, False, tuple(notes))
    if digits is not None:
        facts = Facts(facts.scopes, digits, facts.chain, facts.notes, facts.solved)
    return facts
