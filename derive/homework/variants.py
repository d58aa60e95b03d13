"""Homework variants: derive a problem once, then evaluate and print it many times.

A problem with a ``[vary]`` table is solved once with the varied givens kept as
symbols. Its worked solution is printed once, every number that depends on them
left open (a slot); each slot and each result is compiled to a plain Python
function. A variant is then a few float evaluations and string joins: no SymPy
solving, no SymPy printing.
"""

from __future__ import annotations

import math
import random
import re
from collections.abc import Iterator
from dataclasses import dataclass, replace
from decimal import Decimal
from typing import Any

import sympy

from derive.errors import InputError
from derive.numbers import format_number, format_places, places_that_add_up
from derive.physics.impact import independent_map
from derive.problem import Given, Problem
from derive.problem.units import plain_unit
from derive.steps.model import Solution
from derive.writers.printing import SIDE_BEGIN, SIDE_END, SlotBook, adds_up, exact_latex, printed_number

_TOKEN = re.compile(r"DRVSLOT(\d+)X")
MAX_ATTEMPTS_PER_VARIANT = 200
#: The most variants one run draws (each is a page or two on disk).
MAX_COUNT = 10_000
#: Draws between looks at the rate of success: where it cannot reach the count, stop.
GIVE_UP_AFTER = 2_000
#: What ``derive variants`` writes into its folder (a folder with other files is not replaced).
OWNED = ("variant-*.md", "variant-*.tex", "variant-*.pdf", "variant-*.json", "key.csv", "key.json")


@dataclass(frozen=True)
class Variant:
    """One drawn variant: its number (1, 2, ...) and the varied givens' exact values."""

    number: int
    values: dict[str, sympy.Expr]


@dataclass
class Compiled:
    """A problem derived once, ready to print any variant."""

    problem: Problem
    solution: Solution
    names: tuple[str, ...]
    givens: dict[str, Given]
    templates: dict[str, list[str | int]]
    book: SlotBook
    slot_fn: object
    claim_fns: dict[int, list[tuple[list[object], object]]]
    result_fns: dict[str, object]
    check_fn: object


def _symbolic(problem: Problem) -> Problem:
    """The problem with its varied givens (and givens defined from them) made symbolic."""
    varied = set(problem.vary)
    givens = []
    changed: set[sympy.Symbol] = set()
    for g in problem.givens:
        if g.name in varied or (g.definition is not None and g.definition.free_symbols & changed):
            g = replace(g, value=None)
            changed.add(g.symbol)
        givens.append(g)
    return replace(problem, givens=tuple(givens))


def _lambdify(symbols: tuple[sympy.Symbol, ...], exprs: list[sympy.Expr]) -> object:
    return sympy.lambdify(symbols, exprs, modules=["math"], cse=True)


