"""A row of a student's LaTeX mathematics read by the one parser (:mod:`.parser`, leniently) and
printed back as plain text (``\\frac{a}{b}`` -> ``a/b``, ``\\tan^{-1}`` -> ``atan``), after a
pre-pass that is not maths grammar (a thousands space, a tag, a unit in ``\\text{}``). What the
parser does not take is kept token by token as written: the checker reads it, or reports the
line not read; nothing typed is lost."""

from __future__ import annotations

import re

from derive.mathtext.bracketed import bracketed_names
from derive.mathtext.parser import FUNCTIONS, GREEK, RELATIONS, Parser
from derive.mathtext.tokens import LatexError
from derive.mathtext.tree import Add, Deg, Frac, Func, Hat, Mul, Num, Pow, Sym, Text, Unknown, Vec
from derive.mathtext.units import SCALED, is_unit, plain_unit
from derive.mathtext.vectors import AXES, component

_THOUSANDS = re.compile(r"(?<=\d)\\[,;: ](?=\d{3}(?!\d))")  # 45\,000
#: A decimal comma in braces, as European LaTeX writes it (``0{,}250``, ``3{,}46``): a point.
_DECIMAL_COMMA = re.compile(r"(?<=\d)\s*\{,\}\s*(?=\d)")
_TAG = re.compile(r"\\tag\*?\{([^{}]*)\}")
#: A tag written after the relation: ``\\quad (3)``, ``&& (ii)``.
_TAG_END = re.compile(r"(?:\\q?quad|&|\s)\s*(?:\\[lc]?dots[bc]?\s*)?\(\s*(\d{1,2}[a-z]?|[ivx]{1,4})\s*\)\s*$")
#: A unit in text (``\\text{m\\,s}^{-1}``, ``\\mathrm{m\\,s^{-1}}``, ``\\text{kg}``), its power after it or none.
_ONE_TEXT = r"\\(?:text|textrm|mathrm|mbox|rm)\s*\{(?:[^{}]|\{[^{}]*\})*\}(?:\s*\^\s*(?:\{[^{}]*\}|-?\d))?"
#: A unit as a fraction of two texts (``\\frac{\\text{m}}{\\text{s}}``).
_FRAC_UNIT = re.compile(
    r"\\[dt]?frac\s*\{\s*(\\(?:text|mathrm)\s*\{[^{}]*\})\s*\}\s*\{\s*(\\(?:text|mathrm)\s*\{[^{}]*\})\s*\}"
)
_TEXT_UNIT = re.compile(rf"{_ONE_TEXT}(?:(?:\s|\\[,;: ]|\\cdot|/)*{_ONE_TEXT})*(?!\s*_)")  # \mathrm{m}/\mathrm{s}
#: A unit typed in mathematics without ``\\text`` after a number (``4 m/s``, ``1.6 m s^{-1}``,
#: ``\\frac{48}{12} ms^{-1}``, ``64 J``, ``32 N s``) where a side ends: not a product of names.
_BARE_UNIT = re.compile(
    r"(?<=[\d}])\s*(?:\\[,;: ]\s*)*(?:kg\s*(?:\\[,;]\s*|\\cdot\s*)?m\s*/\s*s|m\s*/\s*s|(?:m\s*(?:\\[,;]\s*)?s|ms)\s*\^\s*\{?\s*-\s*1\s*\}?"
    r"|N\s*(?:\\[,;]\s*|\\cdot\s*)?s|Ns|kJ|J)(?=\s*(?:$|=|\\approx|\\simeq|,|;|&|\\\\|\\q?quad|\\tag|\())"
)
#: Words after a relation that turn it down (``v_P = u is before the collision``, ``x = 3 (rejected)``).
REJECTED = re.compile(
    r"\b(?:is|was|are|gives?)\s+(?:the\s+)?(?:before|initial|not\s+(?:possible|valid|physical|the\s+answer))"
    r"|\b(?:reject(?:ed)?|discard(?:ed)?|impossible|not\s+possible|not\s+valid|not\s+physical)\b"
    r"|(?<=[\d\s(])no(?=\s*[)\]]?\s*[.!]?\s*$)",  # "(e = −9 no)", "e = −9 (no)": a root turned down
    re.I,
)
#: Words in ``\\text{}`` that name what the caller knows: a body's quantity (``speed of A after``,
#: ``B's final velocity``, ``direction of``), a relative speed, a kinetic energy (``KE lost``).
_NAMING = re.compile(
    r"(?:the\s+)?(?:final\s+|initial\s+)?(?:speed|velocity|direction)\s+of(?:\s+[AB](?:\s+(?:after|before))?)?"
    r"|[AB]['’]s\s+(?:final\s+|initial\s+)?(?:speed|velocity)(?:\s+(?:after|before))?"
    r"|(?:(?:speed|velocity)\s+of\s+)?(?:approach|separation|closing|relative)(?:\s+speed)?"
    r"|(?:KE|kinetic energy|loss|lost|gained|before|after|initial|final|\s)+",
    re.I,
)
#: A hat in bold (``\\mathbf{\\hat n}``, ``\\boldsymbol{\\hat{\\imath}}``): a unit vector.
_BOLD_HAT = re.compile(r"\\(?:mathbf|boldsymbol|bm)\s*\{\s*\\hat\s*\{?\s*(\\?[A-Za-z]+)\s*\}?\s*\}")
#: Tokens the parser leaves to the caller, as plain text.
_PLAIN = {
    **dict.fromkeys(("{", r"\{", r"\left(", r"\left[", r"\left\{"), "("),
    **dict.fromkeys(("}", r"\}", r"\right)", r"\right]", r"\right\}"), ")"),
    **dict.fromkeys(
        (r"\left|", r"\right|", r"\vert", r"\lvert", r"\rvert", r"\Vert", r"\lVert", r"\rVert", r"\|"), "|"
    ),
    **dict.fromkeys((r"\cdot", r"\times", r"\ast"), "*"),
    **{tok: {"~": "="}.get(op, op) for tok, op in RELATIONS.items()},  # \approx: =, \leq: <=
    **dict.fromkeys((r"\circ", r"\degree"), "°"),
    **dict.fromkeys((r"\checkmark", r"\ ", r"\boxed", r"\fbox"), ""),  # \boxed{v = 2}: the relation in it
    **{r"\div": "/", r"\%": "%", r"\_": "_"},
}
#: How many tokens the parser may read in one row, tries again included (a hostile row stays cheap).
WORK = 4000


