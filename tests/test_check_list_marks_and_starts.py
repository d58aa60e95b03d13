"""Three readings a phone-typed chain needs (found in a spring-pan derivation, checked on others):
a numbered step's mark ``3)`` opens no bracket, so the relations after it split at their commas;
a letter with 0 beside the chain's letter (``x0`` where the chain's x is the greatest deflection) is
the student's own start value, not x times 0 nor x; a stiffness's unit ``N/m`` is a unit."""

from __future__ import annotations

from support.checked import lines

from derive.checking.naming import rewrite
from derive.mathtext.reader import read_relations


def test_a_list_mark_opens_no_bracket() -> None:
    assert [r.sides for r in read_relations("b) u=3 m/s, v=2 m/s")] == [("u", "3"), ("v", "2")]
    assert [r.sides for r in read_relations("2) k=15 N/m, m=0.5 kg")] == [("k", "15"), ("m", "0.5")]


def test_a_letter_with_nought_is_its_own_name() -> None:
    assert rewrite("x0", {"x", "V"}) == "x0"  # not x, nor x times 0
    assert rewrite("e1", {"e"}) == "e"  # the one e, as before
    assert rewrite("h0", {"h", "h_0"}) == "h_0"


def test_the_pans_static_compression_as_x0_in_a_numbered_list() -> None:
    # Block onto a pan: V = 30(6.264)/40 = 4.698; the pan alone compresses the spring by
    # x0 = 10(9.81)/20000 = 0.004905 m; ½(40)V² + 40(9.81)x = ½(20000)((x0 + x)² − x0²):
    # 441.45 + 392.4x = 10000x² + 98.1x, x = 0.2253 m.
    work = (
        "1) v1 = sqrt(2(9.81)(2)) = 6.264, V = 30(6.264)/40 = 4.698\n"
        "2) k=20000 N/m, x0=10(9.81)/20000=0.004905\n"
        "3) (1/2)(40)(4.698)^2 + 40(9.81)x = (1/2)(20000)((x0 + x)^2 - x0^2)\n"
        "4) x = 0.2253 m\n"
    )
    found = lines("chain-block-onto-spring-pan", work)
    assert [found[n][0] for n in (1, 2, 3, 4)] == ["correct"] * 4
