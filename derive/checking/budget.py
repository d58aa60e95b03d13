"""A bounded time for judging a derivation's lines: a line not judged in time is "not checked",
and the report of the others still comes back (issue #31, item 8: every report in under 10 s).

The budget is CPU seconds of this process (``ITIMER_VIRTUAL``), so that a busy machine does
not turn lines into "not checked" that a quiet one judges; a line still being judged when it
runs out is interrupted (the timer's signal, where this is the main thread; elsewhere the
budget is looked at between lines). A generous wall-clock limit, looked at between lines, keeps
the report inside the command's own time budget on a machine too busy to give it the CPU.
"""

from __future__ import annotations

import signal
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any, TypeVar

#: CPU seconds for judging the lines of one derivation (the corpus's slowest takes about 2).
CPU_SECONDS = 8.0
#: Wall seconds after which the lines not yet judged are not checked (the command stops at 60).
WALL_SECONDS = 40.0

T = TypeVar("T")
R = TypeVar("R")


class OutOfBudget(BaseException):
    """The time for judging ran out. Not an Exception: no ``except Exception`` inside SymPy
    may swallow it."""


def lines_judged(trace: Any, lines: Sequence[Any], text: str) -> list[Any]:
    """A derivation's ``lines`` judged by ``trace`` (:class:`~.lines.Trace`) while the budget
    lasts, an angle line as the angle its words name (:mod:`.angles`) first."""
    from derive.checking.angles import judge as angle
    from derive.checking.byvalue import item, placed_ahead
    from derive.checking.givenlines import restated_item
    from derive.checking.givensigns import named
    from derive.checking.otherroots import not_marked

    typed = text.splitlines()
    placed_ahead(trace, list(lines))  # names read by their values: the first line they hold in
    return judged(
        lambda line: (
            None
            if not_marked(trace, line, lines, typed)
            else restated_item(trace, line, lines, typed)
            or angle(trace, line, typed)
            or named(trace, line, item(trace, line))
        ),
        lines,
        lambda line, why: trace._item(line, "not checked", why, ""),
    )


def judged(judge: Callable[[T], R], lines: Sequence[T], not_checked: Callable[[T, str], R]) -> list[R]:
    """``judge(line)`` for each of ``lines`` in turn, while the budget lasts; then
    ``not_checked(line, why)`` for the line interrupted and each after it."""
    out: list[R] = []
    cpu_end, wall_end = time.process_time() + CPU_SECONDS, time.monotonic() + WALL_SECONDS
    try:
        with _interrupt_after(CPU_SECONDS):
            for line in lines:
                if time.process_time() > cpu_end or time.monotonic() > wall_end:
                    raise OutOfBudget
                out.append(judge(line))
    except OutOfBudget:
        pass
    why = (
        f"Not checked: the time for checking a derivation ({CPU_SECONDS:g} s of computing) ran out before "
        "this line was judged."
    )
    return out + [not_checked(line, why) for line in lines[len(out) :]]


class _interrupt_after:
    """Raise :class:`OutOfBudget` in the main thread after ``seconds`` of this process's CPU time;
    the timer and the handler in place before are put back."""

    def __init__(self, seconds: float) -> None:
        self.seconds = seconds
        self.armed = False
        self.usable = (
            seconds > 0 and hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
        )

    def _fire(self, signum: int, frame: object) -> None:
        if self.armed:
            self.armed = False
            raise OutOfBudget

    def __enter__(self) -> _interrupt_after:
        if self.usable:
            self.old_handler = signal.signal(signal.SIGVTALRM, self._fire)
            self.old_timer = signal.setitimer(signal.ITIMER_VIRTUAL, self.seconds)
            self.armed = True
        return self

    def __exit__(self, *exc: object) -> None:
        if self.usable:
            self.armed = False
            signal.setitimer(signal.ITIMER_VIRTUAL, *self.old_timer)
            signal.signal(signal.SIGVTALRM, self.old_handler)
