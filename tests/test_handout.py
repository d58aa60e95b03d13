"""Handouts: several problems in one document, with a theory page, in three modes.

The PDF tests need TeX Live with latexmk (in CI a missing latexmk fails instead of skipping).
"""

from __future__ import annotations

import re
import shutil
import subprocess
from functools import cache
from pathlib import Path

import pytest
import sympy
from support.output_cases import hostile_problem, missing_tool

import derive
from derive import escape, resources
from derive.homework import theory
from derive.homework.handout import MODES, build_handout
from derive.numbers import format_number
from derive.physics import impact
from derive.writers.printing import Style, latex_eqn
from derive.writers.view import view

BROKEN = """\
title = "Broken: B has no mass"
kind = "direct"

[given]
m_A = "2 kg"
e = 0.5
v_A1 = "3 m/s"
v_B1 = "0 m/s"
"""


@cache
def three() -> tuple[str, str, str]:
    """The notes' two examples and the first bundled direct impact."""
    direct = next(n for n in resources.bundled() if not n.startswith("notes-") and derive.load(n).kind == "direct")
    return ("notes-4c11-two-spheres", "notes-4c12-cue-ball", direct)


def titles(names: tuple[str, ...]) -> list[str]:
    return [derive.load(n).title for n in names]


def broken_problem(tmp_path: Path) -> Path:
    path = tmp_path / "broken-no-mass.toml"
    path.write_text(BROKEN, encoding="utf-8")
    return path


def need_latexmk() -> None:
    for tool in ("latexmk", "pdflatex"):
        if shutil.which(tool) is None:
            missing_tool(f"{tool} is not installed (Debian: apt-get install latexmk texlive-latex-extra)")


def pdf_text(pdf: bytes, tmp_path: Path) -> str | None:
    """The PDF's text by pdftotext, or None when poppler-utils is not installed."""
    if shutil.which("pdftotext") is None:
        return None
    path = tmp_path / "check.pdf"
    path.write_bytes(pdf)
    return subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout


# --- the PDF ---------------------------------------------------------------


@pytest.mark.slow
@pytest.mark.parametrize("mode", MODES, ids=lambda m: f"mode={m}")
def test_pdf_builds_in_each_mode(mode: str, tmp_path: Path) -> None:
    need_latexmk()
    pdf, failures = build_handout(list(three()), title="Central impact: set 1", theory=True, mode=mode, fmt="pdf")
    assert failures == []
    assert isinstance(pdf, bytes) and pdf.startswith(b"%PDF")
    text = pdf_text(pdf, tmp_path)
    if text is not None:
        assert "Central impact: set 1" in text
        assert "Central impact: the equations" in text
        for title in titles(three()):
            assert title.split(":")[0] in text
        assert ("ANSWER" in text) == (mode != "problems")
        assert ("Kinetics" in text) == (mode == "solutions")


@pytest.mark.slow
def test_cli_pdf_with_a_broken_problem_still_has_the_others(cli, tmp_path: Path) -> None:
    """The CLI writes the PDF with every good problem, hostile text included, then reports the broken one."""
    need_latexmk()
    out = tmp_path / "handout.pdf"
    hostile = hostile_problem(tmp_path)
    broken = broken_problem(tmp_path)
    r = cli("handout", "notes-4c11-two-spheres", str(broken), str(hostile), "--mode", "answers", "-o", str(out))
    assert r.code == 1
    assert out.read_bytes().startswith(b"%PDF")
    assert str(broken) in r.err
    text = pdf_text(out.read_bytes(), tmp_path)
    if text is not None:
        assert "Example 4.C.11" in text and "100%" in text
        assert "Broken" not in text


# --- what each mode holds --------------------------------------------------


