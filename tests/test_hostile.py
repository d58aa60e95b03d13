"""Hostile and broken input: nothing runs, nothing leaks into LaTeX/Markdown/HTML, every error is one clear line.

Problem files come from other people. These tests feed derive expression
payloads (code, attribute access, huge powers), text that tries to become
LaTeX/Markdown/HTML markup, and the broken files in ``tests/data``, and check
that each ends in a one-line ``Error: FILE:LINE: FIELD: what was expected``
(exit code 2) within a second, with nothing executed and nothing written.
"""

from __future__ import annotations

import json
import multiprocessing
import os
import re
import subprocess
import sys
import tempfile
import time
from collections import Counter
from pathlib import Path

import pytest
import sympy

import derive
from derive.errors import DeriveError, ExpressionError, InputError
from derive.escape import markdown, tex
from derive.problem import loads
from derive.problem.expr import ParseError, parse

DATA = Path(__file__).parent / "data"
ROOT = Path(__file__).resolve().parent.parent

BASE = """title = "Two carts"
kind = "direct"

[given]
m_A = "2 kg"
m_B = "3 kg"
e = 0.5
v_A1 = "4 m/s"
v_B1 = "-1 m/s"
"""


def toml_str(text: str) -> str:
    """``text`` as a TOML basic string (every character kept)."""
    out = ['"']
    for ch in text:
        if ch == "\\":
            out.append("\\\\")
        elif ch == '"':
            out.append('\\"')
        elif ord(ch) < 32 or ord(ch) == 127:
            out.append(f"\\u{ord(ch):04x}")
        else:
            out.append(ch)
    out.append('"')
    return "".join(out)


# ---------------------------------------------------------------- running a case in a child


def _child(conn, fn, args) -> None:
    start = time.perf_counter()
    try:
        value = fn(*args)
        conn.send(("ok", repr(value)[:200], time.perf_counter() - start))
    except DeriveError as exc:
        conn.send((type(exc).__name__, str(exc), time.perf_counter() - start))
    except BaseException as exc:
        conn.send(("crash:" + type(exc).__name__, str(exc)[:300], time.perf_counter() - start))
    finally:
        conn.close()


def isolated(fn, *args, timeout: float = 20.0) -> tuple[str, str, float]:
    """Run ``fn(*args)`` in a forked child: (outcome, message, seconds). A hang is killed, not waited for."""
    ctx = multiprocessing.get_context("fork")
    parent, child = ctx.Pipe(duplex=False)
    proc = ctx.Process(target=_child, args=(child, fn, args))
    proc.start()
    child.close()
    if not parent.poll(timeout):
        proc.kill()
        proc.join()
        return ("hang", f"did not finish within {timeout:g} s", timeout)
    result = parent.recv()
    proc.join()
    return result


def _load_given(expr: str, extra: str = "") -> derive.Problem:
    return loads(BASE + extra + f"k = {toml_str(expr)}\n", path="hostile.toml")


# ---------------------------------------------------------------- 1. expressions run nothing


CODE_PAYLOADS = [
    "__import__('os').system('touch {marker}')",
    '__import__("os").system("touch {marker}")',
    "open('{marker}', 'w').write('x')",
    "exec(\"open('{marker}', 'w')\")",
    "eval(\"open('{marker}', 'w')\")",
    "compile('1', 'f', 'eval')",
    "().__class__.__bases__[0].__subclasses__()",
    "e.__class__",
    "m_A.real",
    "m_A.__dict__",
    "a.b",
    "lambda: 1",
    "(lambda x: x)(1)",
    "__builtins__",
    "__import__",
    "__class__",
    "_",
    "[1][0]",
    "{1: 2}",
    "'text'",
    "f'{{1}}'",
    "b'x'",
    "1 if e else 2",
    "(k := 1)",
    "1; import os",
    "import os",
    "os.system('touch {marker}')",
    "getattr(e, 'x')",
    "Symbol('x')",
    "sympify('1')",
    "S(1)",
    "E",
    "I",
    "oo",
    "nan",
    "zoo",
    "exp",
    "1 # comment",
    "1 // 2",
    "1 % 2",
    "1 @ 2",
    "~1",
    "1 & 2",
    "1 | 2",
    "1 << 2",
    "not e",
    "1 == 1",
    "1 < 2",
    "$(touch {marker})",
    "`touch {marker}`",
    "\\input{{/etc/passwd}}",
    "m_A\x00",
    "sin(1, 2)",
    "atan2(1)",
    "unknown_function(1)",
]

