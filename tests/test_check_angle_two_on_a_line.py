"""A line with two angles, the second worked from the first after an arrow (``angle from n = … =
57.17° -> from x: 57.17 + 20 = 77.17°``): each relation is judged by its own words, the second's
("from x: 57.17 + 20") not the first's ("angle from n").

FisicaLab example 7 by the source's answers: B leaves at 128.916 m/s, 77.172° from x; the line of
impact is at 20° to x, so from n it is 57.172°, and tan 57.172° = v_B2t/v_B2n = 108.33/69.887.
"""

from __future__ import annotations

import pytest

import derive

PROBLEM = "fisicalab-example-7-normal-at-20deg"


def statuses(work: str) -> list[str]:
    report = derive.check(derive.solve(derive.load(PROBLEM)), derivation=work)
    return [i.status for i in report.items if i.kind == "line"]


@pytest.mark.parametrize(
    ("work", "expected"),
    [
        ("B: angle from n = tan^-1(108.33/69.887) = 57.17 deg -> from x: 57.17 + 20 = 77.17 deg", ["correct"]),
        (
            "$\\beta_B = \\tan^{-1}(108.33/69.887) = 57.17^\\circ \\Rightarrow$ from x: $57.17 + 20 = 77.17^\\circ$",
            ["correct"],
        ),
        ("B: angle from n = tan^-1(108.33/69.887) = 57.17 deg; from x: 57.17 + 20 = 79.17 deg", ["wrong"]),
        ("B: angle from n = tan^-1(108.33/69.887) = 59.17 deg -> from x: 59.17 + 20 = 79.17 deg", ["wrong"]),
    ],
)
def test_each_angle_on_a_line_is_judged_by_its_own_words(work: str, expected: list[str]) -> None:
    assert statuses(work) == expected
