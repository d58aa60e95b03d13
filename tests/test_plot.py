"""The plot of the outcome against e: its curves against conservation laws and the notes,
the ``derive plot`` command, and ``--plot`` in a solution."""

from __future__ import annotations

import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

import derive
from derive.writers import plot

TH = math.radians(37.6)
# Example 4.C.11 (the notes): m_A = 20 kg, m_B = 5 kg; v_A1n = 5 cos(37.6°), v_B1n = -15 cos(37.6°),
# v_A1t = 5 sin(37.6°), v_B1t = -15 sin(37.6°)
M_A, M_B = 20.0, 5.0
A1 = (5 * math.cos(TH), 5 * math.sin(TH))
B1 = (-15 * math.cos(TH), -15 * math.sin(TH))


def kinetic(n_a: float, t_a: float, n_b: float, t_b: float) -> float:
    return 0.5 * M_A * (n_a**2 + t_a**2) + 0.5 * M_B * (n_b**2 + t_b**2)


@pytest.fixture(scope="module")
def c11() -> plot.Curves:
    return plot.curves(derive.load("notes-4c11-two-spheres"))


def test_e_is_from_0_to_1_and_the_problems_e_is_marked(c11: plot.Curves) -> None:
    assert c11.e[0] == 0 and c11.e[-1] == 1 and len(c11.e) >= 51
    assert c11.mark == pytest.approx(0.6)
    assert {s.name for s in c11.series} == {"v_A2n", "v_B2n", "T_lost/T_1"}


def test_plastic_impact_gives_the_common_velocity(c11: plot.Curves) -> None:
    """e = 0: both move on along n at (m_A v_A1n + m_B v_B1n)/(m_A + m_B), and the energy lost
    is what that common velocity leaves of T_1 (t components unchanged)."""
    common = (M_A * A1[0] + M_B * B1[0]) / (M_A + M_B)
    assert c11.at("v_A2n", 0) == pytest.approx(common)
    assert c11.at("v_B2n", 0) == pytest.approx(common)
    t1 = kinetic(A1[0], A1[1], B1[0], B1[1])
    t2 = kinetic(common, A1[1], common, B1[1])
    assert c11.at("T_lost/T_1", 0) == pytest.approx((t1 - t2) / t1)


def test_elastic_impact_keeps_the_kinetic_energy(c11: plot.Curves) -> None:
    """e = 1: nothing lost, and the velocities after carry T_1 and the momentum along n."""
    assert c11.at("T_lost/T_1", 1) == pytest.approx(0, abs=1e-12)
    a, b = c11.at("v_A2n", 1), c11.at("v_B2n", 1)
    assert kinetic(a, A1[1], b, B1[1]) == pytest.approx(kinetic(A1[0], A1[1], B1[0], B1[1]))
    assert M_A * a + M_B * b == pytest.approx(M_A * A1[0] + M_B * B1[0])


def test_at_the_problems_e_the_notes_answer(c11: plot.Curves) -> None:
    """The notes: v_A2n = -1.11 m/s, v_B2n = 8.40 m/s at e = 0.6 (rounded to 3 figures)."""
    assert c11.at("v_A2n", 0.6) == pytest.approx(-1.11, abs=0.006)
    assert c11.at("v_B2n", 0.6) == pytest.approx(8.40, abs=0.006)


def test_symbolic_speed_is_divided_out() -> None:
    """Example 4.C.12 keeps v_A1 (and m) symbolic: velocities per v_A1. The notes' (5):
    v_A2n = sqrt(2)/4 (1 - e) v_A1; with equal masses B takes the rest, v_B2n = sqrt(2)/4 (1 + e) v_A1."""
    c = plot.curves(derive.load("notes-4c12-cue-ball"))
    assert c.per == "v_A1" and c.mark == pytest.approx(0.9)
    for e in (0.0, 0.5, 0.9, 1.0):
        assert c.at("v_A2n", e) == pytest.approx(math.sqrt(2) / 4 * (1 - e))
        assert c.at("v_B2n", e) == pytest.approx(math.sqrt(2) / 4 * (1 + e))


