"""Regressions of issue #12: wrong lines a worked solution showed, each with the report that found it.

Every expected number comes from the physics by hand (conservation of momentum, the
restitution law), not from derive's output.
"""

from __future__ import annotations

import re
import textwrap
from dataclasses import replace
from decimal import Decimal

import sympy

import derive
import derive.resources
from derive.numbers import format_places
from derive.problem import loads
from derive.writers.printing import adds_up


def page(text: str, fmt: str = "md") -> str:
    return derive.render(derive.solve(loads(textwrap.dedent(text), path="t.toml")), fmt)


def test_a_chain_stage_names_the_chains_quantities_not_its_own() -> None:
    # m_A of the stage is the chain's m_B (2 kg), m_B the chain's m_C (3 kg); plastic:
    # v = m_A v_A1 / (m_A + m_B) = 2 * 8 / 5 = 3.2 m/s.
    md = page(
        """
        title = "capture"
        kind = "chain"
        [given]
        m_A = "4 kg"
        m_B = "2 kg"
        m_C = "3 kg"
        [[stage]]
        type = "impact"
        kind = "direct"
        given = { m_A = "m_B", m_B = "m_C", e = 0, v_A1 = "8 m/s", v_B1 = "0 m/s" }
        results = { v_A2 = "v_D" }
        """
    )
    assert r"m_{A} = 2\ \mathrm{kg}" in md
    assert r"m_{B} = m_{C} = 3\ \mathrm{kg}" in md
    assert r"\boxed{v_{A2} = 3.20\ \mathrm{m/s}}" in md
    assert r"\boxed{v_{D} = 3.20\ \mathrm{m/s}}" in md
    assert "4.00" not in md


def test_equal_masses_other_than_one_kilogram_scale_4_before_adding() -> None:
    # 2 v_A2 + 2 v_B2 = 4 and v_B2 - v_A2 = 0: adding (3) and (4) as they stand cancels
    # nothing; 2 x (4) added to (3) gives 4 v_B2 = 4, so v_B2 = 1 m/s.
    md = page(
        """
        title = "equal masses"
        kind = "direct"
        [given]
        m_A = "2 kg"
        m_B = "2 kg"
        e = 0
        v_A1 = "2 m/s"
        v_B1 = 0
        """
    )
    assert "Add (3) and (4)" not in md
    assert "Multiply (4) by $2$ and add it to (3): $v_{A2}$ cancels." in md
    assert "4 v_{B2} = 4 + 0" in md
    assert "3 v_{B2}" not in md
    assert r"\boxed{v_{A2} = 1.000\ \mathrm{m/s}}" in md


def test_an_angle_defined_in_a_chain_is_shown_in_degrees() -> None:
    md = page(
        """
        title = "angle"
        kind = "chain"
        [given]
        th = "-14.036 deg"
        [[stage]]
        type = "define"
        expr = "-th"
        result = "beta"
        """
    )
    assert r"\beta = -th = 14.036^\circ = 14.04^\circ" in md
    assert "0.245" not in md


def test_tiny_masses_are_written_with_powers_of_ten() -> None:
    # equal masses, e = 1: the velocities are exchanged, v_A2 = 0, v_B2 = 2e6 m/s
    md = page(
        """
        title = "protons"
        kind = "direct"
        [given]
        m_A = "1.67e-27 kg"
        m_B = "1.67e-27 kg"
        e = 1
        v_A1 = "2e6 m/s"
        v_B1 = 0
        """
    )
    assert r"m_{A} = 1.67 \times 10^{-27}\ \mathrm{kg}" in md
    assert "0.0000" not in md and "0.00 " not in md and not re.search(r"\b0\.00\b", md)
    assert r"\boxed{v_{B2} = 2.00 \times 10^{6}\ \mathrm{m/s}}" in md
    assert r"\boxed{v_{A2} = 0\ \mathrm{m/s}}" in md