def latex_to_plain(tex: str) -> str:
    """A row of LaTeX mathematics as plain text.

    >>> latex_to_plain(r"v_{A2n} &= \\frac{19.8 - 5(9.51)}{25} \\approx -1.11\\,\\text{m/s}")
    'v_A2n = (19.8 - 5(9.51))/25 = -1.11'
    >>> latex_to_plain(r"\\theta = \\tan^{-1}(3.05/1.11) \\tag{3}")
    'theta = atan(3.05/1.11) (3)'
    """
    tags = [f" ({t.strip()})" for t in _TAG.findall(tex)]
    s = _TAG.sub(" ", _THOUSANDS.sub("", _DECIMAL_COMMA.sub(".", bracketed_names(tex, tex=True))))
    m = _TAG_END.search(s)
    if m:
        s, tags = s[: m.start()], [f" ({m.group(1)})", *tags]
    s = _FRAC_UNIT.sub(lambda m: " " if is_unit(f"{m.group(1)}/{m.group(2)}") else m.group(0), s)
    s = _TEXT_UNIT.sub(_unit_text, s)
    s = _BARE_UNIT.sub("", s)
    s = _BOLD_HAT.sub(r"\\hat{\1}", s)  # \mathbf{\hat n}: the unit vector, as \hat{\mathbf{n}} is
    s = re.sub(
        r"\^\s*\{\s*((?:\\prime\s*)+)\}|\^\s*\\prime", lambda m: "'" * max(1, (m[1] or "").count("prime")), s
    )  # v^{\prime}
    s = re.sub(r"(?<![A-Za-z\\])([A-Za-z])('+)\s*_\s*(\{[^{}]{1,8}\}|[A-Za-z0-9])", r"\1_\3\2", s)  # v'_{Ax}: v_{Ax}'
    s = re.sub(r"_\s*(?:\{\s*\\(max|min)\s*\}|\\(max|min)(?![A-Za-z]))", r"_{\1\2}", s)  # x_{\max}: a name
    parser, out, end, work = Parser(s, lenient=True), [], 0, 0  # leniently, any character is a token
    while not parser.at_end():
        start = parser.i
        try:
            node = parser.expr() if work <= WORK else None
            work += parser.i - start
        except LatexError:
            work += 2 * (parser.i - start) + 1
            node = _prefix(parser, start, parser.i) if work <= WORK else None
        tok = parser.toks[start]
        if node is None:  # the token as plain text, as written where it has no plain form
            parser.i, piece = start + 1, _PLAIN.get(tok, tok[1:] if tok[1:] in GREEK | FUNCTIONS else tok)
        else:
            piece = show(node, top=True)
            piece = f"({piece})" if piece and tok == "{" else piece  # a group
            piece = f"({piece})" if start and parser.toks[start - 1] == r"\div" and "/" in piece else piece  # ÷ ⅔
        out.append(piece if parser.spans[start][0] == end else " " + piece)
        end = parser.spans[parser.i - 1][1]
    plain = " ".join("".join([*out, *tags]).split())
    return re.sub(r"^-\s+(?=[\w(.])", "-", plain)  # "\text{CLM:} -2x": a minus, not a list's dash


