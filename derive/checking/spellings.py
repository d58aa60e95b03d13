"""Names as students spell them, in derive's spelling: subscripts typed as characters (``v₁``),
the notes' spellings (``V_At2``), Greek letters typed as themselves (``λ`` for the problem's
``lam``). :func:`.naming.rewrite` puts a side through them before reading it.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

import sympy

if TYPE_CHECKING:
    from derive.checking.context import Context

#: Greek letters typed as themselves, by their names.
_UNICODE_GREEK = {
    "α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "ε": "epsilon", "θ": "theta", "λ": "lambda",
    "μ": "mu", "σ": "sigma", "τ": "tau", "φ": "phi", "ϕ": "phi", "ψ": "psi", "ω": "omega",
}  # fmt: skip


def greek_letters(text: str, known: set[str]) -> str:
    """Greek letters as the problem names them: ``λ`` and ``lambda`` are the problem's ``lam``
    (a name the Greek name starts with), and a letter typed beside a name is a product
    (``kλu`` -> ``k lam u``)."""

    def alias(name: str) -> str:
        if name in known:
            return name
        short = [k for k in known if len(k) >= 3 and k.isalpha() and name.startswith(k) and k != name]
        return short[0] if len(short) == 1 else name

    def letter(m: re.Match) -> str:
        name = alias(_UNICODE_GREEK[m.group(1)])
        return (m.group(1) if name == _UNICODE_GREEK[m.group(1)] else f" {name}") + (" " if m.group(2) else "")

    text = re.sub(rf"([{''.join(_UNICODE_GREEK)}])(?=([A-Za-z(])?)", letter, text)
    text = re.sub(r"(?<![A-Za-z\\])(" + "|".join(sorted(set(_UNICODE_GREEK.values()))) + r")(?![A-Za-z])",
                  lambda m: alias(m.group(1)), text)  # fmt: skip
    return angle_initials(text, known)


#: A Latin letter as a trigonometric function's argument (``u cos a``, ``sin(b)``, ``cos^2 a``).
_TRIG_LETTER = re.compile(r"(?<![A-Za-z])(a?(?:sin|cos|tan)(?:\^\s*\(?\d\)?)?\s*(?:\(\s*)?)([a-z])(?![\w(])")
#: The problem's angles by their Greek names (``alpha``, ``theta_1``).
_GREEK_ANGLE = re.compile(r"(?:alpha|beta|gamma|delta|theta|phi|psi)(?:_\w+)?")


def angle_initials(text: str, known: set[str]) -> str:
    """``u cos a`` -> ``u cos alpha`` where the problem has one angle whose Greek name starts
    with the letter (a for alpha, b for beta, t for theta, p for phi): typed without Greek, a
    student writes the angle's initial, and a sine's or cosine's argument is an angle. A letter
    the problem or the student already uses (``a`` for a velocity) stays itself."""

    def letter(m: re.Match) -> str:
        if m.group(2) in known:
            return m.group(0)
        angles = [k for k in known if _GREEK_ANGLE.fullmatch(k) and k.startswith(m.group(2))]
        if len(angles) > 1:  # a given angle (alpha) before a result's (alpha_A2, the angle after)
            angles = [k for k in angles if "_" not in k]
        return m.group(1) + angles[0] if len(angles) == 1 else m.group(0)

    return _TRIG_LETTER.sub(letter, text)


def subscript(m: re.Match) -> str:
    digits = m.group(2).translate(str.maketrans("₀₁₂₃₄₅₆₇₈₉", "0123456789"))
    return m.group(1) + ("" if "_" in m.group(1) else "_") + digits


def notes_names(text: str) -> str:
    """The notes' spellings of names as derive's: ``V_At2``, ``V_An2`` -> ``v_A2t``, ``v_A2n``;
    ``V_A2t`` -> ``v_A2t``; ``M_A`` -> ``m_A``; ``0.5 x 0.8`` (x for times) -> ``0.5 * 0.8``."""
    text = re.sub(r"\b[vV]_([AB])([12])([nt])\b", r"v_\1\2\3", text)
    text = re.sub(r"\b[vV]_([AB])([nt])([12])\b", r"v_\1\3\2", text)
    text = re.sub(r"\bM_([AB])\b", r"m_\1", text)
    return re.sub(r"(?<=[\d)])\s+[x×]\s+(?=[\d(.])", " * ", text)


#: A side that is an angle letter plus or minus a bare number (``alpha - 30``, ``90 - theta``).
_ANGLE_LETTER = r"(?:alpha|beta|gamma|delta|theta|phi|psi|varphi|vartheta|[αβγδθφψϕϑ])(?:_?\w{1,3})?"
_ANGLE_SUM = re.compile(
    rf"(?:^\s*{_ANGLE_LETTER}\s*[-+]\s*\d+\.?\d*(?=\s*$)|^\s*\d+\.?\d*(?=\s*[-+]\s*{_ANGLE_LETTER}\s*$))"
)


def angle_sum_in_degrees(side: str) -> str:
    """``alpha - 30`` -> ``alpha - 30°``, ``90 - θ`` -> ``90° - θ``: a bare number added to an
    angle letter is degrees, as the angle's are (a student writes them so)."""
    return _ANGLE_SUM.sub(lambda m: m.group(0).rstrip() + "°", side)


