"""A line labelled in words and worked in numbers: a total of the momenta before the impact
(``p before = 150000 x 0.300 + 110000 x 0.120 = 58200``), a component before. The checker
reads such a line as arithmetic only (its first side is words or a name of the student's own),
but a teacher marks it against the total momentum the problem gives, and names the slip (B's
velocity with the wrong sign, the masses exchanged).

:func:`momentum_before` gives the relation "the total momentum before = that working" when the
line is labelled a momentum before and the working is the total with a common mistake in its
values before, so the trace judges it as the slip it is (and carries the lines worked from it).
"""

from __future__ import annotations

import re
from collections.abc import Callable

import sympy

from derive.checking import slipnames
from derive.checking.context import DEG, Context
from derive.checking.inference import Read
from derive.checking.relations import coefficients
from derive.checking.worlds import Pair, alike

#: A label that says the momentum, or p, before the impact (``p before``, ``p_i``, ``P_1``,
#: ``initial momentum``, ``total momentum``, ``Σp``, ``momentum before``).
_BEFORE = re.compile(
    r"(?i)\bmomentum\b|Σ\s*p\b|(?<![A-Za-z])p\s*(?:_?\{?\s*(?:i|1|0|init|initial|before|tot|total|sys|system)\s*\}?)?"
    r"(?:\s+(?:before|initially|total))?\s*[:=]?\s*$"
)
#: A label that says after the impact: the total after is another quantity.
_AFTER = re.compile(r"(?i)\b(?:after|final|afterwards)\b|(?<![A-Za-z])p\s*_?\{?\s*(?:f|2|final|after)\b|'")


def labelled(
    ctx: Context, line: Read, holds: Callable[[Pair], bool], wrong: frozenset[str] = frozenset()
) -> Pair | None:
    """A line of numbers labelled as a total momentum before or a component before, worked
    with a common mistake: the pair it stands for (:func:`momentum_before`,
    :func:`component_before`); None otherwise."""
    from derive.checking.energylabels import energy_labelled  # KE before: ½(2m)(4)² + ½(3m)(2)

    return (
        momentum_before(ctx, line, holds)
        or component_before(ctx, line, holds)
        or energy_labelled(ctx, line, holds, wrong, label_of)
    )


def of_trace(trace, line: Read) -> Pair | None:
    """:func:`labelled` for the derivation read so far (:class:`.lines.Trace`): against the
    problem's true values, the numbers it wrote wrong known."""
    from derive.checking.energylabels import under_heading

    holds, wrong = (lambda p: trace.holds([p], trace.truth)), frozenset(trace.wrong_values | trace.wrong_numbers)
    return labelled(trace.ctx, under_heading(line, getattr(trace, "typed", []), label_of), holds, wrong)


def _bare(label: str) -> str:
    """A label without the ``=``, ``:`` or ``&`` it ends with (the quantity's words)."""
    return re.sub(r"[\s=:&]+$", "", label) or "it"


def label_of(line: Read) -> str:
    r"""What the line writes just before its first side as read (the words or name the reader
    left out), from the last ``,`` ``;`` ``=`` ``&`` or ``$`` before it: of two relations on a
    line (``along XY $2\cos 60^\circ = 1$, perpendicular $2\sin 60^\circ = \sqrt3$``) each
    has its own."""
    first = line.sides[0].strip() if line.sides else ""
    at = line.written.find(first) if first else -1
    lead = re.match(r"[-+(]*(\d+(?:\.\d+)?)\s*\*?\s*(sin|cos|tan)?", first)
    if at < 0 and lead:  # written in LaTeX (``\text{along: } & 2\sin 60^\circ``): its number and function
        shape = re.escape(lead.group(1)) + (rf"\s*\\?{lead.group(2)}" if lead.group(2) else r"(?![\d.])")
        found = re.search(rf"(?<![\d.]){shape}", line.written)
        at = found.start() if found else -1
    name = re.match(r"[-+(]*([A-Za-z]\w*)\s*\*?\s*(sin|cos)\b", first)
    if at < 0 and name:  # ``$U\sin30° = \tfrac12 U$``: the letter it starts with, and its function
        shape = rf"(?<![A-Za-z\\]){re.escape(name.group(1))}\s*\*?\s*\\?{name.group(2)}"
        found = re.search(shape, line.written)
        at = found.start() if found else -1
    if at <= 0:
        return ""
    before = re.sub(r"\\(?:[,;:! ]|q?quad\b)", " ", line.written[:at])  # LaTeX's spaces (``XY: \; 2\sin 60``)
    piece = re.split(r"[,;=&$]", before.rstrip(" $&=:\t"))[-1].strip()
    if re.match(r"[-+−]?\s*\d", piece) and before.rstrip(" $&=\t").endswith(":"):
        return re.sub(r"^[-+−]?\s*[\d.]+\s*", "", piece)  # "n: 4sin30 = 2   t: 4cos30": t labels the next
    if re.match(r"[-+−]?\s*\d", piece):  # "= 2 along x and 4 sin 60 = …": the words the relation before ends in
        after = re.split(r"[:)]", piece)[-1].strip()  # "(4 m/s, 60 deg to the line of centres): ∥ = …": the label ∥
        parts = re.split(r"\b(?:and|while|whereas|but|then)\b", piece)
        piece = after if after != piece.strip() else parts[-1].strip() if len(parts) > 1 else ""
    return piece


