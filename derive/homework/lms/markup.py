"""derive's Markdown as the simple HTML an LMS shows: headings, paragraphs, lists, math
for MathJax, and text that never turns into math; a statement page and its solution cut apart."""

from __future__ import annotations

import html
import re

#: Where a variant's page turns from the statement to the worked solution.
SOLUTION = "**Solution.**"
_XML_BAD = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")


def md_to_html(md: str) -> str:
    """derive's Markdown as simple HTML: headings, paragraphs, lists, **bold**, *italics*,
    inline math as ``\\( \\)`` and display math (``$$ … $$``) as ``\\[ \\]`` for MathJax.

    Text is HTML-escaped; raw HTML in the Markdown (a figure) is left out.
    """
    out: list[str] = []
    para: list[str] = []
    items: list[str] = []

    def flush() -> None:
        if para:
            out.append(f"<p>{_inline(' '.join(para))}</p>")
            para.clear()
        if items:
            out.append("<ul>" + "".join(f"<li>{_inline(x)}</li>" for x in items) + "</ul>")
            items.clear()

    lines = md.splitlines()
    i = 0
    while i < len(lines):
        s = lines[i].strip()
        i += 1
        if not s:
            flush()
            continue
        if s.startswith("$$"):
            flush()
            rest = s[2:]
            body: list[str] = []
            while not rest.rstrip().endswith("$$"):
                body.append(rest)
                if i >= len(lines):
                    rest = "$$"
                    break
                rest = lines[i]
                i += 1
            body.append(rest.rstrip()[:-2])
            tex = "\n".join(x for x in body if x.strip()).strip()
            if tex:
                out.append(f"<p>\\[ {esc(tex)} \\]</p>")
            continue
        heading = re.match(r"(#{1,6})\s+(.*)", s)
        if heading:
            flush()
            level = min(6, len(heading.group(1)) + 2)
            out.append(f"<h{level}>{_inline(heading.group(2))}</h{level}>")
            continue
        if s.startswith("<"):  # raw HTML (a figure): not carried over
            flush()
            continue
        if s.startswith(("- ", "* ")):
            if para:
                flush()
            items.append(s[2:])
            continue
        if items:
            flush()
        para.append(s)
    flush()
    return "\n".join(out)


def esc(text: str) -> str:
    """``text`` HTML-escaped (quotes left as they are)."""
    return html.escape(text, quote=False)


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


def _inline(text: str) -> str:
    """One line of Markdown text: escapes undone, math kept as TeX, bold and italics."""
    out: list[str] = []
    run: list[str] = []
    open_tags: list[str] = []

    def flush_run() -> None:
        if run:
            out.append(words(html.unescape("".join(run))))
            run.clear()

    i, n = 0, len(text)
    while i < n:
        ch = text[i]
        if ch == "\\" and i + 1 < n:
            run.append(text[i + 1])
            i += 2
            continue
        if ch == "$":
            end = text.find("$", i + 1)
            if end > i + 1:
                flush_run()
                out.append(f"\\({esc(text[i + 1 : end])}\\)")
                i = end + 1
                continue
        if ch == "*":
            tag = "strong" if text.startswith("**", i) else "em"
            flush_run()
            if open_tags and open_tags[-1] == tag:
                open_tags.pop()
                out.append(f"</{tag}>")
            else:
                open_tags.append(tag)
                out.append(f"<{tag}>")
            i += 2 if tag == "strong" else 1
            continue
        run.append(ch)
        i += 1
    flush_run()
    out.extend(f"</{tag}>" for tag in reversed(open_tags))
    return "".join(out)


def statement_html(md: str) -> str:
    """A statement page (heading, source, Given, Find) as HTML, without its title heading
    and without the Source paragraph (citations quote the published answers)."""
    lines = md.splitlines()
    while lines and (not lines[0].strip() or re.match(r"#\s", lines[0])):
        lines.pop(0)
    kept: list[str] = []
    in_source = False
    for line in lines:
        if line.startswith("*Source:"):
            in_source = True
        if in_source:
            in_source = bool(line.strip())
            continue
        kept.append(line)
    return md_to_html("\n".join(kept))


def solution_md(page: str) -> str:
    """The worked solution of a variant's page: from its **Solution.** on."""
    cut = page.find(SOLUTION)
    return page[cut:] if cut >= 0 else page


def clean_xml(text: str) -> str:
    """Text that XML 1.0 can hold (control characters dropped)."""
    return _XML_BAD.sub("", text)
