"""A note in a display's column of its own after ``&&`` that gives a relation and then its reason in
words after a comma (``&& (e = 1,\\ \\mathbf{j}\\text{-part unchanged})``, ``&& \\text{(}e = 0.8\\text{,
as given)}``): the relation is read, the words are prose. Before, the words were read into the
relation (a comma makes a pair, a vector: "e = (1, j-part)"), so the row was not read (the corpus's
ya05) or its note was judged a wrong relation.

Worked by hand (aqa-m3-2007-spheres-approach-head-on: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward
A, e = 0.8): momentum 0.3(3) + 0.2(-2) = 0.5 = 0.3 v_A + 0.2 v_B; restitution v_B - v_A =
0.8(3 + 2) = 4; so 0.5 v_A + 0.8 = 0.5, v_A = -0.6 m/s and v_B = 3.4 m/s.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.mathtext.layout import row_plain

AQA = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(
    "note",
    [
        r"&& (e = 0.8,\ \text{Newton's law})",
        r"&& \text{(}e = 0.8\text{, as given)}",
        r"&& (e = 0.8,\ \text{so the}\ \mathbf{i}\text{-parts only})",
    ],
)
def test_a_notes_reason_after_a_comma_is_prose(note: str) -> None:
    work = (
        "\\begin{align*}\n"
        "0.3(3) + 0.2(-2) &= 0.3 v_A + 0.2 v_B \\\\\n"
        f"v_B - v_A &= 0.8(3 + 2) = 4 {note} \\\\\n"
        "v_A &= -0.6, \\quad v_B = 3.4\n"
        "\\end{align*}"
    )
    assert set(statuses(AQA, work)) == {"correct"}


def test_a_notes_relation_with_no_words_is_still_read() -> None:
    assert "e = 0.8" in row_plain(r"v_B - v_A &= 4 && (e = 0.8)")
    assert "part" not in row_plain(r"\mathbf{v} &= 19.8\,\mathbf{i} && (e = 1,\ \mathbf{j}\text{-part unchanged})")
