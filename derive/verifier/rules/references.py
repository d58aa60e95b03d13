"""Rule ``references``: "Add (3) and (4)", "From (4)", "Substitute into (3)", "Back into (4)".

The equation numbers named exist above the line, in the same part of the page
(an impact's own equations, not another stage's), and the operation does what
the sentence says: the line that follows is, as an equation in the unknowns,
the sum, the difference or the named equation itself (after putting in what
the lines before have found); a term said to cancel cancels. Each equation
number is used once.

The check treats each equation as ``left - right`` and compares the line with
the operation at a few points of the unknowns around their solved values: the
two must be proportional there, within the rounding of the numbers shown.
"""

from __future__ import annotations

import itertools
import re
from collections.abc import Iterator
from dataclasses import dataclass
from decimal import Decimal

from derive.mathtext.display import parse_display
from derive.mathtext.tokens import LatexError
from derive.mathtext.tree import Add, Mul, Num, Side, Sym
from derive.verifier.evaluate import CTX, Undefined, Unresolved, rebuild, substitute, walk
from derive.verifier.judge import Claim, Judge, Value, lone_number, tolerance
from derive.verifier.report import Failure

RULE = "references"
OPERATIONS = (
    (re.compile(r"Add \((\d+)\) and \((\d+)\)"), "add"),
    (re.compile(r"Subtract \((\d+)\) from \((\d+)\)"), "subtract"),
    (re.compile(r"(?:Substitute|Back) into \((\d+)\)"), "into"),
    (re.compile(r"^From \((\d+)\)"), "from"),
    (re.compile(r"^Solve ((?:\(\d+\)(?:,| and)? ?)+) together"), "together"),
    (re.compile(r"^Multiply \((\d+)\) by \$([-\d.]+)\$ and add it to \((\d+)\)"), "multiply-add"),
    (re.compile(r"^Multiply \((\d+)\) by \$([-\d.]+)\$ and subtract it from \((\d+)\)"), "multiply-subtract"),
)
CANCELS = re.compile(r"\$([^$]+)\$ cancels")
STEPS = (CTX.mpf("0.37"), CTX.mpf("-0.61"), CTX.mpf("1.13"))
TOLERANCE_C = CTX.mpf(10) ** -9


@dataclass
class Step:
    """A sentence naming equations, and the first line under it."""

    op: str
    tags: tuple[str, ...]
    cancels: tuple[str, ...]
    claim: Claim
    factor: str = "1"


def _name(latex: str) -> str:
    m = re.fullmatch(r"\s*([A-Za-z]+|\\[A-Za-z]+)(?:_\{?([^{}]*)\}?)?\s*", latex)
    if not m:
        return latex
    base = m.group(1).lstrip("\\")
    sub = re.sub(r"\\mathrm\{([^{}]*)\}", r"\1", m.group(2) or "")
    return base + ("_" + sub if sub else "")


def steps(judge: Judge) -> Iterator[Step]:
    """Each block whose sentence names an operation on equations."""
    seen: set[int] = set()
    for claim in judge.claims:
        line = claim.line
        if line.kind != "display" or line.block in seen or not line.sentence:
            continue
        seen.add(line.block)
        for pattern, op in OPERATIONS:
            m = pattern.search(line.sentence)
            if m:
                if op.startswith("multiply"):  # Multiply (a) by k and add it to (b)
                    tags, factor = (m.group(1), m.group(3)), m.group(2)
                else:
                    tags, factor = tuple(re.findall(r"\(?(\d+)\)", m.group(0))), "1"
                cancels = tuple(_name(c) for c in CANCELS.findall(line.sentence))
                yield Step(op, tags, cancels, claim, factor)
                break


def _equation(claim: Claim) -> object | None:
    """A tagged line as ``left - right`` (its first and last sides)."""
    if not claim.relations or len(claim.relations[0].sides) < 2:
        return None
    sides = claim.relations[0].sides
    return Add(((1, sides[0].expr), (-1, sides[-1].expr)))


def _sides_above(judge: Judge, step: Step) -> Iterator[tuple]:
    """The sides of each line above the step's (same section and scope, earlier blocks) that
    finds an unknown: a name alone on its left."""
    here = step.claim.line
    for claim in judge.claims:
        line = claim.line
        if line.number >= here.number or line.section != here.section or line.scope != here.scope:
            continue
        if line.block == here.block or not claim.relations:
            continue
        sides = claim.relations[0].sides
        if len(sides) >= 2 and isinstance(sides[0].expr, Sym):
            yield sides


