"""Figures of an impact as geometry: bodies at contact, the n and t axes, velocity arrows.

:func:`describe` turns a Solution into a :class:`Figure` (shapes in drawing units,
y up); :func:`to_svg` and :func:`to_tikz` only draw it. The figure reads the
solution's numbers; it does no physics of its own.
"""

from __future__ import annotations

import html
import math
from dataclasses import dataclass, field

import sympy

from derive import escape
from derive.steps.model import Solution
from derive.symbols import latex_name, symbol

MIN_ARROW = 1.3  # drawing units: the shortest arrow still readable
MAX_ARROW = 2.8


@dataclass(frozen=True)
class Circle:
    x: float
    y: float
    r: float
    label: str
    lx: float = 0.0  # where the label goes
    ly: float = 0.0


@dataclass(frozen=True)
class Line:
    x1: float
    y1: float
    x2: float
    y2: float
    label: str = ""
    dashed: bool = False


@dataclass(frozen=True)
class Arrow:
    x1: float
    y1: float
    x2: float
    y2: float
    label: str
    lx: float = 0.0  # where the label goes
    ly: float = 0.0


@dataclass(frozen=True)
class Arc:
    x: float
    y: float
    r: float
    start: float  # degrees, counter-clockwise from +x of the drawing
    end: float
    label: str


@dataclass(frozen=True)
class Surface:
    """A fixed wall or floor: a line with hatching on the side ``(nx, ny)`` points to."""

    x1: float
    y1: float
    x2: float
    y2: float
    nx: float
    ny: float
    label: str


@dataclass(frozen=True)
class Figure:
    title: str
    shapes: tuple[object, ...] = field(default_factory=tuple)

    def bounds(self) -> tuple[float, float, float, float]:
        xs, ys = [], []
        for s in self.shapes:
            if isinstance(s, Circle):
                xs += [s.x - s.r, s.x + s.r, s.lx]
                ys += [s.y - s.r, s.y + s.r, s.ly]
            elif isinstance(s, (Line, Arrow, Surface)):
                xs += [s.x1, s.x2]
                ys += [s.y1, s.y2]
                if isinstance(s, Arrow):
                    xs.append(s.lx)
                    ys.append(s.ly)
            elif isinstance(s, Arc):
                xs += [s.x - s.r, s.x + s.r]
                ys += [s.y - s.r, s.y + s.r]
        pad = 0.6
        return min(xs) - pad, min(ys) - pad, max(xs) + pad, max(ys) + pad


def _num(expr: sympy.Expr | None) -> float | None:
    if expr is None:
        return None
    if getattr(expr, "free_symbols", None):
        return None
    try:
        value = complex(sympy.N(expr))
    except (TypeError, ValueError):
        return None
    return value.real if abs(value.imag) < 1e-12 and math.isfinite(value.real) else None


def _direction(n: sympy.Expr, t: sympy.Expr) -> tuple[float, float, float | None] | None:
    """Unit direction (n, t) of a velocity and its speed (None when symbolic)."""
    nv, tv = _num(n), _num(t)
    if nv is not None and tv is not None:
        speed = math.hypot(nv, tv)
        if speed < 1e-12:
            return None
        return nv / speed, tv / speed, speed
    # a symbolic speed: the direction may still be known (every symbol positive)
    syms = (n.free_symbols | t.free_symbols) if hasattr(n, "free_symbols") else set()
    at = dict.fromkeys(syms, 1)
    nv, tv = _num(sympy.sympify(n).xreplace(at)), _num(sympy.sympify(t).xreplace(at))
    if nv is None or tv is None or math.hypot(nv, tv) < 1e-12:
        return None
    speed = math.hypot(nv, tv)
    return nv / speed, tv / speed, None


