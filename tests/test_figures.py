"""Figures and the HTML page: the arrows agree with the numbers and are to scale, the
bodies to the given radii, floors horizontal, labels clear of everything; the page
works offline."""

from __future__ import annotations

import functools
import math
import os
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from support import figure_cases
from support.pending_syntax import skip_if_pending

import derive
import derive.resources
from derive.writers.figure import Arrow, Axis, Body, Figure, Surface, describe, setup_svg, setup_tikz, to_svg, to_tikz
from derive.writers.figure.model import HEAD, segments
from derive.writers.figure.scene import ARROW_MAX, ARROW_MIN

SVG = "{http://www.w3.org/2000/svg}"
A4_TEXT_WIDTH = 21.0 - 2 * 2.2  # cm: A4 less the templates' 2.2 cm margins (Letter: 17.2 cm)


def arrows_in_svg(svg: str) -> list[tuple[float, float]]:
    """Directions (x right, y up) of the velocity arrows drawn in an SVG, in order."""
    root = ET.fromstring(svg)
    out = []
    for group in root.iter(f"{SVG}g"):
        if group.get("class") == "velocity":
            line = group.find(f"{SVG}line")
            dx = float(line.get("x2")) - float(line.get("x1"))
            dy = -(float(line.get("y2")) - float(line.get("y1")))
            norm = math.hypot(dx, dy)
            out.append((dx / norm, dy / norm))
    return out


def same_direction(a: tuple[float, float], b: tuple[float, float]) -> bool:
    return a[0] * b[0] + a[1] * b[1] > 0.9999


def test_example_4c11_arrows_point_as_the_notes_say() -> None:
    sol = derive.solve(derive.load("notes-4c11-two-spheres"))
    th = math.radians(37.6)
    # n to the right, t up. A moves at 37.6 deg from +n toward +t; B at 37.6 deg from -n toward -t.
    before = arrows_in_svg(to_svg(describe(sol)))
    assert len(before) == 2
    assert same_direction(before[0], (math.cos(th), math.sin(th)))
    assert same_direction(before[1], (-math.cos(th), -math.sin(th)))
    # After: the notes' v_A2 = 3.05 e_t - 1.11 e_n and v_B2 = -9.15 e_t + 8.40 e_n.
    after = arrows_in_svg(to_svg(describe(sol, after=True)))
    assert same_direction(after[0], (-1.11 / math.hypot(1.11, 3.05), 3.05 / math.hypot(1.11, 3.05)))
    assert same_direction(after[1], (8.40 / math.hypot(8.40, 9.15), -9.15 / math.hypot(8.40, 9.15)))


def check_scale(figures: dict[str, Figure], speeds: dict[str, float], rel: float = 1e-6) -> set[str]:
    """Arrows against their speeds (``speeds`` by name, ``figures`` by stage "1" and "2"):
    one arrow per non-zero speed; the greatest speed ARROW_MAX long (in its own figure when
    the figures have scales of their own); every other arrow speed x scale long, except
    exactly those that would be under ARROW_MIN: drawn ARROW_MIN long, flagged, and named in
    the caption. Returns the names of the lengthened arrows."""
    arrows = {s.name: s for fig in figures.values() for s in fig.shapes if isinstance(s, Arrow)}
    moving = {n: v for n, v in speeds.items() if v > 1e-9}
    assert set(arrows) == set(moving)
    top = {k: max((v for n, v in moving.items() if n[3] == k), default=0.0) for k in "12"}
    own = min(top.values()) > 0 and min(top.values()) < max(top.values()) / 4
    longer = set()
    for name, speed in moving.items():
        fig, arrow = figures[name[3]], arrows[name]
        scale = ARROW_MAX / (top[name[3]] if own else max(top.values()))
        if speed * scale < ARROW_MIN:
            longer.add(name)
            assert arrow.lengthened and arrow.length == pytest.approx(ARROW_MIN), name
            assert re.search(rf"except .*\b{name}\b.*drawn longer", fig.caption), (name, fig.caption)
        else:
            assert not arrow.lengthened and arrow.length == pytest.approx(speed * scale, rel=rel), name
            assert not re.search(rf"\b{name}\b", fig.caption), (name, fig.caption)
    for k, fig in figures.items():
        assert ("drawn longer" in fig.caption) == any(n[3] == k for n in longer), fig.caption
    return longer


