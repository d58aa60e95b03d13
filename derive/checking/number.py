"""An answer written as a number (``8.40 m/s``, ``-1.11``, ``2.86°``): judged at the figures written.

Right at the figures written (±1 in the last digit), or within the rounding band
of a right method worked with 3-figure intermediates (:mod:`.rounding`), is
correct; a unit of the wrong kind is a unit mismatch; anything else is wrong, and
the common mistakes (one, else two together) that give it are named.
"""

from __future__ import annotations

from decimal import Decimal
from typing import TYPE_CHECKING

import sympy

from derive.checking.context import Context
from derive.checking.entries import Entry
from derive.checking.figures import figures, judge, method, slack
from derive.checking.report import Diagnosis, Item
from derive.checking.rounding import INTERMEDIATE_FIGURES, rounded_values
from derive.errors import InputError
from derive.mathtext.notation import student
from derive.numbers import format_number, to_decimal
from derive.physics.results import Result
from derive.problem import units
from derive.problem.units import ANGLE, DIMENSIONLESS

if TYPE_CHECKING:
    from derive.checking.mistakes import Outcome

#: A wrong answer this close (relative) to the exact value gets a word about rounding.
NEAR = Decimal("0.01")
#: Other units a value may have been worked out in, by dimension (for the "right value, wrong unit" hint).
ALTERNATIVES: dict[units.Dim, tuple[str, ...]] = {
    units.VELOCITY: ("m/s", "ft/s", "km/h", "mi/h"),
    units.ENERGY: ("J", "ft*lb", "kJ"),
    units.MASS: ("kg", "slug", "g"),
    units.IMPULSE: ("N*s", "lb*s"),
    ANGLE: ("deg", "rad"),
}


def number_item(ctx: Context, e: Entry, r: Result, text: str, number: str, unit: units.Unit | None) -> Item:
    """The verdict on ``number`` (with ``unit``, or None where none is written) for result ``r``."""
    work = ctx.work(r)
    if r.value is None:
        syms = ", ".join(sorted(s.name for s in ctx.num(r.closed).free_symbols)) or "a symbolic given"
        raise e.error(f"{r.name} depends on the symbolic given(s) {syms}: answer with an expression in them")
    u = Decimal(number)
    notes: list[str] = []
    missing = unit is None and work.dim not in (DIMENSIONLESS, ANGLE)
    if missing:
        notes.append(f"No unit given: read as {units.plain_unit(work.text)}.")
    unit_written = unit is not None
    unit = unit if unit is not None else work
    if unit.dim != work.dim:
        return _mismatch(ctx, r, text, u, unit)
    x = r.value * work.factor / unit.factor
    if work.dim == ANGLE:  # a direction: -180° and 180° are the same one
        x = same_turn(x, u, 2 * sympy.pi / unit.factor)
    fields = dict(
        value=float(u),
        unit=unit.text,
        unit_missing=missing,
        expected_value=float(x),
        relative_error=float((u - to_decimal(x)) / abs(to_decimal(x))) if x != 0 else None,
        method=method(u, ctx.tolerance),
        notes=tuple(notes),
    )
    expected = ctx.shown(x, figures(u), unit)
    if judge(u, x, ctx.tolerance) and sympy.Rational(str(u)) == x:  # 4 for 4: no figures' slack, nothing to add
        return Item("answer", r.name, text, "correct", "", "Correct: exactly this problem's value.", **fields)
    if judge(u, x, ctx.tolerance):
        return Item("answer", r.name, text, "correct", expected, f"Correct {fields['method']}.", **fields)
    scale = work.factor / unit.factor
    diags, together = _diagnosis(ctx, r, u, unit, scale, ctx.singles()), False
    if not diags:
        band = _rounding_band(ctx, r, u, scale)
        if band is not None:
            fields["method"] = f"within what {INTERMEDIATE_FIGURES}-figure intermediates give"
            return Item("answer", r.name, text, "correct", expected, _rounded_message(number, band, unit), **fields)
        diags, together = _diagnosis(ctx, r, u, unit, scale, ctx.pairs()), True
    hints = _hints(ctx, r, u, x, unit, number, unit_written)
    if not diags and ctx.tolerance is None and x != 0 and abs(u - to_decimal(x)) <= NEAR * abs(to_decimal(x)):
        hints.append(_near_message(ctx, r, scale, unit))
    if diags and together:
        msg = f"Wrong: {number} is what {'these two mistakes' if len(diags) == 2 else 'two of these mistakes'} give together."
    elif diags:
        one = len(diags) == 1
        msg = f"Wrong: {number} is what {'this mistake' if one else 'these mistakes'} give{'s' if one else ''}."
    else:
        msg = f"Wrong. No common mistake reproduces {number}."
    return Item("answer", r.name, text, "wrong", expected, " ".join([msg, *hints]), diagnosis=diags, **fields)


def same_turn(x: sympy.Expr, u: Decimal, turn: sympy.Expr) -> sympy.Expr:
    """The angle ``x`` give or take whole turns, the one nearest to the written ``u``."""
    k = sympy.floor((sympy.Rational(str(u)) - x) / turn + sympy.Rational(1, 2))
    return x + k * turn if k != 0 else x


