"""What STACK does with derive's STACK export, re-implemented for the tests.

Written from a reading of STACK's public source, github.com/maths/moodle-qtype_stack at
commit a14f3034a0e45aab27dcae96c526a6095dbf6ef7 (STACK 4.11.1, version 2026010500); nothing
is copied:

* ``questiontype.php`` — ``import_from_xml``, ``import_xml_input``, ``import_xml_prt``,
  ``import_xml_prt_node``, ``import_xml_qtest`` (the fields the importer reads, below) and
  ``validate_prt`` (PRT names of at most 18 characters, answer notes unique in a tree);
  ``lang/en/qtype_stack.php`` ``inputnamelength`` (input names: at most 18 characters);
* ``stack/maxima/numericaltest.mac`` — ``numabsolutep``: a response passes NumAbsolute when
  ``abs(sa-ta) < abs(tol) + STACK_NUM_TOL`` with ``STACK_NUM_TOL:10E-10`` (1e-9);
* ``stack/maxima/stackunits.mac`` — ``ATUnitsFun``: UnitsAbsolute with the units of the
  teacher's answer compares the numbers by ``ATNumAbsolute`` (options without units take
  the teacher's);
* ``stack/questiontestresult.php`` — ``test_answer_note``: a question test's expected answer
  note is compared with the last note of the tree's path;
* ``stack/cas/castext2/autogen/parser-grammar.pegjs`` — an escape block runs to the first
  ``[[/escape]]``; if blocks are ``[[if test=...]]``, ``[[elif test=...]]``, ``[[else]]``,
  ``[[/if]]``; ``doc/en/STACK_question_admin/Deploying_systematically.md`` — ``stack_seed``.
"""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import tempfile
import xml.etree.ElementTree as ET
from pathlib import Path

STACK_NUM_TOL = 1e-9

#: The fields of a question that ``import_from_xml`` reads (besides Moodle's own headers).
QUESTION_FIELDS = [
    "name/text",
    "questiontext/text",
    "generalfeedback/text",
    "defaultgrade",
    "penalty",
    "hidden",
    "stackversion/text",
    "questionvariables/text",
    "specificfeedback/text",
    "questionnote/text",
    "questiondescription/text",
    "questionsimplify",
    "assumepositive",
    "assumereal",
    "prtcorrect/text",
    "prtpartiallycorrect/text",
    "prtincorrect/text",
    "decimals",
    "scientificnotation",
    "multiplicationsign",
    "sqrtsign",
    "complexno",
    "inversetrig",
    "logicsymbol",
    "matrixparens",
    "isbroken",
    "variantsselectionseed",
]
INPUT_FIELDS = [
    "name",
    "type",
    "tans",
    "boxsize",
    "strictsyntax",
    "insertstars",
    "syntaxhint",
    "syntaxattribute",
    "forbidwords",
    "allowwords",
    "forbidfloat",
    "requirelowestterms",
    "checkanswertype",
    "mustverify",
    "showvalidation",
    "options",
]
PRT_FIELDS = ["name", "value", "autosimplify", "feedbackstyle", "feedbackvariables/text"]
NODE_FIELDS = [
    "name",
    "description",
    "answertest",
    "sans",
    "tans",
    "testoptions",
    "quiet",
    "truescoremode",
    "truescore",
    "truepenalty",
    "truenextnode",
    "trueanswernote",
    "truefeedback/text",
    "falsescoremode",
    "falsescore",
    "falsepenalty",
    "falsenextnode",
    "falseanswernote",
    "falsefeedback/text",
]
QTEST_FIELDS = [
    "testcase",
    "description",
    "testinput/name",
    "testinput/value",
    "expected/name",
    "expected/expectedscore",
]
QTEST_FIELDS += ["expected/expectedpenalty", "expected/expectedanswernote"]
_NAME = re.compile(r"^[A-Za-z][A-Za-z0-9_]{0,17}$")


def stack_questions(xml_text: str) -> list[ET.Element]:
    return [q for q in ET.fromstring(xml_text).findall("question") if q.get("type") == "stack"]


