"""suvat's letters in the fall a chain starts with, read as a teacher reads them.

A student works a fall with the constant-acceleration equations in their own letters:
``v^2 = u^2 + 2as = 5^2 + 2(9.8)(1.6)``, ``v = 7.51`` "when it hits the ground", ``u = 5, a = 9.8,
s = 1.6``. In those lines ``u`` is the speed the body starts with (the chain's own ``u``, a result
of its impact, is another quantity), ``v`` the speed it lands with (the fall's result), ``s`` the
height and ``a`` the acceleration g. A teacher reads them so whatever the numbers put in for
them: ``v^2 = 5 + 2(9.8)(1.6) = 36.36`` is the landing speed worked wrongly (5 for 5²), a slip,
not a name of the student's own that the line defines and so makes true.

The letters are read so in the relations the derivation opens with, up to the first that names
anything else than suvat's letters, numbers and the givens (a later ``I = mv - mu`` is an
impulse, in the same letters meaning other velocities), and only where a ``v`` of the student's
own is among them. The sign (down positive, or up) is the one that makes more of those relations
hold; down where neither does. A ``u`` the opening works out with no ``v`` beside it, false as the
start speed either way (``u^2 = 2(9.8)(2) = 39.2``, ``u = 6.26``: the student's name for the
landing speed), says the letters are the student's own: then none is read so (the ``v`` after it
is then the rebound's, ``v^2 = 2(9.8)(1.4)``).
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

from derive.checking.naming import PREFIX, Open

#: suvat's letters as the reader keeps a name of the student's own.
LETTERS = {k: sympy.Symbol(PREFIX + k) for k in "uvsa"}


def fall_letters(ctx, read: list, names: Open, said: dict, holds: Callable) -> tuple[list, list[str]]:
    """``read`` with suvat's letters in the opening fall put as the fall's quantities, and the
    notes that say so (``read`` as it is where the chain does not start with a fall). A letter
    met in no later relation is the fall's in ``names`` too, for a side read again (a given
    put back as the problem states it)."""
    stages = getattr(ctx.problem, "stages", ())
    fall = stages[0] if stages and stages[0].get("type") == "fall" else None
    landing = sympy.Symbol(fall["result"]) if fall is not None else None
    if fall is None or said.get(LETTERS["v"], landing) != landing:  # v said to be another quantity
        return read, []
    given = {sympy.Symbol(g.name) for g in getattr(ctx.problem, "givens", ())}
    start = sympy.Symbol(fall["speed"]) if fall.get("speed") else sympy.Integer(0)
    g = sympy.Symbol("g") if sympy.Symbol("g") in given else None
    meaning = {"u": start, "v": landing, "s": sympy.Symbol(fall["height"]), "a": g}
    letters = {LETTERS[k]: x for k, x in meaning.items() if x is not None}
    chain_u = sympy.Symbol("u")
    if chain_u not in given and "u" in meaning:
        letters[chain_u] = start  # the chain's u is its impact's result: the student's is suvat's
    h = sympy.Symbol(PREFIX + "h")  # the height as h, in the law written in the chain's v_1 only (v_1² = u² + 2gh)
    if any(landing in f and h in f for f in (set().union(*(x.free_symbols for x in ex)) for _r, _s, ex in read[:5])):
        letters[h] = sympy.Symbol(fall["height"])
    allowed = set(letters) | given | {landing}  # v_1 = … in the chain's own name for the landing speed
    others = set(letters) - {LETTERS["v"]}  # the law in v_1: suvat's only beside u, s, a (v_1² = u² + 2as)
    n = 0
    for _r, _sides, exprs in read:  # "e = 0.7" beside g on the opening line goes on with it
        restated = len(exprs) == 2 and exprs[0].is_Symbol and exprs[0] not in letters and not exprs[1].free_symbols
        free = set().union(*(x.free_symbols for x in exprs))
        if (not free <= allowed and not restated) or (landing in free and not free & others):
            break
        if h in free and landing not in free:  # h beside no v_1: a later height, not the fall's
            break
        n += 1
    opening = read[:n]
    if not any({LETTERS["v"], landing} & x.free_symbols for _r, _s, ex in opening for x in ex):
        return read, []

    def put(sign: int) -> list:
        subs = {p: sign * x for p, x in letters.items()}
        return [(r, sides, [x.xreplace(subs) for x in exprs]) for r, sides, exprs in opening]

    down, up = put(1), put(-1)
    if _u_own(opening, down, up, holds, {p for p in letters if p.name.lstrip(PREFIX) == "u"}):
        return read, []
    score = [sum(bool(holds(sides, exprs)) for _r, sides, exprs in w) for w in (down, up)]
    sign = -1 if score[1] > score[0] else 1
    later = set().union(*(x.free_symbols for _r, _s, ex in read[n:] for x in ex))
    names.known.update({p.name.lstrip(PREFIX): sign * x for p, x in letters.items() if p not in later | {h}})
    used = sorted({p.name.lstrip(PREFIX) for _r, _s, ex in opening for x in ex for p in x.free_symbols} & set(meaning))
    note = "Read " + ", ".join(f"{k} as {sign * meaning[k]}" for k in used if meaning.get(k) is not None) + "."
    return (up if sign < 0 else down) + read[n:], [note]


def _u_own(opening: list, down: list, up: list, holds: Callable, u: set) -> bool:
    """Whether a relation of ``opening`` in suvat's ``u`` (``u``: its symbols) and no ``v`` holds
    neither way round."""
    for k, (_r, sides, exprs) in enumerate(opening):
        free = set().union(*(x.free_symbols for x in exprs))
        if free & u and LETTERS["v"] not in free and not holds(sides, down[k][2]) and not holds(sides, up[k][2]):
            return True
    return False
