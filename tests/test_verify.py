"""The verifier (derive.verifier): it reads a page back and catches each known class of wrong line.

The pages in tests/data/verify/pages were written by hand in derive's layout,
with numbers from the notes or worked out with a calculator (each page says
how); they hold. Each test puts one bug of issue #12 back into a page, by
editing its text, and asserts that the verifier reports that line under the
right rule. The tests use derive only to load the problem (the facts); they do
not depend on how derive prints, so they pass before and after the printer's fixes.
"""

from __future__ import annotations

import ast
import time
from functools import cache
from pathlib import Path

import pytest

import derive
from derive.mathtext.display import parse_display
from derive.mathtext.tree import Add, Hat, Num, Sym, Vec
from derive.verifier import VerifyReport, verify_text
from derive.verifier.facts import Facts, facts_of
from derive.verifier.judge import read_display
from derive.verifier.reader import read_latex, read_markdown

DATA = Path(__file__).parent / "data" / "verify"
PAGES = DATA / "pages"
#: Which problem each hand-written page works (a bundled name or a file in tests/data/verify).
PROBLEMS = {
    "notes-4c11": "notes-4c11-two-spheres",
    "notes-4c12": "notes-4c12-cue-ball",
    "equal-masses-2kg": DATA / "equal-masses-2kg.toml",
    "tiny-masses": DATA / "tiny-masses.toml",
    "chain-name-capture": DATA / "chain-name-capture.toml",
    "chain-edexcel": "chain-edexcel-m2-three-particles",
    "chain-define-angle": DATA / "chain-define-angle.toml",
    "chain-thrown-down": "chain-ocr-m2-2015-thrown-down-bounce",
    "inverse-1-tan": DATA / "inverse-1-tan.toml",
    "notes-4c11-29kg": DATA / "notes-4c11-29kg.toml",
    "symbolic-energy": "ocr-m2-2014-particles-2m-3m-ke-lost",
}


@cache
def facts(page: str) -> Facts:
    return facts_of(derive.solve(derive.load(str(PROBLEMS[page]))))


def page_text(page: str) -> str:
    return (PAGES / f"{page}.md").read_text()


def line_failures(report: VerifyReport) -> list:
    """Failures of lines (not the page-level notes about derive's own solver)."""
    return [f for f in report.failures if f.rule != "physics"]


# ---------------------------------------------------------------- the pages hold


@pytest.mark.parametrize("page", sorted(PROBLEMS))
def test_a_page_written_by_hand_holds(page: str) -> None:
    report = verify_text(page_text(page), facts(page))
    assert report.lines > 0 and report.relations > 0
    assert not line_failures(report), report.format()
    assert not report.unchecked, f"names the facts do not know: {report.unchecked}"


# ---------------------------------------------------------------- each bug put back

