"""The tables of a chain file: its top-level fields and one table per stage type."""

from __future__ import annotations

from dataclasses import replace

from derive.problem.schema.base import MAX_LINE, MAX_TEXT, NAME_PATTERN, Field, Table
from derive.problem.schema.problem import (
    DIGITS,
    GIVEN,
    IMPACT_FIELDS,
    TEXTS,
    TITLE,
    UNITS,
    VARY,
    conditions_field,
    kind_field,
)


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
        kind_field(("direct", "oblique"), '`"direct"` or `"oblique"`', '"direct" or "oblique"'),
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
        kind_field(("chain",), '`"chain"`', '"chain"'),
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
        Field("vary", "table", "ranges or choices for homework variants, of the chain's givens", table=VARY),
        conditions_field(
            'conditions every variant must meet, on givens and results of any stage, such as `"u_A > w_B"`', "h_2 > 0.5"
        ),
    ),
)