def test_a_sum_that_cannot_add_up_at_the_figures_shown_is_not_shown_term_by_term() -> None:
    # 4.C.11 with other numbers: 29(6.5 cos 37.6°) - 2(14 cos 37.6°) = 127.16...; at four
    # figures 149.3 - 22.18 does not make 127.2, so the page goes straight to (3).
    text = derive.resources.problems_dir().joinpath("notes-4c11-two-spheres.toml").read_text()
    text = text.replace('m_A = "20 kg"', 'm_A = "29 kg"').replace('m_B = "5 kg"', 'm_B = "2 kg"')
    text = text.replace("e = 0.6", "e = 0.7").replace('v_A1 = "5 m/s"', 'v_A1 = "6.5 m/s"')
    text = text.replace('v_B1 = "15 m/s"', 'v_B1 = "14 m/s"')
    md = derive.render(derive.solve(loads(text, path="t.toml")), "md")
    assert "149.3466" not in md and "127.1625" not in md
    assert r"29 v_{A2n} + 2 v_{B2n} = 127.2 \tag{3}" in md
    assert r"= 127.2" in md.split("## 3) Solve")[1]


def test_later_chain_stages_refer_to_equations_that_exist() -> None:
    md = derive.render(derive.solve(derive.load("chain-edexcel-m2-three-particles")), "md")
    tags = set(re.findall(r"\\tag\{(\d+)\}", md))
    refs = re.findall(r"(?:From|Add|Subtract|into|Solve) \((\d+)\)(?: (?:and|from) \((\d+)\))?", md)
    assert refs
    for pair in refs:
        assert {r for r in pair if r} <= tags
    assert "Add (15) and (10)" not in md


def test_the_printer_writes_one_over_tan_as_a_fraction() -> None:
    import sympy

    from derive.writers.printing import StepPrinter

    alpha = sympy.Symbol("alpha", real=True)
    assert StepPrinter().doprint(-1 / sympy.tan(alpha)) == r"-\frac{1}{\tan {\alpha}}"
    assert "1 \\tan" not in StepPrinter().doprint(sympy.atan(-1 / sympy.tan(alpha)))


def test_example_4c12_marks_only_the_angle_it_asks_for() -> None:
    md = derive.render(derive.solve(derive.load("notes-4c12-cue-ball")), "md")
    marked = [ln for ln in md.splitlines() if "ANSWER" in ln]
    assert len(marked) == 1 and r"\theta_{A2}" in marked[0]


def test_example_4c11_marks_both_velocity_vectors_as_the_notes_do() -> None:
    """The notes mark the pair of velocity vectors after the impact as the ANSWER (issue #28):
    both vectors are boxed and marked, nothing else is."""
    md = derive.render(derive.solve(derive.load("notes-4c11-two-spheres")), "md")
    answer = md.split("## 4) Answer")[1].split("Kinetic energy")[0]
    marked = [ln for ln in answer.splitlines() if "ANSWER" in ln]
    assert len(marked) == 2
    assert r"\vec{v}_{A2} = \left(3.05 \hat{e}_{t} - 1.11 \hat{e}_{n}\right)" in marked[0]
    assert r"\vec{v}_{B2} = \left(-9.15 \hat{e}_{t} + 8.40 \hat{e}_{n}\right)" in marked[1]


def test_a_chain_carries_no_number_before_the_unknown_it_depends_on_is_found() -> None:
    # OCR M2 January 2007 Q3 (mark scheme: impact speed 35, rebound 28, e = 0.8, I = 12.6)
    md = derive.render(derive.solve(derive.load("chain-ocr-m2-2007-rebounds-to-start")), "md", figures=False)
    before, after = md.split("**Solution.**")[1].split("## Stage 5")
    assert "-28.0" not in before and "12.6" not in before  # e is found in stage 5
    assert r"u = -35 e_{\mathrm{floor}}\ \mathrm{m/s} \tag{2}" in before  # the floor stage in the chain's names (#28)
    assert r"J = m \left(v_{1} - u\right)" in before  # the impulse is worked out (in the chain's names)
    assert r"v_{2} = -u = -u" not in md
    assert r"h_{2} = 62.5 e_{\mathrm{floor}}^{2} = 40.0\ \mathrm{m}" in after  # the algebra of the solve stage
    assert r"e_{\mathrm{floor}} = 0.800" in after
    assert r"u = -35 e_{\mathrm{floor}} = -28.0\ \mathrm{m/s}" in after
    assert r"J = 7 + 7 e_{\mathrm{floor}} = 12.6\ \mathrm{N\cdot s}" in after  # 7 (1 + 0.8)
    # the file asks for v_1, v_2, e_floor and J: each marked in the chain's Answer, nothing before it
    assert md.count("ANSWER") == 4 and "ANSWER" not in md.split("## Answer")[0]


