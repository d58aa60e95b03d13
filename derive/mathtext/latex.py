"""A row of LaTeX mathematics as plain text: ``\\frac{a}{b}`` -> ``((a)/(b))``, ``v_{A2n}`` ->
``v_A2n``, ``5 \\cos 37.6^\\circ`` -> ``5 cos 37.6°``, spacing (``\\,`` ``\\;`` ``\\quad``) and
alignment (``&``) dropped, ``\\approx`` read as ``=``, ``\\tan^{-1}`` as ``atan``."""

from __future__ import annotations

import re

from derive.mathtext.units import SCALED, is_unit, plain_unit

_DROP = re.compile(
    r"\\(?:left|right|middle|displaystyle|textstyle|scriptstyle|quad|qquad|(?:big|Big|bigg|Bigg)[lrm]?)(?![A-Za-z])"
    r"|\\[,;:! ]|&|~|\\(?:hspace|vspace|phantom|hphantom|vphantom)\*?\{[^{}]*\}"
    r"|\\label\{[^}]*\}|\\nonumber|\\notag"
)
#: A unit in text (``\\text{m\\,s}^{-1}``, ``\\mathrm{m\\,s^{-1}}``, ``\\text{kg}``), its power after it or none.
_ONE_TEXT = r"\\(?:text|textrm|mathrm|mbox|rm)\s*\{(?:[^{}]|\{[^{}]*\})*\}(?:\s*\^\s*(?:\{[^{}]*\}|-?\d))?"
#: A unit as a fraction of two texts (``\\frac{\\text{m}}{\\text{s}}``).
_FRAC_UNIT = re.compile(
    r"\\[dt]?frac\s*\{\s*(\\(?:text|mathrm)\s*\{[^{}]*\})\s*\}\s*\{\s*(\\(?:text|mathrm)\s*\{[^{}]*\})\s*\}"
)
_TEXT_UNIT = re.compile(rf"({_ONE_TEXT}(?:(?:\s|\\[,;: ]|\\cdot)*{_ONE_TEXT})*)()(?!\s*_)")
#: Words after a relation that turn it down (``v_P = u is before the collision``, ``x = 3 (rejected)``).
REJECTED = re.compile(
    r"\b(?:is|was|are|gives?)\s+(?:the\s+)?(?:before|initial|not\s+(?:possible|valid|physical|the\s+answer))"
    r"|\b(?:reject(?:ed)?|discard(?:ed)?|impossible|not\s+possible|not\s+valid|not\s+physical)\b",
    re.I,
)
#: A body's quantity in words (``speed of A after``, ``B's final velocity``).
_BODY_WORDS = re.compile(
    r"(?:the\s+)?(?:final\s+|initial\s+)?(?:speed|velocity|direction)\s+of\s+[AB](?:\s+(?:after|before))?"
    r"|[AB]['’]s\s+(?:final\s+|initial\s+)?(?:speed|velocity)(?:\s+(?:after|before))?",
    re.I,
)
_WORDS = {
    r"\theta": " theta ",
    r"\beta": " beta ",
    r"\alpha": " alpha ",
    r"\phi": " phi ",
    r"\varphi": " phi ",
    r"\pi": " pi ",
    r"\Delta": " Delta ",
    r"\mu": " μ ",  # the Greek letter, never m times u
    r"\lambda": " lambda ",
    r"\omega": " omega ",
    r"\gamma": " gamma ",
    r"\delta": " delta ",
    r"\sigma": " sigma ",
    r"\tau": " tau ",
    r"\psi": " psi ",
    r"\rho": " rho ",
    r"\eta": " eta ",
    r"\Theta": " theta ",
    r"\Phi": " phi ",
    r"\epsilon": " epsilon ",
    r"\varepsilon": " epsilon ",
    r"\lvert": "|",
    r"\rvert": "|",
    r"\lVert": "|",
    r"\rVert": "|",
    r"\vert": "|",
    r"\Vert": "|",
    r"\cdot": "*",
    r"\times": "*",
    r"\div": "/",
    r"\circ": "°",
    r"\approx": "=",
    r"\simeq": "=",
    r"\degree": "°",
    r"\arctan": " atan ",
    r"\arcsin": " asin ",
    r"\arccos": " acos ",
    r"\sin": " sin ",
    r"\cos": " cos ",
    r"\tan": " tan ",
    r"\ln": " log ",
    r"\sqrt": "sqrt",
    r"\checkmark": " ",
    r"\%": "%",
}
_WRAPPERS = (
    "cancel",
    "bcancel",
    "xcancel",
    "boxed",
    "vec",
    "bar",
    "mathbf",
    "mathit",
    "mathrm",
    "overline",
    "operatorname",
    "textbf",
    "bm",
    "boldsymbol",
)


def latex_to_plain(tex: str) -> str:
    """A row of LaTeX mathematics as plain text.

    >>> latex_to_plain(r"v_{A2n} &= \\frac{19.8 - 5(9.51)}{25} \\approx -1.11\\,\\text{m/s}")
    'v_A2n = ((19.8 - 5(9.51))/(25)) = -1.11'
    >>> latex_to_plain(r"\\theta = \\tan^{-1}(3.05/1.11)")
    'theta = atan(3.05/1.11)'
    """
    s = re.sub(r"(?<=\d)\\[,;: ](?=\d{3}(?!\d))", "", tex)  # 45\,000: a thousands space
    s = re.sub(r"\\tag\*?\{([^{}]*)\}", r" (\1)", s)
    s = _FRAC_UNIT.sub(lambda m: " " if is_unit(f"{m.group(1)}/{m.group(2)}") else m.group(0), s)
    s = _TEXT_UNIT.sub(_unit_text, s)
    s = re.sub(r"\\(?:text|textrm|mbox|textit|mathrm)\s*\{([^{}]*)\}", _text, s)
    s = re.sub(r"\\(?:underbrace|overbrace)(\{(?:[^{}]|\{[^{}]*\})*\})(?:[_^]\{(?:[^{}]|\{[^{}]*\})*\})?", r"\1", s)
    s = _DROP.sub(" ", s)
    s = re.sub(r"\\(sin|cos|tan)\s*\^\s*(?:\{\s*-\s*1\s*\}|-\s*1)", r"\\arc\1", s)
    s = re.sub(r"\^\s*\{\s*\\circ\s*\}|\^\s*\\circ", "°", s)
    s = _unit_vectors(s)
    # a bold i, j, k is a unit vector, a factor of its own (a\mathbf{i}: a times i, never a name "ai")
    s = re.sub(r"\\(?:mathbf|boldsymbol|bm)\s*\{\s*([ijk])\s*\}(?!\s*_)", r" \1 ", s)
    for cmd in _WRAPPERS:
        s = re.sub(rf"\\{cmd}\s*\{{([A-Za-z0-9]+)\}}", r"\1", s)  # \mathbf{v}_A: the letter
        s = re.sub(rf"\\{cmd}\s*\{{", "{", s)
    s = re.sub(r"\\sqrt\s*(\d+|[A-Za-z])(?![\w{])", r"sqrt(\1)", s)  # \sqrt3
    s = fracs(s)
    s = s.replace("\\|", "|")  # \|v\|: a norm
    for word, plain in _WORDS.items():
        s = re.sub(re.escape(word) + r"(?![A-Za-z])", plain, s)
    s = re.sub(r"_\{([A-Za-z0-9]+)\}", r"_\1", s)
    s = re.sub(r"_\{([A-Za-z0-9]+),?\s*([A-Za-z0-9]+)\}", r"_\1\2", s)
    s = re.sub(r"\s+_", "_", s)
    s = " ".join(s.replace("{", "(").replace("}", ")").split())
    return re.sub(r"\b(a?(?:sin|cos|tan)|sqrt|log|exp) \(", r"\1(", s)


def _unit_text(m: re.Match) -> str:
    """A unit in text dropped (``\\text{m\\,s}^{-1}``), or kept in plain where it is a multiple
    of the SI unit (``\\mathrm{Mg}``: the reader writes the number in kg); other text as it was."""
    text = m.group(1) + (m.group(2) or "")
    if not is_unit(text):
        head = _unit_head(text)  # "\text{m s}^{-1} \text{ just before it hits}": the unit, then words
        return m.group(0) if head is None else _unit_text(_ONE_RUN.match(head)) + " " + text[len(head) :]
    plain = plain_unit(text)
    return f" {plain} " if plain in SCALED or plain.startswith("km") else " "


_ONE_RUN = re.compile(r"(.*)()", re.S)


def _unit_head(text: str) -> str | None:
    """The longest run of ``\\text{…}`` pieces at the start of ``text`` that is a unit, or None."""
    ends = [m.end() for m in re.finditer(_ONE_TEXT, text)][:-1]
    for end in reversed(ends[:4]):  # a unit is a few pieces at most
        if is_unit(text[:end]):
            return text[:end]
    return None


def _unit_vectors(s: str) -> str:
    """``\\hat{\\imath}``, ``\\hat\\imath``, ``\\hat{x}``, ``\\hat{\\mathbf{i}}`` -> ``i_hat`` (``j_hat``,
    ``n_hat``, ``t_hat``); ``\\hat e_t``, ``\\hat{e}_n`` -> ``e_t``; ``\\vec v_{A2}``, ``\\mathbf u_A``
    (a wrapper without braces) -> the name alone."""
    s = re.sub(r"\\[ij]math(?![A-Za-z])", lambda m: m.group(0)[1], s)
    letter = r"(?:\\mathbf\s*\{\s*([A-Za-z])\s*\}|\{\s*(?:\\mathbf\s*)?\{?\s*([A-Za-z])\s*\}?\s*\}|\s*([A-Za-z]))"

    def hat(m: re.Match) -> str:
        c = next(g for g in m.groups() if g)
        if c == "e":
            return "e"
        return {"x": "i", "y": "j"}.get(c, c) + "_hat"

    s = re.sub(r"\\(?:hat|widehat)\s*" + letter, hat, s)
    return re.sub(r"\\(?:vec|mathbf|bm|boldsymbol|overrightarrow|underline)(?![A-Za-z])\s*(?=[A-Za-z\\])", "", s)


def _text(m: re.Match) -> str:
    """``\\text{…}``: a unit or words are dropped; a tag (``m/s (4)``) is kept; a name written
    in it (``\\text{KE}``, ``T_{\\text{lost}}``) is kept as a name."""
    inner = m.group(1).strip()
    tag = re.search(r"\(\s*\d{1,2}[a-z]?\s*\)\s*$", inner)
    if tag:
        return f" {tag.group(0).strip()} "
    if re.fullmatch(r"[A-Za-z]{1,6}", inner) and inner not in _UNIT_WORDS:
        return inner
    if REJECTED.search(inner):
        return f" {inner} "  # "v_P = u \text{ is before the collision}": the reader turns it down
    if _BODY_WORDS.fullmatch(inner):
        return f" {inner} "  # "\text{speed of A after} = 1.04": a body's quantity the caller knows
    if re.fullmatch(r"(?:direction|speed|velocity)\s+of", inner, re.I):
        return f" {inner} "  # "\text{direction of } A": a name the caller knows
    if re.fullmatch(
        r"(?:(?:speed|velocity)\s+of\s+)?(?:approach|separation|closing|relative)(?:\s+speed)?", inner, re.I
    ):
        return f" {inner} "  # "(\text{approach speed})^2": a quantity the caller knows
    if re.fullmatch(r"(?:KE|kinetic energy|loss|lost|gained|before|after|initial|final|\s)+", inner, re.I):
        return f" {inner} "  # "KE lost": a name the caller knows
    return " "


_UNIT_WORDS = frozenset({"m", "s", "kg", "J", "N", "Ns", "ms", "ft", "lb", "slug", "deg", "rad", "g", "kJ", "km", "h"})


def fracs(s: str) -> str:
    """``\\frac{a}{b}`` (also ``\\dfrac``, ``\\tfrac``, ``\\frac12``) as ``{(a)/(b)}``, nested ones too."""
    pattern = re.compile(r"\\[dt]?frac\s*")
    while True:
        m = pattern.search(s)
        if not m:
            return s
        num, after = group(s, m.end())
        den, end = group(s, after)
        if num is None or den is None:
            return s[: m.start()] + s[m.end() :]
        s = s[: m.start()] + "{(" + num + ")/(" + den + ")}" + s[end:]


def group(s: str, i: int) -> tuple[str | None, int]:
    """The brace group (or single character) at ``s[i]``, and where it ends."""
    while i < len(s) and s[i] == " ":
        i += 1
    if i >= len(s):
        return None, i
    if s[i] != "{":
        return s[i], i + 1
    depth = 0
    for j in range(i, len(s)):
        depth += {"{": 1, "}": -1}.get(s[j], 0)
        if depth == 0:
            return s[i + 1 : j], j + 1
    return None, len(s)
