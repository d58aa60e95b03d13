"""A variant's page: the compiled page with its numbers, figures and optional lines filled
in; its answers and givens; the statement alone."""

from __future__ import annotations

import dataclasses
import functools
import re
import weakref
from collections.abc import Callable, Iterator
from decimal import Decimal
from typing import Any

import sympy

from derive.homework.variants import chain
from derive.homework.variants.chain import ChainCompiled
from derive.homework.variants.compile import FIGURE, Compiled
from derive.homework.variants.figure_numbers import FigureNumbers
from derive.homework.variants.pagetext import drop_lines, sub_opened
from derive.homework.variants.record import Variant
from derive.numbers import float_decimal, format_number, format_places, places_that_add_up
from derive.problem import Given
from derive.problem.units import plain_unit
from derive.writers.printing import SIDE_BEGIN, SIDE_END, adds_up, exact_latex, printed_number
from derive.writers.view.givens import statement_number


def given_text(g: Given, value: sympy.Expr, digits: int | None) -> str:
    """A varied given's value as its page prints it (an angle in degrees)."""
    if g.unit == "deg":
        return exact_latex(value * 180 / sympy.pi, digits, 1)
    return exact_latex(value, digits, 1)


def _places(
    claims: list[tuple[object, object]], args: list[float], digits: int | None, extra: int, seen: dict | None = None
) -> int:
    """Places after the point for a block, so that its sums add up (as printing does);
    ``seen``: the places of the sums met before (a block printed again has the same)."""
    found = [(tuple(terms_fn(*args)), total_fn(*args)) for terms_fn, total_fn in claims]
    key = (digits, extra, *found)  # (-0.0 and 0.0 alike: a zero is left out either way)
    if seen is not None and key in seen:
        return seen[key]
    sums = [([float_decimal(t) for t in terms], float_decimal(total)) for terms, total in found]
    # a compiled page shows every line, so a variant may carry up to three more places
    places = places_that_add_up(sums, digits, extra, more=3)
    if seen is not None:
        seen[key] = places
    return places


def _allowed(x: float, digits: int | None, extra: int) -> int:
    """Significant figures a number at ``digits`` (+``extra``) shows."""
    return len(Decimal(format_number(float_decimal(x), digits, extra=extra).split("e")[0]).as_tuple().digits)


def _number(x: float, digits: int | None, extra: int, integers: bool, places: int | None) -> str:
    # where x is exact at 0, 1 or 2 places, x * 100 is within a millionth of a whole number
    # (the test below allows a billionth at each), so other numbers skip the test
    if integers and abs(x) < 1e9 and abs(x * 100 - round(x * 100)) < 1e-6 * max(1.0, abs(x * 100)):
        for k in range(3):  # an exact short number (20, 7.5, 0.25), as a given is printed
            scaled = x * 10**k
            if abs(scaled - round(scaled)) < 1e-9 * max(1.0, abs(scaled)):
                exact = Decimal(round(scaled)).scaleb(-k) if k else Decimal(round(x))
                if k and len(exact.normalize().as_tuple().digits) > _allowed(x, digits, extra):
                    break  # exact, but more figures than an intermediate shows: 857.3, not 857.25
                return str(exact) if k else str(round(x))
    d = float_decimal(x)
    if places is not None:  # the block's places, never more figures than the rule (-121.2, not -121.22)
        return format_places(d, places, digits, extra)
    text = format_number(d, digits, extra=extra)
    if "e" in text:
        mant, exp = text.split("e")
        return rf"{mant} \times 10^{{{int(exp)}}}"
    return text


