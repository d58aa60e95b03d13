"""Units as students type them after a number, recognised so that they can be taken off.

A speed ``m/s``, ``m s⁻¹``, ``ms^-1``, ``m s^(-1)``, ``ms-1``, ``m·s⁻¹``, ``km/h``, ``km h⁻¹``,
``ft/s``; an acceleration ``m/s²``, ``m s^-2``; a momentum or impulse ``kg m/s``, ``g m/s`` (masses in grams), ``kg m s⁻¹``,
``N s``, ``Ns``, ``N·s``, ``N-s``, ``lb·s``, ``lbf s``, ``lb ft/s``, ``slug ft/s``; a speed squared ``m^2/s^2``; a stiffness ``N/m``; an angular
frequency (its square) ``s⁻¹``, ``s^-2``, ``rad/s``, ``Hz``. Only these shapes: ``2 g h`` (two times g times h) is not a unit.
A unit of one atom (``J``, ``kg``, `` m``) is taken off a side's last number only where it cannot be a
factor (:data:`UNIT_END`, :func:`without_unit`: ``2 m`` metres, ``0.002 + 0.150 m`` a mass in a sum);
:func:`glued_units` takes a letter glued to the number a line of arithmetic ends in (``= 1.02m``).

>>> [bool(UNIT.fullmatch(u)) for u in ("m s⁻¹", "ms-1", "kg m/s", "N s", "g h", "m u")]
[True, True, True, True, False, False]
"""

from __future__ import annotations

import re
from decimal import Decimal

_LENGTH = r"(?:km|cm|mm|ft|mi|m)"
_TIME = r"(?:secs?|s|hr|h|min)"
_JOIN = r"(?:\s*[·*.⋅]\s*|\s+|)"
#: A power -1 or -2 of a time: ``s^-1``, ``s^{-1}``, ``s^(-1)``, ``s⁻¹``, ``s-1``.
_INVERSE = r"(?:\s*\^\s*(?:\{\s*[-−]\s*[12]\s*\}|\(\s*[-−]\s*[12]\s*\)|[-−]\s*[12])|⁻[¹²]|\s*[-−–][12](?!\d))"
#: A time's power -1 or -2 written as a power (``s^-2``, ``s^{-1}``, ``s⁻²``), never ``s-1`` (s minus 1).
_RATE = r"(?:\s*\^\s*(?:\{\s*[-−]\s*[12]\s*\}|\(\s*[-−]\s*[12]\s*\)|[-−]\s*[12])|⁻[¹²])"
#: ``/s``, ``/s²``, ``/s^2``, or a time to the power -1 (-2).
_PER_TIME = rf"(?:\s*/\s*{_TIME}(?:\s*\^\s*\{{?2\}}?|²)?|{_JOIN}{_TIME}{_INVERSE})"
#: A speed (an acceleration), a momentum, an impulse.
UNIT = re.compile(
    rf"(?:(?:kg|g|lb|slug){_JOIN})?{_LENGTH}{_PER_TIME}|(?:N|lbf?)(?:{_JOIN}|\s*-\s*)s|mph"
    r"|(?:m|ft)(?:\s*\^\s*2|²)\s*/\s*s(?:\s*\^\s*2|²)"  # a speed squared, m^2/s^2 (2gh worked in its units)
    r"|N\s*/\s*m(?![A-Za-z])"  # a spring's stiffness, N/m
    rf"|(?:rad{_JOIN})?s{_RATE}|rad\s*/\s*s(?:\s*\^\s*\{{?2\}}?|²)?|Hz"  # ω (ω²) of a stage: s⁻¹, s^-2, rad/s, Hz
)
#: One atom: a unit of its own where the caller says so (``J``, ``kg``, ``kJ``, ``g``).
ATOM = re.compile(r"kg|Mg|g|kJ|J|N|m|s|km|cm|ft|lb|slug|deg|rad|W")
#: LaTeX spacing and product signs inside a unit (``m\,s^{-1}``, ``\mathrm{kg}\cdot\mathrm{m}``).
_TEX = re.compile(r"\\[,;:! ]|\\cdot|~|\\mathrm|\\text|[{}]")


def plain_unit(text: str) -> str:
    """A unit typed in LaTeX as plain text: ``m\\,s^{-1}`` -> ``m s^-1``, ``\\mathrm{Mg}`` -> ``Mg``."""
    return re.sub(r"\s*\^\s*", "^", " ".join(_TEX.sub(" ", text).split()))


def is_unit(text: str) -> bool:
    """Whether ``text`` is all unit (``m\\,s^{-1}``, ``m s⁻¹``, ``kg``), LaTeX spacing aside."""
    plain = plain_unit(text)
    return bool(UNIT.fullmatch(plain) or ATOM.fullmatch(plain))