def test_arrows_and_bodies_are_to_scale() -> None:
    """Example 4.C.11: arrow length / speed is one scale for all four velocities (the notes'
    speeds: 5 and 15 m/s before; 3.05 e_t - 1.11 e_n and -9.15 e_t + 8.40 e_n after; the
    least, v_A2, is 0.65 cm long, over ARROW_MIN: none is lengthened), and the spheres are
    in the ratio of the radii the notes give, 75 mm to 48 mm."""
    sol = derive.solve(derive.load("notes-4c11-two-spheres"))
    speeds = {"v_A1": 5.0, "v_B1": 15.0, "v_A2": math.hypot(3.05, 1.11), "v_B2": math.hypot(9.15, 8.40)}
    figures = {"1": describe(sol), "2": describe(sol, after=True)}
    assert check_scale(figures, speeds, rel=0.01) == set()  # the notes' figures are rounded to 3
    assert figures["2"].caption == "arrows to scale with speed"
    bodies = {s.name: s.r for s in describe(sol).shapes if isinstance(s, Body)}
    assert bodies["A"] / bodies["B"] == pytest.approx(75 / 48)


def test_a_slow_arrow_is_drawn_longer_and_the_caption_says_so() -> None:
    """OCR MEI 2023 Q2: after the impact A moves at 0.2 m/s, back or on; to scale (6 m/s is
    3 cm) its arrow would be 0.1 cm, its head shrunk to nothing, the two cases alike. Drawn
    ARROW_MIN long with a full head, it points back (-n) in one figure and on (+n) in the
    other, and the caption names it with its speed."""
    drawn = {}
    for case, sign in (("backward", -1), ("forward", 1)):
        sol = derive.solve(derive.load(f"ocr-mei-fmm-2023-a-speed-0p2-{case}"))
        before, after = describe(sol), describe(sol, after=True)
        v_B2 = 3.55 if case == "backward" else 3.45  # the mark scheme's
        longer = check_scale({"1": before, "2": after}, {"v_A1": 6, "v_B1": 2, "v_A2": 0.2, "v_B2": v_B2})
        assert longer == {"v_A2"}
        assert "except v_A2 (0.2 m/s), drawn longer to show its direction" in after.caption
        (a2,) = (s for s in after.shapes if isinstance(s, Arrow) and s.name == "v_A2")
        assert a2.length >= ARROW_MIN and (a2.x2 - a2.x1) * sign > 0 and a2.y1 == pytest.approx(a2.y2)
        svg = ET.fromstring(to_svg(after))  # the drawn arrow: its direction, and a full-size head
        direction = arrows_in_svg(to_svg(after))[0]
        head = next(g for g in svg.iter(f"{SVG}g") if g.get("class") == "velocity").find(f"{SVG}polygon")
        (tx, ty), *wings = [tuple(map(float, p.split(","))) for p in head.get("points").split()]
        base = ((wings[0][0] + wings[1][0]) / 2, (wings[0][1] + wings[1][1]) / 2)
        assert math.hypot(tx - base[0], ty - base[1]) == pytest.approx(HEAD * 40, abs=0.2)
        drawn[case] = direction
        page = {fmt: derive.render(sol, fmt) for fmt in ("md", "tex", "html")}
        assert "drawn longer to show its direction" in page["md"] and "<i>v</i><sub>A2</sub> (0.2 m/s)" in page["md"]
        assert r"except $v_{A2}$ (0.2 m/s), drawn longer" in page["tex"]
        assert "After the impact: arrows to scale with speed, except <i>v</i><sub>A2</sub>" in page["html"]
    assert same_direction(drawn["backward"], (-1, 0)) and same_direction(drawn["forward"], (1, 0))
    plain = {fmt: derive.render(derive.solve(derive.load("notes-4c11-two-spheres")), fmt) for fmt in ("md", "tex")}
    assert all("drawn longer" not in text for text in plain.values())


def test_the_caption_names_each_lengthened_arrow_in_the_page_s_notation() -> None:
    """One arrow or two, a speed in numbers or a symbol's (no number), each page's names."""
    fig = Figure("After the impact", own_scale=True, lengthened=(("v_A2", "0.2 m/s"), ("v_B2", "")))
    assert fig.caption == (
        "arrows to scale with speed, a scale of their own in each figure, "
        "except v_A2 (0.2 m/s) and v_B2, drawn longer to show their directions"
    )
    tex = fig.scale_note(lambda n: f"${n}$", lambda t: t.replace("%", r"\%"))
    assert "except $v_A2$ (0.2 m/s) and $v_B2$, drawn" in tex
    assert Figure("x").caption == "arrows to scale with speed"


