"""A bracket at the end of a relation whose terms are joined by operators (``e k u (1 - lam)``)
is mathematics, whatever its names' letters (the problem's own ``lam`` for λ); a bracket with
words in it (``(to the right)``, ``(down +ve)``) is still a remark. Values worked by hand."""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.reader import read_relations

#: S (mass m, speed u) catches T (mass km, speed λu, lam in the problem) and stops:
#: m u + km(λu) = km v_T, so v_T = u(1 + kλ)/k; e = v_T/(u − λu) = (1 + kλ)/(k(1 − λ)).
STOPS = "edexcel-m2-undated-q5-s-brought-to-rest-show-e"


def test_a_bracket_of_terms_after_a_letter_is_a_factor() -> None:
    sides = [r.sides for r in read_relations("u(1 + k lam) = e k u (1 - lam)", {}, True)]
    assert sides == [("u(1 + k lam)", "e k u (1 - lam)")]


def test_words_in_a_bracket_are_still_a_remark() -> None:
    sides = [r.sides for r in read_relations("v = 3 m/s (down +ve)", {}, True)]
    assert sides == [("v", "3")]


def test_restitution_with_the_problems_letter_for_lambda() -> None:
    work = "u(1 + k lam) = e k u (1 - lam)\nk e (1 - lam) = 1 + k lam\n"
    found = worst_lines(STOPS, work)
    assert found[1][0] == found[2][0] == "correct"


def test_a_wrong_bracket_is_still_a_slip() -> None:
    found = worst_lines(STOPS, "u(1 + k lam) = e k u (1 + lam)\n")
    assert found[1][0] == "wrong"
