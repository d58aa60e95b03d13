"""Names known by what they are, not by inference: a name set equal to a number with a unit
(``m = 47/32.2 = 1.4596 slug``, ``$m = 0.150$ kg puck``, ``J = 9.10 lb.s``) or declared in words
as a mass, an impulse or an energy (``impulse J on B``, ``m is the mass of each disc``) is that
kind of quantity, never a velocity.

Where its value is the problem's value of one quantity of that kind (the mass 0.150 kg is the
puck's), the name stands for it, as if declared; where it is not, only quantities of that kind
may be inferred for it (:func:`.inference._infer`). A velocity's unit says nothing new (names of
velocities are inferred anyway), so only masses, impulses and energies are kinds here.
"""

from __future__ import annotations

import math
import re

import sympy

from derive.checking.centremass import common_velocity, moving_together
from derive.checking.context import Context
from derive.checking.numeric import number_of
from derive.checking.spellings import impulse_name
from derive.mathtext.notation import student
from derive.mathtext.reader import Relation
from derive.mathtext.units import in_si
from derive.problem.expr import ParseError, parse
from derive.problem.units import ENERGY, IMPULSE, MASS, VELOCITY, Dim

#: Units as students type them, by the kind of quantity they measure (longest first).
_UNITS: tuple[tuple[str, Dim], ...] = (
    (r"kg\s*[·.*]?\s*m\s*(?:/\s*s|s\^?\{?-1\}?)", IMPULSE),
    (r"(?:N|lb|lbf)\s*[·.*]?\s*s(?:ec)?", IMPULSE),
    (r"ft\s*[·.*-]?\s*lbf?|kJ|J|joules?", ENERGY),
    (r"(?:m|ft|cm|km|mi)\s*(?:/\s*(?:s|h|hr|sec)|s\^?\{?-1\}?)|mph|km/h", VELOCITY),
    (r"kg|kilograms?|grams?|g|slugs?|lbm|tonnes?", MASS),
)
_UNIT = re.compile(r"|".join(f"(?:{u})" for u, _ in _UNITS))
#: LaTeX around a unit: ``\ \mathrm{m\,s^{-1}}``, ``\text{ kg}``, a closing ``$``.
_WRAP = re.compile(r"\\(?:mathrm|text|textrm|mbox|operatorname)\s*\{|\\[,;: ]|\\quad|[${}~]")
#: Words naming a kind of quantity, before the name (``impulse J``) or after it (``J is the impulse``).
_KIND_WORDS: tuple[tuple[str, Dim], ...] = (
    (r"impulse", IMPULSE),
    (r"(?:kinetic\s+)?energy|KE|K\.E\.", ENERGY),
    (r"mass(?:es)?", MASS),
)
_NAME = r"\$?([A-Za-z](?:_\{?[A-Za-z0-9]{1,3}\}?)?)\$?"


def _kind_of_unit(text: str) -> tuple[Dim, str] | None:
    """The kind of quantity the unit at the start of ``text`` measures, and the unit as typed
    (None: no unit there)."""
    if not re.match(r"\s|\\[ ,;:]|\\(?:text|mathrm|mbox)|\$|~", text):
        return None  # glued to its number: 2g is 2 times g, not 2 grams
    text = _WRAP.sub(" ", text).strip()
    m = _UNIT.match(text)
    if m is None or (m.end() < len(text) and text[m.end()].isalpha()):
        return None
    for pattern, dim in _UNITS:
        if re.fullmatch(pattern, m.group(0)):
            return dim, m.group(0)
    return None


