"""A line whose relation is read but whose names are not all placed, judged by their values.

Where a relation of the student's reads but some of its names could not be placed (``a + b =
0.7071v`` after "let A and B have n components a and b", words derive does not read), a teacher
still marks it: they read each name as the quantity its value is. So the few readings the problem
allows for the unplaced names are tried (the velocities after, either way; the common velocity, the
energy lost, the impulse; the velocities and components before, none that is zero; the angles given
for a name inside sin, cos or tan; the masses and their total for a name in m): the line is put in
the reading under which it holds for the problem, or else in the student's own world after a slip,
and judged there as any line is (correct, carried, a slip and its name). Before the lines are
judged, each name is placed by the first line that holds for the problem with it (so a slip made
before that line is found); a name keeps its reading on every line after (the student means one
thing by it): a line that does not hold with it is a slip, not read another way to make it hold.
Where several readings fit, the natural one is taken (A's then B's, the same instant, a velocity
its own way before its reverse); several names are placed by one relation only where at most one
has no sibling in it (A's beside B's); a name the line holds for whatever it stands for (``v sin
45° = 0.7071v``) is not placed by it. Where no reading fits and every name is partly placed (a
mass, an angle, a body's ``v_A``), the reading its working holds for (the sides after its label)
is judged: a slip. Where nothing is placed, a line whose first side is names and whose working after
it is in numbers has that working judged; any other line stays not read. The readings are bounded (at
most three names, at most :data:`MAX_READINGS` readings; numbers, not algebra, pick the reading),
and the item says what was assumed: "a read as v_A2n, by its value".
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import replace
from typing import Any

import sympy

from derive.checking.naming import PREFIX, placeholders
from derive.checking.valuenames import candidates, quantities
from derive.checking.words import meaning
from derive.problem.units import ANGLE, MASS, VELOCITY

MAX_NAMES = 3  # the most unplaced names one line is read by value for
MAX_READINGS = 6000  # the most readings tried for one line
MAX_LINES = 40  # the most lines of one derivation read by value (each pass)
LOOSE = 0.02  # the relative slack a reading is picked with (the line is then judged at its figures)
TIGHT = 0.002  # a reading that holds this closely (to three figures) is taken before those that hold loosely
_MODULES = [{"Abs": abs}, "cmath"]  # the sides worked in complex numbers (a root of a negative)
_ARBITRARY = (1.37, -2.91)  # two values no quantity of a problem is likely to have together


def item(trace: Any, line: Any) -> Any:
    """The verdict on ``line`` (:class:`~.inference.Read`) by ``trace`` (:class:`~.lines.Trace`):
    a line not read for names not placed is judged in the reading its values allow."""
    if line.exprs is not None or not getattr(line, "pending", ()):
        return trace.item(line)
    tried = trace.__dict__["by_value_lines"] = trace.__dict__.get("by_value_lines", 0) + 1
    try:
        reading = _reading(trace, line) if tried <= MAX_LINES else None
    except (TypeError, ValueError, ZeroDivisionError, OverflowError, AttributeError):
        reading = None
    if reading is None:  # μ = 3m·6m/9m = 3m, μ no quantity of the problem's: its working is judged
        working = _worked_out(line.pending)
        return trace.item(
            replace(line, sides=line.sides[1:], exprs=line.pending[1:], error="", own_names=True, pending=())
            if working
            else line
        )
    mapping, said = reading
    exprs = tuple(e.xreplace(mapping) for e in line.pending)
    out = trace.item(replace(line, exprs=exprs, error="", own_names=False, pending=()))
    if out is None or not said:
        return out
    return replace(out, notes=(*out.notes, f"Read by value: {'; '.join(said)}."))


def _options(ctx: Any, truth: dict) -> list[tuple[str, sympy.Expr, str]]:
    """What an unplaced name may stand for, (word, quantity, its kind): :func:`.valuenames.candidates`
    and the velocities given; the angles given (for a name inside sin, cos or tan only); the masses
    and their total (for a name in m only)."""
    out = [(w, c, "") for w, c in candidates(ctx, truth)]
    seen = {c for _w, c, _k in out}
    for g in ctx.problem.givens:
        if g.dim == VELOCITY and g.symbol not in seen and not g.unknown:
            out.append((g.name, g.symbol, ""))
        elif g.dim == ANGLE and not g.unknown:
            out.append((g.name, g.symbol, "angle"))
    masses = quantities(ctx)[MASS]
    out += [(w, c, "mass") for w, c in masses]
    out += [("the total mass", sympy.Add(*(c for _w, c in masses)), "mass")] if len(masses) == 2 else []
    return out + _momenta(ctx)


def _momenta(ctx: Any) -> list[tuple[str, sympy.Expr, str]]:
    """What a name in p may stand for: the bodies' total momentum (the same before and after), each
    body's momentum before and after, along the line of centres."""
    m, nm = ctx.model, ctx.model.nm
    pairs = [("A", m.m_A, nm.A1n, nm.A2n)]
    pairs += [] if ctx.problem.fixed_B or m.m_B is None else [("B", m.m_B, nm.B1n, nm.B2n)]
    out = [("the momentum", sympy.Add(*(mass * u for _b, mass, u, _v in pairs if u is not None)), "momentum")]
    return out + [
        (f"{b}'s momentum {when}", mass * x, "momentum")
        for b, mass, u, v in pairs
        for x, when in ((u, "before"), (v, "after"))
        if x is not None
    ]


