"""Chains: impacts in sequence, and the motion before and after an impact, solved stage by stage.

Each stage takes its inputs from the chain's givens and from the results of the
stages before it, and names its own results for those after it. The notes' rule is
kept: energy methods before and after an impact, never across one; each impact stage
is a problem of its own, solved by the same single-impact physics
(:func:`derive.physics.outcome.solve_impact`). One module per stage type, in
:mod:`derive.physics.stages`, each registered in :data:`STAGES`.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.physics.results import Result
from derive.physics.stages import again, algebra, bounces, energy, impact
from derive.physics.state import ChainOutcome, ChainState, StageOutcome
from derive.problem import ChainProblem

#: Stage type -> the function that solves a stage of that type.
STAGES: dict[str, Callable[[ChainState, int, dict], StageOutcome]] = {
    "fall": energy.fall,
    "rise": energy.rise,
    "slide": energy.slide,
    "spring": energy.spring,
    "impact": impact.impact,
    "bounces": bounces.bounces,
    "again": again.again,
    "define": algebra.define,
    "solve": algebra.solve,
}


def run_chain(chain: ChainProblem) -> ChainOutcome:
    """Solve the chain stage by stage, then every named quantity in the chain's givens."""
    state = ChainState(chain)
    stages: list[StageOutcome] = []
    for i, st in enumerate(chain.stages, 1):
        known = state.snapshot()  # the numbers this stage starts from
        found = STAGES[st["type"]](state, i, st)
        g = state.known.get("g")  # the default g (9.81 m/s²) a stage may add is known from the start
        if g is not None and g.value is not None:
            known.setdefault(g.symbol, g.value)
        stages.append(replace(found, values=known))
    outputs = {n for st in stages for n in st.outputs}
    results = {}
    roots = dict(state.solved)
    for name, g in state.known.items():
        if g.definition is None and not g.unknown and name not in outputs:
            continue
        closed = g.definition if g.definition is not None else roots.get(g.symbol, g.symbol)
        closed = state.in_givens(closed).xreplace(roots)  # in the chain's givens; unknowns by their solutions
        val = state.value(g.symbol if g.unknown else closed)
        number = None if val.free_symbols else val
        if g.unit == "deg" and number is not None:
            number = number * 180 / sympy.pi
        results[name] = Result(name, g.symbol, closed, number, val, g.unit, g.name)
    values = {g.symbol: g.value for g in state.known.values() if g.value is not None}
    values.update(state.solved)
    angles = frozenset(g.symbol for g in state.known.values() if g.unit == "deg")
    return ChainOutcome(chain, tuple(stages), results, values, angles)