def test_markdown_has_each_title_and_no_answer_in_problems_mode() -> None:
    doc, failures = build_handout(list(three()), title="Sheet", theory=True, mode="problems", fmt="md")
    assert failures == []
    assert isinstance(doc, str) and doc.startswith("# Sheet\n")
    for title in titles(three()):
        assert escape.markdown(title) in doc
    assert "ANSWER" not in doc
    assert "\\boxed" not in doc
    assert doc.count("**Find.**") == 3
    assert "**Solution.**" not in doc
    # the set-up figure, before the impact only (+n shown; no velocity after it)
    figures = re.findall(r"<svg.*?</svg>", doc, re.S)
    assert len(figures) == 3
    assert all("Before the impact" in f and ">A2<" not in f and ">B2<" not in f for f in figures)
    assert doc.count("**Sign convention.** Take $n$ along the line of impact") == 3


def test_a_students_sheet_has_no_source_line() -> None:
    """Issue 15: most sources quote the published answers (AQA's "v_B = 3.4, v_A = -0.6")."""
    names = ["notes-4c11-two-spheres", "chain-aqa-m3-2007-collide-again"]
    doc, _ = build_handout(names, title="Sheet", theory=False, mode="problems", fmt="md")
    assert "Source" not in doc and "3.4, v" not in doc
    key, _ = build_handout(names, title="Key", theory=False, mode="answers", fmt="md")
    assert key.count("*Source:") == 2  # the key keeps its citations


def test_a_chain_in_solutions_mode_has_its_givens_carried_results_and_answer() -> None:
    """Issue 15: the handout dropped each impact stage's givens, the results it carries on
    and the chain's final answers (AQA 2007 Q4: they collide again)."""
    doc, _ = build_handout(["chain-aqa-m3-2007-collide-again"], title="S", theory=False, mode="solutions", fmt="md")
    assert r"Given: $m_{A} = 0.3\ \mathrm{kg}$" in doc
    assert r"Carried to the next stages: $u_{A} = v_{A2} = -0.600\ \mathrm{m/s}$" in doc
    assert r"Carried to the next stages: $w_{B} = -2.38\ \mathrm{m/s}$" in doc  # the wall stage writes w_B
    tail = doc[doc.index(") Answer") :]
    assert r"\boxed{\text{Do they collide again? yes}}" in tail and "ANSWER" in tail


def test_answers_mode_has_the_boxed_lines_of_stage_4_only() -> None:
    doc, _ = build_handout(list(three()), title="Answers", theory=False, mode="answers", fmt="md")
    assert isinstance(doc, str)
    assert doc.count("**Answer.**") == 3
    assert "ANSWER" in doc
    boxed = [ln for ln in doc.splitlines() if ln.startswith("\\boxed")]
    assert boxed and all("\\boxed" in ln for ln in boxed)
    expected = [
        ln["latex"]
        for n in three()
        for impact in view(derive.solve(derive.load(n)))["stages"]  # one impact: one stage, its title empty
        for st in impact["stages"]
        if st["number"] == 4
        for b in st["blocks"]
        for ln in b["lines"]
        if ln["boxed"]
    ]
    assert boxed == expected
    assert "Kinetics" not in doc and "<svg" not in doc


def test_solutions_mode_has_the_worked_stages_and_figures() -> None:
    doc, _ = build_handout(list(three()), title="Solutions", theory=False, mode="solutions", fmt="md")
    assert isinstance(doc, str)
    assert doc.count("**Solution.**") == 3
    assert doc.count("### 2) Kinetics") == 3
    assert "<svg" in doc
    assert "## 1. " + escape.markdown(titles(three())[0]) in doc


def test_tex_sections_are_numbered_and_solutions_start_a_page() -> None:
    tex, _ = build_handout(list(three()), title="T", theory=False, mode="solutions", fmt="tex")
    assert isinstance(tex, str) and tex.startswith("\\documentclass")
    assert tex.count("\\section{") == 3 and "\\section*{" not in tex
    assert tex.count("\\clearpage") == 2
    assert "\\begin{tikzpicture}" in tex


