"""Figures and the HTML page: the arrows agree with the numbers; the page works offline."""

from __future__ import annotations

import math
import os
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from pending_syntax import skip_if_pending

import derive
import derive.resources
from derive.writers.figure import Arrow, describe, to_svg, to_tikz

SVG = "{http://www.w3.org/2000/svg}"


def arrows_in_svg(svg: str) -> list[tuple[float, float]]:
    """Directions (x right, y up) of the arrows drawn in an SVG, in order."""
    root = ET.fromstring(svg)
    out = []
    for line in root.iter(f"{SVG}line"):
        if line.get("marker-end"):
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


def test_arrows_scale_with_speed() -> None:
    fig = describe(derive.solve(derive.load("notes-4c11-two-spheres")))
    lengths = [math.hypot(s.x2 - s.x1, s.y2 - s.y1) for s in fig.shapes if isinstance(s, Arrow)]
    assert lengths[1] > lengths[0]  # B (15 m/s) longer than A (5 m/s)


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
