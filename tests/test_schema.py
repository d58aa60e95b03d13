"""The declared schema: one place for every field, the docs and the JSON Schema written from it.

- The field tables in the docs and the JSON Schema files are what ``derive.problem.export``
  writes now (regenerate with ``python -m derive.problem.export``).
- Every bundled problem and every complete example of the docs is valid under the JSON
  Schema an editor uses, and files derive refuses for a wrong type or an unknown key
  the JSON Schema refuses too.
- Each chain stage type has a table, and every field its solver reads is declared in it.
- Errors name the file, the line, the field, what was expected and what was found, with
  "did you mean" for a misspelt key.
"""

from __future__ import annotations

import json
import re
import tomllib
from pathlib import Path

import jsonschema
import pytest

import derive
from derive.physics.chain import STAGES as SOLVERS
from derive.problem import export, loads
from derive.problem.schema import CHAIN, PROBLEM, STAGES

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = sorted((ROOT / "problems").glob("*.toml"))


@pytest.mark.parametrize("path", sorted(export.outputs(ROOT)), ids=lambda p: p.name)
def test_generated_files_are_up_to_date(path: Path) -> None:
    want = export.outputs(ROOT)[path]
    assert path.read_text(encoding="utf-8") == want, f"{path.name} is out of date: run python -m derive.problem.export"


def test_the_docs_have_every_generated_block() -> None:
    text = (ROOT / "docs" / "problem-format.md").read_text(encoding="utf-8")
    text += (ROOT / "docs" / "checking.md").read_text(encoding="utf-8")
    found = set(re.findall(r"<!-- generated: ([\w-]+) -->", text))
    assert found == set(export.BLOCKS)


@pytest.fixture(scope="module")
def problem_validator() -> jsonschema.Draft7Validator:
    schema = json.loads((ROOT / "docs" / "derive-problem.schema.json").read_text(encoding="utf-8"))
    jsonschema.Draft7Validator.check_schema(schema)
    return jsonschema.Draft7Validator(schema)


@pytest.mark.parametrize("path", PROBLEMS, ids=lambda p: p.stem)
def test_bundled_problems_are_valid_under_the_json_schema(problem_validator, path: Path) -> None:
    data = tomllib.loads(path.read_text(encoding="utf-8"))
    errors = [e.message for e in problem_validator.iter_errors(data)]
    assert errors == []


def test_documented_examples_are_valid_under_the_json_schema(problem_validator) -> None:
    blocks = re.findall(r"```toml\n(.*?)```", (ROOT / "docs" / "problem-format.md").read_text(encoding="utf-8"), re.S)
    complete = [b for b in blocks if b.lstrip().startswith("title")]
    assert len(complete) >= 4
    for block in complete:
        assert list(problem_validator.iter_errors(tomllib.loads(block))) == []


def test_answers_schema_accepts_the_documented_answers() -> None:
    schema = json.loads((ROOT / "docs" / "derive-answers.schema.json").read_text(encoding="utf-8"))
    validator = jsonschema.Draft7Validator(schema)
    text = (ROOT / "tests" / "data" / "answers-4c11.toml").read_text(encoding="utf-8")
    assert list(validator.iter_errors(tomllib.loads(text))) == []
    assert list(validator.iter_errors({"answers": {"v_A2n": True}}))
    assert list(validator.iter_errors({"answer": {}}))


CHAIN_HEAD = 'title = "c"\nkind = "chain"\n[given]\nm = "0.2 kg"\nv_0 = "5 m/s"\nk_s = "200 N/m"\n'
#: Files derive refuses for their shape (a wrong type, an unknown key): an editor's schema must too.
REFUSED_BY_BOTH = {
    "title-number": 'title = 5\nkind = "direct"\n[given]\nm_A = 1\n',
    "unknown-key": 'title = "t"\nkind = "direct"\ncolour = "red"\n[given]\nm_A = 1\n',
    "kind-word": 'title = "t"\nkind = "sideways"\n[given]\nm_A = 1\n',
    "digits-zero": 'title = "t"\nkind = "direct"\ndigits = 0\n[given]\nm_A = 1\n',
    "given-list": 'title = "t"\nkind = "direct"\n[given]\nm_A = [1, 2]\n',
    "given-bool": 'title = "t"\nkind = "direct"\n[given]\nm_A = true\n',
    "body-axis": 'title = "t"\nkind = "oblique"\n[given]\nm_A = 1\n[A]\nfrom = "+z"\n',
    "fixed-text": 'title = "t"\nkind = "direct"\n[given]\nm_A = 1\n[B]\nfixed = "yes"\n',
    "vary-form": 'title = "t"\nkind = "direct"\n[given]\nm_A = 1\n[vary]\nm_A = { min = 1 }\n',
    "vertical-text": CHAIN_HEAD
    + '[[stage]]\ntype = "spring"\nspeed = "v_0"\nmass = "m"\nk = "k_s"\nvertical = "false"\n',
    "stage-title-number": CHAIN_HEAD + '[[stage]]\ntype = "define"\nexpr = "v_0"\ntitle = 5\n',
    "range-of-list": CHAIN_HEAD + '[[stage]]\ntype = "again"\nbehind = "v_0"\nahead = "0"\nrange_of = ["e"]\n',
    "stage-unknown-key": CHAIN_HEAD + '[[stage]]\ntype = "rise"\nspeed = "v_0"\nheigth = "1 m"\n',
    "stage-missing": CHAIN_HEAD + '[[stage]]\ntype = "slide"\nspeed = "v_0"\n',
    "stage-type": CHAIN_HEAD + '[[stage]]\ntype = "jump"\n',
    "count-big": CHAIN_HEAD + '[[stage]]\ntype = "bounces"\nheight = "1 m"\ne = 0.5\ncount = 51\n',
    "no-stages": CHAIN_HEAD,
}


