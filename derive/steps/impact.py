"""From a Problem to a Solution: equations (1)-(4), solved, then written out as steps.

The steps follow the notes' layout: 1) geometry (the n-t axes and the
pre-impact components), 2) kinetics (equations (1)-(4), each symbolic, then
with numbers, then collected), 3) the elimination written out, 4) the answer.
"""

from __future__ import annotations

import sympy

from derive.errors import SolveError
from derive.physics.impact import Impact, equation_numbers, evaluate, independent_map, setup
from derive.problem.reader import Problem
from derive.steps.model import Block, Eqn, Math, Result, Side, Solution, Stage, Text
from derive.symbols import symbol, vector

HALF = sympy.Rational(1, 2)


def solve(problem: Problem) -> Solution:
    """Solve ``problem`` in closed form and write its worked solution as data.

    >>> from derive import load, solve  # doctest: +SKIP
    >>> solve(load("notes-4c11-two-spheres")).results["v_A2n"].value  # doctest: +SKIP
    -7*cos(47*pi/225)/5
    """
    from derive.physics.chain import ChainProblem, solve_chain

    if isinstance(problem, ChainProblem):
        return solve_chain(problem)  # type: ignore[return-value]
    imp = setup(problem)
    results = _results(imp)
    values: dict[sympy.Symbol, sympy.Expr] = dict(problem.numeric())
    for motion, (cn, ct) in _xy_motions(imp):
        b = motion.body
        xy = ((symbol(f"v_{b}1x"), motion.x), (symbol(f"v_{b}1y"), motion.y))
        for c, expr in ((cn, motion.n), (ct, motion.t), *xy):
            v = evaluate(expr, problem)
            if not v.free_symbols:
                values[c] = v
    angles = frozenset(g.symbol for g in problem.givens if g.unit == "deg")
    writer = _Writer(imp, results)
    stages = writer.stages()
    return Solution(problem, results, stages, values, angles)


def _xy_motions(imp: Impact) -> list:
    """The bodies whose velocity was given in x-y axes, with their n-t component symbols."""
    p, nm = imp.problem, imp.names
    out = []
    for motion, comps in ((p.motion_A, (nm.A1n, nm.A1t)), (p.motion_B, (nm.B1n, nm.B1t))):
        if motion.x is not None:
            out.append((motion, comps))
    return out


# ---------------------------------------------------------------- results


def _results(imp: Impact) -> dict[str, Result]:
    p, nm = imp.problem, imp.names
    out: dict[str, Result] = {}
    unit_v = _unit(p, "velocity")
    solved = dict(imp.closed)
    varied = {g.symbol for g in p.givens if g.name in p.vary}

    def full(expr: sympy.Expr) -> sympy.Expr:
        """``expr`` in the givens: pre-impact components resolved, unknowns solved."""
        return imp.in_givens(expr).xreplace(solved)

    def add(name: str, closed: sympy.Expr, unit: str, description: str, degrees: bool = False) -> None:
        partial = evaluate(closed, p)
        # simplify what stays symbolic for the reader; a homework variant's givens are
        # numbers later, so their expressions need no simplifying
        if partial.free_symbols - varied and sympy.count_ops(partial) < 150:
            partial = sympy.simplify(partial)
        if degrees and partial.free_symbols and isinstance(partial, sympy.atan2):
            partial = _atan2_number(*partial.args)
        value: sympy.Expr | None = None
        if not partial.free_symbols:
            value = partial * 180 / sympy.pi if degrees else partial
        elif degrees:
            partial = partial * 180 / sympy.pi
        out[name] = Result(name, symbol(name), closed, value, partial, unit, description)

    for g in p.givens:
        if g.unknown:
            add(g.name, solved[g.symbol], g.unit, f"{g.name}, unknown in the file", degrees=g.unit == "deg")
    if p.oblique:
        comps = {"v_A2t": nm.A2t, "v_A2n": nm.A2n, "v_B2t": nm.B2t, "v_B2n": nm.B2n}
        for name, s_ in comps.items():
            body, axis = name[2], name[-1]
            add(name, full(s_), unit_v, f"velocity of {body} after the impact, {axis} component")
        for b in "AB":
            if b == "B" and p.fixed_B:
                continue
            n, t = full(comps[f"v_{b}2n"]), full(comps[f"v_{b}2t"])
            add(f"v_{b}2", sympy.sqrt(n**2 + t**2), unit_v, f"speed of {b} after the impact")
            ang = _angle(n, t, p)
            if ang is not None:
                add(f"theta_{b}2", ang, "deg", f"direction of {b} after the impact, from +t toward +n", degrees=True)
                add(
                    f"beta_{b}2",
                    sympy.atan2(t, n),
                    "deg",
                    f"direction of {b} after the impact, from +n toward +t",
                    degrees=True,
                )
        if p.phi is not None:
            for b in "AB":
                if b == "B" and p.fixed_B:
                    continue
                n, t = full(comps[f"v_{b}2n"]), full(comps[f"v_{b}2t"])
                c, s_ = sympy.cos(p.phi), sympy.sin(p.phi)
                add(f"v_{b}2x", n * c - t * s_, unit_v, f"velocity of {b} after the impact, x component")
                add(f"v_{b}2y", n * s_ + t * c, unit_v, f"velocity of {b} after the impact, y component")
    else:
        add("v_A2", full(nm.A2n), unit_v, "velocity of A after the impact, along +n")
        if not p.fixed_B:
            add("v_B2", full(nm.B2n), unit_v, "velocity of B after the impact, along +n")
    ind = independent_map(p)
    sym = p.symbols()
    m_A = full(sym["m_A"].xreplace(ind))
    m_B = sympy.Integer(0) if p.fixed_B else full(sym["m_B"].xreplace(ind))
    # Kinetic energy. Worked in the component symbols it is polynomial, so it
    # factors quickly and exactly; then the givens go in. (A fixed B has none.)
    sq = {}
    for b, motion in (("A", p.motion_A), ("B", p.motion_B)):
        n1, n2 = getattr(nm, f"{b}1n"), getattr(nm, f"{b}2n")
        t1, t2 = getattr(nm, f"{b}1t"), getattr(nm, f"{b}2t")
        pre_sq = n1**2 + (t1**2 if p.oblique else 0)
        post_sq = n2**2 + (t2**2 if p.oblique else 0)
        speed_sq = motion.speed**2 if (p.oblique and motion.speed is not None) else imp.in_givens(pre_sq)
        sq[b] = (pre_sq, post_sq, full(speed_sq))
    unit_T = _unit(p, "energy")
    T1 = HALF * m_A * sq["A"][2] + HALF * m_B * sq["B"][2]
    T2 = HALF * m_A * full(sq["A"][1]) + HALF * m_B * full(sq["B"][1])
    if imp.inverse:
        lost = T1 - T2
    else:
        lost_c = HALF * m_A * (sq["A"][0] - sq["A"][1].xreplace(imp.by_components))
        lost_c += HALF * m_B * (sq["B"][0] - sq["B"][1].xreplace(imp.by_components))
        lost = sympy.factor_terms(
            imp.in_givens(sympy.factor(lost_c.xreplace({k: v for k, v in imp.pre.items() if v == 0})))
        )
    add("T_1", T1, unit_T, "kinetic energy before the impact")
    add("T_2", T2, unit_T, "kinetic energy after the impact")
    add("T_lost", lost, unit_T, "kinetic energy lost in the impact")
    J = -m_A * (full(nm.A2n) - full(nm.A1n))
    add("J_n", sympy.factor_terms(J), _unit(p, "impulse"), "impulse along +n on B from A (on A it is -J_n)")
    return out


