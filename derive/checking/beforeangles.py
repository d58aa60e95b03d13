"""An angle a student declares in words for a velocity before the impact: "Let θ be the angle
between A's velocity and the line of centres". The rule a teacher follows: a name declared in
words is that quantity, and a line that works out its value must give that quantity's value; it
is never the student's own name, free to take the value they work out (``cos θ = r/2r ⇒ θ = 60°``
where A's path is r from B's centre: sin θ = r/2r, θ = 30°, the angle taken from the other axis).
The angle is the acute one between the velocity and the line the words name: tan = |t|/|n| from
the line of centres, |n|/|t| from the wall, tangent or plane of contact.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context
from derive.checking.statementbodies import at_rest_before


def before_angles(ctx: Context, found: list, given: set[str], read: tuple) -> tuple[dict[str, sympy.Expr], list]:
    """``found``: (name, body, line) of each angle declared in words, as typed, with no word that
    says after; ``read``: derive's body of a word, the Greek letters' names, and the line as typed.
    -> {name: the angle} of those of a body moving before the impact where the line says its
    velocity (as given: "A's path makes with the tangent" may be its path after, and is not read),
    and the rest of ``found`` (of bodies at rest before)."""
    body_of, letters, plain = read
    given_velocity = _VELOCITY.search(plain) is not None and _PATH.search(plain) is None
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    rest = []
    for name, word, line in found:
        body = body_of(word)
        if not body or at_rest_before(ctx, body):
            rest.append((name, word, line))
            continue
        name = letters.get(name.lstrip("\\"), name.lstrip("\\"))
        n, t = names.get(f"v_{body}1n"), names.get(f"v_{body}1t")
        if given_velocity and n is not None and t is not None and name not in given:
            n, t = sympy.Abs(n[0]), sympy.Abs(t[0])
            out.setdefault(name, sympy.atan(t / n) if line[:1] in "lL" else sympy.atan(n / t))
    return out, rest


#: A body's velocity named in a declaration (its given one), and words that may name its path after.
_VELOCITY = re.compile(r"['’]s\s+velocity\b|\bvelocity\s+of\b", re.I)
_PATH = re.compile(r"\b(?:path|direction|motion|moves?|leaves?|new|final)\b", re.I)


def described(x: sympy.Expr) -> str:
    """An angle :func:`before_angles` reads, in words ("" where ``x`` is none of them)."""
    if not isinstance(x, sympy.atan):
        return ""
    names = sorted(s.name for s in x.free_symbols)
    if len(names) != 2 or names[0][:-1] != names[1][:-1] or not names[0].startswith("v_"):
        return ""
    top = [f for f in sympy.Mul.make_args(x.args[0]) if not (isinstance(f, sympy.Pow) and f.exp.is_negative)]
    across = any(s.name.endswith("t") for f in top for s in f.free_symbols)  # tan = |t|/|n|: from the line
    return f"the angle between {names[0][2]}'s velocity before the impact and the {'line of centres' if across else 'tangent'}"
