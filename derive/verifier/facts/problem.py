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
from derive.verifier.facts import source
from derive.verifier.facts.expression import Unread, evaluate
from derive.verifier.facts.model import Table, number
from derive.verifier.facts.physics import Before, after, derived, residuals

POST = {True: ("v_A2n", "v_A2t", "v_B2n", "v_B2t"), False: ("v_A2", "v_B2")}
TOLERANCE = 1e-20


def dim_of(g: object) -> units.Dim:
    d = tuple(getattr(g, "dim", units.NONE))
    return (d[0], d[1], d[2], d[3])


def givens(
    table: Table, problem: object, given_values: Mapping[str, sympy.Expr] | None = None, read: source.Read | None = None
) -> None:
    """Put each given in the table: a value, a definition, a "?" (later) or a letter. A
    value the verifier read from the file itself (``read``) stands before derive's."""
    for g in problem.givens:
        dim = dim_of(g)
        mine = file_value(table, read, g.name)
        if given_values and g.name in given_values:
            table.put(g.name, given_values[g.name], dim, "given")
            table.note_exact(given_values[g.name], g.unit == "deg")
        elif g.unknown:
            table.put(g.name, sympy.Symbol("unknown:" + g.name), dim, "unknown")
        elif mine is not None:
            table.put(g.name, mine, dim, "given")
            table.note_exact(mine, dim == units.ANGLE)
        elif g.value is not None:
            table.put(g.name, g.value, dim, "given")
            table.note_exact(g.value, g.unit == "deg")
        elif g.definition is not None:
            table.put(g.name, table.resolve(g.definition), dim, "given")
        else:
            table.param(g.name, dim)
        if g.written and read is None:
            table.note_exact(sympy.Rational(g.written.split()[0]))
    for typed in read.typed if read is not None else ():
        table.note_exact(typed)


def file_value(table: Table, read: source.Read | None, name: str) -> sympy.Expr | None:
    """The file's value of a given, in the table's numbers (None: a letter, an unknown, unread)."""
    if read is None or name not in read.values or name in read.unknowns:
        return None
    expr = read.values[name]
    if isinstance(expr, sympy.Symbol) and expr.name == name:
        return None
    if not expr.free_symbols:
        return expr  # exact, so that its digits are known as a given's
    value = table.resolve(expr)
    return None if value.free_symbols else value


def misread(table: Table, problem: object, read: source.Read, label: str = "") -> list[str]:
    """Where derive's loaded problem differs from the file as the verifier reads it: a
    value, a letter or an unknown, a dimension, the unit system, a velocity's components."""
    notes = []
    if getattr(problem, "system", read.system) != read.system:
        notes.append(f"{label}the file works in {read.system}; derive read {problem.system}")
    for g in problem.givens:
        if g.name not in read.values:
            continue
        said = f"{label}[given] {g.name}: "
        if g.unknown != (g.name in read.unknowns):
            notes.append(said + ("derive reads an unknown" if g.unknown else "derive reads no unknown"))
            continue
        if read.dims.get(g.name) not in (None, dim_of(g)):
            notes.append(
                said + f"the file gives {units.words(read.dims[g.name])}, derive read {units.words(dim_of(g))}"
            )
        mine, theirs = number(table.resolve(read.values[g.name]), {}), number(table.exprs.get(g.name), {})
        if g.value is not None:
            theirs = number(table.resolve(g.value), {})
        if mine is not None and theirs is not None and not _same(mine, theirs):
            notes.append(said + f"the file gives {float(mine):.6g}, derive read {float(theirs):.6g}")
    for b, mine_nt in read.motions.items():
        motion = getattr(problem, "motion_" + b, None)
        if motion is None or (b == "B" and getattr(problem, "fixed_B", False)):
            continue
        for axis, mine_c, theirs_c in zip("nt", mine_nt, (motion.n, motion.t), strict=True):
            x, y = number(table.resolve(mine_c), {}), number(table.resolve(theirs_c), {})
            if x is not None and y is not None and not _same(x, y) and (problem.kind == "oblique" or axis == "n"):
                notes.append(f"{label}v_{b}1{axis}: the file gives {float(x):.6g}, derive read {float(y):.6g}")
    if bool((read.data.get("B") or {}).get("fixed")) != bool(getattr(problem, "fixed_B", False)):
        notes.append(f"{label}[B] fixed: the file and derive differ")
    return notes