def slot_texts(
    compiled: Compiled, variant: Variant, digits: int | None = None
) -> tuple[dict[int, str], dict[int, int | None]]:
    """The text of each slot of the compiled page for one variant (by slot number), and the
    places after the point of each block whose sums must add up (None: they cannot)."""
    p = compiled.problem
    d = digits if digits is not None else p.digits
    args = [_float(variant.values[n]) for n in compiled.names]
    numbers = compiled.slot_fn(*args) if compiled.slot_fn is not None else []
    seen: dict = {}
    places = {b: _places(c, args, d, 1, seen) for b, c in compiled.claim_fns.items()}
    memo = _memo(compiled)
    texts = {
        compiled.givens[n].symbol: memo.text(given_text, compiled.givens[n], variant.values[n], d)
        for n in compiled.names
    }
    angles = {compiled.givens[n].symbol for n in compiled.names if compiled.givens[n].unit == "deg"}
    values = variant.values
    by_symbol: dict[sympy.Symbol, Given] = {}
    for g in compiled.givens.values():
        by_symbol.setdefault(g.symbol, g)
    return {
        i: _slot_text(compiled, i, numbers, texts, angles, places, d, values, by_symbol, memo)
        for i in range(len(compiled.book.slots))
    }, places


class _Memo:
    """What a compiled page's variants share: its slots' expressions (a given's symbol as the
    given's own object: an equal symbol made apart compares slowly) and the texts of the
    drawn givens met so far (a value recurs in many variants)."""

    def __init__(self, compiled: Compiled) -> None:
        own = {g.symbol: g.symbol for g in compiled.givens.values()}
        self.exprs = [own.get(s.expr, s.expr) for s in compiled.book.slots]
        self.texts: dict[tuple, str] = {}

    def text(self, write: Callable[..., str], g: Given, value: sympy.Expr, *more: Any) -> str:
        """``write(g, value, *more)``, kept (the same given, value and figures write the same)."""
        key = (write, g.name, type(value), value, *more)
        text = self.texts.get(key)
        if text is None:
            text = write(g, value, *more)
            if len(self.texts) < 20_000:
                self.texts[key] = text
        return text


_MEMOS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()  # by the page's slot book


def _memo(compiled: Compiled) -> _Memo:
    memo = _MEMOS.get(compiled.book)
    if memo is None:
        memo = _MEMOS[compiled.book] = _Memo(compiled)
    return memo


_float = functools.lru_cache(maxsize=4096)(float)  # a drawn value as a float (SymPy's is slow)


def _slot_text(
    compiled: Compiled,
    part: int,
    numbers: Any,
    texts: dict[sympy.Symbol, str],
    angles: set[sympy.Symbol],
    places: dict[int, int | None],
    d: int | None,
    values: dict[str, sympy.Expr],
    by_symbol: dict[sympy.Symbol, Given],
    memo: _Memo,
) -> str:
    """One slot's text: a given as written, or a number at the figures its place shows."""
    slot = compiled.book.slots[part]
    kind = slot.kind
    expr = memo.exprs[part]  # slot.expr
    if kind == "given":
        text = texts[expr]
        if expr in angles:
            text += r"^\circ"  # cos 45°, as the substitution lines of a solution write it
        return rf"\left({text}\right)" if text.startswith("-") else text
    if kind.startswith("text"):  # a statement's {name} or {|name|}
        g = by_symbol[expr]
        return memo.text(statement_number, g, values[g.name], d, kind == "text:abs")
    if kind.endswith("number") and isinstance(expr, sympy.Symbol) and expr in texts:
        text = texts[expr]  # a given's own number, as written
        neg = text.startswith("-")
        role = kind.partition(":")[0] if ":" in kind else ""
        if role.startswith("signed"):
            return (" - " if neg else " + ") + text.lstrip("-")
        if role.startswith("lead") or not neg:
            return text
        return rf"\left({text}\right)"
    x = complex(numbers[part]).real
    role, _, what = kind.partition(":") if ":" in kind else ("", "", kind)
    result = what == "result"
    text = _number(abs(x) if role else x, d, slot.extra, not result, None if result else places.get(slot.block))
    if role.endswith("coef") and text == "1":
        text = ""
    if role.startswith("signed"):
        return (" - " if x < 0 else " + ") + text
    if role.startswith("lead"):
        return ("-" if x < 0 else "") + text
    return text


