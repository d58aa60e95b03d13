"""The velocities before the impact and the line of impact: ``[A]``, ``[B]`` and ``[geometry]``.

A velocity is given along n (a direct impact), by its n and t components, by a
speed with a direction (an angle from one axis toward another), or, with a
``[geometry]`` table, in x-y axes; each becomes a :class:`~derive.problem.records.Motion`
with its n and t components in the givens' symbols.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import sympy

from derive.errors import InputError, UnitError
from derive.problem import units
from derive.problem.givens import QUANTITY, given_value, quantity
from derive.problem.records import AXES, XY_AXES, Given, Motion
from derive.problem.source import Source
from derive.problem.units import ANGLE, describe
from derive.symbols import symbol

DIRECTION = ("angle", "from", "toward")


def geometry(
    geo: Any, givens: list[Given], by_name: dict[str, Given], ctx: Source, oblique: bool, system: str
) -> sympy.Symbol | None:
    """The line of impact in the problem's x-y axes: its angle phi from +x toward +y,
    given directly, from an offset between parallel paths (sin phi = d/(r_A + r_B)),
    or from the centres at contact. phi becomes a given, defined by that geometry."""
    if geo is None:
        return None
    if not oblique:
        raise ctx.error('the line of impact from geometry needs kind = "oblique"', section="geometry")
    if "phi" in by_name:
        raise ctx.error(
            "phi is the angle derive gives the line of impact; rename this given", section="given", key="phi"
        )
    methods = [m for m in ("n_angle", "offset", "centre_A") if m in geo]
    if len(methods) != 1 or ("centre_A" in geo) != ("centre_B" in geo):
        raise ctx.error(
            "give exactly one of: n_angle; offset (with r_A and r_B given); centre_A and centre_B", section="geometry"
        )

    def add(name: str, raw: Any, field_: str) -> Given:
        if name in by_name:
            raise ctx.error(f"{name} is given already; [geometry] defines it", section="geometry", key=field_)
        try:
            g = given_value(name, raw, by_name, ctx, oblique, system)
        except InputError as exc:
            raise ctx.error(exc.what, section="geometry", key=field_, value=raw, cls=type(exc)) from None
        givens.append(g)
        by_name[name] = g
        return g

    if "n_angle" in geo:
        raw = geo["n_angle"]
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            raw = f"{raw} deg"
        return add("phi", raw, "n_angle").symbol
    if "offset" in geo:
        for r in ("r_A", "r_B"):
            if r not in by_name or by_name[r].dim != units.LENGTH:
                raise ctx.error(f"an offset needs the radii: give {r} (a length)", section="given", key=r)
        raw = geo["offset"]
        d = by_name[raw.strip()] if isinstance(raw, str) and raw.strip() in by_name else add("d", raw, "offset")
        if d.dim != units.LENGTH:
            raise ctx.error("expected a length", section="geometry", key="offset", value=geo["offset"], cls=UnitError)
        _check_reach(d.value, by_name, ctx, "offset", f"the offset {_shown(raw)} exceeds", raw)
        return add("phi", f"asin({d.name}/(r_A + r_B))", "offset").symbol
    for b in "AB":
        raw = geo[f"centre_{b}"]
        for axis, value in zip("xy", raw, strict=True):
            if _bare_zero(value):  # the origin needs no unit: "0" beside "0.1 m" is 0 m
                value = f"0 {units.working_unit(units.LENGTH, system).text}"
            g = add(f"{axis}_{b}", value, f"centre_{b}")
            if g.dim != units.LENGTH:
                raise ctx.error("expected lengths", section="geometry", key=f"centre_{b}", value=raw, cls=UnitError)
    _check_centres(by_name, ctx, geo["centre_B"])
    return add("phi", "atan2(y_B - y_A, x_B - x_A)", "centre_B").symbol


#: How far the centres' distance may be from r_A + r_B (relative), for coordinates rounded in print.
CONTACT_TOLERANCE = sympy.Rational(2, 100)


def _shown(raw: Any) -> str:
    return raw.strip() if isinstance(raw, str) else str(raw)


def _length(value: sympy.Expr, by_name: Mapping[str, Given]) -> str:
    """A length in the problem's working unit, for a message: "0.1 m"."""
    unit = next((g.unit for g in by_name.values() if g.dim == units.LENGTH and g.unit), "")
    return f"{float(value):.4g} {unit}".strip()


