"""A velocity written as a vector on a head-on impact (``u_A = 3 i``, ``\\mathbf{v}_A = -0.6\\,\\mathbf{i}``,
``\\vec v_B = 3.4\\,\\hat\\imath`` m/s): a head-on impact has one axis, the line of motion, so the
vector's one component is the velocity itself (``u_A = 3 i`` is ``u_A = 3``), not an n component
the problem has no name for.

Values worked by hand from aqa-m3-2007-spheres-approach-head-on's givens: m_A = 0.3, m_B = 0.2,
u_A = 3 (toward B, +), u_B = -2, e = 0.8. Momentum 0.3(3) + 0.2(-2) = 0.5 = 0.3 v_A + 0.2 v_B;
restitution v_B - v_A = 0.8(3 - (-2)) = 4. So 0.5 = 0.3 v_A + 0.2(v_A + 4), 0.5 v_A = -0.3,
v_A = -0.6 and v_B = 3.4.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.mathtext.reader import read_relations

SPHERES = "aqa-m3-2007-spheres-approach-head-on"


@pytest.mark.parametrize(
    ("line", "expected"),
    [
        ("u_A = 3 i, u_B = -2 i", ["correct"]),
        ("v_A = -0.6 i m/s", ["correct"]),
        (r"$\mathbf{v}_B = 3.4\,\mathbf{i}$", ["correct"]),
        (r"\[ \vec v_A = -0.6\,\hat\imath, \quad \vec v_B = 3.4\,\hat\imath \ \text{m/s} \]", ["correct"]),
        ("So v_B = 3.4i m/s (B goes back the way it came)", ["correct"]),
    ],
)
def test_a_one_axis_vector_on_a_head_on_impact_is_the_velocity(line: str, expected: list) -> None:
    assert statuses(SPHERES, line) == expected


def test_a_wrong_one_axis_vector_is_not_correct() -> None:
    assert statuses(SPHERES, "v_B = 3.6 i m/s") != ["correct"]


def test_the_reader_keeps_the_name_when_told_the_impact_is_head_on() -> None:
    assert [r.sides for r in read_relations("u_A = 3 i", head_on=True)] == [("u_A", "3")]
    assert [r.sides for r in read_relations("A after = -0.6 j", head_on=True)] == [("A'", "-0.6")]
    # both axes written: the components, as on an oblique impact
    assert [r.sides for r in read_relations("u = 3i + 4j", head_on=True)] == [("u_n", "3"), ("u_t", "4")]
