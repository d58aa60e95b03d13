"""Renderers: the same Solution as Markdown, LaTeX (document or fragment), HTML or JSON.

Layout lives in the Jinja2 templates (``templates/``); the mathematics is
printed by :mod:`derive.printing`; user text is escaped by :mod:`derive.escape`.
A renderer never does physics.
"""

from __future__ import annotations

import base64
import re
from collections.abc import Mapping
from dataclasses import replace
from functools import cache
from typing import Any

import jinja2
import sympy

from derive import escape
from derive.errors import InputError
from derive.fileio import dumps_json
from derive.numbers import format_number
from derive.problem import ChainProblem, Given, Problem
from derive.problem.units import latex_unit, plain_unit
from derive.resources import templates_dir
from derive.steps.model import Eqn, Math, Solution
from derive.symbols import latex_name, relabel, symbol
from derive.writers import figure
from derive.writers.printing import (
    IMPLIES,
    Row,
    SlotBook,
    StepPrinter,
    Style,
    block_style,
    exact_latex,
    latex_eqn,
    latex_expr,
    latex_inline,
    latex_rows,
)
from derive.writers.targets import FRAGMENT_PACKAGES, GITHUB, HTML, TEX_DOCUMENT, TEX_FRAGMENT, Layout, markdown_target
from derive.writers.width import width_pt

FORMATS = ("md", "tex", "tex-fragment", "html", "json")
ANSWER_MARK = r"\quad\longleftarrow\ \text{ANSWER}"


@cache
def environment(kind: str) -> jinja2.Environment:
    """The strict Jinja environment; LaTeX templates use \\BLOCK{} / \\VAR{} delimiters."""
    options: dict[str, Any] = {}
    if kind == "tex":
        options = dict(
            block_start_string=r"\BLOCK{",
            block_end_string="}",
            variable_start_string=r"\VAR{",
            variable_end_string="}",
            comment_start_string=r"\#{",
            comment_end_string="}",
            line_statement_prefix=None,
            line_comment_prefix=None,
        )
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(templates_dir())),
        undefined=jinja2.StrictUndefined,
        autoescape=False,
        keep_trailing_newline=True,
        trim_blocks=True,
        lstrip_blocks=True,
        **options,
    )
    env.filters["md"] = _markdown_text
    env.filters["tex"] = escape.tex
    env.filters["html"] = escape.html_text
    return env


def _sentence(text: str) -> str:
    """A caption standing alone under its figure: its first letter a capital."""
    return text[:1].upper() + text[1:]


def _html_name(name: str) -> str:
    """A symbol's name in HTML: ``v_A2`` -> ``<i>v</i><sub>A2</sub>``."""
    base, _, sub = name.partition("_")
    return f"<i>{escape.html_text(base)}</i>" + (f"<sub>{escape.html_text(sub)}</sub>" if sub else "")


@jinja2.pass_context
def _markdown_text(context: jinja2.runtime.Context, text: str) -> str:
    """User text as Markdown; ``^`` escaped too where the page is for pandoc (``escape_caret``)."""
    return escape.markdown(text, caret=bool(context.get("escape_caret", False)))


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


def _letters_of(p: Any, values: Mapping[sympy.Symbol, sympy.Expr]) -> frozenset[sympy.Symbol]:
    """The givens kept as letters (u, m, e); in a chain's impact, also the chain's own
    letters its givens are defined from (m_A = m, v_A1 = u_B) that have no number yet."""
    own = {g.symbol for g in p.givens if g.value is None and not g.unknown}
    outer = set().union(*(g.definition.free_symbols for g in p.givens if g.definition is not None))
    return frozenset(own | {s for s in outer if not getattr(values.get(s), "is_number", False)})


def figure_entry(fig: figure.Figure) -> dict[str, str]:
    """A stage's figure as the templates take it: SVG and TikZ, the caption, and the note
    Markdown and LaTeX print under it when an arrow is drawn longer than to scale."""
    html_note = fig.scale_note(_html_name, escape.html_text)
    tex_note = fig.scale_note(lambda n: f"${latex_name(n)}$", escape.tex)
    return {
        "figure_svg": figure.to_svg(fig),
        "figure_tikz": figure.to_tikz(fig),
        "figure_caption": f"{fig.title}: {fig.caption}",
        "figure_caption_html": escape.html_text(f"{fig.title}: ") + html_note,
        "figure_note_html": _sentence(html_note) if fig.lengthened else "",
        "figure_note_tex": _sentence(tex_note) if fig.lengthened else "",
    }