def test_a_body_that_stops_has_no_arrow() -> None:
    """OCR MEI 2024: disc A stops. No arrow, however short the minimum makes arrows: the
    label v_A2 = 0, and the caption names no lengthened arrow."""
    after = describe(derive.solve(derive.load("ocr-mei-fmm-2024-disc-a-stops")), after=True)
    assert [s.name for s in after.shapes if isinstance(s, Arrow)] == ["v_B2"]
    assert any(lab.text == "v_A2" and lab.tail == " = 0" for lab in after.labels)
    assert "v_A2" not in after.caption


def test_a_velocity_the_problem_asks_for_is_drawn_at_its_value() -> None:
    """A given left unknown ("?") is drawn at the value the solution finds, not as 1.
    OCR MEI 2024: A arrives at v_A1n = 9 m/s, B at 2 m/s. Edexcel M2 2017: P and Q move in
    opposite directions, v_A1 = 8v and v_B1 = -4.5v. Edexcel M4 2018: alpha = 72.98 deg
    from the wall."""
    disc = derive.solve(derive.load("ocr-mei-fmm-2024-disc-a-stops"))
    figures = {"1": describe(disc), "2": describe(disc, after=True)}
    speeds = {"v_A1": 9.0, "v_B1": 2.0, "v_A2": 0.0, "v_B2": math.hypot(6.4, math.sqrt(3))}
    assert check_scale(figures, speeds) == set()
    pq = describe(derive.solve(derive.load("edexcel-m2-2017-january-q5-both-reverse-find-speeds-before")))
    a1, b1 = (s for s in pq.shapes if isinstance(s, Arrow))
    assert a1.x2 > a1.x1 and b1.x2 < b1.x1 and a1.length / b1.length == pytest.approx(8 / 4.5)
    wall = describe(derive.solve(derive.load("edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke")))
    (ball,) = (s for s in wall.shapes if isinstance(s, Arrow))
    angle = math.degrees(math.atan2(abs(ball.x2 - ball.x1), abs(ball.y2 - ball.y1)))  # from the wall (t is up)
    assert angle == pytest.approx(72.976, abs=0.01)


def test_a_bullet_that_lodges_gets_a_scale_per_figure() -> None:
    """MSU: 300 m/s before, 1.5 m/s after (0.02 kg into 4.0 kg): on one scale the arrows after
    would be 0.015 cm long, so each figure has its own, and the caption says so."""
    sol = derive.solve(derive.load("msu-lectureonline-bullet-lodges-in-block"))
    before, after = describe(sol), describe(sol, after=True)
    lengths = [s.length for fig in (before, after) for s in fig.shapes if isinstance(s, Arrow)]
    assert min(lengths) > 1.0 and "own" in after.caption
    assert "own" not in describe(derive.solve(derive.load("notes-4c11-two-spheres"))).caption


def test_bodies_are_equal_without_radii() -> None:
    fig = describe(derive.solve(derive.load("notes-4c12-cue-ball")))
    a, b = (s.r for s in fig.shapes if isinstance(s, Body))
    assert a == b


def test_a_drop_falls_onto_a_horizontal_floor() -> None:
    """chain-ocr-m2-2006-drop-rebound: released above the ground, so the ground is drawn
    level, the sphere above it, falling down and rebounding up; n points down."""
    sol = derive.solve(derive.load("chain-ocr-m2-2006-drop-rebound"))
    for after, sign in ((False, -1), (True, 1)):
        fig = describe(sol, after=after)
        (floor,) = (s for s in fig.shapes if isinstance(s, Surface))
        (ball,) = (s for s in fig.shapes if isinstance(s, Body))
        (arrow,) = (s for s in fig.shapes if isinstance(s, Arrow))
        n_axis = next(s for s in fig.shapes if isinstance(s, Axis) and s.name == "n")
        assert floor.y1 == pytest.approx(floor.y2) and ball.y > floor.y1
        assert floor.ny < 0  # hatched below the face
        assert same_direction(((arrow.x2 - arrow.x1) / arrow.length, (arrow.y2 - arrow.y1) / arrow.length), (0, sign))
        assert n_axis.y2 < n_axis.y1 and n_axis.x1 == pytest.approx(n_axis.x2)
        assert "ground" in to_svg(fig)


