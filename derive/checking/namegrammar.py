"""Student names read as a grammar, not a list: a base letter (``v``, ``u``, ``w``, ``V`` a
velocity; ``p``, ``P`` a momentum; ``K``, ``KE``, ``E``, ``Ek`` a kinetic energy) and marks in any
order and any grouping:

- a **body**: ``A``/``B``, the problem's labels (``P``/``Q``), ``1``/``2``, a body's word or its
  initial (``puck``, ``p``, ``goalie``, ``g``);
- a **time**: ``i``/``f``, ``initial``/``final``, ``0`` (before), a prime (after), ``before``/
  ``after``; and ``1``/``2`` where the body is already given by a letter (``v_A1``);
- a **component**: ``n``/``t``, ``x``/``y`` (the first axis is the line of centres), ``∥``/``⊥``.

So ``v_{1i}``, ``v_{i,1}``, ``v1i``, ``v_1^i`` are A's velocity before; ``vAn'``, ``(v_A)_n'`` A's
n component after; ``v_{x,f}`` the one body's component along n after; ``p_i`` the momentum of
both before; ``KE_f`` the kinetic energy after.

Digits are decided from the whole derivation: where any name has a time mark (``i``, ``f``,
a prime, ``0``) or the prose names the bodies by numbers (``ball 1``, ``car 2``), digits are
bodies; otherwise a digit alone is left to the habits (``u_1``, ``v_1``: A before, after). A name
with no time mark is before where the same name is also written with one for after (``vAn`` beside
``vAn'``), and otherwise not read here (habits and the inference from relations decide it). At a
wall a digit beside an axis (``v_t2``) is a time, and a velocity named by the fixed surface's word or
capital (``(v_W)_1``) is 0 (:mod:`.fixedbody`); an energy's letter alone (``K``, ``E_k``, ``T``) beside its
primed twin is the energy before, and a component unprimed beside the same body's primed one
(``v2y`` beside ``v2x'``) is before.
"""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.checking.cancelledmass import cancelled_mass
from derive.checking.centremass import moving_together
from derive.checking.context import Context
from derive.checking.fixedbody import fixed_marks, names_fixed
from derive.checking.statementbodies import statement_bodies, told_apart
from derive.checking.wallnames import typed_at_wall, wall_rebound, wall_timed
from derive.mathtext.bracketed import bracketed_names
from derive.mathtext.reader import Relation

#: Base letters by kind, longest first.
_BASES = (("velocity", "v"), ("vel", "v"), ("KE", "K"), ("Ek", "K"), ("E_k", "K"), ("K", "K"), ("E", "K"), ("T", "K"))
_VELOCITY = frozenset("vuwVUW")
_TIMES = (
    ("initial", "1"), ("final", "2"), ("before", "1"), ("after", "2"), ("init", "1"), ("fin", "2"),
    ("i", "1"), ("f", "2"), ("0", "1"),
)  # fmt: skip
_AXES = (
    ("parallel", "n"),
    ("perpendicular", "t"),
    ("par", "n"),
    ("perp", "t"),
    ("∥", "n"),
    ("⊥", "t"),
    ("n", "n"),
    ("t", "t"),
    ("x", "n"),
    ("y", "t"),
)
#: Prose that names the bodies by numbers: "ball 1", "car 2", "object 1", "puck (1)".
_NUMBERED = re.compile(
    r"\b(?:ball|car|cart|object|body|mass|particle|sphere|puck|disc|disk|block|glider|trolley)\s*\(?[12]\b", re.I
)
#: Words after a body's mass in a statement that are not the body (``{m_A} and B``, ``{m_A} moving``).
_NOT_A_BODY = re.compile(
    r"and|the|of|is|are|at|on|in|to|from|with|which|that|moving|travelling|traveling|moves|hits|strikes|slides"
    r"|collides|flies|rolls|lies|rests|has|was|were|each|both|mass|masses|resting|initially|also|but|while"
    r"|slides|moves|travels|bounces|catches|runs|sits|stands|goes|straight|directly|head|into|toward|towards",
    re.I,
)


