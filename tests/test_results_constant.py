"""The cheap test that spares simplifying an angle's ratio that is no number (CI's and a
teacher's time: a variant's angles keep their varied givens)."""

import sympy

from derive.physics.results import _atan2_number, _may_be_constant

a, b = sympy.symbols("a b", positive=True)
x = sympy.Symbol("x", real=True)


def test_a_ratio_that_varies_is_known_to_be_no_number() -> None:
    assert not _may_be_constant(a / (a + b))
    assert not _may_be_constant(sympy.sin(x) / sympy.cos(x))


def test_a_ratio_that_is_a_number_in_disguise_is_still_simplified() -> None:
    assert _may_be_constant(sympy.sin(x) ** 2 + sympy.cos(x) ** 2)
    assert _may_be_constant((a**2 - b**2) / ((a - b) * (a + b)))
    # 4.C.12's case: the shared speed cancels, the angle is a number (tan = 1/sqrt(3): 30°)
    assert _atan2_number(a * sympy.sin(sympy.pi / 6), a * sympy.cos(sympy.pi / 6)) == sympy.pi / 6


def test_an_angle_that_keeps_its_givens_is_unchanged() -> None:
    assert _atan2_number(a, a + b) == sympy.atan2(a, a + b)