def shared_letters(ctx: Context, used: set[str], problem: dict[str, sympy.Expr]) -> dict[str, sympy.Expr]:
    """A letter without its body (``W = 47 lb each``) where the problem gives the same value for
    both bodies (W_A = W_B = 47 lb): either (A's), as a student writes one weight for both."""
    values = {g.name: g.value for g in ctx.problem.givens}
    out: dict[str, sympy.Expr] = {}
    for name in used - set(problem):
        a, b = f"{name}_A", f"{name}_B"
        if a in problem and b in problem and values.get(a) is not None and values.get(a) == values.get(b):
            out[name] = problem[a]
    return out


def marked_names(text: str) -> str:
    """A name's marks in one spelling before it is read (:mod:`.namegrammar`): a prime as ``'``
    (``v_A^{\\prime}``, ``v_A′``, ``v'_1`` -> ``v_A'``, ``v_1'``), a time as a superscript joined to
    the subscript (``v_1^i`` -> ``v_1i``), braces and commas of a subscript typed as text dropped
    (``v_{A,f}`` -> ``v_Af``), and a body glued to its letter before a prime (``vAn'`` -> ``v_An'``)."""
    text = re.sub(r"\^\s*\(?\s*\{?\s*\\prime\s*\}?\s*\)?|′|’(?=\s*[=+\-*/)^,\s]|$)", "'", text)
    text = re.sub(r"(?<![A-Za-z\\])([A-Za-z])'\s*_\s*(\{[^{}]{1,8}\}|[A-Za-z0-9]{1,3})", r"\1_\2'", text)
    text = re.sub(r"(?<![A-Za-z\\])([A-Za-z]_\{?[A-Za-z0-9]{1,3}\}?)\^\{?(i|f|initial|final)\}?(?![\w])", r"\1\2", text)
    text = re.sub(
        r"(?<![A-Za-z\\])([A-Za-z]{1,2})_\{([A-Za-z0-9]{1,3})\s*,\s*([A-Za-z0-9]{1,3})\}",
        lambda m: f"{m[1]}_{m[2]}{m[3]}",
        text,
    )
    text = re.sub(r"(?<![A-Za-z\\])([A-Za-z]{1,2})_\{([A-Za-z0-9]{1,4})\}", r"\1_\2", text)
    return re.sub(r"(?<![\w\\])([uvVw])([AB12])(\d?[nt]?)(?=')", r"\1_\2\3", text)


