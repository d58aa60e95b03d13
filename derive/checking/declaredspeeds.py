"""A bare name the student declares a speed keeps that meaning on the lines after it.

In an oblique impact the habit reads a bare ``v_A`` (``vB``, ``v_1'``) as the body's n component
after the impact, which is what it is in ``m u_A + m u_B = m v_A + m v_B``. A line that sets the name
equal to the magnitude of two components (``v_A = sqrt(3^2 + 3.46^2) = 4.58``) declares it the body's
speed, and a declaration the student wrote wins over the habit: on every later line whose other names
are not components (``½ m (v_A^2 + v_B^2)``, ``KE_A = ½ m v_A^2``, ``sin β = 2/v_A``) the name is the
speed. A later line that holds a name of a component (``v_An``, ``u_{Bt}``, derive's ``v_A2n``) beside it,
or that adds it to the first power to another bare name the habit reads as a component (a momentum
checked again, ``20 v_A + 5 v_B = 19.8``), keeps the habit's reading there: the student works in
components on that line.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import TYPE_CHECKING, Any

import sympy

from derive.checking.naming import PREFIX
from derive.mathtext.notation import student

if TYPE_CHECKING:
    from derive.checking.context import Context

#: :class:`~.inference.Read` (not imported: inference imports this module).
Read = Any

#: A side that is the magnitude of a vector from its components: ``sqrt(0.3^2 + 0.173^2)``.
MAGNITUDE = re.compile(r"^\s*sqrt\s*\((?=[^=]*\^\s*\(?2)(?=(?:[^=]*?\^\s*\(?2){2}).*\)\s*$")
#: A velocity's name with a body and no component: ``v_A``, ``vB'``, ``V_{1}``, ``u2``.
_BARE = re.compile(r"[uvwUVW]_?\{?[ABPQ12]\}?(?:'|′|_?(?:f|final|after))*")


def _components(ctx: Context) -> set[sympy.Symbol]:
    nm = ctx.model.nm
    out = set()
    for b in "AB":
        for k in ("1n", "1t", "2n", "2t"):
            s = getattr(nm, f"{b}{k}", None)
            if isinstance(s, sympy.Symbol):
                out.add(s)
    return out


def _declared_body(ctx: Context, r: Read, mapping: dict) -> tuple[sympy.Symbol, str] | None:
    """(the placeholder, its body) where ``r`` sets a bare name read as an n component after equal to a
    magnitude of two components."""
    if not r.exprs or len(r.sides) < 2 or not isinstance(r.exprs[0], sympy.Symbol):
        return None
    p = r.exprs[0]
    if not p.name.startswith(PREFIX) or not _BARE.fullmatch(p.name[1:]) or not MAGNITUDE.match(student(r.sides[1])):
        return None
    nm, meant = ctx.model.nm, mapping.get(p)
    for b in "AB":
        n = getattr(nm, f"{b}2n", None)
        if n is not None and meant in (n, -n, sympy.Abs(n)):
            return p, b
    return None


def kept_speeds(ctx: Context, raw: list[Read], mapping: dict, speeds: dict[str, sympy.Expr]) -> list[Read]:
    """``raw`` with a bare name declared a speed read as that speed on the later lines without a component."""
    if not ctx.problem.oblique:
        return raw
    comps, declared, out = _components(ctx), {}, []
    for r in raw:
        r = _as_speeds(r, {p: speeds[f"speed_{b}"] for p, b in declared.items()}, mapping, comps)
        found = _declared_body(ctx, r, mapping) if r.exprs is not None else None
        if found and f"speed_{found[1]}" in speeds:
            declared[found[0]] = found[1]
        out.append(r)
    return out


def speeds_before(ctx: Context, raw: list[Read], meanings: dict, speeds: dict[str, sympy.Expr]) -> list[Read]:
    """``raw`` with a bare name of a velocity before set equal to a letter alone (``with v1 = U``: A moves
    at speed U) read as that body's speed before, on its line and the later lines without a component:
    the letter is then the speed, not the n component the habit reads the bare name as."""
    if not ctx.problem.oblique:
        return raw
    comps, nm = _components(ctx), ctx.model.nm
    meant = {sympy.Symbol(PREFIX + k): v for k, v in meanings.items()}
    declared: dict[sympy.Symbol, sympy.Expr] = {}
    out = []
    for r in raw:
        exprs = r.exprs or ()
        p = exprs[0] if len(exprs) == 2 and all(isinstance(e, sympy.Symbol) for e in exprs) else None
        q = exprs[1] if p is not None else None
        if p is not None and p.name.startswith(PREFIX) and _BARE.fullmatch(p.name[1:]) and q.name.startswith(PREFIX):
            for b in "AB":
                n = getattr(nm, f"{b}1n", None)
                if n is not None and meant.get(p) in (n, -n) and q not in meant and f"speed_{b}1" in speeds:
                    declared[p] = speeds[f"speed_{b}1"]
        out.append(_as_speeds(r, declared, meant, comps))
    return out


def _as_speeds(r: Read, declared: dict, mapping: dict, comps: set[sympy.Symbol]) -> Read:
    """``r`` with the names ``declared`` speeds put in as those speeds, where it does not work in components:
    no name of a component beside them, no two velocity names added to the first power."""
    if r.exprs is None or not declared:
        return r
    held = set().union(*(e.free_symbols for e in r.exprs))
    component = any(
        (q in comps) or (q.name.startswith(PREFIX) and not _BARE.fullmatch(q.name[1:]) and _in(mapping, q, comps))
        for q in held - set(declared)
    )
    velocities = [q for q in held if q.name.startswith(PREFIX) and _in(mapping, q, comps)]
    swap = {p: x for p, x in declared.items() if p in held}
    summed = sum(_linear(r.exprs, q) for q in velocities) >= 2
    if swap and not component and not summed:
        return replace(r, exprs=tuple(e.xreplace(swap) for e in r.exprs))
    return r


def _in(mapping: dict, q: sympy.Symbol, comps: set[sympy.Symbol]) -> bool:
    """Whether the student's ``q`` is read as a component, either way (an energy of them is not one)."""
    meant = mapping.get(q)
    return isinstance(meant, sympy.Expr) and (meant in comps or -meant in comps)


def _linear(exprs: tuple[sympy.Expr, ...], p: sympy.Symbol) -> bool:
    """Whether ``p`` stands to the first power in a side (``20 v_A + 5 v_B``, not ``½ m v_A²``)."""
    return any(e.has(p) and not (d := sympy.diff(e, p)).has(p) and d != 0 for e in exprs)