#: (id, page, text replaced, replacement, the line the failure is on, rules expected there)
BUGS = [
    # Equal masses other than 1 kg: "Add (3) and (4): v_A2 cancels" (it does not) and 3 v_B2 = 4 + 0.
    (
        "equal-masses-add-says-cancels",
        "equal-masses-2kg",
        "From (4):\n\n$$\nv_{B2} = v_{A2} + 0\n$$",
        "Add (3) and (4): $v_{A2}$ cancels.\n\n$$\n3 v_{B2} = 4 + 0\n$$",
        "3 v_{B2} = 4 + 0",
        {"references", "equals"},
    ),
    # Tiny magnitudes: written out in full, and 1.00 v_A2 = 0.00 - 2000000.
    (
        "tiny-mass-written-out",
        "tiny-masses",
        r"m_{A} = 1.67 \times 10^{-27}\ \mathrm{kg}",
        r"m_{A} = 0.00000000000000000000000000167\ \mathrm{kg}",
        "m_{A} = 0.000",
        {"notation"},
    ),
    (
        "tiny-elimination-reads-zero",
        "tiny-masses",
        r"v_{B2} = v_{A2} + 2.00 \times 10^{6}",
        r"1.00 v_{A2} = 0.00 - 2000000",
        "1.00 v_{A2}",
        {"equals", "zero", "notation"},
    ),
    # Chain stage name capture: m_A = m_B = 3 kg, and the momentum line worked with 3 and 3.
    (
        "chain-given-of-another-body",
        "chain-name-capture",
        r"$m_{A} = m_{B} = 2\ \mathrm{kg}$",
        r"$m_{A} = m_{B} = 3\ \mathrm{kg}$",
        "m_{A} = m_{B} = 3",
        {"givens", "equals"},
    ),
    (
        "chain-substitutes-another-body",
        "chain-name-capture",
        r"8 \cdot 2 + 0 \cdot 3 = 2 v_{A2} + 3 v_{B2}",
        r"8 \cdot 3 + 0 \cdot 3 = 2 v_{A2} + 3 v_{B2}",
        r"8 \cdot 3",
        {"givens", "equals"},
    ),
    (
        "chain-boxes-the-captured-answer",
        "chain-name-capture",
        r"\boxed{v_{A2} = 3.20\ \mathrm{m/s}}",
        r"\boxed{v_{A2} = 4.00\ \mathrm{m/s}}",
        "v_{A2} = 4.00",
        {"equals"},
    ),
    # The printer turned -1/tan(x) into "1 tan(x)".
    (
        "one-tan-for-minus-one-over-tan",
        "inverse-1-tan",
        r"e = \frac{\sin {\alpha} - \cos {\alpha}}{\sin {\alpha} + \cos {\alpha}}",
        r"e = 1 \tan{\left(\alpha + 0.785 \right)}",
        r"e = 1 \tan",
        {"equals"},
    ),
    # Equation references in later chain stages: "Add (15) and (10)", "Subtract (10) from (3)".
    (
        "reference-to-no-equation",
        "chain-edexcel",
        "Add (9) and (10)",
        "Add (15) and (10)",
        "2 v_{C2} =",
        {"references"},
    ),
    (
        "reference-to-another-stage",
        "chain-edexcel",
        "Subtract (10) from (9)",
        "Subtract (10) from (3)",
        "2 v_{B2} =",
        {"references"},
    ),
    ("reference-that-means-otherwise", "notes-4c11", "From (4):", "From (3):", "v_{B2n} = v_{A2n} +", {"references"}),
    (
        "cancels-what-does-not",
        "notes-4c12",
        "Add (3) and (4): $v_{A2n}$ cancels.",
        "Add (3) and (4): $v_{B2n}$ cancels.",
        "2 v_{B2n} =",
        {"references"},
    ),
    # An angle in a define stage with its radian value and a degree sign.
    (
        "radians-with-a-degree-sign",
        "chain-define-angle",
        r"\beta = -th = -23.4^\circ \tag{7}",
        r"\beta = -th = -23.41^\circ = -0.409^\circ \tag{7}",
        r"\beta = -th",
        {"angle"},
    ),
    # Homework variants of a varied angle: "10 · cos {30}", an angle in degrees without its sign.
    (
        "degrees-without-a-degree-sign",
        "notes-4c11",
        r"= 5 \cos {37.6^\circ} = 3.96",
        r"= 5 \cos {37.6} = 3.96",
        r"5 \cos {37.6} = 3.96",
        {"angle"},
    ),
    # Digits: 149.3466 - 22.1841 in a 3-figure solution; (3) shown one way and substituted another.
    (
        "too-many-figures",
        "notes-4c11-29kg",
        r"\Rightarrow\quad 29 v_{A2n} + 2 v_{B2n} = 127.2 \tag{3}",
        "149.3466 - 22.1841 = 29 v_{A2n} + 2 v_{B2n}\n$$\n\n$$\n"
        r"\Rightarrow\quad 29 v_{A2n} + 2 v_{B2n} = 127.2 \tag{3}",
        "149.3466",
        {"figures"},
    ),
    (
        "value-shown-two-ways",
        "notes-4c11-29kg",
        r"2\left(v_{A2n} + 11.37\right) = 127.2",
        r"2\left(v_{A2n} + 11.37\right) = 127.16",
        "127.16",
        {"consistent"},
    ),
    # A sum that does not add up: T_1 = 813 J, T_2 = 491 J and a loss of 321 J; the notes' own slip.
    (
        "loss-not-the-difference-shown",
        "notes-4c11",
        r"T_{1} - T_{2} = 812.5 - 491.1 = 321",
        r"T_{1} - T_{2} = 321",
        r"T_{\mathrm{lost}}",
        {"sums"},
    ),
    (
        "the-notes-slip-79.2-59.5",
        "notes-4c11",
        "79.23 - 59.42 = 20 v_{A2n} + 5 v_{B2n}",
        "79.2 - 59.5 = 20 v_{A2n} + 5 v_{B2n}",
        "79.2 - 59.5",
        {"sums"},
    ),
    # One ANSWER mark per answer, and none on a chain's intermediate stage.
    (
        "two-answer-marks",  # the two velocity vectors are marked, as in the notes; a third mark is one too many
        "notes-4c11",
        r"= 813\ \mathrm{J}",
        r"= 813\ \mathrm{J}\quad\longleftarrow\ \text{ANSWER}",
        "= 813",
        {"answers"},
    ),
    (
        "intermediate-marked-answer",
        "chain-name-capture",
        r"\boxed{v_{A2} = 3.20\ \mathrm{m/s}}",
        r"\boxed{v_{A2} = 3.20\ \mathrm{m/s}}\quad\longleftarrow\ \text{ANSWER}",
        r"\boxed{v_{A2} = 3.20",
        {"answers"},
    ),
    # An ANSWER mark on each result asked (a chain marks each of its answers): one missing,
    # one result marked twice, a result not asked marked.
    (
        "chain-answer-not-marked",  # chain-edexcel's file asks for u_B and e; e boxed but unmarked
        "chain-edexcel",
        r"\boxed{e = 0.512}\quad\longleftarrow\ \text{ANSWER}",
        r"\boxed{e = 0.512}",
        r"\boxed{e = 0.512}",
        {"answers"},
    ),
    (
        "chain-answer-not-asked-marked",  # u_C = 1.75 (1 + e)^2 = 4.00 m/s is a step, not asked
        "chain-edexcel",
        r"\boxed{e = 0.512}\quad\longleftarrow\ \text{ANSWER}",
        r"\boxed{e = 0.512}\quad\longleftarrow\ \text{ANSWER}"
        "\n$$\n\n$$\n"
        r"\boxed{u_{C} = 4.00\ \mathrm{m/s}}\quad\longleftarrow\ \text{ANSWER}",
        r"\boxed{u_{C} = 4.00",
        {"answers"},
    ),
    (
        "one-result-marked-twice",  # 4.C.11: B's vector is marked; its speed is the same result again
        "notes-4c11",
        r"= 12.4\ \mathrm{m/s}}",
        r"= 12.4\ \mathrm{m/s}}\quad\longleftarrow\ \text{ANSWER}",
        "= 12.4",
        {"answers"},
    ),
    (
        "answer-with-no-mark",  # 4.C.12 asks for theta_A2: boxed, its mark gone
        "notes-4c12",
        r"\quad\longleftarrow\ \text{ANSWER}",
        "",
        r"\boxed{\theta_{A2}",
        {"answers"},
    ),
    # Chains: a value carried before the unknown it depends on is found; a solve stage with no
    # algebra; v_2 = -u = -u; an impulse carried but never worked out.
    (
        "carried-before-solved",
        "chain-edexcel",
        r"$u_{B} = v_{B2} = \left(3.50 + 3.50 e\right)\ \mathrm{m/s}$",
        r"$u_{B} = v_{B2} = 5.29\ \mathrm{m/s}$",
        "u_{B} = v_{B2} = 5.29",
        {"order"},
    ),
    (
        "solve-stage-without-algebra",
        "chain-edexcel",
        r"u_{C} = 1.75 \left(1 + e\right)^{2} = 4.00\ \mathrm{m/s}"
        "\n$$\n\n$$\n"
        r"\Rightarrow\quad e = \sqrt{\frac{4.00}{1.75}} - 1 = 0.512 \tag{13}",
        "u_{C} = 4.00\n$$\n\n$$\n" r"\Rightarrow\quad e = 0.512 \tag{13}",
        r"e = 0.512 \tag{13}",
        {"derived"},
    ),
    ("side-written-twice", "chain-thrown-down", "v_{2} = -u = 5.26", "v_{2} = -u = -u = 5.26", "v_{2} =", {"repeated"}),
    (
        "impulse-carried-never-worked-out",
        "chain-thrown-down",
        r"\boxed{J_{n} = m_{A} \left(v_{A1} - v_{A2}\right) = 0.2\left(7.507 + 5.255\right) = 2.55\ \mathrm{N\cdot s}}",
        r"\boxed{v_{A2} = -5.26\ \mathrm{m/s}}",
        "Carried to the next stages",
        {"derived"},
    ),
    # Units: a quantity with a unit of another dimension; an energy "22.0 m" read as metres.
    ("unit-of-another-dimension", "notes-4c11", r"= 813\ \mathrm{J}", r"= 813\ \mathrm{m}", "= 813", {"unit"}),
    (
        "energy-read-as-metres",
        "symbolic-energy",
        r"= 22.0 m\ \mathrm{J/kg}",
        "= 22.0 m",
        "= 22.0 m",
        {"unit"},
    ),
    # The values in the Given list and in a substitution line are this problem's, for this body.
    (
        "given-of-another-body",
        "notes-4c11",
        r"$m_{A} = 20\ \mathrm{kg}$",
        r"$m_{A} = 5\ \mathrm{kg}$",
        "m_{A} = 5",
        {"givens"},
    ),
    (
        "substitution-of-another-body",
        "notes-4c11",
        r"20 \cdot 5 \cos {37.6^\circ} - 5 \cdot 15",
        r"20 \cdot 15 \cos {37.6^\circ} - 5 \cdot 5",
        r"20 \cdot 15",
        {"givens", "equals"},
    ),
    # Each = holds to the precision shown.
    ("a-wrong-rounding", "notes-4c11", "+ 8.40 \\hat{e}_{n}", "+ 8.41 \\hat{e}_{n}", "8.41", {"equals"}),
    ("a-line-it-cannot-read", "notes-4c11", "v_{B2n} = v_{A2n} + 9.507", r"v_{B2n} = \foo{9.507}", r"\foo", {"read"}),
]