def _given_latex(g: Given, style: Style) -> tuple[str, str]:
    """A given as LaTeX, and a note in words (symbolic, converted, defined)."""
    name = latex_name(relabel(g.name, style.labels))
    if g.unknown:
        return name + r" = \,?", "unknown: derive finds it"
    if style.slots is not None and g.symbol in style.varied:  # a homework variant's number
        token = style.slots.token(g.symbol, "given", style.digits, 1, None)
        tail = r"^\circ" if g.unit == "deg" else (r"\ " + latex_unit(g.unit) if g.unit else "")
        return f"{name} = {token}{tail}", ""
    if (
        style.slots is not None
        and g.value is None
        and g.definition is not None
        and g.definition.free_symbols & style.varied
    ):  # defined from a varied given (m_A = W_A/g)
        parts = [name, StepPrinter().doprint(g.definition), latex_expr(g.definition, "values", style, 1)]
        value = latex_expr(g.definition, "numeric", style, 1)
        unit = r"\ " + latex_unit(g.unit) if g.unit and g.unit != "deg" else ""
        return " = ".join([*parts, value]) + unit, ""
    if g.value is None:
        if g.definition is not None:
            return f"{name} = {StepPrinter().doprint(g.definition)}", ""
        unit = plain_unit(g.unit) if g.unit else "a pure number"
        return name, f"kept as a symbol ({unit})"
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


def _statement(p: Any, style: Style, text: str | None = None) -> list[tuple[str, str]] | None:
    """The statement (or ``text``, the question) as text and mathematics: each ``{name}``
    of a given becomes its value and unit, or its symbol when it is kept as a letter;
    ``{@name}``, any name (a given, a result, a name of the notes), its symbol, as
    mathematics (``{@theta_1} = {theta_1}``: θ₁ = 45°). Other braces stay as typed."""
    source = p.statement if text is None else text
    if not source:
        return None
    by_name = {g.name: g for g in p.givens}

    def one(name: str) -> tuple[str, str]:
        g = by_name.get(name)
        if g is not None and style.slots is not None and g.symbol in style.varied:  # a variant's number
            token = style.slots.token(g.symbol, "text", style.digits, 1, None)
            return "text", token + ("°" if g.unit == "deg" else (" " + plain_unit(g.unit) if g.unit else ""))
        if name.startswith("@") or (g is not None and g.value is None):
            return "math", latex_name(name.removeprefix("@"))
        if g is None:
            return "text", "{" + name + "}"
        if g.unit == "deg":
            return "text", exact_latex(g.value * 180 / sympy.pi, style.digits, 1) + "°"
        text = exact_latex(g.value, style.digits, 1)
        return "text", text + (" " + plain_unit(g.unit) if g.unit else "")

    parts: list[tuple[str, str]] = []
    pos = 0
    for m in re.finditer(r"\{(@?[A-Za-z][A-Za-z0-9_]*)\}", source):
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


def _named(words: str, labels: tuple[str, str]) -> str:
    """Words about body A or B (``the speed of A``) under the page's letters."""
    return re.sub(r"\b([AB])\b", lambda m: labels["AB".index(m[1])], words) if labels != ("A", "B") else words


_FIND_WORDS = {
    "v_A2": "the speed of A",
    "v_B2": "the speed of B",
    "theta_A2": "the direction of A (from +t)",
    "theta_B2": "the direction of B (from +t)",
    "beta_A2": "the direction of A (from +n)",
    "beta_B2": "the direction of B (from +n)",
    "J_n": "the impulse along n",
    "T_1": "the kinetic energy before the impact",
    "T_2": "the kinetic energy after the impact",
    "T_lost": "the kinetic energy lost",
}


