"""A single impact: a checked problem table assembled into a :class:`~derive.problem.records.Problem`.

The table's fields were checked against the schema (:mod:`derive.problem.validate`);
here the givens are built (:mod:`~derive.problem.givens`), the velocities and the line
of impact worked out (:mod:`~derive.problem.motion`), the results asked for and the
homework fields read (:mod:`~derive.problem.fields`), and the record checks its
physics as it is built; its errors get their place in the file here.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from dataclasses import replace
from typing import Any

import sympy

from derive.problem import fields, units
from derive.problem.givens import GRAVITY, build_givens, given_value, infer_system, quantity, read_assume
from derive.problem.motion import geometry, misspelt, motion
from derive.problem.records import Given, Motion, Problem, RecordError
from derive.problem.schema import PROBLEM
from derive.problem.source import Source
from derive.problem.symbolic import Asks, Relation, read_asks
from derive.problem.units import ANGLE, MASS, VELOCITY, Dim
from derive.problem.validate import check
from derive.symbols import symbol

#: Velocities after the impact, by kind: given in an inverse problem, else unknown.
POST = {"direct": ("v_A2", "v_B2"), "oblique": ("v_A2t", "v_A2n", "v_B2t", "v_B2n")}
_FIXED_B_TAKES_NONE = ("m_B", "W_B", "v_B1", "v_B1n", "v_B1t", "v_B2", "v_B2n", "v_B2t")


def build_problem(data: dict[str, Any], ctx: Source, name: str, seed: Mapping[str, Given] | None = None) -> Problem:
    """A Problem from parsed TOML. ``seed`` holds givens known already (a chain's
    earlier results): the file's values may refer to them, and a required name the
    file leaves out (m_A, e, ...) is taken from them."""
    check(data, PROBLEM, ctx)
    if data["kind"] == "chain":
        raise ctx.error('expected "direct" or "oblique" here', key="kind", value="chain")
    kind, given_tbl = data["kind"], data["given"]
    oblique = kind == "oblique"
    system = data.get("units") or infer_system(given_tbl)
    assume = read_assume(data.get("assume"), given_tbl, ctx)
    # directions after the impact, known; in x-y axes, also velocities after as x/y components
    known_after = AFTER + (AFTER_XY if "geometry" in data else ())
    after = {k: v for k, v in given_tbl.items() if k in known_after}
    given_tbl = {k: v for k, v in given_tbl.items() if k not in known_after}
    givens = build_givens(given_tbl, ctx, oblique, system, seed, assume)
    by_name = {g.name: g for g in givens}
    bodies = {b: data.get(b, {}) for b in "AB"}
    fixed_B = bodies["B"].get("fixed") is True
    _take_from_seed(
        givens, by_name, seed or {}, fixed_B, any(w in given_tbl or w in (seed or {}) for w in ("W_A", "W_B"))
    )
    _check_fixed(bodies, by_name, ctx)
    _masses_from_weights(givens, by_name, fixed_B, system, ctx)
    _check_needs(by_name, kind, fixed_B, ctx)
    phi = geometry(data.get("geometry"), givens, by_name, ctx, oblique, system)
    motions = _motions(bodies, givens, by_name, ctx, oblique, phi, fixed_B)
    unknown = tuple(g.name for g in givens if g.unknown)
    results = fields.result_dims(oblique, fixed_B, phi is not None)
    asks = _asks(data, givens, by_name, after, ctx, oblique, system, results, seed or {})
    extra_names = tuple(d.name for d in asks.defined) + (
        ("v_A2x", "v_A2y", "v_B2x", "v_B2y") if phi is not None else ()
    )
    try:
        return Problem(
            path=ctx.path,
            title=data["title"],
            kind=kind,
            givens=tuple(givens),
            motion_A=motions[0],
            motion_B=motions[1],
            find=fields.find(data.get("find"), ctx, oblique, unknown, extra_names),
            system=system,
            digits=data.get("digits"),
            source=data.get("source"),
            statement=data.get("statement"),
            question=data.get("question"),
            name=name,
            fixed_B=fixed_B,
            name_B=bodies["B"].get("name"),
            labels=_labels(bodies, fixed_B, ctx, in_chain=seed is not None),
            phi=phi,
            answer_units=fields.answer_units(data.get("answer_units"), ctx),
            vary=fields.vary(data.get("vary"), by_name, ctx, oblique, system),
            conditions=fields.conditions(
                data.get("conditions"), by_name, ctx, {n: (symbol(n), d) for n, d in results.items()}, system=system
            ),
            assume=assume,
            asks=asks,
            ctx=ctx,
        )
    except RecordError as exc:
        raw = data.get(exc.section, {}).get(exc.key) if exc.section else data.get(exc.key or "")
        raise ctx.error(exc.what, section=exc.section, key=exc.key, value=raw, cls=exc.cls) from exc


def _motions(
    bodies: Mapping[str, Any],
    givens: list[Given],
    by_name: dict[str, Given],
    ctx: Source,
    oblique: bool,
    phi: sympy.Symbol | None,
    fixed_B: bool,
) -> list[Motion]:
    """A's and B's velocities before the impact; an angle they need is added to the givens."""
    motions = []
    for b in "AB":
        if b == "B" and fixed_B:
            motions.append(Motion("B", sympy.Integer(0), sympy.Integer(0)))
            continue
        found, extra = motion(b, bodies[b], by_name, ctx, oblique, phi)
        if extra is not None:
            givens.append(extra)
            by_name[extra.name] = extra
        motions.append(found)
    return motions


#: Results after the impact a file may give as knowns (each becomes an equation).
AFTER = ("theta_A2", "theta_B2", "beta_A2", "beta_B2")
#: In x-y axes ([geometry]), the velocities after the impact as measured components.
AFTER_XY = ("v_A2x", "v_A2y", "v_B2x", "v_B2y")


def _asks(
    data: Mapping[str, Any],
    givens: list[Given],
    by_name: Mapping[str, Given],
    after: Mapping[str, Any],
    ctx: Source,
    oblique: bool,
    system: str,
    results: Mapping[str, Dim],
    seed: Mapping[str, Given],
) -> Asks:
    """What the problem asks beyond the velocities (``show``, ``range``, ``equations``,
    ``define``, ``answers``), in the givens and the ``results`` this kind of impact has,
    and the directions after the impact given as knowns. In a chain's impact stage they may
    name the chain's quantities too (``seed``)."""
    outer = [g for n, g in seed.items() if n not in by_name and n not in fields.RESULT_DIMS]
    asks = read_asks(
        data,
        {g.name: (g.symbol, g.dim) for g in [*outer, *givens]},
        results,
        {g.name for g in [*outer, *givens] if g.value is None and g.definition is None and not g.unknown},
        system,
        ctx,
    )
    return replace(asks, equations=asks.equations + _known_after(after, by_name, ctx, oblique, system))