def test_a_wall_stands_upright_and_a_block_on_a_spring_pan_falls() -> None:
    wall = describe(derive.solve(derive.load("giancoli-7-18-tennis-ball-wall-45deg")))
    (face,) = (s for s in wall.shapes if isinstance(s, Surface))
    assert face.x1 == pytest.approx(face.x2)
    pan = describe(derive.solve(derive.load("chain-block-onto-spring-pan")))  # a fall, then a vertical spring
    a, b = (s for s in pan.shapes if isinstance(s, Body))
    assert a.y > b.y and a.x == pytest.approx(b.x)
    cases = describe(derive.solve(derive.load("chain-hibbeler-15-58-suitcases")))  # a ramp, then a slide
    a, b = (s for s in cases.shapes if isinstance(s, Body))
    assert a.y == pytest.approx(b.y) and a.x < b.x


def test_xy_axes_where_the_problem_gives_them() -> None:
    """FisicaLab Example 7: n at 20 deg from +x, and the x-y axes drawn."""
    fig = describe(derive.solve(derive.load("fisicalab-example-7-normal-at-20deg")))
    axes = {s.name: s for s in fig.shapes if isinstance(s, Axis)}
    assert {"n", "t", "x", "y"} <= set(axes)
    n = axes["n"]
    assert math.degrees(math.atan2(n.y2 - n.y1, n.x2 - n.x1)) == pytest.approx(20)
    assert axes["x"].y1 == pytest.approx(axes["x"].y2) and axes["y"].x1 == pytest.approx(axes["y"].x2)
    plain = describe(derive.solve(derive.load("notes-4c11-two-spheres")))
    assert not {"x", "y"} & {s.name for s in plain.shapes if isinstance(s, Axis)}


def test_example_4c12_cue_ball_and_object_ball() -> None:
    sol = derive.solve(derive.load("notes-4c12-cue-ball"))
    before = arrows_in_svg(to_svg(describe(sol)))
    assert len(before) == 1  # B at rest: no arrow
    assert same_direction(before[0], (math.sqrt(0.5), math.sqrt(0.5)))  # 45 deg from +t toward +n
    after = arrows_in_svg(to_svg(describe(sol, after=True)))
    # B goes straight along n (to the side pocket); A at 2.86 deg from t toward n.
    assert same_direction(after[1], (1.0, 0.0))
    a = math.radians(math.degrees(math.atan(0.05)))
    assert same_direction(after[0], (math.sin(a), math.cos(a)))


@pytest.mark.parametrize("name", sorted(derive.resources.bundled()))
def test_every_bundled_figure_is_valid_svg_and_tikz(name: str) -> None:
    skip_if_pending(name)
    sol = derive.solve(derive.load(name))
    for after in (False, True):
        fig = describe(sol, after=after)
        ET.fromstring(to_svg(fig))  # well-formed XML
        tikz = to_tikz(fig)
        assert tikz.startswith(r"\begin{tikzpicture}") and tikz.endswith(r"\end{tikzpicture}")


def clashes(fig: Figure, step: float = 0.04) -> list[str]:
    """Labels that meet another label, a stroke or a body's outline: checked by sampling
    points along every stroke and outline and testing them against each label's box."""
    found = []
    boxes = [(lab.text, lab.box) for lab in fig.labels]
    for i, (a, (ax0, ay0, ax1, ay1)) in enumerate(boxes):
        for b, (bx0, by0, bx1, by1) in boxes[i + 1 :]:
            if ax0 < bx1 and bx0 < ax1 and ay0 < by1 and by0 < ay1:
                found.append(f"label {a} meets label {b}")
    points: list[tuple[str, float, float]] = []
    for s in fig.shapes:
        name = getattr(s, "name", type(s).__name__)
        if isinstance(s, Body):
            k = max(8, int(2 * math.pi * s.r / step))
            points += [
                (f"body {name}", s.x + s.r * math.cos(2 * math.pi * j / k), s.y + s.r * math.sin(2 * math.pi * j / k))
                for j in range(k)
            ]
        for (x1, y1), (x2, y2) in segments(s):
            k = max(1, int(math.hypot(x2 - x1, y2 - y1) / step))
            points += [
                (f"{type(s).__name__} {name}", x1 + (x2 - x1) * j / k, y1 + (y2 - y1) * j / k) for j in range(k + 1)
            ]
    for text, (x0, y0, x1, y1) in boxes:
        hit = {what for what, px, py in points if x0 < px < x1 and y0 < py < y1}
        found += [f"label {text} meets {what}" for what in sorted(hit)]
    return found


