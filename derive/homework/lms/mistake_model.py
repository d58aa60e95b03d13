"""Wrong answers that common mistakes give (:mod:`derive.checking.mistakes`) for each
variant, and the ranges in which a response gets a mistake's hint."""

from __future__ import annotations

import copy
from dataclasses import dataclass, replace
from decimal import Decimal

import sympy

from derive.checking import mistakes
from derive.homework.lms.grading import Answer, figures_of, tolerance
from derive.homework.variants import Compiled, Variant
from derive.numbers import float_decimal, format_number
from derive.problem import Problem


@dataclass(frozen=True)
class Wrong:
    """A wrong value that common mistakes predict, shown as the key shows numbers, and their hints."""

    shown: str
    tolerance: Decimal
    mistakes: tuple[str, ...]
    hints: tuple[str, ...]


class MistakeModel:
    """The common mistakes of :mod:`derive.mistakes` for every variant of a compiled problem.

    The mistakes' equations are set up once, on the problem with its varied givens
    symbolic; a variant only puts its numbers in (no new solve of the problem), so
    a variant costs about a tenth of a second.
    """

    def __init__(self, compiled: Compiled) -> None:
        self.compiled = compiled
        # the mistakes are a single impact's: a chain's questions have no mistake answers
        self.base = mistakes.Model(compiled.solution) if isinstance(compiled.problem, Problem) else None
        self.registry = mistakes.REGISTRY
        self._wrong: dict[tuple, list[Wrong]] = {}
        self._outcomes: dict[tuple, list[tuple[str, dict]]] = {}

    def model(self, variant: Variant) -> mistakes.Model:
        """The mistakes' model with this variant's numbers in."""
        base, c = self.base, self.compiled
        values = {c.givens[n].symbol: variant.values[n] for n in c.names}
        numeric = {**base.numeric, **values}
        givens = []
        for g in base.problem.givens:
            if g.name in variant.values:
                g = replace(g, value=variant.values[g.name])
            elif g.value is None and g.definition is not None and not g.unknown:
                value = base.num(g.definition, values)
                if not value.free_symbols:
                    g = replace(g, value=value)
                    numeric[g.symbol] = value
            givens.append(g)
        m = copy.copy(base)  # shares the solved forms of the equations, which hold no numbers
        m.numeric = numeric
        m.problem = replace(base.problem, givens=tuple(givens))
        return m

    def outcomes(self, variant: Variant) -> list[tuple[str, dict]]:
        """(mistake name, the results it gives) for each mistake that applies to the variant,
        worked out once a variant (the STACK export asks for several results of each)."""
        key = (variant.number, tuple(sorted((k, str(x)) for k, x in variant.values.items())))
        if key not in self._outcomes:
            m = self.model(variant)
            out = []
            for mk in self.registry.values():
                built = mk.build(m)
                outcome = m.outcome(built, mk) if built is not None else None
                if outcome is not None:
                    out.append((mk.name, outcome.results))
            self._outcomes[key] = out
        return self._outcomes[key]

    def values(self, variant: Variant, result: str) -> list[tuple[str, float]]:
        """(mistake name, the value of ``result`` it gives) for each mistake that applies."""
        out = []
        for name, results in self.outcomes(variant):
            q = results.get(result)
            if q is None or q.value is None:
                continue
            try:
                x = complex(sympy.sympify(q.value).evalf(30))
            except (TypeError, ValueError):
                continue
            if abs(x.imag) > 1e-9 * max(1.0, abs(x.real)) or x.real != x.real or abs(x.real) == float("inf"):
                continue
            out.append((name, x.real))
        return out

    def wrong(self, variant: Variant, right: Answer, digits: int | None) -> list[Wrong]:
        """The mistakes' values for ``right.name`` that a student would not get right anyway,
        one per value shown (mistakes that give the same value share it), in order of value."""
        if self.base is None:
            return []
        d = digits if digits is not None else self.compiled.problem.digits
        key = (variant.number, tuple(sorted((k, str(x)) for k, x in variant.values.items())), right, d)
        if key in self._wrong:
            return self._wrong[key]
        found: dict[str, list[str]] = {}
        figs: dict[str, int] = {}
        for name, x in self.values(variant, right.name):
            shown = format_number(float_decimal(x), d)
            if abs(Decimal(shown) - right.value) <= right.tolerance:
                continue  # within the right answer's tolerance: it grades as right
            found.setdefault(shown, []).append(name)
            figs.setdefault(shown, figures_of(x, d))
        out = [
            Wrong(
                shown, tolerance(shown, figs[shown]), tuple(names), tuple(self.registry[n].description for n in names)
            )
            for shown, names in sorted(found.items(), key=lambda item: Decimal(item[0]))
        ]
        self._wrong[key] = out
        return out


@dataclass(frozen=True)
class Range:
    """Where a response gets a wrong answer's feedback: center ± half_width."""

    center: Decimal
    half_width: Decimal
    wrong: Wrong

    @property
    def low(self) -> Decimal:
        return self.center - self.half_width

    @property
    def high(self) -> Decimal:
        return self.center + self.half_width


def mistake_ranges(right: Answer, wrongs: list[Wrong]) -> list[Range]:
    """The ranges of the mistakes' answers, so that a response gets the feedback of the
    mistake nearest to it whichever answer an LMS tries first.

    A mistake's range is its own tolerance about its value, cut where it meets the
    right answer's range (which wins) and halfway to the next mistake's value. Each
    mistake's first range is centred on its value (the widest that fits); what is
    left on the wider side follows as a second range with the same feedback.
    """
    ordered = sorted(wrongs, key=lambda w: Decimal(w.shown))
    right_low, right_high = right.value - right.tolerance, right.value + right.tolerance
    out: list[Range] = []
    for i, w in enumerate(ordered):
        v = Decimal(w.shown)
        low, high = v - w.tolerance, v + w.tolerance
        if i > 0:
            low = max(low, (Decimal(ordered[i - 1].shown) + v) / 2)
        if i + 1 < len(ordered):
            high = min(high, (v + Decimal(ordered[i + 1].shown)) / 2)
        if v > right.value:
            low = max(low, right_high)
        else:
            high = min(high, right_low)
        half = min(v - low, high - v)
        if half <= 0:
            continue
        out.append(Range(v, half, w))
        rest_low, rest_high = (v + half, high) if high - v > half else (low, v - half)
        if rest_high > rest_low:
            out.append(Range((rest_low + rest_high) / 2, (rest_high - rest_low) / 2, w))
    return out


def hint_text(wrong: Wrong) -> str:
    """A wrong answer's feedback as one line: a lead sentence, then the mistakes' hints."""
    lead = "A common mistake gives this value." if len(wrong.hints) == 1 else "Common mistakes give this value."
    return " ".join([lead, *wrong.hints])