def fill(compiled: Compiled | ChainCompiled, variant: Variant, fmt: str = "md", digits: int | None = None) -> str:
    """The worked solution of one variant, from the compiled page (a chain's: solved again)."""
    if compiled.is_chain:
        return chain.chain_fill(compiled, variant, fmt, digits)
    texts, places = slot_texts(compiled, variant, digits)
    parts = compiled.templates["tex" if fmt in ("tex", "pdf") else "md"]
    page = "".join([texts[part] if isinstance(part, int) else part for part in parts])
    page = _optional_sides(_optional_lines(page, places))
    return _figures(compiled, variant, page, fmt)


def _figures(compiled: Compiled, variant: Variant, page: str, fmt: str) -> str:
    """The variant's figures put in: drawn from its own numbers (the figure reads the
    compiled solution's closed forms at them; no solve), each with its note, if any (a
    line with an empty note is left out). Only the format written is drawn."""
    from derive.writers import figure
    from derive.writers.view import figure_note

    tex = fmt in ("tex", "pdf")
    for when in ("before", "after"):
        if FIGURE.format("", when) not in page:
            continue
        drawn = drawing(compiled, variant, when)
        page = page.replace(FIGURE.format("", when), figure.to_tikz(drawn) if tex else figure.to_svg(drawn))
        note = figure_note(drawn, tex)
        marker = FIGURE.format("NOTE", when)
        page = page.replace(marker, note) if note else drop_lines(page, marker)
    return page


def drawing(compiled: Compiled, variant: Variant, when: str = "before") -> Any:
    """One variant's figure (a :class:`derive.writers.figure.Figure`), before or after the
    impact; its numbers come from functions compiled once per problem (:class:`FigureNumbers`)."""
    from derive.writers import figure

    values = {compiled.givens[n].symbol: variant.values[n] for n in compiled.names}
    if compiled.figure_numbers is None:
        compiled.figure_numbers = FigureNumbers(tuple(compiled.givens[n].symbol for n in compiled.names))
    numbers = compiled.figure_numbers
    args = [_float(variant.values[n]) for n in compiled.names]
    return figure.describe(
        compiled.solution, when == "after", values=values, numbers=lambda expr, known: numbers(expr, known, args)
    )


def _optional_lines(page: str, places: dict[int, int | None]) -> str:
    """The page with each optional line (a sum shown term by term) kept where its block's
    numbers add up at fixed places, and dropped with its display where they do not."""
    from derive.writers.view import OPTIONAL_BEGIN, OPTIONAL_END

    if OPTIONAL_BEGIN not in page:
        return page  # nothing optional: the substitutions below would leave it as it is
    begin, end = re.escape(OPTIONAL_BEGIN), re.escape(OPTIONAL_END)

    def drop(m: re.Match[str]) -> str:
        return "" if places.get(int(m.group(1))) is None else m.group(0)

    display = rf"(?:\$\$\n|\\begin\{{equation\*\}}\n){begin}(\d+)%.*?{end}.*?(?:\$\$\n\n|\\end\{{equation\*\}}\n)"
    page = sub_opened(re.compile(display, flags=re.S), drop, page, OPTIONAL_BEGIN, ("$$\n", "\\begin{equation*}\n"))
    return re.sub(rf"{begin}\d+%(.*?){end}", r"\1", page, flags=re.S)


_SIDE = re.compile(re.escape(SIDE_BEGIN) + r" = (.*?)" + re.escape(SIDE_END) + r" = ([^\n]*)")


def _optional_sides(page: str) -> str:
    """The page with each optional side (a sum shown term by term) kept where its numbers,
    as this variant prints them, add up to the total after it, and dropped where not."""

    def one(m: re.Match[str]) -> str:
        terms, rest = m.group(1), m.group(2)
        total = re.match(r"[^=]*?(?=\\ |\s*\\tag|\s*\}|\s*\\quad|\s*$)", rest)
        lone = total is not None and printed_number(total.group(0)) is not None
        keep = not lone or adds_up(terms, total.group(0))
        return (f" = {terms}" if keep else "") + f" = {rest}"

    return _SIDE.sub(one, page)


