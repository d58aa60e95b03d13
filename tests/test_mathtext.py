"""derive/mathtext: the one reader of typed mathematics for the checker and the verifier (issue
#25 item 5). The verifier reads derive's pages with mathtext's parser strictly (numbers keep their
figures); a student's LaTeX row is read by the same parser leniently and printed back as plain text.

Values: Example 4.C.11 of the course notes, v_A2n = -1.11 m/s, v_B2n = 8.4 m/s.
"""

from __future__ import annotations

import time

import pytest

import derive
from derive.mathtext import latex, parser
from derive.mathtext.display import parse_display
from derive.mathtext.latex import latex_to_plain
from derive.mathtext.reader import read_relations
from derive.mathtext.tokens import LatexError
from derive.mathtext.tree import Hat, Mul, Num, Pow, Sym


def test_the_students_reader_is_the_verifiers_parser() -> None:
    assert latex.Parser is parser.Parser
    assert not hasattr(latex, "fracs")  # no second grammar of fractions beside the parser
    assert latex_to_plain(r"v = 3.050 \times 10^{-2}") == "v = 3.050 * 10^(-2)"


@pytest.mark.parametrize(
    ("tex", "plain"),
    [
        (r"e^2 (\text{approach speed})^2", "e^2 (approach speed)^2"),
        (r"(\text{speed of the pair})^2 = 4", "(speed of the pair)^2 = 4"),
        (r"p = \frac{\text{change in momentum}}{\text{time}}", "p = (change in momentum)/(time)"),
        (r"\sqrt{\text{sum of squares}} = 5", "sqrt(sum of squares) = 5"),
    ],
)
def test_words_inside_a_power_a_fraction_or_a_root_are_kept(tex: str, plain: str) -> None:
    assert latex_to_plain(tex) == plain  # a factor in words is never left out


@pytest.mark.parametrize(
    ("tex", "plain"),
    [
        (r"\sin^2\theta + \cos^{2}\theta = 1", "sin(theta)^2 + cos(theta)^2 = 1"),
        (r"e \geq 0", "e >= 0"),
        (r"v_{A,2}' = \tfrac12 u", "v_A2' = (1/2) u"),
        (r"w = \frac u2 + \tfrac mM", "w = u/2 + m/M"),  # TeX takes one letter without braces
        (r"\vec v_{B} = \bigl(3\,\hat\imath\bigr)", "v_B = (3 i_hat)"),
        (r"u_A = a\mathbf{i} + 12\mathbf{j}", "u_A = a i + 12 j"),
        (r"x = 2(9.8)h \Rightarrow h = 1.41", r"x = 2(9.8)h \Rightarrow h = 1.41"),
        (r"\boxed{v = 2} \quad (3)", "(v = 2) (3)"),
        (r"v = \frac{u(2e-1)}{3}.", "v = (u(2e - 1))/3."),
        (r"\mu = \frac{1}{2}mu", "μ = (1/2)mu"),
        (r"\frac{\sin\theta}{2} = \tan \frac{x}{2}", "(sin theta)/2 = tan(x/2)"),
        (r"\text{KE}_{\text{lost}} = 5", "KE_lost = 5"),
        (r"v = 36\,\text{km/h}, m = 500\,\mathrm{g}", "v = 36 km/h, m = 500 g"),
    ],
)
def test_a_students_latex_is_read_through_the_tree(tex: str, plain: str) -> None:
    assert latex_to_plain(tex) == plain


def test_what_the_parser_refuses_is_kept_as_written() -> None:
    assert latex_to_plain(r"a = \frac{b}{c \unknown") == r"a = \frac(b)(c \unknown"
    assert latex_to_plain(r"v = \frac{-1.11}") == r"v = \frac(-1.11)"  # never "v = -1.11"


def test_a_row_the_parser_cannot_take_is_reported_not_read() -> None:
    work = "$v_{A2n} = \\frac{-1.11}$\n$v_{B2n} = 8.4$\n"  # a fraction without its denominator
    report = derive.check(derive.solve(derive.load("notes-4c11-two-spheres")), derivation=work)
    assert [(i.name, i.status) for i in report.items] == [("1", "not read"), ("2", "correct")], report.text()


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


HOSTILE = [
    "(" * 3000 + "x",
    r"\sqrt" * 3000,
    "x^{" * 3000 + "2",
    r"\frac{" * 2000,
    "a " * 3000 + r"\frac{",
    "x = " + "1 + " * 100 + r"\frac{",
    "x = " + "a + " * 5000 + ")",  # 10,000 tokens
    "x = " + "(a) " * 2500 + "=",  # 10,000 tokens
]


@pytest.mark.parametrize("row", HOSTILE)
def test_a_hostile_row_stays_cheap(row: str) -> None:
    start = time.process_time()
    assert latex_to_plain(row)
    assert time.process_time() - start < 1.0


@pytest.mark.parametrize("row", HOSTILE)
def test_a_hostile_row_is_refused_with_a_latex_error(row: str) -> None:
    start = time.process_time()
    with pytest.raises(LatexError):  # not RecursionError
        parser.Parser(row, lenient=True).relations()
    assert time.process_time() - start < 1.0


