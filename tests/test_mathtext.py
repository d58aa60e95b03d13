"""derive/mathtext: the reader of typed mathematics for the checker and the verifier (issue #25
item 5). The verifier reads derive's pages with mathtext's parser strictly (numbers keep their
figures); a student's LaTeX row is still rewritten as plain text by mathtext.latex's rules.
"""

from __future__ import annotations

import time

import pytest

from derive.mathtext.display import parse_display
from derive.mathtext.latex import latex_to_plain
from derive.mathtext.reader import read_relations
from derive.mathtext.tokens import LatexError
from derive.mathtext.tree import Hat, Mul, Num, Pow, Sym


def test_a_unit_after_a_space_is_dropped_a_name_next_to_a_number_is_not() -> None:
    assert [r.sides for r in read_relations("$h = 1.41 m$\n$x = 1.2m$\n$T = 0.540\\ \\mathrm{J}$")] == [
        ("h", "1.41"),
        ("x", "1.2m"),
        ("T", "0.540"),
    ]


def test_a_superscript_digit_is_one_digit_as_in_tex() -> None:
    (rel,) = parse_display("y = x^23").relations
    product = rel.sides[1].expr
    assert isinstance(product, Mul) and isinstance(product.factors[0], Pow)
    assert product.factors[0].exp.mantissa == "2" and isinstance(product.factors[1], Num)


def test_a_unit_vector_named_by_its_axis() -> None:
    (rel,) = parse_display(r"u = 3\hat{x} + 4\hat{y}").relations
    hats = [t.factors[1] for _, t in rel.sides[1].expr.terms]
    assert all(isinstance(h, Hat) for h in hats) and [h.axis for h in hats] == ["x", "y"]
    assert isinstance(rel.sides[0].expr, Sym)


def test_deep_nesting_is_refused_not_a_crash() -> None:
    with pytest.raises(LatexError):
        parse_display("x = " + "(" * 300 + "1" + ")" * 300)


@pytest.mark.parametrize(
    "row", ["(" * 3000 + "x", r"\sqrt" * 3000, "a " * 3000 + r"\frac{", "x = " + "1 + " * 100 + r"\frac{"]
)
def test_a_hostile_row_stays_cheap(row: str) -> None:
    start = time.perf_counter()
    assert latex_to_plain(row)
    assert time.perf_counter() - start < 1.0
