"""A relation followed by the student's "not equal" to another value (``= 1/tanα ≠ 2tanα ??``,
``\\neq``, ``!=``): the relation is judged, the comparison after it is a remark, as ``> 0`` after a
relation is (derive/mathtext/reader.py). Before, the whole line was dropped (no verdict).
Each expected mark is worked by hand from the problem's givens."""

from __future__ import annotations

from support.checked import worst_lines


def test_a_relation_then_not_equal_to_the_books_value_is_judged() -> None:
    # OCR M2 2006: A (2 kg) at 5 m/s meets B (1 kg) at 5 m/s head on, e = 0.8 (→ positive):
    # 2(5) - 1(5) = 2x + y, y - x = 0.8(10) = 8 -> x = -1, y = 7. B's 7 is right whatever the
    # student compares it with; A's +1 is wrong (A goes back at 1 m/s: -1).
    work = r"""$$(v_B)_2 = 7 \neq 8 \text{ (the book says 8??)}$$

(v_A)_2 = 1 != -1 ?? answer has -1
"""
    got = worst_lines("ocr-m2-2006-spheres-meet-at-5-ke-lost", work)
    assert got[1][0] == "correct"
    assert got[3][0] == "wrong"


def test_a_lone_inequality_stays_unread() -> None:
    # "e ≠ 1" states no value: no relation to judge; a relation before it is the first line's.
    work = "(v_B)_2 = 7\ne ≠ 1\n"
    got = worst_lines("ocr-m2-2006-spheres-meet-at-5-ke-lost", work)
    assert got[1][0] == "correct"
    assert 2 not in got
