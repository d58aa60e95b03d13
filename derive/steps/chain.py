"""A chain written out stage by stage: each stage type's outcome as blocks, each impact
stage as a page of its own written by the same writer as a single impact, equation
numbers running on through the stages, and the boxed answers at the end."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.errors import InputError
from derive.numbers import exactify
from derive.physics.chain import ChainOutcome
from derive.physics.stages.again import Again
from derive.physics.stages.algebra import Condition, Definition
from derive.physics.stages.bounces import Bounces
from derive.physics.stages.energy import Balance, Spring
from derive.physics.stages.impact import ImpactStage
from derive.physics.state import StageOutcome
from derive.problem import Problem, units
from derive.steps.impact import write_impact
from derive.steps.model import Answer, Block, Eqn, Math, Side, Solution, Stage, Text
from derive.steps.notation import notes_form
from derive.steps.page import Counter, Tags, as_float, interval_text
from derive.symbols import relabel, symbol


def write_chain(outcome: ChainOutcome) -> Solution:
    """The chain's worked page: every stage, then the answers the file asks for."""
    numbers = Counter()
    stages = tuple(WRITERS[st.type](outcome, st, numbers) for st in outcome.stages)
    return Solution(outcome.chain, outcome.results, stages, outcome.values, outcome.angles, answers=_answers(outcome))


def _answers(outcome: ChainOutcome) -> tuple[Answer, ...]:
    """The quantities the file's ``find`` names (else the last stage's), boxed."""
    chain = outcome.chain
    names = list(chain.find) or list(outcome.stages[-1].outputs)
    verdicts = {n for st in outcome.stages if st.type == "again" for n in st.outputs}
    answers = []
    for name in names:
        r = outcome.results.get(name)
        if r is None:
            raise InputError(f"find names {name!r}, which no stage computes", where=chain.path, field="find")
        if name in verdicts and r.value is None:  # a range of a coefficient: the stage worked it out
            said = "yes, for the values found above" if r.closed is not sympy.false else "no, for no value"
            answers.append(Answer(name, verdict=said))
            continue
        if name in verdicts:
            answers.append(Answer(name, verdict="yes" if r.value == 1 else "no"))
            continue
        line = Eqn((Side((r.symbol,)), Side((r.found,), "result")), unit=r.unit or None, boxed=True)
        answers.append(Answer(name, line))
    return tuple(answers)


def _balance_lines(b: Balance, numbers: Counter) -> tuple[Eqn, ...]:
    """Energy conservation written out: the balance, then the result with numbers."""
    solved, result = b.solved, b.result
    return (
        Eqn((Side(b.lhs), Side(b.rhs)), cancel=b.cancel),
        Eqn(
            (Side((result.symbol,)), Side((solved,)), Side((solved,), "values"), Side((b.value,), "result")),
            unit=result.unit,
            implies=True,
            tag=numbers.next(),
        ),
    )


