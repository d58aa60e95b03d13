"""Drawing variants: the varied givens' values, distinct and physical, the same for the same
seed and file anywhere."""

from __future__ import annotations

import math
import random

from derive.errors import InputError
from derive.homework.variants.compile import Compiled
from derive.homework.variants.record import Variant
from derive.problem import ChainProblem, Problem

MAX_ATTEMPTS_PER_VARIANT = 200
#: The most variants one run draws (each is a page or two on disk).
MAX_COUNT = 10_000
#: Draws between looks at the rate of success: where it cannot reach the count, stop.
GIVE_UP_AFTER = 2_000
#: The same where every draw is tested by a solve (a chain: tenths of a second each).
CHAIN_GIVE_UP_AFTER = 50


def draw(compiled: Compiled, count: int, seed: int) -> list[Variant]:
    """``count`` distinct physical variants, the same for the same seed and file anywhere."""
    p = compiled.problem
    look = GIVE_UP_AFTER if compiled.check is not None else CHAIN_GIVE_UP_AFTER
    rng = random.Random(seed)
    pools = [p.vary[n] for n in compiled.names]
    seen: set[tuple[int, ...]] = set()
    out: list[Variant] = []
    attempts = 0
    total = math.prod(len(x) for x in pools)
    budget = MAX_ATTEMPTS_PER_VARIANT * count
    while len(out) < count and attempts < budget and len(seen) < total:
        attempts += 1
        if attempts % look == 0 and len(out) * (budget - attempts) < (count - len(out)) * attempts:
            raise InputError(
                f"{len(out)} of the first {attempts:,} draws {_what_is_met(p)}; at that rate {count} variants "
                f"cannot be found: check the conditions and the [vary] ranges{_last_refusal(compiled)}",
                where=p.path,
                field="--count",
            )
        key = tuple(rng.randrange(len(pool)) for pool in pools)
        if key in seen:
            continue
        seen.add(key)
        values = {n: pool[i] for n, pool, i in zip(compiled.names, pools, key, strict=True)}
        if compiled.accepts(values):
            out.append(Variant(len(out) + 1, values))
    if len(out) < count:
        raise InputError(
            f"only {len(out)} distinct physical variants found for {count} asked "
            f"(widen the [vary] ranges or relax the conditions){_last_refusal(compiled)}",
            where=p.path,
            field="--count",
        )
    return out


def _what_is_met(problem: Problem | ChainProblem) -> str:
    if problem.conditions:
        texts = [c if isinstance(c, str) else c.text for c in problem.conditions]
        return "meet " + " and ".join(texts)
    if problem.kind == "chain":
        return "are physical (every stage solves: bodies that approach, one admissible root)"
    return "are physical (bodies that approach, 0 <= e <= 1, positive masses)"


def _last_refusal(compiled: Compiled) -> str:
    """Why the last refused draw of a chain was refused (a chain says why it does not solve)."""
    reason = getattr(compiled, "refusal", "")
    return f"; the last refused: {reason}" if reason else ""