def _kind(p: sympy.Symbol, exprs: list[sympy.Expr]) -> str:
    """What ``p`` may be: an angle inside sin, cos or tan; a mass where its letter is m; else the rest."""
    if _in_trig(p, exprs):
        return "angle"
    name = p.name[len(PREFIX) :]
    if re.fullmatch(r"[pP](?:_?\{?[A-Za-z0-9]{0,5}\}?)?", name):
        return "momentum"  # p, p_i, P_tot: a momentum
    return "mass" if re.fullmatch(r"[mM](?:_?\{?[A-Za-z0-9]{0,3}\}?)?", name) else ""


def _allows(kind: str, option: str) -> bool:
    """Whether a name of ``kind`` may be read as an option of kind ``option``: a name in p as a
    momentum or as any quantity a name says nothing of (``p``, ``q``: the velocities after)."""
    return option == kind or (kind == "momentum" and not option)


def _in_trig(p: sympy.Symbol, exprs: list[sympy.Expr]) -> bool:
    """Whether ``p`` is (in) the argument of a trigonometric function: an angle's name."""
    return any(p in f.free_symbols for e in exprs for f in e.atoms(sympy.sin, sympy.cos, sympy.tan))


def _symbol_like(name: str) -> bool:
    """A name a student gives a quantity: a letter, with a subscript, digits, a second letter or primes
    (``x``, ``v_A``, ``u1``, ``vB'``, ``KE``); not a word (``mass``) nor a body's own letter (``A``)."""
    if name in ("A", "B"):
        return False
    return re.fullmatch(r"[A-Za-z](?:_\{?\w{1,4}\}?|\d{1,2}|[A-Za-z]\d?)?'*", name) is not None


def _body(name: str) -> str:
    """The body a name says it is of (``v_A``, ``vB``, ``u_{A}``), or "" where it says none."""
    m = re.fullmatch(r"[A-Za-z]+_?\{?([AB])\}?'*", name)
    return m.group(1) if m else ""


def _of_body(word: str, expr: sympy.Expr, body: str) -> bool:
    names = [word, *(s.name for s in expr.free_symbols)]
    return any(re.search(rf"_{body}|{body}\d", n) for n in names)


def _numbers(trace: Any, e: sympy.Expr, values: list[dict]) -> list[complex] | None:
    out = []
    for pt, vals in zip(trace.pts, values, strict=True):
        x = trace.ctx.in_unknowns(e).xreplace(pt).xreplace(vals)
        if x.free_symbols:
            return None
        out.append(complex(x))
    return out


def _sizes(e: sympy.Expr) -> sympy.Expr:
    """``e`` with each sum's terms made positive: the size its terms have (``0.09 - 0.5196x = 0``
    holds at x = 0.1732 to the size of 0.09, not of the zero it comes to)."""
    return e.replace(lambda x: x.is_Add, lambda x: sympy.Add(*(sympy.Abs(a) for a in x.args)))


def _sides(trace: Any, exprs: list[sympy.Expr], free: list[sympy.Symbol], values: list[dict]) -> list | None:
    """Each side at each sample point as functions of the free names (on arrays of their values),
    its value and the size of its terms (None where one does not read)."""
    out = []
    for pt, vals in zip(trace.pts, values, strict=True):
        row = []
        for e in exprs:
            x = sympy.expand(trace.ctx.in_unknowns(e).xreplace(pt).xreplace(vals))
            if x.free_symbols - set(free):
                return None
            x = x.xreplace({f: sympy.Rational(f) for f in x.atoms(sympy.Float)})  # cmath prints no Float
            row.append((sympy.lambdify(free, x, _MODULES), sympy.lambdify(free, _sizes(x), _MODULES)))
        out.append(row)
    return out


