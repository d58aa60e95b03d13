"""A kinetic energy written by its bare name under a label that says its instant: ``KE after:
KE = (4.02)(1.4925)² = 8.96 J``, ``Kinetic energy before: E_k = …``, ``**KE lost:** K = …``.
The reader leaves the label out (words before a colon), and the bare ``KE`` alone is read as
the energy before; the label names which energy it is, so the name takes the label's instant
(``KE after`` -> the kinetic energy after), and the line is judged against that energy (a half
left out: ``ke_formula``), not against the energy before.
"""

from __future__ import annotations

import re
from dataclasses import replace

from derive.mathtext.reader import Relation

#: A kinetic energy's bare name, as a side alone: KE, K.E., E_k, Ek, E_{k}, K; primed too (K', KE').
_BARE = re.compile(r"\s*(?:K\.?\s?E\.?|E_?\{?k\}?|K)\s*['′]?\s*")
#: The label names a kinetic energy ...
_ENERGY = re.compile(r"(?i)(?<![A-Za-z])(?:K\.?\s?E\.?|E_?\{?k\}?|kinetic\s+energy|energy)(?![A-Za-z])")
#: ... at one instant (the first that matches).
_INSTANTS = (
    ("lost", re.compile(r"(?i)\b(?:lost|loss|lose|decrease|dissipated)\b")),
    ("before", re.compile(r"(?i)\b(?:before|initial(?:ly)?)\b")),
    ("after", re.compile(r"(?i)\b(?:after|final(?:ly)?|afterwards)\b")),
)


def instant_of(label: str) -> str:
    """``before``, ``after`` or ``lost`` where ``label`` names a kinetic energy at that instant, else ""."""
    if not _ENERGY.search(label):
        return ""
    said = [word for word, pattern in _INSTANTS if pattern.search(label)]
    return said[0] if len(said) == 1 else ""


def energy_at_labels(relations: tuple[Relation, ...]) -> tuple[Relation, ...]:
    """Each relation whose first side is a kinetic energy's bare name, led in by a label naming
    the energy's instant, with that side named at the instant (``KE`` -> ``KE_after``), and the
    same bare name written again in a later relation named so too (``KE before: K = 3mu²``,
    ``KE after: K' = …``, then ``KE lost = K − K'``): a name the label gave keeps its meaning."""
    out, named = [], {}
    for r in relations:
        at = instant_of(r.label) if r.sides and _BARE.fullmatch(r.sides[0]) else ""
        sides = (f"KE_{at}", *r.sides[1:]) if at else r.sides
        for bare, name in named.items():  # ``KE lost = K - K'``: each named as its label said, never
            # a word of a longer name (``Delta KE``, ``KE lost``)
            sides = tuple(
                re.sub(rf"(?<![\w'′Δ])(?<![A-Za-z] ){re.escape(bare)}(?![\w'′]|\s*[A-Za-z])", name, x) for x in sides
            )
        if at:
            named[r.sides[0].strip()] = f"KE_{at}"  # the name keeps the label's meaning on later lines
        out.append(replace(r, sides=sides) if sides != r.sides else r)
    return tuple(out)
