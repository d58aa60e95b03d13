"""The speed after a rebound named beside "speed after" with its square typed at once: ``speed
after: V² = …`` (Unicode's ², also in brackets as a remark) is V, the speed after, squared; not
the name ``V²``, which nothing declares.

By hand, a 0.5 kg ball at 10 m/s, 30° to a smooth wall, e = 0.5: along the wall 10 cos 30° =
8.660 (75 squared), out of it 0.5 × 10 sin 30° = 2.5 (6.25 squared): V² = 81.25, V = 9.014."""

from __future__ import annotations

import pytest
from support.checked import wall_30_lines


@pytest.mark.parametrize(
    "line",
    [
        "speed after: V² = (10 cos 30°)² + (0.5 × 10 sin 30°)² = 81.25",
        "(speed after: V² = 75 + 6.25 = 81.25)",
        "speed just after the impact: w² = 75 + 6.25 = 81.25",
    ],
)
def test_a_squared_speed_named_after_iswall_30_lines(tmp_path, line: str) -> None:
    assert wall_30_lines(tmp_path, line + "\n") == ["correct"]


def test_a_wrong_squared_speed_named_after_is_wrong(tmp_path) -> None:
    assert wall_30_lines(tmp_path, "speed after: V² = 75 + 25 = 100\n") == ["wrong"]
