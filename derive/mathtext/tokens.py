"""Tokens of LaTeX mathematics: commands, numbers, letter runs, characters.

Spacing commands are dropped, except ``\\ `` before a unit; ``\\left(`` and its
kin are one token. Each token keeps where it stands, so that a side of a
relation can be quoted as written. Read ``lenient`` (what students type), any
other character is a token of its own and sizing commands (``\\big``) and ``&`` are dropped.
"""

from __future__ import annotations

import re

SPACES = {r"\quad", r"\qquad", r"\,", r"\;", r"\:", r"\!", "~", r"\displaystyle", r"\left.", r"\right."}
#: Dropped too when read leniently: sizes, layout, alignment.
LOOSE = {"&", "$", r"\&", r"\textstyle", r"\nonumber", r"\notag", r"\left", r"\right", r"\middle"} | {
    rf"\{b}{lr}" for b in ("big", "Big", "bigg", "Bigg") for lr in ("", "l", "r", "m")
}


class LatexError(ValueError):
    """The text is not in the subset this reader knows (the message says where)."""


_TOKEN = re.compile(
    r"(?P<cmd>\\[A-Za-z]+)|(?P<esc>\\[ ,;:!%{}|_#&])|(?P<num>\d+(?:\.\d+)?|\.\d+)"
    r"|(?P<word>[A-Za-z]+\d*)|(?P<op>[{}()\[\]^_+\-=,/|<>'*!?·:;.~])|(?P<ws>\s+)"
)
_LOOSE_TOKEN = re.compile(_TOKEN.pattern + r"|(?P<other>\S)")


def token_spans(text: str, lenient: bool = False) -> list[tuple[str, int, int]]:
    """Tokens with where each starts and ends in ``text``."""
    out: list[tuple[str, int, int]] = []
    pos = 0
    pattern, drop = (_LOOSE_TOKEN, SPACES | LOOSE) if lenient else (_TOKEN, SPACES)
    while pos < len(text):
        begin = pos
        m = pattern.match(text, pos)
        if not m:
            raise LatexError(f"unexpected {text[pos]!r} in {text!r}")
        pos = m.end()
        kind = m.lastgroup
        tok = m.group(0)
        if kind == "ws":
            continue
        if kind == "cmd" and tok in (r"\left", r"\right") and pos < len(text):
            m2 = re.match(r"\s*(\\[{}|]|[()\[\]|.])", text[pos:])
            if m2:
                tok += m2.group(1)
                pos += m2.end()
        if tok in drop or (tok == r"\ " and not _unit_follows(text, pos)):
            continue
        out.append((tok, begin, pos))
    return out


def _unit_follows(text: str, pos: int) -> bool:
    """After ``\\ ``: True when a unit follows (``\\mathrm{...}`` or ``\\%``)."""
    rest = text[pos:].lstrip()
    return rest.startswith((r"\mathrm", r"\%", r"\text"))
