"""derive.records.dataclass (issue #19): the standard library's dataclass, the code of its
generated methods kept in the user's cache folder so that a process does not compile it again."""

from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
from pathlib import Path

import pytest

from derive.records import dataclass

#: A fresh interpreter defines a frozen record and prints whether it compiled anything new.
_DEFINE = """
import dataclasses, sys
from derive import records
@records.dataclass(frozen=True)
class Point:
    x: int
    y: int = 2
p = Point(1)
assert p == Point(1, 2) and hash(p) == hash(Point(1, 2)) and repr(p).endswith("Point(x=1, y=2)")
try:
    p.x = 3
except dataclasses.FrozenInstanceError:
    pass
else:
    raise SystemExit("not frozen")
print("compiled" if records._dirty else "read")
"""


def _define(cache: Path, **env: str) -> str:
    """Run _DEFINE with XDG_CACHE_HOME=cache; its last line of output."""
    environ = {k: v for k, v in os.environ.items() if k not in ("DERIVE_NO_CACHE", "DERIVE_NO_TEMPLATE_CACHE")}
    environ.update(XDG_CACHE_HOME=str(cache), **env)
    r = subprocess.run([sys.executable, "-c", _DEFINE], capture_output=True, text=True, env=environ, check=True)
    assert r.stderr == ""
    return r.stdout.split()[-1]


def test_a_record_is_what_the_standard_librarys_dataclass_makes() -> None:
    @dataclass(frozen=True)
    class Ours:
        a: int
        b: tuple[int, ...] = ()

    @dataclasses.dataclass(frozen=True)
    class Theirs:
        a: int
        b: tuple[int, ...] = ()

    ours, theirs = Ours(1, (2,)), Theirs(1, (2,))
    assert [f.name for f in dataclasses.fields(ours)] == [f.name for f in dataclasses.fields(theirs)] == ["a", "b"]
    assert repr(ours).split("Ours")[1] == repr(theirs).split("Theirs")[1] == "(a=1, b=(2,))"
    assert ours == Ours(1, (2,)) and ours != Ours(2) and hash(ours) == hash(Ours(1, (2,)))
    assert dataclasses.replace(ours, a=5) == Ours(5, (2,))
    with pytest.raises(dataclasses.FrozenInstanceError):
        ours.a = 2  # type: ignore[misc]
    # no lasting change to the standard library: its dataclasses compile with the builtin exec
    assert "exec" not in vars(dataclasses)


def test_the_compiled_methods_are_kept_in_the_users_cache_folder(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    assert _define(cache) == "compiled"  # the first process compiles and keeps the code
    kept = list((cache / "derive").glob("records-*.marshal"))
    assert len(kept) == 1 and kept[0].stat().st_size > 0
    assert _define(cache) == "read"  # the next one compiles nothing


def test_a_cache_it_cannot_use_never_stops_a_record(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    folder = cache / "derive"
    folder.mkdir(parents=True)
    (folder / f"records-{sys.implementation.cache_tag}.marshal").write_bytes(b"\x00not marshal data")
    assert _define(cache) == "compiled"  # a corrupt file is read as empty, then replaced
    assert _define(cache) == "read"
    if os.geteuid() != 0:  # root writes anywhere
        other = tmp_path / "read-only"
        other.mkdir(mode=0o500)
        assert _define(other) == "compiled"
        assert not any(other.iterdir())


def test_derive_no_cache_writes_nothing(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    assert _define(cache, DERIVE_NO_CACHE="1") == "read"  # the plain dataclass: nothing kept
    assert not cache.exists()


def test_a_cache_another_user_could_write_is_not_read(tmp_path: Path) -> None:
    """derive runs the code its cache holds: a file or folder others may write to is ignored."""
    cache = tmp_path / "cache"
    assert _define(cache) == "compiled"
    kept = cache / "derive" / f"records-{sys.implementation.cache_tag}.marshal"
    kept.chmod(0o666)
    assert _define(cache) == "compiled"  # not read; written again, the user's own
    assert kept.stat().st_mode & 0o777 == 0o600
    assert _define(cache) == "read"
    (cache / "derive").chmod(0o777)
    assert _define(cache) == "compiled"
