"""A user's own equation, labelled with its number in the notes' order, judged by a table of rules.

Each rule of :data:`RULES` looks at the equation one way and returns a
:class:`Verdict` (or None when it has nothing to say); the first verdict stands.
Where no rule finds anything, the mistaken-equation rules are tried again with two
mistakes made together; then the equation is wrong with no mistake named.
:func:`wording` turns a verdict into the report's sentence.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, replace

import sympy

from derive.checking import mistakes
from derive.checking.context import Context
from derive.checking.entries import Entry
from derive.checking.expression import read
from derive.checking.figures import literal_tolerance
from derive.checking.mistakes import EQUATION_TITLES, Outcome
from derive.checking.numeric import listed
from derive.checking.relations import Point, matches, proportional, satisfied, shown, solve_with
from derive.checking.report import Diagnosis, Item
from derive.errors import InputError
from derive.problem.expr import ParseError

SOLVING = "solving with the other equations"


@dataclass(frozen=True)
class Equation:
    """An equation read for checking: ``F`` is ``lhs - rhs`` in the unknowns with
    everything known put in; ``k`` the label when it is one of the problem's (1)-(4);
    ``tol`` the slack of the decimals written; ``pts`` sample points of symbolic givens;
    ``outcomes`` the mistakes tried."""

    text: str
    label: str
    k: int | None
    F: sympy.Expr
    tol: float
    pts: list[Point]
    base: Outcome
    outcomes: list[Outcome]
    numbers: tuple[int, ...]
    notes: tuple[str, ...] = ()
    forms: tuple[Outcome, ...] = ()  # mistakes' equations with no values (see mistakes.forms)

    @property
    def U(self) -> tuple[sympy.Symbol, ...]:
        """The unknowns."""
        return self.base.unknowns

    @property
    def order(self) -> list[int]:
        """The equations it may be: its label's, or all of them."""
        return [self.k] if self.k is not None else list(self.numbers)


@dataclass(frozen=True)
class Verdict:
    """What a rule found: ``rule`` its name; ``correct``; ``equation`` which of (1)-(4)
    the equation is or takes the place of; ``mistakes`` those that reproduce it
    (``together``: made together, where no one of them does)."""

    rule: str
    correct: bool
    equation: int | None = None
    mistakes: tuple[Diagnosis, ...] = ()
    together: bool = False


Rule = Callable[[Context, Equation], "Verdict | None"]


def same_equation(ctx: Context, eq: Equation) -> Verdict | None:
    """It is (k) (or, unlabelled, one of (1)-(4)), up to a factor."""
    for j in eq.order:
        if proportional(eq.F, eq.base.equations[j], eq.U, eq.pts, eq.tol):
            return Verdict("same_equation", True, j)
    return None


def mistaken_equation(ctx: Context, eq: Equation) -> Verdict | None:
    """It is the mistaken (k) of a common mistake, up to a factor (the mistakes as they are
    solved first, then their other forms: energy in place of (4) before in place of (3))."""
    for pool, j in [(pool, j) for pool in (eq.outcomes, list(eq.forms)) for j in eq.order]:

        def fits(o: Outcome, j: int = j) -> str | None:
            mistaken = j in o.equations and not proportional(o.equations[j], eq.base.equations[j], eq.U, eq.pts, 1e-9)
            return "" if mistaken and proportional(eq.F, o.equations[j], eq.U, eq.pts, eq.tol) else None

        found = ctx.diagnose(fits, pool)
        if found:
            return Verdict("mistaken_equation", False, j, found)
    return None


def relabelled(ctx: Context, eq: Equation) -> Verdict | None:
    """It is another of (1)-(4) than its label says."""
    for j in eq.numbers:
        if j not in eq.order and proportional(eq.F, eq.base.equations[j], eq.U, eq.pts, eq.tol):
            return Verdict("relabelled", True, j)
    return None


