"""What the report says of the names a derivation's lines were read with: declared, read by habit,
inferred from the relations, and the positive direction; momenta and energies read by the name grammar
(``p_i``) said in words.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.beforeangles import described
from derive.checking.reducedmass import is_reduced_mass


def words_for(e: sympy.Expr) -> str | None:
    """A momentum or a kinetic energy this grammar reads (``p_i``: m_A v_A1 + m_B v_B1) in words,
    for the report ("the momentum of A and B before the impact"); None for anything else."""
    speeds = [s.name for s in e.free_symbols if re.fullmatch(r"v_[AB][12][nt]?", s.name)]
    masses = [s.name for s in e.free_symbols if re.fullmatch(r"m_[AB]", s.name)]
    if not speeds or not masses or len({n[3] for n in speeds}) != 1:
        return None
    bodies = sorted({n[2] for n in speeds})
    when = "before" if speeds[0][3] == "1" else "after"
    powers = [a for a in sympy.preorder_traversal(e) if isinstance(a, sympy.Pow)]
    per = [a.base for a in powers if a.exp == -1]
    if per and [getattr(p, "name", "") for p in per] != ["m"]:
        return None  # (m_A v_A2 + m_B v_B2)/(m_A + m_B): the common velocity, said as such
    kind = "kinetic energy" if any(a.exp == 2 and a.base.is_Symbol for a in powers) else "momentum"
    whose = "of A and B" if len(bodies) == 2 else f"of {bodies[0]}"
    return f"the {kind} {whose} {when} the impact" + (" over m (the m cancelled)" if per else "")


def said_read(meanings: dict, declared: dict, inferred: dict[str, str], sign: int, declared_sign: int) -> list[str]:
    """What the report says of the names it read: declared, read by habit, inferred, and the sign."""
    out = []
    habit = [f"{n} as {_shown(e)}" for n, e in meanings.items() if n not in declared]
    if declared:
        out.append("Declared: " + ", ".join(f"{n} is {_shown(e)}" for n, e in declared.items()) + ".")
    if habit:
        out.append("Read " + ", ".join(habit) + ".")
    if inferred:
        out.append("Inferred from the relations: " + ", ".join(f"{n} is {what}" for n, what in inferred.items()) + ".")
    if sign == -1 and not declared_sign:
        out.append("Inferred from the values written: the positive direction is opposite to derive's n (B toward A).")
    return out


def _shown(e: sympy.Expr) -> str:
    if isinstance(e, sympy.Abs) and isinstance(e.args[0], sympy.Symbol):
        return e.args[0].name  # a given restated without its sign: said as that given
    if isinstance(-e, sympy.Symbol):
        return (
            f"-{(-e).name}"  # -J_n (the impulse on A), a component on an axis turned round, a speed declared backwards
        )
    if e == 0:
        return "the fixed velocity"  # (v_C)_1: the wall's, which does not move
    if is_reduced_mass(e):
        return "the reduced mass m_A m_B/(m_A + m_B)"
    if e.is_Add and (body := _relative(e)):
        return f"{body} relative to the centre of mass"  # v_A1 - v_cm (:mod:`.cmframe`)
    return e.name if isinstance(e, sympy.Symbol) else words_for(e) or described(e) or "the common velocity"


def _relative(e: sympy.Expr) -> str:
    """``v_A1n`` for v_A1n - (m_A v_A1n + m_B v_B1n)/(m_A + m_B): a velocity less the centre of
    mass's (the velocity whose removal leaves the simplest remainder over m_A + m_B)."""
    found = []
    for s in e.free_symbols:
        rest = sympy.together(s - e)
        if re.fullmatch(r"v_[AB][12]n?", s.name) and {str(x) for x in sympy.denom(rest).free_symbols} == {"m_A", "m_B"}:
            found.append((sympy.count_ops(rest), s.name))
    return min(found)[1] if found else ""


def in_order(meanings: dict, written: list[str]) -> dict:
    """``meanings`` in the order its names are first written (then by name): the readers find them
    in sets, whose order changes from one run to the next with Python's string hashing."""
    first = {w: i for i, w in enumerate(written)}
    return dict(sorted(meanings.items(), key=lambda kv: (first.get(kv[0], len(first)), kv[0])))
