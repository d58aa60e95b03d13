"""A derivation's relations read in the student's names (:mod:`.naming`): each side in the problem's symbols.

Every student name that is not derive's is read first as a placeholder; the placeholders are then given their meaning
all at once. The sign convention and the meaning of the names no declaration or habit settles are chosen to make the
most relations hold with the problem's true values (a slip later on does not move them: the lines before it hold).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

import sympy

from derive.checking.axisnames import components
from derive.checking.bodygivens import body_givens
from derive.checking.byvalue import worked_names
from derive.checking.componentlabels import body_labels
from derive.checking.context import Context
from derive.checking.conventions import signed_by_words
from derive.checking.declaredspeeds import MAGNITUDE, kept_speeds, speeds_before
from derive.checking.declaredspellings import as_read
from derive.checking.degreemode import in_degrees
from derive.checking.energyinstants import energy_at_labels
from derive.checking.frames import (
    along_wall,
    axis_names,
    declared_axes,
    flipped,
    in_said_way,
    reversal_said,
    score,
    uses_n_components,
)
from derive.checking.frames import pairs as frame_pairs
from derive.checking.gluednames import twin_letters
from derive.checking.grounding import grounded, grounded_frame, natural_of, the_speed
from derive.checking.massletters import masses_put_in
from derive.checking.namegrammar import energy_change, grammar_names
from derive.checking.namenotes import in_order, said_read
from derive.checking.naming import (
    GREEK,
    PREFIX,
    Open,
    declarations,
    declares,
    habits,
    of_the_body,
    placeholders,
    read_side,
    rewrite,
)
from derive.checking.ownnames import combos, directed, named_later, own_readings, spells_givens, velocities_before
from derive.checking.reducedmass import mass_named, reduced_mass
from derive.checking.restated import is_size, restated
from derive.checking.saidagain import said_again
from derive.checking.shapes import Shapes
from derive.checking.spellings import shared_letters
from derive.checking.tangentsense import in_student_sense
from derive.checking.valuedlabels import valued_labels
from derive.checking.valuenames import by_letter, by_value, candidates, kinds, of_kind
from derive.checking.velocitywords import along_the_line
from derive.checking.wordlabels import word_label
from derive.mathtext.notation import student
from derive.mathtext.reader import Relation, read_relations
from derive.problem.expr import ParseError
from derive.problem.units import VELOCITY, Dim

#: Greek letters typed as themselves (a student who types μ means a name of its own).
_GREEK_LETTERS = {"mu": "μ", "lambda": "λ", "omega": "ω", "gamma": "γ", "alpha": "α", "phi": "φ", "sigma": "σ"}
JOINT = 2  # the most names inferred together (more are inferred one at a time)
MAX_INFERRED = 6  # the most names inferred in one derivation (the search is bounded; the rest stay unknown)


@dataclass(frozen=True)
class Read:
    """One relation as read: ``sides`` as written (plain syntax), ``exprs`` in the problem's
    symbols (None where it could not be read; ``error`` says why)."""

    number: int
    written: str
    sides: tuple[str, ...]
    tag: str
    exprs: tuple[sympy.Expr, ...] | None
    error: str = ""
    defines: str = ""
    own_names: bool = False  # it uses names of the student's own (x, u_A, v_G)
    direction: int = 0  # its last number's direction in words (:attr:`~.reader.Relation.direction`)
    pending: tuple[sympy.Expr, ...] = ()  # not read for names not placed: its sides with them (:mod:`.byvalue`)


def read_lines(
    ctx: Context, text: str, pt: dict, truth: dict, equations: tuple[sympy.Expr, ...] = ()
) -> tuple[list[Read], list[str]]:
    """The relations of ``text`` in the problem's symbols, and what was inferred (sentences);
    ``equations`` are (1)-(4), whose shape a relation may have with a slip in its numbers."""
    axes = declared_axes(text) if ctx.problem.oblique else {}
    every = directed(read_relations(text, axes, not ctx.problem.oblique), text)
    every = valued_labels(energy_change(energy_at_labels(every)))  # KE after: …; approach speed 2 - (-6) = 8
    relations = tuple(r for k, r in enumerate(every) if not declares(r, k == 0 or every[k - 1].line != r.line))
    problem = {n: s for n, (s, _d) in ctx.equation_names().items()}
    known = set(problem) | {"speed_A", "speed_B", "u", "v", "x", "y", "V", "w"} | set(habits(ctx, None))
    lefts = {r.sides[0].strip() for r in relations if re.fullmatch(r"[A-Za-z]\w*", r.sides[0].strip())}  # "mu = …"
    own = mass_named(ctx, relations)  # mu = 9m/10: a mass, the student's own name, not m times u
    known |= {w for w in lefts if not ((w in GREEK or 1 < len(w) < 4) and all(c in problem for c in w)) or w in own}
    known |= set(reduced := reduced_mass(ctx, relations))  # "mu = (m)(9m)/(10m)": no m times u
    declared, sign = as_read(*declarations(text, ctx, declared_axes if ctx.problem.oblique else None))  # v1: v_1
    reserved = set(problem) | set(declared)
    kinded = {**by_letter(relations, reserved), **kinds(relations, text, reserved)}
    valued = {
        **by_value(ctx, relations, kinded, (pt, truth)),
        **components(relations, ctx, reserved, sign),
        **restated(ctx, relations, reserved),
    }
    known |= set(declared) | set(kinded)  # "let a and b be …": ma + mb is m a + m b
    known |= {"m"} if "m_A" in problem else set()  # m for the masses (m_A = m_B = m): ma + mb is m a + m b
    (split, labels), twins = body_labels(list(relations)), twin_letters(text)  # twins: the bullet's v_b1, block's v_B1
    relations = tuple(split)
    rewritten: list[tuple[str, ...]] = []
    for r, lb in zip(relations, labels, strict=True):
        seen = {w for sides in rewritten for s in sides for w in re.findall(r"\b[A-Za-z]\b|\b[uvwV]_?[xy]\b", s)}
        sides = tuple(rewrite(of_the_body(s, lb, seen, lb == r.label, set(problem)), known, twins) for s in r.sides)
        rewritten.append(along_the_line(ctx, r, masses_put_in(ctx, sides)))  # ½(0.020)(300)²: the bullet's m
    written = [*dict.fromkeys(w for sides in rewritten for s in sides for w in re.findall(r"[A-Za-z][A-Za-z0-9_]*", s))]
    used = set(written)
    grammar = grammar_names(ctx, used, text, set(problem) | set(declared), axes) | body_givens(ctx, used, problem)
    meanings: dict[str, sympy.Expr] = {
        **shared_letters(ctx, used, problem),
        **habits(ctx, used),
        **axis_names(ctx, axes, used),
        **valued,
        **grammar,
        **reduced,  # mu in ½ mu (1 - e²) u²
        **declared,
    }  # p_i: no impulse
    meanings = in_order(meanings, written)  # as the names are first written: the same report every run
    names = Open({**problem, **_speeds(ctx)}, set(meanings))
    raw = [_parse(r, sides, names) for r, sides in zip(relations, rewritten, strict=True)]
    raw = speeds_before(ctx, raw, meanings, _speeds(ctx))  # with v1 = U: U is A's speed
    own_readings(ctx, raw, meanings, (pt, truth), set(declared))  # θ worked out to another value; u_1 = v_1 - v_cm
    defs = _definitions(raw, meanings, [r.aside for r in relations], frozenset(problem))
    equated = _equated(raw, meanings, defs, {g.symbol for g in ctx.problem.givens})
    defs.update(equated)
    on_body = {n for n in meanings if re.fullmatch(r"(?:impulse|dp)_[AB]", n)}  # their sign is the frame's
    own = any(p.name[1:] not in on_body for r in raw if r.exprs for e in r.exprs for p in placeholders(e))
    either = own or (uses_n_components(ctx, raw) and reversal_said(ctx, raw, pt, truth))
    signs = (sign,) if sign else (1, -1) if either else (1,)
    ways = {sg: flipped(ctx, raw, sg) for sg in signs}  # derive's n components in the student's frame
    found = {sg: _infer(ctx, ways[sg], meanings, defs, sg, pt, (truth, equations), kinded, bool(sign)) for sg in signs}
    _, mapping, inferred, s = max(
        ((*found[sg], sg) for sg in signs),
        key=lambda c: c[0] + (0 if own or c[3] == -1 else 1),  # derive's names only: two more must hold
    )
    g = grounded_frame(ctx, ways, {sg: f[1] for sg, f in found.items()}, (pt, truth)) if own else None
    if g:  # the frame the givens as written ground, not the one most lines hold in
        (_, mapping, inferred), s = found[g], g
    raw = ways[s]
    named_later(raw, mapping, problem)
    said_again(raw, mapping)  # "So J = 1.76" after "J = … = 1.76": that number again
    shared = worked_names(raw := kept_speeds(ctx, raw, mapping, _speeds(ctx)), mapping)  # v_A = sqrt(…); b - a = …
    lines = in_said_way(ctx, [signed_by_words(_magnitude(ctx, _resolved(r, mapping, shared)), s) for r in raw], s)
    lines, axes_words = in_student_sense(ctx, lines, pt, truth, axes)  # t the other way round: a frame
    said = [f"{p.name[1:]} is {e.name.removeprefix(PREFIX)}" for p, e in equated.items()]
    greek = {w for r in relations for w in re.findall(r"\\([a-z]+)", r.written)} | {
        n for r in relations for n, c in _GREEK_LETTERS.items() if c in r.written
    }
    split = sorted(greek & GREEK - known)
    split = [w for w in split if all(c in problem for c in w)]  # \mu as m u, where m and u are given
    return lines, said_read(meanings, declared, inferred, s, sign) + axes_words + (
        [f"Read from the relations: {', '.join(said)}."] if said else []
    ) + (["Read " + ", ".join(f"{w} as {'*'.join(w)}" for w in split) + "."] if split else [])


def _magnitude(ctx: Context, r: Read) -> Read:
    """``v_B = sqrt(0.3^2 + 0.173^2)`` (oblique): the student's ``v_B``, read elsewhere as B's n component
    after (``m u_A + m u_B = m v_A + m v_B``), is here B's speed; so is ``|v_B'|`` (US texts' bars)."""
    if not ctx.problem.oblique or not r.own_names or not r.exprs or len(r.sides) < 2:
        return r
    nm, speeds = ctx.model.nm, _speeds(ctx)
    body = next((b for b in "AB" if r.exprs[0] in (n := getattr(nm, f"{b}2n"), -n, sympy.Abs(n))), None)
    if body is None or f"speed_{body}" not in speeds or not MAGNITUDE.match(student(r.sides[1])):
        return r
    return replace(r, exprs=(speeds[f"speed_{body}"], *r.exprs[1:]))


def _equated(raw: list[Read], meanings: dict, defs: dict, givens: set) -> dict[sympy.Symbol, sympy.Symbol]:
    """``v_t = 0.61 = v_A2t = v_B2t``: a name of the student's own set equal to one of derive's names of what
    is worked out, side by side in a relation, stands for it (not a given: ``v_P = u`` is a root turned down)."""
    out: dict[sympy.Symbol, sympy.Symbol] = {}
    for r in raw:
        bare = [e for e in r.exprs or () if isinstance(e, sympy.Symbol)]
        theirs = [e for e in bare if e.name.startswith(PREFIX) and e.name[1:] not in meanings and e not in defs]
        ours = [  # derive's (not a given), or a habit's
            e for e in bare if (not e.name.startswith(PREFIX) and e not in givens) or e.name[1:] in meanings
        ]
        for p in theirs:
            if ours and p not in out:
                out[p] = ours[0]
    return out


def _speeds(ctx: Context) -> dict[str, sympy.Expr]:
    derived = ctx.derived()
    out = {}
    for b in "AB":
        if f"v_{b}2" in derived and ctx.problem.oblique:
            out[f"speed_{b}"] = derived[f"v_{b}2"][0]
        elif not ctx.problem.oblique and getattr(ctx.model.nm, f"{b}2n", None) is not None:
            out[f"speed_{b}"] = sympy.sqrt(getattr(ctx.model.nm, f"{b}2n") ** 2)  # |v_A|, at one dimension
    for b in "AB":  # a speed before ("speed of A before"): the size of the velocity before
        n, t = (getattr(ctx.model.nm, f"{b}1{c}", None) for c in "nt")
        if n is not None:
            out[f"speed_{b}1"] = sympy.sqrt(n**2 + (t**2 if t is not None and ctx.problem.oblique else 0))
    if getattr(ctx.problem, "fixed_B", False) and "speed_A" in out:
        out["speed_after"] = out["speed_A"]  # "rebound speed": only A moves after hitting a wall
        out.update(
            velocity_after=ctx.model.nm.A2n, velocity_before=ctx.model.nm.A1n, speed_before=sympy.Abs(ctx.model.nm.A1n)
        )
    nm = ctx.model.nm
    b1, b2 = nm.B1n if nm.B1n is not None else 0, nm.B2n if nm.B2n is not None else 0
    out["speed_app"] = nm.A1n - b1  # the speed of approach along n (positive: they approach)
    if nm.A2n is not None:
        out["speed_sep"] = b2 - nm.A2n
    return out


def _parse(r: Relation, sides: tuple[str, ...], names: Open) -> Read:
    exprs: list[sympy.Expr] = []
    shown = list(r.sides)
    try:
        for i, side in enumerate(sides):
            try:
                exprs.append(read_side(side, names, i == 0, i == len(sides) - 1))
            except ParseError:
                if i == 0 and (label := word_label(side, names, r.sides[-1])) is not None:  # "impulse = 11.2"
                    exprs.append(label)
                    continue
                if i == 0 and r.lead:  # "loss = ½ mu (relative speed)^2 ⏎ = ½(1.2m)(36)": the chain's subject
                    exprs.append(read_side(rewrite(r.lead, set(names.known) | names.extra), names, True, False))
                    shown[0] = r.lead
                    continue
                if i == len(sides) - 1 or len(sides) < 3 or (i and not exprs and len(sides) - i < 3):
                    raise  # "impulse = change in momentum = 0.8(1.2) + 0.8(4) = 4.16": words, words, then a relation
                shown[i] = None  # "momentum before = 4(3) + 2(-1) = 10": words, then a relation
        first = exprs[0] if exprs else None
        if (
            first is not None
            and first.is_Symbol
            and (first.name.startswith(PREFIX) or _velocity(first))
            and re.search(r"\bspeed\b", r.label, re.I)
        ):
            exprs[0] = sympy.sqrt(exprs[0] ** 2)  # "speed after: v = eu = 1.2": the size of v
    except (ParseError, ValueError, TypeError, RecursionError) as exc:
        return Read(r.line, r.written, r.sides, r.tag, None, str(exc))
    sides, exprs = in_degrees(tuple(s for s in shown if s is not None), tuple(exprs))
    return Read(r.line, r.written, sides, r.tag, exprs, direction=r.direction)


#: A trigonometric function of an angle the student names, and its inverse.
_INVERSE = {sympy.tan: sympy.atan, sympy.sin: sympy.asin, sympy.cos: sympy.acos}


def _definitions(
    raw: list[Read], meanings: dict[str, sympy.Expr], asides: list[bool], given: frozenset[str] = frozenset()
) -> dict[sympy.Symbol, sympy.Expr]:
    """``v_G = (m_A u_A + m_B u_B)/(m_A + m_B)``: a name first met alone on the left of a
    relation whose right side uses only names with a meaning (and some name): defined; so is
    a Greek name or one after "with" (``with mu = 0.4 and w = 4``) by its number."""
    seen: set[sympy.Symbol] = set()
    defs: dict[sympy.Symbol, sympy.Expr] = {}
    for i, r in enumerate(raw):
        if r.exprs is None:
            continue
        left, right = r.exprs[0], r.exprs[1]
        inverse = _INVERSE.get(type(left))
        if inverse is not None and left.args[0].is_Symbol and left.args[0].name[1:] in GREEK:
            left, right = left.args[0], inverse(right)  # "tan β = 2/(√3(1 - e))": β defined
        if left.is_Symbol and left.name.startswith(PREFIX) and left not in seen and left.name[1:] not in meanings:
            if spells_givens(left.name[1:], right, given, r.written):
                continue  # mu = 9m v_A + m v_B, m and u given: m × u, not a name
            right = right.xreplace(defs)
            open_ = {p for p in placeholders(right) if p.name[1:] not in meanings}
            if (right.free_symbols or asides[i] or left.name[1:] in GREEK) and not open_:
                defs[left] = right
                raw[i] = Read(r.number, r.written, r.sides, r.tag, r.exprs, defines=left.name[1:])
        for e in r.exprs:
            seen |= placeholders(e)
    return defs


def _infer(
    ctx: Context,
    raw: list[Read],
    meanings: dict[str, sympy.Expr],
    defs: dict[sympy.Symbol, sympy.Expr],
    sign: int,
    pt: dict,
    known: tuple[dict, tuple[sympy.Expr, ...]],
    kinded: dict[str, Dim] | None = None,
    declared: bool = False,
) -> tuple[float, dict[sympy.Symbol, sympy.Expr], dict[str, str]]:
    """(relations that hold, placeholder -> meaning, inferred name -> what) for one sign; ``known``
    is the true velocities and the equations (1)-(4); ``kinded`` the names whose kind the text
    states (a mass, an impulse): only a quantity of that kind is inferred for them; ``declared``: the
    positive way is said in words."""
    truth, equations = known
    base: dict[sympy.Symbol, sympy.Expr] = {}
    for name, e in meanings.items():
        turned = (_velocity(e) and not is_size(ctx, e)) or re.fullmatch(r"(?:impulse|dp)_[AB]", name)  # on a body
        turned = turned and not (ctx.problem.fixed_B and along_wall(ctx, e))  # out of a wall: t stays
        base[sympy.Symbol(PREFIX + name)] = sign * e if turned else e
    pairs = frame_pairs(ctx, raw, pt, truth)
    if not meanings and not any(placeholders(e) for r in raw if r.exprs for e in r.exprs):
        return score(pairs, {}, ctx, pt, truth) + (0.5 if sign == 1 else 0), {}, {}
    shapes = Shapes(ctx, raw, pt, truth, equations)
    mapping = {**base, **{k: v.xreplace(base) for k, v in defs.items()}}
    unknown: list[sympy.Symbol] = []
    together: list[sympy.Symbol] = []  # the first names met in one relation: inferred together
    for pairs_of_line in pairs:
        for _t, (left, right), _m in pairs_of_line:
            found = sorted(placeholders(left) | placeholders(right), key=str)
            new = [p for p in found if p not in mapping and p not in unknown]  # met first here
            unknown += [p for p in new if p not in unknown]
            if len(new) >= 2 and not together:
                together = new[:JOINT]
    cands = candidates(ctx, truth, set((kinded or {}).values()))
    if ctx.problem.fixed_B:  # a wall's velocities are no one's name
        cands = [c for c in cands if not re.fullmatch(r"v_B\d\w?", _symbol_name(c[1]))]
    kind = {sympy.Symbol(PREFIX + n): d for n, d in (kinded or {}).items()}
    inferred: dict[str, str] = {}
    singles = [[p] for p in unknown if p not in together][: MAX_INFERRED - len(together)]
    groups = ([together] if together else []) + singles  # bounded: the rest stay unknown
    groups.sort(key=lambda g: unknown.index(g[0]))  # in the order met: U in "U cos 30 = 0.866U" before p, q
    solved, known = _solved_for(raw), _knowns(ctx) - set(truth)  # an unknown before (find u) may be solved for
    for group in groups:
        options = [
            c
            for c in combos(group, cands, raw, velocities_before(ctx))
            if not any(p in solved and e in known for p, (_w, e) in zip(group, c, strict=True))
            and all(of_kind(kind.get(p), w) for p, (w, _e) in zip(group, c, strict=True))
            and not (declared and len(group) > 1 and all(isinstance(-sign * e, sympy.Symbol) for _w, e in c))
        ]  # with a positive way said, names met together are not all read the other way (its reverse)
        if not options:
            continue
        tried = [{**mapping, **{p: c[1] for p, c in zip(group, combo, strict=True)}} for combo in options]
        fits = [score(pairs, t, ctx, pt, truth) + shapes.score(t) for t in tried]
        best = max(zip(options, fits, strict=True), key=lambda cf: cf[1] + _natural(group, cf[0]))[0]
        best = grounded(best, options, group, mapping, pairs, (ctx, pt, truth, sign))  # not a slip made right
        ranked = {o: f + _natural(group, o) for o, f in zip(options, fits, strict=True)}  # by its first relation:
        natural = [o for o in options if natural_of(o, options, sign) == o]  # A's then B's, each its own way
        best = shapes.first_shaped(best, options, group, mapping, ranked.__getitem__, natural)
        shown = all(len(r.sides) >= 3 for r in raw if r.exprs and any(set(group) & placeholders(e) for e in r.exprs))
        need = 1 if _natural(group, best) or shown or shapes.grounds(best, group, mapping) else 2  # once: enough
        floor = max(min(fits), score(pairs, mapping, ctx, pt, truth) + shapes.score(mapping))  # what holds anyway
        if fits[options.index(best)] < floor + need:
            best = the_speed(ctx, group, options)  # or "speed U": the problem's speed, renamed
            if best is None:
                continue  # fewer than two relations hold that way: the name stays unknown
        for p, (what, e) in zip(group, best, strict=True):
            mapping[p] = e
            inferred[p.name[1:]] = what
    _by_analogy(unknown, mapping, inferred, {c[1]: c[0] for c in cands})
    mapping = {k: v.xreplace(mapping) for k, v in mapping.items()}
    return score(pairs, mapping, ctx, pt, truth) + (0.5 if sign == 1 else 0), mapping, inferred


def _solved_for(raw: list[Read]) -> set[sympy.Symbol]:
    """The student's names solved for: met first in a relation with more in it (``3a + 4b =
    -21``), then alone = a number (``a = -9``). Such a name is an unknown, never a velocity
    before the impact or a given (which would make ``3(9) + 4(-12) = 3a + 4b`` say nothing)."""
    seen: set[sympy.Symbol] = set()
    out: set[sympy.Symbol] = set()
    for r in raw:
        if r.exprs is None:
            continue
        first = r.exprs[0]
        if first in seen and len(r.exprs) >= 2 and not placeholders(r.exprs[-1]) and first.is_Symbol:
            out.add(first)
        alone = first.is_Symbol and len(r.exprs) >= 2 and not any(placeholders(e) for e in r.exprs[1:])
        if not alone:
            seen |= set().union(*(placeholders(e) for e in r.exprs))
    return out


def _knowns(ctx: Context) -> set[sympy.Expr]:
    """What is known before the impact: the components before and the velocities given."""
    nm = ctx.model.nm
    out = {c for c in (nm.A1n, nm.B1n, nm.A1t, nm.B1t) if c is not None}
    return out | {g.symbol for g in ctx.problem.givens if g.value is None and not g.unknown and g.dim == VELOCITY}


def _by_analogy(unknown: list, mapping: dict, inferred: dict[str, str], named: dict) -> None:
    """A name still unknown whose n component was read (``v_At`` where ``v_An`` is v_A2n) is
    the same velocity's t component (and the other way round); ``v_y`` where ``v_x`` is read, the
    same velocity's other component, whichever of n and t x is."""
    swap = {"n": "t", "t": "n", "x": "y", "y": "x"}
    for p in unknown:
        twin = sympy.Symbol(p.name[:-1] + swap.get(p.name[-1], "?"))
        e = mapping.get(twin)
        if p in mapping or e is None or p.name[-1] not in swap:
            continue
        sign, sym = (-1, -e) if isinstance(-e, sympy.Symbol) else (1, e)
        component = isinstance(sym, sympy.Symbol) and sym.name[-1:] in ("n", "t")
        if component and (p.name[-1] in "xy" or sym.name[-1] != p.name[-1]):
            other = sympy.Symbol(sym.name[:-1] + swap[sym.name[-1]], **sym.assumptions0)
            if other in named:
                mapping[p] = sign * other
                inferred[p.name[1:]] = named.get(sign * other, other.name)


def _natural(group: list[sympy.Symbol], combo: tuple) -> float:
    """A bonus for the natural reading of two names met together (x, y; a, b; p, q): the first
    is A's, the second B's; it takes two more relations holding to read them the other way."""
    if len(group) == 1 and group[0].name[1:] in ("I", "J", "J_n", "Imp") and combo[0][0] in ("J_n", "-J_n"):
        return 1.0  # I or J for the impulse: one relation is enough
    if len(group) != 2:
        return 0.0
    first, second = (_symbol_name(c[1]) for c in combo)  # a body's velocity (the common velocity is neither's)
    same_time = first.replace("A", "B") == second  # v_A2 and v_B2, not v_A1 and v_B2
    return 1.5 if "A" in first and same_time else 0.0


def _symbol_name(e: sympy.Expr) -> str:
    """The name of ``e``, a symbol or its negative ("" for any other expression)."""
    e = -e if isinstance(-e, sympy.Symbol) else e
    return e.name if isinstance(e, sympy.Symbol) else ""


def _velocity(e: sympy.Expr) -> bool:
    return any(s.name.startswith("v_") for s in e.free_symbols)


def _resolved(r: Read, mapping: dict[sympy.Symbol, sympy.Expr], shared: frozenset = frozenset()) -> Read:
    if r.exprs is None:
        return r
    exprs = tuple(e.xreplace(mapping) for e in r.exprs)
    marks, k = [placeholders(e) for e in exprs], 0
    while (left := set().union(*marks[k:])) and len(exprs) - k >= 3 and not r.defines and not marks[k] & shared:
        if set().union(*marks[k + 1 :]) and (left != marks[k] or not exprs[k].is_Symbol):
            break
        k += 1  # "tan φ = e tan θ = 3e": the rest; "p = 0.150 x 35.0 = 5.25": its first side unplaced
    r, exprs = (replace(r, sides=r.sides[k:], exprs=r.exprs[k:]), exprs[k:]) if k else (r, exprs)
    if left and not r.defines:
        names = ", ".join(sorted(p.name[1:] for p in left))
        return Read(r.number, r.written, r.sides, r.tag, None, f"unknown name {names}", pending=exprs)
    own = any(placeholders(e) for e in r.exprs)
    return replace(r, exprs=exprs, own_names=own)