def _prefix(parser: Parser, start: int, far: int) -> object | None:
    """The longest expression from token ``start`` that ends before ``far``, where reading failed
    (``\\frac{2u}{3}`` of ``\\frac{2u}{3} (v_Q = 0 …``), the parser past it; None: none (12 tried)."""
    full, spans = parser.toks, parser.spans
    for k in range(min(far, len(full)), max(start, far - 12), -1):
        parser.toks, parser.spans, parser.i = full[:k], spans[:k], start
        try:
            node = parser.expr()
        except LatexError:
            continue
        finally:
            toks, cut = parser.toks, parser.spans  # a number split after its first digit stays split
            parser.toks, parser.spans = full, spans
        if parser.i == len(toks):
            parser.toks, parser.spans = toks + full[k:], cut + spans[k:]
            return node
    return None


def _unit_text(m: re.Match) -> str:
    """A unit in text dropped (``\\text{m\\,s}^{-1}``), or kept in plain where it is a multiple
    of the SI unit (``\\mathrm{Mg}``: the reader writes the number in kg); other text as it was."""
    vector_next = re.match(r"\s*\\(?:hat|vec|mathbf|boldsymbol|bm)(?![A-Za-z])", m.string[m.end() :])
    return _unit_piece(m.group(0), words=not vector_next)


def _unit_piece(text: str, words: bool = False) -> str:
    plain = plain_unit(text)
    if not is_unit(plain):
        head = _unit_head(text)  # "\text{m s}^{-1} \text{ just before it hits}": the unit, then words
        if head is None:
            return _unit_in_words(text) if words else text
        return _unit_piece(head) + " " + text[len(head) :]
    scaled = plain in SCALED or plain.startswith("km")  # the reader writes 20 Mg, 36 km/h in SI
    return rf"\,\text{{{plain}}}" if scaled else " "  # a space before it: "(20 Mg)", never a product "20Mg"