def line_view(eqn: Eqn, style: Style, layout: Layout, *, answer: bool = False, extra: int = 1) -> dict[str, Any]:
    """One equation line as the templates need it: ``latex`` on one row (with ⇒, box
    and ANSWER mark), its ``tag``, and, where the layout sets a width the line does
    not fit, ``rows`` to lay out (``before`` and ``after`` them: the box and the mark)."""
    body, tag = latex_eqn(eqn, style, extra)
    mark = ANSWER_MARK if answer else ""
    rows: tuple[Row, ...] = ()
    if layout.width is not None and (layout.long_lines == "aligned" or not eqn.boxed):
        rows = latex_rows(eqn, style, layout.width, extra, reserve=width_pt(mark) if mark else 0.0)
    return {
        "latex": body + mark,
        "tag": tag,
        "boxed": eqn.boxed,
        "rows": rows,
        "before": r"\boxed{" if eqn.boxed else "",
        "after": ("}" if eqn.boxed else "") + mark,
        "cancels": bool(eqn.cancel) and style.strike,
    }


#: Around an optional line of a compiled variant page, for the variant to keep or drop.
OPTIONAL_BEGIN, OPTIONAL_END = "%%derive-optional:", "%%derive-end%%"


def blocks_view(blocks_in: tuple, style: Style, layout: Layout = GITHUB) -> list[dict[str, Any]]:
    """Blocks of sentences and equation lines, printed: what blocks.*.j2 lays out."""
    blocks = []
    for block in blocks_in:
        bstyle = block_style(block, style)
        lines: list[dict[str, Any]] = []
        for eqn in block.lines:
            if eqn.optional and bstyle.hide_optional:
                continue
            line = line_view(eqn, bstyle, layout, answer=eqn.mark, extra=bstyle.extra)
            if eqn.optional and bstyle.block is not None:  # a variant's page drops it where it cannot add up
                line["latex"] = f"{OPTIONAL_BEGIN}{bstyle.block}%{line['latex']}{OPTIONAL_END}"
            bare = line["latex"].removeprefix(IMPLIES)
            if lines and lines[-1]["latex"].removeprefix(IMPLIES) == bare and not lines[-1]["boxed"]:
                kept = lines[-1]
                lines[-1] = {**kept, "tag": line["tag"] or kept["tag"], "boxed": eqn.boxed}
                continue  # the same line again (numbers in, but none to put in): once is enough
            lines.append(line)
        text = None
        if block.text is not None:
            text = [("math", latex_inline(t.expr, style)) if isinstance(t, Math) else ("text", t) for t in block.text]
        blocks.append({"text": text, "lines": lines})
    return blocks


def view(
    solution: Solution,
    digits: int | None = None,
    figures: bool = True,
    *,
    slots: SlotBook | None = None,
    varied: frozenset[sympy.Symbol] = frozenset(),
    layout: Layout = GITHUB,
    outer_letters: dict[sympy.Symbol, str] | None = None,
    outer_decimal: frozenset[sympy.Symbol] = frozenset(),
    falls: bool = False,
    known: dict[sympy.Symbol, sympy.Expr] | None = None,
    plot: bool = False,
) -> dict[str, Any]:
    """The data a template needs: every formula already printed as LaTeX, and the
    figures of stage 1 and of the answer as SVG and TikZ.

    With ``slots``, every number that depends on a ``varied`` given is left open
    (a token), so that one compiled page serves every homework variant. ``layout``
    says where the page goes (:mod:`derive.writers.targets`): how wide a line may
    be, and whether cancelled terms are struck out. ``falls`` and ``known`` are for
    an impact inside a chain: drawn with n pointing down, and the chain's numbers for
    symbols the impact leaves open. ``plot`` adds the plot of the outcome against e
    (``plot_svg``, ``plot_tikz``).
    """
    p = solution.problem
    style = Style(
        digits if digits is not None else p.digits,
        1,
        solution.values,
        solution.angles,
        varied=varied,
        slots=slots,
        strike=layout.strike,
        decimal=frozenset(g.symbol for g in p.givens if g.decimal) | outer_decimal,
        letters=_letters_of(p, solution.values) - varied,
        letter_units={**(outer_letters or {}), **letter_units(p)},
        labels=p.labels,
        derived=worked_out(p, solution.values),
    )
    stages = []
    for stage in solution.stages:
        blocks = blocks_view(stage.blocks, style, layout)
        entry = {"number": stage.number, "title": stage.title, "blocks": blocks, "figure_svg": "", "figure_tikz": ""}
        if figures and stage.figure is not None:
            fig = figure.describe(solution, after=stage.figure == "after", falls=falls, values=known)
            entry.update(figure_entry(fig))
        stages.append(entry)
    givens = [dict(zip(("latex", "note"), _given_latex(g, style), strict=False)) for g in p.givens]
    if p.question:
        find = _statement(p, style, p.question) or []
    else:
        unknown = [g.name for g in p.givens if g.unknown]
        words = ("the unknown " + ", ".join(unknown) + "; " if unknown else "") + (
            f"the velocity of {p.labels[0]} immediately after the impact"
            if p.fixed_B
            else f"the velocities of {p.labels[0]} and {p.labels[1]} immediately after the impact"
        )
        extra_words = [
            _named(_FIND_WORDS[f], p.labels)
            for f in p.find
            if f in _FIND_WORDS and not (f in ("v_A2", "v_B2") and not p.oblique)
        ]
        if extra_words:
            words += "; " + ", ".join(extra_words)
        find = [("text", words[0].upper() + words[1:] + ".")]
    plot_svg = plot_tikz = ""
    if plot:
        from derive.writers import plot as plots

        chart = plots.chart(p)
        plot_svg, plot_tikz = plots.to_svg(chart), plots.to_tikz(chart)
    return {
        "title": p.title,
        "kind": p.kind,
        "source": p.source,
        "source_parts": source_parts(p.source),
        "plot_svg": plot_svg,
        "plot_tikz": plot_tikz,
        "statement": _statement(p, style),
        "find": find,
        "givens": givens,
        "stages": stages,
        "system": p.system,
    }


