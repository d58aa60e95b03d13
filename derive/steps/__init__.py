"""From the physics to a worked solution as data: the steps of the notes' layout.
May import: physics, problem and the leaves.

:func:`solve` runs the physics and writes its steps; the writers in
:mod:`derive.writers` turn the :class:`~derive.steps.model.Solution` into text.
"""

from __future__ import annotations

from derive.problem import ChainProblem, Problem
from derive.steps.model import Solution, Stage


def solve(problem: Problem | ChainProblem, *, steps: bool = True) -> Solution:
    """Solve ``problem`` (or a chain, stage by stage) in closed form and write its worked solution.

    ``steps=False`` (a single impact) leaves the worked stages out: the results alone, which
    is all that ``derive check`` reads.

    >>> from derive import load, solve  # doctest: +SKIP
    >>> solve(load("notes-4c11-two-spheres")).results["v_A2n"].value  # doctest: +SKIP
    -7*cos(47*pi/225)/5
    """
    if isinstance(problem, ChainProblem):
        from derive.physics.chain import run_chain
        from derive.steps.chain import write_chain

        return write_chain(run_chain(problem))
    from derive.physics.outcome import solve_impact

    outcome = solve_impact(problem)
    stages: tuple[Stage, ...] = ()
    if steps:  # the step writers are imported only where the steps are written (not for check)
        from derive.steps.impact import write_impact

        stages = write_impact(outcome)
    return Solution(
        problem,
        outcome.results,
        stages,
        outcome.values,
        outcome.angles,
        shown=outcome.shown,
        ranges=outcome.ranges,
        others=outcome.others,
    )
