"""A chain's names declared in words, and a given copied wrongly into a chain's line.

"p = A after, q = B after", "let x and y be the velocities of A and B after the first
impact", "w = velocity of B after" name an impact stage's velocities, which the chain may
not name itself (A's velocity after the first impact): each is known as the chain's
expression of it (:func:`declared`). A line that holds once a number in it is put back as
a given (``m(9) = mp + mq`` where A's speed is 7) copies that given wrongly; the chain
solved again with the given as copied is then the student's own values, carried through
the later lines and stages (:func:`copied`), so one slip in a chain is one mistake.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import replace

import sympy

from derive.checking import copiedsums
from derive.checking.bodylists import written_out
from derive.checking.context import Context
from derive.checking.movenames import moves_after
from derive.checking.naming import PREFIX, Open, read_side, rewrite
from derive.checking.numeric import shown
from derive.checking.report import Item
from derive.checking.restated import stated, written_number
from derive.checking.valuenames import unit_of
from derive.errors import InputError
from derive.problem.expr import ParseError
from derive.problem.units import VELOCITY

_NAME = r"([A-Za-z](?:_\{?\w{1,3}\}?)?)"
_WHEN = r"(?:just\s+|immediately\s+)?(after|before)\b"
_ONE = re.compile(
    rf"(?<![\w\\]){_NAME}\s*(?:=|:|is|be|for|denotes?|represents?)\s*(?:the\s+)?(?:(?:final\s+)?(?:speed|velocity)\s+of\s+)?"
    rf"(?:particle\s+|sphere\s+|ball\s+)?([A-Z])(?:'s|’s)?\s+(?:(?:speed|velocity)\s+)?{_WHEN}"
)
_PAIR = re.compile(
    rf"(?<![\w\\]){_NAME}\s*(?:,|and)\s*{_NAME}\s+(?:be|are|=|for|denote|represent)\s+(?:the\s+)?(?:final\s+)?"
    rf"(?:speeds?|velocit(?:y|ies))\s+of\s+(?:particles\s+|spheres\s+|balls\s+)?([A-Z])\s*(?:,|and|&)\s*([A-Z])\s+{_WHEN}"
)
#: The same the other way round: "the velocities of A and B after the impact be x and y",
#: "the speed of B after it hits the wall is w", "A's velocity after = p".
_BEFORE_NAME = r"[^=;.]{0,40}?\s(?:be|are|is|=|:)\s*"
_PAIR_BACK = re.compile(
    rf"(?:speeds?|velocit(?:y|ies))\s+of\s+(?:particles\s+|spheres\s+|balls\s+)?([A-Z])\s*(?:,|and|&)\s*([A-Z])\s+"
    rf"{_WHEN}{_BEFORE_NAME}{_NAME}\s*(?:,|and)\s*{_NAME}(?![\w(])"
)
_ONE_BACK = re.compile(
    rf"(?:(?:speed|velocity)\s+of\s+(?:particle\s+|sphere\s+|ball\s+)?([A-Z])|\b([A-Z])(?:'s|’s)\s+(speed|velocity))\s+"
    rf"{_WHEN}{_BEFORE_NAME}{_NAME}(?![\w(.])"
)
_ORDINAL = re.compile(r"\b(first|second|third|1st|2nd|3rd)\s+(?:impact|collision)", re.I)
_SURFACE = re.compile(r"\b(wall|ground|floor|cushion|barrier|plane)\b")
_ORDINALS = {"first": 0, "1st": 0, "second": 1, "2nd": 1, "third": 2, "3rd": 2}

#: A declared name: its symbol (the student's own) -> the chain's expression of what it stands for.
Declared = dict[sympy.Symbol, sympy.Expr]


def declared_in(ctx: Context, text: str, read: list) -> tuple[Declared, list]:
    """The names ``text`` declares in words (:func:`declared`) or by an impact's energy
    (:func:`energies`), and the relations read without those that declare them (``p = A after``
    is a name, not a relation to judge)."""
    said, lines = declared(ctx, list(enumerate(written_out(ctx, text).splitlines(), 1)))  # "After: A v1, B v2" too
    read = [x for x in read if not (x[0].line in lines and _declaring(x[2], said))]
    read = [x for x in read if not restated(ctx, x, read, {})]
    return {**energies(ctx, read), **said}, read


def _declaring(exprs: list, said: Declared) -> bool:
    """Whether a relation on a line of declarations is one (``p = A after``), not a value said
    for a name it declares (``After: B w1, C w2 = 4``: w2 = 4)."""
    return len(exprs) == 2 and bool(set(exprs) & set(said)) and not any(x.is_number for x in exprs)


#: Words of a line of givens after a speed (``u = 21 m/s down``, ``Given: …``): the given's own; the sign
#: convention (``Positive: A's way, so u_B = -1.5``): a given's velocity with the convention's sign.
_GIVEN_WORDS = re.compile(
    r"(?:\b(?:given|data|thrown|projected|released|initial\w*|(?:down|up)(?:wards?)?|vertically|positive)|\+ve)\b", re.I
)


def restated(ctx: Context, x: tuple, read: list, said: Declared) -> bool:
    """Whether ``x`` (relation, sides, expressions) restates a given speed on a line of givens before the
    working (``Q5  m = 0.2 kg, u = 5 m/s down, h = 1.6 m``: all of its relations a name set to a
    number, this one with the given's unit or words) in a name the chain has for another quantity:
    its number is a given's (to the figures written, either sign) while the relation, read in the
    chain's names, is false (the chain's ``u`` is the velocity after the bounce). A teacher does not
    mark it; the checker does not judge it. A bare ``v_1 = 5`` (the fall forgotten) is judged. ``said``:
    the names known so far (``(v_B)_1 = 2 m/s ←``, B's velocity before, restates B's given speed)."""
    r, sides, exprs = x
    worked = [y[0].line for y in read if not stated(y[1])]
    if not stated(sides) or (worked and r.line >= min(worked)) or len(exprs) != 2:
        return False
    unit = unit_of(r)
    if not ((unit is not None and unit[0] == VELOCITY) or _GIVEN_WORDS.search(r.written)):
        return False
    value, half = written_number(sides[1]) or (0.0, 0.0)
    body = re.search(r"(?<=[a-z_{])([A-Z])\}?\d*\s*$", sides[0])  # u_B restates B's speed, never A's
    values = [  # a given speed (``e = 0.7`` for a wall's e is a stage's e, which the chain judges)
        abs(float(g.value))
        for g in ctx.problem.givens
        if g.value is not None and g.value.is_number and g.dim == VELOCITY
        if body is None or g.name.rstrip("0123456789n").endswith(body[1])
    ]
    if not any(abs(abs(value) - v) <= half for v in values):
        return False
    chain = {str(k): v for k, v in ctx.solution.values.items()}
    own = exprs[0].xreplace(said)
    own = own.xreplace({s: chain[s.name] for s in own.free_symbols if s.name in chain})
    try:
        return not own.free_symbols and abs(float(own) - float(exprs[1])) > half
    except (TypeError, ValueError):
        return False


def declared(ctx: Context, lines: list[tuple[int, str]]) -> tuple[Declared, set[int]]:
    """The names the lines declare in words, each as the chain's expression of the impact
    stage's velocity it names, and the numbers of the lines that declare them. The stage is
    the one the line names by its order ("after the second impact"), else the first impact
    whose bodies are those named, from the stage of the declaration before it on."""
    impacts = [st for st in getattr(ctx.solution, "stages", ()) if getattr(st, "part", None) is not None]
    out: Declared = {}
    where: set[int] = set()
    last = 0
    for number, text in lines:
        plain = re.sub(r"\$|\\[()]|[{}]|\\[A-Za-z]+(?=\{)", "", text)  # \textbf{Second impact}: the words
        found = [((m[1], m[3]), (m[2], m[4]), m[5], "speed" in m[0]) for m in _PAIR.finditer(plain)]
        found += [((m[1], m[2]), None, m[3], "speed" in m[0]) for m in _ONE.finditer(plain)]
        found += [((m[4], m[1]), (m[5], m[2]), m[3], "speed" in m[0]) for m in _PAIR_BACK.finditer(plain)]
        found += [((m[5], m[1] or m[2]), None, m[4], "speed" in m[0]) for m in _ONE_BACK.finditer(plain)]
        found += [((name, body), None, "after", speed) for name, body, speed in moves_after(plain)]
        if not found:
            continue
        bodies = {f[0][1] for f in found} | {f[1][1] for f in found if f[1]}
        k = _stage(impacts, bodies, plain, last)
        if k is None:
            continue
        last = k
        for first, second, when, speed in found:
            for name, body in (first, second) if second else (first,):
                x = _velocity(ctx, impacts[k], body, when.lower() == "after")
                if x is not None:
                    x = sympy.Abs(x) if speed else x  # a speed is the velocity's size
                    out.setdefault(sympy.Symbol(PREFIX + name.replace("{", "").replace("}", "")), x)
                    where.add(number)
    return out, where


def _stage(impacts: list, bodies: set[str], text: str, last: int) -> int | None:
    """The index of the impact stage a declaration names (see :func:`declared`)."""
    m = _ORDINAL.search(text)
    if m and _ORDINALS[m.group(1).lower()] < len(impacts):
        return _ORDINALS[m.group(1).lower()]
    fits = [k for k, st in enumerate(impacts) if bodies <= set(st.part.problem.labels)]
    said = set(_SURFACE.findall(text.lower()))  # "after it hits the wall": the stage with the wall
    fits = [k for k in fits if said & set(_SURFACE.findall(str(impacts[k].title).lower()))] or fits
    later = [k for k in fits if k >= last]
    return (later or fits or [None])[0]


def _velocity(ctx: Context, stage, body: str, after: bool) -> sympy.Expr | None:
    """The chain's expression of ``body``'s velocity in an impact stage, after or before."""
    part = stage.part
    labels = part.problem.labels
    if body not in labels:
        return None
    return stage_result(ctx, stage, f"v_{'AB'[labels.index(body)]}{'2' if after else '1'}")


def stage_result(ctx: Context, stage, key: str) -> sympy.Expr | None:
    """The chain's expression of an impact stage's result or given ``key`` (``v_A2``, ``T_1``)."""
    part = stage.part
    chain = {str(s): s for s in ctx.solution.values}
    inner = {}
    for g in part.problem.givens:
        outer = g.definition if g.definition is not None else chain.get(g.name, g.value)
        if outer is not None:
            inner[g.name] = outer
    r = part.results.get(key)
    x = r.closed if r is not None else inner.get(key)
    if x is None:
        return None
    x = x.xreplace({s: inner[s.name] for s in x.free_symbols if s.name in inner})
    return x.xreplace({s: chain[s.name] for s in x.free_symbols if s.name in chain})


#: The student's names of an impact's kinetic energies (``KE before``, ``KE after``, ``KE lost``
#: are read as T_1, T_2, T_lost already). ``KE_i`` and ``KE_f`` are not among them: in a chain
#: they are as often the start and end of a later stage's energy balance (the spring's).
_ENERGIES = {"T_1": "T_1", "T_2": "T_2", "T_lost": "T_lost"}
#: The same energies named in words (``KE just after``, ``kinetic energy after the collision``,
#: ``KE immediately before``, ``energy lost in the impact``), read as one name of words.
_ENERGY_WORDS = re.compile(
    r"(?:KE|K_?E|kinetic_energy|E_?k|energy)_(?:(?:just|immediately|right)_)?"
    r"(?:(before|initially|initial)|(after|finally|final)|(lost|loss))(?:_(?:the_)?\w+)?",
    re.I,
)


#: A kinetic energy's letter primed (``K'``, ``KE'``, ``E_k'``, read ``K_p``, ``E_kp``): the energy just after.
_PRIMED = re.compile(r"(?:K_?E|K|E_?k)_?p")


def energy_key(name: str) -> str | None:
    """derive's name of an impact's energy a student's name says (``T_2`` for ``KE just after``)."""
    key = "T_2" if _PRIMED.fullmatch(name) else _ENERGIES.get(name)
    m = _ENERGY_WORDS.fullmatch(name) if key is None else None
    if m is not None:
        key = "T_1" if m[1] else "T_2" if m[2] else "T_lost"
    return key