def describe(solution: Solution, after: bool = False) -> Figure:
    """The figure of stage 1 (before the impact) or of the answer (``after``); for a
    chain, that of its first impact (each impact stage draws its own)."""
    impacts = [st.part for st in solution.stages if st.part is not None]
    if impacts:
        return describe(impacts[0], after)
    p = solution.problem
    values = dict(solution.values)
    phi = _num(values.get(p.phi)) if p.phi is not None else 0.0
    phi = phi or 0.0
    nx, ny = math.cos(phi), math.sin(phi)
    tx, ty = -ny, nx

    def at(a: float, b: float) -> tuple[float, float]:  # n, t -> drawing x, y
        return a * nx + b * tx, a * ny + b * ty

    rA = rB = 1.0
    given = {g.name: g for g in p.givens}
    if "r_A" in given and "r_B" in given:
        a, b = _num(given["r_A"].value), _num(given["r_B"].value)
        if a and b and a > 0 and b > 0:
            rA, rB = 2 * a / (a + b), 2 * b / (a + b)
    shapes: list[object] = []
    cA = at(-rA, 0)
    cB = at(rB, 0)
    shapes.append(Circle(*cA, rA, "A", *at(-2 * rA - 0.35, -0.4)))
    if p.fixed_B:
        half = max(rA, 1.0) + 1.2
        shapes.append(Surface(*at(0, -half), *at(0, half), nx, ny, p.name_B or "wall"))
    else:
        shapes.append(Circle(*cB, rB, "B", *at(2 * rB + 0.35, -0.4)))
    reach = (rB if not p.fixed_B else 0.8) + 1.0
    shapes.append(Line(*at(-2 * rA - 0.8, 0), *at(reach + rB * 0.2, 0), "n"))
    span = max(rA, rB) + 0.9
    shapes.append(Line(*at(0, -span), *at(0, span), "t", dashed=True))

    suffix = "2" if after else "1"
    arrows = []
    for b, centre in (("A", cA), ("B", cB)):
        if b == "B" and p.fixed_B:
            continue
        if after:
            n, t = _value(solution, f"v_{b}2n"), _value(solution, f"v_{b}2t")
            if not p.oblique:
                n, t = _value(solution, f"v_{b}2"), sympy.Integer(0)
        else:
            motion = p.motion_A if b == "A" else p.motion_B
            n, t = (
                motion.n.xreplace(_independent(p)).xreplace(values),
                motion.t.xreplace(_independent(p)).xreplace(values),
            )
        d = _direction(n, t)
        arrows.append((b, centre, d))
    known = [d[2] for _, _, d in arrows if d is not None and d[2] is not None]
    scale = MAX_ARROW / max(known) if known else 1.0
    for b, centre, d in arrows:
        name = f"v_{b}{suffix}"
        if d is None:
            continue
        un, ut, speed = d
        length = MIN_ARROW + 0.6 if speed is None else min(MAX_ARROW, max(MIN_ARROW, speed * scale))
        dx, dy = at(un * length, ut * length)
        ox, oy = at(-ut * 0.3, un * 0.3)  # labels sit beside the arrow, off its line
        if after:  # leaving the centre
            tip = (centre[0] + dx, centre[1] + dy)
            shapes.append(Arrow(*centre, *tip, name, tip[0] + ox + 0.1 * dx, tip[1] + oy + 0.1 * dy))
        else:  # arriving at the centre
            tail = (centre[0] - dx, centre[1] - dy)
            shapes.append(Arrow(*tail, *centre, name, tail[0] + ox - 0.1 * dx, tail[1] + oy - 0.1 * dy))
        if not after:
            motion = p.motion_A if b == "A" else p.motion_B
            if motion.angle is not None and motion.axis_from is not None and motion.axis_from[1] in "nt":
                # the angle between the incoming arrow and the reversed axis (vertical angles)
                ax = {"+n": (-1, 0), "-n": (1, 0), "+t": (0, -1), "-t": (0, 1)}[motion.axis_from]
                start = math.degrees(math.atan2(*reversed(at(*ax))))
                end = math.degrees(math.atan2(-dy, -dx))
                sweep = (end - start + 540) % 360 - 180
                if abs(sweep) > 1:
                    r = 0.55 * (rA if b == "A" else rB) + 0.25
                    shapes.append(Arc(centre[0], centre[1], r, start, start + sweep, motion.angle.name))
    title = "After the impact" if after else "Before the impact"
    return Figure(title, tuple(shapes))


def _value(solution: Solution, name: str) -> sympy.Expr:
    r = solution.results.get(name)
    if r is None:
        return sympy.Integer(0)
    return r.value if r.value is not None else r.partial


def _independent(p) -> dict:
    from derive.physics.impact import independent_map

    return independent_map(p)