def _radii(by_name: Mapping[str, Given]) -> sympy.Expr | None:
    """r_A + r_B where both are given as numbers, else None."""
    r = [by_name[n].value for n in ("r_A", "r_B") if n in by_name and by_name[n].dim == units.LENGTH]
    return r[0] + r[1] if len(r) == 2 and all(x is not None for x in r) else None


def _check_reach(
    d: sympy.Expr | None, by_name: Mapping[str, Given], ctx: Source, key: str, what: str, raw: Any
) -> None:
    """An offset between parallel paths must be at most r_A + r_B, or the spheres never touch."""
    total = _radii(by_name)
    if d is None or total is None or abs(d) <= total:
        return
    raise ctx.error(
        f"{what} r_A + r_B = {_length(total, by_name)}: the spheres cannot touch",
        section="geometry",
        key=key,
        value=raw,
    )


def _check_centres(by_name: Mapping[str, Given], ctx: Source, raw: Any) -> None:
    """The centres at contact are two points r_A + r_B apart (where both are numbers)."""
    xs = [by_name[n].value for n in ("x_A", "y_A", "x_B", "y_B")]
    if any(x is None for x in xs):
        return
    distance = sympy.sqrt((xs[2] - xs[0]) ** 2 + (xs[3] - xs[1]) ** 2)
    if distance == 0:
        raise ctx.error(
            "centre_A and centre_B are the same point: no line of impact joins them", section="geometry", key="centre_B"
        )
    total = _radii(by_name)
    if total is not None and abs(distance - total) > CONTACT_TOLERANCE * total:
        raise ctx.error(
            f"the centres are {_length(distance, by_name)} apart, but at contact they are r_A + r_B = "
            f"{_length(total, by_name)} apart: check the centres or the radii",
            section="geometry",
            key="centre_B",
            value=raw,
        )


def _bare_zero(value: Any) -> bool:
    """True for a coordinate written as a bare zero: 0, 0.0, "0", "0.0"."""
    if isinstance(value, bool):
        return False
    if isinstance(value, (int, float)):
        return value == 0
    try:
        return isinstance(value, str) and float(value.strip()) == 0
    except ValueError:
        return False


def motion(
    b: str,
    tbl: Mapping[str, Any],
    by_name: dict[str, Given],
    ctx: Source,
    oblique: bool,
    phi: sympy.Symbol | None = None,
) -> tuple[Motion, Given | None]:
    """Body ``b``'s velocity before the impact, and the angle given it needs (if one is new)."""
    speed_name, n_name, t_name = f"v_{b}1", f"v_{b}1n", f"v_{b}1t"
    x_name, y_name = f"v_{b}1x", f"v_{b}1y"
    if (x_name in by_name or y_name in by_name) and phi is None:
        key = x_name if x_name in by_name else y_name
        raise ctx.error("x-y components need a [geometry] table that sets the line of impact", section="given", key=key)
    if phi is not None and (x_name in by_name or y_name in by_name):
        return _xy_components(b, by_name, ctx, phi), None
    if not oblique:
        return _direct(b, tbl, by_name, ctx), None
    has_comp = n_name in by_name or t_name in by_name
    if has_comp and speed_name in by_name:
        raise ctx.error(
            f"give either {speed_name} (speed, with a direction) or {n_name} and {t_name}, not both",
            section="given",
            key=speed_name,
        )
    if has_comp:
        if set(DIRECTION) & set(tbl):
            raise ctx.error(f"the velocity of {b} is given by components, so [{b}] needs no angle", section=b)
        _both_components((n_name, t_name), by_name, ctx)
        return Motion(b, by_name[n_name].symbol, by_name[t_name].symbol), None
    return _speed_and_direction(b, tbl, by_name, ctx, phi)


