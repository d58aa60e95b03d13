"""Homework variants: derive a problem once, then evaluate and print it many times.
May import: the rest of homework, writers, steps, physics, problem and the leaves.

A problem with a ``[vary]`` table is solved once with the varied givens kept as
symbols. Its worked solution is printed once, every number that depends on them
left open (a slot); each slot and each result is compiled to a plain Python
function. A variant is then a few float evaluations and string joins: no SymPy
solving, no SymPy printing.

``compile`` derives and compiles the problem, ``draw`` draws the variants, ``fill``
prints a variant's page and answers, ``write`` writes the folder and its answer key.
"""

from __future__ import annotations

from derive.homework.variants.chain import ChainCompiled
from derive.homework.variants.compile import FIGURE, Compiled, compile_problem
from derive.homework.variants.draw import GIVE_UP_AFTER, MAX_ATTEMPTS_PER_VARIANT, MAX_COUNT, draw
from derive.homework.variants.fill import (
    TEX_SOLUTION,
    answers,
    drawing,
    fill,
    fill_view,
    given_text,
    given_values,
    iterate,
    setup_figure,
    sign_convention,
    slot_texts,
    statement_only,
    statement_view,
)
from derive.homework.variants.record import Variant
from derive.homework.variants.write import OWNED, write_variants

__all__ = [
    "FIGURE",
    "GIVE_UP_AFTER",
    "MAX_ATTEMPTS_PER_VARIANT",
    "MAX_COUNT",
    "OWNED",
    "TEX_SOLUTION",
    "ChainCompiled",
    "Compiled",
    "Variant",
    "answers",
    "compile_problem",
    "draw",
    "drawing",
    "fill",
    "fill_view",
    "given_text",
    "given_values",
    "iterate",
    "setup_figure",
    "sign_convention",
    "slot_texts",
    "statement_only",
    "statement_view",
    "write_variants",
]
