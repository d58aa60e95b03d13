"""Common mistakes in central impact, each as a mistaken version of equations (1)-(4).

A student who makes one of these mistakes writes equations (1)-(4) wrongly (or
resolves the velocities wrongly before writing them), then solves them correctly
and gets wrong numbers. Each mistake here is a function that takes the problem's
correct :class:`Model` and returns a :class:`Variant`: what its equations do
differently (B's velocity negated, the restitution differences reversed, ...), or
None where the mistake cannot happen in that problem (no angle, no weight, no t
components in a direct impact). :func:`outcomes` solves every variant that applies
and changes something, and gives its values by result name (the names of
:attr:`derive.Solution.results`) and its equations with the numbers in, so that
:mod:`derive.check` can name the mistake that reproduces a wrong answer, and the
equation where it enters.

The correct equations come from :func:`derive.impact.setup`; a variant only
changes what the mistake changes.
"""

from __future__ import annotations

import random
import weakref
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field

import sympy

from derive.physics.impact import Impact, equation_numbers, setup
from derive.steps.model import Solution
from derive.symbols import symbol

#: What each of the equations is, in words (the notes' three systems and the impact rule).
EQUATION_TITLES = {
    1: "the t-momentum of A",
    2: "the t-momentum of B",
    3: "the n-momentum of the system A + B",
    4: "the impact rule (restitution)",
}

#: Stand-ins for the n components of the velocities before the impact as the
#: impact rule (4) uses them (one mistake puts the speeds there).
_S_A = sympy.Symbol("approach_A", real=True)
_S_B = sympy.Symbol("approach_B", real=True)
_HALF = sympy.Rational(1, 2)


