"""Where a value sits in a user's file, for one-line messages: ``file:line: field: what``.

Every reader of user files (problems, chains, answers) builds its errors here, so a
message always names the file, the line, the field and what was expected. The TOML
is read here too: a byte-order mark is dropped, and a number too long to convert or
arrays nested too deeply end in a one-line error, not a Python exception.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Mapping
from typing import Any

from derive.errors import InputError

MAX_TEXT = 5000
#: Deepest nesting of arrays and tables a file may have (tomllib recurses, and so would we).
MAX_NESTING = 32
_ARRAY_HEADER = re.compile(r"^\[\[\s*(.+?)\s*\]\]")
_TABLE_HEADER = re.compile(r"^\[\s*([^\[\]]+?)\s*\]")
_KEY = re.compile(
    r"""^((?:[A-Za-z0-9_-]+|"(?:[^"\\]|\\.)*"|'[^']*')(?:\s*\.\s*(?:[A-Za-z0-9_-]+|"(?:[^"\\]|\\.)*"|'[^']*'))*)\s*=\s*(.*)$"""
)
#: What the dotted-key pre-check sees: strings and comments (skipped whole), the characters
#: that end a key (``=``, ``,``, brackets, braces, a newline), and dots.
_KEY_SCAN = re.compile(
    r'''"""(?:[^\\]|\\[\s\S])*?"""|\'\'\'[\s\S]*?\'\'\'|"(?:[^"\\\n]|\\.)*"|'[^'\n]*'|#[^\n]*|[=,{}\[\]\n]|\.'''
)
_INLINE_KEY = re.compile(r"""(?:^|[{,])\s*([A-Za-z0-9_-]+|"(?:[^"\\]|\\.)*"|'[^']*')\s*=""")

Path_ = tuple[str | int, ...]


class Source:
    """A file's path and text: finds the line of a field, and builds one-line errors.

    ``scope`` (a path such as ``("stage", 1)``) makes a view of one part of the file:
    a chain's impact stage read as a problem of its own names its own lines.
    """

    def __init__(self, path: str, text: str, *, scope: Path_ = (), label: str = "") -> None:
        self.path = path
        self.text = text
        self.scope = scope
        self.label = label
        self._index: dict[Path_, int] | None = None

    def within(self, *scope: str | int, label: str) -> Source:
        """A view of a part of the file (``("stage", 1)``), its fields labelled ``[label] key``."""
        view = Source(self.path, self.text, scope=self.scope + scope, label=label)
        view._index = self._index
        return view

    def locate(self, *path: str | int) -> int | None:
        """The line of ``path`` (``("given", "m_A")``, ``("stage", 1, "result")``), or of the
        nearest table that holds it; None when not even that is found."""
        if self._index is None:
            self._index = index_lines(self.text)
        full = self.scope + path
        for end in range(len(full), 0, -1):
            line = self._index.get(full[:end])
            if line is not None:
                return line
        return None

    def line_of(self, section: str | None, key: str | None) -> int | None:
        """The line of ``[section] key`` (or of ``[section]``), as :meth:`locate`."""
        path: list[str | int] = [section] if section else []
        if key is not None:
            path += key.split(".")
        return self.locate(*path) if path else None

    def field(self, section: str | None, key: str | None, value: Any = None) -> str | None:
        """How a field is named in a message: ``[given] e = 1.3``, ``title``, ``[stage 2] result``."""
        shown = f" = {shown_value(value)}" if value is not None and key is not None else ""
        if self.label:
            inner = ".".join(printable(p) for p in (section, key) if p)
            return f"[{self.label}]" + (f" {inner}" if inner else "") + shown
        if key is not None:
            return (f"[{section}] " if section else "") + printable(key) + shown
        if section is not None:
            return f"[{section}]"
        return None

    def where(self, line: int | None) -> str:
        """``file:line``, or the file alone when the line is not known."""
        return f"{self.path}:{line}" if line else self.path

    def error(
        self,
        what: str,
        section: str | None = None,
        key: str | None = None,
        value: Any = None,
        cls: type[InputError] = InputError,
    ) -> InputError:
        """A one-line error: ``file:line: [section] key = value: what``."""
        return cls(what, where=self.where(self.line_of(section, key)), field=self.field(section, key, value))


def index_lines(text: str) -> dict[Path_, int]:
    """The line of every table header and key in TOML ``text``, by path.

    A good guess, not a parser: it reads headers (``[a.b]``, ``[[stage]]``, counting the
    elements of an array of tables), ``key = value`` lines (dotted keys too) and the
    keys of a one-line inline table; multi-line strings are skipped.
    """
    out: dict[Path_, int] = {}
    header: Path_ = ()
    arrays: dict[Path_, int] = {}
    open_quote: str | None = None
    for n, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if open_quote is not None:
            if line.count(open_quote) % 2 == 1:
                open_quote = None
            continue
        if not line or line.startswith("#"):
            continue
        m = _ARRAY_HEADER.match(line)
        if m:
            parts = _split_key(m.group(1))
            name = (*_with_indices(parts[:-1], arrays), parts[-1])
            arrays[name] = arrays.get(name, -1) + 1
            header = (*name, arrays[name])
            out.setdefault(header, n)
            continue
        m = _TABLE_HEADER.match(line)
        if m:
            header = _with_indices(_split_key(m.group(1)), arrays)
            out.setdefault(header, n)
            continue
        m = _KEY.match(line)
        if not m:
            continue
        path = header + _split_key(m.group(1))
        out.setdefault(path, n)
        rest = m.group(2)
        if rest.startswith("{"):
            for km in _INLINE_KEY.finditer(rest):
                out.setdefault((*path, *_split_key(km.group(1))), n)
        for quote in ('"""', "'''"):
            if rest.count(quote) % 2 == 1:
                open_quote = quote
    return out