def body_marks(ctx: Context) -> dict[str, str]:
    """The marks that name A and B: their letters, the problem's labels, and each body's word in
    the statement (``a {m_A} puck``) with its initial where that is no time or axis mark."""
    p = ctx.problem
    out = {"A": "A", "B": "B"}
    for label, body in zip(getattr(p, "labels", ("A", "B")), "AB", strict=True):
        out.setdefault(label, body)
    for letter, body in statement_bodies(ctx).items():  # "Particles P (mass 2m) and Q (mass 3m)"
        out.setdefault(letter, body)
    statement = getattr(p, "statement", "") or ""
    words = {}
    for body in "AB":
        before = re.search(
            rf"\b([a-z]{{3,}})\s+(?:\([A-Z]\)\s+)?(?:of\s+mass|with\s+mass|of|weighing)\s+\{{m_{body}\}}", statement
        )
        after = re.search(rf"\{{m_{body}\}}\s+([a-z]{{3,}})\b", statement)
        adjective = re.search(rf"\{{m_{body}\}}\s+[a-z-]+\s+([a-z]{{3,}})\b", statement)  # "{m_B} wooden block"
        for m in (before, adjective, after):
            if m is not None and not _NOT_A_BODY.fullmatch(m.group(1)) and not m.group(1).endswith(("ing", "ly", "ed")):
                words[body] = m.group(1)
                break
    if len(set(words.values())) == len(words):  # "ball" and "ball": no mark
        for body, word in words.items():
            out.setdefault(word, body)
        initials = [w[0] for w in words.values()]
        for body, word in words.items():
            if word[0] not in "intfxy" and initials.count(word[0]) == 1:
                out.setdefault(word[0], body)
    for word, body in told_apart(statement).items():
        out.setdefault(word, body)
    for mark, body in fixed_marks(statement).items() if p.fixed_B else ():  # (v_C)_1 = 0: the surface's
        out.setdefault(mark, body)
    return out


def _split(
    marks: str, bodies: dict[str, str], digits_are_bodies: bool, kind: str, wall: bool = False
) -> tuple[str, str, str] | None:
    """(body, time, axis) of a name's marks (each "" where not said); None where the marks are not
    all body, time and component marks (a word, a name of something else). A digit is a body
    where digits are (``v_{1i}``), else a time after a body's letter (``v_A1``) or in a
    momentum or an energy (``K_1``), or beside an axis at a wall (``wall``: one body moves, so
    ``(v_t)_2``, ``v_{n1}`` are its components); else None (``v_1``: the habits')."""
    if wall and kind == "v" and not digits_are_bodies and (timed := wall_timed(marks)):
        return timed  # v_t2, v_{1n}: the one moving body's component at that time
    body = time = axis = ""
    rest = marks.replace("_", "").replace(",", "")
    long = sorted(
        [("body", k, v) for k, v in bodies.items()] + [("time", *t) for t in _TIMES] + [("axis", *a) for a in _AXES],
        key=lambda x: -len(x[1]),
    )
    if kind != "v":  # p_{tot,i}, KE_{sys,f}: both bodies, as a name with no body says
        rest = re.sub(r"^(?:total|tot|sys|system)|(?:total|tot|sys|system)$", "", rest)
    while rest:
        if rest[0] in "12":
            if digits_are_bodies and not body:
                body = "A" if rest[0] == "1" else "B"
            elif time or not (body or kind != "v"):
                return None
            else:
                time = rest[0]
            rest = rest[1:]
            continue
        hit = next((x for x in long if rest.startswith(x[1])), None)
        if hit is None:
            return None
        what, mark, value = hit
        slot = {"body": body, "time": time, "axis": axis}
        if slot[what] and slot[what] != value:
            return None
        slot[what] = value
        body, time, axis = slot["body"], slot["time"], slot["axis"]
        rest = rest[len(mark) :]
    return body, time, axis


