"""Algebra or arithmetic: how a line that rearranges the relation before it went wrong.

A teacher names a slip in working one relation from the one before it by what was done
wrongly. Algebra: a term moved across without its sign changed (``10 + 4 = v`` from
``10 = 4 + v``), the unknown's coefficient lost or doubled (``0.006 = m`` from
``0.006 = 0.25 m``; ``v² = gh`` from ``½v² = gh``), or a letter lost or gained in a term of
what the unknown comes to (``v = u(1 - e²)`` for u(1 - e)). Arithmetic: the unknown's
terms as they were and a number worked wrongly (``v = 5`` from ``10 = 4 + v``; ``5eu`` for
``3(5eu)``). :func:`kind` finds the first three; the rest is :mod:`.slipnames`' arithmetic.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.relations import coefficients, functions_as_letters, proportional
from derive.checking.worlds import NUMBER_SIDE, Pair
from derive.mathtext.notation import student

#: The factors an unknown's term is taken with wrongly: its ½ dropped, or doubled.
FACTORS = (sympy.Integer(2), sympy.Rational(1, 2))


def kind(bad: Pair, held: Pair, U: tuple, pt: dict) -> str:
    """``algebra`` where ``bad`` (false) is ``held`` (true, the relation just before it) with
    one term's sign lost, its unknown's coefficient lost (or ½ dropped or doubled), or a
    letter lost or gained in one term of what the unknown comes to; ``arithmetic`` where a
    whole number's division was not done (:func:`undivided`); "" otherwise."""
    tol = max(bad.tol, 1e-9)
    if undivided(bad, held, U, pt) or divided_wrongly(bad, held, U, pt) or number_negated(bad, held, U, pt):
        return "arithmetic"
    for variant in _variants(held, bad, set(U)):
        if proportional(bad.difference, variant, U, [pt], tol) and termwise(bad.difference, variant, U, pt, tol):
            return "algebra"
    if _letter_lost(bad.difference, held.difference, U):
        return "algebra"
    return ""


def number_negated(bad: Pair, held: Pair, U: tuple, pt: dict) -> bool:
    """Whether ``bad`` is ``held`` with its terms in the unknowns as they were and the number they
    come to written as one number with its sign lost (``20 v = 0.5`` from ``10 = 20 v + 10.5``,
    10 − 10.5 = −0.5): every term treated alike and a number worked wrongly, arithmetic, as the
    teachers of the corpus name it (the same line is also the unknown's term with its sign lost,
    a step no one takes who keeps that term where it was). Only where ``bad`` writes that side as
    one number: the working shown (``20 v = 10.5 − 10``) is a step of its own."""
    unknowns = set(U)
    if not any(NUMBER_SIDE.match(student(s.strip(" $"))) for s in bad.text.split("=")):
        return False
    F = sympy.expand(held.difference.xreplace(pt))
    terms = sympy.Add.make_args(F)
    inside = sum((t for t in terms if t.free_symbols & unknowns), sympy.Integer(0))
    k = F - inside
    if not inside or not k or k.free_symbols or inside.free_symbols - unknowns:
        return False
    return proportional(bad.difference.xreplace(pt), inside - k, U, [pt], max(bad.tol, 1e-9))


def termwise(F: sympy.Expr, G: sympy.Expr, U: tuple, pt: dict, tol: float) -> bool:
    """Whether ``F`` is a number times ``G`` term by term, each term within ``tol`` of its own size
    (:func:`proportional` measures every term against the largest: ``0.0078 = 0.25 m`` is not
    ``0.01 = 0.25 m``, the 0.002 added with its sign lost, though 0.0022 is small beside 0.25; a
    product of numbers worked wrongly, ``0.0400 × 0.050 = 0.00020``, is that, arithmetic)."""
    F, G, U = functions_as_letters(F, G, U)
    cf, cg = coefficients(F.xreplace(pt), U), coefficients(G.xreplace(pt), U)
    if not cf or not cg:
        return True  # not a polynomial in the unknowns: as proportional found it
    key = max(cg, key=lambda m: abs(cg[m]))
    if not cf.get(key):
        return False
    c = cf[key] / cg[key]
    return all(
        abs(cf.get(m, 0) - c * cg.get(m, 0)) <= max(tol, 1e-9) * max(abs(cf.get(m, 0)), abs(c * cg.get(m, 0)))
        for m in set(cf) | set(cg)
    )


