""" "Forward" as the positive way, said in words: the way the bodies go before the impact.

"Momentum (forward +)", "Forward $= +$", "forwards = positive", "+ve forwards": a student
takes as positive the way the bodies were moving. That is a direction derive knows from the
problem, not from the student's values: derive's n where the moving bodies go along +n before
the impact (a body moving onto one at rest or onto a wall; two bodies moving the same way), its
reverse where they go along -n. Where the two move toward each other "forward" names no one way,
and the convention is left to be inferred from the values, as "right" and "left" are.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

#: "forward" said to be the positive way: "(forward +)", "Forward $= +$", "forwards (A's way) is
#: positive", "forward positive", "+ve forwards", "positive direction: forward".
_SAID = re.compile(
    r"\bforwards?\b(?:\s*\([^()]*\))?\s*(?:direction\s*)?(?:(?:is|as|taken\s+as|:)\s*)?"
    r"(?:\$?\s*=?\s*\+(?!\s*\d)\s*\$?(?:\s*ve\b)?|=?\s*positive\b)"
    r"|(?:\bpositive|\+\s?ve\b|(?<![\w)])\+(?!\s*\d))\s*(?:direction\s*)?(?:is|=|:|->|→)?\s*(?:the\s+)?forwards?\b",
    re.I,
)
_BACK = re.compile(r"\bback(?:wards?)?\s*(?:is\s+|=\s*|as\s+)?(?:\+|positive)", re.I)


def forward_said(line: str) -> bool:
    """Whether ``line`` takes "forward" as the positive way (and not backward too)."""
    return bool(_SAID.search(line)) and not _BACK.search(line)


def forward_sign(ctx: Context) -> int:
    """+1 where the bodies that move before the impact all go along derive's n, -1 where all go
    the other way, 0 where none moves, they move toward each other, or the problem is a chain."""
    if ctx.chain:
        return 0
    try:
        pre = ctx.model.pre
    except (AttributeError, ValueError, TypeError, KeyError):
        return 0
    signs = set()
    for body in ("A", "B"):
        x = next((pre[k] for k in pre if str(k) in (f"v_{body}1n", f"v_{body}1")), None)
        s = _sign(ctx, x) if x is not None else 0
        if s:
            signs.add(s)
    return signs.pop() if len(signs) == 1 else 0


def _sign(ctx: Context, x: sympy.Expr) -> int:
    """The sign of a velocity before in the givens, at the givens' values (a letter's at a sample)."""
    try:
        x = ctx.num(sympy.sympify(x))
        if x.free_symbols:
            x = x.xreplace(ctx.sampler().points(x.free_symbols, n=1)[0])
        x = sympy.N(x)
        return 0 if not x.is_real or abs(x) < 1e-12 else (1 if x > 0 else -1)
    except (TypeError, ValueError, IndexError, ArithmeticError):
        return 0