def _offs(funcs: list, combos: list[tuple], table: list) -> list[float]:
    """For each reading (an option per free name), how far the sides are from the last at worst,
    relative to the size of their terms; ``table`` the options' values (an option by a sample
    point). Infinite where a side does not come to a number; a reading far off at the first point
    is not worked at the others."""
    out = []
    for combo in combos:
        worst = 0.0
        for k, row in enumerate(funcs):
            try:
                worst = max(worst, _off_at(row, tuple(table[i][k] for i in combo)))
            except (ZeroDivisionError, OverflowError, ValueError, TypeError):
                worst = math.inf
            if worst > LOOSE:
                break
        out.append(worst)
    return out


def _off_at(row: list, args: tuple) -> float:
    got = [(complex(f(*args)), abs(size(*args))) for f, size in row]
    last, last_size = got[-1]
    worst = 0.0
    for x, size in got[:-1]:
        scale = max(abs(x), abs(last), size, last_size)
        worst = max(worst, abs(x - last) / scale if scale > 1e-9 else 0.0)
    return worst


def _fits(trace: Any, exprs: list, free: list, allowed: list[list[int]], table: tuple, values: list[dict]) -> list:
    """The readings (an index into the options per free name, from those ``allowed`` it) under which
    the line holds at ``values``; never two names for one quantity or its reverse."""
    funcs = _sides(trace, exprs, free, values)
    options, nums = table
    combos = _combos([[i for i in a if nums[i] is not None] for a in allowed], options)
    if funcs is None or not combos:
        return []
    offs = dict(zip(combos, _offs(funcs, combos, nums), strict=True))
    tight = [c for c in combos if offs[c] <= TIGHT]  # those that hold to the figures written, where any do
    return tight or [c for c in combos if offs[c] <= LOOSE]


def _combos(allowed: list[list[int]], options: list) -> list[tuple]:
    """Every reading of the names, an option each from ``allowed``, no two the same quantity or
    its reverse."""
    same = [next(m for m, o in enumerate(options) if o[1] in (c, -c)) for _w, c, _k in options]
    return [c for c in itertools.product(*allowed) if len({same[i] for i in c}) == len(c)]


def _distinct(trace: Any, options: list, values: list[dict]) -> list:
    """Each option's numbers at ``values``; None for one that is zero (it would make any product
    hold) or that has the numbers of an option before it (the same quantity under two names)."""
    out: list = []
    for _w, c, _a in options:
        n = _numbers(trace, c, values)
        zero = n is not None and all(abs(x) < 1e-12 for x in n)
        same = n is not None and any(
            m is not None and max(abs(a - b) for a, b in zip(n, m, strict=True)) < 1e-12 for m in out
        )
        out.append(None if zero or same else n)
    return out


def _singles(words: list[str]) -> int:
    """How many of ``words`` have no sibling among them (the other body's same quantity: v_A2n, v_B2n)."""
    swap = str.maketrans("AB", "BA")
    return sum(1 for w in words if w.translate(swap) == w or w.translate(swap) not in words)


def _rank(combo: tuple, options: list) -> tuple:
    """The natural reading first: a quantity its own way before its reverse; names met together in
    order (A's, then B's), of the same instant; the quantities after before those before; then the
    earlier options."""
    words = [options[i][0] for i in combo]
    reversed_ = sum(w.startswith("-") for w in words)
    bodies = [("A" if "_A" in w else "B" if "_B" in w else "") for w in words]
    out_of_order = sum(1 for a, b in itertools.combinations(bodies, 2) if a == "B" and b == "A")
    times = {re.sub(r"[^0-9]", "", w.split("_")[-1])[:1] for w in words if "_" in w}
    before = sum(1 for w in words if re.search(r"1[nt]?$", w))  # a name solved for is after, not before
    return (reversed_, out_of_order, len(times), before, sum(combo))


def _idle(trace: Any, exprs: list, p: sympy.Symbol, others: dict, values: list[dict]) -> bool:
    """Whether the line holds whatever ``p`` stands for (``v sin 45° = 0.7071v``): it places nothing."""
    funcs = _sides(trace, [e.xreplace(others) for e in exprs], [p], values)
    if funcs is None:
        return False
    arbitrary = [[complex(a)] * len(values) for a in _ARBITRARY]
    return all(off <= LOOSE for off in _offs(funcs, [(0,), (1,)], arbitrary))


