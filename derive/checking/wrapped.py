"""A sentence of words wrapped over two lines of the source: "let $x$ and $y$ be the velocities
of $A$ and $B$ along the" / "line of centres after the impact. …". A declaration in words is read
from the sentence whole, as a reader reads it, not from each line's half.

>>> wrapped_sentences("Let x and y be the velocities along the\\nline of centres after. Then\\nx + y = 5")
['Let x and y be the velocities along the line of centres after.']
"""

from __future__ import annotations

import re
from itertools import pairwise

#: A line that stops in the middle of a sentence: it ends with a word or a comma.
_OPEN_END = re.compile(r"[A-Za-z,$]\s*$")
#: A line that goes on with the sentence: it starts with a word in lower case.
_GOES_ON = re.compile(r"^\s*[a-z]")
#: Where the sentence ends on the second line.
_STOP = re.compile(r"[.;:](?:\s|$)")


def wrapped_sentences(text: str) -> list[str]:
    """Each line that stops mid-sentence joined with the start of the next, up to the end of its
    sentence (the first line's words after its last full stop only)."""
    lines = text.splitlines()
    out = []
    for first, second in pairwise(lines):
        if not _OPEN_END.search(first) or not _GOES_ON.match(second) or "=" in second.split(".")[0]:
            continue
        head = re.split(r"[.;:](?:\s)", first)[-1].strip()
        stop = _STOP.search(second)
        tail = second[: stop.end()].strip() if stop else second.strip()
        out.append(f"{head} {tail}")
    return out
