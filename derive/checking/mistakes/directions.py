"""Mistakes in the direction after the impact: the other axis, the wrong quadrant."""

from __future__ import annotations

from derive.checking.mistakes.equations import Model
from derive.checking.mistakes.records import Variant, mistake


@mistake(
    "angle_other_axis",
    "the direction after the impact from the other axis",
    "The direction after the impact was measured from the other axis: the angle found is the "
    "complement (90° minus) of the one asked for. Which component goes on top of tan⁻¹ depends on "
    "the axis the angle is measured from: the component across that axis over the one along it.",
    (),
    "the direction after the impact (stage 4)",
    "measures the direction from the other axis",
)
def angle_other_axis(model: Model) -> Variant | None:
    """θ computed as tan⁻¹(v_t/v_n)."""
    if not model.problem.oblique:
        return None
    return Variant(angles="other_axis")


@mistake(
    "angle_quadrant",
    "the direction after the impact in the wrong quadrant",
    "tan⁻¹(v_n/v_t) was taken at face value where v_t < 0: the direction then lies on the other side, "
    "180° away (the calculator's tan⁻¹ cannot tell).",
    (),
    "the direction after the impact (stage 4)",
    "puts the direction in the wrong quadrant",
)
def angle_quadrant(model: Model) -> Variant | None:
    """θ computed as tan⁻¹(v_n/v_t) without its quadrant."""
    if not model.problem.oblique:
        return None
    return Variant(angles="principal")