def worked_names(raw: list, mapping: dict) -> frozenset:
    """The names not placed that the derivation writes on more than one line: quantities it works
    with, which :func:`item` places by value. A first side of them is a side to judge (``b - a =
    0.7(92) = 64.4`` after ``235 = 4a + 3b``), not a label dropped before the working, as a name
    written once is (``p = 0.150 x 35.0 = 5.25``)."""
    seen: dict[sympy.Symbol, set[int]] = {}
    for r in raw:
        for p in set().union(*(placeholders(e) for e in r.exprs or ())) - set(mapping):
            seen.setdefault(p, set()).add(r.number)
    return frozenset(p for p, numbers in seen.items() if len(numbers) > 1)


def _worked_out(pending: tuple) -> bool:
    """Whether a line sets its names to a working in numbers (``a - b = 0.6(3.05 + 11.9) = 8.97``):
    a value that may fit an unnatural reading by chance (B's speed less A's), so it places no name
    ahead of the lines judged before it."""
    return len(pending) >= 3 and bool(placeholders(pending[0])) and not any(map(placeholders, pending[1:]))


def placed_ahead(trace: Any, lines: list) -> None:
    """Before the lines are judged: each name not placed, read by its value on the first line that
    holds for the problem with it (a later line may place the name an earlier slip is made in:
    ``0.2 − 0.5196 = a + 0.1732`` before ``0.1732 − a = e(0.3 + 0.5196)``)."""
    for line in [x for x in lines if x.exprs is None and getattr(x, "pending", ())][:MAX_LINES]:
        if _worked_out(line.pending):
            continue  # b - a = 0.7(92) = 64.4: names its working's number, placed where judged (natural first)
        try:
            _reading(trace, line, ahead=True)
        except (TypeError, ValueError, ZeroDivisionError, OverflowError, AttributeError):
            continue


def _key(p: sympy.Symbol, exprs: list[sympy.Expr]) -> tuple[sympy.Symbol, str]:
    """A name and whether it is an angle here: ``a`` in ``sin a = 0.8`` is not the ``a`` of ``4a + 3b``."""
    return (p, _kind(p, exprs))


def _reading(trace: Any, line: Any, ahead: bool = False) -> tuple[dict, list[str]] | None:
    """(placeholder -> quantity, what was assumed in words) for ``line``, or None; ``ahead``: for
    the problem's values only, before any line is judged."""
    memory: dict = trace.__dict__.setdefault("by_value", {})
    pending = list(line.pending)
    marks = sorted(set().union(*(placeholders(e) for e in pending)), key=str)
    fixed = {p: memory[_key(p, pending)][1] for p in marks if _key(p, pending) in memory}
    free = [p for p in marks if p not in fixed]
    if not all(_symbol_like(p.name[len(PREFIX) :]) for p in free):
        return None  # "mass A = 0.8": words and a body's letter, not names of quantities
    said = [_said(p, memory[_key(p, pending)], line.number, trace.ctx.problem) for p in marks if p in fixed]
    if not free:
        return fixed, said
    exprs = [e.xreplace(fixed) for e in pending]
    kinded = all(_kind(p, exprs) for p in free)  # p²/2M: each a name of a kind (a mass, a momentum)
    if len(free) > MAX_NAMES or len(exprs) < 2 or (len(free) > 1 and not (kinded or _linear(exprs, free))):
        return None
    if all(e in free or not e.free_symbols for e in exprs):
        return None  # "k = 4": a value alone says nothing of what it is the value of
    options = _options(trace.ctx, trace.truth[0])
    allowed = [[i for i, o in enumerate(options) if _allows(_kind(p, exprs), o[2])] for p in free]
    worlds = [trace.truth] + ([trace.world] if trace.world is not None and not ahead else [])
    for values in worlds:
        nums = _distinct(trace, options, values)
        if math.prod(sum(nums[i] is not None for i in a) for a in allowed) > MAX_READINGS:
            return None
        fits = [c for c in _fits(trace, exprs, free, allowed, (options, nums), values) if _natural(c, options)]
        tier = min((_rank(c, options)[:4] for c in fits), default=())
        if len({frozenset(_quantity(options, i) for i in c) for c in fits if _rank(c, options)[:4] == tier}) > 1:
            return None  # the values fit two sets of quantities as naturally: no reading is the student's
        if fits:
            best = min(fits, key=lambda c: _rank(c, options))
            return _placed(trace, (line, exprs, free, best), options, (fixed, said), values)
    return None if ahead else _partial(trace, (line, exprs, free), options, (fixed, said))


