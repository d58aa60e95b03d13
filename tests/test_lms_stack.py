"""STACK export (issue 30): ``derive variants --stack``: Moodle XML with STACK questions whose
variables (plain Maxima) hold derive's variants; checked against STACK's importer, its
CASText blocks, its NumAbsolute answer test (tests/support/stack_check.py) and Debian's Maxima."""

from __future__ import annotations

import json
import math
import textwrap
import xml.etree.ElementTree as ET
from decimal import Decimal
from pathlib import Path

import pytest
from support import stack_check as sc

import derive
from derive.homework import lms, variants
from derive.homework.lms import stack
from derive.problem import loads

NAME = "notes-4c11-two-spheres"
COUNT = 5
SEED = 1


@pytest.fixture(scope="module")
def compiled() -> variants.Compiled:
    return variants.compile_problem(derive.load(NAME))


@pytest.fixture(scope="module")
def chosen(compiled: variants.Compiled) -> list[variants.Variant]:
    return variants.draw(compiled, COUNT, SEED)


@pytest.fixture(scope="module")
def model(compiled: variants.Compiled) -> lms.MistakeModel:
    return lms.MistakeModel(compiled)


@pytest.fixture(scope="module")
def xml(compiled: variants.Compiled, chosen: list[variants.Variant], model: lms.MistakeModel) -> str:
    return stack.stack_xml(compiled, chosen, model=model)


def _asked(q: ET.Element) -> str:
    return q.findtext("name/text", "").rsplit("(", 1)[1].rstrip(")")


def _variables(q: ET.Element) -> str:
    return q.findtext("questionvariables/text", "")


# ---------------------------------------------------------------- structure (no Maxima)


def test_one_stack_question_per_asked_result_with_every_field_stack_reads(xml: str) -> None:
    root = ET.fromstring(xml)
    assert root.find("question").get("type") == "category"
    questions = sc.stack_questions(xml)
    assert [_asked(q) for q in questions] == list(derive.load(NAME).find)  # the file's find list
    for q in questions:
        assert sc.check_fields(q) == []
        assert q.findtext("stackversion/text") == "2026010500"
        assert [s.text for s in q.findall("deployedseed")] == [str(k) for k in range(1, COUNT + 1)]
        assert _variables(q).splitlines()[1] == f"n1:mod(stack_seed-1,{COUNT})+1;"
        lists = sc.python_lists(_variables(q))
        assert lists and all(len(v) == COUNT for v in lists.values())
        assert len(set(lists["dnote"])) == COUNT  # STACK refuses two variants with one note
        ans = q.find("input")
        assert (ans.findtext("name"), ans.findtext("type"), ans.findtext("tans")) == ("ans1", "units", "ta1")
        assert "ta1:dans[n1]*m/s;" in _variables(q)


def test_castext_blocks_are_balanced_and_derive_text_is_escaped(xml: str) -> None:
    for q in sc.stack_questions(xml):
        text = q.findtext("questiontext/text")
        assert sc.check_castext(text, ("input:ans1", "validation:ans1")) == []
        assert text.count("[[input:ans1]]") == 1 and text.count("[[validation:ans1]]") == 1
        feedback = q.findtext("generalfeedback/text")
        assert sc.check_castext(feedback) == []
        assert feedback.count("[[escape]]") == COUNT and feedback.count('[[elif test="is(n1=') == COUNT - 1
        assert sc.check_castext(q.findtext("specificfeedback/text"), ("feedback:prt1",)) == []
        assert sc.check_castext(q.findtext("questionnote/text")) == []
        for node in q.iter("node"):
            assert sc.check_castext(node.findtext("truefeedback/text")) == []


