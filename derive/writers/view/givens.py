"""The Given list, the statement and the source line of a page; which symbols a page keeps as letters."""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

import sympy

from derive.problem import ChainProblem, Given, Problem
from derive.problem.units import latex_unit, plain_unit
from derive.symbols import latex_name, relabel, symbol
from derive.writers.printing import StepPrinter, Style, exact_latex, latex_expr

_URL = re.compile(r"https?://[A-Za-z0-9\-._~:/?#\[\]@!&'()*+,;=%]+")


def source_parts(text: str | None) -> list[tuple[str, str]]:
    """A source line as text and web addresses: ``[("text", "read at "), ("url", "https://…")]``.

    An address ends before trailing punctuation (``.,;:!?'``) and before a ``)`` it did
    not open, so that "(see https://x.org/a)." keeps its bracket and full stop as text.
    """
    if not text:
        return []
    parts: list[tuple[str, str]] = []
    last = 0
    for m in _URL.finditer(text):
        url = m.group(0)
        while url and (url[-1] in ".,;:!?'" or (url[-1] == ")" and url.count(")") > url.count("("))):
            url = url[:-1]
        if len(url) <= len("https://"):
            continue
        if m.start() > last:
            parts.append(("text", text[last : m.start()]))
        parts.append(("url", url))
        last = m.start() + len(url)
    if last < len(text):
        parts.append(("text", text[last:]))
    return parts


def worked_out(p: Any, values: Mapping[sympy.Symbol, sympy.Expr]) -> frozenset[sympy.Symbol]:
    """The symbols whose numbers were worked out (defined from others, carried from an
    earlier stage of a chain, solved for) rather than written in the file."""
    written = {g.symbol for g in p.givens if g.definition is None and g.value is not None}
    return frozenset(values) - written


def letters_of(p: Any, values: Mapping[sympy.Symbol, sympy.Expr]) -> frozenset[sympy.Symbol]:
    """The givens kept as letters (u, m, e); in a chain's impact, also the chain's own
    letters its givens are defined from (m_A = m, v_A1 = u_B) that have no number yet."""
    own = {g.symbol for g in p.givens if g.value is None and not g.unknown}
    outer = set().union(*(g.definition.free_symbols for g in p.givens if g.definition is not None))
    return frozenset(own | {s for s in outer if not getattr(values.get(s), "is_number", False)})


def result_units(sol: Any) -> dict[sympy.Symbol, str]:
    """The unit of each result of a chain (u_B in m/s), for an impact that keeps it a letter
    (its value waits on an unknown a later stage finds)."""
    by_name = {getattr(s, "name", ""): s for s in sol.values}
    return {
        by_name.get(name, symbol(name)): r.unit
        for name, r in sol.results.items()
        if getattr(r, "unit", None) and r.unit != "deg"
    }


def letter_units(p: Problem | ChainProblem) -> dict[sympy.Symbol, str]:
    """The unit of each given kept as a letter (m in kg), for the unit a value in it still needs."""
    return {g.symbol: g.unit for g in p.givens if g.value is None and g.unit and g.unit != "deg"}


#: The note beside a given the problem leaves to find (``e = "?"``); a student's sheet says ``to find``.
UNKNOWN_NOTE = "unknown: derive finds it"


def given_latex(g: Given, style: Style) -> tuple[str, str]:
    """A given as LaTeX, and a note in words (symbolic, converted, defined)."""
    name = latex_name(relabel(g.name, style.labels))
    if g.unknown:
        return name + r" = \,?", UNKNOWN_NOTE
    if g.value is None:
        if g.definition is not None:
            return f"{name} = {StepPrinter().doprint(g.definition)}", ""
        # in words beside the given, in parentheses: not "(kept as a symbol (kg))"
        unit = ("in degrees" if g.unit == "deg" else f"in {plain_unit(g.unit)}") if g.unit else "a pure number"
        return name, f"kept as a symbol, {unit}"
    if g.unit == "deg":
        deg = g.value * 180 / sympy.pi
        value = exact_latex(deg, style.digits, 1, derived=g.symbol in style.derived) + r"^\circ"
    else:
        value = exact_latex(g.value, style.digits, 1, derived=g.symbol in style.derived)
        if g.unit:
            value += r"\ " + latex_unit(g.unit)
    parts = [name]
    if g.definition is not None:
        defined = StepPrinter().doprint(g.definition)  # in the chain's names
        if defined != name:  # m_B = m_B when the page calls A "B": said once
            parts.append(defined)
        shown = latex_expr(g.definition, "values", style, 1)
        if shown != parts[-1] and not g.definition.is_Symbol and g.definition.free_symbols:
            parts.append(shown)
    if g.written is not None:
        number, _, unit = g.written.partition(" ")
        parts.append(
            exact_latex(sympy.Rational(number), style.digits, 1)
            + (latex_unit(unit) if unit in ("deg", "°") else r"\ " + latex_unit(unit))
        )
    if value != parts[-1]:
        parts.append(value)
    return " = ".join(parts), ""


