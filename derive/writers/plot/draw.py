"""The plot drawn: SVG (a string, for Markdown and HTML), TikZ (for LaTeX), and PDF or
PNG through LaTeX (and poppler's ``pdftoppm`` for PNG)."""

from __future__ import annotations

import html
import shutil
import subprocess
import tempfile
from pathlib import Path

from derive import escape
from derive.errors import RenderError
from derive.symbols import latex_name
from derive.writers.figure.svg import PX, svg_head
from derive.writers.plot.chart import Chart, Text

SIZE = 15.0  # px


def _svg_name(name: str) -> str:
    """``v_A2n`` -> v with subscript A2n; ``T_lost/T_1`` -> both parts so."""
    parts = []
    for part in name.split("/"):
        base, _, sub = part.partition("_")
        text = f'<tspan font-style="italic">{html.escape(base)}</tspan>'
        if sub:
            text += f'<tspan dy="4" font-size="{0.72 * SIZE:.1f}">{html.escape(sub)}</tspan><tspan dy="-4"> </tspan>'
        parts.append(text)
    return "/ ".join(parts)


def _svg_text(t: Text, height: float) -> str:
    x, y = t.x * PX, (height - t.y) * PX
    body = _svg_name(t.text) if t.name else html.escape(t.text)
    turn = f' transform="rotate(-90 {x:.1f} {y:.1f})"' if t.rotate else ""
    return f'<text x="{x:.1f}" y="{y:.1f}" text-anchor="{t.anchor}" fill="{t.colour}"{turn}>{body}</text>'


def to_svg(chart: Chart) -> str:
    """The plot as a standalone ``<svg>`` element."""
    out = svg_head(chart.width * PX, chart.height * PX, chart.title, SIZE)
    for s in chart.strokes:
        pts = [(x * PX, (chart.height - y) * PX) for x, y in s.points]
        if s.dot:
            out += [f'<circle cx="{x:.1f}" cy="{y:.1f}" r="4" fill="{s.colour}"/>' for x, y in pts]
            continue
        dash = ' stroke-dasharray="6 4"' if s.dash else ""
        line = " ".join(f"{x:.1f},{y:.1f}" for x, y in pts)
        out.append(f'<polyline points="{line}" fill="none" stroke="{s.colour}" stroke-width="{s.width}"{dash}/>')
    out += [_svg_text(t, chart.height) for t in chart.texts]
    out.append("</svg>")
    return "".join(out)


def _tikz_colour(hex_: str) -> str:
    r, g, b = (int(hex_[i : i + 2], 16) for i in (1, 3, 5))
    return f"{{rgb,255:red,{r};green,{g};blue,{b}}}"


def _tikz_text(t: Text) -> str:
    if t.name:
        body = "$" + "/".join(latex_name(p) for p in t.text.split("/")) + "$"
    else:
        body = escape.tex(t.text).replace("−", "$-$")
    anchor = {"start": "west", "middle": "center", "end": "east"}[t.anchor]
    if t.rotate:
        anchor = "center"
    turn = ", rotate=90" if t.rotate else ""
    colour = _tikz_colour(t.colour)
    return rf"\node[anchor=base {anchor if anchor != 'center' else ''}, inner sep=0pt, text={colour}{turn}, font=\small] at ({t.x:.3f},{t.y:.3f}) {{{body}}};"


def to_tikz(chart: Chart) -> str:
    """The plot as a tikzpicture (1 unit = 1 cm), the same geometry as the SVG."""
    out = [
        r"\begin{tikzpicture}[x=1cm, y=1cm]",
        rf"\useasboundingbox (0,0) rectangle ({chart.width:.3f},{chart.height:.3f});",
    ]
    for s in chart.strokes:
        colour = _tikz_colour(s.colour)
        if s.dot:
            out += [rf"\fill[color={colour}] ({x:.3f},{y:.3f}) circle (0.1);" for x, y in s.points]
            continue
        style = f"color={colour}, line width={s.width * 0.75:.2f}pt, line join=round" + (
            ", dash pattern=on 4pt off 3pt" if s.dash else ""
        )
        path = " -- ".join(f"({x:.3f},{y:.3f})" for x, y in s.points)
        out.append(rf"\draw[{style}] {path};")
    out += [_tikz_text(t) for t in chart.texts]
    out.append(r"\end{tikzpicture}")
    return "\n".join(out)


def to_pdf(chart: Chart) -> bytes:
    """The plot as a one-page PDF, compiled by LaTeX."""
    from derive.writers.pdf import build_pdf

    tex = (
        "\\documentclass[11pt,border=6pt]{standalone}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern,amsmath,tikz}\n"
        "\\begin{document}\n" + to_tikz(chart) + "\n\\end{document}\n"
    )
    return build_pdf(tex)


def to_png(chart: Chart) -> bytes:
    """The plot as PNG: the PDF rasterised by poppler's pdftoppm at 150 dots an inch."""
    tool = shutil.which("pdftoppm")
    if tool is None:
        raise RenderError(
            "a PNG plot needs pdftoppm (Debian: apt-get install poppler-utils); -o FILE.svg needs nothing"
        )
    pdf = to_pdf(chart)
    with tempfile.TemporaryDirectory(prefix="derive-plot-") as tmp:
        src = Path(tmp) / "plot.pdf"
        src.write_bytes(pdf)
        subprocess.run(
            [tool, "-png", "-r", "150", "-singlefile", str(src), str(Path(tmp) / "plot")],
            check=True,
            capture_output=True,
            timeout=60,
        )
        return (Path(tmp) / "plot.png").read_bytes()
