"""From a solution to a figure: bodies at contact, the n and t axes, velocity arrows,
angles, walls and floors, x-y axes, with every label placed.

The figure reads the solution's numbers; it does no physics of its own. A symbol
without a number (a symbolic mass or speed) is drawn as 1, so that arrows stay in
proportion: in Example 4.C.12 every speed is a multiple of v_A1; a coefficient of
restitution kept as a letter is drawn at 0.5 or so, and the caption says so (:mod:`.letters`).

Which way is down: :mod:`.frame`.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from decimal import Decimal
from typing import Any

import sympy

from derive.physics.impact import independent_map
from derive.physics.results import working_unit
from derive.problem import Problem
from derive.steps.model import Solution
from derive.symbols import relabel
from derive.writers.figure.frame import Frame, chain_falls, frame, number
from derive.writers.figure.layout import AROUND, Spec, place
from derive.writers.figure.letters import restitution_drawn
from derive.writers.figure.model import HEAD, Arc, Arrow, Axis, Body, Figure, Guide, Point, Shape, Surface

ARROW_MAX = 3.0  # cm: the arrow of the greatest speed, before or after
#: cm: the least length an arrow is drawn at, two arrowheads: the head at full size (it
#: shrinks below HEAD / 0.6) and a shaft as long as the head, so that the direction reads
#: at a glance. A slower speed's arrow is drawn this long, not to scale, and the caption
#: names it.
ARROW_MIN = 2 * HEAD
R_MAX = 1.3  # cm: the radius of the larger body
ARC_R = 0.75  # cm: the radius of an angle's arc
MIN_ARC = 0.15  # cm: an arc shorter than this (under 11.5° at ARC_R) cannot be seen
#: The order labels are placed in: those with the least room first.
ORDER = {"body": 0, "angle": 1, "velocity": 2, "axis": 3, "surface": 4}


#: How a figure turns an expression into a float, given the numbers known
#: (:func:`~derive.writers.figure.frame.number`; homework variants pass a compiled one).
Numbers = Callable[[object, Mapping], "float | None"]


def radii(problem: Problem, numbers: Numbers = number) -> tuple[float, float]:
    """Drawn radii of A and B: in the ratio of the given r_A and r_B, else equal."""
    given = {g.name: g for g in problem.givens}
    ind = independent_map(problem)
    values = problem.numeric()
    found = []
    for name in ("r_A", "r_B"):
        g = given.get(name)
        expr = None if g is None else (g.value if g.value is not None else g.symbol.xreplace(ind))
        found.append(numbers(expr, values))
    a, b = found
    if a is None or b is None or a <= 0 or b <= 0:
        return R_MAX, R_MAX
    big = max(a, b)
    return R_MAX * a / big, R_MAX * b / big


def _result(solution: Solution, name: str) -> object | None:
    """A velocity component after the impact: found, or given (an inverse problem)."""
    r = solution.results.get(name)
    if r is not None:
        return r.found
    for g in solution.problem.givens:
        if g.name == name:
            return g.value if g.value is not None else g.symbol
    return None


def _components(solution: Solution) -> dict[str, tuple[object, object]]:
    """(n, t) components of each moving body's velocity as expressions: ``A1``, ``B1``,
    ``A2``, ``B2``."""
    p = solution.problem
    ind = independent_map(p)
    out: dict[str, tuple[object, object]] = {}
    for b in "AB":
        if b == "B" and p.fixed_B:
            continue
        motion = p.motion_A if b == "A" else p.motion_B
        out[b + "1"] = (motion.n.xreplace(ind), motion.t.xreplace(ind))
        if p.oblique:
            out[b + "2"] = (_result(solution, f"v_{b}2n"), _result(solution, f"v_{b}2t"))
        else:
            out[b + "2"] = (_result(solution, f"v_{b}2"), 0.0)
    return out


def _known(solution: Solution, values: Mapping) -> dict:
    """Every number the figure may use: the solution's, ``values``, and the givens the
    problem left unknown and the solution found (v_A1n = "?" is 9 m/s, not 1; an angle's
    result is in degrees, its symbol in radians)."""
    found = {}
    for g in solution.problem.givens:
        r = solution.results.get(g.name) if g.unknown else None
        if r is not None:
            found[g.symbol] = r.found * sympy.pi / 180 if g.unit == "deg" else r.found
    return {**found, **solution.values, **values}


def velocities(solution: Solution, values: Mapping, numbers: Numbers = number) -> dict[str, tuple[float, float]]:
    """(n, t) components of each moving body's velocity: ``A1``, ``B1``, ``A2``, ``B2``."""
    known = _known(solution, values)
    out: dict[str, tuple[float, float]] = {}
    for key, (en, et) in _components(solution).items():
        n, t = numbers(en, known), numbers(et, known)
        if n is not None and t is not None:
            out[key] = (n, t)
    return out


