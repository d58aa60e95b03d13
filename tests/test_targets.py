"""Where the output goes (issue #17), checked without the tools: the Markdown targets
(``--for``), heading levels, the fragment's preamble, long lines set on rows, source
links, and how ``--format docx`` finds pandoc. tests/test_interop.py runs the tools.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import sympy
from support.output_cases import solution

import derive
from derive.cli import main
from derive.errors import RenderError
from derive.steps.model import Eqn, Side
from derive.writers import docx
from derive.writers.printing import Style, latex_eqn, latex_rows
from derive.writers.targets import ARTICLE_WIDTH_PT, FRAGMENT_PACKAGES, Layout
from derive.writers.view import markdown, source_parts
from derive.writers.width import width_pt

NOTES = ("notes-4c11-two-spheres", "notes-4c12-cue-ball", "chain-aqa-m3-2007-collide-again")

# Widths pdfTeX gives (\sbox0{$\displaystyle ...$}, Computer Modern 10 pt), in pt.
MEASURED = [
    (r"m_{A} v_{A1} + m_{B} v_{B1} = m_{A} v_{A2} + m_{B} v_{B2}", 161.82),
    (r"\boxed{e = 0}\quad\longleftarrow\ \text{ANSWER}", 109.79),
    (r"\cancel{m_{B}} v_{B1t} = \cancel{m_{B}} v_{B2t}", 82.13),
    (r"v_{A2} = -v_{A1} e = -6.261 e = -6.26 e_{\mathrm{floor}}", 164.89),
]


@pytest.mark.parametrize(("latex", "pt"), MEASURED, ids=[m[0][:24] for m in MEASURED])
def test_width_estimate_is_near_tex(latex: str, pt: float) -> None:
    assert width_pt(latex) == pytest.approx(pt, rel=0.1)


def _sym(name: str) -> sympy.Symbol:
    return sympy.Symbol(name, positive=True)


def test_a_long_line_is_set_one_side_per_row_and_broken_before_a_sign() -> None:
    a, b, c = _sym("a"), _sym("b"), _sym("c")
    long_sum = sum((sympy.Rational(1, k) * a * b * c**k for k in range(2, 16)), sympy.Integer(0))
    eqn = Eqn((Side((sympy.Symbol("T_2"),)), Side((a * b,)), Side((long_sum,)), Side((sympy.Integer(3),))))
    style = Style(3)
    rows = latex_rows(eqn, style, ARTICLE_WIDTH_PT)
    assert [r.rel for r in rows if not r.continued] == ["=", "=", "="]
    assert rows[0].lhs == "T_{2}" and all(not r.lhs for r in rows[1:])
    assert any(r.continued and r.rel in "+-" for r in rows)
    assert all(width_pt(r.lhs) + 13.33 + 22.22 + width_pt(r.rhs) <= ARTICLE_WIDTH_PT for r in rows)
    # the rows put back together are the line
    assert rows[0].lhs + "".join(f" {r.rel} {r.rhs}" for r in rows) == latex_eqn(eqn, style)[0]


def test_a_short_line_stays_on_one_row() -> None:
    a, b = _sym("a"), _sym("b")
    assert latex_rows(Eqn((Side((a,)), Side((b,)))), Style(3), ARTICLE_WIDTH_PT) == ()


def test_without_strokes_a_cancelled_symbol_prints_plain() -> None:
    m, v = _sym("m_A"), _sym("v_A1")
    eqn = Eqn((Side((m * v,)), Side((m * v * 2,))), cancel=frozenset({m}))
    assert r"\cancel{m_{A}}" in latex_eqn(eqn, Style(3))[0]
    assert r"\cancel" not in latex_eqn(eqn, Style(3, strike=False))[0]


@pytest.mark.parametrize(
    ("text", "parts"),
    [
        ("read at https://a.b/q/1", [("text", "read at "), ("url", "https://a.b/q/1")]),
        ("(see http://x.org/a_b).", [("text", "(see "), ("url", "http://x.org/a_b"), ("text", ").")]),
        (
            "https://en.wikipedia.org/wiki/X_(y), p. 3",
            [("url", "https://en.wikipedia.org/wiki/X_(y)"), ("text", ", p. 3")],
        ),
        ("no address: javascript:alert(1)", [("text", "no address: javascript:alert(1)")]),
    ],
)
def test_source_parts(text: str, parts: list[tuple[str, str]]) -> None:
    assert source_parts(text) == parts


@pytest.mark.parametrize("name", NOTES)
def test_default_markdown_keeps_tags_cancel_and_inline_svg(name: str) -> None:
    md = derive.render(solution(name), "md")
    assert "\\tag{" in md and "<svg" in md and "\\require" not in md and "\\text{ } =" not in md


@pytest.mark.parametrize("name", NOTES)
def test_pandoc_markdown(name: str) -> None:
    default = derive.render(solution(name), "md")
    md = derive.render(solution(name), "md", target="pandoc")
    assert "\\tag{" not in md and "\\cancel" not in md and "<svg" not in md
    assert re.findall(r"\\tag\{([^}]*)\}", default) == re.findall(r"\\qquad\\text\{~~\(([^)]*)\)\}", md)
    assert md.count("](data:image/svg+xml;base64,") == default.count("<svg")
    assert "\\begin{aligned}" not in md
    assert not re.search(r"^\$\$\n=", md, flags=re.M), "a display that starts with '='"


def test_markdown_rows_as_one_aligned_display() -> None:
    """A layout with a width and aligned rows (no named target has it yet): one display, rows with &=."""
    layout = Layout(width=ARTICLE_WIDTH_PT)
    page, files = markdown(solution("notes-4c12-cue-ball"), layout)
    assert files == {}
    block = re.search(r"\$\$\n(\\begin\{aligned\}\nT_\{2\} &= .*?)\n\$\$", page, flags=re.S)
    assert block, "T_2 on aligned rows"
    assert block.group(1).count(" \\\\\n&= ") == 2 and block.group(1).endswith("\\end{aligned}")


def test_pandoc_markdown_escapes_carets_in_text(problem_from) -> None:
    problem = problem_from(
        """
        title = "x^2^ is a superscript to pandoc"
        kind = "direct"
        [given]
        m_A = "2 kg"
        m_B = "1 kg"
        e = 0.5
        v_A1 = "3 m/s"
        v_B1 = "0 m/s"
        """
    )
    sol = derive.solve(problem)
    assert "x\\^2\\^" in derive.render(sol, "md", target="pandoc")
    assert "x^2^" in derive.render(sol, "md")


@pytest.mark.parametrize("name", NOTES)
def test_jupyter_markdown_loads_cancel_where_it_strikes(name: str) -> None:
    md = derive.render(solution(name), "md", target="jupyter")
    for display in re.findall(r"\$\$\n(.*?)\n\$\$", md, flags=re.S):
        assert ("\\cancel" in display) == display.startswith("\\require{cancel}")
    assert derive.solve(derive.load(name))._repr_markdown_() == md


@pytest.mark.parametrize("name", NOTES)
@pytest.mark.parametrize("fmt", ["md", "tex-fragment"])
def test_heading_levels(name: str, fmt: str) -> None:
    def levels(text: str) -> list[int]:
        if fmt == "md":
            return [len(m) for m in re.findall(r"^(#+) ", text, flags=re.M)]
        names = ["section", "subsection", "subsubsection", "paragraph", "subparagraph"]
        return [names.index(m) + 1 for m in re.findall(r"^\\([a-z]+)\*\{", text, flags=re.M)]

    default = levels(derive.render(solution(name), fmt))
    assert default[0] == 1
    assert levels(derive.render(solution(name), fmt, heading_level=2)) == [n + 1 for n in default]
    assert levels(derive.render(solution(name), fmt, heading_level=3, title=False)) == [n + 1 for n in default[1:]]


def test_heading_level_is_checked() -> None:
    with pytest.raises(derive.InputError, match="heading level"):
        derive.render(solution(NOTES[0]), "md", heading_level=7)
    with pytest.raises(derive.InputError, match="target"):
        derive.render(solution(NOTES[0]), "md", target="word")


def test_fragment_names_its_preamble_and_help_too(capsys: pytest.CaptureFixture[str]) -> None:
    preamble = "\\usepackage{" + ",".join(FRAGMENT_PACKAGES) + "}"
    assert preamble in derive.render(solution(NOTES[0]), "tex-fragment").splitlines()[0]
    with pytest.raises(SystemExit):
        main(["solve", "--help"])
    assert preamble in capsys.readouterr().out


def test_cli_options_are_checked(cli) -> None:
    r = cli("solve", NOTES[0], "--format", "tex", "--for", "pandoc")
    assert r.code == 2 and "--for is for --format md" in r.err
    r = cli("solve", NOTES[0], "--format", "json", "--no-title")
    assert r.code == 2 and "--no-title" in r.err
    r = cli("solve", NOTES[0], "--heading-level", "9")
    assert r.code == 2 and "--heading-level" in r.err
    r = cli("solve", NOTES[0], "--for", "jupyter")
    assert r.code == 0 and "\\require{cancel}" in r.out


def test_docx_without_pandoc_says_how_to_get_it(cli, monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setattr(docx, "find_pandoc", lambda: None)
    r = cli("solve", NOTES[0], "--format", "docx", "-o", str(tmp_path / "x.docx"))
    assert r.code == 1
    assert r.err == f"Error: {docx.MISSING}\n"
    assert not (tmp_path / "x.docx").exists()


def test_docx_with_something_else_than_pandoc(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setenv("DERIVE_PANDOC", "/bin/true")
    with pytest.raises(RenderError, match="is not pandoc"):
        docx.build_docx(solution(NOTES[0]))
    monkeypatch.setenv("DERIVE_PANDOC", str(tmp_path / "nothing-here"))
    with pytest.raises(RenderError, match="does not run"):
        docx.build_docx(solution(NOTES[0]))


# ---------------------------------------------------------------- long lines on every page


LOST = r"T_{\mathrm{lost}}"


def _lost_row(text: str) -> str:
    """The T_lost line of 4.C.11 as written (with its rows, if set on rows)."""
    start = text.index(LOST + " ")
    return text[start : text.index("321", start)]


def test_a_long_line_is_on_rows_in_mkdocs_html_handouts_and_variants(tmp_path: Path) -> None:
    """4.C.11's T_lost line is wider than a course site's column (the helper's MkDocs page
    cut it off behind a scroll bar), derive's HTML page, and a handout's or a variant's text
    (8-17 pt into the margin): each sets it on rows, as a solve's LaTeX page does."""
    from derive.homework import variants
    from derive.homework.handout import build_handout
    from derive.problem import load

    sol = derive.solve(derive.load("notes-4c11-two-spheres"))
    assert "&=" in _lost_row(derive.render(sol, "tex"))  # the reference: a solve's LaTeX page
    assert "&=" in _lost_row(markdown(sol, layout=derive.writers.targets.MKDOCS)[0])
    assert "&=" not in _lost_row(derive.render(sol, "md"))  # GitHub's page scrolls a wide display
    html = derive.render(sol, "html")
    annotations = re.findall(r'<annotation encoding="application/x-tex">(.*?)</annotation>', html, re.S)
    lost = [a for a in annotations if "T_{\\mathrm{lost}} &amp;=" in a or "T_{\\mathrm{lost}} &=" in a]
    assert lost and "aligned" in lost[0]
    handout, _ = build_handout(["notes-4c11-two-spheres"], title="S", theory=False, mode="solutions", fmt="tex")
    assert "&=" in _lost_row(handout)
    compiled = variants.compile_problem(load("notes-4c11-two-spheres"))
    page = variants.fill(compiled, variants.draw(compiled, 1, seed=1)[0], "tex")
    start = page.index(LOST + " ")
    assert "&=" in page[start : page.index(r"\end", start)]
