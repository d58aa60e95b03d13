"""Units inside expressions: which names are units, and the unit after a number
(``1/3 kg``, ``m^2/s^2``) read from the expression parser's tokens."""

from __future__ import annotations

from derive.problem import units


def is_unit_name(name: str) -> bool:
    """True when ``name`` is one of derive's units (``kg``, ``m``, ``deg``, ``mph``, ``°``)."""
    return name in units.BASE_UNITS or name in units.ALIASES


def unit_text(toks: list[tuple[str, str]], i: int) -> tuple[str, int]:
    """The unit at token ``i``: unit names joined by * or /, each with an optional whole
    power (``m^2/s^2``), as text for :func:`units.parse_unit`, and the index after it.
    Raises ValueError when the name at ``i`` is no unit, or a power is not whole."""

    def peek(j: int) -> str | None:
        return toks[j][1] if j < len(toks) else None

    parts: list[str] = []
    while True:
        val = toks[i][1]
        if not is_unit_name(val):
            if not parts:
                raise ValueError(
                    f"unexpected {val!r} after the expression: a name after a number is a unit "
                    "(kg, m/s, deg, ...); multiply a given with *"
                )
            break
        i += 1
        parts.append(val)
        if peek(i) in ("^", "**"):
            i += 1
            sign = "-" if peek(i) == "-" else ""
            i += bool(sign)
            kind, power = toks[i] if i < len(toks) else ("", "")
            if kind != "num" or not power.isdigit():
                raise ValueError(f"a unit's power is a whole number, not {power!r}")
            i += 1
            parts.append(f"^{sign}{power}")
        if peek(i) in ("*", "/") and i + 1 < len(toks) and toks[i + 1][0] == "name" and is_unit_name(toks[i + 1][1]):
            parts.append(toks[i][1])
            i += 1
            continue
        break
    return "".join(parts), i
