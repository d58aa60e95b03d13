"""Checking hand answers: precision, units, formulas, equations, the mistakes, the CLI.

Every wrong answer here is computed in the test from the mistake's own formula
(momentum and restitution solved by hand with ``math``), never pasted from
derive's output; the problems' data are read from their statements.
"""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable
from pathlib import Path

import pytest

import derive
from derive.checking import mistakes
from derive.checking.answers import Item, load_answers, loads_answers

DATA = Path(__file__).parent / "data"
DOCS = Path(__file__).resolve().parent.parent / "docs" / "checking.md"
_SOLVED: dict[str, derive.Solution] = {}


def solved(name: str) -> derive.Solution:
    """A bundled problem, solved once for the whole module (mistakes are cached per solution)."""
    if name not in _SOLVED:
        _SOLVED[name] = derive.solve(derive.load(name))
    return _SOLVED[name]


def sig(x: float, n: int = 4) -> str:
    """``x`` written to ``n`` significant figures, trailing zeros kept."""
    text = f"{x:#.{n}g}"
    return text.rstrip(".") if "e" not in text else text


def one(problem: str, name: str, value: str, **kw) -> Item:
    report = derive.check(solved(problem), {name: value}, **kw)
    assert len(report.items) == 1
    return report.items[0]


def diagnosed(item) -> list[str]:
    return [d.mistake for d in item.diagnosis]


# ------------------------------------------------------------------ hand formulas


def direct(mA: float, mB: float, e: float, vA: float, vB: float) -> tuple[float, float]:
    """(3) and (4) solved by hand: m_A vA + m_B vB = m_A vA2 + m_B vB2, vB2 - vA2 = e (vA - vB)."""
    vA2 = (mA * vA + mB * vB - mB * e * (vA - vB)) / (mA + mB)
    return vA2, vA2 + e * (vA - vB)


def n_only(mA: float, mB: float, sep: float, nA: float, nB: float) -> tuple[float, float]:
    """(3) with a given separation vB2n - vA2n = sep."""
    vA2 = (mA * nA + mB * nB - mB * sep) / (mA + mB)
    return vA2, vA2 + sep


DEG = math.pi / 180
# Example 4.C.11: 20 kg at 5 m/s and 5 kg at 15 m/s, each at 37.6° to n (B toward A), e = 0.6.
C11 = dict(mA=20.0, mB=5.0, e=0.6, vA=5.0, vB=15.0, th=37.6)
# OCR FM 2023: 5 kg at 4 m/s at 60° to n; 3 kg at 6 m/s along n toward A; e = 3/4.
OCR = dict(mA=5.0, mB=3.0, e=0.75, vA=4.0, vB=6.0, th=60.0)
# Hibbeler 15-58: 15 lb at 19.657 ft/s onto 10 lb at rest, e = 0.3, g = 32.2 ft/s².
HIB = dict(WA=15.0, WB=10.0, g=32.2, e=0.3, vA=19.657)
# Casco, two cars: 4500 lb at 3 ft/s and 3000 lb at -6 ft/s, e = 0.
CARS = dict(WA=4500.0, WB=3000.0, g=32.2, e=0.0, vA=3.0, vB=-6.0)
# BYJU'S: 4 kg at 12 m/s behind 8 kg at 4 m/s, e = 0.5. AQA M3 2007: 0.3 kg at 3, 0.2 kg at -2, e = 0.8.
BYJUS = dict(mA=4.0, mB=8.0, e=0.5, vA=12.0, vB=4.0)
AQA = dict(mA=0.3, mB=0.2, e=0.8, vA=3.0, vB=-2.0)


def c11_components(th: float = C11["th"] * DEG, swap: bool = False) -> tuple[float, float, float, float]:
    s, c = math.sin(th), math.cos(th)
    if swap:
        s, c = c, s
    return C11["vA"] * c, C11["vA"] * s, -C11["vB"] * c, -C11["vB"] * s  # A1n, A1t, B1n, B1t


def c11_post(e: float = C11["e"], **kw) -> tuple[float, float, float, float]:
    """A2n, A2t, B2n, B2t of Example 4.C.11 (t unchanged; n from (3), (4))."""
    a1n, a1t, b1n, b1t = c11_components(**kw)
    a2n, b2n = direct(C11["mA"], C11["mB"], e, a1n, b1n)
    return a2n, a1t, b2n, b1t


def ocr_components(th: float = OCR["th"] * DEG, swap: bool = False) -> tuple[float, float, float, float]:
    s, c = math.sin(th), math.cos(th)
    if swap:
        s, c = c, s
    return OCR["vA"] * c, OCR["vA"] * s, -OCR["vB"], 0.0


def ocr_post(e: float = OCR["e"], **kw) -> tuple[float, float, float, float]:
    a1n, a1t, b1n, b1t = ocr_components(**kw)
    a2n, b2n = direct(OCR["mA"], OCR["mB"], e, a1n, b1n)
    return a2n, a1t, b2n, b1t


