"""The JSON output: its contract, and every result's closed form reproduces its value.

Each ``expr`` is SymPy text written by derive itself (not user input), so
``sympy.sympify`` is fine here. Givens in the JSON carry numbers, angles in degrees;
angle symbols are substituted in radians (an angle's ``expr`` is in radians, its ``value``
and ``value_expr`` in degrees). A numeric result whose expr still has a
symbol (a given kept as a symbol, e.g. the cue ball's speed) must not depend on it:
it is checked at several positive values of that symbol.
"""

from __future__ import annotations

import json
import math
from numbers import Real

import pytest
import sympy
from support.output_cases import bundled_names, hostile_problem, solution

import derive

REL = 1e-9
PROBES = (0.37, 1.0, 2.9, 41.0)  # positive values for givens kept as symbols


def _doc(name: str) -> dict:
    text = derive.render(solution(name), "json")
    assert text.endswith("\n")
    return json.loads(text)


def _symbols(doc: dict) -> dict[str, sympy.Symbol]:
    """Every given and result name as a plain SymPy symbol (so 'e', 'E', 'S', 'N'... are never constants)."""
    names = set(doc["givens"]) | set(doc["results"])
    return {n: sympy.Symbol(n) for n in names}


def _numbers(doc: dict) -> dict[sympy.Symbol, float]:
    """Given -> its number, angles in radians."""
    out = {}
    for name, g in doc["givens"].items():
        if g["value"] is None:
            continue
        value = g["value"]
        out[sympy.Symbol(name)] = math.radians(value) if g["unit"] == "deg" else value
    return out


def _close(a: float, b: float) -> bool:
    return math.isclose(a, b, rel_tol=REL, abs_tol=1e-12)


@pytest.mark.parametrize("name", bundled_names())
def test_json_contract(name: str) -> None:
    doc = _doc(name)
    assert isinstance(doc["title"], str) and doc["title"] == solution(name).problem.title
    assert doc["kind"] in ("direct", "oblique", "chain")
    assert isinstance(doc["results"], dict) and doc["results"]
    for key in doc.get("find", []):
        assert key in doc["results"], f"asked-for {key} is not among the results"
    for key, r in doc["results"].items():
        assert {"value", "unit", "expr", "latex"} <= set(r), key
        assert r["value"] is None or (isinstance(r["value"], Real) and not isinstance(r["value"], bool)), key
        assert r["value"] is None or math.isfinite(r["value"]), key
        assert isinstance(r["unit"], str), key
        assert isinstance(r["expr"], str) and r["expr"], key
        assert isinstance(r["latex"], str) and r["latex"], key
    for key, g in doc["givens"].items():
        assert g["value"] is None or isinstance(g["value"], Real), key
        assert isinstance(g["unit"], str), key


def _check_results(doc: dict) -> list[str]:
    """Every problem with a result's expr: [] when each expr reproduces its value."""
    syms = _symbols(doc)
    numbers = _numbers(doc)
    given_names = set(doc["givens"])
    problems = []
    checked = 0
    for key, r in doc["results"].items():
        expr = sympy.sympify(r["expr"], locals=syms)
        unknown = {str(s) for s in expr.free_symbols} - given_names
        if unknown:
            problems.append(f"{key}: expr {r['expr']!r} uses {sorted(unknown)}, which are not givens")
            continue
        expr = expr.subs(numbers)
        free = sorted(expr.free_symbols, key=str)
        if r["value"] is None:
            if not free:
                problems.append(f"{key}: value is null but expr {r['expr']!r} is the number {sympy.N(expr)}")
            if "value_expr" in r:
                checked += 1
                partial = sympy.sympify(r["value_expr"], locals=syms)
                for probe in PROBES:
                    at = dict.fromkeys(free, probe)
                    a, b = sympy.N(expr.subs(at), 30), sympy.N(partial.subs(at), 30)
                    if not (a.is_real and b.is_real and a.is_finite and b.is_finite):
                        continue  # a pole of the letters (lam = 1 in (1 + k lam)/(k(1 - lam)))
                    # value_expr is in the value's unit: an angle's in degrees, its expr in radians
                    a, b = (math.degrees(float(a)) if r["unit"] == "deg" else float(a)), float(b)
                    if not _close(a, b):
                        problems.append(
                            f"{key}: expr gives {a!r} but value_expr {r['value_expr']!r} gives {b!r} at {at}"
                        )
                        break
            continue
        for probe in PROBES if free else (None,):
            at = dict.fromkeys(free, probe)
            got = sympy.N(expr.subs(at), 30)
            if not got.is_real:
                problems.append(f"{key}: expr {r['expr']!r} gives {got} (not a real number) at {at}")
                break
            got = math.degrees(float(got)) if r["unit"] == "deg" else float(got)
            if not _close(got, r["value"]):
                problems.append(f"{key}: expr {r['expr']!r} gives {got!r}, value is {r['value']!r} (at {at})")
                break
        checked += 1
    if checked == 0:
        problems.append("no result had a number or a value_expr to check")
    return problems


@pytest.mark.parametrize("name", bundled_names())
def test_result_exprs_reproduce_values(name: str) -> None:
    problems = _check_results(_doc(name))
    assert not problems, "\n".join(problems)


def test_hostile_direct_problem_json(tmp_path) -> None:
    text = derive.render(derive.solve(derive.load(hostile_problem(tmp_path))), "json")
    doc = json.loads(text)
    assert doc["title"].startswith("Direct impact: $5 & 100%")
    assert doc["kind"] == "direct"
    problems = _check_results(doc)
    assert not problems, "\n".join(problems)
