"""Stage 4 of the notes' layout: the answer. The velocities after the impact as vectors
in e_t and e_n (boxed), what the question asks besides (speeds, directions, impulse,
other units), and the kinetic energy for the record."""

from __future__ import annotations

from dataclasses import replace

import sympy

from derive.errors import SolveError
from derive.numbers import exactify, format_number
from derive.physics.asks import RELATIONS, Found, Shown
from derive.physics.energy import HALF
from derive.physics.results import Result, convert
from derive.steps.derived import derived_line
from derive.steps.model import Block, Eqn, Math, Side, Text
from derive.steps.page import Page, interval_text, nonzero
from derive.symbols import symbol, vector


def answer(page: Page) -> list[Block]:
    """The answer blocks: velocities, x-y components, closed forms, what was asked, energy.

    The notes' "⟵ ANSWER" mark goes on each result the question asks for (4.C.11 marks
    both velocity vectors): see :func:`_mark_each`.
    """
    p = page.p
    velocities = {"v_A2", "v_B2", "v_A2t", "v_A2n", "v_B2t", "v_B2n", "v_A2x", "v_A2y", "v_B2x", "v_B2y"}
    asks_velocities = bool(velocities & set(p.find))
    candidates = [  # (block, whether it answers the question); the "show that" blocks 5th on
        (_velocities(page), asks_velocities),
        (_xy(page), asks_velocities),
        (_closed_forms(page), False),
        (_asked(page), True),
        *((shown(page, s), True) for s in page.outcome.shown),
        *((ranged(f), False) for f in page.outcome.ranges),
        (others(page), False),
    ]
    blocks = _mark_each(page, candidates)
    return [b for b in blocks if b is not None] + [energy(page)]


def _mark_each(page: Page, candidates: list[tuple[Block | None, bool]]) -> list[Block | None]:
    """The blocks with an ANSWER mark on each result the question asks for, on the last boxed
    line that states it (A's speed asked: its speed's line, not its vector's; v_A2n and v_A2t
    asked: the vector's, as the notes mark both vectors of 4.C.11), as a chain's answer marks
    each, and on each "show that" proved (tan β = e₁ tan α, not β's own line too). Where none
    is boxed, the last boxed line of the last block that answers the question is marked."""
    blocks = [b for b, _ in candidates]
    if not page.marks:
        return blocks
    shown = range(4, 4 + len(page.outcome.shown))  # where answer() lists the "show that" blocks
    proved = {x.name for s in page.outcome.shown for x in (s.relation.lhs - s.relation.rhs).free_symbols}  # tan β: β
    where: dict[str, tuple[int, int]] = {}
    marks: set[tuple[int, int]] = set()
    for i, (b, answers) in enumerate(candidates):
        for j, ln in enumerate(b.lines if b is not None and answers else ()):
            if ln.boxed and i in shown:  # a "show that" proved: the answer to it
                marks.add((i, j))
            for f in page.p.find:
                if ln.boxed and f not in proved and _states(ln, f):
                    where[f] = (i, j)
    marks |= set(where.values())
    if not marks:
        last = max((i for i, (b, asked) in enumerate(candidates) if asked and _boxed(b)), default=None)
        return [_marked(page, b) if i == last else b for i, b in enumerate(blocks)]
    return [
        None
        if b is None
        else replace(b, lines=tuple(replace(ln, mark=True) if (i, j) in marks else ln for j, ln in enumerate(b.lines)))
        for i, b in enumerate(blocks)
    ]


def _states(line: Eqn, asked: str) -> bool:
    """True when the line states ``asked``: itself, or the vector of a component asked (v_A2 of v_A2n)."""
    first = line.sides[0].terms[0] if line.sides and line.sides[0].terms else None
    name = getattr(first, "name", "").removeprefix("vec:")
    return bool(name) and (asked == name or (asked[:-1] == name and asked[-1] in "ntxy"))


