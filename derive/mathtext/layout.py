"""The layout of LaTeX a student types around the mathematics of a display row: environments
nested in a display (``\\[ \\begin{aligned} … \\end{aligned} \\]``), ``\\intertext``, a note in a
column of its own after ``&&``, siunitx's quantities (``\\SI{3}{\\metre\\per\\second}``)."""

from __future__ import annotations

import re

from derive.mathtext.columns import side_by_side
from derive.mathtext.latex import latex_to_plain

#: The display environments students use.
ENV = r"align|equation|gather|eqnarray|multline|alignat|flalign|split|aligned|gathered"
#: An environment inside a display (``\\[ \\begin{aligned} … \\end{aligned} \\]``): layout only.
NESTED = re.compile(
    rf"\\(?:begin|end)\{{(?:{ENV}|array|cases|matrix)\*?\}}(?:\{{[^{{}}]*\}})?"
    r"|\\(?:short)?intertext\s*\{[^{}]*\}"  # words between the rows
)


#: siunitx: a number and its unit (``\\SI{3}{\\metre\\per\\second}``, ``\\qty{3}{m/s}``), a unit alone, a number.
_SIUNITX = (
    (re.compile(r"\\(?:SI|qty)\s*(?:\[[^\]]*\])?\s*\{([^{}]*)\}\s*\{[^{}]*\}"), r" \1 "),
    (re.compile(r"\\(?:si|unit)\s*(?:\[[^\]]*\])?\s*\{[^{}]*\}"), " "),
    (re.compile(r"\\num\s*(?:\[[^\]]*\])?\s*\{([^{}]*)\}"), r"\1"),
    (re.compile(r"\\ang\s*(?:\[[^\]]*\])?\s*\{([^{}]*)\}"), r"\1°"),
)


#: A column vector (``\\begin{pmatrix} 3 \\\\ -1 \\end{pmatrix}``, ``bmatrix``, ``\\left(\\begin{array}{c}
#: … \\end{array}\\right)``), as A-level students write velocities: its entries, first the line of centres.
_COLUMN = re.compile(
    r"(?:\\left\s*[(\[]\s*)?\\begin\{([pbB]?matrix|smallmatrix|array)\}(?:\{[^{}]*\})?(.{0,400}?)\\end\{\1\}"
    r"(?:\s*\\right\s*[)\]])?",
    re.S,
)
#: ``\\binom{3}{-1}``: a column vector of two entries, typed so for its brackets.
_BINOM = re.compile(r"\\[dt]?binom\s*\{([^{}]*)\}\s*\{([^{}]*)\}")


def column_vectors(text: str) -> str:
    """``text`` with each column vector of two entries written as a pair ``(a, b)`` (the reader
    reads a pair as a vector); a matrix of more rows or columns is left as it is."""

    def pair(m: re.Match) -> str:
        rows = [r.strip() for r in re.split(r"\\\\", m.group(2)) if r.strip()]
        if len(rows) != 2 or any("&" in r for r in rows):
            return m.group(0)
        return "(" + ", ".join(rows) + ")"

    return _BINOM.sub(r"(\1, \2)", _COLUMN.sub(pair, text))


def row_plain(row: str) -> str:
    """A row of a display as plain text, without a note in a column of its own after ``&&``
    (``… && \\text{(CLM along } \\mathbf{i})``); a column with a relation in it is kept;
    siunitx's quantities as their numbers."""
    for pattern, plain in _SIUNITX:
        row = pattern.sub(plain, row)
    first, *rest = re.split(r"&\s*&", row)
    kept = [side_by_side(first), *(_worded(c) for c in rest if re.search(r"=|\\approx|\\simeq|≈", c))]
    return latex_to_plain(" ; ".join(kept))


#: A comma in a note's column, then words and no relation to its end (``, \ \mathbf{j}\text{-part
#: unchanged})``, ``\text{, as given)}``): the reason the note gives, not part of its relation.
_REASON = re.compile(r"(?:\\text\{)?,(?=[^=]*\\text\{[^}]*[A-Za-z]{2})[^=]*$")


def _worded(column: str) -> str:
    """A note's column after ``&&`` without the words after its relation (``(e = 1, j-part
    unchanged)`` is ``e = 1``): the relation is read, the reason is prose; its bracket opened
    before the relation goes with the words that close it."""
    m = _REASON.search(column)
    if m is None:
        return column
    kept = column[: m.start()]
    return kept.replace("(", " ", 1) if kept.count("(") > kept.count(")") else kept