def hib(e: float = HIB["e"]) -> tuple[float, float]:
    mA, mB = HIB["WA"] / HIB["g"], HIB["WB"] / HIB["g"]
    return direct(mA, mB, e, HIB["vA"], 0.0)


def cars() -> tuple[float, float]:
    return direct(CARS["WA"] / CARS["g"], CARS["WB"] / CARS["g"], 0.0, CARS["vA"], CARS["vB"])


def byjus(**kw) -> tuple[float, float]:
    d = {**BYJUS, **kw}
    return direct(d["mA"], d["mB"], d["e"], d["vA"], d["vB"])


def aqa(**kw) -> tuple[float, float]:
    d = {**AQA, **kw}
    return direct(d["mA"], d["mB"], d["e"], d["vA"], d["vB"])


def atan_deg(y: float, x: float) -> float:
    return math.degrees(math.atan(y / x))


# One entry per (mistake, problem): the answer a student who makes that mistake writes.
MISTAKEN: list[tuple[str, str, str, Callable[[], float]]] = [
    # B's velocity with the wrong sign: -v_B1 in (3) and (4)
    ("b_sign", "aqa-m3-2007-spheres-approach-head-on", "v_A2", lambda: aqa(vB=-AQA["vB"])[0]),
    ("b_sign", "byjus-4kg-ball-catches-8kg-ball", "v_B2", lambda: byjus(vB=-BYJUS["vB"])[1]),
    (
        "b_sign",
        "notes-4c11-two-spheres",
        "v_B2n",
        lambda: direct(C11["mA"], C11["mB"], C11["e"], c11_components()[0], -c11_components()[2])[1],
    ),
    # restitution reversed: e (vA1 - vB1) = vA2 - vB2, i.e. (4) with -e
    ("restitution_reversed", "byjus-4kg-ball-catches-8kg-ball", "v_A2", lambda: byjus(e=-BYJUS["e"])[0]),
    ("restitution_reversed", "hibbeler-15-58-suitcases", "v_B2", lambda: hib(e=-HIB["e"])[1]),
    ("restitution_reversed", "notes-4c11-two-spheres", "v_B2n", lambda: c11_post(e=-C11["e"])[2]),
    ("restitution_reversed", "edexcel-m2-ball-rebounds-from-wall", "v_A2", lambda: +0.4 * 4.0),
    # e applied to the speeds: e (v_A1 - v_B1) with the signed speeds, not n components
    (
        "e_speeds",
        "notes-4c11-two-spheres",
        "v_A2n",
        lambda: n_only(C11["mA"], C11["mB"], C11["e"] * (5 + 15), c11_components()[0], c11_components()[2])[0],
    ),
    (
        "e_speeds",
        "ocr-fm-2023-oblique-discs-60deg",
        "v_B2n",
        lambda: n_only(OCR["mA"], OCR["mB"], OCR["e"] * (4 + 6), ocr_components()[0], -6.0)[1],
    ),
    # e applied to the t components: v_A2t = e v_A1t
    ("e_on_t", "notes-4c11-two-spheres", "v_A2t", lambda: C11["e"] * c11_components()[1]),
    ("e_on_t", "ocr-fm-2023-oblique-discs-60deg", "v_A2t", lambda: OCR["e"] * ocr_components()[1]),
    # kinetic energy conserved: the energy equation with (3) gives the e = 1 velocities
    ("energy_conserved", "byjus-4kg-ball-catches-8kg-ball", "v_B2", lambda: byjus(e=1.0)[1]),
    ("energy_conserved", "hibbeler-15-58-suitcases", "v_A2", lambda: hib(e=1.0)[0]),
    ("energy_conserved", "edexcel-m2-ball-rebounds-from-wall", "v_A2", lambda: -4.0),
    # the system's t momentum: one t velocity (m_A v_A1t + m_B v_B1t)/(m_A + m_B) for both
    (
        "system_t",
        "notes-4c11-two-spheres",
        "v_B2t",
        lambda: (C11["mA"] * c11_components()[1] + C11["mB"] * c11_components()[3]) / (C11["mA"] + C11["mB"]),
    ),
    (
        "system_t",
        "ocr-fm-2023-oblique-discs-60deg",
        "v_A2t",
        lambda: OCR["mA"] * ocr_components()[1] / (OCR["mA"] + OCR["mB"]),
    ),
    # sin and cos swapped in resolving the velocities before the impact
    ("sin_cos_swapped", "notes-4c11-two-spheres", "v_A2n", lambda: c11_post(swap=True)[0]),
    ("sin_cos_swapped", "ocr-fm-2023-oblique-discs-60deg", "v_B2n", lambda: ocr_post(swap=True)[2]),
    # the direction after the impact from the other axis: atan(v_t / v_n)
    ("angle_other_axis", "notes-4c11-two-spheres", "theta_A2", lambda: atan_deg(c11_post()[1], c11_post()[0])),
    ("angle_other_axis", "ocr-fm-2023-oblique-discs-60deg", "theta_A2", lambda: atan_deg(ocr_post()[1], ocr_post()[0])),
    # the direction without its quadrant: atan(v_n / v_t) with v_t < 0 (theta), atan(v_t / v_n) with v_n < 0 (beta)
    ("angle_quadrant", "notes-4c11-two-spheres", "theta_B2", lambda: atan_deg(c11_post()[2], c11_post()[3])),
    ("angle_quadrant", "ocr-fm-2023-oblique-discs-60deg", "beta_A2", lambda: atan_deg(ocr_post()[1], ocr_post()[0])),
    # degrees read as radians
    ("degrees_as_radians", "notes-4c11-two-spheres", "v_A2n", lambda: c11_post(th=C11["th"])[0]),
    ("degrees_as_radians", "ocr-fm-2023-oblique-discs-60deg", "v_A2t", lambda: OCR["vA"] * math.sin(OCR["th"])),
    ("degrees_as_radians", "giancoli-7-18-tennis-ball-wall-45deg", "v_A2t", lambda: 28 * math.sin(45)),
    # masses swapped
    ("masses_swapped", "byjus-4kg-ball-catches-8kg-ball", "v_A2", lambda: byjus(mA=8.0, mB=4.0)[0]),
    ("masses_swapped", "hibbeler-15-58-suitcases", "v_B2", lambda: direct(10 / 32.2, 15 / 32.2, 0.3, 19.657, 0)[1]),
    (
        "masses_swapped",
        "notes-4c11-two-spheres",
        "v_A2n",
        lambda: direct(C11["mB"], C11["mA"], C11["e"], c11_components()[0], c11_components()[2])[0],
    ),
    # weight used as mass: the velocities survive, the energy lost and the impulse do not
    (
        "weight_as_mass",
        "hibbeler-15-58-suitcases",
        "T_lost",
        lambda: 0.5 * 15 * 19.657**2 - (0.5 * 15 * hib()[0] ** 2 + 0.5 * 10 * hib()[1] ** 2),
    ),
    (
        "weight_as_mass",
        "mcasco-two-cars-no-bounce",
        "T_lost",
        lambda: 0.5 * 4500 * 3**2 + 0.5 * 3000 * 6**2 - 0.5 * 7500 * cars()[0] ** 2,
    ),
    ("weight_as_mass", "mcasco-two-cars-no-bounce", "J_n", lambda: 4500 * (3 - cars()[0])),
]


