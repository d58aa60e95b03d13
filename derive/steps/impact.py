"""One impact written out in the notes' four stages: 1) geometry, 2) kinetics,
3) solve, 4) answer. Each stage is a function of the solved impact; a chain writes
each of its impact stages with the same functions, numbering equations on from the
stages before."""

from __future__ import annotations

from derive.physics.outcome import ImpactOutcome
from derive.steps.answer import answer
from derive.steps.elimination import elimination
from derive.steps.geometry import geometry
from derive.steps.kinetics import kinetics
from derive.steps.model import Stage
from derive.steps.page import Page, Tags


def write_impact(outcome: ImpactOutcome, tags: Tags | None = None, *, marks: bool = True) -> tuple[Stage, ...]:
    """The four stages of the worked solution of one impact; ``marks`` False leaves out
    the ANSWER marks (an impact inside a chain answers nothing by itself)."""
    page = Page(outcome, tags or Tags(), marks)
    kin = kinetics(page)
    return (
        Stage(1, "Geometry: the n–t axes", tuple(geometry(page)), figure="before"),
        Stage(2, "Kinetics", kin.blocks),
        Stage(3, "Solve", tuple(elimination(page, kin))),
        Stage(4, "Answer", tuple(answer(page)), figure="after"),
    )
