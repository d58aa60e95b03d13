"""Chains: each bundled chain reproduces its published answers; the stage types
agree with energy and momentum worked by hand; equation numbers run on."""

from __future__ import annotations

import math
import re
import textwrap
import tomllib
from decimal import ROUND_HALF_UP, Decimal
from functools import cache

import pytest
import sympy

import derive
from derive.problem import loads
from derive.resources import bundled
from derive.steps.model import Solution as ChainSolution

# (chain, quantity, published as printed, rule): "digits" = equal when rounded to the
# published places; "digits±1" = the source rounded an intermediate; "corrected" = the
# source is wrong and the value here is the corrected one (the file says why).
PUBLISHED = [
    ("chain-ocr-m2-2015-thrown-down-bounce", "v_1", "7.507", "digits"),
    ("chain-ocr-m2-2015-thrown-down-bounce", "v_2", "5.255", "digits"),
    ("chain-ocr-m2-2015-thrown-down-bounce", "h_2", "1.409", "digits"),
    ("chain-ocr-m2-2015-thrown-down-bounce", "J", "2.55", "digits"),
    ("chain-ocr-m2-2015-thrown-down-bounce", "E_lost", "2.87", "digits"),
    ("chain-ocr-m2-2007-rebounds-to-start", "v_1", "35", "digits"),
    ("chain-ocr-m2-2007-rebounds-to-start", "v_2", "28", "digits"),
    ("chain-ocr-m2-2007-rebounds-to-start", "e_floor", "0.8", "digits"),
    ("chain-ocr-m2-2007-rebounds-to-start", "J", "12.6", "digits"),
    ("chain-ocr-m2-2006-drop-rebound", "v_1", "6.26", "digits"),
    ("chain-ocr-m2-2006-drop-rebound", "v_2", "5.24", "digits"),
    ("chain-ocr-m2-2006-drop-rebound", "J", "3.45", "digits"),
    ("chain-block-onto-spring-pan", "x", "0.225", "digits"),
    ("chain-msu-bullet-block-swings", "T_after", "4.5", "digits"),
    ("chain-msu-bullet-block-swings", "h_2", "0.11", "corrected"),  # published 0.12 m; V²/2g = 0.114 m
    ("chain-hibbeler-15-58-suitcases", "v_1", "19.657", "digits"),
    ("chain-hibbeler-15-58-suitcases", "u_A", "9.435", "digits"),
    ("chain-hibbeler-15-58-suitcases", "u_B", "15.33", "digits"),
    ("chain-hibbeler-15-58-suitcases", "d_B", "9.127", "digits±1"),  # the source squares a rounded 15.33
    ("chain-car-rear-ends-suv-skid", "V", "6.507", "digits"),
    ("chain-car-rear-ends-suv-skid", "v_car", "21.52", "digits"),
    ("chain-ocr-m2-2011-find-e-mass-then-wall", "e", "0.2", "digits"),
    ("chain-ocr-m2-2011-find-e-mass-then-wall", "m_A", "0.88", "digits"),
    ("chain-ocr-m2-2011-find-e-mass-then-wall", "-w_B", "0.5", "digits"),
    ("chain-ocr-m2-2011-find-e-mass-then-wall", "e_wall", "0.172", "digits"),
    ("chain-edexcel-m2-three-particles", "e", "0.512", "digits"),
    ("chain-aqa-m3-2007-collide-again", "u_A", "-0.6", "digits"),
    ("chain-aqa-m3-2007-collide-again", "u_B", "3.4", "digits"),
    ("chain-aqa-m3-2007-collide-again", "-w_B", "2.38", "digits"),
    ("chain-aqa-m3-2007-collide-again", "again", "1", "digits"),  # "B collides with A again"
]


@cache
def solved(stem: str) -> ChainSolution:
    return derive.solve(derive.load(stem))


def value(sol: ChainSolution, quantity: str) -> sympy.Expr:
    ctx = {n: r.value for n, r in sol.results.items() if r.value is not None}
    return sympy.sympify(quantity, locals={n: v for n, v in ctx.items()})


@pytest.mark.parametrize(("stem", "quantity", "published", "rule"), PUBLISHED, ids=lambda v: str(v))
def test_chain_reproduces_published_answer(stem: str, quantity: str, published: str, rule: str) -> None:
    got = value(solved(stem), quantity)
    pub = Decimal(published)
    exp = pub.as_tuple().exponent
    rounded = Decimal(str(sympy.N(got, 30))).quantize(Decimal(1).scaleb(exp), rounding=ROUND_HALF_UP)
    slack = Decimal(1).scaleb(exp) if rule == "digits±1" else 0
    assert abs(rounded - pub) <= slack, (quantity, sympy.N(got, 10), published)


