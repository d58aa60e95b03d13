"""The vocabulary of the schema: a :class:`Field` (a name, a value type, a meaning and
limits) and a :class:`Table` of fields; the value types a field may have."""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

#: The value types a field may have (each checked by :mod:`derive.problem.validate`).
TYPES = {
    "text": "text",
    "line": "a short line of text",
    "boolean": "true or false",
    "integer": "a whole number",
    "number": "a number",
    "choice": "one of the listed words",
    "value": 'a number, or text: a number with a unit ("5 m/s"), a unit alone (a symbol), an expression, or "?"',
    "expression": "a name or an expression of known names, or a number",
    "name": "a name: a letter, then letters, digits and _",
    "names": "a list of names (or one name)",
    "unit": 'a unit, such as "km/h"',
    "table": "a table",
    "list": "a list",
    "tolerance": 'a relative tolerance: a number such as 0.01, or text such as "1%"',
}
NAME_PATTERN = r"^[A-Za-z][A-Za-z0-9_]{0,31}$"
BAD_NAME = "is not a usable name: start with a letter; letters, digits and _ only"  # what an error says of a name not like that
MAX_TEXT = 5000
MAX_LINE = 40
MAGNITUDE = (1e-30, 1e30)  # a number's magnitude, when not 0


@dataclass(frozen=True)
class Field:
    """One field of a table: its name, value type, meaning and limits.

    ``expected`` overrides the words of an error ("expected <expected>"); ``items`` is
    the type of a list's items; ``table`` the fields of a nested table; ``default``
    what an absent field means (for the docs).
    """

    name: str
    type: str
    meaning: str
    required: bool = False
    default: str = ""
    choices: tuple[str, ...] = ()
    minimum: float | None = None
    maximum: float | None = None
    max_length: int | None = None
    min_items: int = 0
    max_items: int | None = None
    items: Field | None = None
    table: Table | None = None
    expected: str = ""
    also: str = ""  # another accepted form: "name" (find = "v_A2"), "one" (a single item without its list)

    def __post_init__(self) -> None:
        if self.type not in TYPES:
            raise ValueError(f"field {self.name}: unknown type {self.type!r}")
        if (self.type == "table") != (self.table is not None):
            raise ValueError(f"field {self.name}: a table field needs its table, and only it")
        if self.type == "choice" and not self.choices:
            raise ValueError(f"field {self.name}: a choice needs its choices")


@dataclass(frozen=True)
class Table:
    """A table's fields; ``keys`` describes the entries of an open table (``[given]``: any
    name), ``key_pattern`` what its keys look like, ``max_keys`` how many it may have."""

    name: str
    meaning: str
    fields: tuple[Field, ...] = ()
    keys: Field | None = None
    key_pattern: str | None = None
    max_keys: int | None = None
    forms: tuple[tuple[str, ...], ...] = field(default=())  # exactly one of these sets of fields (vary)
    by: str = ""  # the field whose value picks the table in ``cases`` (a stage's type)
    cases: Mapping[str, Table] = field(default_factory=dict)

    def get(self, name: str) -> Field | None:
        """The field called ``name``, or None."""
        for f in self.fields:
            if f.name == name:
                return f
        return None

    @property
    def names(self) -> tuple[str, ...]:
        """The names of its fields, in order."""
        return tuple(f.name for f in self.fields)
