"""What PrairieLearn and Moodle do with derive's LMS exports, re-implemented for the tests.

Nothing here is copied from those projects. Each part is written from a reading of
their public sources and cites what was read (repository, path, commit); the
attribute tables are hand-written lists of what the sources declare, and the
graders are this project's own Python following the algorithm described there.

PrairieLearn (github.com/PrairieLearn/PrairieLearn, commit
88fb8556a7a1768e2082736be9095241b11238d7):

* ``apps/prairielearn/src/schemas/schemas/infoQuestion.json`` — a question's
  info.json: required fields, their types, no other keys;
* ``apps/prairielearn/elements/pl-number-input/schemas/pl-number-input.json`` and
  ``pl-number-input.py`` — the element's attributes, defaults and grading;
* ``apps/prairielearn/python/prairielearn/html_utils.py`` (what counts as a
  boolean, integer or number attribute), ``grading_utils.py`` (the comparisons),
  ``conversion_utils.py`` (how a submitted string becomes a number);
* ``apps/prairielearn/elements/pl-question-panel``, ``pl-answer-panel``,
  ``pl-submission-panel``, ``pl-hide-in-panel`` — their attributes;
* ``apps/prairielearn/src/question-servers/freeform.ts`` — question.html is
  rendered with Mustache (mustache.js) over ``data`` before any element sees it;
  in the grade phase the elements grade first, then server.py's ``grade(data)``.

Moodle (github.com/moodle/moodle):

* ``question/format/xml/format.php`` @ 9094211d277bef39ad1ac09635c200850248b7da —
  ``import_numerical``, ``import_answer``, ``import_headers``, ``import_category``;
* ``question/type/numerical/questiontype.php`` @ 81b24b17cf054b9a3794c7f377ea0ce1cb02b763 —
  ``save_question_options`` / ``save_units`` (how imported answers, tolerances and
  units are stored), ``qtype_numerical_answer_processor::apply_units``;
* ``question/type/numerical/question.php`` @ 3536435e6ab8edd50ffb7ec7eed799ab12b31f28 —
  ``get_matching_answer``, ``apply_unit_penalty``, ``grade_response``,
  ``is_complete_response``, ``qtype_numerical_answer::get_tolerance_interval``;
* ``question/engine/states.php`` @ 9c197f4445212c5e5a3716e364db73b1c214db3c —
  ``graded_state_for_fraction``;
* ``lang/en/langconfig.php`` @ 57054fc66b2a42188743c5a4ded41a9bbc453a60 —
  decimal point ``.`` and thousands separator ``,`` in English.
"""

from __future__ import annotations

import html
import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from decimal import Decimal, InvalidOperation
from html.parser import HTMLParser
from typing import Any

# =============================================================== PrairieLearn: info.json

_UUID = re.compile(r"^[0-9a-fA-F]{8}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{4}-[0-9a-fA-F]{12}$")

#: infoQuestion.json: the question types PrairieLearn knows ("v3" for new questions).
PL_QUESTION_TYPES = ("Calculation", "MultipleChoice", "Checkbox", "File", "MultipleTrueFalse", "v3")
PL_GRADING_METHODS = ("Internal", "External", "Manual")

#: infoQuestion.json: every property it allows (additionalProperties is false), by JSON type.
PL_INFO_PROPERTIES: dict[str, str] = {
    "comment": "any",
    "uuid": "string",
    "type": "string",
    "title": "string",
    "topic": "string",
    "tags": "array of string",
    "authors": "array of object",
    "clientFiles": "array of string",
    "clientTemplates": "array of string",
    "template": "string",
    "gradingMethod": "string",
    "singleVariant": "boolean",
    "showCorrectAnswer": "boolean",
    "partialCredit": "boolean",
    "options": "object",
    "externalGradingOptions": "object",
    "dependencies": "object",
    "workspaceOptions": "object",
    "sharingSets": "array of string",
    "sharePublicly": "boolean",
    "shareSourcePublicly": "boolean",
    "preferences": "object",
}
PL_INFO_REQUIRED = ("uuid", "type", "title", "topic")


