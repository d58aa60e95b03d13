"""A lone ``m`` in a general formula, named by the number put in for it on the same line.

``KE lost = ½ m(u − V)² = ½(0.020)(300 − 1.493)² = 891`` and ``impulse on B: I = m v = 10(10.22)``:
where the two bodies' masses differ, ``m`` is no one mass, and the student says which by the
number written in its place in a side of numbers after it: the one body whose mass (or weight,
a weight taken as a mass) is that number. ``m`` is then that body's mass on that line only, so
that the line is judged (a formula worked wrongly is a slip, not a line derive cannot read).
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

#: A lone m (not m_A, not a unit after a number: 3 m/s).
_M = re.compile(r"(?<![\w.'])m(?![\w']|\s*/\s*s\b|\s*s\^)")
_NUMBER = re.compile(r"(?<![\w.^])(?<!\^\s)\d+(?:\.\d+)?")  # not a power: the 2 of 200^2
#: A side of numbers: digits and operators, and the functions a side may use.
_NUMBERS_ONLY = re.compile(r"(?:[\d\s.+\-*/^()×·]|sqrt|sin|cos|tan|°)+")


def masses_put_in(ctx: Context, sides: tuple[str, ...]) -> tuple[str, ...]:
    """``sides`` with a lone ``m`` written as the one body's mass whose number a side of numbers
    after it puts in its place (``m_B``); as they are where that is not one body's."""
    p = ctx.problem
    first = next((k for k, s in enumerate(sides) if _M.search(s)), None)
    if first is None or p.fixed_B:
        return sides
    values = {g.name: g.value for g in p.givens if g.value is not None and g.value.is_number}
    masses = {b: {values.get(f"m_{b}"), values.get(f"W_{b}")} - {None} for b in "AB"}
    if not masses["A"] or not masses["B"] or masses["A"] & masses["B"]:
        return sides  # equal masses: m is each one's (the habits')
    numbers = [n for s in sides[first + 1 :] if _NUMBERS_ONLY.fullmatch(s.strip()) for n in _NUMBER.findall(s)]
    bodies = {b for b in "AB" for n in numbers if any(_same(n, v) for v in masses[b])}
    if len(bodies) != 1:
        return sides
    name = f"m_{bodies.pop()}"
    return tuple(_M.sub(name, s) for s in sides)


def _same(written: str, value: sympy.Expr) -> bool:
    """Whether the number ``written`` is ``value`` to the figures it is written with."""
    places = len(written.partition(".")[2])
    return abs(float(written) - float(value)) <= 0.5 * 10.0**-places + 1e-12
