"""A plain number set equal to an inverse trig function is degrees, as a calculator in degree mode
shows it; the same number in radians is a calculator in radian mode (``degrees_as_radians``), not
right because the two sides also agree in radians. Each value is worked by hand: tan⁻¹(0.75) =
36.87° = 0.6435 rad, sin⁻¹(0.5) = 30° = 0.5236 rad, cos⁻¹(0.6) = 53.13° = 0.9273 rad."""

from __future__ import annotations

import pytest
from support.checked import worst_lines

PROBLEM = "giancoli-7-18-tennis-ball-wall-45deg"


@pytest.mark.parametrize(
    "line",
    [
        "tan^-1(0.75) = 36.87",
        "$\\arctan(0.75) = 36.9$",
        "\\[ \\sin^{-1}(0.5) = 30 \\]",
        "cos⁻¹(0.6) = 53.1",
        "tan^-1(0.75) = 36.9°",
        "tan^-1(0.75) = 0.6435 rad",
    ],
)
def test_an_inverse_trig_value_in_degrees_or_said_in_radians_is_right(line: str) -> None:
    assert worst_lines(PROBLEM, f"{line}\n")[1][0] == "correct"


@pytest.mark.parametrize("line", ["tan^-1(0.75) = 0.6435", "$\\sin^{-1}(0.5) = 0.5236$", "cos^-1(0.6) = 0.927"])
def test_an_inverse_trig_value_in_radians_unsaid_is_radian_mode(line: str) -> None:
    assert worst_lines(PROBLEM, f"{line}\n")[1] == ("wrong", "degrees_as_radians")
