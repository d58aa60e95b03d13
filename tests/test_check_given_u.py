"""``u`` that is a given of the problem (the speed in ``S moves at speed u``) is not the one-body habit
"u before, v after": with S brought to rest, ``v`` alone is T's velocity after, the one velocity
after that is not given.

Worked by hand (edexcel-m2-undated-q5-s-brought-to-rest-show-e): S (m) at u catches T (km) at λu;
S stops. Momentum mu + km·λu = km v, so v = u(1 + kλ)/k; restitution v − 0 = e(u − λu), so
e = (1 + kλ)/(k(1 − λ)).
"""

from __future__ import annotations

from support.checked import line_statuses as statuses

import derive
from derive.checking.context import Context
from derive.checking.naming import habits

REST = "edexcel-m2-undated-q5-s-brought-to-rest-show-e"
WORK = (
    "Only T moves after the impact, at v.\n"
    "$m u + k m \\lambda u = k m v$\n"
    "$v = u(1 + k\\lambda)/k$\n"
    "$v = e(u - \\lambda u)$\n"
    "$e = \\frac{1 + k\\lambda}{k(1 - \\lambda)}$\n"
)


def test_v_beside_the_given_u_is_the_one_velocity_after_not_given() -> None:
    ctx = Context(derive.solve(derive.load(REST)), None)
    assert str(habits(ctx, {"u", "v", "k", "m"})["v"]) == "v_B2"


def test_the_working_with_v_for_t_is_right() -> None:
    assert statuses(REST, WORK) == ["correct"] * 4


def test_a_letter_lost_in_it_is_still_wrong() -> None:
    assert statuses(REST, WORK.replace("$v = u(1 + k\\lambda)/k$", "$v = u(1 + \\lambda)/k$"))[1] == "wrong"