def shown(page: Page, s: Shown) -> Block:
    """A "show that" result: the closed form found, and whether it is the one to show."""
    rel = s.relation
    text: Text = ("Show that ", Math(sympy.Eq(rel.lhs, rel.rhs, evaluate=False)), ":")
    line = Eqn((Side((rel.lhs,)), Side((page.notes(s.lhs),), "numeric"), Side((rel.rhs,))), boxed=s.holds)
    if s.holds:
        how = (
            ""
            if s.how == "exactly"
            else f" (not proved: derive could not simplify the difference of the two sides to 0, and they agree"
            f" to 40 digits {s.how} of the letters' ranges)"
        )
        return Block((*text, f" from the results above it follows, as required{how}."), (line,))
    if s.difference is not None:  # decided exactly: the sides differ by a term that is not 0
        text = (
            *text,
            " it does not follow. The results above give the left side; the right side minus the left is ",
            Math(s.difference),
            ", which is not 0.",
        )
        return Block(text, (Eqn((Side((rel.lhs,)), Side((s.lhs,), "numeric"))),))
    point = s.counterexample or {}
    values = ", ".join(f"{k.name} = {format_number(v, 3)}" for k, v in point.items())
    sides = [s.lhs, s.rhs]
    left, right = (format_number(x.xreplace({k: sympy.Float(v) for k, v in point.items()}).evalf(), 3) for x in sides)
    text = (
        *text,
        f" it does not follow. The results above give the left side; at {values} it is {left}, the right side {right}.",
    )
    return Block(text, (Eqn((Side((rel.lhs,)), Side((s.lhs,), "numeric"))),))


def others(page: Page) -> Block | None:
    """The other physical solutions, where the data do not choose one: listed, not refused."""
    cases = page.outcome.others
    if not cases:
        return None
    p = page.p
    asked = [g.name for g in p.givens if g.unknown]
    comps = tuple(f"v_{b}2{c}" for b in _bodies(page) for c in (("t", "n") if p.oblique else ("",)))
    given = {g.name for g in p.givens}
    names = [*asked, *(c for c in comps if c not in given), *p.find]
    text: Text = (
        f"These givens allow {len(cases) + 1} physical solutions, and the data do not choose between them; "
        "the steps above follow the first. ",
    )
    for i, results in enumerate(cases, start=2):
        text += (f"Solution {i}: " if len(cases) > 1 else "The other: ",)
        listed = [results[n] for n in dict.fromkeys(names) if n in results]
        for j, r in enumerate(listed):
            text += (Math(r.symbol), " = ", *_valued(r, p.digits), ", " if j < len(listed) - 1 else ". ")
    return Block((*text[:-1], text[-1].rstrip()))


def _valued(r: Result, digits: int | None) -> Text:
    """A result's value as text, with its unit (107.0°, -3.586 m/s), or its closed form."""
    if r.value is None or r.value.free_symbols:
        x = sympy.factor_terms(sympy.radsimp(r.partial))
        coeff, letters = x.as_independent(*x.free_symbols, as_Add=False)
        if coeff.is_number and sympy.count_ops(coeff) > 6:  # a nested radical: its value, as the boxed lines
            x = sympy.Mul(sympy.Symbol(format_number(coeff, digits)), letters, evaluate=False)
        return (Math(x),)
    unit = "°" if r.unit == "deg" else f" {r.unit}" if r.unit else ""
    return (format_number(r.value, digits) + unit,)


#: The longest expression a range's line shows in full (characters of its plain form).
MAX_SHOWN_CHARS = 600


