"""One impact written out in the notes' four stages: 1) geometry, 2) kinetics,
3) solve, 4) answer. Each stage is a function of the solved impact; a chain writes
each of its impact stages with the same functions, numbering equations on from the
stages before."""

from __future__ import annotations

from dataclasses import replace

from derive.physics.outcome import ImpactOutcome
from derive.steps.answer import answer
from derive.steps.elimination import elimination
from derive.steps.geometry import geometry
from derive.steps.kinetics import Kinetics, kinetics
from derive.steps.model import Block, Stage
from derive.steps.page import Page, Tags


def write_impact(outcome: ImpactOutcome, tags: Tags | None = None, *, marks: bool = True) -> tuple[Stage, ...]:
    """The four stages of the worked solution of one impact; ``marks`` False leaves out
    the ANSWER marks (an impact inside a chain answers nothing by itself)."""
    page = Page(outcome, tags or Tags(), marks)
    kin = kinetics(page)
    kinetic, solve = shared_places(page, kin, list(kin.blocks), elimination(page, kin))
    return (
        Stage(1, "Geometry: the n–t axes", tuple(geometry(page)), figure="before"),
        Stage(2, "Kinetics", kinetic),
        Stage(3, "Solve", solve),
        Stage(4, "Answer", tuple(answer(page)), figure="after"),
    )


def shared_places(
    page: Page, kin: Kinetics, kinetic: list[Block], solve: list[Block]
) -> tuple[tuple[Block, ...], tuple[Block, ...]]:
    """The blocks that write (3) and (4) and the solve blocks that use them, all given
    every sum among them and the constants of (3) and (4): one count of places for all,
    so that a number of (3) or (4) is written again as (3) or (4) wrote it (84.8 under
    a (3) that shows 84.8, not 84.77)."""
    tags = {page.tags.peek(3), page.tags.peek(4)} - {None}
    writes = [i for i, b in enumerate(kinetic) if any(ln.tag in tags for ln in b.lines)]
    pinned = []
    if kin.eq3 is not None:
        pinned.append(((kin.eq3[1],), kin.eq3[1]))
    if kin.eq4 is not None:
        pinned.append(((kin.eq4,), kin.eq4))
    every = [s for i in writes for s in kinetic[i].sums] + [s for b in solve for s in b.sums]
    if not every:
        return tuple(kinetic), tuple(solve)
    union = tuple(dict.fromkeys(every + pinned))
    kinetic = [replace(b, sums=union) if i in writes else b for i, b in enumerate(kinetic)]
    return tuple(kinetic), tuple(replace(b, sums=union) for b in solve)
