"""Names a student declares as a component by the words beside them: ``\\text{along l.o.c.:}\\quad
u_1 = u\\sin 30°``, ``perp.: u_2 = u cos 30°``, ``u_x = U sin α (along wall)``, ``u_y = U cos α
(into wall)``. The words name the axis (the line of centres, or across it); the body is the one
whose given velocity the right side resolves, and the time is before, unless the line leads in
with ``After:``. A subscript that names the axis (``u∥``, ``v_perp``) is as good as the words,
where the time is said: under ``After:``, under ``Q b4:`` or ``Before:``, or by the habit's letter
u. A name in another letter with the same subscript under ``After:`` (``v_x`` after ``u_x``) is
the same axis after the impact. The words win over the habits (``u_1``, ``u_2`` are
not A and B here).
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context
from derive.checking.wallnames import typed_at_wall, wall_timed
from derive.mathtext.reader import Relation

#: Words that name the line of centres (derive's n) or the axis across it (t), for two bodies.
_LINE = r"(?:the\s+)?(?:l\.?\s?o\.?\s?c\.?|line\s+of\s+(?:centres|centers|impact)|common\s+normal)"
_ALONG = rf"(?:along|parallel\s+to|∥)\s*{_LINE}|∥|(?:along\s+the\s+)?normal(?:\s+comp\w*)?"
_ACROSS = (
    r"(?:perp(?:\.|endicular)?|⊥)(?:\s*to)?(?:\s*(?:it|the\s+l\w*|l\.?\s?o\.?\s?c\.?))?|across(?:\s+it)?"
    r"|(?:along\s+the\s+(?:common\s+)?)?tangent(?:ial)?(?:\s+comp\w*)?"
)
#: For a wall (or cushion): along it is t, into it (normal to it) is n.
_FIXED = r"(?:the\s+)?(?:wall|cushion|barrier|plane|floor|ground|surface)"
_WALL_T = rf"along\s+{_FIXED}|parallel\s+to\s+{_FIXED}"
_WALL_N = rf"(?:into|towards?|normal\s+to|perpendicular\s+to|away\s+from)\s+{_FIXED}"
_AFTER = re.compile(r"^\s*(?:after(?:wards)?|finally)\b", re.I)
_STRIP = re.compile(r"\\(?:text|textrm|mathrm|mbox)\s*\{([^{}]*)\}|\\q?quad|\\[,;: ]|[$&]")


def _axis(words: str, fixed: bool) -> str:
    """``n`` or ``t`` for the words naming an axis, "" where they name none."""
    words = words.strip().rstrip(":").strip()
    if fixed:
        if re.fullmatch(_WALL_N, words, re.I):
            return "n"
        if re.fullmatch(_WALL_T, words, re.I):
            return "t"
    if re.fullmatch(_ALONG, words, re.I):
        return "n"
    return "t" if re.fullmatch(_ACROSS, words, re.I) else ""


def _words_beside(r: Relation, name: str) -> str:
    """The words just before ``name`` on its line (a lead-in) or in brackets after the relation."""
    plain = _STRIP.sub(lambda m: f" {m.group(1)} " if m.group(1) else " ", r.written)
    at = re.search(rf"(?<![\w']){re.escape(name)}(?![\w'])\s*=", plain)
    if at is None:
        return ""
    before = ([p for p in re.split(r"[,;]|\s{3,}", plain[: at.start()]) if p.strip()] or [""])[-1]
    before = re.sub(r"^\s*(?:before|after(?:wards)?|initially|finally)\s*:\s*", "", before, flags=re.I)
    if before.strip():
        return before
    bracket = re.match(r"[^(,;]*?\(\s*([A-Za-z .]+?)\s*\)", plain[at.end() :])
    return bracket.group(1) if bracket else ""


#: A lead-in that says the time before (``Q b4:``, ``A before:``, ``Initially,``), phone-typed too.
_BEFORE_LEAD = re.compile(r"\b(?:before|b4|initially|initial)\b", re.I)


def _before_said(r: Relation, name: str) -> bool:
    """Whether a component named by its axis in its subscript (``u∥``, ``v_perp``) is before the
    impact: its line's lead-in says so (``Q b4: u∥ = u sin α``), or its letter is the habit's u."""
    if name[0] == "u":
        return True
    at = r.written.find(name.split("_")[0])
    return _BEFORE_LEAD.search(r.label or r.written[: max(at, 0)]) is not None


def _after_by_letter(name: str, sub: str, relations: tuple[Relation, ...], side: str = "") -> bool:
    """Whether a component at a wall named by v (or w) and its axis's sign, with no time said
    (``v_⊥ = ¾ U sin α``, ``v_perp = +14.71`` beside ``u_perp``), is after by the habit's letters:
    u before, v after. Not where the same name is also written primed (``v_perp'``: the unprimed
    one is then before) or with a time mark of its own; and not where ``side`` is a speed resolved
    and nothing more (``v_perp = 10 sin 30°``: the velocity before, resolved) unless the student
    names the components before with u (``u_⊥``): the habit is then theirs."""
    if name[0] not in "vwV" or not sub_axis(sub, True) or _resolved_before(relations, side):
        return False
    primed = re.compile(rf"(?<![\w]){re.escape(name)}(?:_?p\b|')|(?<![\w]){re.escape(name[0])}'_?\{{?{re.escape(sub)}")
    return not any(primed.search(s) for r in relations for s in r.sides)


#: A name of u and an axis's sign (``u_perp``, ``u⊥``, ``|u_\\perp|``); a side that is a speed resolved
#: and nothing more (``10 sin 30°``, ``U\\cos\\alpha``, ``28cos(45)``).
_U_AXIS = re.compile(r"(?<![A-Za-z])u_?\{?\\?([A-Za-z]{1,13}|⊥|∥)\}?")
_RESOLVED_ALONE = re.compile(r"\s*\(?\s*(?:\d+\.?\d*|[A-Za-z]\w{0,3})\s*[*·×]?\s*\\?(?:sin|cos)\b[^=*/+]*?\)?\s*")


def _resolved_before(relations: tuple[Relation, ...], side: str) -> bool:
    """Whether ``side`` is a speed resolved and nothing more where no name of u says an axis: the
    velocity before, resolved (``v_perp = 10 sin 30°``), whatever its letter."""
    if not _RESOLVED_ALONE.fullmatch(side):
        return False
    return not any(sub_axis(m[1], True) for r in relations for s in r.sides for m in _U_AXIS.finditer(s))


def _body(side: str, ctx: Context) -> str:
    """The body whose given velocity before the impact the side resolves ("" where none or both)."""
    found = set()
    for g in ctx.problem.givens:
        m = re.fullmatch(r"v_([AB])1", g.name)
        if m is None:
            continue
        x = getattr(g, "definition", None)
        spelled = {str(s) for s in x.free_symbols} if isinstance(x, sympy.Expr) else set()
        if isinstance(g.value, sympy.Number) and g.value != 0:  # a speed given as a number: as written
            spelled |= {str(g.value), f"{float(g.value):g}"}
        for word in spelled | {g.name}:
            end = r"(?![\d]|\.\d)" if word[0].isdigit() else r"(?![\w]|\.\d)"  # 5sin37.6: the 5 typed glued
            if re.search(rf"(?<![\w.]){re.escape(word)}{end}", side):
                found.add(m.group(1))
    return found.pop() if len(found) == 1 else ""


def components(
    relations: tuple[Relation, ...], ctx: Context, reserved: set[str], sign: int = 0
) -> dict[str, sympy.Expr]:
    """The names declared as components by the words beside them -> derive's component; ``sign`` the
    way the text declares positive (0 where none): a rebound named by its axis is then signed in it,
    not read as a size."""
    if not ctx.problem.oblique:
        return {}
    fixed = bool(ctx.problem.fixed_B)
    nm = ctx.model.nm
    out: dict[str, sympy.Expr] = {}
    letters: dict[str, str] = {}  # a subscript -> the axis its names were declared on
    flips: dict[str, int] = {}  # a subscript across -> -1 where its size is derive's negative
    for r in relations:
        name = r.sides[0].strip()
        if len(r.sides) < 2 or name in reserved or not re.fullmatch(r"[A-Za-z]_?\w{1,3}|[A-Za-z]_[A-Za-z]{4,13}", name):
            continue
        after = bool(_AFTER.match(r.label or "") or _AFTER.match(r.written))
        sub = name.split("_")[-1] if "_" in name else name[1:]
        before = _before_said(r, name) or (
            fixed and sub_axis(sub, True) != "" and _resolved_before(relations, r.sides[1])
        )
        after = after or (not before and fixed and _after_by_letter(name, sub, relations, r.sides[1]))
        rebound = fixed and wall_timed(sub) == ("", "2", "n") and typed_at_wall(name, r.written)  # v_n2: as v_perp
        after = after or rebound
        said = after or before  # v_perp under "After:", or v's habit at a wall
        axis = _axis(_words_beside(r, name), fixed) or (
            sub_axis(sub, fixed) or ("n" if rebound else "") if said else ""
        )
        if not axis and after and sub in letters:
            axis = letters[sub]
        body = "A" if fixed else _body(r.sides[1], ctx)
        if not axis or not body:
            continue
        x = getattr(nm, f"{body}{'2' if after else '1'}{axis}", None)
        if x is not None:
            if axis == "t" and not after and not r.sides[1].lstrip().startswith("-") and _negative(ctx, x):
                flips[sub] = -1  # "perp.: w = 15 sin 37.6°": a size, the student's own way across
            named = sub_axis(sub, fixed) or rebound
            if axis == "n" and after and named and not sign and not r.sides[1].lstrip().startswith("-"):
                x = -x if _negative_after(ctx, x) else x  # "v_perp = eU sin α": the rebound's size
            out.setdefault(name, flips.get(sub, 1) * x if axis == "t" else x)
            letters.setdefault(sub, axis)
    return out


#: A component's subscript that names its axis: parallel or perpendicular (to a wall: along it or
#: into it; to two bodies' line of centres: along it or across it).
_PARALLEL = re.compile(r"par|para|paral|parallel|pl|al|along|∥|\|\|", re.I)
_PERPENDICULAR = re.compile(r"perp|pp|pe|perpendicular|across|⊥", re.I)


def sub_axis(sub: str, fixed: bool) -> str:
    """``n`` or ``t`` for a component's subscript that says its axis (``v_par``, ``v_perp``): for a
    wall parallel is along it (t) and perpendicular into it (n); for two bodies parallel is along
    the line of centres (n); "" for any other subscript."""
    if _PARALLEL.fullmatch(sub):
        return "t" if fixed else "n"
    if _PERPENDICULAR.fullmatch(sub):
        return "n" if fixed else "t"
    return ""


def _negative_after(ctx: Context, c: sympy.Expr) -> bool:
    """Whether the component ``c`` after the impact is negative in the problem solved (at a few
    admissible values of the givens where they are letters)."""
    out = ctx.model.outcome(ctx.model.base())
    if out is None:
        return False
    x = c.xreplace(out.post)
    return x != c and _negative(ctx, x)


def _negative(ctx: Context, c: sympy.Expr) -> bool:
    """Whether the component ``c`` before the impact is negative: decided, or at every one of a
    few admissible values of the givens (``-u sin α``, α acute)."""
    x = ctx.model.num(ctx.model.imp.in_givens(c))
    if x.is_negative is not None or not x.free_symbols:
        return bool(x.is_negative)
    pts = ctx.sampler().points(x.free_symbols, 3)
    values = [sympy.N(x.xreplace(pt)) for pt in pts]
    return bool(values) and all(v.is_real and v < 0 for v in values)


#: The axes' letters students use: the first (n, x, i) is the line of centres, derive's n.
AXIS_LETTERS = {"n": "n", "x": "n", "i": "n", "t": "t", "y": "t", "j": "t"}


def letter_components(ctx: Context, used: set[str] | None = None) -> dict[str, sympy.Expr]:
    """A body's components by its letter and an axis (``A_n``, ``A_x``, ``B_j``: before; primed
    ``A_n'`` after), and ``u_Ax``, ``v_Ay`` (u before, v after) on x and y axes; ``A_T`` the
    component across named in words and written unsigned: its size before, the same way after
    (worked out only where ``used``, the names the text uses, has it)."""
    nm = ctx.model.nm
    out: dict[str, sympy.Expr] = {}
    for body in "AB":
        t1, t2 = getattr(nm, f"{body}1t"), getattr(nm, f"{body}2t")
        if t1 is not None and t2 is not None and (used is None or {f"{body}_T", f"{body}_Tp"} & used):
            flip = -1 if _negative(ctx, t1) else 1
            out[f"{body}_T"], out[f"{body}_Tp"] = flip * t1, flip * t2
        for letter, c in AXIS_LETTERS.items():
            out[f"{body}_{letter}"] = getattr(nm, f"{body}1{c}")
            out[f"{body}_{letter}p"] = getattr(nm, f"{body}2{c}")
            if letter in "xy":
                out[f"u_{body}{letter}"] = getattr(nm, f"{body}1{c}")
                out[f"v_{body}{letter}"] = getattr(nm, f"{body}2{c}")
            if letter in "xynt":  # u_1x, u2y, (u_1)_x: u is before, whichever mark names the body
                one = "1" if body == "A" else "2"
                out[f"u_{one}{letter}"] = out[f"u{one}{letter}"] = getattr(nm, f"{body}1{c}")
    return out