@pytest.mark.parametrize(
    ("mistake", "problem", "name", "value"),
    MISTAKEN,
    ids=[f"{m}-{p.split('-')[0]}-{p.split('-')[1]}-{n}" for m, p, n, _ in MISTAKEN],
)
def test_a_mistaken_answer_is_diagnosed(mistake: str, problem: str, name: str, value: Callable[[], float]) -> None:
    written = sig(value(), 4)
    item = one(problem, name, written)
    assert item.status == "wrong", (written, item.message)
    assert mistake in diagnosed(item), (written, item.expected, diagnosed(item))
    d = next(d for d in item.diagnosis if d.mistake == mistake)
    assert d.title == mistakes.REGISTRY[mistake].title and d.where


def test_every_mistake_is_tested_on_two_bundled_problems() -> None:
    from derive import resources

    bundled = set(resources.bundled())
    for name in mistakes.REGISTRY:
        problems = {p for m, p, _, _ in MISTAKEN if m == name}
        assert len(problems & bundled) >= 2, name
    required = {
        "b_sign",
        "restitution_reversed",
        "e_speeds",
        "e_on_t",
        "energy_conserved",
        "system_t",
        "sin_cos_swapped",
        "degrees_as_radians",
        "masses_swapped",
        "weight_as_mass",
    }
    assert required <= set(mistakes.REGISTRY)
    for m in mistakes.REGISTRY.values():
        assert m.title and m.description.endswith(".") and m.where and m.phrase


def test_no_mistake_matches_says_so() -> None:
    item = one("notes-4c11-two-spheres", "v_A2t", "-3.05")
    assert item.status == "wrong" and item.diagnosis == ()
    assert "No common mistake reproduces -3.05" in item.message
    assert "wrong sign" in item.message
    item = one("byjus-4kg-ball-catches-8kg-ball", "v_B2", "7.123")
    assert item.diagnosis == () and "No common mistake" in item.message


