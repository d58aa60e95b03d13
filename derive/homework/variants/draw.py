"""Drawing variants: the varied givens' values, distinct and physical, the same for the same
seed and file anywhere."""

from __future__ import annotations

import math
import random

from derive.errors import InputError
from derive.homework.variants.compile import Compiled, Variant
from derive.problem import Problem

MAX_ATTEMPTS_PER_VARIANT = 200
#: The most variants one run draws (each is a page or two on disk).
MAX_COUNT = 10_000
#: Draws between looks at the rate of success: where it cannot reach the count, stop.
GIVE_UP_AFTER = 2_000


def draw(compiled: Compiled, count: int, seed: int) -> list[Variant]:
    """``count`` distinct physical variants, the same for the same seed and file anywhere."""
    p = compiled.problem
    rng = random.Random(seed)
    pools = [p.vary[n] for n in compiled.names]
    seen: set[tuple[int, ...]] = set()
    out: list[Variant] = []
    attempts = 0
    total = math.prod(len(x) for x in pools)
    budget = MAX_ATTEMPTS_PER_VARIANT * count
    while len(out) < count and attempts < budget and len(seen) < total:
        attempts += 1
        if attempts % GIVE_UP_AFTER == 0 and len(out) * (budget - attempts) < (count - len(out)) * attempts:
            raise InputError(
                f"{len(out)} of the first {attempts:,} draws {_what_is_met(p)}; at that rate {count} variants "
                "cannot be found: check the conditions and the [vary] ranges",
                where=p.path,
                field="--count",
            )
        key = tuple(rng.randrange(len(pool)) for pool in pools)
        if key in seen:
            continue
        seen.add(key)
        values = {n: pool[i] for n, pool, i in zip(compiled.names, pools, key, strict=True)}
        if compiled.check_fn(*(float(v) for v in values.values())):
            out.append(Variant(len(out) + 1, values))
    if len(out) < count:
        raise InputError(
            f"only {len(out)} distinct physical variants found for {count} asked "
            "(widen the [vary] ranges or relax the conditions)",
            where=p.path,
            field="--count",
        )
    return out


def _what_is_met(problem: Problem) -> str:
    if problem.conditions:
        return "meet " + " and ".join(c.text for c in problem.conditions)
    return "are physical (bodies that approach, 0 <= e <= 1, positive masses)"