def compile_problem(problem: Problem, digits: int | None = None, fmt: str = "md") -> Compiled:
    """Derive ``problem`` once (its varied givens symbolic) and compile its page."""
    from derive.steps import solve
    from derive.writers.targets import GITHUB, TEX_DOCUMENT
    from derive.writers.view import environment, view

    if getattr(problem, "kind", None) == "chain":
        raise InputError(
            "is a chain: derive draws variants of a single impact's [vary] table only", where=problem.path, field="kind"
        )
    if not problem.vary:
        raise InputError("has no [vary] table: nothing to draw variants from", where=problem.path, field="[vary]")
    names = tuple(sorted(problem.vary))
    symbolic = _symbolic(problem)
    solution = solve(symbolic)
    givens = {g.name: g for g in problem.givens}
    symbols = tuple(givens[n].symbol for n in names)
    book = SlotBook()
    layout = TEX_DOCUMENT if fmt in ("tex", "pdf") else GITHUB  # long lines on rows, as a solve's page
    data = view(solution, digits, figures=False, slots=book, varied=frozenset(symbols), layout=layout)
    for entry, stage in zip(data["stages"], solution.stages, strict=True):
        if stage.figure is not None:  # each variant's own figure goes here when it is filled in
            entry["figure_svg"] = entry["figure_tikz"] = FIGURE.format("", stage.figure)
            entry["figure_note_html"] = entry["figure_note_tex"] = FIGURE.format("NOTE", stage.figure)
    templates = {}
    if fmt in ("md", "json"):
        page = environment("md").get_template("solution.md.j2").render(**data)
        templates["md"] = _split(page)
    if fmt in ("tex", "pdf"):
        page = environment("tex").get_template("solution.tex.j2").render(**data)
        templates["tex"] = _split(page)
    fixed = {k: v for k, v in symbolic.numeric().items()}
    ind = independent_map(symbolic)

    def prep(expr: sympy.Expr) -> sympy.Expr:
        return sympy.sympify(expr).xreplace(ind).xreplace(fixed)

    slot_fn = _lambdify(symbols, [prep(s.expr) for s in book.slots]) if book.slots else None
    claim_fns = {
        block: [
            (_lambdify(symbols, [prep(t) for t in terms]), _lambdify(symbols, prep(total))) for terms, total in claims
        ]
        for block, claims in book.claims.items()
    }
    # a result that needs no varied given is a number already: ``value`` (an angle in degrees;
    # its ``partial`` would be radians, atan2(x, 0) = pi/2)
    results = {name: r.value if r.value is not None else r.partial for name, r in solution.results.items()}
    result_fns = {name: _lambdify(symbols, prep(expr)) for name, expr in results.items()}
    check_fn = _checks(symbolic, symbols, results, prep)
    return Compiled(problem, solution, names, givens, templates, book, slot_fn, claim_fns, result_fns, check_fn)


def _split(page: str) -> list[str | int]:
    parts: list[str | int] = []
    pos = 0
    for m in _TOKEN.finditer(page):
        parts.append(page[pos : m.start()])
        parts.append(int(m.group(1)))
        pos = m.end()
    parts.append(page[pos:])
    return parts


def _checks(problem: Problem, symbols: tuple[sympy.Symbol, ...], results: dict[str, sympy.Expr], prep) -> object:
    """One function of the varied values that is True for a physical variant: the
    bodies approach, e in [0, 1], masses positive, and the file's conditions hold.

    An unknown of an inverse problem (``e = "?"``, ``m_B = "? kg"``) is checked as the
    variant solves it, so a draw that makes it unphysical (e > 1, a negative mass) is
    refused. A built-in check on a given kept as a letter (``m = "kg"``: positive by
    its assumptions) is left out: it has no number to check."""
    allowed = set(symbols)

    def solved(expr: sympy.Expr) -> sympy.Expr:
        # by name: an unknown's symbol (e, with its assumptions) is not the condition's e
        expr = sympy.sympify(expr)
        to_results = {s: results[s.name] for s in expr.free_symbols if s.name in results and s not in allowed}
        return prep(expr.xreplace(to_results))

    sym = problem.symbols()
    built_in = [(solved(problem.motion_A.n - problem.motion_B.n), ">")]
    for name in ("m_A", "m_B"):
        if name in sym:
            built_in.append((solved(sym[name]), ">"))
    e = solved(sym["e"])
    built_in += [(e, ">="), (1 - e, ">=")]
    lower = [(x, op) for x, op in built_in if x.free_symbols <= allowed]
    for c in problem.conditions:
        diff = solved(c.lhs - c.rhs)
        if not diff.free_symbols <= allowed:
            names = ", ".join(sorted(str(s) for s in diff.free_symbols - allowed))
            raise InputError(f"{c.text} depends on {names}, which no variant gives a number", field="conditions")
        lower.append((diff if c.op in (">", ">=") else -diff, ">" if c.op in ("<", ">") else ">="))
    if not lower:
        return lambda *args: True
    fn = _lambdify(symbols, [x for x, _ in lower])
    ops = [op for _, op in lower]

    def ok(*args: float) -> bool:
        try:
            vals = fn(*args)
        except (ZeroDivisionError, ValueError, OverflowError):
            return False
        for v, op in zip(vals, ops, strict=True):
            v = complex(v)
            if abs(v.imag) > 1e-12 or not math.isfinite(v.real):
                return False
            if (op == ">" and not v.real > 1e-12) or (op == ">=" and not v.real >= -1e-12):
                return False
        return True

    return ok