def test_mistakes_that_cannot_happen_are_skipped() -> None:
    def applied(problem: str) -> set[str]:
        return {o.mistake.name for o in mistakes.outcomes(solved(problem))}

    direct_names = applied("byjus-4kg-ball-catches-8kg-ball")
    assert not direct_names & {"e_speeds", "e_on_t", "system_t", "sin_cos_swapped", "degrees_as_radians"}
    assert "weight_as_mass" not in direct_names
    wall = applied("edexcel-m2-ball-rebounds-from-wall")
    assert not wall & {"b_sign", "masses_swapped", "system_t"}
    # equal masses: swapping them changes nothing
    assert "masses_swapped" not in applied("mcasco-glancing-disks-us")
    assert "weight_as_mass" in applied("mcasco-glancing-disks-us")


@pytest.mark.parametrize(
    "problem",
    [
        "notes-4c11-two-spheres",
        "notes-4c12-cue-ball",
        "hibbeler-15-58-suitcases",
        "ocr-fm-2023-oblique-discs-60deg",
        "edexcel-m2-ball-rebounds-from-wall",
        "aqa-fm-specimen-discs-show-e-0p8",
        "giancoli-7-18-tennis-ball-wall-45deg",
    ],
)
def test_the_unmistaken_equations_give_the_solution(problem: str) -> None:
    base = mistakes.correct(solved(problem))
    assert base is not None
    for name, r in solved(problem).results.items():
        if r.value is not None:
            assert base.results[name].value is not None, name
            assert float(base.results[name].value) == pytest.approx(float(r.value), rel=1e-12, abs=1e-12), name


# ------------------------------------------------------------------ numbers


V_B2N = 53 / 5 * math.cos(37.6 * DEG)  # 4.C.11 by hand: 8.3983... m/s
V_A2N = -7 / 5 * math.cos(37.6 * DEG)  # -1.1092... m/s


@pytest.mark.parametrize(
    ("name", "written"),
    [
        ("v_B2n", "8.4"),  # 2 figures
        ("v_B2n", "8.40"),  # 3
        ("v_B2n", "8.398"),  # 4
        ("v_B2n", "8.41"),  # ±1 in the last digit
        ("v_B2n", "8.39"),
        ("v_B2n", "8.397 m/s"),
        ("v_A2n", "-1.1"),
        ("v_A2n", "-1.11"),
        ("v_A2n", "-1.109"),
        ("v_A2n", "-1.12"),
        ("v_A2n", "-1.109e0 m/s"),
    ],
)
def test_correct_at_the_figures_written(name: str, written: str) -> None:
    item = one("notes-4c11-two-spheres", name, written)
    assert item.status == "correct", item.message
    x = V_B2N if name == "v_B2n" else V_A2N
    assert item.relative_error == pytest.approx((float(written.split()[0]) - x) / abs(x), rel=1e-6)


@pytest.mark.parametrize(
    ("name", "written"),
    [
        ("v_B2n", "8.42"),
        ("v_B2n", "8.38"),
        ("v_B2n", "8.396"),
        ("v_B2n", "8.2"),
        ("v_A2n", "-1.13"),
        ("v_A2n", "-1.107"),
    ],
)
def test_wrong_at_the_figures_written(name: str, written: str) -> None:
    assert one("notes-4c11-two-spheres", name, written).status == "wrong"


def test_sig_figs_are_judged_on_other_problems() -> None:
    # Hibbeler 15-58 by hand, in ft/s: m = W/g cancels in the velocities.
    vA2, vB2 = hib()
    for n in (2, 3, 4):
        assert one("hibbeler-15-58-suitcases", "v_A2", f"{sig(vA2, n)} ft/s").status == "correct"
        assert one("hibbeler-15-58-suitcases", "v_B2", f"{sig(vB2, n)} ft/s").status == "correct"
    # OCR FM 2023: v_A2n = -13/4 exactly
    assert one("ocr-fm-2023-oblique-discs-60deg", "v_A2n", "-3.250").status == "correct"
    assert one("ocr-fm-2023-oblique-discs-60deg", "v_A2n", "-13/4").status == "correct"
    assert one("ocr-fm-2023-oblique-discs-60deg", "v_A2n", "-3.27").status == "wrong"