#: An impulse said in words as all of a side (``impulse``, ``the impulse on the ball``, ``impulse on
#: B``, ``impulse exerted by the wall``, ``change in momentum``, the impulse on the body): the body it
#: acts on where a letter says it.
_IMPULSE_SAID = re.compile(
    r"^\s*(?:the\s+)?(?:(impulse)|change\s+(?:in|of)\s+(?:its\s+|the\s+)?momentum|momentum\s+change)(?:\s+(?:on|exerted\s+on|given\s+to|of|by|exerted\s+by|from)\s+(?:the\s+)?"
    r"(?:([AB])|ball|particle|sphere|disc|puck|body|wall|cushion|ground|floor|it))?\s*$",
    re.I,
)


#: A change of momentum typed as a name (``Dp``, ``dp``, ``Δp``, ``\Delta p_x``, ``delta_p``, ``Δp_B``),
#: along the line of impact (x, n) or of a body.
_CHANGE_NAME = re.compile(r"^\s*(?:D|d|Δ|\\?Delta\s*|delta_?)\s*p(?:_?\{?(?:([AB])|[xn])\}?)?\s*$")


#: The impulse as the integral of the force over the contact (``\\int F dt``, ``∫ F_B dt``,
#: ``\\int_0^{t} F\\,dt``, ``∫F(t) dt``, ``\\int F \\mathrm{d}t``): on the body a letter names.
_INTEGRAL = re.compile(
    r"^\s*(?:\\int|∫)\s*(?:_\s*(?:\{[^{}]*\}|\([^()]*\)|[^{}()\s])\s*)?(?:\^\s*(?:\{[^{}]*\}|\([^()]*\)|[^{}()\s])\s*)?"
    r"\(?\s*(?:\\vec\s*|\\mathbf\s*)?\(?F\)?(?:_\{?([AB])\}?|_?\{?[nx]\}?)?\s*(?:\(\s*t\s*\))?\s*\)?\s*(?:\\,|\*|·)?\s*"
    r"(?:\\mathrm\s*\{\s*d\s*\}|\(?\s*d\s*\)?)\s*t\s*$"
)


def impulse_name(side: str) -> str | None:
    """A side that is an impulse in words as one name (``impulse``, ``impulse_B`` for "impulse on
    B", ``dp`` for "change in momentum"), or as the integral of the force (``\\int F dt``), whose
    meaning its value or its relations settle (:mod:`.valuenames`); None where the side is not one."""
    m = _INTEGRAL.match(side)
    if m is not None:
        return f"impulse_{m[1]}" if m[1] else "impulse"
    m = _CHANGE_NAME.match(side)
    if m is not None:
        return f"dp_{m[1]}" if m[1] else "dp"
    m = _IMPULSE_SAID.match(side)
    if m is None:
        return None
    name = "impulse" if m[1] else "dp"  # "change in momentum": a name of its own, its sign its own
    return f"{name}_{m[2].upper()}" if m[2] else name


#: A body's speed or velocity and when, in words: "speed of A before", "initial velocity of B",
#: "A's initial speed", "B final velocity", "velocity of A after" (read by :func:`body_when`).
BODY_WHEN = (
    r"(?<![\w'])(?:(initial|final)\s+(speed|velocity)\s+of\s+([AB])|(speed|velocity)\s+of\s+([AB])\s+"
    r"(before|after|initially|finally)|([AB])(?:['’]s)?\s+(initial|final)\s+(speed|velocity))(?![\w'])"
)


def body_when(m: re.Match) -> str:
    """The name for :data:`BODY_WHEN`'s phrase: ``speed_A1`` (a speed before), ``speed_A`` (after),
    ``v_A1``, ``v_A2``."""
    when, kind, body = (m[1], m[2], m[3]) if m[3] else (m[6], m[4], m[5]) if m[5] else (m[8], m[9], m[7])
    before = when.lower() in ("initial", "before", "initially")
    if kind.lower() == "speed":
        return f"speed_{body.upper()}1" if before else f"speed_{body.upper()}"
    return f"v_{body.upper()}{1 if before else 2}"