def draw(compiled: Compiled, count: int, seed: int) -> list[Variant]:
    """``count`` distinct physical variants, the same for the same seed and file anywhere."""
    p = compiled.problem
    rng = random.Random(seed)
    pools = [p.vary[n] for n in compiled.names]
    seen: set[tuple[int, ...]] = set()
    out: list[Variant] = []
    attempts = 0
    total = math.prod(len(x) for x in pools)
    budget = MAX_ATTEMPTS_PER_VARIANT * count
    while len(out) < count and attempts < budget and len(seen) < total:
        attempts += 1
        if attempts % GIVE_UP_AFTER == 0 and len(out) * (budget - attempts) < (count - len(out)) * attempts:
            raise InputError(
                f"{len(out)} of the first {attempts:,} draws {_what_is_met(p)}; at that rate {count} variants "
                "cannot be found: check the conditions and the [vary] ranges",
                where=p.path,
                field="--count",
            )
        key = tuple(rng.randrange(len(pool)) for pool in pools)
        if key in seen:
            continue
        seen.add(key)
        values = {n: pool[i] for n, pool, i in zip(compiled.names, pools, key, strict=True)}
        if compiled.check_fn(*(float(v) for v in values.values())):
            out.append(Variant(len(out) + 1, values))
    if len(out) < count:
        raise InputError(
            f"only {len(out)} distinct physical variants found for {count} asked "
            "(widen the [vary] ranges or relax the conditions)",
            where=p.path,
            field="--count",
        )
    return out


def _what_is_met(problem: Problem) -> str:
    if problem.conditions:
        return "meet " + " and ".join(c.text for c in problem.conditions)
    return "are physical (bodies that approach, 0 <= e <= 1, positive masses)"


def given_text(g: Given, value: sympy.Expr, digits: int | None) -> str:
    if g.unit == "deg":
        return exact_latex(value * 180 / sympy.pi, digits, 1)
    return exact_latex(value, digits, 1)


def _places(claims: list[tuple[object, object]], args: list[float], digits: int | None, extra: int) -> int:
    """Places after the point for a block, so that its sums add up (as printing does)."""
    sums = []
    for terms_fn, total_fn in claims:
        terms = [Decimal(repr(float(t))) for t in terms_fn(*args)]
        sums.append((terms, Decimal(repr(float(total_fn(*args))))))
    # a compiled page shows every line, so a variant may carry up to three more places
    return places_that_add_up(sums, digits, extra, more=3)


def _allowed(x: float, digits: int | None, extra: int) -> int:
    """Significant figures a number at ``digits`` (+``extra``) shows."""
    return len(Decimal(format_number(Decimal(repr(float(x))), digits, extra=extra).split("e")[0]).as_tuple().digits)


def _number(x: float, digits: int | None, extra: int, integers: bool, places: int | None) -> str:
    if integers and abs(x) < 1e9:
        for k in range(3):  # an exact short number (20, 7.5, 0.25), as a given is printed
            scaled = x * 10**k
            if abs(scaled - round(scaled)) < 1e-9 * max(1.0, abs(scaled)):
                exact = Decimal(round(scaled)).scaleb(-k) if k else Decimal(round(x))
                if k and len(exact.normalize().as_tuple().digits) > _allowed(x, digits, extra):
                    break  # exact, but more figures than an intermediate shows: 857.3, not 857.25
                return str(exact) if k else str(round(x))
    d = Decimal(repr(float(x)))
    if places is not None:  # the block's places, never more figures than the rule (-121.2, not -121.22)
        return format_places(d, places, digits, extra)
    text = format_number(d, digits, extra=extra)
    if "e" in text:
        mant, exp = text.split("e")
        return rf"{mant} \times 10^{{{int(exp)}}}"
    return text