def test_digits_apply_to_every_problem() -> None:
    name = "notes-4c11-two-spheres"
    doc, _ = build_handout([name], title="T", theory=False, mode="answers", fmt="md", digits=5)
    assert isinstance(doc, str)
    v_A2t = derive.solve(derive.load(name)).results["v_A2t"].value
    assert format_number(v_A2t, 5) in doc and format_number(v_A2t, 3) + " " not in doc


# --- the theory page -------------------------------------------------------


@pytest.mark.parametrize("fmt", ["md", "tex"])
def test_theory_page_contains_the_four_equations(fmt: str) -> None:
    doc, _ = build_handout(["notes-4c11-two-spheres"], title="T", theory=True, mode="problems", fmt=fmt)
    assert isinstance(doc, str)
    page = doc[: doc.index("Example 4.C.11")]
    for k in (1, 2, 3, 4):
        body, tag = latex_eqn(theory.EQUATION_LINES[k], Style(None))
        assert tag == str(k)
        assert f"{body} \\tag{{{k}}}" in page
    for words in (
        "Impulsive forces",
        "axes clearly",
        "along the line of impact",
        "Mechanical energy is not conserved",
        "System B alone",
    ):
        assert words in page
    assert "m_{B} v_{B2n} + m_{B} v_{B2n}" not in page, "the notes' slip in the system equation is copied"


def test_no_theory_leaves_the_page_out() -> None:
    doc, _ = build_handout(["notes-4c11-two-spheres"], title="T", theory=False, mode="problems", fmt="md")
    assert isinstance(doc, str)
    assert "Central impact: the equations" not in doc and "\\tag{" not in doc


def test_theory_equations_are_the_solver_equations() -> None:
    """(1)-(4) on the page say what derive.impact solves: each gives the same post-impact component."""
    imp = impact.setup(derive.load("notes-4c11-two-spheres"))
    by_name = {s.name: s for eq in imp.equations.values() for s in eq.free_symbols}
    for k, unknown in ((1, "v_A2t"), (2, "v_B2t"), (3, "v_A2n"), (4, "v_B2n")):
        page = theory.equation(k)
        page = page.xreplace({s: by_name[s.name] for s in page.free_symbols if s.name in by_name})
        solver = imp.equations[k]
        u = by_name[unknown]
        got, want = sympy.solve(page, u), sympy.solve(solver, u)
        assert len(got) == len(want) == 1
        assert sympy.simplify(got[0] - want[0]) == 0, k


# --- a batch with failures -------------------------------------------------


def test_broken_problem_is_left_out_and_reported_at_the_end(cli, tmp_path: Path) -> None:
    out = tmp_path / "handout.md"
    broken = broken_problem(tmp_path)
    a, b, c = three()
    r = cli("handout", a, str(broken), b, c, "--mode", "answers", "-o", str(out))
    assert r.code == 1
    doc = out.read_text(encoding="utf-8")
    for title in titles(three()):
        assert escape.markdown(title) in doc
    assert "Broken" not in doc
    *lines, summary = r.err.splitlines()
    assert lines and all(ln.startswith("Error: ") for ln in lines)
    assert str(broken) in lines[0] and "m_B" in lines[0]
    assert "1 of 4" in lines[-1]
    assert summary == f"wrote {out} (md, answers): 3 problems"  # issue 15: one line says what was written
    assert r.out == ""


def test_internal_error_in_one_problem_does_not_stop_the_others(monkeypatch: pytest.MonkeyPatch) -> None:
    from derive.homework import handout

    real = handout.solve

    def flaky(problem: derive.Problem) -> derive.Solution:
        if problem.title.startswith("Example 4.C.12"):
            raise RuntimeError("boom")
        return real(problem)

    monkeypatch.setattr(handout, "solve", flaky)
    doc, failures = build_handout(list(three()), title="T", theory=False, mode="problems", fmt="md")
    assert [f.problem for f in failures] == ["notes-4c12-cue-ball"]
    assert "RuntimeError: boom" in failures[0].error
    assert isinstance(doc, str) and "Example 4.C.11" in doc and "Example 4.C.12" not in doc


