"""derive.physics.algebra skips ``sympy.simplify`` on a number already in its simplest form
(issue #19: the first ``simplify`` of a process imports sympy.physics.units); the skip must
never change a result."""

from __future__ import annotations

import sympy
from hypothesis import given, settings
from hypothesis import strategies as st

from derive.physics.algebra import _plain, collect, satisfies

rationals = st.fractions(min_value=-1000, max_value=1000, max_denominator=200).map(sympy.Rational)
whole = st.integers(min_value=2, max_value=5000).map(sympy.Integer)


def _numbers(draw: st.DrawFn) -> sympy.Expr:
    k, n, c = draw(rationals), draw(whole), draw(rationals)
    q = draw(st.fractions(min_value=-1, max_value=1, max_denominator=500).map(sympy.Rational))
    kind = draw(st.sampled_from(["rational", "root", "cos", "sin", "sum"]))
    return {
        "rational": k,
        "root": k * sympy.sqrt(n),
        "cos": k * sympy.cos(q * sympy.pi),
        "sin": k * sympy.sin(q * sympy.pi),
        "sum": c + k * sympy.sqrt(n),
    }[kind]


@settings(max_examples=200, derandomize=True, deadline=None)
@given(st.composite(_numbers)())
def test_a_plain_number_is_what_simplify_returns(x: sympy.Expr) -> None:
    if _plain(x):
        assert sympy.srepr(sympy.simplify(x)) == sympy.srepr(x)


def test_what_simplify_may_rewrite_is_not_plain() -> None:
    pi = sympy.pi
    assert not _plain(-sympy.cos(sympy.Rational(15, 32) * pi))  # simplify: -sin(pi/32)
    assert not _plain(sympy.cos(pi / 9) + sympy.sin(pi / 9))  # simplify: sqrt(2) sin(13 pi/36)
    assert not _plain(1 / (1 + sympy.sqrt(2)))
    assert not _plain(sympy.sqrt(2) + sympy.sqrt(6))
    assert _plain(sympy.Rational(-9, 10)) and _plain(25 * sympy.cos(sympy.Rational(47, 225) * pi))


def test_collect_with_numbers_and_letters() -> None:
    x, y, m = sympy.symbols("x y m")
    assert collect(3 * sympy.sqrt(2) * x + 1, y, (x,), ()) == ((3 * sympy.sqrt(2) * x,), (y - 1,))
    assert collect(m * x + m * y, 2 * m, (x, y), ()) == ((m * x, m * y), (2 * m,))


def test_satisfies_keeps_true_roots_and_drops_false_ones() -> None:
    """physics.algebra.satisfies (issue #19: it spares SymPy's simplifying check): each case
    decided by hand."""
    x, u = sympy.symbols("x u", positive=True)
    assert satisfies([x**2 - 4], {x: sympy.Integer(2)})
    assert not satisfies([x**2 - 4], {x: sympy.Integer(3)})
    # squaring made x = 4 a root of (2 - x)^2 = x; sqrt(4) + 4 - 2 = 4, not 0; x = 1 is the root
    assert satisfies([sympy.sqrt(x) + x - 2], {x: sympy.Integer(1)})
    assert not satisfies([sympy.sqrt(x) + x - 2], {x: sympy.Integer(4)})
    # letters stay: u x = u^2 holds for x = u whatever u is, not for x = 2u
    assert satisfies([u * x - u**2], {x: u})
    assert not satisfies([u * x - u**2], {x: 2 * u})
    # a root that zeroes a denominator does not solve (x^2 - 1)/(x - 1) = 2
    assert not satisfies([(x**2 - 1) / (x - 1) - 2], {x: sympy.Integer(1)})
    # an exact root with an irrational number: cos(pi/5) = (1 + sqrt 5)/4
    assert satisfies([x - sympy.cos(sympy.pi / 5)], {x: (1 + sympy.sqrt(5)) / 4})


def test_satisfies_leaves_a_residual_that_is_no_number_to_sympy() -> None:
    """sin(oo) is AccumBounds(-1, 1) to SymPy, not a number: satisfies() does not fail on it
    but gives the verdict of SymPy's own check."""
    x = sympy.Symbol("x")
    assert sympy.sin(x).xreplace({x: sympy.oo}) == sympy.AccumBounds(-1, 1)
    expected = sympy.checksol(sympy.sin(x), {x: sympy.oo}) is not False
    assert satisfies([sympy.sin(x)], {x: sympy.oo}) is expected