def unit_of(r: Relation) -> tuple[Dim, str] | None:
    """The kind and unit of the number a relation ends with: in its last side (``9.10 lb.s``) or
    after it on the line (``$m = 0.150$ kg puck``)."""
    value = r.sides[-1].strip()
    m = re.match(r"[-+]?\d[\d.]*", value)
    if m is None:
        return None
    found = _kind_of_unit(value[m.end() :]) if value[m.end() :].strip() else None
    if found is None:  # the unit outside the relation as read (or read into it: 20 g as 20/1000)
        at = re.search(rf"(?<![\d.]){re.escape(m.group(0))}(?![\d])", r.written)
        found = _kind_of_unit(r.written[at.end() :]) if at else None
    for w in re.finditer(r"(?<![\d.])(\d[\d.]*)\s+(g|cm|mm)\b", r.written) if found is None else ():
        if in_si(f"{w[1]} {w[2]}") == m.group(0):
            return _kind_of_unit(" " + r.written[w.start(2) :])  # 20 g read as 0.020: its unit as written
    return found


def _in_words(text: str) -> dict[str, Dim]:
    """Names a line declares in words as a kind: ``impulse J on B``, ``the mass m``, ``let m be the
    mass``, ``J is the impulse``, ``m = mass of each disc``."""
    plain = re.sub(r"\\[()]|\\text\{|[{}]", " ", text)
    out: dict[str, Dim] = {}
    for words, dim in _KIND_WORDS:
        before = rf"\b(?:{words})\s+(?:of\s+(?:each|the\s+\w+|[AB])\s+)?(?:is\s+|as\s+|be\s+)?{_NAME}(?![\w'(])"
        after = rf"(?<![\w\\]){_NAME}\s*(?:is|be|=|denotes?|for|as)\s+(?:the\s+)?(?:\w+\s+)?(?:{words})\b"
        for pattern in (before, after):
            for m in re.finditer(pattern, plain, re.I):
                name = m.group(1).replace("{", "").replace("}", "")
                if name not in ("a", "i", "s", "A", "B"):  # words and the bodies' letters
                    out.setdefault(name, dim)
    return out


def kind_of(what: str) -> Dim:
    """The kind of one of :func:`candidates`' quantities, by derive's name for it."""
    if what in ("J_n", "-J_n"):
        return IMPULSE
    if what in ("T_1", "T_2", "T_lost"):
        return ENERGY
    return MASS if what in ("m_A", "m_B") else VELOCITY


def kinds(relations: tuple[Relation, ...], text: str, reserved: set[str]) -> dict[str, Dim]:
    """Each name of the student's own whose kind the text states: by the unit after its value
    (``m = 1.4596 slug``) or in words (``impulse J``). ``reserved`` are names with a meaning
    already (the problem's, derive's)."""
    out: dict[str, Dim] = {}
    for line in text.splitlines():
        for name, dim in _in_words(line).items():
            out.setdefault(name, dim)
    for r in relations:
        name = r.sides[0].strip()
        if len(r.sides) < 2 or not re.fullmatch(r"[A-Za-z]\w{0,4}", name):
            continue
        unit = unit_of(r)
        if unit is not None:
            out[name] = unit[0]
    return {k: v for k, v in out.items() if k not in reserved}


#: The letters students name a mass or an impulse with: a number set to them is that kind even
#: without a unit (``M = 70.0``, ``J = 5.97``).
_LETTERS = ((re.compile(r"[mM](?:_?\w{1,3})?"), MASS), (re.compile(r"[IJ](?:_?\w{1,2})?"), IMPULSE))


#: A side that is a number, perhaps times a power of ten, and a unit apart from it (``70.0``, ``1.2 kg``).
_NUMBER_SIDE = re.compile(
    r"[-+]?\s*\d[\d.]*(?:\s*(?:×|x|\*|\\times|\\cdot)\s*10\s*\^?\s*\{?[-−]?\d+\}?)?(?:\s+[A-Za-z\\][^=+*]*)?"
)


