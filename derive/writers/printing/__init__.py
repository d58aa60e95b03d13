"""LaTeX for the mathematics of a solution: SymPy's printer, set up for the notes.
May import: steps, physics, problem and the leaves.

A :class:`StepPrinter` prints symbols with the notes' names, numbers at the
problem's significant figures, a given's number in place of its symbol on a
substitution line, struck-out (cancelled) masses, and sums in the order the
equations were written. Renderers call :func:`latex_eqn` and
:func:`latex_inline`; no LaTeX string is patched afterwards.
"""

from __future__ import annotations

from derive.writers.printing.expressions import latex_expr, latex_inline
from derive.writers.printing.numerals import adds_up, exact_latex
from derive.writers.printing.printer import StepPrinter
from derive.writers.printing.rows import IMPLIES, Row, block_style, latex_eqn, latex_rows
from derive.writers.printing.style import Style

__all__ = [
    "IMPLIES",
    "Row",
    "StepPrinter",
    "Style",
    "adds_up",
    "block_style",
    "exact_latex",
    "latex_eqn",
    "latex_expr",
    "latex_inline",
    "latex_rows",
]