def test_units_are_converted_and_checked() -> None:
    ft = V_B2N / 0.3048
    item = one("notes-4c11-two-spheres", "v_B2n", f"{sig(ft, 4)} ft/s")
    assert item.status == "correct" and item.unit == "ft/s"
    assert one("notes-4c11-two-spheres", "v_B2n", f"{sig(V_B2N * 3.6, 3)} km/h").status == "correct"
    item = one("notes-4c11-two-spheres", "v_B2n", "8.40 kg")
    assert item.status == "unit mismatch" and "mass" in item.message
    item = one("notes-4c11-two-spheres", "v_B2n", "8.40")
    assert item.status == "correct" and item.unit_missing and "No unit given: read as m/s" in " ".join(item.notes)
    # a number that is right in another unit
    item = one("notes-4c11-two-spheres", "v_B2n", f"{sig(ft, 4)} m/s")
    assert item.status == "wrong" and "right value in ft/s" in item.message
    # angles: degrees by default, radians when written
    theta = math.degrees(math.atan2(V_A2N, 5 * math.sin(37.6 * DEG)))
    assert one("notes-4c11-two-spheres", "theta_A2", sig(theta, 3)).status == "correct"
    assert one("notes-4c11-two-spheres", "theta_A2", f"{sig(math.radians(theta), 3)} rad").status == "correct"
    assert one("notes-4c11-two-spheres", "theta_A2", f"{sig(theta, 3)}°").status == "correct"
    # energy in US units; e is a pure number
    assert one("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", "e", "0.8").status == "correct"
    assert one("ocr-m2-2006-sphere-hits-sphere-at-rest-find-e", "e", "0.8 m/s").status == "unit mismatch"


def test_tolerance() -> None:
    assert one("notes-4c11-two-spheres", "v_B2n", "8.3", tolerance="2%").status == "correct"
    assert one("notes-4c11-two-spheres", "v_B2n", "8.3", tolerance=0.01).status == "wrong"
    item = one("notes-4c11-two-spheres", "v_B2n", "8.41", tolerance="0.1%")
    assert item.status == "wrong" and "tolerance" in item.method


# ------------------------------------------------------------------ formulas


@pytest.mark.parametrize(
    ("problem", "name", "written"),
    [
        ("notes-4c12-cue-ball", "v_B2", "sqrt(2)/4*(1+e)*v_A1"),  # the notes' (4), with theta_1 = 45°
        ("notes-4c12-cue-ball", "v_B2n", "(1+e)*v_A1*sin(theta_1)/2"),  # a formula in every given
        ("notes-4c12-cue-ball", "v_A2n", "sqrt(2)/4*(1-e)*v_A1"),  # the notes' (5)
        ("notes-4c12-cue-ball", "v_A2n", "v_A1*(1 - 0.9)*sqrt(2)/4"),
        ("notes-4c12-cue-ball", "v_A2t", "v_A1*cos(45*deg)"),
        ("notes-4c12-cue-ball", "theta_A2", "atan(0.05)"),  # the notes' tan^-1(0.05)
        ("notes-4c12-cue-ball", "T_lost", "m*v_A1^2*(1 - e^2)/4*sin(theta_1)^2"),
        ("aqa-m3-2014-symbolic-2m-hits-m", "v_A2", "8*u/9"),
        ("aqa-m3-2014-symbolic-2m-hits-m", "v_B2", "8*u/9 + 2/3*(2*u)"),
        (
            "notes-4c11-two-spheres",
            "v_A2n",
            "(m_A - e*m_B)*v_A1*cos(theta)/(m_A + m_B) - (1 + e)*m_B*v_B1*cos(theta)/(m_A + m_B)",
        ),
        ("notes-4c11-two-spheres", "v_A2t", "5*sin(37.6*deg)"),
    ],
)
def test_equivalent_formulas_pass(problem: str, name: str, written: str) -> None:
    item = one(problem, name, written)
    assert item.status == "correct", item.message
    assert "simplification" in item.method or "evaluation" in item.method


@pytest.mark.parametrize(
    ("problem", "name", "written"),
    [
        ("notes-4c12-cue-ball", "v_B2", "sqrt(2)/4*(1-e)*v_A1"),
        ("notes-4c12-cue-ball", "v_B2n", "(1+e)*v_A1/2"),  # sin(theta_1) forgotten
        ("notes-4c12-cue-ball", "theta_A2", "atan(0.5)"),
        ("aqa-m3-2014-symbolic-2m-hits-m", "v_B2", "8*u/3"),  # the mark scheme's slip
        ("aqa-m3-2014-symbolic-2m-hits-m", "v_A2", "2*u/3"),
        ("notes-4c11-two-spheres", "v_A2n", "(m_A - e*m_B)*v_A1*cos(theta)/(m_A + m_B)"),
    ],
)
def test_non_equivalent_formulas_fail(problem: str, name: str, written: str) -> None:
    assert one(problem, name, written).status == "wrong"


def test_the_report_says_which_method_decided() -> None:
    item = one("notes-4c12-cue-ball", "v_B2n", "(1+e)*v_A1*sin(theta_1)/2")
    assert item.method == "simplification" and "as a formula in the givens" in item.message
    # |sin(theta_1)| in the closed form: simplification cannot tell, random points can
    item = one("notes-4c12-cue-ball", "v_B2", "(1+e)*v_A1*sin(theta_1)/2")
    assert item.status == "correct" and item.method.startswith("evaluation at 8 random admissible points")
    item = one("notes-4c12-cue-ball", "v_B2", "sqrt(2)/4*(1+e)*v_A1")
    assert "with this problem's numbers" in item.message


