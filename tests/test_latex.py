"""derive's LaTeX compiles: the whole document, the fragment inside a minimal document, and the CLI's PDF.

Needs TeX Live with latexmk; in CI (CI=true) a missing latexmk fails instead of skipping.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from support.output_cases import bundled_names, hostile_problem, missing_tool, solution

import derive
from derive import resources
from derive.writers.pdf import build_pdf

REPO = Path(__file__).resolve().parents[1]

pytestmark = pytest.mark.slow


@pytest.fixture(autouse=True)
def _need_latexmk() -> None:
    for tool in ("latexmk", "pdflatex"):
        if shutil.which(tool) is None:
            missing_tool(
                f"{tool} is not installed (Debian: apt-get install latexmk texlive-latex-extra texlive-science)"
            )


def _pdf_text(pdf: bytes, tmp_path: Path) -> str | None:
    """The PDF's text by pdftotext, or None when poppler-utils is not installed."""
    if shutil.which("pdftotext") is None:
        return None
    path = tmp_path / "check.pdf"
    path.write_bytes(pdf)
    return subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout


@pytest.mark.parametrize("name", bundled_names())
def test_document_compiles(name: str, tmp_path: Path) -> None:
    tex = derive.render(solution(name), "tex")
    assert tex.lstrip().startswith("\\documentclass")
    pdf = build_pdf(tex)
    assert pdf.startswith(b"%PDF")
    text = _pdf_text(pdf, tmp_path)
    if text is not None:
        assert "ANSWER" in text
        # the heading may wrap: compare with runs of white space as one space; an apostrophe
        # typed in the title prints as one (A's: A\u2019s)
        title = solution(name).problem.title.split(":")[0].replace("'", "\u2019")
        assert " ".join(title.split()) in " ".join(text.split())


def test_hostile_text_document_compiles(tmp_path: Path) -> None:
    """A title and statement full of TeX specials ($ & % # _ { } \\ ^ ~) still compile, as text."""
    s = derive.solve(derive.load(hostile_problem(tmp_path)))
    pdf = build_pdf(derive.render(s, "tex"))
    assert pdf.startswith(b"%PDF")
    text = _pdf_text(pdf, tmp_path)
    if text is not None:
        assert "\\input{/etc/passwd}" in text
        assert "100%" in text


_NEEDS = re.compile(r"\bNeeds\b\s*:?\s*(?P<list>[^.]*)", re.IGNORECASE)


def _packages_from(comment: str) -> list[str] | None:
    r"""Package names from a comment: ``\usepackage{a,b}`` lines, or 'Needs a, b and c.'."""
    used = re.findall(r"\\usepackage(?:\[[^\]]*\])?\{([^}]*)\}", comment)
    if used:
        return [p.strip() for group in used for p in group.split(",") if p.strip()]
    m = _NEEDS.search(comment)
    if m is None:
        return None
    words = re.split(r",|\band\b", m.group("list"))
    names = [w.strip() for w in words if w.strip()]
    assert all(re.fullmatch(r"[A-Za-z][A-Za-z0-9-]*", n) for n in names), f"cannot read package names from {comment!r}"
    return names


def _fragment_packages(fragment: str) -> list[str]:
    """The packages the fragment says it needs: its leading % comment, else the template's comment."""
    leading = []
    for line in fragment.splitlines():
        if not line.strip():
            continue
        if not line.lstrip().startswith("%"):
            break
        leading.append(line.lstrip().lstrip("%"))
    found = _packages_from("\n".join(leading))
    if found is None:
        template = (resources.templates_dir() / "fragment.tex.j2").read_text(encoding="utf-8")
        found = _packages_from(template.split("}", 1)[0] if template.startswith("\\#{") else template)
    assert found, "the fragment (and its template) do not say which packages the fragment needs"
    return found


@pytest.mark.parametrize("name", bundled_names())
def test_fragment_compiles_in_a_minimal_document(name: str) -> None:
    fragment = derive.render(solution(name), "tex-fragment")
    assert "\\documentclass" not in fragment and "\\begin{document}" not in fragment
    packages = _fragment_packages(fragment)
    doc = "\n".join(
        [
            "\\documentclass{article}",
            *(f"\\usepackage{{{p}}}" for p in packages),
            "\\begin{document}",
            fragment,
            "\\end{document}",
            "",
        ]
    )
    assert build_pdf(doc).startswith(b"%PDF")


def test_cli_writes_a_pdf(tmp_path: Path) -> None:
    out = tmp_path / "X.pdf"
    proc = subprocess.run(
        [sys.executable, "-m", "derive", "solve", "notes-4c11-two-spheres", "--format", "pdf", "-o", str(out)],
        cwd=REPO,
        capture_output=True,
        text=True,
        timeout=300,
        stdin=subprocess.DEVNULL,
    )
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout == ""
    assert out.read_bytes().startswith(b"%PDF")
    assert not list(tmp_path.glob("*.tex")) and not list(tmp_path.glob("*.log")), "LaTeX left files beside the PDF"
