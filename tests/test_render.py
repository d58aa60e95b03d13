"""The worked solution reads like the notes: stages, equations (1)-(4), substitution lines, answer."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

import derive


@pytest.fixture(scope="module")
def md11() -> str:
    return derive.render(derive.solve(derive.load("notes-4c11-two-spheres")), "md")


@pytest.fixture(scope="module")
def md12() -> str:
    return derive.render(derive.solve(derive.load("notes-4c12-cue-ball")), "md")


def test_layout_of_the_notes(md11: str) -> None:
    heads = re.findall(r"^## (\d)\) (.+)$", md11, flags=re.M)
    assert [h[0] for h in heads] == ["1", "2", "3", "4"]
    assert "**Given.**" in md11 and "**Find.**" in md11
    for tag in "1234":
        assert md11.count(rf"\tag{{{tag}}}") == 1, tag
    assert md11.index(r"\tag{1}") < md11.index(r"\tag{2}") < md11.index(r"\tag{3}") < md11.index(r"\tag{4}")


def test_substitution_lines_are_shown(md11: str) -> None:
    # (3) with numbers, not simplified away: 20(5 cos 37.6) - 5(15 cos 37.6) = 20 v_A2n + 5 v_B2n
    assert r"20 \cdot 5 \cos {37.6^\circ} - 5 \cdot 15 \cos {37.6^\circ} = 20 v_{A2n} + 5 v_{B2n}" in md11
    # (4) with numbers
    assert r"0.6\left(5 \cos {37.6^\circ} + 15 \cos {37.6^\circ}\right) = v_{B2n} - v_{A2n}" in md11
    # the masses cancel in (1) and (2), as in the notes
    assert r"\cancel{m_{A}} v_{A1t} = \cancel{m_{A}} v_{A2t}" in md11


def test_rounded_intermediates_agree(md11: str) -> None:
    # 100 cos 37.6 = 79.229, 75 cos 37.6 = 59.422, sum 19.807 (the notes' 79.2 - 59.5 = 19.8 is a slip)
    assert "79.23 - 59.42 = 20 v_{A2n} + 5 v_{B2n}" in md11
    assert r"20 v_{A2n} + 5 v_{B2n} = 19.81 \tag{3}" in md11
    assert "59.5" not in md11


def test_elimination_is_written_out(md11: str) -> None:
    assert "From (4):" in md11
    assert "Substitute into (3):" in md11
    assert r"20 v_{A2n} + 5\left(v_{A2n} + 9.51\right) = 19.81" in md11  # notes: 9.5 and 19.8


def test_answer_is_boxed_and_marked(md11: str) -> None:
    assert r"\boxed{\vec{v}_{A2} = \left(3.05 \hat{e}_{t} - 1.11 \hat{e}_{n}\right)\ \mathrm{m/s}}" in md11
    assert r"\boxed{\vec{v}_{B2} = \left(-9.15 \hat{e}_{t} + 8.40 \hat{e}_{n}\right)\ \mathrm{m/s}}" in md11
    assert "ANSWER" in md11


def test_equal_symbolic_masses_cancel_and_add_subtract(md12: str) -> None:
    # Example 4.C.12: m cancels in (3); (3) and (4) are added and subtracted.
    assert r"\cancel{m} v_{A1} \sin {\theta_{1}} = \cancel{m} v_{A2n} + \cancel{m} v_{B2n}" in md12
    assert "Add (3) and (4)" in md12 and "Subtract (4) from (3)" in md12
    assert r"\tan^{-1}" in md12 and r"2.86^\circ" in md12


def test_digits_option_changes_figures() -> None:
    sol = derive.solve(derive.load("notes-4c11-two-spheres"))
    md = derive.render(sol, "md", digits=4)
    assert r"- 1.109 \hat{e}_{n}" in md
    data = json.loads(derive.render(sol, "json", digits=5))
    assert data["results"]["v_B2n"]["shown"] == "8.3983"


def test_json_contract() -> None:
    data = json.loads(derive.render(derive.solve(derive.load("notes-4c12-cue-ball")), "json"))
    assert {"title", "kind", "results"} <= set(data)
    assert data["kind"] == "oblique"
    r = data["results"]
    for name in ("v_A2n", "v_A2t", "v_B2n", "v_B2t", "v_A2", "v_B2", "theta_A2", "theta_B2", "T_lost"):
        assert set(r[name]) >= {"value", "unit", "expr", "latex"}, name
    assert r["v_B2n"]["value"] is None  # depends on the symbolic v_A1
    assert r["v_B2n"]["unit"] == "m/s"
    assert r["theta_A2"]["unit"] == "deg"
    assert r["theta_A2"]["value"] == pytest.approx(2.8624, abs=1e-4)


def test_user_text_is_escaped_in_every_format(problem_from) -> None:
    p = problem_from(
        r"""
        title = "Evil \\input{/etc/passwd} $x$ <script>alert(1)</script> # _"
        kind = "direct"
        statement = "\\write18{rm -rf /} \\def\\x{} \\catcode`\\@=11"
        [given]
        m_A = "1 kg"
        m_B = "1 kg"
        e = 0.5
        v_A1 = "1 m/s"
        v_B1 = "0 m/s"
        """
    )
    sol = derive.solve(p)
    tex = derive.render(sol, "tex")
    for bad in (r"\input{", r"\write18", r"\def\x", r"\catcode"):
        assert bad not in tex
    md = derive.render(sol, "md")
    assert "<script>" not in md
    assert r"\$x\$" in md


def test_jupyter_representations() -> None:
    sol = derive.solve(derive.load("notes-4c11-two-spheres"))
    assert sol._repr_markdown_().startswith("# Example 4.C.11")
    latex = sol._repr_latex_()
    assert latex.startswith("$$\\boxed{") and r"\hat{e}_{t}" in latex


def test_a_statement_writes_names_as_symbols() -> None:
    """Issue 15: 4.C.12's statement printed "theta_1" and "v_A1" literally. ``{name}`` of a
    given with a value is its value; of a letter or a result, its symbol; ``{@name}`` the symbol."""
    sol = derive.solve(derive.load("notes-4c12-cue-ball"))
    md = derive.render(sol, "md")
    given = md[md.index("**Given.**") : md.index("\n", md.index("**Given.**"))]
    assert r"speed $v_{A1}$, its velocity at $\theta_{1}$ = 45° to" in given
    assert r"at angle $\theta_{2}$" in given and "theta_" not in given.replace(r"\theta_", "")
    assert r"**Find.** Determine the rebound angle $\theta_{2}$ of A." in md
    tex = derive.render(sol, "tex")
    assert r"at $\theta_{1}$ = 45\textdegree{} to" in tex
    html = derive.render(sol, "html")
    given_html = html[html.index("<strong>Given.</strong>") : html.index("</p>", html.index("<strong>Given.</strong>"))]
    shown = re.sub(r"<annotation.*?</annotation>", "", given_html, flags=re.S)  # KaTeX keeps the TeX there
    assert "theta" not in shown and "katex" in shown  # typeset, not the letters


def test_unicode_subscripts_reach_latex_as_subscripts() -> None:
    """A statement's θ₂ came out of LaTeX as θ? (issue 15)."""
    from derive.escape import tex

    assert tex("θ₂") == r"$\theta$\textsubscript{2}"
    assert "?" not in tex("x₀ y₉ m² t⁴")


def test_a_page_writes_nothing_but_its_output(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """No cache on disk (issue #25): rendering a page writes nothing into the working folder,
    the temporary folder or the user's cache folder, and derive runs twice in a row in a
    process without ``os.geteuid`` (as on Windows, where a cache check once crashed the
    second run)."""
    import os
    import tempfile

    from derive.writers.view.jinja import environment

    work, tmp, cache = tmp_path / "cwd", tmp_path / "tmp", tmp_path / "cache"
    for folder in (work, tmp, cache):
        folder.mkdir()
    monkeypatch.chdir(work)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp))
    monkeypatch.setenv("XDG_CACHE_HOME", str(cache))
    monkeypatch.delattr(os, "geteuid", raising=False)
    environment.cache_clear()
    try:
        for _ in range(2):
            page = derive.render(derive.solve(derive.load("notes-4c11-two-spheres")), "md")
            assert "\\tag{4}" in page
            environment.cache_clear()
        assert list(work.iterdir()) == [] and list(tmp.iterdir()) == [] and list(cache.iterdir()) == []
    finally:
        environment.cache_clear()
