"""The student's frame: which way along the line of centres is positive, for derive's own names too.

A student who takes the other way as positive ("left as positive", "away from the wall is +ve",
or no words at all) and writes derive's names (``(v_A)_1 = -3``, ``v_A2 = +1.6``) means derive's
components with the sign changed. :mod:`.inference` reads the relations both ways and keeps the
way the values written hold in; this module flips derive's n components for the other way, and
scores a reading: how many ``=`` hold of those that a reading can move (a name of the student's
own, or one of derive's n components).
"""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.checking.context import Context
from derive.checking.conventions import sign_of
from derive.checking.figures import literal_tolerance
from derive.checking.naming import PREFIX
from derive.checking.numeric import number_of
from derive.checking.towardwords import original_way
from derive.mathtext.unitframe import declares_frame


def n_components(ctx: Context) -> dict[sympy.Symbol, sympy.Expr]:
    """derive's components along n (before and after, A and B) -> the same in the reversed frame."""
    nm = ctx.model.nm
    out: dict[sympy.Symbol, sympy.Expr] = {}
    for c in (nm.A1n, nm.B1n, nm.A2n, nm.B2n):
        if isinstance(c, sympy.Symbol):
            out[c] = -c
    return out


def along_wall(ctx: Context, e: sympy.Expr) -> bool:
    """Whether ``e`` is the ball's component along a wall: the way out of the wall taken positive
    turns the normal round, not the wall's own direction."""
    nm = ctx.model.nm
    return e in {c for c in (nm.A1t, nm.A2t) if c is not None}


def uses_n_components(ctx: Context, raw: list) -> bool:
    """Whether a relation the student wrote has one of derive's n components in it."""
    ns = set(n_components(ctx))
    return any(ns & e.free_symbols for r in raw if r.exprs for e in r.exprs)


def flipped(ctx: Context, raw: list, sign: int) -> list:
    """The relations with derive's n components read in the student's frame (``sign`` -1: the
    reversed one, so ``v_A1 = -3`` is A's velocity before, 3 along derive's n)."""
    if sign == 1:
        return list(raw)
    flip = n_components(ctx)
    out = []
    for r in raw:
        if r.exprs is None or not any(flip.keys() & e.free_symbols for e in r.exprs):
            out.append(r)
            continue
        out.append(replace(r, exprs=tuple(e.xreplace(flip) for e in r.exprs)))
    return out


def reversal_said(ctx: Context, raw: list, pt: dict, truth: dict) -> bool:
    """Whether the values written put derive's own names in the reversed frame: a line writes a
    velocity BEFORE (a given) with the reversed sign (``v_A1 = -12`` where A moves at 12 along
    derive's n), and none writes one with derive's sign. The answers alone never choose the frame
    (``v_A2 = -4``, ``v_B2 = -8`` is two sign slips, not a frame)."""
    before = [c for c in (ctx.model.nm.A1n, ctx.model.nm.B1n) if isinstance(c, sympy.Symbol)]
    votes = set()
    for r in raw:
        for c in before:
            if r.exprs is None or c not in r.exprs:
                continue
            true = number_of(ctx.in_unknowns(c).xreplace(pt).xreplace(truth))
            for e in r.exprs:
                value = number_of(e) if not e.free_symbols else None
                if value is None or true is None or abs(true) < 1e-9:
                    continue
                if abs(value - true) <= 1e-3 * abs(true):
                    votes.add(1)
                elif abs(value + true) <= 1e-3 * abs(true):
                    votes.add(-1)
    return votes == {-1}


Pair = tuple[float, tuple[sympy.Expr, sympy.Expr], bool]


def pairs(ctx: Context, raw: list, pt: dict, truth: dict) -> list[list[Pair]]:
    """For each relation, each ``=`` as (tolerance, (left, right) with the true values in,
    whether a reading moves it: a student's name or derive's n component in it)."""
    ns = set(n_components(ctx))
    out = []
    for r in raw:
        if r.exprs is None or r.defines or r.direction:  # a direction in words is derive's: no sign to infer
            out.append([])
            continue
        diffs = []
        for i in range(len(r.exprs) - 1):
            tol = max(literal_tolerance(f"{r.sides[i]} = {r.sides[i + 1]}", ctx.data), 1e-9)
            pair = r.exprs[i : i + 2]
            moved = any(s.name.startswith(PREFIX) or s in ns for x in pair for s in x.free_symbols)
            left, right = (ctx.in_unknowns(x).xreplace(pt).xreplace(truth) for x in pair)
            diffs.append((tol, (left, right), moved))
        out.append(diffs)
    return out


