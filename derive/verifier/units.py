"""Units a worked solution shows (``\\mathrm{m/s}``, ``^\\circ``, ``\\%``): dimension and size.

The verifier keeps its own table, from the definitions (1 ft = 0.3048 m,
1 lbf = 0.45359237 kg x 9.80665 m/s^2), so that a wrong factor in derive
cannot hide behind the same factor here. A dimension is the exponent tuple
(mass, length, time, angle).
"""

from __future__ import annotations

import re
from fractions import Fraction

Dim = tuple[int, int, int, int]

NONE: Dim = (0, 0, 0, 0)
MASS: Dim = (1, 0, 0, 0)
LENGTH: Dim = (0, 1, 0, 0)
TIME: Dim = (0, 0, 1, 0)
ANGLE: Dim = (0, 0, 0, 1)
VELOCITY: Dim = (0, 1, -1, 0)
ACCELERATION: Dim = (0, 1, -2, 0)
FORCE: Dim = (1, 1, -2, 0)
ENERGY: Dim = (1, 2, -2, 0)
IMPULSE: Dim = (1, 1, -1, 0)
STIFFNESS: Dim = (1, 0, -2, 0)

WORDS = {
    NONE: "a pure number",
    MASS: "a mass",
    LENGTH: "a length",
    TIME: "a time",
    ANGLE: "an angle",
    VELOCITY: "a velocity",
    ACCELERATION: "an acceleration",
    FORCE: "a force",
    ENERGY: "an energy",
    IMPULSE: "an impulse",
    STIFFNESS: "a stiffness",
}

_FT = Fraction("0.3048")
_LBF = Fraction("0.45359237") * Fraction("9.80665")
#: Angles are measured in radians; a degree is pi/180 of one (the factor is applied apart).
BASE: dict[str, tuple[Fraction, Dim]] = {
    "kg": (Fraction(1), MASS),
    "g": (Fraction(1, 1000), MASS),
    "Mg": (Fraction(1000), MASS),
    "t": (Fraction(1000), MASS),
    "slug": (_LBF / _FT, MASS),
    "m": (Fraction(1), LENGTH),
    "mm": (Fraction(1, 1000), LENGTH),
    "cm": (Fraction(1, 100), LENGTH),
    "km": (Fraction(1000), LENGTH),
    "in": (_FT / 12, LENGTH),
    "ft": (_FT, LENGTH),
    "mi": (_FT * 5280, LENGTH),
    "s": (Fraction(1), TIME),
    "min": (Fraction(60), TIME),
    "h": (Fraction(3600), TIME),
    "N": (Fraction(1), FORCE),
    "kN": (Fraction(1000), FORCE),
    "lb": (_LBF, FORCE),
    "lbf": (_LBF, FORCE),
    "J": (Fraction(1), ENERGY),
    "kJ": (Fraction(1000), ENERGY),
    "rad": (Fraction(1), ANGLE),
    "lbm": (Fraction("0.45359237"), MASS),
}
#: Other spellings a problem file may use (``mph``, ``sec``).
ALIASES = {"mph": "mi/h", "kph": "km/h", "fps": "ft/s", "sec": "s", "hr": "h", "lbs": "lb"}
DEGREES = ("deg", "°", "circ", "degree", "degrees")
SYSTEM_BASE = {"SI": ("kg", "m", "s"), "US": ("slug", "ft", "s")}


class UnknownUnit(ValueError):
    """A unit this table does not know."""


def parse(text: str) -> tuple[Fraction, Dim, bool]:
    """``m/s^2`` -> (factor to SI, dimension, degrees?). ``%`` is 1/100 of a pure number."""
    src = text.strip().replace("·", "*").replace(" ", "")
    if src == "%":
        return Fraction(1, 100), NONE, False
    if src in DEGREES:
        return Fraction(1), ANGLE, True
    src = re.sub(r"[A-Za-z]+", lambda m: ALIASES.get(m[0], m[0]), src)
    factor, dim, sign = Fraction(1), [0, 0, 0, 0], 1
    for m in re.finditer(r"([*/])?([A-Za-z]+)(?:\^\{?(-?\d+)\}?)?", src):
        op, name, power = m.groups()
        if op == "/":
            sign = -1
        elif op == "*":
            sign = 1
        if name not in BASE:
            raise UnknownUnit(f"unknown unit {name!r} in {text!r}")
        f, d = BASE[name]
        p = sign * int(power or 1)
        factor *= f**p
        dim = [a + p * b for a, b in zip(dim, d, strict=True)]
    if not re.fullmatch(r"(?:[*/]?[A-Za-z]+(?:\^\{?-?\d+\}?)?)+", src):
        raise UnknownUnit(f"cannot read the unit {text!r}")
    return factor, (dim[0], dim[1], dim[2], dim[3]), False


def working_factor(dim: Dim, system: str) -> Fraction:
    """Size of the unit a solution in ``system`` works in for ``dim``, in SI (slug^a ft^b s^c)."""
    mass, length, time = SYSTEM_BASE.get(system, SYSTEM_BASE["SI"])
    return BASE[mass][0] ** dim[0] * BASE[length][0] ** dim[1] * BASE[time][0] ** dim[2]


def to_working(text: str, system: str) -> tuple[Fraction, Dim, bool]:
    """The factor that turns a number shown in ``text`` into the working unit of its dimension."""
    factor, dim, degrees = parse(text)
    return factor / working_factor(dim, system), dim, degrees


def words(dim: Dim) -> str:
    """'a velocity', or the exponents."""
    return WORDS.get(dim, "M^{} L^{} T^{} angle^{}".format(*dim))


def multiply(a: Dim, b: Dim, power: int = 1) -> Dim:
    """The dimension of a * b**power."""
    return (a[0] + power * b[0], a[1] + power * b[1], a[2] + power * b[2], a[3] + power * b[3])
