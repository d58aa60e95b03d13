"""Issue #28, item 4: figures a teacher can hand out.

Was: on 4.C.11 (before) θ's label sat on the far side of A's centre from its arc; on
4.C.12 (after) the 2.86° arc could not be seen but was labelled; an x-y problem's figure
left out the angle between x and n that the statement gives; a variant's figure drew the
stated radii beside masses that are not the statement's, and said nothing.
"""

from __future__ import annotations

import math

import pytest
from support.output_cases import solution

import derive
from derive.writers.figure import Arc, Arrow, describe
from derive.writers.figure.scene import ARC_R, MIN_ARC


def _arcs(fig) -> list[Arc]:
    return [s for s in fig.shapes if isinstance(s, Arc)]


def test_an_angles_label_is_on_the_side_of_its_arc() -> None:
    """4.C.11 before: each θ's label lies on its arc's side of the body's centre, near it."""
    fig = describe(solution("notes-4c11-two-spheres"), after=False)
    labels = [lab for lab in fig.labels if lab.role == "angle"]
    assert len(labels) == 2
    for arc in _arcs(fig):
        mid = math.radians((arc.start + arc.end) / 2)
        bisector = (math.cos(mid), math.sin(mid))
        nearest = min(labels, key=lambda lab: math.hypot(lab.x - arc.x, lab.y - arc.y))
        towards = (nearest.x - arc.x) * bisector[0] + (nearest.y - arc.y) * bisector[1]
        assert towards > 0.5 * ARC_R, (arc, nearest)
        ax, ay = arc.x + ARC_R * bisector[0], arc.y + ARC_R * bisector[1]
        assert math.hypot(nearest.x - ax, nearest.y - ay) < 1.0, (arc, nearest)


def test_an_arc_too_small_to_see_is_neither_drawn_nor_labelled() -> None:
    """4.C.12 after: θ_A2 = tan⁻¹(0.05) = 2.86° (the notes): an arc of 0.75 cm radius is
    0.04 cm long; it is left out, and so is its label."""
    fig = describe(solution("notes-4c12-cue-ball"), after=True)
    assert all(abs(math.radians(a.end - a.start)) * a.r >= MIN_ARC for a in _arcs(fig))
    assert not [lab for lab in fig.labels if lab.text == "theta_A2"]


def test_b_leaves_along_n_in_4c12() -> None:
    """4.C.12: (2) gives v_B2t = 0 (B moves "directly to the side pocket", along the line of
    impact), so B's arrow after the impact lies along n."""
    s = solution("notes-4c12-cue-ball")
    assert s.results["v_B2t"].value == 0
    fig = describe(s, after=True)
    arrow = next(a for a in fig.shapes if isinstance(a, Arrow) and a.name == "v_B2")
    axis = next(a for a in fig.shapes if getattr(a, "name", "") == "n" and not isinstance(a, Arrow))
    cross = (arrow.x2 - arrow.x1) * (axis.y2 - axis.y1) - (arrow.y2 - arrow.y1) * (axis.x2 - axis.x1)
    assert abs(cross) < 1e-9


def test_an_xy_figure_shows_the_angle_between_x_and_n() -> None:
    """FisicaLab Example 7: the common normal at 20° from the x axis."""
    fig = describe(solution("fisicalab-example-7-normal-at-20deg"), after=False)
    assert any(a.name == "phi" and abs((a.end - a.start) - 20) < 1e-6 for a in _arcs(fig))
    assert any(lab.text == "20°" for lab in fig.labels)


def test_a_variants_figure_says_its_sizes_are_schematic(tmp_path) -> None:
    """4.C.11's radii (75 and 48 mm) are stated; a variant's masses are not the statement's."""
    from derive.homework.variants.compile import compile_problem
    from derive.homework.variants.draw import draw

    compiled = compile_problem(derive.load("notes-4c11-two-spheres"))
    variant = draw(compiled, 1, seed=3)[0]
    assert describe(compiled.solved(variant.values), after=False).schematic
    assert not describe(solution("notes-4c11-two-spheres")).schematic
    page = derive.render(solution("notes-4c11-two-spheres"), "md")
    assert "schematic" not in page


def test_the_acute_angle_asked_is_drawn_from_the_line_of_centres() -> None:
    """OCR 2023 asks for the angle A's velocity makes with the line of centres, 46.8° (the
    mark scheme): the after figure draws that arc, from the sense of n that A moves along."""
    fig = describe(solution("ocr-fm-2023-oblique-discs-60deg"), after=True)
    arc = next(a for a in _arcs(fig) if a.name == "alpha_A2")
    assert abs(abs(arc.end - arc.start) - 46.8) < 0.05
    assert any(lab.text == "alpha_A2" for lab in fig.labels)


def _along(fig, name: str) -> tuple[float, float]:
    """The unit vector of the axis ``name`` (n or t) as drawn."""
    axis = next(a for a in fig.shapes if getattr(a, "name", "") == name and not isinstance(a, Arrow))
    dx, dy = axis.x2 - axis.x1, axis.y2 - axis.y1
    return dx / math.hypot(dx, dy), dy / math.hypot(dx, dy)


def test_a_coefficient_kept_as_a_letter_is_drawn_at_a_half_and_the_caption_says_so() -> None:
    """Pre-U 9795/2 specimen Q2: equal balls, B at rest, the line of centres at 30° to A's path;
    the mark scheme's v_1 = (√3/4) u (1 − e) along the line of centres, and A keeps u sin 30° = u/2
    across it. Drawn with every letter 1, e = 1 made v_A2n = 0: A went off along t whatever e.
    At e = 1/2 A's arrow makes tan⁻¹((√3/8)/(1/2)) = tan⁻¹(√3/4) with t."""
    fig = describe(solution("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg"), after=True)
    arrow = next(a for a in fig.shapes if isinstance(a, Arrow) and a.name == "v_A2")
    dx, dy = arrow.x2 - arrow.x1, arrow.y2 - arrow.y1
    (nx, ny), (tx, ty) = _along(fig, "n"), _along(fig, "t")
    assert (dx * nx + dy * ny) / (dx * tx + dy * ty) == pytest.approx(math.sqrt(3) / 4, rel=1e-6)
    assert fig.drawn_for == (("e", "0.5"),)
    assert "drawn for e = 0.5" in fig.caption
    md = derive.render(solution("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg"), "md")
    assert "drawn for <i>e</i> = 0.5, a letter in the problem" in md
    # a number for e, or none needed (the figure before the impact): nothing drawn for
    assert describe(solution("notes-4c11-two-spheres"), after=True).drawn_for == ()
    assert describe(solution("pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg")).drawn_for == ()


def test_a_coefficient_kept_as_a_letter_is_not_drawn_where_it_stops_a_body() -> None:
    """Edexcel M2 January 2015 Q7 (mark scheme: v = u - 2ue, w = u(1 + e)): at e = 1/2 P would
    stand still; it is drawn at e = 0.6 instead, P moving back at u(1 - 1.2) = -0.2u."""
    fig = describe(solution("edexcel-m2-2015-january-q7-m-at-3u-hits-2m-p-reverses"), after=True)
    assert fig.drawn_for == (("e", "0.6"),)
    arrow = next(a for a in fig.shapes if isinstance(a, Arrow) and a.name == "v_A2")
    (nx, ny) = _along(fig, "n")
    assert (arrow.x2 - arrow.x1) * nx + (arrow.y2 - arrow.y1) * ny < 0