def energies(ctx: Context, read: list) -> Declared:
    """The kinetic energies before and after the impact, and the energy lost, where the chain
    has one impact and the student names them (``KE before``, ``KE after``, ``KE lost``): the
    impact's own values, as a single impact's are, so a slip in them is found there."""
    impacts = [st for st in getattr(ctx.solution, "stages", ()) if getattr(st, "part", None) is not None]
    used = {s for _r, _sides, exprs in read for x in exprs for s in x.free_symbols if s.name.startswith(PREFIX)}
    out: Declared = {}
    for p in used if len(impacts) == 1 else ():
        key = energy_key(p.name[len(PREFIX) :])
        x = _chain_energy(ctx, key) or stage_result(ctx, impacts[0], key) if key else None
        if x is not None:
            out[p] = plain(x)
    return out


def side_or_words(side: str, names: Open) -> sympy.Expr:
    """A side as written, in the chain's names; a name in words (``KE just after``) as one name of
    the student's own, as :func:`.chainlines._read` reads it (a side neither raises ParseError)."""
    try:
        return read_side(rewrite(side, set(names.known)), names, False, False)
    except ParseError:
        said = re.fullmatch(r"\s*([A-Za-z]{2,}(?:\s+[A-Za-z]{2,}){0,5})\s*", side)
        if said is None:
            raise
        return sympy.Symbol(PREFIX + "_".join(said.group(1).split()))


