"""The view of any solution: its head (title, Given, Find), its stages and its answers.

A chain's stages are its own; a single impact is a chain of one stage whose title is empty,
that stage holding the notes' four stages. Each stage of the view is a dict: ``number``,
``title``, ``stages`` (an impact's own stages: blocks and figures), ``givens`` and ``carried``
(what an impact takes in and hands on), ``blocks`` (any other stage's lines).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

import sympy

from derive.problem.units import latex_unit
from derive.steps.model import Solution
from derive.symbols import latex_name, relabel, symbol
from derive.writers.printing import Style, exact_latex, latex_eqn
from derive.writers.targets import GITHUB, Layout
from derive.writers.view.givens import given_latex, letter_units, result_units, source_parts, statement, worked_out
from derive.writers.view.lines import ANSWER_MARK, blocks_view, heading_parts, line_view
from derive.writers.view.problem import convention, impact_view


def view(
    solution: Solution,
    digits: int | None = None,
    figures: bool = True,
    *,
    layout: Layout = GITHUB,
    plot: bool = False,
    standalone: bool = True,
) -> dict[str, Any]:
    """The data the page templates need, every formula printed as LaTeX: a chain's givens,
    stages and answers, or a single impact's page as a chain of one stage whose title is empty.

    ``layout`` says where the page goes (:mod:`derive.writers.targets`); ``plot`` adds one
    impact's plot of the outcome against e; ``standalone`` False makes a LaTeX fragment."""
    if not solution.is_chain:
        page = impact_view(solution, digits, figures, layout=layout, plot=plot)
        page["stages"] = [_stage(1, "", stages=page["stages"])]
        return {**page, "answers": [], "answer_names": [], "standalone": standalone}
    p = solution.problem
    style = Style(
        digits if digits is not None else p.digits,
        1,
        solution.values,
        solution.angles,
        decimal=_decimal(p),
        letters=frozenset(g.symbol for g in p.givens if g.value is None),  # an unknown is a letter until solved
        strike=layout.strike,
        letter_units=letter_units(p),
        derived=worked_out(p, solution.values),
    )
    names = [a.name for a in solution.answers]
    quantities = _sentence("The quantities ", [latex_name(n) for n in names], ", ")["text"]  # Find, with no question
    return {
        "answer_names": _answer_names(solution, names),
        "title": p.title,
        "kind": p.kind,
        "source": p.source,
        "source_parts": source_parts(p.source),
        "statement": statement(p, style),
        "givens": _givens(solution, style),
        "find": [("text", p.question)] if p.question or not names else quantities,
        "stages": _stages(solution, style, layout, figures),
        "answers": _answers(solution, style, layout),
        "plot_svg": "",
        "plot_tikz": "",
        "system": p.system,
        "standalone": standalone,
    }


def _stage(number: int, title: str, names: frozenset[str] = frozenset(), **parts: Any) -> dict[str, Any]:
    """A stage of the view: an impact's (``stages``, ``givens``, ``carried``), or any other's
    ``blocks``; ``heading`` its title as text and mathematics, each of the page's ``names`` in
    it typeset (Solve for $e_{\\mathrm{floor}}$), ``title`` the words as the file or stage says them."""
    heading = heading_parts(title, names)
    return {
        "number": number,
        "title": title,
        "heading": heading,
        "stages": [],
        "givens": [],
        "carried": [],
        "blocks": [],
        **parts,
    }


def _names(sol: Solution) -> frozenset[str]:
    """The names of a chain's quantities: its givens and every value its stages found."""
    return frozenset(g.name for g in sol.problem.givens) | frozenset(str(k) for k in sol.values)


