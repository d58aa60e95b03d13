"""The speed after a rebound named beside "speed after" with its square typed at once: ``speed
after: V² = …`` (Unicode's ², also in brackets as a remark) is V, the speed after, squared; not
the name ``V²``, which nothing declares.

By hand, a 0.5 kg ball at 10 m/s, 30° to a smooth wall, e = 0.5: along the wall 10 cos 30° =
8.660 (75 squared), out of it 0.5 × 10 sin 30° = 2.5 (6.25 squared): V² = 81.25, V = 9.014."""

from __future__ import annotations

import pytest

import derive

WALL_30 = """title = "A ball strikes a smooth wall at 30 degrees"
kind = "oblique"
statement = "A ball of mass 0.5 kg hits a smooth wall at 10 m/s at 30 degrees to the wall; e = 0.5."
question = "Find the velocity after the impact."

[given]
m_A = "0.5 kg"
e = 0.5
v_A1 = "10 m/s"
alpha = "30 deg"

[A]
angle = "alpha"
from = "+t"
toward = "+n"

[B]
fixed = true
name = "wall"
"""


def _judged(tmp_path, work: str) -> list[str]:
    path = tmp_path / "wall.toml"
    path.write_text(WALL_30)
    sol = derive.solve(derive.load(str(path)))
    return [i.status for i in derive.check(sol, derivation=work).items if i.kind == "line"]


@pytest.mark.parametrize(
    "line",
    [
        "speed after: V² = (10 cos 30°)² + (0.5 × 10 sin 30°)² = 81.25",
        "(speed after: V² = 75 + 6.25 = 81.25)",
        "speed just after the impact: w² = 75 + 6.25 = 81.25",
    ],
)
def test_a_squared_speed_named_after_is_judged(tmp_path, line: str) -> None:
    assert _judged(tmp_path, line + "\n") == ["correct"]


def test_a_wrong_squared_speed_named_after_is_wrong(tmp_path) -> None:
    assert _judged(tmp_path, "speed after: V² = 75 + 25 = 100\n") == ["wrong"]
