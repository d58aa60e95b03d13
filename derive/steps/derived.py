"""The lines of results worked out from an impact's components: speeds, directions (from an
axis, or the acute angle with the line of centres or the plane of contact), the angle a velocity
turns through, the impulse, and the quantities a file defines."""

from __future__ import annotations

import sympy

from derive.numbers import tidy
from derive.physics.results import Result
from derive.steps.model import Eqn, Side
from derive.steps.page import Page, as_float, over, show
from derive.symbols import symbol


def derived_line(page: Page, r: Result, boxed: bool) -> Eqn:
    """A result worked out from the components after the impact (a speed, a direction, an
    acute angle, the turn, the impulse) or a defined quantity, as one line: its symbol, its
    form, the numbers put in and its value."""
    nm = page.nm
    if r.name in ("v_A2", "v_B2"):
        n, t = getattr(nm, f"{r.name[-2]}2n"), getattr(nm, f"{r.name[-2]}2t")
        nv, tv = page.value_of(n), page.value_of(t)
        sides = [Side((r.symbol,)), Side((sympy.sqrt(sympy.Add(t**2, n**2, evaluate=False), evaluate=False),))]
        if not ((nv.free_symbols | tv.free_symbols) - page.varied):
            squares = sympy.Add(
                sympy.Pow(as_float(tv), 2, evaluate=False), sympy.Pow(as_float(nv), 2, evaluate=False), evaluate=False
            )
            sides.append(Side((show(sympy.Pow(squares, sympy.Rational(1, 2), evaluate=False)),), "numeric"))
        sides.append(Side((r.found,), "result"))
        return Eqn(tuple(sides), unit=r.unit, boxed=boxed)
    if r.name in ("theta_A2", "theta_B2", "beta_A2", "beta_B2"):  # theta from +t, beta from +n
        n, t = getattr(nm, f"{r.name[-2]}2n"), getattr(nm, f"{r.name[-2]}2t")
        y, x = (n, t) if r.name.startswith("theta") else (t, n)
        return angle_line(page, r, y, x, page.value_of(y), page.value_of(x), boxed)
    if r.name[:-1] in ("alpha_A", "alpha_B", "gamma_A", "gamma_B"):
        return _acute_line(page, r, boxed)
    if r.name in ("delta_A", "delta_B"):
        return _deflection_line(page, r, boxed)
    if r.name == "J_n":
        return _impulse_line(page, r, boxed)
    defined = {d.name: d for d in page.p.asks.defined}
    if r.name in defined:  # F_avg = J_n/dt = ...
        if r.unit == "deg" and getattr(r.found, "free_symbols", None):  # an angle in letters: no degrees to show
            return Eqn((Side((r.symbol,)), Side((defined[r.name].expr,))), boxed=boxed)
        return Eqn(
            (Side((r.symbol,)), Side((defined[r.name].expr,)), Side((r.found,), "result")), unit=r.unit, boxed=boxed
        )
    return Eqn((Side((r.symbol,)), Side((r.found,), "result")), unit=r.unit, boxed=boxed)


def angle_line(
    page: Page, r: Result, y: sympy.Symbol, x: sympy.Symbol, yv: sympy.Expr, xv: sympy.Expr, boxed: bool
) -> Eqn:
    """A direction: tan^-1(y/x), with 180° added where x < 0 (written atan2 where
    the sign of x is not known when the page is written)."""
    numeric = not ((xv.free_symbols | yv.free_symbols) - page.varied)
    known = numeric and not (xv.free_symbols | yv.free_symbols)
    sides = [Side((r.symbol,))]
    ratio = None if xv == 0 else tidy(sympy.simplify(yv / xv))
    if xv == 0:
        pass
    elif (known and xv > 0) or (not numeric and ratio is not None and ratio.is_number and xv.is_positive):
        sides.append(Side((sympy.atan(over(y, x), evaluate=False),)))
        shown = over(as_float(yv), as_float(xv)) if known else as_float(ratio)
        sides.append(Side((show(sympy.atan(shown, evaluate=False)),), "numeric"))
    elif known:  # x < 0: the angle lies beyond ±90°
        turn = sympy.Symbol(r"\,180^\circ" if yv >= 0 else r"\,(-180^\circ)")
        sides.append(Side((sympy.atan(over(y, x), evaluate=False), turn)))
        shown = over(as_float(yv), as_float(xv))
        sides.append(Side((show(sympy.atan(shown, evaluate=False)), turn), "numeric"))
    else:
        sides.append(Side((sympy.atan2(y, x, evaluate=False),)))
    sides.append(Side((r.found,), "result"))
    return Eqn(tuple(sides), unit=r.unit, boxed=boxed)