def _show(expr: sympy.Expr) -> sympy.Expr:
    """Mark a display structure of numbers (a fraction, a root) to be printed as built."""
    return sympy.UnevaluatedExpr(expr)


def _f(x: sympy.Expr) -> sympy.Expr:
    """A pure number as a Float (kept apart in printed sums); other expressions as they are."""
    from derive.writers.printing import _short_decimal

    if x.is_number and not x.is_Integer and not _short_decimal(x):
        return sympy.Float(x.evalf(30), 30)
    return x


def _angle(n: sympy.Expr, t: sympy.Expr, p: Problem) -> sympy.Expr | None:
    """atan2(n, t) in closed form; None where the direction is undefined (a body at rest)."""
    nv, tv = evaluate(n, p), evaluate(t, p)
    if nv == 0 and tv == 0:
        return None
    return sympy.atan2(n, t)


def _atan2_number(y: sympy.Expr, x: sympy.Expr) -> sympy.Expr:
    """atan2(y, x) as a number when y/x is one and the sign of x is known (4.C.12: v_A1 cancels)."""
    ratio = sympy.simplify(y / x) if x != 0 else None
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


def _convert_result(r: Result, unit_text: str) -> sympy.Expr:
    """A result's value (or closed form) in another unit of the same kind."""
    from derive.problem import units

    src, dst = units.parse_unit(r.unit if r.unit != "deg" else "deg"), units.parse_unit(unit_text)
    if src.dim != dst.dim:
        raise SolveError(
            f"answer_units: {r.name} is {units.describe(src.dim)}, which cannot be shown in {unit_text}",
        )
    value = r.value if r.value is not None else r.partial
    return value * src.factor / dst.factor


def _unit(p: Problem, what: str) -> str:
    from derive.problem import units

    dim = {"velocity": units.VELOCITY, "energy": units.ENERGY, "impulse": units.IMPULSE}[what]
    return units.SYSTEMS[p.system][dim]


# ---------------------------------------------------------------- steps


def _terms(expr: sympy.Expr) -> tuple[sympy.Expr, ...]:
    """The terms of a sum in a stable order (A before B, as the equations are built)."""
    if isinstance(expr, sympy.Add):
        return tuple(expr.args)
    return (expr,)


def _nonzero(terms: tuple[sympy.Expr, ...]) -> tuple[sympy.Expr, ...]:
    kept = tuple(t for t in terms if t != 0)
    return kept or (sympy.Integer(0),)


