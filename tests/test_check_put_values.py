"""A symbolic given the student puts a number for (``putting m = 1 and u = 1``, ``calculator, put
u = 1: x = 0.5``): their numbers are the quantities in units of it, and are judged so; the line that
puts it is never wrong.

Worked by hand (cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u): A (5m) at u meets B (2m) at
2u head-on, A's way positive. Momentum 5mu − 4mu = 5m v_A + 2m v_B; v_B − v_A = 3eu; so
7 v_A = u − 6eu. With m = u = 1: 5(1) − 2(2) = 1 = 5v_A + 2v_B, v_B − v_A = 3e, v_A = (1 − 6e)/7,
and KE before ½(5)(1)² + ½(2)(2)² = 2.5 + 4 = 6.5 (that is 6.5 m u²).
"""

from __future__ import annotations

from support.checked import line_statuses as statuses

import derive
from derive.checking.context import Context
from derive.checking.putvalues import put_values

SPHERES = "cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u"
WORK = "5(1) - 2(2) = 5v_A + 2v_B\nv_B - v_A = 3e\nv_A = (1 - 6e)/7\nKE before = 0.5(5)(1)^2 + 0.5(2)(2)^2 = 6.5\n"


def test_the_givens_put_equal_to_a_number_are_read() -> None:
    ctx = Context(derive.solve(derive.load(SPHERES)), None)
    found = put_values(ctx, "so putting $m = 1$ and u = 2.")
    assert {s.name: v for s, v in found.items()} == {"m": 1, "u": 2}
    assert put_values(ctx, "putting e = 1") == {}  # e is not a unit to work in
    assert put_values(ctx, "substituting x = 3 into (1)") == {}  # not a given


def test_work_in_units_of_the_givens_put_equal_to_1_is_right() -> None:
    said = "everything has m and u in it, so I'm putting m = 1 and u = 1.\n"
    assert statuses(SPHERES, said + WORK) == ["correct"] * 5


def test_without_the_words_or_with_a_wrong_number_it_is_judged_as_before() -> None:
    assert statuses(SPHERES, WORK)[0] == "wrong"
    said = "putting m = 1 and u = 1\n"
    assert statuses(SPHERES, said + WORK.replace("(1 - 6e)/7", "(1 - 5e)/7"))[3] == "wrong"
