"""Label placement: each label goes to the first candidate position around its anchor
whose box meets no stroke, no body outline and no label placed before it.

Text extents are estimated from the font size and the glyphs (a subscript at 70 %),
a little wider than Computer Modern and the common serif fonts, so that a box that
is free on paper is free in the drawing too.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass

from derive.writers.figure.model import Body, Label, Point, Segment, Shape, segments

EM = 0.40  # cm: the labels' font size (11 pt is 0.39 cm)
GAP = 0.07  # cm: the clearance kept around a label
SUB = 0.7  # a subscript's size relative to the text
GREEK = {"theta": "θ", "phi": "φ", "alpha": "α", "beta": "β", "gamma": "γ", "psi": "ψ", "delta": "δ"}

#: Distances (cm) from an anchor to a label's near edge, tried nearest first.
DISTANCES = (0.08, 0.22, 0.4, 0.65, 0.95, 1.3, 1.75, 2.3, 3.0)
#: Directions tried after a label's own preferences: sixteen around, from straight up.
AROUND = tuple((math.cos(math.radians(90 + 22.5 * k)), math.sin(math.radians(90 + 22.5 * k))) for k in range(16))


@dataclass(frozen=True)
class Spec:
    """A label to place: its text, its anchors (a point and the directions to try from
    it, best first; :data:`AROUND` for all), and the body it may sit inside (its own,
    or the one its angle is drawn in)."""

    text: str
    role: str
    anchors: tuple[tuple[Point, tuple[Point, ...]], ...]
    math: bool = True
    tail: str = ""
    home: Body | None = None
    inside: bool = False  # try the home body's inside first (a body's own letter)


def split(name: str) -> tuple[str, str]:
    """``v_A1`` -> ("v", "A1"); ``theta_1`` -> ("θ", "1"); words stay whole."""
    base, _, sub = name.partition("_")
    return GREEK.get(base, base), sub


#: Widths in em of the characters narrower or wider than their kind (capitals 0.76, digits 0.56, the rest 0.58).
_WIDTHS = {" ": 0.3, **dict.fromkeys("=+−-", 0.8), **dict.fromkeys("ilj.,", 0.34), "m": 0.85, "w": 0.85}


def _glyphs(text: str) -> float:
    """Width of ``text`` in em."""
    w = 0.0
    for ch in text:
        if ch in _WIDTHS:
            w += _WIDTHS[ch]
        elif ch.isupper():
            w += 0.76
        else:
            w += 0.56 if ch.isdigit() else 0.58
    return w


@functools.lru_cache(maxsize=256)  # a figure's labels are the same few texts
def extent(text: str, math_: bool = True, tail: str = "") -> tuple[float, float]:
    """The estimated width and height (cm) of a label."""
    if not math_:
        return EM * _glyphs(text) + 2 * GAP, EM * 1.05
    base, sub = split(text)
    w = _glyphs(base) + SUB * _glyphs(sub) + _glyphs(tail)
    h = 1.25 if sub else 1.05
    return EM * w + 2 * GAP, EM * h


def _box_hits_segment(box: tuple[float, float, float, float], seg: Segment) -> bool:
    """True when the segment crosses or lies in the box (Liang-Barsky clipping)."""
    x0, y0, x1, y1 = box
    (ax, ay), (bx, by) = seg
    dx, dy = bx - ax, by - ay
    lo, hi = 0.0, 1.0
    # the four sides in turn: where p < 0 the segment enters (lo rises), where p > 0 it leaves
    for p, q in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
        if p == 0:
            if q < 0:
                return False
        elif p < 0:
            r = q / p
            if r > lo:  # lo = max(lo, r)
                lo = r
                if lo > hi:
                    return False
        else:
            r = q / p
            if r < hi:  # hi = min(hi, r)
                hi = r
                if lo > hi:
                    return False
    return True


def _box_vs_disc(box: tuple[float, float, float, float], b: Body) -> str:
    """ "inside" (the whole box in the disc), "outside" (no point in it) or "across"."""
    x0, y0, x1, y1 = box
    nx, ny = min(max(b.x, x0), x1), min(max(b.y, y0), y1)
    if math.hypot(nx - b.x, ny - b.y) >= b.r:
        return "outside"
    far = max(math.hypot(cx - b.x, cy - b.y) for cx in (x0, x1) for cy in (y0, y1))
    return "inside" if far <= b.r else "across"


def _boxes_meet(a: tuple[float, float, float, float], b: tuple[float, float, float, float]) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def _grow(box: tuple[float, float, float, float], by: float) -> tuple[float, float, float, float]:
    return box[0] - by, box[1] - by, box[2] + by, box[3] + by


class Board:
    """What is drawn so far: strokes, bodies and the labels already placed."""

    def __init__(self, shapes: Iterable[Shape]) -> None:
        shapes = list(shapes)
        self.strokes: list[tuple[float, float, float, float, Segment]] = []
        #: The strokes shape by shape, each group with its bounding box first: a box that
        #: misses a group's box misses each of its strokes (an arc is 24 of them).
        self.groups: list[tuple[float, float, float, float, list[tuple[float, float, float, float, Segment]]]] = []
        inf = math.inf
        for s in shapes:
            group = []
            gx0, gy0, gx1, gy1 = inf, inf, -inf, -inf  # the group's box: no NaN in it
            for a, b in segments(s):  # min and max written out (as they compare, NaN included)
                (ax, ay), (bx, by) = a, b
                sx0, sy0 = (bx if bx < ax else ax), (by if by < ay else ay)
                sx1, sy1 = (bx if bx > ax else ax), (by if by > ay else ay)
                group.append((sx0, sy0, sx1, sy1, (a, b)))
                gx0, gy0 = (sx0 if sx0 < gx0 else gx0), (sy0 if sy0 < gy0 else gy0)
                gx1, gy1 = (sx1 if sx1 > gx1 else gx1), (sy1 if sy1 > gy1 else gy1)
            if group:
                self.strokes += group
                self.groups.append((gx0, gy0, gx1, gy1, group))
        self.bodies: list[Body] = [s for s in shapes if isinstance(s, Body)]
        self.discs = [(b.x, b.y, b.r, b) for b in self.bodies]
        self.labels: list[Label] = []
        self.boxes: list[tuple[float, float, float, float]] = []  # the labels' boxes
        self.last: tuple | None = None  # the stroke that met the last box tried: tried first

    def add(self, label: Label) -> None:
        """A label placed: later labels keep clear of it."""
        self.labels.append(label)
        self.boxes.append(label.box)

    def _hit(self, x0: float, y0: float, x1: float, y1: float, home: Body | None) -> bool:
        """True when a label's box, grown by the clearance to (x0, y0, x1, y1), touches anything
        drawn (``any(clashes)``): the likeliest and cheapest tests first (a figure tries thousands
        of boxes): the stroke that met the box tried last, labels, bodies, strokes."""
        last = self.last
        if last is not None:
            sx0, sy0, sx1, sy1, seg = last
            if sx0 <= x1 and x0 <= sx1 and sy0 <= y1 and y0 <= sy1 and _box_hits_segment((x0, y0, x1, y1), seg):
                return True
        for a0, b0, a1, b1 in self.boxes:
            if x0 < a1 and a0 < x1 and y0 < b1 and b0 < y1:
                return True
        hypot = math.hypot
        for bx, by, r, b in self.discs:
            nx = x0 if x0 > bx else bx  # min(max(bx, x0), x1), written out
            nx = x1 if x1 < nx else nx
            ny = y0 if y0 > by else by
            ny = y1 if y1 < ny else ny
            if hypot(nx - bx, ny - by) >= r:
                continue  # outside
            if b is not home or (  # inside or across another body, or across its own
                hypot(x0 - bx, y0 - by) > r
                or hypot(x0 - bx, y1 - by) > r
                or hypot(x1 - bx, y0 - by) > r
                or hypot(x1 - bx, y1 - by) > r
            ):
                return True
        for gx0, gy0, gx1, gy1, strokes in self.groups:
            if gx0 <= x1 and x0 <= gx1 and gy0 <= y1 and y0 <= gy1:
                for stroke in strokes:
                    sx0, sy0, sx1, sy1, seg = stroke
                    if sx0 <= x1 and x0 <= sx1 and sy0 <= y1 and y0 <= sy1 and _box_hits_segment((x0, y0, x1, y1), seg):
                        self.last = stroke
                        return True
        return False

    def first_free(self, points: Iterable[Point], w: float, h: float, home: Body | None) -> Point | None:
        """The first of ``points`` (centres) where a w x h label hits nothing, else None."""
        hw, hh = w / 2, h / 2
        hit = self._hit
        for cx, cy in points:
            # the box (cx - w / 2, ...) grown by the clearance, as :meth:`clashes` grows it
            if not hit(cx - hw - GAP, cy - hh - GAP, cx + hw + GAP, cy + hh + GAP, home):
                return cx, cy
        return None

    def clashes(self, box: tuple[float, float, float, float], home: Body | None) -> Iterator[bool]:
        """For each thing drawn, whether a label's box (clearance included) touches it."""
        x0, y0, x1, y1 = grown = _grow(box, GAP)
        for sx0, sy0, sx1, sy1, seg in self.strokes:
            yield sx0 <= x1 and x0 <= sx1 and sy0 <= y1 and y0 <= sy1 and _box_hits_segment(grown, seg)
        for b in self.bodies:
            where = _box_vs_disc(grown, b)
            yield where == "across" or (where == "inside" and b is not home)
        for lab in self.labels:
            yield _boxes_meet(grown, lab.box)


