"""The Jinja environments the page templates render in (Markdown and HTML; LaTeX).

jinja2 is imported on first use (``derive solve -f json`` and ``derive check`` never need
it). Compiled templates are kept in Jinja's bytecode cache (``$XDG_CACHE_HOME/derive``, by
default ``~/.cache/derive``: never the temporary folder or the folder a command writes to),
so that a process does not compile them again: Jinja checks
each template's source against the cache (a changed template is compiled afresh), and the
cache files are named by the environment's options and Jinja's version, so an
environment never reads another's code. ``DERIVE_NO_CACHE=1`` turns it off.
"""

from __future__ import annotations

import contextlib
import hashlib
from functools import cache
from typing import TYPE_CHECKING, Any

from derive import escape
from derive.resources import cache_disabled, cache_folder, private, templates_dir

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
        loader=jinja2.FileSystemLoader(str(templates_dir())),
        undefined=jinja2.StrictUndefined,
        bytecode_cache=_bytecode_cache(kind, options),
        **options,
    )
    env.filters["md"] = jinja2.pass_context(_markdown_text)
    env.filters["tex"] = escape.tex
    env.filters["html"] = escape.html_text
    return env


def _bytecode_cache(kind: str, options: dict[str, Any]) -> jinja2.BytecodeCache | None:
    """Jinja's file cache of compiled templates, one set of files per environment's options."""
    import jinja2

    if cache_disabled():
        return None
    key = hashlib.sha256(repr((kind, sorted(options.items()), jinja2.__version__)).encode()).hexdigest()[:16]
    try:
        folder = cache_folder() / "templates"
        folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    except (OSError, RuntimeError):  # no home, or a read-only one: compile each time
        return None
    if not private(folder):  # another user could have written its code: compile each time
        return None

    class Cache(jinja2.FileSystemBytecodeCache):
        """A cache that never stops a page: a file it cannot read or write is compiled afresh."""

        def load_bytecode(self, bucket: jinja2.bccache.Bucket) -> None:
            with contextlib.suppress(OSError):
                super().load_bytecode(bucket)

        def dump_bytecode(self, bucket: jinja2.bccache.Bucket) -> None:
            with contextlib.suppress(OSError):  # a read-only or full disk
                super().dump_bytecode(bucket)

    return Cache(str(folder), pattern=f"__derive_{key}_%s.cache")


def _markdown_text(context: Any, text: str) -> str:
    """User text as Markdown; ``^`` escaped too where the page is for pandoc (``escape_caret``)."""
    return escape.markdown(text, caret=bool(context.get("escape_caret", False)))
