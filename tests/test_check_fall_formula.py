"""The fall a chain opens with, worked from suvat's law written in letters first: the law quoted
after words that lead to it ("using v^2 = u^2 + 2as") is a formula stated, not marked; the law in
the chain's own name for the landing speed and h for the height (``v_1^2 = u^2 + 2gh``) is read in
the fall's quantities (u its start speed, h its height), not the chain's u (the rebound) or a
later height; and a speed with its way in brackets of two letters, ``28 m/s (up)``, is read as
``(down)`` is.

Worked by hand: OCR M2 2006 (chain-ocr-m2-2006-drop-rebound), released from rest 2 m up:
v_1^2 = 0 + 2(9.8)(2) = 39.2, v_1 = 6.26; it rises to 1.4 m: v_2 = sqrt(2(9.8)(1.4)) = sqrt(27.44)
= 5.24 m/s up.
"""

from __future__ import annotations

from support.checked import lines

from derive.mathtext.reader import read_relations

PROBLEM = "chain-ocr-m2-2006-drop-rebound"


def test_a_law_quoted_after_words_is_not_a_relation() -> None:
    for typed in ("(i) using v^2 = u^2 + 2as", "From: v = u + at", "applying v^2 = u^2 + 2as"):
        assert list(read_relations(typed)) == []
    assert [r.sides for r in read_relations("using v^2 = u^2 + as")] == [("using v^2", "u^2 + as")]


def test_the_law_in_the_chains_name_and_h() -> None:
    work = "Down positive.\nv_1^2 = u^2 + 2gh\nv_1^2 = 0 + 2(9.8)(2) = 39.2\nv_1 = 6.26 m/s\n"
    got = lines(PROBLEM, work)
    assert {n: got[n][0] for n in (2, 3, 4)} == dict.fromkeys((2, 3, 4), "correct")


def test_a_speed_with_up_in_brackets() -> None:
    got = lines(PROBLEM, "v_2 = sqrt(2(9.8)(1.4)) = sqrt(27.44) = 5.24 m/s (up)\n")
    assert got[1][0] == "correct"


def test_a_later_height_h_is_not_the_falls() -> None:
    # the rise after the bounce in h: 5.24^2 = 27.46, h = 27.46/19.6 = 1.40 m (the rebound height)
    work = (
        "v^2 = u^2 + 2as = 0 + 2(9.8)(2) = 39.2\nv = 6.26 m/s\nup +ve: 0 = 5.24^2 - 2(9.8)h\nh = 27.46/19.6 = 1.40 m\n"
    )
    got = lines(PROBLEM, work)
    assert got[3][0] == "correct" and got[4][0] == "correct"
