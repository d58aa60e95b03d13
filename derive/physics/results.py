"""What an impact gives besides the velocities: speeds, directions, kinetic energies, impulse.

Each result keeps its closed form in the givens' symbols and its exact value (or,
where a given stays symbolic, the numbers substituted and the symbols kept).
"""

from __future__ import annotations

import functools
from collections.abc import Callable, Iterator, Mapping
from dataclasses import dataclass
from typing import Any

import sympy

from derive.errors import SolveError
from derive.physics import forms
from derive.physics.energy import HALF
from derive.physics.impact import Impact, evaluate, independent_map
from derive.problem import Problem, units
from derive.symbols import symbol


@dataclass(frozen=True)
class Result:
    """A computed quantity.

    ``closed`` is its closed form in the givens' symbols; ``value`` its exact
    value in the problem's working unit (degrees for angles), or None when it
    depends on a symbolic given, in which case ``partial`` holds the numbers
    substituted and the symbols kept.
    """

    name: str
    symbol: sympy.Symbol
    closed: sympy.Expr
    value: sympy.Expr | None
    partial: sympy.Expr
    unit: str
    description: str

    @property
    def found(self) -> sympy.Expr:
        """Its value, else (a symbolic given in it) its partial form: the numbers in, the symbols kept."""
        return self.value if self.value is not None else self.partial


class Results(Mapping[str, Result]):
    """The results of one impact by name, in order. Each is worked out (evaluated, and
    simplified where symbols stay) when it is first read, then kept: ``derive check`` pays
    only for the results it is asked about (issue #19), a page reads them all. A result
    depends on the impact alone, never on which others were read before it."""

    def __init__(self) -> None:
        self._todo: dict[str, Callable[[], Result]] = {}
        self._done: dict[str, Result] = {}
        #: Where a result exists only for some numbers (a direction: not for a body at rest).
        self._present: dict[str, Callable[[], bool]] = {}

    def put(self, name: str, make: Callable[[], Result], present: Callable[[], bool] | None = None) -> None:
        """Set out result ``name``: ``make`` works it out; ``present`` (when given) says whether it exists."""
        self._todo[name] = make
        if present is not None:
            self._present[name] = present

    def _exists(self, name: str) -> bool:
        if name not in self._todo:
            return False
        test = self._present.get(name)
        if test is not None:  # asked once, then known
            if not test():
                del self._todo[name]
            del self._present[name]
        return name in self._todo

    def __getitem__(self, name: str) -> Result:
        done = self._done.get(name)
        if done is None:
            if not self._exists(name):
                raise KeyError(name)
            done = self._done[name] = self._todo[name]()
        return done

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and self._exists(name)

    def __iter__(self) -> Iterator[str]:
        return iter([name for name in list(self._todo) if self._exists(name)])

    def __len__(self) -> int:
        return sum(1 for _ in self)

    def __repr__(self) -> str:
        return f"Results({', '.join(self)})"


def results(imp: Impact) -> Results:
    """Every result of the impact, in order: unknowns named in the file, velocities after
    the impact (and their speeds and directions), kinetic energies, the impulse, and the
    quantities the file defines from them; each worked out when first read (:class:`Results`)."""
    r = _Collector(imp)
    for g in r.p.givens:
        if g.unknown:
            r.add(
                g.name,
                lambda g=g: r.solved[g.symbol],
                g.unit,
                f"{g.name}, unknown in the file",
                degrees=g.unit == "deg",
            )
    _velocities(r)
    m_A, m_B = _masses(r)
    _energies(r, m_A, m_B)
    nm, p = imp.names, r.p

    def impulse() -> sympy.Expr:
        return sympy.factor_terms(-m_A * (r.full(nm.A2n) - r.full(nm.A1n)))

    r.add("J_n", impulse, working_unit(p, "impulse"), "impulse along +n on B from A (on A it is -J_n)")
    for d in p.asks.defined:  # quantities the file defines from the results (F_avg = J_n/dt)
        before = list(r.out)

        def defined(d: Any = d, before: list[str] = before) -> sympy.Expr:
            known = {r.out[n].symbol: r.out[n].closed for n in before}
            closed = d.expr.xreplace(known)
            _check_defined(d, closed, known, p)
            return closed

        r.add(d.name, defined, d.unit, f"{d.name}, defined in the file", degrees=d.unit == "deg")
    return r.out


