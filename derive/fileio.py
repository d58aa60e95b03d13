"""Writing outputs so that nothing is lost: a temporary file, then an atomic rename."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path

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
            raise RenderError(f"{path}: cannot write the output ({exc.strerror or exc})") from exc
        return
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=folder)
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
        raise RenderError(f"{path}: cannot write the output ({exc.strerror or exc})") from exc
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


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
