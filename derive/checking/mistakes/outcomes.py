"""The mistakes solved for one solution, cached: the correct outcome, each mistake's, each pair's."""

from __future__ import annotations

import itertools

import sympy

from derive.checking.mistakes.equations import Model, point
from derive.checking.mistakes.pairs import MAX_PAIRS, combine
from derive.checking.mistakes.records import Outcome
from derive.checking.mistakes.registry import FORMS, REGISTRY
from derive.steps.model import Solution


class _Entry:
    """What is cached for one solution: its model, the correct outcome, the mistakes' outcomes."""

    def __init__(self, solution: Solution) -> None:
        self.model = Model(solution)
        self.base = self.model.outcome(self.model.base())
        self.found: list[Outcome] | None = None
        self.paired: list[Outcome] | None = None
        self.shapes: list[Outcome] | None = None

    def outcomes(self) -> list[Outcome]:
        if self.found is None:
            found = []
            for m in REGISTRY.values():
                variant = m.build(self.model)
                if variant is None:
                    continue
                out = self.model.outcome(variant, m)
                if out is None or self.base is None or not changes(out, self.base):
                    continue
                found.append(out)
            self.found = found
        return self.found

    def forms(self) -> list[Outcome]:
        """Each mistake's equations as a student writes them where solving them gives nothing
        (B's sign in a find-e problem leaves no approach) or the mistake is made on one side
        of an equation only: their equations, and the unknowns they give where they give them
        (``post``; no other results)."""
        if self.shapes is None:
            solved = {o.mistake.name for o in self.outcomes() if o.mistake is not None}
            found = []
            for m in REGISTRY.values():
                variant = m.build(self.model)
                if variant is None:
                    continue
                shapes = [] if m.name in solved else [self.model.numbered(variant)]
                if m.name in FORMS:
                    shapes += FORMS[m.name](self.model, variant)
                found += [Outcome(m, {}, self._post(eqs), eqs, self.model.unknowns) for eqs in shapes]
            self.shapes = found
        return self.shapes

    def _post(self, eqs: dict[int, sympy.Expr]) -> dict[sympy.Symbol, sympy.Expr]:
        """The unknowns as ``eqs`` give them (numbers only; {} where they give none)."""
        if any(x.free_symbols - set(self.model.unknowns) for x in eqs.values()):
            return {}
        near = self.base.post if self.base is not None else None
        numeric = [sympy.N(x, 30) for x in eqs.values()]  # exact cosines make SymPy's solve slow
        return self.model.roots(numeric, near) or {}

    def pairs(self) -> list[Outcome]:
        if self.paired is None:
            singles = self.outcomes()
            found = []
            for a, b in itertools.islice(itertools.combinations(singles, 2), MAX_PAIRS):
                assert a.mistake is not None and b.mistake is not None
                both = combine(a.mistake, b.mistake)
                variant = both.build(self.model)
                out = self.model.outcome(variant, both) if variant is not None else None
                if out is None or self.base is None:
                    continue
                if all(changes(out, other) for other in (self.base, a, b)):
                    found.append(out)
            self.paired = found
        return self.paired


#: The mistakes solved lately, by the results they were solved against: a solution of the same
#: problem (loaded again, :mod:`derive.physics.recent`) shares its results, and its mistakes.
_CACHE: list[_Entry] = []


def _cached(solution: Solution) -> _Entry:
    for entry in reversed(_CACHE):
        if entry.model.results is solution.results:
            return entry
    entry = _Entry(solution)
    _CACHE.append(entry)
    if len(_CACHE) > 8:
        _CACHE.pop(0)
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


def forms(solution: Solution) -> list[Outcome]:
    """The mistakes' equations that are not an outcome's: unsolvable, or the mistake made on
    one side of an equation only (cached; ``results`` and ``post`` empty)."""
    return list(_cached(solution).forms())


def pair_outcomes(solution: Solution) -> list[Outcome]:
    """Every pair of those mistakes that gives something neither gives alone, solved (cached;
    at most :data:`~.pairs.MAX_PAIRS` pairs are tried)."""
    return list(_cached(solution).pairs())


def changes(out: Outcome, base: Outcome) -> bool:
    """True when some result of ``out`` differs from ``base``'s."""
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
            d = d.xreplace(point(syms))
        try:
            x = complex(d.evalf(30))
            scale = max(1.0, abs(complex(b.partial.xreplace(point(syms) if syms else {}).evalf(30))))
        except (TypeError, ValueError):
            continue
        if abs(x) > 1e-12 * scale:
            return True
    return False
