"""Names typed so that their letters need telling apart: a mass glued to a velocity's name (``mvA``,
``2mvQ``: m times v_A), and a body's lowercase letter written beside the other body's capital (the
bullet's ``v_b1`` beside the block's ``v_B1``: two bodies, not B twice).
"""

from __future__ import annotations

import re

#: A mass glued to a velocity's name, phone-typed: ``mvA``, ``2mvQ``, ``muA`` (not ``mu1``, μ₁).
GLUED_MASS = re.compile(r"\b(\d*[mM])([vVw](?=[A-Z12])|u(?=[A-Z]))(\w)(\d?[nt]?)\b")


def twin_letters(text: str) -> frozenset[str]:
    """The lowercase body letters a derivation writes beside their capitals in velocities' names (the
    bullet's ``v_b1`` beside the block's ``v_B1``): two bodies, so ``v_b`` is not B's."""
    return frozenset(
        c for c in "ab" if all(re.search(rf"(?<![A-Za-z\\])[uvVw]_?[({{]?{x}(?![a-z])", text) for x in (c, c.upper()))
    )