def parse(
    name: str, bodies: dict[str, str], digits_are_bodies: bool, primed: bool = False, wall: bool = False
) -> tuple[str, str, str, str] | None:
    """(kind, body, time, axis) of a student's name (kind "v" velocity, "p" momentum, "K" energy,
    "m" mass);
    ``primed``: the name was written with a prime (after)."""
    for base, k in _BASES:
        if name.startswith(base) and (name != base or k == "K"):  # K alone: an energy, its time from its twin
            kind, marks = k, name[len(base) :]
            break
    else:
        if name[0] in _VELOCITY:
            kind, marks = "v", name[1:]
        elif name[0] == "p" or (name[0] == "P" and "P" not in bodies):  # P: the exam's body P
            kind, marks = "p", name[1:]
        elif name[0] in "mM":
            kind, marks = "m", name[1:]
        elif re.fullmatch(r"[ab]_?[ntxy]", name):  # a_n, b_t: a body's own letter and a component
            kind, marks = "v", name[0].upper() + name[-1]
        else:
            return None
    if not re.fullmatch(r"[A-Za-z0-9_,∥⊥]*", marks) or not (marks or primed or kind == "K"):
        return None
    parts = _split(marks, bodies, digits_are_bodies, kind, wall)
    if parts is None:
        return None
    body, time, axis = parts
    if primed:
        if time == "1":
            return None
        time = "2"
    return kind, body, time, axis


def _digits_are_bodies(text: str, names: set[str], bodies: dict[str, str]) -> bool:
    """Whether the derivation's digits name bodies: a name with a time mark of its own (``v_1i``,
    ``v1f``, ``v_2'``), or prose naming the bodies by numbers (``ball 1``)."""
    if _NUMBERED.search(text):
        return True
    for n in names:
        got = parse(n, bodies, True) if re.search(r"[12]", n) else None
        if got is not None and got[1] and got[2] and not re.fullmatch(r"[A-Za-z]+_?[AB][12]\w?", n):
            return True  # v_{1x,i}, v1f, K_{2,final} (not v_A1: a body's letter, then its time)
    return bool(re.search(r"(?<![\w.])[vuwVpP]_?\{?[12]\w?\}?\s*(?:'|′|\\prime|\^\{?\\prime)", text))


def _velocity(ctx: Context, body: str, time: str, axis: str) -> sympy.Expr | None:
    p, nm = ctx.problem, ctx.model.nm
    if p.fixed_B and body == "B":
        return None
    if p.oblique and not axis and time == "1":  # a body at rest before: 0 in every reading (v_{Pi} = 0)
        return next((g.symbol for g in p.givens if g.name == f"v_{body}1" and g.value == 0), None)
    if p.oblique:  # without a component: a speed, or the n component where the t one is dropped
        return getattr(nm, f"{body}{time}{axis}", None) if axis else None  # (habits, inference)
    return None if axis == "t" else getattr(nm, f"{body}{time}n", None)