def by_letter(relations: tuple[Relation, ...], reserved: set[str]) -> dict[str, Dim]:
    """The names set to a number whose letter says its kind (``m``, ``M_2`` a mass; ``J``, ``I`` an
    impulse), a kind that a unit or words after it may still overrule (:func:`kinds`)."""
    out: dict[str, Dim] = {}
    for r in relations:
        name = impulse_name(r.sides[0]) or r.sides[0].strip()
        if len(r.sides) < 2 or name in reserved or not _NUMBER_SIDE.fullmatch(r.sides[-1].strip()):
            continue  # "mu = -mv + 2m(eu - v) = 2meu - 3mv": letters, not a mass's number
        if name.startswith(("impulse", "dp")) and impulse_name(r.sides[0]):
            out[name] = IMPULSE  # "impulse on the ball = 11.2 N s"
        for pattern, dim in _LETTERS:
            if pattern.fullmatch(name):
                out[name] = dim
    return out


def quantities(ctx: Context) -> dict[Dim, list[tuple[str, sympy.Expr]]]:
    """The problem's quantities of each kind a name may stand for (derive's name, symbol)."""
    model = ctx.model
    derived = {k: v[0] for k, v in ctx.derived().items()}
    out: dict[Dim, list[tuple[str, sympy.Expr]]] = {
        MASS: [("m_A", model.m_A), ("m_B", model.m_B)] if not ctx.problem.fixed_B else [("m_A", model.m_A)],
        ENERGY: [(n, derived[n]) for n in ("T_1", "T_2", "T_lost") if n in derived],
        IMPULSE: [(n, derived[n]) for n in ("J_n",) if n in derived],
    }
    if "J_n" in derived:
        out[IMPULSE].append(("-J_n", -derived["J_n"]))
    return out


def by_value(
    ctx: Context, relations: tuple[Relation, ...], found: dict[str, Dim], values: tuple[dict, dict]
) -> dict[str, sympy.Expr]:
    """The names of ``found`` (name -> kind) set equal to a number that is the problem's value of
    one quantity of their kind (to the figures written): name -> that quantity. ``values`` (the
    point of the givens, the true values of the unknowns) puts the numbers in."""
    out: dict[str, sympy.Expr] = {}
    table = quantities(ctx)
    asked = {g.name for g in ctx.problem.givens if g.unknown}
    for k, r in enumerate(relations):
        name = impulse_name(r.sides[0]) or r.sides[0].strip()
        dim = found.get(name)
        if (
            dim is None
            or name in out
            or len(r.sides) < 2
            or (_defined_by_expression(r.sides[1:-1]) and not _the_impulse(name, r.sides[1:-1], table.get(dim, [])))
        ):
            continue  # "mu = m1 m2/(m1 + m2) = 0.1497 kg": a name defined by its expression
        solved = _met_before(name, relations[:k])  # "6M = 7200 -> M = 1200 kg": a result, not a given restated
        m = re.match(r"([-+]?)(\d+)\.?(\d*)", r.sides[-1].strip())
        try:  # "20/1000": 20 g read in kg
            value = number_of(parse(student(r.sides[-1]), {}).expr) if m else None
        except ParseError:
            value = None
        if m is None or value is None or float(m.group(0)) == 0:
            if (
                m is not None
                and value == 0
                and _says_impulse(name)
                and (only := _only_one(table.get(dim, []))) is not None
            ):
                out[name] = only  # "impulse = 0": the one impulse, its sign no matter
            continue
        written = value.real
        if (on := _body_impulse(name, table.get(dim, []))) is not None:
            out[name] = on  # "impulse on A = 32 N s": A's, whatever its sign (a wrong sign is a slip)
            continue
        half = (0.5 * 10 ** -len(m.group(3)) + 1e-12) * abs(written / float(m.group(0)))  # to the figures written
        hits = []
        for what, e in table.get(dim, []):
            if solved and what in ("m_A", "m_B") and what not in asked:
                continue  # a mass solved for is the one asked for, even where a slip makes it the other's
            x = number_of(ctx.in_unknowns(e).xreplace(values[0]).xreplace(values[1]))
            if x is not None and abs(x.imag) < 1e-12 and abs(x.real - written) <= 1.01 * half:
                hits.append(e)
        if hits:
            out[name] = hits[0]  # equal masses: either, and the first is A's
        elif not solved and (copied := _copied_mass(ctx, table.get(dim, []), written, values, asked)) is not None:
            out[name] = copied  # "m = 20 g = 0.2 kg": the bullet's mass copied wrongly (its line's slip)
        elif _says_impulse(name) and (only := _only_one(table.get(dim, []))) is not None:  # "J = 0.238", worked wrongly
            x = number_of(ctx.in_unknowns(only).xreplace(values[0]).xreplace(values[1]))
            out[name] = -only if x is not None and abs(x.imag) < 1e-12 and x.real * written < 0 else only
    return out


