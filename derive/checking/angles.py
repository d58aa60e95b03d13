"""A direction line judged as the angle it says it is, not by its arithmetic alone.

``tan⁻¹(6.4/1.732) = 74.9° to XY`` is right as a calculation, and wrong as the angle B's
velocity makes with XY (15.1°): the words after the angle (``to XY``, ``from i``, ``with the
line of centres``, ``below the horizontal``) name the quantity, and the line is right when it
is that quantity for this problem. An angle *to* or *with* a line is the acute angle between
the velocity and the line; an angle *from* an axis (``from i``, ``from n``, ``from the x
axis``) is a direction, measured from that axis (either way round: the student's own
perpendicular), so that a direction in the wrong quadrant is not the same direction.

A wrong angle is named where the evidence is there: the angle with the other axis
(``angle_other_axis``: the complement), or tan⁻¹ of the ratio taken at face value where the
axis component is negative (``angle_quadrant``: 180° away, the components in the line show it).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace
from decimal import Decimal
from typing import TYPE_CHECKING, Protocol

import sympy

from derive.checking.context import DEG
from derive.checking.mistakes import REGISTRY, phrase
from derive.checking.numeric import decimals, number_of
from derive.checking.report import Diagnosis

if TYPE_CHECKING:
    from derive.checking.context import Context
    from derive.checking.inference import Read
    from derive.checking.relations import Point, Values
    from derive.checking.report import Item


class Trace(Protocol):
    """What of :class:`~.lines.Trace` (the derivation read so far) an angle's verdict uses."""

    ctx: Context
    pts: list[Point]
    truth: list[Values]
    world: list[Values] | None
    slips: list[int]
    named: dict[int, set[str]]
    wrong_values: set[str]

    def holds(self, pairs: list, values: list[Values]) -> bool: ...
    def pairs(self, line: Read) -> list: ...
    def _answer(self, line: Read) -> Item | None: ...
    def _carried(self, line: Read) -> Item: ...
    def _slips_named(self) -> str: ...
    def _item(self, line: Read, status: str, message: str, method: str, **kw: object) -> Item: ...


#: The method a line's verdict names (as :mod:`.lines` does).
TRUE = "substituting the correct values"
_INVERSE = (sympy.atan, sympy.asin, sympy.acos, sympy.atan2)
_TRIG = (sympy.sin, sympy.cos, sympy.tan)
#: The last side of a direction line: the angle, a degree mark, and the words that name it.
CLAIM = re.compile(r"^\s*([-+]?)\(?(\d+(?:\.\d*)?|\.\d+)\)?\s*(?:°|\*?deg\b|degrees?\b)\s*([A-Za-z+].*)?$")
#: The components in ``tan⁻¹(Y/X)`` as written (plain syntax), signs kept.
RATIO = re.compile(
    r"(?:atan|arctan|tan\^-1|tan⁻¹|tan\^\(-1\))\s*\(+\s*([-+]?\d+\.?\d*)\s*\)*\s*/\s*\(*\s*([-+]?\d+\.?\d*)\s*\)"
)
_PREP = r"(?:(?:is|was|at|measured|relative|anticlockwise|clockwise|counter-?clockwise)\s+)*"
_AXES = {
    "n": r"xy|ab|n|\+n|i|\+i|(?:the\s+)?(?:common\s+)?normal|(?:the\s+)?line\s+of\s+(?:cent(?:re|er)s|impact)",
    "t": r"j|t|\+t|\+j|(?:the\s+)?(?:common\s+)?tangent|(?:the\s+)?plane\s+of\s+contact|(?:the\s+)?wall|(?:the\s+)?cushion",
    "x": r"x|ox|\+x|(?:the\s+)?(?:positive\s+)?x[- ]?axis|(?:the\s+)?horizontal",
    "y": r"y|oy|\+y|(?:the\s+)?(?:positive\s+)?y[- ]?axis|(?:the\s+)?vertical",
}
#: A one-letter axis (or an axis named as such): "from" it is a direction, not a line's angle.
_DIRECTED = re.compile(r"^(?:\+?[a-z]|(?:the\s+)?(?:positive\s+)?[xy][- ]?axis)$")