def _xy_components(b: str, by_name: Mapping[str, Given], ctx: Source, phi: sympy.Symbol) -> Motion:
    x_name, y_name = f"v_{b}1x", f"v_{b}1y"
    if {f"v_{b}1n", f"v_{b}1t", f"v_{b}1"} & set(by_name):
        raise ctx.error(f"give the velocity of {b} one way only", section="given", key=x_name)
    _both_components((x_name, y_name), by_name, ctx)
    vx, vy = by_name[x_name].symbol, by_name[y_name].symbol
    n = vx * sympy.cos(phi) + vy * sympy.sin(phi)
    t = -vx * sympy.sin(phi) + vy * sympy.cos(phi)
    return Motion(b, n, t, x=vx, y=vy)


def _both_components(names: tuple[str, str], by_name: Mapping[str, Given], ctx: Source) -> None:
    """Raises unless both components in ``names`` are given (naming the first missing one)."""
    missing = [k for k in names if k not in by_name]
    if missing:
        raise ctx.error(
            f"is missing: with components give both {names[0]} and {names[1]}{misspelt(missing[0], by_name)}",
            section="given",
            key=missing[0],
        )


def misspelt(name: str, by_name: Mapping[str, Any]) -> str:
    """A note naming a given that looks like ``name`` mistyped (v_b1 for v_B1), or ''."""
    import difflib

    near = [k for k in by_name if k != name and k.lower() == name.lower()]
    near = near or difflib.get_close_matches(name, [k for k in by_name if k != name], n=1, cutoff=0.8)
    return f" (the file gives {near[0]}: did you mean {name}?)" if near else ""


def _direct(b: str, tbl: Mapping[str, Any], by_name: Mapping[str, Given], ctx: Source) -> Motion:
    speed_name, n_name, t_name = f"v_{b}1", f"v_{b}1n", f"v_{b}1t"
    if n_name in by_name or t_name in by_name or set(DIRECTION) & set(tbl):
        key = n_name if n_name in by_name else t_name if t_name in by_name else None
        raise ctx.error(
            f"a direct impact has one velocity component: give {speed_name}, signed along +n (from A toward B)",
            section="given" if key else b,
            key=key,
        )
    if speed_name not in by_name:
        raise ctx.error(
            f"is missing: give the velocity of {b} before the impact, signed along +n{misspelt(speed_name, by_name)}",
            section="given",
            key=speed_name,
        )
    return Motion(b, by_name[speed_name].symbol, sympy.Integer(0))


