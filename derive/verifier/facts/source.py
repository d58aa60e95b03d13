"""The problem file read again, apart from derive's loader: givens, units, angles, velocities.

derive's loader turns ``m_A = "22 g"`` into 0.022 kg and ``[A] angle = "theta", from =
"+n", toward = "+t"`` into v_A1n = v_A1 cos(theta); a wrong factor or a misread field
there would make every line of the page agree with the wrong problem. So the
verifier reads the TOML itself (:mod:`tomllib`), with its own unit table
(:mod:`derive.verifier.units`) and its own expression reader (:mod:`.expression`),
and the facts use these values; where derive's loaded problem says otherwise, the
difference is reported (:func:`compare`).

A letter kept symbolic (``u = "m/s"``) or an unknown ("?", listed in ``unknowns``) is
a SymPy symbol of its name.
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path
from typing import Any

import sympy

from derive.verifier import units
from derive.verifier.facts.expression import Unread, evaluate

#: Names whose dimension the notes fix (a bare number is in the working unit).
RESERVED: dict[str, units.Dim] = {
    "m_A": units.MASS,
    "m_B": units.MASS,
    "e": units.NONE,
    "W_A": units.FORCE,
    "W_B": units.FORCE,
    "g": units.ACCELERATION,
    "phi": units.ANGLE,
    **{f"v_{b}{w}{c}": units.VELOCITY for b in "AB" for w in "12" for c in ("", "n", "t", "x", "y")},
}
GRAVITY = {"SI": "9.81 m/s^2", "US": "32.2 ft/s^2"}
_QUANTITY = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(\S.*?)?\s*$")
_US = {"in", "ft", "mi", "slug", "lb", "lbf", "lbm", "mph", "fps"}
_SI = {"m", "mm", "cm", "km", "kg", "g", "Mg", "N", "kN", "J", "kJ", "kph"}


@dataclass
class Read:
    """What the file says: each given's value in working units (radians for angles), its
    dimension, the numbers it typed, and each body's velocity before the impact (n, t)."""

    system: str = "SI"
    values: dict[str, sympy.Expr] = field(default_factory=dict)
    dims: dict[str, units.Dim] = field(default_factory=dict)
    typed: set[sympy.Rational] = field(default_factory=set)
    motions: dict[str, tuple[sympy.Expr, sympy.Expr]] = field(default_factory=dict)
    unread: list[str] = field(default_factory=list)
    pending: set[str] = field(default_factory=set)
    unknowns: set[str] = field(default_factory=set)
    data: dict[str, Any] = field(default_factory=dict)

    def named(self) -> dict[str, tuple[sympy.Expr, units.Dim]]:
        return {n: (v, self.dims[n]) for n, v in self.values.items()}


def load(problem: Any, text: str | None = None) -> Read | None:
    """The file of ``problem`` read again (``text``: its TOML, when it is not on disk);
    None when there is no file to read (a homework variant built in memory)."""
    if text is None:
        path = Path(str(getattr(problem, "path", "") or ""))
        if path.suffix != ".toml" or not path.is_file():
            return None
        text = path.read_text(encoding="utf-8-sig")
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        return None
    read = Read(data=data)
    givens = data.get("given") or {}
    read.system = data.get("units") or system_of(givens)
    read_givens(read, givens)
    if data.get("kind") in ("direct", "oblique"):
        read_impact(read, data)
    return read


def system_of(givens: Mapping[str, Any]) -> str:
    """ "US" when more givens are in US customary units than in SI."""
    votes = {"SI": 0, "US": 0}
    for raw in givens.values():
        if isinstance(raw, str):
            m = _QUANTITY.match(raw)
            unit = (m[2] or "") if m else raw
            names = set(re.findall(r"[A-Za-z]+", unit))
            votes["US"] += bool(names & _US)
            votes["SI"] += bool(names & _SI) and not names & _US
    return "US" if votes["US"] > votes["SI"] else "SI"


def working(number: sympy.Expr, unit: str, system: str) -> tuple[sympy.Expr, units.Dim]:
    """A number in ``unit`` as a value in the working unit of ``system`` (radians for degrees)."""
    factor, dim, degrees = units.to_working(unit, system)
    if degrees:
        return number * sympy.pi / 180, units.ANGLE
    return number * sympy.Rational(factor.numerator, factor.denominator), dim


def value_of(name: str, raw: Any, read: Read) -> tuple[sympy.Expr, units.Dim]:
    """One given's value: a bare number, a number with its unit, a letter, "?" or an expression."""
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        number = sympy.Rational(str(Fraction(repr(raw))))
        dim = RESERVED.get(name, units.NONE)
        read.typed.add(number)
        return (number * sympy.pi / 180 if dim == units.ANGLE else number), dim
    if not isinstance(raw, str):
        raise Unread(f"not a value: {raw!r}")
    text = raw.strip()
    if text == "?" or text.startswith("? "):
        dim = _unit_dim(text[1:].strip(), RESERVED.get(name, units.NONE))
        read.unknowns.add(name)
        return sympy.Symbol(name), dim
    m = _QUANTITY.match(text)
    if m and m[2] and re.fullmatch(r"[A-Za-z°%][A-Za-z°/*^·\d\s-]*", m[2]) and "_" not in m[2]:
        number = sympy.Rational(m[1])
        read.typed.add(number)
        return working(number, m[2], read.system)
    if m and not m[2]:
        number = sympy.Rational(m[1])
        read.typed.add(number)
        dim = RESERVED.get(name, units.NONE)
        return (number * sympy.pi / 180 if dim == units.ANGLE else number), dim
    if text == name and name not in read.values:
        return sympy.Symbol(name), RESERVED.get(name, units.NONE)
    words = set(re.findall(r"[A-Za-z_][A-Za-z_0-9]*", text))
    if words & (read.pending - {name}):
        raise Unread("names a given not read yet")
    if re.fullmatch(r"[A-Za-z°][A-Za-z°/*^·\d\s]*", text) and not words <= set(read.values):
        return sympy.Symbol(name), _unit_dim(text, RESERVED.get(name, units.NONE))  # a unit alone: a letter
    return evaluate(text, read.named())