@pytest.mark.parametrize(("page", "old", "new", "where", "rules"), [b[1:] for b in BUGS], ids=[b[0] for b in BUGS])
def test_a_bug_put_back_is_caught(page: str, old: str, new: str, where: str, rules: set[str]) -> None:
    text = page_text(page)
    assert old in text, f"the page no longer has {old!r}"
    text = text.replace(old, new, 1)
    report = verify_text(text, facts(page))
    at = [f for f in line_failures(report) if where in f.text or where in text.splitlines()[f.line - 1]]
    found = {f.rule for f in at}
    assert rules <= found, f"expected {sorted(rules)} at the line with {where!r}, got:\n{report.format()}"


def test_the_report_names_whose_value_a_wrong_given_is() -> None:
    text = page_text("chain-name-capture").replace(r"$m_{A} = m_{B} = 2\ ", r"$m_{A} = m_{B} = 3\ ", 1)
    reasons = [f.reason for f in verify_text(text, facts("chain-name-capture")).failures if f.rule == "givens"]
    assert reasons == ["m_A here is 2; 3 is m_B of this stage"]


def test_the_same_page_in_latex_is_read_the_same() -> None:
    md = page_text("notes-4c11")
    # the same page as LaTeX: $$ pairs become equation* environments, sections \subsection*
    out, inside = [], False
    for row in md.splitlines():
        if row == "$$":
            out.append(r"\end{equation*}" if inside else r"\begin{equation*}")
            inside = not inside
        elif inside:
            out.append(row)
        elif row.startswith("## "):
            out.append(r"\subsection*{" + row[3:] + "}")
        elif row.startswith("- $"):
            out.append(r"  \item " + row[2:])
        elif row and not row.startswith(("<", "#", "*")):
            out.append(r"\noindent " + row + r"\par")
    a = [(c.kind, c.latex) for c in read_markdown(md)]
    b = [(c.kind, c.latex) for c in read_latex("\n".join(out))]
    assert a == b
    assert verify_text("\n".join(out), facts("notes-4c11"), "tex").ok


