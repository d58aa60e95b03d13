"""The Jinja environments the page templates render in (Markdown and HTML; LaTeX)."""

from __future__ import annotations

from functools import cache
from typing import Any

import jinja2

from derive import escape
from derive.resources import templates_dir


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


@jinja2.pass_context
def _markdown_text(context: jinja2.runtime.Context, text: str) -> str:
    """User text as Markdown; ``^`` escaped too where the page is for pandoc (``escape_caret``)."""
    return escape.markdown(text, caret=bool(context.get("escape_caret", False)))
