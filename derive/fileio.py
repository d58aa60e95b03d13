"""Reading user files and writing outputs so that nothing is lost or half-written.

A file is written to a temporary file and renamed over the output; a folder of outputs
is written to a temporary folder and swapped with the old one in one step, so a run
stopped at any point (Ctrl-C, a time-out, ``kill -9``) leaves the old output or the new
one, never a mix. JSON is written strictly: no NaN or Infinity, which is not JSON.
"""

from __future__ import annotations

import contextlib
import math
import os
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from derive.errors import InputError, RenderError


def write_atomic(path: str | Path, data: str | bytes, *, inputs: tuple[Path, ...] = ()) -> None:
    """Write ``data`` to ``path`` atomically; refuse to overwrite any of ``inputs``.

    A reader sees the old file or the new one, never half of either.
    """
    path = Path(path)
    for src in inputs:
        try:
            if path.exists() and src.exists() and path.resolve() == src.resolve():
                raise InputError("refusing to overwrite the input file with the output", where=str(path), field="-o")
        except OSError:
            continue
    if path.is_dir():
        raise InputError("is a folder; give a file name for the output", where=str(path), field="-o")
    folder = path.parent if str(path.parent) else Path(".")
    if not folder.is_dir():
        raise InputError("the folder for the output does not exist", where=str(path), field="-o")
    payload = data.encode("utf-8") if isinstance(data, str) else data
    if path.exists() and not path.is_file():
        # a device or a pipe (-o /dev/stdout): write into it; renaming over it would replace it
        try:
            with open(path, "wb") as fh:
                fh.write(payload)
        except OSError as exc:
            raise _cannot_write(path, exc) from exc
        return
    try:
        _sweep(folder, path.name)
        fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise _cannot_write(path, exc) from exc
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(payload)
            fh.flush()
            os.fsync(fh.fileno())
        if path.exists():
            os.chmod(tmp, path.stat().st_mode & 0o777)
        else:
            os.chmod(tmp, 0o644)
        os.replace(tmp, path)
    except OSError as exc:
        raise _cannot_write(path, exc) from exc
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


def _cannot_write(path: Path, exc: OSError) -> RenderError:
    return RenderError(f"{path}: cannot write the output ({exc.strerror or exc})")


MAX_INPUT = 1_000_000  # bytes: a problem or answers file is small


def read_user_text(path: str | Path, what: str) -> str:
    """The text of a file someone wrote (``what``: "a problem file", "an answers file"),
    or a one-line InputError naming the file: missing, a folder, unreadable, too
    large, or not UTF-8."""
    shown = str(path)
    try:
        with open(path, "rb") as fh:  # no more than the limit: /dev/zero or a huge file must not fill memory
            raw = fh.read(MAX_INPUT + 1)
    except FileNotFoundError:
        raise InputError("no such file", where=shown) from None
    except IsADirectoryError:
        raise InputError(f"is a folder, not {what}", where=shown) from None
    except OSError as exc:
        raise InputError(f"cannot be read ({exc.strerror})", where=shown) from exc
    if len(raw) > MAX_INPUT:
        raise InputError(f"is too large for {what} (over 1 MB)", where=shown)
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise InputError(f"is not UTF-8 text (byte {exc.start + 1})", where=shown) from exc


def dumps_json(doc: Any) -> str:
    """``doc`` as JSON text (indented, UTF-8), or a one-line RenderError naming the value
    that JSON cannot hold (a number too large: Infinity, or NaN)."""
    import json  # imported where JSON is written: most commands write none

    try:
        return json.dumps(doc, indent=2, ensure_ascii=False, allow_nan=False) + "\n"
    except ValueError:
        where = _non_finite(doc) or "a value"
        raise RenderError(f"{where} is not a finite number (too large to write as JSON)") from None