# ---------------------------------------------------------------- the reader


def test_numbers_keep_the_figures_they_show() -> None:
    (rel,) = parse_display(r"v = 3.050 + 1.67 \times 10^{-27} + 37.6^\circ + 12300").relations
    terms = [t for _, t in rel.sides[1].expr.terms]
    assert [(n.mantissa, n.exponent, n.degrees, n.figures) for n in terms] == [
        ("3.050", 0, False, 4),
        ("1.67", -27, False, 3),
        ("37.6", 0, True, 3),
        ("12300", 0, False, 3),
    ]
    assert str(terms[0].ulp) == "0.001"


def test_a_line_and_its_decorations() -> None:
    d = read_display(
        r"\Rightarrow\quad \boxed{\vec{v}_{A2} = 3.05 \hat{e}_{t} - \cancel{m_{A}} \hat{e}_{n}\ \mathrm{m/s}}"
        r"\quad\longleftarrow\ \text{ANSWER} \tag{7}"
    )
    assert (d.implies, d.boxed, d.answer_marks, d.tag) == (True, True, 1, "7")
    (rel,) = d.relations
    assert isinstance(rel.sides[0].expr, Vec) and rel.sides[0].expr.name == "v_A2"
    assert rel.sides[1].unit == "m/s"
    right = rel.sides[1].expr
    assert isinstance(right, Add) and isinstance(right.terms[0][1].factors[1], Hat)
    assert right.terms[1][1].factors[0] == Sym("m_A", cancelled=True) or right.terms[1][1].factors[0].cancelled


