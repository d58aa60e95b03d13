"""Units: parse "number unit" text and convert it to a problem's working units.

Scale factors are exact by definition (1 ft = 381/1250 m, 1 lb = 0.45359237 kg),
so a given converts without rounding. A dimension is the exponent tuple
(mass, length, time, angle); angles are kept apart so that "deg" is not
mistaken for a pure number.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import sympy

Dim = tuple[int, int, int, int]

DIMENSIONLESS: Dim = (0, 0, 0, 0)
MASS: Dim = (1, 0, 0, 0)
LENGTH: Dim = (0, 1, 0, 0)
TIME: Dim = (0, 0, 1, 0)
ANGLE: Dim = (0, 0, 0, 1)
VELOCITY: Dim = (0, 1, -1, 0)
FORCE: Dim = (1, 1, -2, 0)
ENERGY: Dim = (1, 2, -2, 0)
IMPULSE: Dim = (1, 1, -1, 0)
ACCELERATION: Dim = (0, 1, -2, 0)
STIFFNESS: Dim = (1, 0, -2, 0)

DIM_NAMES: dict[Dim, str] = {
    DIMENSIONLESS: "a pure number",
    MASS: "a mass",
    LENGTH: "a length",
    TIME: "a time",
    ANGLE: "an angle",
    VELOCITY: "a velocity",
    FORCE: "a force",
    ENERGY: "an energy",
    IMPULSE: "an impulse",
    ACCELERATION: "an acceleration",
    STIFFNESS: "a spring stiffness",
}


#: Exact by definition (the international yard and pound, 1959): no unit system is
#: built at import time (tests/test_units.py checks them against sympy.physics.units).
_G = sympy.Rational(980665, 100000)  # standard gravity, m/s^2
_LB = sympy.Rational(45359237, 100000000)  # pound mass in kg
_FT = sympy.Rational(3048, 10000)  # foot in m
_IN = _FT / 12
_MI = 5280 * _FT

#: name -> (factor to SI, dimension). Angles: factor to radians.
BASE_UNITS: dict[str, tuple[sympy.Expr, Dim]] = {
    "m": (sympy.Integer(1), LENGTH),
    "mm": (sympy.Rational(1, 1000), LENGTH),
    "cm": (sympy.Rational(1, 100), LENGTH),
    "km": (sympy.Integer(1000), LENGTH),
    "in": (_IN, LENGTH),
    "ft": (_FT, LENGTH),
    "mi": (_MI, LENGTH),
    "kg": (sympy.Integer(1), MASS),
    "g": (sympy.Rational(1, 1000), MASS),
    "lbm": (_LB, MASS),  # pound-mass
    "Mg": (sympy.Integer(1000), MASS),  # megagram (tonne)
    "slug": (_LB * _G / _FT, MASS),  # 1 lbf·s²/ft
    "s": (sympy.Integer(1), TIME),
    "min": (sympy.Integer(60), TIME),
    "h": (sympy.Integer(3600), TIME),
    "N": (sympy.Integer(1), FORCE),
    "kN": (sympy.Integer(1000), FORCE),
    "lb": (_LB * _G, FORCE),  # a pound is a weight (pound-force)
    "lbf": (_LB * _G, FORCE),
    "J": (sympy.Integer(1), ENERGY),
    "kJ": (sympy.Integer(1000), ENERGY),
    "rad": (sympy.Integer(1), ANGLE),
    "deg": (sympy.pi / 180, ANGLE),
    "°": (sympy.pi / 180, ANGLE),
}

ALIASES = {
    "mph": "mi/h",
    "kph": "km/h",
    "fps": "ft/s",
    "degree": "deg",
    "degrees": "deg",
    "lbs": "lb",
    "sec": "s",
    "hr": "h",
}

#: Working units of each system, by dimension: what the solution computes in.
SYSTEMS: dict[str, dict[Dim, str]] = {
    "SI": {
        MASS: "kg",
        LENGTH: "m",
        TIME: "s",
        VELOCITY: "m/s",
        FORCE: "N",
        ENERGY: "J",
        IMPULSE: "N*s",
        ACCELERATION: "m/s^2",
        STIFFNESS: "N/m",
        ANGLE: "deg",
        DIMENSIONLESS: "",
    },
    "US": {
        MASS: "slug",
        LENGTH: "ft",
        TIME: "s",
        VELOCITY: "ft/s",
        FORCE: "lb",
        ENERGY: "ft*lb",
        IMPULSE: "lb*s",
        ACCELERATION: "ft/s^2",
        STIFFNESS: "lb/ft",
        ANGLE: "deg",
        DIMENSIONLESS: "",
    },
}

_SI_NAMES = {"m", "mm", "cm", "km", "kg", "g", "Mg", "N", "kN", "J", "kJ"}
_US_NAMES = {"in", "ft", "mi", "slug", "lb", "lbf", "lbm"}

_TOKEN = re.compile(r"\s*(?:([A-Za-z°]+)|(\*|/|·|\^)|(-?\d+))")


@dataclass(frozen=True)
class Unit:
    """A parsed unit: its text, exact factor to SI (radians for angles), dimension."""

    text: str
    factor: sympy.Expr
    dim: Dim

    @property
    def system(self) -> str | None:
        """'SI' or 'US' when the unit's names belong to one system, else None."""
        names = set(re.findall(r"[A-Za-z]+", self.text))
        if names & _US_NAMES:
            return "US"
        if names & _SI_NAMES:
            return "SI"
        return None


