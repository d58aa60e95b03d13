"""Handouts: several problems gathered into one document.

A handout has a title, an optional theory page in the notes' layout (the three
systems and equations (1)-(4), from :mod:`derive.theory`), then each problem as
a section, in one of three modes:

- ``problems``: the heading, Given and Find, the set-up before the impact and (HTML)
  the sign convention in words; no Source line, no answers (a student's sheet);
- ``answers``: the same, followed by the boxed answer lines of stage 4;
- ``solutions``: the full worked solution, stages 1-4 with their figures.

Every problem is printed by :func:`derive.writers.view`, as a single solution
is. A problem that fails to load or solve is left out and reported; the others
are still included.

>>> doc, failures = build_handout(["notes-4c11-two-spheres"], title="Impact", theory=False,
...                               mode="answers", fmt="md")  # doctest: +SKIP
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Literal, NamedTuple

from derive.errors import DeriveError, InputError
from derive.homework import theory as theory_page
from derive.problem import load
from derive.steps import solve
from derive.writers.pdf import build_pdf
from derive.writers.targets import GITHUB, HTML, TEX_DOCUMENT, Layout
from derive.writers.view import check_digits, environment, problem_view, student_sheet
from derive.writers.view.html import html_pages

Mode = Literal["problems", "answers", "solutions"]
Format = Literal["md", "tex", "pdf", "html"]
MODES: tuple[str, ...] = ("problems", "answers", "solutions")
FORMATS: tuple[str, ...] = ("md", "tex", "pdf", "html")
#: The layout of each format's pages: long lines on rows as a solve's page of that format.
LAYOUTS = {"md": GITHUB, "html": HTML, "tex": TEX_DOCUMENT, "pdf": TEX_DOCUMENT}

#: The title of a handout when none is given, by mode.
DEFAULT_TITLES = {
    "problems": "Central impact: problems",
    "answers": "Central impact: problems and answers",
    "solutions": "Central impact: worked solutions",
}


class Failure(NamedTuple):
    """A problem left out of a handout: as it was named, and why (one line)."""

    problem: str
    error: str

    def line(self) -> str:
        """The error, naming the problem unless the message already does."""
        return self.error if self.problem in self.error else f"{self.problem}: {self.error}"


class NoProblemsError(InputError):
    """Not one problem of a handout could be included; ``failures`` says why for each."""

    def __init__(self, failures: list[Failure]) -> None:
        super().__init__(f"none of the {len(failures)} problems could be included; the handout was not written")
        self.failures = failures


def _one_line(text: str) -> str:
    return " ".join(text.split())


def _problem_view(
    name: str | Path, mode: str, digits: int | None, plot: bool = False, layout: Layout = GITHUB
) -> dict[str, Any]:
    """One problem as the handout templates need it: :func:`problem_view`, one problem's shape
    with its boxed answer lines."""
    solution = solve(load(name))
    data = problem_view(solution, digits, mode != "answers", layout=layout, plot=plot and mode == "solutions")
    if mode == "problems":
        # a student's sheet: the set-up figure (before the impact: which way +n points), and
        # no Source line (citations quote the published answers)
        stages = data["stages"][0]["stages"]
        data["setup_svg"] = next((st["figure_svg"] for st in stages if st.get("figure_svg")), "")
        data["setup_tikz"] = next((st["figure_tikz"] for st in stages if st.get("figure_tikz")), "")
        student_sheet(data)
    return data


def build_handout(
    problems: list[str | Path],
    *,
    title: str,
    theory: bool = True,
    mode: Mode = "solutions",
    fmt: Format = "md",
    digits: int | None = None,
    plot: bool = False,
) -> tuple[str | bytes, list[Failure]]:
    """Gather ``problems`` (paths or bundled names) into one document.

    Parameters
    ----------
    problems
        Problem files, or names of bundled problems, in the order they appear.
    title
        The handout's title.
    theory
        Whether a theory page (the three systems, equations (1)-(4)) comes first.
    mode
        ``"problems"``, ``"answers"`` or ``"solutions"`` (see the module docstring).
    fmt
        ``"md"``, ``"tex"`` or ``"html"`` (text: HTML is one self-contained page in the
        style of ``derive solve -f html``), or ``"pdf"`` (bytes, compiled by LaTeX).
    digits
        Significant figures (default: each problem's own, else the textbook rule).
    plot
        In ``solutions`` mode, each single impact's plot of the outcome against e
        after its answer (chains are left without).

    Returns
    -------
    The document, and the problems left out with a one-line reason each.

    Raises
    ------
    InputError
        A bad mode, format or ``digits``; :class:`NoProblemsError` when no problem
        could be included.
    """
    _check(problems, mode, fmt, digits)
    views, failures = [], []
    for name in problems:
        try:
            views.append(_problem_view(name, mode, digits, plot, LAYOUTS[fmt]))
        except DeriveError as exc:
            failures.append(Failure(str(name), _one_line(str(exc))))
        except Exception as exc:  # a bug with one problem must not lose the others
            failures.append(Failure(str(name), _one_line(f"internal error ({type(exc).__name__}: {exc})")))
    if not views:
        raise NoProblemsError(failures)
    data = {"title": title, "mode": mode, "problems": views, "theory": theory_page.view() if theory else None}
    return _document(data, fmt), failures


def _check(problems: list[str | Path], mode: str, fmt: str, digits: int | None) -> None:
    """A handout's options, checked before any problem is solved."""
    if mode not in MODES:
        raise InputError(f"unknown mode {mode!r} (expected one of: {', '.join(MODES)})", field="--mode")
    if fmt not in FORMATS:
        raise InputError(f"unknown handout format {fmt!r} (expected one of: {', '.join(FORMATS)})", field="format")
    check_digits(digits)
    if not problems:
        raise InputError("a handout needs at least one problem")


def _document(data: dict[str, Any], fmt: str) -> str | bytes:
    """The handout's data as a document: Markdown, HTML, LaTeX or (bytes) PDF."""
    if fmt == "md":
        return environment("md").get_template("handout.md.j2").render(**data)
    if fmt == "html":
        return html_pages([("handout", data)])[0]
    tex = environment("tex").get_template("handout.tex.j2").render(**data)
    return tex if fmt == "tex" else build_pdf(tex)
