"""Issue #28, item 1: text from a problem file reaches the PDF as typed (NFC-normalised),
or derive names the character it cannot set, in one line.

Was: Greek letters after rho came out shifted by one (sigma as tau, phi as chi, omega as
"?"), because the table counted from alpha and final sigma (U+03C2) sits between rho and
sigma; accents typed decomposed (e + U+0301), Cyrillic, Omega and infinity printed "?".
"""

from __future__ import annotations

import shutil
import subprocess
import unicodedata
from pathlib import Path

import pytest
from support.output_cases import missing_tool

import derive
from derive.errors import InputError
from derive.escape import tex
from derive.writers.pdf import build_pdf

REPROS = Path(__file__).parent / "data" / "repros2"

SMALL = "".join(chr(c) for c in range(0x03B1, 0x03CA))  # alpha ... omega, final sigma included
CAPITAL = "".join(chr(c) for c in range(0x0391, 0x03AA) if c != 0x03A2)  # Alpha ... Omega
NFD = "re\u0301gle\u0301e"  # réglée typed as macOS copy-paste gives it

#: Greek capitals that pdflatex's fonts shape exactly as a Latin capital: the PDF holds that letter.
LATIN_SHAPED = dict(zip("ΑΒΕΖΗΙΚΜΝΟΡΤΧ", "ABEZHIKMNOPTX", strict=True))


def test_every_greek_letter_maps_to_its_own_command() -> None:
    for ch in SMALL + CAPITAL:
        name = unicodedata.name(ch).split()[-1].lower().replace("lamda", "lambda")
        if ch in "εφ":  # U+03B5 is the open epsilon, U+03C6 the looped phi
            name = "var" + name
        out = tex(ch)
        if ch in LATIN_SHAPED:
            assert out == LATIN_SHAPED[ch]
        elif ch == "ο":
            assert out == "o"
        elif ch == "ς":
            assert out == r"$\varsigma$"
        else:
            assert out.lower() == rf"$\{name}$", (ch, out)


def test_decomposed_accents_are_joined_and_latin_accents_are_set() -> None:
    assert tex(NFD) == "réglée"
    assert tex("ā ő č") == r"\={a} \H{o} \v{c}"
    assert tex("∞ Ω") == r"$\infty$ $\Omega$"


@pytest.mark.parametrize("text", ["Мяч", "😀", "中"])
def test_a_character_latex_cannot_set_is_named(text: str) -> None:
    with pytest.raises(InputError) as err:
        tex(f"Ball {text} one")
    message = str(err.value)
    assert "\n" not in message
    assert f"U+{ord(text[0]):04X} {unicodedata.name(text[0])}" in message


def _pdftotext(pdf: bytes, tmp_path: Path) -> str:
    path = tmp_path / "out.pdf"
    path.write_bytes(pdf)
    return subprocess.run(["pdftotext", str(path), "-"], capture_output=True, text=True, check=True).stdout


def _same_text(text: str) -> str:
    """Text as pdftotext and the file may both spell it: NFKC (the micro sign is mu), the
    Adobe glyph names' increment sign as Delta, and no white space (kerning may add some)."""
    text = unicodedata.normalize("NFKC", text).replace("\u2206", "Δ")
    return "".join(text.split())


def _need_tex() -> None:
    for tool in ("latexmk", "pdflatex", "pdftotext"):
        if shutil.which(tool) is None:
            missing_tool(f"{tool} is not installed")


@pytest.mark.slow
def test_pdf_text_reads_back_as_typed(problem_from, tmp_path: Path) -> None:
    _need_tex()
    title = f"Greek {SMALL} {CAPITAL} {NFD} ∞"
    problem = problem_from(
        f'title = "{title}"\nkind = "direct"\n[given]\nm_A = "2 kg"\nm_B = "3 kg"\ne = 0.8\nv_A1 = "4 m/s"\nv_B1 = 0\n'
    )
    text = _pdftotext(build_pdf(derive.render(derive.solve(problem), "tex")), tmp_path)
    expected = unicodedata.normalize("NFC", title).translate(str.maketrans(LATIN_SHAPED))
    expected = expected.replace("ο", "o")  # omicron: a Latin o in every TeX font
    assert _same_text(expected) in _same_text(text)


@pytest.mark.slow
def test_repro_tex_text_question_marks(cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The repro of input2: its Cyrillic cannot be set by pdflatex: one line names it, no PDF
    with "?" in it; without the Cyrillic, the PDF shows the title as typed."""
    _need_tex()
    monkeypatch.chdir(tmp_path)
    src = (REPROS / "tex-text-question-marks.toml").read_text(encoding="utf-8")
    Path("q.toml").write_text(src, encoding="utf-8")
    r = cli("solve", "q.toml", "-f", "pdf", "-o", "out.pdf")
    assert r.code == 2 and r.err.count("\n") == 1, r.err
    assert "U+041C CYRILLIC CAPITAL LETTER EM" in r.err
    assert not Path("out.pdf").exists()
    Path("ok.toml").write_text(src.replace(r"\u041c\u044f\u0447 ", ""), encoding="utf-8")
    r = cli("solve", "ok.toml", "-f", "pdf", "-o", "ok.pdf")
    assert r.code == 0, r.err
    text = _pdftotext(Path("ok.pdf").read_bytes(), tmp_path)
    assert _same_text("Collision de la boule réglée (NFD) vs réglée (NFC); Ω ∞") in _same_text(text)
    assert "?" not in text


def test_repro_tex_text_question_marks_names_the_character(
    cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """The input2 repro as LaTeX: one line naming the first character pdflatex cannot set;
    Markdown shows every character as typed."""
    monkeypatch.chdir(tmp_path)
    Path("q.toml").write_text((REPROS / "tex-text-question-marks.toml").read_text(encoding="utf-8"), encoding="utf-8")
    r = cli("solve", "q.toml", "-f", "tex")
    assert r.code == 2 and r.out == "" and r.err.count("\n") == 1, r.err
    assert r.err.startswith("Error: ") and "U+041C CYRILLIC CAPITAL LETTER EM" in r.err
    md = cli("solve", "q.toml")
    assert md.code == 0 and "Мяч Ω ∞" in md.out


def test_quote_marks_are_the_curly_ones_they_stand_for() -> None:
    # was \textquotesingle{}: a straight typewriter mark in "A's" and "the notes'"
    assert tex("A's speed, the notes' equations") == "A's speed, the notes' equations"
    assert tex("(answers 'v = 3', \"u = 4\")") == "(answers `v = 3', ``u = 4'')"
    assert tex("5'' of rain") == "5'{}' of rain"  # two marks never join into one
    assert "textquotesingle" not in tex("it's") and "ttfamily" not in tex('"x"')


@pytest.mark.slow
def test_pdf_text_has_curly_apostrophes_and_quotes(problem_from, tmp_path: Path) -> None:
    _need_tex()
    problem = problem_from(
        'title = "A\'s first impact, \'quoted\' and \\"double\\""\nkind = "direct"\n'
        '[given]\nm_A = "2 kg"\nm_B = "3 kg"\ne = 0.8\nv_A1 = "4 m/s"\nv_B1 = 0\n'
    )
    text = _pdftotext(build_pdf(derive.render(derive.solve(problem), "tex")), tmp_path)
    assert "A\u2019s first impact, \u2018quoted\u2019 and \u201cdouble\u201d" in text
    assert "'" not in text and '"' not in text