def test_formula_mistakes_are_diagnosed() -> None:
    # the energy-conserving answer for AQA M3 2014 (v_B2 = 8u/3 in the mark scheme): e = 1 by hand
    _, vB2 = direct(2.0, 1.0, 1.0, 2.0, 0.0)
    assert vB2 == pytest.approx(8 / 3)
    item = one("aqa-m3-2014-symbolic-2m-hits-m", "v_B2", "8*u/3")
    assert "energy_conserved" in diagnosed(item)
    # 4.C.12 with the restitution differences reversed: v_A2n = (1+e) v_A1 sin(theta_1)/2
    item = one("notes-4c12-cue-ball", "v_A2n", "(1+e)*v_A1*sin(theta_1)/2")
    assert item.status == "wrong" and "restitution_reversed" in diagnosed(item)


def test_formula_units() -> None:
    assert one("notes-4c12-cue-ball", "v_B2", "e*m").status == "unit mismatch"
    assert one("notes-4c12-cue-ball", "v_B2", "v_A1 + m").status == "unit mismatch"
    item = one("ocr-fm-2023-oblique-discs-60deg", "v_B2n", "11/4 m/s")
    assert item.status == "correct" and not item.unit_missing


# ------------------------------------------------------------------ equations


@pytest.mark.parametrize(
    ("label", "equation", "status", "needle"),
    [
        ("3", "20*v_A2n + 5*v_B2n = 19.8", "correct", "is the n-momentum of the system A + B: correct"),
        ("3", "m_A*v_A1n + m_B*v_B1n = m_A*v_A2n + m_B*v_B2n", "correct", "n-momentum"),
        ("3", "20*5*cos(37.6*deg) - 5*15*cos(37.6*deg) = 20*v_A2n + 5*v_B2n", "correct", "n-momentum"),
        ("4", "v_B2n - v_A2n = 9.5", "correct", "is the impact rule"),
        ("4", "e = (v_B2n - v_A2n)/(v_A1n - v_B1n)", "correct", "impact rule"),
        ("1", "v_A2t = 3.05", "correct", "t-momentum of A"),
        ("4", "v_A2n - v_B2n = 9.5", "wrong", "has the impact rule the wrong way round"),
        (
            "3",
            "20*v_A2n + 5*v_B2n = 20*5*cos(37.6*deg) + 5*15*cos(37.6*deg)",
            "wrong",
            "B's velocity with the wrong sign",
        ),
        ("3", "20*v_A2n + 5*v_B2n = 20*5*cos(37.6) - 5*15*cos(37.6)", "wrong", "degrees as radians"),
        ("4", "T_1 = T_2", "wrong", "conserves kinetic energy"),
        ("4", "v_B2n - v_A2n = 0.6*(5 + 15)", "wrong", "applies e to the speeds"),
        # the masses swapped after the impact only (19.8 is the momentum before, right)
        ("3", "5*v_A2n + 20*v_B2n = 19.8", "wrong", "has the masses swapped"),
        ("3", "20*v_A2n + 7*v_B2n = 19.8", "wrong", "does not agree with (3)"),
        # 23.7 for 19.81 moves v_A2n from -1.109 to -0.953: not hidden by v_B2t = -9.15
        ("3", "20*v_A2n + 5*v_B2n = 23.7", "wrong", "does not agree with (3)"),
        ("4", "20*v_A2n + 5*v_B2n = 19.81", "correct", "it is (3)"),
        ("5", "25*v_A2n = 19.8 - 5*9.5", "correct", "correct"),
    ],
)
def test_equations(label: str, equation: str, status: str, needle: str) -> None:
    report = derive.check(solved("notes-4c11-two-spheres"), None, equations={label: equation})
    item = report.items[0]
    text = " ".join([item.message, *item.notes, *(d.title for d in item.diagnosis)])
    assert item.status == status, text
    assert needle.lower() in text.lower(), text


def test_equations_in_a_symbolic_problem() -> None:
    eqs = {
        "3": "m*v_A1*sin(theta_1) = m*v_A2n + m*v_B2n",
        "4": "sqrt(2)/2*e*v_A1 = v_B2n - v_A2n",
        "1": "v_A2t = v_A1*cos(theta_1)",
        "x": "v_A2n + v_B2n = e*v_A1*sqrt(2)/2",
    }
    report = derive.check(solved("notes-4c12-cue-ball"), None, equations=eqs)
    assert [i.status for i in report.items] == ["correct", "correct", "correct", "wrong"]


# ------------------------------------------------------------------ reports, files, API