def _stages(sol: Solution, style: Style, layout: Layout, figures: bool) -> list[dict[str, Any]]:
    """Each stage of the chain printed: an impact as its own view, any other stage as blocks."""
    stages = []
    names = _names(sol)
    falls: dict[int, bool] = {}
    if figures:  # the figure modules only where a page draws one (JSON draws none)
        from derive.writers.figure import chain_falls

        falls = chain_falls(sol)
    for st in sol.stages:
        stage_style = style if st.values is None else replace(style, values=st.values)
        if st.part is None:
            stages.append(_stage(st.number, st.title, names, blocks=blocks_view(st.blocks, stage_style, layout)))
            continue
        v = impact_view(
            st.part,
            stage_style.digits,
            figures=figures,
            layout=layout,
            outer_letters={**letter_units(sol.problem), **result_units(sol)},
            outer_decimal=_decimal(sol.problem)
            & _stage_data(sol, st),  # g = 9.8: -6.26 e_floor; not a later e_wall = 0.5
            falls=falls.get(st.number, False),
            known=sol.values,
        )
        renamed = set(st.part.names)  # e = e_wall, v_A1 = u_B: the page says e_wall, u_B
        for g, shown in zip(st.part.problem.givens, v["givens"], strict=True):
            if g.name in renamed:
                shown["latex"] = shown["latex"].split(" = ", 1)[1]
        own = replace(stage_style, labels=st.part.problem.labels)  # v_A2 of a stage that calls A "B"
        carried = [latex_eqn(eqn, own)[0] for eqn in st.carried]
        stages.append(_stage(st.number, st.title, names, stages=v["stages"], givens=v["givens"], carried=carried))
    return stages


def _answers(sol: Solution, style: Style, layout: Layout) -> list[dict[str, Any]]:
    """The chain's answers, boxed, each with the ANSWER mark: each is a result the question
    asks for (the file's ``find``, else the last stage's), as the notes mark each asked vector."""
    answers = []
    for a in sol.answers:
        if a.verdict is not None:
            verdict = rf"\boxed{{\text{{Do they collide again? {a.verdict}}}}}"
            answers.append({"latex": verdict + ANSWER_MARK, "tag": None, "boxed": True})
        else:
            assert a.line is not None
            answers.append({**line_view(a.line, _own_data(sol, a.name, style), layout, answer=True), "tag": None})
    return answers


def _decimal(p: Any) -> frozenset:
    """The chain's givens written as decimals."""
    return frozenset(g.symbol for g in p.givens if g.decimal)


def _data(sol: Solution, expr: sympy.Expr) -> set:
    """The chain's givens ``expr`` is worked out from: a name an earlier stage defined, by its closed form."""
    out: set = set()
    for s in expr.free_symbols:
        r = sol.results.get(s.name)
        closed = getattr(r, "closed", None)
        out |= closed.free_symbols if isinstance(closed, sympy.Expr) and closed != s else {s}
    return out


def _stage_data(sol: Solution, st: Any) -> set:
    """The chain's givens an impact stage's own givens are worked out from."""
    out: set = set()
    for g in st.part.problem.givens:
        if isinstance(g.definition, sympy.Expr):
            out |= _data(sol, g.definition)
    return out


def _own_data(sol: Solution, name: str, style: Style) -> Style:
    """The style of an answer in letters: decimal only where its own data are (u_A = 3u/2 - 7eu/2
    of exact data stays exact when a later stage's e_wall = 0.5 is decimal)."""
    r = sol.results.get(name)
    closed = getattr(r, "closed", None)
    if r is None or r.value is not None or not isinstance(closed, sympy.Expr):
        return style
    return replace(style, decimal=style.decimal & _data(sol, closed))


def _givens(sol: Solution, style: Style) -> list[dict[str, str]]:
    """The chain's Given list, with standard gravity where a stage uses it and the file does not give it."""
    p = sol.problem
    givens = [dict(zip(("latex", "note"), given_latex(g, style), strict=False)) for g in p.givens]
    g_sym = symbol("g", "positive")
    if g_sym in sol.values and "g" not in {g.name for g in p.givens}:
        shown = exact_latex(sol.values[g_sym], style.digits, 1)
        unit = "m/s^2" if p.system == "SI" else "ft/s^2"
        givens.append({"latex": rf"g = {shown}\ {latex_unit(unit)}", "note": "standard gravity, not given"})
    return givens