def check_fields(q: ET.Element) -> list[str]:
    """Every field STACK's importer reads is there; names are at most 18 characters; answer
    notes are unique in each tree; next nodes exist."""
    errors = [f"no <{f}>" for f in QUESTION_FIELDS if q.find(f) is None]
    for el in q.findall("input"):
        errors += [f"input: no <{f}>" for f in INPUT_FIELDS if el.find(f) is None]
        if not _NAME.match(el.findtext("name", "")):
            errors.append(f"input name {el.findtext('name')!r}")
    for prt in q.findall("prt"):
        errors += [f"prt: no <{f}>" for f in PRT_FIELDS if prt.find(f) is None]
        if not _NAME.match(prt.findtext("name", "")):
            errors.append(f"prt name {prt.findtext('name')!r}")
        nodes = prt.findall("node")
        names = {n.findtext("name") for n in nodes}
        notes = []
        for n in nodes:
            errors += [f"node: no <{f}>" for f in NODE_FIELDS if n.find(f) is None]
            notes += [n.findtext("trueanswernote"), n.findtext("falseanswernote")]
            for branch in ("truenextnode", "falsenextnode"):
                if n.findtext(branch) != "-1" and n.findtext(branch) not in names:
                    errors.append(f"node {n.findtext('name')}: {branch} {n.findtext(branch)} is no node")
        if len(set(notes)) != len(notes):
            errors.append("answer notes are not unique")
    for t in q.findall("qtest"):
        errors += [f"qtest: no <{f}>" for f in QTEST_FIELDS if t.find(f) is None]
    return errors


_TOKEN = re.compile(
    r"\[\[escape\]\](?:(?!\[\[/\s*escape\s*\]\]).)*\[\[/escape\]\]"  # an escape block, whole
    r'|\[\[(?:[^\]"]|"[^"]*")*\]\]'  # a block's tag (a test may hold "]")
    r"|\{[@#]|[@#]\}",
    re.S,
)


def check_castext(text: str, allowed: tuple[str, ...] = ()) -> list[str]:
    """The CASText blocks outside escape blocks: if/elif/else balanced, only ``allowed``
    other blocks (``input:ans1``, ...), every ``{@``/``{#`` closed; no ``[[`` or ``{@`` left
    in the text between them."""
    errors, depth = [], 0
    pos = 0
    for m in _TOKEN.finditer(text):
        between = text[pos : m.start()]
        pos = m.end()
        if "[[" in between or "]]" in between:
            errors.append(f"stray brackets: {between[:40]!r}")
        tok = m.group(0)
        if tok.startswith("[[escape]]"):
            continue
        if tok.startswith("[[if "):
            depth += 1
        elif tok.startswith(("[[elif ", "[[else]]")):
            errors += [] if depth > 0 else ["elif/else outside if"]
        elif tok == "[[/if]]":
            depth -= 1
            errors += [] if depth >= 0 else ["[[/if]] without [[if]]"]
        elif tok in ("{@", "{#"):
            end = text.find("@}" if tok == "{@" else "#}", m.end())
            if end < 0:
                errors.append("unclosed " + tok)
        elif tok.startswith("[[") and tok[2:-2] not in allowed:
            errors.append(f"unknown block {tok}")
    return errors + ([f"{depth} [[if]] left open"] if depth else [])


def python_lists(variables: str) -> dict[str, list]:
    """The question variables' lists, read in Python (derive writes them as JSON-like lists)."""
    return {m.group(1): json.loads(m.group(2)) for m in re.finditer(r"^(\w+):(\[.*\]);$", variables, re.M)}


def at(expr: str, values: dict[str, list], k: int) -> float:
    """The number of a node's or test's expression, ``NAME[n1]`` or ``NAME[n1]*units``, in variant k."""
    m = re.fullmatch(r"(\w+)\[n1\](\*.+)?", expr)
    assert m, f"not a list entry: {expr}"
    return float(values[m.group(1)][k - 1])


