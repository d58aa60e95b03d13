"""Common mistakes in central impact, each as a mistaken version of equations (1)-(4).
May import: the rest of checking, steps, physics, problem and the leaves.

A student who makes one of these mistakes writes equations (1)-(4) wrongly (or
resolves the velocities wrongly before writing them), then solves them correctly
and gets wrong numbers. Each mistake is a function that takes the problem's
correct :class:`Model` and returns a :class:`Variant`: what its equations do
differently (B's velocity negated, the restitution differences reversed, ...), or
None where the mistake cannot happen in that problem (no angle, no weight, no t
components in a direct impact). :func:`outcomes` solves every variant that applies
and changes something, and gives its values by result name (the names of
:attr:`derive.Solution.results`) and its equations with the numbers in, so that
the checker can name the mistake that reproduces a wrong answer, and the equation
where it enters; :func:`pair_outcomes` does the same for two mistakes made together.

Modules: ``records`` (Variant, Mistake, Outcome), ``equations`` (the equations
and their solution), ``quantities`` (results from velocities), one module per family
of mistakes (``velocities``, ``restitution``, ``tangential``, ``directions``,
``masses``), ``registry`` (the table of kinds), ``pairs`` and ``outcomes`` (the cache).
"""

from __future__ import annotations

from derive.checking.mistakes.equations import Model
from derive.checking.mistakes.outcomes import changes, correct, forms, model, outcomes, pair_outcomes
from derive.checking.mistakes.pairs import MAX_PAIRS, combine
from derive.checking.mistakes.records import Mistake, Outcome, Quantity, Variant, mistake
from derive.checking.mistakes.registry import EQUATION_TITLES, KINDS, REGISTRY, phrase, register
from derive.checking.mistakes.velocities import of_one_body, sin_cos_swapped_as_written

__all__ = [
    "EQUATION_TITLES",
    "KINDS",
    "MAX_PAIRS",
    "REGISTRY",
    "Mistake",
    "Model",
    "Outcome",
    "Quantity",
    "Variant",
    "changes",
    "combine",
    "correct",
    "forms",
    "mistake",
    "model",
    "of_one_body",
    "outcomes",
    "pair_outcomes",
    "phrase",
    "register",
    "sin_cos_swapped_as_written",
]