def test_names_as_the_page_writes_them() -> None:
    (rel,) = parse_display(r"T_{\mathrm{lost}} = \theta_{A2} + e_{\mathrm{floor}} + \mu_{k} + m_{pan}").relations
    names = [rel.sides[0].expr.name] + [t.name for _, t in rel.sides[1].expr.terms]
    assert names == ["T_lost", "theta_A2", "e_floor", "mu_k", "m_pan"]


def test_inverse_functions_and_roots() -> None:
    (rel,) = parse_display(
        r"\theta = \tan^{-1}\left(\frac{1}{2}\right) + \sin^{2} {\phi} + \sqrt{2} + \left|{x}\right|"
    ).relations
    names = [type(t).__name__ + ":" + getattr(t, "name", "") for _, t in rel.sides[1].expr.terms]
    assert names == ["Func:atan", "Pow:", "Func:sqrt", "Func:abs"]


# ---------------------------------------------------------------- independence, API, CLI


def test_only_the_facts_touch_derive() -> None:
    """The checking logic imports nothing of derive but the verifier itself and the leaf that
    reads typed mathematics, mathtext (the facts may read derive's objects and its expression
    parser; no module prints or solves)."""
    root = Path(derive.__file__).parent / "verifier"
    for path in root.rglob("*.py"):
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.ImportFrom) and node.module:
                names = [node.module]
            elif isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            for name in names:
                if not name.startswith("derive") or name.startswith(("derive.verifier", "derive.mathtext")):
                    continue
                where = path.relative_to(root).as_posix()
                if where.startswith("facts/"):
                    assert name in ("derive.problem.expr",), f"{where} imports {name}"
                else:
                    assert where == "__init__.py" and name == "derive.writers.view", f"{where} imports {name}"


def test_derive_verify_from_python() -> None:
    solution = derive.solve(derive.load("notes-4c11-two-spheres"))
    report = derive.verify(solution)
    assert isinstance(report, VerifyReport) and report.lines > 30
    assert derive.verify(solution, "tex").lines == report.lines


def test_derive_solve_verify(cli, tmp_path: Path) -> None:
    """--verify prints each failing line with its reason and exits 1 on any failure, else 0."""
    problem = DATA / "equal-masses-2kg.toml"
    expected = derive.verify(derive.solve(derive.load(str(problem))))
    r = cli("solve", str(problem), "--verify", "--no-figure")
    assert r.code == (0 if expected.ok else 1)
    assert r.err.strip().splitlines()[-1].startswith("verify: ")
    for f in expected.failures:
        assert f.reason in r.err


def test_fast_enough() -> None:
    """Well under half a second for a page (the figure is in docs/verify.md)."""
    solution = derive.solve(derive.load("notes-4c11-two-spheres"))
    text = derive.render(solution, "md", figures=False)
    start = time.perf_counter()
    verify_text(text, facts_of(solution))
    assert time.perf_counter() - start < 1.0


def test_numbers_and_names_of_the_tree() -> None:
    assert Num("0.00").figures == 0 and Num("2000000").figures == 1 and Num("1.000").figures == 4