def speed_words(solution: Solution, key: str, speed: float, values: Mapping) -> str:
    """A drawn speed in words for a caption ("0.2 m/s"), or "" when it is a symbol's
    (drawn as if each symbol were 1, so its number means nothing to the reader)."""
    known = _known(solution, values)
    if any(_symbolic(c, known) for c in _components(solution)[key] if c is not None):
        return ""
    return f"{Decimal(f'{speed:.3g}').normalize():f} {working_unit(solution.problem, 'velocity')}"


def _symbolic(expr: object, known: Mapping) -> bool:
    """True when ``expr`` with the numbers ``known`` put in still has a symbol in it. Where each
    of its symbols is known as a number (every key a symbol), it has none, found without
    building it (a sympy expression a variant's figure would build, only to drop)."""
    e = sympy.sympify(expr)
    symbols = e.free_symbols
    if all(isinstance(k, sympy.Symbol) for k in known) and all(
        s in known and not getattr(known[s], "free_symbols", ()) for s in symbols
    ):
        return False
    return bool(e.xreplace(known).free_symbols)


def _perps(ux: float, uy: float, away: Point) -> tuple[Point, Point]:
    """The two directions across (ux, uy), the one pointing along ``away`` first."""
    left, right = (-uy, ux), (uy, -ux)
    return (left, right) if left[0] * away[0] + left[1] * away[1] >= 0 else (right, left)


def arrow_spec(a: Arrow, free_end: Point, outward: Point, text: str | None = None) -> Spec:
    """Where a velocity's label may go: beside its middle (on the side away from the
    point of contact, else above), beyond its free end, beside its quarters."""
    ux, uy = (a.x2 - a.x1) / a.length, (a.y2 - a.y1) / a.length
    mid = ((a.x1 + a.x2) / 2, (a.y1 + a.y2) / 2)
    p1, p2 = _perps(ux, uy, (mid[0] + 1e-6, mid[1] + 1e-3))
    quarter = ((3 * free_end[0] + mid[0]) / 4, (3 * free_end[1] + mid[1]) / 4)
    return Spec(
        a.name if text is None else text,
        "velocity",
        ((mid, (p1, p2)), (free_end, (outward, p1, p2)), (quarter, (p1, p2)), (mid, AROUND)),
    )


def _ring(b: Body) -> tuple[tuple[Point, tuple[Point, ...]], ...]:
    """Anchors on a body's outline, each with its outward direction (below and above first)."""
    order = [AROUND[k] for k in (8, 0, 4, 12, 6, 10, 2, 14)]
    return tuple(((b.x + b.r * ux, b.y + b.r * uy), ((ux, uy),)) for ux, uy in order)


def _frame_shapes(
    p: Problem, fr: Frame, A: Body, B: Body | None, arrows: list[Arrow]
) -> tuple[list[Shape], list[Spec]]:
    """The bodies (or the wall), the line of impact n (reaching past any arrow that lies
    along it, so that their heads stay apart) and the plane of contact t."""
    shapes: list[Shape] = [A]
    specs = [Spec(p.labels[0], "body", _ring(A), home=A, inside=True)]
    span = max(A.r, B.r if B else 0.0)
    if B is not None:
        shapes.append(B)
        specs.append(Spec(p.labels[1], "body", _ring(B), home=B, inside=True))
        n_end, t_half = B.r * 2 + 0.8, span + 0.8
    else:
        half = A.r + 0.9
        face = Surface(*fr.at(0, -half), *fr.at(0, half), *fr.n, p.name_B or "wall")
        shapes.append(face)
        tip = fr.at(0.5 * 0.3, half)
        specs.append(Spec(face.name, "surface", ((tip, (fr.t, fr.n, *AROUND)),), math=False))
        n_end, t_half = 1.0, half + 0.6
    along = [fr.along(x, y) for a in arrows for x, y in ((a.x1, a.y1), (a.x2, a.y2)) if abs(fr.across(x, y)) < 0.3]
    if B is not None and along:
        n_end = max(n_end, max(along) + 0.6)
    n_axis = Axis(*fr.at(-2 * A.r - 0.5, 0), *fr.at(n_end, 0), "n")
    t_axis = Axis(*fr.at(0, -t_half), *fr.at(0, t_half), "t", dashed=True)
    shapes += [n_axis, t_axis]
    for ax, along in ((n_axis, fr.n), (t_axis, fr.t)):
        specs.append(Spec(ax.name, "axis", (((ax.x2, ax.y2), (along, *AROUND)),)))
    return shapes, specs