def _converted(g: Given) -> bool:
    """True for a given typed in a unit other than the working one, as a nonzero number."""
    return g.written is not None and g.typed is not None and sympy.Rational(g.typed) != 0


def _found(name: str, found: Mapping[str, sympy.Expr], style: Style) -> str:
    """``{=name}``: the number the solution finds for an unknown or a result (exact and short
    as found, 0.8; a variant's at the page's figures, 0.361), without a unit; the placeholder
    as typed where there is no such number."""
    value = found.get(name)
    if value is None or not getattr(value, "is_number", True):
        return "{=" + name + "}"
    return exact_latex(value, style.digits, 0)


def statement_unit(g: Given) -> str:
    """The unit after a given's number in a statement: the one the file typed it in."""
    if g.unit == "deg":
        return "°"
    if _converted(g):  # 36 km/h, 22 g
        return " " + plain_unit(g.written.partition(" ")[2])
    return " " + plain_unit(g.unit) if g.unit else ""


def statement_number(g: Given, value: sympy.Expr, digits: int | None, magnitude: bool = False) -> str:
    """A given's number (``value``, in the working unit) as a statement prints it: in the
    unit the file typed it in, with at least the places after the point it was typed with
    (2.50 of "2.50 m/s" prints a drawn 3.1 as 3.10); its magnitude with ``magnitude``."""
    value = abs(value) if magnitude else value
    if g.unit == "deg":
        value = value * 180 / sympy.pi
    elif _converted(g) and g.value:
        value = value * sympy.Rational(g.typed) / g.value  # back into the typed unit
    text = exact_latex(value, digits, 1)
    places = len(g.typed.partition(".")[2]) if g.typed is not None else 0
    if re.fullmatch(r"-?\d+(\.\d*)?", text):
        have = len(text.partition(".")[2])
        if have < places:
            text += ("" if "." in text else ".") + "0" * (places - have)
    return text


_PLACEHOLDER = re.compile(r"\{([@=]?[A-Za-z][A-Za-z0-9_]*|\|[A-Za-z][A-Za-z0-9_]*\|)\}")


def statement(
    p: Any, style: Style, text: str | None = None, found: Mapping[str, Any] | None = None
) -> list[tuple[str, str]] | None:
    """The statement (or ``text``, the question) as text and mathematics: each ``{name}``
    of a given becomes its value and unit (as the file typed it: :func:`statement_number`),
    or its symbol when it is kept as a letter; ``{|name|}`` its magnitude (a speed given as
    a signed component); ``{@name}``, any name (a given, a result, a name of the notes), its
    symbol, as mathematics (``{@theta_1} = {theta_1}``: θ₁ = 45°); ``{=name}`` the number the
    solution ``found`` for an unknown or a result ("show that e = {=e}"). Other braces stay as typed."""
    source = p.statement if text is None else text
    if not source:
        return None
    by_name = {g.name: g for g in p.givens}

    def one(name: str) -> tuple[str, str]:
        if name.startswith("="):  # the value derive finds: "show that e = {=e}"
            return "text", _found(name[1:], found or {}, style)
        bare = name.strip("|")
        g = by_name.get(bare)
        if name.startswith("@") or (g is not None and g.value is None and bare == name):
            return "math", latex_name(name.removeprefix("@"))
        if g is None or g.value is None:
            return "text", "{" + name + "}"
        return "text", statement_number(g, g.value, style.digits, bare != name) + statement_unit(g)

    parts: list[tuple[str, str]] = []
    pos = 0
    for m in _PLACEHOLDER.finditer(source):
        parts.append(("text", source[pos : m.start()]))
        parts.append(one(m.group(1)))
        pos = m.end()
    parts.append(("text", source[pos:]))
    merged: list[tuple[str, str]] = []  # neighbouring texts as one (a value joins its sentence)
    for kind, text in parts:
        if merged and kind == "text" and merged[-1][0] == "text":
            merged[-1] = ("text", merged[-1][1] + text)
        elif text:
            merged.append((kind, text))
    return merged
