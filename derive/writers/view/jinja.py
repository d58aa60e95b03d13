"""The Jinja environments the page templates render in (Markdown and HTML; LaTeX).

jinja2 is imported on first use (``derive solve -f json`` and ``derive check`` never need
it). Templates are loaded from the package's folder and compiled in memory, once a process;
nothing is written to disk.
"""

from __future__ import annotations

from functools import cache
from typing import TYPE_CHECKING, Any

from derive import escape
from derive.resources import templates_dir

if TYPE_CHECKING:
    import jinja2


def _options(kind: str) -> dict[str, Any]:
    """The environment's syntax options: LaTeX templates use \\BLOCK{} / \\VAR{} delimiters."""
    options: dict[str, Any] = dict(autoescape=False, keep_trailing_newline=True, trim_blocks=True, lstrip_blocks=True)
    if kind == "tex":
        options.update(
            block_start_string=r"\BLOCK{",
            block_end_string="}",
            variable_start_string=r"\VAR{",
            variable_end_string="}",
            comment_start_string=r"\#{",
            comment_end_string="}",
            line_statement_prefix=None,
            line_comment_prefix=None,
        )
    return options


@cache
def environment(kind: str) -> jinja2.Environment:
    """The strict Jinja environment; LaTeX templates use \\BLOCK{} / \\VAR{} delimiters."""
    import jinja2

    options = _options(kind)
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(templates_dir())), undefined=jinja2.StrictUndefined, **options
    )
    env.filters["md"] = jinja2.pass_context(_markdown_text)
    env.filters["tex"] = escape.tex
    env.filters["html"] = escape.html_text
    return env


def _markdown_text(context: Any, text: str) -> str:
    """User text as Markdown; ``^`` escaped too where the page is for pandoc (``escape_caret``)."""
    return escape.markdown(text, caret=bool(context.get("escape_caret", False)))
