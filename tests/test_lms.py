"""LMS exports of homework variants: Moodle XML and a PrairieLearn question folder."""

from __future__ import annotations

import json
import re
import textwrap
import uuid
import xml.etree.ElementTree as ET
from decimal import Decimal
from pathlib import Path

import pytest

import derive
from derive.checking import mistakes
from derive.homework import lms, variants
from derive.problem import loads


def _sign_convention(compiled: variants.Compiled) -> str:
    """The sign convention in words (where +n and +t point), as the student's sheet says it in Markdown."""
    from derive import escape
    from derive.steps import solve
    from derive.writers.view import problem_view

    data = problem_view(solve(compiled.problem), figures=False)  # the file's own numbers
    return "".join(f"${s}$" if kind == "math" else escape.markdown(s) for kind, s in data["convention"])


NAME = "notes-4c11-two-spheres"
SEED = 7
COUNT = 4
RESULT = "v_A2n"


@pytest.fixture(scope="module")
def compiled() -> variants.Compiled:
    return variants.compile_problem(derive.load(NAME))


@pytest.fixture(scope="module")
def chosen(compiled: variants.Compiled) -> list[variants.Variant]:
    return variants.draw(compiled, COUNT, seed=SEED)


@pytest.fixture(scope="module")
def moodle(compiled: variants.Compiled, chosen: list[variants.Variant]) -> str:
    return lms.moodle_xml(compiled, chosen, result=RESULT, category=f"$course$/derive/{NAME}")