def test_every_problem_failing_exits_2_and_writes_nothing(cli, tmp_path: Path) -> None:
    out = tmp_path / "handout.md"
    r = cli("handout", str(broken_problem(tmp_path)), "no-such-problem", "-o", str(out))
    assert r.code == 2
    assert not out.exists()
    assert "no-such-problem" in r.err and "broken-no-mass.toml" in r.err
    assert all(ln.startswith("Error: ") for ln in r.err.splitlines())


@pytest.mark.parametrize(
    "args",
    [
        ("notes-4c11-two-spheres", "-o", "handout.docx"),
        ("notes-4c11-two-spheres", "-o", "handout"),
        ("notes-4c11-two-spheres", "-o", "h.md", "--mode", "everything"),
        ("notes-4c11-two-spheres", "-o", "h.md", "--digits", "0"),
        ("-o", "h.md"),
        ("notes-4c11-two-spheres",),
    ],
    ids=["unknown-extension", "no-extension", "bad-mode", "bad-digits", "no-problem", "no-output"],
)
def test_bad_usage_exits_2(cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, args: tuple[str, ...]) -> None:
    monkeypatch.chdir(tmp_path)
    r = cli("handout", *args)
    assert r.code == 2
    assert r.err.startswith("Error: ") and len(r.err.splitlines()) == 1
    assert list(tmp_path.iterdir()) == []


def test_cli_title_and_no_theory(cli, tmp_path: Path) -> None:
    out = tmp_path / "h.md"
    r = cli("handout", "notes-4c12-cue-ball", "--title", "Week 9 & more", "--no-theory", "-o", str(out))
    assert r.code == 0, r.err
    assert r.err == f"wrote {out} (md, solutions): 1 problem\n"
    doc = out.read_text(encoding="utf-8")
    assert doc.startswith("# Week 9 &amp; more\n")
    assert "Central impact: the equations" not in doc


def test_cli_refuses_to_overwrite_a_problem(cli, tmp_path: Path) -> None:
    src = tmp_path / "p.md"
    src.write_text(resources.bundled()["notes-4c11-two-spheres"].read_text(encoding="utf-8"), encoding="utf-8")
    r = cli("handout", str(src), "-o", str(src))
    assert r.code == 2
    assert "refusing to overwrite" in r.err


def test_a_chains_answer_key_says_what_its_names_stand_for() -> None:
    """Issue 15: the key gave u_A, u_B and w_B with no word on what they are (AQA 2007 Q4:
    u_A and u_B after the first impact, w_B after B's rebound from the wall)."""
    key, _ = build_handout(["chain-aqa-m3-2007-collide-again"], title="K", theory=False, mode="answers", fmt="md")
    assert (
        r"**Answer.** Where $u_{A}$ is $v_{A2}$ after A and B collide; $u_{B}$ is $v_{B2}$ after A and B "
        r"collide; $w_{B}$ is $v_{B2}$ after B strikes the wall." in key
    )
    tex, _ = build_handout(["chain-aqa-m3-2007-collide-again"], title="K", theory=False, mode="answers", fmt="tex")
    assert r"Where $u_{A}$ is $v_{A2}$ after A and B collide" in tex


# --- HTML: a student's sheet and a key, in the page's style ----------------------------------


def _shown_answers(name: str) -> list[str]:
    """The numbers of a problem's answers as its page shows them (3.25 of v_A2 = 3.25 m/s)."""
    from derive.writers.view import plain_answers

    text = " ".join(plain_answers(derive.solve(derive.load(name))))
    return re.findall(r"(?<![\w.])-?\d+\.\d+", text)


HTML_NAMES = ["notes-4c11-two-spheres", "ocr-m2-2012-particle-hits-wall", "chain-ocr-m2-2006-drop-rebound"]