HUGE_PAYLOADS = [
    "9**9**9",
    "10^10^10",
    "(2^64)^64^64",
    "2^(2^64)",
    "9^9^9^9",
    "(10^30)^64",
    "1e30^64",
    "2**-4096",
    "(1/3)^-4096",
    "1e999",
    "1" * 40,
    "2^64.5^64",
    "pi^64^64",
    "(1+1e-30)^(1e30)",
    "exp(exp(exp(exp(exp(1)))))",
    "exp(" * 10 + "1" + ")" * 10,
    "exp(10^4)^64",
    "(exp(700)^64)^64",
    "exp(690)*exp(690)",
    "(((sqrt(2)+sqrt(3))^64+1)^64+1)^64",
    "sin(1e30^40*1e30^40*1e30^40*1e30^40)",
    "0^(-1)^0.5",  # an imaginary exponent: was TypeError (found by the fuzz tests)
    "2^log(-1)",
    "(" * 60 + "1" + ")" * 60,
    "-" * 100 + "1",
    "+" * 100 + "1",
    "1+" * 300 + "1",
    "sqrt(" * 50 + "2" + ")" * 50,
    "x" * 600,
    "1" + "*1" * 400,
]

#: Expressions in the givens whose size shows only once their values are put in.
SYMBOLIC_PAYLOADS = [
    ("x = 1e30\n", "x^x"),
    ("x = 10\n", "x^x^x^x"),
    ("x = 1e30\n", "((x^64)^64)^64"),
    ("x = 2\n", "sin(((x^64)^64)^64)"),
    ("x = 1e30\n", "sin(exp(x))"),
    ("x = 1\n", "exp(exp(exp(exp(exp(x)))))"),
    ("x = 10\n", "exp(exp(exp(exp(x))))"),
    ("x = 10\n", "10^x"),
    ('x = 10\ny = "x^x"\nz = "y^y"\n', "z^z"),
    ("x = 1e30\n", "x^64*x^64*x"),
]


@pytest.mark.parametrize("payload", CODE_PAYLOADS + HUGE_PAYLOADS, ids=lambda p: repr(p[:40]))
def test_expression_payload_is_refused_quickly_and_runs_nothing(tmp_path: Path, payload: str) -> None:
    marker = tmp_path / "pwned"
    text = payload.format(marker=marker) if "{marker}" in payload or "{{" in payload else payload
    outcome, message, seconds = isolated(_load_given, text)
    assert outcome in ("ExpressionError", "InputError", "UnitError"), (outcome, message)
    assert seconds < 1.0, (seconds, message)
    assert "\n" not in message
    assert message.startswith("hostile.toml:10: [given] k"), message
    assert not marker.exists()
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("extra", "payload"), SYMBOLIC_PAYLOADS, ids=lambda v: repr(v[:30]))
def test_expression_in_the_givens_is_refused_quickly(extra: str, payload: str) -> None:
    outcome, message, seconds = isolated(_load_given, payload, extra)
    assert outcome in ("ExpressionError", "InputError"), (outcome, message)
    assert seconds < 1.0, (seconds, message)
    assert re.search(r"hostile.toml:\d+: \[given\] [kyz] = ", message), message


@pytest.mark.parametrize("payload", CODE_PAYLOADS + HUGE_PAYLOADS, ids=lambda p: repr(p[:40]))
def test_parser_alone_refuses_payloads(payload: str) -> None:
    names = {n: (sympy.Symbol(n, real=True), (0, 0, 0, 0)) for n in ("e", "m_A", "x")}
    with pytest.raises(ParseError):
        parse(payload.replace("{marker}", "/nonexistent/x").replace("{{", "{").replace("}}", "}"), names)


def test_parser_never_calls_eval_or_sympify(monkeypatch: pytest.MonkeyPatch) -> None:
    import builtins

    def forbidden(*args: object, **kwargs: object) -> None:
        raise AssertionError("evaluated text")

    monkeypatch.setattr(builtins, "eval", forbidden)
    monkeypatch.setattr(builtins, "exec", forbidden)
    monkeypatch.setattr(sympy, "sympify", forbidden)
    monkeypatch.setattr(sympy, "parse_expr", forbidden, raising=False)
    import sympy.parsing.sympy_parser as sp

    monkeypatch.setattr(sp, "parse_expr", forbidden)
    x = sympy.Symbol("x", real=True)
    out = parse("2*x^2 + sqrt(4) - atan(1)/atan2(1, 1) + pi", {"x": (x, (0, 0, 0, 0))})
    assert out.expr == 2 * x**2 + 1 + sympy.pi


def test_expressions_that_are_fine_still_work() -> None:
    p = loads(BASE + 'theta = "asin(75/123)"\nk = "2*m_A + m_B"\nr = "sqrt(v_A1^2) * 2^(1/2)"\n', path="ok.toml")
    assert p.given("k").value == 7
    assert sympy.simplify(p.given("r").value - 4 * sympy.sqrt(2)) == 0
    assert sympy.simplify(p.given("theta").value - sympy.asin(sympy.Rational(75, 123))) == 0