def test_hostile_text_stays_text() -> None:
    """A statement with CASText of its own (an escape block's end, {@...@}, [[if]]) is printed,
    never run: it is inside [[escape]] and cannot close it."""
    text = textwrap.dedent(
        """
        title = "Carts [[/escape]] {@x@}"
        kind = "direct"
        statement = "Cart A at {v_A1} meets B [[/escape]][[if test='true']] {#1#} $5 at rest."
        [given]
        m_A = "2 kg"
        m_B = "3 kg"
        e = 0.5
        v_A1 = "2.50 m/s"
        v_B1 = "0 m/s"
        [vary]
        v_A1 = { min = "2 m/s", max = "4 m/s", step = "0.5 m/s" }
        """
    )
    compiled = variants.compile_problem(loads(text, path="carts.toml"))
    chosen = variants.draw(compiled, 3, seed=2)
    for q in sc.stack_questions(stack.stack_xml(compiled, chosen, result="v_A2")):
        for field in ("questiontext/text", "generalfeedback/text"):
            found = q.findtext(field)
            assert sc.check_castext(found, ("input:ans1", "validation:ans1")) == []
        assert "[&#91;/escape]][[if test='true']] {#1#} &#36;5" in q.findtext("questiontext/text")


def test_question_tests_pass_on_every_variant_in_stack_s_answer_test(xml: str) -> None:
    for q in sc.stack_questions(xml):
        tests = q.findall("qtest")
        assert tests[0].findtext("expected/expectedanswernote") == "right"
        assert len(tests) > 1  # mistakes reach their own notes
        assert sc.replay_qtests(q, sc.python_lists(_variables(q)), COUNT) == []


def test_the_tree_grades_as_derive_does(
    xml: str, compiled: variants.Compiled, chosen: list[variants.Variant], model: lms.MistakeModel
) -> None:
    """In every variant: the right range is derive's (shown ± 1.5 units of the last figure), each
    value a mistake gives reaches that mistake's note, and no two ranges overlap."""
    for q in sc.stack_questions(xml):
        result, prt, lists = _asked(q), q.find("prt"), sc.python_lists(_variables(q))
        for k, v in enumerate(chosen, 1):
            row = variants.answers(compiled, v)[result]
            right = lms.grading.asked_answer(result, row, compiled.problem.digits)
            shown, tol = float(right.shown), float(right.tolerance)
            for x, want in ((shown, 1.0), (shown + 0.99 * tol, 1.0), (shown - tol, 1.0), (shown + 1.02 * tol, 0.0)):
                assert sc.replay(prt, lists, k, x)[0] == want, (k, x)
            wrongs = model.wrong(v, right, None)
            assert wrongs
            for w in wrongs:
                note = sc.replay(prt, lists, k, float(w.shown))[1][-1]
                assert note in w.mistakes, (k, w.shown, note)
            spans = [(shown - tol, shown + tol)]
            for i in range(1, len(q.findall("prt/node"))):
                c, h = lists[f"dc{i}"][k - 1], lists[f"dh{i}"][k - 1]
                if h > 0:
                    spans.append((c - h, c + h))
            assert sc.overlaps(spans) == []


def test_right_answer_and_two_mistakes_from_the_physics(xml: str) -> None:
    """Independent of derive: momentum and restitution along n, t kept (tests/test_lms_formats.py's
    physics), from the givens the question variables hold; B's velocity with the wrong sign and
    the masses swapped are the same physics with v_B1 or the masses changed."""
    from test_lms_formats import physics_4c11

    for q in sc.stack_questions(xml):
        result, lists = _asked(q), sc.python_lists(_variables(q))
        names = [n.findtext("trueanswernote") for n in q.findall("prt/node")]
        for k in range(COUNT):
            g = {n: lists["dg_" + n][k] for n in ("m_A", "m_B", "e", "v_A1", "v_B1")}
            tol = lists["dtol"][k]
            assert abs(lists["dans"][k] - physics_4c11(g)[result]) <= tol / 3  # shown to 3 figures
            flipped = physics_4c11({**g, "v_B1": -g["v_B1"]})[result]
            swapped = physics_4c11({**g, "m_A": g["m_B"], "m_B": g["m_A"]})[result]
            for mistake, value in (("b_sign", flipped), ("masses_swapped", swapped)):
                if mistake not in names:  # the mistake leaves this result as it is (v_A2t: B's sign)
                    assert abs(value - physics_4c11(g)[result]) <= tol
                    continue
                i = names.index(mistake)
                assert math.isclose(lists[f"dw{i}"][k], float(f"{value:.3g}"))