def test_an_inverse_problem_is_plotted_at_the_e_it_finds() -> None:
    """OpenStax 8-31: 3.00 m/s into the cushion, back at 2.40 m/s, so e = 0.8; against a
    fixed cushion v_A2 = -e v_A1 and T_lost/T_1 = 1 - e^2."""
    c = plot.curves(derive.load("openstax-cp-8-31-billiard-ball-cushion"))
    assert c.mark == pytest.approx(0.8)
    assert {s.name for s in c.series} == {"v_A2", "T_lost/T_1"}
    for e in (0.0, 0.8, 1.0):
        assert c.at("v_A2", e) == pytest.approx(-3.0 * e)
        assert c.at("T_lost/T_1", e) == pytest.approx(1 - e * e)


def test_a_chains_impact_stage() -> None:
    """OCR M2 2006: a sphere reaches the ground at sqrt(2 g h) = sqrt(4g) = 6.26 m/s (g = 9.8)."""
    problem = plot.impact_of(derive.load("chain-ocr-m2-2006-drop-rebound"))
    c = plot.curves(problem)
    assert c.at("v_A2", 1) == pytest.approx(-math.sqrt(4 * 9.8))
    assert c.at("v_A2", 0) == pytest.approx(0, abs=1e-12)


def test_plot_command_writes_svg(cli, tmp_path: Path) -> None:
    out = cli("plot", "notes-4c11-two-spheres")
    assert out.code == 0
    root = ET.fromstring(out.out)
    assert root.get("role") == "img" and len(root.findall("{http://www.w3.org/2000/svg}polyline")) > 20
    target = tmp_path / "p.svg"
    assert cli("plot", "notes-4c11-two-spheres", "-o", str(target)).code == 0
    ET.fromstring(target.read_text())
    bad = cli("plot", "notes-4c11-two-spheres", "-o", str(tmp_path / "p.txt"))
    assert bad.code == 2 and "extension" in bad.err
    assert cli("plot", "chain-ocr-m2-2006-drop-rebound", "--stage", "1").code == 2
    assert cli("plot", "chain-ocr-m2-2006-drop-rebound", "--stage", "2").code == 0


def test_solution_with_plot(cli) -> None:
    plain = cli("solve", "notes-4c11-two-spheres").out
    with_plot = cli("solve", "notes-4c11-two-spheres", "--plot").out
    assert with_plot.count("<svg") == plain.count("<svg") + 1
    assert "outcome against e" in with_plot
    assert r"\begin{tikzpicture}" in cli("solve", "notes-4c11-two-spheres", "--plot", "-f", "tex").out
    assert cli("solve", "chain-ocr-m2-2006-drop-rebound", "--plot").code == 2


def test_import_derive_stays_light() -> None:
    """Neither ``import derive`` nor the plot imports a plotting library; the plot module
    loads only when asked for."""
    code = (
        "import sys, derive; assert 'derive.writers.plot' not in sys.modules; "
        "from derive.writers import plot; "
        "assert not [m for m in sys.modules if m.split('.')[0] in ('matplotlib', 'numpy')]"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


@pytest.mark.slow
def test_plot_as_pdf_and_png(cli, tmp_path: Path) -> None:
    import shutil

    if not shutil.which("latexmk") or not shutil.which("pdftoppm"):
        pytest.skip("needs TeX Live and poppler-utils")
    pdf, png = tmp_path / "p.pdf", tmp_path / "p.png"
    assert cli("plot", "notes-4c11-two-spheres", "-o", str(pdf)).code == 0
    assert pdf.read_bytes().startswith(b"%PDF")
    assert cli("plot", "notes-4c11-two-spheres", "-o", str(png)).code == 0
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_handout_with_plot(cli, tmp_path: Path) -> None:
    """--plot puts each single impact's plot after its worked solution; a chain has none."""
    out = tmp_path / "h.md"
    args = ["handout", "notes-4c11-two-spheres", "chain-ocr-m2-2006-drop-rebound", "--no-theory", "-o", str(out)]
    assert cli(*args).code == 0
    plain = out.read_text().count("<svg")
    assert cli(*args, "--plot").code == 0
    assert out.read_text().count("<svg") == plain + 1
