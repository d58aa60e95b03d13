"""Issue #28, item 2: every bundled problem boxes what its question asks, in the form it asks.

The angles a question asks for in words are results: ``alpha`` (the acute angle with the
line of centres), ``gamma`` (with the plane of contact, a wall) and ``delta`` (the angle a
velocity turns through). Each value below is the published one, with its source.
"""

from __future__ import annotations

import math
import re
import tomllib

import pytest
from support.output_cases import bundled_names, solution

import derive
from derive.resources import bundled
from derive.symbols import latex_name

#: (problem, result boxed, published value, how many figures the source gives, source)
PUBLISHED = [
    (
        "ocr-fm-2023-oblique-discs-60deg",
        "alpha_A2",
        46.8,
        "OCR A Level Further Mathematics (H245) Further Mechanics, June 2023, Q3, mark scheme: "
        "'tan^-1(2 sqrt(3)/3.25) = 46.8', the angle A's velocity makes with the line of centres",
    ),
    (
        "ocr-m3-2007-oblique-sin-alpha-0p8",
        "beta_A2",
        111,
        "OCR M3 Q4 mark scheme: 'direction is 111° anticlockwise from i' (i along the line of centres)",
    ),
    (
        "ocr-mei-fmm-2024-disc-a-stops",
        "delta_B",
        44.9,
        "OCR MEI Further Mechanics Major 2024, Q12(c) mark scheme: 'Angle turned through is 44.9'",
    ),
    (
        "fisicalab-example-7-normal-at-20deg",
        "psi_A2",
        100.326,
        "GNU FisicaLab manual, Example 7 (d): 'ang_A = 100.326 degrees' from the x axis",
    ),
    (
        "fisicalab-example-7-normal-at-20deg",
        "psi_B2",
        77.172,
        "GNU FisicaLab manual, Example 7 (d): 'ang_B = 77.172 degrees' from the x axis",
    ),
]


def _boxed(md: str) -> list[str]:
    return [line for line in md.splitlines() if r"\boxed{" in line]


@pytest.mark.parametrize(("name", "result", "published", "source"), PUBLISHED, ids=lambda x: str(x)[:40])
def test_the_angle_asked_is_boxed_at_its_published_value(name: str, result: str, published: float, source: str) -> None:
    s = solution(name)
    assert result in s.problem.find, source
    value = float(s.results[result].value)
    step = 10.0 ** -_places(str(published))
    assert abs(value - published) <= step / 2, (value, source)  # the source's rounding of it
    md = derive.render(s, "md")
    lines = [ln for ln in _boxed(md) if ln.lstrip().startswith(r"\boxed{" + latex_name(result) + " ")]
    assert lines, f"{result} is not boxed"
    m = re.search(r"= (-?[\d.]+)\^\\circ\}", lines[0])
    assert m, lines[0]
    shown = float(m[1])
    half = max(step, 10.0 ** -_places(m[1])) / 2
    assert abs(shown - published) <= half + 1e-9, (shown, published, source)


def _places(text: str) -> int:
    return len(text.split(".")[1]) if "." in text else 0


def test_acute_angles_by_hand() -> None:
    """OCR 2023: after the impact A has v_t = 2√3 and v_n = −13/4 (the mark scheme's
    components): alpha = tan⁻¹(2√3 / 3.25), gamma = 90° − alpha; A's path turns from 60°
    off +n to (180° − alpha) off +n, so delta = 120° − alpha."""
    r = solution("ocr-fm-2023-oblique-discs-60deg").results
    alpha = math.degrees(math.atan(2 * math.sqrt(3) / 3.25))
    assert float(r["alpha_A2"].value) == pytest.approx(alpha)
    assert float(r["gamma_A2"].value) == pytest.approx(90 - alpha)
    assert float(r["delta_A"].value) == pytest.approx(120 - alpha)


def test_the_notes_mark_both_velocity_vectors_of_4c11() -> None:
    """The notes: V_A2 = +3.05 e_t − 1.11 e_n, V_B2 = −9.15 e_t + 8.4 e_n, '← ANSWER' beside
    the two; no speed is asked, so none is boxed as an answer."""
    md = derive.render(solution("notes-4c11-two-spheres"), "md")
    marked = [ln for ln in md.splitlines() if "ANSWER" in ln]
    assert len(marked) == 2
    assert r"\vec{v}_{A2} = \left(3.05 \hat{e}_{t} - 1.11 \hat{e}_{n}\right)" in marked[0]
    assert r"\vec{v}_{B2} = \left(-9.15 \hat{e}_{t} + 8.40 \hat{e}_{n}\right)" in marked[1]
    assert not any(ln.lstrip().startswith(r"\boxed{v_{") for ln in _boxed(md))


@pytest.mark.parametrize("name", [n for n in bundled_names() if not n.startswith("chain-")])
def test_every_result_asked_is_boxed(name: str) -> None:
    """Each name of ``find`` has a boxed line that states it (a velocity component: its
    vector's line; an unknown that a "show that" proves: that line)."""
    s = solution(name)
    md = derive.render(s, "md", figures=False)
    starts = [ln.lstrip().removeprefix(r"\boxed{") for ln in _boxed(md)]
    for asked in s.problem.find:
        heads = [latex_name(asked)]
        if re.fullmatch(r"v_[AB]2[nt]", asked):
            heads.append(r"\vec{v}_{" + asked[2:4] + "}")
        found = any(st.startswith(h) and st[len(h) : len(h) + 1] in (" ", "=", "") for st in starts for h in heads)
        shown = any(asked in str(x.relation.lhs.free_symbols | x.relation.rhs.free_symbols) for x in s.shown)
        assert found or shown, (asked, starts)


