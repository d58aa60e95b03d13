"""HTML's character references in a Markdown derivation, as a Markdown page shows them:
``&nbsp;`` a space, ``&times;`` ×, ``&minus;`` −, ``&deg;`` °, ``&alpha;`` α, ``&#8730;`` √.

Only a complete reference (``&`` a name or a number ``;``) is one: LaTeX's column marks
(``a &= b``, ``&&``) and a bare ``&`` are left as they are."""

from __future__ import annotations

import html
import re

_REFERENCE = re.compile(r"&(?:[A-Za-z][A-Za-z0-9]{1,31}|#[0-9]{1,7}|#[xX][0-9A-Fa-f]{1,6});")
#: Spaces of every width: a space to the reader.
_SPACES = dict.fromkeys(map(ord, "\u00a0\u2002\u2003\u2009\u200a\u202f"), " ") | {0x200B: ""}


def decoded(text: str) -> str:
    """``text`` with each complete character reference as its character (a space for the spaces)."""
    if "&" not in text:
        return text
    return _REFERENCE.sub(lambda m: html.unescape(m.group(0)).translate(_SPACES), text)
