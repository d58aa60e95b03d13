"""The fast paths (issue 19) against the plain definitions they replace: Liang-Barsky
clipping against the separating axis test, rounding against a Decimal context made per
number, and a variant's pages (solved variants are cached) against writing them afresh
in another order. Random cases come from fixed seeds."""

from __future__ import annotations

import random
import re
from decimal import ROUND_FLOOR, ROUND_HALF_UP, Decimal, localcontext
from fractions import Fraction

import pytest

import derive
from derive.homework import variants
from derive.numbers import format_fixed, format_number, places_that_add_up
from derive.writers.figure.layout import _box_hits_segment


def _separated(box: tuple[float, ...], seg: tuple[tuple[float, float], ...]) -> bool:
    """True when an axis separates the closed box from the segment (exact, in fractions)."""
    x0, y0, x1, y1 = (Fraction(v) for v in box)
    (ax, ay), (bx, by) = ((Fraction(p[0]), Fraction(p[1])) for p in seg)
    if max(ax, bx) < x0 or min(ax, bx) > x1 or max(ay, by) < y0 or min(ay, by) > y1:
        return True
    sides = {(bx - ax) * (cy - ay) - (by - ay) * (cx - ax) for cx in (x0, x1) for cy in (y0, y1)}
    return all(s > 0 for s in sides) or all(s < 0 for s in sides)


def test_clipping_agrees_with_the_separating_axis_test() -> None:
    rng = random.Random(21)
    for _ in range(5_000):
        xs, ys = sorted(rng.uniform(-2, 2) for _ in range(2)), sorted(rng.uniform(-2, 2) for _ in range(2))
        box = (xs[0], ys[0], xs[1], ys[1])
        seg = ((rng.uniform(-3, 3), rng.uniform(-3, 3)), (rng.uniform(-3, 3), rng.uniform(-3, 3)))
        assert _box_hits_segment(box, seg) == (not _separated(box, seg)), (box, seg)
    # a segment along an edge, a point inside, a segment that stops short of the box
    assert _box_hits_segment((0.0, 0.0, 1.0, 1.0), ((0.0, -1.0), (0.0, 2.0)))
    assert _box_hits_segment((0.0, 0.0, 1.0, 1.0), ((0.5, 0.5), (0.5, 0.5)))
    assert not _box_hits_segment((0.0, 0.0, 1.0, 1.0), ((-2.0, 0.5), (-0.1, 0.5)))


def _format_per_context(d: Decimal, digits: int | None, extra: int) -> str:
    """The textbook rule written plainly: a context per number, the first digit by scaling."""
    if d == 0:
        return "0"
    if digits is None:
        first = abs(d).scaleb(-abs(d).adjusted()).to_integral_value(rounding=ROUND_FLOOR)
        digits = 4 if first == 1 else 3
    with localcontext() as ctx:
        ctx.prec = 50
        exp = d.adjusted() - (digits + extra) + 1
        r = d.quantize(Decimal(1).scaleb(exp), rounding=ROUND_HALF_UP)
        if r.adjusted() != d.adjusted():
            r = r.quantize(Decimal(1).scaleb(exp + 1), rounding=ROUND_HALF_UP)
    if -4 <= r.adjusted() < 6:
        return format(r, "f")
    return f"{format(r.scaleb(-r.adjusted()), 'f')}e{r.adjusted():+d}"


def _random_decimal(rng: random.Random) -> Decimal:
    kind = rng.random()
    if kind < 0.4:  # as a variant's floats come: twelve figures
        return Decimal(f"{rng.uniform(-1e3, 1e3) * 10 ** rng.randint(-6, 6):.12g}")
    if kind < 0.7:  # next to a carry: 9.995, 1.9996
        nines = "9" * rng.randint(1, 30)
        return Decimal(f"{rng.choice('-+')}{rng.choice('19')}.{nines}{rng.choice('456')}E{rng.randint(-8, 8)}")
    digits = "".join(rng.choice("0123456789") for _ in range(rng.randint(1, 40)))  # exact values: 40 digits
    return Decimal(f"{rng.choice('-+')}{rng.choice('123456789')}{digits}E{rng.randint(-30, 30)}")


def test_rounding_agrees_with_a_context_per_number() -> None:
    rng = random.Random(22)
    for _ in range(5_000):
        d = _random_decimal(rng)
        for digits in (None, 2, 3, 4):
            for extra in (0, 1):
                assert format_number(d, digits, extra=extra) == _format_per_context(d, digits, extra), (d, digits)
        with localcontext() as ctx:
            ctx.prec = 200  # every digit of these numbers
            places = rng.randint(0, 6)
            want = d.quantize(Decimal(1).scaleb(-places), rounding=ROUND_HALF_UP)
        text = format_fixed(d, places)
        assert Decimal(text) == want and not re.fullmatch(r"-0(\.0*)?", text), (d, places)


def _places_plainly(sums: list, digits: int | None, extra: int, more: int) -> int | None:
    """places_that_add_up written with the text of each number (as before issue 19)."""

    def shown(x: Decimal, k: int) -> int:
        text = format_number(x, digits, extra=k)
        return len(text.split(".")[1]) if "." in text else 0

    numbers = [x for terms, total in sums for x in (*terms, total)]
    if any(x != 0 and not -4 <= x.adjusted() < 6 for x in numbers):
        return None
    biggest = max((abs(x) for x in numbers), default=Decimal(0))
    text = format_number(biggest, digits, extra=extra) if biggest else ""
    start = (len(text.split(".")[1]) if "." in text else 0) if text and "e" not in text else 2
    nonzero = [x for x in numbers if x != 0]
    most = min((shown(x, extra) for x in nonzero), default=start)
    start = max(start, max((shown(x, 0) for x in nonzero), default=start))
    for places in range(start, min(start + more, most) + 1):
        if all(
            sum(Decimal(format_fixed(t, places)) for t in terms) == Decimal(format_fixed(total, places))
            for terms, total in sums
        ):
            return places
    return None


def test_places_that_add_up_agree_with_the_written_numbers() -> None:
    rng = random.Random(23)
    found = 0
    for _ in range(3000):
        terms = [Decimal(f"{rng.uniform(-300, 300) * 10 ** rng.randint(-3, 2):.12g}") for _ in range(rng.randint(1, 3))]
        sums = [(terms, Decimal(f"{float(sum(terms)):.12g}"))]
        for digits in (None, 3, 4):
            got = places_that_add_up(sums, digits, 1)
            assert got == _places_plainly(sums, digits, 1, 1), sums
            found += got is not None
    assert found > 1000
    # 79.23 - 59.42 = 19.81 at two places (the docstring's example, added by hand)
    assert places_that_add_up([([Decimal("79.2345"), Decimal("-59.4234")], Decimal("19.8111"))], None, 1) == 2


@pytest.fixture(scope="module")
def compiled() -> variants.Compiled:
    return variants.compile_problem(derive.load("notes-4c11-two-spheres"))


def test_a_pages_texts_are_the_same_filled_again_in_any_order(compiled: variants.Compiled) -> None:
    chosen = variants.draw(compiled, 6, seed=5)
    pages = [variants.fill(compiled, v) for v in chosen]
    assert [variants.fill(compiled, v) for v in reversed(chosen)] == pages[::-1]
    assert len(set(pages)) == len(pages)
