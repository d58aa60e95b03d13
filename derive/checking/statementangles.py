"""An angle the question asks for named in its statement by a Greek letter alone ("just after,
it makes an angle β with the line of centres"; show ``(1 - e) tan β = 2 tan α``), while the problem
file names the result by body and time (``beta_A2``): the student's ``β``, ``\\beta`` or ``beta``
is that result, as the statement says.
"""

from __future__ import annotations

import re

from derive.problem import Problem

#: An angle's result by body and time: its Greek name, the body, after.
_ANGLE_RESULT = re.compile(r"(alpha|beta|gamma|delta|theta|phi|psi)_([AB])2")
_GREEK = {"alpha": "α", "beta": "β", "gamma": "γ", "delta": "δ", "theta": "θ", "phi": "φ", "psi": "ψ"}


def statement_angles(problem: Problem) -> dict[str, str]:
    """The Greek letters the statement gives an asked angle -> the result's name (``{"beta":
    "beta_A2"}``); none where the letter is a given, or two results share it."""
    asks = problem.asks
    asked = set(asks.answers) | set(getattr(problem, "find", ()) or ())
    for r in asks.show:
        asked |= {s.name for s in r.lhs.free_symbols | r.rhs.free_symbols}
    statement = getattr(problem, "statement", "") or ""
    taken = {g.name for g in problem.givens} | {d.name for d in asks.defined}
    found: dict[str, list[str]] = {}
    for name in sorted(asked):
        m = _ANGLE_RESULT.fullmatch(name)
        if m is None or m.group(1) in taken:
            continue
        if _GREEK[m.group(1)] in statement or re.search(rf"\b{m.group(1)}\b", statement):
            found.setdefault(m.group(1), []).append(name)
    out = {letter: names[0] for letter, names in found.items() if len(names) == 1}
    out.update(_defined_angle(problem, asked, taken | set(found), statement))
    return out


#: "turns A's direction of motion through an angle θ", "makes an angle of φ with": a letter named
#: as an angle in the statement or the question.
_NAMED_ANGLE = re.compile(r"\bangle\s+(?:of\s+)?(" + "|".join(_GREEK.values()) + r")")
_LETTERS = {g: name for name, g in _GREEK.items()}


def _defined_angle(problem: Problem, asked: set[str], taken: set[str], statement: str) -> dict[str, str]:
    """The statement's one angle letter of its own (``θ`` in "turns A's direction through an angle
    θ") -> the one asked quantity the file defines from the angles (``deflection = beta_A2 - psi``):
    the file's name for what the statement calls θ. None where either is not alone."""
    text = f"{statement} {getattr(problem, 'question', '') or ''}"
    letters = {_LETTERS[g] for g in _NAMED_ANGLE.findall(text)} - taken
    defined = [
        d.name
        for d in problem.asks.defined
        if d.name in asked
        and any(_ANGLE_RESULT.fullmatch(s.name) or s.name.startswith("delta_") for s in d.expr.free_symbols)
    ]
    if len(letters) != 1 or len(defined) != 1:
        return {}
    return {letters.pop(): defined[0]}
