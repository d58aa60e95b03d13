"""A given copied wrongly, then written so again in a later line of a chain's derivation.

``v^2 = 21^2 + 2(9.8)(30)`` where the height is 40 m is the first slip (a given copied
wrongly). Where the student writes 30 for the height again in a new relation (``0 = v2^2 -
2(9.8)(30)`` for the rise back to the start), that line holds in the student's world, but a
teacher does not call it carried: the student made the same mistake a second time, not a
relation worked from a number already wrong. It is the same mistake, made again. Where the
first slip states the given as that number (``e = 0.6``), a later line with it is worked from
the student's own value: carried.
"""

from __future__ import annotations

import re
from dataclasses import replace

from derive.checking.chainnames import Holds, Reread, copied
from derive.checking.context import Context
from derive.checking.report import Item


def copied_again(ctx: Context, item: Item, sides, items: list[Item], reread: Reread, holds: Holds, names) -> Item:
    """``item`` (a carried line) as the given copied wrongly again, where the first slip is that
    given copied as the same number, putting the given back makes this line hold too, and the
    line is of other quantities than the first (``names``: a line's number -> the names in its
    relations): the same quantities again (``y - x = 0.8(5 + 2)`` after ``0.3(5) - 0.2(2) = 0.3x +
    0.2y``) are worked on from the student's own reading of the problem, carried."""
    first = next((i for i in items if i.status == "wrong" and i.slip == "copied_wrong"), None)
    if item.status != "carried" or first is None or len(sides) < 2 or names(first.name) & names(item.name):
        return item
    found = copied(ctx, tuple(sides), reread, holds)
    found = copied(ctx, tuple(sides[:2]), reread, holds) if found is None and len(sides) > 2 else found
    if found is None or not first.message.endswith(found[0]):
        return item
    token = found[0].rsplit("not ", 1)[-1].rstrip(".")
    if re.search(rf"[A-Za-z][\w(){{}}\\^']*\s*=\s*{re.escape(token)}(?![\d.])", first.written):  # ``(v_B)_2 = 2.6``
        return item  # "e = 0.6" stated, then used: worked from the student's own e, carried
    said = f"False: the same mistake as in line {first.name}, made again{found[0]}"
    return replace(item, status="wrong", again=True, slip="copied_wrong", message=said)