def ranged(f: Found) -> Block:
    """The values of a letter for which an inequality between results holds."""
    rng, x = f.range, f.range.of
    rel = RELATIONS[rng.op]
    text: Text = ("For ", Math(rel(rng.lhs, rng.rhs)), ": ")
    if len(str(f.expr)) > MAX_SHOWN_CHARS:  # v_A2^63 < v_B2^63: a page of polynomial, not shown
        text += (
            "once the factors that keep one sign for these letters are dropped, ",
            Math(rel(exactify(f.reduced), 0)),
        )
    else:
        text += (Math(rel(exactify(f.expr), 0)),)
        if f.dropped:
            text += (" and, as ", Math(sympy.StrictGreaterThan(sympy.Mul(*f.dropped), 0, evaluate=False)), ", ")
            text += (Math(rel(exactify(f.reduced), 0)),)
    if f.interval is None:
        return Block((*text, f"; {f.reason or 'this depends on the other letters and is not worked out here'}."))
    return Block((*text, ", that is for ", *interval_text(f.interval, x), "."))


def _boxed(block: Block | None) -> bool:
    return block is not None and any(ln.boxed for ln in block.lines)


def _about(line: Eqn, find: tuple[str, ...]) -> bool:
    """True when the line states a quantity asked for (v_A2, or its vector for v_A2n)."""
    first = line.sides[0].terms[0] if line.sides and line.sides[0].terms else None
    name = getattr(first, "name", "").removeprefix("vec:")
    return bool(name) and any(f == name or f.startswith(name) for f in find)


def _marked(page: Page, block: Block | None) -> Block | None:
    """``block`` with the ANSWER mark on its last boxed line that states a result asked for, else its last boxed."""
    if block is None or not page.marks:
        return block
    boxed = [i for i, ln in enumerate(block.lines) if ln.boxed]
    asked_lines = [i for i in boxed if _about(block.lines[i], page.p.find)]
    last = max(asked_lines or boxed, default=-1)  # the last line asked for, else the last boxed
    if last < 0:
        return block
    lines = tuple(replace(ln, mark=True) if i == last else ln for i, ln in enumerate(block.lines))
    return replace(block, lines=lines)


def _bodies(page: Page) -> str:
    return "A" if page.p.fixed_B else "AB"


def _velocities(page: Page) -> Block:
    """The velocities after the impact: vectors in e_t and e_n (a direct impact: along n)."""
    p = page.p
    e_t, e_n = vector("e_t"), vector("e_n")
    lines = []
    given_names = {g.name for g in p.givens}
    for b in _bodies(page):
        if p.oblique:
            t = page.value_of(symbol(f"v_{b}2t"))
            n = page.value_of(symbol(f"v_{b}2n"))
            comps = nonzero(tuple(c * u for c, u in ((t, e_t), (n, e_n)) if c != 0))
            found = not {f"v_{b}2t", f"v_{b}2n"} <= given_names  # a velocity the file gave is no answer
            lines.append(Eqn((Side((vector(f"v_{b}2"),)), Side(comps, "result")), unit=page.unit_v, boxed=found))
        else:
            value = page.value_of(symbol(f"v_{b}2"))
            boxed = f"v_{b}2" not in given_names
            lines.append(Eqn((Side((symbol(f"v_{b}2"),)), Side((value,), "result")), unit=page.unit_v, boxed=boxed))
    heading = f"The velocity of {page.a}" if p.fixed_B else "The velocities"
    return Block((heading + " immediately after the impact:",), tuple(lines))


def _xy(page: Page) -> Block | None:
    """The velocities in the problem's x-y axes, where it gave them."""
    if page.p.phi is None:
        return None
    e_x, e_y = vector("e_x"), vector("e_y")
    lines = []
    for b in _bodies(page):
        x, y = page.value_of(symbol(f"v_{b}2x")), page.value_of(symbol(f"v_{b}2y"))
        comps = nonzero(tuple(c * u for c, u in ((x, e_x), (y, e_y)) if c != 0))
        lines.append(Eqn((Side((vector(f"v_{b}2"),)), Side(comps, "result")), unit=page.unit_v, boxed=True))
    text: Text = ("In the problem's x–y axes (x = n cos φ − t sin φ, y = n sin φ + t cos φ):",)
    return Block(text, tuple(lines))


