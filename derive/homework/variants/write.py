"""Writing variants: each variant's files and the answer key, into a folder written whole."""

from __future__ import annotations

from derive.homework.variants.chain import ChainCompiled, chain_html
from derive.homework.variants.compile import Compiled, compile_problem
from derive.homework.variants.draw import draw
from derive.homework.variants.fill import (
    answers,
    fill,
    fill_view,
    given_values,
    setup_figure,
    sign_convention,
    statement_only,
)
from derive.homework.variants.record import Variant
from derive.problem import ChainProblem, Problem

#: What ``derive variants`` writes into its folder (a folder with other files is not replaced).
OWNED = (
    "variant-*.md",
    "variant-*.tex",
    "variant-*.pdf",
    "variant-*.json",
    "variant-*.html",
    "key.csv",
    "key.json",
)


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
    problem: Problem | ChainProblem, out_dir: str, *, count: int, seed: int, fmt: str = "md", digits: int | None = None
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


def _write_one(
    compiled: Compiled | ChainCompiled, v: Variant, folder, stem: str, fmt: str, digits: int | None, row: dict
) -> None:
    """One variant's files: statement and worked solution (md, html), LaTeX, PDF or JSON."""
    from derive.fileio import dumps_json

    if fmt == "json":
        (folder / f"{stem}.json").write_text(dumps_json(row), encoding="utf-8")
    elif fmt == "html":
        sheet, page = variant_html(compiled, v, stem, digits)
        (folder / f"{stem}-problem.html").write_text(sheet, encoding="utf-8")
        (folder / f"{stem}.html").write_text(page, encoding="utf-8")
    elif fmt == "md":
        page = fill(compiled, v, "md", digits)
        sheet = statement_only(page, setup_figure(compiled, v, "md"), sign_convention(compiled, "md"))
        (folder / f"{stem}-problem.md").write_text(sheet, encoding="utf-8")
        (folder / f"{stem}.md").write_text(page, encoding="utf-8")
    else:
        tex = fill(compiled, v, "tex", digits)
        if fmt == "tex":
            sheet = statement_only(tex, setup_figure(compiled, v, "tex"), sign_convention(compiled, "tex"))
            (folder / f"{stem}-problem.tex").write_text(sheet, encoding="utf-8")
            (folder / f"{stem}.tex").write_text(tex, encoding="utf-8")
        else:
            from derive.writers.pdf import build_pdf

            (folder / f"{stem}-problem.pdf").write_bytes(
                build_pdf(statement_only(tex, setup_figure(compiled, v, "tex"), sign_convention(compiled, "tex")))
            )
            (folder / f"{stem}.pdf").write_bytes(build_pdf(tex))


def variant_html(
    compiled: Compiled | ChainCompiled, v: Variant, stem: str, digits: int | None = None
) -> tuple[str, str]:
    """One variant as HTML, typeset together: a student's sheet (Given, Find, the set-up before
    the impact, the sign convention in words; no Source line, no answers) and the worked solution."""
    import copy

    if compiled.is_chain:
        return chain_html(compiled, v, stem, digits)

    from derive.writers.view import student_sheet
    from derive.writers.view.html import html_pages as typeset

    page = fill_view(compiled, v, digits)
    student = student_sheet(copy.deepcopy(page))
    student.update(title=stem.replace("variant-", "Variant "), setup_svg=setup_figure(compiled, v, "html"))
    sheet = {"title": compiled.problem.title, "mode": "problems", "problems": [student], "theory": None}
    student_page, worked = typeset([("handout", {**sheet, "numbered": False}), ("solution", page)])
    return student_page, worked
