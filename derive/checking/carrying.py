"""What a student carries on after a slip: the numbers written wrong, the own values of names
got wrong, and whether a later line is worked from them (a carried error, not a new mistake).

:class:`Carrying` is the part of :class:`~.lines.Trace` that keeps them; the trace judges a
line, and asks these whether what makes it hold, or look right, is the student's own wrong
number carried on.
"""

from __future__ import annotations

import re
from dataclasses import replace
from decimal import Decimal

import sympy

from derive.checking import figures, wholesides
from derive.checking.context import Context
from derive.checking.dependency import GOES_ON, Depending, side_value
from derive.checking.figures import literal_tolerance
from derive.checking.inference import Read
from derive.checking.misread import with_copied
from derive.checking.naming import Open, read_side, rewrite
from derive.checking.numeric import decimals, number_of
from derive.checking.ownresults import worked_from_own
from derive.checking.putback import independent
from derive.checking.relations import Point, Values
from derive.checking.worlds import NUMBER_SIDE, Pair, written_right
from derive.mathtext.notation import student
from derive.problem.expr import ParseError

Line = Read


#: A value in the symbolic givens as written: ``5u``, ``-4u/3``, ``0.5mu``.
_TERM = re.compile(r"^[-+]?((?:\d+\.?\d*)[A-Za-z]{1,2}(?:/\d+)?)$")


def together(G: sympy.Expr, U: tuple[sympy.Symbol, ...]) -> bool:
    """Whether ``G = 0`` says two velocities after are equal (u1 - u2 = 0), and nothing more."""
    x = sympy.expand(G)
    pair = [u for u in U if x.has(u)]
    return len(pair) == 2 and sympy.expand(x - (pair[0] - pair[1])) in (0, -2 * (pair[0] - pair[1]))


#: A number in powers of ten as written: ``4.20 * 10^(-4)``, ``4.20e-4``.
_POWER = re.compile(r"^\s*(\d+\.?\d*)\s*(?:(?:\*|×|x)\s*10\s*\^\s*\(?\s*([-+−]?\d+)\s*\)?|[eE]([-+]?\d+))\s*$")


def _other_forms(side: str) -> set[str]:
    """The same number written the other way, so that a later line that writes it is seen to
    use it: ``4.20 * 10^(-4)`` is also ``0.000420``, and ``0.000420`` is ``4.20`` × 10⁻⁴."""
    text = side.strip().lstrip("+-−")
    m = _POWER.match(text)
    if m:
        d = Decimal(m.group(1)).scaleb(int((m.group(2) or m.group(3)).replace("−", "-")))
        return {f"{d:f}"} if "." in f"{d:f}" else set()
    m = re.fullmatch(r"0\.(0+)([1-9]\d*)", text)
    if m and len(m.group(2)) > 1:
        return {f"{m.group(2)[0]}.{m.group(2)[1:]}"}
    return set()


def _slack(side: str) -> float:
    """The relative slack of a step of numbers: ±1 in the last place of a number as written
    (0.6 for 0.5999), the decimals' own slack for a side that is worked."""
    m = NUMBER_SIDE.match(student(side.strip()))
    if m is None or m.group(3):
        return literal_tolerance(side, set()) + 1e-9
    d = Decimal(m.group(2))
    return float(figures.last_place(d) / abs(d)) + 1e-9 if d else 1e-9


#: A side of decimals each times the same one letter (``0.7071v - 0.6718v``): its numbers, and the letter.
_PER_LETTER = re.compile(r"^\s*[-+]?\s*\d+\.\d+\s*([A-Za-z])(?:\s*[-+]\s*\d+\.\d+\s*\1)+\s*$")


def _per_letter_slack(side: str, data: set) -> float:
    """The relative slack of a side of rounded decimals each times the same letter, worked as one
    number (``0.7071v - 0.6718v = 0.0353v``: ±0.0001v on 0.0353v, the last digits of both carried
    through the subtraction, not the last digit of either); 0 for any other side."""
    m = _PER_LETTER.match(side)
    if m is None:
        return 0.0
    numbers = re.sub(rf"(?<=\d)\s*{m.group(1)}", "", side)
    value, slack = side_value(numbers), figures.side_slack(numbers, data, side_value)
    return slack / abs(value) if value and slack else 0.0