def test_cli_injection_runs_nothing(tmp_path: Path) -> None:
    """The real command, in a fresh interpreter: the payload in tests/data would touch a file in cwd."""
    proc = subprocess.run(
        [sys.executable, "-m", "derive", "solve", str(DATA / "expr-injection.toml")],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
    )
    assert proc.returncode == 2, proc.stderr
    assert proc.stdout == ""
    assert proc.stderr.startswith("Error: ") and proc.stderr.count("\n") == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    assert "expr-injection.toml:10" in proc.stderr and "[given] k" in proc.stderr
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------- 2. text is escaped

TEX_PAYLOADS = [
    r"\input{/etc/passwd}",
    r"\include{/etc/passwd}",
    r"\immediate\write18{touch pwned-by-tex}",
    r"\write18{touch pwned-by-tex}",
    r"\def\x{\input{/etc/passwd}}\x",
    r"\gdef\y{1}\edef\z{2}\let\a\b",
    r"\catcode`\@=11 \catcode92=12",
    r"\immediate\openout5=pwned-by-tex.tex \immediate\write5{x}\immediate\closeout5",
    r"\openin1=/etc/passwd \read1 to \line",
    r"^^5cinput{/etc/passwd} ^^5c^^69nput ^^M ^^?",
    r"\csname input\endcsname{/etc/passwd}",
    r"\directlua{os.execute('touch pwned-by-tex')}",
    r"\usepackage{shellesc}\ShellEscape{touch pwned-by-tex}",
    r"\loop\iftrue\repeat",
    r"\makeatletter\@@input /etc/passwd",
    r"\special{ps: (pwned) show}",
    r"}}}\end{document}",
    r"\begin{verbatim}",
    r"% a comment that eats the rest of the line",
    r"#1 $x$ $$y$$ & _ ~ \\ \ { }",
    "line one\nline two\r\n\\endinput\tafter tab",
]
MD_HTML_PAYLOADS = [
    "<script>alert('md')</script>",
    '<img src=x onerror="alert(1)">',
    "<iframe src='javascript:alert(1)'></iframe>",
    "[click](javascript:alert(1))",
    "![img](http://example.com/x.png)",
    "**bold** _italic_ `code` ~~strike~~ $x^2$ $$y$$",
    "# heading\n## another\n---\n> quote\n- item",
    "| a | b |\n|---|---|",
    "&lt;script&gt; &amp; &#60;",
    "{{ title }} {% if 1 %}x{% endif %} \\VAR{title} \\BLOCK{if 1}",
    "</title></head><body onload=alert(1)>",
    '" onmouseover="alert(1)',
]
UNICODE_PAYLOADS = ["\u202eevil\u202c", "\x1b[31mred\x1b[0m", "zero\u200bwidth", "Ω θ ° ½ µ ß é ∞ re\u0301gle\u0301e"]
ALL_TEXT = TEX_PAYLOADS + MD_HTML_PAYLOADS + UNICODE_PAYLOADS

DANGEROUS_TEX = [
    "input",
    "include",
    "write",
    "immediate",
    "def",
    "gdef",
    "edef",
    "xdef",
    "let",
    "catcode",
    "openout",
    "openin",
    "read",
    "csname",
    "directlua",
    "ShellEscape",
    "loop",
    "makeatletter",
    "special",
    "endinput",
    "end",
    "begin",
    "usepackage",
]


def _problem_text(title: str, statement: str, source: str, question: str) -> str:
    head = "\n".join(
        [
            f"title = {toml_str(title)}",
            'kind = "direct"',
            f"source = {toml_str(source)}",
            f"statement = {toml_str(statement)}",
            f"question = {toml_str(question)}",
        ]
    )
    return head + "\n" + BASE.split("\n", 2)[2]


@pytest.fixture(scope="module")
def hostile() -> derive.Solution:
    text = " ".join(ALL_TEXT)
    problem = loads(
        _problem_text(text[:4000], "\n".join(ALL_TEXT), " / ".join(ALL_TEXT)[:4000], "? ".join(ALL_TEXT)[:4000]),
        path="hostile.toml",
    )
    return derive.solve(problem)


@pytest.fixture(scope="module")
def benign() -> derive.Solution:
    problem = loads(_problem_text("Plain title", "A plain statement.", "A plain source", "A plain question?"))
    return derive.solve(problem)


def _code(tex_source: str) -> str:
    """TeX source without comments (an unescaped % starts one)."""
    return "\n".join(re.sub(r"(?<!\\)%.*", "", line) for line in tex_source.splitlines())


def _control_words(tex_source: str) -> dict[str, int]:
    code = _code(tex_source)
    return {w: len(re.findall(rf"\\{w}(?![A-Za-z])", code)) for w in DANGEROUS_TEX}


