"""Timing hostile input against a baseline measured in the same run (the machines are shared
and noisy: an absolute limit fails on a busy machine, a ratio does not)."""

from __future__ import annotations

import time
from collections.abc import Callable


def cpu_seconds(run: Callable[[], object]) -> float:
    """The process's CPU time one call of ``run`` takes."""
    start = time.process_time()
    run()
    return time.process_time() - start


def grows_about_linearly(run: Callable[[int], object], small: int, large: int) -> tuple[float, float]:
    """Time ``run(small)`` and ``run(large)``; fail when the large one takes more than two and a
    half times what a linear growth gives (a quadratic growth gives ``large/small`` times that).
    The small one's best of three, and the large one's best of two where the first is over: a
    pause of the machine's in one run is not the code's growth."""
    run(small)  # anything done once (the problem's solution, imports) is out of both figures
    t_small = min(cpu_seconds(lambda: run(small)) for _ in range(3))
    limit = 2.5 * (large / small) * max(t_small, 0.02)
    t_large = cpu_seconds(lambda: run(large))
    if t_large >= limit:
        t_large = min(t_large, cpu_seconds(lambda: run(large)))
    assert t_large < limit, f"{large} took {t_large:.2f} s, {small} took {t_small:.2f} s: not linear"
    return t_small, t_large
