"""``dataclass``: the standard library's, with the code of its generated methods kept on disk.

A frozen dataclass costs Python 3.11 about 0.6 ms to define: ``dataclasses`` writes the source
of six methods (``__init__``, ``__repr__``, ``__eq__``, ``__hash__``, ``__setattr__``,
``__delattr__``) and compiles each with ``exec``. derive defines over a hundred, 43 of them on
the way to one worked solution: 26 ms of a 0.4 s command (issue #19). Compiling the same source
text always gives the same code, so the code is kept, by source text, in the user's cache folder
(``$XDG_CACHE_HOME/derive``, as the compiled templates are) and read back once a process: the
same 43 classes then take about 5 ms. The classes are exactly what ``dataclasses.dataclass``
makes; only the compiling is skipped. (The verifier, which reads derive's pages and imports
nothing of derive, keeps the standard library's.) ``DERIVE_NO_CACHE=1`` turns the cache off,
and a cache that cannot be read or written, or that another user could have written, is
ignored (the methods are compiled, as without it).
"""

from __future__ import annotations

import atexit
import builtins
import dataclasses
import marshal
import os
import sys
from pathlib import Path
from types import CodeType
from typing import Any

from derive.resources import cache_disabled, cache_folder, private

__all__ = ["dataclass"]


#: Source text of a generated method -> its code, for this Python (None: not read yet).
_codes: dict[str, CodeType] | None = None
#: Whether a method was compiled that the file on disk does not hold.
_dirty = False
#: The source texts this process used (what the file keeps when it has grown too big).
_used: set[str] = set()
#: Methods the file holds at most: derive's own are about 650; more are older versions'.
LIMIT = 2000


def dataclass(cls: type | None = None, /, **options: Any) -> Any:
    """``dataclasses.dataclass(cls, **options)``, its methods' code read from the cache."""
    if cls is None:
        return lambda c: dataclass(c, **options)
    if cache_disabled():
        return dataclasses.dataclass(cls, **options)
    # dataclasses compiles with the name exec from its own module globals (the builtin):
    # for this one class it finds _exec instead, which compiles only what is not kept
    had = "exec" in vars(dataclasses)
    saved = vars(dataclasses).get("exec")
    dataclasses.exec = _exec  # type: ignore[attr-defined]
    try:
        return dataclasses.dataclass(cls, **options)
    finally:
        if had:
            dataclasses.exec = saved  # type: ignore[attr-defined]
        else:
            del dataclasses.exec  # type: ignore[attr-defined]


def _exec(source: Any, globals_: dict[str, Any] | None = None, locals_: dict[str, Any] | None = None) -> None:
    """``exec(source, globals_, locals_)``, the source's compiled code taken from the cache."""
    global _dirty
    if not isinstance(source, str):
        builtins.exec(source, globals_, locals_)
        return
    codes = _cache()
    _used.add(source)
    code = codes.get(source)
    if code is None:
        code = codes[source] = compile(source, "<string>", "exec")
        if not _dirty:
            _dirty = True
            atexit.register(_save)
    builtins.exec(code, globals_, locals_)


def _file() -> Path:
    """The cache file: one per Python (marshal's format and the code differ between them)."""
    return cache_folder() / f"records-{sys.implementation.cache_tag}.marshal"


def _cache() -> dict[str, CodeType]:
    """The kept code, read from disk on first use (empty when there is none or it is unreadable)."""
    global _codes
    if _codes is None:
        _codes = {}
        data = None
        try:
            path = _file()
            if private(path) and private(path.parent):  # only code the user's own processes wrote
                data = marshal.loads(path.read_bytes())
        except (OSError, RuntimeError, ValueError, EOFError, TypeError):
            data = None
        if isinstance(data, dict):
            _codes = {k: v for k, v in data.items() if isinstance(k, str) and isinstance(v, CodeType)}
    return _codes


def _save() -> None:
    """Write the kept code (at exit, when something new was compiled), atomically; a disk that
    is read-only or full leaves it unwritten."""
    try:
        path = _file()
        import tempfile  # only when something new is written

        path.parent.mkdir(mode=0o700, parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=".records-", suffix=".tmp")
        try:
            codes = _cache()
            if len(codes) > LIMIT:  # older versions' methods: keep this process's only
                codes = {k: v for k, v in codes.items() if k in _used}
            with os.fdopen(fd, "wb") as out:
                marshal.dump(codes, out)
            os.replace(tmp, path)
        except BaseException:
            os.unlink(tmp)
            raise
    except (OSError, RuntimeError, ValueError):
        pass
