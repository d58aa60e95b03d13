"""A chain's wrong line named by its one wrong term: a sign lost, or a squared term's ½.

A chain's lines are judged as numbers (:mod:`.chainlines`); a line that holds once one of its
terms is put right names the slip: a sign (:func:`~.slipnames.sign_of_a_term`), or the factor
2 of a square: the ½ of ½ m v² dropped is the kinetic energy's formula (``ke_formula``), a
½ lost from V² once the masses cancelled is a slip in rearranging (``algebra``).
"""

from __future__ import annotations

from collections.abc import Callable

import sympy

from derive.checking.rearranging import FACTORS
from derive.checking.slipnames import FLIPPED, sign_of_a_term

#: What a report says of a chain's line that holds with a squared term's factor of 2 put right.
HALVED = {
    "ke_formula": ": the kinetic energy is worked without its half (T = ½ m v²).",
    "algebra": ": it holds with a factor of 2 put back (a slip in rearranging: a factor lost).",
}


def term_slip(exprs: list[sympy.Expr], holds: Callable[[list], bool | None]) -> tuple[str, str]:
    """A chain's line named by the one term that is wrong, with the words for it: a sign lost
    (:func:`~.slipnames.sign_of_a_term`), else a squared term's factor of 2 lost or doubled:
    ``ke_formula`` where the square has a mass with it (``(15)(6) = (15/32.2) v1²``: the ½ of
    ½ m v² dropped), ``algebra`` where it stands alone (``V² = μ g d`` from ½ V² = μ g d: the
    masses cancelled and the ½ lost); ("", "") otherwise."""
    flip = sign_of_a_term(exprs, holds)
    if flip:
        return flip, FLIPPED[flip]
    found = set()
    for i, side in enumerate(exprs):
        for t in sympy.Add.make_args(side):
            squares = [p for p in t.atoms(sympy.Pow) if p.exp == 2 and p.base.free_symbols]
            if len(squares) != 1:
                continue
            for k in FACTORS:
                if holds([*exprs[:i], side + (k - 1) * t, *exprs[i + 1 :]]):
                    found.add("algebra" if abs(t / squares[0]) == 1 else "ke_formula")
    if len(found) != 1:
        return "", ""
    name = found.pop()
    return name, HALVED[name]