@dataclass(frozen=True)
class Variant:
    """A mistaken set of equations: only what differs from the correct one.

    ``pre`` maps the components before the impact (``v_A1n`` ...) to their
    expressions in the givens; ``approach`` is what (4) uses for v_A1n and v_B1n;
    ``masses`` are (m_A, m_B) as the equations use them; ``restitution`` is
    "normal" or "reversed"; ``t_rule`` is "each" (equations (1), (2)), "scaled"
    (v_X2t = e v_X1t) or "system" (one t velocity for both); ``energy`` replaces
    (4) with conservation of kinetic energy (its nontrivial root is e = 1);
    ``values`` overrides the numbers of some givens; ``angles`` is how the
    directions after the impact are computed: "atan2", "other_axis"
    (tan⁻¹(v_t/v_n)) or "principal" (tan⁻¹(v_n/v_t) without the quadrant).
    """

    pre: Mapping[sympy.Symbol, sympy.Expr] | None = None
    approach: tuple[sympy.Expr, sympy.Expr] | None = None
    masses: tuple[sympy.Expr, sympy.Expr] | None = None
    e: sympy.Expr | None = None
    restitution: str = "normal"
    t_rule: str = "each"
    energy: bool = False
    values: Mapping[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    angles: str = "atan2"


@dataclass(frozen=True)
class Mistake:
    """One common mistake: its name, what it is, and where it enters the solution.

    ``enters`` are the equations it changes (none for a direction computed
    wrongly at the end); ``where`` says the same in words; ``phrase`` completes
    "your (4) ...".
    """

    name: str
    title: str
    description: str
    enters: tuple[int, ...]
    where: str
    phrase: str
    build: Callable[[Model], Variant | None]

    def where_in(self, model: Model) -> str:
        """``where`` for this problem: only the equations it has."""
        nums = [k for k in self.enters if k in model.numbers]
        if not self.enters:
            return self.where
        listed = ", ".join(f"({k})" for k in nums)
        return f"{listed}: {self.where}" if listed else self.where


@dataclass(frozen=True)
class Quantity:
    """A result under a set of equations: ``partial`` with the numbers in (symbolic
    givens kept; angles in radians), ``value`` the number in the working unit
    (degrees for angles), or None when a symbolic given remains."""

    partial: sympy.Expr | None
    value: sympy.Expr | None


@dataclass(frozen=True)
class Outcome:
    """The correct equations (``mistake`` None) or a mistaken set, solved.

    ``results`` by result name; ``post`` the velocity components after the impact
    and the unknown givens, numbers in; ``equations`` each equation as
    ``lhs - rhs`` with the numbers in and the unknowns as symbols.
    """

    mistake: Mistake | None
    results: dict[str, Quantity]
    post: dict[sympy.Symbol, sympy.Expr]
    equations: dict[int, sympy.Expr]
    unknowns: tuple[sympy.Symbol, ...]


REGISTRY: dict[str, Mistake] = {}


def mistake(
    name: str, title: str, description: str, enters: tuple[int, ...], where: str, phrase: str
) -> Callable[[Callable[[Model], Variant | None]], Callable[[Model], Variant | None]]:
    """Register a mistake: ``build(model)`` returns its Variant, or None where it does not apply."""

    def register(build: Callable[[Model], Variant | None]) -> Callable[[Model], Variant | None]:
        REGISTRY[name] = Mistake(name, title, description, enters, where, phrase, build)
        return build

    return register


# ---------------------------------------------------------------- the model


class Model:
    """A problem's correct equations and numbers, and the machinery to solve a variant of them."""

    def __init__(self, solution: Solution) -> None:
        p = solution.problem
        self.results = solution.results  # not the solution itself: the cache holds models weakly by solution
        self.problem = p
        self.imp: Impact = setup(p)
        nm = self.nm = self.imp.names
        self.numbers = equation_numbers(p)
        sym = p.symbols()
        self.m_A, self.e = sym["m_A"], sym["e"]
        self.m_B = sym.get("m_B", symbol("m_B", "positive"))
        self.ind = self.imp.independent
        self.numeric = p.numeric()
        post = (nm.A2n, nm.B2n, nm.A2t, nm.B2t)
        self.zeros = {k: v for k, v in self.imp.pre.items() if k in post}
        pre_names = [nm.A1n, nm.B1n] + ([nm.A1t, nm.B1t] if p.oblique else [])
        self.pre = {k: self.imp.pre.get(k, k) for k in pre_names}
        self.unknowns = self.imp.unknowns
        self.inverse = self.imp.inverse
        self._structures: dict[tuple[str, str], dict[sympy.Symbol, sympy.Expr] | None] = {}

    # numbers ------------------------------------------------------------
    def num(self, expr: sympy.Expr, values: Mapping[sympy.Symbol, sympy.Expr] | None = None) -> sympy.Expr:
        """``expr`` with the numeric givens in (``values`` overriding some)."""
        vals = {**self.numeric, **(values or {})}
        return sympy.sympify(expr).xreplace(self.ind).xreplace(vals)

    def is_zero(self, expr: sympy.Expr) -> bool:
        """True when ``expr`` (numbers in) is zero, also at a random point for symbolic givens."""
        v = self.num(expr)
        if v == 0:
            return True
        if v.free_symbols:
            v = v.xreplace(_point(v.free_symbols))
        try:
            return abs(complex(v.evalf(30))) < 1e-20
        except (TypeError, ValueError):
            return False

    def base(self) -> Variant:
        """The correct equations."""
        return Variant()

    # equations ------------------------------------------------------------
    def equations(self, v: Variant) -> dict[int, sympy.Expr]:
        """Equations (1)-(4) of ``v`` as ``lhs - rhs`` in the component symbols, with
        placeholders for the masses, e and (in (4)) the approach components."""
        nm, p = self.nm, self.problem
        mA, mB, e = self.m_A, self.m_B, self.e
        eqs: dict[int, sympy.Expr] = {}
        if p.oblique:
            if v.t_rule == "system":
                eqs[1] = mA * nm.A1t + mB * nm.B1t - mA * nm.A2t - mB * nm.B2t
                eqs[2] = nm.A2t - nm.B2t
            else:
                k = e if v.t_rule == "scaled" else 1
                if 1 in self.numbers:
                    eqs[1] = mA * (k * nm.A1t - nm.A2t)
                if 2 in self.numbers:
                    eqs[2] = mB * (k * nm.B1t - nm.B2t)
        if 3 in self.numbers:
            eqs[3] = mA * nm.A1n + mB * nm.B1n - mA * nm.A2n - mB * nm.B2n
        sep = nm.B2n - nm.A2n if v.restitution == "normal" else nm.A2n - nm.B2n
        eqs[4] = e * (_S_A - _S_B) - sep
        return eqs

    def energy_equation(self) -> sympy.Expr:
        """Kinetic energy before minus after, in the component symbols."""
        nm, p = self.nm, self.problem
        t = (nm.A1t, nm.B1t, nm.A2t, nm.B2t) if p.oblique else (0, 0, 0, 0)
        before = _HALF * self.m_A * (nm.A1n**2 + t[0] ** 2) + _HALF * self.m_B * (nm.B1n**2 + t[1] ** 2)
        after = _HALF * self.m_A * (nm.A2n**2 + t[2] ** 2) + _HALF * self.m_B * (nm.B2n**2 + t[3] ** 2)
        return before - after

    def substitutions(self, v: Variant) -> dict[sympy.Symbol, sympy.Expr]:
        """Placeholders -> what ``v`` puts there (components before, masses, e, approach)."""
        pre = dict(v.pre) if v.pre is not None else dict(self.pre)
        approach = v.approach if v.approach is not None else (pre[self.nm.A1n], pre[self.nm.B1n])
        masses = v.masses if v.masses is not None else (self.m_A, self.m_B)
        subs = {**pre, _S_A: approach[0], _S_B: approach[1], self.m_A: masses[0], self.m_B: masses[1]}
        subs[self.e] = v.e if v.e is not None else self.e
        return subs

    def _structure(self, v: Variant) -> dict[sympy.Symbol, sympy.Expr] | None:
        """The solution of ``v``'s equations in the component symbols (cached by form)."""
        key = (v.restitution, v.t_rule)
        if key not in self._structures:
            eqs = [sympy.expand(x.xreplace(self.zeros)) for x in self.equations(v).values()]
            sol = sympy.solve(eqs, self.unknowns, dict=True)
            ok = len(sol) == 1 and set(sol[0]) == set(self.unknowns)
            self._structures[key] = sol[0] if ok else None
        return self._structures[key]

    def solve(self, v: Variant) -> dict[sympy.Symbol, sympy.Expr] | None:
        """The components after the impact (and unknown givens) under ``v``, numbers in."""
        subs = self.substitutions(v)
        if not self.inverse:
            sol = self._structure(v)
            if sol is None:
                return None
            return {u: self.num(sol[u].xreplace(subs), v.values) for u in self.unknowns}
        eqs = [self.num(x.xreplace(self.zeros).xreplace(subs), v.values) for x in self.equations(v).values()]
        # plain real unknowns: a mistaken e may come out negative, a mistaken mass too
        plain = {u: sympy.Dummy(u.name, real=True) for u in self.unknowns}
        back = {d: u for u, d in plain.items()}
        try:
            found = sympy.solve([sympy.expand(x.xreplace(plain)) for x in eqs], list(plain.values()), dict=True)
        except NotImplementedError:
            return None
        roots = [{back[d]: val for d, val in r.items()} for r in found]
        roots = [r for r in roots if set(r) == set(self.unknowns) and all(_real(r[u]) for u in self.unknowns)]
        if not roots:
            return None
        roots.sort(key=lambda r: -self._plausible(r))
        return roots[0]

    def _plausible(self, root: dict[sympy.Symbol, sympy.Expr]) -> int:
        score = 0
        for u, val in root.items():
            x = _float(val)
            if x is None:
                continue
            if u.name == "e" and 0 <= x <= 1:
                score += 1
            if u.is_positive and x > 0:
                score += 1
        return score

    def outcome(self, v: Variant, m: Mistake | None = None) -> Outcome | None:
        """Solve ``v`` and derive every result of the problem from it."""
        # the correct inverse problem: the solution's physical root
        sol = {u: self._correct(u) for u in self.unknowns} if m is None and self.inverse else self.solve(v)
        if sol is None:
            return None
        nm, p = self.nm, self.problem
        subs = self.substitutions(v)
        post = {}
        for c in (nm.A2n, nm.B2n, nm.A2t, nm.B2t):
            if c is None:
                continue
            post[c] = sol.get(c, self.zeros.get(c, c))
        post = {c: self.num(x, v.values) for c, x in post.items()}
        for u in self.unknowns:
            post[u] = sol[u]
        pre = {c: self.num(subs[c], v.values) for c in self.pre}
        masses = [self.num(subs[self.m_A], v.values), self.num(subs[self.m_B], v.values)]
        if p.fixed_B:
            masses[1] = sympy.Integer(0)
        known = dict(sol)
        masses = [mm.xreplace(known) for mm in masses]
        pre = {c: x.xreplace(known) for c, x in pre.items()}
        res: dict[str, Quantity] = {}

        def put(name: str, expr: sympy.Expr) -> None:
            expr = sympy.sympify(expr).xreplace(known)
            res[name] = Quantity(expr, None if expr.free_symbols else expr)

        for g in p.givens:
            if g.unknown:
                if g.unit == "deg":
                    val = sol[g.symbol]
                    res[g.name] = Quantity(val, None if val.free_symbols else val * 180 / sympy.pi)
                else:
                    put(g.name, sol[g.symbol])
        if p.oblique:
            for name, c in (("v_A2t", nm.A2t), ("v_A2n", nm.A2n), ("v_B2t", nm.B2t), ("v_B2n", nm.B2n)):
                put(name, post[c])
            for b in "AB":
                if b == "B" and p.fixed_B:
                    continue
                n, t = post[getattr(nm, f"{b}2n")].xreplace(known), post[getattr(nm, f"{b}2t")].xreplace(known)
                put(f"v_{b}2", sympy.sqrt(n**2 + t**2))
                if not (n == 0 and t == 0):
                    res[f"theta_{b}2"], res[f"beta_{b}2"] = _angles(n, t, v.angles)
                if p.phi is not None:
                    phi = self.num(p.phi, v.values)
                    put(f"v_{b}2x", n * sympy.cos(phi) - t * sympy.sin(phi))
                    put(f"v_{b}2y", n * sympy.sin(phi) + t * sympy.cos(phi))
        else:
            put("v_A2", post[nm.A2n])
            if not p.fixed_B:
                put("v_B2", post[nm.B2n])
        sq = {}
        for b, (n1, t1, n2, t2) in (
            ("A", (nm.A1n, nm.A1t, nm.A2n, nm.A2t)),
            ("B", (nm.B1n, nm.B1t, nm.B2n, nm.B2t)),
        ):
            before = pre[n1] ** 2 + (pre[t1] ** 2 if t1 is not None else 0)
            after = post[n2] ** 2 + (post[t2] ** 2 if t2 is not None else 0)
            sq[b] = (before, after)
        T1 = _HALF * masses[0] * sq["A"][0] + _HALF * masses[1] * sq["B"][0]
        T2 = _HALF * masses[0] * sq["A"][1] + _HALF * masses[1] * sq["B"][1]
        put("T_1", T1)
        put("T_2", T2)
        put("T_lost", T1 - T2)
        put("J_n", -masses[0] * (post[nm.A2n] - pre[nm.A1n]))
        eqs = self.equations(v)
        if v.energy:
            eqs[4] = self.energy_equation()
        equations = {k: self.num(x.xreplace(self.zeros).xreplace(subs), v.values) for k, x in eqs.items()}
        return Outcome(m, res, post, equations, self.unknowns)

    def _correct(self, u: sympy.Symbol) -> sympy.Expr:
        r = self.results[u.name]
        if r.unit == "deg":
            return r.value * sympy.pi / 180 if r.value is not None else r.partial * sympy.pi / 180
        return r.value if r.value is not None else r.partial


def _real(x: sympy.Expr) -> bool:
    if x.free_symbols:
        return True
    try:
        c = complex(x.evalf(30))
    except (TypeError, ValueError):
        return False
    return abs(c.imag) <= 1e-12 * max(1.0, abs(c.real))


def _float(x: sympy.Expr) -> float | None:
    if x.free_symbols:
        return None
    try:
        return float(sympy.re(x.evalf(30)))
    except (TypeError, ValueError):
        return None


def _point(symbols: set[sympy.Symbol]) -> dict[sympy.Symbol, sympy.Expr]:
    """A fixed, ordinary point for symbolic givens (positive, not special)."""
    rng = random.Random(1729)
    return {s: sympy.Rational(rng.randint(1300, 2900), 1000) for s in sorted(symbols, key=lambda s: s.name)}


def _angles(n: sympy.Expr, t: sympy.Expr, rule: str) -> tuple[Quantity, Quantity]:
    """theta (from +t toward +n) and beta (from +n toward +t) of the direction (n, t)."""
    if rule == "atan2":
        return _direction(n, t, True), _direction(t, n, True)
    if rule == "other_axis":
        return _direction(t, n, False), _direction(n, t, False)
    return _direction(n, t, False), _direction(t, n, False)


def _direction(y: sympy.Expr, x: sympy.Expr, quadrant: bool) -> Quantity:
    """atan2(y, x) (or, without ``quadrant``, tan⁻¹(y/x)) in radians and degrees."""
    if x == 0 and not quadrant:
        return Quantity(None, None)
    if x == 0 and (y.is_positive or y.is_negative):
        rad = sympy.pi / 2 if y.is_positive else -sympy.pi / 2
        return Quantity(rad, rad * 180 / sympy.pi)
    if not (y.free_symbols or x.free_symbols):
        rad = sympy.atan2(y, x) if quadrant else sympy.atan(y / x)
        return Quantity(rad, rad * 180 / sympy.pi)
    ratio = sympy.simplify(y / x) if x != 0 else None
    if ratio is not None and ratio.is_number:
        rad = sympy.atan(ratio)
        if quadrant:
            if x.is_negative:
                rad += sympy.pi if y.is_nonnegative else -sympy.pi
            elif not x.is_positive:
                return Quantity(sympy.atan2(y, x), None)
        return Quantity(rad, rad * 180 / sympy.pi)
    return Quantity(sympy.atan2(y, x) if quadrant else sympy.atan(y / x), None)


# ---------------------------------------------------------------- the mistakes


@mistake(
    "b_sign",
    "B's velocity with the wrong sign",
    "B's velocity before the impact was taken with the wrong sign, as if B moved the other way: "
    "n points from A toward B, so a B moving toward A has v_B1n < 0.",
    (2, 3, 4),
    "B's velocity before the impact, v_B1n (and v_B1t)",
    "has B's velocity with the wrong sign",
)
def b_sign(model: Model) -> Variant | None:
    if model.problem.fixed_B:
        return None
    pre = {k: (-x if k in (model.nm.B1n, model.nm.B1t) else x) for k, x in model.pre.items()}
    if all(model.is_zero(model.pre[k]) for k in model.pre if k in (model.nm.B1n, model.nm.B1t)):
        return None
    return Variant(pre=pre)


@mistake(
    "restitution_reversed",
    "restitution with the differences reversed",
    "The impact rule was written with the relative velocities the wrong way round, "
    "e (v_A1n − v_B1n) = v_A2n − v_B2n: separation is v_B2n − v_A2n, approach v_A1n − v_B1n.",
    (4,),
    "the impact rule",
    "has the relative velocities the wrong way round",
)
def restitution_reversed(model: Model) -> Variant | None:
    return Variant(restitution="reversed")


@mistake(
    "e_speeds",
    "e applied to speeds instead of n components",
    "The impact rule used the speeds before the impact, e (v_A1 − v_B1) = v_B2n − v_A2n, "
    "instead of their n components: restitution relates the normal components only.",
    (4,),
    "the impact rule",
    "applies e to the speeds, not to the n components",
)
def e_speeds(model: Model) -> Variant | None:
    p = model.problem
    if not p.oblique:
        return None
    nm = model.nm
    signed = []
    for motion, n, t, sense in ((p.motion_A, nm.A1n, nm.A1t, 1), (p.motion_B, nm.B1n, nm.B1t, -1)):
        if motion.body == "B" and p.fixed_B:
            signed.append(sympy.Integer(0))
            continue
        speed = motion.speed if motion.speed is not None else sympy.sqrt(model.pre[n] ** 2 + model.pre[t] ** 2)
        sign = sympy.sign(model.num(model.pre[n]).xreplace(_point(model.num(model.pre[n]).free_symbols)))
        signed.append((sign if sign != 0 else sense) * speed)
    if model.is_zero(signed[0] - model.pre[nm.A1n]) and model.is_zero(signed[1] - model.pre[nm.B1n]):
        return None
    return Variant(approach=(signed[0], signed[1]))


@mistake(
    "e_on_t",
    "e applied to the t components",
    "The t components were reduced by e as well (v_A2t = e v_A1t, v_B2t = e v_B1t), as if restitution "
    "acted in the plane of contact: with smooth bodies each t component is unchanged.",
    (1, 2),
    "the t-momentum of each body",
    "applies e to the t components",
)
def e_on_t(model: Model) -> Variant | None:
    if not model.problem.oblique:
        return None
    return Variant(t_rule="scaled")


@mistake(
    "energy_conserved",
    "kinetic energy conserved across the impact",
    "Kinetic energy was taken as conserved across the impact, in place of the impact rule: that holds "
    "only when e = 1, so the velocities are those of a perfectly elastic impact.",
    (4,),
    "the impact rule, replaced by conservation of kinetic energy",
    "conserves kinetic energy instead of applying the impact rule",
)
def energy_conserved(model: Model) -> Variant | None:
    if model.e in model.unknowns:
        return None
    return Variant(e=sympy.Integer(1), energy=True)


@mistake(
    "system_t",
    "the system's t momentum used instead of each body's",
    "The t-momentum of A + B together was conserved in place of each body's, with one t velocity for "
    "both, (m_A + m_B) v_2t = m_A v_A1t + m_B v_B1t: no t force acts on either body, so each keeps its own.",
    (1, 2),
    "the t-momentum of each body",
    "uses the t momentum of the system instead of each body's",
)
def system_t(model: Model) -> Variant | None:
    p = model.problem
    if not p.oblique or p.fixed_B:
        return None
    return Variant(t_rule="system")


def _resolved_with_angle(model: Model) -> list:
    p = model.problem
    return [m for m in (p.motion_A, p.motion_B) if m.angle is not None and m.speed is not None]


@mistake(
    "sin_cos_swapped",
    "sin and cos swapped (angle from the other axis)",
    "The velocities before the impact were resolved with sin and cos swapped, as if the angle were "
    "measured from the other axis (from t instead of n, or from n instead of t).",
    (1, 2, 3, 4),
    "the n and t components before the impact (stage 1), and through them every equation",
    "has sin and cos swapped",
)
def sin_cos_swapped(model: Model) -> Variant | None:
    motions = _resolved_with_angle(model)
    if not model.problem.oblique or not motions:
        return None
    nm, p = model.nm, model.problem
    pre = dict(model.pre)
    for motion, (n, t) in ((p.motion_A, (nm.A1n, nm.A1t)), (p.motion_B, (nm.B1n, nm.B1t))):
        if motion in motions:
            swap = {motion.angle: sympy.pi / 2 - motion.angle}
            pre[n] = model.pre[n].xreplace(swap)
            pre[t] = model.pre[t].xreplace(swap)
    return Variant(pre=pre)


@mistake(
    "angle_other_axis",
    "the direction after the impact from the other axis",
    "The direction after the impact was measured from the other axis, tan⁻¹(v_t/v_n) instead of "
    "θ = tan⁻¹(v_n/v_t) (θ is from +t toward +n, β from +n toward +t).",
    (),
    "the direction after the impact (stage 4)",
    "measures the direction from the other axis",
)
def angle_other_axis(model: Model) -> Variant | None:
    if not model.problem.oblique:
        return None
    return Variant(angles="other_axis")


@mistake(
    "angle_quadrant",
    "the direction after the impact in the wrong quadrant",
    "tan⁻¹(v_n/v_t) was taken at face value where v_t < 0: the direction then lies on the other side, "
    "180° away (the calculator's tan⁻¹ cannot tell).",
    (),
    "the direction after the impact (stage 4)",
    "puts the direction in the wrong quadrant",
)
def angle_quadrant(model: Model) -> Variant | None:
    if not model.problem.oblique:
        return None
    return Variant(angles="principal")


@mistake(
    "degrees_as_radians",
    "degrees read as radians",
    "An angle given in degrees was used as if it were in radians (a calculator in radian mode): "
    "sin 37.6 instead of sin 37.6°.",
    (1, 2, 3, 4),
    "the n and t components before the impact (stage 1), and through them every equation",
    "reads the angle in degrees as radians",
)
def degrees_as_radians(model: Model) -> Variant | None:
    from derive.problem.units import ANGLE

    values = {}
    for g in model.problem.givens:
        if g.dim == ANGLE and g.value is not None and g.definition is None and g.written is None and not g.unknown:
            values[g.symbol] = g.value * 180 / sympy.pi
    if not values:
        return None
    return Variant(values=values)


@mistake(
    "masses_swapped",
    "masses swapped",
    "m_A and m_B were exchanged (in the momentum of the system and the kinetic energies).",
    (3,),
    "the masses in the n-momentum of the system",
    "has the masses swapped",
)
def masses_swapped(model: Model) -> Variant | None:
    if model.problem.fixed_B or model.is_zero(model.m_A - model.m_B):
        return None
    return Variant(masses=(model.m_B, model.m_A))


@mistake(
    "weight_as_mass",
    "weight used as mass",
    "A weight was used as the mass, without dividing by g (m = W/g). With both masses off by the same "
    "factor the velocities can come out right; the kinetic energies and the impulse do not.",
    (3,),
    "the masses, m = W/g (in the momentum and the kinetic energies)",
    "uses the weights as masses",
)
def weight_as_mass(model: Model) -> Variant | None:
    p = model.problem
    values = {}
    for b in "AB":
        try:
            m, w = p.given(f"m_{b}"), p.given(f"W_{b}")
        except KeyError:
            continue
        if w.value is not None and m.value is not None and not m.unknown:
            values[m.symbol] = w.value
    if not values:
        return None
    return Variant(values=values)


# ---------------------------------------------------------------- outcomes


class _Entry:
    """What is cached for one solution: its model, the correct outcome, the mistakes' outcomes."""

    def __init__(self, solution: Solution) -> None:
        self.ref = weakref.ref(solution)
        self.model = Model(solution)
        self.base = self.model.outcome(self.model.base())
        self.found: list[Outcome] | None = None

    def outcomes(self) -> list[Outcome]:
        if self.found is None:
            found = []
            for m in REGISTRY.values():
                variant = m.build(self.model)
                if variant is None:
                    continue
                out = self.model.outcome(variant, m)
                if out is None or self.base is None or not _changes(out, self.base):
                    continue
                found.append(out)
            self.found = found
        return self.found


_CACHE: dict[int, _Entry] = {}


def _cached(solution: Solution) -> _Entry:
    key = id(solution)
    hit = _CACHE.get(key)
    if hit is not None and hit.ref() is solution:
        return hit
    entry = _Entry(solution)
    weakref.finalize(solution, _CACHE.pop, key, None)
    _CACHE[key] = entry
    return entry


def model(solution: Solution) -> Model:
    """The problem's equations, ready for variants (cached per solution)."""
    return _cached(solution).model


def correct(solution: Solution) -> Outcome | None:
    """The correct equations solved by this module (agrees with ``solution``)."""
    return _cached(solution).base


def outcomes(solution: Solution) -> list[Outcome]:
    """Every mistake that applies to the problem and changes some result, solved (cached)."""
    return list(_cached(solution).outcomes())


def _changes(out: Outcome, base: Outcome) -> bool:
    for name, q in out.results.items():
        b = base.results.get(name)
        if b is None:
            continue
        if (q.partial is None) != (b.partial is None):
            return True
        if q.partial is None or b.partial is None:
            continue
        d = q.partial - b.partial
        syms = d.free_symbols
        if syms:
            d = d.xreplace(_point(syms))
        try:
            x = complex(d.evalf(30))
            scale = max(1.0, abs(complex(b.partial.xreplace(_point(syms) if syms else {}).evalf(30))))
        except (TypeError, ValueError):
            continue
        if abs(x) > 1e-12 * scale:
            return True
    return False
