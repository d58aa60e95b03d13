"""What every rule needs: the page's claims read and placed, and their values under the facts.

A :class:`Judge` holds the claims of one page (each line read into relations),
the facts of each part of the page, and answers the questions the rules ask:
what is this side worth here, how much rounding may its numbers hide, which
numbers are data (exact), what is the figures rule.
"""

from __future__ import annotations

import copy
from collections.abc import Iterator
from dataclasses import dataclass
from decimal import Decimal
from fractions import Fraction

from derive.mathtext.display import parse_display, parse_inline
from derive.mathtext.tokens import LatexError
from derive.mathtext.tree import Display, Hat, Num, ParsedRelation, Side, Sym, Unknown, Vec
from derive.verifier import units
from derive.verifier.evaluate import CTX, ZERO, Env, Undefined, Unresolved, measure, mpf, walk
from derive.verifier.facts import Facts, Scope
from derive.verifier.reader import PageLine

#: The mark after an answer on derive's pages, as a reader sees it on the page.
ANSWER_MARK = r"\quad\longleftarrow\ \text{ANSWER}"
TOLERANCE = CTX.mpf(10) ** -20
TINY = CTX.mpf(10) ** -20  # an absolute floor: 25 cos 90° at 40 digits is 1e-42, not 0


def tolerance(*values: Value) -> object:
    """What exact arithmetic at 40 digits may leave over: relative to the sizes involved."""
    return TOLERANCE * max([TINY, *(max(abs(v.center), v.scale) for v in values)])


@dataclass(frozen=True)
class Claim:
    """A line of the page, read: a display, or one relation (a given, a carried value)."""

    line: PageLine
    display: Display | None
    error: str | None = None

    @property
    def relations(self) -> tuple[ParsedRelation, ...]:
        return self.display.relations if self.display is not None else ()


def read_display(latex: str) -> Display:
    """A displayed line of the page read, its ANSWER marks counted."""
    return parse_display(latex, ANSWER_MARK)


def read_claim(line: PageLine) -> Claim:
    """Parse one line; a line the reader cannot read keeps the reason."""
    try:
        if line.kind == "display":
            return Claim(line, read_display(line.latex))
        return Claim(line, Display(relations=(parse_inline(line.latex),), body=line.latex))
    except (LatexError, IndexError) as exc:
        return Claim(line, None, str(exc))


@dataclass(frozen=True)
class Value:
    """A side's value in working units (radians for angles), the rounding it may hide, its unit's dimension."""

    center: object
    radius: object
    unit_dim: units.Dim | None = None
    scale: object = ZERO


