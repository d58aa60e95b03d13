"""The declared schema of derive's files: every field's type, range and meaning, in one place.
May import: the rest of problem and the leaves.

Problem files, chain files (each stage type) and answers files are described here as
:class:`Table` records of :class:`Field` records. :mod:`derive.problem.validate` checks a
file against them before anything is built from it; :mod:`derive.problem.export`
writes the field tables of ``docs/problem-format.md`` and the JSON Schema that
editors use (``docs/derive-problem.schema.json``) from them. Pure Python: no SymPy.
"""

from derive.problem.schema.answers import ANSWERS
from derive.problem.schema.base import MAGNITUDE, NAME_PATTERN, TYPES, Field, Table
from derive.problem.schema.chain import CHAIN, STAGES
from derive.problem.schema.problem import ASSUMPTIONS, BODY, GEOMETRY, PROBLEM, RANGE

__all__ = [
    "ANSWERS",
    "ASSUMPTIONS",
    "BODY",
    "CHAIN",
    "GEOMETRY",
    "MAGNITUDE",
    "NAME_PATTERN",
    "PROBLEM",
    "RANGE",
    "STAGES",
    "TYPES",
    "Field",
    "Table",
]