@pytest.mark.parametrize("fmt", ["tex", "tex-fragment"])
def test_latex_has_no_control_sequence_from_the_file(
    hostile: derive.Solution, benign: derive.Solution, fmt: str
) -> None:
    bad = derive.render(hostile, fmt)
    good = derive.render(benign, fmt)
    assert _control_words(bad) == _control_words(good)
    assert "^^" not in _code(bad)
    assert "pwned-by-tex" in bad  # the text is there, as text
    assert r"\textbackslash{}input\{/etc/passwd\}" in bad
    assert r"\textbackslash{}immediate\textbackslash{}write18\{touch pwned-by-tex\}" in bad
    assert r"\textasciicircum{}\textasciicircum{}5cinput" in bad
    assert "\x1b" not in bad and "\x00" not in bad
    # the payload cannot close the groups the template opens
    assert _braces_balanced(_code(bad))


def _braces_balanced(code: str) -> bool:
    depth = 0
    i = 0
    while i < len(code):
        c = code[i]
        if c == "\\":
            i += 2
            continue
        if c == "{":
            depth += 1
        elif c == "}":
            depth -= 1
            if depth < 0:
                return False
        i += 1
    return depth == 0


@pytest.mark.parametrize("payload", ALL_TEXT, ids=lambda p: repr(p[:30]))
def test_tex_escape_of_each_payload(payload: str) -> None:
    out = tex(payload)
    assert "\n" not in out and "\r" not in out
    assert "^^" not in out
    assert _braces_balanced(out)
    words = re.findall(r"\\([A-Za-z]+)", out)
    assert set(words) <= SAFE_TEX_WORDS, set(words) - SAFE_TEX_WORDS
    assert "%" not in out.replace(r"\%", "")
    assert "#" not in out.replace(r"\#", "")


def _table_words() -> set[str]:
    from derive import escape

    words: set[str] = {"allowbreak"}  # a line may break there (inside a long URL): a penalty, nothing more
    for table in (escape._TEX_SPECIAL, escape._TEX_UNICODE, escape._TEX_ACCENTS):
        for out in table.values():
            words |= set(re.findall(r"\\([A-Za-z]+)", out))
    return words


#: Control words escape.tex may write: the ones its tables hold, none of them able to read, write or define.
SAFE_TEX_WORDS = _table_words()


def test_escape_tables_hold_only_harmless_commands() -> None:
    assert SAFE_TEX_WORDS, "the tables were not found"
    assert not SAFE_TEX_WORDS & set(DANGEROUS_TEX)
    greek = set(
        [
            "alpha",
            "beta",
            "gamma",
            "delta",
            "epsilon",
            "zeta",
            "eta",
            "theta",
            "iota",
            "kappa",
            "lambda",
            "mu",
            "nu",
            "xi",
            "pi",
            "rho",
            "sigma",
            "tau",
            "upsilon",
            "phi",
            "chi",
            "psi",
            "omega",
        ]
    )
    greek |= {g.capitalize() for g in greek}
    symbols = {"dots", "pm", "times", "cdot", "rightarrow", "Rightarrow", "approx", "leq", "geq", "surd"}
    symbols |= {"varepsilon", "varphi", "vartheta", "varpi", "varrho"}
    symbols |= {"infty", "mp", "neq", "equiv", "propto", "angle", "nabla", "partial", "varsigma"}
    symbols |= {"leftarrow", "uparrow", "downarrow", "leftrightarrow"}
    symbols |= {"i", "l", "L", "oe", "OE", "dj", "DJ", "ng", "NG"}  # letters T1 fonts have
    symbols |= {"u", "r", "H", "v", "d", "c", "k", "b"}  # accents over a letter: \v{c}
    glyphs = {"char", "ttfamily", "allowbreak"}  # {\ttfamily\char34}: a glyph by its number, in a group
    unknown = {w for w in SAFE_TEX_WORDS if not (w.startswith("text") or w in greek | symbols | glyphs)}
    assert not unknown, f"escape.tex writes new commands {unknown}: check they cannot read, write or define"


def test_markdown_has_no_markup_from_the_file(hostile: derive.Solution, benign: derive.Solution) -> None:
    md = derive.render(hostile, "md")
    assert Counter(_tags(md)) == Counter(_tags(derive.render(benign, "md")))  # the figures' SVG only
    # the one link: a web address of the source line, as a CommonMark autolink (http and https only)
    links = re.findall(r"<([a-z]+:[^<>\s]*)>", md)
    assert links == ["http://example.com/x.png"]
    assert all(f"<{u}>" in next(ln for ln in md.splitlines() if ln.startswith("*Source:")) for u in links)
    assert _handlers(md) == []
    assert "\x1b" not in md
    assert not re.search(r"(?<!\\)\]\(", md)  # no link or image: every ] from the file is escaped
    assert "&lt;script&gt;alert('md')&lt;/script&gt;" in md
    assert r"\[click\](javascript:alert(1))" in md
    assert r"\*\*bold\*\* \_italic\_ \`code\` \~\~strike\~\~ \$x^2\$" in md
    assert "&amp;lt;script&amp;gt;" in md  # entities stay text
    title_line = md.splitlines()[0]
    assert title_line.startswith("# ") and "\\# heading" in md