@dataclass(frozen=True)
class Claim:
    """An angle as written (degrees), the axis it is measured from, and how."""

    value: float
    unit: float  # one in the last figure written
    axis: str  # "n", "t", "x" or "y"
    directed: bool  # from the axis (a direction), not with the line (an acute angle)
    ratio: tuple[float, float] | None  # (Y, X) of tan⁻¹(Y/X) as written
    room: float = 0.005  # relative room for the student's own components rounded to three figures


def claim(line: Read, before: str = "") -> Claim | None:
    """The angle ``line`` says it is, where words name what it is measured from: after the
    angle (``= 74.9° to XY``), else before the relation on its line (``the angle with XY is
    θ = …``), else ending the prose line ``before`` it (``… the angle its path makes with the
    line of centres is``)."""
    if len(line.sides) < 2:
        return None
    m = CLAIM.match(line.sides[-1].replace("−", "-").replace("\\circ", "°").replace("^°", "°"))
    if not m:
        return None
    after = (m.group(3) or "").strip() or _after(line.written, m.group(2))
    named = _reference(re.sub(r"[.,;:!)]+$", "", after.lower()), after=True) if after else None
    if named is None and not after:
        lead = _own_lead(line.written, m.group(2))
        named = _reference(_words(lead), after=False) or (_reference(_words(before), after=False) if before else None)
    if named is None:
        return None
    prep, ref, axis = named
    number = Decimal(m.group(2))
    value = float(number) * (-1 if m.group(1) == "-" else 1)
    unit = float(Decimal(1).scaleb(number.as_tuple().exponent))
    r = RATIO.search(" ".join(line.sides[:-1]).replace(" ", ""))
    ratio = (float(r.group(1)), float(r.group(2))) if r else None
    letter = re.fullmatch(r"\+?[a-z]", ref) is not None  # "to i", "from n": a direction from a vector
    directed = (prep == "from" and bool(_DIRECTED.match(ref))) or (prep == "to" and letter)
    return Claim(value, unit, axis, directed, ratio)


def _own_lead(written: str, number: str) -> str:
    """The words before the relation whose value is ``number`` on a line of several (``angle from n =
    … = 57.17° -> from x: 57.17 + 20 = 77.17°``: the second's are "from x: 57.17 + 20", not the first's)."""
    for part in re.split(r"->|→|⇒|=>|\\Rightarrow|\\implies|;", written):
        if re.search(rf"=\s*-?\s*{re.escape(number)}(?!\.?\d)", part):
            return part.split("=")[0]
    return written.split("=")[0]


def _after(written: str, number: str) -> str:
    """The words after the angle ``number``° on the line as typed (``$… = 74.9^\\circ$ to XY``),
    up to the end of its clause: where the reader has dropped them from the relation's side."""
    text = re.sub(r"\\(?:text|mathrm|textrm)\s*\{([^}]*)\}", r" \1 ", written)
    text = re.sub(r"\^\s*\{?\s*\\circ\s*\}?|\\degree\b", "°", text)
    text = re.sub(r"\\[,;:! ]|\\q?quad\b|\$|\\[()\[\]]|&", " ", text)
    found = re.search(rf"(?<![\d.]){re.escape(number)}\s*(?:°|deg(?:rees?)?\b)\s*([A-Za-z+][^,;=]*)", text)
    return found.group(1).strip() if found else ""


def _words(text: str) -> str:
    """Prose as plain lower-case words (TeX markup, dollars and punctuation dropped)."""
    text = re.sub(r"\\(?:text|textbf|emph|mathrm)\{([^}]*)\}", r" \1 ", text)
    text = re.sub(r"\\[A-Za-z]+|[$*_{}\\&]", " ", text)
    return " ".join(re.sub(r"[.,;:!()]", " ", text).lower().split())