def _aligned(line: dict[str, Any]) -> str:
    """A line as one display: on one row, or its rows (a long line) as an ``aligned``."""
    rows = line.get("rows") or ()
    if not rows:
        return line["latex"]
    body = []
    for row in rows:
        if row.continued:
            body.append(rf"&\quad {row.rel} {row.rhs}")
        else:
            body.append((f"{row.lhs} " if row.lhs else "") + f"&{row.rel} {row.rhs}")
    return line["before"] + r"\begin{aligned}" + r" \\ ".join(body) + r"\end{aligned}" + line["after"]


def _html(data: dict[str, Any]) -> str:
    """The HTML page: every formula typeset by KaTeX (under Node.js when there is one)."""
    from derive.writers import katex as html_mod

    items: list[tuple[str, bool]] = []

    def slot(tex: str, display: bool) -> int:
        items.append((tex, display))
        return len(items) - 1

    for g in data["givens"]:
        g["slot"] = slot(g["latex"], False)
    statement = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in data["statement"] or ()]
    find = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in data["find"]]
    for stage in data["stages"]:
        for block in stage["blocks"]:
            if block["text"]:
                block["text"] = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in block["text"]]
            for line in block["lines"]:
                line["slot"] = slot(_aligned(line), True)
    rendered = html_mod.render_math(items)
    if rendered is None:  # no Node.js: the page typesets itself, offline, with the inlined script
        rendered = [
            f'<span class="math{" display" if disp else ""}">{escape.html_text(tex)}</span>' for tex, disp in items
        ]
        script = html_mod.katex_script()
    else:
        script = ""
    for g in data["givens"]:
        g["html"] = rendered[g.pop("slot")]
    data["statement"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in statement]
    for stage in data["stages"]:
        stage["figure"] = stage.get("figure_svg", "")
        for block in stage["blocks"]:
            if block["text"]:
                block["text"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in block["text"]]
            for line in block["lines"]:
                line["html"] = rendered[line.pop("slot")]
    data["find"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in find]
    return (
        environment("md").get_template("solution.html.j2").render(**data, katex_css=html_mod.katex_css(), script=script)
    )


