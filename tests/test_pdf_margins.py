"""Issue #28: nothing a teacher prints runs into the margin. Each line of text of a PDF (pdftotext
with each word's box: tests/support/pdf_pages.py) lies between the left and right margins
(2.2 cm, the preamble's geometry). Found by looking at every bundled PDF as PNG and by the
LaTeX logs' "Overfull \\hbox": the title of edexcel-fm1-2023-june-q7a-cushion-show-tan-beta
("... show tan(beta) = e_1 tan(alpha)", justified) went 11.8 pt into the right margin."""

from __future__ import annotations

import shutil

import pytest
from support.output_cases import missing_tool, solution
from support.pdf_pages import MARGIN, read_pages

import derive
from derive.writers.pdf import build_pdf

#: Less than this past a margin is rounding of the boxes pdftotext reports (points).
SLACK = 1.0

PAGES = [
    "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta",  # a long title of unbreakable words
    "notes-4c11-two-spheres",
    "chain-ocr-m2-2006-drop-rebound",  # "Carried to the next stages" with a long impulse
    "ocr-mei-fmm-2022-offset-spheres-symbolic",  # wide closed forms in letters
    # its closed forms in e (given as 3/4) were nested radicals 12.3 pt wider than the line: a closed
    # form past steps.answer.READABLE_OPS operations is no longer shown beside its value
    "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke",
]


@pytest.mark.slow
@pytest.mark.parametrize("name", PAGES)
def test_no_line_runs_into_the_margin(name: str) -> None:
    for tool in ("latexmk", "pdflatex", "pdftotext"):
        if shutil.which(tool) is None:
            missing_tool(f"{tool} is not installed")
    pages = read_pages(build_pdf(derive.render(solution(name), "tex")))
    wide = [
        (p.number, round(max(MARGIN - ln.left, ln.right - (p.width - MARGIN)), 1), ln.text[:50])
        for p in pages
        for ln in p.lines
        if ln.left < MARGIN - SLACK or ln.right > p.width - MARGIN + SLACK
    ]
    assert not wide, (name, wide)
