"""Where a page goes, and what that changes in how it is written.

The same worked solution is read by KaTeX, MathJax 2 and 3, pandoc, Word and
TeX; each has its gaps (see docs/interop.md). A :class:`Layout` names the few
choices that differ, and the templates and the printer follow it: nothing is
rewritten after it is printed.

Markdown targets (``derive solve --for TARGET``):

- ``github`` (the default) and ``mkdocs``: math for KaTeX and MathJax 3, figures
  as inline SVG;
- ``jupyter``: as github, and every formula that strikes a term out loads
  ``\\require{cancel}`` first (nbconvert and the classic notebook typeset with MathJax 2.7);
- ``pandoc``: for ``pandoc -t docx`` (Word) and pandoc's LaTeX: no ``\\tag`` (pandoc
  drops it: the number is written as text), no ``\\cancel`` (pandoc before 3.8 leaves
  the formula as raw TeX), a long line as consecutive displays (Word's equation
  arrays lose rows in LibreOffice), figures as images, ``^`` escaped in text.

LaTeX: a fragment to ``\\input`` into someone else's document is set for the
narrowest common text (``article`` at 10 pt: 345 pt); derive's own document for
its wider text (11 pt, 2.2 cm margins).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from derive.errors import InputError

#: The width (pt of 10 pt type) a display line may take in ``article`` (345 pt of text),
#: less a margin for the estimate (see :mod:`derive.writers.width`) and for an equation number.
ARTICLE_WIDTH_PT = 300.0
#: The same for derive's own LaTeX document (11 pt type, 2.2 cm margins: 489 pt, 447 pt at 10 pt).
DOCUMENT_WIDTH_PT = 400.0


@dataclass(frozen=True)
class Layout:
    """The choices that depend on where the page goes.

    ``width``: the pt (10 pt type) a display line may take before it is set on rows
    (None: never split); ``long_lines``: the rows as one ``aligned`` display, or as
    consecutive displays (a boxed line is then left whole); ``strike``: cancelled
    terms struck out; ``require_cancel``: ``\\require{cancel}`` before a formula that
    strikes (MathJax 2); ``tags``: equation numbers as ``\\tag{n}`` or as text;
    ``figures``: inline SVG, or a Markdown image (a data URI, or a file named for the
    caller to write); ``escape_caret``: ``^`` escaped in text (pandoc's superscript).
    """

    width: float | None = None
    long_lines: Literal["aligned", "displays"] = "aligned"
    strike: bool = True
    require_cancel: bool = False
    tags: Literal["tag", "text"] = "tag"
    figures: Literal["inline", "image", "files"] = "inline"
    escape_caret: bool = False


GITHUB = Layout()
JUPYTER = Layout(require_cancel=True)
PANDOC = Layout(
    width=ARTICLE_WIDTH_PT, long_lines="displays", strike=False, tags="text", figures="image", escape_caret=True
)
#: A course site's narrower column (mkdocs-material: about 700 px at a 1,440 px window) and
#: derive's HTML page (52 rem): a line wider than ``article``'s text (about 600 px of KaTeX
#: or MathJax) is set on rows, not cut off behind a scroll bar.
MKDOCS = Layout(width=ARTICLE_WIDTH_PT)
HTML = Layout(width=ARTICLE_WIDTH_PT)
#: Markdown targets by the name ``--for`` takes.
MARKDOWN_TARGETS: dict[str, Layout] = {"github": GITHUB, "jupyter": JUPYTER, "mkdocs": MKDOCS, "pandoc": PANDOC}
TEX_FRAGMENT = Layout(width=ARTICLE_WIDTH_PT)
TEX_DOCUMENT = Layout(width=DOCUMENT_WIDTH_PT)
#: The packages a LaTeX fragment needs, as its first line, ``--help`` and docs/interop.md name them.
FRAGMENT_PACKAGES = ("amsmath", "amssymb", "cancel", "tikz", "xurl")


def markdown_target(name: str) -> Layout:
    """The layout of a Markdown target: 'github', 'jupyter', 'mkdocs' or 'pandoc'."""
    if name not in MARKDOWN_TARGETS:
        raise InputError(f"unknown target {name!r} (expected one of: {', '.join(MARKDOWN_TARGETS)})", field="--for")
    return MARKDOWN_TARGETS[name]