#: Units that are a multiple of the SI unit of their kind, by that multiple (as a factor to write).
SCALED = {"g": "/1000", "Mg": "*1000", "t": "*1000", "kJ": "*1000", "km": "*1000", "cm": "/100", "mm": "/1000"}
_SCALED = re.compile(
    r"^\s*([-+−]?(?:\d+\.?\d*|\.\d+))\s*(?:(g|Mg|t|kJ|km|cm|mm)|(km\s*/\s*h|km\s*h\s*\^?\s*\(?-1\)?|km\s*h⁻¹|kph))\s*$"
)


def in_si(side: str) -> str | None:
    """A side that is a number and a multiple of an SI unit (``22 g``, ``20 Mg``, ``45 km/h``) as
    that number in the SI unit (``0.022``, ``20*1000``, ``45*5/18``), a fraction of it as a decimal
    with the figures written (``225 mm``: ``0.225``); None for any other side."""
    m = _SCALED.match(side)
    if m is None:
        return None
    factor = SCALED[m.group(2)] if m.group(2) else "*5/18"
    if factor.startswith("/"):  # 225 mm: 0.225, its figures kept (a rounded 225 is a rounded 0.225)
        shifted = Decimal(m.group(1).replace("−", "-")).scaleb(-len(factor) + 2)
        return format(shifted, "f")
    return m.group(1) + factor


#: A lone ``m`` or ``g`` after the number of a term added to others (``0.00020 + 0.150 m``,
#: ``0.008 = 0.002 + 0.150\,m``): a mass (or g) times the number, as a momentum's term; a unit
#: would be after the whole sum or after every term of it (``1.41 m``, ``2 m + 3 m``).
_LETTER_IN_SUM = re.compile(r"(?<=[\w)}\]])\s*[-+−]\s*\d[\d.]*\s+[mg]\.?\s*$")


def letter_in_sum(side: str) -> bool:
    """Whether ``side`` ends in a term of a sum whose lone ``m`` or ``g`` is a name, not a unit
    (no other term of the sum has a unit)."""
    m = _LETTER_IN_SUM.search(side)
    return m is not None and not re.search(r"\d\s*[mg]\s*[-+−]", side)


#: A side of numbers only: digits, signs, brackets, powers and the functions of a calculator.
_NUMBERS_ONLY = re.compile(r"(?:[\d.\s+\-−*/×·^()\[\]²³√]|sqrt|sin|cos|tan|ln|log|exp|pi|π)+")
#: A number's last letter glued to it at the end of a side: ``1.02m``, ``6.3s``, ``19.6N``.
_GLUED = re.compile(r"(?<=\d)(?<!\^\d)([mNs])\.?$")


def glued_units(sides: tuple[str, ...]) -> tuple[str, ...]:
    """``sides`` without a unit's letter glued to the last side's number where a side before it
    (not the first) is numbers only: ``h = 19.98/19.6 = 1.02m`` is 1.02 metres, for a number worked
    out is no number times a mass (``p = 1.2m`` alone stays 1.2 times m: the letter may be a name)."""
    if len(sides) < 3 or not any(_NUMBERS_ONLY.fullmatch(s.strip()) for s in sides[1:-1]):
        return sides
    return (*sides[:-1], _GLUED.sub("", sides[-1].strip()))


#: A unit after the number a side ends in: ``1.41 m``, ``3 m/s``, ``2 N s``, ``4 J ✓``.
UNIT_END = re.compile(
    rf"(?:(?<=[\d.)\s°])(?<![-+−*/×=]\s)\s*(?:{UNIT.pattern}|mi/h|N[·*\s.\-]?s|Ns|lbf?\s?[·*.\-]?\s?s(?:ec)?|kg|kJ|J|ft[·*\s.\-]?lbf?|slugs?|ft|lbf?)"
    r"|(?<=[\d.)°])\s+(?:m|s|N|g))"  # 1.41 m, not 1.2m (1.2 times m), nor mu g (mu times g)
    r"\.?(?:\s*(?:✓|✔|\\checkmark))?\s*$"
)

#: A momentum's unit after a number: ``60 kg m/s``, ``12 kg m s^-1``, ``3 kg·m/s``.
_MOMENTUM_UNIT = re.compile(
    r"(?<=[\d.)\s])\s*kg\s*[·*×⋅-]?\s*(?:m\s*/\s*s|m\s*s\s*\^\s*\(?\s*-\s*1\s*\)?|ms\^?-1)\.?\s*$"
)


def without_unit(side: str) -> str:
    """``side`` with the unit after its number taken off, a momentum's too (``60 kg m/s``)."""
    return side if letter_in_sum(side) else UNIT_END.sub("", _MOMENTUM_UNIT.sub("", side))  # 0.002 + 0.150 m: m a mass
