"""A momentum named with the common mass cancelled: the student says the m cancels ("dividing by m
throughout", "the m's cancel") before naming the momentum, and writes p without m where the masses
are multiples of m. The p is then the momentum over m, as a teacher reads it; a momentum written
with its m before the words is still the momentum itself.

Worked by hand. Edexcel M2 2004 (2m at 5u hits 3m at rest): momentum over m before 2(5u) = 10u;
after 2v_A + 3v_B = 10u, with v_B - v_A = 5eu: 5v_B = 10u + 10eu, v_B = 2(1 + e)u.
CIE 2012 (3m at u hits 6m at rest): momentum over m 3u = 3v_A + 6v_B.
"""

from __future__ import annotations

from support.checked import lines

EDEXCEL = """\
Dividing by m throughout.
p_i = 2(5u) + 3(0) = 10u
p_f = 2v_A + 3v_B = 10u
v_B - v_A = 5eu
5v_B = 10u + 10eu, so v_B = 2(1 + e)u
"""


def test_momentum_named_over_m() -> None:
    got = lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", EDEXCEL)
    assert {n: got[n][0] for n in (2, 3, 4, 5)} == dict.fromkeys((2, 3, 4, 5), "correct")


CIE = r"""
The $m$'s cancel, so with $p$ for the momentum:
$$p_{before} = 3u, \qquad p_{after} = 3v_A + 6v_B$$
"""


def test_momentum_over_m_in_latex() -> None:
    got = lines("cie-9231-p2-2012-june-q1-3m-hits-6m-show-ke-lost", CIE)
    assert got[3][0] == "correct"


def test_a_momentum_with_its_m_before_the_words_is_the_momentum() -> None:
    kept = "p_i = 2m(5u) = 10mu\n(the m's cancel in what follows)\n"
    assert lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", kept)[1][0] == "correct"
    slipped = "p_i = 2(5u) = 10u\n"  # no words of cancelling: 10u is not the momentum 10mu
    assert lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", slipped)[1][0] == "wrong"