def _known_after(
    after: Mapping[str, Any], by_name: Mapping[str, Given], ctx: Source, oblique: bool, system: str
) -> tuple[Relation, ...]:
    """A direction after the impact given as a known: ``theta_A2 = "30 deg"`` is the
    equation theta_A2 = 30°, which fixes one more unknown."""
    out = []
    for name, raw in after.items():
        if not oblique:
            raise ctx.error('a direction after the impact needs kind = "oblique"', section="given", key=name)
        g = given_value(name, raw, by_name, ctx, oblique, system)
        if name in AFTER_XY:  # v_A2x = "1 m/s": the equation v_A2x = 1 (a line of impact "?" may follow)
            if g.dim != VELOCITY or g.value is None:
                raise ctx.error('expected a velocity such as "1.5 m/s"', section="given", key=name, value=raw)
            out.append(Relation(f"{name} = {raw}", symbol(name), g.value))
            continue
        if g.dim != ANGLE or g.value is None:
            raise ctx.error('expected an angle such as "30 deg"', section="given", key=name, value=raw)
        out.append(Relation(f"{name} = {raw}", symbol(name), g.value * 180 / sympy.pi))
    return tuple(out)


def _take_from_seed(
    givens: list[Given], by_name: dict[str, Given], seed: Mapping[str, Given], fixed_B: bool, weights: bool
) -> None:
    """A required given the stage leaves out is the chain's given of the same name."""
    needed = ("m_A", "e", "v_A1", "v_A1n", "v_A1t", "W_A")
    if not fixed_B:
        needed += ("m_B", "v_B1", "v_B1n", "v_B1t", "W_B")
    if weights:
        needed += ("g",)
    for key, g in seed.items():
        if key in needed and key not in by_name:
            givens.append(g)
            by_name[key] = g


