"""Writing variants: each variant's files and the answer key, into a folder written whole.

Each variant is its own problem solved and written (:mod:`.fill`); with more than a few,
they are made on every core (forked processes, in the order drawn) and written here.
"""

from __future__ import annotations

import os
import time
from collections.abc import Iterator

from derive.errors import DeriveError
from derive.homework.variants.compile import Compiled, compile_problem
from derive.homework.variants.draw import draw
from derive.homework.variants.fill import answers, fill, given_values, sheet, variant_html
from derive.homework.variants.record import Variant
from derive.problem import ChainProblem, Problem

#: What ``derive variants`` writes into its folder (a folder with other files is not replaced).
OWNED = ("variant-*.md", "variant-*.tex", "variant-*.pdf", "variant-*.json", "variant-*.html", "key.csv", "key.json")


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
    problem: Problem | ChainProblem,
    out_dir: str,
    *,
    count: int,
    seed: int,
    fmt: str = "md",
    digits: int | None = None,
    compiled: Compiled | None = None,
) -> list[str]:
    """Draw ``count`` variants and write each (statement and worked solution) and the
    answer key (key.csv, key.json) into ``out_dir``.

    The folder is written whole: into a temporary folder that then takes ``out_dir``'s
    place, so a run stopped at any point leaves the old folder or the new one. Returns
    the one-line errors of the variants that could not be written (a PDF that did not
    compile); the others are written all the same. ``compiled``: the problem compiled
    already (by the caller that also exports it).
    """
    from derive.fileio import folder_atomic

    compiled = compiled or compile_problem(problem)
    chosen = draw(compiled, count, seed)
    width = max(2, len(str(count)))
    failures: list[str] = []
    with folder_atomic(out_dir, owned=OWNED) as folder, _Key(folder, problem, seed, count, compiled.names) as key:
        for v, row, files, error in made(compiled, chosen, fmt, digits, width):
            key.add(v.number, row)
            for name, data in files:
                path = folder / name
                if isinstance(data, bytes):
                    path.write_bytes(data)
                else:
                    path.write_text(data, encoding="utf-8")
            if error:
                failures.append(error)
            _progress(v.number, len(chosen))
    return failures


#: Variants below which one process makes them all (a pool costs more than it saves).
POOL_FROM = 8

_JOB: tuple = ()  # what each forked worker makes its variants of (set before the pool forks)


def made(
    compiled: Compiled, chosen: list[Variant], fmt: str, digits: int | None, width: int
) -> Iterator[tuple[Variant, dict, list[tuple[str, str | bytes]], str]]:
    """Each variant (in the order drawn) with its key row, its files and the error that kept
    them from being written (or ""): on every core where there are many and ``fork`` is there."""
    global _JOB
    import multiprocessing

    workers = min(os.cpu_count() or 1, max(1, len(chosen) // POOL_FROM))
    if workers < 2 or "fork" not in multiprocessing.get_all_start_methods():
        for v in chosen:
            yield _one(compiled, v, fmt, digits, width)
        return
    from concurrent.futures import ProcessPoolExecutor

    _JOB = (compiled, fmt, digits, width)
    try:
        context = multiprocessing.get_context("fork")
        with ProcessPoolExecutor(workers, mp_context=context, initializer=_leave_with, initargs=(os.getpid(),)) as pool:
            yield from pool.map(_job, chosen, chunksize=4)
    finally:
        _JOB = ()


def _leave_with(parent: int) -> None:
    """A worker ends when the process that made it is gone (killed by SIGKILL, say): forked
    workers hold the pipe of their own queue open, so they would otherwise wait on it for ever."""
    import threading

    def watch() -> None:
        while os.getppid() == parent:
            time.sleep(0.5)
        os._exit(1)

    threading.Thread(target=watch, daemon=True).start()


def _job(v: Variant) -> tuple[Variant, dict, list[tuple[str, str | bytes]], str]:
    return _one(*_JOB[:1], v, *_JOB[1:])


def _one(
    compiled: Compiled, v: Variant, fmt: str, digits: int | None, width: int
) -> tuple[Variant, dict, list[tuple[str, str | bytes]], str]:
    stem = f"variant-{v.number:0{width}d}"
    row: dict = {"variant": v.number, "givens": given_values(compiled, v), "results": {}}
    try:
        row["results"] = answers(compiled, v, digits)
        return v, row, _files(compiled, v, stem, fmt, digits, row), ""
    except DeriveError as exc:
        return v, row, [], f"{stem}: {exc}"


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


def _files(
    compiled: Compiled, v: Variant, stem: str, fmt: str, digits: int | None, row: dict
) -> list[tuple[str, str | bytes]]:
    """One variant's files: statement and worked solution (md, tex, html, pdf), or its key row (json)."""
    from derive.fileio import dumps_json

    if fmt == "json":
        return [(f"{stem}.json", dumps_json(row))]
    if fmt == "html":
        student, page = variant_html(compiled, v, stem, digits)
        return [(f"{stem}-problem.html", student), (f"{stem}.html", page)]
    student, page = sheet(compiled, v, fmt, digits), fill(compiled, v, fmt, digits)
    if fmt in ("md", "tex"):
        return [(f"{stem}-problem.{fmt}", student), (f"{stem}.{fmt}", page)]
    from derive.writers.pdf import build_pdf

    return [(f"{stem}-problem.pdf", build_pdf(student)), (f"{stem}.pdf", build_pdf(page))]