def _reference(words: str, after: bool) -> tuple[str, str, str] | None:
    """(preposition, reference, axis) of ``to XY`` (the words after an angle: all of them), or
    of ``the angle … makes with the line of centres is`` (words before one: their end)."""
    if after:
        found = re.fullmatch(rf"{_PREP}(to|with|from|above|below|makes?\s+with)\s+(.+)", words)
        if not found:
            return None
        prep, ref = found.group(1).split()[0], found.group(2).strip()
        axis = _axis(ref)
        return (prep, ref, axis) if axis is not None else None
    found = re.search(r"\b(?:angle|direction|inclined|inclination)\b.*?\b(to|with|from|above|below)\s+(.+)$", words)
    if not found:
        return None
    rest = found.group(2).split()
    for k in range(len(rest), 0, -1):  # "… with the line of centres is theta": the longest axis, then a name
        tail = rest[k:]
        if len(tail) > 2 or any(w not in ("is", "of", "=") and len(w) > 5 for w in tail):
            continue
        axis = _axis(" ".join(rest[:k]))
        if axis is not None:
            return found.group(1), " ".join(rest[:k]), axis
    return None


def _axis(ref: str) -> str | None:
    return next((a for a, pattern in _AXES.items() if re.fullmatch(pattern, ref)), None)


def judge(trace: Trace, line: Read, text: list[str]) -> Item | None:
    """The verdict on a direction line as the angle it names (None: not such a line, or right
    for the problem: judged as any line is)."""
    if not trace.ctx.problem.oblique:
        return None
    c = claim(line, _before(text, line.number))
    if c is None:
        return _named(trace, line)
    truth = _velocities(trace, c, trace.truth[0])
    if truth is None:
        return None
    if any(_is(c, v) for v in truth) or any(_is(c, v, loose=False) for v in _velocities(trace, c, {}, True) or []):
        return _right(trace, line, c, exact=any(_is(replace(c, room=0.0), v) for v in truth))
    world = _velocities(trace, c, trace.world[0]) if trace.world is not None else None
    if world and any(_is(c, v) for v in world):
        return trace._carried(line)
    if trace.slips and trace.world is None and _worked_from_wrong(trace, line):
        return trace._carried(line)
    found = [(i, m) for vels in (world or [], truth) for i, v in enumerate(vels) if (m := _mistake(c, v))]
    if not found and _own_quadrant(c):
        found = [(i, "angle_quadrant") for i, v in enumerate(truth) if any(v)][:1]
    fits = [i for i, v in enumerate(truth) if c.ratio is not None and _same_size(c.ratio, v)]
    moving = [i for i, v in enumerate(truth) if any(v)]
    body = found[0][0] if found else fits[0] if fits else moving[0] if len(moving) == 1 else None
    name = found[0][1] if found else ""
    mistake = REGISTRY.get(name)
    diags = trace.ctx.diagnosis(mistake) if mistake is not None else ()
    return _slip(trace, line, diags, _expected(c, truth[body]) if body is not None else "")


def _worked_from_wrong(trace: Trace, line: Read) -> bool:
    """``90 - 1.27 = 88.7°`` after a wrong angle 1.27 (no velocities to judge the angle by): the
    line is worked from a number the student got wrong, and right as arithmetic."""
    if not line.exprs or len(line.exprs) != len(line.sides) or len(line.exprs) < 2:
        return False
    pairs = trace.pairs(line)
    return trace._uses_wrong_numbers(line, pairs) and trace.holds(pairs, trace.truth)


#: The angles the checker derives from the velocities (context's ``derived``), by their names' stems.
_ANGLES = ("theta_", "beta_", "alpha_", "gamma_", "delta_")


def in_degrees(derived: dict[str, tuple[sympy.Symbol, sympy.Expr]]) -> list[sympy.Expr]:
    """The directions the impact gives, in degrees: what a line of numbers ending in degrees
    (``tan^-1(3.464/3) = 49.1deg``) may come to."""
    return [x * 180 / sympy.pi for n, (_, x) in derived.items() if n.startswith(_ANGLES)]


def _before(text: list[str], number: int) -> str:
    """The prose line just before line ``number`` (blank lines passed over; "" where the line
    before holds a relation, or there is none)."""
    i = number - 2
    while i >= 0 and not text[i].strip() and i > number - 4:
        i -= 1
    if i < 0 or i >= len(text) or "=" in text[i] or not text[i].strip():
        return ""
    return text[i]


