"""A percentage written after a side multiplied by 100: ``64/352 × 100 = 18.2 %``.

The student's ``× 100`` already makes the fraction a number of per cent, and the ``%`` after
the result only says so: a teacher reads ``x × 100 = p %`` as ``x × 100 % = p %``. Read
literally (``%`` as ``/100``) the two sides differ by a factor of 100 and a right line would
be false. The side before the percentage is given its ``%`` too, so both sides are read alike.

>>> per_cent_sides(("percentage lost", "(891/900) * 100", "99.0%"))
('percentage lost', '(891/900) * 100%', '99.0%')
>>> per_cent_sides(("100 x 64/352", "18.2 %"))
('100% * 64/352', '18.2 %')
>>> per_cent_sides(("T_2/T_1", "0.6", "60%"))
('T_2/T_1', '0.6', '60%')
"""

from __future__ import annotations

import re

#: A side that is a number and a per cent sign: ``18.2%``, ``18.2 %``.
_PERCENT = re.compile(r"^\s*[-+]?(?:\d+\.?\d*|\.\d+)\s*%\s*$")
#: A side that ends (starts) with a factor 100: ``… × 100``, ``… * 100``, ``… x 100``, ``100 × …``.
_TIMES = r"(?:\*|×|x|·|\\times|\\cdot)"
_ENDS = re.compile(rf"{_TIMES}\s*100(?:\.0*)?\s*$")
_STARTS = re.compile(rf"^\s*100(?:\.0*)?\s*{_TIMES}\s*")


def _top_level_product(side: str) -> bool:
    """Whether ``side`` is a product at the top level: no ``+`` or ``-`` outside its brackets
    (a leading sign aside)."""
    depth = 0
    for k, c in enumerate(side.strip()):
        depth += c in "([{"
        depth -= c in ")]}"
        if depth == 0 and c in "+-−" and k > 0:
            return False
    return True


def per_cent_sides(sides: tuple[str, ...]) -> tuple[str, ...]:
    """``sides`` with the side just before a percentage marked per cent where it multiplies by
    100 and has no ``%`` of its own."""
    out = list(sides)
    for k in range(1, len(sides)):
        before = sides[k - 1]
        if not _PERCENT.match(sides[k]) or "%" in before or not _top_level_product(before):
            continue
        if _ENDS.search(before):
            out[k - 1] = _ENDS.sub("* 100%", before, count=1)
        elif _STARTS.match(before):
            out[k - 1] = _STARTS.sub("100% * ", before, count=1)
    return tuple(out)


#: A quantity after said to be a percentage of itself before (``KE after = 60% of before``, ``speed
#: after = 80 % of the original``, ``T_2 = 36% of T_1``): the name, the percentage, what it is of.
_PER_CENT_OF = re.compile(
    r"(?P<name>\b[A-Za-z][\w ]{0,30}?\s*(?:after|final|2|_2|f)\s*)=\s*(?P<p>\d+\.?\d*\s*%)\s+of\s+(?:the\s+|its\s+)?"
    r"(?P<of>(?:value\s+)?(?:before|initial(?:ly)?|original(?:\s+value)?|it)\b|[A-Za-z][\w ]{0,30}?\s*(?:before|initial|1|_1|i)\b)(?P<rest>\s*,[^=\d,;]*$)?",
    re.I,
)
_TIME = re.compile(r"(?:after|final)(?=\s*$)|(?<=_)2(?=\s*$)|(?<=[A-Za-z])2(?=\s*$)|(?<=_)f(?=\s*$)", re.I)


def per_cent_of(text: str) -> str:
    """``KE after = 60% of before`` as ``KE after = 60% * KE before``: a percentage of a quantity
    is that fraction times it; "of before" (the original, it) is of the same quantity before. Words
    after it (``, find α``) are dropped: the quantity is no number they could follow."""

    def times(m: re.Match) -> str:
        of = m["of"]
        if re.fullmatch(r"(?:value\s+)?(?:before|initial(?:ly)?|original(?:\s+value)?|it)", of.strip(), re.I):
            before = {"after": "before", "final": "initial", "2": "1", "f": "i"}
            of = _TIME.sub(lambda t: before[t.group(0).lower()], m["name"].strip())
            if of == m["name"].strip():
                return m.group(0)
        return f"{m['name']}= {m['p']} * {of}"

    return _PER_CENT_OF.sub(times, text)
