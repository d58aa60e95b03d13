"""A variant's page edited as text, without a regular expression scanning the whole page:
a page with its figures in it is long, and a pattern tried at each of its characters costs
more than filling in its numbers."""

from __future__ import annotations

import re
from collections.abc import Callable


def drop_lines(page: str, marker: str) -> str:
    """``page`` without each whole line (ended by a newline) that holds ``marker``: as
    ``re.sub(rf"^.*{re.escape(marker)}.*\\n", "", page, flags=re.M)``."""
    kept = []
    pos = 0
    while (at := page.find(marker, pos)) >= 0 and (end := page.find("\n", at)) >= 0:
        kept.append(page[pos : page.rfind("\n", 0, at) + 1])
        pos = end + 1
    kept.append(page[pos:])
    return "".join(kept)


def sub_opened(
    pattern: re.Pattern[str], repl: Callable[[re.Match[str]], str], page: str, marker: str, opens: tuple[str, ...]
) -> str:
    """``pattern.sub(repl, page)`` for a pattern each of whose matches starts with one of
    ``opens`` followed by ``marker`` (no text in ``opens`` holding a character of it):
    tried only where ``marker`` is."""
    kept, pos, at = [], 0, page.find(marker)
    while at >= 0:
        for head in opens:
            start = at - len(head)
            if start >= pos and page.startswith(head, start):
                m = pattern.match(page, start)
                if m is not None:
                    kept += [page[pos:start], repl(m)]
                    pos = m.end()
                break
        at = page.find(marker, max(at + 1, pos))
    return "".join(kept) + page[pos:]
