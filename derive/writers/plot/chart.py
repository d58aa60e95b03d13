"""The plot laid out as geometry (centimetres, y up): two panels over e from 0 to 1,
the velocities along n after the impact above, the fraction of kinetic energy lost
below, the problem's e marked across both. :mod:`.draw` draws it as SVG or TikZ.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from derive.writers.plot.curves import Curves

WIDTH = 13.0  # cm: fits the text width of A4 (16.6 cm) and Letter (17.2 cm)
LEFT, RIGHT = 1.9, 0.5  # margins for tick labels and the axis titles
TOP_H, LOW_H, GAP = 5.0, 3.2, 1.3
COLOURS = {"v_A2n": "#b00000", "v_A2": "#b00000", "v_B2n": "#0050a0", "v_B2": "#0050a0", "T_lost/T_1": "#2a7a2a"}

Point = tuple[float, float]


@dataclass(frozen=True)
class Stroke:
    """A polyline; ``dash`` draws it dashed, ``dot`` a filled dot at each point instead."""

    points: tuple[Point, ...]
    colour: str = "#222222"
    width: float = 1.0
    dash: bool = False
    dot: bool = False


@dataclass(frozen=True)
class Text:
    """Text at (x, y): ``anchor`` start/middle/end; ``name`` set for a symbol with a subscript."""

    x: float
    y: float
    text: str
    anchor: str = "middle"
    colour: str = "#222222"
    name: bool = False
    rotate: bool = False
    size: float = 1.0


@dataclass(frozen=True)
class Chart:
    width: float
    height: float
    strokes: tuple[Stroke, ...]
    texts: tuple[Text, ...]
    title: str


def ticks(lo: float, hi: float) -> list[float]:
    """Round tick values covering [lo, hi] in about five steps (of 1, 2, 2.5 or 5 times a power of ten)."""
    if hi - lo < 1e-12:
        lo, hi = lo - 1, hi + 1
    raw = (hi - lo) / 5
    power = 10 ** math.floor(math.log10(raw))
    step = next(m * power for m in (1, 2, 2.5, 5, 10) if m * power >= raw)
    first = math.floor(lo / step + 1e-9) * step
    last = math.ceil(hi / step - 1e-9) * step
    n = round((last - first) / step)
    return [round(first + k * step, 10) for k in range(n + 1)]


def _shown(x: float) -> str:
    text = f"{x:.4g}"
    return "−" + text[1:] if text.startswith("-") else text


def _panel(
    c: Curves, panel: str, y0: float, height: float, title: str
) -> tuple[list[Stroke], list[Text], dict[str, list[Point]]]:
    """One panel: frame, grid, ticks, the curves of ``panel``, dots at the problem's e."""
    chosen = [s for s in c.series if s.panel == panel]
    lo = min(0.0, *(min(s.values) for s in chosen))
    hi = max(0.0, *(max(s.values) for s in chosen))
    ys = ticks(lo, hi) if panel == "velocity" else [0, 0.25, 0.5, 0.75, 1.0]
    x0, x1 = LEFT, WIDTH - RIGHT

    def X(e: float) -> float:
        return x0 + (x1 - x0) * e

    def Y(v: float) -> float:
        return y0 + height * (v - ys[0]) / (ys[-1] - ys[0])

    strokes: list[Stroke] = []
    texts: list[Text] = []
    for v in ys:
        strokes.append(Stroke(((x0, Y(v)), (x1, Y(v))), "#bbbbbb" if v else "#666666", 0.5 if v else 0.8))
        texts.append(Text(x0 - 0.15, Y(v) - 0.13, _shown(v), "end"))
    for k in range(11):
        e = k / 10
        strokes.append(Stroke(((X(e), y0), (X(e), y0 + height)), "#e2e2e2", 0.5))
        if k % 2 == 0:
            texts.append(Text(X(e), y0 - 0.45, _shown(e)))
    strokes.append(Stroke(((x0, y0), (x1, y0), (x1, y0 + height), (x0, y0 + height), (x0, y0)), "#222222", 0.9))
    texts.append(Text(0.45, y0 + height / 2, title, rotate=True))
    curves = {}
    for s in chosen:
        pts = [(X(e), Y(v)) for e, v in zip(c.e, s.values, strict=True)]
        curves[s.name] = pts
        strokes.append(Stroke(tuple(pts), COLOURS.get(s.name, "#222222"), 1.8))
        if c.mark is not None:
            strokes.append(Stroke(((X(c.mark), Y(c.at(s.name, c.mark))),), COLOURS.get(s.name, "#222222"), dot=True))
    if c.mark is not None:
        strokes.append(Stroke(((X(c.mark), y0), (X(c.mark), y0 + height)), "#444444", 1.0, dash=True))
    texts.append(Text((x0 + x1) / 2, y0 - 0.95, "e", name=True))
    return strokes, texts, curves


def layout(c: Curves) -> Chart:
    """The two panels one above the other, a legend and the mark's label on top."""
    low_y = 1.2
    top_y = low_y + LOW_H + GAP
    unit = f"/ {c.per}" if c.per else f"({c.unit})"
    s1, t1, _ = _panel(c, "velocity", top_y, TOP_H, f"velocity along n {unit}")
    s2, t2, _ = _panel(c, "energy", low_y, LOW_H, "fraction of T lost")
    height = top_y + TOP_H + 1.4
    strokes, texts = s1 + s2, t1 + t2
    x = LEFT
    for s in c.series:  # the legend, in a row above the panels
        colour = COLOURS.get(s.name, "#222222")
        strokes.append(Stroke(((x, height - 0.35), (x + 0.7, height - 0.35)), colour, 1.8))
        texts.append(Text(x + 0.85, height - 0.48, s.name, "start", colour, name=True))
        x += 1.3 + 0.3 * len(s.name)
    if c.mark is not None:
        mx = LEFT + (WIDTH - LEFT - RIGHT) * c.mark
        texts.append(Text(mx, top_y + TOP_H + 0.2, f"e = {_shown(c.mark)}", "middle", "#444444"))
    return Chart(WIDTH, height, tuple(strokes), tuple(texts), f"{c.title}: the outcome against e")