def _with_indices(name: Path_, arrays: Mapping[Path_, int]) -> Path_:
    """``("stage", "given")`` under ``[[stage]]`` is ``("stage", 3, "given")``: the latest element."""
    out: list[str | int] = []
    for part in name:
        out.append(part)
        if tuple(out) in arrays:
            out.append(arrays[tuple(out)])
    return tuple(out)


def _split_key(text: str) -> tuple[str, ...]:
    """A (dotted, quoted) TOML key as its parts; the text itself when TOML cannot read it."""
    try:
        doc: Any = tomllib.loads(f"{text} = 0")
    except tomllib.TOMLDecodeError:
        return (text,)
    parts = []
    while isinstance(doc, dict) and len(doc) == 1:
        key = next(iter(doc))
        parts.append(key)
        doc = doc[key]
    return tuple(parts)


def printable(text: str) -> str:
    """A key from the file as it can appear in a one-line message: control and
    line-breaking characters escaped (a newline, ESC, U+2028 stay visible and harmless)."""
    return "".join(ch if ch.isprintable() else ch.encode("unicode_escape").decode("ascii") for ch in text)


def shown_value(value: Any) -> str:
    """A value from the file as a message shows it: quoted text, at most 60 characters, one line."""
    text = repr(value) if isinstance(value, str) else _short_str(value)
    if len(text) > 60:
        text = text[:57] + "…"
    return printable(text.replace("\n", " "))


def _short_str(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) >= 10**60:
        return f"a whole number of {len(str(abs(value)))} digits"
    if isinstance(value, (list, dict)):
        return str(value)[:200] if _depth(value) < MAX_NESTING else "…"
    return str(value)


def _depth(value: Any) -> int:
    """How deeply lists and tables nest in ``value`` (iteratively: a deep value cannot overflow)."""
    deepest, todo = 0, [(value, 0)]
    while todo:
        item, d = todo.pop()
        deepest = max(deepest, d)
        if d > MAX_NESTING:
            break
        if isinstance(item, dict):
            todo += [(v, d + 1) for v in item.values()]
        elif isinstance(item, list):
            todo += [(v, d + 1) for v in item]
    return deepest


def parse_toml(text: str, path: str) -> dict[str, Any]:
    """TOML text as a table, or a one-line InputError at the line TOML names.

    A UTF-8 byte-order mark (as Windows editors write) is not part of the text.
    """
    text = text.removeprefix("\ufeff")
    _check_dotted_keys(text, path)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\(at line (\d+), column \d+\)", msg)
        where = f"{path}:{m.group(1)}" if m else path
        what = re.sub(r"\s*\(at line \d+, column \d+\)", "", msg) or "invalid TOML"
        raise InputError(f"not valid TOML: {what[0].lower() + what[1:]}", where=where) from None
    except ValueError as exc:  # a whole number of over 4,300 digits
        line = _first_line(text, re.compile(r"\d{4300}"))
        raise InputError(
            "not valid TOML: a number has too many digits to read", where=f"{path}:{line}" if line else path
        ) from exc
    except RecursionError:
        raise _too_deep(text, path) from None
    if _depth(data) > MAX_NESTING:
        raise _too_deep(text, path)
    return data


def _check_dotted_keys(text: str, path: str) -> None:
    """Refuse a dotted key or table header of more parts than :data:`MAX_NESTING` before
    tomllib reads it: tomllib builds such a key in time and memory that grow with the square of
    its parts (20,000 parts, 40 KB of text, took 1.6 GB). Linear: strings and comments are
    skipped whole, and the dots between two of ``= , { } [ ]`` or a newline are counted."""
    dots = 0
    for m in _KEY_SCAN.finditer(text):
        if m.group() != ".":
            dots = 0 if len(m.group()) == 1 and m.group() in "=,{}[]\n" else dots
            continue
        dots += 1
        if dots >= MAX_NESTING:
            line = text.count("\n", 0, m.start()) + 1
            raise InputError(
                f"a dotted key or table header has too many parts: tables are nested too deeply "
                f"(at most {MAX_NESTING} levels)",
                where=f"{path}:{line}",
            )


def _too_deep(text: str, path: str) -> InputError:
    depth, line = 0, None
    for n, raw in enumerate(text.splitlines(), 1):
        for ch in raw:
            depth += (ch in "[{") - (ch in "]}")
            if depth > MAX_NESTING:
                line = n
                break
        if line:
            break
    where = f"{path}:{line}" if line else path
    return InputError(f"arrays or tables are nested too deeply (at most {MAX_NESTING} levels)", where=where)


def _first_line(text: str, pattern: re.Pattern[str]) -> int | None:
    for n, raw in enumerate(text.splitlines(), 1):
        if pattern.search(raw):
            return n
    return None


def type_name(value: Any) -> str:
    """Words for the TOML type of ``value``: "true/false", "a number", "text", "a list"…"""
    import datetime as dt

    if isinstance(value, bool):
        return "true/false"
    if isinstance(value, (int, float)):
        return "a number"
    if isinstance(value, str):
        return "text"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, (dt.datetime, dt.date, dt.time)):
        return "a date or time"
    return type(value).__name__