def test_markdown_escape_per_character() -> None:
    for ch in "\\`*_[]|$~#<>&":
        out = markdown(ch)
        assert out != ch, ch
    assert markdown("a\nb\rc") == "a b c"


def test_html_has_no_markup_from_the_file(hostile: derive.Solution, benign: derive.Solution) -> None:
    bad = derive.render(hostile, "html")
    good = derive.render(benign, "html")
    assert Counter(_tags(bad)) == Counter(_tags(good))
    assert _handlers(bad) == _handlers(good) == []
    assert "&lt;script&gt;alert(&#x27;md&#x27;)&lt;/script&gt;" in bad


def _tags(page: str) -> list[str]:
    """HTML tags (an autolink such as <https://x.org> is not one)."""
    return re.findall(r"<\s*/?\s*([A-Za-z][\w-]*)(?![\w-]*:)", page)


def _handlers(page: str) -> list[str]:
    """Event-handler attributes inside real tags (text such as &lt;img onerror=...&gt; is not a tag)."""
    return re.findall(r"<[A-Za-z][^<>]*\son[a-z]+\s*=", page)


def test_json_keeps_the_text_exactly(hostile: derive.Solution) -> None:
    doc = json.loads(derive.render(hostile, "json"))
    p = hostile.problem
    assert doc["title"] == p.title == " ".join(ALL_TEXT)[:4000]  # nothing lost on the way in or out
    assert doc["source"] == p.source
    assert p.statement == "\n".join(ALL_TEXT)
    if "statement" in doc:
        assert doc["statement"] == p.statement


def test_given_names_that_are_tex_primitives_stay_letters() -> None:
    """Names are letters, digits and _ only; one spelled like a TeX primitive is still just letters."""
    names = ["input", "write18", "def", "catcode", "immediate", "openout", "csname", "input_x", "endinput"]
    extra = "".join(f'{n} = "{i + 2} m/s"\n' for i, n in enumerate(names))
    solution = derive.solve(loads(BASE + extra, path="names.toml"))
    for fmt in ("tex", "tex-fragment", "md"):
        out = derive.render(solution, fmt)
        words = _control_words(out)
        good = _control_words(derive.render(derive.solve(loads(BASE, path="plain.toml")), fmt))
        assert words == good, fmt
    assert "\\input" not in derive.render(solution, "md")


def test_latex_escapes_the_name_of_a_fixed_b() -> None:
    """Was: figure.to_tikz put [B] name into the TikZ figure unescaped (\\input{...} reached TeX)."""
    text = (
        'title = "Wall"\nkind = "direct"\n[given]\nm_A = "0.5 kg"\ne = 0.8\nv_A1 = "6 m/s"\n'
        '[B]\nfixed = true\nname = "\\\\input{/etc/hostname}"\n'
    )
    solution = derive.solve(loads(text, path="wall.toml"))
    assert solution.problem.name_B == r"\input{/etc/hostname}"
    out = derive.render(solution, "tex")
    assert r"\input{/etc/hostname}" not in _code(out)


# ---------------------------------------------------------------- 2b. the PDF still compiles, and TeX is boxed in


def _latex_available() -> bool:
    import shutil

    return shutil.which("latexmk") is not None and shutil.which("pdflatex") is not None


@pytest.mark.slow
@pytest.mark.skipif(not _latex_available(), reason="needs TeX Live with latexmk")
def test_hostile_pdf_compiles_and_writes_nothing_outside(
    hostile: derive.Solution, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    from derive.writers.pdf import build_pdf
    from derive.writers.view.jinja import environment

    work, tmp = tmp_path / "cwd", tmp_path / "tmp"
    work.mkdir()
    tmp.mkdir()
    monkeypatch.chdir(work)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp))
    environment.cache_clear()  # a fresh environment: its template cache is made here, too
    pdf = build_pdf(derive.render(hostile, "tex"))
    assert pdf.startswith(b"%PDF")
    assert list(work.iterdir()) == []
    assert list(tmp.iterdir()) == []  # its temporary folder is gone too


RAW_TEX = {
    "shell": ("\\immediate\\write18{{touch {outside}/shell}}ok", None),
    "absolute-write": (
        "\\immediate\\openout5={outside}/abs.tex \\immediate\\write5{{x}}\\immediate\\closeout5",
        "can't write",
    ),
    "relative-write": (
        "\\immediate\\openout6=../../outside/rel.tex \\immediate\\write6{{x}}\\immediate\\closeout6",
        "can't write",
    ),
    "absolute-read": ("\\input{{/etc/hostname}}", "not found"),
    "relative-read": ("\\input{{../../../../../../../etc/hostname}}", "not found"),
    "endless-loop": ("\\loop\\iftrue\\repeat", "did not finish"),
}


