"""Inline mathematics inside a sentence in brackets, and words after it that start with a body's
possessive: the student's prose, not part of the relation (``(And $x = …$, A's part along the line
of centres.)``, ``(it should lose $\\tfrac12\\mu(1-e^2)u^2$ with $\\mu = \\frac{2m \\cdot m}{3m}$):``).

Values worked by hand: Edexcel M2 January 2010 Q2, P (2m) at 2u meets Q (m) at u head-on. Along
P's way: CLM 2m(2u) - m u = 3mu = 2m x + m y; NEL y - x = e(2u + u) = 3eu; so 3x = 3u - 3eu,
x = u(1 - e), y = u(1 + 2e). The reduced mass is 2m * m/(2m + m) = 2m/3.
"""

from __future__ import annotations

import pytest
from support.checked import worst_lines

from derive.mathtext.reader import read_relations

PROBLEM = "edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u"
WORK = """Let $x$ be the velocity of P after and $y$ the velocity of Q after, both in P's direction.

$4mu - mu = 2mx + my$

$y - x = 3eu$

So $y = u(1 + 2e)$ {line7}

{line9}
"""


def sides(text: str) -> list[tuple[str, ...]]:
    return [r.sides for r in read_relations(text)]


def test_words_after_a_relation_that_open_with_a_bodys_possessive_are_prose() -> None:
    assert sides("(And $x = u(1 - e)$, P's velocity along the line.)") == [("x", "u(1 - e)")]


def test_a_bracket_closed_after_the_mathematics_is_the_sentences() -> None:
    text = r"(the loss is $\tfrac12\mu(1-e^2)w^2$ with $\mu = \frac{2m \cdot m}{3m} = \frac{2m}{3}$):"
    assert sides(text)[-1] == ("μ", "(2m * m)/(3m)", "(2m)/3")


@pytest.mark.parametrize(
    "line9",
    [
        "(And $x = u(1 - e)$, P's velocity after the impact.)",
        "(so $x = u(1 - e)$, Q's is faster.)",
        "(Then $x = u - eu$, which is P's)",
    ],
)
def test_a_right_relation_inside_a_sentence_in_brackets_is_correct(line9: str) -> None:
    assert worst_lines(PROBLEM, WORK.format(line7="", line9=line9))[9][0] == "correct"


def test_a_wrong_relation_inside_a_sentence_in_brackets_is_wrong() -> None:
    line9 = "(And $x = u(1 + e)$, P's velocity after the impact.)"
    assert worst_lines(PROBLEM, WORK.format(line7="", line9=line9))[9][0] == "wrong"


def test_a_greek_name_set_inside_a_bracketed_sentence_is_read() -> None:
    line7 = r"(the loss is $\tfrac12\mu(1-e^2)(3u)^2$ where $\mu = \frac{2m \cdot m}{3m} = \frac{2m}{3}$)."
    assert worst_lines(PROBLEM, WORK.format(line7=line7, line9=""))[7][0] == "correct"