def parse_unit(text: str) -> Unit:
    """Parse ``text`` such as ``m/s``, ``km/h``, ``ft*lb`` or ``deg``.

    Raises ValueError with a sentence naming the unknown part.
    """
    src = ALIASES.get(text.strip(), text.strip())
    if src == "":
        return Unit("", sympy.Integer(1), DIMENSIONLESS)
    pos, factor, dim, sign, expect_name = 0, sympy.Integer(1), [0, 0, 0, 0], 1, True
    last: tuple[sympy.Expr, Dim] | None = None
    while pos < len(src):
        m = _TOKEN.match(src, pos)
        if not m:
            raise ValueError(f"cannot read the unit {text!r}")
        pos = m.end()
        name, op, _num = m.groups()
        if name is not None:
            if not expect_name:
                raise ValueError(f"cannot read the unit {text!r}")
            name = ALIASES.get(name, name)
            if name not in BASE_UNITS:
                known = ", ".join(sorted(k for k in BASE_UNITS if k != "°"))
                raise ValueError(f"unknown unit {name!r} (known: {known})")
            last = BASE_UNITS[name]
            factor *= last[0] ** sign
            dim = [a + sign * b for a, b in zip(dim, last[1], strict=False)]
            expect_name = False
        elif op in ("*", "·", "/"):
            if expect_name:
                raise ValueError(f"cannot read the unit {text!r}")
            sign = -1 if op == "/" else 1
            expect_name = True
        elif op == "^":
            m2 = _TOKEN.match(src, pos)
            if last is None or not m2 or m2.group(3) is None:
                raise ValueError(f"cannot read the unit {text!r}")
            pos = m2.end()
            p = int(m2.group(3))
            if abs(p) > 4:
                raise ValueError(f"the power {p} in the unit {text!r} is out of range")
            factor *= last[0] ** (sign * (p - 1))
            dim = [a + sign * (p - 1) * b for a, b in zip(dim, last[1], strict=False)]
        else:
            raise ValueError(f"cannot read the unit {text!r}")
    if expect_name:
        raise ValueError(f"cannot read the unit {text!r}")
    return Unit(src, factor, (dim[0], dim[1], dim[2], dim[3]))


def working_unit(dim: Dim, system: str) -> Unit:
    """The unit a ``system`` ('SI' or 'US') computes quantities of ``dim`` in."""
    name = SYSTEMS[system].get(dim)
    if name is None:
        raise ValueError(f"no working unit for {describe(dim)} in {system}")
    return parse_unit(name)


def working_factor(dim: Dim, system: str | None) -> sympy.Expr:
    """The factor to SI of the working unit of ``dim`` in ``system`` (None: SI), built from the
    system's units of mass, length and time (angles in radians): it holds for every dimension,
    m^2/s^2 as well as m/s."""
    if system not in SYSTEMS:
        return sympy.Integer(1)
    work = SYSTEMS[system]
    mass, length, time = (BASE_UNITS[work[d]][0] for d in (MASS, LENGTH, TIME))
    return mass ** dim[0] * length ** dim[1] * time ** dim[2]


def convert(value: sympy.Expr, src: Unit, dst: Unit) -> sympy.Expr:
    """``value`` in ``src`` expressed exactly in ``dst`` (same dimension)."""
    if src.dim != dst.dim:
        raise ValueError(f"cannot convert {src.text} to {dst.text}")
    return value * src.factor / dst.factor  # exact: the factors are exact


def describe(dim: Dim) -> str:
    """Words for a dimension: 'a velocity', or its exponents."""
    if dim in DIM_NAMES:
        return DIM_NAMES[dim]
    m, length, t, a = dim
    return f"a quantity of dimension M^{m} L^{length} T^{t} angle^{a}"


def latex_unit(text: str) -> str:
    """``m/s`` -> ``\\mathrm{m/s}``; ``deg`` -> ``{}^\\circ``; ``ft*lb`` -> ``\\mathrm{ft\\cdot lb}``."""
    if text in ("deg", "°"):
        return r"^\circ"
    if text == "":
        return ""
    body = text.replace("*", r"\cdot ").replace("^2", "^{2}")
    return r"\mathrm{" + body + "}"


def plain_unit(text: str) -> str:
    """``ft*lb`` -> ``ft·lb``; ``deg`` -> ``°``; for terminals and JSON."""
    if text == "deg":
        return "°"
    return text.replace("*", "·").replace("^2", "²")