def _named(trace: Trace, line: Read) -> Item | None:
    """``θ_2 = tan⁻¹(v_A2t/v_A2n) = tan⁻¹(20) = 87.1°``: a direction result worked in a chain is
    judged as the answer its name and value give (``θ_2 = 87.1°``), where that names a mistake
    in the direction; None otherwise (judged as any line)."""
    left = line.exprs[0] if line.exprs else None
    if len(line.sides) < 3 or not isinstance(left, sympy.Symbol) or left.name not in trace.ctx.results:
        return None
    if trace.ctx.results[left.name].unit != "deg" or any(g.name == left.name for g in trace.ctx.problem.givens):
        return None  # not a direction the impact gives (an unknown given angle is judged as any line)
    answer = trace._answer(replace(line, sides=(line.sides[0], line.sides[-1]), exprs=(left, line.exprs[-1])))
    if answer is None or answer.correct or not answer.diagnosis:
        return None
    if not {d.mistake for d in answer.diagnosis} <= {"angle_other_axis", "angle_quadrant"}:
        return None
    if trace.world is not None and trace.holds(trace.pairs(line), trace.world):
        return None  # right given an earlier slip: carried, as any line
    return _slip(trace, line, answer.diagnosis, answer.expected, f"the direction {line.sides[0].strip()}")


def _right(trace: Trace, line: Read, c: Claim, exact: bool = True) -> Item | None:
    """A line whose angle is the one its words name: correct where its working (each side, in
    degrees) comes to that angle too, or cannot be read; else judged as any line (None). Not
    ``exact`` (off by more than its last figure) and worked from a number the student got
    wrong or rounded too early: carried."""
    for x in line.exprs or ():
        if isinstance(x, sympy.Symbol) or x.has(*_TRIG):
            continue  # a name; a side of sines and cosines (not an angle)
        if x.has(*_INVERSE):  # in radians
            value = number_of(x.xreplace({DEG: sympy.pi / 180}) * 180 / sympy.pi)
        else:  # degrees, with or without the mark
            value = number_of(x.xreplace({DEG: sympy.Integer(1)}))
        if value is None or not _near(value.real, c.value, c):
            return None
    if trace.slips and ((not exact and decimals(line.sides[:-1]) & trace.wrong_values) or _the_slips(trace, c)):
        return trace._carried(line)  # within its figures, but worked from a number got wrong (or rounded early)
    return trace._item(line, "correct", "True for this problem: it is the angle its words name.", TRUE)


def _the_slips(trace: Trace, c: Claim) -> bool:
    """Whether the angle is, rounded to the figures written, the one the slip's world gives and
    not the problem's (``80.1°`` from ``tan⁻¹(4/.696)``: the slip's 80.13°, the problem's 80.17°):
    the student's own, carried."""
    world = _velocities(trace, c, trace.world[0]) if trace.world is not None else None
    rounded = replace(c, room=0.0, unit=c.unit / 2)
    truth = _velocities(trace, c, trace.truth[0]) or []
    return any(_is(rounded, v) for v in world or []) and not any(_is(rounded, v) for v in truth)


def _slip(
    trace: Trace, line: Read, diags: tuple[Diagnosis, ...], expected: str, what: str = "the angle its words name"
) -> Item:
    """The line as a slip: the angle it names is not this one (``diags`` the mistake, if any)."""
    name = ",".join(d.mistake for d in diags)
    again = [n for n, names in trace.named.items() if name and name in names]
    if again:
        lead = f"False: the same mistake as in line {again[0]}, made again"
    elif trace.slips:
        lead = f"False, and not explained by {trace._slips_named()}: a further slip"
    else:
        lead = "The first line that is false for this problem"
    said = f": it {' / '.join(phrase(d.mistake) or d.title for d in diags)}" if diags else ""
    that = f": that is {expected}" if expected else ""
    message = f"{lead}{said}. It is not {what}{that}."
    trace.named[line.number] = {name} if name else set()
    trace.slips.append(line.number)
    trace.wrong_values |= decimals(line.sides[-1:])
    item = trace._item(line, "wrong", message, TRUE, diagnosis=diags, expected=expected)
    return replace(item, slip=name, again=bool(again))