def fill(compiled: Compiled, variant: Variant, fmt: str = "md", digits: int | None = None) -> str:
    """The worked solution of one variant, from the compiled page."""
    p = compiled.problem
    d = digits if digits is not None else p.digits
    args = [float(variant.values[n]) for n in compiled.names]
    numbers = compiled.slot_fn(*args) if compiled.slot_fn is not None else []
    places = {b: _places(c, args, d, 1) for b, c in compiled.claim_fns.items()}
    texts = {compiled.givens[n].symbol: given_text(compiled.givens[n], variant.values[n], d) for n in compiled.names}
    angles = {compiled.givens[n].symbol for n in compiled.names if compiled.givens[n].unit == "deg"}
    out = []
    for part in compiled.templates["tex" if fmt in ("tex", "pdf") else "md"]:
        if isinstance(part, str):
            out.append(part)
            continue
        slot = compiled.book.slots[part]
        kind = slot.kind
        if kind in ("given", "text"):
            text = texts[slot.expr]
            if kind == "given" and slot.expr in angles:
                text += r"^\circ"  # cos 45°, as the substitution lines of a solution write it
            out.append(rf"\left({text}\right)" if kind == "given" and text.startswith("-") else text)
            continue
        if isinstance(slot.expr, sympy.Symbol) and slot.expr in texts and kind.endswith("number"):
            text = texts[slot.expr]  # a given's own number, as written
            neg = text.startswith("-")
            role = kind.partition(":")[0] if ":" in kind else ""
            if role.startswith("signed"):
                out.append((" - " if neg else " + ") + text.lstrip("-"))
            elif role.startswith("lead") or not neg:
                out.append(text)
            else:
                out.append(rf"\left({text}\right)")
            continue
        x = complex(numbers[part]).real
        role, _, what = kind.partition(":") if ":" in kind else ("", "", kind)
        result = what == "result"
        text = _number(abs(x) if role else x, d, slot.extra, not result, None if result else places.get(slot.block))
        if role.endswith("coef") and text == "1":
            text = ""
        if role.startswith("signed"):
            out.append((" - " if x < 0 else " + ") + text)
        elif role.startswith("lead"):
            out.append(("-" if x < 0 else "") + text)
        else:
            out.append(text)
    page = _optional_sides(_optional_lines("".join(out), places))
    return _figures(compiled, variant, page, fmt)


#: Where a stage's figure ("before" or "after" the impact), and the note under it, go in
#: a compiled page.
FIGURE = "DRVFIGURE{}-{}-X"


def _figures(compiled: Compiled, variant: Variant, page: str, fmt: str) -> str:
    """The variant's figures put in: drawn from its own numbers (the figure reads the
    compiled solution's closed forms at them; no solve), each with its note, if any (a
    line with an empty note is left out)."""
    from derive.writers.view import figure_entry

    tex = fmt in ("tex", "pdf")
    for when in ("before", "after"):
        if FIGURE.format("", when) not in page:
            continue
        entry = figure_entry(drawing(compiled, variant, when))
        page = page.replace(FIGURE.format("", when), entry["figure_tikz" if tex else "figure_svg"])
        note = entry["figure_note_tex" if tex else "figure_note_html"]
        marker = FIGURE.format("NOTE", when)
        page = page.replace(marker, note) if note else re.sub(rf"^.*{marker}.*\n", "", page, flags=re.M)
    return page


def drawing(compiled: Compiled, variant: Variant, when: str = "before") -> Any:
    """One variant's figure (a :class:`derive.writers.figure.Figure`), before or after the impact."""
    from derive.writers import figure

    values = {compiled.givens[n].symbol: variant.values[n] for n in compiled.names}
    return figure.describe(compiled.solution, when == "after", values=values)


