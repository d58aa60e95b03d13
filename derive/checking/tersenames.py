"""Names declared tersely, a body's letter and a time: ``x = A after, y = B after (along
l.o.c.)``, ``p = P before``, the other way round (``A after=x B after=y``) or under a label of time
(``vel after: A=a B=b``). Each is that body's velocity then; in an oblique impact, its component along
the line of centres where the line says so (across it where it says that), and nothing where it says
neither.

>>> [m.groups() for m in TERSE.finditer("x = A after, y = B after (along l.o.c.)")]
[('x', 'A', 'after'), ('y', 'B', 'after')]
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context
from derive.checking.statementbodies import statement_bodies

#: A name, ``=``, a body's letter and a time: ``x = A after``, ``v = B's after``.
TERSE = re.compile(
    r"(?<![\w\\'])([A-Za-z](?:_?\w{1,2})?)\s*=\s*(?:the\s+)?([A-Z])(?:['’]s)?\s+(?:just\s+)?(after|before)\b(?!\s*=)"
)
#: The same the other way round, phone-typed: ``A after=x B after=y``, ``B's before = u``.
TERSE_AFTER = re.compile(
    r"(?<![\w\\'])(?<!\bof\s)(?<!\bof\sthe\s)(?:the\s+)?([A-Z])(?:['’]s)?\s+(?:just\s+)?(after|before)\s*=\s*"
    r"([A-Za-z](?:_?\d|_\w{1,2})?)"  # x, v1, x_A: a name, not a product of letters (eu)
    r"(?![\w('])(?!\s*[-+*/^=])"
)
#: A time said in a label, then bodies' letters set to names: ``vel after: A=a B=b``, ``After impact: P = x, Q = y``.
_TIME_LABEL = re.compile(r"\b(after|before)\b[^:=]{0,30}:\s*(.*)$", re.I)
_LETTER_NAME = re.compile(  # a body's letter, not a quantity's (V, U, J, K, T, E, F, ...): "After: V = u" is judged
    r"(?<![\w\\'])((?![EFGHIJKMNTUVW])[A-Z])\s*=\s*([A-Za-z](?:_?\d|_\w{1,2})?)(?![\w('])(?!\s*[-+*/^=])"
)
_ALONG = re.compile(r"\balong\s+(?:the\s+)?(?:line\s+of\s+(?:centres|centers|impact)|l\.?\s?o\.?\s?c\b)", re.I)
_ACROSS = re.compile(r"\b(?:across|perp(?:endicular)?|tangent(?:ial)?)\b", re.I)


def terse_names(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names ``line`` declares tersely (:data:`TERSE`), each with derive's name for it."""
    found = [m.groups() for m in TERSE.finditer(line)]
    found += [(m[3], m[1], m[2]) for m in TERSE_AFTER.finditer(line)]
    label = _TIME_LABEL.search(line)
    if label:
        found += [(m[2], m[1], label[1].lower()) for m in _LETTER_NAME.finditer(label[2])]
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
    letters = {a: "A", b: "B", "A": "A", "B": "B", **statement_bodies(ctx)}  # "Particles P (mass 2m) and Q"
    out: dict[str, sympy.Expr] = {}
    givens = {g.name for g in ctx.problem.givens}
    for name, letter, time in found:
        body = letters.get(letter, "")
        when = "2" if time == "after" else "1"
        x = getattr(nm, f"{body}{when}{axis or 'n'}", None) if body else None
        if x is not None and name not in letters and name not in givens:  # "speed of Q after = u": u given
            out.setdefault(name, x)
    return out


def terse_only(text: str) -> bool:
    """Whether every ``=`` of ``text`` is in a terse declaration (``A after=x B after=y``, two or more
    the other way round, or under a label of time): a line of names, not a relation to judge."""
    rest, pairs = TERSE_AFTER.subn(" ", TERSE.sub(" ", text))
    label = _TIME_LABEL.search(rest)
    if label:
        rest = rest[: label.start(2)] + _LETTER_NAME.sub(" ", label[2])
    elif pairs == 1:  # "Q after = u" alone: an answer in words as often as a name
        return False
    return rest != text and "=" not in rest
