"""LaTeX mathematics read into a small expression tree (:mod:`.tree`).

The reader covers the LaTeX subset a worked solution uses: numbers as shown
(``3.05``, ``1.67 \\times 10^{-27}``, ``37.6^\\circ``), names with subscripts
(``v_{A1n}``, ``T_{\\mathrm{lost}}``, ``\\theta_{1}``), ``\\frac``, ``\\sqrt``,
powers, ``\\cdot`` and juxtaposition, ``\\left( \\right)``, ``\\left| \\right|``,
functions (``\\cos {\\theta}``, ``\\tan^{-1}\\left(x\\right)``,
``\\operatorname{atan2}``), ``\\cancel``, ``\\vec{v}_{A2}``, ``\\hat{e}_{t}``,
units (``\\ \\mathrm{m/s}``, ``\\ \\%``), and the line's decorations
(``\\Rightarrow\\quad``, ``\\boxed{}``, ``\\tag{}``, a mark the caller names: :mod:`.display`).

Read ``lenient`` (what students type: :mod:`.latex`), it takes more: ``\\tfrac12``, ``\\sqrt3``,
``\\mathbf{v}``, ``\\bigl(``, ``\\hspace{}``, primes, ``°``, ``\\mu`` as μ.

Numbers keep their text, so a rule can ask how many figures a number shows and
what rounding it may hide (SymPy's ``parse_latex`` makes ``3.050`` a float, reads
no units, ``\\cancel``, ``\\boxed`` or ``\\tag``: docs/verify.md).
"""

from __future__ import annotations

import re

from derive.mathtext.tokens import LatexError, token_spans
from derive.mathtext.tree import Add, Deg, Frac, Func, Hat, Mul, Num, ParsedRelation, Pow, Side, Sym, Text, Unknown, Vec

GREEK = frozenset(
    re.findall(
        r"\w+",
        "alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi rho sigma "
        "tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega",
    )
)
FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "sinh", "cosh", "tanh", "ln", "log", "exp"}
FUNCTIONS |= {"arcsin", "arccos", "arctan"}  # read as asin, acos, atan
#: How deep brackets and commands may nest (a page nests a few; a hostile text must stay cheap).
MAX_DEPTH = 40
RELATIONS = {"=": "=", "<": "<", ">": ">", r"\leq": "<=", r"\geq": ">=", r"\le": "<=", r"\ge": ">="}
RELATIONS |= {r"\neq": "!=", r"\approx": "~", r"\simeq": "~", r"\ne": "!="}
#: Greek letters as the checker names them, read leniently (``\mu``: μ, never m times u).
LOOSE_GREEK = {"mu": "μ", "varphi": "phi", "Phi": "phi", "Theta": "theta", "varepsilon": "epsilon"}


# ---------------------------------------------------------------- parser


