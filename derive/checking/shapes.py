"""A derivation's relations read by their shape: the terms in the unknowns of one of (1)-(4)
up to a factor, whatever their numbers, so that a name is read by the equations it stands
in (``5x + 3y = -0.7`` after a slip is (3) in its shape: x is A's, y is B's), not only by
the values that make its relations hold (:mod:`.inference`)."""

from __future__ import annotations

import sympy

from derive.checking.context import Context
from derive.checking.naming import placeholders
from derive.checking.numeric import number_of


class Shapes:
    """The relations in the student's names whose terms in the unknowns are those of one of
    (1)-(4) up to a factor, whatever their numbers (``5x + 3y = -0.7`` after a slip is (3) in
    its shape): a name is read by the equations it stands in, not only by the values."""

    #: A shape counts for less than a relation that holds (and not at all where it holds too).
    WEIGHT = 0.4

    def __init__(self, ctx: Context, raw: list, pt: dict, truth: dict, equations) -> None:
        self.ctx, self.pt, self.U, self.truth = ctx, pt, tuple(truth), truth
        self.targets = [c for c in (linear_part(e.xreplace(pt), self.U) for e in equations) if c and len(c) >= 2]
        self.diffs = [
            ctx.in_unknowns(r.exprs[i] - r.exprs[i + 1]).xreplace(pt)
            for r in raw
            if r.exprs and not r.defines
            for i in range(len(r.exprs) - 1)
            if placeholders(r.exprs[i]) | placeholders(r.exprs[i + 1])
        ]

    def score(self, mapping: dict) -> float:
        if not self.targets:
            return 0.0
        subs = {k: self.ctx.in_unknowns(v).xreplace(self.pt) for k, v in mapping.items()}
        n = 0
        for d in self.diffs:
            c = linear_part(d.xreplace(subs), self.U)
            if c and any(alike(c, t) for t in self.targets) and not self._holds(d.xreplace(subs)):
                n += 1  # two unknowns or more: (3), (4)
        return self.WEIGHT * n

    def first_shaped(self, best: tuple, options: list[tuple], group: list, mapping: dict, key, natural: list) -> tuple:
        """A teacher reads names met together by the first relation they stand in: where it holds and
        has the shape of one of (1)-(4) under a natural reading, that reading, ahead of ``best`` (one
        such relation is enough, though a slip on the next line leaves it the only one that holds);
        where it holds with the problem's values under neither ``best`` nor another reading (a slip before it) and
        has the shape of one of (1)-(4) under some reading but not under ``best``, that reading
        (the best of them by ``key``): ``5(3.46) + 3(-6) = 5a + 3b`` after A's components were
        swapped is (3), a A's and b B's, whatever number a later line's a comes to. Only a
        ``natural`` reading (A's then B's, each its own way) is taken so: a shape that needs the
        bodies swapped is the masses swapped, a slip, not the names' reading."""
        first = next((d for d in self.diffs if placeholders(d) & set(group)), None)
        if first is None or not self.targets:
            return best

        def reads(option: tuple) -> tuple[bool, bool]:
            return self._reads(first, option, group, mapping)

        if not all(reads(best)) and (held := [o for o in natural if all(reads(o))]):
            return max(held, key=key)  # it holds as (1)-(4) read so: the names' reading, whatever a slip after
        if any(reads(best)) or any(reads(o)[0] for o in options):
            return best
        shaped = [o for o in natural if reads(o)[1]]
        return max(shaped, key=key) if shaped else best

    def grounds(self, option: tuple, group: list, mapping: dict) -> bool:
        """Whether the first relation the names of ``group`` stand in holds under ``option`` and has
        the shape of one of (1)-(4) there: ``3a + 5(1) = 3(0) + 5b``, each name beside its body's mass
        on its instant's side, is (3) with a A's before and b B's after, one relation enough to read
        them, as a teacher does, though a later line's slip leaves it the only one that holds."""
        first = next((d for d in self.diffs if placeholders(d) & set(group)), None)
        return first is not None and bool(self.targets) and all(self._reads(first, option, group, mapping))

    def _reads(self, first: sympy.Expr, option: tuple, group: list, mapping: dict) -> tuple[bool, bool]:
        """(holds, has a shape of (1)-(4)) of the relation ``first`` with ``group`` read as ``option``."""
        m = {**mapping, **{p: e for p, (_w, e) in zip(group, option, strict=True)}}
        d = first.xreplace({k: self.ctx.in_unknowns(v).xreplace(self.pt) for k, v in m.items()})
        c = linear_part(d, self.U)
        return self._holds(d), bool(c and any(alike(c, t) for t in self.targets))

    def _holds(self, d: sympy.Expr) -> bool:
        terms = [number_of(t.xreplace(self.truth)) for t in sympy.Add.make_args(sympy.expand(d))]
        if any(t is None for t in terms):
            return False
        return abs(sum(terms)) <= 0.01 * max([abs(t) for t in terms] + [1e-12])


def linear_part(expr: sympy.Expr, U: tuple) -> dict | None:
    """The coefficients of ``expr``'s terms in the unknowns (its constant left out)."""
    if expr.free_symbols - set(U) or not expr.free_symbols:
        return None
    out = {}
    for m, c in sympy.expand(expr).as_coefficients_dict().items():
        x = number_of(c)
        if x is None:
            return None
        if m != 1 and abs(x) > 1e-12:
            out[m] = x
    return out


def alike(a: dict, b: dict) -> bool:
    if set(a) != set(b):
        return False
    key = next(iter(b))
    ratio = a[key] / b[key]
    return all(abs(a[m] - ratio * b[m]) <= 2e-3 * abs(ratio * b[m]) for m in b)
