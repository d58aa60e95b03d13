"""A contact sheet of every bundled problem's figures, to look at what users see.

    python benchmarks/contact_sheet.py OUT_DIR [--png]

Writes ``OUT_DIR/figures.html`` (each problem's before and after figures as SVG, one
pair per impact stage of a chain) and ``OUT_DIR/figures.tex`` (the same figures as
TikZ, compiled to ``figures.pdf``). With ``--png`` it also turns them into PNG: the
PDF's pages with ``pdftoppm -png -r 80`` and the HTML page, in slices, with headless
chromium.
"""

from __future__ import annotations

import argparse
import html
import shutil
import subprocess
import tempfile
from pathlib import Path

import derive
from derive.resources import bundled
from derive.writers import figure
from derive.writers.pdf import build_pdf

CHROMIUM_FLAGS = (
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
)


def figures_of(name: str) -> list[tuple[str, figure.Figure, figure.Figure]]:
    """(heading, before, after) for a problem, or for each impact stage of a chain."""
    sol = derive.solve(derive.load(name))
    if not sol.is_chain:
        return [(name, figure.describe(sol), figure.describe(sol, after=True))]
    falls = figure.chain_falls(sol)
    out = []
    for st in sol.stages:
        if st.part is not None:
            opts = {"falls": falls[st.number], "values": sol.values}
            before = figure.describe(st.part, **opts)
            out.append((f"{name}, stage {st.number}", before, figure.describe(st.part, after=True, **opts)))
    return out


def write_html(rows: list[tuple[str, figure.Figure, figure.Figure]], path: Path) -> None:
    cells = "".join(
        f"<h3>{html.escape(head)}</h3><div class='row'>{figure.to_svg(a)}{figure.to_svg(b)}</div>"
        for head, a, b in rows
    )
    style = "body{font-family:serif;margin:12px} .row{display:flex;gap:24px;align-items:flex-start} svg{border:1px solid #ddd}"
    path.write_text(
        f"<!DOCTYPE html><html><head><meta charset='utf-8'><style>{style}</style></head><body>{cells}</body></html>"
    )


def write_tex(rows: list[tuple[str, figure.Figure, figure.Figure]], path: Path) -> bytes:
    def fit(fig: figure.Figure) -> str:
        """Side by side, each shrunk to half the text width if it is wider (on the page it is not)."""
        pic = figure.to_tikz(fig)
        if fig.width > 8.0:
            pic = "\\resizebox{\\linewidth}{!}{" + pic + "}"
        return "\\begin{minipage}[t]{0.49\\linewidth}\\centering " + pic + "\\end{minipage}"

    body = "\n".join(
        "\\subsection*{" + head.replace("_", "\\_") + "}\n\\noindent" + fit(a) + "\\hfill" + fit(b) + "\\par"
        for head, a, b in rows
    )
    tex = (
        "\\documentclass[11pt]{article}\n\\usepackage[T1]{fontenc}\n\\usepackage{lmodern,amsmath,tikz}\n"
        "\\usepackage[margin=2.2cm,a4paper]{geometry}\n\\usepackage{graphicx}\n\\begin{document}\n"
        + body
        + "\n\\end{document}\n"
    )
    path.write_text(tex)
    return build_pdf(tex)


def screenshots(page: Path, out: Path, height: int) -> None:
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        raise SystemExit("chromium is not installed")
    with tempfile.TemporaryDirectory() as profile:
        subprocess.run(
            [chromium, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", f"--window-size=1100,{height}",
             f"--screenshot={out}", page.resolve().as_uri()],
            check=True, capture_output=True, timeout=180,
        )  # fmt: skip


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out", type=Path)
    ap.add_argument("--png", action="store_true")
    ap.add_argument("--only", nargs="*", help="bundled names (default: all)")
    args = ap.parse_args()
    args.out.mkdir(parents=True, exist_ok=True)
    rows = [row for name in (args.only or bundled()) for row in figures_of(name)]
    write_html(rows, args.out / "figures.html")
    (args.out / "figures.pdf").write_bytes(write_tex(rows, args.out / "figures.tex"))
    if args.png:
        subprocess.run(
            ["pdftoppm", "-png", "-r", "80", str(args.out / "figures.pdf"), str(args.out / "tex")], check=True
        )
        screenshots(args.out / "figures.html", args.out / "svg.png", 340 * len(rows) + 100)
    print(f"{len(rows)} figure pairs in {args.out}")


if __name__ == "__main__":
    main()
