"""A statement's numbers read as the file typed them, in the solve and in every variant
(issue 15): the places typed ("2.50 m/s"), the unit typed ("22 g", "36 km/h") and a
speed given as a signed component (``{|v_B1|}``)."""

from __future__ import annotations

import re
from decimal import Decimal

import sympy

import derive
from derive.homework import variants
from derive.problem import loads

CARTS = """
title = "Two carts"
kind = "direct"
statement = "Cart A ({m_A}) at {v_A1} meets cart B ({m_B}) coming the other way at {|v_B1|}; e = {e}."
[given]
m_A = "22 g"
m_B = "2.0 kg"
e = 0.5
v_A1 = "2.50 m/s"
v_B1 = "-1.20 m/s"
[vary]
v_A1 = { min = "2 m/s", max = "4 m/s", step = "0.125 m/s" }
v_B1 = { choices = ["-1 m/s", "-1.5 m/s"] }
m_A = { choices = ["20 g", "36 g"] }
"""


def _given_paragraph(md: str) -> str:
    start = md.index("**Given.**")
    return md[start : md.index("\n", start)]


def _problem():
    return loads(CARTS, path="carts.toml")


def test_a_solve_prints_the_numbers_as_typed() -> None:
    md = derive.render(derive.solve(_problem()), "md")
    said = _given_paragraph(md)
    # 2.50 keeps its zero, 22 g stays in grams (not 0.022 kg), B's speed is 1.20, not -1.20
    assert "Cart A (22 g) at 2.50 m/s meets cart B (2.0 kg) coming the other way at 1.20 m/s; e = 0.5." in said


def test_the_given_list_still_works_in_the_working_units() -> None:
    md = derive.render(derive.solve(_problem()), "md")
    assert r"m_{A} = 22\ \mathrm{g} = 0.022\ \mathrm{kg}" in md
    assert r"v_{B1} = -1.2\ \mathrm{m/s}" in md


def test_each_variant_prints_its_numbers_with_the_places_and_unit_typed() -> None:
    compiled = variants.compile_problem(_problem())
    seen = set()
    for v in variants.draw(compiled, 30, seed=4):
        said = _given_paragraph(variants.fill(compiled, v))
        v_A1 = v.values["v_A1"]
        # at least the two places typed, more where the drawn value needs them (2.125)
        places = max(2, len(str(sympy.Float(v_A1)).rstrip("0").partition(".")[2]))
        shown_v = f"{float(v_A1):.{places}f}"
        grams = int(v.values["m_A"] * 1000)
        speed_B = f"{abs(float(v.values['v_B1'])):.2f}"
        assert f"Cart A ({grams} g) at {shown_v} m/s meets" in said, said
        assert f"coming the other way at {speed_B} m/s;" in said, said
        seen.add(shown_v)
    assert {"2.00", "2.125"} & seen or len(seen) > 5  # whole and longer values both occur


def test_a_magnitude_of_a_letter_or_an_unknown_name_stays_as_typed() -> None:
    text = CARTS.replace("{|v_B1|}", "{|u|} or {|nothing|}").replace("e = 0.5", 'e = 0.5\nu = "m/s"')
    said = _given_paragraph(derive.render(derive.solve(loads(text, path="c.toml")), "md"))
    assert r"coming the other way at {\|u\|} or {\|nothing\|};" in said  # Markdown escapes the bars


def test_a_bundled_statement_reads_as_before_with_placeholders() -> None:
    """The bundled files whose statements now use placeholders read as they were typed."""
    cases = {
        "openstax-cp-8-train-cars-couple": "velocity 0.300 m/s; the other has mass 110,000 kg and velocity -0.120 m/s",
        "gramoll-ecourses-two-balls-elastic": "ball B moves at 3 m/s straight along",
        "young-freedman-8-96-pucks-find-mass": "blue puck of mass 0.0400 kg slides at 0.200 m/s",
    }
    for name, text in cases.items():
        assert text in _given_paragraph(derive.render(derive.solve(derive.load(name)), "md")), name


def test_a_question_can_state_the_value_derive_finds() -> None:
    """aqa-fm: "show that e = {=e}" reads "show that e = 0.8" in the solve (as typed before)
    and, in each variant, the e that variant's numbers give: the key's number (a variant's page
    is the solve's, which writes an exact short decimal as it is: 0.4875 where the key has 0.488)."""
    problem = derive.load("aqa-fm-specimen-discs-show-e-0p8")
    md = derive.render(derive.solve(problem), "md")
    assert "**Find.** Find the velocity of B after the collision and show that e = 0.8." in md
    compiled = variants.compile_problem(problem)
    for v in variants.draw(compiled, 6, seed=3):
        page = variants.fill(compiled, v)
        shown = variants.answers(compiled, v)["e"]["shown"]
        said = re.search(r"show that e = ([\d.]+)\.", page)
        assert said is not None, page[:2000]
        half = Decimal(1).scaleb(Decimal(shown).as_tuple().exponent) / 2  # half the key's last place
        assert abs(Decimal(said.group(1)) - Decimal(shown)) <= half, (said.group(1), shown)


def test_a_found_value_placeholder_of_no_result_stays_as_typed() -> None:
    text = CARTS.replace("; e = {e}.", "; {=nothing} and {=m_A}.")
    said = _given_paragraph(derive.render(derive.solve(loads(text, path="c.toml")), "md"))
    assert said.endswith(r"; {=nothing} and {=m\_A}.")  # a given is no found value (Markdown escapes _)