def _tex_processes_in(folder: Path) -> list[int]:
    """Live processes whose working folder is under ``folder`` (a pdflatex left running)."""
    pids = []
    for proc in Path("/proc").iterdir():
        if not proc.name.isdigit():
            continue
        try:
            cwd = os.readlink(proc / "cwd")
            state = (proc / "stat").read_text().rsplit(")", 1)[1].split()[0]
        except OSError:
            continue
        if cwd.startswith(str(folder)) and state != "Z":
            pids.append(int(proc.name))
    return pids


@pytest.mark.slow
@pytest.mark.skipif(not _latex_available(), reason="needs TeX Live with latexmk")
@pytest.mark.parametrize("case", sorted(RAW_TEX))
def test_build_pdf_sandboxes_even_raw_tex(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, case: str) -> None:
    """Defence in depth: were a payload to reach TeX, it could not run a program, read or write
    outside its folder, or run for ever (and no pdflatex is left running after a time-out)."""
    from derive.errors import RenderError
    from derive.writers.pdf import build_pdf

    work, tmp, outside = tmp_path / "cwd", tmp_path / "tmp", tmp_path / "outside"
    for d in (work, tmp, outside):
        d.mkdir()
    monkeypatch.chdir(work)
    monkeypatch.setattr(tempfile, "tempdir", str(tmp))
    body, error = RAW_TEX[case]
    doc = "\\documentclass{article}\\begin{document}\n" + body.format(outside=outside) + "\nhello\n\\end{document}\n"
    if error is None:
        assert build_pdf(doc, time_limit=60).startswith(b"%PDF")
    else:
        with pytest.raises(RenderError) as info:
            build_pdf(doc, time_limit=5 if case == "endless-loop" else 60)
        assert error in str(info.value) and "\n" not in str(info.value), str(info.value)
    assert list(outside.iterdir()) == []
    assert list(work.iterdir()) == []
    assert list(tmp.iterdir()) == []
    assert _tex_processes_in(tmp) == []


# ---------------------------------------------------------------- 3. every broken file: one line, exit 2

