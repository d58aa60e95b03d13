"""A slip named as a teacher names it, where the line holds exactly for the named wrong model.

:mod:`.lines` finds the slip (the first false line) and tries the common mistakes of the
equations (1)-(4) first; these name what is left, each only when the evidence supports it
(a wrong name is worse than none):

- a result's value as a mistake gives it (``T_1 = ½(15)(19.657)² = 2898``: the weight used
  as the mass; ``θ_2 = tan⁻¹(v_t/v_n)``: the direction from the other axis), put in for the
  result's name on the line;
- ``ke_formula``: a kinetic energy worked with a wrong formula: ½m(u − v)² for
  ½m(u² − v²), ½mv without the square, mv² without the half;
- ``algebra`` and ``arithmetic``: a line solved from the relation just before it, right as
  far as it goes, but with a sign lost in rearranging (algebra: it holds with one term of
  that relation moved across without its sign changed, or the expression it shows is not
  the rearranged one while its own arithmetic is right), or with a number worked wrongly
  from it (arithmetic).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace
from decimal import Decimal

import sympy

from derive.checking import energyforms, mistakes, rearranging
from derive.checking.context import DEG, Context
from derive.checking.massresults import masses_in_results
from derive.checking.mistakes import Mistake
from derive.checking.relations import coefficients
from derive.checking.worlds import NUMBER_SIDE, Pair
from derive.mathtext.notation import student

Holds = Callable[[Pair], bool]
#: The relation just before a line, if it held: its text and its pairs.
Previous = tuple[str, list[Pair]] | None
COPIED = "a given is copied wrongly into it (the line holds with the given as the problem states it)."
KE_FORMULA = (
    "the kinetic energy is worked with the wrong formula (T = ½ m v² for each body; "
    "the energy lost is ½ m (u² − v²), not ½ m (u − v)²)."
)
ENERGY_WORDS = {"ke_formula": KE_FORMULA, "arithmetic": "a speed is put in without its square (T = ½ m v²)."}


def before_impact(ctx: Context, bad: Pair, holds: Holds) -> list[Mistake]:
    """The mistakes in the values before the impact (sin and cos swapped, B's sign, radians,
    masses) that make ``bad`` hold."""
    if bad.raw is None:
        return []
    model, found = ctx.model, []
    for m in mistakes.REGISTRY.values():
        v = m.build(model)
        if v is None or (v.pre is None and v.masses is None):
            continue
        subs = dict(v.pre or {})
        if v.masses is not None:
            subs.update({model.m_A: v.masses[0], model.m_B: v.masses[1]})
        if _holds_with(ctx, bad, subs, holds):
            found.append(m)
    swapped = mistakes.REGISTRY.get("sin_cos_swapped")
    written = mistakes.sin_cos_swapped_as_written(model) if swapped is not None and not found else None
    if written is not None and written.pre is not None and _holds_with(ctx, bad, dict(written.pre), holds):
        found.append(replace(swapped, build=mistakes.sin_cos_swapped_as_written))  # B at 100° from n: 110 sin 100°
    if not found and "degrees_as_radians" in mistakes.REGISTRY:  # a calculator in radian mode
        trig = any(x.has(DEG) for x in bad.raw)
        if trig and _holds_with(ctx, bad, {DEG: sympy.Integer(1)}, holds):
            found.append(mistakes.REGISTRY["degrees_as_radians"])
    return found


def as_named(ctx: Context, m: Mistake) -> Mistake:
    """``sin_cos_swapped`` on an angle the problem asks for (α from the wall, resolved as if from
    the normal) is that angle taken from the other axis, as a teacher names it."""
    p = ctx.problem
    asked = {g.symbol for g in p.givens if g.unknown}
    angles = {x.angle for x in (p.motion_A, p.motion_B) if x is not None and x.angle is not None}
    if m.name == "sin_cos_swapped" and angles & asked and "angle_other_axis" in mistakes.REGISTRY:
        return mistakes.REGISTRY["angle_other_axis"]
    return m


def under_results(ctx: Context, bad: Pair, holds: Holds) -> list[Mistake]:
    """The mistakes whose value of a result named on the line makes ``bad`` hold; else those of the
    masses (the weights, swapped) in a result worked from the velocities ``holds`` has, or in a
    mass the line names (``m(v_B)_2 = 10(10.22)`` with 10 lb B's weight)."""
    if bad.raw is None:
        return []
    syms = set().union(*(x.free_symbols for x in bad.raw))
    names = {sym: name for name, (sym, _expr) in ctx.derived().items() if sym in syms}
    found: list[Mistake] = []
    for o in ctx.singles():
        if o.mistake is None:
            continue
        subs = {s: o.results[n].partial for s, n in names.items() if n in o.results}
        subs = {s: x for s, x in subs.items() if x is not None}
        if subs and _holds_with(ctx, bad, subs, holds):
            found.append(o.mistake)
    masses = syms & {ctx.model.m_A, ctx.model.m_B}  # m(vB)2 = 10(10.22): a mass by its name, as a weight
    return found or (
        masses_in_results(ctx, bad, lambda subs: _holds_with(ctx, bad, subs, holds)) if names or masses else []
    )


def carried_by_results(ctx: Context, pairs: list[Pair], named: set[str], holds: Holds) -> bool:
    """Whether every pair of a line that is false holds with the results as one of the mistakes
    ``named`` gives them."""
    false = [p for p in pairs if not holds(p)]
    return bool(false) and all(
        {m.name for m in under_results(ctx, p, holds)} & named or with_mistakes_values(ctx, p, named, holds)
        for p in false
    )


def with_mistakes_values(ctx: Context, bad: Pair, named: set[str], holds: Holds) -> bool:
    """Whether ``bad`` holds with the masses or the values before the impact as one of the
    mistakes ``named`` has them, in every result on the line, and the velocities after as
    ``holds`` has them (``KE after = ½(7500)(4.2²)``: the weights as masses, and the common
    velocity an earlier slip gave)."""
    if bad.raw is None:
        return False
    for name in sorted(named):
        m = mistakes.REGISTRY.get(name)
        v = m.build(ctx.model) if m is not None else None
        if v is None or (v.pre is None and v.masses is None and not v.values):
            continue
        subs = {**v.values, **(v.pre or {})}
        if v.masses is not None:
            subs.update({ctx.model.m_A: v.masses[0], ctx.model.m_B: v.masses[1]})
        results = {sym: x.xreplace(subs) for sym, x in ctx.derived().values()}
        if _holds_with(ctx, bad, {**results, **subs}, holds):
            return True
    return False


def ke_formula(ctx: Context, bad: Pair, holds: Holds) -> str:
    """The name of ``bad``'s slip where it holds with a kinetic energy (``T_1``, ``T_2``,
    ``T_lost``) worked by a wrong formula, the velocities right: ``ke_formula``; ``arithmetic``
    where only the speeds put in unsquared explain it (as a teacher marks them anywhere); "" else."""
    if bad.raw is None:
        return ""
    derived = ctx.derived()
    syms = set().union(*(x.free_symbols for x in bad.raw))
    named = {n: derived[n][0] for n in ("T_1", "T_2", "T_lost") if n in derived and derived[n][0] in syms}
    if not named:
        return ""
    forms = wrong_energies(ctx)
    for form in [*forms[1:], forms[0]]:  # the speeds unsquared last: a number worked wrongly
        if set(named) <= set(form) and _holds_with(ctx, bad, {s: form[n] for n, s in named.items()}, holds):
            return "arithmetic" if form is forms[0] else "ke_formula"
    return ""


def wrong_energies(ctx: Context) -> list[dict[str, sympy.Expr]]:
    """The kinetic energies (by result name) as the common wrong formulas give them, in the
    components: without the square, without the half; the energy lost as ½m(u − v)² (of the
    speeds, or of the velocities; of both bodies, or of one alone: the bullet's, the block
    left out)."""
    model, p = ctx.model, ctx.problem
    nm = model.nm
    bodies = [("A", model.m_A)] + ([] if p.fixed_B else [("B", model.m_B)])
    zero = sympy.Integer(0)

    def comps(b: str, k: str) -> tuple[sympy.Expr, sympy.Expr]:
        n, t = getattr(nm, f"{b}{k}n"), getattr(nm, f"{b}{k}t") if p.oblique else None
        return n, (t if t is not None else zero)

    def speed(b: str, k: str) -> sympy.Expr:
        n, t = comps(b, k)
        return sympy.sqrt(n**2 + t**2)

    half = sympy.Rational(1, 2)
    forms: list[dict[str, sympy.Expr]] = []
    for energy in (lambda m, s: half * m * s, lambda m, s: m * s**2):  # no square; no half
        t1 = sum((energy(m, speed(b, "1")) for b, m in bodies), zero)
        t2 = sum((energy(m, speed(b, "2")) for b, m in bodies), zero)
        forms.append({"T_1": t1, "T_2": t2, "T_lost": t1 - t2})
    if len(bodies) > 1:  # the energy before or after of one body alone, the other left out
        t1, t2 = ({b: half * m * speed(b, k) ** 2 for b, m in bodies} for k in "12")
        for b in t1:
            forms.append({"T_2": t2[b], "T_lost": sum(t1.values(), zero) - t2[b]})
            forms.append({"T_1": t1[b], "T_lost": t1[b] - sum(t2.values(), zero)})
    lost_speeds = sum((half * m * (speed(b, "1") - speed(b, "2")) ** 2 for b, m in bodies), zero)
    lost_velocities = sum(
        (half * m * sum(((a - c) ** 2 for a, c in zip(comps(b, "1"), comps(b, "2"), strict=True)), zero))
        for b, m in bodies
    )
    forms += [{"T_lost": lost_speeds}, {"T_lost": lost_velocities}]
    for b, m in bodies if len(bodies) > 1 else ():  # ½m(u − V)² of one body, the other left out
        forms.append(
            {"T_lost": half * m * sum(((a - c) ** 2 for a, c in zip(comps(b, "1"), comps(b, "2"), strict=True)), zero)}
        )
    return forms + energyforms.more_energies(ctx)  # one body's energy for both; e times the energy


def _holds_with(ctx: Context, bad: Pair, subs: dict[sympy.Symbol, sympy.Expr], holds: Holds) -> bool:
    assert bad.raw is not None
    sides = [ctx.in_unknowns(x.xreplace(subs)) for x in bad.raw]
    return holds(replace(bad, left=sides[0], right=sides[1]))


def solving_slip(
    line_sides: tuple[str, ...], pairs: list[Pair], previous: Previous, at: tuple[tuple, dict], holds: Holds
) -> str:
    """``algebra`` or ``arithmetic`` where the line works on the relation just before it (which
    holds), in the same one unknown, and gets it wrong; "" where that is not what the line is.
    ``at``: the unknowns and a sample point of the symbolic givens."""
    if previous is None:
        return ""
    U, pt = at
    prev_text, prev_pairs = previous
    unknowns = set(U)
    line_u = set().union(*(p.difference.free_symbols & unknowns for p in pairs))
    prev_u = set().union(*(p.difference.free_symbols & unknowns for p in prev_pairs))
    if not line_u or line_u != prev_u:  # the same unknowns: 90 = 4 v_A + 8 v_B after 4(12) + 8(4) = …
        return ""
    plain = [p for p in pairs if not p.difference.free_symbols & unknowns]
    failing = [p for p in pairs if p.difference.free_symbols & unknowns and not holds(p)]
    if not failing or not all(holds(p) for p in plain):
        return ""
    held = [p for p in prev_pairs if p.difference.free_symbols & unknowns]
    if len(line_u) == 1 and held and rearranging.divided_wrongly(failing[0], held[-1], U, pt):
        return "arithmetic"  # ``c x = k`` divided wrongly: nothing moved across
    # algebra: the rearranged expression shown is not the relation's, its own arithmetic right
    shown = [s for s in line_sides[1:] if not NUMBER_SIDE.match(student(s.strip())) and not _has_letters(s)]
    numbers = set(re.findall(r"\d+\.?\d*", prev_text))
    if len(line_u) == 1 and plain and any(set(re.findall(r"\d+\.?\d*", s)) <= numbers | {"1", "2"} for s in shown):
        return "algebra"
    # arithmetic: the relation before, its terms in the unknown as they were (up to a factor),
    # and only its number worked wrongly (``v = 5`` from ``10 = 4 + v``; 100 x 1/2 written 25)
    shows = replace(failing[0], text=" = ".join(line_sides))  # ``v = 10 + 4 = 14``: the 4 moved, on the line
    if len(line_u) == 1 and held and (how := rearranging.kind(shows, held[-1], U, pt)):  # a sign, a factor, a letter
        return how
    if held and rearranging.letter_term(failing[0], held[-1], U, pt):  # a mass divided out of all but one term
        return "algebra"
    if held and same_but_number(failing[0].difference, held[-1].difference, U, pt):
        return "algebra" if rearranging.sign_carried(failing[0], held[-1], U, pt) else "arithmetic"
    return ""


def same_but_number(F: sympy.Expr, G: sympy.Expr, U: tuple, pt: dict) -> bool:
    """Whether ``F`` is ``c G`` but for its number (the terms free of the unknowns)."""
    cf, cg = coefficients(F.xreplace(pt), U), coefficients(G.xreplace(pt), U)
    if not cf or not cg:
        return False
    constant = (0,) * len(U)
    terms = (set(cf) | set(cg)) - {constant}
    if not terms:
        return False
    key = max(terms, key=lambda m: abs(cg.get(m, 0)))
    if not cg.get(key) or not cf.get(key):
        return False
    c = cf[key] / cg[key]
    scale = max(abs(cf.get(m, 0)) for m in terms)
    return all(abs(cf.get(m, 0) - c * cg.get(m, 0)) <= 1e-9 * scale for m in terms)


def _simple_fraction(x: sympy.Expr) -> bool:
    """A proper fraction of a small denominator, as a fraction given is written (⅓, ¾, 2/5)."""
    return bool(x.is_Rational and not x.is_Integer and abs(x) < 1 and x.q <= 10)


def _has_letters(text: str) -> bool:
    return (
        re.search(r"(?<!\\)\b[A-Za-z]\w*", re.sub(r"\\(?:frac|dfrac|tfrac|times|cdot|left|right)", " ", text))
        is not None
    )


def copied_wrong(ctx: Context, bad: Pair, holds: Holds, text: str = "") -> bool:
    """Whether ``bad`` holds once a number or letter in it that looks like one of the givens
    (its digits in another order or place, or its coefficient dropped: ``u`` for ``2u``) is
    put back as that given, or a number it comes to scaled as that given's copy written on the
    line (``text``: all its sides) scales it."""
    if bad.raw is None:
        return False
    values = [g.value if g.value is not None else g.definition for g in ctx.problem.givens if not g.unknown]
    givens = [x for x in values if x is not None and x != 0]
    factored = tuple(sympy.factor_terms(x) for x in bad.raw)  # 6(1020 + M), read as 6M + 6120: 1020 again
    for raw in (bad.raw, factored) if factored != bad.raw else (bad.raw,):
        atoms = set().union(*(x.atoms(sympy.Number, sympy.Symbol) for x in raw)) - {DEG}
        for a in atoms:
            for g in givens:
                if _looks_like(a, g) and _holds_with(ctx, replace(bad, raw=raw), {a: g}, holds):
                    return True
    return _scaled_copy(ctx, bad, givens, holds, text or bad.text)


def _scaled_copy(ctx: Context, bad: Pair, givens: list[sympy.Expr], holds: Holds, text: str) -> bool:
    """Whether ``bad`` holds once a number it comes to is scaled as a given copied wrongly on the
    line scales it: ``(3/4)(2u)`` read as 3u/2, with e = 2/3 copied as 3/4; ``2(7.84)(7.2) = 112.9``
    with the 2.7 m copied as 7.2 (112.9 is then 42.3)."""
    assert bad.raw is not None
    written = {sympy.Rational(t) for t in re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?:/\d+)?(?![\w.])", text)}
    numbers = set().union(*(x.atoms(sympy.Number) for x in bad.raw)) - {sympy.Integer(0)}
    for c in written:
        for g in givens:
            if not (c and g.is_Rational and _looks_like(c, g)):
                continue
            for a in numbers:
                if any(_holds_with(ctx, bad, {a: a * k}, holds) for k in (g / c, c / g)):
                    return True
    return False


def copied_into_working(ctx: Context, sides: tuple[str, ...], exprs: list, holds: Callable[[list], bool]) -> bool:
    """Whether a line of working holds once each of its sides of numbers is scaled as a given's
    copy written on it scales it (``V² = 2ad = 2(7.84)(7.2) = 112.9`` with the skid's 2.7 m
    copied as 7.2: 2(7.84)(2.7) = 42.3); ``holds`` judges the sides (in the student's names)."""
    written = {sympy.Rational(t) for t in re.findall(r"(?<![\w.])\d+(?:\.\d+)?(?:/\d+)?(?![\w.])", " ".join(sides))}
    data = [g for g in ctx.data if g.is_Rational and g != 0]
    numeric = [not x.free_symbols for x in exprs]
    if not any(numeric) or all(numeric):
        return False
    for c in written - set(ctx.data):
        for g in data:
            if not (c and _looks_like(c, g)):
                continue
            for k in (g / c, c / g):  # the copy a factor of the working, or a divisor (g in V²/2g)
                if holds([x * k if n else x for x, n in zip(exprs, numeric, strict=True)]):
                    return True
    return False


def _looks_like(a: sympy.Expr, g: sympy.Expr) -> bool:
    """``a`` written for the given ``g``: the same digits in another order or place (3.64 for
    3.46, 60 for 6), a letter with its coefficient lost (``u`` for ``2u``), or another simple
    fraction of the same sign (½ for ⅓)."""
    if a == g or a == -g:
        return False
    if isinstance(a, sympy.Symbol):
        ratio = sympy.simplify(g / a)
        return bool(ratio.is_number and ratio not in (1, -1) and g.free_symbols == {a})
    if not (a.is_number and g.is_number and a.is_Rational and g.is_Rational):
        return False

    def digits(x: sympy.Expr) -> str:
        return re.sub(r"[^0-9]", "", format(Decimal(str(sympy.Float(x, 15))).normalize(), "f")).strip("0")

    if len(digits(g)) >= 2 and sorted(digits(a)) == sorted(digits(g)):
        return True
    if _simple_fraction(a) and _simple_fraction(g) and (a > 0) == (g > 0):  # e = 1/2 written for 1/3
        return True
    whole = [format(Decimal(str(sympy.Float(x, 15))).normalize(), "f") for x in (a, g)]  # 1020 for 1200: zeros too
    return "." not in "".join(whole) and len(whole[1]) >= 3 and sorted(whole[0]) == sorted(whole[1])


#: What a report says of a line that holds with one term's sign flipped, by the slip's name.
FLIPPED = {
    "algebra": ": it holds with the sign of one term changed (a slip in rearranging: a sign lost).",
    "b_sign": ": it holds with one velocity's sign reversed (a velocity taken in the wrong direction).",
}


#: A slip found by a term's sign: its name, and the line with that sign put right (in the
#: unknowns: the equation the line stands for).
Flip = tuple[str, sympy.Expr | None]


def sign_flipped(ctx: Context, bad: Pair, unknowns: tuple, holds: Holds) -> Flip:
    """``algebra`` or ``b_sign`` where ``bad`` holds with the sign of exactly one of its terms
    changed (``v = 3eu - w`` from ``w - v = 3eu``: v's sign lost; ``0.5(6) + 2(2) = 0.5(0.2) + 2v``
    for an A that moves back: a velocity's); "" otherwise. A flipped term that is a mass times
    a velocity of the problem (or times a number on the line) is ``b_sign``; any other,
    ``algebra``. Only lines of three terms or
    more: ``v = 1.6`` for -1.6 is an answer's sign."""
    if bad.raw is None:
        return "", None
    terms = [sympy.Add.make_args(x) for x in bad.raw]
    two = sum(len(t) for t in terms) == 2 and rearranging.written_terms(bad.text) >= 3  # 4u/3 - 4u: -8u/3
    if sum(len(t) for t in terms) < 3 and not two:
        return "", None
    found = []
    for i, side in enumerate(bad.raw):
        for term in terms[i]:
            raw = list(bad.raw)
            raw[i] = side - 2 * term
            left, right = (ctx.in_unknowns(x) for x in raw)
            if holds(replace(bad, left=left, right=right, raw=(raw[0], raw[1]))):
                found.append((term, left - right))
    if two and len(found) == 2:  # a = b with a's sign or b's: the same relation; the unknown's term
        found = [f for f in found if ctx.in_unknowns(f[0]).free_symbols & set(unknowns)]
    if len(found) != 1:
        return "", None  # none, or more than one way: not this slip
    term, right_way = found[0]
    if ctx.in_unknowns(term).free_symbols & set(unknowns):
        return "algebra", right_way
    return "b_sign" if _momentum_of_velocity(ctx, term, bad.text) else "algebra", right_way


def sign_of_a_term(exprs: list, holds: Callable[[list], bool]) -> str:
    """A chain's line ``a = b`` (in letters and numbers) that holds with the sign of exactly one
    of its terms changed (``0 = v_2² + 2(9.8)(1.4)`` for ``0 = v_2² - 2(9.8)(1.4)``): ``algebra``
    where that term has a letter, ``b_sign`` where it is a number (a momentum, a mass times a
    velocity); "" otherwise (none, more than one, or a line of numbers only: arithmetic)."""
    if len(exprs) != 2 or not any(x.free_symbols for x in exprs):
        return ""
    terms = [sympy.Add.make_args(x) for x in exprs]
    if sum(len(t) for t in terms) < 3:
        return ""
    found = [
        (t, [*exprs[:i], side - 2 * t, *exprs[i + 1 :]])
        for i, side in enumerate(exprs)
        for t in terms[i]
        if t != 0 and holds([*exprs[:i], side - 2 * t, *exprs[i + 1 :]])
    ]
    if len(_one_up_to_sign([x[0] - x[1] for _t, x in found])) != 1:
        return ""
    return "algebra" if any(t.free_symbols for t, _x in found) else "b_sign"


def _one_up_to_sign(differences: list[sympy.Expr]) -> list[sympy.Expr]:
    """The relations ``differences`` (each lhs - rhs), one of each up to its sign (``0 = -v² + 27.4``
    is ``0 = v² - 27.4``: the same sign lost, found from either term)."""
    out: list[sympy.Expr] = []
    for d in differences:
        if not any(sympy.expand(d - o) == 0 or sympy.expand(d + o) == 0 for o in out):
            out.append(d)
    return out


def _momentum_of_velocity(ctx: Context, term: sympy.Expr, text: str) -> bool:
    """Whether ``term`` is a mass of the problem times one of its velocities (given, or a number
    written on the line): ``0.5(0.2)`` with m_A = 0.5 kg and A's 0.2 m/s."""
    givens = [g for g in ctx.problem.givens if g.value is not None and not g.unknown and g.value != 0]
    masses = [g.value for g in givens if g.name.startswith("m")]
    velocities = [g for g in givens if g.name[:1] in "uvw"]
    written = {sympy.Rational(t) for t in re.findall(r"(?<![\w.])\d+(?:\.\d+)?", text)}
    for m in masses:
        v = sympy.simplify(term / m)
        v = sympy.nsimplify(v, rational=True) if v.is_number else v
        if any(sympy.simplify(abs(v) - abs(g.value)) == 0 for g in velocities):
            return True
        if v.is_number and v != 0 and abs(v) in written:
            return True
    return False


#: Two mistakes that are one misunderstanding written in two lines: e put on the component along
#: the surface and left off the normal one (its restitution as if e = 1): e moved to the wrong
#: component, whichever line comes first.
ONE_MISTAKE = (frozenset({"e_on_t", "energy_conserved"}),)


def same_mistake(named: set[str], made: set[str]) -> bool:
    """Whether the mistakes ``made`` in a line are those ``named`` at an earlier slip, made again
    (the same mistake, or the other half of one misunderstanding of :data:`ONE_MISTAKE`)."""
    return bool(named & made) or any(named & pair and made & pair and not named & made for pair in ONE_MISTAKE)
