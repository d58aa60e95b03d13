"""A general result's letter given its value for one stage: a substitution, not a claim.

A student who works a chain's impacts once in letters (``p + q = w``, ``q - p = e w``, ``q =
w(1 + e)/2``: a mass at speed w strikes an equal one at rest) then applies the result to each
stage, saying what the letter is there: ``A hits B (w = 7): u_B = 7(1 + e)/2``, then ``B hits C
(w = u_B): …``, or ``with w = 7``, ``putting w = u_B``. Each ``w = …`` puts a value into the
letter for that stage; it is not a relation to judge (w = 7 is false for the second stage and
true for the first). Such a relation is known by its words (in brackets, or after "with",
"put", "taking", "for", "where", "setting", "sub", "when") and by the letter being given two
different values in the derivation, the letter being used in a relation of the general result.
A number put in must be one of the chain's values or one the student found before (``w = 3``
where the stage's speed is 5.29 is a wrong value put in: judged, not passed over).
"""

from __future__ import annotations

import re

import sympy

from derive.checking.naming import PREFIX

#: Words before a letter's value put into a general result (``with w = 7``, ``putting w = u_B``).
_WORDS = r"(?:with|put|putting|taking|take|for|where|setting|set|sub|substituting|when|using|let)"


def _said_as_put(name: str, written: str) -> bool:
    """Whether ``written`` sets the letter ``name`` in brackets or after a word of substitution."""
    letters = r"[{}_\s]*".join(re.escape(c) for c in name.replace("_", ""))
    head = rf"(?<![\w\\]){letters}[{{}}\s]*="
    return bool(
        re.search(rf"\(\s*\$?\s*{head}[^()]*\)", written) or re.search(rf"\b{_WORDS}\s+\$?\s*{head}", written, re.I)
    )


def _known(x: sympy.Expr, k: int, read: list, known: tuple[float, ...]) -> bool:
    """Whether the value ``x`` put in at ``read[k]`` is not a number, a number judged where the
    line goes on to write it (``(w = 8): u_B = 8(1 + e)/2``), or a number of the chain (``known``)
    or one written as a side before it, within 1 %."""
    if not x.is_number:
        return True
    r, number = read[k][0], re.escape(read[k][1][-1].strip().strip("$ "))
    if any(
        re.search(rf"(?<![\d.]){number}(?![\d.])", side)
        for j, (o, sides, _x) in enumerate(read)
        if j != k and o.line == r.line
        for side in sides
    ):
        return True
    before = [float(y) for _r, _s, exprs in read[:k] for y in exprs if y is not None and y.is_number and y.is_real]
    return x.is_real and any(abs(float(x) - v) <= 0.01 * abs(v) + 1e-9 for v in (*known, *before))


def put_in(read: list, known: tuple[float, ...] | None = None) -> set[int]:
    """The indices in ``read`` ((relation, sides, expressions) of a chain's derivation) of the
    relations that put a value into a general result's letter (see the module's words); with
    ``known`` (the chain's values), not those that put in a number neither known nor found."""
    sets: dict[sympy.Symbol, list[int]] = {}
    for k, (r, _sides, exprs) in enumerate(read):
        left = exprs[0]
        if len(exprs) != 2 or not left.is_Symbol or not left.name.startswith(PREFIX) or left in exprs[1].free_symbols:
            continue
        if _said_as_put(left.name[len(PREFIX) :], r.written):
            sets.setdefault(left, []).append(k)
    out: set[int] = set()
    for p, ks in sets.items():
        values = {sympy.srepr(read[k][2][1]) for k in ks}
        used = any(p in x.free_symbols for j, (_r, _s, exprs) in enumerate(read) if j not in ks for x in exprs)
        if len(values) >= 2 and used:
            out |= {k for k in ks if known is None or _known(read[k][2][1], k, read, known)}
    return out


def judged(read: list, values: dict | None = None) -> list:
    """The relations of ``read`` to judge: not those that put a value into a letter (:func:`put_in`);
    ``values``: the chain's values, a number put in must be one of them or one found before."""
    known = None if values is None else tuple(float(v) for v in values.values() if v.is_number and v.is_real)
    put = put_in(read, known)
    return [x for k, x in enumerate(read) if k not in put]
