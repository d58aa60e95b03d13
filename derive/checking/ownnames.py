"""Names of the student's own that a first reading gets wrong (:mod:`.inference` reads with them).

An angle name the habits give a given (θ for θ_A1) that the student works out to another value
is the student's own angle; a name met first in a relation and set equal, alone, to an expression
in known names later (``φ = 90° − θ``) stands for it on every line; where the text writes u for
what comes before, a name in v (``v_P``, ``v1``) is not a velocity before the impact; a value
with a direction opposite to the one the student takes as positive (``right positive``, then
``v_A = 1.04 m/s to the left``) is negative; a habit's name for a quantity another name already
stands for, defined alone by a relation false in that reading (``u_1 = v_1 - v_cm`` beside ``v_1``),
is the student's own quantity, worth its defining line.
"""

from __future__ import annotations

import itertools
import re
from dataclasses import replace
from typing import Any

import sympy

from derive.checking.cmframe import relative_to_centre
from derive.checking.context import DEG, Context
from derive.checking.lonenames import lone_name
from derive.checking.naming import GREEK, PREFIX, placeholders
from derive.checking.numeric import number_of
from derive.problem.units import ANGLE, VELOCITY


def own_angles(ctx: Context, raw: list, meanings: dict[str, sympy.Expr]) -> None:
    """``tan θ = 2√3/3.25 ⇒ θ = 46.8°``: a habitual angle name (θ for the given θ_A1) that the
    student works out to another value than the given's is the student's own angle, not the given."""
    numeric = {s: v for s, v in ((sympy.Symbol(n), v) for n, v in ((str(k), v) for k, v in ctx.numeric.items()))}
    for name, e in list(meanings.items()):
        if name not in GREEK or not isinstance(e, sympy.Symbol) or sympy.Symbol(e.name) not in numeric:
            continue
        p, value = sympy.Symbol(PREFIX + name), numeric[sympy.Symbol(e.name)]
        verdicts = [_holds_at(r.exprs, {p: value, DEG: sympy.pi / 180}) for r in raw if r.exprs and _alone(r.exprs, p)]
        if False in verdicts and True not in verdicts:
            del meanings[name]
    _given_angles(ctx, raw, meanings, numeric)
    _sums_in_degrees(raw, meanings)


#: derive's names of angles (an angle a student declares in words stands for one of them).
_ANGLE = re.compile(r"(?:alpha|beta|gamma|delta|theta|phi|psi)(?:_\w+)?")


def _sums_in_degrees(raw: list, meanings: dict[str, sympy.Expr]) -> None:
    """``theta = a - 30`` where ``a`` is declared an angle (``A now moves at angle a to the line of
    centres``) and ``theta`` is one (declared, derive's, or the statement's letter): a bare number
    added to angles is degrees, as the angles' are (``raw`` changed in place)."""
    angles = {
        sympy.Symbol(PREFIX + n)
        for n, e in meanings.items()
        if isinstance(e, sympy.Symbol) and _ANGLE.fullmatch(e.name)
    }
    for i, r in enumerate(raw):  # derive's own angles too (``theta``, the statement's letter; ``beta_A2``)
        known = {s for e in r.exprs or () for s in e.free_symbols if _ANGLE.fullmatch(s.name)}
        if r.exprs and angles:
            exprs = tuple(_in_degrees(e, angles | known) for e in r.exprs)
            raw[i] = replace(r, exprs=exprs) if exprs != r.exprs else r


def _in_degrees(e: sympy.Expr, angles: set[sympy.Symbol]) -> sympy.Expr:
    """``a - 30`` -> ``a - 30°`` where each term but the one number is an angle (either sign)."""
    if not isinstance(e, sympy.Add):
        return e
    numbers = [t for t in e.args if t.is_number]
    rest = [t for t in e.args if not t.is_number]
    if len(numbers) != 1 or not rest or not all(t in angles or -t in angles for t in rest):
        return e
    return e - numbers[0] + numbers[0] * DEG


def _given_angles(ctx: Context, raw: list, meanings: dict[str, sympy.Expr], numeric: dict) -> None:
    """``sin θ = r/2r = 1/2 ⇒ θ = 30°``: a Greek name of no meaning whose every relation alone in
    it holds at one given angle's value (and at no other's) is that given angle."""
    angles = [g.symbol for g in ctx.problem.givens if g.dim == ANGLE and sympy.Symbol(g.symbol.name) in numeric]
    names = {s.name[len(PREFIX) :] for r in raw if r.exprs for e in r.exprs for s in e.free_symbols}
    for name in sorted(n for n in names if n in GREEK and n not in meanings):
        p = sympy.Symbol(PREFIX + name)
        alone = [r.exprs for r in raw if r.exprs and _alone(r.exprs, p)]
        fits = [
            a
            for a in angles
            if alone
            and all(_holds_at(x, {p: numeric[sympy.Symbol(a.name)], DEG: sympy.pi / 180}) is True for x in alone)
        ]
        if len(fits) == 1:
            meanings[name] = fits[0]