def _linear(exprs: list[sympy.Expr], free: list[sympy.Symbol]) -> bool:
    """Whether every side is of the first degree in the names together (momentum, restitution:
    ``2a + b``, ``a - b``); names multiplied together (``a b + c``) are read by value only alone."""
    try:
        return all(sympy.Poly(sympy.expand(e), *free).total_degree() <= 1 for e in exprs)
    except sympy.PolynomialError:
        return False


def _quantity(options: list, i: int) -> sympy.Expr:
    """The quantity of option ``i`` whichever way it is taken (v_A2n for -v_A2n)."""
    c = options[i][1]
    return -c if c.could_extract_minus_sign() else c


def _natural(combo: tuple, options: list) -> bool:
    """A reading of several names by one relation is a teacher's only where at most one of them has
    no sibling in it (a + b = 0.7071v: a and b A's and B's, v alone); two unrelated quantities that
    happen to make one relation hold (A's t component and the common velocity) are not."""
    return _singles([options[i][0] for i in combo if not options[i][2]]) <= 1


def _placed(trace: Any, found: tuple, options: list, known: tuple, values: list[dict]) -> tuple[dict, list[str]]:
    """The reading ``best`` of the ``free`` names kept (a name the line holds for whatever it is, not)."""
    line, exprs, free, best = found
    fixed, said = known
    memory = trace.__dict__["by_value"]
    mapping = {**fixed, **{p: options[i][1] for p, i in zip(free, best, strict=True)}}
    for p, i in zip(free, best, strict=True):
        others = {q: v for q, v in mapping.items() if q != p}
        if _idle(trace, exprs, p, others, values):
            said.append(f"it holds whatever {p.name[len(PREFIX) :]} stands for")
            continue
        memory[_key(p, exprs)] = (options[i][0], options[i][1], line.number)
        said.append(_said(p, memory[_key(p, exprs)], line.number, trace.ctx.problem))
    return mapping, said


def _said(p: sympy.Symbol, kept: tuple, number: int, problem: Any) -> str:
    where = "" if kept[2] == number else f" in line {kept[2]}"
    return f"{p.name[len(PREFIX) :]} read as {_in_words(kept[0], problem)}, by its value{where}"


def _in_words(word: str, problem: Any) -> str:
    """An option's name as the report says it: ``v_A2n`` as A's velocity after the impact, along the
    line of centres; the total mass as it is."""
    said = meaning(word, problem)
    return word if said == f"the given {word}" and word.startswith("the ") else said


def _partly(p: sympy.Symbol, kind: str, options: list) -> list[int]:
    """The readings a name partly placed allows: a mass's (``m``), an angle's, or its body's
    quantities after (``v_A``); none for a name that says nothing of what it is."""
    if kind:
        return [i for i, o in enumerate(options) if o[2] == kind]
    body = _body(p.name[len(PREFIX) :])
    return [
        i
        for i, (w, c, k) in enumerate(options)
        if body and not k and not w.startswith("-") and _of_body(w, c, body) and not re.search(r"1[nt]?$", w)
    ]


def _partial(trace: Any, found: tuple, options: list, known: tuple) -> tuple[dict, list[str]] | None:
    """Where no reading makes the line hold: each name partly placed (a mass, an angle, a body's)
    is read as the one its working holds for (``mv^2 = 70.15*0.0748^2`` with m the total mass, its
    label ``KE after`` not): the line is then judged in that reading, wrong. A name that says
    nothing of what it is, or working that holds in no reading, stays not read."""
    line, exprs, free = found
    fixed, said = known
    allowed = [_partly(p, _kind(p, exprs), options) for p in free]
    if not all(allowed) or math.prod(len(a) for a in allowed) > MAX_READINGS:
        return None
    nums = _distinct(trace, options, trace.truth)
    combos = _combos([[i for i in a if nums[i] is not None] for a in allowed], options)
    if len(combos) == 1:  # the one reading the names allow ("tan q = 0.5", q the one angle given)
        best = combos[0]
    else:
        funcs = _sides(trace, exprs[1:], free, trace.truth) if len(exprs) >= 3 else None
        offs = _offs(funcs, combos, nums) if funcs is not None else []
        if not offs or min(offs) > LOOSE:
            return None
        best = combos[offs.index(min(offs))]
    memory = trace.__dict__["by_value"]
    mapping = {**fixed, **{p: options[i][1] for p, i in zip(free, best, strict=True)}}
    for p, i in zip(free, best, strict=True):
        memory[_key(p, exprs)] = (options[i][0], options[i][1], line.number)
        said.append(
            f"{p.name[len(PREFIX) :]} read as {_in_words(options[i][0], trace.ctx.problem)}, the one its working holds for"
        )
    return mapping, said