def _chain_html(data: dict[str, Any]) -> str:
    """A chain's HTML page: every formula typeset by KaTeX, as :func:`_html` does for one impact."""
    from derive.writers import katex as html_mod

    items: list[tuple[str, bool]] = []

    def slot(tex: str, display: bool) -> int:
        items.append((tex, display))
        return len(items) - 1

    def slot_blocks(blocks: list[dict[str, Any]]) -> None:
        for block in blocks:
            block["text"] = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in block["text"] or ()]
            for line in block["lines"]:
                line["slot"] = slot(_aligned(line), True)

    def fill_blocks(blocks: list[dict[str, Any]]) -> None:
        for block in blocks:
            block["text"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in block["text"]]
            for line in block["lines"]:
                line["html"] = rendered[line.pop("slot")]

    for g in data["givens"]:
        g["slot"] = slot(g["latex"], False)
    statement = [(k, slot(s_, False) if k == "math" else s_) for k, s_ in data["statement"] or ()]
    for st in data["stages"]:
        if st["impact"]:
            for g in st["givens"]:
                g["slot"] = slot(g["latex"], False)
            for sub in st["stages"]:
                slot_blocks(sub["blocks"])
            st["carried"] = [slot(c, False) for c in st["carried"]]
        else:
            slot_blocks(st["blocks"])
    for line in data["answers"]:
        line["slot"] = slot(_aligned(line), True)
    rendered = html_mod.render_math(items)
    if rendered is None:  # no Node.js: the page typesets itself, offline, with the inlined script
        rendered = [
            f'<span class="math{" display" if disp else ""}">{escape.html_text(tex)}</span>' for tex, disp in items
        ]
        script = html_mod.katex_script()
    else:
        script = ""
    for g in data["givens"]:
        g["html"] = rendered[g.pop("slot")]
    data["statement"] = [("math", rendered[s_]) if k == "math" else (k, s_) for k, s_ in statement]
    for st in data["stages"]:
        if st["impact"]:
            for g in st["givens"]:
                g["html"] = rendered[g.pop("slot")]
            for sub in st["stages"]:
                sub["figure"] = sub.get("figure_svg", "")
                fill_blocks(sub["blocks"])
            st["carried"] = [rendered[c] for c in st["carried"]]
        else:
            fill_blocks(st["blocks"])
    for line in data["answers"]:
        line["html"] = rendered[line.pop("slot")]
    return environment("md").get_template("chain.html.j2").render(**data, katex_css=html_mod.katex_css(), script=script)


def _text_with_math(parts: list[tuple[str, str]] | None) -> str:
    if not parts:
        return ""
    return "".join(f"${s}$" if kind == "math" else s for kind, s in parts)


def _givens_json(givens: tuple[Given, ...]) -> dict[str, dict[str, Any]]:
    """Each given's number (angles in degrees; null when symbolic) and unit."""
    return {
        g.name: {
            "value": None
            if g.value is None
            else float(sympy.N(g.value * 180 / sympy.pi if g.unit == "deg" else g.value, 17)),
            "unit": "deg" if g.unit == "deg" else plain_unit(g.unit),
        }
        for g in givens
    }


def to_json(solution: Solution, digits: int | None = None) -> str:
    """The JSON contract of DESIGN.md: title, kind, results (+ givens and steps)."""
    p = solution.problem
    d = digits if digits is not None else p.digits
    results = {}
    printer = StepPrinter()
    for name, r in solution.results.items():
        value = None if r.value is None else float(sympy.N(r.value, 17))
        entry: dict[str, Any] = {
            "value": value,
            "unit": plain_unit(r.unit) if r.unit != "deg" else "deg",
            "expr": str(r.closed),
            "latex": printer.doprint(r.closed),
            "description": r.description,
        }
        if r.value is not None:
            entry["shown"] = format_number(r.value, d)
        else:
            entry["value_expr"] = str(r.partial)
        results[name] = entry
    v = view(solution, digits)
    doc = {
        "title": p.title,
        "kind": p.kind,
        "source": p.source,
        "units": p.system,
        "find": list(p.find),
        "results": results,
        "givens": _givens_json(p.givens),
        "show": [
            {
                "relation": s.relation.text,
                "holds": s.holds,
                "decided": s.how,
                "found": str(s.lhs),
                "counterexample": {k.name: v for k, v in (s.counterexample or {}).items()} or None,
            }
            for s in solution.shown
        ],
        "ranges": [
            {
                "of": f.range.of.name,
                "where": f.range.text,
                "interval": None if f.interval is None else str(f.interval),
                "latex": None if f.interval is None else printer.doprint(f.interval),
            }
            for f in solution.ranges
        ],
        "stages": [
            {
                "number": s["number"],
                "title": s["title"],
                "blocks": [
                    {
                        "text": _text_with_math(b["text"]),
                        "lines": [{"latex": ln["latex"], "tag": ln["tag"]} for ln in b["lines"]],
                    }
                    for b in s["blocks"]
                ],
            }
            for s in v["stages"]
        ],
    }
    return dumps_json(doc)


