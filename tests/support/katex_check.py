"""Helpers for the KaTeX tests: pull every formula out of derive's Markdown, check them with KaTeX.

The checking is done by ``tests/katex/check.mjs`` under node, with the KaTeX version
pinned in ``tests/katex/package.json`` / ``package-lock.json``. Install it with
``npm ci --prefix tests/katex``.

In CI (``CI=true``) a missing node or a missing/mismatched ``tests/katex/node_modules``
fails the test; on a developer's machine it skips, saying what to run.
"""

from __future__ import annotations

import json
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

from support.output_cases import missing_tool

KATEX_DIR = Path(__file__).resolve().parents[1] / "katex"
CHECKER = KATEX_DIR / "check.mjs"
INSTALL_HINT = "npm ci --prefix tests/katex"


@dataclass(frozen=True)
class Formula:
    """One formula of a document: its LaTeX, display or inline, and where it was found."""

    tex: str
    display: bool
    where: str


class MarkdownMathError(ValueError):
    """The Markdown's math delimiters do not pair up (an unclosed ``$`` or ``$$``)."""


def _inline_math(line: str, where: str) -> list[Formula]:
    """Formulas in one line of Markdown text: ``$...$`` (and ``$$...$$`` inside a line).

    Outside math a backslash escapes the next character (``\\$`` is a literal
    dollar, ``\\\\`` a literal backslash); inside math a backslash starts a TeX
    control sequence, so ``\\$`` there does not close the formula. Code spans are
    skipped.
    """
    found: list[Formula] = []
    i, n = 0, len(line)
    while i < n:
        ch = line[i]
        if ch == "\\":
            i += 2
            continue
        if ch == "`":
            ticks = len(line[i:]) - len(line[i:].lstrip("`"))
            close = line.find("`" * ticks, i + ticks)
            if close < 0:
                i += ticks
                continue
            i = close + ticks
            continue
        if ch != "$":
            i += 1
            continue
        delim = "$$" if line.startswith("$$", i) else "$"
        j = i + len(delim)
        start = j
        while j < n:
            if line[j] == "\\":
                j += 2
                continue
            if line.startswith(delim, j):
                break
            j += 1
        if j >= n:
            raise MarkdownMathError(f"{where}: unclosed {delim} in {line!r}")
        found.append(Formula(line[start:j], delim == "$$", where))
        i = j + len(delim)
    return found


def markdown_formulas(md: str, name: str = "<md>") -> list[Formula]:
    """Every formula in ``md``: display math between lines that are just ``$$``, and inline math.

    Raises :class:`MarkdownMathError` when a ``$$`` block or a ``$`` is never closed.
    """
    formulas: list[Formula] = []
    lines = md.splitlines()
    i = 0
    fence: str | None = None
    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        where = f"{name}:{i + 1}"
        if fence is not None:
            if stripped.startswith(fence):
                fence = None
            i += 1
            continue
        if stripped.startswith(("```", "~~~")):
            fence = stripped[:3]
            i += 1
            continue
        if stripped == "$$":
            body: list[str] = []
            j = i + 1
            while j < len(lines) and lines[j].strip() != "$$":
                body.append(lines[j])
                j += 1
            if j >= len(lines):
                raise MarkdownMathError(f"{where}: display math opened by $$ is never closed")
            formulas.append(Formula("\n".join(body).strip(), True, where))
            i = j + 1
            continue
        formulas.extend(_inline_math(line, where))
        i += 1
    return formulas


def _pinned_version() -> str:
    return json.loads((KATEX_DIR / "package.json").read_text(encoding="utf-8"))["dependencies"]["katex"]


def require_katex() -> str:
    """The path of node, after checking that node and the pinned KaTeX are installed."""
    node = shutil.which("node")
    if node is None:
        missing_tool("node is not installed (the KaTeX check runs under node 18+)")
    installed = KATEX_DIR / "node_modules" / "katex" / "package.json"
    if not installed.exists():
        missing_tool(f"KaTeX is not installed in tests/katex/node_modules: run {INSTALL_HINT}")
    version = json.loads(installed.read_text(encoding="utf-8"))["version"]
    if version != _pinned_version():
        missing_tool(
            f"tests/katex/node_modules has KaTeX {version}, not the pinned {_pinned_version()}: run {INSTALL_HINT}"
        )
    assert node is not None
    return node


def katex_errors(formulas: list[Formula], timeout: float = 120) -> list[dict]:
    """Check ``formulas`` with KaTeX in one node call; the list of errors ([] when all render)."""
    node = require_katex()
    payload = json.dumps([{"tex": f.tex, "display": f.display, "where": f.where} for f in formulas])
    proc = subprocess.run(
        [node, str(CHECKER)],
        input=payload,
        capture_output=True,
        text=True,
        encoding="utf-8",
        timeout=timeout,
        cwd=KATEX_DIR,
    )
    if proc.returncode not in (0, 1):
        raise RuntimeError(f"check.mjs failed (exit {proc.returncode}): {proc.stderr.strip()}")
    errors = json.loads(proc.stdout)
    if (proc.returncode == 1) != bool(errors):
        raise RuntimeError(f"check.mjs: exit {proc.returncode} does not match its {len(errors)} errors")
    return errors


def describe(errors: list[dict]) -> str:
    """KaTeX's errors, one formula each, for an assertion message."""
    return "\n".join(f"{e['where']}: {e['error']}\n    {'$$' if e['display'] else '$'}{e['tex']}" for e in errors)