@pytest.mark.parametrize(
    ("text", "plain"),
    [
        ("sqrt3 u", "sqrt(3)*u"),  # the root of 3 times u, as √3 u is
        ("(sqrt2/2) v", "(sqrt(2)/2)*v"),
        ("1/sqrt5", "1/sqrt(5)"),
        ("w/(sqrt3(1+k))", "w/(sqrt(3)*(1+k))"),
        ("sqrt 7", "sqrt(7)"),
        ("2sqrt3", "2*sqrt(3)"),
        ("u root2/2", "u*sqrt(2)/2"),
        ("x_sqrt3", "x_sqrt3"),  # part of a name: kept
    ],
)
def test_a_root_glued_to_its_number_is_the_root(text: str, plain: str) -> None:
    from derive.mathtext.notation import student

    assert student(text) == plain


@pytest.mark.parametrize(
    "mark", ["∎", "□", "■", "QED", "Q.E.D.", "qed", r"\qed", r"\blacksquare", r"\square", "//", "(!!)", "(?)"]
)
def test_the_mark_that_ends_a_proof_is_not_part_of_the_relation(mark: str) -> None:
    assert [r.sides for r in read_relations(f"(2 + k) w = 3 p   {mark}")] == [("(2 + k) w", "3 p")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("V = 4.1 x 2 = 8.2 m/s   (~29.5 km/h!!)", ("V", "4.1 x 2", "8.2")),
        ("W = 19.6 N (about 2 kg)", ("W", "19.6")),
        ("E = 2400 J (= 2.4 kJ)", ("E", "2400")),
        ("V = 8.2 m/s - about 29.5 km/h", ("V", "8.2")),
        ("V = 8.2 m/s — roughly 18 mph!", ("V", "8.2")),
        ("x = 2 - about 3 m", ("x", "2 - about 3")),  # no unit before the dash: not an aside
        ("v = 2u (1.5 m/s)", ("v", "2u (1.5)")),  # no unit before it: not an aside (a factor; its unit taken off)
        ("x = 4 (3 + y)", ("x", "4 (3 + y)")),
    ],
)
def test_the_value_again_in_another_unit_in_brackets_is_a_remark(text: str, expected: tuple[str, ...]) -> None:
    assert [r.sides for r in read_relations(text)] == [expected]


@pytest.mark.parametrize(
    ("tex", "plain"),
    [
        (r"w = 3.5\ \text{m/s along } t", "w = 3.5 along t"),  # the unit dropped, the words kept
        (r"w = 3.5\ \text{ft/s along the line}", "w = 3.5"),
        (r"w = 3.5\ \text{m/s}", "w = 3.5"),
    ],
)
def test_a_unit_and_then_words_in_one_text_is_a_unit_and_words(tex: str, plain: str) -> None:
    assert latex_to_plain(tex) == plain


def test_a_unit_and_words_before_a_unit_vector_stay_a_component() -> None:
    assert ("w_t", "3.5") in [r.sides for r in read_relations(r"\[ w = 3.5\ \text{m/s along }\hat t \]")]


@pytest.mark.parametrize("unit", ["lb s", "lb·s", "lb-s", "lbf s", "N-s", "slug ft/s", "lb ft/s"])
def test_an_impulse_or_momentum_in_imperial_units_is_a_unit(unit: str) -> None:
    from derive.mathtext.units import is_unit

    assert is_unit(unit)
    assert [r.sides for r in read_relations(rf"\[ I = 0.84\ \text{{{unit}}} \]")] == [("I", "0.84")]


@pytest.mark.parametrize(
    "text",
    [
        r"$3(4) = 2(3) + 6$ \checkmark",
        r"$3(4) = 2(3) + 6 \ding{51}$",
        r"$3(4) = 2(3) + 6$ \ding{52} checks",
        r"$3(4) = 2(3) + 6$ \cmark",
        r"$3(4) = 2(3) + 6$ \tick",
        "*3(4) = 2(3) + 6*",
        "- **3(4) = 2(3) + 6**",
    ],
)
def test_a_tick_or_emphasis_around_a_relation_is_layout(text: str) -> None:
    assert [r.sides for r in read_relations(text)] == [("3(4)", "2(3) + 6")]


def test_stars_between_factors_are_products_not_italics() -> None:
    assert [r.sides for r in read_relations("y = 2*k*3 = 6k")] == [("y", "2*k*3", "6k")]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("(v_A)_1 + 2 (v_B)_1 = 7", ("v_A1 + 2 v_B1", "7")),
        (r"\[ (v_{P})_{2} = 0.4(6.5) = 2.6\ \text{ft/s} \]", ("v_P2", "0.4(6.5)", "2.6")),
        (r"\[ (v_Q)_2 &= (v_Q)_{1} + 3 \]", ("v_Q2", "v_Q1 + 3")),
    ],
)
def test_a_name_in_brackets_with_its_instant_after_them_is_one_name(text: str, expected: tuple[str, ...]) -> None:
    assert [r.sides for r in read_relations(text)] == [expected]
