"""A body's component named in words, its words in any order (derive/checking/componentlabels.py,
``said_component``): the body, the axis and the instant, with nothing else but the words between
(``Q's component perpendicular after``, ``A after ⊥``, ``the velocity of A perpendicular to the
line of centres after``); the exam's P and Q after an arrow or in ``component of Q`` read as the
bodies (derive/checking/bodywords.py). Before, these lines were dropped as prose: no verdict.
Each expected mark is worked by hand from the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines


def test_components_in_words_in_other_orders_are_judged() -> None:
    # AQA M3 2007: A at u, 30° to the line of centres, hits an identical B at rest.
    # Along the line of centres A has u cos 30° before; across it u sin 30° = u/2, unchanged after.
    # B moves off along the line of centres: its component across after is 0, not u sin 30°.
    work = """A's component along the line of centres before = u cos 30
A after, across = u sin 30 = u/2
the velocity of A perpendicular to the line of centres after = u/2
B after perpendicular = u sin 30
"""
    got = worst_lines("aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b", work)
    assert [got[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert got[4][0] == "wrong"


def test_the_exams_letters_after_an_arrow_and_after_component_of() -> None:
    # Edexcel M4 2005: Q (moving at u at alpha to the line of centres) hits P at rest; Q's component
    # perpendicular to the line of centres, u sin(alpha), is unchanged; P's across after is 0.
    work = """Q before: along u cos(alpha), perp u sin(alpha)
smooth => Q after ⊥ = u sin(alpha)
perpendicular component of Q after = u sin(alpha)
P's component perpendicular after = u sin(alpha)
"""
    got = worst_lines("edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta", work)
    assert [got[n][0] for n in (2, 3)] == ["correct"] * 2
    assert got[4][0] == "wrong"