def _json_type_ok(value: Any, kind: str) -> bool:
    if kind == "any":
        return True
    if kind == "string":
        return isinstance(value, str)
    if kind == "boolean":
        return isinstance(value, bool)
    if kind == "object":
        return isinstance(value, dict)
    if kind.startswith("array of "):
        item = kind.removeprefix("array of ")
        return isinstance(value, list) and all(_json_type_ok(x, item) for x in value)
    raise ValueError(kind)


def check_pl_info(obj: Any) -> list[str]:
    """What PrairieLearn's schema for a question's info.json finds wrong with ``obj`` ([] if valid)."""
    if not isinstance(obj, dict):
        return ["info.json is not a JSON object"]
    errors = [f"missing required property {name!r}" for name in PL_INFO_REQUIRED if name not in obj]
    for key, value in obj.items():
        kind = PL_INFO_PROPERTIES.get(key)
        if kind is None:
            errors.append(f"unknown property {key!r} (the schema allows no others)")
        elif not _json_type_ok(value, kind):
            errors.append(f"property {key!r} must be {kind}, not {type(value).__name__}")
    if isinstance(obj.get("uuid"), str) and not _UUID.match(obj["uuid"]):
        errors.append(f"uuid {obj['uuid']!r} does not match the UUID pattern")
    if isinstance(obj.get("type"), str) and obj["type"] not in PL_QUESTION_TYPES:
        errors.append(f"type {obj['type']!r} is not one of {PL_QUESTION_TYPES}")
    if isinstance(obj.get("gradingMethod"), str) and obj["gradingMethod"] not in PL_GRADING_METHODS:
        errors.append(f"gradingMethod {obj['gradingMethod']!r} is not one of {PL_GRADING_METHODS}")
    if isinstance(obj.get("authors"), list) and len(obj["authors"]) > 10:
        errors.append("at most 10 authors")
    return errors


# =============================================================== PrairieLearn: elements

#: The core elements (apps/prairielearn/elements/ at the commit above).
PL_CORE_ELEMENTS = frozenset(
    {
        "pl-answer-panel",
        "pl-big-o-input",
        "pl-card",
        "pl-checkbox",
        "pl-code",
        "pl-dataframe",
        "pl-drawing",
        "pl-dropdown",
        "pl-excalidraw",
        "pl-external-grader-results",
        "pl-external-grader-variables",
        "pl-figure",
        "pl-file-download",
        "pl-file-editor",
        "pl-file-preview",
        "pl-file-upload",
        "pl-graph",
        "pl-hidden-hints",
        "pl-hide-in-manual-grading",
        "pl-hide-in-panel",
        "pl-image-capture",
        "pl-integer-input",
        "pl-manual-grading-only",
        "pl-matching",
        "pl-matrix-component-input",
        "pl-matrix-input",
        "pl-matrix-latex",
        "pl-multiple-choice",
        "pl-number-input",
        "pl-order-blocks",
        "pl-overlay",
        "pl-prairiedraw-figure",
        "pl-python-variable",
        "pl-question-panel",
        "pl-rich-text-editor",
        "pl-sketch",
        "pl-string-input",
        "pl-submission-panel",
        "pl-symbolic-input",
        "pl-template",
        "pl-units-input",
        "pl-variable-output",
        "pl-variable-score",
        "pl-workspace",
        "pl-xss-safe",
    }
)

# Attribute kinds: "string", "boolean", "integer", "number", or a tuple of allowed values.
_NUMBER_INPUT_ATTRS: dict[str, Any] = {
    "allow-blank": "boolean",
    "allow-complex": "boolean",
    "allow-fractions": "boolean",
    "answers-name": "string",
    "aria-label": "string",
    "atol": "number",
    "blank-value": "string",
    "comparison": ("relabs", "sigfig", "decdig"),
    "correct-answer": "number-or-empty",
    "custom-format": "string",
    "digits": "integer",
    "display": ("block", "inline"),
    "initial-value": "string",
    "label": "string",
    "placeholder": "string",
    "rtol": "number",
    "show-correct-answer": "boolean",
    "show-help-text": "boolean",
    "show-placeholder": "boolean",
    "show-score": "boolean",
    "size": "integer",
    "suffix": "string",
    "weight": "integer",
}