#: The most operations a closed form may have and still be shown beside its value: past it, a
#: line of nested radicals says less than the value does (edexcel-m4-2018 solves alpha from
#: the kinetic energies with e given as 3/4: its v_A2 in e had 93 operations, printed over two
#: lines and wider than the page). The longest the bundled pages keep has 27.
READABLE_OPS = 30


def readable(expr: sympy.Expr) -> bool:
    """Whether a closed form is short enough to teach from (see :data:`READABLE_OPS`)."""
    return sympy.count_ops(expr) <= READABLE_OPS


def _closed_forms(page: Page) -> Block | None:
    """Velocities that stay symbolic, in closed form in the givens."""
    names = ("v_A2t", "v_A2n", "v_B2t", "v_B2n", "v_A2", "v_B2")
    symbolic = [
        r for r in page.results.values() if r.value is None and r.partial.free_symbols - page.varied and r.name in names
    ]
    if not symbolic:
        return None
    lines = [
        Eqn(
            (Side((r.symbol,)), Side((page.notes(r.closed),)), Side((page.notes(page.value_of(r.symbol)),), "result")),
            unit=r.unit,
        )
        for r in symbolic
        if r.closed != 0 and readable(r.closed)
    ]
    if not lines:
        return None
    return Block(("In closed form, in the givens:",), tuple(lines))


def _asked(page: Page) -> Block | None:
    """What the question asks besides the velocities, and results in the units it asks for."""
    p = page.p
    extra = []
    for name in p.find:
        if (name in ("v_A2", "v_B2") and not p.oblique) or name in ("v_A2t", "v_A2n", "v_B2t", "v_B2n"):
            continue
        r = page.results.get(name)
        if r is not None:
            extra.append(derived_line(page, r, boxed=True))
    for name, unit in p.answer_units.items():
        r = page.results.get(name)
        if r is None:
            raise SolveError(f"answer_units names {name!r}, which is not a result of this problem", where=p.path)
        try:
            value = convert(r, unit)
        except SolveError as exc:
            raise SolveError(str(exc), where=p.path) from None
        extra.append(Eqn((Side((r.symbol,)), Side((value,), "result")), unit=unit, boxed=True))
    if not extra:
        return None
    text: Text = ("As asked:",)
    if "J_n" in p.find:
        J = symbol("J_n")
        text = ("As asked (", Math(J), f" is the impulse along +n on {page.b}; on {page.a} it is ", Math(-J), "):")
    # the components at the figures the boxed vectors show them: √(3.05² + (-1.11)²), one precision
    return Block(text, tuple(extra), answer_figures=True)