def test_the_kinetic_energy_lost_is_not_shown_as_a_difference_that_does_not_add_up() -> None:
    # 4.C.11: T_1 = 20·5²/2 + 5·15²/2 = 812.5 J exactly, shown 813 J; with the notes' rounded
    # velocities T_2 = 10(3.05² + 1.11²) + 2.5(9.15² + 8.40²) = 491 J. The loss, from its own
    # closed form m_A m_B/(2(m_A + m_B)) (1 - e²)(v_A1n - v_B1n)², is 321 J: not "813 - 491 = 321".
    md = derive.render(derive.solve(derive.load("notes-4c11-two-spheres")), "md")
    energy = md.split("Kinetic energy, for the record")[1]
    assert re.search(r"T_\{1\} = .* = 813\\ \\mathrm\{J\}", energy)
    assert re.search(r"T_\{2\} = .* = 491\\ \\mathrm\{J\}", energy)
    lost = re.search(r"T_\{\\mathrm\{lost\}\} = (.*) = ([\d.]+)\\ \\mathrm\{J\}", energy)
    assert lost and lost.group(2) == "321" and "T_{1} - T_{2}" not in lost.group(1)
    assert r"\left(1 - e^{2}\right)" in lost.group(1)


def test_letters_are_written_exactly_where_the_data_are_exact() -> None:
    # m_A = m, m_B = 2m, B at rest, A at u, e kept as a letter. By hand from (3) and (4):
    # v_A2 = u(1 - 2e)/3, v_B2 = u(1 + e)/3, T_2 = m u^2 (1 + 2e^2)/6.
    md = page(
        """
        title = "letters"
        kind = "direct"
        [given]
        m_A = "m"
        m_B = "2*m"
        m = "kg"
        e = "e"
        v_A1 = "u"
        v_B1 = "0 m/s"
        u = "m/s"
        """
    )
    assert r"\boxed{v_{A2} = \frac{u \left(1 - 2 e\right)}{3}}" in md
    assert r"\boxed{v_{B2} = \frac{u \left(e + 1\right)}{3}}" in md
    assert r"\frac{m u^{2} \left(2 e^{2} + 1\right)}{6}" in md
    assert "1.000" not in md and "0.333" not in md and "0.500" not in md


def test_example_4c12_keeps_the_notes_root_two_over_two() -> None:
    """(1) keeps the notes' √2/2; a sum is written at one precision (issue #28: never
    (√2/2) v_A1 + 0.6364 v_A1 in one line), so no line mixes √2 with a decimal."""
    md = derive.render(derive.solve(derive.load("notes-4c12-cue-ball")), "md")
    assert r"v_{A2t} = \frac{\sqrt{2}}{2} v_{A1} \tag{1}" in md
    for line in md.splitlines():
        assert not ("sqrt{2}" in line and re.search(r"\b0\.\d{3,} v_", line)), line


def test_parts_of_a_nested_radical_are_one_term() -> None:
    """Edexcel M4 2018 Q2 (issue 14): the ball leaves the wall with the normal component
    3/4 U sin(alpha), sin^2(alpha) = 32/35 (the mark scheme's tan^2 alpha = 32/3), so
    v_A2n = -0.75 sqrt(32/35) U = -0.717 U; the page wrote it as -0.555 U - 0.1624 U."""
    import math

    md = derive.render(derive.solve(derive.load("edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke")), "md")
    want = f"{-0.75 * math.sqrt(32 / 35):.3f} U"
    assert want == "-0.717 U"
    assert f"v_{{A2n}} = {want}" in md
    assert not re.search(r"-?\d\.\d+ U [-+] \d\.\d+ U", md), "two rounded parts of one coefficient"


# ---------------------------------------------------------------- sums, figures and units (#12)


