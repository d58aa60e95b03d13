"""The letters a problem's statement gives its bodies (``A smooth sphere P lies at rest … a second
sphere Q, moving …``), matched to derive's A and B by what the statement says of each, and the
names a student declares by such a letter in words (``Let x = Q along the line of centres after,
y = P after``).

A statement whose bodies are not derive's A and B by letter names them by other letters: the body
it says is at rest is the one derive has at rest (``v_B1 = 0``: B), the other is the other. Where the
statement does not settle it, nothing is read (the caller's default stays).
"""

from __future__ import annotations

import functools
import re

import sympy

from derive.checking.context import Context

#: A body's letter in a statement: "sphere P", "particle Q", "ball X" (a capital alone after the noun).
_NOUN = r"(?:sphere|particle|ball|disc|puck|body|block|trolley|car|truck)"
_LETTER = re.compile(rf"\b{_NOUN}\s+([A-Z])\b")
#: The letter of a body said to be at rest ("P lies at rest", "sphere P is stationary", "a stationary sphere P").
_AT_REST = re.compile(
    r"\b([A-Z])\s+(?:of\s+mass\s+[\w*/.]+\s+)?(?:(?:that|which)\s+)?(?:(?:lies|is|rests|sits|stands)\s+)?"
    rf"(?:at\s+rest|stationary)|\bstationary\s+{_NOUN}\s+([A-Z])\b"
)


def statement_bodies(ctx: Context) -> dict[str, str]:
    """The statement's letters for the bodies -> derive's "A" or "B" ({} where they are A and B, or
    where the statement does not say which is which)."""
    statement = getattr(ctx.problem, "statement", "") or ""
    letters = list(dict.fromkeys(_LETTER.findall(statement)))
    labels = set(getattr(ctx.problem, "labels", ("A", "B")))
    letters = [x for x in letters if x not in labels and x not in ("A", "B")]
    by_mass = _by_mass(ctx, statement, labels)
    if len(by_mass) == 1 and len(letters) == 2 and set(by_mass) <= set(letters):  # "S of mass m … T, mass km"
        body, other = next(iter(by_mass.values())), next(x for x in letters if x not in by_mass)
        by_mass[other] = "B" if body == "A" else "A"  # one letter placed by its mass: the other is the other body
    if len(by_mass) == 2:
        return by_mass
    if len(letters) != 2:
        return {}
    rest = _AT_REST.search(statement)
    if rest is None:
        return {}
    still = rest.group(1) or rest.group(2)
    if still not in letters:
        return {}
    other = letters[1 - letters.index(still)]
    at_rest = [b for b in ("A", "B") if at_rest_before(ctx, b)]
    if len(at_rest) != 1:
        return {}
    moving = "B" if at_rest[0] == "A" else "A"
    return {still: at_rest[0], other: moving}


#: A letter with the mass the statement gives it: "P (mass 2m)", "particle Q, of mass 0.5 kg", "Q has mass 3m".
_MASS = re.compile(r"\b([A-Z])\s*(?:\(\s*|,\s*)?(?:(?:of|with|has)\s+)?(?:a\s+)?mass\s+(\d*\.?\d*\s*\*?\s*[a-z]?)\b")


def _by_mass(ctx: Context, statement: str, labels: set[str]) -> dict[str, str]:
    """The statement's letters matched to A and B by the mass it gives each (``Particles P (mass 2m)
    and Q (mass 3m)`` with m_A = 2m): those found where the masses tell them apart."""
    masses = {}
    for g in ctx.problem.givens:
        if g.name in ("m_A", "m_B"):
            x = g.definition if g.definition is not None else g.value
            masses[g.name[-1]] = _simplest(x) if x is not None else None
    if len(masses) != 2 or None in masses.values() or masses["A"] == masses["B"]:
        return {}
    out: dict[str, str] = {}
    for m in _MASS.finditer(statement):
        letter, text = m.group(1), re.sub(r"(\d)\s*\*?\s*([a-z])", r"\1*\2", m.group(2).strip())
        if letter in labels or letter in ("A", "B") or not text:
            continue
        try:
            said = _simplest(text)
        except (sympy.SympifyError, TypeError, ValueError):
            continue
        body = next((b for b, x in masses.items() if x == said), None)
        if body is not None and letter not in out and body not in out.values():
            out[letter] = body
    return out  # one letter, or both: the caller completes one


