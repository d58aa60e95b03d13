"""A name times a unit vector with a hat, typed with no space between (``v_1\\hat n``,
``w_{B}\\hat{t}``): in LaTeX a subscript takes one token, so this is v_1 times n̂, as
``a\\mathbf{i}`` is a times i, never one name ``v_1n_hat``.

Worked by hand (notes-4c11-two-spheres): A (20 kg) at 5 m/s and B (5 kg) at 15 m/s, each at 37.6°
to the line of centres: A's components 5 cos 37.6° = 3.96 along n, 5 sin 37.6° = 3.05 across; B's
-15 cos 37.6° = -11.88, -15 sin 37.6° = -9.15; the t components are unchanged by the impact.
Momentum 20(3.96) + 5(-11.88) = 19.8 = 20 v_1 + 5 v_2; restitution v_2 - v_1 = 0.6(15.84) = 9.504;
25 v_1 = 19.8 - 47.52, v_1 = -1.11 m/s.
"""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.latex import latex_to_plain

SPHERES = "notes-4c11-two-spheres"
WORK = (
    "$\\hat n$ along the line of centres from A to B, $\\hat t$ across it.\n"
    "\n"
    "After: $\\vec v_A' = v_1\\hat n + 3.05\\hat t$ and $\\vec v_B' = v_2\\hat n - 9.15\\hat t$.\n"
    "\n"
    "$20(3.96) + 5(-11.88) = 20v_1 + 5v_2$\n"
    "\n"
    "$v_2 - v_1 = 0.6(3.96 + 11.88)$\n"
    "\n"
    "$25 v_1 = 19.8 - 47.52$, so $v_1 = -1.11$ m/s\n"
)


def test_a_subscripted_name_glued_to_a_hat_is_a_product() -> None:
    assert latex_to_plain(r"\vec v_{2f} = v_2\hat n") == "v_2f = v_2 n_hat"
    assert latex_to_plain(r"w_{B}\hat{t} - u_A\hat{\imath}") == "w_B t_hat - u_A i_hat"


def test_velocities_after_as_components_times_unit_vectors_are_read() -> None:
    found = worst_lines(SPHERES, WORK)
    assert [found[n][0] for n in (3, 5, 7, 9)] == ["correct"] * 4


def test_a_t_component_with_its_sign_lost_there_is_wrong() -> None:
    found = worst_lines(SPHERES, WORK.replace("v_2\\hat n - 9.15\\hat t", "v_2\\hat n + 9.15\\hat t"))
    assert found[3][0] == "wrong"