def test_html_sheet_has_statements_figures_convention_and_no_answers() -> None:
    """Issue 15: a student's sheet as HTML: each statement with its set-up before the impact
    and the sign convention in words; no Source line, no answer, no worked solution."""
    from support.output_cases import html_text

    doc, failures = build_handout(HTML_NAMES, title="Sheet <1>", theory=False, mode="problems", fmt="html")
    assert failures == [] and isinstance(doc, str)
    assert doc.startswith("<!DOCTYPE html>") and "<title>Sheet &lt;1&gt;</title>" in doc
    text = html_text(doc)
    for title in titles(tuple(HTML_NAMES)):
        assert title in text
    assert text.count("Find.") == 3 and text.count("Sign convention.") == 3
    assert "positive from the centre of A toward the centre of B" in text
    assert "positive from A toward the wall" in text and "signed along +n" in text
    assert "Source" not in text and "Solution." not in text and "ANSWER" not in text
    assert "derive finds it" not in text and "(to find)" in text
    for name in HTML_NAMES:
        for shown in _shown_answers(name):
            assert shown not in text, (name, shown)
    figures = re.findall(r"<svg.*?</svg>", doc, re.S)
    assert len(figures) == 3 and all(">A2<" not in f and ">B2<" not in f for f in figures)


def test_html_keys_have_every_answer() -> None:
    """The key (answers mode) and the worked solutions hold each problem's answers and its Source."""
    from support.output_cases import html_text

    for mode in ("answers", "solutions"):
        doc, _ = build_handout(HTML_NAMES, title="Key", theory=mode == "solutions", mode=mode, fmt="html")
        text = html_text(doc)
        assert text.count("Source:") == 3 and "ANSWER" in text
        for name in HTML_NAMES:
            for shown in _shown_answers(name):
                assert shown in text, (mode, name, shown)
    assert "Kinetics" in text and "Three systems" in text and text.count("Solution.") == 3


def test_cli_handout_html_from_the_extension_or_format(cli, tmp_path: Path) -> None:
    out = tmp_path / "sheet.html"
    assert cli("handout", "notes-4c11-two-spheres", "-o", str(out), "--mode", "problems").code == 0
    assert out.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    other = tmp_path / "sheet.page"
    assert cli("handout", "notes-4c11-two-spheres", "-o", str(other), "--format", "html").code == 0
    assert other.read_text(encoding="utf-8").startswith("<!DOCTYPE html>")
    r = cli("handout", "notes-4c11-two-spheres", "-o", str(tmp_path / "x.md"), "--format", "html")
    assert r.code == 2 and "--format html" in r.err and not (tmp_path / "x.md").exists()


def test_html_handout_carries_no_markup_from_the_file(tmp_path: Path) -> None:
    """A title, source and statement with HTML, TeX and Markdown in them come out as text."""
    from support.output_cases import html_text

    path = hostile_problem(tmp_path)
    for mode in MODES:
        doc, failures = build_handout([str(path)], title="<i>T</i>", theory=False, mode=mode, fmt="html")
        assert failures == [] and isinstance(doc, str)
        assert "<i>T</i>" not in doc and "<b> |" not in doc and "&lt;b&gt; |" in doc
        text = html_text(doc)  # well formed: nothing of the file opened an element
        assert "<b> | `code` *bold* [l](u) café θ" in text
        assert ("Made up" in text) == (mode != "problems")


def test_html_handout_without_node_typesets_itself(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without Node.js each formula stays TeX in a span and KaTeX's script comes inline."""
    from support.output_cases import html_text

    from derive.writers import katex

    monkeypatch.setattr(katex, "render_math", lambda items: None)
    doc, _ = build_handout(["notes-4c11-two-spheres"], title="S", theory=True, mode="problems", fmt="html")
    assert '<span class="math">m_{A} = 20\\ \\mathrm{kg}</span>' in doc
    assert "katex.render(el.textContent" in doc and 'class="katex"' not in doc
    assert "Sign convention." in html_text(doc)