def chain_view(
    sol: Any, digits: int | None = None, figures: bool = True, standalone: bool = True, layout: Layout = GITHUB
) -> dict[str, Any]:
    """The data the chain templates need: the chain's givens, each stage printed."""
    p = sol.problem
    style = Style(
        digits if digits is not None else p.digits,
        1,
        sol.values,
        sol.angles,
        decimal=frozenset(g.symbol for g in p.givens if g.decimal),
        letters=frozenset(g.symbol for g in p.givens if g.value is None),  # an unknown is a letter until solved
        strike=layout.strike,
        letter_units=letter_units(p),
        derived=worked_out(p, sol.values),
    )
    stages = []
    falls = figure.chain_falls(sol) if figures else {}
    for st in sol.stages:
        stage_style = style if st.values is None else replace(style, values=st.values)
        if st.part is not None:
            v = view(
                st.part,
                style.digits,
                figures=figures,
                layout=layout,
                outer_letters={**letter_units(p), **_result_units(sol)},
                outer_decimal=frozenset(g.symbol for g in p.givens if g.decimal),  # g = 9.8: -6.26 e_floor
                falls=falls.get(st.number, False),
                known=sol.values,
            )
            own = replace(stage_style, labels=st.part.problem.labels)  # v_A2 of a stage that calls A "B"
            carried = [latex_eqn(eqn, own)[0] for eqn in st.carried]
            stages.append(
                {
                    "number": st.number,
                    "title": st.title,
                    "impact": True,
                    "givens": v["givens"],
                    "stages": v["stages"],
                    "carried": carried,
                }
            )
        else:
            stages.append(
                {
                    "number": st.number,
                    "title": st.title,
                    "impact": False,
                    "blocks": blocks_view(st.blocks, stage_style, layout),
                }
            )
    answers = []
    for i, a in enumerate(sol.answers):
        last = i == len(sol.answers) - 1
        if a.verdict is not None:
            verdict = rf"\boxed{{\text{{Do they collide again? {a.verdict}}}}}"
            answers.append({"latex": verdict + (ANSWER_MARK if last else ""), "tag": None, "boxed": True})
        else:
            assert a.line is not None
            answers.append({**line_view(a.line, style, layout, answer=last), "tag": None})
    givens = [dict(zip(("latex", "note"), _given_latex(g, style), strict=False)) for g in p.givens]
    g_sym = symbol("g", "positive")
    if g_sym in sol.values and "g" not in {g.name for g in p.givens}:
        shown = exact_latex(sol.values[g_sym], style.digits, 1)
        unit = "m/s^2" if p.system == "SI" else "ft/s^2"
        givens.append({"latex": rf"g = {shown}\ {latex_unit(unit)}", "note": "standard gravity, not given"})
    names = [a.name for a in sol.answers]
    find = p.question or ("The quantities " + ", ".join(names).replace("_", " ") + "." if names else "")
    return {
        "answer_names": _answer_names(sol, names),
        "title": p.title,
        "source": p.source,
        "source_parts": source_parts(p.source),
        "statement": _statement(p, style),
        "givens": givens,
        "find": find,
        "stages": stages,
        "answers": answers,
        "standalone": standalone,
    }


def _answer_names(sol: Any, names: list[str]) -> list[tuple[str, str]]:
    """What each answer's name stands for where an impact stage carried it on (u_A is
    v_A2 after A and B collide), as text and mathematics for the answer key's sentence."""
    said: dict[str, tuple[str, str]] = {}
    parts = {st.number: st for st in sol.stages if st.part is not None}
    for number, raw in enumerate(sol.problem.stages, 1):
        if raw.get("type") != "impact" or number not in parts:
            continue
        labels = parts[number].part.problem.labels
        title = str(parts[number].title or f"stage {number}")
        title = "t" + title[1:] if title.startswith("The ") else title
        for slot_name, new in (raw.get("results") or {}).items():
            said.setdefault(str(new), (latex_name(relabel(str(slot_name), labels)), title))
    out: list[tuple[str, str]] = []
    for name in names:
        if name in said:
            slot_tex, title = said[name]
            out += [("text", "; " if out else "Where "), ("math", latex_name(name)), ("text", " is ")]
            out += [("math", slot_tex), ("text", f" after {title}")]
    return [*out, ("text", ".")] if out else []


