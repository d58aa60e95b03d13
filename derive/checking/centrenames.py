"""A name given in words to the velocity of the centre of mass (the common velocity):
"the centre of mass is not moving ($V = 0$)", "let W be the velocity of the centre of mass",
"in the CM frame … V = (m_A u_A + m_B u_B)/(m_A + m_B)", "the common velocity is w". The name is the
one set equal to something, or said after "is", "be", "at", "(" on a line that speaks of the
centre of mass; a body's velocity (``V_A``, ``v_1``) is never one.

>>> sorted(_said("So the centre of mass is not moving ($V = 0$), and in the CM frame …"))
['V']
>>> sorted(_said("let W be the velocity of the centre of mass"))
['W']
>>> sorted(_said("V_A = 2 and the centre of mass moves at v_{cm}"))
['v_cm']
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

#: Words for the centre of mass, its frame and its velocity.
_CENTRE = re.compile(
    r"\bcent(?:re|er)\s+of\s+(?:mass|momentum)\b|\bc\.\s?o\.\s?m\b\.?|\b(?:CoM|CM|COM|ZMF)\b"
    r"|\bzero[- ]momentum\s+frame\b|\bcommon\s+velocity\b",
    re.I,
)
#: A velocity's letter alone or with a subscript that names no body (``V``, ``W``, ``V_0``, ``v_{cm}``).
_CANDIDATE = re.compile(r"(?<![\w\\'])([VUWw]|[vVuU]_\{?(?:G|g|c|cm|CM|com|COM|CoM|0|ZMF)\}?)(?![\w'{])")
#: Words just before a name that say it is what the line speaks of.
_SAYS = re.compile(r"(?:\b(?:let|is|be|at|by|called|say|denote|call)|[(:])\s*$", re.I)
#: Subscripts that name a body: such a name is a body's velocity, not the centre of mass's.
_BODY_MARKS = frozenset("ABPQ12")
#: A body's label as the subject of the clause before a name ("in the CM frame B moves at w"):
#: the name is that body's velocity (in the frame), not the centre of mass's.
_BODY_SUBJECT = re.compile(r"(?<![\w\\'])[A-HJ-Z](?![\w'])")


def _said(line: str) -> set[str]:
    """The names ``line`` gives the velocity of the centre of mass (as the reader writes them)."""
    if not _CENTRE.search(line):
        return set()
    plain = line.replace("$", " ").replace("\\(", " ").replace("\\)", " ")
    out = set()
    for m in _CANDIDATE.finditer(plain):
        name = re.sub(r"[{}]", "", m[1])
        if name.split("_")[-1] in _BODY_MARKS:
            continue
        clause = re.split(r"[,;:(]|\band\b", plain[: m.start()])[-1]
        if _BODY_SUBJECT.search(clause):
            continue  # "in the CM frame B moves at w = -3": B's velocity there
        if re.match(r"\s*(?:=|≈)", plain[m.end() :]) or _SAYS.search(plain[: m.start()]):
            out.add(name)
    return out


def centre_names(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names ``line`` declares in words as the velocity of the centre of mass -> derive's
    expression for it, (m_A v_A1 + m_B v_B1)/(m_A + m_B) (its component along the line of centres)."""
    said = _said(line)
    m, nm = ctx.model, ctx.model.nm
    if not said or nm.A1n is None or ctx.problem.fixed_B:
        return {}
    b1 = nm.B1n if nm.B1n is not None else 0
    return dict.fromkeys(said, (m.m_A * nm.A1n + m.m_B * b1) / (m.m_A + m.m_B))
