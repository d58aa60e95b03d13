"""Issue #28 (pages a teacher hands out as they are): a chain's names in its prose. A stage's
heading writes a symbol as a symbol ("Solve for $e_{\\mathrm{floor}}$", never "e\\_floor"),
in every format and in the sentences that quote a stage's title."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

import derive
from derive.verifier import verify
from derive.verifier.facts.chain import stage_letters
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
    assert r"$J = \left(1.88 + 1.88 e_{\mathrm{floor}}\right)\ \mathrm{N\cdot s}$" in md  # carried on
    assert r"= \left(1.88 + 1.88 e_{\mathrm{floor}}\right)\ \mathrm{N\cdot s}}" in md


def _stage(md: str, k: int) -> str:
    start = md.index(f"## Stage {k}:")
    end = md.find("## Stage", start + 1)
    return md[start : end if end > 0 else None]


def test_a_wall_stage_writes_the_chain_names_throughout() -> None:
    """OCR M2 June 2011 Q4: B (0.2 kg) leaves A at 2.9 m/s (u_B), strikes the wall and comes
    back at w_B; the wall's impulse 0.58 (1 + e_wall) = 0.68 N s gives e_wall = 5/29 and
    w_B = -0.5 m/s (mark scheme: 0.5, e = 0.172). The wall stage calls them u_B, w_B, J_w:
    not v_B1 and v_B2, which stage 1 uses for B before and after the first impact."""
    sol = _solution("chain-ocr-m2-2011-find-e-mass-then-wall")
    md = derive.render(sol, "md", figures=False)
    wall = _stage(md, 2)
    assert "v_{B1}" not in wall and "v_{B2}" not in wall and "J_{n}" not in wall, wall
    assert r"**Given.** $m_{B} = 0.2\ \mathrm{kg}$, $e_{\mathrm{wall}}$, $u_{B} = 2.9\ \mathrm{m/s}$" in wall
    assert r"e_{\mathrm{wall}} = \frac{v_{W2} - w_{B}}{u_{B} - v_{W1}}" in wall
    assert r"\boxed{w_{B} = -2.9 e_{\mathrm{wall}}\ \mathrm{m/s}}" in wall
    assert r"\boxed{J_{w} = m_{B} \left(u_{B} - w_{B}\right) = \left(0.58 + 0.58 e_{\mathrm{wall}}\right)" in wall
    assert r"Carried to the next stages: $J_{w} = \left(0.58 + 0.58 e_{\mathrm{wall}}\right)" in wall
    assert r"$w_{B} = -2.9 e_{\mathrm{wall}}\ \mathrm{m/s}$." in wall
    assert r"\boxed{w_{B} = -0.500\ \mathrm{m/s}}" in md  # the mark scheme's 0.5
    assert "v_{B2} = 2.90" in _stage(md, 1)  # stage 1 keeps the notes' names for its own impact


def test_a_wall_stage_figure_labels_its_arrows_by_the_chain_names() -> None:
    tex = derive.render(_solution("chain-aqa-m3-2007-collide-again"), "tex")
    wall = tex[tex.index("Stage 2: B strikes the wall") : tex.index("Stage 3:")]
    labels = re.findall(r"text=red!70!black\] at \([^)]*\) \{\$([^$]*)\$\}", wall)
    assert labels == ["u_{B}", "w_{B}"], labels


def test_the_ground_has_its_own_letter_and_the_sphere_the_chain_names() -> None:
    """OCR M2 June 2006 Q2: v_1 = sqrt(2 g h_0) = 6.26 m/s at impact, u = -e v_1 after,
    J = m (1 + e) v_1; the ground is G (never B, nor the sphere's v_A1/v_A2)."""
    md = derive.render(_solution("chain-ocr-m2-2006-drop-rebound"), "md", figures=False)
    ground = _stage(md, 2)
    assert "G is the fixed ground" in ground
    assert r"e_{\mathrm{floor}} = \frac{v_{G2} - u}{v_{1} - v_{G1}}" in ground
    assert not re.search(r"v_\{[AB][12]\}", ground), ground
    assert r"\boxed{J = m \left(v_{1} - u\right) = \left(1.88 + 1.88 e_{\mathrm{floor}}\right)" in ground


@pytest.mark.parametrize(
    "name", sorted(p.stem for p in (Path(derive.__file__).parent.parent / "problems").glob("chain-*.toml"))
)
def test_the_verifier_passes_every_chain_page(name: str) -> None:
    sol = _solution(name)
    for fmt in ("md", "tex"):
        report = verify(sol, fmt)
        assert not report.failures, [(f.line, f.rule, f.reason) for f in report.failures]


def test_the_verifier_reads_a_wall_stage_in_its_own_names() -> None:
    """A wrong number in the wall stage's own names is caught (w_B = -2.7 e_wall for -2.9 e_wall)."""
    sol = _solution("chain-ocr-m2-2011-find-e-mass-then-wall")
    text = derive.render(sol, "md", figures=False)
    good = r"w_{B} = -2.9 e_{\mathrm{wall}}\ \mathrm{m/s} \tag{3}"
    assert good in text
    report = verify(sol, "md", text=text.replace(good, good.replace("2.9", "2.7"), 1))
    assert "equals" in [f.rule for f in report.failures]


def test_the_verifier_names_a_stage_s_bodies_from_the_file() -> None:
    assert stage_letters({"A": {"label": "B"}, "B": {"fixed": True, "name": "wall"}}) == ("B", "W")
    assert stage_letters({"B": {"fixed": True, "name": "ground"}}) == ("A", "G")
    assert stage_letters({"B": {"fixed": True, "name": "ground"}, "A": {"label": "G"}}) == ("G", "W")
    assert stage_letters({}) == ("A", "B")
