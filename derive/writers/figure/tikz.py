"""A figure as a ``tikzpicture``: one drawing unit is one centimetre, not scaled, so
that the labels (set in the document's font) keep the room the layout gave them."""

from __future__ import annotations

import functools

from derive import escape
from derive.symbols import latex_name
from derive.writers.figure.model import Arc, Arrow, Axis, Body, Figure, Guide, Label, Surface, hatch_ticks, head

INK = {"velocity": "red!70!black", "angle": "blue!65!black", "axis": "black!80", "body": "black", "surface": "black"}


def _p(x: float, y: float) -> str:
    return f"({x:.3f},{y:.3f})"


def _with_head(s: Arrow | Axis, style: str, colour: str) -> list[str]:
    wings = head(s.x1, s.y1, s.x2, s.y2)
    if not wings:
        return []
    (tip, w1), (_, w2) = wings
    base = ((w1[0] + w2[0]) / 2, (w1[1] + w2[1]) / 2)
    return [
        rf"\draw[{style}, {colour}] {_p(s.x1, s.y1)} -- {_p(*base)};",
        rf"\fill[{colour}] {_p(*tip)} -- {_p(*w1)} -- {_p(*w2)} -- cycle;",
    ]


def _shape(s: object) -> list[str]:
    if isinstance(s, Body):
        return [rf"\draw[fill=blue!6, line width=0.8pt] {_p(s.x, s.y)} circle ({s.r:.3f});"]
    if isinstance(s, Surface):
        out = [rf"\draw[line width=1.3pt] {_p(s.x1, s.y1)} -- {_p(s.x2, s.y2)};"]
        return out + [rf"\draw[line width=0.5pt] {_p(*a)} -- {_p(*b)};" for a, b in hatch_ticks(s)]
    if isinstance(s, Axis):
        return _with_head(s, "line width=0.55pt" + (", dash pattern=on 3.5pt off 2pt" if s.dashed else ""), INK["axis"])
    if isinstance(s, Arrow):
        return _with_head(s, "line width=1.1pt", INK["velocity"])
    if isinstance(s, Arc):
        return [
            rf"\draw[{INK['angle']}, line width=0.65pt] {_p(s.x, s.y)} ++({s.start:.2f}:{s.r:.3f}) "
            rf"arc[start angle={s.start:.2f}, end angle={s.end:.2f}, radius={s.r:.3f}];"
        ]
    if isinstance(s, Guide):
        return [
            rf"\draw[black!60, line width=0.5pt, dash pattern=on 1pt off 1.5pt] {_p(s.x1, s.y1)} -- {_p(s.x2, s.y2)};"
        ]
    return []


def _label(lab: Label) -> str:
    text = _label_text(lab.text, lab.role, lab.math, lab.tail)
    return rf"\node[inner sep=0pt, text={INK.get(lab.role, 'black')}] at {_p(lab.x, lab.y)} {{{text}}};"


@functools.lru_cache(maxsize=256)  # a figure's labels are the same few texts
def _label_text(text: str, role: str, math: bool, tail: str) -> str:
    if not math:
        return escape.tex(text)
    if role == "body":
        return r"\textbf{" + escape.tex(text) + "}"
    return "$" + latex_name(text) + tail + "$"


def to_tikz(fig: Figure) -> str:
    """The figure as a tikzpicture (1 unit = 1 cm), its bounding box that of the SVG."""
    x0, y0, x1, y1 = fig.bounds()
    out = [r"\begin{tikzpicture}[x=1cm, y=1cm]", rf"\useasboundingbox {_p(x0, y0)} rectangle {_p(x1, y1)};"]
    for s in fig.shapes:
        out += _shape(s)
    out += [_label(lab) for lab in fig.labels]
    out.append(r"\end{tikzpicture}")
    return "\n".join(out)
