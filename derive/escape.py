"""Escaping of user text (titles, statements, sources) for each output format.

Text from a problem file is data: nothing in it may become a LaTeX command
(``\\input``, ``\\write18``, ``\\def``, ``\\catcode``), Markdown markup or HTML.
"""

from __future__ import annotations

import html
import re
import unicodedata

from derive.errors import InputError

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
#: Greek letters by their Unicode names, as pdflatex sets them: lower case and the capitals
#: with shapes of their own in math mode; the capitals shaped as Latin ones (Alpha, Beta, ...)
#: as those Latin letters, which is how they print in any Greek font.
_GREEK_SMALL = (
    "alpha beta gamma delta varepsilon zeta eta theta iota kappa lambda mu nu xi omicron pi rho"
    " varsigma sigma tau upsilon varphi chi psi omega"
)  # U+03B5 and U+03C6 are the open epsilon and the looped phi: \varepsilon, \varphi
#: The Greek symbol variants, each its own character: lunate epsilon, straight phi, ...
_GREEK_SYMBOLS = {"ϵ": r"$\epsilon$", "ϕ": r"$\phi$", "ϑ": r"$\vartheta$", "ϖ": r"$\varpi$", "ϱ": r"$\varrho$"}
_GREEK_CAPITAL = "A B Gamma Delta E Z H Theta I K Lambda M N Xi O Pi P Sigma T Upsilon Phi X Psi Omega"


def _greek() -> dict[str, str]:
    table = {}
    # U+03B1 alpha ... U+03C2 final sigma, U+03C3 sigma ... U+03C9 omega
    for i, name in enumerate(_GREEK_SMALL.split()):
        table[chr(0x03B1 + i)] = "o" if name == "omicron" else rf"$\{name}$"
    for i, name in enumerate(_GREEK_CAPITAL.split()):  # U+0391 ... U+03A9, no letter at U+03A2
        table[chr(0x0391 + i + (i >= 17))] = name if len(name) == 1 else rf"$\{name}$"
    return table | _GREEK_SYMBOLS


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
    "∞": r"$\infty$",
    "∓": r"$\mp$",
    "≠": r"$\neq$",
    "≡": r"$\equiv$",
    "∝": r"$\propto$",
    "∠": r"$\angle$",
    "∆": r"$\Delta$",
    "∇": r"$\nabla$",
    "∂": r"$\partial$",
    "←": r"$\leftarrow$",
    "↑": r"$\uparrow$",
    "↓": r"$\downarrow$",
    "↔": r"$\leftrightarrow$",
    "′": r"$'$",
    "″": r"$''$",
    "•": r"\textbullet{}",
    "€": r"\texteuro{}",
    "™": r"\texttrademark{}",
    "‰": r"\textperthousand{}",
    "ı": r"\i{}",
    "ł": r"\l{}",
    "Ł": r"\L{}",
    "œ": r"\oe{}",
    "Œ": r"\OE{}",
    "đ": r"\dj{}",
    "Đ": r"\DJ{}",
    "ŋ": r"\ng{}",
    "Ŋ": r"\NG{}",
    "½": r"\textonehalf{}",
    "¼": r"\textonequarter{}",
    "¾": r"\textthreequarters{}",
    "µ": r"\textmu{}",
    "`": r"\textasciigrave{}",
}
#: A typed quote mark as the curly one it stands for: opening at the start of a word or after a
#: bracket or dash (' 'v = 3' ' ‘v = 3’), closing elsewhere (A's ⇒ A’s, the notes' ⇒ notes’).
#: A quote before another is closed with {}, so that the two never join into one mark ('' ⇒ ”).
_TEX_QUOTES = {"'": ("`", "'"), '"': ("``", "''")}
_OPENS_AFTER = frozenset('([{<-/\u2013\u2014\u2018\u201c"')
for _i in range(10):  # θ₂, x⁴: the digits written below and above the line
    _TEX_UNICODE[chr(0x2080 + _i)] = rf"\textsubscript{{{_i}}}"
    _TEX_UNICODE.setdefault("⁰¹²³⁴⁵⁶⁷⁸⁹"[_i], rf"\textsuperscript{{{_i}}}")
_TEX_UNICODE.update(_greek())