def _sums_add_up(md: str) -> list[str]:
    """Lines ``x = a ± b = c`` (plain numbers) whose a ± b, added by hand, does not round to c."""
    wrong = []
    for a, sign, b, c in re.findall(r"= (-?\d+\.?\d*) ([+-]) (\d+\.?\d*) = (-?\d+\.?\d*)", md):
        total = Decimal(a) + (Decimal(b) if sign == "+" else -Decimal(b))
        places = len(c.partition(".")[2])
        if abs(total - Decimal(c)) > Decimal(1).scaleb(-places) / 2:
            wrong.append(f"{a} {sign} {b} = {c}")
    return wrong


def _variant(text: str, values: dict[str, sympy.Expr], fmt: str = "md") -> tuple[str, list]:
    """One homework variant's page with ``values``, and the verifier's failures on it."""
    from derive.homework import variants
    from derive.verifier import verify_text
    from derive.verifier.facts import facts_of

    problem = loads(text, path="t.toml")
    compiled = variants.compile_problem(problem)
    filled = variants.fill(compiled, variants.Variant(1, values), fmt)
    known = {g.symbol: values[g.name] for g in problem.givens if g.name in values}
    mine = replace(
        problem,
        givens=tuple(replace(g, value=known[g.symbol]) if g.symbol in known else g for g in problem.givens),
    )
    return filled, verify_text(filled, facts_of(mine), fmt).failures


def _notes_4c11(**given: str) -> str:
    text = derive.resources.problems_dir().joinpath("notes-4c11-two-spheres.toml").read_text()
    for name, value in given.items():
        text = re.sub(rf"^{name} = .*$", f"{name} = {value}", text, count=1, flags=re.M)
    return text


def test_back_into_4_shows_its_sum_only_where_the_rounded_terms_add_up() -> None:
    # 4.C.11 with m_A = 16 kg, m_B = 6.5 kg, e = 0.8, v_A1 = 5 m/s, v_B1 = 19 m/s. With
    # c = cos 37.6°: (3) 16 x + 6.5 y = 80c - 123.5c, (4) y - x = 0.8 (5c + 19c) = 19.2c, so
    # 22.5 x = -43.5c - 6.5 (19.2c) and x = -7.48c = -5.9263, y = 11.72c = 9.2856 -> 9.29.
    # At the figures an intermediate shows, -5.926 + 15.21 = 9.284 is 9.28, not 9.29: the
    # notes' 79.2 - 59.5 = 19.8 again. The line goes straight to the value.
    text = _notes_4c11(m_A='"16 kg"', m_B='"6.5 kg"', e="0.8", v_A1='"5 m/s"', v_B1='"19 m/s"')
    md = derive.render(derive.solve(loads(text, path="t.toml")), "md")
    back = md.split("Back into (4):")[1].split("##")[0]
    assert r"= 9.29\ \mathrm{m/s}" in back
    assert not _sums_add_up(md)
    values = {"m_A": sympy.Integer(16), "m_B": sympy.Rational(13, 2), "e": sympy.Rational(4, 5)}
    values |= {"v_A1": sympy.Integer(5), "v_B1": sympy.Integer(19)}
    for fmt in ("md", "tex"):
        page, failures = _variant(text, values, fmt)
        assert not failures, failures
        assert r"v_{B2n} = 9.29\ \mathrm{m/s}" in page
        assert "-5.926 + 15.21" not in page and not _sums_add_up(page)


def test_the_notes_sum_back_into_4_is_kept_where_it_adds_up() -> None:
    # the notes' own line: -1.11 + 9.51 = 8.40
    md = derive.render(derive.solve(derive.load("notes-4c11-two-spheres")), "md")
    assert r"v_{B2n} = -1.11 + 9.51 = 8.40\ \mathrm{m/s}" in md


