"""The reduced mass as students name it: ``μ`` (``\\mu``, or ``mu`` set equal to an expression,
``mu = m1 m2/(m1 + m2)``) in the kinetic energy lost in a direct impact, ``ΔK = ½ μ (1 - e²) u²``,
a formula students remember. It stands for m_A m_B/(m_A + m_B) where two bodies move (against a
fixed wall there is no second mass); a name the student declares otherwise keeps its declaration.
A one-word name set equal to masses alone (``mu = (m)(9m)/(10m) = 9m/10``) is the student's own
name, never m times u: a momentum is never a mass alone."""

from __future__ import annotations

import re
from collections.abc import Iterable

import sympy

from derive.checking.context import Context
from derive.mathtext.reader import Relation
from derive.problem.units import MASS

#: The reduced mass's letter typed as a Greek letter (``\\mu``, ``μ``).
_TYPED = re.compile(r"\\mu(?![A-Za-z])|μ")


#: ``mu`` in letters as m times u: squared (``mu^2``, ``½ mu²``) or after a number (``2mu``).
_M_TIMES_U = re.compile(r"(?<![\\A-Za-z])mu\s*(?:\^|²)|\d\s*mu(?![A-Za-z])")
#: A mass's name (``m``, ``M``, ``m1``, ``m_2``, ``m_A``, ``mB``): what the other sides of ``mu = …`` hold.
_MASS = re.compile(r"[mM](?:_\{?[0-9A-Za-z]{1,2}\}?|[0-9ABPQ])?")


def reduced_mass(ctx: Context, relations: tuple[Relation, ...]) -> dict[str, sympy.Expr]:
    """``{"mu": m_A m_B/(m_A + m_B)}`` where the derivation names the reduced mass ``mu`` (typed as
    a Greek letter, or set equal to masses alone: ``mu = (m)(9m)/(10m)``, not m times u); else nothing."""
    model = ctx.model
    if ctx.problem.fixed_B or model.m_B is None:
        return {}
    if not any(_TYPED.search(r.written) or _defined(r) for r in relations):
        return {}
    if any(_M_TIMES_U.search(r.written) for r in relations):
        return {}  # "½ mu^2", "2mu": m times u in letters, which μ would hide
    return {"mu": model.m_A * model.m_B / (model.m_A + model.m_B)}


def _defined(r: Relation) -> bool:
    """Whether ``r`` is ``mu = …`` with masses and numbers only on its other sides, one a quotient
    (``mu = m1 m2/(m1 + m2)``; ``mu = 2ma + mb`` and ``mu = 12`` are momenta, m times u)."""
    sides = [s.strip() for s in r.sides]
    masses = all(not re.search(r"[A-Za-z]", _MASS.sub("", s)) for s in sides[1:])
    return sides[0] == "mu" and masses and any("/" in s for s in sides[1:])  # a quotient: "mu = 2ma + mb" is m u


def is_reduced_mass(e: object) -> bool:
    """Whether ``e`` is m_A m_B/(m_A + m_B), for the report's words."""
    if not isinstance(e, sympy.Expr) or {s.name for s in e.free_symbols} != {"m_A", "m_B"}:
        return False
    a, b = sorted(e.free_symbols, key=lambda s: s.name)
    return sympy.simplify(e - a * b / (a + b)) == 0


_MASS_LETTER = re.compile(r"[mM](?:_?[AB12])?")


def mass_named(ctx: Context, relations: Iterable[Relation]) -> set[str]:
    """The one-word left sides of ``relations`` whose other sides hold masses and numbers only."""
    masses = {g.name for g in ctx.problem.givens if g.dim == MASS}
    out = set()
    for r in relations:
        left = r.sides[0].strip()
        if not re.fullmatch(r"[A-Za-z]\w*", left) or len(r.sides) < 2:
            continue
        names = re.findall(r"[A-Za-z]\w*", " ".join(r.sides[1:]))
        if names and all(n in masses or _MASS_LETTER.fullmatch(n) for n in names):
            out.add(left)
    return out