class Carrying(Depending):
    """The numbers and values the student got wrong so far, and the tests that use them."""

    ctx: Context
    U: tuple[sympy.Symbol, ...]
    pts: list[Point]
    truth: list[Values]
    world: list[Values] | None
    wrong_values: set[str]
    wrong_numbers: set[str]
    stated: dict[int, set[str]]
    wrong_terms: set[str]
    own: dict[sympy.Symbol, sympy.Expr]
    wrong_number: tuple[str, sympy.Expr] | None
    #: The wrong numbers before the last (a vector's two components, both worked wrong), the latest first.
    earlier_numbers: tuple[tuple[str, sympy.Expr], ...] = ()
    wrong_amounts: list[float]
    right_terms: dict[str, sympy.Expr]

    def pairs(self, line: Line) -> list[Pair]:  # pragma: no cover - the trace's
        raise NotImplementedError

    def holds(self, pairs: list[Pair], values: list[Values]) -> bool:  # pragma: no cover - the trace's
        raise NotImplementedError

    def _tolerance(self, sides: tuple[str, ...], raw: list[sympy.Expr], ik: tuple[int, int], worked: str) -> float:
        """The relative slack of the pair of sides ``ik``: each rounded decimal's last digit,
        carried through the arithmetic of a side of numbers only (so a number near the value
        from another formula, ``½(0.020)(300 - 1.49)²`` for 900 - 4.48, is not within it)."""
        texts = [sides[j] for j in ik]
        exact = _whole_numbers(texts, raw, ik)
        if exact is not None:  # 6750 + 792 = 7452: whole numbers added are exact, not 7542 at 3 figures
            return exact
        whole = literal_tolerance(f"{' = '.join(texts)} {worked}", self.ctx.data)
        plain = [j for j in ik if not raw[j].free_symbols and number_of(raw[j]) is not None]
        values = [abs(complex(number_of(raw[j]))) for j in plain]  # type: ignore[arg-type]
        if not plain or max(values) == 0:
            return max([whole, *(_per_letter_slack(sides[j], self.ctx.data) for j in ik)])
        slack = [figures.side_slack(sides[j], self.ctx.data, side_value) for j in plain]
        if any(x is None for x in slack):
            return whole
        rest = literal_tolerance(" ".join([*(sides[j] for j in ik if j not in plain), worked]), self.ctx.data)
        return min(whole, sum(x for x in slack if x is not None) / max(values) + rest)

    #: Whether the relation judged last was wrong or carried (a line that goes on from it with
    #: "= ..." works on its wrong value).
    went_wrong = False
    previous: tuple[str, list[Pair]] | None = None  # the relation just before, if it held
    worked: tuple[Pair, ...] = ()  # the carried relations in the unknowns, so far
    displaced: tuple[int, sympy.Expr] | None = None  # the equation the last slip took the place of
    said: dict[sympy.Expr, sympy.Expr] = {}  # noqa: RUF012 - the results as last said (replaced, never changed)
    wrong_forms: dict[sympy.Expr, sympy.Expr] = {}  # noqa: RUF012 - forms in letters worked wrongly, as written
    unrefined: tuple[int, list[Values]] | None = None  # the world before a carried line's rounding refined it
    right_values: frozenset[str] = frozenset()  # the decimals written on lines judged correct

    def _note(self, line: Line, status: str) -> None:
        """What a relation judged ``status`` leaves for the lines after it."""
        self._note_stated(line, status)  # the value its head comes to (:mod:`.dependency`)
        held = status in ("correct", "carried")
        pairs = self.pairs(line) if held else []
        if status == "correct":  # "(0.150 - 70.0)/(70.15) * 35.0": numbers the student has right
            self.right_values = self.right_values | decimals(line.sides)
        self.previous = (" = ".join(line.sides), pairs) if held else None
        self.went_wrong = status in ("wrong", "carried")
        if status == "carried":  # a student's own value (a = (5 - 3e)u/3 after a slip), kept by a later slip
            self.worked += tuple(p for p in pairs if p.difference.free_symbols & set(self.U))
        first = line.exprs[0] if held and line.exprs and len(line.exprs) >= 2 else None
        results = {s for s, _x in self.ctx.derived().values()} if isinstance(first, sympy.Symbol) else set()
        if first in results:  # "KE after = … = ⅛mu²[(e - 1)² + (1 + e)²]"
            self.said = {**self.said, first: line.exprs[-1]}  # type: ignore[index, misc]
            if status == "carried":  # "KE after = ¼mu²(e² - e + 1)" from a form worked wrongly: its own value
                self.own[first] = line.exprs[-1]  # type: ignore[index]

    def _continues(self, line: Line) -> bool:
        """Whether ``line`` goes on from a wrong or carried line (``= u(1 + kλ)/(ku(1 + λ))`` under
        ``e = w/(u(1 + λ))`` with the approach wrong): right as algebra, it carries the slip."""
        return self.went_wrong and GOES_ON.match(line.written) is not None

    def _wrote_wrong(self, line: Line) -> None:
        """The numbers a wrong or carried line states: its last side, and any side that is a
        number as written (``v_t = (61.0 - 45.75)/25 = 0.61 = v_A2t``); a last side that is working
        (``= 2(70.0)/(70.15) * 35.0``) states none of the numbers the student had right before."""
        stated = [s for s in line.sides[:-1] if NUMBER_SIDE.match(student(s.strip()))]
        last = set(decimals(line.sides[-1:]))
        if line.sides and not NUMBER_SIDE.match(student(line.sides[-1].strip())):
            last -= self.right_values
        self.wrong_values |= decimals(stated) | last
        self.wrong_values |= _other_forms(line.sides[-1]) if line.sides else set()
        self.wrong_numbers |= set(re.findall(r"\d+\.?\d*", line.sides[-1]))
        self.stated.setdefault(line.number, set()).update(re.findall(r"\d+\.?\d*", line.sides[-1]))
        last = line.exprs[-1] if line.exprs else None
        value = number_of(last) if last is not None and not last.free_symbols else None
        if value is not None and abs(value.imag) < 1e-12 and value.real != 0:
            self.wrong_amounts.append(value.real)  # "= 0.01 x 89108" on the next line goes on from it
        term = _TERM.match(line.sides[-1].replace(" ", "").replace("*", ""))
        if term and line.exprs and line.exprs[-1].free_symbols and not set(self.U) & line.exprs[-1].free_symbols:
            self.wrong_terms.add(term.group(1))  # "w = 5u": a value in the symbolic givens

    def _own_value(self, line: Line) -> None:
        """``u_n = 28 cos 45 = 14.7`` wrong: the student's own value of u_n, for the lines after."""
        left = line.exprs[0] if line.exprs else None
        term = _TERM.match(line.sides[-1].replace(" ", "").replace("*", "")) if len(line.sides) >= 2 else None
        if term and line.exprs and len(line.exprs) >= 2 and not self._in_unknowns(line.exprs[-2:]):
            self.right_terms[term.group(1)] = line.exprs[-2]  # "μ = 3m·6m/9m = 3m": 3m, where 2m is right
        m = NUMBER_SIDE.match(student(line.sides[-1].strip())) if line.sides else None
        if isinstance(left, sympy.Symbol) and m and not m.group(3) and len(line.sides) >= 2:
            self.own[left] = sympy.Rational(m.group(1) + m.group(2))
        elif isinstance(left, sympy.Symbol) and len(line.exprs or ()) >= 2 and line.exprs[-1].is_number:
            self.own[left] = line.exprs[-1]  # "ΔT = ½(2)(5 + 1)² + ½(1)(-5 - 7)²": worked on the next line
        elif isinstance(left, sympy.Symbol) and len(line.exprs or ()) >= 2 and line.exprs[-1].free_symbols:
            last = line.exprs[-1]  # "KE before = … = 28m": a value in the symbolic givens
            if not self.ctx.in_unknowns(last).free_symbols & set(self.U) and (last.is_Mul or left in self.U):
                self.own[left] = last
            elif left in {s for s, _x in self.ctx.derived().values()} and left not in last.free_symbols:
                self.own[left] = last  # "KE after = ½(6m)v_A² + ½(3m)v_B²": the student's own formula of it
        elif left is not None and len(line.exprs or ()) >= 2:
            self._worked_result(left, line.exprs[-1])

    def _in_unknowns(self, exprs: tuple[sympy.Expr, ...]) -> bool:
        return any(self.ctx.in_unknowns(x).free_symbols & set(self.U) for x in exprs)

    def _with_terms_put_right(self, line: Line) -> bool:
        """Whether ``line`` holds once a value in letters the student worked wrongly, written
        again on it (``½(3m)(1 - e²)u²`` after ``μ = 3m·6m/9m = 3m``), is put right (2m)."""
        if not self.right_terms or not line.exprs:
            return False
        names = Open({n: s for n, (s, _d) in self.ctx.equation_names().items()})
        exprs, changed = list(line.exprs), False
        for i, side in enumerate(line.sides):
            text = side
            for term, right in self.right_terms.items():
                text = re.sub(rf"(?<![\w.]){re.escape(term)}(?![\w.])", f"({sympy.sstr(right)})", text)
            if text == side:
                continue
            try:
                exprs[i] = read_side(rewrite(text, set(names.known)), names, i == 0, i == len(line.sides) - 1)
            except (ParseError, ValueError, TypeError, RecursionError):
                return False
            changed = True
        if not changed or names.placeholders:
            return False
        fixed = self.pairs(replace(line, exprs=tuple(exprs)))
        for world in [w for w in (self.world, self.truth) if w is not None]:  # a formula of the givens only
            pairs = zip(self.pairs(line), fixed, strict=True)  # each step right as written, or put right
            if all(self.holds([p], world) or self.holds([q], world) for p, q in pairs):
                return True
        return False

    def _worked_result(self, first: sympy.Expr, last: sympy.Expr) -> None:
        """``½(3m)(2u)^2 + ½mu^2 = … = 7/2 mu^2`` under a heading "KE before": a first side
        that is a result's true value (here T_1, 13/2 mu^2) worked to a wrong last one is the
        student's value of that result."""
        if set(self.U) & (first.free_symbols | self.ctx.in_unknowns(last).free_symbols):
            return
        x = number_of(first.xreplace(self.pts[0]))
        for name in ("T_1", "T_2", "T_lost", "J_n"):
            sym, _expr = self.ctx.derived().get(name, (None, None))
            true = number_of(self.ctx.in_unknowns(sym).xreplace(self.pts[0]).xreplace(self.truth[0])) if sym else None
            if x is not None and true is not None and abs(x - true) <= 1e-9 * max(abs(true), 1e-12):
                self.own[sym] = last
                return

    def _with_own_values(self, line: Line) -> bool:
        """Whether ``line`` holds with the values the student got wrong earlier put in (as
        their lines stated them, :mod:`.dependency`, or as :meth:`_own_value` kept them)."""
        if self._holds_with_stated(line):
            return True
        worked = {n: y for n, x in self.said.items() if n not in self.own and (y := x.xreplace(self.wrong_forms)) != x}
        own = {**self.own, **worked}  # a result said right, worked on with a form the student got wrong
        if not own or not line.exprs:
            return False
        d = self.ctx.derived()  # the energy lost is T_1 - T_2, whichever of them the student got wrong
        lost = {d["T_lost"][0]: d["T_1"][0] - d["T_2"][0]} if "T_lost" in d else {}
        exprs = tuple(x.xreplace(own).xreplace(lost).xreplace(own) for x in line.exprs)  # own T_lost first
        givens = {g.symbol: x for g in self.ctx.problem.givens if (x := own.get(g.symbol)) is not None}
        put = tuple(with_copied(self.ctx, x, givens) for x in exprs)  # a given written wrongly (0.22 kg for
        if put == line.exprs:  # 22 g), in a result worked from it (KE_i = ½(0.22)(3.5)²)
            return False
        world = self.world or self.truth  # else the result worked from them (T_2 = T_1 - own T_lost)
        return self.holds(self.pairs(replace(line, exprs=put)), world) or worked_from_own(self, line, exprs)

    def _uses_wrong_numbers(self, line: Line, pairs: list[Pair]) -> bool:
        """A line of numbers only, right as arithmetic, worked from numbers the student got wrong
        earlier (``sqrt(12.2^2 + 9.15^2) = 15.25`` after ``v_B2n = 12.2``): carried, not correct;
        so is one in the unknowns that holds given the slip too (``v_B = sqrt(71.0^2 + 108.3^2)
        = 129.5``, near the true 128.9 only because the t component is the larger)."""
        if self.world is not None and self._writes_copied(line) and self.holds(pairs, self.world):
            return True  # 0.3 = (v_B2 - v_A2)/(19.567 - 0): the given as copied, put in
        if wholesides.slip_exact(self, pairs):
            return True  # v = 3 where the slip gives 3 exactly and the truth is 3.45
        working = " ".join(line.sides[:-1]).replace(" ", "").replace("*", "")
        terms = any(re.search(rf"(?<![\w.]){re.escape(t)}(?!\w)", working) for t in self.wrong_terms)
        # a decimal the problem types (0.0400 kg) is the data, though a wrong value came to it; not written -35.0
        typed = {g.typed for g in self.ctx.problem.givens if g.typed} - set(re.findall(r"-\s*(\d+\.\d+)", working))
        if not (decimals(line.sides[:-1]) & self.wrong_values) - typed and not terms and not self._wrong_integers(line):
            return self._goes_on(line, pairs)
        if any(p.difference.free_symbols & set(self.U) for p in pairs):
            if self.world is not None and self.holds(pairs, self.world) and self._moved(pairs):
                return True
            return self._with_own_values(line)  # ΔKE = KE_f - KE_i = 0.000420 - 91.875 after KE_f wrong
        return not independent(self, line)  # 0.7776/2.16 = 36 % after both energies without the ½

    def _writes_copied(self, line: Line) -> bool:
        """Whether ``line`` writes, on any side, a decimal given as the student copied it wrongly."""
        written = {number_of(sympy.Float(d)) for d in decimals(line.sides)}
        return any(number_of(v) in written for v in self.copied.values() if not v.free_symbols)

    def _wrong_integers(self, line: Line) -> bool:
        """Whether the working of ``line`` has a whole number the student wrote as the value of a
        wrong or carried line (``74250 - 1350 = 72900`` after ``KE before = … = 74250`` worked
        with the weights as masses): two figures or more, and not a number of the problem's data."""
        found = re.findall(r"(?<![\w.])\d+(?![\w.])", " ".join(line.sides[:-1]))
        return any(
            t in self.wrong_numbers and len(t.strip("0")) >= 2 and sympy.Integer(t) not in self.ctx.data for t in found
        )

    def _goes_on(self, line: Line, pairs: list[Pair]) -> bool:
        """Whether a line of numbers only goes on from the value a wrong or carried line came
        to (``= 0.01 x 89108`` under ``KE lost = ½(0.020)(300 - 1.49)² ``): a side of it is that
        value, at the precision the line is written with."""
        if not self.wrong_amounts or not line.exprs or any(p.difference.free_symbols & set(self.U) for p in pairs):
            return False
        tol = max((p.tol for p in pairs), default=0.0)
        for x in line.exprs[:1]:
            v = number_of(x) if not x.free_symbols else None
            if v is None or abs(v.imag) >= 1e-12:
                continue
            if any(abs(v.real - w) <= max(2 * tol, 1e-9) * abs(w) for w in self.wrong_amounts[-1:]):
                return True
        return False

    def _moved(self, pairs: list[Pair]) -> bool:
        """Whether the slip moves the value of a side of ``pairs`` (a kinetic energy lost from
        the speeds is the same whichever way the rebound is signed: it does not depend on it)."""
        assert self.world is not None
        for p in pairs:
            for side in (p.left, p.right):
                a, b = (number_of(side.xreplace(self.pts[0]).xreplace(v[0])) for v in (self.truth, self.world))
                if a is not None and b is not None and abs(a - b) > 1e-9 * max(abs(a), abs(b), 1e-12):
                    return True
        return False

    def _number_wrong(self, bad: Pair) -> None:
        """The number written wrong in ``bad``, a pair with no unknowns (``294.855/25 = 11.97``):
        kept with its right value where that is the same at every sample point, so that the
        lines worked from it are carried (:meth:`_carries_number`)."""
        left, right = (number_of(x.xreplace(self.pts[0])) for x in (bad.left, bad.right))
        if bad.raw is not None and (bad.left.free_symbols or bad.right.free_symbols) and not bad.raw[0].is_Symbol:
            self.wrong_forms = {**self.wrong_forms, bad.raw[0]: bad.raw[1]}  # (1 + e)² + (e - 1)² = 2e² - 2e + 2
        if left is None or right is None or bad.left.free_symbols or bad.right.free_symbols:
            return
        sides = bad.text.split(" = ")
        if self.wrong_number is not None:
            self.earlier_numbers = (self.wrong_number, *self.earlier_numbers[:2])
        if NUMBER_SIDE.match(sides[1]):
            self.wrong_number = (sides[1], bad.left)
        elif NUMBER_SIDE.match(sides[0]):
            self.wrong_number = (sides[0], bad.right)
        elif abs(right.imag) < 1e-12 and right.real != 0:  # working on both sides (a vector's component in
            self.wrong_number = (f"{right.real:.12g}", bad.left)  # the student's axes): the later side's value

    def _carries_number(self, line: Line) -> bool:
        """Whether ``line`` is true once the wrong number of an arithmetic slip is put right, or says again one a slip
        before it wrote (``u_B = 55.00 i + 95.26 j`` has two); a number written with its sign is put right with it."""
        assert self.wrong_number is not None
        if not self._carries_one(line, *self.wrong_number) and not any(
            self._carries_one(line, *n, only_said=True) for n in self.earlier_numbers
        ):
            return False
        self._wrote_wrong(line)  # its numbers are the student's wrong ones, as a carried line's are
        return True

    def _carries_one(self, line: Line, wrong: str, right: sympy.Expr, only_said: bool = False) -> bool:
        value = number_of(right.xreplace(self.pts[0]))
        if value is None:
            return False
        try:
            written = sympy.Rational(wrong.lstrip("+-"))
        except (TypeError, ValueError):
            return False
        if only_said:
            return self._restates(line, written, value.real)
        size = sympy.Float(-value.real if wrong.lstrip().startswith("-") else value.real, 20)  # -68.85: 68.85 is 69.85
        exprs = tuple(x.xreplace({written: size, -written: -size}) for x in line.exprs or ())
        if exprs != line.exprs and self.holds(self.pairs(replace(line, exprs=exprs)), self.truth):
            return True
        return self._worked_on(line, wrong.lstrip("+-"), float(size)) or self._restates(line, written, value.real)

    def _restates(self, line: Line, wrong: sympy.Rational, right: float) -> bool:
        """``J ≈ 0.238`` after ``0.060 × (-39.6) = -0.2376`` (2.376): the wrong number said again,
        rounded and maybe as a size, for a quantity: true once its right value is put in its place;
        worked again in numbers first, right as arithmetic (``u_B · n̂ = 55.00 cos 20° + 95.26 sin 20°
        = 84.26`` after the vector ``u_B = 55.00 i + 95.26 j`` written wrong)."""
        if not line.exprs or len(line.exprs) < 2 or not line.exprs[0].free_symbols or right == 0:
            return False
        numbers = replace(line, sides=line.sides[1:], exprs=line.exprs[1:])  # "u_B · n = 55 cos 20 + … = 84.26"
        if len(line.exprs) > 2 and (
            self._in_unknowns(numbers.exprs) or not self.holds(self.pairs(numbers), self.truth)
        ):
            return False
        line = replace(line, sides=(line.sides[0], line.sides[-1]), exprs=(line.exprs[0], line.exprs[-1]))
        m = NUMBER_SIDE.match(student(line.sides[-1].strip()))
        if m is None or m.group(3) or not written_right(Decimal(m.group(2)), sympy.Float(abs(wrong), 20)):
            return False
        put = sympy.Float(abs(right) * (-1 if m.group(1) == "-" else 1), 20)
        for fixed in (put, -put):  # the size of the right value, or the value with its sign
            if self.holds(self.pairs(replace(line, exprs=(line.exprs[0], fixed))), self.truth):
                return True
        return False

    def _worked_on(self, line: Line, wrong: str, right: float) -> bool:
        """``v_A2 = 1.3(11.97) - 0.3(19.657) = 9.664`` after ``V = … = 11.97`` (11.79), or
        ``3.564 - 3 = v_A2n + v_B2n`` after ``4 cos 30 = 3.564``: the wrong number put into a
        right formula and worked on: the side in the unknowns equals the first side of numbers
        that has it once that number is put right, and each step of numbers after that side
        is right as written."""
        exprs, token = line.exprs or (), rf"(?<![\w.]){re.escape(wrong)}(?![\w.]|\d)"
        unknown = [i for i, x in enumerate(exprs) if self.ctx.in_unknowns(x).free_symbols & set(self.U)]
        at = next((i for i in range(len(exprs)) if re.search(token, line.sides[i])), None)
        if not unknown or at is None or at in unknown or exprs[at].free_symbols:
            return False
        if at == len(exprs) - 1 and len(exprs) > 2:  # the wrong number is the result: not worked on
            return False
        text, found = line.sides[at], list(re.finditer(token, line.sides[at]))
        put = [re.sub(token, f"({right!r})", text)]  # every one, or one only (0.5196 also B's value before)
        put += [text[: m.start()] + f"({right!r})" + text[m.end() :] for m in found] if len(found) > 1 else []
        worlds, k = [w for w in (self.truth, self.world) if w is not None], unknown[0]
        for fixed in (side_value(t) for t in put):
            pair = replace(line, sides=(line.sides[k], text), exprs=(exprs[k], sympy.Float(fixed or 0, 20)))
            if fixed is not None and any(self.holds(self.pairs(pair), w) for w in worlds):
                break
        else:
            return False
        worked = number_of(exprs[at])
        for side, x in zip(line.sides[at + 1 :], exprs[at + 1 :], strict=True):  # each step at its figures
            if x.free_symbols:
                break
            v = number_of(x)
            if worked is None or v is None or abs(v - worked) > _slack(side) * max(abs(v), abs(worked)):
                return False
        return True


#: A side of whole numbers added or subtracted only (``6750 + 792``, ``45\,000 + 13\,200``).
_WHOLE = re.compile(r"^\s*\d+(?:\s*[+\-−]\s*\d+)*\s*$")


def _whole_numbers(texts: list[str], raw: list[sympy.Expr], ik: tuple[int, int]) -> float | None:
    """The slack of ``a + b = c`` in whole numbers alone (one on each side at least two digits):
    a unit in the last place the result is written to (7540 rounds to tens), as a fraction of
    it; None for any other pair."""
    plain = [re.sub(r"\\[,;:!]|\{,\}|(?<=\d)[ ,](?=\d{3}\b)", "", t) for t in texts]
    if not all(_WHOLE.match(t) for t in plain) or not any(re.search(r"\d\s*[+\-−]\s*\d", t) for t in plain):
        return None
    values = [number_of(raw[j]) for j in ik]
    if any(v is None or v == 0 for v in values):
        return None
    last = plain[-1].strip()
    unit = 10 ** (len(last) - len(last.rstrip("0"))) if last.isdigit() else 1
    return unit / max(abs(complex(v)) for v in values)  # type: ignore[arg-type]