#: A word longer than this (a URL) may break after any of :data:`_BREAK_AFTER`.
LONG_WORD = 30
_BREAK_AFTER = frozenset("/.-_?&=#:;,")


#: The combining accents that T1 fonts set over a Latin letter, and the LaTeX accent for each.
_TEX_ACCENTS = {
    "\u0300": r"\`",
    "\u0301": r"\'",
    "\u0302": r"\^",
    "\u0303": r"\~",
    "\u0304": r"\=",
    "\u0306": r"\u",
    "\u0307": r"\.",
    "\u0308": r"\"",
    "\u030a": r"\r",
    "\u030b": r"\H",
    "\u030c": r"\v",
    "\u0323": r"\d",
    "\u0327": r"\c",
    "\u0328": r"\k",
    "\u0331": r"\b",
}


class UnsetCharacter(InputError):
    """A character of the user's text that LaTeX (pdflatex with T1 fonts) cannot set."""


def tex(text: str) -> str:
    """``text`` as LaTeX that prints it literally and runs nothing; a long word (a URL) may
    break across lines after a slash, a dot, a hyphen and the like, so it cannot run off
    the page.

    The text is NFC-normalised first (an accent typed as a separate combining character,
    as macOS copy-paste gives, joins its letter). A character LaTeX cannot set (Cyrillic,
    an emoji) raises :class:`UnsetCharacter`, which names it, rather than printing "?".
    """
    text = unicodedata.normalize("NFC", text)
    return "".join(_tex_word(w, len(w) > LONG_WORD, text) for w in re.split(r"(\s+)", text))


def _tex_word(word: str, breakable: bool, text: str) -> str:
    out = []
    for i, ch in enumerate(word):
        if ch in _TEX_QUOTES:
            opening = i == 0 or word[i - 1] in _OPENS_AFTER
            out.append(_TEX_QUOTES[ch][0 if opening else 1])
            if word[i + 1 : i + 2] in ("'", '"', "`"):
                out.append("{}")
            continue
        out.append(_tex_char(ch, text))
        if breakable and ch in _BREAK_AFTER:
            out.append(r"\allowbreak{}")
    return "".join(out)


def _tex_char(ch: str, text: str) -> str:
    if ch in _TEX_SPECIAL:
        return _TEX_SPECIAL[ch]
    if ch in _TEX_UNICODE:
        return _TEX_UNICODE[ch]
    if ord(ch) < 32 or ord(ch) == 127:
        return " "
    if ord(ch) < 128 or 0xC0 <= ord(ch) <= 0xFF:
        return ch  # ASCII and Latin-1 letters: T1 fonts have them
    if unicodedata.category(ch) == "Cf":
        return ""  # invisible: a zero-width space, a direction mark
    accented = _accented(ch)
    if accented is not None:
        return accented
    name = unicodedata.name(ch, "no name")
    shown = text if len(text) <= 60 else text[:57] + "..."
    raise UnsetCharacter(
        f"LaTeX cannot set {ch!r} (U+{ord(ch):04X} {name}) in {shown!r}: "
        "write it another way, or choose --format md or html, which show it"
    )


def _accented(ch: str) -> str | None:
    """A Latin letter with accents (ā, ő, č, ǵ) as LaTeX accent commands over the letter, or None."""
    base, *marks = unicodedata.normalize("NFD", ch)
    if not marks or not ("a" <= base.lower() <= "z") or any(m not in _TEX_ACCENTS for m in marks):
        return None
    out = r"\i{}" if base == "i" and marks[0] in "\u0300\u0301\u0302\u0304\u0306\u0308" else base
    for mark in marks:
        out = _TEX_ACCENTS[mark] + "{" + out + "}"
    return out


_MD_SPECIAL = set("\\`*_[]|$~#")
_MD_ENTITIES = {"<": "&lt;", ">": "&gt;", "&": "&amp;"}


def markdown(text: str, *, caret: bool = False) -> str:
    """``text`` as Markdown that shows it literally (no markup, no math, no HTML);
    ``caret`` escapes ``^`` too, which pandoc's Markdown reads as a superscript."""
    special = _MD_SPECIAL | {"^"} if caret else _MD_SPECIAL
    out = []
    for ch in text:
        if ch in _MD_ENTITIES:
            out.append(_MD_ENTITIES[ch])
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
