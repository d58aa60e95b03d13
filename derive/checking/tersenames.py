"""Names declared tersely, a body's letter and a time: ``x = A after, y = B after (along
l.o.c.)``, ``p = P before``. Each is that body's velocity then; in an oblique impact, its
component along the line of centres where the line says so (across it where it says that), and
nothing where it says neither.

>>> [m.groups() for m in TERSE.finditer("x = A after, y = B after (along l.o.c.)")]
[('x', 'A', 'after'), ('y', 'B', 'after')]
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

#: A name, ``=``, a body's letter and a time: ``x = A after``, ``v = B's after``.
TERSE = re.compile(
    r"(?<![\w\\'])([A-Za-z](?:_?\w{1,2})?)\s*=\s*(?:the\s+)?([A-Z])(?:['’]s)?\s+(?:just\s+)?(after|before)\b(?!\s*=)"
)
_ALONG = re.compile(r"\balong\s+(?:the\s+)?(?:line\s+of\s+(?:centres|centers|impact)|l\.?\s?o\.?\s?c\b)", re.I)
_ACROSS = re.compile(r"\b(?:across|perp(?:endicular)?|tangent(?:ial)?)\b", re.I)


def terse_names(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names ``line`` declares tersely (:data:`TERSE`), each with derive's name for it."""
    found = list(TERSE.finditer(line))
    if not found:
        return {}
    nm = ctx.model.nm
    axis = ""
    if ctx.problem.oblique:
        along, across = bool(_ALONG.search(line)), bool(_ACROSS.search(line))
        if along == across:
            return {}
        axis = "n" if along else "t"
    a, b = ctx.problem.labels
    out: dict[str, sympy.Expr] = {}
    for m in found:
        body = "A" if m[2] in (a, "A") else "B" if m[2] in (b, "B") else ""
        when = "2" if m[3] == "after" else "1"
        x = getattr(nm, f"{body}{when}{axis or 'n'}", None) if body else None
        if x is not None and m[1] not in (a, b):
            out.setdefault(m[1], x)
    return out