def meaning(ctx: Context, kind: str, body: str, time: str, axis: str) -> sympy.Expr | None:
    """derive's expression for a parsed name (None: not one this grammar places)."""
    p, m = ctx.problem, ctx.model
    if kind == "m":  # m_1, m_puck, M_g: a body's mass
        return None if time or axis or not body or (p.fixed_B and body == "B") else {"A": m.m_A, "B": m.m_B}[body]
    if not time:
        return None
    if kind == "v":
        if not body:
            if p.fixed_B:
                body = "A"
            elif time == "2" and any(g.name == "e" and g.value == 0 for g in p.givens) and not axis:
                return moving_together(ctx, m.nm.A2n, m.nm.B2n)  # they move off together: one velocity
            else:
                return None
        return _velocity(ctx, body, time, axis)
    mass = {"A": m.m_A, "B": m.m_B}
    bodies = [body] if body else ["A"] if p.fixed_B else ["A", "B"]
    if kind == "p":
        terms = [(b, _velocity(ctx, b, time, axis or ("n" if p.oblique else ""))) for b in bodies]
        if any(v is None for _b, v in terms):
            return None
        return sympy.Add(*(mass[b] * v for b, v in terms))
    if kind == "K" and not axis:
        if not body:
            derived = ctx.derived().get(f"T_{time}")
            return derived[0] if derived else None
        if p.oblique:
            n, t = (_velocity(ctx, body, time, c) for c in "nt")
            return None if n is None or t is None else mass[body] * (n**2 + t**2) / 2
        v = _velocity(ctx, body, time, "")
        return None if v is None else mass[body] * v**2 / 2
    return None


def grammar_names(
    ctx: Context, used: set[str], text: str, skip: set[str], axes: dict | None = None
) -> dict[str, sympy.Expr]:
    """The names of ``used`` (as rewritten) that the grammar places -> derive's expression;
    ``skip`` are names with a meaning already (the problem's, declared ones); ``axes``: the
    student's x and y placed in words (:func:`.frames.declared_axes`), the axes of x and y in a name."""
    bodies = body_marks(ctx)
    primed = {n[:-2] if n.endswith("_p") else n[:-1] for n in used if re.search(r"(?<=[A-Za-z0-9])_?p$", n)}
    primed = {n for n in primed if _primed_in(text, n)}
    digits = _digits_are_bodies(text, used, bodies)
    parsed: dict[str, tuple[str, str, str, str]] = {}
    for name in used:
        if name in skip:
            continue
        stem = name[:-2] if name.endswith("_p") else name[:-1] if name.endswith("p") else ""
        wall = bool(ctx.problem.fixed_B and ctx.problem.oblique) and typed_at_wall(name, text)
        got = parse(stem, bodies, digits, True, wall) if stem in primed else parse(name, bodies, digits, wall=wall)
        if got is not None:
            parsed[name] = got
    out: dict[str, sympy.Expr] = wall_words(ctx, used - skip, primed)  # par, perp: a wall's components
    m = ctx.model
    if "m" in used and "m" not in skip and not ctx.problem.fixed_B and _equal(ctx, m.m_A, m.m_B):
        out["m"] = m.m_A  # two equal masses: m is each one's
    for name, (kind, body, time, axis) in parsed.items():
        if not time and any(
            q[:2] == (kind, body) and q[2] == "2" and q[3] == axis and (kind != "K" or body or other.startswith(name))
            for other, q in parsed.items()
        ):
            time = "1"  # vAn beside vAn': before; K beside K' (or K_f): the energy before
        elif (
            not time
            and kind == "v"
            and body
            and axis
            and any(
                o[0] == name[0] and o.endswith("p") and q[1:3] == (body, "2") and q[3] not in ("", axis)
                for o, q in parsed.items()
            )
        ):
            time = "1"  # v2y beside v2x' (the body's other component primed): before, a prime its after
        elif not time and kind == "v" and body and _only_before_marked(parsed, body, axis):
            time = "2"  # vAx beside vAx1 (and none marked after): after
        elif not time and kind == "v" and body and _by_word(name, bodies) and not _said_speed(name, text):
            time = "1" if name[0] == "u" else "2"  # v_red, u_car: the habit's u before, v after
        elif not time and kind == "v" and axis and _uv_twins(name, used, body or ctx.problem.fixed_B):
            time = "1" if name[0] == "u" else "2"  # u_perp beside v_perp: u before, v after
        axis = _at_a_wall(name, axis, ctx.problem.fixed_B)  # v_perp at a wall: into it, n
        if ctx.problem.fixed_B and (time, axis) == ("2", "n") and wall_rebound(name):
            continue  # the rebound named by its axis: a size or signed, as the words say (axisnames)
        axis, sign = _in_axes(name, axis, axes or {})  # y along the line of impact: (v_Ay)_1 is n
        if kind == "v" and body == "B" and time and ctx.problem.fixed_B and names_fixed(name, bodies):
            out[name] = sympy.S.Zero  # (v_C)_1 = 0, v_W2: the wall's velocity, which does not move
            continue
        e = meaning(ctx, kind, body, time, axis)
        if e is not None:
            e = sign * e
            out[name] = e / per if kind == "p" and (per := cancelled_mass(ctx, text)) is not None else e
    return out