def _answer_names(sol: Solution, names: list[str]) -> list[tuple[str, str]]:
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
            out += [("math", slot_tex), ("text", " after "), *heading_parts(title, _names(sol))]
    return [*out, ("text", ".")] if out else []


_NO_FIGURE = {"figure_svg": "", "figure_tikz": ""}


def problem_view(
    solution: Solution, digits: int | None = None, figures: bool = True, *, layout: Layout = GITHUB, plot: bool = False
) -> dict[str, Any]:
    """``solution``'s view in one problem's shape (a handout's problem, a student's sheet, an LMS
    question): one stage whose title is empty, holding every stage in order (an impact's own
    stages numbered k.1, k.2, ... after a titled one, its givens first and the results it carries
    on last), then a chain's boxed answers as a last stage; ``answers`` the boxed lines of that
    last stage; ``convention`` the sign convention in words (:func:`conventions`)."""
    data = view(solution, digits, figures, layout=layout, plot=plot)
    stages = []
    for st in data["stages"]:
        if not st["title"]:
            stages += st["stages"]
        elif not st["stages"]:
            stages.append({**{k: st[k] for k in ("number", "title", "heading", "blocks")}, **_NO_FIGURE})
        else:
            subs = [
                {
                    **sub,
                    "number": f"{st['number']}.{sub['number']}",
                    "title": f"{st['title']}: {sub['title']}",
                    "heading": [*st["heading"], ("text", f": {sub['title']}")],
                }
                for sub in st["stages"]
            ]
            subs[0] = {
                **subs[0],
                "blocks": [_sentence("Given: ", [g["latex"] for g in st["givens"]], ", "), *subs[0]["blocks"]],
            }
            if st["carried"]:
                subs[-1] = {
                    **subs[-1],
                    "blocks": [*subs[-1]["blocks"], _sentence("Carried to the next stages: ", st["carried"], "; ")],
                }
            stages += subs
    if data["answers"]:
        answer = {
            "number": len(data["stages"]) + 1,
            "title": "Answer",
            "heading": [("text", "Answer")],
            "blocks": [{"text": [], "lines": data["answers"]}],
            "closing": True,  # the answers alone: a document keeps them with what precedes them
        }
        stages.append({**answer, **_NO_FIGURE})
    boxed = [line for block in stages[-1]["blocks"] for line in block["lines"] if line["boxed"]]
    return {**data, "stages": [_stage(1, "", stages=stages)], "answers": boxed, "convention": conventions(data)}


def conventions(data: dict[str, Any]) -> list[tuple[str, str]]:
    """The sign convention of every impact stage of a view (:func:`view`), in words, for a
    student's sheet: each impact's sentence (where n and t point), after the impact's title
    where the chain has more than one ("B strikes the wall: take n ...")."""
    impacts = [st for st in data["stages"] if st["stages"]]
    out: list[tuple[str, str]] = []
    for st in impacts:
        parts = list(convention(st["stages"]))
        if not parts:
            continue
        if len(impacts) > 1:
            kind, first = parts[0]
            if kind == "text" and first.startswith("Take "):
                parts[0] = (kind, "take " + first[len("Take ") :])
            parts[:0] = [*st["heading"], ("text", ": ")]
        out += ([("text", " ")] if out else []) + parts
    return out


def _sentence(lead: str, maths: list[str], between: str) -> dict[str, Any]:
    """A block of one sentence: ``lead`` then each piece of mathematics."""
    text: list[tuple[str, str]] = [("text", lead)]
    for i, m in enumerate(maths):
        text += [("text", between)] if i else []
        text.append(("math", m))
    text.append(("text", "."))
    return {"text": text, "lines": []}
