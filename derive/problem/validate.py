"""Check a file's tables against the declared schema (:mod:`derive.problem.schema`).

Every field is checked for its type, its range and its length before anything is built
from it, and every error is one line: ``file:line: field = value: what was expected,
what was found``; an unknown key gets "did you mean" when a known one is close.
Checking only reads: the builders take the same tables afterwards, knowing their types.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from typing import Any

from derive.errors import InputError
from derive.problem.schema import MAGNITUDE, TYPES, Field, Table
from derive.problem.schema.base import BAD_NAME
from derive.problem.source import Source, type_name

Path_ = tuple[str, ...]


def check(data: Mapping[str, Any], table: Table, src: Source, path: Path_ = ()) -> None:
    """Raise a one-line :class:`InputError` at the first field of ``data`` that ``table`` does not admit."""
    if table.fields or not table.keys:
        _unknown_keys(data, table, src, path)
    if table.forms:
        _forms(data, table, src, path)
    for f in table.fields:
        if f.name in data:
            check_value(data[f.name], f, src, (*path, f.name))
        elif f.required:
            raise missing(f, src, path)
    if table.keys is not None:
        _open_entries(data, table, src, path)
    if table.by and isinstance(data.get(table.by), str) and data[table.by] in table.cases:
        check(data, table.cases[data[table.by]], src, path)


def missing(f: Field, src: Source, path: Path_ = ()) -> InputError:
    """The error for a required field left out."""
    what = f"is missing: expected {f.expected or TYPES[f.type]} ({f.meaning.replace('`', '')})"
    if f.type == "table":
        return src.error(what, section=_dotted((*path, f.name)))
    return err(src, (*path, f.name), what)


def err(src: Source, path: Path_, what: str, value: Any = None, cls: type[InputError] = InputError) -> InputError:
    """An error at ``path`` (``("given", "m_A")``): the first part is the section, the rest the key."""
    if len(path) == 1:
        return src.error(what, key=path[0], value=value, cls=cls)
    return src.error(what, section=path[0] if path else None, key=_dotted(path[1:]) or None, value=value, cls=cls)


def _dotted(parts: Path_) -> str:
    return ".".join(parts)


def did_you_mean(word: str, known: tuple[str, ...] | list[str]) -> str:
    """``; did you mean "title"?`` when a known word is close to ``word``, else nothing."""
    import difflib  # an error's hint only

    close = difflib.get_close_matches(word, known, n=1, cutoff=0.6)
    if not close and word.strip() != word:
        close = [w for w in known if w == word.strip()]
    return f'; did you mean "{close[0]}"?' if close else ""


def _unknown_keys(data: Mapping[str, Any], table: Table, src: Source, path: Path_) -> None:
    known = table.names
    if table.by and isinstance(data.get(table.by), str) and data[table.by] in table.cases:
        known = table.cases[data[table.by]].names
    for key in data:
        if key not in known:
            hint = did_you_mean(key, known)
            raise err(src, (*path, key), f"unknown field{hint} (expected one of: {', '.join(known)})")


def _forms(data: Mapping[str, Any], table: Table, src: Source, path: Path_) -> None:
    if tuple(sorted(data)) in {tuple(sorted(f)) for f in table.forms}:
        return
    shown = " or ".join("{ " + ", ".join(f"{k} = ..." for k in form) + " }" for form in table.forms)
    raise err(src, path, f"expected {shown}, found {{ {', '.join(data) or 'nothing'} }}")


def _open_entries(data: Mapping[str, Any], table: Table, src: Source, path: Path_) -> None:
    assert table.keys is not None
    if table.max_keys is not None and len(data) > table.max_keys:
        raise src.error(
            f"has too many entries ({len(data)}, at most {table.max_keys})", section=_dotted(path) or table.name
        )
    pattern = re.compile(table.key_pattern) if table.key_pattern else None
    for key, value in data.items():
        if pattern is not None and not pattern.match(key):
            raise err(src, (*path, key), BAD_NAME)
        check_value(value, table.keys, src, (*path, key))


def check_value(value: Any, f: Field, src: Source, path: Path_) -> None:
    """Check one value against its field: type first, then range and length."""
    CHECKS[f.type](value, f, src, path)


def _wrong_type(value: Any, f: Field, src: Source, path: Path_, expected: str | None = None) -> InputError:
    words = expected or f.expected or TYPES[f.type]
    return err(src, path, f"expected {words}, found {type_name(value)}", value)


def _text(value: Any, f: Field, src: Source, path: Path_) -> None:
    if not isinstance(value, str):
        raise _wrong_type(value, f, src, path)
    _text_limits(value, f, src, path)


def _text_limits(value: str, f: Field, src: Source, path: Path_) -> None:
    if f.max_length is not None and len(value) > f.max_length:
        raise err(src, path, f"is too long ({len(value)} characters, at most {f.max_length})")
    if "\x00" in value:
        raise err(src, path, "contains a NUL character")


def _line(value: Any, f: Field, src: Source, path: Path_) -> None:
    if not isinstance(value, str):
        raise _wrong_type(value, f, src, path)
    if not value.strip() or (f.max_length and len(value) > f.max_length):
        raise err(src, path, f"expected {f.expected or TYPES['line']} (at most {f.max_length} characters)", value)
    _text_limits(value, f, src, path)


def _boolean(value: Any, f: Field, src: Source, path: Path_) -> None:
    if not isinstance(value, bool):
        raise _wrong_type(value, f, src, path, "true or false")


def _integer(value: Any, f: Field, src: Source, path: Path_) -> None:
    if isinstance(value, bool) or not isinstance(value, int):
        raise _wrong_type(value, f, src, path)
    if (f.minimum is not None and value < f.minimum) or (f.maximum is not None and value > f.maximum):
        raise err(src, path, f"expected {f.expected or f'a whole number from {f.minimum:g} to {f.maximum:g}'}", value)


def _number(value: Any, f: Field, src: Source, path: Path_) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise _wrong_type(value, f, src, path)
    _finite(value, src, path)


def _finite(value: int | float, src: Source, path: Path_) -> None:
    """A number in a file: finite, and 0 or of a magnitude between 1e-30 and 1e30."""
    if isinstance(value, float) and not math.isfinite(value):
        raise err(src, path, "expected a finite number", value)
    lo, hi = MAGNITUDE
    if abs(value) > hi or (value != 0 and abs(value) < lo):
        raise err(src, path, f"is out of range (expected a magnitude between {lo:g} and {hi:g})", value)


def _choice(value: Any, f: Field, src: Source, path: Path_) -> None:
    if isinstance(value, str) and value in f.choices:
        return
    hint = did_you_mean(value, list(f.choices)) if isinstance(value, str) else ""
    words = f.expected or f"one of {', '.join(f.choices)}"
    found = "" if isinstance(value, str) else f", found {type_name(value)}"
    raise err(src, path, f"expected {words}{found}{hint}", value)


def _value(value: Any, f: Field, src: Source, path: Path_) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise _wrong_type(value, f, src, path)
    if isinstance(value, str):
        _text_limits(value, f, src, path)
    else:
        _finite(value, src, path)


def _expression(value: Any, f: Field, src: Source, path: Path_) -> None:
    _value(value, f, src, path)
    if isinstance(value, str):
        from derive.problem.expr import ParseError, scan

        try:
            scan(value)
        except ParseError as exc:
            raise err(src, path, str(exc), value) from None


def _name(value: Any, f: Field, src: Source, path: Path_) -> None:
    from derive.problem.schema import NAME_PATTERN

    if not isinstance(value, str):
        raise _wrong_type(value, f, src, path)
    if not re.match(NAME_PATTERN, value):
        raise err(src, path, f"expected {TYPES['name']} (at most 32)", value)


def _names(value: Any, f: Field, src: Source, path: Path_) -> None:
    if isinstance(value, str) and f.also == "name":
        return
    if not isinstance(value, list) or not all(isinstance(x, str) for x in value):
        raise err(src, path, f"expected {f.expected or TYPES['names']}", value)
    if f.max_items is not None and len(value) > f.max_items:
        raise err(src, path, f"has too many names ({len(value)}, at most {f.max_items})")


def _table(value: Any, f: Field, src: Source, path: Path_) -> None:
    if not isinstance(value, dict):
        raise _wrong_type(value, f, src, path, f.expected or "a table")
    assert f.table is not None
    check(value, f.table, src, path)


def _list(value: Any, f: Field, src: Source, path: Path_) -> None:
    if f.also == "one" and f.items is not None and not isinstance(value, list):  # one item, without its list
        value = [value]
    if not isinstance(value, list):
        raise _wrong_type(value, f, src, path)
    if len(value) < f.min_items or (f.max_items is not None and len(value) > f.max_items):
        most = f"at most {f.max_items}" if f.min_items <= 1 else f"exactly {f.min_items}"
        if f.min_items == 1 and not value:
            raise err(src, path, f"is empty: expected {f.expected or TYPES['list']}", value)
        raise err(src, path, f"has {len(value)} items ({most})", value)
    item = f.items
    if item is None:
        return
    for i, x in enumerate(value):
        if item.type == "table":
            if not isinstance(x, dict):
                raise _wrong_type(x, f, src, path)
            assert item.table is not None
            check(x, item.table, src.within(*path, i, label=f"{_dotted(path)} {i + 1}"))
        else:
            check_value(x, item, src, path)


_TOLERANCE = re.compile(r"^\s*(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,2})?\s*%?\s*$")


def _tolerance(value: Any, f: Field, src: Source, path: Path_) -> None:
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise _wrong_type(value, f, src, path)
    words = 'expected a relative tolerance such as 0.01 or "1%", between 0 and 1 (0 % and 100 %)'
    if isinstance(value, str):
        _text_limits(value, f, src, path)
        if not _TOLERANCE.match(value):
            raise err(src, path, words, value)
    elif not (math.isfinite(value) and 0 < value < 1):
        raise err(src, path, words, value)


CHECKS = {
    "text": _text,
    "line": _line,
    "boolean": _boolean,
    "integer": _integer,
    "number": _number,
    "choice": _choice,
    "value": _value,
    "expression": _expression,
    "name": _name,
    "names": _names,
    "unit": _text,
    "table": _table,
    "list": _list,
    "tolerance": _tolerance,
}