def yes_no(ctx: Context) -> set[sympy.Symbol]:
    """The chain's answers that are a yes or a no (``again`` = 1: do they collide again?), kept as
    1 and 0 with no unit: no quantity a student's name stands for."""
    results = (getattr(ctx.solution, "results", {}) or {}).items()
    return {sympy.Symbol(n) for n, r in results if r.unit == "" and r.value in (0, 1) and not n.startswith("e")}


def _chain_energy(ctx: Context, key: str) -> sympy.Symbol | None:
    """The chain's own value of an impact's energy (``T_after`` for T_2), where it has one: the
    student's wrong value of it is then known, carried, from their wrong velocities."""
    ends = {"T_1": ("before", "1"), "T_2": ("after", "2"), "T_lost": ("lost", "loss")}[key]
    found = [s for s in ctx.solution.values if re.fullmatch(rf"(?:T|KE)_?(?:{'|'.join(ends)})", str(s))]
    return sympy.Symbol(str(found[0])) if len(found) == 1 else None


#: The A-level habit (u before, v after; a prime after) in a chain's one impact.
def plain(x: sympy.Expr) -> sympy.Expr:
    """``x`` in symbols of the chain's names with no assumptions, as the chain's lines are read."""
    return x.xreplace({s: sympy.Symbol(s.name) for s in x.free_symbols})


