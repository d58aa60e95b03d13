"""The relation a line ``= …`` goes on from when the line above ends with a where-clause: a name
the line's formula uses, defined after it and worked to a number (``KE lost = ½μ(1 − e²)w², μ =
(2)(1)/(2 + 1)`` then ``= ½ × ⅔ × 0.36 × 10² = 12``; ``p = m v, m = 0.5`` then ``= 0.5 × 4``).
The definition only feeds the formula; the next line goes on from the formula, as a teacher reads
it. A last relation whose name no earlier relation of its line uses, or that is not worked to
numbers (``v_B = 2 + v_A, v_A = 3 - v_B``), is the one the next line goes on from, as before.

>>> from types import SimpleNamespace as R
>>> main, where = R(sides=("KE lost", "½μ(1 − e²)w²")), R(sides=("μ", "(2)(1)/(2 + 1)"))
>>> went_on_from(where, [main, where]).sides[0]
'KE lost'
>>> went_on_from(R(sides=("v_A", "3 - v_B")), [R(sides=("v_B", "2 + v_A"))]).sides[0]
'v_A'
"""

from __future__ import annotations

import re
from typing import Any

#: A name a where-clause defines: a letter (Latin or Greek) and its subscript, nothing else.
_NAME = re.compile(r"[A-Za-z\u0391-\u03c9]'*(?:_\{?\w{1,4}\}?)?'*")
#: A side of numbers only (no letter): the definition worked to its value.
_LETTER = re.compile(r"[A-Za-z\u0391-\u03c9]")


def went_on_from(above: Any, line: list[Any]) -> Any:
    """The relation a line ``= …`` goes on from: ``above``, the last relation read on the line
    before, or, where ``above`` defines a name in numbers that an earlier relation of ``line``
    (that line's relations, in order) uses on its last side, that earlier relation."""
    name = above.sides[0].strip() if len(above.sides) >= 2 else ""
    if not _NAME.fullmatch(name) or _LETTER.search(above.sides[-1]):
        return above
    used = re.compile(r"(?<![A-Za-z_'])" + re.escape(name) + r"(?![A-Za-z0-9_'])")  # ½μ: a factor
    for r in reversed(line[: next((k for k, r in enumerate(line) if r is above), len(line))]):
        if len(r.sides) >= 2 and r.sides[0].strip() != name and used.search(r.sides[-1]):
            return r
    return above
