"""Names under a lead-in that says they are after the impact (``After: x = u cos θ``): the student's
own names used before it primed, so that ``Before: x = …`` and ``After: x = …`` are two quantities,
and so are a velocity's components by their axis (``- before: vx = …``, ``- after: vx = …``)."""

from __future__ import annotations

import re

#: A lead-in that says the names under it are after the impact (``After: x = u cos θ``).
_AFTER = re.compile(r"^(?:after(?:wards)?|finally|final|after\s+(?:the\s+)?(?:impact|collision|bounce))$", re.I)


def after_label(text: str, label: str, seen: set[str]) -> str:
    """A side under ``After:`` with the one-letter names of the student's own used before it
    primed (``x`` -> ``x'``): ``Before: x = u cos θ`` and ``After: x = u cos θ`` are two
    quantities; so are a velocity's components by their axis (``Before: vx = …``, ``After: vx = …``).
    Names with a time of their own (``u``, ``v``, ``V``, ``w``), ``e``, ``m``, ``g`` and ``i``, ``j``
    are kept."""
    if not _AFTER.match(label.strip()):
        return text

    def primed(m: re.Match) -> str:
        return m.group(1) + ("'" if m.group(1) in seen else "")

    text = re.sub(r"(?<![A-Za-z_'.])([a-dfhk-lnoprstx-zA-LN-UX-Z])(?![\w'(])", primed, text)
    return re.sub(r"(?<![A-Za-z_'.])([uvwV]_?[xy])(?![\w'(])", primed, text)  # vx under Before: and After:
