"""A row of LaTeX mathematics as plain text, read through the one parser (:mod:`.parser`,
leniently) and printed back: ``\\frac{a}{b}`` -> ``a/b``, ``v_{A2n}`` -> ``v_A2n``,
``5 \\cos 37.6^\\circ`` -> ``5 cos(37.6°)``, ``\\tan^{-1}`` -> ``atan``, ``\\approx`` -> ``=``,
spacing and alignment dropped, a unit after a value dropped, words in ``\\text{}`` kept where
they may name something. What the parser does not take (prose, a lone bracket, an arrow, an
unknown command) is kept token by token as written, so that nothing typed is lost."""

from __future__ import annotations

import re

from derive.mathtext.parser import FUNCTIONS, GREEK, Parser
from derive.mathtext.tokens import LatexError
from derive.mathtext.tree import Add, Deg, Frac, Func, Hat, Mul, Num, Pow, Sym, Text, Unknown, Vec

_THOUSANDS = re.compile(r"(?<=\d)\\[,;: ](?=\d{3}(?!\d))")  # 45\,000
_TAG = re.compile(r"\\tag\*?\{([^{}]*)\}|\\label\{[^{}]*\}")
_TAG_END = re.compile(r"(?:&&|\\q?quad|\s)\s*\(\s*(\d{1,2}[a-z]?|[ivx]{1,4})\s*\)\s*$")
#: Tokens the parser leaves to the caller, as plain text.
_PLAIN = {
    **dict.fromkeys(("{", r"\{", r"\left(", r"\left[", r"\left\{"), "("),
    **dict.fromkeys(("}", r"\}", r"\right)", r"\right]", r"\right\}"), ")"),
    **dict.fromkeys((r"\left|", r"\right|", r"\vert", r"\lvert", r"\rvert"), "|"),
    **dict.fromkeys((r"\cdot", r"\times", r"\ast"), "*"),
    **dict.fromkeys((r"\approx", r"\simeq", r"\equiv"), "="),
    **dict.fromkeys((r"\le", r"\leq", r"\leqslant"), "≤"),
    **dict.fromkeys((r"\ge", r"\geq", r"\geqslant"), "≥"),
    **dict.fromkeys((r"\ne", r"\neq"), "≠"),
    **dict.fromkeys((r"\circ", r"\degree"), "°"),
    **dict.fromkeys((r"\checkmark", r"\ "), ""),
    r"\div": "/",
    r"\%": "%",
    r"\_": "_",
    r"\imath": "i",
    r"\jmath": "j",
    r"\ln": "log",
}
#: A row longer than this is kept token by token (the parser retries at each token where it
#: fails: a hostile row must stay cheap).
MAX_TOKENS = 160
_UNIT_WORDS = frozenset({"m", "s", "kg", "J", "N", "Ns", "ms", "ft", "lb", "slug", "deg", "rad", "g", "kJ", "km", "h"})


def latex_to_plain(tex: str) -> str:
    """A row of LaTeX mathematics as plain text.

    >>> latex_to_plain(r"v_{A2n} &= \\frac{19.8 - 5(9.51)}{25} \\approx -1.11\\,\\text{m/s}")
    'v_A2n = (19.8 - 5*9.51)/25 = -1.11'
    >>> latex_to_plain(r"\\theta = \\tan^{-1}(3.05/1.11) \\tag{3}")
    'theta = atan(3.05/1.11) (3)'
    """
    tags: list[str] = []
    s = _TAG.sub(lambda m: tags.append(m.group(1)) or " " if m.group(1) else " ", _THOUSANDS.sub("", tex))
    m = _TAG_END.search(s)
    if m:
        s, tags = s[: m.start()], [m.group(1), *tags]
    parser, out, end = Parser(s, lenient=True), [], 0
    parse = len(parser.toks) <= MAX_TOKENS
    while not parser.at_end():
        start = parser.i
        try:
            if not parse:
                raise LatexError("too long to parse")
            piece = show(parser.expr())
            piece = f"({piece})" if parser.toks[start] == "{" and not re.fullmatch(r"[\w.']*", piece) else piece
        except LatexError:
            parser.i = start
            tok = parser.take()
            piece = _PLAIN.get(tok, tok[1:] if tok[1:] in GREEK | FUNCTIONS else tok)
        out.append(piece if parser.spans[start][0] == end else " " + piece)
        end = parser.spans[parser.i - 1][1]
    return " ".join("".join([*out, *(f" ({t})" for t in tags)]).split())


def show(node: object) -> str:
    """A node of the tree in plain syntax (brackets where the reading needs them)."""
    if isinstance(node, Num):
        power = f"*10^({node.exponent})" if node.exponent else ""
        return node.mantissa + power + ("°" if node.degrees else "")
    if isinstance(node, (Sym, Vec)):
        return node.name
    if isinstance(node, Hat):
        return {"x": "i_hat", "y": "j_hat"}.get(node.axis, f"e_{node.axis}")
    if isinstance(node, Text):
        return _text(node.text)
    if isinstance(node, Add):
        out = "".join(f" {'-' if sign < 0 else '+'} {_wrapped(t, Add)}" for sign, t in node.terms)
        return out[3:] if out.startswith(" + ") else "-" + out[3:]
    if isinstance(node, Mul):
        return _product(node)
    if isinstance(node, Frac):
        return f"{_wrapped(node.num, Add)}/{_wrapped(node.den, Add, Mul, Frac)}"
    if isinstance(node, Pow):
        base = show(node.base)
        if not base:
            return ""  # \text{m}^{-1}: a unit's power
        exp = show(node.exp)
        exp = exp if re.fullmatch(r"\w+", exp) else f"({exp})"
        return f"{_wrapped(node.base, Add, Mul, Frac, Pow, Deg)}^{exp}"
    if isinstance(node, Func):
        args = ", ".join(show(a) for a in node.args)
        return f"|{args}|" if node.name == "abs" else f"{'log' if node.name == 'ln' else node.name}({args})"
    if isinstance(node, Deg):
        return _wrapped(node.inner, Add, Mul, Frac) + "°"
    return "?" if isinstance(node, Unknown) else str(node)


def _wrapped(node: object, *kinds: type) -> str:
    """``node`` shown, in brackets where it is one of ``kinds`` (or a number with a power of ten)."""
    text = show(node)
    bare = not isinstance(node, kinds) and not (isinstance(node, Num) and node.exponent)
    return text if bare or not text else f"({text})"


def _product(node: Mul) -> str:
    """Factors joined as written: a space kept (``1.41 m``: a unit the reader may drop), side by
    side a number and a name or a bracket (``5v_A``, ``0.2(v + 4)``), else ``*`` (``m(u)``)."""
    out = ""
    gaps = node.gaps or (" ",) * (len(node.factors) - 1)
    for k, factor in enumerate(node.factors):
        text = _wrapped(factor, Add, Mul)
        if k and text:
            gap = gaps[k - 1]
            glued = text[0] == "(" or (re.match(r"[A-Za-z]", text) and re.search(r"[\d)]$", out))
            out += gap if gap or glued else "*"
        out += text
    return out


def _text(inner: str) -> str:
    """``\\text{…}``: a unit or words are dropped; a tag (``m/s (4)``) is kept; a name written
    in it (``\\text{KE}``, ``T_{\\text{lost}}``) is kept as a name."""
    inner = inner.strip()
    tag = re.search(r"\(\s*\d{1,2}[a-z]?\s*\)\s*$", inner)
    if tag:
        return f" {tag.group(0).strip()} "
    if re.fullmatch(r"[A-Za-z]{1,6}", inner) and inner not in _UNIT_WORDS:
        return inner
    if re.fullmatch(r"(?:direction|speed|velocity)\s+of", inner, re.I):
        return f" {inner} "  # "\text{direction of } A": a name the caller knows
    if re.fullmatch(r"(?:KE|kinetic energy|loss|lost|gained|before|after|initial|final|\s)+", inner, re.I):
        return f" {inner} "  # "KE lost": a name the caller knows
    return ""