class Parser:
    """A recursive-descent reader of ``text``. ``lenient`` reads what students type too
    (:data:`LOOSE_ATOMS`, a single token for a group, primes, ``°``) and keeps how the
    factors of a product were joined."""

    def __init__(self, text: str, lenient: bool = False) -> None:
        spans = token_spans(text, lenient)
        self.lenient = lenient
        self.atoms = _ATOMS | LOOSE_ATOMS if lenient else _ATOMS
        self.text = text
        self.toks = [t for t, _, _ in spans]
        self.spans = [(a, b) for _, a, b in spans]
        self.i = self.depth = 0

    def peek(self, k: int = 0) -> str | None:
        j = self.i + k
        return self.toks[j] if j < len(self.toks) else None

    def take(self, expected: str | None = None) -> str:
        tok = self.peek()
        if tok is None or (expected is not None and tok != expected):
            raise LatexError(f"expected {expected or 'more'} at token {self.i}, found {tok!r}")
        self.i += 1
        return tok

    def at_end(self) -> bool:
        return self.i >= len(self.toks)

    # relations ---------------------------------------------------------
    def relations(self) -> list[ParsedRelation]:
        out = [self.relation()]
        while self.peek() == r"\Rightarrow":
            self.take()
            out.append(self.relation())
        if not self.at_end():
            raise LatexError(f"unread tokens from {self.peek()!r}")
        return out

    def relation(self) -> ParsedRelation:
        sides = [self.side()]
        ops = []
        while self.peek() in RELATIONS:
            ops.append(RELATIONS[self.take()])
            sides.append(self.side())
        return ParsedRelation(tuple(sides), tuple(ops))

    def side(self) -> Side:
        start = self.i
        if self.peek() == "?":
            self.take()
            return Side(Unknown(), None, "?")
        expr = self.expr()
        unit = None
        if self.peek() == r"\ ":
            self.take()
            unit = self.unit()
        elif self.peek() == r"\%":
            self.take()
            unit = "%"
        return Side(expr, unit, self.source(start))

    def source(self, start: int) -> str:
        """The text of tokens ``start`` .. now, as written."""
        if start >= self.i:
            return ""
        return self.text[self.spans[start][0] : self.spans[self.i - 1][1]].strip()

    def unit(self) -> str:
        tok = self.take()
        if tok == r"\%":
            return "%"
        if tok in (r"\mathrm", r"\text"):
            return _plain(self.group_tokens())
        raise LatexError(f"expected a unit after '\\ ', found {tok!r}")

    # expressions -------------------------------------------------------
    def expr(self) -> object:
        terms: list[tuple[int, object]] = []
        sign = 1
        if self.peek() in ("+", "-"):
            sign = -1 if self.take() == "-" else 1
        terms.append((sign, self.term()))
        while self.peek() in ("+", "-"):
            sign = -1 if self.take() == "-" else 1
            terms.append((sign, self.term()))
        if len(terms) == 1 and terms[0][0] == 1:
            return terms[0][1]
        return Add(tuple(terms))

    def term(self) -> object:
        factors, gaps = [self.factor()], []
        while True:
            tok = self.peek()
            if tok in (r"\cdot", r"\times", "*", "·"):
                self.take()
                factors.append(self.factor())
                gaps.append({r"\cdot": "·", "·": "·", r"\times": "×"}.get(tok, "*"))  # between vectors: · and ×
            elif tok == "/":
                self.take()
                den = self.factor()
                num = factors[0] if len(factors) == 1 else Mul(tuple(factors), tuple(gaps))
                factors, gaps = [Frac(num, den)], []
            elif self.starts_factor(tok):
                gaps.append(" " if self.spans[self.i - 1][1] < self.spans[self.i][0] else "")
                factors.append(self.factor())
            else:
                break
        return factors[0] if len(factors) == 1 else Mul(tuple(factors), tuple(gaps))

    def starts_factor(self, tok: str | None) -> bool:
        if tok is None:
            return False
        if tok[0].isdigit() or (tok[0] == "." and len(tok) > 1) or tok[0].isalpha():
            return True  # ".5", not a full stop
        if tok in ("{", "(", "[", r"\left(", r"\left[", r"\left|", r"\left\{", "|"):
            return tok != "|"
        if tok.startswith("\\"):
            name = tok[1:]
            return name in GREEK or name in FUNCTIONS or name in self.atoms
        return self.lenient and tok.isalpha()  # θ

    def factor(self) -> object:
        node = self.atom()
        while self.peek() == "^" or (self.lenient and self.peek() in ("°", r"\degree")):
            if self.take() != "^":
                node = Num(node.mantissa, node.exponent, True) if isinstance(node, Num) else Deg(node)
                continue
            if self.peek() == r"\circ":
                self.take()
                node = Num(node.mantissa, node.exponent, True) if isinstance(node, Num) else Deg(node)
                continue
            if self.peek() == "{" and self.peek(1) == r"\circ" and self.peek(2) == "}":
                self.i += 3
                node = Num(node.mantissa, node.exponent, True) if isinstance(node, Num) else Deg(node)
                continue
            node = Pow(node, self.script())
        return node

    def script(self) -> object:
        """A superscript: a braced group or a single token."""
        if self.peek() == "{":
            return self.atom()  # counted as deep as a bracket: x^{x^{x^{…}}}
        self.first_digit()
        tok = self.take()
        if tok[0].isdigit():
            return Num(tok)
        if tok.isalpha():
            return Sym(tok)
        raise LatexError(f"cannot read the superscript {tok!r}")

    def group(self) -> object:
        if self.lenient and self.peek() != "{":
            return self.loose_group()
        self.take("{")
        if self.peek() == "}":
            self.take()
            return Mul(())
        node = self.expr()
        self.take("}")
        return node

    def loose_group(self) -> object:
        """A group written without braces, as students do: ``\\frac12``, ``\\sqrt3``, ``\\vec v``, ``\\frac u2``."""
        self.first_digit()
        self.first_letter()
        return self.atom()

    def first_letter(self) -> None:
        """A run of letters next splits after its first letter, as TeX takes it: ``\\frac u2`` is u/2."""
        tok = self.peek()
        if tok is not None and len(tok) > 1 and tok[0].isalpha() and tok[0] != "\\":
            begin, end = self.spans[self.i]
            self.toks[self.i : self.i + 1] = [tok[0], tok[1:]]
            self.spans[self.i : self.i + 1] = [(begin, begin + 1), (begin + 1, end)]

    def first_digit(self) -> None:
        """A whole number next splits after its first digit: TeX's ``x^23`` is ``x^{2}3``."""
        tok = self.peek()
        if tok is not None and tok[0].isdigit() and len(tok) > 1 and "." not in tok:
            begin, end = self.spans[self.i]
            self.toks[self.i : self.i + 1] = [tok[0], tok[1:]]
            self.spans[self.i : self.i + 1] = [(begin, begin + 1), (begin + 1, end)]

    def group_tokens(self) -> list[str]:
        """The raw tokens of a braced group."""
        if self.lenient and self.peek() != "{":
            return [self.take()]
        self.take("{")
        depth, out = 1, []
        while True:
            tok = self.take()
            if tok == "{":
                depth += 1
            elif tok == "}":
                depth -= 1
                if depth == 0:
                    return out
            out.append(tok)

    def atom(self) -> object:
        """A number, a name, a bracket or a command (at most :data:`MAX_DEPTH` inside each other)."""
        self.depth += 1
        try:
            if self.depth > MAX_DEPTH:
                raise LatexError(f"more than {MAX_DEPTH} brackets or commands inside each other")
            return self.bare_atom()
        finally:
            self.depth -= 1

    def bare_atom(self) -> object:
        tok = self.peek()
        if tok is None:
            raise LatexError("the line ends where a term was expected")
        if tok[0].isdigit() or (tok[0] == "." and len(tok) > 1):
            return self.number()
        if tok[0].isalpha():
            self.take()
            return Sym(tok + self.subscript())
        if tok == "{":
            return self.group()
        if tok in ("(", r"\left(", "[", r"\left["):
            self.take()
            inner = self.expr()
            self.take({"(": ")", r"\left(": r"\right)", "[": "]", r"\left[": r"\right]"}[tok])
            return Func("()", (inner,)) if self.lenient else inner  # leniently, the brackets as written
        if tok == r"\left|":
            self.take()
            inner = self.expr()
            self.take(r"\right|")
            return Func("abs", (inner,))
        if tok.startswith("\\"):
            return self.command()
        raise LatexError(f"unexpected {tok!r}")

    def number(self) -> Num:
        mant = self.take()
        if self.peek() == r"\times" and self.peek(1) == "10" and self.peek(2) == "^":
            save = self.i
            self.i += 3
            exp = self.script()
            if isinstance(exp, Num) and exp.integer:
                return Num(mant, int(exp.mantissa))
            if isinstance(exp, Add) and len(exp.terms) == 1 and isinstance(exp.terms[0][1], Num):
                return Num(mant, exp.terms[0][0] * int(exp.terms[0][1].mantissa))
            self.i = save
        return Num(mant)

    def subscript(self) -> str:
        """A name's subscript as plain text (``_{A2n}`` -> ``_A2n``); read leniently, with the
        primes after it (``v_A'``: after) and no comma (``v_{A,2}``)."""
        sub = ""
        if self.peek() == "_":
            self.take()
            sub = "_" + _plain(self.group_tokens() if self.peek() == "{" else [self.take()])
        while self.lenient and self.peek() == "'":
            sub += self.take()
        return sub.replace(",", "") if self.lenient else sub

    def command(self) -> object:
        tok = self.take()
        name = tok[1:]
        if name in GREEK:
            return Sym((LOOSE_GREEK.get(name, name) if self.lenient else name) + self.subscript())
        if name in FUNCTIONS:
            return self.function(name)
        handler = self.atoms.get(name)
        if handler is None:
            raise LatexError(f"unknown command {tok}")
        return handler(self)

    def function(self, name: str) -> object:
        name = "a" + name[3:] if name.startswith("arc") else name  # \arctan
        power = None
        if self.peek() == "^":
            self.take()
            power = self.script()
        arg = self.factor()
        inverse = isinstance(power, Add) and len(power.terms) == 1 and power.terms[0][0] == -1
        if inverse and isinstance(power.terms[0][1], Num) and power.terms[0][1].mantissa == "1":
            return Func("a" + name, (arg,))
        node = Func(name, (arg,))
        return Pow(node, power) if power is not None else node

    def frac(self) -> object:
        return Frac(self.frac_group(), self.frac_group())

    def frac_group(self) -> object:
        """A fraction's argument; unbraced, one character as TeX takes it: ``\\frac u2`` is u/2,
        ``\\tfrac ab`` a/b (a name of several letters or a letter and digits is split after its first)."""
        return self.group()  # split unbraced by loose_group

    def sqrt(self) -> object:
        if self.peek() == "[":
            self.take()
            index = self.expr()
            self.take("]")
            return Pow(self.group(), Frac(Num("1"), index))
        return Func("sqrt", (self.group(),))

    def operatorname(self) -> object:
        name = _plain(self.group_tokens())
        opener = self.take()
        closer = {r"\left(": r"\right)", "(": ")"}.get(opener)
        if closer is None:
            raise LatexError(f"expected the arguments of {name}")
        args = [self.expr()]
        while self.peek() == ",":
            self.take()
            args.append(self.expr())
        self.take(closer)
        return Func(name, tuple(args))

    def vec(self) -> object:
        base = _plain(self.group_tokens())
        return Vec(base + self.subscript())

    def hat(self) -> object:
        toks = self.group_tokens()
        base = _plain(toks)
        sub = self.subscript()
        axis = {"imath": "x", "i": "x", "jmath": "y", "j": "y"}.get(base) or sub.lstrip("_") or base
        return Hat(axis)

    def cancel(self) -> object:
        node = self.group()
        return Sym(node.name, cancelled=True) if isinstance(node, Sym) else node

    def text(self) -> object:
        """Words in the maths, as written between the braces; read leniently, a word with a
        subscript is a name (``\\text{KE}_{\\text{lost}}``: ``KE_lost``)."""
        if self.peek() != "{":
            return Text(" ".join(self.group_tokens()))
        begin = self.spans[self.i][1]
        self.group_tokens()
        words = self.text[begin : self.spans[self.i - 1][0]].strip()
        return Sym(words + self.subscript()) if self.lenient and self.peek() == "_" and words.isalnum() else Text(words)

    def mathrm(self) -> object:
        return Sym(_plain(self.group_tokens()) + self.subscript())

    def boxed(self) -> object:
        return self.group()

    def skip(self) -> object:
        """``\\hspace{1em}``, ``\\phantom{x}``, ``\\label{…}``: layout, nothing to read."""
        if self.peek() == "*":
            self.take()
        self.group_tokens()
        return Mul(())

    def brace(self) -> object:
        """``\\underbrace{x}_{\\text{...}}``: the x."""
        node = self.group()
        if self.peek() in ("_", "^"):
            self.take()
            self.group_tokens()
        return node