#: file -> (exit code, pieces of its one-line message: the file (and line), the field, what was expected)
BROKEN = {
    "bad-unit.toml": (2, ["bad-unit.toml:5", "[given] m_A = '2 stone'", "unknown unit 'stone'", "known:", "kg"]),
    "unknown-unit-alone.toml": (2, ["unknown-unit-alone.toml:6", "[given] m_B = 'furlong'", "known unit"]),
    "negative-mass.toml": (2, ["negative-mass.toml:6", "[given] m_B = '-3 kg'", "mass must be positive"]),
    "zero-mass.toml": (2, ["zero-mass.toml:6", "[given] m_B = 0", "mass must be positive"]),
    "no-approach.toml": (2, ["no-approach.toml:4", "[given]", "do not approach", "-1.000", "must be positive"]),
    "zero-relative-velocity.toml": (2, ["zero-relative-velocity.toml:4", "[given]", "do not approach", "= 0"]),
    "e-too-big.toml": (2, ["e-too-big.toml:7", "[given] e = 1.3", "between 0 and 1"]),
    "e-negative.toml": (2, ["e-negative.toml:7", "[given] e = -0.2", "between 0 and 1"]),
    "missing-mass.toml": (2, ["missing-mass.toml", "[given] m_B", "missing", "mass of B"]),
    "missing-e.toml": (2, ["missing-e.toml", "[given] e", "missing", "coefficient of restitution"]),
    "missing-title.toml": (2, ["missing-title.toml", "title", "missing", "line of text"]),
    "missing-kind.toml": (2, ["missing-kind.toml", "kind", "missing", '"direct" or "oblique"']),
    "missing-given.toml": (2, ["missing-given.toml", "[given]", "missing", "masses"]),
    "missing-velocity.toml": (2, ["missing-velocity.toml", "[given] v_B1", "missing", "velocity of B"]),
    "missing-direction.toml": (2, ["missing-direction.toml", "[A]", "missing", "angle, from, toward"]),
    "empty.toml": (2, ["empty.toml", "title", "missing"]),
    "undetermined.toml": (2, ["undetermined.toml", "[given]", "cannot determine", "unknowns", "e"]),
    "overdetermined.toml": (2, ["overdetermined.toml", "[given]", "over-determine"]),
    "nan-mass.toml": (2, ["nan-mass.toml:5", "[given] m_A = nan", "finite number"]),
    "inf-speed.toml": (2, ["inf-speed.toml:8", "[given] v_A1 = inf", "finite number"]),
    "huge-number.toml": (2, ["huge-number.toml:8", "[given] v_A1 = '4e99 m/s'", "out of range", "1e30"]),
    "wrong-type.toml": (2, ["wrong-type.toml:5", "[given] m_A = [2, 'kg']", "expected a number or text", "list"]),
    "bool-mass.toml": (2, ["bool-mass.toml:5", "[given] m_A", "expected a number or text", "true/false"]),
    "date-mass.toml": (2, ["date-mass.toml:5", "[given] m_A = 1979-05-27", "expected a number or text"]),
    "given-not-table.toml": (2, ["given-not-table.toml:3", "given", "expected a table"]),
    "title-not-text.toml": (2, ["title-not-text.toml:1", "title = 42", "expected text"]),
    "title-nul.toml": (2, ["title-nul.toml:1", "title", "NUL"]),
    "bad-toml.toml": (2, ["bad-toml.toml:10", "not valid TOML"]),
    "duplicate-key.toml": (2, ["duplicate-key.toml:10", "not valid TOML"]),
    "unknown-field.toml": (2, ["unknown-field.toml:1", "colour", "unknown field", "expected one of", "title"]),
    "bad-kind.toml": (2, ["bad-kind.toml:2", "kind = 'sideways'", '"direct" or "oblique"']),
    "digits-zero.toml": (2, ["digits-zero.toml:1", "digits = 0", "from 1 to 10"]),
    "bad-units-system.toml": (2, ["bad-units-system.toml:1", "units = 'imperial'", '"SI" or "US"']),
    "wrong-dimension.toml": (2, ["wrong-dimension.toml:8", "[given] v_A1 = '4 kg'", "expected a velocity", "mass"]),
    "weight-as-mass.toml": (2, ["weight-as-mass.toml:5", "[given] m_A = '2 lb'", "expected a mass", "force"]),
    "bad-name.toml": (2, ["bad-name.toml:10", "[given] 2x", "not a usable name", "start with a letter"]),
    "computed-name.toml": (2, ["computed-name.toml:10", "[given] T_lost", "derive computes"]),
    "function-name.toml": (2, ["function-name.toml:10", "[given] sin", "name of a constant or function"]),
    "circular.toml": (2, ["circular.toml:10", "[given] a = 'b + 1'", "circle"]),
    "expr-injection.toml": (2, ["expr-injection.toml:10", '[given] k = "__import__', "unexpected character '_'"]),
    "attribute-access.toml": (2, ["attribute-access.toml:10", "[given] k = 'e.__class__'", "unexpected character '.'"]),
    "lambda.toml": (2, ["lambda.toml:10", "[given] k = 'lambda: 1'", "unexpected character ':'"]),
    "dunder-name.toml": (2, ["dunder-name.toml:10", "[given] k = '__builtins__'", "unexpected character '_'"]),
    "unknown-function.toml": (
        2,
        ["unknown-function.toml:10", "[given] k = 'system(1)'", "unknown function", "allowed"],
    ),
    "unknown-name.toml": (2, ["unknown-name.toml:10", "[given] k = '2*zeta'", "unknown name 'zeta'", "known:"]),
    "huge-power.toml": (2, ["huge-power.toml:10", "[given] k = '9**9**9'", "exponent", "too large", "at most 64"]),
    "power-tower.toml": (2, ["power-tower.toml:10", "[given] k = '10^10^10'", "too large"]),
    "nested-power.toml": (2, ["nested-power.toml:10", "[given] k = '(2^64)^64^64'", "too large"]),
    "symbolic-exponent.toml": (2, ["symbolic-exponent.toml:11", "[given] k = 'x^x'", "exponent must be a number"]),
    "exp-tower.toml": (2, ["exp-tower.toml:10", "[given] k = 'exp(exp(", "nested too deeply"]),
    "deep-nesting.toml": (2, ["deep-nesting.toml:10", "[given] k = '(((", "nested too deeply", "at most 40"]),
    "long-expression.toml": (2, ["long-expression.toml:10", "[given] k = '1+1+", "too long", "at most 500"]),
    "division-by-zero.toml": (2, ["division-by-zero.toml:10", "[given] k = '1/(e - 0.5)'", "finite real number"]),
    "unit-mismatch-expression.toml": (
        2,
        ["unit-mismatch-expression.toml:10", "[given] k = 'v_A1 + m_A'", "cannot add a velocity and a mass"],
    ),
    "oblique-both-ways.toml": (2, ["oblique-both-ways.toml:8", "[given] v_A1", "give either", "not both"]),
    "bad-axis.toml": (2, ["bad-axis.toml:13", "[A] from = '+z'", "expected one of +n, -n, +t, -t"]),
    "axes-not-at-right-angles.toml": (2, ["axes-not-at-right-angles.toml:14", "[A] toward = '-n'", "right angles"]),
    "negative-speed.toml": (2, ["negative-speed.toml:8", "[given] v_A1 = '-4 m/s'", "speed cannot be negative"]),
    "angle-not-angle.toml": (2, ["angle-not-angle.toml:12", "[A] angle = '30 kg'", "expected an angle"]),
    "direct-with-angle.toml": (2, ["direct-with-angle.toml:11", "[A]", "direct impact has one velocity component"]),
    "fixed-with-mass.toml": (2, ["fixed-with-mass.toml:6", "[given] m_B", "B is fixed", "no mass or velocity"]),
    "fixed-a.toml": (2, ["fixed-a.toml:12", "[A] fixed", "only B can be fixed"]),
    "find-unknown.toml": (2, ["find-unknown.toml:1", "find = ['v_C2']", "unknown result 'v_C2'", "expected some of"]),
    "control-chars-in-key.toml": (2, ["control-chars-in-key.toml", "[given] x", "not a usable name"]),
    "newline-in-key.toml": (2, ["newline-in-key.toml", "[given] a\\nb", "not a usable name"]),
    "not-utf8.toml": (2, ["not-utf8.toml", "not UTF-8", "byte 13"]),
    "utf16.toml": (2, ["utf16.toml", "not UTF-8", "byte 1"]),
    "binary.toml": (2, ["binary.toml", "not UTF-8"]),
}

