"""The asked result of each variant and its tolerance: the significant-figure rule of
``derive check`` (1.5 units in the last significant digit shown; ±0.005 for an exact zero)."""

from __future__ import annotations

from dataclasses import dataclass
from decimal import Decimal

from derive.errors import InputError
from derive.homework.variants import Compiled, Variant, answers
from derive.numbers import figures_for, float_decimal

#: The tolerance in units of the last digit shown: ½ (rounding) + 1 (the checker's allowance).
TOLERANCE_UNITS = Decimal("1.5")
#: The tolerance of an answer shown as an exact zero (it rounds to 0.00).
ZERO_TOLERANCE = Decimal("0.005")
#: PrairieLearn compares |x - c| <= atol in doubles, where 8.385 - 8.40 is 0.0150000000000006: its
#: atol is the tolerance widened by this fraction of the larger of |c| and the tolerance, so that the
#: ends of the range are right (Moodle widens its ranges the same way, by 1e-14).
EDGE = Decimal("1e-12")


@dataclass(frozen=True)
class Answer:
    """A variant's answer to the asked result: shown text, value, unit and tolerance."""

    name: str
    shown: str
    value: Decimal
    unit: str
    tolerance: Decimal
    figures: int  # the significant figures ``shown`` was rounded to


def significant_figures(shown: str) -> int:
    """The significant figures of a number as written, when nothing else is known: every
    digit from the first non-zero one, except the trailing zeros of a whole number."""
    d = Decimal(shown)
    if d == 0:
        return 1
    digits = "".join(map(str, d.as_tuple().digits)).lstrip("0")
    exp = d.as_tuple().exponent
    assert isinstance(exp, int)
    return len(digits.rstrip("0")) if exp >= 0 else len(digits)


def tolerance(shown: str, figures: int | None = None) -> Decimal:
    """The tolerance of an answer shown as ``shown``, rounded to ``figures`` significant
    figures: 1.5 units in its last significant digit (``figures`` None: counted by
    :func:`significant_figures`)."""
    d = Decimal(shown)
    if d == 0:
        return ZERO_TOLERANCE
    figs = significant_figures(shown) if figures is None else figures
    return TOLERANCE_UNITS.scaleb(d.adjusted() - figs + 1)


def figures_of(value: float, digits: int | None) -> int:
    """The figures ``format_number(value, digits)`` rounds to (as the key shows numbers)."""
    return figures_for(float_decimal(value), digits)


def asked_answer(name: str, row: dict, digits: int | None) -> Answer:
    """The :class:`Answer` of an answer-key row (``shown``, ``value``, ``unit``)."""
    shown = row["shown"]
    figs = figures_of(row["value"], digits)
    return Answer(name, shown, Decimal(shown), row["unit"], tolerance(shown, figs), figs)


def default_result(compiled: Compiled, variants: list[Variant], digits: int | None = None) -> str:
    """The first of the problem's ``find`` results with a number in every variant (else the first result)."""
    common = _numeric_results(compiled, variants, digits)
    for name in compiled.problem.find:
        if name in common:
            return name
    if not common:
        raise InputError("no result has a number in the variants (a symbolic given remains)", field="--result")
    return common[0]


def _numeric_results(compiled: Compiled, variants: list[Variant], digits: int | None) -> list[str]:
    """The results shown as a number in every variant (not a chain's yes or no)."""
    names: list[str] | None = None
    for v in variants:
        have = [n for n, row in answers(compiled, v, digits).items() if _is_number(row["shown"])]
        names = have if names is None else [n for n in names if n in have]
    return names or []


def _is_number(text: str) -> bool:
    try:
        Decimal(text)
    except ArithmeticError:
        return False
    return True


def resolve_result(compiled: Compiled, variants: list[Variant], result: str | None, digits: int | None = None) -> str:
    """``result`` checked (a result with a number in every variant), or the default."""
    if result is None:
        return default_result(compiled, variants, digits)
    have = _numeric_results(compiled, variants, digits)
    if result not in have:
        raise InputError(
            f"no such result with a number in every variant (expected one of: {', '.join(have)})",
            field=f"--result {result}",
        )
    return result
