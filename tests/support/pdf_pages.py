"""A PDF read back page by page, for the tests of page breaks (issue #28 item 6).

pdftotext -bbox gives each word with its box; the words are grouped into lines by their
baseline, and each page's fill is how far down its text area its lowest line of text reaches
(the page number left out). The text area is the page less derive's margins (2.2 cm, the
preamble's geometry), so a fill of 0.5 is a page that ends half way down.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from dataclasses import dataclass
from html import unescape
from pathlib import Path

from support.output_cases import missing_tool

MARGIN = 2.2 / 2.54 * 72  # the preamble's geometry, in PDF points
_PAGE = re.compile(r'<page width="([\d.]+)" height="([\d.]+)">(.*?)</page>', re.S)
_WORD = re.compile(r'<word xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">(.*?)</word>')


@dataclass(frozen=True)
class Line:
    """One line of text: its words, the top and bottom of its box (points from the page's top)
    and its left and right ends (points from the page's left edge)."""

    text: str
    top: float
    bottom: float
    left: float = 0.0
    right: float = 0.0


@dataclass(frozen=True)
class Page:
    """One page: its lines of text top to bottom (the page number left out), its height and width."""

    number: int
    lines: tuple[Line, ...]
    height: float
    width: float = 0.0

    @property
    def fill(self) -> float:
        """How far down the text area the lowest line reaches: 0 empty, 1 full."""
        if not self.lines:
            return 0.0
        area = self.height - 2 * MARGIN
        return (max(ln.bottom for ln in self.lines) - MARGIN) / area

    @property
    def text(self) -> str:
        return "\n".join(ln.text for ln in self.lines)


def read_pages(pdf: bytes) -> list[Page]:
    """The pages of ``pdf`` as lines of text with their heights on the page."""
    if shutil.which("pdftotext") is None:
        missing_tool("pdftotext is not installed")
    with tempfile.TemporaryDirectory(prefix="derive-pages-") as tmp:
        path = Path(tmp) / "doc.pdf"
        path.write_bytes(pdf)
        html = subprocess.run(["pdftotext", "-bbox", str(path), "-"], capture_output=True, text=True, check=True).stdout
    pages = []
    for k, (width, height, body) in enumerate(_PAGE.findall(html), 1):
        words = [(float(y0), float(y1), float(x0), unescape(w), float(x1)) for x0, y0, x1, y1, w in _WORD.findall(body)]
        pages.append(Page(k, _lines(words, float(height)), float(height), float(width)))
    return pages


def _lines(words: list[tuple[float, float, float, str, float]], height: float) -> tuple[Line, ...]:
    """Words grouped into lines (a word whose box overlaps the line's middle joins it), the
    page number (a lone number in the footer) left out."""
    lines: list[list[tuple[float, float, float, str, float]]] = []
    for word in sorted(words):
        for line in lines:
            middle = (line[0][0] + line[0][1]) / 2
            if word[0] <= middle <= word[1]:
                line.append(word)
                break
        else:
            lines.append([word])
    out = []
    for line in lines:
        top, bottom = min(w[0] for w in line), max(w[1] for w in line)
        text = " ".join(w[3] for w in sorted(line, key=lambda w: w[2]))
        if top > height - MARGIN and text.isdigit():
            continue  # the page number, in the footer
        out.append(Line(text, top, bottom, min(w[2] for w in line), max(w[4] for w in line)))
    return tuple(sorted(out, key=lambda ln: ln.top))