def undivided(bad: Pair, held: Pair, U: tuple, pt: dict) -> bool:
    """Whether ``bad`` is ``held`` (``k x = E``, the unknown's term alone on its side, k a whole
    number) with the division by k not done: ``x = E`` (``2q = 7 + 7e`` then ``q = 7(1 + e)``).
    A teacher calls this arithmetic; a ½ dropped (``v² = gh`` from ``½v² = gh``) stays algebra."""
    unknowns = set(U)
    for side, other in ((held.left, held.right), (held.right, held.left)):
        terms = sympy.Add.make_args(sympy.expand(side))
        if len(terms) != 1 or not terms[0].free_symbols & unknowns or other.free_symbols & unknowns:
            continue
        c, rest = terms[0].as_coeff_Mul()
        if not (c.is_Integer and abs(c) >= 2) or rest.free_symbols - unknowns:
            continue
        return proportional(bad.difference, rest - other, U, [pt], max(bad.tol, 1e-9))
    return False


def divided_wrongly(bad: Pair, held: Pair, U: tuple, pt: dict) -> bool:
    """Whether ``bad`` is ``held`` (``c x = k`` as typed: one term in the unknowns, one free of them) solved
    by a division of numbers done wrongly: its sign lost (``v = 0.025`` from ``20 v = −0.5``),
    multiplied instead (``sin²α = 0.4 × 7/16`` from ``(7/16) sin²α = 0.4``) or turned over
    (``e = 5/4`` from ``4 = 5e``). Nothing is moved across in such a step, and the teachers of the
    corpus call it arithmetic, as they call the division not done (:func:`undivided`); the unknown's
    ½ dropped stays algebra (its coefficient lost, :func:`_variants`)."""
    unknowns = set(U)
    terms = sympy.Add.make_args(sympy.expand(held.difference))
    inside = [t for t in terms if t.free_symbols & unknowns]
    if len(terms) != 2 or len(inside) != 1 or written_terms(held.text) != 2:  # ``10 = 20v + 10.5``: three
        return False
    t, k = inside[0], next(x for x in terms if x is not inside[0])
    c, rest = t.as_coeff_Mul()
    if c in (0, 1, -1) or not k or rest.free_symbols - unknowns:
        return False
    tol = max(bad.tol, 1e-9)
    wrong = (c * rest - k, rest + k * c, k * rest + c)  # the sign lost, multiplied, turned over
    return any(proportional(bad.difference, w, U, [pt], tol) or _same_ratio(bad.difference, w, U, pt) for w in wrong)


def _same_ratio(F: sympy.Expr, G: sympy.Expr, U: tuple, pt: dict, tol: float = 1e-3) -> bool:
    """Whether ``F`` is a number times ``G`` at two points of the unknowns (``sin²α − 0.175`` and
    ``sin²α − 7/40``: not polynomials in α, so not :func:`proportional`'s)."""
    ratios = []
    for a in (0.3, 0.7):
        at = {**pt, **{u: sympy.Float(a + i / 10) for i, u in enumerate(U)}}
        try:
            f, g = complex(F.xreplace(at).evalf()), complex(G.xreplace(at).evalf())
        except (TypeError, ValueError):
            return False  # a letter left: not a number
        if abs(g) < 1e-12:
            return False
        ratios.append(f / g)
    return abs(ratios[0]) > 1e-12 and abs(ratios[0] - ratios[1]) <= tol * abs(ratios[0])


def _variants(held: Pair, bad: Pair, unknowns: set) -> list[sympy.Expr]:
    """``held`` (left − right) with one term changed as a slip in rearranging changes it: its
    sign (a term in letters written on ``bad``; a number whether shown or not: ``2v = 7.1`` from
    ``7 = 0.1 + 2v`` moves the 0.1 across with its sign kept, as most teachers of the corpus
    mark it), its numeric coefficient dropped or the term halved or doubled (a term in the
    unknowns that ``bad`` does not show as it was: ``12 = 2v + 8`` from ``12 = 2v + 10`` keeps
    2v, and only its number is worked wrongly)."""
    sides = (held.left, held.right)
    out = []
    through = _through(held, unknowns)
    lone = sum(1 for x in sides for t in sympy.Add.make_args(sympy.expand(x)) if t.free_symbols & unknowns) == 1
    for i, side in enumerate(sides):
        sign = 1 if i == 0 else -1
        for t in sympy.Add.make_args(sympy.expand(side)):
            changed = [-t] if not t.free_symbols or _written(t, bad) else []
            if t.free_symbols & unknowns and not _kept(t, bad):
                c, _rest = t.as_coeff_Mul()
                changed += [t / c] if c not in (0, 1, -1) else []  # its coefficient dropped
                changed += [t / c**2] if c not in (0, 1, -1) and lone else []  # ``c x = k``: x = k c
                changed += [t * k for k in FACTORS]
            elif through is not None and t.free_symbols and _written(t, bad):
                changed.append(t * through)  # ``2v = u + eu`` -> ``v = u/2 + eu``: the eu not divided
            elif not t.free_symbols:
                changed += [n for n in _unexpanded(t, held.text) if _written(n, bad)]  # 8(v + 4): 8v + 4
            out += [held.difference + sign * (x - t) for x in changed]
    return out + (_turned_over(held, unknowns) if lone else [])


