"""Equations (1)-(4) of the notes, solved here again, apart from derive's solver.

With n the line of impact (from A's centre toward B's) and t the plane of contact::

    (1) m_A v_A1t = m_A v_A2t
    (2) m_B v_B1t = m_B v_B2t
    (3) m_A v_A1n + m_B v_B1n = m_A v_A2n + m_B v_B2n
    (4) e (v_A1n - v_B1n) = v_B2n - v_A2n

so that, for two free bodies, v_A2n = (m_A a + m_B b - m_B e (a - b)) / (m_A + m_B)
and v_B2n = (m_A a + m_B b + m_A e (a - b)) / (m_A + m_B), with a = v_A1n and
b = v_B1n; against a fixed B (a wall at rest) v_A2n = -e a. The t components
do not change. Nothing here knows about derive.
"""

from __future__ import annotations

from dataclasses import dataclass

import sympy

HALF = sympy.Rational(1, 2)


@dataclass(frozen=True)
class Before:
    """The data of one impact: masses, e, and the components before it."""

    m_A: sympy.Expr
    m_B: sympy.Expr
    e: sympy.Expr
    a_n: sympy.Expr
    a_t: sympy.Expr
    b_n: sympy.Expr
    b_t: sympy.Expr
    fixed: bool = False


def after(d: Before) -> dict[str, sympy.Expr]:
    """The components after the impact, from (1)-(4) in closed form."""
    if d.fixed:
        return {"A2n": -d.e * d.a_n, "A2t": d.a_t, "B2n": sympy.Integer(0), "B2t": sympy.Integer(0)}
    total = d.m_A + d.m_B
    momentum = d.m_A * d.a_n + d.m_B * d.b_n
    approach = d.a_n - d.b_n
    return {
        "A2n": (momentum - d.m_B * d.e * approach) / total,
        "B2n": (momentum + d.m_A * d.e * approach) / total,
        "A2t": d.a_t,
        "B2t": d.b_t,
    }


def residuals(d: Before, post: dict[str, sympy.Expr]) -> dict[int, sympy.Expr]:
    """Left minus right of each of (1)-(4) that applies: all zero for a true solution."""
    out = {1: d.m_A * (d.a_t - post["A2t"]), 4: d.e * (d.a_n - d.b_n) - (post["B2n"] - post["A2n"])}
    if not d.fixed:
        out[2] = d.m_B * (d.b_t - post["B2t"])
        out[3] = d.m_A * d.a_n + d.m_B * d.b_n - d.m_A * post["A2n"] - d.m_B * post["B2n"]
    return out


def derived(d: Before, post: dict[str, sympy.Expr], phi: sympy.Expr | None) -> dict[str, sympy.Expr]:
    """Speeds, directions (theta from +t toward +n, beta from +n toward +t), kinetic
    energies (the loss 1/2 mu (1 - e^2)(v_A1n - v_B1n)^2, mu = m_A m_B / (m_A + m_B), or
    m_A against a fixed B), the impulse on B along +n, and x-y components when n is at
    ``phi`` from x."""
    out: dict[str, sympy.Expr] = {}
    for body in "AB":
        if body == "B" and d.fixed:
            continue
        n, t = post[body + "2n"], post[body + "2t"]
        out[f"v_{body}2"] = sympy.sqrt(n**2 + t**2)
        if not (n == 0 and t == 0):
            out[f"theta_{body}2"] = sympy.atan2(n, t)
            out[f"beta_{body}2"] = sympy.atan2(t, n)
            # the acute angles with the line of centres (alpha) and the plane of contact (gamma)
            out[f"alpha_{body}2"] = sympy.atan2(sympy.Abs(t), sympy.Abs(n))
            out[f"gamma_{body}2"] = sympy.atan2(sympy.Abs(n), sympy.Abs(t))
            n1, t1 = (d.a_n, d.a_t) if body == "A" else (d.b_n, d.b_t)
            if not (n1 == 0 and t1 == 0):  # the angle the velocity turns through
                out[f"delta_{body}"] = sympy.acos((n1 * n + t1 * t) / sympy.sqrt((n1**2 + t1**2) * (n**2 + t**2)))
    mb = 0 if d.fixed else d.m_B
    t1 = HALF * d.m_A * (d.a_n**2 + d.a_t**2) + HALF * mb * (d.b_n**2 + d.b_t**2)
    t2 = HALF * d.m_A * (post["A2n"] ** 2 + post["A2t"] ** 2) + HALF * mb * (post["B2n"] ** 2 + post["B2t"] ** 2)
    # T_1 - T_2 in closed form: exact zero for e = 1 however large the energies
    reduced = d.m_A if d.fixed else d.m_A * d.m_B / (d.m_A + d.m_B)
    lost = HALF * reduced * (1 - d.e**2) * (d.a_n - d.b_n) ** 2
    out.update(T_1=t1, T_2=t2, T_lost=lost, J_n=d.m_A * (d.a_n - post["A2n"]))
    if phi is not None:
        c, s = sympy.cos(phi), sympy.sin(phi)
        comps = {"1": (d.a_n, d.a_t, d.b_n, d.b_t), "2": (post["A2n"], post["A2t"], post["B2n"], post["B2t"])}
        for when, (an, at, bn, bt) in comps.items():
            out[f"v_A{when}x"], out[f"v_A{when}y"] = an * c - at * s, an * s + at * c
            if not d.fixed:
                out[f"v_B{when}x"], out[f"v_B{when}y"] = bn * c - bt * s, bn * s + bt * c
        for body in "AB" if not d.fixed else "A":  # the direction after the impact from +x
            x, y = out[f"v_{body}2x"], out[f"v_{body}2y"]
            if not (x == 0 and y == 0):
                out[f"psi_{body}2"] = sympy.atan2(y, x)
    return out