def _blocked(a: Arrow, others: list[Body], fr: Frame, wall: bool) -> bool:
    """True when an arrow would run into another body, or through the wall."""
    if wall and max(fr.along(a.x1, a.y1), fr.along(a.x2, a.y2)) > -0.01:
        return True
    for b in others:
        dx, dy = a.x2 - a.x1, a.y2 - a.y1
        k = max(0.0, min(1.0, ((b.x - a.x1) * dx + (b.y - a.y1) * dy) / (dx * dx + dy * dy)))
        if math.hypot(a.x1 + k * dx - b.x, a.y1 + k * dy - b.y) < b.r + 0.05:
            return True
    return False


def _arrow(
    body: Body, d: Point, length: float, name: str, after: bool, room: Callable[[Arrow], bool]
) -> tuple[Arrow, int]:
    """A velocity arrow on the ray through the body's centre, starting at its outline: after
    the impact leaving it ahead (side +1), before it arriving from behind (side -1); the
    other way round when that side is taken by the other body or the wall. A ``length``
    under :data:`ARROW_MIN` is drawn at it, the arrow marked ``lengthened``."""
    longer = length < ARROW_MIN
    r0, r1 = body.r + 0.06, body.r + 0.06 + max(length, ARROW_MIN)
    ahead = Arrow(body.x + r0 * d[0], body.y + r0 * d[1], body.x + r1 * d[0], body.y + r1 * d[1], name, longer)
    behind = Arrow(body.x - r1 * d[0], body.y - r1 * d[1], body.x - r0 * d[0], body.y - r0 * d[1], name, longer)
    first, second = ((ahead, 1), (behind, -1)) if after else ((behind, -1), (ahead, 1))
    return first if room(first[0]) or not room(second[0]) else second


def _angle(centre: Body, ref: Point, d: Point, name: str, guide: bool) -> tuple[list[Shape], Spec | None]:
    """The arc from direction ``ref`` to ``d`` at a body's centre, its guide line and label."""
    start = math.degrees(math.atan2(ref[1], ref[0]))
    sweep = (math.degrees(math.atan2(d[1], d[0])) - start + 540) % 360 - 180
    if abs(math.radians(sweep)) * ARC_R < MIN_ARC or abs(abs(sweep) - 180) < 1:
        return [], None  # an arc too short to see (2.86° in 4.C.12) is not drawn, nor labelled
    arc = Arc(centre.x, centre.y, ARC_R, start, start + sweep, name)
    shapes: list[Shape] = [arc]
    if guide:
        reach = ARC_R + 0.45
        shapes.append(Guide(centre.x, centre.y, centre.x + reach * ref[0], centre.y + reach * ref[1]))
    anchors = []
    for frac in (0.5, 0.3, 0.7):
        a = math.radians(start + frac * sweep)
        u = (math.cos(a), math.sin(a))
        anchors.append(((centre.x + ARC_R * u[0], centre.y + ARC_R * u[1]), (u,)))
    mid = math.radians(start + sweep / 2)  # beside the arc's middle, any side, before the centre
    u_mid = (math.cos(mid), math.sin(mid))
    anchors.append(((centre.x + ARC_R * u_mid[0], centre.y + ARC_R * u_mid[1]), AROUND))
    # where the wedge is too narrow for it: just outside the body, across from the arc's opening
    anchors.append(((centre.x + centre.r * u_mid[0], centre.y + centre.r * u_mid[1]), (u_mid,)))
    anchors.append(((centre.x, centre.y), AROUND))
    return shapes, Spec(name, "angle", tuple(anchors), home=centre)


def _unit(fr: Frame, vel: tuple[float, float]) -> Point:
    dx, dy = fr.at(*vel)
    size = math.hypot(dx, dy)
    return dx / size, dy / size


def scales(vel: dict[str, tuple[float, float]]) -> dict[str, float]:
    """Centimetres per unit of speed, before ("1") and after ("2"): one scale for both,
    unless one figure's greatest speed is under a quarter of the other's (a bullet that
    lodges), when each figure has its own."""
    top = {k: max((math.hypot(*v) for b, v in vel.items() if b[1] == k), default=0.0) for k in "12"}
    both = max(top.values())
    if both == 0:
        return {"1": 1.0, "2": 1.0}
    if min(top.values()) > 0 and min(top.values()) < both / 4:
        return {k: ARROW_MAX / top[k] for k in "12"}
    return {k: ARROW_MAX / both for k in "12"}