def solves_correctly(ctx: Context, eq: Equation) -> Verdict | None:
    """In place of (k) (or of one of them), with the others it gives the correct velocities."""
    for j in eq.order:
        roots = solve_with(eq.F, eq.base.equations, j, eq.U, eq.pts)
        if roots is not None and matches(roots, eq.base, eq.U, eq.pts, eq.tol):
            return Verdict("solves_correctly", True, j)
    return None


def solves_as_mistake(ctx: Context, eq: Equation) -> Verdict | None:
    """In place of (k), with the others it gives the velocities of a common mistake."""
    for j in eq.order:
        roots = solve_with(eq.F, eq.base.equations, j, eq.U, eq.pts)
        if roots is None:
            continue
        shapes = [o for o in eq.forms if o.post and not eq.pts[0]]  # the forms' velocities are numbers
        found = ctx.diagnose(
            lambda o, r=roots: "" if matches(r, o, eq.U, eq.pts, eq.tol) else None, [*eq.outcomes, *shapes]
        )
        if found:
            return Verdict("solves_as_mistake", False, j, found)
    return None


def consistent(ctx: Context, eq: Equation) -> Verdict | None:
    """The correct velocities satisfy it (a step of the elimination, say)."""
    if satisfied(eq.F, eq.base.post, eq.U, eq.pts, eq.tol):
        return Verdict("consistent", True)
    return None


#: The rules, in the order they are tried; the first verdict stands.
RULES: list[Rule] = [
    same_equation,
    mistaken_equation,
    relabelled,
    solves_correctly,
    solves_as_mistake,
    consistent,
]
#: Tried again with two mistakes together where no rule found anything.
PAIR_RULES: list[Rule] = [mistaken_equation, solves_as_mistake]


def judge(ctx: Context, eq: Equation) -> Verdict:
    """The first verdict of :data:`RULES` (then of :data:`PAIR_RULES` with pairs of mistakes);
    else wrong with no mistake named (rule "no_match")."""
    for rule in RULES:
        v = rule(ctx, eq)
        if v is not None:
            return v
    paired = replace(eq, outcomes=ctx.pairs())
    for rule in PAIR_RULES:
        v = rule(ctx, paired)
        if v is not None:
            return replace(v, together=True)
    return Verdict("no_match", False, eq.k)


def equation_item(ctx: Context, e: Entry) -> Item:
    """The verdict on the equation ``e`` as a report item."""
    eq = read_equation(ctx, e)
    v = judge(ctx, eq)
    message, method = wording(eq, v)
    notes = eq.notes
    if v.rule == "relabelled":
        notes += (f"It is labelled ({eq.k}) but it is ({v.equation}).",)
    expected = shown(eq.base.equations[eq.k], eq.U, _first(ctx, eq.k)) if eq.k is not None else ""
    status = "correct" if v.correct else "wrong"
    return Item("equation", eq.label, eq.text, status, expected, message, method, notes=notes, diagnosis=v.mistakes)


def wording(eq: Equation, v: Verdict) -> tuple[str, str]:
    """The report's sentence for a verdict, and the method it names."""
    who = f"Your ({eq.label})" if eq.label else "This equation"
    j, k = v.equation, eq.k
    named = _named(j, k) if j is not None else ""
    what = (" and " if v.together else " / ").join(_phrase(d) for d in v.mistakes)
    if v.rule in ("same_equation", "relabelled"):
        return f"{who} is {named}: correct.", "comparison"
    if v.rule == "mistaken_equation":
        return (f"{who} {what}." if j == k else f"{who} is {named}, but it {what}."), "comparison"
    rest = listed([f"({i})" for i in eq.numbers if i != j])
    with_rest = f"with {rest}" if rest else "on its own"
    if v.rule == "solves_correctly":
        if j == k:
            return (
                f"{who} is not written as {named}, but {with_rest} it gives the correct velocities: correct.",
                SOLVING,
            )
        return f"{who} gives the correct velocities {with_rest}: correct.", SOLVING
    that = "those mistakes made together" if v.together else "that mistake"
    if v.rule == "solves_as_mistake":
        return f"{who} {what}: {with_rest} it gives the velocities of {that}.", SOLVING
    if v.rule == "satisfied_by_mistake":
        return (
            f"{who} {what}: the velocities of that mistake satisfy it.",
            "substituting the velocities of each mistake",
        )
    if v.rule == "consistent":
        tail = f", though it is not ({k}), {EQUATION_TITLES[k]}" if k is not None else ""
        return f"{who} is consistent with the physics: the correct velocities satisfy it{tail}.", (
            "substituting the correct velocities"
        )
    if k is not None:
        return f"{who} does not agree with ({k}), {EQUATION_TITLES[k]}. No common mistake reproduces it.", "comparison"
    either = " or ".join(f"({i})" for i in eq.numbers)
    return (
        f"{who} is not {either}, and the correct velocities do not satisfy it. No common mistake reproduces it.",
        "comparison",
    )


