"""Typed derivations: the reader of plain and LaTeX lines, and the line-by-line judge
(the first false line, the mistake that explains it, the lines carried from it).

The derivations follow the notes' Example 4.C.11 (m_A = 20 kg, m_B = 5 kg, e = 0.6,
5 m/s and 15 m/s at 37.6°) and 4.C.12; every wrong number in them is worked here by
hand from the slip it carries, never taken from derive's output.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import pytest
from support.checked import lines

import derive
from derive.mathtext.latex import latex_to_plain
from derive.mathtext.reader import read_relations

DOCS = Path(__file__).resolve().parent.parent / "docs" / "checking.md"
C11 = "notes-4c11-two-spheres"
C12 = "notes-4c12-cue-ball"
DEG = math.pi / 180
COS, SIN = math.cos(37.6 * DEG), math.sin(37.6 * DEG)
_SOLVED: dict[str, derive.Solution] = {}


def solved(name: str) -> derive.Solution:
    if name not in _SOLVED:
        _SOLVED[name] = derive.solve(derive.load(name))
    return _SOLVED[name]


def statuses(report: derive.checking.report.CheckReport) -> dict[str, str]:
    return {i.name: i.status for i in report.items}


# ------------------------------------------------------------------ the reader


@pytest.mark.parametrize(
    ("tex", "plain"),
    [
        (r"v_{A2t} = 5 \sin 37.6^\circ", "v_A2t = 5 sin 37.6°"),
        (r"e = \frac{v_{B2n} - v_{A2n}}{v_{A1n} - v_{B1n}}", "e = (v_B2n - v_A2n)/(v_A1n - v_B1n)"),
        (r"\frac{\sqrt{2}}{4} (1-e) v_{A1}", "(sqrt(2)/4) (1 - e) v_A1"),
        (r"\cancel{m_A} v_{At2} = \cancel{m_A} v_{At1}", "(m_A) v_At2 = (m_A) v_At1"),
        (r"\theta_2 = \tan^{-1}(0.05)", "theta_2 = atan(0.05)"),
        (r"v_{B2n} - v_{A2n} = 9.5 \text{ m/s (4)}", "v_B2n - v_A2n = 9.5 (4)"),
        (r"\underbrace{v_{A2} \cos \theta_2}_{v_{A2t}} = 3", "v_A2 cos theta_2 = 3"),
        (r"a \cdot b \times c", "a * b * c"),
    ],
)
def test_latex_rows_become_plain_text(tex: str, plain: str) -> None:
    assert latex_to_plain(tex) == plain


def test_plain_lines_are_read_one_relation_a_line() -> None:
    text = "# my work\n20 v_A2n + 5 v_B2n = 19.8\n\nv_B2n - v_A2n = 9.5   (4)\nso v_A2n = -1.11 m/s\nplug in (3)\n"
    lines = read_relations(text)
    assert [ln.line for ln in lines] == [2, 4, 5]
    assert [ln.sides for ln in lines] == [
        ("20 v_A2n + 5 v_B2n", "19.8"),
        ("v_B2n - v_A2n", "9.5"),
        ("v_A2n", "-1.11"),
    ]
    assert [ln.tag for ln in lines] == ["", "4", ""]


def test_markdown_and_latex_maths_are_found_with_their_line_numbers() -> None:
    text = "\n".join(
        [
            "Some words, $v_{A2t} = 3.05$ inline.",  # 1
            "$$m_A v_{A1n} + m_B v_{B1n}",  # 2
            "= m_A v_{A2n} + m_B v_{B2n}$$",  # 3
            r"\[ v_{B2n} - v_{A2n} = 9.51 \tag{4} \]",  # 4
            r"\begin{align}",  # 5
            r"20 v_{A2n} + 5(9.5 + v_{A2n}) &= 19.8 \\",  # 6
            r"v_{A2n}(20 + 5) &= 19.8 - 5(9.5)",  # 7
            r"\end{align}",  # 8
            r"$$v_{A2n} = -1.11 \text{ m/s} \rightarrow \text{in (4)} \Rightarrow v_{B2n} = 8.4 \text{ m/s}$$",  # 9
        ]
    )
    lines = read_relations(text)
    assert [ln.line for ln in lines] == [1, 2, 4, 6, 7, 9, 9]
    assert lines[1].sides == ("m_A v_A1n + m_B v_B1n", "m_A v_A2n + m_B v_B2n")
    assert lines[2].tag == "4"
    assert lines[4].sides == ("v_A2n(20 + 5)", "19.8 - 5(9.5)")
    assert [ln.sides for ln in lines[5:]] == [("v_A2n", "-1.11"), ("v_B2n", "8.4")]


def test_the_notes_spelling_of_names() -> None:
    from derive.checking.naming import notes_names

    assert notes_names("M_A V_At1 = M_A V_A2t") == "m_A v_A1t = m_A v_A2t"


def test_lines_that_are_not_relations_are_skipped() -> None:
    assert read_relations("F_AB ≠ 0\nmomentum is conserved\nx < 3\n") == ()


# ------------------------------------------------------------------ the judge


def test_the_documented_derivation_is_reported_as_documented() -> None:
    """docs/checking.md: Example 4.C.11 with 79.2 − 59.5 copied as 79.2 + 59.5 in (3)."""
    text = DOCS.read_text(encoding="utf-8")
    work = re.search(r"```markdown\n(.*?)```", text, flags=re.S).group(1)
    shown = re.search(r"```text\n(derive check: .*?)```", text, flags=re.S).group(1)
    report = derive.check(solved(C11), derivation=work)
    assert report.render("text") == shown
    lines = work.splitlines()
    slip = next(n for n, ln in enumerate(lines, 1) if "79.2 + 59.5" in ln)
    by_line = {int(i.name): i for i in report.items}
    assert by_line[slip].status == "wrong"
    assert [d.mistake for d in by_line[slip].diagnosis] == ["b_sign"]  # (3) with +v_B1n
    assert all(i.status == "correct" for n, i in by_line.items() if n < slip)
    after = {n: i.status for n, i in by_line.items() if n > slip}
    assert set(after.values()) == {"carried", "correct"}
    carried = [lines[n - 1] for n, s in after.items() if s == "carried"]
    assert any("138.7 \\quad (3)" in ln for ln in carried)
    assert any("v_{B2n} = 9.51 + 3.65 = 13.2" in ln for ln in carried)
    # (4) and the impact rule do not depend on the slip: they stay correct
    correct_after = [lines[n - 1] for n, s in after.items() if s == "correct"]
    assert any("9.51" in ln and "(4)" in ln for ln in correct_after)
    assert report.exit_code == 1


def test_the_documented_slip_carries_these_numbers() -> None:
    """The docs' derivation by hand: the slip's (3), 20 v_A2n + 5 v_B2n = 79.2 + 59.5 as the
    student wrote it (the notes' 79.2 - 59.5 with the sign flipped), with the correct (4)."""
    assert round(20 * 5 * COS, 1) == 79.2  # the notes' 79.2 (their 59.5 is 59.43)
    c3 = 79.2 + 59.5
    c4 = 0.6 * (5 + 15) * COS
    a = (c3 - 5 * c4) / 25
    assert round(c4, 2) == 9.51 and round(a, 2) == 3.65 and round(a + c4, 1) == 13.2


def test_plain_lines_with_a_sin_cos_swap() -> None:
    # A student who resolves with sin for n: (3) then reads 20(5 sin 37.6°) - 5(15 sin 37.6°)
    c3 = 20 * 5 * SIN - 5 * 15 * SIN
    c4 = 0.6 * (5 + 15) * COS
    a = (c3 - 5 * c4) / 25
    work = "\n".join(
        [
            "v_A2t = 5 sin 37.6°",
            "20(5 sin 37.6°) - 5(15 sin 37.6°) = 20 v_A2n + 5 v_B2n",
            f"20 v_A2n + 5 v_B2n = {c3:.2f}",
            "v_B2n - v_A2n = 0.6(5 cos 37.6° + 15 cos 37.6°)",
            f"v_A2n = {a:.3f}",
            f"v_B2n = {a + c4:.3f}",
        ]
    )
    report = derive.check(solved(C11), derivation=work)
    assert statuses(report) == {
        "1": "correct",
        "2": "wrong",
        "3": "carried",
        "4": "correct",
        "5": "carried",
        "6": "carried",
    }, report.text()
    slip = report.items[1]
    assert [d.mistake for d in slip.diagnosis] == ["sin_cos_swapped"]
    assert "first line that is false" in slip.message  # (3), in words (issue #31, item 7)
    assert "momentum of A and B together along the line of impact" in slip.message


def test_the_same_mistake_made_again_is_said_so() -> None:
    work = "v_A2t = 5 cos 37.6°\nv_B2t = -15 cos 37.6°\n"
    report = derive.check(solved(C11), derivation=work)
    assert [i.status for i in report.items] == ["wrong", "wrong"]
    assert "same mistake as in line 1" in report.items[1].message


def test_an_arithmetic_slip_carries_its_number() -> None:
    wrong = 29.7  # 79.2 - 59.5 is 19.7
    a = (wrong - 5 * 9.51) / 25
    work = f"79.2 - 59.5 = {wrong}\n20 v_A2n + 5 v_B2n = {wrong}\nv_B2n - v_A2n = 9.51\nv_A2n = {a:.3f}\n"
    report = derive.check(solved(C11), derivation=work)
    assert [i.status for i in report.items] == ["wrong", "carried", "correct", "carried"], report.text()
    assert "19.70, not 29.7" in report.items[0].message


def test_a_final_answer_slip_and_rounded_working() -> None:
    # the notes' own numbers, (3) 19.8 and (4) 9.5, then a slip in the last line
    work = "20 v_A2n + 5 v_B2n = 19.8\nv_B2n - v_A2n = 9.5\nv_A2n = (19.8 - 5*9.5)/25\nv_A2n = -1.11\nv_B2n = 9.5 - 1.11\nv_B2n = 7.39\n"
    report = derive.check(solved(C11), derivation=work)
    assert [i.status for i in report.items] == ["correct"] * 5 + ["wrong"], report.text()


def test_a_line_that_cannot_be_read_is_not_read_and_the_rest_is_judged() -> None:
    # issue 31: one unreadable line never turns the report into bad input
    work = "20 v_A2n + 5 v_B2n = 19.8\nv_X2 = 3\nv_B2n - v_A2n = 9.5\n"
    report = derive.check(solved(C11), derivation=work)
    assert [i.status for i in report.items] == ["correct", "not read", "correct"]
    assert "v_X2" in report.items[1].message
    assert report.exit_code == 0 and "1 not read" in report.summary()


def test_the_notes_derivation_of_4c12_is_all_correct() -> None:
    work = "\n".join(
        [
            r"$$m v_{A1} \sin \theta_1 = m v_{A2} \sin \theta_2 + m v_{B2}$$",
            r"$$\frac{\sqrt{2}}{2} v_{A1} = v_{A2n} + v_{B2n} \quad (1)$$",
            r"$$\frac{\sqrt{2}}{2} e v_{A1} = -v_{A2n} + v_{B2n} \quad (3)$$",
            r"$$v_{B2n} = \frac{\sqrt{2}}{4} (1+e) v_{A1} \quad (4)$$",
            r"$$\frac{\sqrt{2}}{4} (1-e) v_{A1} = v_{A2n} \quad (5)$$",
            r"$$\theta_2 = \tan^{-1}(0.05) \approx 2.86^\circ$$",
        ]
    )
    report = derive.check(solved(C12), derivation=work)
    assert report.all_correct, report.text()
    assert len(report.items) == 6


def test_a_slip_in_a_symbolic_derivation() -> None:
    # 4.C.12 with (1 - e) for (1 + e): v_B2n would be sqrt(2)/4 (1 - e) v_A1
    work = r"$$v_{B2n} = \frac{\sqrt{2}}{4} (1-e) v_{A1}$$" + "\n" + r"$$v_{B2} = 0.0354 v_{A1}$$"
    report = derive.check(solved(C12), derivation=work)
    assert [i.status for i in report.items] == ["wrong", "carried"], report.text()
    assert math.sqrt(2) / 4 * (1 - 0.9) == pytest.approx(0.0354, abs=1e-4)


def test_cli_derivation(cli, tmp_path: Path) -> None:
    work = tmp_path / "work.txt"
    work.write_text("20 v_A2n + 5 v_B2n = 19.8\nv_B2n - v_A2n = 9.5\nv_A2n = -1.11\n", encoding="utf-8")
    r = cli("check", C11, "--derivation", str(work))
    assert r.code == 0, r.out + r.err
    assert "3 of 3 correct" in r.out
    r = cli("check", C11, "--derivation", str(tmp_path / "missing.md"))
    assert r.code == 2 and r.err.startswith("Error: ")
    empty = tmp_path / "empty.md"
    empty.write_text("no mathematics here\n", encoding="utf-8")
    r = cli("check", C11, "--derivation", str(empty), "--format", "json")
    assert r.code == 2 and '"status": "error"' in r.out


def test_a_long_derivation_says_what_was_not_checked() -> None:
    from derive.checking.lines import MAX_LINES

    work = "v_A2t = 5 sin 37.6°\n" * (MAX_LINES + 3)
    report = derive.check(solved(C11), derivation=work)
    assert len(report.items) == MAX_LINES + 1
    assert report.items[-1].status == "error" and "3 more relations" in report.items[-1].message


def test_two_values_with_or_where_the_relations_are_linear_are_a_guess() -> None:
    # OCR M2 2014: A (2m) at 4, B (3m) at -2, e = 0.4. 2 = 2x + 3y, y - x = 0.4(6) = 2.4: x = -1.04,
    # y = 1.36, one solution (no quadratic). "x = -1.04 or x = -1.4" hedges: the -1.4 is a slip, as is
    # Edexcel M2 2004's "y = 2u + 2eu or y = 2u - 2eu" (10u = 2x + 3y, y - x = 5eu: y = 2(1 + e)u only).
    head = "2m(4) + 3m(-2) = 2m v_A2 + 3m v_B2\n2 = 2v_A2 + 3v_B2\nv_B2 - v_A2 = 2.4\n"
    assert lines("ocr-m2-2014-particles-2m-3m-ke-lost", head + "v_A2 = -1.04 or v_A2 = -1.4\n")[4][0] == "wrong"
    work = "10mu = 2m v_A2 + 3m v_B2\nv_B2 - v_A2 = 5eu\nv_B2 = 2u + 2eu or v_B2 = 2u - 2eu\n"
    assert lines("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", work)[3][0] == "wrong"


def test_both_roots_of_a_quadratic_and_the_rejected_one_are_not_slips() -> None:
    # CIE 9231 June 2014 Q3: A (m) at u hits B (9m) at rest, half the KE lost. x for A, y for B:
    # u = x + 9y, x² + 9y² = u²/2 -> 180y² - 36uy + u² = 0 = (6y - u)(30y - u): y = u/6 or u/30.
    # y = u/30 gives x = 7u/10 > y (A through B): rejected; y = u/6, x = -u/2. The root not kept
    # is no slip, nor is the line that tries it and rejects it; two values neither of which is a
    # root (u/30 or u/5) are still wrong.
    problem = "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost"
    head = "Let $x = v_{A2}$, $y = v_{B2}$\n$u = x + 9y$\n$x^2 + 9y^2 = u^2/2$\n"
    work = (
        "$(6y - u)(30y - u) = 0$ so $y = \\frac{u}{30}$ or $y = \\frac{u}{6}$\n"
        "If $y = \\frac{u}{30}$ then $x = \\frac{7u}{10}$, faster than B: reject.\n"
        "$y = \\frac{u}{6}$, $x = -\\frac{u}{2}$\n"
    )
    found = lines(problem, head + work)
    assert found[4][0] == found[6][0] == "correct"
    assert found.get(5, ("not read",))[0] in ("not read", "correct")
    assert lines(problem, head + "(6y - u)(30y - u) = 0\ny = u/30 or u/6\n")[5][0] == "correct"
    assert lines(problem, head + "(6y - u)(30y - u) = 0\ny = u/30 or y = u/5\n")[5][0] == "wrong"


@pytest.mark.parametrize("end", ["\r", "\u2028", "\x0c"])
def test_lines_ended_by_other_line_ends_are_each_judged(end: str) -> None:
    # Notes 4.C.11: normal components before 5 cos 37.6° = 3.962 and -15 cos 37.6° = -11.885;
    # momentum 20(3.962) + 5(-11.885) = 19.8, restitution 0.6(3.962 + 11.885) = 9.5, so
    # 25 v_A2n = 19.8 - 5(9.5) and v_A2n = -1.11 (the notes' value). A line separator (U+2028)
    # or a form feed once ran the three lines into one, judged wrong.
    work = end.join(["20 v_A2n + 5 v_B2n = 19.8", "v_B2n - v_A2n = 9.5", "v_A2n = -1.11"])
    found = lines("notes-4c11-two-spheres", work)
    assert {n: found[n][0] for n in found} == {1: "correct", 2: "correct", 3: "correct"}
