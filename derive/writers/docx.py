"""Word (.docx) through pandoc: derive's Markdown for pandoc, converted by pandoc.

pandoc is found as ``$DERIVE_PANDOC``, else the binary the ``pypandoc-binary`` wheel
ships (``pip install 'derive[docx]'``), else ``pandoc`` on the PATH; it must be 2.17
or later. The Markdown is the ``pandoc`` target's (:mod:`derive.writers.targets`):
equation numbers as text, long lines as consecutive displays, the figures as SVG
files beside it (pandoc adds a PNG copy when ``rsvg-convert`` is installed, which
LibreOffice needs), cancelled terms struck out only where pandoc converts
``\\cancel`` (3.8 and later). pandoc reads it with raw HTML and raw TeX off, in a
temporary folder that is removed afterwards.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
import tempfile
from dataclasses import replace
from pathlib import Path

from derive.errors import RenderError
from derive.steps.model import Solution
from derive.writers.targets import PANDOC
from derive.writers.view import markdown

#: The oldest pandoc that writes Word equations from derive's Markdown.
MIN_VERSION = (2, 17)
#: The first pandoc that converts ``\cancel`` (earlier ones leave the formula as raw TeX).
STRIKE_VERSION = (3, 8)
MISSING = (
    "--format docx needs pandoc: pip install 'derive[docx]' (or apt-get install pandoc); "
    "--format md writes the Markdown instead"
)
TIMEOUT_S = 120


def find_pandoc() -> str | None:
    """The pandoc to run: ``$DERIVE_PANDOC``, else pypandoc-binary's, else the PATH's (None: none)."""
    named = os.environ.get("DERIVE_PANDOC")
    if named:
        return named
    spec = importlib.util.find_spec("pypandoc")
    if spec is not None and spec.origin:
        for exe in ("pandoc", "pandoc.exe"):
            bundled = Path(spec.origin).parent / "files" / exe
            if bundled.is_file():
                return str(bundled)
    return shutil.which("pandoc")


def pandoc_version(path: str) -> tuple[int, ...]:
    """The version of the pandoc at ``path`` (``pandoc 3.9.0.2`` gives (3, 9, 0, 2))."""
    try:
        proc = subprocess.run(
            [path, "--version"], capture_output=True, text=True, timeout=30, stdin=subprocess.DEVNULL, check=False
        )
    except (OSError, subprocess.TimeoutExpired) as exc:
        raise RenderError(f"{MISSING} ({path} does not run: {exc})") from exc
    first = proc.stdout.splitlines()[0] if proc.stdout else ""
    m = re.match(r"pandoc(?:\.exe)?\s+([\d.]+)", first)
    if proc.returncode != 0 or m is None:
        raise RenderError(f"{MISSING} ({path} is not pandoc: {first or proc.stderr.strip()[:80]!r})")
    return tuple(int(x) for x in m.group(1).strip(".").split("."))


def build_docx(
    solution: Solution,
    *,
    digits: int | None = None,
    figures: bool = True,
    heading_level: int = 1,
    show_title: bool = True,
) -> bytes:
    """``solution`` as a Word document (the bytes of a .docx), converted by pandoc.

    Raises :class:`~derive.errors.RenderError` when there is no pandoc, or one older
    than 2.17, or pandoc fails.
    """
    pandoc = find_pandoc()
    if pandoc is None:
        raise RenderError(MISSING)
    version = pandoc_version(pandoc)
    if version < MIN_VERSION:
        shown = ".".join(map(str, version))
        raise RenderError(f"{MISSING} (found pandoc {shown} at {pandoc}; 2.17 or later is needed)")
    layout = replace(PANDOC, strike=version >= STRIKE_VERSION, figures="files")
    page, files = markdown(
        solution, layout, digits=digits, figures=figures, heading_level=heading_level, show_title=show_title
    )
    with tempfile.TemporaryDirectory(prefix="derive-docx-") as tmp:
        folder = Path(tmp)
        for name, svg in files.items():
            (folder / name).write_text(svg, encoding="utf-8")
        (folder / "solution.md").write_text(page, encoding="utf-8")
        args = [pandoc, "solution.md", "-f", "markdown-raw_html-raw_tex", "-t", "docx", "-o", "solution.docx"]
        try:
            proc = subprocess.run(
                args, cwd=folder, capture_output=True, text=True, timeout=TIMEOUT_S, stdin=subprocess.DEVNULL
            )
        except subprocess.TimeoutExpired as exc:
            raise RenderError(f"pandoc took longer than {TIMEOUT_S} s to write the .docx") from exc
        except OSError as exc:
            raise RenderError(f"{MISSING} ({pandoc} does not run: {exc})") from exc
        out = folder / "solution.docx"
        if proc.returncode != 0 or not out.is_file():
            last = (proc.stderr.strip().splitlines() or ["no message"])[-1]
            raise RenderError(f"pandoc could not write the .docx (exit {proc.returncode}): {last}")
        return out.read_bytes()