def test_cli_writes_stack_questions_and_caps_the_count(cli, tmp_path: Path) -> None:
    out, q = tmp_path / "hw", tmp_path / "q.xml"
    r = cli("variants", NAME, "--count", "5", "--seed", "1", "-o", str(out), "--stack", str(q))
    assert r.code == 0, r.err
    assert r.err == f"wrote 5 variants (md) to {out}, key.csv, key.json, {q} (STACK questions)\n"
    assert len(sc.stack_questions(q.read_text(encoding="utf-8"))) == len(derive.load(NAME).find)
    r = cli("variants", NAME, "--count", "51", "-o", str(tmp_path / "b"), "--stack", str(tmp_path / "b.xml"))
    assert r.code == 2 and "at most 50 variants" in r.err and len(r.err.splitlines()) == 1
    assert not (tmp_path / "b").exists() and not (tmp_path / "b.xml").exists()
    r = cli("variants", NAME, "-o", str(tmp_path / "c"), "--stack", str(tmp_path / "c.xml"), "--result", "v_A2n")
    assert r.code == 0, r.err
    assert json.loads((tmp_path / "c" / "key.json").read_text())["count"] == stack.DEFAULT_COUNT
    assert [_asked(x) for x in sc.stack_questions((tmp_path / "c.xml").read_text())] == ["v_A2n"]
    r = cli("variants", NAME, "-n", "2", "-o", str(tmp_path / "d"), "--stack", str(tmp_path / "d.xml"), "--result", "x")
    assert r.code == 2 and not (tmp_path / "d").exists() and not (tmp_path / "d.xml").exists()


# ---------------------------------------------------------------- Maxima


def maxima_checks(
    compiled: variants.Compiled, chosen: list[variants.Variant], xml_text: str, model: lms.MistakeModel
) -> list[str]:
    """Maxima, given stack_seed:k and each question's variables: n1 = k, every list N long, the
    teacher's answer the key's, each mistake value derive's, the statement is each variant's own sheet;
    then the question tests replayed on Maxima's values and the ranges checked for overlap."""
    errors: list[str] = []
    n = len(chosen)
    for q in sc.stack_questions(xml_text):
        result, variables = _asked(q), _variables(q)
        unit = stack.STACK_UNITS.get(_unit(compiled, chosen[0], result), "")
        values = sc.maxima_values(variables, n, unit)
        lists: dict[str, list] = {}
        for k, v in enumerate(chosen, 1):
            got = values[k]
            errors += [
                f"{result} {k}: {name} has {got[name]}" for name in got if name[0] == "#" and got[name] != str(n)
            ]
            for name in got:
                if name[0] != "#" and name not in ("n1", "ta1"):
                    lists.setdefault(name, []).append(got[name])
            row = variants.answers(compiled, v)[result]
            right = lms.grading.asked_answer(result, row, compiled.problem.digits)
            if got["n1"] != str(k) or float(got["ta1"]) != float(right.shown):
                errors.append(f"{result} {k}: n1 {got['n1']}, ta1 {got['ta1']}, key {right.shown}")
            if abs(Decimal(got["ta1"]) - Decimal(repr(row["value"]))) > right.tolerance:
                errors.append(f"{result} {k}: ta1 {got['ta1']} is not the key's {row['value']}")
            errors += _mistakes_match(q, got, model.wrong(v, right, None), f"{result} {k}")
        numbers = {
            name: [float(x) for x in xs] for name, xs in lists.items() if name[:2] in ("da", "dt", "dc", "dh", "dw")
        }
        errors += sc.replay_qtests(q, numbers, n)
        for k in range(1, n + 1):
            spans = [(numbers["dans"][k - 1] - numbers["dtol"][k - 1], numbers["dans"][k - 1] + numbers["dtol"][k - 1])]
            for i in range(1, len(q.findall("prt/node"))):
                c, h = numbers[f"dc{i}"][k - 1], numbers[f"dh{i}"][k - 1]
                spans += [(c - h, c + h)] if h > 0 else []
            errors += [f"{result} {k}: ranges {pair} overlap" for pair in sc.overlaps(spans)]
    return errors