def _alone(exprs: tuple[sympy.Expr, ...], p: sympy.Symbol) -> bool:
    """Whether ``p`` is the one name of a relation (degrees aside)."""
    found = set().union(*(e.free_symbols for e in exprs)) - {DEG}
    return found == {p}


def _holds_at(exprs: tuple[sympy.Expr, ...], values: dict) -> bool | None:
    nums = [number_of(e.xreplace(values)) for e in exprs]
    if any(x is None for x in nums):
        return None
    return all(abs(a - nums[0]) <= 0.01 * max(abs(a), abs(nums[0]), 1e-9) for a in nums[1:])


def spells_givens(name: str, right: sympy.Expr, given: frozenset[str], written: str) -> bool:
    """Whether a Greek letter's name typed in letters (``mu``, not ``\\mu`` or ``μ``, the
    reduced mass) set equal to an expression in names (not a number: ``mu = 0.4`` is a
    coefficient) is the product of the givens it spells, m × u where m and u are given
    (``mu = 9m v_A + m v_B``, a momentum right or wrong)."""
    return (
        len(name) >= 2
        and name.isalpha()
        and all(c in given for c in name)
        and bool(right.free_symbols - {DEG})
        and re.search(rf"(?<![\\A-Za-z]){name}(?![A-Za-z])", written) is not None
    )


def named_later(raw: list, mapping: dict[sympy.Symbol, sympy.Expr], given: dict | None = None) -> None:
    """``φ = 90° − θ`` after ``tan φ = e tan θ``: a name nothing else gave a meaning, set equal
    alone to an expression in known names, is the student's name for it on every line; one
    that spells given letters (``mu``) is their product (:func:`spells_givens`)."""
    for i, r in enumerate(raw):
        if r.exprs is None or len(r.exprs) != 2 or r.defines:
            continue
        left, right = r.exprs[0], r.exprs[1].xreplace(mapping)
        if given and left.is_Symbol and spells_givens(left.name[len(PREFIX) :], right, frozenset(given), r.written):
            mapping.setdefault(left, sympy.Mul(*(given[c] for c in left.name[len(PREFIX) :])))
            continue
        if (
            left.is_Symbol
            and left.name.startswith(PREFIX)
            and lone_name(r.sides[0])
            and left not in mapping
            and right.free_symbols - {DEG}
            and not placeholders(right)
        ):
            mapping[left] = right
            raw[i] = replace(r, defines=left.name[1:])


def velocities_before(ctx: Context) -> set[sympy.Expr]:
    """The velocities before the impact, and the velocity givens (u for v_A1 = u)."""
    nm = ctx.model.nm
    out = {c for c in (nm.A1n, nm.B1n, nm.A1t, nm.B1t) if c is not None}
    return out | {g.symbol for g in ctx.problem.givens if g.dim == VELOCITY}


def combos(group: list[sympy.Symbol], cands: list, raw: list, before: set[sympy.Expr]) -> list[tuple]:
    """What the names of ``group`` may stand for together: where the text writes u for what
    comes before (``mu = mv_P + 2mv_Q``), a name in v (``v_P``, ``v1``) is not a velocity before."""
    u_used = any(re.search(r"(?<![A-Za-z])u(?![A-Za-z])", s) for r in raw for s in r.sides)

    def allowed(p: sympy.Symbol) -> list:
        if u_used and re.match(r"[vV](?:_|\d|$)", p.name[1:]):
            return [c for c in cands if c[1] not in before and -c[1] not in before]
        return cands

    return list(itertools.product(*(allowed(p) for p in group)))


_DIRECTIONS = {"left": "right", "right": "left", "up": "down", "down": "up"}
#: An arrow after a value that points each way (``0.025 m/s $\leftarrow$``, ``0.6 ft/s ←``).
_ARROW = {
    # a left arrow before words that say no way (``3 m/s <- speed of B after``, ``← A's``) points at a note
    "left": r"(?:←|⟵|<-{1,2}(?![->])|\\(?:long)?leftarrow\b)(?!\s*(?!(?:to\s+the\s+)?(?:left|west|back)\w*)[A-Za-z])",
    # a right arrow with more working after it (``0.6 ft/s -> +ve so …``, ``-> v = …``) is "so", not
    # a way; one before words (``7 m/s → and …``, ``→ (to the right)``) is still the way
    "right": r"(?:→|⟶|(?<![<-])-{1,2}>|\\(?:long)?rightarrow\b)"
    r"(?!\s*(?:[-+−]\s*[\w(]|\d|[A-Za-z_]\w*\s*=|(?:so|hence|thus|therefore|positive|negative|[+-]?ve)\b))",
    "up": r"↑|\\uparrow\b",
    "down": r"↓|\\downarrow\b",
}
_WAY = r"(left|right|up|down)(?:wards?)?"
_POSITIVE = re.compile(
    rf"(?:taking|take|with)?\s*(?:the\s+)?(?:direction\s+)?(?:to\s+the\s+)?{_WAY}\s*(?:is|=|as|taken\s+as)?\s*"
    rf"(?:positive|\+\s?ve|\+)(?![\w])|positive\s*(?:is|=|:)?\s*(?:to\s+the\s+|to\s+|towards\s+the\s+)?{_WAY}",
    re.I,
)