def _chain_json(sol: Any, digits: int | None) -> str:
    p = sol.problem
    d = digits if digits is not None else p.digits
    results = {}
    for name, r in sol.results.items():
        results[name] = {
            "value": None if r.value is None else float(sympy.N(r.value, 17)),
            "unit": "deg" if r.unit == "deg" else plain_unit(r.unit),
            "expr": str(r.closed),
            "latex": StepPrinter().doprint(r.closed),
        }
        if r.value is not None:
            results[name]["shown"] = format_number(r.value, d)
    givens = _givens_json(p.givens)
    view_ = chain_view(sol, digits, figures=False)
    stages = []
    for st in view_["stages"]:
        subs = st["stages"] if st["impact"] else [{"blocks": st["blocks"]}]
        blocks = [b for sub in subs for b in sub["blocks"]]
        stages.append(
            {
                "number": st["number"],
                "title": st["title"],
                "blocks": [
                    {
                        "text": _text_with_math(b["text"]),
                        "lines": [{"latex": ln["latex"], "tag": ln["tag"]} for ln in b["lines"]],
                    }
                    for b in blocks
                ],
            }
        )
    doc = {
        "title": p.title,
        "kind": "chain",
        "source": p.source,
        "find": list(p.find),
        "givens": givens,
        "results": results,
        "stages": stages,
    }
    return dumps_json(doc)


def render(
    solution: Solution,
    fmt: str = "md",
    *,
    digits: int | None = None,
    figures: bool = True,
    target: str = "github",
    heading_level: int = 1,
    title: bool = True,
    plot: bool = False,
) -> str:
    """``solution`` as text in ``fmt``: 'md', 'tex' (a document), 'tex-fragment', 'html' or 'json'.

    ``digits`` overrides the significant figures (default: the problem's, else
    the textbook rule); ``figures`` False leaves the figures out. ``target`` names
    where Markdown goes: 'github' (also KaTeX, MkDocs), 'jupyter', 'mkdocs' or
    'pandoc' (see :mod:`derive.writers.targets`). ``heading_level`` puts the title at
    that level (1: ``#``/``\\section*``) and the stages below it; ``title`` False
    leaves the title out (the caller's heading stands) and starts the stages at
    ``heading_level``. For a PDF see :func:`derive.writers.pdf.build_pdf`, for Word
    :func:`derive.writers.docx.build_docx`; ``plot`` adds the plot of the outcome against e after the answer.
    """
    if digits is not None and not (isinstance(digits, int) and 1 <= digits <= 10):
        raise InputError("expected a whole number of significant figures from 1 to 10", field="--digits")
    tex_vars = {**_headings(heading_level, title), "fragment_packages": ",".join(FRAGMENT_PACKAGES)}
    if solution.is_chain and plot:
        raise InputError("a chain has several impacts: plot one with 'derive plot PROBLEM --stage N'", field="--plot")
    if fmt == "md":
        page, _ = markdown(
            solution,
            markdown_target(target),
            digits=digits,
            figures=figures,
            heading_level=heading_level,
            show_title=title,
            plot=plot,
        )
        return page
    if solution.is_chain:
        if fmt == "json":
            return _chain_json(solution, digits)
        if fmt in ("tex", "tex-fragment"):
            layout = TEX_DOCUMENT if fmt == "tex" else TEX_FRAGMENT
            data = chain_view(solution, digits, figures, standalone=fmt == "tex", layout=layout)
            return environment("tex").get_template("chain.tex.j2").render(**data, **tex_vars)
        if fmt == "html":
            return _chain_html(chain_view(solution, digits, figures, layout=HTML))
        raise InputError(f"a chain is written as md, tex, pdf, html or json, not {fmt}", field="--format")
    if fmt == "json":
        return to_json(solution, digits)
    if fmt not in FORMATS:
        raise InputError(f"unknown format {fmt!r} (expected one of: {', '.join((*FORMATS, 'pdf'))})", field="--format")
    if fmt == "html":
        return _html(view(solution, digits, figures, plot=plot, layout=HTML))
    layout = TEX_DOCUMENT if fmt == "tex" else TEX_FRAGMENT
    data = view(solution, digits, figures, layout=layout, plot=plot)
    template = "solution.tex.j2" if fmt == "tex" else "fragment.tex.j2"
    return environment("tex").get_template(template).render(**data, **tex_vars)