def at(x: sympy.Expr, values: dict) -> sympy.Expr:
    """``x`` with the chain's values put in (by name: a stage's symbols may differ in assumptions)."""
    by_name = {str(k): v for k, v in values.items()}
    return x.xreplace({s: by_name[s.name] for s in x.free_symbols if s.name in by_name})


#: How a side is read again in the chain's names, and whether sides read so hold for the problem.
Reread = Callable[[str], sympy.Expr]
Holds = Callable[[tuple[str, ...], list[sympy.Expr]], bool]


def _stated_as(name: str, n: sympy.Rational, givens: list, reread: Reread, holds: Holds):
    """The one given whose value, written for ``n``, makes ``name = n`` hold: a name the habit reads
    (``(v_B)_2 = 2.6`` for B's 2.9 m/s after, the chain's ``s_B``) set alone to a given's number
    copied wrongly, the line stating data, not a value worked out; None where not exactly one."""
    fits = [g for g in givens if n != abs(g.value) and holds((name, f"{float(g.value):.6f}"), [reread(name), g.value])]
    return fits[0] if len(fits) == 1 and n * fits[0].value > 0 else None


def copied(ctx: Context, sides: tuple[str, ...], reread: Reread, holds: Holds) -> tuple[str, dict] | None:
    """A given copied wrongly into a line of working (a number that, put back as the given,
    makes the line hold; not the value a line works out, ``v = 9``): the words of the slip,
    and the chain's values solved again with the given as copied (None where it is not so)."""
    chain = ctx.solution.problem
    givens = [g for g in chain.givens if not g.unknown and g.value is not None and g.value.is_Rational and g.value]
    written = {abs(g.value) for g in givens}
    if len(sides) == 2 and copiedsums.NUMBER.fullmatch(sides[1].strip()):  # ``e = 0.6`` where the problem gives e = 0.4
        try:
            left, n = reread(sides[0]), sympy.Rational(sides[1].strip())
        except (ParseError, ValueError, TypeError, ArithmeticError, InputError):
            return None  # "down +ve, u = 21": a side that is not a quantity
        g = next(
            (g for g in givens if getattr(left, "name", None) == g.name and n != g.value and n * g.value > 0), None
        ) or _stated_as(sides[0], n, givens, reread, holds)
        world = copiedsums.solved_with(chain, g.name, n) if g is not None else None
        if world is not None:
            return (
                f": a given is copied wrongly: the problem gives {g.name} = {shown(g.value)}, not {sides[1].strip()}.",
                world,
            )
    for i, side in enumerate(sides):
        others = [t for k, t in enumerate(sides) if k != i]
        if copiedsums.NUMBER.fullmatch(side.strip()) and (
            len(sides) > 2 or re.fullmatch(r"\s*[A-Za-z]\w*\s*", others[0])
        ):
            continue  # ``v = 9``, ``3 + 4 = 9``: a value worked out, not a given copied into working
        for token in dict.fromkeys(copiedsums.NUMBER.findall(side)):
            n = sympy.Rational(token)
            if n in written or n == 0:
                continue
            for g in givens:
                fixed = copiedsums.put_back(tuple(sides), i, token, str(abs(g.value)), written)  # in a total too
                try:
                    exprs = [reread(s) for s in fixed]
                except (ParseError, ValueError, TypeError, ArithmeticError, InputError):
                    continue
                if not holds(tuple(fixed), exprs):
                    continue
                world = copiedsums.solved_with(chain, g.name, n if g.value > 0 else -n)
                if world is not None:
                    return (
                        f": a given is copied wrongly: the problem gives {g.name} = {shown(g.value)}, not {token}.",
                        world,
                    )
    return None