def _non_finite(doc: Any, path: str = "") -> str | None:
    """The path (``results.T_1.value``) of the first number in ``doc`` that is not finite."""
    if isinstance(doc, float) and not math.isfinite(doc):
        return path or "a value"
    items = doc.items() if isinstance(doc, dict) else enumerate(doc) if isinstance(doc, (list, tuple)) else ()
    for k, v in items:
        found = _non_finite(v, f"{path}.{k}" if path else str(k))
        if found:
            return found
    return None


@contextlib.contextmanager
def folder_atomic(path: str | Path, *, owned: tuple[str, ...] = ()) -> Iterator[Path]:
    """Write a folder of outputs as a whole: yields an empty temporary folder beside ``path``;
    when the block ends without error it takes ``path``'s place in one step (the old
    folder is swapped out, then removed). On any error, or if the process is killed,
    ``path`` is as it was.

    An existing ``path`` may hold only files derive writes there (``owned``: glob
    patterns): a folder with other files in it is refused, never replaced.
    """
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise InputError("exists and is not a folder", where=str(path), field="-o")
    if path.is_dir():
        _check_owned(path, owned)
    parent = path.parent if str(path.parent) else Path(".")
    try:
        parent.mkdir(parents=True, exist_ok=True)
        _sweep(parent, path.name)
        tmp = Path(tempfile.mkdtemp(prefix=f".{path.name}.{os.getpid()}.", suffix=".tmp", dir=parent))
    except OSError as exc:
        raise _cannot_write(path, exc) from exc
    try:
        yield tmp
        os.chmod(tmp, 0o755)
        _swap_in(tmp, path)
    except OSError as exc:
        raise _cannot_write(path, exc) from exc
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def _sweep(parent: Path, name: str) -> None:
    """Remove the temporary files and folders that runs killed while writing ``name`` left
    behind (``.NAME.PID.XXXX.tmp``, where process PID is gone)."""
    import glob

    for leftover in parent.glob(f".{glob.escape(name)}.*.*"):
        pid = leftover.name[len(name) + 2 :].split(".")[0]
        if leftover.suffix not in (".tmp", ".old") or not pid.isdigit() or _alive(int(pid)):
            continue
        if leftover.is_dir() and not leftover.is_symlink():
            shutil.rmtree(leftover, ignore_errors=True)
        else:
            with contextlib.suppress(OSError):
                leftover.unlink()


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except OSError:
        return True
    return True


def _check_owned(path: Path, owned: tuple[str, ...]) -> None:
    try:
        names = sorted(p.name for p in path.iterdir())
    except OSError as exc:
        raise RenderError(f"{path}: cannot read the output folder ({exc.strerror or exc})") from exc
    others = [n for n in names if not any(Path(n).match(pattern) for pattern in owned)]
    if others:
        shown = ", ".join(others[:3]) + (", …" if len(others) > 3 else "")
        raise InputError(
            f"the folder holds files derive did not write ({shown}); give a new or empty folder",
            where=str(path),
            field="-o",
        )


def _swap_in(new: Path, path: Path) -> None:
    """Put folder ``new`` at ``path``: a rename, or where ``path`` exists an exchange of the two
    (renameat2 RENAME_EXCHANGE: one step), after which the old folder is removed."""
    if not path.exists():
        os.rename(new, path)
        return
    if not _exchange(new, path):  # no atomic exchange here: two renames, the old kept until the end
        old = Path(tempfile.mkdtemp(prefix=f".{path.name}.{os.getpid()}.", suffix=".old", dir=path.parent))
        os.rmdir(old)
        os.rename(path, old)
        os.rename(new, path)
        new = old
    shutil.rmtree(new, ignore_errors=True)


def _exchange(a: Path, b: Path) -> bool:
    """Swap two paths in one step (Linux renameat2 RENAME_EXCHANGE); False where it cannot be done."""
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        renameat2 = libc.renameat2
    except (OSError, AttributeError):
        return False
    at_fdcwd, rename_exchange = -100, 2
    done = renameat2(at_fdcwd, os.fsencode(a), at_fdcwd, os.fsencode(b), rename_exchange)
    return done == 0