_ATOMS = {
    "frac": Parser.frac,
    "dfrac": Parser.frac,
    "sqrt": Parser.sqrt,
    "operatorname": Parser.operatorname,
    "vec": Parser.vec,
    "hat": Parser.hat,
    "cancel": Parser.cancel,
    "text": Parser.text,
    "mathrm": Parser.mathrm,
    "boxed": Parser.boxed,
    "imath": lambda p: Sym("i"),
    "jmath": lambda p: Sym("j"),
}
#: What students write besides: more wrappers, ``\\tfrac``, words.
LOOSE_ATOMS = {
    **dict.fromkeys(("mathbf", "bm", "boldsymbol", "bar", "overline", "overrightarrow", "underline"), Parser.vec),
    **dict.fromkeys(("mathit", "textbf", "pmb"), Parser.vec),
    **dict.fromkeys(("text", "textrm", "mbox", "textit", "mathrm", "mathsf"), Parser.text),
    **dict.fromkeys(("bcancel", "xcancel"), Parser.cancel),
    **dict.fromkeys(("underbrace", "overbrace"), Parser.brace),
    **dict.fromkeys(("hspace", "vspace", "phantom", "hphantom", "vphantom", "label"), Parser.skip),
    "tfrac": Parser.frac,
    "widehat": Parser.hat,
}


def _plain(tokens: list[str]) -> str:
    """A subscript or unit group as plain text: ``\\mathrm { lost }`` -> ``lost``."""
    out = []
    for tok in tokens:
        if tok in ("{", "}", r"\mathrm", r"\text", r"\rm", r"\mathbf", r"\bm", r"\boldsymbol"):
            continue
        if tok == r"\cdot":
            out.append("*")
        elif tok == r"\_":
            out.append("_")
        elif tok.startswith("\\") and tok[1:] in GREEK | {"imath", "jmath"}:
            out.append(tok[1:])
        else:
            out.append(tok)
    return "".join(out)