def words_after(line: Read) -> str:
    """The words just after the line's relation, to the next ``,`` ``;`` ``=`` or "and" (``= 2 along
    x and …``: "along x"), "" where a number or nothing follows it."""
    last = line.sides[-1].strip() if line.sides else ""
    end = line.written.find(last, max(line.written.find(line.sides[0].strip()), 0)) if last else -1
    if end < 0:
        return ""
    tail = re.split(r"[,;=&$]|\band\b", line.written[end + len(last) :], maxsplit=1)[0].strip(" .")
    return tail if re.fullmatch(r"[A-Za-z][A-Za-z .']*", tail) else ""


def momentum_before(ctx: Context, line: Read, holds: Callable[[Pair], bool]) -> Pair | None:
    """The pair "total momentum before = the line's first working" where the line, a line of
    numbers labelled a momentum before, works that total with a mistake in the values before
    (``holds`` says whether a pair holds for the problem); None otherwise."""
    p = ctx.problem
    exprs = line.exprs or ()
    if getattr(p, "oblique", False) or len(exprs) < 2 or any(x.free_symbols for x in exprs):
        return None
    label = label_of(line)
    if not label or not _BEFORE.search(label) or _AFTER.search(label):
        return None
    if not re.search(r"[\d)]\s*[-+−]\s*[\d(]", line.sides[0]):  # a sum of the two bodies' momenta
        return None
    names = ctx.equation_names()
    if not all(k in names for k in ("m_A", "m_B", "v_A1", "v_B1")):
        return None
    total = names["m_A"][0] * names["v_A1"][0] + names["m_B"][0] * names["v_B1"][0]
    first = exprs[0]
    pair = Pair(f"{_bare(label)} = {line.sides[0]}", ctx.in_unknowns(total), first, 1e-3, (total, first))
    other = Pair(pair.text, -pair.left, first, 1e-3, (-total, first))  # B's direction taken positive
    if holds(pair) or holds(other):
        return None
    found = slipnames.before_impact(ctx, pair, holds) or slipnames.before_impact(ctx, other, holds)
    if not found:
        return None
    return pair if slipnames.before_impact(ctx, pair, holds) else other


#: The axis a label names: along the line of centres (n), or across it (t).
_ALONG = re.compile(
    r"(?i)\balong\b|\bparallel\b|line of (?:centres|centers|impact)|\bnormal\b|(?<![A-Za-z])[xn](?![A-Za-z])"
    r"|\bl\.?\s?o\.?\s?c\b|∥"  # ∥ alone: the word parallel
)
_ACROSS = re.compile(r"(?i)\bperp|⊥|\bacross\b|\btangent|plane of contact|(?<![A-Za-z])[yt](?![A-Za-z])")


#: A fixed body's surface, and the axes a label names by it: along it (t), into it (n).
_FIXED = r"(?:the\s+)?(?:wall|cushion|barrier|plane|floor|ground|surface)\b"
_ALONG_FIXED = re.compile(rf"(?i)\b(?:along|parallel\s+to)\s+{_FIXED}")
_INTO_FIXED = re.compile(rf"(?i)\b(?:into|towards?|normal\s+to|perp(?:\.|endicular)?\s*to|away\s+from|off)\s+{_FIXED}")


def _wall_axis(ctx: Context, label: str) -> str:
    """The axis a label names against a fixed body (``along wall``: t, ``into the wall``: n), ""
    where the problem has none or the label names it by no fixed surface."""
    if not getattr(ctx.problem, "fixed_B", False):
        return ""
    if _INTO_FIXED.search(label):
        return "n"
    return "t" if _ALONG_FIXED.search(label) else ""