class Judge:
    """The claims of a page under its facts."""

    def __init__(self, facts: Facts, lines: list[PageLine]) -> None:
        self.facts = facts
        self.claims = [read_claim(line) for line in lines]
        self.unresolved: set[tuple[int, str]] = set()
        #: line -> why a side of it could not be valued (the rule ``read`` reports them)
        self.unvalued: dict[int, str] = {}
        #: read a number with the figures of an intermediate as a rounding, even where its
        #: digits are a given's (76.37 for v_A2 when v_A1 = 76.37 is given)
        self.coincident = False
        #: the decimal places of the line being valued that a number of three figures shows
        self.shared: set[int] | None = None

    def rounded_view(self) -> Judge:
        """The same claims with a given's digits in a working line allowed to be a rounding."""
        other = copy.copy(self)
        other.coincident = True
        other.unvalued = {}
        other.unresolved = set()
        return other

    def solved_view(self) -> Judge | None:
        """The same claims with a chain's unknowns solved everywhere (None when nothing changes)."""
        if not self.facts.solved:
            return None
        other = copy.copy(self)
        f = self.facts
        other.facts = Facts({**f.scopes, **f.solved}, f.digits, f.chain, f.notes)
        other.unresolved = set()
        other.unvalued = {}
        return other

    # scopes ----------------------------------------------------------------
    def scope(self, key: str) -> Scope:
        if key in self.facts.scopes:
            return self.facts.scopes[key]
        return next(iter(self.facts.scopes.values()))

    def chain_of(self, key: str) -> list[Scope]:
        """The scope and its parents, nearest first."""
        out, seen = [], set()
        scope: Scope | None = self.scope(key)
        while scope is not None and scope.key not in seen:
            out.append(scope)
            seen.add(scope.key)
            scope = self.facts.scopes.get(scope.parent) if scope.parent else None
        return out

    def side_scopes(self, claim: Claim, index: int) -> list[Scope]:
        """Where a side's names are looked up: a stage's Given line names the stage's
        given on the left and the chain's names on the right; a carried value the reverse."""
        scopes = self.chain_of(claim.line.scope)
        if len(scopes) > 1 and (
            (claim.line.kind == "given" and index > 0) or (claim.line.kind == "carried" and index == 0)
        ):
            return scopes[1:] + scopes[:1]
        return scopes

    def quantity(self, name: str, scopes: list[Scope]):
        for s in scopes:
            q = s.quantities.get(name)
            if q is not None:
                return q
        return None

    def env(self, scopes: list[Scope], axis: str | None = None, overrides: dict | None = None) -> Env:
        over = overrides or {}

        def scalar(name: str) -> object | None:
            if name in over:
                return over[name]
            q = self.quantity(name, scopes)
            if q is None and name == "pi":  # \pi, unless the problem names something pi
                return CTX.pi
            return None if q is None else q.value

        def vector(name: str, ax: str) -> object | None:
            for s in scopes:
                comps = s.vectors.get(name)
                if comps is not None:
                    return comps.get(ax)
            return None

        return Env(scalar, vector, axis)

    # numbers -----------------------------------------------------------------
    def rule_figures(self, value: Decimal) -> int:
        """Figures a value is shown with: the problem's digits, else 3 (4 when the leading digit is 1)."""
        if self.facts.digits is not None:
            return self.facts.digits
        if value == 0:
            return 3
        lead = abs(value).scaleb(-abs(value).adjusted())
        return 4 if int(lead) == 1 else 3

    def is_exact(self, num: Num, scopes: list[Scope], result: bool = False) -> bool:
        """A number a reader takes as exact: a small whole number, or a given written as
        the Given list writes it (0.15, not 0.150; a result is never one)."""
        if num.value == 0 and num.integer:
            return True
        # 100 may be 99.99... rounded (a leading 9 allows three figures): exact only if no
        # value just below it would be shown so
        rule = min(self.rule_figures(num.value), self.rule_figures(abs(num.value) - Decimal("0.5")))
        if num.integer and len(num.mantissa) < rule:
            return True
        short = not num.integer and not num.exponent and num.figures < min(rule, 3) and not result
        if short and self.shared is not None and num.decimals not in self.shared:
            return True  # 4.5 e = 0.9 where the rule shows 3 figures: a rounding would read 4.50
        canonical = "." not in num.mantissa or not num.mantissa.endswith("0")
        if result or not canonical:
            return False
        if self.coincident and num.figures >= rule:
            return False
        v = num.value.normalize()
        return any(v in s.exact for s in scopes)

    def _may_be_rounded(self, num: Num) -> bool:
        """A number with at least the rule's figures: a rounding could have written it
        (0.12 for 0.1223 where v_B1 = -0.12; a small whole number is exact)."""
        digits = num.mantissa.lstrip("-").replace(".", "").lstrip("0")
        rule = self.rule_figures(num.value)
        if num.integer:
            return num.value != 0 and len(digits) >= rule and len(digits.rstrip("0")) >= rule
        return num.value != 0 and len(digits) >= rule

    def halfwidth(self, num: Num, scopes: list[Scope], result: bool = False) -> object:
        """Half a unit in the last figure shown; 0 for an exact number. A whole number
        ending in zeros may hide rounding up to its zeros (12300 for 12345). A whole number
        equal to a given but with the figures of a rounding may be one (20 for 19.8 at one
        figure, where m_A = 20 kg), so it is measured as one."""
        if self.is_exact(num, scopes, result) and not self._may_be_rounded(num):
            return ZERO
        if not num.integer:
            return mpf(num.ulp) / 2
        digits = num.mantissa.lstrip("-")
        zeros = len(digits) - len(digits.rstrip("0"))
        room = len(digits) - self.rule_figures(num.value)
        return CTX.mpf(10) ** max(0, min(zeros, room)) / 2

    # values ---------------------------------------------------------------
    def value(
        self,
        side: Side,
        scopes: list[Scope],
        axis: str | None = None,
        overrides: dict | None = None,
        result: bool = False,
    ) -> Value:
        """A side's value and radius, its unit applied; raises Unresolved or Undefined.
        ``result``: the side states a result, so its number is a rounding, never a datum."""
        env = self.env(scopes, axis, overrides)
        center, radius, scale = measure(side.expr, env, lambda n: self.halfwidth(n, scopes, result))
        unit_dim = None
        if side.unit is not None:
            factor, unit_dim, _ = units.to_working(side.unit, scopes[0].system)
            f = mpf(Fraction(factor))
            center, radius, scale = center * f, radius * f, scale * f
        elif any(isinstance(n, Num) and n.degrees for n in walk(side.expr)):
            unit_dim = units.ANGLE
        return Value(center, radius, unit_dim, scale)

    def axes(self, relation: ParsedRelation) -> list[str | None]:
        """The components a relation is read in: none, or those of its unit vectors."""
        found: list[str] = []
        has_vec = False
        for side in relation.sides:
            for node in walk(side.expr):
                if isinstance(node, Hat) and node.axis not in found:
                    found.append(node.axis)
                has_vec = has_vec or isinstance(node, Vec)
        if has_vec and not found:
            found = ["t", "n"]
        if found and set(found) <= {"t", "n"}:
            return ["t", "n"]
        if found and set(found) <= {"x", "y"}:
            return ["x", "y"]
        return found or [None]

    def values(self, claim: Claim, relation: ParsedRelation, axis: str | None) -> list[Value | None]:
        """Each side's value (None where a name has no value or the side no number)."""
        out: list[Value | None] = []
        # places a line shares among its numbers (0.31 v_A2 + 0.12 v_B2 = 8.54): at those, a short
        # number is a rounding; elsewhere a short decimal is exact
        self.shared = {n.decimals for n in walk_claim(claim) if isinstance(n, Num) and n.figures >= 3}
        for i, side in enumerate(relation.sides):
            if isinstance(side.expr, Unknown):  # "e = ?": the name must be one the problem asks for
                self._unknown_given(claim, relation)
                out.append(None)
                continue
            try:
                out.append(self.value(side, self.side_scopes(claim, i), axis, result=is_stated(claim, relation, i)))
            except Unresolved as exc:
                self.unresolved.add((claim.line.number, str(exc)))
                self.unvalued.setdefault(claim.line.number, f"{side.source} names {exc}, which has no value here")
                out.append(None)
            except units.UnknownUnit as exc:
                self.unvalued.setdefault(claim.line.number, str(exc))
                out.append(None)
            except (Undefined, ZeroDivisionError, ValueError, OverflowError) as exc:
                self.unvalued.setdefault(claim.line.number, f"{side.source} has no value ({exc})")
                out.append(None)
        self.shared = None  # only while this claim is valued
        return out

    def _unknown_given(self, claim: Claim, relation: ParsedRelation) -> None:
        first = relation.sides[0].expr
        scopes = self.side_scopes(claim, 0)
        q = self.quantity(first.name, scopes) if isinstance(first, Sym) else None
        asked = q is not None and (q.role == "unknown" or any(q.name in s.asked for s in scopes))
        if not asked:
            self.unvalued.setdefault(claim.line.number, f"{relation.sides[0].source} is shown as unknown (?)")

    def names(self, node: object) -> Iterator[str]:
        for n in walk(node):
            if isinstance(n, (Sym, Vec)):
                yield n.name

    def roles(self, node: object, scopes: list[Scope]) -> set[str]:
        out = set()
        for name in self.names(node):
            q = self.quantity(name, scopes)
            if q is not None:
                out.add(q.role)
        return out


