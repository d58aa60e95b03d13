"""Figures of an impact: one geometric description, drawn as SVG and as TikZ.
May import: the rest of writers, steps, physics, problem and the leaves.

- :mod:`.model`: the shapes and labels, in centimetres (y up);
- :mod:`.frame`: which way n points (a floor is level, a drop falls down);
- :mod:`.scene`: a solution's figure, before or after the impact (:func:`describe`);
- :mod:`.layout`: label placement by bounding boxes;
- :mod:`.svg`, :mod:`.tikz`: the drawing, pure functions returning text.

>>> import derive  # doctest: +SKIP
>>> svg = setup_svg(derive.solve(derive.load("notes-4c11-two-spheres")))  # doctest: +SKIP
"""

from __future__ import annotations

from derive.steps.model import Solution
from derive.writers.figure.frame import chain_falls
from derive.writers.figure.model import Arc, Arrow, Axis, Body, Figure, Surface
from derive.writers.figure.scene import describe
from derive.writers.figure.svg import to_svg
from derive.writers.figure.tikz import to_tikz


def setup_svg(solution: Solution) -> str:
    """The set-up figure of a problem statement (before the impact), as SVG.

    For a student sheet: the bodies, the n-t axes, the given velocities and
    angles, nothing found. A chain gives its first impact's.
    """
    return to_svg(describe(solution, after=False))


def setup_tikz(solution: Solution) -> str:
    """The set-up figure of a problem statement (before the impact), as a tikzpicture."""
    return to_tikz(describe(solution, after=False))


__all__ = [
    "Arc",
    "Arrow",
    "Axis",
    "Body",
    "Figure",
    "Surface",
    "chain_falls",
    "describe",
    "setup_svg",
    "setup_tikz",
    "to_svg",
    "to_tikz",
]