def _unit_in_words(text: str) -> str:
    """One ``\\text{…}`` that is a unit and then words (``\\text{ft/s along } n``): the unit
    read as a unit, the words kept as words; other text as it was."""
    m = re.fullmatch(r"\\(?:text|textrm|mbox)\s*\{\s*([^{}]*?)\s*\}", text)
    words = m.group(1).split() if m else []
    for k in range(min(3, len(words) - 1), 0, -1):
        unit, rest = " ".join(words[:k]), " ".join(words[k:])
        if is_unit(unit) and re.match(r"[A-Za-z]{2,}", rest):
            return _unit_piece(rf"\text{{{unit}}}") + rf" \text{{ {rest} }}"
    return text


def _unit_head(text: str) -> str | None:
    """The longest run of ``\\text{…}`` pieces at the start of ``text`` that is a unit, or None."""
    ends = [m.end() for m in re.finditer(_ONE_TEXT, text)][:-1]
    for end in reversed(ends[:4]):  # a unit is a few pieces at most
        if is_unit(text[:end]):
            return text[:end]
    return None


def show(node: object, top: bool = False) -> str:
    """A node of the tree in plain syntax, with brackets where the reading needs them. Words
    (``\\text{}``) that say nothing the caller reads are left out only at the ``top`` of a row,
    never from inside a power, a fraction or a function (``(\\text{approach speed})^2``)."""
    if isinstance(node, Num):
        return node.mantissa + (f" * 10^({node.exponent})" if node.exponent else "") + ("°" if node.degrees else "")
    if isinstance(node, (Sym, Vec)):
        return f"({node.name})" if getattr(node, "cancelled", False) else node.name
    if isinstance(node, Hat):
        return {"x": "i_hat", "y": "j_hat", "e": "e"}.get(node.axis, f"{node.axis}_hat")
    if isinstance(node, Text):
        return _text(node.text) if top else _text(node.text) or node.text
    if isinstance(node, Add):
        out = "".join(f" {'-' if sign < 0 else '+'} {_wrapped(t, top, Add)}" for sign, t in node.terms)
        return out[3:] if out.startswith(" + ") else "-" + out[3:]
    if isinstance(node, Mul):
        return _product(node, top)
    if isinstance(node, Frac):
        return f"{_wrapped(node.num, False, Add, Mul, Frac, Text)}/{_wrapped(node.den, False, Add, Mul, Frac, Pow, Deg, Text)}"
    if isinstance(node, Pow):
        exp = show(node.exp)
        exp = exp if re.fullmatch(r"\w+", exp) else f"({exp})"
        base = _function(node.base, bare=False) if isinstance(node.base, Func) else None
        return f"{base or _wrapped(node.base, False, Add, Mul, Frac, Pow, Deg, Text)}^{exp}"
    if isinstance(node, Func):
        return _function(node, top=top)
    if isinstance(node, Deg):
        return _wrapped(node.inner, False, Add, Mul, Frac, Pow) + "°"
    return "?" if isinstance(node, Unknown) else str(node)


def _function(node: Func, bare: bool = True, top: bool = False) -> str:
    """``sin theta``, ``cos 37.6°`` (of one atom, as the checker reads them; not ``bare``: in
    brackets), ``sin(x + y)``, ``atan(0.5)``, ``sqrt(x)``, ``|x|``, ``atan2(a, b)``, ``(x)``."""
    name = "log" if node.name == "ln" else node.name
    args = ", ".join(show(a, top and name == "()") for a in node.args)
    if name in ("abs", "()"):
        return f"|{args}|" if name == "abs" else f"({args.strip()})" if args.strip() else ""
    atom = isinstance(node.args[0], (Sym, Vec, Num)) and not getattr(node.args[0], "exponent", 0)
    if bare and atom and name in ("sin", "cos", "tan"):
        return f"{name} {args}"
    return name + args if isinstance(node.args[0], Func) and node.args[0].name == "()" else f"{name}({args})"


