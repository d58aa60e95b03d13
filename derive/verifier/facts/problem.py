"""Facts of one impact, read from derive's Problem (the data) and checked against (1)-(4).

The givens come from the problem as loaded; the velocities after the impact are
worked out again by :mod:`derive.verifier.facts.physics`. Where derive had to
find unknowns (an inverse problem: e, a mass, an angle), its values are taken
and put back into (1)-(4); a value that does not satisfy them is a note.
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy

from derive.verifier import units
from derive.verifier.facts.model import Table, number
from derive.verifier.facts.physics import Before, after, derived, residuals

POST = {True: ("v_A2n", "v_A2t", "v_B2n", "v_B2t"), False: ("v_A2", "v_B2")}
TOLERANCE = 1e-20


def dim_of(g: object) -> units.Dim:
    d = tuple(getattr(g, "dim", units.NONE))
    return (d[0], d[1], d[2], d[3])


def givens(table: Table, problem: object, given_values: Mapping[str, sympy.Expr] | None = None) -> None:
    """Put each given in the table: a value, a definition, a "?" (later) or a letter."""
    for g in problem.givens:
        dim = dim_of(g)
        if given_values and g.name in given_values:
            table.put(g.name, given_values[g.name], dim, "given")
            table.note_exact(given_values[g.name], g.unit == "deg")
        elif g.unknown:
            table.put(g.name, sympy.Symbol("unknown:" + g.name), dim, "unknown")
        elif g.value is not None:
            table.put(g.name, g.value, dim, "given")
            table.note_exact(g.value, g.unit == "deg")
        elif g.definition is not None:
            table.put(g.name, table.resolve(g.definition), dim, "given")
        else:
            table.param(g.name, dim)
        if g.written:
            table.note_exact(sympy.Rational(g.written.split()[0]))


def _from_results(table: Table, solution: object, name: str) -> sympy.Expr | None:
    r = getattr(solution, "results", {}).get(name)
    if r is None:
        return None
    value = r.value if r.value is not None else r.partial
    if r.unit == "deg":
        value = value * sympy.pi / 180
    return table.resolve(value)


def impact(
    table: Table,
    solution: object,
    given_values: Mapping[str, sympy.Expr] | None = None,
    label: str = "",
) -> list[str]:
    """Fill ``table`` with the impact's givens, components and results; return notes.

    ``solution`` may be a bare Problem (a homework variant's): its results are then
    worked out here only, and an inverse problem's unknowns are not known.
    """
    problem = getattr(solution, "problem", solution)
    givens(table, problem, given_values)
    oblique = problem.kind == "oblique"
    inverse = any(g.unknown for g in problem.givens) or any(n in table.exprs for n in POST[oblique])
    for g in problem.givens:
        if g.unknown:
            table.exprs[g.name] = _from_results(table, solution, g.name)
    sym = table.exprs
    data = Before(
        sym["m_A"],
        sympy.Integer(0) if problem.fixed_B else sym["m_B"],
        sym["e"],
        table.resolve(problem.motion_A.n),
        table.resolve(problem.motion_A.t) if oblique else sympy.Integer(0),
        table.resolve(problem.motion_B.n),
        table.resolve(problem.motion_B.t) if oblique else sympy.Integer(0),
        problem.fixed_B,
    )
    post = after(data)
    notes: list[str] = []
    if inverse:
        post = _inverse_post(table, solution, data, post, oblique)
        notes += _check_residuals(table, data, post, label)
    _put_components(table, data, post, oblique)
    phi = table.exprs.get("phi") if getattr(problem, "phi", None) is not None else None
    for name, expr in derived(data, post, phi).items():
        if not (oblique or name.startswith(("T_", "J_"))):
            continue
        table.put(name, expr, _DIMS.get(name[:2], units.ANGLE if name.startswith(("theta", "beta")) else units.NONE))
    for b in "AB":
        comps = {"t": post[b + "2t"], "n": post[b + "2n"]}
        if phi is not None:
            comps.update(x=table.exprs.get(f"v_{b}2x", 0), y=table.exprs.get(f"v_{b}2y", 0))
        table.vectors[f"v_{b}2"] = comps
    notes += _compare(table, solution, label)
    return notes


_DIMS = {"v_": units.VELOCITY, "T_": units.ENERGY, "J_": units.IMPULSE}


def _inverse_post(table: Table, solution: object, data: Before, post: dict, oblique: bool) -> dict:
    """The components after the impact of an inverse problem: given, or derive's."""
    out = dict(post)
    for name in POST[oblique]:
        key = name[3:] if oblique else name[3:] + "n"
        if data.fixed and key.startswith("B"):
            continue
        if name in table.exprs:
            out[key] = table.exprs[name]
        else:
            found = _from_results(table, solution, name)
            if found is not None:
                out[key] = found
    if not oblique:
        out["A2t"] = out["B2t"] = sympy.Integer(0)
    return out


def _check_residuals(table: Table, data: Before, post: dict, label: str) -> list[str]:
    notes = []
    for k, res in residuals(data, post).items():
        x = number(res, {})
        if x is not None and abs(x) > TOLERANCE * max(1, float(abs(number(data.m_A, {}) or 1))):
            notes.append(
                f"{label}derive's solution does not satisfy equation ({k}) of the notes (residual {float(x):.3g})"
            )
    return notes


def _put_components(table: Table, data: Before, post: dict, oblique: bool) -> None:
    """v_A1n ... v_B2t (oblique), or v_A1 ... v_B2 signed along n, with v_A1n ... as aliases (direct)."""
    before = {"A1n": data.a_n, "A1t": data.a_t, "B1n": data.b_n, "B1t": data.b_t}
    for key, expr in (*before.items(), *post.items()):
        if not oblique and key.endswith("t"):
            continue
        names = (f"v_{key}",) if oblique else (f"v_{key[:2]}", f"v_{key}")
        given = table.roles.get(names[0]) == "given"
        kind = "given" if key[1] == "1" or given or (data.fixed and key.startswith("B")) else "unknown"
        for name in names:
            if table.roles.get(name) != "given":
                table.put(name, expr, units.VELOCITY, kind)
    if oblique:
        for b in "AB":
            if f"v_{b}1" not in table.exprs:
                table.put(f"v_{b}1", sympy.sqrt(before[b + "1n"] ** 2 + before[b + "1t"] ** 2), units.VELOCITY)
            table.vectors[f"v_{b}1"] = {"t": before[b + "1t"], "n": before[b + "1n"]}


def _compare(table: Table, solution: object, label: str) -> list[str]:
    """derive's velocities after the impact and its unknowns against the ones worked out
    here: a difference is a note (the rest derives from these on the page itself)."""
    notes = []
    problem = getattr(solution, "problem", solution)
    core = (*POST[True], *POST[False], *(g.name for g in problem.givens if g.unknown))
    for name in (n for n in getattr(solution, "results", {}) if n in core):
        mine = table.exprs.get(name)
        theirs = _from_results(table, solution, name)
        a, b = number(mine, {}), number(theirs, {})
        if a is None or b is None:
            continue
        if abs(a - b) > 1e-12 * max(1, abs(a), abs(b)):
            notes.append(f"{label}derive's {name} = {float(b):.6g}, but (1)-(4) give {float(a):.6g}")
    return notes