def _kept(t: sympy.Expr, bad: Pair) -> bool:
    """Whether the term ``t`` in the unknowns is on ``bad`` as it was (or negated: moved across)."""
    terms = set().union(*(sympy.Add.make_args(sympy.expand(x)) for x in (bad.left, bad.right)))
    return t in terms or -t in terms


def _turned_over(held: Pair, unknowns: set) -> list[sympy.Expr]:
    """``held`` (``k = c x``, numbers, one unknown) solved the wrong way round: ``x = c/k``."""
    x = held.difference.free_symbols & unknowns
    F = sympy.expand(held.difference)
    if len(x) != 1 or F.free_symbols != x:
        return []
    u = next(iter(x))
    c, k = F.coeff(u, 1), F.coeff(u, 0)
    if not (c.is_number and k.is_number) or not c or not k or F.has(u**2):
        return []
    return [k * u + c]


def _unexpanded(t: sympy.Expr, text: str) -> list[sympy.Expr]:
    """The numbers ``n`` a number term ``t`` is ``k n`` of, for a bracket ``k(… n …)`` of ``text``
    (``0.2(v + 4)``: 0.8 is 0.2 x 4; a term not multiplied out comes to 4), signed as ``t``."""
    out = []
    for m in _BRACKET.finditer(text):
        k = sympy.Rational(m[1])
        for n in re.findall(r"(?<![\w.^])\d+(?:\.\d+)?(?![\w.])", m[2]):
            if k not in (0, 1) and sympy.Rational(n) and abs(t) == k * sympy.Rational(n):
                out.append(sympy.sign(t) * sympy.Rational(n))
    return out


#: A number times a bracket: ``0.2(v + 4)``, ``8 (x - 3)``, ``5*(w + 1.5)``.
_BRACKET = re.compile(r"(?<![\w.^])(\d+(?:\.\d+)?)\s*\*?\s*\(([^()]*)\)")


def _through(held: Pair, unknowns: set) -> sympy.Expr | None:
    """The number the relation ``held`` is divided through by to give its one unknown alone (its
    coefficient there: 2 in ``2v = u + eu``, ½ in ``v/2 = u``); None where that is not one number."""
    x = held.difference.free_symbols & unknowns
    if len(x) != 1:
        return None
    c = sympy.expand(held.difference).coeff(next(iter(x)))
    if not c.is_number or c == 0 or abs(c) == 1:
        return None
    return abs(c)


def _written(t: sympy.Expr, bad: Pair) -> bool:
    """Whether the term ``t`` (or its negative) is on ``bad``: a term with letters among its
    sides' terms, a number among the numbers of its text."""
    if t.free_symbols:
        terms = set().union(*(sympy.Add.make_args(sympy.expand(x)) for x in (bad.left, bad.right)))
        c, _rest = t.as_coeff_Mul()  # ``4u + \tfrac52 u``: summed at once, the 5/2 still shown
        return (
            t in terms
            or -t in terms
            or (abs(c) != 1 and sympy.nsimplify(abs(c), rational=True) in _written_numbers(bad.text))
        )
    return sympy.nsimplify(abs(t), rational=True) in _written_numbers(bad.text)


#: A fraction as students type it: ``5/2``, ``5u/2``, ``\frac{5}{2}``, ``\tfrac52``, ``\dfrac{5u}{2}``.
_FRACTIONS = (
    re.compile(r"(?<![\w.])(\d+)\s*(?:[A-Za-z]\w*\s*)?/\s*(\d+)(?![\w.])"),
    re.compile(r"\\[dt]?frac\s*(?:\{\s*(\d+)\s*(?:[A-Za-z]\w*\s*)?\}|(\d))\s*(?:\{\s*(\d+)\s*\}|(\d))"),
)