# ------------------------------------------------------------------ SVG

PX = 46.0  # pixels per drawing unit


def _svg_label(name: str) -> str:
    """``v_A1`` -> v<tspan>A1</tspan> (subscript); Greek names as letters."""
    base, _, sub = name.partition("_")
    greek = {"theta": "θ", "phi": "φ", "alpha": "α", "beta": "β", "gamma": "γ", "psi": "ψ"}
    head = html.escape(greek.get(base, base))
    if not sub:
        return head
    return f'{head}<tspan baseline-shift="sub" font-size="70%">{html.escape(sub)}</tspan>'


def to_svg(fig: Figure) -> str:
    """The figure as a standalone SVG element (no scripts, no external references)."""
    x0, y0, x1, y1 = fig.bounds()
    w, h = (x1 - x0) * PX, (y1 - y0) * PX

    def X(x: float) -> float:
        return round((x - x0) * PX, 2)

    def Y(y: float) -> float:
        return round((y1 - y) * PX, 2)

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0f}" height="{h:.0f}" '
        f'viewBox="0 0 {w:.2f} {h:.2f}" role="img" aria-label="{html.escape(fig.title)}" '
        'font-family="serif" font-size="15">',
        f"<title>{html.escape(fig.title)}</title>",
        '<defs><marker id="arrowhead" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" markerHeight="7" '
        'orient="auto-start-reverse"><path d="M0,0 L10,5 L0,10 z" fill="#b00"/></marker></defs>',
    ]
    for s in fig.shapes:
        if isinstance(s, Circle):
            out.append(
                f'<circle cx="{X(s.x)}" cy="{Y(s.y)}" r="{s.r * PX:.2f}" fill="#eef2f8" stroke="#223" stroke-width="1.5"/>'
            )
            out.append(
                f'<text x="{X(s.lx)}" y="{Y(s.ly)}" font-weight="bold" text-anchor="middle" '
                f'dominant-baseline="middle">{_svg_label(s.label)}</text>'
            )
        elif isinstance(s, Line):
            dash = ' stroke-dasharray="6 4"' if s.dashed else ""
            out.append(
                f'<line x1="{X(s.x1)}" y1="{Y(s.y1)}" x2="{X(s.x2)}" y2="{Y(s.y2)}" stroke="#555" stroke-width="1"{dash}/>'
            )
            out.append(f'<text x="{X(s.x2) + 4}" y="{Y(s.y2) - 4}" font-style="italic">{_svg_label(s.label)}</text>')
        elif isinstance(s, Surface):
            out.append(
                f'<line x1="{X(s.x1)}" y1="{Y(s.y1)}" x2="{X(s.x2)}" y2="{Y(s.y2)}" stroke="#222" stroke-width="2.5"/>'
            )
            steps = 10
            for i in range(steps + 1):
                px = s.x1 + (s.x2 - s.x1) * i / steps
                py = s.y1 + (s.y2 - s.y1) * i / steps
                qx = px + 0.3 * s.nx + 0.3 * (s.x2 - s.x1) / math.hypot(s.x2 - s.x1, s.y2 - s.y1) * -1
                qy = py + 0.3 * s.ny + 0.3 * (s.y2 - s.y1) / math.hypot(s.x2 - s.x1, s.y2 - s.y1) * -1
                out.append(
                    f'<line x1="{X(px)}" y1="{Y(py)}" x2="{X(qx)}" y2="{Y(qy)}" stroke="#222" stroke-width="1"/>'
                )
            out.append(f'<text x="{X(s.x2) + 6}" y="{Y(s.y2) + 4}">{html.escape(s.label)}</text>')
        elif isinstance(s, Arrow):
            out.append(
                f'<line x1="{X(s.x1)}" y1="{Y(s.y1)}" x2="{X(s.x2)}" y2="{Y(s.y2)}" stroke="#b00" stroke-width="2" '
                'marker-end="url(#arrowhead)"/>'
            )
            out.append(
                f'<text x="{X(s.lx)}" y="{Y(s.ly)}" fill="#b00" font-style="italic" text-anchor="middle" '
                f'dominant-baseline="middle">{_svg_label(s.label)}</text>'
            )
        elif isinstance(s, Arc):
            a0, a1 = math.radians(s.start), math.radians(s.end)
            sx, sy = s.x + s.r * math.cos(a0), s.y + s.r * math.sin(a0)
            ex, ey = s.x + s.r * math.cos(a1), s.y + s.r * math.sin(a1)
            sweep = 0 if s.end > s.start else 1
            large = 1 if abs(s.end - s.start) > 180 else 0
            out.append(
                f'<path d="M{X(sx)},{Y(sy)} A{s.r * PX:.2f},{s.r * PX:.2f} 0 {large},{sweep} {X(ex)},{Y(ey)}" '
                'fill="none" stroke="#06c" stroke-width="1.2"/>'
            )
            mid = math.radians((s.start + s.end) / 2)
            lx, ly = s.x + (s.r + 0.3) * math.cos(mid), s.y + (s.r + 0.3) * math.sin(mid)
            out.append(
                f'<text x="{X(lx) - 5}" y="{Y(ly) + 5}" fill="#06c" font-style="italic">{_svg_label(s.label)}</text>'
            )
    out.append("</svg>")
    return "".join(out)


