"""A slip named by the model of it a teacher sees (docs/checking.md, "Naming a slip"): e moved
from the n components to the t ones is e on the t components (``e_on_t``); a term put over a
fraction's denominator without being multiplied by it is ``algebra``. Each derivation is on
another problem or phrasing than the corpus file it stands for (u09, zc13); every value is
worked by hand from the problem's givens."""

from __future__ import annotations

import sympy
from support.checked import worst_lines

from derive.checking.relations import proportional

#: OCR M3 2007: A (4 kg) at 15 m/s at α to the line of centres, sin α = 0.8, B (3 kg) at 12 m/s
#: toward it, e = 0.5: A's components before 15(0.6) = 9 along, 15(0.8) = 12 across; B's -12, 0.
#: Rightly A keeps 12 across and the separation is 0.5(9 + 12) = 10.5.
OBLIQUE = "ocr-m3-2007-oblique-sin-alpha-0p8"
BEFORE = "sin a = 0.8 so cos a = 0.6\nalong loc before: uA = 15(0.6) = 9, uB = -12\nA perp before = 15(0.8) = 12\n"


def test_e_moved_from_the_line_of_centres_to_the_tangent_is_e_on_t() -> None:
    # e put on A's component across (0.5 x 12 = 6) and taken off the separation (9 + 12 = 21)
    found = worst_lines(OBLIQUE, BEFORE + "after: A perp = 0.5 x 12 = 6, vB - vA = 9 + 12 = 21\n")
    assert [found[n][0] for n in (1, 2, 3)] == ["correct"] * 3
    assert found[4] == ("wrong", "e_on_t")


#: Edexcel M4 2018: a ball at U, α to a smooth wall, e = 3/4, α asked: rightly U cos α along the
#: wall is kept and (3/4) U sin α is the component away from it.
WALL = "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke"


def test_e_taken_off_the_normal_at_a_wall_where_the_angle_is_asked_is_e_on_t() -> None:
    # the normal component written first, without e: U sin α (an equation in sin α, α unknown)
    work = (
        "speed before U at angle alpha to the wall\n"
        "components before: along wall U cos(alpha), towards wall U sin(alpha)\n"
        "after: v_perp = U sin(alpha)\n"
        "v_par = (3/4) U cos(alpha)\n"
    )
    assert worst_lines(WALL, work)[3] == ("wrong", "e_on_t")


def test_equations_in_a_function_of_an_unknown_compare_up_to_a_factor() -> None:
    # U sin α + v = 0 and 2U sin α + 2v = 0 are one equation; U cos α + v = 0 is another
    U, v, a = sympy.symbols("U v alpha")
    pts = [{U: sympy.Rational(3, 2)}]
    assert proportional(U * sympy.sin(a) + v, 2 * U * sympy.sin(a) + 2 * v, (v, a), pts, 1e-9)
    assert not proportional(U * sympy.sin(a) + v, U * sympy.cos(a) + v, (v, a), pts, 1e-9)


#: AQA M3 2009: m at 5u catches 7m at u: 12u = x + 7y, y - x = 4eu, so 12u = 8y - 4eu,
#: y = (3 + e)u/2 and x = y - 4eu = (3 + e - 8e)u/2 = (3 - 7e)u/2.
CATCH = "aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u"
CATCH_START = (
    "x, y = velocities of A and B after\n"
    "CLM: 5mu + 7mu = mx + 7my so 12u = x + 7y\n"
    "NEL: y - x = e(5u - u) = 4eu\n"
    "x = y - 4eu so 12u = 8y - 4eu\n"
    "y = (3 + e)u/2\n"
)


def test_a_term_put_over_the_denominator_without_multiplying_is_algebra() -> None:
    # the 4eu put over the 2 as it is: (3 + e - 4e)u/2 = (3 - 3e)u/2
    found = worst_lines(CATCH, CATCH_START + "x = (3 + e)u/2 - 4eu = (3 - 3e)u/2\n")
    assert [found[n][0] for n in (2, 3, 4, 5)] == ["correct"] * 4
    assert found[6] == ("wrong", "algebra")