def _optional_lines(page: str, places: dict[int, int | None]) -> str:
    """The page with each optional line (a sum shown term by term) kept where its block's
    numbers add up at fixed places, and dropped with its display where they do not."""
    from derive.writers.view import OPTIONAL_BEGIN, OPTIONAL_END

    begin, end = re.escape(OPTIONAL_BEGIN), re.escape(OPTIONAL_END)

    def drop(m: re.Match[str]) -> str:
        return "" if places.get(int(m.group(1))) is None else m.group(0)

    display = rf"(?:\$\$\n|\\begin\{{equation\*\}}\n){begin}(\d+)%.*?{end}.*?(?:\$\$\n\n|\\end\{{equation\*\}}\n)"
    page = re.sub(display, drop, page, flags=re.S)
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


def answers(compiled: Compiled, variant: Variant, digits: int | None = None) -> dict[str, dict]:
    """The answer key of one variant: each result's value, unit and shown text."""
    p = compiled.problem
    d = digits if digits is not None else p.digits
    args = [float(variant.values[n]) for n in compiled.names]
    out = {}
    for name, fn in compiled.result_fns.items():
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
            "shown": format_number(Decimal(repr(x)), d),
        }
    return out


def given_values(compiled: Compiled, variant: Variant) -> dict[str, dict]:
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


def statement_only(page: str, figure: str = "") -> str:
    """The part of a worked page a student gets: up to the solution (Markdown, or a
    LaTeX document, which is then closed), without the Source line (citations quote
    the published answers), with ``figure`` (SVG or TikZ: the set-up) after Find."""
    if TEX_SOLUTION in page:
        head = page[: page.index(TEX_SOLUTION)]
        head = re.sub(r"^\{\\raggedright\\noindent\{\\itshape Source: .*\n", "", head, flags=re.M)
        shown = f"\n\n\\begin{{center}}\n{figure}\n\\end{{center}}" if figure else ""
        return head.rstrip() + shown + "\n\n\\end{document}\n"
    cut = page.find("**Solution.**")
    head = page if cut < 0 else page[:cut]
    head = re.sub(r"^\*Source: .*\n\n?", "", head, flags=re.M)
    shown = f'\n\n<div align="center">{figure}</div>' if figure else ""
    return head.rstrip() + shown + "\n"


def setup_figure(compiled: Compiled, variant: Variant, fmt: str = "md") -> str:
    """A variant's figure before the impact (which way +n points, its own speeds) as SVG
    or (tex, pdf) TikZ, for the student's statement; empty when its page has none."""
    if not any(s.figure == "before" for s in compiled.solution.stages):
        return ""
    from derive.writers import figure

    drawn = drawing(compiled, variant, "before")
    return figure.to_tikz(drawn) if fmt in ("tex", "pdf") else figure.to_svg(drawn)


def iterate(
    compiled: Compiled, variants: list[Variant], fmt: str = "md", digits: int | None = None
) -> Iterator[tuple[Variant, str]]:
    """Each variant with its page, one at a time (nothing kept in memory)."""
    for v in variants:
        yield v, fill(compiled, v, fmt, digits)


# ------------------------------------------------------------------ writing


def _progress(done: int, total: int) -> None:
    """A progress bar on stderr, only on a terminal."""
    import sys

    if not sys.stderr.isatty():
        return
    width = 30
    filled = int(width * done / total)
    sys.stderr.write(f"\r[{'#' * filled}{'.' * (width - filled)}] {done}/{total}")
    if done == total:
        sys.stderr.write("\n")
    sys.stderr.flush()