def test_report_formats() -> None:
    report = derive.check(
        solved("notes-4c11-two-spheres"),
        ["v_A2n=-1.11", "v_B2n=8.4 m/s", "v_A2t=-3.05"],
        equations=["3: 20*v_A2n + 5*v_B2n = 19.8"],
    )
    assert [i.status for i in report.items] == ["correct", "correct", "wrong", "correct"]
    assert not report.all_correct and report.exit_code == 1
    text = report.render("text")
    assert "✓" in text and "✗" in text and "3 of 4 correct" in text
    rows = [ln for ln in text.splitlines() if ln.startswith("  ✓") or ln.startswith("  ✗")]
    cols = {ln.index("expected") for ln in rows if "expected" in ln}
    assert len(cols) == 1  # aligned
    md = report.render("md")
    assert md.startswith("## Check:") and "| ✗ |" in md
    data = json.loads(report.render("json"))
    assert data["all_correct"] is False and data["counts"]["wrong"] == 1
    assert data["items"][0]["unit_missing"] is True and data["items"][0]["status"] == "correct"
    assert data["items"][2]["expected_value"] == pytest.approx(5 * math.sin(37.6 * DEG))


def test_check_accepts_a_problem_and_mappings() -> None:
    report = derive.check(derive.load("byjus-4kg-ball-catches-8kg-ball"), {"v_A2": 4, "v_B2": 8.0})
    assert report.all_correct and report.exit_code == 0
    assert "check" in derive.__all__


def test_answers_file(tmp_path: Path) -> None:
    given = load_answers(DATA / "answers-4c11.toml")
    report = derive.check(solved("notes-4c11-two-spheres"), given)
    by_name = {i.name: i for i in report.items}
    assert by_name["v_A2n"].status == "correct"
    assert by_name["v_B2n"].status == "correct"
    assert by_name["v_B2t"].unit_missing
    assert by_name["v_A2t"].status == "wrong" and "sin_cos_swapped" in diagnosed(by_name["v_A2t"])
    assert by_name["3"].status == "correct" and by_name["4"].status == "wrong"


@pytest.mark.parametrize(
    ("body", "needle"),
    [
        ("[answers]\nv_X2 = 1\n", "answers.toml:2: [answers] v_X2: unknown result"),
        ("[answers]\nv_A2n = true\n", "[answers] v_A2n = true: expected a number or text"),
        ('[answers]\nv_A2n = "1.2 parsecs"\n', "unknown unit 'parsecs'"),
        ('[answers]\nv_A2n = "1.2 +* 3"\n', "[answers] v_A2n"),
        ('[answers]\nv_A2n = "import os"\n', "[answers] v_A2n"),
        ("[answers]\nv_A2n = \"__import__('os')\"\n", "[answers] v_A2n"),
        ("[answer]\nv_A2n = 1\n", "unknown field"),
        ("[answers\n", "not valid TOML"),
        ('tolerance = "lots"\n[answers]\nv_A2n = 1\n', "relative tolerance"),
        ('[equations]\n"3" = "20*v_A2n + 5*v_B2n"\n', "exactly one '='"),
        ("", "nothing to check"),
    ],
)
def test_answers_file_errors(tmp_path: Path, body: str, needle: str) -> None:
    path = tmp_path / "answers.toml"
    path.write_text(body)
    with pytest.raises(derive.InputError) as info:
        derive.check(solved("notes-4c11-two-spheres"), load_answers(path))
    assert needle in str(info.value)
    assert "\n" not in str(info.value)


def test_a_symbolic_result_needs_a_formula() -> None:
    with pytest.raises(derive.InputError, match="depends on the symbolic given"):
        one("notes-4c12-cue-ball", "v_B2", "0.95")


def test_documented_answer_files_check() -> None:
    blocks = re.findall(r"```toml\n(.*?)```", DOCS.read_text(encoding="utf-8"), flags=re.S)
    assert len(blocks) == 2
    r11 = derive.check(solved("notes-4c11-two-spheres"), loads_answers(blocks[0]))
    assert [i.status for i in r11.items] == ["correct"] * 7
    r12 = derive.check(solved("notes-4c12-cue-ball"), loads_answers(blocks[1]))
    assert r12.all_correct, r12.text()


# ------------------------------------------------------------------ CLI


def test_cli_all_correct_exit_0(cli) -> None:
    r = cli("check", "notes-4c11-two-spheres", "--answer", "v_A2n=-1.11 m/s", "--answer", "v_B2n=8.40 m/s")
    assert r.code == 0, r.err
    assert "2 of 2 correct" in r.out and "✓" in r.out and r.err == ""


def test_cli_wrong_exit_1(cli) -> None:
    r = cli(
        "check",
        "notes-4c11-two-spheres",
        "--answer",
        "v_A2n=-1.11",
        "--answer",
        "v_B2n=8.4 m/s",
        "--answer",
        "v_A2t=-3.05",
    )
    assert r.code == 1
    assert "✗" in r.out and "No common mistake" in r.out
    r = cli("check", "notes-4c11-two-spheres", "--answer", "v_B2n=8.4 kg", "--format", "json")
    assert r.code == 1 and json.loads(r.out)["items"][0]["status"] == "unit mismatch"


