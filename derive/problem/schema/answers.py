"""The table of an answers file (``derive check --answers FILE``)."""

from __future__ import annotations

from derive.problem.schema.base import Field, Table

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
                max_keys=100,
            ),
        ),
        Field("tolerance", "tolerance", "relative tolerance for numbers (default: the figures written)"),
    ),
)