def named_copied(ctx: Context, item: Item, sides, reread: Reread, holds: Holds, own: dict, said: Declared) -> Item:
    """The first slip, where it is a given copied wrongly into the working: named so, and the
    chain solved again with the given as copied kept in ``own`` as the student's own values
    (the names declared in words too), for the lines and stages after it. A line that works on
    from the copied number (``v^2 = 21^2 + 2(9.8)(30) = 1029``) is named by its first two sides."""
    found = copied(ctx, tuple(sides), reread, holds)
    found = copied(ctx, tuple(sides[:2]), reread, holds) if found is None and len(sides) > 2 else found
    if found is None:
        return item
    words, world = found
    own.update({sympy.Symbol(str(k)): v for k, v in world.items()})
    own.update({p: at(x, world) for p, x in said.items()})
    return replace(item, slip="copied_wrong", message=f"{item.message.split(': ')[0]}{words}")


def put_right(side: str, own_defs: dict, values: dict) -> sympy.Expr | None:
    """A side of numbers with each the student worked wrongly (a chain value's, as written on
    its line) put back as its true value; None where it has none, or does not read."""
    text = put_back(side, own_defs, values)
    if text is None:
        return None
    try:
        return read_side(text, Open({}), False, False)
    except (ParseError, ValueError, TypeError):
        return None


