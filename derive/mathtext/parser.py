"""LaTeX mathematics read into a small expression tree (:mod:`.tree`).

The reader covers the LaTeX subset a worked solution uses: numbers as shown
(``3.05``, ``1.67 \\times 10^{-27}``, ``37.6^\\circ``), names with subscripts
(``v_{A1n}``, ``T_{\\mathrm{lost}}``, ``\\theta_{1}``), ``\\frac``, ``\\sqrt``,
powers, ``\\cdot`` and juxtaposition, ``\\left( \\right)``, ``\\left| \\right|``,
functions (``\\cos {\\theta}``, ``\\tan^{-1}\\left(x\\right)``,
``\\operatorname{atan2}``), ``\\cancel``, ``\\vec{v}_{A2}``, ``\\hat{e}_{t}``,
units (``\\ \\mathrm{m/s}``, ``\\ \\%``), and the line's decorations
(``\\Rightarrow\\quad``, ``\\boxed{}``, ``\\tag{}``, a mark the caller names).

It is written here rather than taken from SymPy's ``parse_latex``: that one
turns ``3.050`` into a float and forgets the figures shown, reads neither
units, ``\\cancel``, ``\\boxed`` nor ``\\tag``, and would tie the check to the
same library that printed the line. Numbers keep their text, so a rule can ask
how many figures a number shows and what rounding it may hide.
"""

from __future__ import annotations

import re

from derive.mathtext.tokens import LatexError, token_spans
from derive.mathtext.tree import (
    Add,
    Deg,
    Display,
    Frac,
    Func,
    Hat,
    Mul,
    Num,
    Pow,
    Relation,
    Side,
    Sym,
    Text,
    Unknown,
    Vec,
)

GREEK = frozenset(
    re.findall(
        r"\w+",
        "alpha beta gamma delta epsilon varepsilon zeta eta theta vartheta iota kappa lambda mu nu xi pi rho sigma "
        "tau upsilon phi varphi chi psi omega Gamma Delta Theta Lambda Xi Pi Sigma Upsilon Phi Psi Omega",
    )
)
FUNCTIONS = {"sin", "cos", "tan", "cot", "sec", "csc", "sinh", "cosh", "tanh", "ln", "log", "exp"}
RELATIONS = {"=": "=", "<": "<", ">": ">", r"\leq": "<=", r"\geq": ">=", r"\le": "<=", r"\ge": ">="}
RELATIONS |= {r"\neq": "!=", r"\approx": "~", r"\ne": "!="}
TAG = re.compile(r"\\tag\{([^{}]*)\}\s*$")


# ---------------------------------------------------------------- parser