def _check_defined(d: Any, closed: sympy.Expr, known: Mapping[sympy.Symbol, sympy.Expr], p: Problem) -> None:
    """A quantity the file defines must work out to a finite real number where the givens are
    numbers: one that divides by a result that is 0 here (``J_n/T_lost`` with e = 1) or takes
    ``acos`` of a number beyond 1 is refused, naming the field and the cause."""
    value = evaluate(closed, p)
    if value.free_symbols and not value.has(sympy.zoo, sympy.nan):
        return
    if not value.free_symbols and value.is_extended_real and value.is_finite:
        return
    field = f"[define] {d.name} = {d.text!r}" if d.text else f"[define] {d.name}"
    raise SolveError(f"{field}: {_why_not_real(d.expr, known, p)}", where=d.where or p.path)


def _why_not_real(expr: sympy.Expr, known: Mapping[sympy.Symbol, sympy.Expr], p: Problem) -> str:
    """Why ``expr`` (in the file's names) is no finite real number here, in the file's terms."""
    for sub in sympy.preorder_traversal(expr):
        if isinstance(sub, sympy.Pow) and sub.exp.is_negative:
            base = evaluate(sub.base.xreplace(known), p)
            if base == 0:
                return f"divides by {sub.base}, which is 0 here"
        if isinstance(sub, (sympy.asin, sympy.acos)):
            arg = evaluate(sub.args[0].xreplace(known), p)
            if arg.is_number and arg.is_real and abs(arg) > 1:
                return f"{sub.func.__name__} of {float(arg):.4g} is not real (its argument must be from -1 to 1)"
    return "does not work out to a finite real number here"


