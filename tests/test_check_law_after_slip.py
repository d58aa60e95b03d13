"""A law written in names after a slip (``m_A u_A + m_B u_B = m_A v_A + m_B v_B``) is true for the
problem and says nothing about the student's numbers: a teacher ticks it, with no remark that it
"does not follow from the slip" (found checking a derivation as a student, issue #31 item 7)."""

from __future__ import annotations

import derive

#: AQA M3 2007: A 0.3 kg at 3 m/s, B 0.2 kg at 2 m/s toward A, e = 0.8. B's sign lost in the
#: momentum: 0.3(3) + 0.2(2) = 1.3 (0.5 with it); then restitution as a law in names.
WORK = """Take A's direction as positive.
0.3(3) + 0.2(2) = 0.3 v_A + 0.2 v_B
0.3 v_A + 0.2 v_B = 1.3
v_B - v_A = e(u_A - u_B)
"""

#: OCR FM 2023 discs at 60°: A 5 kg at 4 m/s at 60° to the line of centres, so v_A1n = 4 cos 60 = 2;
#: sin and cos swapped gives 3.464 (the student's); momentum 5(3.464) + 3(-6) = -0.68 from it.
OBLIQUE = r"""$$v_{A1n} = 4\sin 60^\circ = 3.464, \quad v_{A1t} = 4\cos 60^\circ = 2$$
$$v_{B1n} = -6$$
$$m_A v_{A1n} + m_B v_{B1n} = m_A v_{A2n} + m_B v_{B2n}$$
$$5 v_{A2n} + 3 v_{B2n} = -0.68$$
"""


def _lines(problem: str, text: str) -> dict[str, object]:
    report = derive.check(derive.load(problem), derivation=text)
    return {i.name: i for i in report.items if i.kind == "line"}


def test_a_law_in_names_after_a_slip_is_ticked_without_a_remark() -> None:
    for problem, text, law in (
        ("aqa-m3-2007-spheres-approach-head-on", WORK, "4"),
        ("ocr-fm-2023-oblique-discs-60deg", OBLIQUE, "3"),
    ):
        lines = _lines(problem, text)
        assert lines[law].status == "correct", (problem, lines[law].message)
        assert not any("does not follow" in n for n in lines[law].notes), (problem, lines[law].notes)
        assert lines["2" if problem.startswith("aqa") else "1"].status == "wrong"