def test_cli_files_equations_tolerance_formats(cli) -> None:
    r = cli("check", "notes-4c11-two-spheres", "--answers", str(DATA / "answers-4c11.toml"), "--format", "md")
    assert r.code == 1 and r.out.startswith("## Check:")
    r = cli(
        "check",
        "notes-4c11-two-spheres",
        "--equation",
        "(4) v_B2n - v_A2n = 9.5",
        "--answer",
        "v_B2n=8.3",
        "--tolerance",
        "2%",
    )
    assert r.code == 0, r.out


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (["--answer", "v_X2=1"], "--answer v_X2: unknown result"),
        (["--answer", "v_A2n"], "expected NAME=VALUE"),
        (["--answer", "v_A2n=1.2 parsecs"], "unknown unit"),
        (["--answer", "v_A2n=1", "--tolerance", "lots"], "--tolerance"),
        (["--answer", "v_A2n=1", "--tolerance", "150%"], "between 0 and 1"),
        (["--answers", "no-such-file.toml"], "no such file"),
        ([], "nothing to check"),
        (["--equation", "3: v_A2n + v_B2n"], "exactly one '='"),
        (["--answer", "v_A2n=1", "--format", "pdf"], "invalid choice"),
    ],
)
def test_cli_bad_input_exit_2(cli, args: list[str], needle: str) -> None:
    r = cli("check", "notes-4c11-two-spheres", *args)
    assert r.code == 2, r.out
    assert r.err.startswith("Error: ") and needle in r.err, r.err
    assert r.err.count("\n") == 1


def test_cli_bad_problem_exit_2(cli) -> None:
    r = cli("check", "no-such-problem", "--answer", "v_A2=1")
    assert r.code == 2 and r.err.startswith("Error: ")


def test_a_chains_answers_are_checked_as_numbers() -> None:
    """Once an internal error ('ChainProblem' object has no attribute 'numeric'). The AQA
    mark scheme's answers (M3 June 2007 Q4: v_A = -0.6, v_B = 3.4, then 2.38 m/s off the
    wall; momentum 0.3*3 - 0.2*2 = 0.3*(-0.6) + 0.2*3.4) are right; a sign slip is wrong."""
    sol = derive.solve(derive.load("chain-aqa-m3-2007-collide-again"))
    report = derive.check(sol, {"u_A": "-0.6 m/s", "u_B": "3.4 m/s", "w_B": "-2.38 m/s"})
    assert report.all_correct and report.exit_code == 0
    wrong = derive.check(sol, {"w_B": "2.38 m/s"})
    assert not wrong.all_correct and wrong.exit_code == 1
    with pytest.raises(derive.InputError, match="checked for a single impact"):
        derive.check(sol, {"u_A": "-0.6 m/s"}, equations={"3": "0.3*v_A2 + 0.2*v_B2 = 0.5"})
    formula = derive.check(sol, {"u_A": "-0.6 m/s", "w_B": "-2.38*u"})
    assert [i.status for i in formula.items] == ["correct", "error"]


def test_a_whole_number_ending_in_zeros_is_judged_at_the_figures_it_may_stand_for() -> None:
    # OpenStax 8 (train cars couple, e = 0) by hand: v = (150000(0.300) + 110000(-0.120))/260000
    # = 0.12231 m/s; T_1 = ½(150000)(0.3²) + ½(110000)(0.12²) = 7542 J, T_2 = ½(260000)v² = 1944.7 J,
    # so T_lost = 5597.3 J and J_n = 110000(v + 0.120) = 26654 N·s.
    v = (150000 * 0.300 - 110000 * 0.120) / 260000
    lost = 7542 - 0.5 * 260000 * v**2
    assert lost == pytest.approx(5597.3, abs=0.1)
    problem = "openstax-cp-8-train-cars-couple"
    for written in ("5600 J", "5600", "5.60e3 J", "5597 J", "5597.3 J"):  # 3 (or 2) figures, 4, 5
        assert one(problem, "T_lost", written).status == "correct", written
    for written in ("6000 J", "5700 J", "5580 J", "56000 J"):  # 1 figure; not 5597 rounded; a power out
        assert one(problem, "T_lost", written).status == "wrong", written
    assert one(problem, "J_n", "26700 N*s").status == "correct"  # 3 figures
    assert one(problem, "J_n", "27000 N*s").status == "correct"  # 2 figures
    assert one(problem, "J_n", "30000 N*s").status == "wrong"  # 1 figure is not read as rounded
    # a single figure before the zeros stays exact: 20 for 24 is wrong (4.C.11's v_B2n is 8.398)
    assert one("notes-4c11-two-spheres", "v_B2n", "10").status == "wrong"