def _fall(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    text: Text = (
        "Before the impact no impulsive force acts: mechanical energy is conserved (datum at the lowest point), ",
        Math(sympy.Eq(symbol("T_1") + symbol("V_1"), symbol("T_2") + symbol("V_2"))),
        ". The mass cancels.",
    )
    return Stage(st.number, st.title, (Block(text, _balance_lines(st.data, numbers)),), kind=st.type, values=st.values)


def _rise(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    text: Text = ("After the impact, mechanical energy is conserved again up to the highest point: ",)
    return Stage(st.number, st.title, (Block(text, _balance_lines(st.data, numbers)),), kind=st.type, values=st.values)


def _slide(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    text: Text = (
        "After the impact, work and energy: kinetic friction ",
        Math(sympy.Eq(symbol("F"), st.data.friction)),
        " does the work that stops the body.",
    )
    return Stage(st.number, st.title, (Block(text, _balance_lines(st.data, numbers)),), kind=st.type, values=st.values)


def _spring(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    s: Spring = st.data
    X = s.result.symbol
    if s.vertical:
        text: Text = (
            "After the impact, energy is conserved while the spring compresses by a further ",
            Math(X),
            " below the equilibrium position (gravity does work too):",
        )
    else:
        text = (
            "After the impact, energy is conserved while the spring compresses: kinetic energy becomes spring energy.",
        )
    lines = (
        Eqn(
            (Side(s.lhs), Side(tuple(notes_form(t, {}) for t in s.rhs)))
        ),  # (kx + m g)²/(2k): no fraction in a fraction
        Eqn((Side((X,)), Side((s.root,), "result")), unit=s.result.unit, implies=True, tag=numbers.next()),
    )
    return Stage(st.number, st.title, (Block(text, lines),), kind=st.type, values=st.values)


def _impact(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    data: ImpactStage = st.data
    inner = data.outcome
    to = own_names(inner.problem, data.exports)
    written = _one_name(write_impact(inner, Tags(running=numbers), marks=False), to)
    values = {**inner.values, **{new: inner.values[old] for old, new in to.items() if old in inner.values}}
    names = {old.name: new.name for old, new in to.items()}
    part = Solution(inner.problem, inner.results, written, values, inner.angles, names=names)
    carried = []
    for (new, rname), value in zip(data.exports, data.carried, strict=True):
        r = outcome.results[new]
        shown = _in_unit(sympy.factor(value) if value.free_symbols else value, r.unit)
        slot = (
            () if symbol(rname) in to else (Side((symbol(rname),)),)
        )  # w_B = v_B2 = ..., or w_B = ... where w_B is written
        carried.append(Eqn((Side((r.symbol,)), *slot, Side((shown,), "result")), unit=r.unit or None))
    return Stage(st.number, st.title, part=part, carried=tuple(carried), kind=st.type, values=st.values)


def own_names(problem: Problem, exports: tuple[tuple[str, str], ...] = ()) -> dict[sympy.Symbol, sympy.Symbol]:
    """An impact stage's symbols the page writes in the chain's names, so that the page has
    one name per quantity: its coefficient ``e`` where the stage takes it from a coefficient
    of the chain's (e = "e_wall": e_wall, not e beside e_wall, nor e for two coefficients);
    against a wall or floor, also each given the chain names (v_A1 = "u_B": u_B) and each
    result it hands on (``exports``: v_A2 -> w_B, J_n -> J_w), so that v_B1 and v_B2 of a
    wall stage are not v_B1 and v_B2 of the impact before it (the wall's stage writes
    u_B, w_B). A chain name that is itself a body's name (v_B) is left out: the stage's
    letters would rename it."""
    out: dict[sympy.Symbol, sympy.Symbol] = {}
    for g in problem.givens:
        named = g.definition
        if g.name != "e" and not problem.fixed_B:
            continue
        if isinstance(named, sympy.Symbol) and named.name != g.name and relabel(named.name, ("B", "A")) == named.name:
            out[g.symbol] = named
    if problem.fixed_B:
        for new, slot in exports:
            if relabel(new, ("B", "A")) == new and new != slot:
                out.setdefault(symbol(slot), symbol(new))
    return out


def _one_name(stages: tuple[Stage, ...], to: dict[sympy.Symbol, sympy.Symbol]) -> tuple[Stage, ...]:
    """The stages of an impact written in its own names (:func:`own_names`)."""
    if not to:
        return stages

    def math(t):
        return Math(t.expr.xreplace(to)) if isinstance(t, Math) else t

    def line(ln: Eqn) -> Eqn:
        sides = tuple(replace(sd, terms=tuple(sympy.sympify(x).xreplace(to) for x in sd.terms)) for sd in ln.sides)
        return replace(ln, sides=sides, cancel=frozenset(to.get(c, c) for c in ln.cancel))

    def block(b: Block) -> Block:
        sums = tuple((tuple(x.xreplace(to) for x in ts), total.xreplace(to)) for ts, total in b.sums)
        text = tuple(math(t) for t in b.text) if b.text else b.text
        return replace(b, text=text, lines=tuple(line(ln) for ln in b.lines), sums=sums)

    return tuple(replace(st, blocks=tuple(block(b) for b in st.blocks)) for st in stages)


def _define(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    d: Definition = st.data
    out = d.result
    line = Eqn(
        (
            Side((out.symbol,)),
            Side((d.expr,)),
            Side((d.expr,), "values"),
            Side((_in_unit(d.value, out.unit),), "result"),
        ),
        unit=out.unit or None,
        tag=numbers.next(),
    )
    return Stage(st.number, st.title, (Block((d.text,), (line,)),), kind=st.type, values=st.values)


def _solve(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    c: Condition = st.data
    g, u = c.given, c.given.symbol
    sides = [Side((c.lhs,))]
    if c.in_unknown is not None and c.in_unknown != c.lhs:
        sides.append(Side((c.in_unknown,), "numeric"))
    rhs = _in_unit(c.rhs, c.lhs_unit or "") if c.rhs.is_number else c.rhs  # an angle, held in radians, in degrees
    sides.append(Side((rhs,), "result"))
    unit = g.unit or None
    root = Eqn((Side((u,)), Side((_in_unit(c.root, g.unit),), "result")), unit=unit, implies=True, tag=numbers.next())
    said = f" {c.lhs_unit}" if c.lhs_unit and c.rhs.is_number and c.rhs != 0 else ""  # h_2 = 40 m, not 40
    said = "°" if said == " deg" else said
    text: Text = ("The condition ", Math(sympy.Eq(c.lhs, rhs)), said + " fixes the unknown ", Math(u), ":")
    blocks = [Block(text, (Eqn(tuple(sides), unit=c.lhs_unit), root))]
    if c.roots > 1:
        if u.name.startswith("e"):
            why: Text = ("0 ≤ ", Math(u), " ≤ 1")
        elif u.is_positive or u.is_nonnegative:
            why = (Math(u), " ≥ 0")
        else:
            why = (Math(u), " for which every impact still has its bodies approaching")
        blocks.append(Block((f"Of the {c.roots} roots, the one with ", *why, " is the physical one.")))
    if c.updated:
        lines = tuple(
            Eqn(
                (
                    Side((q.symbol,)),
                    Side((sympy.N(before, 15) if q.decimal else before,), "numeric"),  # -6.261 e_floor, from g = 9.8
                    Side((_in_unit(now, q.unit),), "result"),
                ),
                unit=q.unit or None,
            )
            for q, before, now in c.updated
        )
        blocks.append(
            Block(
                (
                    "With ",
                    Math(sympy.Eq(u, as_float(_in_unit(c.root, g.unit)))),
                    "°" if g.unit == "deg" else "",  # th = -30.0°, not its radians
                    ", the quantities that waited for it:",
                ),
                lines,
            )
        )
    return Stage(st.number, st.title, tuple(blocks), kind=st.type, values=st.values)


def _bounces(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    b: Bounces = st.data
    v_0 = symbol("v_0")
    velocity = units.working_unit(units.VELOCITY, outcome.chain.system).text
    lines = [
        Eqn(
            (Side((v_0,)), Side((sympy.sqrt(2 * b.g * b.h0),)), Side((b.v0,), "result")),
            unit=velocity,
            tag=numbers.next(),
        )
    ]
    for k, (vk, hk) in enumerate(zip(b.speeds, b.heights, strict=True), 1):
        lines.append(Eqn((Side((vk.symbol,)), Side((b.e**k * v_0,)), Side((vk.definition,), "result")), unit=vk.unit))
        lines.append(
            Eqn((Side((hk.symbol,)), Side((hk.definition,), "values"), Side((hk.definition,), "result")), unit=hk.unit)
        )
    total = b.total
    sides = (Side((total.symbol,)), Side((total.definition,)), Side((total.definition,), "values"))
    lines.append(Eqn((*sides, Side((total.definition,), "result")), unit=total.unit, tag=numbers.next()))
    text: Text = (
        "Each bounce is an impact with the floor (a fixed body): the rebound speed is e times the impact speed, "
        "and between bounces energy is conserved, so the height after bounce k is ",
        Math(sympy.Eq(symbol("h_k"), b.e ** (2 * symbol("k")) * symbol("h_0"))),
        ". The distance travelled before the ball comes to rest is the sum of a geometric series.",
    )
    return Stage(st.number, st.title, (Block(text, tuple(lines)),), kind=st.type, values=st.values)


def _again(outcome: ChainOutcome, st: StageOutcome, numbers: Counter) -> Stage:
    a: Again = st.data
    text: Text = (
        "They collide again if the one behind moves faster along +n than the one ahead: ",
        Math(sympy.StrictGreaterThan(a.behind, a.ahead)),
        ".",
    )
    velocity = units.working_unit(units.VELOCITY, outcome.chain.system).text
    blocks = [Block(text, (Eqn((Side((a.behind, -a.ahead)), Side((a.difference,), "result")), unit=velocity),))]
    if a.verdict is not None:
        blocks.append(Block(("Yes: they collide again." if a.verdict else "No: they do not collide again.",)))
    if a.param is not None:
        general = exactify(a.general)
        words: Text = (
            "For other values of ",
            Math(a.param),
            ": they collide again when ",
            Math(sympy.StrictGreaterThan(general, 0, evaluate=False)),
            ", that is for ",
            *interval_text(a.interval, a.param),
            ".",
        )
        blocks.append(Block(words))
    return Stage(st.number, st.title, tuple(blocks), kind=st.type, values=st.values)


def _in_unit(value: sympy.Expr, unit: str) -> sympy.Expr:
    """A value as its unit shows it: an angle, held in radians, in degrees."""
    return value * 180 / sympy.pi if unit == "deg" else value


#: Stage type -> the function that writes a stage of that type.
WRITERS: dict[str, Callable[[ChainOutcome, StageOutcome, Counter], Stage]] = {
    "fall": _fall,
    "rise": _rise,
    "slide": _slide,
    "spring": _spring,
    "impact": _impact,
    "bounces": _bounces,
    "again": _again,
    "define": _define,
    "solve": _solve,
}