def _same(a: object, b: object) -> bool:
    return abs(a - b) <= 1e-15 * max(1, abs(a), abs(b))


def _from_results(table: Table, solution: object, name: str) -> sympy.Expr | None:
    r = getattr(solution, "results", {}).get(name)
    if r is None:
        return None
    return table.resolve(r.found * sympy.pi / 180 if r.unit == "deg" else r.found)


def impact(
    table: Table,
    solution: object,
    given_values: Mapping[str, sympy.Expr] | None = None,
    label: str = "",
    read: source.Read | None = None,
) -> list[str]:
    """Fill ``table`` with the impact's givens, components and results; return notes.

    ``solution`` may be a bare Problem (a homework variant's): its results are then
    worked out here only, and an inverse problem's unknowns are not known.
    """
    problem = getattr(solution, "problem", solution)
    givens(table, problem, given_values, read)
    notes: list[str] = misread(table, problem, read, label) if read is not None else []
    oblique = problem.kind == "oblique"
    inverse = any(g.unknown for g in problem.givens) or any(n in table.exprs for n in POST[oblique])
    for g in problem.givens:
        if g.unknown:
            table.exprs[g.name] = _from_results(table, solution, g.name)
    sym = table.exprs
    a_n, a_t = _motion(table, problem.motion_A, read, "A")
    b_n, b_t = _motion(table, problem.motion_B, read, "B")
    data = Before(
        sym["m_A"],
        sympy.Integer(0) if problem.fixed_B else sym["m_B"],
        sym["e"],
        a_n,
        a_t if oblique else sympy.Integer(0),
        b_n,
        b_t if oblique else sympy.Integer(0),
        problem.fixed_B,
    )
    post = after(data)
    if inverse:
        post = _inverse_post(table, solution, data, post, oblique)
        notes += _check_residuals(data, post, label)
    _put_components(table, data, post, oblique)
    phi = table.exprs.get("phi") if getattr(problem, "phi", None) is not None else None
    for name, expr in derived(data, post, phi).items():
        if not (oblique or name.startswith(("T_", "J_"))):
            continue
        table.put(
            name,
            expr,
            _DIMS.get(
                name[:2],
                units.ANGLE if name.startswith(("theta", "beta", "alpha", "gamma", "delta", "psi")) else units.NONE,
            ),
        )
    for b in "AB":
        comps = {"t": post[b + "2t"], "n": post[b + "2n"]}
        if phi is not None:
            comps.update(x=table.exprs.get(f"v_{b}2x", 0), y=table.exprs.get(f"v_{b}2y", 0))
        table.vectors[f"v_{b}2"] = comps
    if read is not None:
        _define(table, read)
    notes += _compare(table, solution, label)
    return notes


def _define(table: Table, read: source.Read) -> None:
    """The file's ``[define]`` quantities, from the results worked out here."""
    for name, text in (read.data.get("define") or {}).items():
        names = {n: (sympy.Symbol(n), table.dims.get(n, units.NONE)) for n in table.exprs}
        try:
            value, dim = evaluate(str(text), names)
        except (Unread, units.UnknownUnit):
            read.unread.append(f"[define] {name}")
            continue
        table.put(name, table.resolve(value), dim)


def _motion(table: Table, motion: object, read: source.Read | None, body: str) -> tuple[sympy.Expr, sympy.Expr]:
    """A body's (n, t) before the impact: as the file gives it, else as derive read it."""
    if read is not None and body in read.motions:
        mine = tuple(table.resolve(c) for c in read.motions[body])
        if not any(c.free_symbols - {s for s in c.free_symbols if s.name.startswith("unknown:")} for c in mine):
            return mine  # type: ignore[return-value]
    return table.resolve(motion.n), table.resolve(motion.t)


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


def _check_residuals(data: Before, post: dict, label: str) -> list[str]:
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
