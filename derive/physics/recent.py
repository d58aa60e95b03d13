"""The last few problems worked out, found again by value: a problem loaded again from the
same file (a second ``derive check``, the corpus's many derivations of one problem, a
notebook) is a new object equal to the old, and what was worked out for the old holds for it.

A key is the problem and the text it was read from (a comment moved in the file moves the
lines its messages name); a lookup compares keys with ``==``, newest first, so the store is
a short list, not a hash table (a problem holds dictionaries and is not hashable).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, Generic, TypeVar

V = TypeVar("V")


def value_key(problem: Any) -> tuple[Any, ...]:
    """``problem`` with what its equality leaves out: the file's text and place, whether its
    sizes are schematic."""
    src = getattr(problem, "ctx", None)
    where = tuple(getattr(src, k, None) for k in ("path", "text", "scope", "label")) if src is not None else None
    return (type(problem), problem, where, getattr(problem, "sizes_schematic", None))


class Recent(Generic[V]):
    """At most ``size`` values, each under the key of the problem it was worked out for."""

    def __init__(self, size: int = 8) -> None:
        self.size = size
        self.entries: list[tuple[tuple[Any, ...], V]] = []

    def get(self, problem: Any, work: Callable[[], V], adopt: Callable[[V], V] | None = None) -> V:
        """The value kept for a problem equal to ``problem``, else ``work()`` kept for it; a value
        found for another object equal to it is ``adopt``-ed and kept for this one (so that the
        same object finds the same value again)."""
        key = value_key(problem)
        for i in range(len(self.entries) - 1, -1, -1):
            k, value = self.entries[i]
            if k[1] is problem or k == key:
                if k[1] is not problem and adopt is not None:
                    value = adopt(value)
                    k = key
                self.entries.pop(i)
                self.entries.append((k, value))
                return value
        value = work()
        self.entries.append((key, value))
        if len(self.entries) > self.size:
            self.entries.pop(0)
        return value