def _named(j: int, k: int | None) -> str:
    title = EQUATION_TITLES[j]
    return title if j == k else f"({j}), {title}"


def _phrase(d: Diagnosis) -> str:
    m = mistakes.REGISTRY.get(d.mistake)
    return m.phrase if m is not None else d.title


def _first(ctx: Context, k: int) -> tuple[sympy.Symbol, ...]:
    nm = ctx.model.nm
    return (nm.B2n, nm.A2n) if k == 4 else ()


# ---------------------------------------------------------------- reading


def read_equation(ctx: Context, e: Entry, label: str | None = None) -> Equation:
    """``e`` read as an equation of this problem (bad input raises :class:`InputError`)."""
    raw = e.raw
    if not isinstance(raw, str):
        raise e.error('expected an equation as text, such as "v_B2n - v_A2n = 9.5"')
    text = raw.replace("−", "-").strip()
    if len(text) > 500:
        raise e.error("is too long (at most 500 characters)")
    if text.count("=") != 1 or re.search(r"[<>!]=|==", text):
        raise e.error("an equation needs exactly one '=' between its two sides")
    lhs_text, rhs_text = text.split("=")
    names = ctx.equation_names()
    try:
        lhs, rhs = read(lhs_text, names).expr, read(rhs_text, names).expr
    except ParseError as exc:
        raise e.error(str(exc)) from None
    label = e.name.strip().strip("()").strip() if label is None else label
    return relation(ctx, text, label, lhs - rhs, e.error)


def relation(
    ctx: Context, text: str, label: str, difference: sympy.Expr, error: Callable[[str], InputError] = InputError
) -> Equation:
    """The equation ``difference = 0`` (in the names of :meth:`Context.equation_names`),
    labelled ``label``, ready for the rules."""
    model = ctx.model
    k = int(label) if label in ("1", "2", "3", "4") else None
    notes = []
    if k is not None and k not in model.numbers:
        notes.append(f"There is no equation ({k}) here: {_why_not(ctx)}. It was checked against each of them.")
        k = None
    F = ctx.in_unknowns(difference)
    base = mistakes.correct(ctx.solution)
    if base is None:
        raise error("this problem's equations cannot be set up for checking")
    # the sample points are of every symbolic given of the system it is solved with, not only of
    # its own: (1 - 9e)^2 + 9(1 + e)^2 = 25 is solved with m u = m x + 9m y at numbers for m and u
    known = (F, *base.equations.values(), *base.post.values())
    extra = set().union(*(x.free_symbols for x in known)) - set(model.unknowns)
    pts = ctx.sampler().points(extra, 3) if extra else [{}]
    tol = max(literal_tolerance(text, ctx.data), 1e-9)
    found = [o for o in ctx.singles() if o.mistake is not None]
    return Equation(text, label, k, F, tol, pts, base, found, model.numbers, tuple(notes), tuple(ctx.forms()))


def _why_not(ctx: Context) -> str:
    p = ctx.problem
    if not p.fixed_B:
        return "a direct impact has no t equations (1), (2)"
    surface = p.name_B or "surface"
    if not p.oblique:
        return f"against a fixed {surface} in a direct impact only (4) applies"
    return f"against a fixed {surface} only (1) and (4) apply (its supports exert an impulse)"