def test_every_bundled_chain_is_checked() -> None:
    chains = {s for s in bundled() if s.startswith("chain-")}
    assert len(chains) >= 8
    assert chains <= {row[0] for row in PUBLISHED}


@pytest.mark.parametrize("stem", sorted(s for s in bundled() if s.startswith("chain-")))
def test_chain_renders_with_stages_and_running_numbers(stem: str) -> None:
    sol = solved(stem)
    md = derive.render(sol, "md")
    assert md.count("## Stage ") == len(sol.stages)
    tags = [int(t) for t in re.findall(r"\\tag\{(\d+)\}", md)]
    # the page numbers its own equations 1, 2, ..., n in order, with no gap (issue #28 item 5)
    assert tags == list(range(1, len(tags) + 1)), tags
    # every reference is to an equation the page numbered, above it
    for m in re.finditer(r"(?:From|into|Add|from|to) \((\d+)\)", md):
        k = int(m.group(1))
        assert f"\\tag{{{k}}}" in md[: m.start()], (m.group(0), tags)
    # the notes' equations are named in words, never by a number that is also the page's
    assert not re.search(r"\(\d\)[^.$]* of the notes|equation \(\d\) does|\(\d\) says", md), md
    assert "ANSWER" in md
    assert derive.render(sol, "json").startswith("{")


def test_energy_is_used_before_and_after_never_across() -> None:
    md = derive.render(solved("chain-ocr-m2-2015-thrown-down-bounce"), "md")
    before, impact = md.index("## Stage 1"), md.index("## Stage 2")
    assert "mechanical energy is conserved" in md[before:impact]
    stage2 = md[impact : md.index("## Stage 3")]
    assert "Impact rule" in stage2 and "never used to find the velocities" in stage2


def chain(text: str) -> ChainSolution:
    return derive.solve(loads(textwrap.dedent(text), path="c.toml"))


def test_fall_rise_slide_and_spring_against_hand_formulas() -> None:
    sol = chain(
        """
        title = "hand"
        kind = "chain"
        [given]
        m = "2 kg"
        h = "5 m"
        mu = 0.25
        k = "800 N/m"
        g = "9.81 m/s^2"
        [[stage]]
        type = "fall"
        height = "h"
        result = "v"
        [[stage]]
        type = "rise"
        speed = "v/2"
        result = "h2"
        [[stage]]
        type = "slide"
        speed = "v"
        mu = "mu"
        result = "d"
        [[stage]]
        type = "spring"
        speed = "v"
        mass = "m"
        k = "k"
        result = "x"
        """
    )
    v = math.sqrt(2 * 9.81 * 5)
    r = {n: float(x.value) for n, x in sol.results.items() if x.value is not None}
    assert r["v"] == pytest.approx(v)
    assert r["h2"] == pytest.approx((v / 2) ** 2 / (2 * 9.81))  # a quarter of the height
    assert r["d"] == pytest.approx(v**2 / (2 * 0.25 * 9.81))  # = h / mu
    assert r["x"] == pytest.approx(v * math.sqrt(2 / 800))


def test_bounces_follow_the_geometric_series() -> None:
    sol = chain(
        """
        title = "bounces"
        kind = "chain"
        [given]
        h = "2 m"
        e = 0.6
        g = "9.81 m/s^2"
        [[stage]]
        type = "bounces"
        height = "h"
        e = "e"
        count = 3
        """
    )
    r = {n: float(x.value) for n, x in sol.results.items() if x.value is not None}
    v0 = math.sqrt(2 * 9.81 * 2)
    for k in (1, 2, 3):
        assert r[f"v_b{k}"] == pytest.approx(0.6**k * v0)
        assert r[f"h_b{k}"] == pytest.approx(0.6 ** (2 * k) * 2)  # each rebound: (e v)²/2g
    # total distance: h + 2 h e² + 2 h e⁴ + ... = h (1 + e²)/(1 - e²)
    assert r["s_total"] == pytest.approx(2 * (1 + 0.36) / (1 - 0.36))