def put_back(side: str, own_defs: dict, values: dict) -> str | None:
    """``side`` with each number the student worked wrongly put back as its true value, as
    text (None where it has none): see :func:`put_right`."""
    wrong = {v: values[k] for k, v in own_defs.items() if k in values and v.is_Rational and v != values[k]}
    found = False

    def true(m: re.Match) -> str:
        nonlocal found
        x = sympy.Rational(m.group(0))
        if x not in wrong:
            return m.group(0)
        found = True
        return f"({sympy.N(wrong[x], 15)})"

    text = re.sub(r"(?<=[\d)])\s+[x×]\s+(?=[\d(.])", " * ", side)  # 3.3 x 10.6: x for times
    text = re.sub(r"(?<![\w.])\d+\.\d+", true, text)
    return text if found else None


def aliases(said: Declared, values: dict, givens: set) -> dict[sympy.Symbol, sympy.Symbol]:
    """The declared names that are a value the chain names too (x, A's velocity after the
    first impact, is u_A): found by number, among the chain's results (not its ``givens``)."""
    out = {}
    for p, x in said.items():
        v = sympy.N(at(x, values))
        for k, w in values.items():
            if k not in givens and v.is_number and w.is_number and abs(v - sympy.N(w)) <= 1e-9 * max(1, abs(v)):
                out[p] = k
                break
    return out


def with_declared(stages: list, alias: dict) -> list:
    """Each stage mistake's values (by the chain's names) with the declared names that are
    those values too: a slip written in the student's names is named as in the chain's."""
    return [(name, {**given, **{p: given[k] for p, k in alias.items() if k in given}}) for name, given in stages]


def own_solved(
    ctx: Context, written: list[list[sympy.Expr]], said: Declared, own: dict, defs: tuple[dict, dict]
) -> None:
    """After a slip in a line with names declared in words: the names solved from the
    student's own relations in them so far (``0.3x + 0.2y = 0.5`` right, ``y - x = 0.8``
    the slip: x = 0.68, y = 1.48), kept as the student's values, and as the values of the
    chain's names they are, for the lines and stages after."""
    alias, values = defs
    unknown = set(said) & set().union(*(x.free_symbols for x in written[-1]))
    if not unknown:
        return
    rest = {k: v for k, v in own.items() if k not in unknown}
    eqs = []
    for exprs in written:  # first side = last, in the names declared alone (the rest as the student has them)
        eq = at((exprs[0] - exprs[-1]).xreplace(rest), values).xreplace(ctx.unit_subs())
        if eq.free_symbols & unknown and eq.free_symbols <= unknown:
            eqs.append(eq)
    try:
        found = sympy.solve(eqs, sorted(unknown, key=str), dict=True)
    except (NotImplementedError, ValueError, TypeError):
        return
    if len(found) != 1 or set(found[0]) != unknown or any(x.free_symbols for x in found[0].values()):
        return
    for p, x in found[0].items():
        own[p] = x
        if p in alias:
            own[alias[p]] = x


def lone_restitution(values: dict) -> dict[str, sympy.Symbol]:
    """``e`` for the chain's one coefficient of restitution where the chain names it otherwise
    (``e_floor``, ``e_wall``): a student writes e for it, and ``e = 6.26/5.24`` is then judged
    as that coefficient (not a name of the student's own); {} where the chain has an ``e`` or
    more than one coefficient."""
    names = [k for k in values if re.fullmatch(r"e_[A-Za-z]\w*", str(k))]
    if any(str(k) == "e" for k in values) or len(names) != 1:
        return {}
    return {"e": names[0]}
