"""The ``impact`` stage: a central impact inside a chain, read as a problem of its own
and solved by the same single-impact physics as a problem file."""

from __future__ import annotations

from dataclasses import dataclass, replace

import sympy

from derive.errors import InputError
from derive.physics.impact import independent_map
from derive.physics.outcome import ImpactOutcome, solve_impact
from derive.physics.state import ChainState, StageOutcome, resolve
from derive.problem import build_problem, units


@dataclass(frozen=True)
class ImpactStage:
    """The impact solved, and the results it hands on: ``exports`` pairs each new name
    for later stages with the impact's own result name; ``carried`` holds their values
    as far as they are known at this stage (in the unknowns a later stage solves for). A value
    whose chain letters the stage uses for other quantities (the chain's v_A1 where the stage's
    v_A1 is u_B) is kept in the names the stage has (u_B): its carried line is read in them."""

    outcome: ImpactOutcome
    exports: tuple[tuple[str, str], ...] = ()
    carried: tuple[sympy.Expr, ...] = ()


#: Results an impact stage works out on its page when a later stage takes them.
WORKED = ("J_n", "T_1", "T_2", "T_lost", "theta_A2", "theta_B2", "beta_A2", "beta_B2")


def impact(state: ChainState, i: int, st: dict) -> StageOutcome:
    """Solve the impact; name its results (``results = { v_A2 = "v_D" }``) for later stages."""
    table = {k: v for k, v in st.items() if k not in ("type", "results", "title")}
    data = {"title": st.get("title", "An impact"), **table}
    data.setdefault("given", {})
    data.setdefault("units", state.chain.system)  # its givens name the chain's: its units are the chain's
    exported = st.get("results", {})
    worked = [r for r in exported if r in WORKED] if isinstance(exported, dict) else []
    if worked and isinstance(data.get("find", []), list):
        data["find"] = list(dict.fromkeys([*data.get("find", ["v_A2", "v_B2"]), *worked]))
    # a chain's unknowns are symbols inside the stage: a later stage finds them
    seed = {n: (replace(g, unknown=False) if g.unknown else g) for n, g in state.known.items()}
    try:
        problem = build_problem(data, state.chain.stage_source(i), f"stage-{i}", seed=seed)
    except InputError as exc:
        raise type(exc)(exc.what, where=exc.where, field=exc.field or f"[stage {i}]") from None
    outcome = solve_impact(problem)
    results = st.get("results", {})
    if not isinstance(results, dict):
        raise state.err(i, "results", 'expected a table such as { v_A2 = "u_A" }', results)
    # into the chain's names: a stage given defined from them by its definition,
    # one written in the stage as a number by that number
    own = {
        g.symbol: (g.definition if g.definition is not None else g.value)
        for g in problem.givens
        if seed.get(g.name) is not g and (g.definition is not None or g.value is not None)
    }
    ind = independent_map(problem)
    state.approaches.append(resolve((problem.motion_A.n - problem.motion_B.n).xreplace(ind), own))
    outputs, exports, carried = [], [], []
    for rname, new in results.items():
        r = outcome.results.get(rname)
        if r is None or not isinstance(new, str):
            raise state.err(i, "results", f"{rname!r} is not a result of this impact", rname)
        dim = dimension_of(rname)
        expr = resolve(r.closed.xreplace(ind), own)  # m_A = W_A/g, W_A = W_bag: down to the chain's names
        if rname.startswith(("theta", "beta")):
            expr = r.partial * sympy.pi / 180 if r.value is None else r.value * sympy.pi / 180
        g = state.define(i, new, expr, dim, "deg" if dim == units.ANGLE else None)
        outputs.append(g.name)
        exports.append((g.name, rname))
        value = state.value(expr)
        if {x.name for x in value.free_symbols} & {x.name for x in own}:
            numbers = {g.symbol: g.value for g in state.known.values() if g.value is not None}
            value = sympy.expand(expr.xreplace(numbers).xreplace(state.solved))
        carried.append(value)
    for g in problem.givens:  # unknowns found by this impact become known to later stages
        if g.unknown and g.name not in state.known:
            r = outcome.results[g.name]
            state.define(i, g.name, resolve(r.closed.xreplace(ind), own), g.dim, g.unit)
            outputs.append(g.name)
    return StageOutcome(
        i, "impact", data["title"], ImpactStage(outcome, tuple(exports), tuple(carried)), tuple(outputs)
    )


def dimension_of(name: str) -> units.Dim:
    """The dimension of an impact's result, by its name."""
    if name.startswith(("theta", "beta")):
        return units.ANGLE
    if name.startswith("T_"):
        return units.ENERGY
    if name == "J_n":
        return units.IMPULSE
    if name in ("e",):
        return units.DIMENSIONLESS
    if name.startswith("m_"):
        return units.MASS
    return units.VELOCITY