@functools.lru_cache(maxsize=256)
def _simplest(x: object) -> str:
    """A mass as the simplest number or formula it is (``0.5*m`` and ``m/2`` alike), by value:
    a statement's masses are read for every name a derivation declares."""
    return str(sympy.nsimplify(sympy.sympify(x)))


def at_rest_before(ctx: Context, body: str) -> bool:
    """Whether derive has ``body`` at rest before the impact (its velocity given as 0; a fixed wall too)."""
    if body == "B" and getattr(ctx.problem, "fixed_B", False):
        return True
    for g in ctx.problem.givens:
        if g.name in (f"v_{body}1", f"v_{body}1n") and g.value is not None:
            try:
                return bool(sympy.sympify(g.value) == 0)
            except (sympy.SympifyError, TypeError):
                return False
    return False


_ONE = r"([A-Za-z](?:_?\w{1,2})?)"
_LOC = r"(?:along\s+(?:the\s+)?(?:line\s+of\s+(?:centres|centers|impact)|l\.?\s?o\.?\s?c\b\.?))"
#: "x = Q along the line of centres after", "let y = P after": a name, a body's letter, when.
_NAMED = re.compile(rf"(?:\blet\s+)?\b{_ONE}\s*=\s*([A-Z])\s+(?:({_LOC})\s*,?\s*)?(after|before)\b", re.I)


def said_by_letter(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names ``line`` declares by a body's letter and words of when (``x = Q along the line of
    centres after, y = P after``): each the body's velocity then (its component along the line of
    centres in an oblique impact, where the line says so for it or for a name before it)."""
    bodies = statement_bodies(ctx)
    if not bodies:
        return {}
    plain = re.sub(r"\$|\\[()]|[{}]", " ", line)
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    along = bool(re.search(_LOC, plain, re.I))
    for m in _NAMED.finditer(plain):
        body = bodies.get(m.group(2))
        if body is None:
            continue
        when = "2" if m.group(4).lower() == "after" else "1"
        key = f"v_{body}{when}n" if ctx.problem.oblique else f"v_{body}{when}"
        if ctx.problem.oblique and not along:
            continue
        if key in names:
            out.setdefault(m.group(1), names[key][0])
    return out


#: A body named by a word before its noun in a statement: "a blue puck", "the red puck", "a cue ball".
_NOUN_WORD = re.compile(rf"\b(?i:a|an|the)\s+([a-z]{{3,}})\s+{_NOUN}\b")
#: Words before a noun that never tell two bodies apart.
_ALIKE = frozenset({"small", "smooth", "uniform", "identical", "large", "heavy", "light", "second", "other", "same"})


def told_apart(statement: str) -> dict[str, str]:
    """The words that tell the statement's two bodies of one noun apart (``A blue puck of mass {m_A}
    … a red puck``) -> "A" or "B": the one said with A's mass (``{m_A}``) is A, or with B's is B, and
    the other is the other; {} unless exactly two such words are found and the masses say which."""
    words = list(dict.fromkeys(w for w in _NOUN_WORD.findall(statement) if w not in _ALIKE))
    if len(words) != 2:
        return {}
    for body in "AB":
        with_mass = [
            w
            for w in words
            if re.search(rf"\b{w}\s+{_NOUN}\s+(?:\([A-Z]\)\s+)?(?:\(|(?:of|with)\s+mass\s+)\{{m_{body}\}}", statement)
        ]
        if len(with_mass) == 1:
            other = "B" if body == "A" else "A"
            return {with_mass[0]: body, words[1 - words.index(with_mass[0])]: other}
    return {}
