"""Sin and cos swapped on a velocity whose angle from the line of impact is obtuse, as the student
writes it: with n at 20° to x and B moving at 120° to x, B is at 100° from n; its components are
110 cos 100° = -19.10 along n and 110 sin 100° = 108.3 across. Swapped as written, 110 sin 100° =
108.3 along n and 110 cos 100° = -19.10 across: the slip, the same mistake again, and the lines
after judged in the world with B's components so (not with each part keeping its way, -108.3).

Given the slip (A's right: 80 cos 25° = 72.50 along n): v_B2n - v_A2n = 0.7(72.50 - 108.3) =
-25.06; 4 v_A2n + 3 v_B2n = 4(72.50) + 3(108.3) = 614.9; so 7 v_A2n = 614.9 + 3(25.06) = 690.1,
v_A2n = 98.58, 98.6.
"""

from __future__ import annotations

from support.checked import lines

PROBLEM = "fisicalab-example-7-normal-at-20deg"
WORK = """v_A1n = 80 cos 25° = 72.50
v_B1n = 110 sin 100° = 108.3
v_B1t = 110 cos 100° = -19.10
v_B2n - v_A2n = 0.7(72.50 - 108.3) = -25.06
4 v_A2n + 3 v_B2n = 4(72.50) + 3(108.3) = 614.9
7 v_A2n = 614.9 + 3(25.06) = 690.1
v_A2n = 98.6 m/s
"""


def test_sin_and_cos_swapped_as_written_on_an_obtuse_angle_carries() -> None:
    found = lines(PROBLEM, WORK)
    assert found[1][0] == "correct", found
    assert found[2] == ("wrong", "sin_cos_swapped", False), found
    assert found[3] == ("wrong", "sin_cos_swapped", True), found
    assert [found[n][0] for n in (4, 5, 6, 7)] == ["carried"] * 4, found