def energy(page: Page) -> Block:
    p = page.p
    m_A, m_B = page.m_A, page.m_B
    s1A = p.motion_A.speed if p.oblique and p.motion_A.speed is not None else None
    s1B = p.motion_B.speed if p.oblique and p.motion_B.speed is not None else None
    if p.oblique:
        v1A = s1A**2 if s1A is not None else sympy.Add(page.nm.A1n**2, page.nm.A1t**2, evaluate=False)
        v1B = s1B**2 if s1B is not None else sympy.Add(page.nm.B1n**2, page.nm.B1t**2, evaluate=False)
        v2A, v2B = symbol("v_A2", "positive") ** 2, symbol("v_B2", "positive") ** 2
    else:
        v1A, v1B = symbol("v_A1") ** 2, symbol("v_B1") ** 2
        v2A, v2B = symbol("v_A2") ** 2, symbol("v_B2") ** 2
    if p.fixed_B:
        forms = {"T_1": (HALF * m_A * v1A,), "T_2": (HALF * m_A * v2A,)}
    else:
        forms = {"T_1": (HALF * m_A * v1A, HALF * m_B * v1B), "T_2": (HALF * m_A * v2A, HALF * m_B * v2B)}
    lines = []
    for name, terms in forms.items():
        r = page.results[name]
        sides = [Side((r.symbol,)), Side(terms)]
        if r.value is None:
            if r.closed != r.partial and r.partial.free_symbols - page.varied and readable(r.closed):
                sides.append(Side((page.notes(r.closed),)))
            sides.append(Side((page.notes(page.value_of(r.symbol)),), "result"))
        else:
            sides.append(Side((r.value,), "result"))
        lines.append(Eqn(tuple(sides), unit=r.unit))
    lines.append(_loss_line(page))
    r1, rl = page.results["T_1"], page.results["T_lost"]
    if r1.value is not None and rl.value is not None and r1.value != 0:
        percent = rl.value / r1.value * 100
    else:
        ratio = sympy.simplify(rl.partial / r1.partial)
        percent = ratio * 100 if ratio.is_number else None
    if percent is not None:
        ratio_name = sympy.Symbol(r"\frac{T_{\mathrm{lost}}}{T_{1}}")
        lines.append(Eqn((Side((ratio_name,)), Side((percent,), "result")), unit="%"))
    text: Text = (
        "Kinetic energy, for the record: it is not conserved across the impact unless ",
        Math(sympy.Eq(page.e, 1)),
        ", so it is never used to find the velocities.",
    )
    if rl.value is not None and rl.value < 0:  # e > 1, from velocities measured after the impact
        text += (
            " Here the data imply a gain of kinetic energy (",
            Math(sympy.StrictLessThan(symbol("T_lost"), 0, evaluate=False)),
            ", ",
            Math(sympy.StrictGreaterThan(page.e, 1, evaluate=False)),
            "): no collision of passive bodies does that; a release of stored energy (a spring, an "
            "explosive charge) could, or the measured velocities are in error.",
        )
    return Block(text, tuple(lines))


def _loss_line(page: Page) -> Eqn:
    """The energy lost. With letters, as T_1 - T_2; with numbers, from the loss's own
    closed form (half the reduced mass times (1 - e^2) times the closing speed squared),
    so that it is not read as the difference of T_1 and T_2 rounded (813 - 491 != 321)."""
    r = page.results["T_lost"]
    if r.value is None and r.partial.free_symbols - page.varied:  # letters, not a variant's open numbers
        sides = [Side((r.symbol,)), Side((symbol("T_1"), -symbol("T_2")))]
        if r.closed != r.partial and r.partial.free_symbols - page.varied and readable(r.closed):
            sides.append(Side((page.notes(r.closed),)))
        sides.append(Side((page.notes(page.value_of(r.symbol)),), "result"))
        return Eqn(tuple(sides), unit=r.unit)
    p, e = page.p, page.e
    a, b = (page.nm.A1n, page.nm.B1n) if p.oblique else (symbol("v_A1"), symbol("v_B1"))

    def loss(a: sympy.Expr, b: sympy.Expr) -> sympy.Expr:
        if p.fixed_B:
            return sympy.Mul(HALF, page.m_A, 1 - e**2, a**2, evaluate=False)
        two_sum = sympy.Mul(2, sympy.Add(page.m_A, page.m_B), evaluate=False)
        reduced = sympy.Mul(page.m_A, page.m_B, sympy.Pow(two_sum, -1, evaluate=False), evaluate=False)
        return sympy.Mul(reduced, 1 - e**2, sympy.Add(a, -b, evaluate=False) ** 2, evaluate=False)

    sides = [Side((r.symbol,)), Side((loss(a, b),))]
    numbers = loss(page.givens(a), page.givens(b))
    if page.has_values(numbers) and not (numbers.free_symbols - set(page.outcome.values) - page.varied):
        sides.append(Side((numbers,), "values"))  # every letter has its number (not a solved e)
    sides.append(Side((page.value_of(r.symbol),), "result"))
    return Eqn(tuple(sides), unit=r.unit)