def _unit_dim(text: str, default: units.Dim) -> units.Dim:
    if not text:
        return default
    _, dim, degrees = units.parse(text)
    return units.ANGLE if degrees else dim


def read_givens(read: Read, givens: Mapping[str, Any]) -> None:
    """Each entry of ``[given]``, in the order their names allow (an expression after its names)."""
    left = dict(givens)
    while left:
        read.pending = set(left)
        done = []
        for name, raw in left.items():
            try:
                read.values[name], read.dims[name] = value_of(name, raw, read)
                read.pending.discard(name)
            except Unread:
                continue
            except units.UnknownUnit:
                read.unread.append(name)
                done.append(name)
                continue
            done.append(name)
        for name in done:
            left.pop(name)
            read.pending.discard(name)
        if not done:
            read.unread += list(left)
            return


def read_impact(read: Read, data: Mapping[str, Any]) -> None:
    """Masses from weights, the line of impact from ``[geometry]``, each body's (n, t) before."""
    for b in "AB":
        if f"m_{b}" not in read.values and f"W_{b}" in read.values:
            if "g" not in read.values:
                read.values["g"], read.dims["g"] = value_of("g", GRAVITY[read.system], read)
            read.values[f"m_{b}"] = read.values[f"W_{b}"] / read.values["g"]
            read.dims[f"m_{b}"] = units.MASS
    phi = _phi(read, data.get("geometry"))
    oblique = data.get("kind") == "oblique"
    for b in "AB":
        tbl = data.get(b) or {}
        if b == "B" and tbl.get("fixed"):
            read.motions[b] = (sympy.Integer(0), sympy.Integer(0))
            continue
        try:
            read.motions[b] = _motion(read, b, tbl, oblique, phi)
        except (Unread, KeyError, units.UnknownUnit):
            read.unread.append(f"[{b}]")


def _phi(read: Read, geo: Mapping[str, Any] | None) -> sympy.Expr | None:
    if not geo:
        return None
    try:
        if "n_angle" in geo:
            raw = geo["n_angle"]
            read.values["phi"], read.dims["phi"] = value_of("phi", raw, read)
        elif "offset" in geo:
            raw = geo["offset"]
            if not (isinstance(raw, str) and raw.strip() in read.values):
                read.values["d"], read.dims["d"] = value_of("d", raw, read)
                raw = "d"
            read.values["phi"] = evaluate(f"asin(({raw})/(r_A + r_B))", read.named())[0]
        else:
            for b in "AB":
                for axis, raw in zip("xy", geo[f"centre_{b}"], strict=True):
                    zero = (isinstance(raw, (int, float)) and raw == 0) or (
                        isinstance(raw, str) and raw.strip() in ("0", "0.0")
                    )
                    read.values[f"{axis}_{b}"] = sympy.Integer(0) if zero else value_of(f"{axis}_{b}", raw, read)[0]
                    read.dims[f"{axis}_{b}"] = units.LENGTH
            read.values["phi"] = evaluate("atan2(y_B - y_A, x_B - x_A)", read.named())[0]
    except (Unread, KeyError, ValueError):
        read.unread.append("[geometry]")
        return None
    read.dims["phi"] = units.ANGLE
    return read.values["phi"]


def _motion(read: Read, b: str, tbl: Mapping[str, Any], oblique: bool, phi: sympy.Expr | None) -> tuple:
    v = read.values
    if phi is not None and (f"v_{b}1x" in v or f"v_{b}1y" in v):
        return _from_xy(v[f"v_{b}1x"], v[f"v_{b}1y"], phi)
    if not oblique:
        return v[f"v_{b}1"], sympy.Integer(0)
    if f"v_{b}1n" in v or f"v_{b}1t" in v:
        return v[f"v_{b}1n"], v[f"v_{b}1t"]
    speed = v[f"v_{b}1"]
    if "angle" not in tbl:
        return sympy.Integer(0) * speed, sympy.Integer(0)
    raw = tbl["angle"]
    if isinstance(raw, str) and raw.strip() in v:
        angle = v[raw.strip()]
    else:
        raw = f"{raw} deg" if isinstance(raw, (int, float)) else raw
        angle = value_of(f"theta_{b}1", raw, read)[0]
        v[f"theta_{b}1"], read.dims[f"theta_{b}1"] = angle, units.ANGLE
    comps = {tbl["from"]: speed * sympy.cos(angle), tbl["toward"]: speed * sympy.sin(angle)}

    def along(axis: str) -> sympy.Expr:
        return sum((c if ax[0] == "+" else -c for ax, c in comps.items() if ax[1] == axis), sympy.Integer(0))

    if phi is not None and tbl["from"][1] in "xy":
        return _from_xy(along("x"), along("y"), phi)
    return along("n"), along("t")


def _from_xy(x: sympy.Expr, y: sympy.Expr, phi: sympy.Expr) -> tuple[sympy.Expr, sympy.Expr]:
    return x * sympy.cos(phi) + y * sympy.sin(phi), -x * sympy.sin(phi) + y * sympy.cos(phi)
