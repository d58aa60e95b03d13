"""The declared schema of derive's files: every field's type, range and meaning, in one place.

Problem files, chain files (each stage type) and answers files are described here as
:class:`Table` records of :class:`Field` records. :mod:`derive.problem.validate` checks a
file against them before anything is built from it; :mod:`derive.problem.export`
writes the field tables of ``docs/problem-format.md`` and the JSON Schema that
editors use (``docs/derive-problem.schema.json``) from them. Pure Python: no SymPy.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field, replace

#: The value types a field may have (each checked by :mod:`derive.problem.validate`).
TYPES = {
    "text": "text",
    "line": "a short line of text",
    "boolean": "true or false",
    "integer": "a whole number",
    "number": "a number",
    "choice": "one of the listed words",
    "value": 'a number, or text: a number with a unit ("5 m/s"), a unit alone (a symbol), an expression, or "?"',
    "expression": "a name or an expression of known names, or a number",
    "name": "a name: a letter, then letters, digits and _",
    "names": "a list of names (or one name)",
    "unit": 'a unit, such as "km/h"',
    "table": "a table",
    "list": "a list",
    "tolerance": 'a relative tolerance: a number such as 0.01, or text such as "1%"',
}
NAME_PATTERN = r"^[A-Za-z][A-Za-z0-9_]{0,31}$"
MAX_TEXT = 5000
MAX_LINE = 40
MAGNITUDE = (1e-30, 1e30)  # a number's magnitude, when not 0


@dataclass(frozen=True)
class Field:
    """One field of a table: its name, value type, meaning and limits.

    ``expected`` overrides the words of an error ("expected <expected>"); ``items`` is
    the type of a list's items; ``table`` the fields of a nested table; ``default``
    what an absent field means (for the docs).
    """

    name: str
    type: str
    meaning: str
    required: bool = False
    default: str = ""
    choices: tuple[str, ...] = ()
    minimum: float | None = None
    maximum: float | None = None
    max_length: int | None = None
    min_items: int = 0
    max_items: int | None = None
    items: Field | None = None
    table: Table | None = None
    expected: str = ""
    also: str = ""  # another accepted form, for the docs and the JSON Schema: "name" (find = "v_A2")

    def __post_init__(self) -> None:
        if self.type not in TYPES:
            raise ValueError(f"field {self.name}: unknown type {self.type!r}")
        if (self.type == "table") != (self.table is not None):
            raise ValueError(f"field {self.name}: a table field needs its table, and only it")
        if self.type == "choice" and not self.choices:
            raise ValueError(f"field {self.name}: a choice needs its choices")


@dataclass(frozen=True)
class Table:
    """A table's fields; ``keys`` describes the entries of an open table (``[given]``: any
    name), ``key_pattern`` what its keys look like, ``max_keys`` how many it may have."""

    name: str
    meaning: str
    fields: tuple[Field, ...] = ()
    keys: Field | None = None
    key_pattern: str | None = None
    key_words: str = ""
    max_keys: int | None = None
    forms: tuple[tuple[str, ...], ...] = field(default=())  # exactly one of these sets of fields (vary)
    by: str = ""  # the field whose value picks the table in ``cases`` (a stage's type)
    cases: Mapping[str, Table] = field(default_factory=dict)

    def get(self, name: str) -> Field | None:
        """The field called ``name``, or None."""
        for f in self.fields:
            if f.name == name:
                return f
        return None

    @property
    def names(self) -> tuple[str, ...]:
        """The names of its fields, in order."""
        return tuple(f.name for f in self.fields)


# ---------------------------------------------------------------- parts shared by problems and stages

VALUE = Field("value", "value", "a given's value", expected='a number or text such as "5 m/s"')
#: What a file may assume of a letter -> the symbol's assumptions (an acute angle is
#: positive, and its range is used where a sign is decided).
ASSUMPTIONS = {
    "positive": "positive",
    "nonnegative": "nonnegative",
    "real": "real",
    "negative": "negative",
    "acute": "positive",
}
ASSUME = Table(
    "assume",
    'what a letter of [given] is: { alpha = "acute" } (letters are positive unless it says otherwise)',
    keys=Field("assumption", "choice", "what the letter is", choices=tuple(ASSUMPTIONS)),
    key_pattern=NAME_PATTERN,
    key_words="a given kept as a letter",
    max_keys=60,
)
AXES = ("+n", "-n", "+t", "-t", "+x", "-x", "+y", "-y")
GIVEN = Table(
    "given",
    "the data: each entry a name and a value",
    keys=VALUE,
    key_pattern=NAME_PATTERN,
    key_words="a name: a letter, then letters, digits and _",
    max_keys=60,
)
BODY = Table(
    "body",
    "the direction of a body's velocity, or a fixed B",
    (
        Field(
            "angle", "value", 'the angle of the velocity: a given\'s name, or "37.6 deg" (a bare number is in degrees)'
        ),
        Field("from", "choice", "the axis the angle is measured from", choices=AXES),
        Field("toward", "choice", "the axis (at right angles) the angle turns toward", choices=AXES),
        Field("fixed", "boolean", "B only: a wall or floor (infinite mass, at rest)", default="false"),
        Field(
            "name",
            "line",
            'what a fixed B is called in the sentences ("wall", "floor")',
            max_length=MAX_LINE,
            expected='a short name such as "wall" or "floor"',
        ),
    ),
)
GEOMETRY = Table(
    "geometry",
    "the line of impact in the problem's x-y axes: one of n_angle, offset, or centre_A and centre_B",
    (
        Field("n_angle", "value", 'the angle of n from +x toward +y ("20 deg")'),
        Field("offset", "value", "the offset between parallel paths along x (give r_A and r_B)"),
        Field("centre_A", "list", "A's centre at contact: two coordinates", min_items=2, max_items=2, items=VALUE),
        Field("centre_B", "list", "B's centre at contact: two coordinates", min_items=2, max_items=2, items=VALUE),
    ),
)
RANGE = Table(
    "range",
    "the values a given takes in variants",
    (
        Field("min", "value", "the smallest value"),
        Field("max", "value", "the largest value"),
        Field("step", "value", "the step between values"),
        Field("choices", "list", "the values to choose from", min_items=1, max_items=10_000, items=VALUE),
    ),
    forms=(("min", "max", "step"), ("choices",)),
)
VARY = Table(
    "vary",
    "ranges or choices for homework variants, by given",
    keys=Field(
        "range",
        "table",
        "a range or choices",
        table=RANGE,
        expected="{ min = ..., max = ..., step = ... } or { choices = [...] }",
    ),
    key_pattern=NAME_PATTERN,
    key_words="the name of a given",
    max_keys=60,
)
ANSWER_UNITS = Table(
    "answer_units",
    'results to show also in another unit: { v_A2 = "km/h" }',
    keys=Field("unit", "unit", "the unit", expected="a unit as text", max_length=40),
    key_pattern=NAME_PATTERN,
    key_words="a result's name",
    max_keys=60,
)
FIND = Field(
    "find",
    "names",
    "extra results to box in the answer: `v_A2`, `v_B2` (speeds), `theta_A2`, `theta_B2` (from +t toward +n), "
    "`beta_A2`, `beta_B2` (from +n toward +t), `T_1`, `T_2`, `T_lost`, `J_n`, and the unknowns of an inverse problem",
    max_items=30,
    default="the velocities after the impact",
    expected="a list of result names",
    also="name",
)
DIGITS = Field(
    "digits",
    "integer",
    "significant figures, 1–10",
    minimum=1,
    maximum=10,
    default="the textbook rule, 3, or 4 when the first digit is 1",
    expected="a whole number of significant figures from 1 to 10",
)
UNITS = Field(
    "units",
    "choice",
    "the system the solution works in",
    choices=("SI", "US"),
    default="the one most givens use",
    expected='"SI" or "US"',
)
TEXTS = (
    Field("source", "text", "where the problem comes from (printed under the title)", max_length=MAX_TEXT),
    Field("statement", "text", "the problem in words (the **Given** paragraph)", max_length=MAX_TEXT),
    Field(
        "question",
        "text",
        "the **Find** sentence",
        max_length=MAX_TEXT,
        default="the velocities after the impact",
    ),
)
TITLE = Field(
    "title",
    "text",
    "a line of text, the heading of the solution",
    required=True,
    max_length=MAX_TEXT,
    expected="text",
)


def _kind(choices: tuple[str, ...], meaning: str, expected: str) -> Field:
    return Field("kind", "choice", meaning, required=True, choices=choices, expected=expected)


#: The fields of a problem (and of a chain's impact stage) after ``title`` and ``kind``.
IMPACT_FIELDS = (
    *TEXTS,
    FIND,
    DIGITS,
    UNITS,
    Field("answer_units", "table", 'results to show also in another unit: `{ v_A2 = "km/h" }`', table=ANSWER_UNITS),
    Field(
        "assume",
        "table",
        'what a letter of `[given]` is: `{ alpha = "acute" }` (positive, nonnegative, real, negative or acute; '
        "letters are positive unless it says otherwise)",
        table=ASSUME,
    ),
    Field(
        "given",
        "table",
        "the data: the masses, e and the velocities before the impact, and any other givens (below)",
        required=True,
        table=GIVEN,
    ),
    Field("geometry", "table", "the line of impact in x-y axes (below)", table=GEOMETRY),
    Field("vary", "table", "ranges or choices for homework variants (below)", table=VARY),
    Field(
        "conditions",
        "list",
        'conditions every variant must meet, such as `"v_B2 > 0"`',
        max_items=20,
        items=Field("condition", "text", "a comparison", max_length=500),
        expected='a list of conditions such as ["v_B2n > 0"]',
    ),
    Field("A", "table", "the direction of A's velocity", table=BODY),
    Field("B", "table", "the direction of B's velocity; `fixed = true` for a wall or floor", table=BODY),
)
PROBLEM = Table(
    "problem",
    "a single central impact",
    (
        TITLE,
        _kind(
            ("direct", "oblique", "chain"),
            '`"direct"` (every velocity along n) or `"oblique"` (`"chain"`: stages, below)',
            '"direct" or "oblique" (or "chain" for stages)',
        ),
        *IMPACT_FIELDS,
    ),
)

# ---------------------------------------------------------------- chains


def _expr(name: str, meaning: str, *, required: bool = True, default: str = "") -> Field:
    return Field(name, "expression", meaning, required=required, default=default, max_length=500)


def _result(default: str, meaning: str = "the name of its result, for later stages") -> Field:
    return Field("result", "name", meaning, default=default)


STAGE_TITLE = Field("title", "text", "the stage's heading", max_length=MAX_TEXT)
STAGE_TYPE = ["fall", "rise", "slide", "spring", "impact", "bounces", "again", "define", "solve"]
RESULTS = Table(
    "results",
    'the impact\'s results under new names: { v_A2 = "u" }',
    keys=Field("new", "name", "the new name"),
    key_pattern=NAME_PATTERN,
    key_words="a result of the impact",
    max_keys=30,
)


def _stage(type_: str, meaning: str, *fields: Field) -> Table:
    head = Field("type", "choice", "the stage type", required=True, choices=tuple(STAGE_TYPE))
    return Table(type_, meaning, (head, STAGE_TITLE, *fields))


STAGES: dict[str, Table] = {
    "fall": _stage(
        "fall",
        "the speed after falling (or swinging) through the height: ½mv₀² + mgh = ½mv²",
        _expr("height", "the height fallen (a length)"),
        _expr("speed", "the speed at the top (a velocity)", required=False, default="0"),
        _result("v_<stage>"),
        Field("body", "line", 'what falls, in the sentences ("the block")', max_length=MAX_LINE, default="the body"),
    ),
    "rise": _stage(
        "rise",
        "the height reached: ½mv² = mgh",
        _expr("speed", "the speed at the bottom (a velocity)"),
        _result("h_<stage>"),
    ),
    "slide": _stage(
        "slide",
        "the distance to rest with kinetic friction: ½mv² = μmgd",
        _expr("speed", "the speed at the start (a velocity)"),
        _expr("mu", "the coefficient of kinetic friction (a pure number)"),
        _result("d_<stage>"),
    ),
    "spring": _stage(
        "spring",
        "the greatest further compression of a spring",
        _expr("speed", "the speed of the body that hits the spring (a velocity)"),
        _expr("mass", "the mass moving with the spring"),
        _expr("k", "the spring's stiffness"),
        Field("vertical", "boolean", "a vertical spring: gravity works too", default="false"),
        _expr("static", "a vertical spring's compression before (a length)", required=False, default="0"),
        _result("x_<stage>"),
    ),
    "impact": _stage(
        "impact",
        "a central impact, as a problem file: its givens are expressions of the chain's names",
        _kind(("direct", "oblique"), '`"direct"` or `"oblique"`', '"direct" or "oblique"'),
        Field("results", "table", "the impact's results under new names", table=RESULTS),
        *(replace(f, required=False) for f in IMPACT_FIELDS),
    ),
    "bounces": _stage(
        "bounces",
        "a ball dropped on a floor: `v_b1 ...`, `h_b1 ...` after each bounce, and `s_total`, the distance to rest",
        _expr("height", "the height it is dropped from"),
        _expr("e", "the coefficient of restitution with the floor"),
        Field(
            "count",
            "integer",
            "how many bounces",
            minimum=1,
            maximum=50,
            default="3",
            expected="a whole number of bounces from 1 to 50",
        ),
    ),
    "again": _stage(
        "again",
        "whether two bodies collide again, and for which values of a coefficient",
        _expr("behind", "the velocity along +n of the body behind"),
        _expr("ahead", "the velocity along +n of the body ahead"),
        Field("range_of", "name", "a coefficient (such as e): the values for which they collide again"),
        _result("again", "the name of the answer (1 if they collide again, else 0)"),
    ),
    "define": _stage(
        "define",
        "a quantity from others",
        _expr("expr", "the expression"),
        _result("q_<stage>"),
        Field("text", "text", "the sentence before it", max_length=MAX_TEXT, default="Then:"),
    ),
    "solve": _stage(
        "solve",
        'an unknown of the chain (a given marked "?") from a condition',
        Field("condition", "text", 'one equation, such as "h_2 = 40 m"', required=True, max_length=500),
        Field("for", "name", 'the given marked "?" to find', default="the only unknown left"),
    ),
}
STAGE = Table(
    "stage",
    "a stage of a chain, by its type",
    (Field("type", "choice", "the stage type", required=True, choices=tuple(STAGE_TYPE)),),
    by="type",
    cases=STAGES,
)
CHAIN = Table(
    "chain",
    "impacts in sequence, and the motion before and after",
    (
        TITLE,
        _kind(("chain",), '`"chain"`', '"chain"'),
        *TEXTS,
        DIGITS,
        UNITS,
        Field("given", "table", "the chain's givens, as in a problem", table=GIVEN),
        Field(
            "stage",
            "list",
            "the stages, worked in order: `[[stage]]` tables (below)",
            required=True,
            min_items=1,
            max_items=30,
            items=Field("stage", "table", "a stage", table=STAGE),
            expected="[[stage]] tables",
        ),
        Field("find", "names", "the names boxed in the answer", max_items=30, expected="a list of names"),
    ),
)

# ---------------------------------------------------------------- answers files

ANSWERS = Table(
    "answers",
    "a student's answers and equations to check (`derive check --answers FILE`)",
    (
        Field(
            "answers",
            "table",
            'answers by result name: `v_B2n = "8.40 m/s"`, or a formula in the givens',
            table=Table(
                "answers",
                "answers by result name",
                keys=Field(
                    "answer",
                    "value",
                    "a number, a number with a unit, or a formula",
                    expected='a number or text such as "8.40 m/s"',
                    max_length=500,
                ),
                key_words="a result's name",
                max_keys=100,
            ),
        ),
        Field(
            "equations",
            "table",
            'equations by label: `"3" = "20*v_A2n + 5*v_B2n = 19.8"`',
            table=Table(
                "equations",
                "equations by label",
                keys=Field(
                    "equation",
                    "text",
                    "an equation with one =",
                    expected='an equation as text, such as "v_B2n - v_A2n = 9.5"',
                    max_length=500,
                ),
                key_words="a label",
                max_keys=100,
            ),
        ),
        Field("tolerance", "tolerance", "relative tolerance for numbers (default: the figures written)"),
    ),
)