def _unit(compiled: variants.Compiled, v: variants.Variant, result: str) -> str:
    return variants.answers(compiled, v)[result]["unit"]


def _mistakes_match(q: ET.Element, got: dict[str, str], wrongs: list, where: str) -> list[str]:
    """Each node that is on in this variant holds a value derive's mistakes give, named by one of them."""
    names = [n.findtext("trueanswernote") for n in q.findall("prt/node")]
    by_value = {Decimal(w.shown): w for w in wrongs}
    errors = []
    for i in range(1, len(names)):
        if float(got[f"dh{i}"]) == 0:
            continue
        w = by_value.get(Decimal(got[f"dw{i}"]))
        if w is None or names[i] not in w.mistakes:
            errors.append(f"{where}: node {names[i]} holds {got[f'dw{i}']}, derive's: {[x.shown for x in wrongs]}")
    return errors


@pytest.mark.slow
def test_maxima_evaluates_each_teacher_answer_to_the_key(cli, tmp_path: Path) -> None:
    """Issue 30, done when: derive variants notes-4c11-two-spheres --count 5 --seed 1 -o hw --stack q.xml;
    Maxima with stack_seed:k evaluates each question's teacher's answer to key.json's for variant k."""
    assert sc.have_maxima(), "Debian's maxima is needed (.ci/install installs it)"
    out, q = tmp_path / "hw", tmp_path / "q.xml"
    r = cli("variants", NAME, "--count", "5", "--seed", "1", "-o", str(out), "--stack", str(q))
    assert r.code == 0, r.err
    key = json.loads((out / "key.json").read_text(encoding="utf-8"))
    xml_text = q.read_text(encoding="utf-8")
    for question in sc.stack_questions(xml_text):
        result = _asked(question)
        values = sc.maxima_values(_variables(question), 5, "m/s")
        for k, row in enumerate(key["variants"], 1):
            assert Decimal(values[k]["ta1"]) == Decimal(row["results"][result]["shown"])
    compiled = variants.compile_problem(derive.load(NAME))
    assert maxima_checks(compiled, variants.draw(compiled, 5, 1), xml_text, lms.MistakeModel(compiled)) == []


def _tables() -> list[str]:
    from derive.resources import bundled

    return sorted(name for name, path in bundled().items() if "\n[vary]" in path.read_text(encoding="utf-8"))


@pytest.mark.slow
@pytest.mark.parametrize("name", _tables())
def test_every_bundled_table_exports_to_stack_and_maxima_agrees(name: str) -> None:
    assert sc.have_maxima(), "Debian's maxima is needed (.ci/install installs it)"
    compiled = variants.compile_problem(derive.load(name))
    chosen = variants.draw(compiled, 2, 3)
    model = lms.MistakeModel(compiled)
    xml_text = stack.stack_xml(compiled, chosen, model=model)
    for q in sc.stack_questions(xml_text):
        assert sc.check_fields(q) == []
        assert sc.check_castext(q.findtext("questiontext/text"), ("input:ans1", "validation:ans1")) == []
        assert sc.check_castext(q.findtext("generalfeedback/text")) == []
    assert maxima_checks(compiled, chosen, xml_text, model) == []
