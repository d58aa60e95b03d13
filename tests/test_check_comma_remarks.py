"""Words after a comma at the end of a relation whose last side ends in a letter, a power or a
prime (``(3010)V², cancel 3010``, ``(m_A + m_B)v', dividing through``) are a remark, not part of
the side: the relation is read without them and judged (fixC, eighth session). Before, only a
side ending in a digit lost its words, and the relation was dropped unread."""

from __future__ import annotations

import pytest

import derive
from derive.mathtext.reader import read_relations


@pytest.mark.parametrize(
    ("text", "sides"),
    [
        ("(4.02)(9.81)h = (4.02)V², cancel 4.02", ("(4.02)(9.81)h", "(4.02)V²")),
        ("m_A u = (m_A + m_B)v', dividing through", ("m_A u", "(m_A + m_B)v'")),
        ("T_2 = ½(m + M)V², with V from (1)", ("T_2", "½(m + M)V²")),
    ],
)
def test_words_after_a_comma_are_a_remark(text: str, sides: tuple[str, str]) -> None:
    assert tuple(read_relations(text)[-1].sides) == sides


def test_a_half_dropped_with_a_remark_after_it_is_the_slip() -> None:
    # MSU bullet and block: V = 6/4.02 = 1.4925; (M + m) g h = ½ (M + m) V², so h = V²/(2g) = 0.1135 m.
    # Written without the ½: 9.81 h = V², h = 1.49²/9.81 = 0.226 (the slip carried).
    work = "0.020(300) = 4.02 V\nV = 1.49 m/s\n(4.02)(9.81)h = (4.02)V², cancel 4.02\nh = 1.49²/9.81 = 0.226 m\n"
    report = derive.check(derive.solve(derive.load("chain-msu-bullet-block-swings")), derivation=work)
    found = {int(i.name): (i.status, i.slip) for i in report.items if i.kind == "line" and i.name.isdigit()}
    assert found[3] == ("wrong", "ke_formula")
    assert found[4][0] == "carried"