def walk_claim(claim: Claim) -> Iterator[object]:
    """Every node of every side of a claim."""
    for rel in claim.relations:
        for side in rel.sides:
            yield from walk(side.expr)


def lone_number(side: Side) -> Num | None:
    """The number when a side is one number (perhaps negative), else None."""
    from derive.mathtext.tree import Add

    expr = side.expr
    if isinstance(expr, Add) and len(expr.terms) == 1 and expr.terms[0][0] == -1:
        expr = expr.terms[0][1]
    return expr if isinstance(expr, Num) else None


def signed_value(side: Side) -> Decimal | None:
    """A lone number's value with its sign, as shown."""
    from derive.mathtext.tree import Add

    num = lone_number(side)
    if num is None:
        return None
    neg = isinstance(side.expr, Add)
    return -num.value if neg else num.value


def is_stated(claim: Claim, relation: ParsedRelation, index: int) -> bool:
    """True for the last side of a line that states a value (with a unit, boxed, carried):
    its numbers are roundings, even one that happens to read like a given."""
    if index == 0 or index != len(relation.sides) - 1 or claim.line.kind == "given":
        return False
    boxed = claim.display is not None and claim.display.boxed
    return relation.sides[index].unit is not None or boxed or claim.line.kind == "carried"


def is_result(claim: Claim, relation: ParsedRelation, index: int) -> bool:
    """True for the last side of a line that states a result: one number, with a unit or boxed."""
    side = relation.sides[index]
    if index != len(relation.sides) - 1 or index == 0 or lone_number(side) is None or claim.line.kind == "given":
        return False
    boxed = claim.display is not None and claim.display.boxed
    num = lone_number(side)
    return side.unit is not None or boxed or claim.line.kind == "carried" or bool(num and num.degrees)
