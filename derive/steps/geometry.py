"""Stage 1 of the notes' layout: the n-t axes, and each velocity before the impact
resolved along them (from a speed and a direction, from components, or from x-y axes)."""

from __future__ import annotations

import sympy

from derive.problem import Motion
from derive.steps.model import Block, Eqn, Math, Side, Text
from derive.steps.page import Page
from derive.symbols import symbol


def geometry(page: Page) -> list[Block]:
    """The n-t axes, then each body's velocity before the impact along them."""
    p = page.p
    blocks = [_axes(page)]
    if p.fixed_B:
        blocks.append(
            Block((f"{page.b} is the fixed {page.surface}: infinite mass, at rest before and after the impact.",))
        )
    if not p.oblique:
        lines = []
        for s_ in (page.nm.A1n,) + (() if p.fixed_B else (page.nm.B1n,)):
            if s_ in page.numeric or s_ in page.varied:
                lines.append(Eqn((Side((s_,)), Side((s_,), "result")), unit=page.unit_v))
        text = "The impact is direct: every velocity lies along n and is signed along +n."
        return [*blocks, Block((text,), tuple(lines))]
    for motion, comps in ((p.motion_A, (page.nm.A1n, page.nm.A1t)), (p.motion_B, (page.nm.B1n, page.nm.B1t))):
        if not (motion.body == "B" and p.fixed_B):
            blocks.append(_resolved(page, motion, comps))
    return blocks


def _axes(page: Page) -> Block:
    """Where n and t point (n from A's centre toward B's, or toward the fixed surface)."""
    p = page.p
    turned = " (n turned 90° counter-clockwise)." if p.oblique else "."
    if p.fixed_B:
        where = f" along the line of impact, normal to the {page.surface}, positive from {page.a} toward the {page.surface}, and "
        tail = " along the " + page.surface + turned
    else:
        where = f" along the line of impact, positive from the centre of {page.a} toward the centre of {page.b}, and "
        tail = " in the plane of contact" + turned
    return Block(("Take ", Math(symbol("n")), where, Math(symbol("t")), tail))


def _resolved(page: Page, motion: Motion, comps: tuple[sympy.Symbol, sympy.Symbol]) -> Block:
    """One body's velocity before the impact, resolved along n and t."""
    b, (cn, ct) = motion.body, comps
    if motion.speed is not None and motion.angle is None:
        return Block(
            (f"{page.label(b)} is at rest before the impact: ", Math(sympy.Eq(cn, 0)), ", ", Math(sympy.Eq(ct, 0)), ".")
        )
    if motion.angle is not None:
        text: Text = (
            f"{page.label(b)} moves at ",
            Math(motion.speed),
            ", at ",
            Math(motion.angle),
            f" from {motion.axis_from} toward {motion.toward}:",
        )
    else:
        text = (f"The velocity of {page.label(b)} before the impact is given by its components:",)
    if motion.x is not None:
        return Block(text, tuple(_xy_lines(page, motion, cn, ct)))
    lines = []
    defined = {g.symbol: g.definition for g in page.p.givens if g.definition is not None}
    open_ = {g.symbol for g in page.p.givens if g.value is None} & page.varied  # a variant's numbers, not yet in
    for c in (cn, ct):
        expr = page.imp.pre[c]
        if expr == c and c in defined and defined[c].free_symbols & open_:  # a variant's v_B1n = -u_B cos(alpha)
            expr = defined[c]  # (its number is open, so the line shows where it comes from)
        sides = [Side((c,))]
        if expr != c:
            sides.append(Side((expr,)))
            if page.has_values(expr) and not expr.is_Symbol:
                sides.append(Side((expr,), "values"))
        if not (expr.free_symbols & set(page.unknowns)):
            sides.append(Side((expr,), "result"))
        lines.append(Eqn(tuple(sides), unit=page.unit_v))
    return Block(text, tuple(lines))


def _xy_lines(page: Page, motion: Motion, cn: sympy.Symbol, ct: sympy.Symbol) -> list[Eqn]:
    """A velocity given in x-y axes: its x and y components, then n and t through phi."""
    b, phi = motion.body, page.p.phi
    vx, vy = symbol(f"v_{b}1x"), symbol(f"v_{b}1y")
    lines = []
    for s_, expr in ((vx, motion.x), (vy, motion.y)):
        if expr == s_:
            continue
        sides = [Side((s_,)), Side((expr,))]
        if page.has_values(expr):
            sides.append(Side((expr,), "values"))
        sides.append(Side((sympy.expand(page.num(expr)),), "result"))  # 0, not 0 v_A1
        lines.append(Eqn(tuple(sides), unit=page.unit_v))
    n_form = (vx * sympy.cos(phi), vy * sympy.sin(phi))
    t_form = (-vx * sympy.sin(phi), vy * sympy.cos(phi))
    for c, form, expr in ((cn, n_form, motion.n), (ct, t_form, motion.t)):
        value = sympy.expand(page.num(expr))  # cos 0° = 1 and 0 · v_A1 = 0 done, not shown
        lines.append(Eqn((Side((c,)), Side(form), Side(form, "values"), Side((value,), "result")), unit=page.unit_v))
    return lines