def _found_before(judge: Judge, step: Step) -> dict[str, object]:
    """Unknowns the lines above (same section, earlier blocks) have found: name -> its expression."""
    return {s[0].expr.name: (s[1] if len(s) == 2 else s[-1]).expr for s in _sides_above(judge, step)}


def _shown_before(judge: Judge, step: Step) -> dict[str, str]:
    """Unknowns the lines above (same section) found, each with its value as written there."""
    return {s[0].expr.name: s[-1].source.strip() for s in _sides_above(judge, step) if lone_number(s[-1]) is None}


def _known_above(judge: Judge, step: Step, unknowns: frozenset[str]) -> set[str]:
    """Unknowns a line above (in this part of the page) gives a value free of other unknowns."""
    here = step.claim.line
    out: set[str] = set()
    for claim in judge.claims:
        line = claim.line
        if line.number >= here.number or line.scope != here.scope or not claim.relations or line.kind != "display":
            continue
        sides = claim.relations[0].sides
        named = len(sides) >= 2 and isinstance(sides[0].expr, Sym) and sides[0].expr.name in unknowns
        if named and any(not set(judge.names(s.expr)) & unknowns for s in sides[1:]):
            out.add(sides[0].expr.name)
    return out


class _Operation:
    """The line under a step and the operation's equation, valued at points of the unknowns."""

    def __init__(self, judge: Judge, step: Step, tagged: dict[str, Claim]) -> None:
        self.judge = judge
        self.step = step
        self.scopes = judge.chain_of(step.claim.line.scope)
        eqs = [_equation(tagged[t]) for t in step.tags]
        if step.op == "add":
            ref = Add(((1, eqs[0]), (1, eqs[1])))
        elif step.op == "subtract":  # Subtract (a) from (b): (b) - (a)
            ref = Add(((1, eqs[1]), (-1, eqs[0])))
        elif step.op.startswith("multiply"):  # (b) + k (a), or (b) - k (a)
            sign = 1 if step.op == "multiply-add" else -1
            ref = Add(((1, eqs[1]), (sign, Mul((Num(step.factor.lstrip("-")), eqs[0])))))
            if step.factor.startswith("-"):
                ref = Add(((1, eqs[1]), (-sign, Mul((Num(step.factor.lstrip("-")), eqs[0])))))
        else:
            ref = eqs[0]
        self.line = _equation(step.claim)
        self.alternatives: list[object] = []  # other readings of the middle side ("4 + 4")
        unknowns = self.scopes[0].unknowns()
        self.free = ({n for n in judge.names(self.line) if n in unknowns} | set(step.cancels)) & unknowns
        before = _found_before(judge, step)
        if step.op == "into":  # what earlier lines found in terms of the unknowns left goes in
            found = {
                n: e
                for n, e in before.items()
                if n not in self.free and n in unknowns and set(judge.names(e)) & self.free
            }
            ref = substitute(ref, found)
            sides = step.claim.relations[0].sides if step.claim.relations else ()
            if len(sides) >= 3:  # a value found above, put in as it was shown: "Back into (4): -1.11 + 9.51"
                middle = self._shown_as_names(sides[1], unknowns)
                middle = self._numbers_as_names(middle, before, unknowns)
                if middle is not sides[1].expr:
                    self.line = Add(((1, sides[0].expr), (-1, middle)))
                self.alternatives = [Add(((1, sides[0].expr), (-1, m))) for m in self.alternatives[1:]]
        # an unknown of the equation named that no line above has found is free too:
        # "From (4)" cannot give v_B2 while (4) still holds e
        known = _known_above(judge, step, unknowns)
        self.free |= {n for n in judge.names(ref) if n in unknowns and n not in known}
        self.ref = ref

    def _shown_as_names(self, side: Side, unknowns: frozenset[str]) -> object:
        """The side with each expression that shows a value found above (in its last side,
        as written) read as that unknown: u(3 - 7e)/2 in "Back into (4)" is v_A2."""
        text, names = side.source, {}
        for k, (name, shown) in enumerate(_shown_before(self.judge, self.step).items()):
            if name in unknowns and name not in self.free and len(shown) > 3 and text.count(shown) == 1:
                text = text.replace(shown, rf"\left(Q_{{{k}}}\right)")
                names[f"Q_{k}"] = Sym(name)
        if not names:
            return side.expr
        try:
            expr = parse_display(text).relations[0].sides[0].expr
        except (LatexError, IndexError):
            return side.expr
        self.free |= {n.name for n in names.values()}
        return substitute(expr, names)

    def _numbers_as_names(self, line: object, before: dict[str, object], unknowns: frozenset[str]) -> object:
        """The line with each number that shows a value found above read as that unknown."""
        shown: dict[Decimal, object] = {}
        for name, expr in before.items():
            num = expr if isinstance(expr, Num) else None
            if isinstance(expr, Add) and len(expr.terms) == 1 and isinstance(expr.terms[0][1], Num):
                num, sign = expr.terms[0][1], expr.terms[0][0]
            else:
                sign = 1
            if num is None or name not in unknowns or name in self.free or Decimal(num.mantissa) == 0:
                continue
            shown[Decimal(num.mantissa)] = Sym(name) if sign > 0 else Add(((-1, Sym(name)),))
        # a number of the line that shows a found value, perhaps with more figures (9.4354 for
        # 9.435) or fewer (0.6 for -0.600); where two numbers could be it (4 + 4), each is tried
        matches: dict[Decimal, list[Num]] = {}
        for node in walk(line):
            if isinstance(node, Num) and not node.degrees and not node.exponent:
                mine = Decimal(node.mantissa)
                for value in shown:
                    longer = -mine.as_tuple().exponent >= -value.as_tuple().exponent
                    half = Decimal(1).scaleb(value.as_tuple().exponent) / 2
                    if mine == value or (longer and abs(mine - value) <= half):
                        matches.setdefault(value, []).append(node)
        if not matches:
            return line
        choices = [[(n, shown[v]) for n in nodes] for v, nodes in matches.items()]
        for picked in itertools.islice(itertools.product(*choices), 4):
            by_id = {id(n): tree for n, tree in picked}
            self.alternatives.append(rebuild(line, lambda n, by_id=by_id: by_id.get(id(n))))
        self.free |= {n for alt in self.alternatives for n in self.judge.names(alt) if n in unknowns}
        return self.alternatives[0]

    def point(self, k: int) -> dict[str, object]:
        out = {}
        for i, name in enumerate(sorted(self.free)):
            q = self.judge.quantity(name, self.scopes)
            base = q.value if q is not None and q.value is not None else CTX.mpf(1)
            scale = max(CTX.mpf(1), abs(base))
            out[name] = base + STEPS[(k + i) % len(STEPS)] * scale
        return out

    def value(self, tree: object, point: dict[str, object]) -> Value:
        return self.judge.value(Side(tree), self.scopes, overrides=point)

    def reasons(self) -> Iterator[str]:
        first = list(self._reasons())
        for other in self.alternatives:  # another reading of which number is the value found
            if not first:
                break
            self.line = other
            if not list(self._reasons()):
                first = []
        yield from first

    def _reasons(self) -> Iterator[str]:
        if self.line is None or self.ref is None:
            return
        if self.free and not set(self.judge.names(self.ref)) & self.free:
            named = " and ".join(f"({t})" for t in self.step.tags)
            yield f"{named} has none of the unknowns of the line under it ({', '.join(sorted(self.free))})"
            return
        pts = [self.point(k) for k in range(len(STEPS))]
        shown = [self.value(self.line, p) for p in pts]
        ref = [self.value(self.ref, p) for p in pts]
        yield from self._cancels(pts[0], ref[0])
        yield from self._proportional(shown, ref)

    def _cancels(self, p0: dict[str, object], r0: Value) -> Iterator[str]:
        for name in self.step.cancels:
            if name in set(self.judge.names(self.line)):
                yield f"{name} is said to cancel but is still in the line"
                continue
            moved = self.value(self.ref, {**p0, name: p0.get(name, 0) + max(CTX.mpf(1), abs(p0.get(name, 1)))})
            if abs(moved.center - r0.center) > moved.radius + r0.radius + tolerance(moved, r0):
                what = " + ".join(f"({t})" for t in self.step.tags)
                if self.step.op == "subtract":
                    what = f"({self.step.tags[1]}) - ({self.step.tags[0]})"
                yield f"{name} does not cancel in {what}"

    def _proportional(self, shown: list[Value], ref: list[Value]) -> Iterator[str]:
        k = max(range(len(ref)), key=lambda i: abs(ref[i].center))
        what = {"add": "the sum of", "subtract": "the difference of", "into": "substitution into"}.get(self.step.op, "")
        what = "the combination of" if self.step.op.startswith("multiply") else what
        named = " and ".join(f"({t})" for t in self.step.tags)
        if all(abs(r.center) <= tolerance(r) for r in ref) and any(
            abs(x.center) > x.radius + tolerance(x) for x in shown
        ):
            yield f"the line does not follow from {what} {named}: it reads 0 = 0 there".replace("  ", " ")
            return
        if abs(ref[k].center) <= ref[k].radius + tolerance(ref[k]):
            # the equation named is nothing in these unknowns; say so only when that is exact
            # (not when its rounded numbers leave it undecided)
            if not ref[k].radius and any(abs(s.center) > s.radius + tolerance(s) for s in shown):
                yield f"the line does not follow from {what} {named}".replace("  ", " ")
            return
        c = shown[k].center / ref[k].center
        dc = (shown[k].radius + abs(c) * ref[k].radius) / abs(ref[k].center)
        if self.step.op not in ("from", "into") and abs(abs(c) - 1) > dc + TOLERANCE_C:
            yield f"the line is not {what} {named} (it is {float(c):.4g} times it)"
            return
        for s, r in zip(shown, ref, strict=True):
            slack = s.radius + abs(c) * r.radius + abs(r.center) * dc + tolerance(s) + abs(c) * tolerance(r)
            if abs(s.center - c * r.center) > slack or not c:
                yield f"the line is not {what} {named}".replace("  ", " ")
                return