#: Elements whose attributes the tests know (the ones derive may write), with required attributes.
PL_ELEMENT_ATTRS: dict[str, tuple[dict[str, Any], tuple[str, ...]]] = {
    "pl-number-input": (_NUMBER_INPUT_ATTRS, ("answers-name",)),
    "pl-question-panel": ({}, ()),
    "pl-answer-panel": ({}, ()),
    "pl-submission-panel": ({}, ()),
    "pl-hide-in-panel": ({"question": "boolean", "submission": "boolean", "answer": "boolean"}, ()),
}

#: html_utils.py: the strings a boolean attribute may hold.
PL_TRUE = frozenset({"true", "t", "1", "True", "T", "TRUE", "yes", "y", "Yes", "Y", "YES"})
PL_FALSE = frozenset({"false", "f", "0", "False", "F", "FALSE", "no", "n", "No", "N", "NO"})

#: pl-number-input.py defaults.
PL_NUMBER_DEFAULTS = {
    "comparison": "relabs",
    "rtol": 1e-2,
    "atol": 1e-8,
    "digits": 2,
    "weight": 1,
    "allow-complex": False,
    "allow-fractions": True,
    "allow-blank": False,
    "blank-value": "0",
    "show-correct-answer": True,
}
PL_PRECISION_WARNING = "Your answer does not have precision within the specified relative tolerance."


def _is_int(text: str) -> bool:
    try:
        int(text)
    except ValueError:
        return False
    return True