def test_collide_again_and_the_range_of_e() -> None:
    md = derive.render(solved("chain-aqa-m3-2007-collide-again"), "md")
    assert "Yes: they collide again." in md
    # B returns at 3.4 e_wall; A moves back at 0.6: they meet again when 3.4 e_wall > 0.6
    m = re.search(r"\$\\frac\{(\d+)\}\{(\d+)\} < e_\{\\mathrm\{wall\}\}\$ and \$e_\{\\mathrm\{wall\}\} \\leq 1\$", md)
    assert m and int(m.group(1)) / int(m.group(2)) == pytest.approx(0.6 / 3.4, rel=1e-12)


def test_a_stage_error_names_the_stage() -> None:
    with pytest.raises(derive.InputError, match="stage 1"):
        chain(
            """
            title = "bad"
            kind = "chain"
            [given]
            h = "2 kg"
            [[stage]]
            type = "fall"
            height = "h"
            """
        )


# ---------------------------------------------------------------- stage letters (issues 16, 17)


def _stage(md: str, number: int) -> str:
    """One stage of a chain's Markdown page, heading to the next heading of its level."""
    start = md.index(f"## Stage {number}:")
    end = md.find("\n## ", start + 1)
    return md[start : end if end > 0 else len(md)]


def test_a_stage_calls_its_bodies_by_the_stage_s_letters() -> None:
    """AQA 2007 Q4, stage 2: sphere B (0.2 kg, 3.4 m/s) strikes the wall. The page, its
    figure and its answer call it B and the wall W; the numbers stay the mark scheme's
    (B rebounds at 0.7 x 3.4 = 2.38 m/s)."""
    sol = solved("chain-aqa-m3-2007-collide-again")
    stage = _stage(derive.render(sol, "md"), 2)
    words = re.sub(r"<svg.*?</svg>", "", stage, flags=re.S)
    assert not re.search(r"[vm]_\{A", stage), "no symbol of A on B's stage"
    assert r"**Given.** $m_{B} = 0.2\ \mathrm{kg}$" in stage  # m_B said once, not "m_B = m_B"
    assert r"$u_{B} = 3.4\ \mathrm{m/s}$" in stage  # B's velocity before, by the chain's name
    # the wall's own coefficient by its own name (stage 1's e is the spheres' 0.8; issue #28), and
    # B's velocities by the chain's names u_B, w_B: not v_B1, v_B2, which stage 1 uses for B
    assert r"e_{\mathrm{wall}} = \frac{v_{W2} - w_{B}}{u_{B} - v_{W1}}" in stage
    assert "v_{B1}" not in stage and "v_{B2}" not in stage
    assert "positive from B toward the wall" in words and "W is the fixed wall" in words
    assert "The velocity of B immediately after the impact" in words
    assert not re.search(r"\bA\b", words.replace("## Stage 2: B strikes the wall", "")), "the word A on B's stage"
    assert r"\boxed{w_{B} = -2.38\ \mathrm{m/s}}" in stage
    assert r"$w_{B} = -2.38\ \mathrm{m/s}$" in stage  # carried by the name the stage writes
    # the figure: the body is labelled B, its arrows u_B (before) and w_B (after)
    labels = re.findall(r'font-weight="bold">(\w+)</text>', stage)
    assert labels == ["B", "B"]
    assert re.findall(r'italic">(\w)<tspan dy="[\d.]+" font-size="[\d.]+">(\w+)</tspan>', stage) == [
        ("u", "B"),
        ("w", "B"),
    ]
    # JSON keeps the notes' names (the contract): the stage's result is still carried as w_B
    assert float(sol.results["w_B"].value) == pytest.approx(-2.38, abs=1e-12)
    tex = _stage_tex(derive.render(sol, "tex"), 2)
    assert "u_{B}" in tex and "v_{B1}" not in tex and not re.search(r"[vm]_\{A", tex)


def _stage_tex(tex: str, number: int) -> str:
    start = tex.index(rf"Stage {number}:")
    end = tex.find(r"Stage ", start + 10)
    return tex[start:end]


def test_three_particles_stage_two_is_b_strikes_c() -> None:
    """Edexcel M2: in stage 2 B (moving at u_B) strikes C at rest: B and C on the page."""
    stage = _stage(derive.render(solved("chain-edexcel-m2-three-particles"), "md"), 2)
    assert r"$m_{B} = m$, $m_{C} = m$" in stage
    assert "from the centre of B toward the centre of C" in stage
    assert "system B + C" in stage
    assert not re.search(r"[vm]_\{A", stage)


