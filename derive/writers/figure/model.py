"""A figure as plain geometry: shapes and placed labels, in centimetres, y up.

Nothing here knows the physics or a drawing format. :mod:`.scene` fills these
records from a solution, :mod:`.layout` places the labels, :mod:`.svg` and
:mod:`.tikz` draw them. One drawing unit is one centimetre on the printed page.
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Callable
from dataclasses import dataclass, field

Point = tuple[float, float]
Segment = tuple[Point, Point]

HEAD = 0.28  # length of an arrowhead
HATCH = 0.3  # depth of a wall's hatching


@dataclass(frozen=True)
class Body:
    """A body drawn as a circle of radius ``r`` about its centre."""

    x: float
    y: float
    r: float
    name: str


@dataclass(frozen=True)
class Surface:
    """A fixed wall or floor: its face from (x1, y1) to (x2, y2), hatched on the side (nx, ny)."""

    x1: float
    y1: float
    x2: float
    y2: float
    nx: float
    ny: float
    name: str


@dataclass(frozen=True)
class Axis:
    """An axis (n, t, x or y): a line with an arrowhead at (x2, y2)."""

    x1: float
    y1: float
    x2: float
    y2: float
    name: str
    dashed: bool = False


@dataclass(frozen=True)
class Arrow:
    """A velocity, to scale with speed: from (x1, y1) to its head at (x2, y2).

    ``lengthened``: the speed to scale would be shorter than the least length an arrow
    is drawn at (its direction unreadable), so it is drawn at that length instead.
    """

    x1: float
    y1: float
    x2: float
    y2: float
    name: str
    lengthened: bool = False

    @property
    def length(self) -> float:
        """The arrow's length (the speed times the figure's scale, unless ``lengthened``)."""
        return math.hypot(self.x2 - self.x1, self.y2 - self.y1)


@dataclass(frozen=True)
class Arc:
    """An angle: an arc about (x, y) from ``start`` to ``end`` (degrees, counter-clockwise from +x)."""

    x: float
    y: float
    r: float
    start: float
    end: float
    name: str


@dataclass(frozen=True)
class Guide:
    """A thin dotted line that an angle is measured from (an axis moved to a body's centre)."""

    x1: float
    y1: float
    x2: float
    y2: float


@dataclass(frozen=True)
class Label:
    """A label placed at its centre (x, y) with its estimated extent w x h.

    ``text`` is a symbol name (``v_A1``, ``theta_1``) when ``math`` is true, else
    words; ``tail`` follows it (`` = 0``); ``role`` sets its style.
    """

    text: str
    x: float
    y: float
    w: float
    h: float
    role: str
    math: bool = True
    tail: str = ""

    @property
    def box(self) -> tuple[float, float, float, float]:
        """(left, bottom, right, top)."""
        return self.x - self.w / 2, self.y - self.h / 2, self.x + self.w / 2, self.y + self.h / 2


Shape = Body | Surface | Axis | Arrow | Arc | Guide


@dataclass(frozen=True)
class Figure:
    """Shapes and labels of one figure; ``title`` names it (before or after the impact).

    How it is drawn, for its caption: ``own_scale`` when the figures before and after
    each have a scale of their own; ``lengthened`` the arrows drawn longer than to
    scale, each as (name, speed in words, "" when the speed is a symbol's).
    """

    title: str
    shapes: tuple[Shape, ...] = ()
    labels: tuple[Label, ...] = field(default_factory=tuple)
    own_scale: bool = False
    lengthened: tuple[tuple[str, str], ...] = ()
    schematic: bool = False  # the bodies' sizes are not this variant's (its masses vary, the radii do not)
    drawn_for: tuple[tuple[str, str], ...] = ()  # (name, value) of a letter drawn at a number (e = 0.5)

    @property
    def caption(self) -> str:
        """How the figure is drawn, in plain text: "arrows to scale with speed, ..."."""
        return self.scale_note()

    def scale_note(self, name: Callable[[str], str] = str, text: Callable[[str], str] = str) -> str:
        """The caption, with ``name`` writing a velocity's name (``v_A2``) and ``text``
        escaping the words around it, for the page the caption goes on."""
        out = text("arrows to scale with speed")
        if self.own_scale:
            out += text(", a scale of their own in each figure")
        if self.lengthened:
            each = [name(n) + (text(f" ({speed})") if speed else "") for n, speed in self.lengthened]
            listed = each[0] if len(each) == 1 else ", ".join(each[:-1]) + text(" and ") + each[-1]
            whose = "its direction" if len(each) == 1 else "their directions"
            out += text(", except ") + listed + text(f", drawn longer to show {whose}")
        if self.schematic:
            out += text("; the bodies' sizes are schematic (the radii stated, not this variant's masses)")
        if self.drawn_for:
            each = [name(n) + text(f" = {v}") for n, v in self.drawn_for]
            out += text("; drawn for ") + (text(", ").join(each)) + text(", a letter in the problem")
        return out

    def bounds(self, pad: float = 0.25) -> tuple[float, float, float, float]:
        """(left, bottom, right, top) of everything drawn, with ``pad`` around."""
        xs: list[float] = []
        ys: list[float] = []
        for s in self.shapes:
            if isinstance(s, Body):
                xs += [s.x - s.r, s.x + s.r]
                ys += [s.y - s.r, s.y + s.r]
            elif isinstance(s, Arc):  # its points: each inner one ends two of its strokes
                for px, py in _arc_points(s):
                    xs.append(px)
                    ys.append(py)
            else:
                for (ax, ay), (bx, by) in segments(s):
                    xs += (ax, bx)
                    ys += (ay, by)
        for lab in self.labels:
            x0, y0, x1, y1 = lab.box
            xs += [x0, x1]
            ys += [y0, y1]
        if not xs:
            return -pad, -pad, pad, pad
        return min(xs) - pad, min(ys) - pad, max(xs) + pad, max(ys) + pad

    @property
    def width(self) -> float:
        """Width in centimetres."""
        x0, _, x1, _ = self.bounds()
        return x1 - x0

    @property
    def height(self) -> float:
        """Height in centimetres."""
        _, y0, _, y1 = self.bounds()
        return y1 - y0


def head(x1: float, y1: float, x2: float, y2: float) -> list[Segment]:
    """The two sides of an arrowhead at (x2, y2) on the line from (x1, y1)."""
    length = math.hypot(x2 - x1, y2 - y1)
    if length == 0:
        return []
    size = min(HEAD, 0.6 * length)
    ux, uy = (x2 - x1) / length, (y2 - y1) / length
    bx, by = x2 - size * ux, y2 - size * uy
    w = 0.4 * size
    return [((x2, y2), (bx - w * uy, by + w * ux)), ((x2, y2), (bx + w * uy, by - w * ux))]


def arc_points(a: Arc) -> list[Point]:
    """Points along an arc (25, 24 steps apart), for drawing checks."""
    return list(_arc_points(a))


@functools.lru_cache(maxsize=64)  # a figure's arcs are met by its layout, its bounds and its drawing
def _arc_points(a: Arc) -> tuple[Point, ...]:
    out = []
    for i in range(25):
        ang = math.radians(a.start + (a.end - a.start) * i / 24)
        out.append((a.x + a.r * math.cos(ang), a.y + a.r * math.sin(ang)))
    return tuple(out)


def hatch_ticks(s: Surface) -> list[Segment]:
    """The short slanted strokes behind a wall's face (13, at 12 equal steps along it)."""
    length = math.hypot(s.x2 - s.x1, s.y2 - s.y1)
    ux, uy = (s.x2 - s.x1) / length, (s.y2 - s.y1) / length
    out = []
    for i in range(13):
        px, py = s.x1 + (s.x2 - s.x1) * i / 12, s.y1 + (s.y2 - s.y1) * i / 12
        out.append(((px, py), (px + HATCH * (s.nx - ux), py + HATCH * (s.ny - uy))))
    return out


def segments(s: Shape) -> list[Segment]:
    """Every stroke of a shape but a body's circle, as straight segments."""
    if isinstance(s, (Axis, Arrow)):
        return [((s.x1, s.y1), (s.x2, s.y2)), *head(s.x1, s.y1, s.x2, s.y2)]
    if isinstance(s, Guide):
        return [((s.x1, s.y1), (s.x2, s.y2))]
    if isinstance(s, (Surface, Arc)):
        return list(_many_segments(s))
    return []


@functools.lru_cache(maxsize=64)  # a figure's arcs and walls are met by its layout and its bounds
def _many_segments(s: Surface | Arc) -> tuple[Segment, ...]:
    if isinstance(s, Surface):
        return (((s.x1, s.y1), (s.x2, s.y2)), *hatch_ticks(s))
    return tuple(itertools.pairwise(arc_points(s)))
