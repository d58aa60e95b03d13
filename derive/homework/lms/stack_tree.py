"""What a STACK question grades with, for one asked result: each variant's right answer and,
for each common mistake, the range of responses that gets its feedback in each variant.

The potential response tree is the same for every variant (STACK keeps one tree per
question); what changes from variant to variant is held in the question variables' lists,
indexed by the variant. So the tree has one node per mistake (the answer note is the
mistake's name, so that STACK's response report counts each mistake across the class),
and each node's range is that mistake's range in the variant: the ranges of
:func:`~derive.homework.lms.mistake_model.mistake_ranges`, where a mistake's ranges make
one interval (the range centred on its value and what is left on its wider side). Where
mistakes give the same value in a variant, the node of the first (in the order of
:data:`derive.checking.mistakes.REGISTRY`) holds it and gives all their hints. A node with
no range in a variant (the mistake gives no value there, or the right one, or a value held
by another node) is off: its range is the right answer's value with no width, which the
right answer's node, tried first, always takes.
"""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal

from derive.homework.lms.grading import Answer, asked_answer
from derive.homework.lms.mistake_model import MistakeModel, Wrong, mistake_ranges
from derive.homework.variants import Compiled, Variant, answers


@dataclass(frozen=True)
class Span:
    """A node's range in one variant, center ± half; ``shown`` the mistake's value as the key
    shows it and ``names`` the mistakes that give it (both empty when the node is off)."""

    center: Decimal
    half: Decimal
    shown: str
    names: tuple[str, ...]

    @property
    def live(self) -> bool:
        return bool(self.names)


@dataclass(frozen=True)
class MistakeNode:
    """A node of the tree after the right answer's: the mistake that names it, its hint, and
    its range in each variant (in the order of the variants)."""

    name: str
    hint: str
    spans: tuple[Span, ...]

    def shared(self) -> dict[str, tuple[int, ...]]:
        """The other mistakes whose value this node holds, and in which variants (1-based)."""
        out: dict[str, list[int]] = {}
        for k, span in enumerate(self.spans, 1):
            for other in span.names:
                if other != self.name:
                    out.setdefault(other, []).append(k)
        return {name: tuple(ks) for name, ks in out.items()}

    def always_live(self) -> bool:
        """Whether the node has a range in every variant (a question test can then reach it)."""
        return all(s.live for s in self.spans)


@dataclass(frozen=True)
class Tree:
    """One asked result's right answers (one per variant) and mistake nodes."""

    result: str
    rights: tuple[Answer, ...]
    nodes: tuple[MistakeNode, ...]


def _spans(right: Answer, wrongs: list[Wrong]) -> list[tuple[Wrong, Decimal, Decimal]]:
    """Each wrong value's range as one interval (low, high): the union of its ranges."""
    bounds: dict[str, tuple[Wrong, Decimal, Decimal]] = {}
    for r in mistake_ranges(right, wrongs):
        w, low, high = bounds.get(r.wrong.shown, (r.wrong, r.low, r.high))
        bounds[r.wrong.shown] = (w, min(low, r.low), max(high, r.high))
    return list(bounds.values())


def build_tree(
    compiled: Compiled, variants: list[Variant], result: str, digits: int | None, model: MistakeModel
) -> Tree:
    """The right answers and mistake nodes of ``result`` over ``variants``."""
    d = digits if digits is not None else compiled.problem.digits
    order = list(model.registry)
    rights: list[Answer] = []
    held: list[dict[str, Span]] = []
    for v in variants:
        right = asked_answer(result, answers(compiled, v, digits)[result], d)
        rights.append(right)
        spans: dict[str, Span] = {}
        for w, low, high in _spans(right, model.wrong(v, right, digits)):
            holder = min(w.mistakes, key=order.index)
            spans[holder] = Span((low + high) / 2, (high - low) / 2, w.shown, w.mistakes)
        held.append(spans)
    nodes = []
    for name in order:
        if not any(name in spans for spans in held):
            continue
        row = tuple(
            spans.get(name) or Span(right.value, Decimal(0), "", ()) for spans, right in zip(held, rights, strict=True)
        )
        nodes.append(MistakeNode(name, model.registry[name].description, row))
    return Tree(result, tuple(rights), tuple(nodes))
