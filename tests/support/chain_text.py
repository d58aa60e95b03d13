"""A chain file with a variant's numbers written into its [given] table, as an instructor
would type them: for the tests that compare a chain variant with ``derive solve`` of that file.

Written here, not by derive: a number goes in the unit the file typed (a value in the key's
unit converted by the table below), with at least the places the file typed (0.020 kg at
0.015 is "0.015 kg"; 4.0 kg at 2 is "2.0 kg"), a bare number where the file typed one.
"""

from __future__ import annotations

import re
from decimal import Decimal

#: How many of the key's unit one of the typed unit is (the units the bundled chains type
#: in a unit other than the one their key gives).
UNITS_PER_TYPED = {("kN/m", "N/m"): Decimal(1000), ("N*s", "N·s"): Decimal(1)}


def _plain(d: Decimal) -> str:
    text = format(d.normalize(), "f")
    return "0" if text in ("-0", "0") else text


def written(raw: str, value: Decimal, unit: str) -> str:
    """The TOML value of a [given] line ``raw`` (as the file has it) at ``value`` in the key's ``unit``."""
    raw = raw.split("#")[0].strip()
    if not raw.startswith('"'):  # a bare number: e = 0.8
        return _plain(value)
    number, _, typed = raw.strip('"').partition(" ")
    typed = typed.strip()
    if typed and typed != unit and (typed, unit) not in UNITS_PER_TYPED:
        raise AssertionError(f"no conversion from {unit} to {typed}")
    value = value / UNITS_PER_TYPED.get((typed, unit), Decimal(1))
    text = _plain(value)
    places = len(number.partition(".")[2])
    have = len(text.partition(".")[2])
    if have < places:
        text += ("" if "." in text else ".") + "0" * (places - have)
    return f'"{text} {typed}"' if typed else f'"{text}"'


def with_numbers(text: str, givens: dict[str, tuple[Decimal, str]]) -> str:
    """The chain file ``text`` with each given's line of its [given] table holding the number
    (``givens``: name -> (value, unit as the key gives it)), and its [vary] table and
    conditions left out."""
    head, _, rest = text.partition("\n[given]\n")
    body, sep, tail = rest.partition("\n[[stage]]")
    for name, (value, unit) in givens.items():
        m = re.search(rf"^{name} = (.*)$", body, flags=re.M)
        assert m is not None, name
        body = body[: m.start()] + f"{name} = {written(m.group(1), value, unit)}" + body[m.end() :]
    out = head + "\n[given]\n" + body + sep + tail
    out = re.sub(r"^conditions = \[.*\]\n", "", out, flags=re.M)
    return re.sub(r"\n(?:#[^\n]*\n)*\[vary\]\n(?:(?!\[).*\n?)*", "\n", out)