def _copied_mass(
    ctx: Context, table: list[tuple[str, sympy.Expr]], written: float, values: tuple[dict, dict], asked: set[str]
) -> sympy.Expr | None:
    """The one given mass ``written`` is a copy of, wrongly made: the same digits with the point
    moved (a unit turned wrongly, 20 g as 0.2 kg) or in another order (0.51 for 0.15); None where
    no given mass, or more than one, is so like it. The name is that mass's: the line that sets it
    is the slip, and the lines after it carried, as a teacher reads "m = 0.2 kg" for the bullet."""
    found = []
    for what, e in table:
        x = number_of(ctx.in_unknowns(e).xreplace(values[0]).xreplace(values[1])) if what in ("m_A", "m_B") else None
        if x is not None and what not in asked and abs(x.imag) < 1e-12 and x.real and _a_copy(written, x.real):
            found.append(e)
    return found[0] if len(found) == 1 else None


def _a_copy(written: float, true: float) -> bool:
    """Whether ``written`` is ``true`` with its point moved (by one to three places) or its digits
    in another order (two digits or more), and not ``true`` itself."""
    if written <= 0 or true <= 0 or abs(written - true) <= 1e-9 * true:
        return False
    k = round(math.log10(written / true))
    if 1 <= abs(k) <= 3 and abs(written / true / 10**k - 1) < 1e-9:
        return True
    digits = [re.sub(r"[^0-9]", "", f"{x:.6f}").strip("0") for x in (written, true)]
    return len(digits[1]) >= 2 and sorted(digits[0]) == sorted(digits[1])


def _defined_by_expression(middle: tuple[str, ...]) -> bool:
    """Whether a side between the name and its number has letters in it (``m1 m2/(m1 + m2)``)."""
    return any(re.search(r"[A-Za-z]", x) and not impulse_name(x) for x in middle)


def _the_impulse(name: str, middle: tuple[str, ...], impulses: list[tuple[str, sympy.Expr]]) -> bool:
    """Whether ``name`` says the impulse (``J``, ``I``, ``J_n``, ``impulse``; not a component ``J_y``)
    where the problem has only one, defined as a change in momentum (``J = m Δv = 47(6.235) = 293``):
    named by its letter whatever its number."""
    plain = re.fullmatch(r"[IJ](?:_n)?|impulse\w*|dp\w*", name) is not None
    change = any(re.search(r"Δ|\\?Delta|\bchange\b|\bd[pv]\b", x) or _after_less_before(x) for x in middle)
    return plain and change and _says_impulse(name) and _only_one(impulses) is not None


def _body_impulse(name: str, impulses: list[tuple[str, sympy.Expr]]) -> sympy.Expr | None:
    """The impulse on the body a name says (``impulse_A``, ``dp_B`` from "impulse on A", "change in
    momentum of B"): on B it is derive's J_n, on A -J_n (n from A toward B); None for no body."""
    m = re.fullmatch(r"(?:impulse|dp)_([AB])", name)
    only = _only_one(impulses) if m else None
    if only is None:
        return None
    return only if m[1] == "B" else -only


