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


#: How maths typed in ASCII looks in a title, a statement or a question: a teacher hands out
#: "tan β = e₁ tan α" and "30°", never "tan(beta) = e_1 tan(alpha)" and "30 deg".
_ASCII_MATHS = re.compile(r"\b(?:alpha|beta|theta|lambda|phi|sqrt)\b|\b\d+ deg\b|\b[a-zA-Z]_\d\b|\b(?:sin|cos|tan)\(")


def test_bundled_problems_say_their_maths_as_printed_not_as_typed_in_ascii() -> None:
    """A bundled problem's title, statement and question are text on every page and LMS
    export: Greek letters, degrees, roots and subscripts in the characters they print as."""
    import tomllib
    from pathlib import Path

    found = []
    for path in sorted((Path(__file__).parents[1] / "problems").glob("*.toml")):
        data = tomllib.loads(path.read_text(encoding="utf-8"))
        for field in ("title", "statement", "question"):
            text = re.sub(r"\{[^{}]*\}", "", str(data.get(field, "")))  # placeholders are typeset
            found += [f"{path.stem} {field}: {m.group(0)!r}" for m in _ASCII_MATHS.finditer(text)]
    assert not found, "\n".join(found)
