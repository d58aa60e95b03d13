"""What a command prints, made safe for a terminal, and its time budget."""

from __future__ import annotations

import contextlib
import re
import signal
import sys
import threading
import time
from collections.abc import Iterator
from typing import Any, TextIO

#: Characters never written raw to a terminal: C0 and C1 controls but tab and newline,
#: DEL, and the invisible ones that reorder or break lines (bidi controls, U+2028/9).
_HIDDEN = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def one_line(text: str) -> str:
    """A message as one line of plain text: a key or value from a file may hold a newline or a
    terminal escape (ESC [31m); those are shown escaped, never sent to the terminal."""
    import unicodedata

    out = []
    for ch in text:
        if ch in "\r\n\t":
            out.append(" ")
        elif unicodedata.category(ch) in ("Cc", "Cf", "Zl", "Zp", "Cs"):
            out.append(f"\\x{ord(ch):02x}" if ord(ch) < 256 else f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    return "".join(out)


def visible(text: str) -> str:
    """``text`` with every control character shown as an escape (``\\u001b``), not sent raw.

    In JSON the escape is the character itself, written the JSON way: the document is unchanged.
    """
    return _HIDDEN.sub(lambda m: f"\\u{ord(m.group()):04x}", text)


class _Visible:
    """A text stream that passes everything written to it through :func:`visible`."""

    def __init__(self, stream: TextIO) -> None:
        self.stream = stream

    def write(self, text: str) -> int:
        self.stream.write(visible(text))
        return len(text)

    def __getattr__(self, name: str) -> Any:
        return getattr(self.stream, name)


def _encodable(stream: TextIO, page: bool) -> dict[str, str] | None:
    """Make ``stream`` able to write any page, whatever its encoding (cp1252 for a Windows
    console redirected to a file, ASCII under an old locale): a page sent to a file or a pipe
    is written in UTF-8, as derive writes its files; a terminal keeps its encoding and shows
    what it cannot as ``\\u221e``. Returns the settings to put back, or None if unchanged."""
    encoding = (getattr(stream, "encoding", None) or "").lower().replace("_", "-")
    if encoding in ("utf-8", "utf8") or not hasattr(stream, "reconfigure"):
        return None
    old = {"encoding": stream.encoding, "errors": stream.errors}
    try:
        tty = stream.isatty()
    except (OSError, ValueError):
        tty = False
    try:
        if page and not tty:
            stream.reconfigure(encoding="utf-8", errors="strict")
        else:
            stream.reconfigure(errors="backslashreplace")
    except (OSError, ValueError, LookupError):
        return None
    return old


@contextlib.contextmanager
def terminal_safe() -> Iterator[None]:
    """Standard output and error, for the time of a command, show control characters escaped
    and can write every character (:func:`_encodable`)."""
    out, err = sys.stdout, sys.stderr
    settings = [(stream, _encodable(stream, page)) for stream, page in ((out, True), (err, False))]
    sys.stdout, sys.stderr = _Visible(out), _Visible(err)  # type: ignore[assignment]
    try:
        yield
    finally:
        sys.stdout, sys.stderr = out, err
        for stream, old in settings:
            if old is not None:
                with contextlib.suppress(OSError, ValueError, LookupError):
                    stream.flush()
                    stream.reconfigure(**old)  # type: ignore[attr-defined]


class OutOfTime(BaseException):
    """A command ran past its time budget. Not an Exception: no ``except Exception`` inside SymPy
    may swallow it."""


@contextlib.contextmanager
def time_budget(seconds: float) -> Iterator[None]:
    """Raise :class:`OutOfTime` in the main thread after ``seconds`` (0: no limit).

    An alarm already set (by a caller) is put back afterwards, less the time spent.
    """
    usable = seconds > 0 and hasattr(signal, "setitimer") and threading.current_thread() is threading.main_thread()
    if not usable:
        yield
        return

    def alarm(signum: int, frame: object) -> None:
        raise OutOfTime(seconds)

    start = time.monotonic()
    old_handler = signal.signal(signal.SIGALRM, alarm)
    old_delay, _ = signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old_handler)
        if old_delay > 0:
            signal.setitimer(signal.ITIMER_REAL, max(0.001, old_delay - (time.monotonic() - start)))
