"""Matrices as students type them to solve two (or three) simultaneous equations: a matrix
equation (``\\begin{pmatrix} 2 & 1 \\\\ -1 & 1 \\end{pmatrix}\\begin{pmatrix} a \\\\ b \\end{pmatrix}
= \\begin{pmatrix} 7 \\\\ 4 \\end{pmatrix}``, ``bmatrix``, ``\\left( \\begin{array}{cc} … \\end{array}
\\right)``) is its equations one row each, set apart by ``\\\\`` as a display's rows are
(``2a + 1b = 7 \\\\ -1a + 1b = 4``); a determinant (``\\begin{vmatrix} … \\end{vmatrix}``,
``\\det`` or ``| … |`` around a matrix, Cramer's rule) is its value written out, ``((p)(s) - (q)(r))``."""

from __future__ import annotations

import re

_ENVS = r"[pbBvV]?matrix|smallmatrix|array"
#: One matrix: its environment (an ``array``'s column spec after it), its body; brackets or bars
#: around it (``\\left( … \\right)``, ``\\left| … \\right|``, ``| … |``) or ``\\det`` before it.
_MATRIX = re.compile(
    r"(?P<before>\\det\s*|\\left\s*[(\[|]\s*|\\lvert\s*|\\vert\s*|\|\s*)?"
    rf"\\begin\{{(?P<env>{_ENVS})\}}(?:\{{[^{{}}]*\}})?(?P<body>.{{0,600}}?)\\end\{{(?P=env)\}}"
    r"(?P<after>\s*\\right\s*[)\]|]|\s*\\rvert|\s*\\vert|\s*\|)?",
    re.S,
)
#: The most rows (and columns) of a matrix read.
_MOST = 3


def _cells(body: str) -> list[list[str]] | None:
    """The rows of a matrix's body, each its cells; None where it is not rectangular or too big."""
    rows = [r for r in re.split(r"\\\\(?:\[[^\]]*\])?", body) if r.strip()]
    cells = [[c.strip() for c in r.split("&")] for r in rows]
    if not cells or len(cells) > _MOST or any(len(r) != len(cells[0]) or len(r) > _MOST for r in cells):
        return None
    if any(not c for r in cells for c in r):
        return None
    return cells


def _determinant(cells: list[list[str]]) -> str | None:
    """The determinant of a square matrix of two or three rows, written out in its entries."""
    n = len(cells)
    if n != len(cells[0]) or n < 2:
        return None
    if n == 2:
        (p, q), (r, s) = cells
        return f"(({p})({s}) - ({q})({r}))"
    terms = []
    for j, sign in zip(range(3), ("+", "-", "+"), strict=True):
        minor = [[row[k] for k in range(3) if k != j] for row in cells[1:]]
        terms.append(f"{sign} ({cells[0][j]}){_determinant(minor)}")
    return "(" + " ".join(terms).lstrip("+ ") + ")"


def _is_determinant(m: re.Match) -> bool:
    """Whether a matrix is written as its determinant: ``vmatrix``, ``\\det`` or bars around it."""
    before, after = (m.group("before") or "").strip(), (m.group("after") or "").strip()
    if m.group("env") in ("vmatrix", "Vmatrix") or before.startswith("\\det"):
        return True
    return before.endswith(("|", "\\lvert", "\\vert")) and after.endswith(("|", "\\rvert", "\\vert"))


def determinants(text: str) -> str:
    """``text`` with each determinant written as its value in its entries."""

    def value(m: re.Match) -> str:
        cells = _cells(m.group("body")) if _is_determinant(m) else None
        found = _determinant(cells) if cells else None
        return f" {found} " if found else m.group(0)

    return _MATRIX.sub(value, text)


def matrix_equations(text: str) -> str:
    """``text`` with a matrix equation (a square matrix times a column, equal to a column) written
    as its equations, one a row, set apart by ``\\\\``; anything else as it is."""
    found = list(_MATRIX.finditer(text))
    for k in range(len(found) - 2):
        a, x, b = found[k : k + 3]
        if text[a.end() : x.start()].strip(" \\,;:!") not in ("", "\\cdot", "\\times") or not _equals(
            text[x.end() : b.start()]
        ):
            continue
        rows = _rows(_cells(a.group("body")), _cells(x.group("body")), _cells(b.group("body")))
        if rows is not None:
            return text[: a.start()] + " \\\\ ".join(rows) + text[b.end() :]
    return text


def _equals(between: str) -> bool:
    """Whether the text between a matrix product and its right side is just ``=``."""
    return between.strip(" \\,;:!") == "="


def _rows(
    matrix: list[list[str]] | None, column: list[list[str]] | None, right: list[list[str]] | None
) -> list[str] | None:
    """The equations of ``matrix · column = right``; None where their shapes do not agree."""
    if not matrix or not column or not right:
        return None
    n = len(matrix)
    if n < 2 or len(matrix[0]) != n or len(column) != n or len(right) != n:
        return None
    if any(len(r) != 1 for r in column) or any(len(r) != 1 for r in right):
        return None
    return [
        " + ".join(f"({c})({x[0]})" for c, x in zip(row, column, strict=True)) + f" = {r[0]}"
        for row, r in zip(matrix, right, strict=True)
    ]


def matrices(text: str) -> str:
    """``text`` with its determinants as their values and a matrix equation as its equations."""
    return matrix_equations(determinants(text))
