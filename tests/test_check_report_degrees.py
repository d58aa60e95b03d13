"""An angle worked wrongly is reported in the degrees the student wrote, not in radians
("α is 46.83°, not 43.2°"; it read "α is 0.8173, but 43.2° is 0.7540"): found checking a
derivation as a student (issue #31, item 7)."""

from __future__ import annotations

import math

import pytest

import derive
from derive.checking.words import unequal


@pytest.mark.parametrize("written", ["43.2°", "(43.2*deg)", "43.2 °"])
def test_an_angle_in_degrees_is_reported_in_degrees(written: str) -> None:
    # tan α = 2√3/3.25: α = atan(1.0658) = 46.83°, worked by hand
    alpha = math.atan(2 * math.sqrt(3) / 3.25)
    assert round(math.degrees(alpha), 2) == 46.83
    said = unequal("α", alpha, written, math.radians(43.2))
    assert said == "α is 46.83°, not 43.2° (an arithmetic slip).", said


def test_a_derivation_s_angle_slip_is_said_in_degrees() -> None:
    # Giancoli 7-18: a ball at 25 m/s strikes the wall at 45° and rebounds elastically; its
    # direction after is again 45° from the normal: tan θ = 17.68/17.68 = 1, θ = 45°, not 40°.
    work = "v_x = 25 cos 45 = 17.68\nv_y = 25 sin 45 = 17.68\ntan θ = 17.68/17.68 = 1\nθ = tan^-1(1) = 40°\n"
    report = derive.check(derive.load("giancoli-7-18-tennis-ball-wall-45deg"), derivation=work)
    line = next(i for i in report.items if i.kind == "line" and i.name == "4")
    assert line.status == "wrong"
    assert "θ is 45.00°, not 40°" in line.message and "0.78" not in line.message, line.message
