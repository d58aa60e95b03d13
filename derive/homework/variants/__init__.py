"""Homework variants: a problem with a ``[vary]`` table, drawn again and again with other numbers.
May import: the rest of homework, writers, steps, physics, problem and the leaves.

A variant is the problem file with its drawn numbers written into ``[given]``: it is read,
solved and written as ``derive solve`` reads, solves and writes a file, through the same
writers (one engine for a single impact and a chain). A single impact is also solved once
with its varied givens as symbols: its closed forms test each draw quickly.

``compile`` makes a problem ready (each drawn value as the file writes it, the test of a
draw), ``draw`` draws the variants, ``fill`` writes a variant's pages, key and data,
``write`` the folder and its answer key (on every core).
"""

from __future__ import annotations

from derive.homework.variants.compile import Compiled, compile_problem
from derive.homework.variants.draw import MAX_COUNT, draw
from derive.homework.variants.fill import answers, fill, fill_view, given_values, setup_figure, sheet
from derive.homework.variants.record import Variant
from derive.homework.variants.write import write_variants

__all__ = [
    "MAX_COUNT",
    "Compiled",
    "Variant",
    "answers",
    "compile_problem",
    "draw",
    "fill",
    "fill_view",
    "given_values",
    "setup_figure",
    "sheet",
    "write_variants",
]
