"""Issue #28: what a teacher sees on the pages, looked at as PNG (every bundled PDF, a student
sheet, a key, a handout, variants): the slips a glance showed, each held here where a test can
see it (the PDF ones are in test_page_breaks.py and test_pdf_margins.py)."""

from __future__ import annotations

import re

from support.output_cases import solution

import derive


def test_a_given_kept_as_a_letter_says_its_unit_without_nested_parentheses() -> None:
    # was "m (kept as a symbol (kg))", "alpha (kept as a symbol (°))" in the Given list
    md = derive.render(solution("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta"), "md", figures=False)
    notes = dict(re.findall(r"^- \$(.+?)\$ \((.*)\)$", md, flags=re.M))
    assert notes["m"] == "kept as a symbol, in kg"
    assert notes["U"] == "kept as a symbol, in m/s"
    assert notes["e_{1}"] == "kept as a symbol, a pure number"
    assert notes[r"\alpha"] == "kept as a symbol, in degrees"
    tex = derive.render(solution("notes-4c12-cue-ball"), "tex")
    assert r"\item $v_{A1}$ (kept as a symbol, in m/s)" in tex and "(kept as a symbol (" not in tex
