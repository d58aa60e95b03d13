"""A velocity after the impact declared in words as minus a name: the name is the size of a
velocity that comes back.

"I take the direction towards the wall as positive, so the ball's velocity before the impact is
+4 m/s and after it is $-v$, where $v$ is the speed we want"; "B's velocity after = −w"; "let the
velocity after the collision be -x": the student's velocity after is −v in their own frame, so v is
minus that velocity (the rebound's speed where it comes back), whatever the habits make of the
letter v (the velocity itself). The body is the one the words name by its possessive, or the one
body at a wall.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

_MINUS = re.compile(
    r"(?:\b(?P<whose>\w+)['’]s\s+)?\bvelocity\b(?P<between>[^.;=]{0,60}?)\bafter(?:wards)?\b"
    r"(?:\s+(?:the\s+)?(?:impact|collision|bounce|rebound))?(?:\s+it)?\s*(?:is|=|be|will\s+be|becomes)\s*"
    r"-\s*(?P<name>[A-Za-z])(?![\w'(])"
    r"|\bafter(?:wards)?(?:\s+the\s+(?:impact|collision|bounce|rebound))?,?\s+(?:the\s+|its\s+)?(?:(?P<whose2>\w+)['’]s\s+)?"
    r"velocity\s+(?:is|=|becomes)\s*-\s*(?P<name2>[A-Za-z])(?![\w'(])",
    re.I,
)


def minus_names(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """{v: -v_A2} for each velocity after that ``line`` declares as minus a name."""
    plain = re.sub(r"\$|\\[()]|[{}]", " ", line).replace("−", "-")
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    for m in _MINUS.finditer(plain):
        body, name = _whose(m["whose"] or m["whose2"] or "", ctx), m["name"] or m["name2"]
        key = f"v_{body}2"
        if body and key in names and name not in {g.name for g in ctx.problem.givens}:
            out.setdefault(name, -names[key][0])
    return out


def _whose(word: str, ctx: Context) -> str:
    """The body a possessive names (its letter or label), else the one body at a wall."""
    labels = dict(zip(ctx.problem.labels, "AB", strict=True)) | {"A": "A", "B": "B"}
    if word in labels:
        return labels[word]
    return "A" if getattr(ctx.problem, "fixed_B", False) else ""
