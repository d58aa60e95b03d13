"""Mathematics as students type it, rewritten into the restricted grammar of :mod:`derive.problem.expr`.

``20 v_A2n + 5 v_B2n``, ``0.6(5 cos 37.6° + 15 cos 37.6°)``, ``5·sin(37.6 deg)``,
``v_A2n(20 + 5)``: products without ``*``, functions without parentheses around a
single number or name, degree marks (``°``, ``deg``) after a number, and a few
Unicode signs (− × · ÷ ² ³ √, Greek letters). Only the text changes: the result is read by
the same parser as everything else, so nothing is evaluated that it would refuse.
"""

from __future__ import annotations

import re
import unicodedata
from fractions import Fraction

#: The functions of the parser (a name followed by "(" is a call only for these).
FUNCTIONS = frozenset({"sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "exp", "log"})

_UNICODE = {
    "−": "-",
    "–": "-",
    "×": "*",
    "·": "*",
    "⋅": "*",
    "÷": "/",
    "²": "^2",
    "³": "^3",
    "π": " pi ",
    "θ": " theta",
    "β": " beta",
    "α": " alpha",
    "γ": " gamma",
    "δ": " delta",
    "ε": " epsilon",
    "λ": " lambda",
    "μ": " mu",
    "σ": " sigma",
    "τ": " tau",
    "φ": " phi",
    "ϕ": " phi",
    "ψ": " psi",
    "ω": " omega",
    "√": " sqrt ",
    "½": "(1/2)",
    "¼": "(1/4)",
    "¾": "(3/4)",
    "⅓": "(1/3)",
    "[": "(",
    "]": ")",
}
#: Vulgar fractions (``⅔``, ``⅝``) and runs of superscript digits and signs (``⁻³``, ``⁴``).
_VULGAR = re.compile("[\u2150-\u215e\u00bc-\u00be]")
_SUPER = dict(zip("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+", strict=True))
_SUPERSCRIPT = re.compile("[⁰¹⁴⁵⁶⁷⁸⁹⁻⁺][⁰¹²³⁴⁵⁶⁷⁸⁹]*|[²³]?[⁰¹²³⁴⁵⁶⁷⁸⁹]{2,}")


def _vulgar(m: re.Match) -> str:
    value = Fraction(unicodedata.numeric(m.group(0))).limit_denominator(10)
    return f"({value.numerator}/{value.denominator})"


def _superscript(m: re.Match) -> str:
    return "^(" + "".join(_SUPER[c] for c in m.group(0)) + ")"


#: A Greek letter with a Latin letter right after it (``λu``, ``μu^2``): two factors.
_GREEK_BEFORE_LETTER = re.compile(r"([θβαγδελμστφϕψωπ])(?=[A-Za-z])")
#: ``tan^-1``, ``tan^(-1)``, ``tan^{-1}``, ``tan⁻¹``: the inverse functions.
_INVERSE = re.compile(r"\b(sin|cos|tan)\s*(?:\^\s*(?:\(\s*-\s*1\s*\)|\{\s*-\s*1\s*\}|-\s*1)|⁻¹)")
#: ``|x|``: the size of what stands between two bars.
_BARS = re.compile(r"\|([^|]+)\|")
_NUM = r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_ANGLE_MARK = re.compile(rf"(?<![\w.])({_NUM})\s*(?:°|deg(?:rees?)?\b|(rad(?:ians?)?\b))")
#: ``sqrt3``, ``2sqrt3``, ``root3``, ``rt3`` (typed on a phone), ``2rt(3)``: a root glued to the
#: number after it, or to a number alone in brackets (not a name ``sqrtx`` or ``rt``).
_GLUED_ROOT = re.compile(r"(?<![A-Za-z_])(?:sqrt|root|rt)(?=\d|\(\d+\))")
_BARE_CALL = re.compile(rf"\b({'|'.join(sorted(FUNCTIONS))})\s+([A-Za-z][A-Za-z0-9_]*|{_NUM})")
_TOKEN = re.compile(rf"\s*({_NUM}|[A-Za-z][A-Za-z0-9_]*|\*\*|[-+*/^(),=]|\S)")


def student(text: str) -> str:
    """``text`` with students' notation written out for the parser.

    >>> student("0.6(5 cos 37.6° + 15 cos 37.6°) = v_B2n − v_A2n")
    '0.6*(5*cos(37.6*deg)+15*cos(37.6*deg))=v_B2n-v_A2n'
    >>> student("20 v_A2n + 5 v_B2n")
    '20*v_A2n+5*v_B2n'
    """
    text = _GREEK_BEFORE_LETTER.sub(r"\1 ", text)  # kλu: k times lambda times u, not "lambdau"
    text = _VULGAR.sub(_vulgar, text)  # ⅔ as (2/3)
    text = _SUPERSCRIPT.sub(_superscript, text)  # 10⁻³ as 10^(-3); ² and ³ as before
    for sign, plain in _UNICODE.items():
        text = text.replace(sign, plain)
    text = _STANDARD_FORM.sub(_standard_form, text)  # 3.52 x 10^2 as 3.52e2: one number, at its figures
    text = _X_TIMES.sub(" * ", text)  # 4 x 12, 4 x v_A2: x standing for times between factors
    text = _MIXED.sub(_mixed, text)  # 2 2/9 u: two and two ninths
    text = _BARS.sub(r" sqrt((\1)^2) ", text.replace("‖", "|"))  # |v_P|: its size
    text = _INVERSE.sub(lambda m: "a" + m.group(1), text)
    text = function_powers(text)
    text = _PERCENT.sub(r"(\1/100)", text)  # 36% = 0.36
    text = _OVER_PRODUCT.sub(r"/(\1*\2)", text)  # v^2/2g, (…)/3m: over the product, as a teacher reads it
    text = degree_marks(text)
    text = _GLUED_ROOT.sub(" sqrt ", text)  # sqrt3: the root of 3, as √3 is
    text = _BARE_CALL.sub(lambda m: f"{m.group(1)}({m.group(2)})", text)
    return implicit_products(text)


#: A number in standard form: ``3.52 × 10^2``, ``3.52 x 10^(2)``, ``1.5*10^-3``, ``2·10⁴`` (after the
#: Unicode signs are written out): the mantissa's figures are the figures written.
_STANDARD_FORM = re.compile(
    r"(?<![\w.^])(\d+\.?\d*|\.\d+)\s*[*xX]\s*10\s*\^\s*(?:\(\s*([-+]?)\s*(\d{1,3})\s*\)|\{\s*([-+]?)\s*(\d{1,3})\s*\}|([-+]?)(\d{1,3}))(?![\d.^])"
)


#: ``x`` for times, spaced, between a number, a bracket, a letter or a name with a subscript and a
#: number, a bracket or a name with a subscript (``4 x 12``, ``2 x (3 + 1)``, ``4 x v_A2``, ``e x 4``,
#: ``v_A x 2``): a student's own x is not written so.
_X_TIMES = re.compile(r"(?:(?<=[\d)])|(?<=\b[A-Za-z])|(?<=_\w))\s+[xX]\s+(?=[\d(.]|[A-Za-z]\w*_)")
#: x for times between two numbers typed without spaces, the first a number of its own (not v2x3),
#: the second bare or alone in brackets (``0.2x(-2)``: not ``3x(v + 1)``, a name's product).
_X_GLUED = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?)[xX](?=\.?\d|\(\s*[-+−]?\s*\.?\d[\d.]*\s*\))")


def glued_times(text: str) -> str:
    """``0.5x0.8x1.2^2`` as ``0.5*0.8*1.2^2``: x typed for times between numbers, without spaces.

    >>> glued_times("0.5x0.8x1.2^2 + v2x3")
    '0.5*0.8*1.2^2 + v2x3'
    """
    for _ in range(2):  # each inner number stands on both sides of an x
        text = _X_GLUED.sub(r"\1*", text)
    return text


#: A mixed number (``2 2/9``, ``1 1/2``): a whole number, a space and a proper fraction.
_MIXED = re.compile(r"(?<![\w.^/*)])(\d{1,3})\s+(\d{1,2})\s*/\s*(\d{1,2})(?![\d.^(])")


def _mixed(m: re.Match) -> str:
    whole, num, den = (int(g) for g in m.groups())
    return f"({whole}+{num}/{den})" if 0 < num < den else m.group(0)


def _standard_form(m: re.Match) -> str:
    sign = m.group(2) or m.group(4) or m.group(6) or ""
    power = m.group(3) or m.group(5) or m.group(7)
    return f"{m.group(1)}e{sign}{power}"


#: A percentage: ``36%``, ``36 %``.
_PERCENT = re.compile(r"(?<![\w.])(\d+\.?\d*)\s*%")
#: A division by a number and a name written together (``/3m``, ``/2g``): the product is the divisor.
_OVER_PRODUCT = re.compile(r"/\s*(\d+\.?\d*)([A-Za-z](?:_[A-Za-z0-9]+)?)(?![\w(^])")
_FUNCTION_POWER = re.compile(r"(?<![A-Za-z])(sin|cos|tan)\s*\^\s*\(?(\d)\)?\s*")  # u^2cos^2 a too


def function_powers(text: str) -> str:
    """``cos^2(alpha)`` (and ``cos^2 alpha``) as ``cos(alpha)^2``: the square of the cosine."""
    for _ in range(20):
        m = _FUNCTION_POWER.search(text)
        if m is None:
            return text
        rest = text[m.end() :]
        if rest.startswith("("):
            depth, end = 0, None
            for k, c in enumerate(rest):
                depth += {"(": 1, ")": -1}.get(c, 0)
                if depth == 0:
                    end = k + 1
                    break
            if end is None:
                return text
            arg = rest[:end]
        else:
            word = re.match(r"[A-Za-z][A-Za-z0-9_]*|\d+\.?\d*(?:\s*°)?", rest)
            if word is None:
                return text
            end, arg = word.end(), f"({word.group(0)})"
        text = f"{text[: m.start()]}{m.group(1)}{arg}^{m.group(2)}{rest[end:]}"
    return text


def degree_marks(text: str) -> str:
    """``37.6°`` and ``37.6 deg`` as ``(37.6*deg)`` (``0.5 rad`` as ``(0.5*rad)``), so that
    the mark binds to its number: ``sin(37.6°)``, ``180/37.6 deg``."""
    return _ANGLE_MARK.sub(lambda m: f"({m.group(1)}*{'rad' if m.group(2) else 'deg'})", text)


def implicit_products(text: str) -> str:
    """``*`` written where two factors stand side by side: ``20 v_A2n``, ``5(9.5 + v)``,
    ``v_A2n(20 + 5)``, ``(a)(b)``; a function name before "(" stays a call."""
    tokens = [m.group(1) for m in _TOKEN.finditer(text)]
    out: list[str] = []
    for tok in tokens:
        if out and _ends_factor(out[-1]) and _starts_factor(tok):
            out.append("*")
        out.append(tok)
    return "".join(out)


def _ends_factor(tok: str) -> bool:
    return tok == ")" or _is_number(tok) or (_is_name(tok) and tok not in FUNCTIONS)


def _starts_factor(tok: str) -> bool:
    return tok == "(" or _is_number(tok) or _is_name(tok)


def _is_number(tok: str) -> bool:
    return re.fullmatch(_NUM, tok) is not None


def _is_name(tok: str) -> bool:
    return re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*", tok) is not None


#: A trigonometric function glued to a decimal angle (``sin46.8``, ``4.75cos46.8°``).
_GLUED_ANGLE = re.compile(r"(?<![A-Za-z_\\])(a?(?:sin|cos|tan))(?=\d+\.\d)")


def glued_angles(text: str) -> str:
    """``text`` with a function glued to a decimal angle spaced from it (``sin46.8``: ``sin 46.8``),
    so that the angle is a number written, with its figures, wherever the checker looks for one."""
    return _GLUED_ANGLE.sub(r"\1 ", text)
