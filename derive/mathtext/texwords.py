"""The words around a student's LaTeX mathematics, as a teacher reads them: without TeX's spacing and
layout commands (``\\quad``, ``\\noindent``), its formatting of words (``\\textbf{Stage 3.}``,
``\\section*{…}``), a box or colour around the mathematics (``\\fbox{$v = 2$}``), and a TeX
comment after ``%``.
"""

from __future__ import annotations

import re

#: TeX spacing and layout commands in the text around mathematics (``\\quad $u_B = 2$``).
#: A line break (``\\\\``, ``\\\\[4pt]``) in the text after the mathematics is layout too (``$T = 6.4$ J \\\\``).
_TEX_SPACE = re.compile(
    r"\\(?:quad|qquad|noindent|medskip|smallskip|bigskip|newline|hfill|par)(?![A-Za-z])|\\[,;:! ]"
    r"|\\\\\*?(?:\s*\[[^\]]*\])?"
)


#: LaTeX's formatting of words outside mathematics (``\\textbf{Stage 3.}``, ``\\section*{…}``).
_TEX_WORDS = re.compile(
    r"\\(?:textbf|textit|emph|underline|textsc|(?:sub)*section\*?|paragraph\*?|item)\s*(?:\{([^{}]*)\})?"
)


#: A box or colour around mathematics in text (``\\fbox{$v = 2$}``, ``\\colorbox{yellow}{$…$}``): its
#: command, options and colour; the braces around the mathematics are dropped with the other braces.
_TEX_BOX = re.compile(
    r"\\(?:fbox|framebox|boxed|mbox|makebox|hbox|underline|colorbox|fcolorbox|textcolor|color|parbox|textbf|textit|emph)"
    r"(?![A-Za-z])"
    r"\s*(?:\[[^\]]*\]\s*)*(?:\{[A-Za-z!0-9.]*\}\s*(?=\{))*\{?"
)


#: siunitx in text after the mathematics (``$v = 4$ \\si{m/s}``, ``\\SI{4}{m/s}``): the number and the
#: unit as typed (a unit of commands, ``\\metre\\per\\second``, dropped).
_SIUNITX = re.compile(r"\\SI\s*\{([^{}]*)\}\s*\{([^{}]*)\}|\\si\s*\{([^{}]*)\}")


def _siunitx(m: re.Match[str]) -> str:
    unit = m[2] or m[3]
    return f" {m[1] or ''} {'' if chr(92) in unit else unit} "


def tex_text(text: str) -> str:
    """Words around mathematics without LaTeX's spacing and formatting commands, a box's command
    and the brace that closes it (``\\fbox{$v = 2$}``: the ``}`` after the mathematics)."""
    text = _SIUNITX.sub(_siunitx, text)  # \si{m/s} after the mathematics: its unit
    text = _TEX_SPACE.sub(" ", _TEX_BOX.sub(" ", text))
    text = _TEX_WORDS.sub(lambda m: f" {m.group(1) or ''} ", text)
    out, depth = [], 0
    for ch in text:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        out.append(" " if depth < 0 else ch)
        depth = max(depth, 0)
    return "".join(out)


def tex_comment(line: str) -> str:
    """A line without its TeX comment (``%`` not after a backslash)."""
    m = re.search(r"(?<!\\)%", line)
    return line[: m.start()] if m and not re.search(r"\d\s*$", line[: m.start()]) else line


#: A row's end with LaTeX's extra space or its no-break star (``\\[4pt]``, ``\\*``, ``\\ [2mm]``).
_ROW_END = re.compile(r"\\\\\*?(?:\s*\[\s*-?[\d.]*\s*(?:pt|mm|cm|em|ex|in|bp|pc|sp|\\[A-Za-z]+)\s*\])?")


def tex_row_ends(line: str) -> str:
    """``line`` with each row's end ``\\\\[4pt]`` or ``\\\\*`` as a plain ``\\\\``: the space asked for
    is layout, never the start of the next row's mathematics."""
    return _ROW_END.sub(lambda m: "\\\\", line)