def _velocities(trace: Trace, c: Claim, values: dict, before: bool = False) -> list[tuple[float, float]] | None:
    """Each body's velocity after the impact (or before) in ``values``, as (along the claim's
    axis, across it); None where one is not a number."""
    ctx, nm = trace.ctx, trace.ctx.model.nm
    phi = number_of(ctx.num(ctx.problem.phi)) if ctx.problem.phi is not None else None
    if c.axis in "xy" and phi is None:  # no x-y frame given: x is the line of centres
        c = replace(c, axis="n" if c.axis == "x" else "t")
    out = []
    for b in "AB" if not ctx.problem.fixed_B else "A":
        comps = []
        for part in "nt":
            s = getattr(nm, f"{b}{1 if before else 2}{part}")
            x = number_of(ctx.in_unknowns(s).xreplace(trace.pts[0]).xreplace(values)) if s is not None else 0j
            if x is None or abs(x.imag) > 1e-9:
                return None
            comps.append(x.real)
        n, t = comps
        if c.axis in "xy":
            p = phi.real if phi is not None else 0.0
            n, t = n * math.cos(p) - t * math.sin(p), n * math.sin(p) + t * math.cos(p)
        out.append((n, t) if c.axis in "nx" else (t, n))
    return out


def _near(a: float, b: float, c: Claim, turn: float = 360.0) -> bool:
    """``a`` is ``b`` at the figures written (give or take whole turns), with room for the
    student's own components rounded to three figures."""
    d = (a - b) % turn
    return min(d, turn - d) <= c.unit + c.room * max(abs(a), abs(b), 1.0)


def _acute(a: float) -> float:
    a = a % 180
    return min(a, 180 - a)


def _is(c: Claim, v: tuple[float, float], loose: bool = True) -> bool:
    """Whether the claim is the angle of the velocity ``v`` (along, across); ``loose``: a
    direction either way round, from the axis either way (a velocity after the impact: the
    student's own axes), else only as derive's axes measure it (a velocity before)."""
    along, across = v
    if not (along or across):
        return False
    if not c.directed:
        return _near(_acute(c.value), math.degrees(math.atan2(abs(across), abs(along))), c, 180)
    directions = [math.degrees(math.atan2(across, along))]
    if not loose:
        return _near(c.value, directions[0], c)
    if c.ratio is not None and _same_size(c.ratio, v) and c.ratio[1] * along < 0:
        directions.append(math.degrees(math.atan2(across, -along)))  # the student's axis may be the other way
    return any(_near(c.value, d, c) or _near(c.value, -d, c) for d in directions)  # either way round


def _same_size(ratio: tuple[float, float], v: tuple[float, float]) -> bool:
    """Whether tan⁻¹(Y/X) is of this velocity's components (Y across, X along)."""
    (y, x), (along, across) = ratio, v
    return all(abs(abs(a) - abs(b)) <= 0.01 * max(abs(b), 1e-9) + 0.051 for a, b in ((y, across), (x, along)))


def _mistake(c: Claim, v: tuple[float, float]) -> str:
    """The mistake that gives the claim from the velocity ``v``: "" where none does."""
    along, across = v
    if not (along or across):
        return ""
    if _near(_acute(c.value), math.degrees(math.atan2(abs(along), abs(across))), c, 180) and not _is(c, v):
        return "angle_other_axis"
    if not c.directed or abs(c.value) > 90 + c.unit:
        return ""
    if c.ratio is not None and not (_same_size(c.ratio, v) and c.ratio[1] < 0):
        return ""  # its own components do not show the axis component negative
    direction = math.degrees(math.atan2(across, along))
    if along < 0 and (_near(c.value, direction + 180, c) or _near(c.value, -direction + 180, c)):
        return "angle_quadrant"
    return ""


def _own_quadrant(c: Claim) -> bool:
    """Whether the line's own tan⁻¹(Y/X), X < 0, is taken at face value for a direction: its
    components point the other way (``tan^-1(12/-9) = -53.1° from i``: -9i + 12j is at 126.9°)."""
    if c.ratio is None or not c.directed or c.ratio[1] >= 0:
        return False
    y, x = c.ratio
    face = math.degrees(math.atan(y / x))
    return _near(c.value, face, c) and not _near(c.value, math.degrees(math.atan2(y, x)), c)


def _expected(c: Claim, v: tuple[float, float]) -> str:
    """The angle the line names, of the velocity ``v``, as its words measure it."""
    along, across = v
    angle = math.degrees(math.atan2(across, along) if c.directed else math.atan2(abs(across), abs(along)))
    return f"{angle:.1f}°"
