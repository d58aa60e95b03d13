"""The JSON of one impact (the contract of DESIGN.md) and of a chain."""

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
from derive.writers.view.chain import chain_view
from derive.writers.view.problem import view


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


def _results(found: Mapping[str, Result], d: int) -> dict[str, dict[str, Any]]:
    """Each result of one impact: its number, unit, expression (text and LaTeX) and description."""
    results = {}
    printer = StepPrinter()
    for name, r in found.items():
        value = None if r.value is None else float(sympy.N(r.value, 17))
        entry: dict[str, Any] = {
            "value": value,
            "unit": plain_unit(r.unit) if r.unit != "deg" else "deg",
            "expr": str(r.closed),
            "latex": printer.doprint(r.closed),
            "description": r.description,
        }
        if r.value is not None:
            entry["shown"] = format_number(r.value, d)
        else:
            entry["value_expr"] = str(r.partial)
        results[name] = entry
    return results


def to_json(solution: Solution, digits: int | None = None) -> str:
    """The JSON contract of DESIGN.md: title, kind, results (+ givens and steps)."""
    p = solution.problem
    d = digits if digits is not None else p.digits
    results = _results(solution.results, d)
    printer = StepPrinter()
    v = view(solution, digits, figures=False)  # the lines only: JSON has no figures
    doc = {
        "title": p.title,
        "kind": p.kind,
        "source": p.source,
        "units": p.system,
        "find": list(p.find),
        "results": results,
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
        "stages": [
            {
                "number": s["number"],
                "title": s["title"],
                "blocks": [
                    {
                        "text": _text_with_math(b["text"]),
                        "lines": [{"latex": ln["latex"], "tag": ln["tag"]} for ln in b["lines"]],
                    }
                    for b in s["blocks"]
                ],
            }
            for s in v["stages"]
        ],
    }
    if solution.others:  # the data allow more than one physical solution: the others, in order
        doc["others"] = [_results(found, d) for found in solution.others]
    return dumps_json(doc)


def chain_json(sol: Any, digits: int | None) -> str:
    """A chain's JSON: its givens, results (number, unit, expression) and each stage's lines."""
    p = sol.problem
    d = digits if digits is not None else p.digits
    results = {}
    for name, r in sol.results.items():
        results[name] = {
            "value": None if r.value is None else float(sympy.N(r.value, 17)),
            "unit": "deg" if r.unit == "deg" else plain_unit(r.unit),
            "expr": str(r.closed),
            "latex": StepPrinter().doprint(r.closed),
        }
        if r.value is not None:
            results[name]["shown"] = format_number(r.value, d)
    givens = _givens_json(p.givens)
    view_ = chain_view(sol, digits, figures=False)
    stages = []
    for st in view_["stages"]:
        subs = st["stages"] if st["impact"] else [{"blocks": st["blocks"]}]
        blocks = [b for sub in subs for b in sub["blocks"]]
        stages.append(
            {
                "number": st["number"],
                "title": st["title"],
                "blocks": [
                    {
                        "text": _text_with_math(b["text"]),
                        "lines": [{"latex": ln["latex"], "tag": ln["tag"]} for ln in b["lines"]],
                    }
                    for b in blocks
                ],
            }
        )
    doc = {
        "title": p.title,
        "kind": "chain",
        "source": p.source,
        "find": list(p.find),
        "givens": givens,
        "results": results,
        "stages": stages,
    }
    return dumps_json(doc)