@functools.cache
def bundled_figures() -> list[tuple[str, Figure]]:
    """Before and after figures of every bundled problem, each impact stage of a chain too."""
    out = []
    for name in sorted(derive.resources.bundled()):
        sol = derive.solve(derive.load(name))
        parts = [(name, sol, {})]
        if sol.is_chain:
            from derive.writers.figure import chain_falls

            falls = chain_falls(sol)
            parts = [
                (f"{name}#{st.number}", st.part, {"falls": falls[st.number], "values": sol.values})
                for st in sol.stages
                if st.part
            ]
        for label, part, opts in parts:
            out += [
                (f"{label} {'after' if after else 'before'}", describe(part, after, **opts)) for after in (False, True)
            ]
    return out


def test_no_label_overlaps_in_bundled_figures() -> None:
    figures = bundled_figures()
    bad = [f"{name}: {c}" for name, fig in figures for c in clashes(fig)]
    assert bad == []
    assert len(figures) >= 2 * len(derive.resources.bundled())


def test_no_label_overlaps_in_500_generated_figures() -> None:
    bad = []
    for seed in range(figure_cases.CASES):
        sol = figure_cases.solution(figure_cases.case(seed))
        for after in (False, True):
            bad += [f"case {seed} {'after' if after else 'before'}: {c}" for c in clashes(describe(sol, after))]
    assert bad == []


def test_generated_arrows_are_to_scale() -> None:
    """Length / speed is one number in each figure, and the same before and after unless
    one figure's greatest speed is under a quarter of the other's (then each has its own);
    an arrow is drawn longer, and named in the caption, exactly when it would be under
    ARROW_MIN (:func:`check_scale`)."""
    longer = 0
    for seed in range(0, figure_cases.CASES, 5):
        c = figure_cases.case(seed)
        sol = figure_cases.solution(c)
        figures = {"1": describe(sol), "2": describe(sol, after=True)}
        out = figure_cases.outcome(c)
        speeds = {"v_A1": math.hypot(*c.A1), "v_B1": math.hypot(*c.B1), "v_A2": math.hypot(out["A2n"], out["A2t"])}
        if not c.fixed:
            speeds["v_B2"] = math.hypot(out["B2n"], out["B2t"])
        try:
            longer += len(check_scale(figures, speeds))
        except AssertionError as exc:
            raise AssertionError(f"case {seed}") from exc
    assert longer >= 5  # the generated cases do reach the minimum


def test_figures_fit_the_page() -> None:
    """Drawn at 1:1 (labels in the text's 11 pt), every figure fits the text width of A4 and
    Letter with room to spare; the SVG is 40 px per cm (a 12 cm figure is 480 px)."""
    for name, fig in bundled_figures():
        assert fig.width < 0.8 * A4_TEXT_WIDTH and fig.height < 12, name
        svg = ET.fromstring(to_svg(fig))
        assert float(svg.get("width")) == pytest.approx(fig.width * 40, abs=1)


def test_setup_figure_for_a_student_sheet() -> None:
    """The figure of a statement: the given velocities and angles, nothing found."""
    sol = derive.solve(derive.load("notes-4c11-two-spheres"))
    svg, tikz = setup_svg(sol), setup_tikz(sol)
    ET.fromstring(svg)
    assert "A1" in svg and "A2" not in svg and "θ" in svg
    assert r"v_{A1}" in tikz and r"v_{A2}" not in tikz
    chain = derive.solve(derive.load("chain-ocr-m2-2006-drop-rebound"))
    assert "ground" in setup_svg(chain)


def test_wall_is_hatched() -> None:
    text = """title = "ball and wall"
kind = "oblique"
[given]
m_A = "0.2 kg"
e = 0.5
v_A1 = "10 m/s"
[A]
angle = "30 deg"
from = "+t"
toward = "+n"
[B]
fixed = true
name = "wall"
"""
    from derive.problem import loads

    sol = derive.solve(loads(text, path="w.toml"))
    svg = to_svg(describe(sol))
    assert "wall" in svg
    assert len(re.findall(r'stroke-width="1"/>', svg)) >= 10  # the hatching
    assert len(arrows_in_svg(svg)) == 1