def directed(relations: tuple, text: str) -> tuple:
    """The relations with a value written with a direction opposite to the positive one the
    text declares (``right as positive``; ``v_A = 1.04 m/s to the left``) made negative; their
    directions in words are then read (not taken as derive's, right along +n)."""
    m = _POSITIVE.search(text)
    if m is None:
        return relations
    opposite = _DIRECTIONS[(m.group(1) or m.group(2)).lower()]
    out: list[Any] = []
    for r in relations:
        last = r.sides[-1].strip()
        way = rf"\b(?:to(?:wards)?\s+the\s+|to\s+)?{opposite}(?:wards?)?\b|{_ARROW[opposite]}"
        if re.fullmatch(r"\d+\.?\d*", last) and re.search(
            rf"(?<![\d.]){re.escape(last)}\b[^=\d]*?(?:{way})", r.written, re.I
        ):
            r = replace(r, sides=(*r.sides[:-1], f"-{last}"))
        out.append(replace(r, direction=0) if getattr(r, "direction", 0) else r)
    return tuple(out)


def own_readings(
    ctx: Context, raw: list, meanings: dict[str, sympy.Expr], at: tuple[dict, dict], kept: set[str]
) -> None:
    """The habits' readings the student's own lines overrule: angles (:func:`own_angles`) and
    quantities defined anew (:func:`defined_anew`), velocities relative to the centre of mass
    (:mod:`.cmframe`); ``at``: the givens' sample point and the unknowns' values there;
    ``meanings`` changed in place."""
    pt, truth = at
    own_angles(ctx, raw, meanings)
    relative_to_centre(ctx, raw, meanings, (pt, truth), kept)  # u_A = 12 - 20/3 after v_cm = 20/3
    defined_anew(ctx, raw, meanings, truth, kept)


def defined_anew(ctx: Context, raw: list, meanings: dict[str, sympy.Expr], truth: dict, kept: set[str]) -> None:
    """``u_1 = v_1 - v_cm`` beside ``v_1`` for A's velocity before; ``u = m_1 v_1/(m_1 + m_2)``, the
    common velocity: a name the habits read as a quantity another name of the derivation already
    stands for, met first alone on the left of a relation in other names that is false under that
    reading, is a quantity of the student's own (a velocity relative to the centre of mass, the
    velocity at the greatest compression), worth what its defining line says, not that quantity
    written twice. ``kept``: names declared in words, never read anew (``meanings`` changed in place)."""
    seen: set[sympy.Symbol] = set()
    own: dict[sympy.Symbol, sympy.Expr] = {}  # names read anew -> their definitions in derive's names
    for r in raw:
        if not r.exprs or len(r.exprs) < 2:
            continue
        left, right = r.exprs[0], r.exprs[1]
        name = left.name[len(PREFIX) :] if left.is_Symbol and left.name.startswith(PREFIX) else ""
        if name in meanings and name not in kept and left not in seen and lone_name(r.sides[0]):
            held = meanings[name]
            if placeholders(right) and _held_elsewhere(raw, meanings, name, held):
                reading = {p: own.get(p, meanings.get(p.name[len(PREFIX) :], p)) for p in placeholders(right) | {left}}
                value = right.xreplace(reading)
                if (
                    not placeholders(value)
                    and _holds_at((ctx.num(held.xreplace(truth)), ctx.num(value.xreplace(truth))), {}) is False
                ):
                    del meanings[name]
                    own[left] = value
        for e in r.exprs:
            seen |= placeholders(e)


def _held_elsewhere(raw: list, meanings: dict[str, sympy.Expr], name: str, held: sympy.Expr) -> bool:
    """Whether a name of the derivation other than ``name`` stands for ``held`` (derive's own
    name written, or another name read as it)."""
    written = {s for r in raw if r.exprs for e in r.exprs for s in e.free_symbols}
    return any(
        s == held
        or (s.name.startswith(PREFIX) and s.name[len(PREFIX) :] != name and meanings.get(s.name[len(PREFIX) :]) == held)
        for s in written
    )