def component_before(ctx: Context, line: Read, holds: Callable[[Pair], bool]) -> Pair | None:
    """The pair "a body's component before = the line's first working" where the line, a line
    of numbers labelled by its axis in words (``along: 2 sin 60° = 1.732``, ``perp: 2 cos 60° =
    1``), resolves a body's given speed with a common mistake (sin and cos swapped, the angle
    from the other axis); None otherwise."""
    exprs = line.exprs or ()
    if not getattr(ctx.problem, "oblique", False) or len(exprs) < 2:
        return None
    label = label_of(line)
    if not (_ALONG.search(label) or _ACROSS.search(label) or _wall_axis(ctx, label)):
        label = words_after(line) or label  # "4 sin 60 = 3.46 along y": the axis its value is said along
    if not label:
        return None
    across = _ACROSS.search(label) is not None  # "perp to l.o.c": across the line it names
    along = _ALONG.search(label) is not None and not across
    wall = _wall_axis(ctx, label)  # "along the wall": t; "into the wall": n
    if along == across and not wall:
        return None
    return resolved(ctx, line.sides, exprs, wall or ("n" if along else "t"), (_bare(label), holds))


def resolved(ctx: Context, sides, exprs, axis: str, said: tuple[str, Callable[[Pair], bool]]) -> Pair | None:
    """The pair "a body's component before on ``axis`` = the first side" where that side resolves
    one body's given speed (its number, or its letter, with sin or cos) and holds only with a
    mistake in the values before; None otherwise (``said``: the quantity's words, and whether a
    pair holds for the problem)."""
    label, holds = said
    givens = {g.symbol for g in ctx.problem.givens}
    if any(x.free_symbols - {DEG} - givens for x in exprs):
        return None  # numbers, and the problem's letters (``u sin 30 = u/2``, u A's speed)
    if not re.search(r"(?i)(?<![a-z])(?:sin|cos)(?![a-z])", sides[0]):  # sin30 too
        return None
    names = ctx.equation_names()
    spaced = re.sub(r"(?i)(sin|cos|tan)", r" \1 ", sides[0])  # "2sin60": 2 and 60
    written = {t for t in re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?![\w.])", spaced)}
    bodies = []
    for b in "AB":
        speed = names.get(f"v_{b}1")
        value = ctx.in_unknowns(speed[0]) if speed is not None else None
        known = value is not None and value != 0 and f"v_{b}1{axis}" in names
        if known and value.is_number and any(abs(float(t) - float(value)) < 1e-12 for t in written):
            bodies.append(b)
        elif known and isinstance(value, sympy.Symbol) and value in exprs[0].free_symbols:
            bodies.append(b)  # "A has u sin30 = u/2": A's speed u, a letter
    if len(bodies) != 1:
        return None
    sym = names[f"v_{bodies[0]}1{axis}"][0]
    first = ctx.in_unknowns(exprs[0])  # its degrees in
    pair = Pair(f"{label} = {sides[0]}", ctx.in_unknowns(sym), first, 1e-3, (sym, exprs[0]))
    flipped = Pair(pair.text, -pair.left, first, 1e-3, (-sym, exprs[0]))  # a size where derive's axis points back
    if holds(pair) or holds(flipped):
        return None
    return next((p for p in (pair, flipped) if slipnames.before_impact(ctx, p, holds)), None)


def notes_number(tag: str, F: sympy.Expr, equations: dict[int, sympy.Expr], unknowns: tuple, pt: dict) -> str:
    """A student's tag ``(2)`` as the notes' equation (2) only where the relation ``F = 0`` is in
    that equation's unknowns and more like it than like any other (at the sample point ``pt``): a
    student numbers their own equations, (1) the momentum and (2) the restitution, which in an
    oblique impact are the notes' (3) and (4) (their (1) and (2) are the t momenta), and steps
    (3), (4) in any order, so a tag that names an equation of other unknowns is their own ("")."""
    if tag not in ("1", "2", "3", "4") or int(tag) not in equations:
        return ""
    own = F.free_symbols & set(unknowns)
    if not own or not own <= equations[int(tag)].free_symbols:
        return ""
    cf = coefficients(F.xreplace(pt), unknowns)
    near = {j: alike(cf, c) for j, G in equations.items() if cf and (c := coefficients(G.xreplace(pt), unknowns))}
    return tag if not near or near.get(int(tag), 0.0) >= max(near.values()) - 1e-9 else ""