@pytest.mark.parametrize(
    ("tables", "message"),
    [
        ('A = { label = "b" }', "label.*a capital letter"),
        ('A = { label = "B" }\nB = { label = "B" }', "both called"),
    ],
)
def test_a_stage_letter_is_a_capital_and_each_body_has_its_own(tables: str, message: str) -> None:
    text = textwrap.dedent(
        """
        title = "letters"
        kind = "chain"
        [given]
        m = "1 kg"
        [[stage]]
        type = "impact"
        kind = "direct"
        given = { m_A = "m", m_B = "m", e = 0.5, v_A1 = "2 m/s", v_B1 = "0 m/s" }
        """
    ) + textwrap.dedent(tables)
    with pytest.raises(derive.InputError, match=message) as err:
        derive.solve(loads(text, path="letters.toml"))
    assert "letters.toml" in str(err.value) and "\n" not in str(err.value)


# the stage types that are physics of their own (an impact, or motion between impacts);
# define, solve and again work on results and add no physics
PHYSICS_STAGES = {"impact", "fall", "rise", "slide", "spring", "bounces"}


def test_no_single_impact_problem_in_the_library_is_a_chain() -> None:
    """Issue 14: a problem with one impact and nothing before or after it is stated as a
    problem file (letters, show-that, defined quantities); a chain only where the physics
    has more than one stage."""
    for stem in sorted(s for s in bundled() if s.startswith("chain-")):
        stages = tomllib.loads(bundled()[stem].read_text(encoding="utf-8"))["stage"]
        physics = [s["type"] for s in stages if s["type"] in PHYSICS_STAGES]
        assert len(physics) >= 2, f"{stem} has one stage of physics ({physics}): state it as a problem file"


@pytest.mark.parametrize("stem", sorted(s for s in bundled() if s.startswith("chain-")))
def test_every_chain_has_an_html_page(stem: str) -> None:
    """Issue 15: chains had no HTML. The page has each stage, each impact's own stages and
    figures, every formula typeset (KaTeX: no TeX left outside its annotations), the results
    carried on and the answers of the Markdown page."""
    sol = solved(stem)
    html = derive.render(sol, "html")
    md = derive.render(sol, "md")
    assert html.startswith("<!DOCTYPE html>") and html.rstrip().endswith("</html>")
    for n in range(1, len(sol.problem.stages) + 1):
        assert f"<h2>Stage {n}: " in html
    assert html.count('<div class="figure"><svg') == md.count('<div align="center"><svg') > 0
    shown = re.sub(r"<annotation.*?</annotation>", "", html, flags=re.S)
    shown = re.sub(r"<script>.*?</script>|<style>.*?</style>", "", shown, flags=re.S)
    assert "\\frac" not in shown and "\\mathrm" not in shown and "$" not in shown
    assert html.count("Carried to the next stages") == md.count("Carried to the next stages")
    answers = md[md.rindex("Answer") :].count(r"\boxed")
    tail = html[html.rindex("<h2>Answer</h2>") :] if answers else ""
    assert tail.count('class="eq"') == answers


def test_a_stage_title_keeps_the_body_as_typed() -> None:
    """The Hibbeler chain's stage read "Suitcase a falls through the height" (str.capitalize)."""
    md = derive.render(derive.solve(derive.load("chain-hibbeler-15-58-suitcases")), "md")
    assert "## Stage 1: Suitcase A falls through the height" in md


def test_a_single_impact_is_a_chain_of_one_untitled_stage() -> None:
    """One view and one set of templates for every solution (issue #25): a single impact's page
    is one stage whose title is empty, holding the notes' four stages; a chain's stages are its
    own, titled; no chain.* templates, and the kinds are told apart in at most three places."""
    from pathlib import Path

    from derive.resources import templates_dir
    from derive.writers.view import view

    single = view(derive.solve(derive.load("notes-4c11-two-spheres")), figures=False)
    (stage,) = single["stages"]
    assert stage["title"] == "" and [sub["number"] for sub in stage["stages"]] == [1, 2, 3, 4]
    assert single["answers"] == []  # its answers are boxed in its stage 4
    chain = view(derive.solve(derive.load("chain-aqa-m3-2007-collide-again")), figures=False)
    assert len(chain["stages"]) == 3 and all(st["title"] for st in chain["stages"])
    assert [len(st["stages"]) for st in chain["stages"]] == [4, 4, 0]  # two impacts, then the "again" test
    assert not any(p.name.startswith("chain.") for p in Path(templates_dir()).iterdir())
    package = Path(derive.__file__).parent
    uses = sum(p.read_text(encoding="utf-8").count("is_chain") for p in package.rglob("*.py"))
    assert uses <= 3
