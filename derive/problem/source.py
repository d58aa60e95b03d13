"""Where a value sits in a user's file, for one-line messages: ``file:line: field: what``.

Every reader of user files (problems, chains, answers) builds its errors here, so a
message always names the file, the line, the field and what was expected.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Mapping
from typing import Any

from derive.errors import InputError

MAX_TEXT = 5000


class Source:
    """Where we are in a file, to put in messages."""

    def __init__(self, path: str, text: str) -> None:
        self.path = path
        self.lines = text.splitlines()

    def line_of(self, section: str | None, key: str | None) -> int | None:
        current: str | None = None
        for i, raw in enumerate(self.lines, 1):
            line = raw.strip()
            m = re.match(r"^\[\s*([^\]]+?)\s*\]", line)
            if m:
                current = m.group(1)
                continue
            if current == section and re.match(rf"^[\"']?{re.escape(key or '')}[\"']?\s*=", line):
                return i
        if key is None and section is not None:
            for i, raw in enumerate(self.lines, 1):
                if re.match(rf"^\s*\[\s*{re.escape(section)}\s*\]", raw):
                    return i
        return None

    def error(
        self,
        what: str,
        section: str | None = None,
        key: str | None = None,
        value: Any = None,
        cls: type[InputError] = InputError,
    ) -> InputError:
        line = self.line_of(section, key)
        where = f"{self.path}:{line}" if line else self.path
        fld = None
        if key is not None:
            shown = shown_value(value) if value is not None else None
            fld = (f"[{section}] " if section else "") + printable(key) + (f" = {shown}" if shown is not None else "")
        elif section is not None:
            fld = f"[{section}]"
        return cls(what, where=where, field=fld)


def printable(text: str) -> str:
    """A key from the file as it can appear in a one-line message: control and
    line-breaking characters escaped (a newline, ESC, U+2028 stay visible and harmless)."""
    return "".join(ch if ch.isprintable() else ch.encode("unicode_escape").decode("ascii") for ch in text)


def shown_value(value: Any) -> str:
    text = repr(value) if isinstance(value, str) else str(value)
    if len(text) > 60:
        text = text[:57] + "…"
    return text.replace("\n", " ")


def parse_toml(text: str, path: str) -> dict[str, Any]:
    """TOML text as a table, or a one-line InputError at the line TOML names."""
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        msg = str(exc)
        m = re.search(r"\(at line (\d+), column \d+\)", msg)
        where = f"{path}:{m.group(1)}" if m else path
        what = re.sub(r"\s*\(at line \d+, column \d+\)", "", msg) or "invalid TOML"
        raise InputError(f"not valid TOML: {what[0].lower() + what[1:]}", where=where) from None


def text_field(data: Mapping[str, Any], key: str, ctx: Source, required: bool = False) -> str | None:
    value = data.get(key)
    if value is None:
        if required:
            raise ctx.error("is missing: give the problem a title (a line of text)", key=key)
        return None
    if not isinstance(value, str):
        raise ctx.error(f"expected text, not {type_name(value)}", key=key, value=value)
    if len(value) > MAX_TEXT:
        raise ctx.error(f"is too long ({len(value)} characters, at most {MAX_TEXT})", key=key)
    if "\x00" in value:
        raise ctx.error("contains a NUL character", key=key)
    return value


def type_name(value: Any) -> str:
    return {bool: "true/false", int: "a number", float: "a number", str: "text", list: "a list", dict: "a table"}.get(
        type(value), type(value).__name__
    )