class _Collector:
    """The results of one impact as they are set out, in order (each worked out when read)."""

    def __init__(self, imp: Impact) -> None:
        self.imp, self.p = imp, imp.problem
        self.out = Results()
        self.solved = dict(imp.closed)
        self.varied = {g.symbol for g in self.p.givens if g.name in self.p.vary}

    def full(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` in the givens: pre-impact components resolved, unknowns solved."""
        return self.imp.in_givens(expr).xreplace(self.solved)

    def moving_after(self, comps: dict[str, sympy.Symbol]) -> list[tuple[str, sympy.Expr, sympy.Expr]]:
        """Each body that can move (not a fixed B), with its n and t components after the
        impact (``comps`` by name) in the givens."""
        return [
            (b, self.full(comps[f"v_{b}2n"]), self.full(comps[f"v_{b}2t"])) for b in ("A" if self.p.fixed_B else "AB")
        ]

    def add(
        self,
        name: str,
        closed: Callable[[], sympy.Expr],
        unit: str,
        description: str,
        degrees: bool = False,
        present: Callable[[], bool] | None = None,
    ) -> None:
        """A result from its closed form (made when the result is first read): evaluated,
        simplified where symbols stay, in degrees for an angle; ``present`` says whether it
        exists at all (a direction: not for a body at rest)."""
        self.out.put(name, lambda: self._result(name, closed(), unit, description, degrees), present)

    def _result(self, name: str, closed: sympy.Expr, unit: str, description: str, degrees: bool) -> Result:
        partial = evaluate(closed, self.p)
        # simplify what stays symbolic for the reader; a homework variant's givens are
        # numbers later, so their expressions need no simplifying
        if partial.free_symbols - self.varied and sympy.count_ops(partial) < 150:
            partial = sympy.simplify(partial)
        if degrees and partial.free_symbols and isinstance(partial, sympy.atan2):
            partial = _atan2_number(*partial.args)
        value: sympy.Expr | None = None
        if not partial.free_symbols:
            value = partial * 180 / sympy.pi if degrees else partial
        elif degrees:
            partial = partial * 180 / sympy.pi
        return Result(name, symbol(name), closed, value, partial, unit, description)


def _velocities(r: _Collector) -> None:
    """The velocities after the impact: along n (direct), or by components with speeds and
    directions (oblique), and in x and y where the line of impact is at an angle phi."""
    p, nm = r.p, r.imp.names
    unit_v = working_unit(p, "velocity")
    if not p.oblique:
        r.add("v_A2", lambda: r.full(nm.A2n), unit_v, "velocity of A after the impact, along +n")
        if not p.fixed_B:
            r.add("v_B2", lambda: r.full(nm.B2n), unit_v, "velocity of B after the impact, along +n")
        return
    comps = {"v_A2t": nm.A2t, "v_A2n": nm.A2n, "v_B2t": nm.B2t, "v_B2n": nm.B2n}
    for name, s_ in comps.items():
        body, axis = name[2], name[-1]
        r.add(name, lambda s_=s_: r.full(s_), unit_v, f"velocity of {body} after the impact, {axis} component")
    for b, n, t in r.moving_after(comps):
        r.add(f"v_{b}2", lambda n=n, t=t: sympy.sqrt(n**2 + t**2), unit_v, f"speed of {b} after the impact")
        moving = _moving(n, t, p)
        for angle, y, x, sense in (("theta", n, t, "from +t toward +n"), ("beta", t, n, "from +n toward +t")):
            r.add(
                f"{angle}_{b}2",
                lambda y=y, x=x: sympy.atan2(y, x),
                "deg",
                f"direction of {b} after the impact, {sense}",
                degrees=True,
                present=moving,
            )
    _acute_angles(r, comps)
    if p.phi is not None:
        for b, n, t in r.moving_after(comps):
            c, s_ = r.full(sympy.cos(p.phi)), r.full(sympy.sin(p.phi))  # phi may be an unknown, found

            def x(n: sympy.Expr = n, t: sympy.Expr = t, c: sympy.Expr = c, s_: sympy.Expr = s_) -> sympy.Expr:
                return n * c - t * s_

            def y(n: sympy.Expr = n, t: sympy.Expr = t, c: sympy.Expr = c, s_: sympy.Expr = s_) -> sympy.Expr:
                return n * s_ + t * c

            r.add(f"v_{b}2x", x, unit_v, f"velocity of {b} after the impact, x component")
            r.add(f"v_{b}2y", y, unit_v, f"velocity of {b} after the impact, y component")


def _acute_angles(r: _Collector, comps: dict[str, sympy.Symbol]) -> None:
    """The angles a question asks for in words, each between 0° and 90° (180° for a deflection):

    - ``alpha_A2``: between A's velocity after the impact and the line of centres (n),
      alpha = tan^-1(|v_A2t| / |v_A2n|);
    - ``gamma_A2``: between it and the plane of contact, a wall (t), gamma = 90° - alpha;
    - ``delta_A``: the angle A's velocity turns through in the impact (its deflection),
      delta = atan2(|v_A1 x v_A2|, v_A1 . v_A2), between 0° and 180°.
    """
    p, nm = r.p, r.imp.names
    for b, n, t in r.moving_after(comps):
        moving = _moving(n, t, p)
        for name, y, x, words in (
            (f"alpha_{b}2", t, n, "the line of centres (n)"),
            (f"gamma_{b}2", n, t, "the plane of contact (t), a wall"),
        ):
            r.add(
                name,
                lambda y=y, x=x: sympy.atan2(sympy.Abs(y), sympy.Abs(x)),
                "deg",
                f"acute angle between the velocity of {b} after the impact and {words}",
                degrees=True,
                present=moving,
            )
        n1, t1 = r.full(getattr(nm, f"{b}1n")), r.full(getattr(nm, f"{b}1t"))
        before = _moving(n1, t1, p)
        r.add(
            f"delta_{b}",
            lambda n=n, t=t, n1=n1, t1=t1: sympy.atan2(sympy.Abs(t1 * n - n1 * t), t1 * t + n1 * n),
            "deg",
            f"angle the velocity of {b} turns through in the impact (its deflection)",
            degrees=True,
            present=lambda moving=moving, before=before: moving() and before(),
        )


def _masses(r: _Collector) -> tuple[sympy.Expr, sympy.Expr]:
    """The masses in the givens (a fixed B: 0, it has no kinetic energy)."""
    p = r.p
    ind = independent_map(p)
    sym = p.symbols()
    m_A = r.full(sym["m_A"].xreplace(ind))
    m_B = sympy.Integer(0) if p.fixed_B else r.full(sym["m_B"].xreplace(ind))
    return m_A, m_B


def _energies(r: _Collector, m_A: sympy.Expr, m_B: sympy.Expr) -> None:
    """The kinetic energies before and after the impact, and the energy lost.

    Worked in the component symbols the loss is polynomial, so it factors quickly and
    exactly; then the givens go in."""
    p, nm, imp = r.p, r.imp.names, r.imp

    @functools.cache
    def squares() -> dict[str, tuple[sympy.Expr, sympy.Expr, sympy.Expr]]:
        sq = {}
        for b, motion in (("A", p.motion_A), ("B", p.motion_B)):
            n1, n2 = getattr(nm, f"{b}1n"), getattr(nm, f"{b}2n")
            t1, t2 = getattr(nm, f"{b}1t"), getattr(nm, f"{b}2t")
            pre_sq = n1**2 + (t1**2 if p.oblique else 0)
            post_sq = n2**2 + (t2**2 if p.oblique else 0)
            speed_sq = motion.speed**2 if (p.oblique and motion.speed is not None) else imp.in_givens(pre_sq)
            sq[b] = (pre_sq, post_sq, r.full(speed_sq))
        return sq

    def before() -> sympy.Expr:
        sq = squares()
        return HALF * m_A * sq["A"][2] + HALF * m_B * sq["B"][2]

    def after() -> sympy.Expr:
        sq = squares()
        return HALF * m_A * r.full(sq["A"][1]) + HALF * m_B * r.full(sq["B"][1])

    def lost() -> sympy.Expr:
        if imp.inverse:
            return before() - after()
        sq = squares()
        lost_c = HALF * m_A * (sq["A"][0] - sq["A"][1].xreplace(imp.by_components))
        lost_c += HALF * m_B * (sq["B"][0] - sq["B"][1].xreplace(imp.by_components))
        zero = {k: v for k, v in imp.pre.items() if v == 0}
        return sympy.factor_terms(imp.in_givens(forms.factored(lost_c.xreplace(zero))))

    unit_T = working_unit(p, "energy")
    r.add("T_1", before, unit_T, "kinetic energy before the impact")
    r.add("T_2", after, unit_T, "kinetic energy after the impact")
    r.add("T_lost", lost, unit_T, "kinetic energy lost in the impact")


def _moving(n: sympy.Expr, t: sympy.Expr, p: Problem) -> Callable[[], bool]:
    """Whether a body moves after the impact (its direction is defined), asked when it matters."""

    @functools.cache
    def moving() -> bool:
        return not (evaluate(n, p) == 0 and evaluate(t, p) == 0)

    return moving


def _atan2_number(y: sympy.Expr, x: sympy.Expr) -> sympy.Expr:
    """atan2(y, x) as a number when y/x is one and the sign of x is known (4.C.12: v_A1 cancels);
    else with the positive letters both share taken out (a variant's angle in its own numbers)."""
    shared = y.free_symbols & x.free_symbols if x != 0 and y != 0 else y.free_symbols | x.free_symbols
    for s in sorted(shared, key=str):
        if s.is_positive:
            for k in range(1, 5):  # v_A1 or v_A1^2 (a deflection: a product of two velocities)
                ys, xs = sympy.cancel(y / s**k), sympy.cancel(x / s**k)
                if not (ys.has(s) or xs.has(s)):
                    y, x = ys, xs
                    break
    ratio = sympy.simplify(y / x) if x != 0 and _may_be_constant(y / x) else None
    if ratio is not None and ratio.is_number:
        if x.is_positive:
            return sympy.atan(ratio)
        if x.is_negative:
            return sympy.atan(ratio) + (sympy.pi if y.is_nonnegative else -sympy.pi)
    if x == 0 and y.is_positive:
        return sympy.pi / 2
    if x == 0 and y.is_negative:
        return -sympy.pi / 2
    return sympy.atan2(y, x)


def _may_be_constant(expr: sympy.Expr) -> bool:
    """False when ``expr`` takes two different values at two points (it is then no number,
    however simplified): a variant's angle keeps its varied givens, and simplifying their
    ratio only to learn that cost seconds for each angle of an oblique problem."""
    free = sorted(expr.free_symbols, key=str)
    if not free:
        return True
    values = []
    for k in (0, 1):
        point = {s: sympy.Rational(3 + 2 * k + i, 2 + k + 2 * i) for i, s in enumerate(free)}  # positive
        value = sympy.N(expr.xreplace(point), 30)
        if not value.is_Number or not value.is_finite:
            return True
        values.append(value)
    return abs(values[0] - values[1]) <= 1e-20 * (1 + abs(values[0]))


def convert(r: Result, unit_text: str) -> sympy.Expr:
    """A result's value (or closed form) in another unit of the same kind."""

    src, dst = units.parse_unit(r.unit if r.unit != "deg" else "deg"), units.parse_unit(unit_text)
    if src.dim != dst.dim:
        raise SolveError(f"answer_units: {r.name} is {units.describe(src.dim)}, which cannot be shown in {unit_text}")
    return r.found * src.factor / dst.factor


def working_unit(p: Problem, what: str) -> str:
    """The unit results of this kind are worked in (m/s or ft/s, J or ft·lb, ...)."""

    dim = {"velocity": units.VELOCITY, "energy": units.ENERGY, "impulse": units.IMPULSE}[what]
    return units.SYSTEMS[p.system][dim]