def _motion_shapes(
    solution: Solution, fr: Frame, bodies: dict[str, Body], vel: dict[str, tuple[float, float]], after: bool
) -> tuple[list[Shape], list[Spec]]:
    """Velocity arrows to scale (none shorter than :data:`ARROW_MIN`), the angles of their
    directions, "= 0" for a body at rest."""
    p = solution.problem
    stage = "2" if after else "1"
    scale = scales(vel)[stage]
    shapes: list[Shape] = []
    specs: list[Spec] = []
    for b, body in bodies.items():
        v = vel.get(b + stage)
        name = f"v_{b}{stage}"
        if v is None:
            continue
        if math.hypot(*v) * scale < 1e-6:
            specs.append(Spec(_label(solution, name), "velocity", _ring(body), tail=" = 0"))
            continue
        others = [o for o in bodies.values() if o is not body]
        d = _unit(fr, v)
        arrow, side = _arrow(
            body, d, math.hypot(*v) * scale, name, after, lambda a, o=others: not _blocked(a, o, fr, p.fixed_B)
        )
        shapes.append(arrow)
        free, outward = ((arrow.x2, arrow.y2), d) if side > 0 else ((arrow.x1, arrow.y1), (-d[0], -d[1]))
        specs.append(arrow_spec(arrow, free, outward, _label(solution, name)))
        leg = (side * d[0], side * d[1])
        found = _after_angles(p, b, fr, d) if after else _before_angle(p, b, fr)
        for ref, label, guide in found:
            more, spec = _angle(body, (side * ref[0], side * ref[1]), leg, label, guide)
            if more:  # the arrow's own leg of the angle, from the centre to the arrow
                more.append(Guide(body.x, body.y, body.x + (body.r + 0.06) * leg[0], body.y + (body.r + 0.06) * leg[1]))
            shapes += more
            specs += [spec] if spec else []
    return shapes, specs


def _before_angle(p: Problem, b: str, fr: Frame) -> list[tuple[Point, str, bool]]:
    """The given angle of a velocity: the axis it is measured from, its name, and whether
    that axis needs a guide line (it is not the line of impact)."""
    motion = p.motion_A if b == "A" else p.motion_B
    if motion.angle is None or motion.axis_from is None:
        return []
    return [(fr.axis(motion.axis_from), motion.angle.name, motion.axis_from[1] != "n")]


def _after_angles(p: Problem, b: str, fr: Frame, d: Point) -> list[tuple[Point, str, bool]]:
    """The directions the problem asks for: theta from +t, beta from +n; the acute angles
    alpha with the line of centres and gamma with the plane of contact, from whichever
    sense of n or t the velocity ``d`` leans to."""
    out = []
    if f"theta_{b}2" in p.find:
        out.append((fr.t, f"theta_{b}2", True))
    if f"beta_{b}2" in p.find:
        out.append((fr.n, f"beta_{b}2", False))
    for name, axis, guide in ((f"alpha_{b}2", fr.n, False), (f"gamma_{b}2", fr.t, True)):
        if name in p.find:
            sense = 1 if axis[0] * d[0] + axis[1] * d[1] >= 0 else -1
            out.append(((sense * axis[0], sense * axis[1]), name, guide))
    return out


def _xy_axes(shapes: list[Shape], fr: Frame) -> tuple[list[Shape], list[Spec]]:
    """Small x-y axes left of the drawing, for problems posed in x-y, with the angle the
    statement gives between x and the line of impact n (a dotted n beside them)."""
    x0, y0, _, _ = Figure("", tuple(shapes)).bounds(pad=0.0)
    ox, oy = x0 - 1.9, y0 + 0.1
    axes = [Axis(ox, oy, ox + 1.2, oy, "x"), Axis(ox, oy, ox, oy + 1.2, "y")]
    specs = [Spec(a.name, "axis", (((a.x2, a.y2), (d, *AROUND)),)) for a, d in zip(axes, ((1, 0), (0, 1)), strict=True)]
    out: list[Shape] = list(axes)
    phi = math.degrees(math.atan2(fr.n[1], fr.n[0]))
    if abs(math.radians(phi)) * 0.8 >= MIN_ARC and abs(abs(phi) - 90) > 1:
        out.append(Guide(ox, oy, ox + 1.2 * fr.n[0], oy + 1.2 * fr.n[1]))
        mid = math.radians(phi / 2)
        out.append(Arc(ox, oy, 0.8, 0.0, phi, "phi"))
        where = (ox + 0.8 * math.cos(mid), oy + 0.8 * math.sin(mid))
        text = f"{phi:.3g}°".replace("-", "−")
        specs.append(Spec(text, "angle", ((where, ((math.cos(mid), math.sin(mid)), *AROUND)),), math=False))
        specs.append(Spec("n", "axis", (((ox + 1.2 * fr.n[0], oy + 1.2 * fr.n[1]), (fr.n, *AROUND)),)))
    return out, specs