def candidates(spec: Spec, w: float, h: float) -> Iterable[Point]:
    """Centres to try, nearest first: inside the home body, then around each anchor."""
    if spec.inside and spec.home is not None:
        b = spec.home
        for k in (0.0, 0.45, 0.55):
            for ux, uy in ((0, 1), (0, -1), (-1, 0), (1, 0), *AROUND):
                yield b.x + k * b.r * ux, b.y + k * b.r * uy
                if not k:
                    break  # the centre, once: every direction gives it
    for d in DISTANCES:
        for (px, py), prefer in spec.anchors:
            for ux, uy in prefer:
                reach = d + abs(ux) * w / 2 + abs(uy) * h / 2
                yield px + ux * reach, py + uy * reach


def place(specs: Sequence[Spec], shapes: Iterable[Shape]) -> tuple[Label, ...]:
    """Place ``specs`` in order, each at its first free candidate (else the least crowded)."""
    board = Board(shapes)
    for spec in specs:
        w, h = extent(spec.text, spec.math, spec.tail)
        free = board.first_free(candidates(spec, w, h), w, h, spec.home)
        if free is not None:
            cx, cy = free
        else:  # nowhere free: the candidate that touches fewest things
            cx, cy = min(
                candidates(spec, w, h),
                key=lambda c: sum(board.clashes((c[0] - w / 2, c[1] - h / 2, c[0] + w / 2, c[1] + h / 2), spec.home)),
            )
        board.add(Label(spec.text, cx, cy, w, h, spec.role, spec.math, spec.tail))
    return tuple(board.labels)