def num_absolute(sa: float, ta: float, tol: float) -> bool:
    """STACK's ``numabsolutep``."""
    return abs(sa - ta) < abs(tol) + STACK_NUM_TOL


def replay(prt: ET.Element, values: dict[str, list], k: int, response: float) -> tuple[float, list[str]]:
    """The tree's score and answer notes for a response (in the asked unit) in variant k."""
    nodes = {n.findtext("name"): n for n in prt.findall("node")}
    name, notes, score = "0", [], 0.0
    while name != "-1":
        n = nodes[name]
        assert n.findtext("answertest") in ("NumAbsolute", "UnitsAbsolute"), n.findtext("answertest")
        ok = num_absolute(response, at(n.findtext("tans"), values, k), at(n.findtext("testoptions"), values, k))
        branch = "true" if ok else "false"
        score = float(n.findtext(f"{branch}score"))
        notes.append(n.findtext(f"{branch}answernote"))
        name = n.findtext(f"{branch}nextnode")
    return score, notes


def replay_qtests(q: ET.Element, values: dict[str, list], count: int) -> list[str]:
    """Every question test on every deployed variant, through :func:`replay`."""
    prt = q.find("prt")
    errors = []
    for t in q.findall("qtest"):
        for k in range(1, count + 1):
            x = at(t.findtext("testinput/value"), values, k)
            score, notes = replay(prt, values, k, x)
            want = (float(t.findtext("expected/expectedscore")), t.findtext("expected/expectedanswernote"))
            if (score, notes[-1]) != want:
                errors.append(f"variant {k}, test {t.findtext('testcase')}: {score} {notes[-1]}, expected {want}")
    return errors


def have_maxima() -> bool:
    return shutil.which("maxima") is not None


def maxima_values(variables: str, count: int, unit: str) -> dict[int, dict[str, str]]:
    """Maxima's values, for each ``stack_seed`` 1..count, of ``n1``, the teacher's answer ``ta1``
    (divided by ``unit``) and each list's entry at ``n1`` (``NAME``) and length (``#NAME``)."""
    names = re.findall(r"^(\w+):\[", variables, re.M)
    body = re.sub(r";$", "$", variables, flags=re.M)
    ta = f"float(ta1/({unit}))" if unit else "float(ta1)"
    script = ["display2d:false$", "linel:100000$"]
    for k in range(1, count + 1):
        script += [f"stack_seed:{k}$", body, f'print(sconcat("DERIVE|{k}|n1|", n1))$']
        script.append(f'print(sconcat("DERIVE|{k}|ta1|", {ta}))$')
        for n in names:
            script.append(f'print(sconcat("DERIVE|{k}|{n}|", {n}[n1]))$')
            script.append(f'print(sconcat("DERIVE|{k}|#{n}|", length({n})))$')
    with tempfile.TemporaryDirectory() as tmp:
        path = Path(tmp) / "q.mac"
        path.write_text("\n".join(script) + "\n", encoding="utf-8")
        run = subprocess.run(
            ["maxima", "--very-quiet", "--batch-string", f'batchload("{path}")$'],
            capture_output=True,
            text=True,
            timeout=300,
        )
    assert run.returncode == 0, run.stderr[-2000:]
    out: dict[int, dict[str, str]] = {}
    for line in run.stdout.splitlines():
        if line.startswith("DERIVE|"):
            _, k, name, value = line.split("|", 3)
            out.setdefault(int(k), {})[name] = value.rstrip(" ")
    assert sorted(out) == list(range(1, count + 1)), run.stdout[-2000:] + run.stderr[-2000:]
    return out


def overlaps(spans: list[tuple[float, float]]) -> list[tuple[int, int]]:
    """The pairs of ranges (low, high) whose interiors overlap (a shared end is no overlap)."""
    out = []
    for i, (a0, a1) in enumerate(spans):
        for j, (b0, b1) in enumerate(spans[:i]):
            eps = 1e-12 * max(1.0, abs(a0), abs(a1), abs(b0), abs(b1))
            if min(a1, b1) - max(a0, b0) > eps:
                out.append((j, i))
    return out
