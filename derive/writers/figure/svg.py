"""A figure as an SVG element: a pure function of the figure, returning a string.

One centimetre of the figure is :data:`PX` pixels (40: a little over the 37.8 px of a
CSS centimetre), so labels are 16 px, the size of body text in a browser. The
element has no scripts and no external references; it can be inlined in Markdown
or HTML, or written to a file or a data URI as it is.
"""

from __future__ import annotations

import functools
import html

from derive.writers.figure.layout import EM, split
from derive.writers.figure.model import Arc, Arrow, Axis, Body, Figure, Guide, Label, Surface, arc_points, head
from derive.writers.figure.model import hatch_ticks as ticks

PX = 40.0  # pixels per centimetre
FONT = "'Latin Modern Roman', 'CMU Serif', 'Times New Roman', Times, 'Liberation Serif', serif"
INK = {"velocity": "#b00000", "angle": "#0050a0", "axis": "#333333", "body": "#111111", "surface": "#111111"}


class _Canvas:
    """Centimetres (y up) to pixels (y down) inside the figure's bounds."""

    def __init__(self, fig: Figure) -> None:
        self.x0, self.y0, self.x1, self.y1 = fig.bounds()

    def x(self, x: float) -> str:
        return f"{(x - self.x0) * PX:.1f}"

    def y(self, y: float) -> str:
        return f"{(self.y1 - y) * PX:.1f}"

    def pts(self, points: list[tuple[float, float]]) -> str:
        x0, y1 = self.x0, self.y1  # :meth:`x` and :meth:`y` written out (an arc has 25 points)
        return " ".join([f"{(px - x0) * PX:.1f},{(y1 - py) * PX:.1f}" for px, py in points])


def _line(c: _Canvas, x1: float, y1: float, x2: float, y2: float, attrs: str) -> str:
    x0, top = c.x0, c.y1  # c.x() and c.y() written out
    return (
        f'<line x1="{(x1 - x0) * PX:.1f}" y1="{(top - y1) * PX:.1f}" '
        f'x2="{(x2 - x0) * PX:.1f}" y2="{(top - y2) * PX:.1f}" {attrs}/>'
    )


def _with_head(c: _Canvas, s: Arrow | Axis, colour: str, width: float, extra: str = "", cls: str = "") -> str:
    """A line ending in a filled arrowhead (the line stops where the head begins)."""
    wings = head(s.x1, s.y1, s.x2, s.y2)
    if not wings:
        return ""
    (tip, w1), (_, w2) = wings
    base = ((w1[0] + w2[0]) / 2, (w1[1] + w2[1]) / 2)
    stroke = f'stroke="{colour}" stroke-width="{width}"{extra}'
    klass = f' class="{cls}"' if cls else ""
    return (
        f"<g{klass}>{_line(c, s.x1, s.y1, base[0], base[1], stroke)}"
        f'<polygon points="{c.pts([tip, w1, w2])}" fill="{colour}"/></g>'
    )


def _shape(c: _Canvas, s: object) -> str:
    if isinstance(s, Body):
        return (
            f'<circle cx="{c.x(s.x)}" cy="{c.y(s.y)}" r="{s.r * PX:.1f}" '
            'fill="#e8eef7" stroke="#1a2233" stroke-width="1.6"/>'
        )
    if isinstance(s, Surface):
        hatch = "".join(_line(c, *a, *b, 'stroke="#111" stroke-width="1"') for a, b in ticks(s))
        return _line(c, s.x1, s.y1, s.x2, s.y2, 'stroke="#111" stroke-width="2.6"') + hatch
    if isinstance(s, Axis):
        dash = ' stroke-dasharray="7 4"' if s.dashed else ""
        return _with_head(c, s, INK["axis"], 1.1, dash, f"axis axis-{s.name}")
    if isinstance(s, Arrow):
        return _with_head(c, s, INK["velocity"], 2.2, "", "velocity")
    if isinstance(s, Arc):
        return f'<polyline points="{c.pts(arc_points(s))}" fill="none" stroke="{INK["angle"]}" stroke-width="1.3"/>'
    if isinstance(s, Guide):
        return _line(c, s.x1, s.y1, s.x2, s.y2, 'stroke="#555" stroke-width="1" stroke-dasharray="2 3"')
    return ""


def _label(c: _Canvas, lab: Label) -> str:
    """A label centred on its box: a symbol with its subscript, or words."""
    style, colour, body, shift = _label_text(lab.text, lab.role, lab.math, lab.tail)
    y = (c.y1 - lab.y + shift * EM) * PX
    return f'<text x="{c.x(lab.x)}" y="{y:.1f}" text-anchor="middle" fill="{colour}"{style}>{body}</text>'


@functools.lru_cache(maxsize=256)  # a figure's labels are the same few texts
def _label_text(text: str, role: str, math: bool, tail: str) -> tuple[str, str, str, float]:
    """A label's style, colour, content and the shift (em) of its baseline below its centre."""
    size = EM * PX
    style = {"body": ' font-weight="bold"', "surface": ""}.get(role, ' font-style="italic"')
    colour = INK.get(role, "#111")
    if not math:
        body, shift = html.escape(text), 0.25
    else:
        base, sub = split(text)
        body, shift = html.escape(base), 0.25
        if sub:
            drop = 0.25 * size
            body += f'<tspan dy="{drop:.1f}" font-size="{0.7 * size:.1f}">{html.escape(sub)}</tspan>'
            shift = 0.16
            if tail:
                body += f'<tspan dy="{-drop:.1f}" font-style="normal">{html.escape(tail)}</tspan>'
        elif tail:
            body += f'<tspan font-style="normal">{html.escape(tail)}</tspan>'
    return style, colour, body, shift


def svg_head(w: float, h: float, title: str, size: float) -> list[str]:
    """The opening ``<svg>`` tag of a ``w`` x ``h`` px drawing (a figure's or a plot's), and its title."""
    title = html.escape(title)
    return [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0f}" height="{h:.0f}" viewBox="0 0 {w:.1f} {h:.1f}" '
        f'role="img" aria-label="{title}" font-family="{html.escape(FONT)}" font-size="{size:.0f}">',
        f"<title>{title}</title>",
    ]


def to_svg(fig: Figure) -> str:
    """The figure as a standalone ``<svg>`` element (no scripts, no external references)."""
    c = _Canvas(fig)
    out = svg_head((c.x1 - c.x0) * PX, (c.y1 - c.y0) * PX, fig.title, EM * PX)
    out += [_shape(c, s) for s in fig.shapes]
    out += [_label(c, lab) for lab in fig.labels]
    out.append("</svg>")
    return "".join(out)