class _Writer:
    """Writes the stages of one solution."""

    def __init__(self, imp: Impact, results: dict[str, Result]) -> None:
        self.imp = imp
        self.p = imp.problem
        self.nm = imp.names
        self.results = results
        self.ind = imp.independent
        self.numeric = self.p.numeric()
        sym = self.p.symbols()
        self.m_A, self.e = sym["m_A"], sym["e"]
        self.m_B = sym.get("m_B", symbol("m_B", "positive"))
        self.unit_v = _unit(self.p, "velocity")
        self.nums = equation_numbers(self.p)
        self.unknowns = imp.unknowns
        self.collected_eqs: dict[int, sympy.Expr] = {}
        self.shown: set[sympy.Symbol] = set()
        self.surface = self.p.name_B or "surface"
        # homework variants: givens left symbolic only to be filled in later count as numbers
        self.varied = {g.symbol for g in self.p.givens if g.name in self.p.vary}

    # helpers -----------------------------------------------------------
    def givens(self, expr: sympy.Expr) -> sympy.Expr:
        """``expr`` in the givens' symbols (pre-impact components resolved, except those
        resolved from x-y axes, which the geometry stage has turned into numbers)."""
        keep = {c for _, comps in _xy_motions(self.imp) for c in comps}
        pre = {k: v for k, v in self.imp.pre.items() if k not in keep}
        return expr.xreplace(pre).xreplace(self.ind)

    def has_values(self, expr: sympy.Expr) -> bool:
        keep = {c for _, comps in _xy_motions(self.imp) for c in comps}
        return bool(expr.free_symbols & (set(self.numeric) | keep | self.varied))

    def num(self, expr: sympy.Expr) -> sympy.Expr:
        return evaluate(expr.xreplace(self.imp.pre), self.p)

    def value_of(self, s: sympy.Symbol) -> sympy.Expr:
        """A solved quantity: its number, or its closed form with numbers in."""
        r = self.results.get(s.name)
        if r is not None:
            return r.value if r.value is not None else r.partial
        return self.num(self.imp.closed[s])

    results_value = value_of

    def unit_of(self, s: sympy.Symbol) -> str | None:
        g = next((g for g in self.p.givens if g.symbol == s), None)
        if g is not None:
            return g.unit or None
        return self.unit_v

    # stages --------------------------------------------------------------
    def stages(self) -> tuple[Stage, ...]:
        return (
            Stage(1, "Geometry: the n–t axes", tuple(self.geometry())),
            Stage(2, "Kinetics", tuple(self.kinetics())),
            Stage(3, "Solve", tuple(self.elimination())),
            Stage(4, "Answer", tuple(self.answer())),
        )

    def geometry(self) -> list[Block]:
        p = self.p
        if p.fixed_B:
            first: Text = (
                "Take ",
                Math(symbol("n")),
                f" along the line of impact, normal to the {self.surface}, positive from A toward the {self.surface}, and ",
                Math(symbol("t")),
                " along the " + self.surface + (" (n turned 90° counter-clockwise)." if p.oblique else "."),
            )
        else:
            first = (
                "Take ",
                Math(symbol("n")),
                " along the line of impact, positive from the centre of A toward the centre of B, and ",
                Math(symbol("t")),
                " in the plane of contact" + (" (n turned 90° counter-clockwise)." if p.oblique else "."),
            )
        blocks = [Block(first)]
        if p.fixed_B:
            blocks.append(
                Block((f"B is the fixed {self.surface}: infinite mass, at rest before and after the impact.",))
            )
        if not p.oblique:
            lines = []
            for s_ in (self.nm.A1n,) + (() if p.fixed_B else (self.nm.B1n,)):
                if s_ in self.numeric or s_ in self.varied:
                    lines.append(Eqn((Side((s_,)), Side((s_,), "result")), unit=self.unit_v))
            blocks.append(
                Block(("The impact is direct: every velocity lies along n and is signed along +n.",), tuple(lines))
            )
            return blocks
        for motion, (cn, ct) in (
            (p.motion_A, (self.nm.A1n, self.nm.A1t)),
            (p.motion_B, (self.nm.B1n, self.nm.B1t)),
        ):
            b = motion.body
            if b == "B" and p.fixed_B:
                continue
            if motion.speed is not None and motion.angle is None:
                blocks.append(
                    Block(
                        (f"{b} is at rest before the impact: ", Math(sympy.Eq(cn, 0)), ", ", Math(sympy.Eq(ct, 0)), ".")
                    )
                )
                continue
            if motion.angle is not None:
                text: Text = (
                    f"{b} moves at ",
                    Math(motion.speed),
                    ", at ",
                    Math(motion.angle),
                    f" from {motion.axis_from} toward {motion.toward}:",
                )
            else:
                text = (f"The velocity of {b} before the impact is given by its components:",)
            lines = []
            if motion.x is not None:
                lines.extend(self.xy_lines(motion, cn, ct))
                blocks.append(Block(text, tuple(lines)))
                continue
            for c in (cn, ct):
                expr = self.imp.pre[c]
                sides = [Side((c,))]
                if expr != c:
                    sides.append(Side((expr,)))
                    if self.has_values(expr) and not expr.is_Symbol:
                        sides.append(Side((expr,), "values"))
                if not (expr.free_symbols & set(self.unknowns)):
                    sides.append(Side((expr,), "result"))
                lines.append(Eqn(tuple(sides), unit=self.unit_v))
            blocks.append(Block(text, tuple(lines)))
        return blocks

    def xy_lines(self, motion, cn: sympy.Symbol, ct: sympy.Symbol) -> list[Eqn]:
        """A velocity given in x-y axes: its x and y components, then n and t through phi."""
        b, phi = motion.body, self.p.phi
        vx, vy = symbol(f"v_{b}1x"), symbol(f"v_{b}1y")
        lines = []
        for s_, expr in ((vx, motion.x), (vy, motion.y)):
            if expr == s_:
                continue
            sides = [Side((s_,)), Side((expr,))]
            if self.has_values(expr):
                sides.append(Side((expr,), "values"))
            sides.append(Side((expr,), "result"))
            lines.append(Eqn(tuple(sides), unit=self.unit_v))
        n_form = (vx * sympy.cos(phi), vy * sympy.sin(phi))
        t_form = (-vx * sympy.sin(phi), vy * sympy.cos(phi))
        for c, form, expr in ((cn, n_form, motion.n), (ct, t_form, motion.t)):
            value = sympy.expand(self.num(expr))  # cos 0° = 1 and 0 · v_A1 = 0 done, not shown
            lines.append(
                Eqn((Side((c,)), Side(form), Side(form, "values"), Side((value,), "result")), unit=self.unit_v)
            )
        return lines

    def kinetics(self) -> list[Block]:
        blocks: list[Block] = []
        nm, p = self.nm, self.p
        if p.oblique:
            blocks.append(
                Block(
                    (
                        "Linear momentum in the t-direction is conserved for each particle: "
                        "no impulsive force acts on A or on B along t (the surfaces are smooth).",
                    )
                )
            )
            for tag, b, m, c1, c2 in (("1", "A", self.m_A, nm.A1t, nm.A2t), ("2", "B", self.m_B, nm.B1t, nm.B2t)):
                if b == "B" and p.fixed_B:
                    blocks.append(Block((f"B, the {self.surface}, does not move: (2) says nothing.",)))
                    continue
                blocks.append(self.t_momentum(tag, b, m, c1, c2))
        else:
            blocks.append(
                Block(
                    (
                        "The impact is direct: there are no t components, so equations (1) and (2) of the notes read 0 = 0.",
                    )
                )
            )
        if p.fixed_B:
            blocks.append(
                Block(
                    (
                        f"Linear momentum along n is not conserved for A and the {self.surface}: its supports exert an "
                        "impulsive reaction, so equation (3) does not apply. The impact rule alone gives the n component.",
                    )
                )
            )
        else:
            blocks.append(self.momentum_n())
        blocks.append(self.restitution())
        return blocks

    def t_momentum(self, tag: str, b: str, m: sympy.Symbol, c1: sympy.Symbol, c2: sympy.Symbol) -> Block:
        pre = self.givens(c1)
        lines = [Eqn((Side((m * c1,)), Side((m * c2,))), cancel=frozenset({m}))]
        given_c2 = c2.name in {g.name for g in self.p.givens}
        if not given_c2 and not (pre.free_symbols & set(self.unknowns)):
            lines.append(Eqn((Side((c2,)), Side((c1,))) + ((Side((pre,)),) if pre != c1 else ()), implies=True))
            if self.has_values(pre) and not pre.is_Symbol and pre != 0:
                lines.append(Eqn((Side((c2,)), Side((pre,), "values"))))
            lines.append(Eqn((Side((c2,)), Side((self.value_of(c2),), "result")), tag=tag, unit=self.unit_v))
            self.shown.add(c2)
        else:
            lines.append(Eqn((Side((pre,)), Side((c2,))), implies=True))
            lines.append(Eqn((Side((pre,), "values"), Side((c2,), "values")), tag=tag))
            self.collected_eqs[int(tag)] = self.num(pre - c2)
        return Block((f"System {b}: ", Math(sympy.Symbol(r"\Sigma F_t = 0")), ","), tuple(lines))

    def collected(
        self, lhs: sympy.Expr, rhs: sympy.Expr, order: tuple[sympy.Symbol, ...]
    ) -> tuple[tuple[sympy.Expr, ...], tuple[sympy.Expr, ...]]:
        """Unknown terms (in ``order``) = constant, from ``lhs = rhs`` with numbers in;
        an equation not linear in its unknowns is left as it stands."""
        expr = sympy.expand(self.num(lhs) - self.num(rhs))
        us = [u for u in order if expr.has(u)] + [u for u in self.unknowns if expr.has(u) and u not in order]
        poly = expr.is_polynomial(*us) if us else False
        if (
            not poly
            or any(sympy.degree(expr, u) > 1 for u in us)
            or any(expr.coeff(u).has(*[w for w in us if w != u]) for u in us)
        ):
            return (self.num(lhs),), (self.num(rhs),)
        terms = []
        for u in us:
            c = expr.coeff(u)
            if c != 0:
                terms.append(sympy.simplify(c) * u)
        const = sympy.simplify(-(expr - sum(terms)))
        if len(terms) == 1 and terms[0].could_extract_minus_sign():
            return (-terms[0],), (-const,)  # v_A2n = -4.8, not -v_A2n = 4.8
        return tuple(terms) or (sympy.Integer(0),), (const,)

    def momentum_n(self) -> Block:
        nm, m_A, m_B = self.nm, self.m_A, self.m_B
        lhs_terms = (m_A * nm.A1n, m_B * nm.B1n)
        rhs_terms = (m_A * nm.A2n, m_B * nm.B2n)
        lines = [Eqn((Side(lhs_terms), Side(rhs_terms)))]
        g_lhs = _nonzero(tuple(self.givens(t) for t in lhs_terms))
        g_rhs = tuple(self.givens(t) for t in rhs_terms)
        if g_lhs != lhs_terms or g_rhs != rhs_terms:
            lines.append(Eqn((Side(g_lhs), Side(g_rhs)), implies=True))
        common = self.common_factor(g_lhs + g_rhs)
        if common is not None:
            lines[-1] = Eqn(lines[-1].sides, cancel=frozenset({common}), implies=lines[-1].implies)
            g_lhs = _nonzero(tuple(sympy.cancel(t / common) for t in g_lhs))
            g_rhs = tuple(sympy.cancel(t / common) for t in g_rhs)
            lines.append(Eqn((Side(g_lhs), Side(g_rhs)), implies=True))
        sums = []
        if any(self.has_values(t) for t in g_lhs + g_rhs):
            lines.append(Eqn((Side(g_lhs, "values"), Side(g_rhs, "values"))))
            lhs_num = _nonzero(tuple(self.num(t) for t in g_lhs))
            if len(lhs_num) > 1 and all(not (t.free_symbols - self.varied) for t in lhs_num):
                lines.append(Eqn((Side(lhs_num, "numeric"), Side(g_rhs, "values"))))
                sums.append((lhs_num, sympy.Add(*lhs_num)))
        terms, const = self.collected(sympy.Add(*g_rhs), sympy.Add(*g_lhs), (nm.A2n, nm.B2n))
        lines.append(Eqn((Side(terms, "numeric"), Side(const, "numeric")), tag="3", implies=True))
        self.eq3 = (terms, const[0])
        self.collected_eqs[3] = self.num(sympy.Add(*g_rhs) - sympy.Add(*g_lhs))
        return Block(
            (
                "Linear momentum in the n-direction is conserved for the system A + B: the contact forces are internal to it.",
            ),
            tuple(lines),
            tuple(sums),
        )

    def common_factor(self, terms: tuple[sympy.Expr, ...]) -> sympy.Symbol | None:
        """A symbolic mass shared by every term (m in 4.C.12), which cancels."""
        nonzero = [t for t in terms if t != 0]
        for cand in sorted(set(nonzero[0].free_symbols), key=str) if nonzero else []:
            if cand in self.numeric or not cand.is_positive or cand in self.unknowns:
                continue
            if all(
                sympy.cancel(t / cand).free_symbols.isdisjoint({cand}) and (t / cand).is_polynomial(cand)
                for t in nonzero
            ) and all(sympy.Poly(t, cand).degree() == 1 for t in nonzero):
                return cand
        return None

    def restitution(self) -> Block:
        nm, e = self.nm, self.e
        sep = sympy.Add(nm.B2n, -nm.A2n, evaluate=False)
        app = sympy.Add(nm.A1n, -nm.B1n, evaluate=False)
        lines = [
            Eqn((Side((e,)), Side((sympy.Mul(sep, sympy.Pow(app, -1, evaluate=False), evaluate=False),)))),
            Eqn((Side((sympy.Mul(e, app, evaluate=False),)), Side((nm.B2n, -nm.A2n))), implies=True),
        ]
        g_app = _nonzero(tuple(self.givens(t) for t in (nm.A1n, -nm.B1n)))
        g_sep = _nonzero(tuple(self.givens(t) for t in (nm.B2n, -nm.A2n)))
        g_app_expr = sympy.Add(*g_app, evaluate=False) if len(g_app) > 1 else g_app[0]
        g_lhs = sympy.Mul(e, g_app_expr, evaluate=False)
        if g_app != (nm.A1n, -nm.B1n) or g_sep != (nm.B2n, -nm.A2n):
            lines.append(Eqn((Side((g_lhs,)), Side(g_sep)), implies=True))
        if self.has_values(g_lhs) or any(self.has_values(t) for t in g_sep):
            lines.append(Eqn((Side((g_lhs,), "values"), Side(g_sep, "values"))))
        if self.p.fixed_B:
            terms, const = self.collected(sympy.Add(*g_sep), e * sympy.Add(*g_app), (nm.A2n,))
        else:
            terms, const = self.collected(sympy.Add(*g_sep), e * sympy.Add(*g_app), (nm.B2n, nm.A2n))
        lines.append(Eqn((Side(terms, "numeric"), Side(const, "numeric")), tag="4", implies=True))
        self.eq4 = const[0]
        self.collected_eqs[4] = self.num(sympy.Add(*g_sep) - e * sympy.Add(*g_app))
        text: Text = (
            "Impact rule: the coefficient of restitution relates the normal components only, separation over approach.",
        )
        ev = self.numeric.get(e)
        if ev == 1:
            text += (" Here ", Math(sympy.Eq(e, 1)), ": the impact is perfectly elastic.")
        elif ev == 0:
            text += (" Here ", Math(sympy.Eq(e, 0)), ": the impact is perfectly plastic.")
        return Block(text, tuple(lines))

    def elimination(self) -> list[Block]:
        if self.imp.inverse:
            return self.generic_solve()
        nm = self.nm
        if self.p.fixed_B:
            x = nm.A2n
            g_app = self.givens(nm.A1n)
            form = -self.e * g_app
            sides = [Side((x,)), Side((form,))]
            if self.has_values(form):
                sides.append(Side((form,), "values"))
            sides.append(Side((self.value_of(x),), "result"))
            return [
                Block(("From (4), with the " + self.surface + " at rest:",), (Eqn(tuple(sides), unit=self.unit_v),))
            ]
        x, y = nm.A2n, nm.B2n
        (terms3, c) = self.eq3
        k = self.eq4
        a = sympy.expand(sympy.Add(*terms3)).coeff(x)
        b = sympy.expand(sympy.Add(*terms3)).coeff(y)
        xv, yv = self.value_of(x), self.value_of(y)
        blocks: list[Block] = []
        if sympy.simplify(a - b) == 0:
            # equal coefficients: add and subtract (3) and (4), as in Example 4.C.12
            a1 = sympy.simplify(a)
            blocks.append(
                Block(
                    ("Add (3) and (4): ", Math(x), " cancels."),
                    (
                        Eqn((Side((sympy.Mul(a1 + 1, y, evaluate=False),), "numeric"), Side((c, k), "numeric"))),
                        Eqn((Side((y,)), Side((yv,), "result")), unit=self.unit_v, tag="5", implies=True),
                    ),
                    self.sum_check((c, k)),
                )
            )
            blocks.append(
                Block(
                    ("Subtract (4) from (3): ", Math(y), " cancels."),
                    (
                        Eqn((Side((sympy.Mul(a1 + 1, x, evaluate=False),), "numeric"), Side((c, -k), "numeric"))),
                        Eqn((Side((x,)), Side((xv,), "result")), unit=self.unit_v, tag="6", implies=True),
                    ),
                    self.sum_check((c, -k)),
                )
            )
            return blocks
        sub = sympy.Add(x, _f(k), evaluate=False)
        blocks.append(Block(("From (4):",), (Eqn((Side((y,)), Side((x, k), "numeric"))),)))
        lhs = (a * x, sympy.Mul(b, sub, evaluate=False))
        coef = sympy.Add(a, b, evaluate=False)
        bk = sympy.Mul(_f(-b), _f(k), evaluate=False)
        frac_num = sympy.Add(_f(c), bk, evaluate=False)
        blocks.append(
            Block(
                ("Substitute into (3):",),
                (
                    Eqn((Side(lhs, "numeric"), Side((c,), "numeric"))),
                    Eqn(
                        (Side((sympy.Mul(coef, x, evaluate=False),), "numeric"), Side((c, bk), "numeric")), implies=True
                    ),
                    Eqn(
                        (
                            Side((x,)),
                            Side(
                                (_show(sympy.Mul(frac_num, sympy.Pow(_f(a + b), -1, evaluate=False), evaluate=False)),),
                                "numeric",
                            ),
                            Side((xv,), "result"),
                        ),
                        unit=self.unit_v,
                        implies=True,
                    ),
                ),
            )
        )
        blocks.append(
            Block(
                ("Back into (4):",),
                (Eqn((Side((y,)), Side((xv, k), "numeric"), Side((yv,), "result")), unit=self.unit_v),),
                (((xv, k), yv),) if not ((xv.free_symbols | yv.free_symbols) - self.varied) else (),
            )
        )
        return blocks

    def generic_solve(self) -> list[Block]:
        """Inverse problems: take each equation with one unknown left, in turn."""
        blocks: list[Block] = []
        remaining = [u for u in self.unknowns if u not in self.shown]
        eqs = dict(sorted(self.collected_eqs.items()))
        known: dict[sympy.Symbol, sympy.Expr] = {}
        while remaining:
            step = None
            for k, ex in eqs.items():
                us = [u for u in remaining if ex.xreplace(known).has(u)]
                if len(us) == 1:
                    step = (k, us[0])
                    break
            if step is None:
                lines = tuple(
                    Eqn((Side((u,)), Side((self.value_of(u),), "result")), unit=self.unit_of(u)) for u in remaining
                )
                listed = " and ".join(f"({k})" for k in eqs)
                blocks.append(Block((f"Solve {listed} together:",), lines))
                break
            k, u = step
            sides = [Side((u,))]
            if u == self.e and k == 4:
                nm = self.nm
                sep = sympy.Add(*_nonzero(tuple(self.givens(t) for t in (nm.B2n, -nm.A2n))), evaluate=False)
                app = sympy.Add(*_nonzero(tuple(self.givens(t) for t in (nm.A1n, -nm.B1n))), evaluate=False)
                frac = sympy.Mul(sep, sympy.Pow(app, -1, evaluate=False), evaluate=False)
                sides.append(Side((frac,)))
                sides.append(Side((_show(self.substituted(frac, known)),), "numeric"))
            sides.append(Side((self.value_of(u),), "result"))
            why = self.root_reason(u)
            text: Text = (f"From ({k}):" + (f" {why}" if why else ""),)
            blocks.append(Block(text, (Eqn(tuple(sides), unit=self.unit_of(u)),)))
            known[u] = self.value_of(u)
            remaining.remove(u)
            del eqs[k]
        return blocks

    def substituted(self, expr: sympy.Expr, known: dict[sympy.Symbol, sympy.Expr]) -> sympy.Expr:
        """``expr`` with every known quantity's number in its place, structure kept."""
        vals = {**self.numeric, **known}
        if isinstance(expr, sympy.Symbol):
            return _f(vals[expr]) if expr in vals else expr
        if expr.is_Atom:
            return expr
        return expr.func(*(self.substituted(a, known) for a in expr.args), evaluate=False)

    def root_reason(self, u: sympy.Symbol) -> str:
        """Why the root shown is the one kept, where the equations have several."""
        eqs = [ex for ex in self.collected_eqs.values() if ex.has(u)]
        if any(not ex.is_polynomial(u) or sympy.degree(ex, u) > 1 for ex in eqs if ex.is_polynomial(u) or True):
            if u.name == "e":
                return "the root with 0 ≤ e ≤ 1 is the physical one."
            g = next((g for g in self.p.givens if g.symbol == u), None)
            if g is not None and g.unit == "deg":
                return "the root between -180° and 180° for which the bodies approach is the physical one."
            if u.is_positive or u.is_nonnegative:
                return f"the root with {u.name} ≥ 0 is the physical one."
        return ""

    def sum_check(self, terms: tuple[sympy.Expr, ...]) -> tuple[tuple[tuple[sympy.Expr, ...], sympy.Expr], ...]:
        """The sum claim for a line of numeric terms (none when a symbol remains)."""
        nums = tuple(self.num(t) for t in terms)
        if any(t.free_symbols - self.varied for t in nums):
            return ()
        return ((nums, sympy.Add(*nums)),)

    def answer(self) -> list[Block]:
        p = self.p
        blocks: list[Block] = []
        e_t, e_n = vector("e_t"), vector("e_n")
        lines = []
        bodies = "A" if p.fixed_B else "AB"
        given_names = {g.name for g in p.givens}
        if p.oblique:
            for b in bodies:
                t = self.value_of(symbol(f"v_{b}2t"))
                n = self.value_of(symbol(f"v_{b}2n"))
                comps = _nonzero(tuple(c * u for c, u in ((t, e_t), (n, e_n)) if c != 0))
                found = not {f"v_{b}2t", f"v_{b}2n"} <= given_names  # a velocity the file gave is no answer
                lines.append(Eqn((Side((vector(f"v_{b}2"),)), Side(comps, "result")), unit=self.unit_v, boxed=found))
        else:
            for b in bodies:
                lines.append(
                    Eqn(
                        (Side((symbol(f"v_{b}2"),)), Side((self.value_of(symbol(f"v_{b}2")),), "result")),
                        unit=self.unit_v,
                        boxed=f"v_{b}2" not in given_names,
                    )
                )
        heading = "The velocity of A" if p.fixed_B else "The velocities"
        blocks.append(Block((heading + " immediately after the impact:",), tuple(lines)))
        if p.phi is not None:
            e_x, e_y = vector("e_x"), vector("e_y")
            lines = []
            for b in bodies:
                x, y = self.value_of(symbol(f"v_{b}2x")), self.value_of(symbol(f"v_{b}2y"))
                comps = _nonzero(tuple(c * u for c, u in ((x, e_x), (y, e_y)) if c != 0))
                lines.append(Eqn((Side((vector(f"v_{b}2"),)), Side(comps, "result")), unit=self.unit_v, boxed=True))
            text: Text = ("In the problem's x–y axes (x = n cos φ − t sin φ, y = n sin φ + t cos φ):",)
            blocks.append(Block(text, tuple(lines)))
        symbolic = [
            r
            for r in self.results.values()
            if r.value is None
            and r.partial.free_symbols - self.varied
            and r.name in ("v_A2t", "v_A2n", "v_B2t", "v_B2n", "v_A2", "v_B2")
        ]
        if symbolic:
            lines = []
            for r in symbolic:
                if r.closed == 0:
                    continue
                lines.append(Eqn((Side((r.symbol,)), Side((r.closed,)), Side((r.partial,), "result")), unit=r.unit))
            blocks.append(Block(("In closed form, in the givens:",), tuple(lines)))
        extra = []
        for name in p.find:
            if name in ("v_A2", "v_B2") and not p.oblique:
                continue
            if name in ("v_A2t", "v_A2n", "v_B2t", "v_B2n"):
                continue
            r = self.results.get(name)
            if r is None:
                continue
            extra.append(self.derived_line(r, boxed=True))
        for name, unit in p.answer_units.items():
            r = self.results.get(name)
            if r is None:
                raise SolveError(f"answer_units names {name!r}, which is not a result of this problem", where=p.path)
            converted = _convert_result(r, unit)
            extra.append(Eqn((Side((r.symbol,)), Side((converted,), "result")), unit=unit, boxed=True))
        if extra:
            text: Text = ("As asked:",)
            if "J_n" in p.find:
                text = (
                    "As asked (",
                    Math(symbol("J_n")),
                    " is the impulse along +n on B; on A it is ",
                    Math(-symbol("J_n")),
                    "):",
                )
            blocks.append(Block(text, tuple(extra)))
        blocks.append(self.energy())
        return blocks

    def derived_line(self, r: Result, boxed: bool) -> Eqn:
        nm = self.nm
        val = r.value if r.value is not None else r.partial
        if r.name in ("v_A2", "v_B2", "theta_A2", "theta_B2"):
            b = r.name[-2]
            n, t = getattr(nm, f"{b}2n"), getattr(nm, f"{b}2t")
            nv, tv = self.results_value(n), self.results_value(t)
            if r.name.startswith("v"):
                form = sympy.sqrt(sympy.Add(t**2, n**2, evaluate=False), evaluate=False)
                shown = None
                if not ((nv.free_symbols | tv.free_symbols) - self.varied):
                    shown = _show(
                        sympy.Pow(
                            sympy.Add(
                                sympy.Pow(_f(tv), 2, evaluate=False),
                                sympy.Pow(_f(nv), 2, evaluate=False),
                                evaluate=False,
                            ),
                            sympy.Rational(1, 2),
                            evaluate=False,
                        )
                    )
            else:
                return self.angle_line(r, n, t, nv, tv, boxed)
            sides = [Side((r.symbol,)), Side((form,))]
            if shown is not None:
                sides.append(Side((shown,), "numeric"))
            sides.append(Side((val,), "result"))
            return Eqn(tuple(sides), unit=r.unit, boxed=boxed)
        if r.name in ("beta_A2", "beta_B2"):
            b = r.name[-2]
            n, t = getattr(nm, f"{b}2n"), getattr(nm, f"{b}2t")
            return self.angle_line(r, t, n, self.results_value(t), self.results_value(n), boxed)
        if r.name == "J_n":
            return self.impulse_line(r, boxed)
        return Eqn((Side((r.symbol,)), Side((val,), "result")), unit=r.unit, boxed=boxed)

    def angle_line(
        self, r: Result, y: sympy.Symbol, x: sympy.Symbol, yv: sympy.Expr, xv: sympy.Expr, boxed: bool
    ) -> Eqn:
        """A direction: tan^-1(y/x), with 180° added where x < 0 (written atan2 where
        the sign of x is not known when the page is written)."""
        val = r.value if r.value is not None else r.partial
        numeric = not ((xv.free_symbols | yv.free_symbols) - self.varied)
        known = numeric and not (xv.free_symbols | yv.free_symbols)
        sides = [Side((r.symbol,))]
        ratio = None if xv == 0 else sympy.simplify(yv / xv)
        if xv == 0:
            pass
        elif (known and xv > 0) or (not numeric and ratio is not None and ratio.is_number and xv.is_positive):
            sides.append(
                Side((sympy.atan(sympy.Mul(y, sympy.Pow(x, -1, evaluate=False), evaluate=False), evaluate=False),))
            )
            shown = _f(ratio) if not known else sympy.Mul(_f(yv), sympy.Pow(_f(xv), -1, evaluate=False), evaluate=False)
            sides.append(Side((_show(sympy.atan(shown, evaluate=False)),), "numeric"))
        elif known:  # x < 0: the angle lies beyond ±90°
            turn = sympy.Symbol(r"\,180^\circ" if yv >= 0 else r"\,(-180^\circ)")
            form = sympy.atan(sympy.Mul(y, sympy.Pow(x, -1, evaluate=False), evaluate=False), evaluate=False)
            sides.append(Side((form, turn)))
            shown = sympy.Mul(_f(yv), sympy.Pow(_f(xv), -1, evaluate=False), evaluate=False)
            sides.append(Side((_show(sympy.atan(shown, evaluate=False)), turn), "numeric"))
        else:
            sides.append(Side((sympy.atan2(y, x, evaluate=False),)))
        sides.append(Side((val,), "result"))
        return Eqn(tuple(sides), unit=r.unit, boxed=boxed)

    def impulse_line(self, r: Result, boxed: bool) -> Eqn:
        """J_n = m_A (v_A1n - v_A2n): the impulse along +n on B (on A it is -J_n)."""
        nm = self.nm
        form = sympy.Mul(self.m_A, sympy.Add(nm.A1n, -nm.A2n, evaluate=False), evaluate=False)
        sides = [Side((r.symbol,)), Side((form,))]
        vals = {nm.A1n: self.num(self.imp.pre.get(nm.A1n, nm.A1n)), nm.A2n: self.value_of(nm.A2n)}
        m = self.num(self.m_A.xreplace(self.ind))
        if not ((m.free_symbols | vals[nm.A1n].free_symbols | vals[nm.A2n].free_symbols) - self.varied):
            shown = sympy.Mul(_f(m), sympy.Add(_f(vals[nm.A1n]), -_f(vals[nm.A2n]), evaluate=False), evaluate=False)
            sides.append(Side((_show(shown),), "numeric"))
        val = r.value if r.value is not None else r.partial
        sides.append(Side((val,), "result"))
        return Eqn(tuple(sides), unit=r.unit, boxed=boxed)

    def energy(self) -> Block:
        p = self.p
        m_A, m_B = self.m_A, self.m_B
        s1A = p.motion_A.speed if p.oblique and p.motion_A.speed is not None else None
        s1B = p.motion_B.speed if p.oblique and p.motion_B.speed is not None else None
        if p.oblique:
            v1A = s1A**2 if s1A is not None else sympy.Add(self.nm.A1n**2, self.nm.A1t**2, evaluate=False)
            v1B = s1B**2 if s1B is not None else sympy.Add(self.nm.B1n**2, self.nm.B1t**2, evaluate=False)
            v2A, v2B = symbol("v_A2", "positive") ** 2, symbol("v_B2", "positive") ** 2
        else:
            v1A, v1B = symbol("v_A1") ** 2, symbol("v_B1") ** 2
            v2A, v2B = symbol("v_A2") ** 2, symbol("v_B2") ** 2
        if p.fixed_B:
            forms = {"T_1": (HALF * m_A * v1A,), "T_2": (HALF * m_A * v2A,)}
        else:
            forms = {
                "T_1": (HALF * m_A * v1A, HALF * m_B * v1B),
                "T_2": (HALF * m_A * v2A, HALF * m_B * v2B),
            }
        forms["T_lost"] = (symbol("T_1"), -symbol("T_2"))
        lines = []
        for name, terms in forms.items():
            r = self.results[name]
            sides = [Side((r.symbol,)), Side(terms)]
            if r.value is None:
                if r.closed != r.partial and r.partial.free_symbols - self.varied:
                    sides.append(Side((r.closed,)))
                sides.append(Side((r.partial,), "result"))
            else:
                sides.append(Side((r.value,), "result"))
            lines.append(Eqn(tuple(sides), unit=r.unit))
        r1, rl = self.results["T_1"], self.results["T_lost"]
        if r1.value is not None and rl.value is not None and r1.value != 0:
            frac = rl.value / r1.value * 100
            lines.append(
                Eqn((Side((sympy.Symbol(r"\frac{T_{\mathrm{lost}}}{T_{1}}"),)), Side((frac,), "result")), unit="%")
            )
        else:
            frac = sympy.simplify(rl.partial / r1.partial)
            if frac.is_number:
                lines.append(
                    Eqn(
                        (Side((sympy.Symbol(r"\frac{T_{\mathrm{lost}}}{T_{1}}"),)), Side((frac * 100,), "result")),
                        unit="%",
                    )
                )
        text: Text = (
            "Kinetic energy, for the record: it is not conserved across the impact unless ",
            Math(sympy.Eq(self.e, 1)),
            ", so it is never used to find the velocities.",
        )
        return Block(text, tuple(lines))