def _wrapped(node: object, top: bool, *kinds: type) -> str:
    """``node`` shown, in brackets where it is one of ``kinds`` (or a number with a power of ten,
    or in a fraction a function written without brackets: ``(sin x)/2``)."""
    text = show(node, top).strip()
    bare = not isinstance(node, kinds) and not (isinstance(node, Num) and node.exponent)
    bare = bare and not (isinstance(node, Func) and text.startswith(node.name + " ") and Text in kinds)
    return text if bare or not text or (isinstance(node, Mul) and len(node.factors) < 2) else f"({text})"


def _product(node: Mul, top: bool) -> str:
    """Factors joined as written: ``*`` where ``\\cdot`` or ``\\times`` stood, a space where one
    stood, side by side where they were (``5eu``, ``5(9.51)``), a space between two names."""
    out = ""
    gaps = node.gaps or (" ",) * (len(node.factors) - 1)
    dot = _dot_product(node)
    if dot:
        return dot
    for k, factor in enumerate(node.factors):
        text = _wrapped(factor, top, Add, Mul, Frac) if len(node.factors) > 1 else show(factor, top)
        if k and text and out:
            gap = {"*": " * ", "·": " * ", "×": " * "}.get(gaps[k - 1], gaps[k - 1])
            if isinstance(factor, Hat) or (isinstance(factor, Vec) and factor.name in ("i", "j", "k")):
                gap = gap or " "  # a\mathbf{i}, v_1\hat n: a times the unit vector, not a name "ai", "v_1n_hat"
            elif not gap and out[-1].isalnum() and text[0].isalnum():
                gap = "" if out[-1].isdigit() and text[0].isalpha() and " " not in text else " "  # 5eu; 5 cos x
            out += gap
        out += text
    return out


def _dot_product(node: Mul) -> str:
    """Two vectors with a dot between them (``(-\\mathbf{v}_{in})\\cdot\\mathbf{v}_{out}``,
    ``\\vec a \\cdot \\vec b``) as the sum of the products of their components, each named as a
    vector's component is (:func:`.vectors.component_name`): ``-(v_inn v_outn + v_int v_outt)``;
    with ``\\times`` between them, their cross product in the plane, ``a_n b_t - a_t b_n``; ""
    where it is not that (a unit vector, a number)."""
    if node.gaps not in (("·",), ("×",)):
        return ""
    operands = [_vector_operand(f) for f in node.factors]
    if None in operands:
        return ""
    (sa, a), (sb, b) = operands
    if node.gaps == ("×",):  # two plane vectors' cross product: its one component, across the plane
        n, t = AXES
        terms = f"{component(a, n)} {component(b, t)} - {component(a, t)} {component(b, n)}"
    else:
        terms = " + ".join(f"{component(a, axis)} {component(b, axis)}" for axis in AXES)
    return f"({terms})" if sa * sb > 0 else f"-({terms})"


def _vector_operand(node: object) -> tuple[int, str] | None:
    """(sign, name) of a vector named in bold or with an arrow, alone, negated or in brackets."""
    if isinstance(node, Func) and node.name == "()" and len(node.args) == 1:
        node = node.args[0]
    sign = 1
    if isinstance(node, Add) and len(node.terms) == 1:
        sign, node = node.terms[0]
    if isinstance(node, Vec) and node.name not in ("i", "j", "k"):
        return sign, node.name
    return None


def _text(inner: str) -> str:
    """``\\text{…}`` at the top of a row: a unit or words are dropped; a tag (``m/s (4)``) is
    kept; a name written in it (``\\text{KE}``), words that name what the caller knows
    (``speed of A after``, ``approach speed``) or turn the relation down (``rejected``) are kept."""
    inner = inner.strip()
    tag = re.search(r"\(\s*\d{1,2}[a-z]?\s*\)\s*$", inner)
    if tag:
        return f" {tag.group(0).strip()} "
    if re.fullmatch(r"[A-Za-z]{1,6}", inner) and not is_unit(inner):
        return inner
    if REJECTED.search(inner) or _NAMING.fullmatch(inner) or (is_unit(inner) and (inner in SCALED or "km" in inner)):
        return f" {inner} "
    return ""