def test_a_variants_fraction_shows_no_more_figures_than_the_rule() -> None:
    # 4.C.11 with m_A = 12 kg, m_B = 6 kg, e = 0.5, v_A1 = 3 m/s, v_B1 = 20 m/s; c = cos 37.6°:
    # (3) gives 36c - 120c = -84c, (4) 0.5 (23c) = 11.5c; the numerator -84c - 6 (11.5c) =
    # -153c = -121.22, at the four figures of an intermediate -121.2.
    values = {"m_A": sympy.Integer(12), "m_B": sympy.Integer(6), "e": sympy.Rational(1, 2)}
    values |= {"v_A1": sympy.Integer(3), "v_B1": sympy.Integer(20)}
    page, failures = _variant(_notes_4c11(), values)
    assert not failures, failures
    # a variant's page is the solve's: the notes' "19.8 - 5(9.5)", at the figures of an intermediate
    assert r"\frac{-66.55 - 6 \cdot 9.11}{18} = -6.73\ \mathrm{m/s}" in page and "121.22" not in page
    assert r"v_{A2n} \left(12 + 6\right) = -66.55 - 6 \cdot 9.11" in page  # as the notes: v_A2n (20 + 5)


def test_a_variant_whose_masses_add_to_one_keeps_the_unit_of_each_velocity() -> None:
    # m_A = m_B = 0.5 kg, e = 0, v_A1 = 5.5 m/s, v_B1 = -1 m/s: they move together at
    # (0.5 * 5.5 - 0.5 * 1) / 1 = 2.25 m/s. "v_A2 = 2.25 + 0" would be a velocity without a unit.
    from support import verify_corpus

    text = verify_corpus.VARY[0].text
    values = {"m_A": sympy.Rational(1, 2), "m_B": sympy.Rational(1, 2), "e": sympy.Integer(0)}
    values |= {"v_A1": sympy.Rational(11, 2)}
    for fmt in ("md", "tex"):
        page, failures = _variant(text, values, fmt)
        assert not failures, failures
        assert r"v_{A2} = 2.25 + 0 = 2.25" in page
        assert r"\boxed{v_{A2} = 2.25\ \mathrm{m/s}}" in page


def test_a_value_carried_into_a_chain_stage_is_rounded_like_any_intermediate() -> None:
    # equal masses, e = 0.1, A at 8.25 m/s onto B at rest: v_B2 = (1 + e) v_A1 / 2 =
    # 0.55 * 8.25 = 4.5375 m/s exactly; stage 2 is not given 4.5375 in a file, so it shows
    # 4.538 (four figures for an intermediate), never all five.
    md = page(
        """
        title = "three particles"
        kind = "chain"
        [given]
        m = "5 kg"
        e = 0.1
        [[stage]]
        type = "impact"
        kind = "direct"
        given = { m_A = "m", m_B = "m", e = "e", v_A1 = "8.25 m/s", v_B1 = "0 m/s" }
        results = { v_B2 = "u_B" }
        [[stage]]
        type = "impact"
        kind = "direct"
        given = { m_A = "m", m_B = "2*m", e = "e", v_A1 = "u_B", v_B1 = "0 m/s" }
        results = { v_B2 = "u_C" }
        """
    )
    assert "4.5375" not in md
    assert r"v_{A1} = u_{B} = 4.538\ \mathrm{m/s}" in md
    assert r"4.538 \cdot 5 + 0 \cdot 10 = 5 v_{A2} + 10 v_{B2}" in md


def test_numbers_at_shared_places_keep_to_the_rule() -> None:
    assert format_places(Decimal("-121.2166"), 2, 3, 1) == "-121.2"  # five figures at 2 places
    assert format_places(Decimal("19.8133"), 2, 3, 1) == "19.81"
    assert format_places(Decimal("0.5"), 3, 3, 1) == "0.500"


def test_a_printed_sum_adds_up_as_a_reader_adds_it() -> None:
    assert adds_up("-1.11 + 9.51", "8.40")  # the notes, 4.C.11
    assert adds_up("79.23 - 59.42", "19.81")
    assert not adds_up("79.2 - 59.5", "19.8")  # the notes' slip: 79.2 - 59.5 is 19.7
    assert not adds_up("-5.926 + 15.21", "9.29")
    assert not adds_up(r"-8.971 \times 10^{6} + 9 \times 10^{6}", "28800")  # 29000
    assert adds_up(r"\left(-3\right) + 5", "2")
    assert adds_up("x + 3", "4")  # letters: nothing to add
