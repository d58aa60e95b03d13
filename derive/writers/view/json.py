"""The JSON of a solution: one impact's (the contract of DESIGN.md) or a chain's, from its view."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import sympy

from derive.fileio import dumps_json
from derive.numbers import format_number
from derive.physics.results import Result
from derive.problem import Given
from derive.problem.units import plain_unit
from derive.steps.model import Solution
from derive.writers.printing import StepPrinter
from derive.writers.view.page import view


def _text_with_math(parts: list[tuple[str, str]] | None) -> str:
    if not parts:
        return ""
    return "".join(f"${s}$" if kind == "math" else s for kind, s in parts)


def _givens_json(givens: tuple[Given, ...]) -> dict[str, dict[str, Any]]:
    """Each given's number (angles in degrees; null when symbolic) and unit."""
    return {
        g.name: {
            "value": None
            if g.value is None
            else float(sympy.N(g.value * 180 / sympy.pi if g.unit == "deg" else g.value, 17)),
            "unit": "deg" if g.unit == "deg" else plain_unit(g.unit),
        }
        for g in givens
    }


#: The keys of each kind's JSON, in order: one impact's (the contract of DESIGN.md: with what
#: its physics decided, "show that" results and ranges), and a chain's (one per stage of the chain).
KEYS = {
    "impact": ("title", "kind", "source", "units", "find", "results", "givens", "show", "ranges", "stages"),
    "chain": ("title", "kind", "source", "find", "givens", "results", "stages"),
}


def _results(found: Mapping[str, Result], d: int, described: bool) -> dict[str, dict[str, Any]]:
    """Each result: its number, unit, expression (text and LaTeX), the number as shown, and
    (``described``: one impact's) its description, or its expression where it has no number."""
    results = {}
    printer = StepPrinter()
    for name, r in found.items():
        entry: dict[str, Any] = {
            "value": None if r.value is None else float(sympy.N(r.value, 17)),
            "unit": plain_unit(r.unit) if r.unit != "deg" else "deg",
            "expr": str(r.closed),
            "latex": printer.doprint(r.closed),
        }
        if described:
            entry["description"] = r.description
        if r.value is not None:
            entry["shown"] = format_number(r.value, d)
        elif described:
            entry["value_expr"] = str(r.partial)
        results[name] = entry
    return results


def _stages(page: dict[str, Any]) -> list[dict[str, Any]]:
    """Each stage's sentences and lines: a titled stage (a chain's) as one, its own stages'
    blocks run together; the stages of the untitled one (a single impact's) each as one."""
    stages = []
    for st in page["stages"]:
        subs = [st] if st["title"] else st["stages"]
        for sub in subs:
            blocks = [b for inner in sub["stages"] for b in inner["blocks"]] if sub is st else []
            stages.append(
                {
                    "number": sub["number"],
                    "title": sub["title"],
                    "blocks": [
                        {
                            "text": _text_with_math(b["text"]),
                            "lines": [{"latex": ln["latex"], "tag": ln["tag"]} for ln in b["lines"]],
                        }
                        for b in [*blocks, *sub["blocks"]]
                    ],
                }
            )
    return stages


def to_json(solution: Solution, digits: int | None = None, page: dict[str, Any] | None = None) -> str:
    """The solution as JSON: title, kind, results (+ givens and each stage's lines), the keys
    of :data:`KEYS` for its kind; ``page`` is its view (:func:`view`), when already made."""
    p = solution.problem
    d = digits if digits is not None else p.digits
    page = page if page is not None else view(solution, digits, figures=False)  # the lines only
    kind = "chain" if any(st["title"] for st in page["stages"]) else "impact"
    printer = StepPrinter()
    doc = {
        "title": p.title,
        "kind": p.kind,
        "source": p.source,
        "units": p.system,
        "find": list(p.find),
        "results": _results(solution.results, d, kind == "impact"),
        "givens": _givens_json(p.givens),
        "show": [
            {
                "relation": s.relation.text,
                "holds": s.holds,
                "decided": s.how,
                "found": str(s.lhs),
                "counterexample": {k.name: v for k, v in (s.counterexample or {}).items()} or None,
            }
            for s in solution.shown
        ],
        "ranges": [
            {
                "of": f.range.of.name,
                "where": f.range.text,
                "interval": None if f.interval is None else str(f.interval),
                "latex": None if f.interval is None else printer.doprint(f.interval),
            }
            for f in solution.ranges
        ],
        "stages": _stages(page),
    }
    out = {key: doc[key] for key in KEYS[kind]}
    if solution.others:  # the data allow more than one physical solution: the others, in order
        out["others"] = [_results(found, d, True) for found in solution.others]
    return dumps_json(out)