#: What each bundled chain's file asks for (its ``find``, read here from the file), in the order
#: its final "Answer" lists them. E.g. chain-aqa-m3-2007-collide-again asks (AQA MM03 June 2007
#: Q4) for A's and B's velocities after the first impact (u_A, u_B), B's after the wall (w_B)
#: and whether they collide again (again); chain-hibbeler-15-58-suitcases for A's speed at the
#: ramp's foot (v_1), both velocities after the impact (u_A, u_B) and B's slide (d_B).
CHAIN_ASKS = {
    "chain-aqa-m3-2007-collide-again": ["u_A", "u_B", "w_B", "again"],
    "chain-block-onto-spring-pan": ["x"],
    "chain-car-rear-ends-suv-skid": ["V", "v_car"],
    "chain-edexcel-m2-three-particles": ["u_B", "e"],
    "chain-hibbeler-15-58-suitcases": ["v_1", "u_A", "u_B", "d_B"],
    "chain-msu-bullet-block-swings": ["T_after", "h_2"],
    "chain-ocr-m2-2006-drop-rebound": ["v_1", "v_2", "J", "e_floor"],
    "chain-ocr-m2-2007-rebounds-to-start": ["v_1", "v_2", "e_floor", "J"],
    "chain-ocr-m2-2011-find-e-mass-then-wall": ["e", "m_A", "e_wall", "w_B"],
    "chain-ocr-m2-2015-thrown-down-bounce": ["v_1", "v_2", "h_2", "J", "E_lost"],
}


def test_every_bundled_chain_is_listed_with_what_it_asks() -> None:
    chains = [n for n in bundled_names() if n.startswith("chain-")]
    assert sorted(CHAIN_ASKS) == sorted(chains)
    for name, asks in CHAIN_ASKS.items():
        with open(bundled()[name], "rb") as f:
            assert tomllib.load(f)["find"] == asks, name


@pytest.mark.parametrize("fmt", ["md", "tex"])
@pytest.mark.parametrize("name", sorted(CHAIN_ASKS))
def test_a_chain_marks_each_result_it_asks_for(name: str, fmt: str) -> None:
    """A chain's final "Answer" boxes each result asked for and marks each ANSWER (as the notes
    mark each asked vector of 4.C.11), and nothing else on the page is marked."""
    text = derive.render(solution(name), fmt, figures=False)
    heading = "\n## Answer\n" if fmt == "md" else "\n\\subsection*{Answer}\n"
    before, answer = text.split(heading)
    assert "ANSWER" not in before
    boxed = [ln.strip() for ln in answer.splitlines() if ln.strip().startswith(r"\boxed{")]
    marked = [ln for ln in boxed if ln.endswith(r"\quad\longleftarrow\ \text{ANSWER}")]
    assert marked == boxed and len(marked) == len(CHAIN_ASKS[name])
    for line, asked in zip(marked, CHAIN_ASKS[name], strict=True):
        head = r"\boxed{\text{Do they collide again?" if asked == "again" else rf"\boxed{{{latex_name(asked)} = "
        assert line.startswith(head), (asked, line)


@pytest.mark.parametrize(
    ("name", "heads"),
    [
        # OCR H245 June 2023 Q3: "the velocities after the collision and the angle A's velocity
        # then makes with the line of centres" (find: v_A2, alpha_A2, v_B2): each marked
        ("ocr-fm-2023-oblique-discs-60deg", [r"v_{A2} = ", r"\alpha_{A2} = ", r"v_{B2} = "]),
        # AQA MM03 June 2009 Q6: the speeds of both after the collision (find: v_B2, v_A2)
        ("aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u", [r"v_{A2} = ", r"v_{B2} = "]),
        # Edexcel FM1 June 2023 Q7(a): "Show that tan(beta) = e_1 tan(alpha)": the relation
        # shown is the answer, not beta's own line beside it
        ("edexcel-fm1-2023-june-q7a-cushion-show-tan-beta", [r"\tan {\beta} = "]),
        # Pre-U specimen Q2: the component along the line of centres (v_A2n) and "show tan(theta)"
        ("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg", [r"v_{A2n} = ", r"\tan {deflection} = "]),
    ],
    ids=lambda x: x if isinstance(x, str) else "",
)
def test_a_single_impact_marks_each_result_it_asks_for(name: str, heads: list[str]) -> None:
    """Each result the question asks for carries an ANSWER mark once (was: only the last), on
    the line that states it, as a chain's answer marks each (and 4.C.11 both vectors)."""
    md = derive.render(solution(name), "md", figures=False)
    marked = [ln.removeprefix(r"\boxed{") for ln in md.splitlines() if ln.endswith(r"\longleftarrow\ \text{ANSWER}")]
    assert [next((h for h in heads if ln.startswith(h)), ln) for ln in marked] == heads