def _is_float(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _attr_ok(value: str, kind: Any) -> bool:
    if isinstance(kind, tuple):
        return value in kind
    if kind == "string":
        return True
    if kind == "boolean":
        return value in PL_TRUE or value in PL_FALSE
    if kind == "integer":
        return _is_int(value)
    if kind == "number":
        return _is_float(value)
    if kind == "number-or-empty":
        return value == "" or _is_float(value)
    raise ValueError(kind)


@dataclass
class PlElement:
    tag: str
    attrs: dict[str, str]


class _Tags(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.elements: list[PlElement] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        # lxml (what PrairieLearn parses with) also lower-cases names and reads a bare attribute as "".
        # An attribute written twice: lxml keeps the first.
        got: dict[str, str] = {}
        for k, v in attrs:
            got.setdefault(k, v if v is not None else "")
        self.elements.append(PlElement(tag, got))


def pl_elements(page: str) -> list[PlElement]:
    """Every element of an HTML page, with its attributes (entities decoded)."""
    parser = _Tags()
    parser.feed(page)
    parser.close()
    return parser.elements


def check_pl_question_html(page: str) -> list[str]:
    """What PrairieLearn would reject in a (Mustache-rendered) question.html ([] if nothing).

    Only core elements whose attribute lists are known here are accepted; each
    attribute must be declared by the element's schema and hold a value of its
    type; pl-number-input's own checks (tolerances and digits not negative,
    answers-name given once) are applied too.
    """
    errors: list[str] = []
    names: set[str] = set()
    for el in pl_elements(page):
        if not el.tag.startswith("pl-"):
            continue
        if el.tag not in PL_CORE_ELEMENTS:
            errors.append(f"<{el.tag}> is not a PrairieLearn core element")
            continue
        if el.tag not in PL_ELEMENT_ATTRS:
            errors.append(f"<{el.tag}>: no attribute table in these tests")
            continue
        table, required = PL_ELEMENT_ATTRS[el.tag]
        # element_schemas.py reads an underscore spelling as the hyphenated name.
        attrs = {k.replace("_", "-"): v for k, v in el.attrs.items()}
        errors += [f'<{el.tag}> is missing required attribute "{r}"' for r in required if r not in attrs]
        for key, value in attrs.items():
            if key not in table:
                errors.append(f'Unknown attribute "{key}" on <{el.tag}>')
            elif "{{" in value:
                errors.append(f'Attribute "{key}" on <{el.tag}> holds unrendered Mustache: {value!r}')
            elif not _attr_ok(value, table[key]):
                errors.append(f'Attribute "{key}" on <{el.tag}> must be {table[key]}, not {value!r}')
        if el.tag == "pl-number-input":
            for key in ("rtol", "atol", "digits"):
                if key in attrs and _is_float(attrs[key]) and float(attrs[key]) < 0:
                    errors.append(f"Attribute {key} = {attrs[key]} must be non-negative")
            name = attrs.get("answers-name", "")
            if "answers-name" in attrs and not name.strip():
                errors.append('"answers-name" attribute cannot be empty')
            if name in names:
                errors.append(f'Duplicate "answers-name" attribute: "{name}"')
            names.add(name)
    return errors


# ------------------------------------------------------------- Mustache (mustache.js), as PL renders

_MUSTACHE = re.compile(r"\{\{\{\s*([^}]*?)\s*\}\}\}|\{\{\s*([&#^/!>=]?)\s*([^}]*?)\s*\}\}")
_MUSTACHE_ESCAPES = {
    "&": "&amp;",
    "<": "&lt;",
    ">": "&gt;",
    '"': "&quot;",
    "'": "&#39;",
    "/": "&#x2F;",
    "`": "&#x60;",
    "=": "&#x3D;",
}


def js_string(value: Any) -> str:
    """``String(value)`` in JavaScript, for the JSON values server.py hands to Mustache."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if value != value:
            return "NaN"
        if math.isinf(value):
            return "Infinity" if value > 0 else "-Infinity"
        if value == 0:
            return "0"
        d = Decimal(repr(value))
        digits = d.as_tuple().digits
        while len(digits) > 1 and digits[-1] == 0:
            digits = digits[:-1]
        exp10 = d.adjusted()  # ECMAScript Number::toString: plain from 1e-7 to 1e21
        sign = "-" if value < 0 else ""
        s = "".join(map(str, digits))
        k, n = len(s), exp10 + 1
        if k <= n <= 21:
            return sign + s + "0" * (n - k)
        if 0 < n <= 21:
            return sign + s[:n] + "." + s[n:]
        if -6 < n <= 0:
            return sign + "0." + "0" * (-n) + s
        mant = s[0] + ("." + s[1:] if k > 1 else "")
        return f"{sign}{mant}e{'+' if n - 1 >= 0 else '-'}{abs(n - 1)}"
    return str(value)


def mustache_render(template: str, data: dict) -> tuple[str, list[str]]:
    """The template rendered over ``data`` as mustache.js would, for plain variables
    (``{{x.y}}`` HTML-escaped, ``{{{x.y}}}`` and ``{{& x.y}}`` raw), and the problems found:
    a name not in ``data`` (mustache.js writes nothing for it) or a tag these tests
    do not render (sections, partials, comments)."""
    problems: list[str] = []

    def look(path: str) -> Any:
        cur: Any = data
        for part in path.split("."):
            if not isinstance(cur, dict) or part not in cur:
                problems.append(f"{{{{{path}}}}} is not in the data")
                return ""
            cur = cur[part]
        return cur

    def sub(m: re.Match[str]) -> str:
        if m.group(1) is not None:
            return js_string(look(m.group(1)))
        sigil, name = m.group(2), m.group(3)
        if sigil == "&":
            return js_string(look(name))
        if sigil:
            problems.append(f"Mustache tag {m.group(0)!r} is not rendered by these tests")
            return m.group(0)
        text = js_string(look(name))
        return "".join(_MUSTACHE_ESCAPES.get(c, c) for c in text)

    return _MUSTACHE.sub(sub, template), problems


# ------------------------------------------------------------- pl-number-input: parse and grade


def _pl_bool(attrs: dict[str, str], name: str) -> bool:
    if name not in attrs:
        return bool(PL_NUMBER_DEFAULTS[name])
    return attrs[name] in PL_TRUE


def _pl_string_to_number(s: str) -> float | None:
    """conversion_utils.string_to_number without complex numbers (the element's default)."""
    s = s.replace("\u2212", "-")
    s = re.sub(r"(?<=\d)\s+(?=\d)", "", s)
    try:
        return float(s)
    except ValueError:
        return None


def pl_parse(raw: str | None, attrs: dict[str, str]) -> tuple[float | None, str | None]:
    """The submitted string as pl-number-input's parse() reads it: (value, format error)."""
    if raw is None:
        return None, "No submitted answer."
    if _pl_bool(attrs, "allow-blank") and raw.strip() == "":
        raw = attrs.get("blank-value", PL_NUMBER_DEFAULTS["blank-value"])
    if raw.strip() == "":
        return None, "The submitted answer was blank."
    s = raw.replace("\u2215", "/").replace("\u00f7", "/")
    if s.count("/") == 1:
        if not _pl_bool(attrs, "allow-fractions"):
            return None, "Fractional answers are not allowed in this input."
        top, bottom = (_pl_string_to_number(x) for x in s.split("/"))
        if top is None or not math.isfinite(top):
            return None, "Invalid format: The numerator could not be interpreted as a decimal number."
        if bottom is None or not math.isfinite(bottom):
            return None, "Invalid format: The denominator could not be interpreted as a decimal number."
        if bottom == 0:
            return None, "Your expression resulted in a division by zero."
        return top / bottom, None
    value = _pl_string_to_number(s)
    if value is None:
        return None, "Invalid format: The submitted answer could not be interpreted as a decimal number."
    if not math.isfinite(value):
        return None, "Invalid format: The submitted answer is not a finite number."
    return value, None


def _pl_normalized(raw: str) -> str | None:
    s = raw.strip().lstrip("+-\u2212")
    if "/" in s:
        return None
    if "e" in s.lower():
        try:
            return format(Decimal(s), "f")
        except InvalidOperation:
            return s
    return s


def pl_string_precision(raw: str) -> float:
    """The place value of a submitted string's last digit (0 for a fraction)."""
    s = _pl_normalized(raw)
    if s is None:
        return 0.0
    if "." in s:
        return 10.0 ** -len(s.partition(".")[2])
    return 10.0 ** (len(s) - len(s.rstrip("0")))


def pl_string_sigfigs(raw: str) -> int:
    """Significant digits PrairieLearn counts in a submitted string (1000 for a fraction)."""
    s = _pl_normalized(raw)
    if s is None:
        return 1000
    if "." in s:
        whole, _, frac = s.partition(".")
        digits = (whole + frac).lstrip("0")
        return len(digits) if digits else (len(frac) if frac else 1)
    digits = s.strip("0")
    return len(digits) if digits else 1


def pl_string_decimals(raw: str) -> int:
    s = _pl_normalized(raw)
    if s is None:
        return 1000
    return len(s.partition(".")[2].lstrip("0")) if "." in s else 0


@dataclass
class PlGrade:
    score: float
    feedback: str | None
    format_error: str | None = None

    @property
    def correct(self) -> bool:
        return self.format_error is None and self.score >= 1


def pl_grade(attrs: dict[str, str], submitted: str, correct: float) -> PlGrade:
    """pl-number-input's parse then grade of ``submitted`` against ``correct_answers[name]``.

    relabs: right when |x - c| <= atol + rtol*|c| (numpy.allclose, in doubles); a wrong
    answer whose last digit's place value exceeds rtol is told it lacks precision.
    sigfig: right when strictly within 0.51 units of the digits-th significant place of c;
    decdig: strictly within 0.51 units of the digits-th decimal; both warn when the
    answer has fewer digits than asked.
    """
    value, error = pl_parse(submitted, attrs)
    if error is not None:
        return PlGrade(0.0, None, error)
    assert value is not None
    comparison = attrs.get("comparison", PL_NUMBER_DEFAULTS["comparison"])
    c = float(correct)
    feedback: str | None = None
    if comparison == "relabs":
        rtol = float(attrs.get("rtol", PL_NUMBER_DEFAULTS["rtol"]))
        atol = float(attrs.get("atol", PL_NUMBER_DEFAULTS["atol"]))
        # numpy.allclose: |x - c| <= atol + rtol*|c|; infinities only equal themselves
        finite = math.isfinite(c) and math.isfinite(value)
        ok = abs(value - c) <= atol + rtol * abs(c) if finite else value == c
        if not ok and pl_string_precision(submitted) > rtol:
            feedback = PL_PRECISION_WARNING
    elif comparison == "sigfig":
        digits = int(attrs.get("digits", PL_NUMBER_DEFAULTS["digits"]))
        n = digits - 1 if c == 0 else -math.floor(math.log10(abs(c))) + (digits - 1)
        eps = 0.51 * 10.0**-n
        ok = c - eps < value < c + eps
        if not ok and pl_string_sigfigs(submitted) < digits:
            feedback = PL_PRECISION_WARNING
    elif comparison == "decdig":
        digits = int(attrs.get("digits", PL_NUMBER_DEFAULTS["digits"]))
        eps = 0.51 * 10.0**-digits
        ok = c - eps < value < c + eps
        if not ok and pl_string_decimals(submitted) < digits:
            feedback = PL_PRECISION_WARNING
    else:
        raise ValueError(f"comparison {comparison!r}")
    if ok and _pl_bool(attrs, "show-correct-answer"):
        feedback = f"The correct answer used for grading was {c!r}."
    return PlGrade(1.0 if ok else 0.0, feedback)


# =============================================================== Moodle: XML import

#: PHP's default ``precision`` ini setting: floats are stored as text with 14 significant digits.
PHP_PRECISION = 14
UNITINPUT, UNITRADIO, UNITSELECT, UNITNONE = 0, 1, 2, 3
UNITGRADEDOUTOFMARK, UNITGRADEDOUTOFMAX = 1, 2


class MoodleImportError(ValueError):
    """The file would not import (or an answer would be stored as invalid)."""


@dataclass
class MoodleAnswer:
    answer: float | str  # '*' matches anything
    fraction: float
    feedback: str
    tolerance: float
    text: str  # as written in the file


@dataclass
class MoodleQuestion:
    qtype: str
    name: str = ""
    questiontext: str = ""
    questiontextformat: str = "html"
    generalfeedback: str = ""
    defaultmark: float = 1.0
    penalty: float = 0.3333333
    answers: list[MoodleAnswer] = field(default_factory=list)
    units: dict[str, float] = field(default_factory=dict)  # name -> multiplier, in file order
    unitgradingtype: int = 0
    unitpenalty: float = 0.1
    showunits: int = UNITNONE
    unitsleft: bool = False
    category: str = ""


def _php_float_text(x: float) -> float:
    """A float as Moodle stores it in a text column (PHP's string cast at precision 14)."""
    return float(format(x, f".{PHP_PRECISION}G"))


def _text_of(el: ET.Element | None, path: str, default: str = "") -> str:
    if el is None:
        return default
    found = el.find(path)
    return default if found is None or found.text is None else found.text


_FORMATS = {"moodle_auto_format", "html", "plain_text", "wiki_like", "markdown"}


def moodle_import(xml_text: str) -> list[MoodleQuestion]:
    """The questions as Moodle's XML importer reads and stores them.

    Answers keep their order in the file (Moodle stores them in that order and
    reads them back by id). Each answer's text and tolerance are parsed with the
    question's units, as ``save_question_options`` does; units with an empty name
    or multiplier are dropped and a repeated name keeps its first multiplier.
    """
    try:
        root = ET.fromstring(xml_text.encode("utf-8"))
    except ET.ParseError as exc:
        raise MoodleImportError(f"not well-formed XML: {exc}") from None
    if root.tag != "quiz":
        raise MoodleImportError(f"root element is <{root.tag}>, not <quiz>")
    out: list[MoodleQuestion] = []
    for q in root.findall("question"):
        qtype = q.get("type")
        if qtype == "category":
            cat = q.find("category/text")
            if cat is None:
                raise MoodleImportError("category question without <category><text>")
            out.append(MoodleQuestion("category", category=(cat.text or "").strip()))
            continue
        if qtype != "numerical":
            raise MoodleImportError(f"question type {qtype!r}: only numerical questions are read here")
        out.append(_import_numerical(q))
    return out


def _import_numerical(q: ET.Element) -> MoodleQuestion:
    name = _text_of(q, "name/text").strip()
    if not name:
        raise MoodleImportError("a question has no name")
    mq = MoodleQuestion("numerical", name=name)
    qt = q.find("questiontext")
    mq.questiontext = _text_of(q, "questiontext/text").strip()
    mq.questiontextformat = (qt.get("format") if qt is not None else None) or "html"
    for fmt_el in (qt, q.find("generalfeedback")):
        fmt = fmt_el.get("format") if fmt_el is not None else None
        if fmt is not None and fmt.strip() not in _FORMATS:
            raise MoodleImportError(f"unrecognised text format {fmt!r}")
    mq.generalfeedback = _text_of(q, "generalfeedback/text").strip()
    mq.defaultmark = float(_text_of(q, "defaultgrade", "1"))
    mq.penalty = float(_text_of(q, "penalty", "0.3333333"))
    if abs(mq.penalty - 0.3333333) < 0.005:
        mq.penalty = 0.3333333
    # Units first: answers and tolerances are stored through them.
    for u in q.findall("units/unit"):
        mult_text = _text_of(u, "multiplier", "1")
        unit = _text_of(u, "unit_name").strip()
        mult = _apply_units_number(mult_text, {}, False)
        if not unit or not mult or unit in mq.units:
            continue
        mq.units[unit] = mult
    mq.unitgradingtype = int(_text_of(q, "unitgradingtype", "0"))
    mq.unitpenalty = float(_text_of(q, "unitpenalty", "0.1"))
    show = q.find("showunits")
    if show is None or show.text is None:
        mq.showunits = UNITNONE if not mq.units else UNITINPUT
    else:
        mq.showunits = int(show.text)
    mq.unitsleft = bool(int(_text_of(q, "unitsleft", "0") or 0))
    answers = q.findall("answer")
    if not answers:
        raise MoodleImportError(f"{name}: a numerical question needs at least one <answer>")
    for a in answers:
        text = _text_of(a, "text").strip()
        frac_el = a.find("fraction")  # deprecated tag, wins over the attribute
        fraction = float(frac_el.text) if frac_el is not None and frac_el.text else float(a.get("fraction", "0")) / 100
        tol_text = _text_of(a, "tolerance", "0")
        if text == "*":
            value: float | str = "*"
        else:
            parsed = _apply_units_number(text, mq.units, mq.unitsleft)
            if parsed is None:
                raise MoodleImportError(f"{name}: answer {text!r} is not a number")
            value = _php_float_text(parsed)
        if tol_text.strip() == "":
            tol = 0.0
        else:
            parsed_tol = _apply_units_number(tol_text, mq.units, mq.unitsleft)
            if parsed_tol is None:
                raise MoodleImportError(f"{name}: tolerance {tol_text!r} is not a number")
            tol = _php_float_text(parsed_tol)
        feedback = _text_of(a, "feedback/text").strip()
        mq.answers.append(MoodleAnswer(value, fraction, feedback, abs(tol), text))
    return mq


# ------------------------------------------------------------- Moodle: numbers with units

_EXPONENT_FORMS = re.compile(r"(?:e|E|(?:x|\*|×)10(?:\^|\*\*))([+-]?\d+)")
_NUMBER_AT_START = re.compile(r"^[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:e[-+]?\d+)?")
_NUMBER_AT_END = re.compile(r"[+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:e[-+]?\d+)?$")


def apply_units(response: str, units: dict[str, float], unitsleft: bool) -> tuple[float | None, str, float | None]:
    """``qtype_numerical_answer_processor::apply_units``: (number, unit text, multiplier).

    Spaces are dropped; ``x10^``, ``*10**`` and ``×10^`` mean ``e``; with a ``.`` or more
    than one ``,`` every ``,`` is a thousands separator, else a lone ``,`` is the
    decimal point. The number is read from the start (the end when units go
    left); the rest is the unit, whose multiplier converts to the first unit
    (value / multiplier). An unknown unit gives multiplier None.
    """
    s = response.replace(" ", "")
    s = _EXPONENT_FORMS.sub(r"e\1", s)
    s = s.replace(",", "") if "." in s or s.count(",") > 1 else s.replace(",", ".")
    m = (_NUMBER_AT_END if unitsleft else _NUMBER_AT_START).search(s)
    if m is None:
        return None, "", None
    number = m.group(0)
    unit = s[: len(s) - len(number)] if unitsleft else s[len(number) :]
    multiplier = 1 / units[unit] if unit in units else None
    return float(number), unit, multiplier


def _apply_units_number(text: str, units: dict[str, float], unitsleft: bool) -> float | None:
    value, _, multiplier = apply_units(text, units, unitsleft)
    if value is None:
        return None
    return value * multiplier if multiplier is not None else value


# ------------------------------------------------------------- Moodle: grading


def tolerance_interval(answer: MoodleAnswer) -> tuple[float, float]:
    """A numerical answer's range: "nominal" tolerance (the only type a numerical
    question has), widened by 1e-14 of the larger of the tolerance and the answer."""
    assert not isinstance(answer.answer, str)
    eps = 10.0**-PHP_PRECISION
    tol = answer.tolerance + eps * max(abs(answer.tolerance), abs(answer.answer), eps)
    return answer.answer - tol, answer.answer + tol


def within_tolerance(answer: MoodleAnswer, value: float) -> bool:
    if answer.answer == "*":
        return True
    lo, hi = tolerance_interval(answer)
    return lo <= value <= hi


@dataclass
class MoodleGrade:
    fraction: float
    feedback: str | None  # the matched answer's feedback; None when no answer matched
    answer_index: int | None = None
    invalid: str | None = None  # why Moodle would not grade the response (it asks again)

    @property
    def right(self) -> bool:
        # question_state::graded_state_for_fraction: right above 0.9999999
        return self.invalid is None and self.fraction > 0.9999999


#: English decimal point and thousands separator (lang/en/langconfig.php).
MOODLE_THOUSANDS_SEP = ","


def moodle_grade(question: MoodleQuestion, response: str, unit: str | None = None) -> MoodleGrade:
    """``grade_response`` of a numerical question: the first answer (in order) whose
    range holds the value — scaled by the unit's multiplier if the unit is known,
    else as typed — gives the fraction and the feedback; a missing or unknown unit
    costs the unit penalty when units are graded (unitgradingtype 1 or 2)."""
    if not response and response != "0":
        return MoodleGrade(0.0, None, invalid="Please enter an answer.")
    separate = question.showunits in (UNITRADIO, UNITSELECT)
    value, typed_unit, multiplier = apply_units(response, question.units, question.unitsleft)
    if value is None:
        return MoodleGrade(0.0, None, invalid="You have not entered a valid number.")
    if question.showunits != UNITINPUT and typed_unit:
        return MoodleGrade(0.0, None, invalid="You must not enter a unit here.")
    if separate:
        if not unit:
            return MoodleGrade(0.0, None, invalid="Please select a unit.")
        multiplier = 1 / question.units[unit] if unit in question.units else None
    if MOODLE_THOUSANDS_SEP in response:
        return MoodleGrade(0.0, None, invalid="Please enter your answer without using the thousand separator (,).")
    scaled = value * multiplier if multiplier is not None else value
    for i, answer in enumerate(question.answers):
        if within_tolerance(answer, scaled):
            unit_right = multiplier is not None
        elif within_tolerance(answer, value):
            unit_right = False
        else:
            continue
        fraction = answer.fraction
        if not unit_right:
            if question.unitgradingtype == UNITGRADEDOUTOFMARK:
                fraction -= question.unitpenalty * fraction
            elif question.unitgradingtype == UNITGRADEDOUTOFMAX:
                fraction -= question.unitpenalty
            fraction = max(fraction, 0.0)
        return MoodleGrade(fraction, answer.feedback, i)
    return MoodleGrade(0.0, None)


def html_text(fragment: str) -> str:
    """The visible text of an HTML fragment (tags dropped, entities decoded)."""
    return html.unescape(re.sub(r"<[^>]+>", " ", fragment))