def _mismatch(ctx: Context, r: Result, text: str, u: Decimal, unit: units.Unit) -> Item:
    work = ctx.work(r)
    what = units.describe(work.dim) if work.dim != DIMENSIONLESS else "a pure number"
    return Item(
        "answer",
        r.name,
        text,
        "unit mismatch",
        ctx.shown(r.value, figures(u), work),
        f"Unit mismatch: {unit.text} is {units.describe(unit.dim)}, but {r.name} is {what}"
        + (f" ({units.plain_unit(work.text)})." if work.text else "."),
        value=float(u),
        unit=unit.text,
        expected_value=float(r.value),
    )


def _diagnosis(
    ctx: Context, r: Result, u: Decimal, unit: units.Unit, scale: sympy.Expr, found: list[Outcome]
) -> tuple[Diagnosis, ...]:
    """The mistakes of ``found`` that give ``u`` at the figures written."""

    def fits(out: Outcome) -> str | None:
        q = out.results.get(r.name)
        if q is None or q.value is None:
            return None
        key = ("value", q.value, scale)  # evaluated once: every wrong answer of r is compared with it
        if key not in ctx.memo:
            ctx.memo[key] = sympy.Float((q.value * scale).evalf(40), 40)
        mx = ctx.memo[key]
        return ctx.shown(mx, figures(u), unit) if judge(u, mx, ctx.tolerance) else None

    return ctx.diagnose(fits, found)


def _rounding_band(ctx: Context, r: Result, u: Decimal, scale: sympy.Expr) -> tuple[str, str] | None:
    """(lowest, highest) that 3-figure intermediates give, as shown, where ``u`` lies
    within them (±1 in its last digit); None where it does not, or a tolerance is set."""
    if ctx.tolerance is not None or r.value == 0:  # an exact zero is written as zero
        return None
    values = [to_decimal(v * scale) for v in rounded_values(ctx, r.name)]
    if not values:
        return None
    exact = to_decimal(r.value * scale)
    lo, hi = min([*values, exact]), max([*values, exact])
    if not lo - slack(u, exact) <= u <= hi + slack(u, exact):
        return None
    return format_number(lo, 4), format_number(hi, 4)


def _rounded_message(number: str, band: tuple[str, str], unit: units.Unit) -> str:
    lo, hi = band
    span = f"{lo} to {hi}" if lo != hi else lo
    return (
        f"Correct, with rounded intermediates: {number} is off at the figures written, but it is what the right "
        f"method gives with intermediates rounded to {INTERMEDIATE_FIGURES} significant figures ({span}"
        f"{' ' + units.plain_unit(unit.text) if unit.text and units.plain_unit(unit.text) != '°' else ''}). "
        "Carry a figure more through the working to land on the exact value."
    )


def _near_message(ctx: Context, r: Result, scale: sympy.Expr, unit: units.Unit) -> str:
    """A wrong answer within :data:`NEAR` of the exact value: perhaps rounding."""
    values = [to_decimal(v * scale) for v in rounded_values(ctx, r.name)]
    band = ""
    if values:
        exact = to_decimal(r.value * scale)
        lo, hi = min([*values, exact]), max([*values, exact])
        band = f" ({INTERMEDIATE_FIGURES}-figure intermediates give {format_number(lo, 4)} to {format_number(hi, 4)})"
    return (
        f"It is within {NEAR * 100:.0f} % of the exact value: if it was worked from rounded intermediates, "
        f"carry more figures{band}."
    )


def _hints(
    ctx: Context, r: Result, u: Decimal, x: sympy.Expr, unit: units.Unit, number: str, unit_written: bool
) -> list[str]:
    """Near misses: the right size with the wrong sign, the right value in another unit."""
    work = ctx.work(r)
    hints = []
    if x != 0 and judge(u, -x, ctx.tolerance):
        hints.append("It has the right size but the wrong sign: check the positive senses of n and t.")
    for alt in ALTERNATIVES.get(work.dim, ()):
        alt_unit = units.parse_unit(alt)
        if alt_unit.text == unit.text or alt_unit.factor == unit.factor:
            continue
        if judge(u, r.value * work.factor / alt_unit.factor, ctx.tolerance):
            fix = "the unit is wrong" if unit_written else "give its unit"
            hints.append(f"{number} is the right value in {units.plain_unit(alt_unit.text)}: {fix}.")
    return hints


def line_answer(ctx: Context, sides: tuple[str, ...], exprs: tuple | None, written: str) -> Item | None:
    """A derivation's line ``v_A2n = -1.11`` (a result's name = a number) judged as an answer is
    (figures written, rounding of intermediates, the mistakes that give it); None where the
    line is not one, or is right only as a number of one figure that is not the value rounded."""
    from derive.checking.worlds import NUMBER_SIDE, written_right  # a derivation's, not an answer's (start-up)

    left = exprs[0] if exprs else None
    if len(sides) != 2 or not isinstance(left, sympy.Symbol) or left.name not in ctx.results:
        return None
    m = NUMBER_SIDE.match(student(sides[1]))
    if not m:
        return None
    sign, number, unit = m.groups()
    number = ("-" if sign == "-" else "") + number
    r = ctx.results[left.name]
    try:
        u = units.parse_unit(unit) if unit else None
        item = number_item(ctx, Entry(r.name, number), r, written, number, u)
    except InputError:
        return None
    x = item.expected_value
    if item.correct and x is not None and not written_right(Decimal(number), sympy.Float(x, 15)):
        return None  # one figure, not the value rounded: judged as a relation
    return item