def _in_axes(name: str, axis: str, axes: dict) -> tuple[str, int]:
    """The axis (and its sign) of a name's x or y where the student's words place the axes
    ("line of impact = y axis": ``v_Ay1`` is A's n component before); else as the grammar reads it."""
    letter = {"n": "x", "t": "y"}.get(axis, "")
    if not letter or axis not in axes or letter not in name[1:]:
        return axis, 1
    return axes[axis]


#: A component named by its axis alone at a wall (``par = U cos α``, ``perp' = eU sin α``): parallel
#: to the wall is derive's t, perpendicular (normal) to it n. "parallel" and "perpendicular" in full
#: as a whole name too ("Velocity before: parallel = U cos α, perpendicular = U sin α"); "normal" in
#: full is prose as often ("the angle with the normal = 90 - 1.27").
_WALL_WORDS = {"par": "t", "para": "t", "perp": "n", "norm": "n", "parallel": "t", "perpendicular": "n"}


def wall_words(ctx: Context, used: set[str], primed: set[str]) -> dict[str, sympy.Expr]:
    """The ball's components at a wall named by their axis alone: before, or after where primed;
    sizes, as words name them (the normal one after is out of the wall: -v_A2n)."""
    if not (ctx.problem.fixed_B and ctx.problem.oblique):
        return {}
    out = {}
    for name in used:
        stem = name[:-2] if name.endswith("_p") and name[:-2] in primed else name
        axis = _WALL_WORDS.get(stem.lower())
        x = getattr(ctx.model.nm, f"A{'2' if stem != name else '1'}{axis}", None) if axis else None
        if x is not None:
            out[name] = -x if stem != name and axis == "n" else x
    return out


def _uv_twins(name: str, used: set[str], body: str | bool) -> bool:
    """Whether ``name`` is ``u`` or ``v`` with an axis's sign or word (and a body's, or at a wall) and
    the other letter is written with the same marks (``u_perp`` and ``v_perp``, ``u_{A,par}`` and
    ``v_{A,par}``): the habit's u before and v after, as a pair says it."""
    if not re.search(r"par|perp|∥|⊥", name):  # u_x, v_x: x's axis and time are the frame's to say
        return False
    return bool(body) and name[0] in "uv" and ("vu"[name[0] == "v"] + name[1:]) in used


def _at_a_wall(name: str, axis: str, fixed: bool) -> str:
    """The axis of a component named parallel or perpendicular (``v_par``, ``u_⊥``): at a wall
    parallel is along it (t) and perpendicular into it (n), not the line of centres' reading."""
    if fixed and axis in ("n", "t") and re.search(r"par|perp|∥|⊥", name):
        return "t" if axis == "n" else "n"
    return axis


def _by_word(name: str, bodies: dict[str, str]) -> bool:
    """Whether ``name`` is ``u`` or ``v`` with a body's word from the statement after it and nothing
    else (``v_red``, ``u_car``), or the statement's letter for it (``u_S``, ``v_T`` for spheres S and
    T): the habit's letters, u before and v after, for that body. The exam's P and Q (and A, B) are
    left to the relations, which read their time and sign as before."""
    m = re.fullmatch(r"([uv])_?([a-z]{3,}|(?![ABPQ])[A-Z])", name)
    return m is not None and m.group(2) in bodies