def answers(compiled: Compiled | ChainCompiled, variant: Variant, digits: int | None = None) -> dict[str, dict]:
    """The answer key of one variant: each result's value, unit and shown text. A result that
    is a given of the file (v_A2 given in an inverse problem) is no answer: the key has it once,
    among the givens."""
    if compiled.is_chain:
        return chain.chain_answers(compiled, variant, digits)
    p = compiled.problem
    givens = {g.name for g in p.givens if not g.unknown}
    d = digits if digits is not None else p.digits
    args = [float(variant.values[n]) for n in compiled.names]
    out = {}
    for name, fn in compiled.result_fns.items():
        if name in givens:
            continue
        r = compiled.solution.results[name]
        try:
            value = complex(fn(*args))
        except (ZeroDivisionError, ValueError, TypeError, OverflowError):
            continue
        if abs(value.imag) > 1e-9 * max(1.0, abs(value.real)):
            continue
        x = value.real
        out[name] = {
            "value": x,
            "unit": "deg" if r.unit == "deg" else plain_unit(r.unit),
            "shown": format_number(float_decimal(x), d),
        }
    return out


def given_values(compiled: Compiled | ChainCompiled, variant: Variant) -> dict[str, dict]:
    """The varied givens of a variant, in the problem's units (angles in degrees)."""
    out = {}
    for n in compiled.names:
        g = compiled.givens[n]
        v = variant.values[n]
        value = float(v * 180 / sympy.pi) if g.unit == "deg" else float(v)
        out[n] = {"value": value, "unit": "deg" if g.unit == "deg" else plain_unit(g.unit)}
    return out


#: The line a LaTeX page has where its solution starts (templates/problem-body.tex.j2).
TEX_SOLUTION = "% derive: the solution\n"


def statement_only(page: str, figure: str = "", convention: str = "") -> str:
    """The part of a worked page a student gets: up to the solution (Markdown, or a
    LaTeX document, which is then closed), without the Source line (citations quote
    the published answers), a given left to find marked "to find", with ``figure`` (SVG or
    TikZ: the set-up) after Find and then ``convention`` (:func:`sign_convention`)."""
    from derive.writers.view.givens import UNKNOWN_NOTE

    page = page.replace(f"({UNKNOWN_NOTE})", "(to find)")
    if TEX_SOLUTION in page:
        head = page[: page.index(TEX_SOLUTION)]
        head = re.sub(r"^\{\\raggedright\\noindent\{\\itshape Source: .*\n", "", head, flags=re.M)
        shown = f"\n\n\\begin{{center}}\n{figure}\n\\end{{center}}" if figure else ""
        shown += f"\n\n\\noindent\\textbf{{Sign convention.}} {convention}" if convention else ""
        return head.rstrip() + shown + "\n\n\\end{document}\n"
    cut = page.find("**Solution.**")
    head = page if cut < 0 else page[:cut]
    head = re.sub(r"^\*Source: .*\n\n?", "", head, flags=re.M)
    shown = f'\n\n<div align="center">{figure}</div>' if figure else ""
    shown += f"\n\n**Sign convention.** {convention}" if convention else ""
    return head.rstrip() + shown + "\n"


def sign_convention(compiled: Compiled | ChainCompiled, fmt: str = "md") -> str:
    """The sign convention in words (stage 1's sentence: where +n and +t point; a chain's
    of every impact stage) as Markdown or (tex, pdf) LaTeX text, for a student's sheet;
    empty when the page has none."""
    if compiled.is_chain:
        return chain.chain_sign_convention(compiled, fmt)
    from derive import escape
    from derive.writers.view import convention

    parts = convention(compiled.view["stages"]) if compiled.view is not None else []
    text = escape.tex if fmt in ("tex", "pdf") else escape.markdown
    return "".join(f"${s}$" if kind == "math" else text(s) for kind, s in parts)


def setup_figure(compiled: Compiled | ChainCompiled, variant: Variant, fmt: str = "md") -> str:
    """A variant's figure before the impact (a chain's: its first impact; which way +n points,
    its own speeds) as SVG or (tex, pdf) TikZ, for the student's statement; empty when its
    page has none."""
    if compiled.is_chain:
        return chain.chain_setup_figure(compiled, variant, fmt)
    if not any(s.figure == "before" for s in compiled.solution.stages):
        return ""
    from derive.writers import figure

    drawn = drawing(compiled, variant, "before")
    return figure.to_tikz(drawn) if fmt in ("tex", "pdf") else figure.to_svg(drawn)


