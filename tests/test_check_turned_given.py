"""suvat's a restated for the next leg of a fall with the other way positive ("going up, with up
positive: a = -9.8") is that leg's given in the line's own convention, not a slip in g: a teacher
does not mark it wrong. Without words of a convention, or with another size, it is still judged.

Worked by hand: OCR M2 2006 (chain-ocr-m2-2006-drop-rebound), dropped from 2 m: v^2 = 2(9.8)(2)
= 39.2, v = 6.26; it rebounds to 1.4 m: 0 = w^2 - 2(9.8)(1.4), w = sqrt(27.44) = 5.24.
OCR M2 2015 (chain-ocr-m2-2015-thrown-down-bounce): thrown down at 5 m/s from 1.6 m: v^2 = 25 +
2(9.8)(1.6) = 56.36, v = 7.51.
"""

from __future__ import annotations

from support.checked import lines

DROP = """\
Down is positive, u = 0, a = 9.8, s = 2
v^2 = u^2 + 2as = 0 + 2(9.8)(2) = 39.2
v = 6.26 m/s
Then going up, with up positive: a = -9.8
0 = w^2 - 2(9.8)(1.4), w = 5.24 m/s
"""


def test_g_turned_round_for_the_rise_is_its_given() -> None:
    got = lines("chain-ocr-m2-2006-drop-rebound", DROP)
    assert got[4][0] == "correct" and got[5][0] == "correct"


THROWN = r"""
Falling, down $+$: $a = 9.8$, $u = 5$, $s = 1.6$
$$v^2 = u^2 + 2as = 25 + 2(9.8)(1.6) = 56.36, \quad v = 7.51$$
Rise, taking upwards as +ve: $a = -9.8$ m/s$^2$
"""


def test_g_turned_round_in_latex_words() -> None:
    got = lines("chain-ocr-m2-2015-thrown-down-bounce", THROWN)
    assert got[4][0] == "correct"


def test_without_a_convention_or_with_another_size_it_is_judged() -> None:
    assert lines("chain-ocr-m2-2006-drop-rebound", DROP.replace("with up positive: ", ""))[4][0] == "wrong"
    assert lines("chain-ocr-m2-2006-drop-rebound", DROP.replace("a = -9.8", "a = -4.9"))[4][0] == "wrong"