_LABEL = re.compile(r"[A-Z][0-9]?")


def _labels(
    bodies: Mapping[str, Mapping[str, Any]], fixed_B: bool, ctx: Source, in_chain: bool = False
) -> tuple[str, str]:
    """The letters the page calls A and B by: the file's ``label``; a fixed B not
    labelled whose letter A took, or any fixed B of a chain's stage (whose B may be a
    sphere of another stage), is called by its name's initial (W for a wall, G for the
    ground): a wall's velocities are never v_B1 and v_B2 beside a sphere B's."""
    for b in "AB":
        label = bodies[b].get("label")
        if label is not None and not _LABEL.fullmatch(label):
            raise ctx.error('expected a capital letter, optionally with a digit ("B", "C", "P1")', b, "label", label)
    a = bodies["A"].get("label", "A")
    b = bodies["B"].get("label")
    if b is None:
        initial = (bodies["B"].get("name") or "wall")[:1].upper() if fixed_B else ""
        named = initial if _LABEL.fullmatch(initial) and initial != a else "W"
        b = "B" if a != "B" and not (in_chain and fixed_B) else named
    if a == b:
        raise ctx.error(f'A and B are both called "{a}": give each body its own letter', "B", "label", b)
    return a, b


def _check_fixed(bodies: Mapping[str, Mapping[str, Any]], by_name: Mapping[str, Given], ctx: Source) -> None:
    if bodies["A"].get("fixed"):
        raise ctx.error(
            "only B can be fixed: let A be the moving body and B the wall or floor", section="A", key="fixed"
        )
    if not bodies["B"].get("fixed"):
        return
    for k in _FIXED_B_TAKES_NONE:
        if k in by_name:
            raise ctx.error(
                "B is fixed (a wall or floor: infinite mass, at rest), so it takes no mass or velocity",
                section="given",
                key=k,
            )
    for k in ("angle", "from", "toward"):
        if k in bodies["B"]:
            raise ctx.error("B is fixed: it has no velocity to give a direction to", section="B", key=k)


def _masses_from_weights(
    givens: list[Given], by_name: dict[str, Given], fixed_B: bool, system: str, ctx: Source
) -> None:
    """m = W/g for a body given by its weight (g: the file's, else the system's standard gravity)."""
    for b in "A" if fixed_B else "AB":
        m, w = f"m_{b}", f"W_{b}"
        if m in by_name and w in by_name:
            raise ctx.error(f"give the mass {m} or the weight {w}, not both", section="given", key=w)
        if m in by_name or w not in by_name:
            continue
        if "g" not in by_name:
            number, unit_text = GRAVITY[system]
            unit = units.parse_unit(unit_text)
            g_given = quantity(
                "g", symbol("g", "positive"), sympy.Rational(number), unit, units.ACCELERATION, system, None
            )
            givens.append(g_given)
            by_name["g"] = g_given
        weight, grav = by_name[w], by_name["g"]
        value = None if weight.value is None or grav.value is None else weight.value / grav.value
        work = units.working_unit(MASS, system).text
        mass = Given(m, symbol(m, "positive"), MASS, value, work, definition=weight.symbol / grav.symbol)
        givens.append(mass)
        by_name[m] = mass


def _check_needs(by_name: Mapping[str, Given], kind: str, fixed_B: bool, ctx: Source) -> None:
    for need in ("m_A", "e") if fixed_B else ("m_A", "m_B", "e"):
        if need not in by_name:
            what = {"e": "the coefficient of restitution e"}.get(
                need, f"the mass of {need[-1]} (or its weight W_{need[-1]})"
            )
            raise ctx.error(f"is missing: give {what}{misspelt(need, by_name)}", section="given", key=need)
    post = POST[kind]
    for k in by_name:
        if k.startswith(("v_A2", "v_B2")) and k not in post:
            raise ctx.error(
                f"is not a velocity this kind of impact uses after the impact (use {', '.join(post)})",
                section="given",
                key=k,
            )


__all__ = ["POST", "build_problem", "infer_system"]