# ------------------------------------------------------------------ TikZ


def to_tikz(fig: Figure) -> str:
    """The figure as a tikzpicture (1 drawing unit = 1 cm)."""
    out = [r"\begin{tikzpicture}[>=stealth, scale=0.9]"]

    def lab(name: str) -> str:
        return "$" + latex_name(name) + "$"  # Greek names (alpha, theta_1) as letters

    for s in fig.shapes:
        if isinstance(s, Circle):
            out.append(rf"\draw[fill=blue!6] ({s.x:.3f},{s.y:.3f}) circle ({s.r:.3f});")
            out.append(rf"\node at ({s.lx:.3f},{s.ly:.3f}) {{\textbf{{{s.label}}}}};")
        elif isinstance(s, Line):
            style = "dashed, gray" if s.dashed else "gray"
            out.append(
                rf"\draw[{style}] ({s.x1:.3f},{s.y1:.3f}) -- ({s.x2:.3f},{s.y2:.3f}) node[anchor=south west] {{{lab(s.label)}}};"
            )
        elif isinstance(s, Surface):
            out.append(
                rf"\draw[very thick] ({s.x1:.3f},{s.y1:.3f}) -- ({s.x2:.3f},{s.y2:.3f}) node[anchor=west] {{{escape.tex(s.label)}}};"
            )
            length = math.hypot(s.x2 - s.x1, s.y2 - s.y1)
            ux, uy = (s.x2 - s.x1) / length, (s.y2 - s.y1) / length
            for i in range(11):
                px, py = s.x1 + (s.x2 - s.x1) * i / 10, s.y1 + (s.y2 - s.y1) * i / 10
                qx, qy = px + 0.3 * s.nx - 0.3 * ux, py + 0.3 * s.ny - 0.3 * uy
                out.append(rf"\draw ({px:.3f},{py:.3f}) -- ({qx:.3f},{qy:.3f});")
        elif isinstance(s, Arrow):
            out.append(rf"\draw[->, very thick, red!70!black] ({s.x1:.3f},{s.y1:.3f}) -- ({s.x2:.3f},{s.y2:.3f});")
            out.append(rf"\node[red!70!black] at ({s.lx:.3f},{s.ly:.3f}) {{{lab(s.label)}}};")
        elif isinstance(s, Arc):
            out.append(
                rf"\draw[blue!70!black] ({s.x:.3f},{s.y:.3f}) ++({s.start:.2f}:{s.r:.3f}) "
                rf"arc[start angle={s.start:.2f}, end angle={s.end:.2f}, radius={s.r:.3f}];"
            )
            mid = math.radians((s.start + s.end) / 2)
            out.append(
                rf"\node[blue!70!black] at ({s.x + (s.r + 0.3) * math.cos(mid):.3f},{s.y + (s.r + 0.3) * math.sin(mid):.3f}) {{{lab(s.label)}}};"
            )
    out.append(r"\end{tikzpicture}")
    return "\n".join(out)


__all__ = ["Arc", "Arrow", "Circle", "Figure", "Line", "Surface", "describe", "symbol", "to_svg", "to_tikz"]
