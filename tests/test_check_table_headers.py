"""A Markdown table of components read as a teacher reads it: a cell under a column headed by an
axis (``n``, ``t before``), in a row labelled by a body (``A before``, ``ball B``, ``A after``),
is that body's component, so ``4 sin 30° = 2`` under ``n`` in A's row is A's n component before
(truly 4 cos 30° = 3.464), not arithmetic that holds. Gramoll's two balls: A at 4 m/s, 30° from
the line of impact; B at 3 m/s along it toward A; equal masses, e = 1 (worked in the comments)."""

from __future__ import annotations

from support.checked import worst_lines as lines

BALLS = "gramoll-ecourses-two-balls-elastic"


def test_a_components_row_with_sin_and_cos_swapped_is_the_slip() -> None:
    # along n: 4 cos 30° = 3.464 (written 4 sin 30° = 2); across: 4 sin 30° = 2 (written 3.46).
    work = "| | n before | t before |\n|---|---|---|\n| ball A | 4 sin 30° = 2 | 4 cos 30° = 3.46 |\n"
    assert lines(BALLS, work)[3] == ("wrong", "sin_cos_swapped")


def test_rows_before_and_after_under_axis_headers_are_the_components() -> None:
    # before: A (3.464, 2), B (-3, 0); e = 1, equal masses: the n components exchange, so A after
    # is (-3, 2) and B after (3.464, 0).
    work = (
        "| | n | t |\n|---|---|---|\n| A before | 4 cos 30° = 3.464 | 4 sin 30° = 2 |\n| B before | -3 | 0 |\n"
        "| A after | -3 | 2 |\n| B after | 3.464 | 0 |\n"
    )
    found = lines(BALLS, work)
    assert [found[n][0] for n in (3, 4, 5, 6)] == ["correct"] * 4
    wrong = work.replace("| A after | -3 | 2 |", "| A after | 3 | 2 |")
    assert lines(BALLS, wrong)[5][0] == "wrong"
