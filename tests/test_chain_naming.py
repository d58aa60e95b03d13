"""Issue #28 item 5: a chain's page prints exact numbers where its data are exact, a range
without a bound that is already true (never "True"), and no page prints True or False."""

from __future__ import annotations

import re
import textwrap
from pathlib import Path

import sympy

import derive
from derive.steps.model import Math
from derive.steps.page import interval_text

GOLDEN = Path(__file__).parent / "golden"

# AQA M3 June 2009 Q6: A (m) at 5u catches B (7m) at u, coefficient e; then B rebounds
# from a wall (part (c): e = 1/2). Mark scheme: v_A = u/2 (3 - 7e), v_B = u/2 (e + 3),
# and a second collision for e < 9/13. By hand: w_B = -e_wall u (e + 3)/2 = -u(e + 3)/4;
# u_A > w_B <=> 6 - 14e > -e - 3 <=> e < 9/13.
CATCH_UP = textwrap.dedent(
    """
    title = "A catches B, B rebounds from a wall: do they collide again?"
    kind = "chain"
    statement = "A ({m_A}) at {v_A} catches B ({m_B}) at {v_B}; e = {e}. B then strikes a wall (e = {e_wall})."
    find = ["u_A", "u_B", "w_B", "again"]

    [given]
    m = "kg"
    u = "m/s"
    e = "e"
    m_A = "m"
    m_B = "7*m"
    v_A = "5*u"
    v_B = "u"
    e_wall = 0.5

    [[stage]]
    type = "impact"
    title = "A and B collide"
    kind = "direct"
    given = { m_A = "m_A", m_B = "m_B", e = "e", v_A1 = "v_A", v_B1 = "v_B" }
    results = { v_A2 = "u_A", v_B2 = "u_B" }

    [[stage]]
    type = "impact"
    title = "B strikes the wall"
    kind = "direct"
    given = { m_A = "m_B", e = "e_wall", v_A1 = "u_B" }
    A = { label = "B" }
    B = { fixed = true, name = "wall" }
    results = { v_A2 = "w_B" }

    [[stage]]
    type = "again"
    title = "Do A and B collide again?"
    behind = "u_A"
    ahead = "w_B"
    result = "again"
    range_of = "e"
    """
)


def _page(tmp_path: Path) -> str:
    f = tmp_path / "catch-up.toml"
    f.write_text(CATCH_UP)
    return derive.render(derive.solve(derive.load(str(f))), "md")


def test_exact_data_print_exact_although_a_later_stage_is_decimal(tmp_path: Path) -> None:
    md = _page(tmp_path)
    # the mark scheme's u/2 (3 - 7e) and u/2 (e + 3), in fractions: e_wall = 0.5 is not their data
    assert r"\boxed{u_{A} = \frac{3 u}{2} - \frac{7 e u}{2}}" in md
    assert r"\boxed{u_{B} = \frac{3 u}{2} + \frac{e u}{2}}" in md
    assert r"e < \frac{9}{13}" in md  # the mark scheme's range
    stage1 = md[md.index("## Stage 1") : md.index("## Stage 2")]
    maths = re.findall(r"\$\$(.*?)\$\$|\$(.*?)\$", re.sub(r"<svg.*?</svg>", "", stage1, flags=re.S), flags=re.S)
    assert maths and not [m for pair in maths for m in pair if re.search(r"\d\.\d", m)]


def test_a_sum_never_mixes_fractions_and_decimals(tmp_path: Path) -> None:
    md = _page(tmp_path)
    for line in md.splitlines():
        if line.startswith(r"\boxed"):
            assert not (r"\frac" in line and re.search(r"\d\.\d", line)), line
    # a single impact of exact data: 3/2 - 7e/2 < 0, not 3/2 - 3.5e < 0
    aqa = (GOLDEN / "pages" / "aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u.md").read_text()
    assert r"\frac{3}{2} - \frac{7 e}{2} < 0" in aqa


def test_a_bound_already_true_is_left_out_of_a_range() -> None:
    e = sympy.Symbol("e", nonnegative=True)
    words = interval_text(sympy.Interval.Ropen(0, sympy.Rational(2, 3)), e)
    maths = [w.expr for w in words if isinstance(w, Math)]
    assert maths and all(m.func(*m.args) not in (sympy.true, sympy.false) for m in maths)
    assert sympy.StrictLessThan(e, sympy.Rational(2, 3)) in maths


def test_no_bundled_page_prints_true_or_false() -> None:
    for f in sorted((GOLDEN / "pages").glob("*.md")) + sorted((GOLDEN / "pages").glob("*.tex")):
        text = re.sub(r"<svg.*?</svg>", "", f.read_text(), flags=re.S)
        assert not re.search(r"\b(True|False)\b", text), f.name


def _maths(text: str) -> list[str]:
    """The mathematics of a Markdown page, display and inline, without its figures."""
    text = re.sub(r"<svg.*?</svg>", "", text, flags=re.S)
    return [a or b for a, b in re.findall(r"\$\$(.*?)\$\$|\$(.*?)\$", text, flags=re.S)]


def test_a_stage_writes_its_coefficient_by_the_chains_name() -> None:
    """One name per quantity: an impact stage given e = e_wall (or e_floor) writes e_wall
    throughout, never a bare e beside it (nor e for a second coefficient on the page)."""
    checked = 0
    for f in sorted((GOLDEN / "pages").glob("chain-*.md")):
        md = f.read_text()
        for stage in re.split(r"\n## Stage ", md)[1:]:
            given = stage.split("\n\n", 2)[1] if "**Given.**" in stage else ""
            if not re.search(r"e_\{\\mathrm\{(wall|floor)\}\}", given):
                continue
            checked += 1
            for m in _maths(stage):
                bare = re.sub(r"\\[A-Za-z]+", "", re.sub(r"\\mathrm\{[^}]*\}", "", m))
                assert not re.search(r"(?<![A-Za-z])e(?![A-Za-z_])", bare), (f.name, m)
            assert not re.search(r"\$e = e_", given), (f.name, given)
    assert checked >= 5
