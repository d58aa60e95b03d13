"""The signs ∥ and ⊥ standing alone as words (``∥ cpt = ⊥ cpt``, ``no ⊥ imp``) are the words
parallel and perpendicular: a statement in words with an "=" in it, a remark beside the relation
that follows it on the line, as "parallel cpt = perp cpt" is. Glued to a name (``v⊥``, ``v_∥``)
they stay the name's mark.

Example 4.C.11 by hand (theta = 37.6 deg, sin 0.61015, cos 0.79229): each body keeps its t
component, v_A2t = 5 sin = 3.051, v_B2t = -15 sin = -9.152. MEI FMM 2021 Q5: B leaves at 45 deg
with its across component 2.5 kept, so its along component is 2.5/tan 45 = 2.5.
"""

from __future__ import annotations

import pytest

import derive


def statuses(problem: str, work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(problem)), derivation=work)
    return [i.status for i in report.items]


NOTES = "notes-4c11-two-spheres"
MEI = "ocr-mei-fmm-2021-b-at-45deg-find-e"


@pytest.mark.parametrize(
    ("problem", "work", "expected"),
    [
        (NOTES, "⊥ cpt = ⊥ cpt: v_A2t = 5sin37.6 = 3.051", ["correct"]),
        (NOTES, "no ⊥ imp, so ⊥ v = ⊥ u: v_B2t = -15sin37.6 = -9.152", ["correct"]),
        (NOTES, "⊥ cpt = ⊥ cpt: v_A2t = 5sin37.6 = 3.5", ["wrong"]),  # the words do not hide a slip
        (MEI, "at 45°, ∥ v = ⊥ v so v_B2n = 2.5", ["correct"]),
        (MEI, "at 45°, ∥ v = ⊥ v so v_B2n = 3.5", ["wrong"]),
    ],
)
def test_parallel_and_perpendicular_signs_as_words(problem: str, work: str, expected: list[str]) -> None:
    assert statuses(problem, work) == expected