def score(found: list[list[Pair]], mapping: dict, ctx: Context, pt: dict, truth: dict) -> int:
    """How many ``=`` hold (of those a reading moves) under ``mapping``."""
    subs = {k: ctx.in_unknowns(v).xreplace(pt).xreplace(truth) for k, v in mapping.items()}
    n = 0
    for line in found:
        for tol, (left, right), moved in line:
            if not moved:
                continue
            a, b = number_of(left.xreplace(subs)), number_of(right.xreplace(subs))
            if a is not None and b is not None and abs(a - b) <= 2 * tol * max(abs(a), abs(b)) + 1e-12:
                n += 1
    return n


#: A unit vector or an axis as students name it in words (``\mathbf{i}``, ``î``, ``the x-axis``),
#: by the axis the vector reader gives it (:data:`~derive.mathtext.vectors.UNITS`): n or t.
#: Only a letter the clause names as an axis: ``x-axis``, a unit vector ``i`` (not a part ``(i)``),
#: ``x along …``, ``take x …``; never a lone ``x`` for "times" (``1 x 19.8``).
_UNIT_WORD = re.compile(
    r"(?<![\w\\(])([ijxyXY])[-\s]?(?:axis|direction)\b"
    r"|(?<![\w\\(])([ij])(?![\w()])"  # not "I take", not "(i)"
    r"|(?<![\w\\(])([xyXY])(?=\s+(?:along|parallel|perpendicular|normal|at\s+right|is|points?|pointing|positive"
    r"|taken|away|out|into|towards?|to|as)\b)"
    r"|\b(?:[Tt]ake|[Tt]aking|[Ll]et|[Ww]ith|[Cc]hoos(?:e|ing))\s+([xyXY])\b",
)
_STYLED = re.compile(r"\\(?:mathbf|hat|vec|boldsymbol|underline|bm|textbf|mathit)\s*\{?\s*\\?([a-z])(?:math)?\s*\}?")
_WALL = r"(?:the\s+)?(?:wall|cushion|barrier|plane|floor|ground|surface|table\s+edge|side)"
_LINE = r"(?:the\s+)?(?:l\.?\s?o\.?\s?c\.?|line\s+of\s+(?:centres|centers|impact)|common\s+normal|normal)"
#: Words that place an axis: (pattern, derive's axis, sign).
_PLACES = (
    (rf"(?:along|parallel\s+to)\s+{_WALL}|{_WALL}\s+(?:is\s+)?(?:along|parallel\s+to)", "t", 1),
    (rf"(?:away\s+from|out\s+of|out\s+from)\s+{_WALL}", "n", -1),
    (rf"(?:perpendicular|normal|at\s+right\s+angles)\s+to\s+{_WALL}", "n", 0),  # before "to the wall"
    (rf"(?:into|towards?|to)\s+{_WALL}", "n", 1),
    (rf"(?:along|parallel\s+to)\s+{_LINE}(?:\s+from\s+B\s+to(?:wards)?\s+A\b)", "n", -1),
    (rf"(?:along|parallel\s+to)\s+{_LINE}", "n", 1),
    (rf"(?:perpendicular|at\s+right\s+angles)\s+to\s+{_LINE}|along\s+the\s+(?:common\s+)?tangent", "t", 0),
)


def declared_axes(text: str) -> dict[str, tuple[str, int]]:
    """The axes a student places in words (``wall along i, j pointing away from the wall``): the
    vector reader's axis of each unit vector (i, x: n; j, y: t) -> derive's axis and its sign
    (0 where the words give none). Empty where no axis is placed, or where it is derive's own."""
    if declares_frame(text):  # "n̂ = cos 20° i + sin 20° j": i and j are the student's x and y
        return {}
    plain = (
        _STYLED.sub(r"\1", text)
        .replace("$", " ")
        .replace("î", "i")
        .replace("ĵ", "j")
        .replace("ŷ", "y")
        .replace("\u0302", "")
    )  # x̂: a hat typed as a combining accent
    found: dict[str, tuple[str, int]] = {}
    last = ""  # the unit a clause without one goes on placing ("j perpendicular to it, away from …")
    wall = re.search(rf"\b{_WALL}", plain, re.I) and not re.search(rf"\b{_LINE}(?![a-z])", plain, re.I)  # "j … it"
    for clause in re.split(r"[.;,\n]|\band\b", plain):
        clause = re.sub(r"\bit\b", "the wall", clause) if wall else clause
        units = {"n" if m.group(m.lastindex).lower() in "ix" else "t" for m in _UNIT_WORD.finditer(clause)}
        last = units.pop() if len(units) == 1 else "" if units else last
        place = next(((a, sg) for pattern, a, sg in _PLACES if re.search(pattern, clause, re.I)), None)
        if last and place and (last not in found or (found[last][0] == place[0] and not found[last][1])):
            found[last] = place
    if len(found) == 1:  # the other axis is the other one, its sign as derive's
        ((mine, (axis, _sign)),) = found.items()
        found[{"n": "t", "t": "n"}[mine]] = ({"n": "t", "t": "n"}[axis], 1)
    if len(found) != 2 or found["n"][0] == found["t"][0]:
        return {}
    out = {k: (a, s or 1) for k, (a, s) in found.items()}
    return {} if out == {"n": ("n", 1), "t": ("t", 1)} else out


