"""A wall's components named by their axis and a time, with no body's letter: at a wall one body
moves, so ``(v_t)_2``, ``v_{t1}``, ``v_{1n}``, ``u_{t,2}`` are that body's component along the
wall (t) or into it (n), before (1) or after (2). The component into the wall after (``v_n2``) is
the rebound, which students write as a size or signed as their words say: it is left to those
words, as ``v_perp`` is (:mod:`.axisnames`), never read as derive's signed component."""

from __future__ import annotations

import re

#: A wall's component by its axis letter and a time's digit, either order (``t2``, ``1n``).
_TIMED = re.compile(r"([nt])([12])|([12])([nt])")


def wall_timed(marks: str) -> tuple[str, str, str] | None:
    """(body, time, axis) of a velocity's marks at a wall (``t2``, ``_1n``, ``t,1``), the body
    left for the one moving body; None for other marks."""
    m = _TIMED.fullmatch(marks.replace("_", "").replace(",", ""))
    return None if m is None else ("", m[2] or m[3], m[1] or m[4])


def typed_at_wall(name: str, text: str) -> bool:
    """Whether ``name`` may be read as a wall's component by :func:`wall_timed`: its axis before its
    digit (``v_t2``, ``(v_t)_2``), or its digit first as the student typed it (``v_{1t}``, ``v1t``);
    not ``v_1n`` made from a vector ``\\vec v_1 = … \\hat\\imath + …``, whose i and j are the student's
    own axes, placed by the frame they declare."""
    m = re.fullmatch(r"([A-Za-z])_?([12])_?([nt])", name)
    if m is None:
        return True
    letter, digit, axis = m.groups()
    return re.search(rf"(?<![A-Za-z\\]){letter}_?\{{?{digit}\s*,?\s*{axis}(?![A-Za-z])", text) is not None


def wall_rebound(name: str) -> bool:
    """Whether ``name`` at a wall is the rebound named by its axis (``v_perp``, ``v_n2``, ``u_{2n}``):
    a size or signed as the words say, not derive's signed component."""
    return bool(re.search(r"par|perp|∥|⊥", name) or re.fullmatch(r"[A-Za-z]_?(?:n_?,?2|2_?,?n)", name))