def check(judge: Judge) -> Iterator[Failure]:
    """Equation numbers used once, named only when they are above, and doing what is said."""
    tagged: dict[str, Claim] = {}
    for claim in judge.claims:
        tag = claim.display.tag if claim.display is not None else None
        if tag is None:
            continue
        if tag in tagged:
            line = claim.line
            yield Failure(line.number, line.latex, RULE, f"({tag}) numbers two equations", line.scope)
        else:
            tagged[tag] = claim
    for step in steps(judge):
        line = step.claim.line
        reason = _missing(step, tagged)
        if reason is None and step.op == "together":
            reason = _together(judge, step, tagged)
        elif reason is None:
            try:
                reason = next(_Operation(judge, step, tagged).reasons(), None)
            except (Unresolved, Undefined, ZeroDivisionError):
                reason = None
        if reason:
            yield Failure(line.number, line.latex, RULE, f"{line.sentence} {reason}", line.scope)


def _together(judge: Judge, step: Step, tagged: dict[str, Claim]) -> str | None:
    """ "Solve (3) and (4) together": distinct equations, each with an unknown that the
    lines under the sentence find, and together all of them."""
    if len(set(step.tags)) != len(step.tags):
        return "— an equation is named twice"
    scopes = judge.chain_of(step.claim.line.scope)
    unknowns = scopes[0].unknowns()
    found = set()
    for claim in judge.claims:
        if claim.line.block == step.claim.line.block and claim.relations:
            first = claim.relations[0].sides[0].expr
            if isinstance(first, Sym) and first.name in unknowns:
                found.add(first.name)
    named: set[str] = set()
    for t in step.tags:
        eq = _equation(tagged[t])
        names = set(judge.names(eq)) & unknowns if eq is not None else set()
        if found and not names & found:
            return f"— ({t}) has none of the unknowns found here ({', '.join(sorted(found))})"
        named |= names
    if found - named:
        return f"— no equation named has {', '.join(sorted(found - named))}"
    return None


def _missing(step: Step, tagged: dict[str, Claim]) -> str | None:
    here = step.claim.line
    for t in step.tags:
        target = tagged.get(t)
        if target is None or target.line.number >= here.number:
            return f"— ({t}) is not an equation above this line"
        if target.line.scope != here.scope:
            where = target.line.scope or "another part of the page"
            return f"— ({t}) is an equation of {where}, not of this one"
    return None