def _said_speed(name: str, text: str) -> bool:
    """Whether the text calls ``name`` a speed in its sentence ("Speeds before: $u_P$ (P) and $u_Q$",
    "$u_P$ and $u_Q$ are the **speeds** before"): a size, which the inference signs, not the habit's
    velocity."""
    m = re.fullmatch(r"([uv])_?([A-Z])", name)
    if m is None:
        return False
    typed = rf"{m.group(1)}_?\{{?{m.group(2)}\}}?(?![A-Za-z])"
    return re.search(rf"\bspeeds?\b[^.\n]*{typed}|{typed}[^.\n]*\bspeeds?\b", text, re.I) is not None


def _only_before_marked(parsed: dict[str, tuple[str, str, str, str]], body: str, axis: str) -> bool:
    """Whether the velocity of ``body`` along ``axis`` is written with the time before marked
    (``vAx1``, ``u_A1``) and never with the time after: the name without a mark is then after."""
    times = {q[2] for q in parsed.values() if q[0] == "v" and q[1] == body and q[3] == axis}
    return "1" in times and "2" not in times


def _equal(ctx: Context, a: sympy.Expr, b: sympy.Expr) -> bool:
    """Whether two of the problem's quantities are equal (by their definitions or their values)."""
    defs, values = ctx.definitions(), ctx.problem.numeric()
    x, y = (e.xreplace(defs).xreplace(values) for e in (a, b))
    return sympy.simplify(x - y) == 0


def _primed_in(text: str, stem: str) -> bool:
    """Whether ``stem`` (a rewritten name) is written primed in ``text`` in another spelling
    (``v_{A}'``, ``v_A^{\\prime}``, ``v_A′``), or with the prime on its base letter (``v'_{Ax}``), or
    under a lead-in ``After:`` (which primes it, ``Before: vx = …`` beside ``After: vx = …``)."""
    chars = stem.replace("_", "")
    loose = r"[_{}()]*".join(re.escape(c) for c in chars)
    prime = r"(?:'|′|’|\\prime|\^\{?\\prime\}?)"
    pattern = rf"(?<![\w])\(?{loose}[_{{}})]*\s*{prime}"
    rest = r"[_{}()]*".join(re.escape(c) for c in chars[1:])  # v'_{Ax}: the prime on the base letter
    on_letter = rf"(?<![\w\\]){re.escape(chars[:1])}\s*{prime}\s*[_{{(]+\s*{rest}[}})]*(?![\w'′’])"
    if any(re.search(p, t) for t in (text, bracketed_names(text)) for p in (pattern, on_letter)):  # (v_2')_t
        return True
    under_after = rf"(?im)^[\s*>#-]*after(?:wards)?\s*:.*?(?<![\w']){re.escape(stem)}(?![\w'′’])"
    return re.search(under_after, text) is not None  # "After: vx = …" beside "Before: vx = …": vx′


#: A change of kinetic energy by its Greek capital (``ΔKE``, ``\Delta K``, ``ΔE_k``), or typed with a d (``dK``).
_CHANGE = re.compile(r"^\s*(?:(?:\\?Delta|Δ)\s*(?:KE|K|E_?k|E|T)|d(?:KE|K|E_?k))\s*$")


def energy_change(relations: tuple[Relation, ...]) -> tuple[Relation, ...]:
    """``ΔKE = 6523 - 7542 = -1019 J``: a change of kinetic energy worked out negative is the
    energy after less the energy before, minus the energy lost (read elsewhere as the loss, which
    a student states positive: ``ΔT = 2898 - 1513 = 1385 lost``)."""
    out = []
    for r in relations:
        if len(r.sides) >= 2 and _CHANGE.match(r.sides[0]) and re.match(r"\s*[-−]\s*\d", r.sides[-1]):
            r = replace(r, sides=(f"-({r.sides[0].strip()})", *r.sides[1:]))
        out.append(r)
    return tuple(out)