def test_every_term_over_the_denominator_with_a_number_wrong_stays_arithmetic() -> None:
    # 4eu = 8eu/2 rightly, then e - 8e worked as -6e: (3 - 6e)u/2
    found = worst_lines(CATCH, CATCH_START + "x = (3 + e)u/2 - 4eu = (3 - 6e)u/2\n")
    assert found[6] == ("wrong", "arithmetic")


#: Edexcel M2 2004: P (2m) at 5u hits Q (3m) at rest: 10u = 2x + 3y, y - x = 5eu, so
#: 10u = 5x + 15eu, x = (10 - 15e)u/5 and y = x + 5eu = (10 - 15e + 25e)u/5 = (10 + 10e)u/5.
PQ = "edexcel-m2-2004-june-q5-2m-at-5u-hits-3m"


def test_a_term_put_over_a_fraction_in_latex_without_multiplying_is_algebra() -> None:
    # 5eu put over the 5 as it is: (10 - 15e + 5e)u/5 = (10 - 10e)u/5
    work = r"""Let $x$ and $y$ be the velocities of P and Q after the impact.
\begin{align*}
2m(5u) &= 2m x + 3m y \quad\Rightarrow\quad 10u = 2x + 3y \\
y - x &= 5eu \\
10u &= 5x + 15eu \\
x &= \frac{(10 - 15e)u}{5} \\
y &= \frac{(10 - 15e)u}{5} + 5eu = \frac{(10 - 10e)u}{5}
\end{align*}
"""
    found = worst_lines(PQ, work)
    assert [found[n][0] for n in (3, 4, 5, 6)] == ["correct"] * 4
    assert found[7] == ("wrong", "algebra")


#: Example 4.C.11: A at 5 m/s, 37.6° from the line of impact: n 5 cos 37.6° = 3.96, t 5 sin 37.6° = 3.05.
NOTES = "notes-4c11-two-spheres"


def test_labels_after_a_gap_lead_their_own_relation_and_the_swap_is_named() -> None:
    # "n: … = 3.05   t: …": the t labels the next relation (not 3.05 t); sin and cos swapped
    assert worst_lines(NOTES, "A before   n: 5sin37.6 = 3.05   t: 5cos37.6 = 3.96\n")[1] == ("wrong", "sin_cos_swapped")


def test_a_one_word_label_after_a_value_starts_the_next_relation() -> None:
    from derive.mathtext.splitting import split_relations

    assert split_relations("x: 2cos60 = 1 y: 2sin60 = 1.73") == ["x: 2cos60 = 1", "y: 2sin60 = 1.73"]
    assert split_relations("m = 0.5 kg: T = 2")[0] == "m = 0.5 kg"  # a unit stays its value's
    assert split_relations("along: 6cos30 = 5.2   across: 6sin30 = 3") == ["along: 6cos30 = 5.2", "across: 6sin30 = 3"]


#: OCR M3 2006 (problem ocr-m3-2006-oblique-a-across-centres): A (5 kg) at 4 m/s across the line of
#: centres, B (2 kg) at 4 m/s along it toward A, e = 0.75: A keeps its 4 m/s across (no t force);
#: e put on it gives 0.75 x 4 = 3.
ACROSS = "ocr-m3-2006-oblique-a-across-centres"


def test_a_component_with_its_axis_said_first_is_that_component() -> None:
    # "⊥ cpt A after", "the perpendicular component of A after the impact": A's t component after,
    # so 3 is e put on it (not A's n component after, which no mistake gives as 3)
    for words in ("⊥ cpt A after", "the perpendicular component of A after the impact", "A's perp cpt after"):
        found = worst_lines(
            ACROSS, f"A 5kg perpendicular to loc at 4, B 2kg along loc at 4 towards A\n{words} = 0.75 x 4 = 3\n"
        )
        assert found[2] == ("wrong", "e_on_t"), words


def test_a_component_along_the_line_said_first_is_that_component() -> None:
    # B's component along the line of centres before is -4 (toward A): right as written
    found = worst_lines(ACROSS, "B's along loc component before = -4\n")
    assert found[1] == ("correct", "")
