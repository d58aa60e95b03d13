"""The 17 broken and hostile files of issue 18 (tests/data/repros/), each run as its first
line says, and each ending as the issue asks: one clear line and exit code 2, or a
correct, bounded run. Whatever the outcome, nothing raw reaches the terminal: no control
character on standard output or error, no traceback, no "internal error".
"""

from __future__ import annotations

import re
import shutil
import time
from pathlib import Path

import pytest

REPROS = Path(__file__).parent / "data" / "repros"
#: C0 and C1 control characters but newline and tab, and the invisible ones that reorder text.
RAW = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
#: Seconds a repro may take here (they used to take minutes, or not end).
BOUND = 60.0


def run(cli, *args: str):
    start = time.monotonic()
    r = cli(*args)
    seconds = time.monotonic() - start
    assert seconds < BOUND, f"{args} took {seconds:.0f} s"
    assert not RAW.search(r.out) and not RAW.search(r.err), (r.out[-300:], r.err)
    assert "Traceback" not in r.err and "internal error" not in r.err, r.err
    return r


def one_line_error(r, *needles: str) -> None:
    assert r.code == 2, r.err
    assert r.out == ""
    assert r.err.startswith("Error: ") and r.err.count("\n") == 1, r.err
    for needle in needles:
        assert needle in r.err, (needle, r.err)


