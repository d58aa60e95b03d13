"""The common mistakes, in the order a report lists them: one entry per kind.

A new kind is a function in one of the family modules (decorated with
:func:`~.records.mistake`) and one line here.
"""

from __future__ import annotations

from derive.checking.mistakes import directions, masses, restitution, tangential, velocities
from derive.checking.mistakes.records import Mistake

#: What each of the equations is, in words (the notes' three systems and the impact rule).
EQUATION_TITLES = {
    1: "the t-momentum of A",
    2: "the t-momentum of B",
    3: "the n-momentum of the system A + B",
    4: "the impact rule (restitution)",
}

KINDS: tuple[Mistake, ...] = (
    velocities.b_sign,
    restitution.restitution_reversed,
    restitution.e_speeds,
    tangential.e_on_t,
    restitution.energy_conserved,
    tangential.system_t,
    velocities.sin_cos_swapped,
    directions.angle_other_axis,
    directions.angle_quadrant,
    velocities.degrees_as_radians,
    masses.masses_swapped,
    masses.weight_as_mass,
)

#: Every mistake by name.
REGISTRY: dict[str, Mistake] = {m.name: m for m in KINDS}


def phrase(name: str) -> str | None:
    """What completes "your (4) ..." for a mistake, or two together (``e_on_t+system_t``)."""
    parts = [REGISTRY.get(n) for n in name.split("+")]
    if any(m is None for m in parts):
        return None
    return " and ".join(m.phrase for m in parts if m is not None)
