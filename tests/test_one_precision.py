"""Issue #28, item 3: one precision per line, and closed forms in the notes' style.

Was: √(3.051² + (−1.109)²) under boxed components 3.05 and −1.11; (√2/2) v_A1 + 0.6364 v_A1
in one sum (4.C.12); −v_A1 sin θ₁ (e − 1)/2 where the notes write (1 − e); |sin θ₁| with
θ₁ = 45°; T_2 of 4.C.12 with a fraction inside a fraction.
"""

from __future__ import annotations

import re

import sympy
from support.output_cases import solution

import derive
from derive.steps.notation import notes_form


def _lines(name: str) -> list[str]:
    return derive.render(solution(name), "md", figures=False).splitlines()


def test_a_speed_is_worked_from_the_components_as_boxed() -> None:
    """OCR 2023: v_A2t = 2√3 = 3.46, v_A2n = −13/4 = −3.25 (mark scheme); the speed line
    squares the numbers the boxed vector shows."""
    lines = _lines("ocr-fm-2023-oblique-discs-60deg")
    vector = next(ln for ln in lines if ln.startswith(r"\boxed{\vec{v}_{A2}"))
    speed = next(ln for ln in lines if ln.startswith(r"\boxed{v_{A2} ="))
    assert r"3.46 \hat{e}_{t} - 3.25 \hat{e}_{n}" in vector
    assert r"\sqrt{3.46^{2} + \left(-3.25\right)^{2}}" in speed
    angle = next(ln for ln in lines if ln.startswith(r"\boxed{\alpha_{A2}"))
    assert r"\frac{3.46}{3.25}" in angle


def test_a_sum_has_one_kind_of_number() -> None:
    """4.C.12: 2 v_B2n = (√2/2) v_A1 + 0.9 (√2/2) v_A1 = 0.7071 v_A1 + 0.6364 v_A1."""
    lines = _lines("notes-4c12-cue-ball")
    assert r"2 v_{B2n} = 0.7071 v_{A1} + 0.6364 v_{A1}" in lines
    assert r"2 v_{A2n} = 0.7071 v_{A1} - 0.6364 v_{A1}" in lines
    assert not any(r"\frac{\sqrt{2}}{2} v_{A1} + 0.6364" in ln for ln in lines)


def _nested_fraction(tex: str) -> bool:
    """True when a \\frac's numerator or denominator holds another \\frac."""
    for m in re.finditer(r"\\frac\{", tex):
        depth, i = 1, m.end()
        while depth and i < len(tex):
            depth += {"{": 1, "}": -1}.get(tex[i], 0)
            i += 1
        if r"\frac" in tex[m.end() : i]:
            return True
    return False


def test_closed_forms_in_the_notes_style() -> None:
    """4.C.12 in closed form: v_A2n = v_A1 sin θ₁ (1 − e)/2 (the notes: (√2/4)(1 − e) v_A1),
    v_B2 = v_A1 sin θ₁ (1 + e)/2 with no |sin θ₁| (θ₁ = 45°), and T_2 over one denominator."""
    lines = _lines("notes-4c12-cue-ball")
    a2n = next(ln for ln in lines if ln.startswith("v_{A2n} = "))
    assert r"\left(1 - e\right)" in a2n and "e - 1" not in a2n and not a2n.startswith("v_{A2n} = -")
    assert not any(r"\left|" in ln for ln in lines if ln.startswith("v_{B2} = "))
    t2 = next(ln for ln in lines if ln.startswith("T_{2} = "))
    assert not _nested_fraction(t2), t2
    t_lost = next(ln for ln in lines if ln.startswith(r"T_{\mathrm{lost}} = "))
    assert "e - 1" not in t_lost


def test_notes_form_keeps_the_value() -> None:
    e, v, th = sympy.symbols("e v theta", positive=True)
    exprs = [
        -v * sympy.sin(th) * (e - 1) / 2,
        sympy.Abs(sympy.sin(th)) * v * (e + 1) / 2,
        v * (sympy.cos(th) ** 2 + (e - 1) ** 2 * sympy.sin(th) ** 2 / 4) / 2,
    ]
    for x in exprs:
        y = notes_form(x, {th: sympy.pi / 4})
        assert sympy.simplify((y - x).subs(th, sympy.pi / 4)) == 0