def axes_said(axes: dict[str, tuple[str, int]]) -> list[str]:
    """What the report says of the axes placed in words."""
    if not axes:
        return []
    way = {("n", 1): "n", ("n", -1): "-n", ("t", 1): "t", ("t", -1): "-t"}
    said = f"i (or x) is derive's {way[axes['n']]}, j (or y) is derive's {way[axes['t']]}"
    return [f"Read your axes from your words: {said} (n: the line of impact, from A toward B or into the wall)."]


def axis_names(ctx: Context, axes: dict[str, tuple[str, int]], used: set[str]) -> dict[str, sympy.Expr]:
    """With the axes placed in words, ``u_x``, ``v_y``, ``u_Ax`` (u before, v after; x and y the
    student's axes) are derive's components on them, with their signs (``y`` away from a wall:
    ``u_y`` is -n before); ``v_x`` beside ``v_x'`` is before, the primed one after. Only the names
    ``used`` are given."""
    if not axes or not ctx.problem.oblique:
        return {}
    nm = ctx.model.nm
    out: dict[str, sympy.Expr] = {}
    bodies = ("A",) if ctx.problem.fixed_B else ("A", "B")
    for base, time in (("u", "1"), ("v", "2")):
        for letter, mine in (("x", "n"), ("y", "t")):
            axis, sign = axes[mine]
            for body in bodies:
                c = getattr(nm, f"{body}{time}{axis}", None)
                if c is None:
                    continue
                spelled = {f"{base}_{body}{letter}", f"{base}{body}{letter}", f"{base}_{body}_{letter}"}
                if len(bodies) == 1:
                    spelled |= {f"{base}_{letter}", f"{base}{letter}"}
                out.update({n: sign * c for n in spelled & used})
                before = getattr(nm, f"{body}1{axis}", None)
                for n in spelled & {u[:-2] for u in used if u.endswith("_p")} if before is not None else ():
                    out[n], out[f"{n}_p"] = sign * before, sign * c  # vx beside vx': before, and after
    return out


#: The way a line says its values are measured in (``v_A = -2eu in its original direction``, after
#: working with B's direction positive): a body's original direction (its own, A's, B's; P and Q
#: the exam's letters for A and B); a teacher reads the line's values with that way positive.
_ORIGINAL = re.compile(
    r"\bin\s+(?:(its|[ABPQ](?=['’]s))(?:['’]s)?\s+(?:original|initial|first)\s+direction"
    r"|the\s+(?:original|initial)\s+direction\s+of\s+(?:motion\s+of\s+)?([ABPQ])\b"
    r"|the\s+direction\s+of\s+([ABPQ])['’]s\s+(?:original|initial)\s+motion)",
    re.I,
)
_BODY = {"A": 1, "P": 1, "B": -1, "Q": -1}
#: A sign convention in brackets in a quantity's name (``velocity after (towards the wall as
#: positive) = -1.2``): the line's values are measured with that way positive.
_NAMED_CONVENTION = re.compile(r"\(\s*([^()=]*(?:\+\s?ve\b|\bpositive\b)[^()=]*)\)", re.I)


def _said(ctx: Context, r) -> int:
    """+1 where the line says derive's n is positive (A's original direction, or B's where B moved
    the same way, catching up or caught), -1 the reversed way (B's, toward A), 0 where it says
    none (or "its" with no body named before it, or the body was at rest)."""
    if r.exprs is None:
        return 0
    named = _NAMED_CONVENTION.search(r.written.split("=")[0])
    if named is not None and sign_of(named[1]):  # "velocity after (towards the wall as positive) = -1.2"
        return sign_of(named[1])
    m = _ORIGINAL.search(r.written)
    if m is None:
        return 0
    letter = m.group(1) or m.group(2) or m.group(3)
    if letter.lower() == "its":  # the body the relation is of: "v_A = v_B - 4eu = … in its …" (A's)
        letters = re.findall(r"(?<![A-Za-z])([ABPQ])(?![A-Za-z])", r.written[: m.start()])
        letter = letters[0] if letters else ""
    body = _BODY.get(letter.upper(), 0)
    return body and original_way(ctx, body)


def in_said_way(ctx: Context, lines: list, frame: int) -> list:
    """``lines`` (each a :class:`~.inference.Read`, in derive's symbols, read in the student's
    ``frame``) with a line whose words name the other way positive read in that way: derive's n
    components turned round on it."""
    flip = n_components(ctx)
    out = []
    for r in lines:
        said = _said(ctx, r)
        if said and said != frame and r.exprs is not None:
            r = replace(r, exprs=tuple(sympy.sympify(e).xreplace(flip) for e in r.exprs))
        out.append(r)
    return out
