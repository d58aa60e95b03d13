"""The slip is where its wrong value is first written.

A line that works a quantity of the student's own out by arithmetic (``v_y = 0.75 × 4 = 3``
for A's component across the line of centres; ``w = 5u`` for B's velocity after, solved from
an impulse with B's velocity before taken the wrong way) is right as arithmetic, and the checker
cannot tell at that line what it stands for. Where the first slip found later is explained by a
mistake whose world gives one of the velocities after exactly the value that line came to (and
the problem another), that earlier line is where the mistake was made: a teacher marks the slip
there, with the mistake's name, and the later line, worked from it, as carried.
"""

from __future__ import annotations

import re
from dataclasses import replace
from typing import Any

import sympy

from derive.checking.naming import PREFIX
from derive.checking.report import Item

#: How near two values are to be the same (relative), and far to be another.
_SAME = 1e-6
_NUMBER = re.compile(r"^\s*([-+]?\d+(?:\.\d+)?)(?![\d.])\s*(?:[A-Za-z][A-Za-z/\s]*)?$")  # a unit may follow


def moved_back(trace: Any, lines: list, items: list[Item | None]) -> list[Item | None]:
    """``items`` with the first slip moved back to the line that first wrote its value (see above)."""
    first = next((i for i in items if i is not None and i.kind == "line" and i.status == "wrong"), None)
    if first is None or not first.name.isdigit() or not (first.slip or first.diagnosis):
        return items
    worlds = [trace.world] if trace.world is not None else []
    named = {d.mistake for d in first.diagnosis} | set(first.slip.split(","))
    for o in trace.ctx.singles():  # the named mistake's own velocities after (a result's slip keeps none)
        if o.mistake is not None and o.mistake.name in named:
            worlds.append([{u: o.post[u].xreplace(pt) for u in trace.U} for pt in trace.pts])
    at = int(first.name)
    for line in lines:
        if line.number >= at or line.exprs is None or len(line.exprs) < 2:
            continue
        own = [i for i in items if i is not None and i.name == str(line.number)]
        if not own or any(i.status != "correct" for i in own) or not any(_unjudged(i, line) for i in own):
            continue
        if any(_the_worlds_value(trace, line, first, w) for w in worlds):
            m = _NUMBER.match(line.sides[-1])
            return _moved(items, line.number, first, m.group(1).lstrip("+") if m else "")
    return items


def _unjudged(item: Item, line: Any) -> bool:
    """Whether the line was right only as arithmetic or as a name of the student's own defined: its
    head a number (its name left out) or a name of the student's own, never a quantity of the
    problem (``v_B1 = 4`` states a given, whatever a slip's world makes of another velocity); a
    name defined there (``w = 5u``) is read as its value."""
    head = line.exprs[0]
    if head.is_Symbol and not head.name.startswith(PREFIX):
        return False  # a quantity of the problem, stated
    return item.message == "Its arithmetic is right." or item.method == "a definition" or bool(line.own_names)


def _the_worlds_value(trace: Any, line: Any, first: Item, slipped: list) -> bool:
    """Whether the value ``line`` came to is, at every sample point, a velocity after as the slip's
    world has it and not as the problem has it; a plain number must be written again in the slip."""
    value = trace.ctx.in_unknowns(line.exprs[-1])
    if any(trace.ctx.in_unknowns(x).free_symbols & set(trace.U) for x in line.exprs):
        return False  # judged as a relation in the velocities after: what it stands for was known
    m = _NUMBER.match(line.sides[-1])
    last = m.group(1) if m else line.sides[-1].strip()
    if not value.free_symbols and not (
        m and re.search(rf"(?<![\d.]){re.escape(last.lstrip('+'))}(?![\d.])", first.written)
    ):
        return False
    at = [sympy.N(value.xreplace(pt)) for pt in trace.pts]
    # a number at the figures written (half a unit in its last place), its size where written without a sign
    tol = 0.5 * 10.0 ** -len(last.split(".")[1]) if "." in last else 0.5 if not value.free_symbols else 0.0
    size = not value.free_symbols and not last.startswith(("-", "+"))
    before = [trace.ctx.num(x) for x in trace.ctx.model.pre.values()]  # the components before: the data
    given = [g.value for g in trace.ctx.problem.givens if g.value is not None]
    if any(_near(at[0], sympy.N(trace.ctx.in_unknowns(x).xreplace(trace.pts[0])), tol, True) for x in before + given):
        return False  # a value of the data, either way round (A's 9 before, u1 = 0.250): stated, not the slip's
    for u in trace.U:
        world = [sympy.N(w[u]) for w in slipped]
        truth = [sympy.N(t[u]) for t in trace.truth]
        if all(_near(a, w, tol, size) for a, w in zip(at, world, strict=True)) and not _near(
            at[0], truth[0], tol, size
        ):
            return True
    return False


def _near(a: sympy.Expr, b: sympy.Expr, tol: float, size: bool) -> bool:
    try:
        a, b = complex(a), complex(b)
    except TypeError:
        return False
    if size:
        a, b = abs(a), abs(b)
    return abs(a - b) <= max(tol, _SAME * max(abs(a), abs(b), 1.0))


def _moved(items: list[Item | None], k: int, first: Item, number: str) -> list[Item | None]:
    """The line ``k`` the slip, as ``first`` was named; ``first`` carried from it, and so is a line
    after it right only as arithmetic whose working writes the slip's ``number`` (``tan⁻¹(3/2)``)."""
    out: list[Item | None] = []
    uses = re.compile(rf"(?<![\d.]){re.escape(number)}(?![\d.])") if number else None
    for i in items:
        if i is not None and i.name.isdigit() and int(i.name) > int(first.name) and uses is not None:
            worked = " = ".join(i.written.split("=")[:-1])
            if i.status == "correct" and i.message == "Its arithmetic is right." and uses.search(worked):
                i = replace(i, status="carried", message=f"Right given the slip in line {k}: a carried error.")
        if i is not None and i.name == str(k):
            lead = "The first line that is false for this problem: the value it comes to is the slip's"
            said = first.message.split(":", 1)[1].strip() if ":" in first.message else ""
            i = replace(i, status="wrong", message=f"{lead}{': ' + said if said else '.'}", slip=first.slip)
            i = replace(i, diagnosis=first.diagnosis, method=first.method)
        elif i is not None and i.name == first.name and i.status == "wrong":
            msg = f"Right given the slip in line {k}: a carried error, not a new mistake."
            i = replace(i, status="carried", message=msg, slip="", diagnosis=(), expected="")
        out.append(i)
    return out