class _Parser:
    def __init__(self, text: str) -> None:
        spans = token_spans(text)
        self.text = text
        self.toks = [t for t, _, _ in spans]
        self.spans = [(a, b) for _, a, b in spans]
        self.i = 0

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
    def relations(self) -> list[Relation]:
        out = [self.relation()]
        while self.peek() == r"\Rightarrow":
            self.take()
            out.append(self.relation())
        if not self.at_end():
            raise LatexError(f"unread tokens from {self.peek()!r}")
        return out

    def relation(self) -> Relation:
        sides = [self.side()]
        ops = []
        while self.peek() in RELATIONS:
            ops.append(RELATIONS[self.take()])
            sides.append(self.side())
        return Relation(tuple(sides), tuple(ops))

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
        factors = [self.factor()]
        while True:
            tok = self.peek()
            if tok in (r"\cdot", r"\times", "*", "·"):
                self.take()
                factors.append(self.factor())
            elif tok == "/":
                self.take()
                den = self.factor()
                num = factors[0] if len(factors) == 1 else Mul(tuple(factors))
                factors = [Frac(num, den)]
            elif self.starts_factor(tok):
                factors.append(self.factor())
            else:
                break
        return factors[0] if len(factors) == 1 else Mul(tuple(factors))

    def starts_factor(self, tok: str | None) -> bool:
        if tok is None:
            return False
        if tok[0].isdigit() or tok[0] == "." or tok[0].isalpha():
            return True
        if tok in ("{", "(", "[", r"\left(", r"\left[", r"\left|", r"\left\{", "|"):
            return tok != "|"
        if tok.startswith("\\"):
            name = tok[1:]
            return name in GREEK or name in FUNCTIONS or name in _ATOMS
        return False

    def factor(self) -> object:
        node = self.atom()
        while self.peek() == "^":
            self.take()
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
            return self.group()
        tok = self.take()
        if tok[0].isdigit():
            return Num(tok[0]) if len(tok) > 1 and "." not in tok else Num(tok)
        if tok.isalpha():
            return Sym(tok)
        raise LatexError(f"cannot read the superscript {tok!r}")

    def group(self) -> object:
        self.take("{")
        if self.peek() == "}":
            self.take()
            return Mul(())
        node = self.expr()
        self.take("}")
        return node

    def group_tokens(self) -> list[str]:
        """The raw tokens of a braced group."""
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
        tok = self.peek()
        if tok is None:
            raise LatexError("the line ends where a term was expected")
        if tok[0].isdigit() or tok[0] == ".":
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
            return inner
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
        if self.peek() != "_":
            return ""
        self.take()
        if self.peek() == "{":
            return "_" + _plain(self.group_tokens())
        return "_" + _plain([self.take()])

    def command(self) -> object:
        tok = self.take()
        name = tok[1:]
        if name in GREEK:
            return Sym(name + self.subscript())
        if name in FUNCTIONS:
            return self.function(name)
        handler = _ATOMS.get(name)
        if handler is None:
            raise LatexError(f"unknown command {tok}")
        return handler(self)

    def function(self, name: str) -> object:
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
        return Frac(self.group(), self.group())

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
        axis = {"imath": "x", "i": "x", "jmath": "y", "j": "y"}.get(base) or sub.lstrip("_")
        return Hat(axis)

    def cancel(self) -> object:
        node = self.group()
        return Sym(node.name, cancelled=True) if isinstance(node, Sym) else node

    def text(self) -> object:
        return Text(" ".join(self.group_tokens()))

    def mathrm(self) -> object:
        return Sym(_plain(self.group_tokens()) + self.subscript())

    def boxed(self) -> object:
        return self.group()


_ATOMS = {
    "frac": _Parser.frac,
    "dfrac": _Parser.frac,
    "sqrt": _Parser.sqrt,
    "operatorname": _Parser.operatorname,
    "vec": _Parser.vec,
    "hat": _Parser.hat,
    "cancel": _Parser.cancel,
    "text": _Parser.text,
    "mathrm": _Parser.mathrm,
    "boxed": _Parser.boxed,
    "imath": lambda p: Sym("i"),
    "jmath": lambda p: Sym("j"),
}


def _plain(tokens: list[str]) -> str:
    """A subscript or unit group as plain text: ``\\mathrm { lost }`` -> ``lost``."""
    out = []
    for tok in tokens:
        if tok in ("{", "}", r"\mathrm", r"\text", r"\rm"):
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


# ---------------------------------------------------------------- lines


def strip_boxed(body: str) -> tuple[str, bool]:
    """``\\boxed{X}`` (the whole line) -> X."""
    s = body.strip()
    if not s.startswith(r"\boxed{"):
        return s, False
    depth = 0
    for i, ch in enumerate(s[len(r"\boxed") :], len(r"\boxed")):
        if ch == "{":
            depth += 1
        elif ch == "}":
            depth -= 1
            if depth == 0:
                if s[i + 1 :].strip():
                    return s, False
                return s[len(r"\boxed{") : i], True
    raise LatexError(r"unbalanced braces after \boxed")


def parse_display(body: str, mark: str = "") -> Display:
    """A displayed line (the text between its delimiters) read into a :class:`Display`;
    each ``mark`` in it (text that flags an answer) is counted in ``answer_marks`` and left out."""
    s = body.strip()
    tag = None
    m = TAG.search(s)
    if m:
        tag, s = m.group(1).strip(), s[: m.start()].rstrip()
    marks = s.count(mark) if mark else 0
    s = s.replace(mark, "").strip() if mark else s
    implies = s.startswith(r"\Rightarrow")
    s = re.sub(r"^\\Rightarrow(?:\\quad|\\qquad|\\,|\s)*", "", s)
    s, boxed = strip_boxed(s)
    if re.fullmatch(r"\\text\{[^{}]*\}", s):
        return Display(implies, boxed, marks, tag, (), True, body)
    relations = _Parser(s).relations()
    return Display(implies, boxed, marks, tag, tuple(relations), False, body)


def parse_inline(body: str) -> Relation:
    """Inline mathematics (a given, a carried value) read as one relation."""
    rels = _Parser(body.strip()).relations()
    return rels[0]