def describe(
    solution: Solution,
    after: bool = False,
    *,
    falls: bool | None = None,
    values: Mapping | None = None,
    numbers: Numbers = number,
) -> Figure:
    """The figure of an impact, before it or (``after``) after it.

    ``falls`` draws n pointing down (see the module docstring; by default, a fixed
    floor does); ``values`` gives numbers to symbols the solution leaves open (a
    chain's later results); ``numbers`` turns an expression into a float (default
    :func:`~derive.writers.figure.frame.number`). A chain gives the figure of its first impact.
    """
    first = next((st for st in solution.stages if st.part is not None), None)
    if first is not None:  # a chain: its first impact
        down = chain_falls(solution)[first.number] if falls is None else falls
        return describe(first.part, after, falls=down, values={**solution.values, **(values or {})}, numbers=numbers)
    p = solution.problem
    known = {**solution.values, **(values or {})}
    fr = frame(p, bool(falls), known, numbers)
    rA, rB = radii(p, numbers)
    A = Body(*fr.at(-rA, 0), rA, "A")
    B = None if p.fixed_B else Body(*fr.at(rB, 0), rB, "B")
    bodies = {"A": A} if B is None else {"A": A, "B": B}
    moved = [c for key, pair in _components(solution).items() if key.endswith("2") for c in pair if c is not None]
    stand_ins = restitution_drawn(p, known, moved, numbers) if after else {}
    vel = velocities(solution, {**stand_ins, **known}, numbers)
    more, more_specs = _motion_shapes(solution, fr, bodies, vel, after)
    shapes, specs = _frame_shapes(p, fr, A, B, [s for s in more if isinstance(s, Arrow)])
    shapes += more
    specs += more_specs
    if fr.xy:
        axes, axis_specs = _xy_axes(shapes, fr)
        shapes += axes
        specs += axis_specs
    title = "After the impact" if after else "Before the impact"
    specs.sort(key=lambda s: ORDER[s.role])  # the most constrained labels first
    own = scales(vel)
    longer = tuple(  # named as the labels name them (a chain stage that calls A "B")
        (_label(solution, a.name), speed_words(solution, a.name[2:], math.hypot(*vel[a.name[2:]]), known))
        for a in more
        if isinstance(a, Arrow) and a.lengthened
    )
    return Figure(
        title,
        tuple(shapes),
        place(specs, shapes),
        own_scale=own["1"] != own["2"],
        lengthened=longer,
        schematic=_masses_drawn_otherwise(p, values or {}, numbers),
        drawn_for=tuple((s.name, f"{float(v):g}") for s, v in stand_ins.items()),
    )


def _masses_drawn_otherwise(p: Problem, values: Mapping, numbers: Numbers) -> bool:
    """True for a variant whose masses are not the statement's while the radii drawn are the
    stated ones: its figure's sizes say nothing of its bodies (B may be denser than gold)."""
    if getattr(p, "sizes_schematic", False):
        return True
    given = {g.name: g for g in p.givens}
    if not ("r_A" in given and "r_B" in given):
        return False
    for name in ("m_A", "m_B", "W_A", "W_B"):
        g = given.get(name)
        if g is None or g.symbol not in values:
            continue
        if g.value is None and name in p.vary:  # a compiled variant's mass: its own number
            return True
        if g.value is None:
            continue
        stated, drawn = numbers(g.value, p.numeric()), numbers(values[g.symbol], p.numeric())
        if stated is not None and drawn is not None and abs(stated - drawn) > 1e-9 * max(1.0, abs(stated)):
            return True
    return False


def _label(solution: Any, name: str) -> str:
    """A velocity's label: a chain stage's own name for it (u_B, w_B), else its name under
    the stage's letters (v_B1 where the stage calls A "B")."""
    own = getattr(solution, "names", {}).get(name)
    return own if own is not None else relabel(name, solution.problem.labels)