def _speed_and_direction(
    b: str, tbl: Mapping[str, Any], by_name: Mapping[str, Given], ctx: Source, phi: sympy.Symbol | None
) -> tuple[Motion, Given | None]:
    speed_name = f"v_{b}1"
    if speed_name not in by_name:
        raise ctx.error(
            f"is missing: give the speed {speed_name} with [{b}] angle, from and toward, "
            f"or the components v_{b}1n and v_{b}1t{misspelt(speed_name, by_name)}",
            section="given",
            key=speed_name,
        )
    speed = by_name[speed_name]
    if not set(DIRECTION) & set(tbl):
        if speed.value == 0:
            return Motion(b, sympy.Integer(0), sympy.Integer(0), speed=speed.symbol), None
        raise ctx.error(f"is missing: give the direction of {b}'s velocity (angle, from, toward)", section=b)
    for k in DIRECTION:
        if k not in tbl:
            raise ctx.error(f"is missing: the direction of {b} needs angle, from and toward", section=b, key=k)
    axis_from, toward = tbl["from"], tbl["toward"]
    _check_axes(b, axis_from, toward, ctx, phi)
    angle, extra = _angle(b, tbl["angle"], by_name, ctx)
    v, th = speed.symbol, angle.symbol
    comps = {axis_from: v * sympy.cos(th), toward: v * sympy.sin(th)}
    if axis_from in XY_AXES:
        assert phi is not None
        x = sympy.sympify(sum((c if ax == "+x" else -c) for ax, c in comps.items() if ax[1] == "x"))
        y = sympy.sympify(sum((c if ax == "+y" else -c) for ax, c in comps.items() if ax[1] == "y"))
        n = x * sympy.cos(phi) + y * sympy.sin(phi)
        t = -x * sympy.sin(phi) + y * sympy.cos(phi)
        return Motion(b, n, t, speed=v, angle=th, axis_from=axis_from, toward=toward, x=x, y=y), extra
    n = sum((c if ax == "+n" else -c) for ax, c in comps.items() if ax[1] == "n")
    t = sum((c if ax == "+t" else -c) for ax, c in comps.items() if ax[1] == "t")
    return Motion(b, sympy.sympify(n), sympy.sympify(t), speed=v, angle=th, axis_from=axis_from, toward=toward), extra


def _check_axes(b: str, axis_from: str, toward: str, ctx: Source, phi: sympy.Symbol | None) -> None:
    allowed = AXES + (XY_AXES if phi is not None else ())
    for k, ax in (("from", axis_from), ("toward", toward)):
        if ax not in allowed:
            hint = "" if phi is not None else " (x-y axes need a [geometry] table)"
            raise ctx.error(f"expected one of {', '.join(allowed)}{hint}", section=b, key=k, value=ax)
    if (axis_from in XY_AXES) != (toward in XY_AXES):
        raise ctx.error("measure the angle between two x-y axes or two n-t axes", section=b, key="toward", value=toward)
    if axis_from[1] == toward[1]:
        raise ctx.error(
            f"the angle is measured from {axis_from} toward an axis at right angles to it (±n or ±t), not {toward}",
            section=b,
            key="toward",
            value=toward,
        )


def _angle(b: str, raw: Any, by_name: Mapping[str, Given], ctx: Source) -> tuple[Given, Given | None]:
    """The angle of ``b``'s velocity: a given named by ``raw``, or a new given theta_B1 from its number."""
    if isinstance(raw, str) and raw.strip() in by_name:
        angle = by_name[raw.strip()]
        if angle.dim != ANGLE:
            raise ctx.error(
                f'{angle.name} is {describe(angle.dim)}, not an angle: give it with its unit, such as "30 deg"',
                section=b,
                key="angle",
                value=raw,
                cls=UnitError,
            )
        return angle, None
    name = f"theta_{b}1"
    if name in by_name:
        raise ctx.error(f'{name} is already given: write angle = "{name}"', section=b, key="angle", value=raw)

    def err(what: str, cls: type[InputError] = InputError) -> InputError:
        return ctx.error(what, section=b, key="angle", value=raw, cls=cls)

    text = raw
    if isinstance(raw, (int, float)) and not isinstance(raw, bool):
        if not math.isfinite(raw):
            raise err("expected a finite angle")
        text = f"{raw} deg"
    m = QUANTITY.match(text) if isinstance(text, str) else None
    if not m:
        raise err('expected an angle such as "30 deg" or the name of a given angle')
    try:
        unit = units.parse_unit(m.group(2) or "deg")
    except ValueError as exc:
        raise err(str(exc), UnitError) from None
    if unit.dim != ANGLE:
        raise err(f"expected an angle, but {unit.text} is {describe(unit.dim)}", UnitError)
    angle = quantity(name, symbol(name), sympy.Rational(m.group(1)), unit, ANGLE, "SI", err)
    return angle, angle
