"""A plot of an impact's outcome against the coefficient of restitution e.
May import: the rest of writers, steps, physics, problem and the leaves.

:mod:`.curves` evaluates the physics' closed forms for e from 0 to 1; :mod:`.chart`
lays them out; :mod:`.draw` draws SVG by hand and TikZ (PDF, PNG through LaTeX).
Why no plotting library: docs/figures.md.

>>> import derive  # doctest: +SKIP
>>> svg = plot_svg(derive.load("notes-4c11-two-spheres"))  # doctest: +SKIP
"""

from __future__ import annotations

from derive.errors import InputError
from derive.problem import ChainProblem, Problem
from derive.writers.plot.chart import Chart, layout
from derive.writers.plot.curves import Curves, curves
from derive.writers.plot.draw import to_pdf, to_png, to_svg, to_tikz


def chart(problem: Problem) -> Chart:
    """The plot of ``problem``'s outcome against e, as geometry."""
    return layout(curves(problem))


def impact_of(problem: Problem | ChainProblem, stage: int | None = None) -> Problem:
    """The impact to plot: the problem itself, or a chain's impact stage ``stage``
    (its number in the chain; default: the first impact)."""
    if isinstance(problem, Problem):
        if stage is not None:
            raise InputError("--stage is for a chain", where="usage")
        return problem
    from derive.physics.chain import run_chain

    impacts = {st.number: st.data.outcome.problem for st in run_chain(problem).stages if st.type == "impact"}
    if stage is None:
        return impacts[min(impacts)]
    if stage not in impacts:
        shown = ", ".join(str(n) for n in sorted(impacts))
        raise InputError(f"stage {stage} is not an impact (impact stages: {shown})", where="usage", field="--stage")
    return impacts[stage]


def plot_svg(problem: Problem) -> str:
    """The plot as an SVG element."""
    return to_svg(chart(problem))


__all__ = ["Curves", "chart", "curves", "plot_svg", "to_pdf", "to_png", "to_svg", "to_tikz"]
