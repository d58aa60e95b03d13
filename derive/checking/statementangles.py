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
    return {letter: names[0] for letter, names in found.items() if len(names) == 1}