def _says_impulse(name: str) -> bool:
    """Whether the name's letter or word says it is the impulse (``J``, ``I_n``, ``impulse``, ``dp``),
    not a quantity of the same unit a student names otherwise (``P``, a total momentum)."""
    return bool(_LETTERS[1][0].fullmatch(name)) or name.startswith(("impulse", "dp"))


def _only_one(quantities: list[tuple[str, sympy.Expr]]) -> sympy.Expr | None:
    """The one quantity of a kind, up to its sign (the impulse ``J_n`` and ``-J_n``), or None
    where the kind has more than one (two masses, three energies)."""
    first = {what.lstrip("-") for what, _e in quantities}
    if len(first) != 1:
        return None
    return next(e for what, e in quantities if not what.startswith("-"))


def _met_before(name: str, earlier: tuple[Relation, ...]) -> bool:
    """Whether ``name`` is written in one of the ``earlier`` relations among other terms
    (``(1200 + M) x 6``): a value it is set to afterwards is what the student solved for."""
    word = re.compile(rf"(?<![\w\\]){re.escape(name)}(?!\w)")
    return any(len(r.sides) >= 2 and any(word.search(s) for s in r.sides) for r in earlier)


def of_kind(dim: Dim | None, what: str) -> bool:
    """Whether a name of the kind ``dim`` (None: not stated) may stand for the candidate ``what``:
    a stated kind takes its own only; a name of no stated kind is no mass and no energy but the loss."""
    if dim is None:
        return kind_of(what) != MASS and what not in ("T_1", "T_2")
    return kind_of(what) == dim


def candidates(ctx: Context, truth: dict, dims: set[Dim] = frozenset()) -> list[tuple[str, sympy.Expr]]:
    """What an unknown name may stand for: a velocity after the impact, the common velocity,
    an unknown given, the energy lost, the impulse; with either sign for velocities; and, for
    names stated to be a mass or an energy (``dims``), the masses and energies."""
    U = list(truth)
    out = [(u.name, u) for u in U]
    nm = ctx.model.nm
    if any(g.name == "e" and g.value == 0 for g in ctx.problem.givens) and not ctx.problem.fixed_B:
        out.insert(0, ("the common velocity after", moving_together(ctx, nm.A2n, nm.B2n)))  # e = 0: one velocity
    out.append(("the common velocity", common_velocity(ctx)))
    derived = ctx.derived()
    out += [(n, derived[n][0]) for n in ("T_lost", "J_n") if n in derived]
    out += [("-J_n", -derived["J_n"][0])] if "J_n" in derived else []
    if ctx.problem.oblique:  # "V cos β = U cos α": a speed after, its components written from it
        bodies = "A" if ctx.problem.fixed_B else "AB"
        out += [(f"v_{b}2", derived[f"v_{b}2"][0]) for b in bodies if f"v_{b}2" in derived]
    out += [(f"-{u.name}", -u) for u in U if u.name.startswith("v_")]
    out += [(g.name, g.symbol) for g in ctx.problem.givens if g.value is None and not g.unknown and g.dim == VELOCITY]
    zeros = ctx.model.zeros
    out += [
        (c.name, c) for c in (nm.A1n, nm.B1n, nm.A1t, nm.B1t) if c is not None and c not in truth and c not in zeros
    ]
    table = quantities(ctx)
    out += [c for d in dims & {MASS, ENERGY} for c in table[d] if c not in out]
    zero = {g.symbol for g in ctx.problem.givens if g.value is not None and g.value == 0}
    return [(w, c) for w, c in out if c not in zero]  # B at rest: 0, which any product of it equals


def _after_less_before(side: str) -> bool:
    """Whether ``side`` is a mass times a velocity after less one before (``m(v - u)``,
    ``m(v_n - u_n)``, ``m_A(v_2 - v_1)``): a change in momentum written out."""
    return bool(re.search(r"\(\s*(?:v[\w']*\s*-\s*u[\w']*|[A-Za-z]\w*2\s*-\s*[A-Za-z]\w*1)\s*\)", side))