def _headings(level: int, title: bool) -> dict[str, Any]:
    """The template variables for headings: the title's level, and whether it is shown."""
    if not (isinstance(level, int) and 1 <= level <= 6):
        raise InputError("expected a heading level from 1 to 6", field="--heading-level")
    return {"heading_level": level, "show_title": bool(title)}


def markdown(
    solution: Solution,
    layout: Layout = GITHUB,
    *,
    digits: int | None = None,
    figures: bool = True,
    heading_level: int = 1,
    show_title: bool = True,
    plot: bool = False,
) -> tuple[str, dict[str, str]]:
    """The Markdown for ``layout``, and the figure files it names (``figure-1.svg``: SVG
    text) when the layout writes figures as files for the caller to put beside it."""
    data = (
        chain_view(solution, digits, figures, layout=layout)
        if solution.is_chain
        else view(solution, digits, figures, layout=layout, plot=plot)
    )
    files = _figure_images(data, layout)
    page = (
        environment("md")
        .get_template("chain.md.j2" if solution.is_chain else "solution.md.j2")
        .render(
            **data,
            heading_level=heading_level,
            show_title=show_title,
            figure_images=layout.figures != "inline",
            tags_as_text=layout.tags == "text",
            require_cancel=layout.require_cancel,
            long_lines=layout.long_lines,
            escape_caret=layout.escape_caret,
        )
    )
    return page, files


def _figure_images(data: dict[str, Any], layout: Layout) -> dict[str, str]:
    """Give each figure of the page (a chain's included) the address of its image:
    a data URI, or a file name; the files to write, by name."""
    files: dict[str, str] = {}
    if layout.figures == "inline":
        return files
    stages = [sub for st in data["stages"] for sub in st.get("stages", [st])]
    for stage in stages:
        svg = stage.get("figure_svg")
        if not svg:
            continue
        if layout.figures == "files":
            name = f"figure-{len(files) + 1}.svg"
            files[name] = svg
            stage["figure_src"] = name
        else:
            stage["figure_src"] = "data:image/svg+xml;base64," + base64.b64encode(svg.encode("utf-8")).decode("ascii")
    return files


def boxed_lines(solution: Solution) -> list[str]:
    """The LaTeX of the solution's boxed lines (its answers)."""
    if solution.is_chain:
        return [a["latex"] for a in chain_view(solution, figures=False)["answers"]]
    stages = view(solution, figures=False)["stages"]
    return [ln["latex"] for st in stages for b in st["blocks"] for ln in b["lines"] if ln["boxed"]]


def plain_answers(solution: Solution) -> list[str]:
    """The answers the problem asks for, as short plain text: ``v_A2 = 3.05 e_t - 1.11 e_n m/s``."""
    p = solution.problem
    verdicts = {a.name: a.verdict for a in solution.answers if a.verdict is not None}
    names = [a.name for a in solution.answers] if solution.is_chain else list(p.find)
    out = []
    for name in names:
        if name in verdicts:
            out.append(f"{name}: {verdicts[name]}")
            continue
        t, n = solution.results.get(name + "t"), solution.results.get(name + "n")
        r = solution.results.get(name)
        if not solution.is_chain and p.oblique and name in ("v_A2", "v_B2") and t and n:
            if t.value is not None and n.value is not None:
                sign = "-" if n.value < 0 else "+"
                shown_n = format_number(abs(n.value), p.digits)
                out.append(f"{name} = {format_number(t.value, p.digits)} e_t {sign} {shown_n} e_n {plain_unit(t.unit)}")
        elif r is not None and r.value is not None:
            unit = "°" if r.unit == "deg" else (" " + plain_unit(r.unit) if r.unit else "")
            out.append(f"{name} = {format_number(r.value, p.digits)}{unit}")
    return out


def _result_units(sol: Any) -> dict[sympy.Symbol, str]:
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