@pytest.mark.parametrize("name", sorted(REFUSED_BY_BOTH))
def test_derive_and_the_json_schema_refuse_the_same_shapes(problem_validator, name: str) -> None:
    text = REFUSED_BY_BOTH[name]
    assert list(problem_validator.iter_errors(tomllib.loads(text))), "the JSON Schema accepts it"
    with pytest.raises(derive.InputError) as info:
        loads(text, path="x.toml")
    message = str(info.value)
    assert message.startswith("x.toml"), message
    assert "\n" not in message


def test_every_stage_type_has_a_table_and_a_solver() -> None:
    assert set(STAGES) == set(SOLVERS)


@pytest.mark.parametrize("module", sorted((ROOT / "derive" / "physics" / "stages").glob("*.py")), ids=lambda p: p.stem)
def test_every_field_a_stage_reads_is_declared(module: Path) -> None:
    """The fields each stage solver reads (``st.get("speed")``, ``state.quantity(i, st, "speed", ...)``)
    are in the schema of its stage type."""
    source = module.read_text(encoding="utf-8")
    declared = {f.name for table in STAGES.values() for f in table.fields}
    read = set(re.findall(r'st\.get\("(\w+)"', source)) | set(re.findall(r'quantity\(i, st, "(\w+)"', source))
    read |= set(re.findall(r'st\["(\w+)"\]', source))
    assert read <= declared, read - declared
    for func in re.findall(r"^def (\w+)\(state: ChainState, i: int, st: dict\)", source, re.M):
        assert func in STAGES or func in ("impact",), func


def test_top_level_tables_list_their_fields() -> None:
    assert PROBLEM.names[:2] == ("title", "kind") and CHAIN.names[:2] == ("title", "kind")
    assert {"given", "A", "B", "geometry", "vary", "conditions", "find", "digits", "units"} <= set(PROBLEM.names)


# ---------------------------------------------------------------- the messages


@pytest.mark.parametrize(
    ("text", "needles"),
    [
        ('titel = "t"\nkind = "direct"\n', ["x.toml:1: titel: unknown field", 'did you mean "title"?']),
        (
            'title = "t"\nkind = "direct"\n[given]\nm_A = 1\n[A]\nangel = "30 deg"\n',
            ["x.toml:6: [A] angel: unknown field", 'did you mean "angle"?', "expected one of: angle, from"],
        ),
        ('title = "t"\nkind = "dirct"\n', ["x.toml:2: kind = 'dirct'", 'did you mean "direct"?']),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "rise"\nspeed = "v_0"\nreslt = "h"\n',
            ["x.toml:10: [stage 1] reslt: unknown field", 'did you mean "result"?'],
        ),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "rise"\nspeed = "v_0"\n[[stage]]\ntype = "fall"\nheight = 2\nbody = 7\n',
            ["x.toml:13: [stage 2] body = 7: expected", "found a number"],
        ),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "spring"\nspeed = "v_0"\nmass = "m"\nk = "k_s"\nvertical = "false"\n',
            ["x.toml:12: [stage 1] vertical = 'false': expected true or false, found text"],
        ),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "slide"\nspeed = "v_0"\n',
            ["x.toml:7: [stage 1] mu: is missing: expected", "coefficient of kinetic friction"],
        ),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "impact"\nkind = "direct"\ngiven = { m_A = true }\n',
            ["x.toml:10: [stage 1] given.m_A = true: expected a number or text", "found true/false"],
        ),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "define"\nexpr = "v_0 +* 2"\nresult = "v_0"\n',
            ["x.toml:10: [stage 1] result = 'v_0': 'v_0' is used already"],
        ),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "define"\nexpr = "sin(sin(sin(sin(sin(v_0)))))"\n',
            ["x.toml:9: [stage 1] expr = ", "functions are nested too deeply"],
        ),
        (
            CHAIN_HEAD + '[[stage]]\ntype = "solve"\ncondition = "v_0 = 1e40 m/s"\n',
            ["x.toml:9: [stage 1] condition = 'v_0 = 1e40 m/s'", "out of range"],
        ),
        ("\ufeff" + 'title = "t"\nkind = "direct"\n[given]\nm_A = [[[[1]]]]\n', ["x.toml:4: [given] m_A"]),
    ],
    ids=lambda v: v if isinstance(v, str) and len(v) < 40 else None,
)
def test_error_names_file_line_field_expected_found(text: str, needles: list[str]) -> None:
    with pytest.raises(derive.InputError) as info:
        loads(text, path="x.toml")
    message = str(info.value)
    for needle in needles:
        assert needle in message, (needle, message)


def test_no_did_you_mean_when_nothing_is_close() -> None:
    with pytest.raises(derive.InputError) as info:
        loads('zzzzzz = 1\ntitle = "t"\nkind = "direct"\n', path="x.toml")
    assert "did you mean" not in str(info.value) and "unknown field (expected one of: title" in str(info.value)


def test_a_stage_given_names_its_own_line() -> None:
    """An impact stage's table is checked again when its stage is solved (it may name earlier results):
    its errors then point at the stage's line, not at the chain's [given]."""
    text = CHAIN_HEAD + '[[stage]]\ntype = "impact"\nkind = "direct"\ngiven = { m_A = "m", e = 1.5, v_A1 = "v_0" }\n'
    text += "B = { fixed = true }\n"
    with pytest.raises(derive.InputError) as info:
        derive.solve(loads(text, path="x.toml"))
    assert str(info.value).startswith("x.toml:10: [stage 1] given.e = 1.5: the coefficient of restitution"), str(
        info.value
    )
