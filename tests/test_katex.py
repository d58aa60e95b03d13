"""Every formula derive writes into Markdown (and JSON) is valid KaTeX.

All formulas of all problems go to KaTeX in one node call (see katex_check.py).
Needs ``npm ci --prefix tests/katex``; in CI a missing node or KaTeX fails.
"""

from __future__ import annotations

import json

import pytest
from support.katex_check import Formula, MarkdownMathError, describe, katex_errors, markdown_formulas
from support.output_cases import bundled_names, hostile_problem, solution

import derive

# ---------------------------------------------------------------- the extractor itself


def test_extracts_display_and_inline_math():
    md = "\n".join(
        [
            "# Title with \\$5 and a\\_b",
            "",
            "Text $x_1$ and \\$ not math \\$, then $\\frac{a}{b}$.",
            "",
            "$$",
            "a = b \\tag{1}",
            "$$",
            "",
            "- $m = 2\\ \\mathrm{kg}$ (a note with \\\\ and \\`)",
            "Inline display $$y$$ here, and $\\$ \\text{in math}$ too.",
        ]
    )
    got = [(f.tex, f.display) for f in markdown_formulas(md)]
    assert got == [
        ("x_1", False),
        ("\\frac{a}{b}", False),
        ("a = b \\tag{1}", True),
        ("m = 2\\ \\mathrm{kg}", False),
        ("y", True),
        ("\\$ \\text{in math}", False),
    ]


def test_escaped_dollars_and_code_are_not_math():
    assert markdown_formulas("costs \\$3 and \\$4, `$x$` in code, \\\\$y$") == [Formula("y", False, "<md>:1")]
    assert markdown_formulas("```\n$$\n$x\n```\n") == []


@pytest.mark.parametrize("md", ["a $x", "$$\nx = 1\n", "a \\\\$x"])
def test_unclosed_math_is_an_error(md):
    with pytest.raises(MarkdownMathError):
        markdown_formulas(md)


# ---------------------------------------------------------------- KaTeX


@pytest.mark.slow
def test_checker_catches_an_error():
    errors = katex_errors(
        [
            Formula("\\frac{1}{", False, "bad-1"),
            Formula("x = 1", False, "good"),
            Formula("\\SI{5}{m/s}", True, "bad-2"),
        ]
    )
    assert [e["where"] for e in errors] == ["bad-1", "bad-2"]
    assert "KaTeX parse error" in errors[0]["error"]
    assert errors[0]["tex"] == "\\frac{1}{"


def _json_formulas(name: str, data: dict) -> list[Formula]:
    out = []
    for key, r in data["results"].items():
        out.append(Formula(r["latex"], True, f"{name}.json:results.{key}.latex"))
    for stage in data["stages"]:
        for k, block in enumerate(stage["blocks"]):
            where = f"{name}.json:stage {stage['number']} block {k}"
            out.extend(markdown_formulas(block["text"], where) if block["text"] else [])
            for line in block["lines"]:
                tex = line["latex"] + (f" \\tag{{{line['tag']}}}" if line["tag"] else "")
                out.append(Formula(tex, True, where))
    return out


@pytest.fixture(scope="module")
def all_formulas(tmp_path_factory) -> dict[str, list[Formula]]:
    """Formulas per document: the Markdown of every bundled problem (+ the hostile one) and their JSON."""
    docs: dict[str, list[Formula]] = {}
    for name in bundled_names():
        s = solution(name)
        docs[f"{name}.md"] = markdown_formulas(derive.render(s, "md"), f"{name}.md")
        docs[f"{name}.json"] = _json_formulas(name, json.loads(derive.render(s, "json")))
    hostile = derive.solve(derive.load(hostile_problem(tmp_path_factory.mktemp("katex"))))
    docs["hostile-direct.md"] = markdown_formulas(derive.render(hostile, "md"), "hostile-direct.md")
    return docs


@pytest.fixture(scope="module")
def katex_result(all_formulas) -> list[dict]:
    """KaTeX's errors for every formula of every document: one node call."""
    return katex_errors([f for formulas in all_formulas.values() for f in formulas])


def test_markdown_has_math_to_check(all_formulas):
    for name in bundled_names():
        formulas = all_formulas[f"{name}.md"]
        md = derive.render(solution(name), "md")
        n_display = sum(1 for f in formulas if f.display)
        assert n_display == sum(1 for line in md.splitlines() if line.strip() == "$$") // 2
        assert n_display >= 10, f"{name}: only {n_display} display formulas found"
        assert any(not f.display for f in formulas), f"{name}: no inline math found"
        assert any("\\boxed" in f.tex for f in formulas), f"{name}: no boxed answer found"


@pytest.mark.slow
@pytest.mark.parametrize("name", [*bundled_names(), "hostile-direct"])
def test_markdown_math_renders_in_katex(name, katex_result):
    errors = [e for e in katex_result if e["where"].startswith(f"{name}.md:")]
    assert not errors, f"KaTeX rejects {len(errors)} formula(s) of {name}.md:\n{describe(errors)}"


@pytest.mark.slow
@pytest.mark.parametrize("name", bundled_names())
def test_json_latex_renders_in_katex(name, katex_result):
    errors = [e for e in katex_result if e["where"].startswith(f"{name}.json:")]
    assert not errors, f"KaTeX rejects {len(errors)} formula(s) of {name}'s JSON:\n{describe(errors)}"


def test_hostile_text_makes_no_math(tmp_path):
    """User text full of $, \\, _ and friends is escaped: the title, source and statement hold no math."""
    md = derive.render(derive.solve(derive.load(hostile_problem(tmp_path))), "md")
    lines = md.splitlines()
    assert lines[0].startswith("# Direct impact")
    text_lines = [ln for ln in lines if ln.startswith(("# ", "*Source", "**Given.**", "**Find.**"))]
    assert len(text_lines) == 4
    for line in text_lines:
        assert markdown_formulas(line) == [], line
