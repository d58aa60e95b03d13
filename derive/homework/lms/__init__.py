"""Homework variants for a learning-management system: Moodle XML, PrairieLearn and STACK.
May import: the rest of homework, checking's mistakes, writers, steps, physics, problem and the leaves.

The Moodle and PrairieLearn exports ask for one result (``--result``) of each variant drawn by
:mod:`derive.variants`, graded by the significant-figure rule of ``derive check``:

* the right answer is the value as the answer key shows it (key.json ``shown``);
* the tolerance is 1.5 units in its last significant digit: half a unit, so that
  any answer that rounds to the shown value counts, plus the ±1 in the last digit
  that ``derive check`` allows for rounded intermediates. For v = 8.40 m/s it is
  0.015 m/s (8.385 to 8.415). The significant figures are those the value was
  rounded to, so the trailing zeros of a rounded whole number do not count:
  1045.81 J at three figures is shown as 1050 J, ± 15 J. An exact zero (shown
  ``0``) gets ±0.005.

Moodle: one numerical question per variant, all in one category (a random
question drawn from it gives each student a variant), with the worked solution as
general feedback and, where :mod:`derive.mistakes` predicts the value a common
mistake gives, that value as a wrong answer with the mistake's hint as feedback.
Moodle gives the feedback of the first answer whose range holds the response, so
the mistakes' ranges are cut where they would overlap the right answer's or each
other's (:func:`mistake_ranges`): a student gets the hint of the mistake nearest
to their value.

PrairieLearn: a question folder (``info.json``, ``question.html``, ``server.py``)
whose ``generate()`` picks one of the same variants by ``data["variant_seed"]``
and whose ``grade()`` gives a wrong answer the same mistake hints (in place of
pl-number-input's "does not have precision" message, which ``rtol="0"`` would give
every wrong answer).

STACK (:mod:`~derive.homework.lms.stack`): Moodle XML with one STACK question per asked
result holding every variant (question variables in Maxima indexed by the deployed seed),
graded by the same rule, with one node of its response tree per common mistake.

No question text carries the problem's citation (its Source line): the
citations of the bundled problems quote their published answers.

Nothing here needs more than the standard library and derive itself.
"""

from __future__ import annotations

from derive.homework.lms.exports import build_exports
from derive.homework.lms.grading import ZERO_TOLERANCE, default_result, tolerance
from derive.homework.lms.markup import esc, solution_html, statement_html
from derive.homework.lms.mistake_model import MistakeModel
from derive.homework.lms.moodle import moodle_xml
from derive.homework.lms.pl import prairielearn, prairielearn_files
from derive.homework.lms.stack import stack_xml

__all__ = [
    "ZERO_TOLERANCE",
    "MistakeModel",
    "build_exports",
    "default_result",
    "esc",
    "moodle_xml",
    "prairielearn",
    "prairielearn_files",
    "solution_html",
    "stack_xml",
    "statement_html",
    "tolerance",
]
