"""Issue #28 (pages a teacher hands out as they are): a chain's names in its prose. A stage's
heading writes a symbol as a symbol ("Solve for $e_{\\mathrm{floor}}$", never "e\\_floor"),
in every format and in the sentences that quote a stage's title."""

from __future__ import annotations

import re

import pytest

import derive
from derive.writers.view import problem_view

#: The chains whose pages have a "solve" stage or a symbol in a stage's title.
CHAINS = [
    "chain-ocr-m2-2006-drop-rebound",
    "chain-ocr-m2-2007-rebounds-to-start",
    "chain-ocr-m2-2011-find-e-mass-then-wall",
    "chain-car-rear-ends-suv-skid",
]


def _solution(name: str) -> derive.Solution:
    return derive.solve(derive.load(name))


def _headings(md: str) -> list[str]:
    return [ln for ln in md.splitlines() if ln.startswith("#")]


@pytest.mark.parametrize("name", CHAINS)
def test_no_raw_name_in_a_markdown_or_latex_heading(name: str) -> None:
    sol = _solution(name)
    md = derive.render(sol, "md")
    heads = [h for h in _headings(md) if h.startswith("## Stage")]
    assert heads and not [h for h in heads if re.search(r"[A-Za-z]\\_[A-Za-z0-9]", h)], heads
    tex = derive.render(sol, "tex")
    subs = re.findall(r"\\subsection\*\{(Stage .*)\}", tex)
    assert subs and not [s for s in subs if re.search(r"[A-Za-z]\\_[A-Za-z0-9]", s)], subs


def test_the_solve_stage_heading_typesets_its_unknown() -> None:
    sol = _solution("chain-ocr-m2-2006-drop-rebound")
    assert "## Stage 5: Solve for $e_{\\mathrm{floor}}$" in derive.render(sol, "md")
    assert "\\subsection*{Stage 5: Solve for $e_{\\mathrm{floor}}$}" in derive.render(sol, "tex")
    html = derive.render(sol, "html")
    head = re.search(r"<h2>Stage 5: (.*?)</h2>", html, flags=re.S)
    assert head and "e_floor" not in head[1] and 'class="katex"' in head[1]


def test_a_typed_title_names_its_symbols_as_symbols() -> None:
    md = derive.render(_solution("chain-ocr-m2-2011-find-e-mass-then-wall"), "md")
    assert "## Stage 1: A and B collide (find $e$ and $m_{A}$)" in md


def test_a_problem_shaped_view_typesets_the_name() -> None:
    data = problem_view(_solution("chain-ocr-m2-2006-drop-rebound"))
    stages = data["stages"][0]["stages"]
    solve = next(st for st in stages if st["title"].startswith("Solve for"))
    assert solve["heading"] == [("text", "Solve for "), ("math", r"e_{\mathrm{floor}}")]


def _sum_before_unit(tex: str) -> list[str]:
    """Lines whose last side is a sum written straight before a unit: ``1.88 + 1.88 e N·s``."""
    bad = []
    for line in re.findall(r"\$\$\n(.*?)\n\$\$|\$([^$]+)\$", tex):
        body = line[0] or line[1]
        m = re.search(r"= ([^=]*?)\\ \\mathrm\{[^}]*\}\}?(?: \\tag\{\d+\})?$", body.removesuffix(ANSWER).strip())
        if m and _top_level_sum(m[1]):
            bad.append(body)
    return bad


ANSWER = r"\quad\longleftarrow\ \text{ANSWER}"


def _top_level_sum(side: str) -> bool:
    """Whether a side is a sum outside every group ({...}, \\left( ... \\right))."""
    flat, before = side, None
    while flat != before:
        before = flat
        flat = re.sub(r"\{[^{}]*\}", "", flat)
        flat = re.sub(r"\\left\((?:(?!\\left\().)*?\\right\)", "", flat)
    return bool(re.search(r"\S [+-] ", flat))


@pytest.mark.parametrize(
    "name", ["chain-ocr-m2-2006-drop-rebound", "chain-ocr-m2-2007-rebounds-to-start", "notes-4c11-two-spheres"]
)
def test_a_sum_before_its_unit_is_bracketed(name: str) -> None:
    # J = m_A (v_A1 - v_A2) = m (1 + e) v_1: a sum times N·s; the vectors' components times m/s
    md = derive.render(_solution(name), "md")
    assert not _sum_before_unit(md), _sum_before_unit(md)


def test_the_impulse_from_the_ground_is_bracketed() -> None:
    # OCR June 2006 Q2: J = m (1 + e) sqrt(2 g h_0) = 0.3 * 6.261 (1 + e) = 1.878 (1 + e) N s
    md = derive.render(_solution("chain-ocr-m2-2006-drop-rebound"), "md")
    assert r"J = J_{n} = \left(1.88 + 1.88 e_{\mathrm{floor}}\right)\ \mathrm{N\cdot s}" in md
    assert r"= \left(1.88 + 1.88 e_{\mathrm{floor}}\right)\ \mathrm{N\cdot s}}" in md
