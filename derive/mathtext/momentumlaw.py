"""The conservation of momentum stated as a sum before it is worked: ``\\sum m v_1 = \\sum m v_2``,
``Σmu = Σmv``, ``Σp_i = Σp_f``. A teacher marks it as the method, right: it is read as the total
momentum before equal to the total after (``p_before = p_after``), which derive knows.

>>> momentum_law(r"\\sum m v_1 = \\sum m v_2"), momentum_law("Σ mu = Σ mv"), momentum_law("Σ m v_1 = 3")
('p_before = p_after', 'p_before = p_after', 'Σ m v_1 = 3')
"""

from __future__ import annotations

import re

_SUM = r"(?:\\sum|\\Sigma|Sigma|Σ|∑|sum)(?:_\{?[A-Za-z]\}?)?\s*"
_TERM = r"(?:m\s*\*?\s*[uv]|p)"
_BEFORE = rf"{_SUM}(?:{_TERM}\s*_?\s*\{{?\s*(?:1|i|0|before|initial|init)\s*\}}?|m\s*\*?\s*u)"
_AFTER = rf"{_SUM}(?:{_TERM}\s*_?\s*\{{?\s*(?:2|f|after|final)\s*\}}?|m\s*\*?\s*v(?:'|_?p)?)"
_LAW = re.compile(rf"^\s*(?:{_BEFORE}\s*=\s*{_AFTER}|{_AFTER}\s*=\s*{_BEFORE})\s*(?=$|=(?!=))", re.I)


def momentum_law(text: str) -> str:
    """``text`` as ``p_before = p_after`` where it states the conservation of momentum as sums of
    the bodies' momenta before and after, its worked value after them kept (``Σmu = Σmv = 2m``:
    ``p_before = p_after = 2m``); any other text as it is."""
    m = _LAW.match(text)
    if m is None:
        return text
    return f"p_before = p_after {text[m.end() :].strip()}".rstrip()