@pytest.fixture
def here(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A scratch folder holding the repro files, as the current folder (their commands use bare names)."""
    for f in REPROS.glob("*.toml"):
        shutil.copy(f, tmp_path / f.name)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def test_all_seventeen_are_here() -> None:
    assert len(list(REPROS.glob("*.toml"))) == 17
    for f in REPROS.glob("*.toml"):
        assert "derive " in f.read_text(encoding="utf-8").splitlines()[0], f.name


# ---------------------------------------------------------------- internal errors: now one clear line


@pytest.mark.parametrize(
    ("name", "needles"),
    [
        ("chain-stage-title-number", [":10: [stage 1] title = 5: expected text, found a number"]),
        ("chain-range-of-list", [":11: [stage 1] range_of = ['e_floor']: expected a name", "found a list"]),
        ("chain-solve-bad-number", [":13: [stage 2] condition = 'q = 1.2.3 m/s'", "'1.2.3' is not a number"]),
        ("toml-big-int", [":4: not valid TOML: a number has too many digits"]),
        ("toml-deep-array", [":2: arrays or tables are nested too deeply (at most 32 levels)"]),
    ],
)
def test_was_an_internal_error(cli, here: Path, name: str, needles: list[str]) -> None:
    one_line_error(run(cli, "solve", f"{name}.toml"), f"Error: {name}.toml", *needles)


def test_variants_of_a_huge_mass_is_refused_at_load(cli, here: Path) -> None:
    """Was OverflowError: m_A = u*(1e30)^10 is 1e300 kg, outside the range any number keeps."""
    r = run(cli, "variants", "variants-overflow.toml", "--count", "2", "-o", "hv")
    one_line_error(r, "variants-overflow.toml:8: [given] m_A = 'u*(1e30)^10'", "out of range", "1e+300")
    assert not (here / "hv").exists()


@pytest.mark.slow
def test_pdf_with_latin1_url_builds_and_breaks_the_url(cli, here: Path) -> None:
    """Was UnicodeDecodeError reading TeX's output (a byte 0xff); the URL ran off the page."""
    if shutil.which("latexmk") is None:
        pytest.skip("needs TeX Live with latexmk")
    r = run(cli, "solve", "pdf-latin1-overfull.toml", "-f", "pdf", "-o", "out.pdf")
    assert r.code == 0, r.err
    assert (here / "out.pdf").read_bytes().startswith(b"%PDF")
    import subprocess

    run(cli, "solve", "pdf-latin1-overfull.toml", "-f", "tex", "-o", "out.tex")
    subprocess.run(
        ["latexmk", "-pdf", "-interaction=nonstopmode", "-halt-on-error", "out.tex"],
        cwd=here,
        capture_output=True,
        timeout=300,
        check=True,
    )
    log = (here / "out.log").read_bytes()
    assert b"Overfull" not in log


def test_tex_log_is_read_as_bytes(monkeypatch: pytest.MonkeyPatch) -> None:
    """The PDF writer's error path on a log that is not UTF-8: a one-line RenderError, no UnicodeDecodeError."""
    import subprocess

    from derive.errors import RenderError
    from derive.writers import pdf

    monkeypatch.setattr(pdf.shutil, "which", lambda name: "/bin/true")
    monkeypatch.setattr(
        pdf, "_run", lambda *a, **k: subprocess.CompletedProcess([], 1, b"! Undefined \xff\xfe stra\xdfe.\n", b"")
    )
    with pytest.raises(RenderError) as info:
        pdf.build_pdf("x")
    assert "LaTeX failed: ! Undefined" in str(info.value) and "\n" not in str(info.value)


# ---------------------------------------------------------------- silently wrong pages: now refused


def test_vertical_as_text_is_not_a_boolean(cli, here: Path) -> None:
    r = run(cli, "solve", "chain-vertical-string.toml")
    one_line_error(r, "chain-vertical-string.toml:14: [stage 1] vertical = 'false': expected true or false, found text")


def test_again_may_not_overwrite_a_given(cli, here: Path) -> None:
    r = run(cli, "solve", "chain-again-overwrites-given.toml")
    one_line_error(r, "chain-again-overwrites-given.toml:12: [stage 1] result = 'm'", "'m' is used already")


def test_again_result_is_checked_when_solving_too() -> None:
    """A second line of defence: were a stage table to skip the load-time check, the solver's
    ``define`` still refuses to overwrite a given (it used to assign it)."""
    from dataclasses import replace

    import derive
    from derive.physics.chain import run_chain

    text = (REPROS / "chain-again-overwrites-given.toml").read_text(encoding="utf-8").replace('result = "m"', "")
    from derive.problem import loads

    chain = loads(text, path="again.toml")
    bad = replace(chain, stages=({**chain.stages[0], "result": "m"}, *chain.stages[1:]))
    with pytest.raises(derive.InputError, match=r"\[stage 1\] result = 'm': 'm' is not a new name"):
        run_chain(bad)


# ---------------------------------------------------------------- no end: now bounded


def test_condition_exponent_is_refused_before_it_is_built(cli, here: Path) -> None:
    r = run(cli, "solve", "dos-chain-condition-exponent.toml")
    one_line_error(r, ":13: [stage 2] condition = 'q = 1e99999999 m/s'", "out of range")


def test_nested_sin_is_refused_before_it_is_solved(cli, here: Path) -> None:
    r = run(cli, "solve", "dos-nested-sin-e.toml")
    one_line_error(r, ":7: [given] e = 'sin(sin(", "functions are nested too deeply (at most 4 levels)")


def test_variants_give_up_early_and_count_is_bounded(cli, here: Path) -> None:
    r = run(cli, "variants", "dos-variants-never.toml", "--count", "10000", "-o", "out")
    one_line_error(r, "0 of the first 2,000 draws meet v_B2 > 1000", "check the conditions")
    assert not (here / "out").exists()
    r = run(cli, "variants", "dos-variants-never.toml", "--count", "100000", "-o", "out")
    one_line_error(r, "--count 100000: expected a count from 1 to 10000")


# ---------------------------------------------------------------- invalid output: now an error


def test_json_never_holds_infinity(cli, here: Path) -> None:
    r = run(cli, "solve", "json-infinity.toml", "-f", "json")
    one_line_error(r, "json-infinity.toml:8: [given] m_A = 'u*(1e30)^10'", "out of range")


def test_a_chain_result_beyond_range_is_one_line(cli, here: Path) -> None:
    """Givens keep 1e-30..1e30; a result a stage works out from them must stay finite in every output."""
    (here / "big.toml").write_text(
        'title = "c"\nkind = "chain"\n[given]\nv_0 = "1e30 m/s"\n[[stage]]\ntype = "define"\nexpr = "v_0^11"\n'
        'result = "q"\n'
    )
    for fmt in ("json", "md"):
        r = run(cli, "solve", "big.toml", "-f", fmt)
        one_line_error(r, "big.toml:8: [stage 1] result = 'q': q works out beyond", "at most 1e300")


def test_strict_json_names_the_value(tmp_path: Path) -> None:
    from derive.errors import RenderError
    from derive.fileio import dumps_json

    assert dumps_json({"a": [1.5, None]}) == '{\n  "a": [\n    1.5,\n    null\n  ]\n}\n'
    with pytest.raises(RenderError, match=r"results\.T_1\.value is not a finite number"):
        dumps_json({"results": {"v": {"value": 1.0}, "T_1": {"value": float("inf")}}})


# ---------------------------------------------------------------- live escapes: now shown escaped


def test_answers_label_reaches_the_terminal_escaped(cli, here: Path) -> None:
    r = run(cli, "check", "notes-4c11-two-spheres", "--answers", "answers-label-escape.toml")
    assert r.code == 0, r.err
    assert "(\\u001b]0;PWNED\\u0007\\u001b[2J\\u001b[32m)" in r.out
    assert "\x1b" not in r.out


@pytest.mark.parametrize("fmt", ["text", "md", "json"])
def test_title_reaches_the_terminal_escaped(cli, here: Path, fmt: str) -> None:
    r = run(cli, "check", "terminal-escape-title.toml", "--answer", "v_B2=2", "--format", fmt)
    assert "PWNED" in r.out  # run() asserted that no control character is in it
    if fmt != "md":  # Markdown writes control characters as spaces
        assert "Evil \\u001b]0;PWNED\\u0007\\u001b[2J\\u001b[31mRED" in r.out
    if fmt == "json":
        import json

        assert json.loads(r.out)["title"] == "Evil \x1b]0;PWNED\x07\x1b[2J\x1b[31mRED"  # the text itself, kept


def test_lms_statement_math_is_not_typeset(cli, here: Path) -> None:
    """The file's $ and \\( reach no LMS HTML as delimiters: Moodle's TeX filter reads the
    HTML source (character references hide them), MathJax reads the decoded text (a span
    with its ignore classes hides them); derive's own math stays \\( \\) and \\[ \\]."""
    import xml.etree.ElementTree as ET

    r = run(
        cli,
        "variants",
        "lms-math-delimiters.toml",
        "--count",
        "2",
        "-o",
        "hw",
        "--moodle",
        "q.xml",
        "--prairielearn",
        "pl",
    )
    assert r.code == 0, r.err
    root = ET.parse(here / "q.xml").getroot()
    pages = [t.text or "" for t in root.iter("text") if (t.text or "").lstrip().startswith("<")]
    pages += [f.read_text(encoding="utf-8") for f in (here / "pl").rglob("question.html")]
    assert len(pages) >= 4
    for page in pages:
        for delimiter in ("$", "\\(", "\\[", "\\input"):
            outside = re.sub(r"\\\((.*?)\\\)|\\\[(.*?)\\\]", "", page, flags=re.S)  # derive's own math
            assert delimiter not in outside, (delimiter, page[:300])
    statements = [p for p in pages if "It costs" in p]
    assert statements, "the statement reaches the question text"
    for page in statements:
        assert '<strong>Given.</strong> <span class="mathjax_ignore tex2jax_ignore">It costs &#36;5 or &#36;10' in page
        assert "&#92;(&#92;frac{1}{2}&#92;) of &#36;&#36;&#92;input{x}&#36;&#36;." in page
    info = [p for p in pages if "variants drawn by derive" in p]
    assert info and "Price &#36;x^2&#36;" in info[0]


def test_lms_run_itself_is_clean(cli, here: Path) -> None:
    r = run(cli, "variants", "lms-math-delimiters.toml", "--count", "2", "-o", "hw", "--moodle", "q.xml")
    assert r.code == 0, r.err
    assert (here / "q.xml").is_file() and (here / "hw" / "key.json").is_file()


# ---------------------------------------------------------------- refused for no reason: now read


def test_byte_order_mark_is_accepted(cli, here: Path) -> None:
    r = run(cli, "solve", "toml-bom.toml", "-f", "json")
    assert r.code == 0, r.err
    import json

    doc = json.loads(r.out)
    assert doc["title"] == "BOM" and doc["results"]["v_A2"]["value"] == pytest.approx(-0.32)


def test_a_stage_result_that_works_out_complex_is_one_line() -> None:
    """Fuzz case 5549 (seed 18): a bounces stage with e = sqrt(-1) was an internal error in JSON."""
    import derive
    from derive.problem import loads

    text = (
        'title = "t"\nkind = "chain"\n[given]\nh_0 = "1.6 m"\n'
        '[[stage]]\ntype = "bounces"\nheight = "h_0"\ne = "sqrt(-1)"\ncount = 2\n'
    )
    with pytest.raises(derive.InputError, match="complex number") as info:
        derive.solve(loads(text, path="x.toml"))
    assert str(info.value).startswith("x.toml:") and "\n" not in str(info.value)