_CONTROL = re.compile(r"[\x00-\x09\x0b-\x1f\x7f-\x9f]")


@pytest.mark.parametrize("name", sorted(BROKEN))
def test_broken_file_gives_one_clear_line(cli, name: str) -> None:
    code, needles = BROKEN[name]
    path = DATA / name
    assert path.is_file(), path
    r = cli("solve", str(path))
    assert r.code == code, r.err
    assert r.out == ""
    assert r.err.startswith("Error: "), r.err
    assert r.err.endswith("\n") and r.err.count("\n") == 1, r.err  # one line
    assert "Traceback" not in r.err and "internal error" not in r.err
    assert not _CONTROL.search(r.err), repr(r.err)  # nothing that moves a terminal's cursor or colour
    assert str(path) in r.err
    for needle in needles:
        assert needle in r.err, (needle, r.err)


@pytest.mark.parametrize("name", ["no-approach.toml", "not-utf8.toml", "bad-unit.toml"])
def test_broken_file_in_a_fresh_interpreter(name: str) -> None:
    proc = subprocess.run(
        [sys.executable, "-m", "derive", "solve", str(DATA / name)],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
    )
    assert proc.returncode == 2
    assert proc.stdout == ""
    assert proc.stderr.startswith("Error: ") and proc.stderr.count("\n") == 1, proc.stderr
    assert name in proc.stderr


@pytest.mark.parametrize("special", ["/dev/zero", "huge-sparse"])
def test_endless_or_huge_input_is_refused_without_reading_it_all(tmp_path: Path, special: str) -> None:
    """`derive solve /dev/zero` (or a 4 GB file) stops at the 1 MB limit, in a process allowed 1.5 GB."""
    path = special
    if special == "huge-sparse":
        big = tmp_path / "huge.toml"
        with big.open("wb") as fh:
            fh.truncate(4 * 2**30)  # sparse: takes no disk
        path = str(big)
    code = (
        "import resource, sys\n"
        "resource.setrlimit(resource.RLIMIT_AS, (1536 * 2**20, 1536 * 2**20))\n"
        "from derive.cli import main\n"
        "sys.exit(main(['solve', sys.argv[1]]))\n"
    )
    proc = subprocess.run(
        [sys.executable, "-c", code, path],
        capture_output=True,
        text=True,
        timeout=120,
        env={**os.environ, "PYTHONPATH": str(ROOT)},
    )
    assert proc.returncode == 2, proc.stderr[-500:]
    assert proc.stderr.startswith("Error: ") and proc.stderr.count("\n") == 1, proc.stderr[-500:]
    assert "too large" in proc.stderr and path in proc.stderr


def test_debug_prints_the_traceback_too(cli) -> None:
    r = cli("--debug", "solve", str(DATA / "e-too-big.toml"))
    assert r.code == 2
    assert "Traceback" in r.err and "PhysicsError" in r.err
    assert r.err.rstrip("\n").splitlines()[-1].startswith("Error: ")


def test_error_types_are_input_errors() -> None:
    """Each broken file raises an InputError subclass from the library, not just from the CLI."""
    for name, (code, _) in BROKEN.items():
        if code != 2:
            continue
        with pytest.raises(InputError):
            derive.solve(derive.load(str(DATA / name)))


@pytest.mark.parametrize("key", ["a\\nb", "x\\u001b[31mred", "z\\u2028y"])
def test_library_messages_are_one_line_even_for_odd_keys(key: str) -> None:
    with pytest.raises(InputError) as info:
        loads(BASE + f'"{key}" = 1\n', path="keys.toml")
    message = str(info.value)
    assert "\n" not in message and not _CONTROL.search(message) and "\u2028" not in message, repr(message)


def test_expression_error_is_an_input_error() -> None:
    with pytest.raises(ExpressionError) as info:
        _load_given("__import__('os')")
    assert isinstance(info.value, InputError)
    assert info.value.where == "hostile.toml:10"
    assert info.value.field is not None and info.value.field.startswith("[given] k")