def _written_numbers(text: str) -> set[sympy.Rational]:
    """The numbers written in ``text``: decimals and whole numbers, and fractions in the forms
    students type them (the top and bottom of each, as one number)."""
    out = {sympy.Rational(n) for n in re.findall(r"(?<![\w.])\d+(?:\.\d+)?", text)}
    for pattern in _FRACTIONS:
        for m in pattern.finditer(text):
            top, bottom = [g for g in m.groups() if g is not None][:2]
            if int(bottom):
                out.add(sympy.Rational(int(top), int(bottom)))
    return out


def _letter_lost(F: sympy.Expr, G: sympy.Expr, U: tuple) -> bool:
    """Whether ``F`` and ``G`` (each linear in the one unknown) give it as expressions in the
    symbolic givens that differ in one term only, by a factor of letters (``u - e²u`` for
    ``u - eu``), not by a number (``u - 3eu``: that is arithmetic)."""
    x = [u for u in U if F.has(u)]
    if len(x) != 1:
        return False
    values = [_root(e, x[0]) for e in (F, G)]
    if any(v is None or not v.free_symbols for v in values):
        return False
    terms = [set(sympy.Add.make_args(sympy.expand(v))) for v in values]
    only = [list(terms[0] - terms[1]), list(terms[1] - terms[0])]
    if len(only[0]) != 1 or len(only[1]) != 1:
        return False
    ratio = sympy.simplify(only[0][0] / only[1][0])
    c, rest = ratio.as_coeff_Mul()
    return abs(c) == 1 and bool(rest.free_symbols) and rest.is_Mul | rest.is_Pow | rest.is_Symbol


def _root(F: sympy.Expr, x: sympy.Symbol) -> sympy.Expr | None:
    """The value of ``x`` that ``F = 0`` gives, where ``F`` is linear in it."""
    F = sympy.expand(sympy.numer(sympy.together(F)))
    a, b = F.coeff(x, 1), F.coeff(x, 0)
    if a == 0 or F.has(x**2) or (a.has(x) or b.has(x)):
        return None
    return -b / a


def written_terms(text: str) -> int:
    """How many terms the sides of ``text`` show as typed (``3v = \\tfrac43 u - 4u``: three), before
    any like terms are summed: a sign at the top level of a side, not a leading one or an exponent's."""
    count, depth, last = 0, 0, "="
    for ch in text:
        if ch in "([{":
            depth += 1
        elif ch in ")]}":
            depth -= 1
        elif depth == 0 and (ch == "=" or (ch in "+-−" and last not in "=(*/^eE:")):
            count += 1
        if not ch.isspace():
            last = ch
    return count + 1


def letter_term(bad: Pair, held: Pair, U: tuple, pt: dict) -> bool:
    """Whether ``bad`` is ``held`` divided through (or not) with one term's letter factor of the
    givens missed or taken off with it (``4u = 2 v_A + m v_B`` from ``4mu = 2m v_A + m v_B``;
    ``u + λu = kv`` from ``mu + kmλu = kmv``), in one unknown or more: algebra."""
    letters = held.difference.free_symbols - set(U)
    terms = sympy.Add.make_args(sympy.expand(held.difference))
    if len(terms) < 2 or not letters:
        return False
    tol = max(bad.tol, 1e-9)
    for t in terms:
        for s in letters:
            for x in (t * s, t / s):
                if proportional(bad.difference, held.difference - t + x, U, [pt], tol):
                    return True
    return False


def sign_carried(bad: Pair, held: Pair, U: tuple, pt: dict) -> bool:
    """Whether ``bad`` is ``held`` with its terms in the unknowns as they were (up to a factor) and
    its one term free of them, written as it was, on the wrong side of the sign: ``v_1 = v_2 +
    u/2`` from ``v_2 − v_1 = u/2``. Nothing was worked out in that step, so nothing can be
    arithmetic: the term was carried across with its sign kept, algebra. A number worked out
    from several (``20 v = 0.5`` from ``10 = 20 v + 10.5``) is not this (:func:`number_negated`)."""
    unknowns = set(U)
    if held.raw is None:
        return False
    free = [
        t for side in held.raw for t in sympy.Add.make_args(sympy.expand(side)) if t and not t.free_symbols & unknowns
    ]
    if len(free) != 1:
        return False
    F = sympy.expand(held.difference.xreplace(pt))
    inside = sum((t for t in sympy.Add.make_args(F) if t.free_symbols & unknowns), sympy.Integer(0))
    k = F - inside
    if not inside or not k or k.free_symbols:
        return False
    return proportional(bad.difference.xreplace(pt), inside - k, U, [pt], max(bad.tol, 1e-9))