def write_variants(
    problem: Problem, out_dir: str, *, count: int, seed: int, fmt: str = "md", digits: int | None = None
) -> list[str]:
    """Draw ``count`` variants and write each (statement and worked solution) and the
    answer key (key.csv, key.json) into ``out_dir``.

    The folder is written whole: into a temporary folder that then takes ``out_dir``'s
    place, so a run stopped at any point leaves the old folder or the new one. Returns
    the one-line errors of the variants that could not be written (a PDF that did not
    compile); the others are written all the same.
    """
    from derive.errors import DeriveError
    from derive.fileio import folder_atomic

    compiled = compile_problem(problem, digits, fmt)
    chosen = draw(compiled, count, seed)
    width = max(2, len(str(count)))
    failures: list[str] = []
    with folder_atomic(out_dir, owned=OWNED) as folder, _Key(folder, problem, seed, count, compiled.names) as key:
        for v in chosen:
            stem = f"variant-{v.number:0{width}d}"
            row = {"variant": v.number, "givens": given_values(compiled, v), "results": answers(compiled, v, digits)}
            key.add(v.number, row)
            try:
                _write_one(compiled, v, folder, stem, fmt, digits, row)
            except DeriveError as exc:
                failures.append(f"{stem}: {exc}")
            _progress(v.number, len(chosen))
    return failures


class _Key:
    """The answer key, streamed to key.csv and key.json as the variants are written
    (memory stays flat however many are drawn)."""

    def __init__(self, folder, problem: Problem, seed: int, count: int, names: tuple[str, ...]) -> None:
        self.folder, self.names = folder, list(names)
        self.head = {"title": problem.title, "source": problem.source, "seed": seed, "count": count}
        self.result_names: list[str] = []

    def __enter__(self) -> _Key:
        import csv

        from derive.fileio import dumps_json

        self.csv_fh = open(self.folder / "key.csv", "w", newline="", encoding="utf-8")
        self.json_fh = open(self.folder / "key.json", "w", encoding="utf-8")
        self.writer = csv.writer(self.csv_fh, lineterminator="\n")
        self.json_fh.write(dumps_json(self.head)[:-3] + ',\n  "variants": [\n')
        return self

    def add(self, number: int, row: dict) -> None:
        """One variant's row: its givens and results."""
        import textwrap

        from derive.fileio import dumps_json

        if not self.result_names:
            self.result_names = list(row["results"])
            header = ["variant"]
            header += [f"{n} [{row['givens'][n]['unit']}]" for n in self.names]
            header += [f"{n} [{row['results'][n]['unit']}]" for n in self.result_names]
            self.writer.writerow(header)
        cells = [number, *(repr(row["givens"][n]["value"]) for n in self.names)]
        cells += [row["results"][n]["shown"] if n in row["results"] else "" for n in self.result_names]
        self.writer.writerow(cells)
        sep = ",\n" if number > 1 else ""
        self.json_fh.write(sep + textwrap.indent(dumps_json(row).rstrip("\n"), "    "))

    def __exit__(self, *exc: object) -> None:
        if exc[0] is None:
            self.json_fh.write("\n  ]\n}\n")
        self.csv_fh.close()
        self.json_fh.close()


def _write_one(compiled: Compiled, v: Variant, folder, stem: str, fmt: str, digits: int | None, row: dict) -> None:
    """One variant's files: statement and worked solution (md), LaTeX, PDF or JSON."""
    from derive.fileio import dumps_json

    if fmt == "json":
        (folder / f"{stem}.json").write_text(dumps_json(row), encoding="utf-8")
    elif fmt == "md":
        page = fill(compiled, v, "md", digits)
        sheet = statement_only(page, setup_figure(compiled, v, "md"))
        (folder / f"{stem}-problem.md").write_text(sheet, encoding="utf-8")
        (folder / f"{stem}.md").write_text(page, encoding="utf-8")
    else:
        tex = fill(compiled, v, "tex", digits)
        if fmt == "tex":
            sheet = statement_only(tex, setup_figure(compiled, v, "tex"))
            (folder / f"{stem}-problem.tex").write_text(sheet, encoding="utf-8")
            (folder / f"{stem}.tex").write_text(tex, encoding="utf-8")
        else:
            from derive.writers.pdf import build_pdf

            (folder / f"{stem}-problem.pdf").write_bytes(
                build_pdf(statement_only(tex, setup_figure(compiled, v, "tex")))
            )
            (folder / f"{stem}.pdf").write_bytes(build_pdf(tex))