def _acute_line(page: Page, r: Result, boxed: bool) -> Eqn:
    """An acute angle with the line of centres (alpha) or the plane of contact (gamma):
    tan^-1 of the other component's size over this one's, between 0° and 90°."""
    b, nm = r.name[-2], page.nm
    n, t = getattr(nm, f"{b}2n"), getattr(nm, f"{b}2t")
    y, x = (t, n) if r.name.startswith("alpha") else (n, t)
    yv, xv = page.value_of(y), page.value_of(x)
    sides = [Side((r.symbol,))]
    if xv != 0:
        sides.append(Side((sympy.atan(over(sympy.Abs(y), sympy.Abs(x)), evaluate=False),)))
        if not ((xv.free_symbols | yv.free_symbols) - page.varied):
            shown = over(as_float(abs(yv)), as_float(abs(xv)))
            sides.append(Side((show(sympy.atan(shown, evaluate=False)),), "numeric"))
    sides.append(Side((r.found,), "result"))
    return Eqn(tuple(sides), unit=r.unit, boxed=boxed)


def _deflection_line(page: Page, r: Result, boxed: bool) -> Eqn:
    """The angle a velocity turns through: cos^-1 of v_1 . v_2 over the speeds' product."""
    b, nm = r.name[-1], page.nm
    n1, t1 = getattr(nm, f"{b}1n"), getattr(nm, f"{b}1t")
    n2, t2 = getattr(nm, f"{b}2n"), getattr(nm, f"{b}2t")
    dot = sympy.Add(sympy.Mul(t1, t2, evaluate=False), sympy.Mul(n1, n2, evaluate=False), evaluate=False)
    speeds = sympy.Mul(symbol(f"v_{b}1"), symbol(f"v_{b}2"), evaluate=False)
    form = sympy.acos(over(dot, speeds), evaluate=False)
    return Eqn((Side((r.symbol,)), Side((form,)), Side((r.found,), "result")), unit=r.unit, boxed=boxed)


def _impulse_line(page: Page, r: Result, boxed: bool) -> Eqn:
    """J_n = m_A (v_A1n - v_A2n): the impulse along +n on B (on A it is -J_n)."""
    nm = page.nm
    form = sympy.Mul(page.m_A, sympy.Add(nm.A1n, -nm.A2n, evaluate=False), evaluate=False)
    sides = [Side((r.symbol,)), Side((form,))]
    vals = {nm.A1n: page.num(page.imp.pre.get(nm.A1n, nm.A1n)), nm.A2n: page.value_of(nm.A2n)}
    m = page.num(page.m_A.xreplace(page.ind))
    if not ((m.free_symbols | vals[nm.A1n].free_symbols | vals[nm.A2n].free_symbols) - page.varied):
        shown = sympy.Mul(
            as_float(m), sympy.Add(as_float(vals[nm.A1n]), -as_float(vals[nm.A2n]), evaluate=False), evaluate=False
        )
        sides.append(Side((show(shown),), "numeric"))
    sides.append(Side((r.found,), "result"))
    return Eqn(tuple(sides), unit=r.unit, boxed=boxed)
