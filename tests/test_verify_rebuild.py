"""The verifier's one tree map: names and shown numbers are replaced at any depth, so a
found value shown inside a square or a root is read as that value (it was left as a
number inside powers, functions and degrees)."""

from derive.mathtext.tree import Add, Deg, Func, Mul, Num, Pow, Sym
from derive.verifier.evaluate import Env, rebuild, substitute, value

ENV = Env(lambda name: None)


def test_a_shown_number_inside_a_square_and_a_root_is_replaced() -> None:
    two_four = Num("2.4")
    tree = Mul((Num("0.5"), Pow(two_four, Num("2")), Func("sqrt", (two_four,))))
    out = rebuild(tree, lambda n: Sym("v") if n is two_four else None)
    assert abs(float(value(substitute(out, {"v": Num("3")}), ENV)) - 0.5 * 9 * 3**0.5) < 1e-12


def test_a_name_inside_a_degree_and_a_sum_is_substituted() -> None:
    tree = Add(((1, Func("sin", (Deg(Sym("theta")),))), (1, Sym("theta"))))
    out = substitute(tree, {"theta": Num("30")})
    assert abs(float(value(out, ENV)) - 30.5) < 1e-12
