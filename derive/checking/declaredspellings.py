"""Names declared in words, spelled as the relations are read: "A's speed before is v1" declares
``v1``, and the relations' ``3 v1 + 5`` are read with ``v1`` written ``v_1`` (the habit's spelling
of a letter and a digit, :func:`.naming.rewrite`), so the declaration is the rewritten name's too;
without it the habit's ``v_1`` (A's velocity after) would stand where the student said otherwise.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.naming import rewrite


def as_read(declared: dict[str, sympy.Expr], sign: int) -> tuple[dict[str, sympy.Expr], int]:
    """``declared`` with each name also under the spelling a relation's name is read in (where that
    is one name and no other declaration has it), and ``sign`` as it is."""
    out = dict(declared)
    for name, meaning in declared.items():
        spelled = rewrite(name, set()).strip()
        if spelled != name and re.fullmatch(r"[A-Za-z]\w*", spelled) and spelled not in out:
            out[spelled] = meaning
    return out, sign
