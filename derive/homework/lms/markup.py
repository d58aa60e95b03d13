"""The HTML an LMS shows, built by the page's HTML writer (:func:`derive.writers.view.html.lms_html`)
from a variant's page data: text that never turns into math, the math for MathJax."""

from __future__ import annotations

import re
from typing import Any

from derive import escape
from derive.problem import ChainProblem
from derive.writers.view import student_sheet
from derive.writers.view.html import lms_html

_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")

#: ``text`` HTML-escaped (quotes left as they are).
esc = escape.html_body

#: Classes MathJax 3 (PrairieLearn, Moodle 4.5+) and MathJax 2 (older Moodle) skip.
_NO_MATH = "mathjax_ignore tex2jax_ignore"


def words(text: str) -> str:
    """A file's text (a title, a statement's words) as HTML that never turns into math:
    ``$`` and ``\\`` as character references, so a filter reading the HTML source (Moodle's
    TeX filter) finds no delimiter, and inside a span MathJax is told to skip, so the
    decoded text (``$5 or $10``, ``\\(x\\)``) is not typeset either."""
    out = esc(text)
    if "$" not in out and "\\" not in out:
        return out
    out = out.replace("$", "&#36;").replace("\\", "&#92;")
    return f'<span class="{_NO_MATH}">{out}</span>'


def statement_html(data: dict[str, Any]) -> str:
    """A variant's statement (Given, Find) as LMS HTML, as a student's sheet reads: no title,
    no Source line (citations quote the published answers), an unknown given "to find", and
    the sign convention in words (which way +n points: the answer is a signed component)."""
    sheet = student_sheet({**data, "givens": [dict(g) for g in data["givens"]]})  # the page left as it was
    return lms_html(sheet, "statement", words).strip()


def solution_html(data: dict[str, Any]) -> str:
    """A variant's worked solution (from **Solution.** on) as LMS HTML, without its figures."""
    return lms_html(data, "solution", words).strip()


def result_html(compiled: Any, name: str) -> str:
    """What the asked result is, as HTML for the sentence that asks for it: "the " and its
    description; a chain's as :func:`~derive.homework.variants.chain.chain_result_words` says
    it (\\(v_{A2}\\) after A and B collide), its mathematics for MathJax."""
    from derive.homework.variants.chain import chain_result_words

    if isinstance(compiled.problem, ChainProblem):
        parts = chain_result_words(compiled, name)
    else:
        parts = [("text", "the " + compiled.solution.results[name].description)]
    return "".join(rf"\({esc(s)}\)" if kind == "math" else esc(s) for kind, s in parts)


def clean_xml(text: str) -> str:
    """Text that XML 1.0 can hold (control characters dropped)."""
    return _XML_BAD.sub("", text)