def test_no_figure_option(cli) -> None:
    with_fig = cli("solve", "notes-4c11-two-spheres")
    without = cli("solve", "notes-4c11-two-spheres", "--no-figure")
    assert "<svg" in with_fig.out and "<svg" not in without.out


def test_html_page_is_self_contained(tmp_path: Path) -> None:
    page = derive.render(derive.solve(derive.load("notes-4c11-two-spheres")), "html")
    assert page.startswith("<!DOCTYPE html>")
    refs = re.findall(r'(?:src|href)\s*=\s*"([^"]*)"', page)
    assert all(not r.startswith(("http:", "https:", "//")) for r in refs), refs
    assert "@import" not in page
    assert page.count('role="img"') == 2  # the two figures (KaTeX draws some symbols as SVG too)
    assert "@media print" in page


def _screenshot(chromium: str, page: Path, out: Path) -> None:
    subprocess.run(
        [
            chromium,
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
            f"--user-data-dir={page.parent / 'profile'}",
            "--window-size=900,1200",
            f"--screenshot={out}",
            page.as_uri(),
        ],
        check=True,
        capture_output=True,
        timeout=120,
    )


@pytest.mark.slow
@pytest.mark.parametrize("name", ["notes-4c11-two-spheres", "notes-4c12-cue-ball"])
def test_html_screenshot_is_not_blank(name: str, tmp_path: Path) -> None:
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        if os.environ.get("CI"):
            pytest.fail("chromium is missing: apt-get install chromium")
        pytest.skip("chromium is not installed")
    page = tmp_path / "page.html"
    page.write_text(derive.render(derive.solve(derive.load(name)), "html"), encoding="utf-8")
    blank = tmp_path / "blank.html"
    blank.write_text("<!DOCTYPE html><html><body></body></html>", encoding="utf-8")
    _screenshot(chromium, page, tmp_path / "page.png")
    _screenshot(chromium, blank, tmp_path / "blank.png")
    shot, empty = (tmp_path / "page.png").read_bytes(), (tmp_path / "blank.png").read_bytes()
    assert shot[:8] == b"\x89PNG\r\n\x1a\n"
    # A page of text, formulas and a figure compresses far worse than a white one.
    assert len(shot) > 8 * len(empty), (len(shot), len(empty))


@pytest.mark.slow
def test_rendered_label_widths_fit_their_boxes(tmp_path: Path) -> None:
    """Chromium lays the SVG labels out: each is no wider than the box the layout kept for
    it (the height getBBox gives is the font's line box, not the ink, so only widths)."""
    import json

    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    if chromium is None:
        pytest.skip("chromium is not installed")
    svgs, widths = [], []
    for _, fig in bundled_figures():
        svgs.append(to_svg(fig))
        widths.append([lab.w * 40 for lab in fig.labels])
    script = (
        "<script>const w = " + json.dumps(widths) + "; const bad = [];"
        "document.querySelectorAll('svg').forEach((s, i) => s.querySelectorAll('text').forEach((t, j) => {"
        "const b = t.getBBox(); if (b.width > w[i][j]) bad.push([i, t.textContent, b.width, w[i][j]]); }));"
        "document.getElementById('out').textContent = 'RESULT' + JSON.stringify(bad) + 'END';</script>"
    )
    page = tmp_path / "labels.html"
    page.write_text("<!DOCTYPE html><html><body>" + "".join(svgs) + "<pre id='out'></pre>" + script + "</body></html>")
    flags = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run"]
    flags += ["--disable-background-networking", "--disable-component-update", "--disable-sync"]
    dom = subprocess.run(
        [
            chromium,
            *flags,
            f"--user-data-dir={tmp_path / 'profile'}",
            "--virtual-time-budget=5000",
            "--dump-dom",
            page.as_uri(),
        ],
        check=True,
        capture_output=True,
        text=True,
        timeout=180,
    ).stdout
    found = re.search(r"RESULT(.*?)END", dom)
    assert found is not None, "the page's script did not run"
    assert json.loads(found.group(1).replace("&quot;", '"')) == []
