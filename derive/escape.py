"""Escaping of user text (titles, statements, sources) for each output format.

Text from a problem file is data: nothing in it may become a LaTeX command
(``\\input``, ``\\write18``, ``\\def``, ``\\catcode``), Markdown markup or HTML.
"""

from __future__ import annotations

import html
import re

_TEX_SPECIAL = {
    "\\": r"\textbackslash{}",
    "{": r"\{",
    "}": r"\}",
    "$": r"\$",
    "&": r"\&",
    "%": r"\%",
    "#": r"\#",
    "_": r"\_",
    "^": r"\textasciicircum{}",
    "~": r"\textasciitilde{}",
    "<": r"\textless{}",
    ">": r"\textgreater{}",
    "|": r"\textbar{}",
    "\n": " ",
    "\r": " ",
    "\t": " ",
}
_GREEK = [
    "alpha",
    "beta",
    "gamma",
    "delta",
    "epsilon",
    "zeta",
    "eta",
    "theta",
    "iota",
    "kappa",
    "lambda",
    "mu",
    "nu",
    "xi",
    "omicron",
    "pi",
    "rho",
    "sigma",
    "tau",
    "upsilon",
    "phi",
    "chi",
    "psi",
    "omega",
]
_TEX_UNICODE = {
    "°": r"\textdegree{}",
    "±": r"$\pm$",
    "×": r"$\times$",
    "·": r"$\cdot$",
    "−": "-",
    "–": "--",
    "—": "---",
    "“": "``",
    "”": "''",
    "‘": "`",
    "’": "'",
    "…": r"\dots{}",
    "→": r"$\rightarrow$",
    "⇒": r"$\Rightarrow$",
    "≈": r"$\approx$",
    "≤": r"$\leq$",
    "≥": r"$\geq$",
    "√": r"$\surd$",
    "²": r"\textsuperscript{2}",
    "³": r"\textsuperscript{3}",
    "\u00a0": "~",
    "½": r"\textonehalf{}",
    "¼": r"\textonequarter{}",
    "¾": r"\textthreequarters{}",
    "µ": r"\textmu{}",
    "`": r"\textasciigrave{}",
    "'": r"\textquotesingle{}",
    '"': r"{\ttfamily\char34}",  # a straight double quote in any font encoding
}
for _i in range(10):  # θ₂, x⁴: the digits written below and above the line
    _TEX_UNICODE[chr(0x2080 + _i)] = rf"\textsubscript{{{_i}}}"
    _TEX_UNICODE.setdefault("⁰¹²³⁴⁵⁶⁷⁸⁹"[_i], rf"\textsuperscript{{{_i}}}")
for _i, _name in enumerate(_GREEK):
    if _name == "omicron":
        continue
    _TEX_UNICODE[chr(0x03B1 + _i)] = rf"$\{_name}$"
    if _name not in ("epsilon",):
        cap = _name.capitalize()
        if cap in ("Gamma", "Delta", "Theta", "Lambda", "Xi", "Pi", "Sigma", "Upsilon", "Phi", "Psi", "Omega"):
            _TEX_UNICODE[chr(0x0391 + _i)] = rf"$\{cap}$"


#: A word longer than this (a URL) may break after any of :data:`_BREAK_AFTER`.
LONG_WORD = 30
_BREAK_AFTER = frozenset("/.-_?&=#:;,")


def tex(text: str) -> str:
    """``text`` as LaTeX that prints it literally and runs nothing; a long word (a URL) may
    break across lines after a slash, a dot, a hyphen and the like, so it cannot run off
    the page."""
    return "".join(_tex_word(w, len(w) > LONG_WORD) for w in re.split(r"(\s+)", text))


def _tex_word(word: str, breakable: bool) -> str:
    out = []
    for ch in word:
        out.append(_tex_char(ch))
        if breakable and ch in _BREAK_AFTER:
            out.append(r"\allowbreak{}")
    return "".join(out)


def _tex_char(ch: str) -> str:
    if ch in _TEX_SPECIAL:
        return _TEX_SPECIAL[ch]
    if ch in _TEX_UNICODE:
        return _TEX_UNICODE[ch]
    if ord(ch) < 32 or ord(ch) == 127:
        return " "
    if ord(ch) < 128 or 0xC0 <= ord(ch) <= 0xFF:
        return ch  # ASCII and Latin-1 letters: T1 fonts have them
    return "?"


_MD_SPECIAL = set("\\`*_[]|$~#")


def markdown(text: str, *, caret: bool = False) -> str:
    """``text`` as Markdown that shows it literally (no markup, no math, no HTML);
    ``caret`` escapes ``^`` too, which pandoc's Markdown reads as a superscript."""
    special = _MD_SPECIAL | {"^"} if caret else _MD_SPECIAL
    out = []
    for ch in text.replace("\r", " ").replace("\n", " "):
        if ch == "<":
            out.append("&lt;")
        elif ch == ">":
            out.append("&gt;")
        elif ch == "&":
            out.append("&amp;")
        elif ch in special:
            out.append("\\" + ch)
        elif ord(ch) < 32:
            out.append(" ")
        else:
            out.append(ch)
    return "".join(out)


#: Control characters, a parse error in HTML (and an ESC recolours a terminal showing the page):
#: C0 but tab, newline and carriage return, DEL and C1. Shown as a space, as in TeX and Markdown.
_HTML_CONTROL = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\x7f-\x9f]")


def html_text(text: str) -> str:
    """``text`` as HTML text content (or an attribute's value), control characters as spaces."""
    return html.escape(_HTML_CONTROL.sub(" ", text), quote=True)


def html_body(text: str) -> str:
    """``text`` as HTML element content (``<``, ``>``, ``&`` escaped; quotes as they are;
    control characters as spaces)."""
    return html.escape(_HTML_CONTROL.sub(" ", text), quote=False)
