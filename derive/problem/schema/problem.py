"""The tables of a problem file: its top-level fields, [given], [A]/[B], [geometry],
[vary], answer_units and [assume]."""

from __future__ import annotations

from derive.problem.schema.base import MAX_LINE, MAX_TEXT, NAME_PATTERN, Field, Table

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
    max_keys=60,
)
AXES = ("+n", "-n", "+t", "-t", "+x", "-x", "+y", "-y")
GIVEN = Table("given", "the data: each entry a name and a value", keys=VALUE, key_pattern=NAME_PATTERN, max_keys=60)
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
        Field(
            "label",
            "line",
            "the letter the page calls the body by, in its symbols, sentences and figure "
            '(a chain stage where sphere B strikes a wall: A = { label = "B" })',
            default='"A", "B"',
            max_length=3,
            expected='a capital letter, optionally with a digit ("B", "C", "P1")',
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
    max_keys=60,
)
ANSWER_UNITS = Table(
    "answer_units",
    'results to show also in another unit: { v_A2 = "km/h" }',
    keys=Field("unit", "unit", "the unit", expected="a unit as text", max_length=40),
    key_pattern=NAME_PATTERN,
    max_keys=60,
)
FIND = Field(
    "find",
    "names",
    "extra results to box in the answer: `v_A2`, `v_B2` (speeds), `theta_A2`, `theta_B2` (from +t toward +n), "
    "`beta_A2`, `beta_B2` (from +n toward +t), `alpha_A2`, `alpha_B2` (the acute angle with the line of centres), "
    "`gamma_A2`, `gamma_B2` (the acute angle with the plane of contact, a wall), `delta_A`, `delta_B` (the angle "
    "a velocity turns through), `T_1`, `T_2`, `T_lost`, `J_n`, and the unknowns of an inverse problem",
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
    Field("question", "text", "the **Find** sentence", max_length=MAX_TEXT, default="the velocities after the impact"),
)
TITLE = Field(
    "title", "text", "a line of text, the heading of the solution", required=True, max_length=MAX_TEXT, expected="text"
)


def kind_field(choices: tuple[str, ...], meaning: str, expected: str) -> Field:
    return Field("kind", "choice", meaning, required=True, choices=choices, expected=expected)


def conditions_field(meaning: str, example: str) -> Field:
    """The ``conditions`` every homework variant must meet (of a problem, or of a chain)."""
    return Field(
        "conditions",
        "list",
        meaning,
        max_items=20,
        items=Field("condition", "text", "a comparison", max_length=500),
        expected=f'a list of conditions such as ["{example}"]',
    )


RELATION = Field("relation", "text", "an equation in the givens and results", max_length=500)
ASK_RANGE = Table(
    "range",
    "the values of a letter for which a comparison holds",
    (
        Field("of", "name", "a given kept as a letter (such as e)", required=True),
        Field("where", "text", 'a comparison with <, <=, > or >=, such as "v_A2 < 0"', required=True, max_length=500),
    ),
)
#: What a problem asks beyond the velocities (read by :mod:`derive.problem.symbolic`).
ASKS = (
    Field(
        "show",
        "list",
        'relations to show from the closed forms, such as `"v_B2 = 2/5*(1 + e)*u"`',
        max_items=20,
        items=RELATION,
        also="one",
        expected='a relation such as "v_B2 = 2/5*(1 + e)*u", or a list of them',
    ),
    Field(
        "range",
        "list",
        'for which values of a letter a comparison holds: `{ of = "e", where = "v_A2 < 0" }`, or a list of them',
        max_items=20,
        items=Field("range", "table", "a range", table=ASK_RANGE),
        also="one",
        expected='{ of = "e", where = "v_A2 < 0" }',
    ),
    Field(
        "equations",
        "list",
        'more equations that fix "?" unknowns, such as `"T_2 = 3/4*T_1"`',
        max_items=20,
        items=RELATION,
        also="one",
        expected='one equation such as "T_2 = 3/4*T_1", or a list of them',
    ),
    Field(
        "define",
        "table",
        'quantities defined from the results: `{ F_avg = "J_n/dt" }`',
        table=Table(
            "define",
            "quantities from the results",
            keys=Field("definition", "text", "an expression of the givens and results", max_length=500),
            key_pattern=NAME_PATTERN,
            max_keys=20,
        ),
    ),
    Field(
        "answers",
        "table",
        'published answers, for tests and keys: `{ v_B2 = "2/5*(1 + e)*u" }`',
        table=Table(
            "answers",
            "published answers",
            keys=Field(
                "published",
                "value",
                "a number with its unit, or an expression",
                max_length=500,
                expected="a number with its unit or an expression",
            ),
            key_pattern=NAME_PATTERN,
            max_keys=40,
        ),
    ),
)
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
    *ASKS,
    Field("vary", "table", "ranges or choices for homework variants (below)", table=VARY),
    conditions_field('conditions every variant must meet, such as `"v_B2 > 0"`', "v_B2n > 0"),
    Field("A", "table", "the direction of A's velocity", table=BODY),
    Field("B", "table", "the direction of B's velocity; `fixed = true` for a wall or floor", table=BODY),
)
PROBLEM = Table(
    "problem",
    "a single central impact",
    (
        TITLE,
        kind_field(
            ("direct", "oblique", "chain"),
            '`"direct"` (every velocity along n) or `"oblique"` (`"chain"`: stages, below)',
            '"direct" or "oblique" (or "chain" for stages)',
        ),
        *IMPACT_FIELDS,
    ),
)
