"""A root turned down with a bare "no" after it (``e = 2/3 (e = −2/3 no)``, ``(e = −9 no)``,
``e = −2/3 (no)``) is not a relation to mark, as with "rejected" (:data:`derive.mathtext.latex.REJECTED`):
the root kept is judged alone, correct or carried. Values worked by hand from the givens."""

from __future__ import annotations

from support.checked import lines

# CIE 2014 Q3: m at u hits 9m at rest, half the KE lost. u = x + 9y, y - x = eu:
# (1 - 9e)^2 + 9(1 + e)^2 = 50, 10 + 90e^2 = 50, e^2 = 4/9, e = 2/3 (the root -2/3 turned down).
# The slip 81e^2 + 9e^2 = 80e^2: e^2 = 1/2, e = 0.707 (the root -0.707 turned down): carried.
CIE = "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost"
START = "u = x + 9y\ny - x = eu\n(1 - 9e)^2 + 9(1 + e)^2 = 50\n"


def test_a_root_said_no_is_not_marked_and_the_one_kept_is_correct() -> None:
    found = lines(CIE, START + "10 + 90e^2 = 50\ne^2 = 4/9\ne = 2/3 (e = -2/3 no)\n")
    assert found[6][0] == "correct"


def test_after_a_slip_the_root_kept_beside_one_said_no_is_carried() -> None:
    found = lines(CIE, START + "10 + 80e^2 = 50\ne^2 = 1/2\ne = 0.707 (e = -0.707 no)\n")
    assert found[4][0] == "wrong"
    assert found[5][0] == found[6][0] == "carried"