def iterate(
    compiled: Compiled | ChainCompiled, variants: list[Variant], fmt: str = "md", digits: int | None = None
) -> Iterator[tuple[Variant, str]]:
    """Each variant with its page, one at a time (nothing kept in memory)."""
    for v in variants:
        yield v, fill(compiled, v, fmt, digits)


_SLOT = re.compile(r"DRVSLOT(\d+)X")


def fill_view(
    compiled: Compiled | ChainCompiled,
    variant: Variant,
    digits: int | None = None,
    slot: Callable[[int], str] | None = None,
) -> dict[str, Any]:
    """One variant's page as data for the writers (:func:`derive.writers.view.view`'s
    shape): the compiled page's data with its numbers, optional lines and sides and its
    figures filled in, as :func:`fill` fills the printed page. ``slot`` (a slot's number
    to its text) replaces the variant's numbers (PrairieLearn's ``{{params.NAME}}``).
    A chain's: its page in one problem's shape, without figures (no slots)."""
    from derive.writers.view import figure_entry

    if compiled.is_chain:
        return chain.chain_view_of(compiled, variant, digits)

    if compiled.view is None:
        raise ValueError("compiled without its page data")
    texts, places = slot_texts(compiled, variant, digits)
    put = slot if slot is not None else texts.__getitem__

    def one(text: str) -> str:
        return _SLOT.sub(lambda m: put(int(m.group(1))), text)

    data = _filled(compiled.view, one)
    for stage in data["stages"]:
        for block in stage["blocks"]:
            block["lines"] = [ln for ln in (_optional(ln, places) for ln in block["lines"]) if ln is not None]
        marker = stage.get("figure_svg", "")
        if marker:
            when = "after" if marker == FIGURE.format("", "after") else "before"
            stage.update(figure_entry(drawing(compiled, variant, when)))
    return data


def _filled(obj: Any, one: Callable[[str], str]) -> Any:
    """A copy of the page data with each string's slots filled in."""
    if isinstance(obj, str):
        return one(obj) if "DRVSLOT" in obj else obj
    if isinstance(obj, dict):
        return {k: _filled(v, one) for k, v in obj.items()}
    if isinstance(obj, list):
        return [_filled(v, one) for v in obj]
    if isinstance(obj, tuple) and not hasattr(obj, "_fields"):
        return tuple(_filled(v, one) for v in obj)
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return dataclasses.replace(obj, **{f.name: _filled(getattr(obj, f.name), one) for f in dataclasses.fields(obj)})
    return obj


def _optional(line: dict[str, Any], places: dict) -> dict[str, Any] | None:
    """An equation line of a variant: an optional line dropped where its block's numbers do not
    add up at fixed places, else its markers taken out; an optional side kept where it adds up."""
    from derive.writers.view import OPTIONAL_BEGIN, OPTIONAL_END

    latex = line["latex"]
    m = re.match(re.escape(OPTIONAL_BEGIN) + r"(\d+)%(.*)" + re.escape(OPTIONAL_END) + r"(.*)", latex, flags=re.S)
    if m is not None:
        if places.get(int(m.group(1))) is None:
            return None
        latex = m.group(2) + m.group(3)
    return {**line, "latex": _optional_sides(latex)}


def statement_view(compiled: Compiled, slot: Callable[[int], str]) -> dict[str, Any]:
    """The statement part of the compiled page's data (title, statement, Given list, Find),
    each slot's text from ``slot`` (a slot's number to its text): a template of the statement."""
    if compiled.view is None:
        raise ValueError("compiled without its page data")

    def one(text: str) -> str:
        return _SLOT.sub(lambda m: slot(int(m.group(1))), text)

    from derive.writers.view import student_sheet

    data = {k: _filled(compiled.view[k], one) for k in ("title", "statement", "givens", "find")}
    data["stages"] = compiled.view["stages"]  # read for the sign convention's words only
    sheet = student_sheet(data)
    del sheet["stages"]
    return sheet