@pytest.fixture(scope="module")
def pl_folder(compiled: variants.Compiled, chosen: list[variants.Variant], tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("pl") / "question"
    lms.prairielearn(compiled, chosen, folder, result=RESULT, seed=SEED)
    return folder


def _text(el: ET.Element, path: str) -> str:
    found = el.find(path)
    assert found is not None, f"missing <{path}>"
    return found.text or ""


def _numerical(xml: str) -> list[ET.Element]:
    root = ET.fromstring(xml)
    return [q for q in root.findall("question") if q.get("type") == "numerical"]


def _statement(q: ET.Element) -> str:
    """A Moodle question's statement: its text before the set-up figure and what to enter
    (PrairieLearn's panel has the same statement, without the figure)."""
    return _text(q, "questiontext/text").split("\n<p><img")[0].split("\n<p>Enter")[0]


def _ulp(shown: str) -> Decimal:
    return Decimal(1).scaleb(Decimal(shown).as_tuple().exponent)


# ---------------------------------------------------------------- Moodle XML


def test_moodle_xml_has_a_category_and_one_numerical_question_per_variant(
    moodle: str, compiled: variants.Compiled, chosen: list[variants.Variant]
) -> None:
    assert moodle.startswith('<?xml version="1.0" encoding="UTF-8"?>')
    root = ET.fromstring(moodle)
    assert root.tag == "quiz"
    questions = root.findall("question")
    assert questions[0].get("type") == "category"
    assert _text(questions[0], "category/text") == f"$course$/derive/{NAME}"
    numerical = _numerical(moodle)
    assert len(numerical) == len(questions) - 1 == COUNT
    for q, v in zip(numerical, chosen, strict=True):
        key = variants.answers(compiled, v)[RESULT]  # what key.json holds
        assert f"variant {v.number:02d}" in _text(q, "name/text")
        assert q.find("questiontext").get("format") == "html"
        text = _text(q, "questiontext/text")
        given = variants.given_values(compiled, v)
        assert f"m_{{A}} = {given['m_A']['value']:g}" in text and "<strong>Given.</strong>" in text
        assert r"Enter \(v_{A2n}\)" in text and "in m/s" in text
        assert "**" not in text and "$" not in text and "ANSWER" not in text
        assert q.find("generalfeedback").get("format") == "html"
        feedback = _text(q, "generalfeedback/text")
        assert r"\[" in feedback and "ANSWER" in feedback and "$$" not in feedback
        assert float(_text(q, "defaultgrade")) > 0 and 0 <= float(_text(q, "penalty")) <= 1
        right = [a for a in q.findall("answer") if a.get("fraction") == "100"]
        assert len(right) == 1
        assert Decimal(_text(right[0], "text")) == Decimal(key["shown"])
        assert right[0].find("feedback/text") is not None
        tol = Decimal(_text(right[0], "tolerance"))
        assert tol > 0 and tol == Decimal("1.5") * _ulp(key["shown"])
        assert abs(Decimal(repr(key["value"])) - Decimal(key["shown"])) <= tol  # the exact value is accepted
        assert _text(q, "units/unit/unit_name") == "m/s" and _text(q, "units/unit/multiplier") == "1"
        assert _text(q, "showunits") == "0" and _text(q, "unitgradingtype") == "0"


def test_moodle_xml_has_the_common_mistakes_as_wrong_answers(moodle: str) -> None:
    hints = {m.description for m in mistakes.REGISTRY.values()}
    total = 0
    for q in _numerical(moodle):
        right = next(a for a in q.findall("answer") if a.get("fraction") == "100")
        r, tol = Decimal(_text(right, "text")), Decimal(_text(right, "tolerance"))
        wrong = [a for a in q.findall("answer") if a.get("fraction") == "0"]
        values = [Decimal(_text(a, "text")) for a in wrong]
        assert len(set(values)) == len(values)  # one answer per value
        for a, x in zip(wrong, values, strict=True):
            assert abs(x - r) > tol  # never a right answer marked wrong
            assert Decimal(_text(a, "tolerance")) > 0
            feedback = _text(a, "feedback/text")
            assert feedback.strip() and any(lms.esc(h) in feedback for h in hints)
        total += len(wrong)
    assert total >= COUNT


def test_moodle_wrong_values_are_what_the_checker_predicts(
    compiled: variants.Compiled, chosen: list[variants.Variant]
) -> None:
    """The cheap per-variant mistakes equal those of a fresh solve of the variant's numbers."""
    v = chosen[1]
    text = Path(derive.resources.bundled()[NAME]).read_text()
    for name, value in v.values.items():
        unit = {"m_A": "kg", "m_B": "kg", "v_A1": "m/s", "v_B1": "m/s", "e": ""}[name]
        shown = format(Decimal(str(float(value))).normalize(), "f")
        text = re.sub(
            rf"^{name} = .*$", f'{name} = "{shown} {unit}"' if unit else f"{name} = {shown}", text, count=1, flags=re.M
        )
    fresh = mistakes.outcomes(derive.solve(loads(text, path="variant.toml")))
    mine = dict(lms.MistakeModel(compiled).values(v, RESULT))
    assert fresh
    for out in fresh:
        q = out.results[RESULT]
        assert mine[out.mistake.name] == pytest.approx(float(q.value), rel=1e-9)


def test_moodle_xml_is_reproducible(compiled: variants.Compiled, moodle: str) -> None:
    again = lms.moodle_xml(
        compiled, variants.draw(compiled, COUNT, seed=SEED), result=RESULT, category=f"$course$/derive/{NAME}"
    )
    assert again == moodle
    other = lms.moodle_xml(compiled, variants.draw(compiled, 2, seed=SEED + 1), result=RESULT)
    assert other != moodle and len(_numerical(other)) == 2


def test_default_result_and_a_bad_one(compiled: variants.Compiled, chosen: list[variants.Variant]) -> None:
    # 4.C.11 asks for the velocities as vectors (the notes): its first result is v_A2t
    assert lms.default_result(compiled, chosen) == compiled.problem.find[0] == "v_A2t"
    with pytest.raises(derive.errors.InputError, match="--result nope"):
        lms.moodle_xml(compiled, chosen, result="nope")


def test_tolerance_rule() -> None:
    """1.5 units in the last significant figure of the value as rounded (issue #15: 1045.81
    at three figures is shown as 1050 and is right from 1035 to 1065)."""
    assert lms.tolerance("8.40", 3) == lms.tolerance("8.40") == Decimal("0.015")
    assert lms.tolerance("-1.109", 4) == Decimal("0.0015")
    assert lms.tolerance("1050", 3) == Decimal("15")
    assert lms.tolerance("1200", 4) == Decimal("1.5")
    assert lms.tolerance("1200") == Decimal("150")  # figures unknown: trailing zeros of a whole number don't count
    assert lms.tolerance("10.0", 3) == Decimal("0.15")
    assert lms.tolerance("1.23e+7", 3) == lms.tolerance("1.23e+7") == Decimal("1.5e5")
    assert lms.tolerance("0") == lms.tolerance("0", 3) == lms.ZERO_TOLERANCE


def _lms_data() -> dict:
    """Page data (the writers' shape) with hostile text: markup, dollars, backslashes."""
    line = {"latex": r"x = \frac{1}{2}", "tag": "1", "rows": (), "before": "", "after": "", "boxed": False}
    return {
        "title": "Title",
        "statement": [("text", "m = 2 *kg* costs $5 <b>or</b> "), ("math", "a < b"), ("text", r" \(y\).")],
        "givens": [{"latex": "m_{A} = 2", "note": None}, {"latex": "e = 0.5", "note": "a <guess>"}],
        "find": [("text", "x & y")],
        "stages": [  # one impact: one stage, its title empty, holding its own stages
            {
                "number": 1,
                "title": "",
                "givens": [],
                "carried": [],
                "blocks": [],
                "stages": [
                    {"number": 1, "title": "Stage <1>", "blocks": [{"text": [("text", "Take ")], "lines": [line]}]}
                ],
            }
        ],
    }


def test_lms_html_is_the_page_writer_with_mathjax_delimiters() -> None:
    """The LMS's statement and solution come from the page's data through the HTML writer
    (no Markdown parsed): math in \\( \\) and \\[ \\] with its number inside, text that
    never turns into math, no Source line, no <html> wrapper."""
    statement = lms.statement_html(_lms_data())
    assert statement.startswith(
        '<p><strong>Given.</strong> <span class="mathjax_ignore tex2jax_ignore">m = 2 *kg* costs &#36;5 &lt;b&gt;or&lt;/b&gt; </span>'
    )
    assert r"\(a &lt; b\)" in statement and "&#92;(y&#92;)" in statement
    assert r"<li>\(m_{A} = 2\)</li>" in statement and r"<li>\(e = 0.5\) (a &lt;guess&gt;)</li>" in statement
    assert "<p><strong>Find.</strong> x &amp; y</p>" in statement
    solution = lms.solution_html(_lms_data())
    assert solution.startswith("<p><strong>Solution.</strong></p>")
    assert "<h4>1) Stage &lt;1&gt;</h4>" in solution
    assert r"<p>\[ x = \frac{1}{2} \tag{1} \]</p>" in solution
    for out in (statement, solution):
        assert "<html" not in out and "$" not in out and "Title" not in out
        ET.fromstring(f"<div>{out.replace('&#36;', '').replace('&#92;', '')}</div>")  # well-formed


def _numbers(text: str) -> list[str]:
    return sorted(re.findall(r"-?\d+(?:\.\d+)?", text))


def test_lms_feedback_has_the_numbers_of_the_variant_page(
    compiled: variants.Compiled, chosen: list[variants.Variant], moodle: str
) -> None:
    """Moodle's general feedback shows every number of the variant's worked solution (the
    Markdown page, figures aside), and its question text every number of the statement."""
    for v, q in zip(chosen, _numerical(moodle), strict=True):
        page = variants.fill(compiled, v, "md")
        page = re.sub(r"<div align=\"center\">.*?</div>\n", "", page)
        head, _, solution = page.partition("**Solution.**")
        feedback = re.sub(r"<[^>]+>", " ", _text(q, "generalfeedback/text"))
        assert _numbers(feedback) == _numbers(solution)
        question = re.sub(r"<[^>]+>", " ", _text(q, "questiontext/text")).rsplit("Enter", 1)[0]
        head = re.sub(r"^# .*\n|^\*Source: .*\n", "", head, flags=re.M)
        assert _numbers(question) == _numbers(head + _sign_convention(compiled))  # as the sheet


# ---------------------------------------------------------------- PrairieLearn


def test_prairielearn_info_json(pl_folder: Path, compiled: variants.Compiled, chosen: list[variants.Variant]) -> None:
    assert sorted(p.name for p in pl_folder.iterdir()) == ["info.json", "question.html", "server.py"]
    info = json.loads((pl_folder / "info.json").read_text())
    assert info["type"] == "v3" and info["topic"] and compiled.problem.title in info["title"]
    assert isinstance(info["tags"], list) and "derive" in info["tags"]
    assert uuid.UUID(info["uuid"]).version == 5
    same = lms.prairielearn_files(compiled, chosen, result=RESULT, seed=SEED)
    assert json.loads(same["info.json"])["uuid"] == info["uuid"]  # deterministic
    other = lms.prairielearn_files(compiled, chosen, result=RESULT, seed=SEED + 1)
    assert json.loads(other["info.json"])["uuid"] != info["uuid"]


def _server(folder: Path) -> dict:
    code = (folder / "server.py").read_text()
    namespace: dict = {}
    exec(compile(code, str(folder / "server.py"), "exec"), namespace)
    return namespace


def _mustache(page: str, params: dict) -> str:
    page = re.sub(r"\{\{\{params\.(\w+)\}\}\}", lambda m: str(params[m.group(1)]), page)
    return re.sub(r"\{\{params\.(\w+)\}\}", lambda m: str(params[m.group(1)]), page)


def test_prairielearn_question_and_server(
    pl_folder: Path, compiled: variants.Compiled, chosen: list[variants.Variant], moodle: str
) -> None:
    html = (pl_folder / "question.html").read_text()
    assert "<pl-question-panel>" in html and "</pl-question-panel>" in html
    tag = re.search(r"<pl-number-input [^>]*>", html)
    assert tag and f'answers-name="{RESULT}"' in tag.group(0) and 'atol="{{params.derive_atol}}"' in tag.group(0)
    assert 'suffix="m/s"' in tag.group(0)
    assert "{{{params.derive_statement}}}" in html  # each variant's statement, as its sheet prints it
    server = _server(pl_folder)
    questions = _numerical(moodle)
    for seed, index in ((0, 0), (COUNT + 2, 2)):
        data = {"params": {}, "correct_answers": {}, "variant_seed": seed}
        server["generate"](data)
        v = chosen[index]
        key = variants.answers(compiled, v)[RESULT]
        assert data["correct_answers"][RESULT] == float(key["shown"])
        assert data["params"]["derive_variant"] == v.number
        assert data["params"]["derive_atol"] == pytest.approx(1.5 * float(_ulp(key["shown"])))
        for name, given in variants.given_values(compiled, v).items():
            assert float(data["params"][name]) == pytest.approx(given["value"])
        # the statement PrairieLearn shows is the Moodle question's, with the same numbers
        panel = (
            _mustache(html, data["params"]).split("<pl-question-panel>\n")[1].split('\n<div class="derive-figure">')[0]
        )
        moodle_text = _statement(questions[index])
        assert panel == moodle_text
        assert "ANSWER" in data["params"]["derive_solution"]
        # and its figure before the impact, the variant's own (issue #15: there was none)
        assert data["params"]["derive_figure"] == variants.setup_figure(compiled, v, "md")
        shown = _mustache(html, data["params"])
        assert '<div class="derive-figure"><svg' in shown and 'aria-label="Before the impact"' in shown
    bare: dict = {"variant_seed": 1}
    server["generate"](bare)  # a plain dict works too
    assert bare["correct_answers"][RESULT] == float(variants.answers(compiled, chosen[1])[RESULT]["shown"])


def test_prairielearn_statement_is_one_parameter(
    compiled: variants.Compiled, chosen: list[variants.Variant], moodle: str, tmp_path: Path
) -> None:
    """A variant's statement goes whole into the params (a variant is its own problem)."""
    lms.prairielearn(compiled, chosen[:2], tmp_path, result=RESULT)
    assert "{{{params.derive_statement}}}" in (tmp_path / "question.html").read_text()
    data: dict = {"variant_seed": 1}
    _server(tmp_path)["generate"](data)
    moodle_text = _statement(_numerical(moodle)[1])
    assert data["params"]["derive_statement"] == moodle_text


# ---------------------------------------------------------------- the CLI


def test_cli_writes_moodle_and_prairielearn(cli, tmp_path: Path) -> None:
    out, xml, pl = tmp_path / "hw", tmp_path / "hw.xml", tmp_path / "pl" / "impact"
    r = cli(
        "variants", NAME, "--count", "3", "--seed", "4", "-o", str(out),
        "--moodle", str(xml), "--prairielearn", str(pl), "--result", "v_B2n",
    )  # fmt: skip
    assert r.code == 0, r.err
    assert r.err == f"wrote 3 variants (md) to {out}, key.csv, key.json, {xml}, {pl} (PrairieLearn question)\n"
    key = json.loads((out / "key.json").read_text())
    questions = _numerical(xml.read_text())
    assert len(questions) == len(key["variants"]) == 3
    server = _server(pl)
    for i, (q, row) in enumerate(zip(questions, key["variants"], strict=True)):
        shown = row["results"]["v_B2n"]["shown"]
        right = next(a for a in q.findall("answer") if a.get("fraction") == "100")
        assert Decimal(_text(right, "text")) == Decimal(shown)
        data: dict = {"params": {}, "correct_answers": {}, "variant_seed": i}
        server["generate"](data)
        assert data["correct_answers"]["v_B2n"] == float(shown)
    assert 'answers-name="v_B2n"' in (pl / "question.html").read_text()


def test_cli_bad_result_writes_nothing(cli, tmp_path: Path) -> None:
    out, xml = tmp_path / "hw", tmp_path / "hw.xml"
    r = cli("variants", NAME, "--count", "2", "-o", str(out), "--moodle", str(xml), "--result", "v_C2")
    assert r.code == 2 and "--result v_C2" in r.err and "v_A2n" in r.err
    assert not out.exists() and not xml.exists()
    r = cli("variants", NAME, "--count", "2", "-o", str(out), "--result", "v_A2n")
    assert r.code == 2 and "--moodle" in r.err


def test_prairielearn_statement_prints_numbers_as_typed(tmp_path: Path) -> None:
    """A statement's 2.50 m/s, 22 g and {|v_B1|} read in PrairieLearn as in the Moodle
    question and the student's sheet: the places and unit typed, a speed's magnitude."""
    text = textwrap.dedent(
        """
        title = "Two carts"
        kind = "direct"
        statement = "Cart A ({m_A}) at {v_A1} meets cart B coming the other way at {|v_B1|}."
        [given]
        m_A = "22 g"
        m_B = "2.0 kg"
        e = 0.5
        v_A1 = "2.50 m/s"
        v_B1 = "-1.20 m/s"
        [vary]
        v_A1 = { min = "2 m/s", max = "4 m/s", step = "0.5 m/s" }
        v_B1 = { choices = ["-1 m/s", "-1.5 m/s"] }
        m_A = { choices = ["20 g", "36 g"] }
        """
    )
    compiled = variants.compile_problem(loads(text, path="carts.toml"))
    chosen = variants.draw(compiled, 4, seed=2)
    lms.prairielearn(compiled, chosen, tmp_path, result="v_A2")
    moodle = _numerical(lms.moodle_xml(compiled, chosen, result="v_A2"))
    page = (tmp_path / "question.html").read_text()
    server = _server(tmp_path)
    for i, v in enumerate(chosen):
        data: dict = {"params": {}, "correct_answers": {}, "variant_seed": i}
        server["generate"](data)
        panel = (
            _mustache(page, data["params"]).split("<pl-question-panel>\n")[1].split('\n<div class="derive-figure">')[0]
        )
        assert panel == _statement(moodle[i])
        speed = f"{abs(float(v.values['v_B1'])):.2f}"
        assert f"({int(v.values['m_A'] * 1000)} g) at {float(v.values['v_A1']):.2f} m/s" in panel, panel
        assert f"the other way at {speed} m/s." in panel, panel


def test_moodle_question_text_has_the_variants_set_up_figure(
    compiled: variants.Compiled, chosen: list[variants.Variant], moodle: str
) -> None:
    """Issue #15: the question text showed no figure. Each question carries its variant's
    figure before the impact as a file of its text, as Moodle's XML importer reads one
    (qformat_xml::import_files_as_draft: questiontext/file, @name, @path, base64), and the
    text shows it through @@PLUGINFILE@@."""
    import base64

    questions = _numerical(moodle)
    assert len(questions) == len(chosen)
    for q, v in zip(questions, chosen, strict=True):
        text = q.find("questiontext")
        (file,) = text.findall("file")
        assert file.attrib == {"name": "setup.svg", "path": "/", "encoding": "base64"}
        svg = base64.b64decode(file.text).decode("utf-8")
        assert svg == variants.setup_figure(compiled, v, "md")
        assert svg.startswith("<svg") and 'aria-label="Before the impact"' in svg
        assert '<img src="@@PLUGINFILE@@/setup.svg"' in text.find("text").text


@pytest.mark.parametrize("name", [NAME, "young-freedman-8-96-pucks-find-mass"])
def test_an_lms_question_reads_as_the_students_sheet(name: str, cli, tmp_path: Path) -> None:
    """Issue 15: a single impact's LMS question gave no sign convention (the answer is a signed
    component) and marked an inverse problem's unknown "(unknown: derive finds it)"."""
    xml, pl = tmp_path / "q.xml", tmp_path / "pl"
    r = cli("variants", name, "-n", "2", "-o", str(tmp_path / "hw"), "--moodle", str(xml), "--prairielearn", str(pl))
    assert r.code == 0, r.err
    compiled = variants.compile_problem(derive.load(name))
    words = _sign_convention(compiled)
    assert words.startswith("Take $n$ along the line of impact")
    texts = [_text(q, "questiontext/text") for q in _numerical(xml.read_text())]
    data: dict = {"variant_seed": 0}
    _server(pl)["generate"](data)
    texts.append(data["params"]["derive_statement"])  # PrairieLearn's statement, each variant's own
    for text in texts:
        assert "<strong>Sign convention.</strong> Take \\(n\\) along the line of impact" in text
        assert "derive finds it" not in text
    if name != NAME:  # the mass of the inverse problem is the unknown
        assert all("to find" in text for text in texts)


def _tables() -> list[str]:
    from derive.resources import bundled

    return sorted(name for name, path in bundled().items() if "\n[vary]" in path.read_text(encoding="utf-8"))


@pytest.mark.slow
@pytest.mark.parametrize("name", _tables())
def test_every_bundled_table_exports_to_moodle_and_prairielearn(name: str, cli, tmp_path: Path) -> None:
    """Every [vary] table exports (ocr-m3-2013 stopped with "internal error (NotInvertible:
    zero divisor)": a mistake SymPy could not solve); each question's right answer is the key's."""
    xml, pl = tmp_path / "q.xml", tmp_path / "pl"
    r = cli(
        "variants",
        name,
        "-n",
        "2",
        "--seed",
        "5",
        "-o",
        str(tmp_path / "hw"),
        "--moodle",
        str(xml),
        "--prairielearn",
        str(pl),
    )
    assert r.code == 0, r.err
    key = json.loads((tmp_path / "hw" / "key.json").read_text(encoding="utf-8"))
    questions = _numerical(xml.read_text(encoding="utf-8"))
    assert len(questions) == 2 and (pl / "server.py").is_file()
    asked = re.search(r"\((\w+)\)$", _text(questions[0], "name/text")).group(1)
    for q, row in zip(questions, key["variants"], strict=True):
        right = next(a for a in q.findall("answer") if a.get("fraction") == "100")
        assert Decimal(_text(right, "text")) == Decimal(row["results"][asked]["shown"].split()[0])


def test_a_mistake_with_surds_in_the_variant_still_gives_its_value() -> None:
    """ocr-m3-2013, variant 1 of seed 3: the mistaken equations of e_speeds (restitution with
    speeds) have cos/sin of the angle among their numbers; solved exactly they were factored
    over the surds' number field for a minute and gave nothing, so the STACK question lost
    that mistake. Its value is a root of the mistaken equations, in [0, 1] and not the key's."""
    compiled = variants.compile_problem(derive.load("ocr-m3-2013-b-turns-through-right-angle"))
    v = variants.draw(compiled, 2, 3)[0]
    model = lms.MistakeModel(compiled)
    found = dict(model.outcomes(v))
    assert "e_speeds" in found
    e = float(found["e_speeds"]["e"].value)
    key = float(variants.answers(compiled, v)["e"]["value"])
    assert 0 <= e <= 1 and abs(e - key) > 1e-3
