"""Reading work typed as students in Germany, France, Spain or Italy type it (issue #31): decimal
commas (``0,25``, LaTeX's ``0{,}25``), and the words between relations in their languages ("also",
"donc", "por lo tanto", ``\\Leftrightarrow``). A decimal comma is a point; a pair in brackets of its
own (``(3,4)``) and thousands (``20,000``) stay what they were.

Values worked by hand from each problem's givens (never from derive's output):

- byjus-4kg-ball-catches-8kg-ball: m_A = 4, m_B = 8, e = 0.5, v_A1 = 12, v_B1 = 4 (m/s). Momentum
  4(12) + 8(4) = 80 = 4 v_A2 + 8 v_B2; v_B2 - v_A2 = 0.5(12 - 4) = 4; 12 v_A2 = 48: v_A2 = 4,
  v_B2 = 8. KE before 288 + 64 = 352 J, after 32 + 256 = 288 J, lost 64 J.
- edexcel-m2-ball-rebounds-from-wall: m = 2 kg, u = 4 m/s into the wall, e = 0.4: v = -1.6 m/s;
  impulse 2(1.6 + 4) = 11.2 N s; KE 16 J before, 2.56 J after, 13.44 J lost.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.mathtext.reader import read_relations

DIRECT = "byjus-4kg-ball-catches-8kg-ball"
WALL = "edexcel-m2-ball-rebounds-from-wall"


def sides(text: str) -> list[tuple[str, ...]]:
    return [r.sides for r in read_relations(text)]


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("u = 0,250 m/s", [("u", "0.250")]),
        ("v = 2(0,25)", [("v", "2(0.25)")]),
        ("a = 1,5, b = 2,5", [("a", "1.5"), ("b", "2.5")]),
        ("v = 3,46; w = 0", [("v", "3.46"), ("w", "0")]),
        (r"$v_{A2} = -0{,}4 \cdot 4 = -1{,}6$", [("v_A2", "-0.4 * 4", "-1.6")]),
        (r"$v = 3,46\ \text{m/s}$", [("v", "3.46")]),
        # not decimals: thousands, a pair in brackets of its own, a list of three
        ("p = 20,000", [("p", "20000")]),
        ("v = (3,4)", [("v_n", "3"), ("v_t", "4")]),
        ("x = 1,2,3", [("x", "1,2,3")]),
    ],
)
def test_a_decimal_comma_is_a_point(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("text", "expected"),
    [
        ("Impulserhaltung: 4*12 + 8*4 = 80, also v_A2 = 4", [("4*12 + 8*4", "80"), ("v_A2", "4")]),
        ("v_B2 - v_A2 = 4 daher v_B2 = 8", [("v_B2 - v_A2", "4"), ("v_B2", "8")]),
        ("donc v_A2 = 4 m/s et v_B2 = 8 m/s", [("v_A2", "4"), ("v_B2", "8")]),
        ("12 v_A2 = 48 por lo tanto v_A2 = 4", [("12 v_A2", "48"), ("v_A2", "4")]),
        ("12 v_A2 = 48 quindi v_A2 = 4", [("12 v_A2", "48"), ("v_A2", "4")]),
        (r"$I_A = -I_B \;\Leftrightarrow\; m_A(2 - 3) = -0{,}88$", [("I_A", "-I_B"), ("m_A(2 - 3)", "-0.88")]),
        ("12 v_A2 = 48 ⇔ v_A2 = 4", [("12 v_A2", "48"), ("v_A2", "4")]),
    ],
)
def test_so_in_other_languages_parts_two_relations(text: str, expected: list) -> None:
    assert sides(text) == expected


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (DIRECT, "v_B2 - v_A2 = 0,5(12 - 4) = 4"),
        (DIRECT, r"$v_{B2} - v_{A2} = 0{,}5\,(12 - 4) = 4\ \mathrm{m/s}$"),
        (DIRECT, "e = 0,5"),
        (DIRECT, "Impulserhaltung: 4 · 12 + 8 · 4 = 4 v_A2 + 8 v_B2, also 80 = 4 v_A2 + 8 v_B2"),
        (DIRECT, "Conservation de la quantité de mouvement : 48 + 32 = 4 v_A2 + 8 v_B2, donc v_A2 = 4 m/s"),
        (DIRECT, "Energía cinética perdida = 352 - 288 = 64 J"),
        (WALL, "v_A2 = -0,4 · 4 = -1,6 m/s"),
        (WALL, r"$v = -0{,}4 \times 4 = -1{,}6\ \text{m/s}$"),
        (WALL, "KE lost = 16 - 2,56 = 13,44 J"),
    ],
)
def test_work_with_decimal_commas_is_judged_correct(problem: str, text: str) -> None:
    got = statuses(problem, text)
    assert got and all(s == "correct" for s in got), got


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (DIRECT, "v_B2 - v_A2 = 0,5(12 - 4) = 5"),
        (WALL, "v_A2 = -0,4 · 4 = -1,2 m/s"),
        (WALL, r"$\Delta E = 16 - 2{,}56 = 14{,}44\ \text{J}$"),
    ],
)
def test_a_slip_with_decimal_commas_is_wrong(problem: str, text: str) -> None:
    assert "wrong" in statuses(problem, text)


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (DIRECT, "Impulserhaltung: m_A·v_A + m_B·v_B = m_A·v_A' + m_B·v_B'"),
        (DIRECT, "Impulserhaltung: 4 · 12 + 8 · 4 = 4 · v_A' + 8 · v_B'"),
        (DIRECT, "Stoßzahl: e = (v_B' − v_A')/(v_A − v_B) = 0,5"),
        (DIRECT, "Daraus folgt: v_A' = 4 m/s und v_B' = 8 m/s."),
        (DIRECT, "Die Geschwindigkeit von A nach dem Stoß beträgt v_A' = 4 m/s."),
        (DIRECT, "Conservation de la quantité de mouvement : 4 × 12 + 8 × 4 = 4 v'_A + 8 v'_B"),
        (DIRECT, "d'où v'_A = 4 m·s⁻¹ et v'_B = 8 m·s⁻¹"),
        (DIRECT, "Conservación del momento: 4(12) + 8(4) = 4 v_A' + 8 v_B'"),
        (DIRECT, "por lo tanto v_A' = 4 m/s y v_B' = 8 m/s"),
        (DIRECT, "Energía cinética antes: E_c = ½·4·12² + ½·8·4² = 352 J"),
        (DIRECT, "Perdita di energia: ΔE = 352 − 288 = 64 J"),
        (DIRECT, "v_A' = 4,0 m/s ; v_B' = 8,0 m/s"),
        (WALL, "v' = −e · v = −0,4 · 4 m/s = −1,6 m/s"),
        (WALL, "Kraftstoß: I = m · (v' − v) = 2 kg · (−1,6 − 4) m/s = −11,2 Ns"),
        (WALL, "Energieverlust: ΔE = ½ · 2 · 4² − ½ · 2 · 1,6² = 16 − 2,56 = 13,44 J"),
        (WALL, "la vitesse après le choc est v' = 1,6 m/s (vers la gauche)"),
    ],
)
def test_a_line_typed_abroad_is_read_as_at_home(problem: str, text: str) -> None:
    """v and v' on a wall: the ball's velocity before and after (v' = -e v = -0.4(4) = -1.6)."""
    got = statuses(problem, text)
    assert got and all(s == "correct" for s in got), got


@pytest.mark.parametrize(
    ("problem", "text"),
    [
        (WALL, "v' = −e · v = −0,4 · 4 m/s = −1,2 m/s"),
        (WALL, "Kraftstoß: I = m · (v' − v) = 2 kg · (1,6 − 4) m/s = −4,8 Ns"),
        (DIRECT, "por lo tanto v_A' = 5 m/s y v_B' = 8 m/s"),
    ],
)
def test_a_slip_typed_abroad_is_wrong(problem: str, text: str) -> None:
    assert "wrong" in statuses(problem, text)


def test_points_between_thousands_where_commas_are_the_decimals() -> None:
    """mcasco-two-cars-no-bounce in a German hand: 4500 lb at 3 ft/s, 3000 lb at 6 ft/s the other
    way; 4500(3) - 3000(6) = 13500 - 18000 = -4500; V = -4500/7500 = -0.6 ft/s."""
    work = "4.500 · 3 − 3.000 · 6 = 13.500 − 18.000 = −4.500\nV = −4.500/7.500 = −0,6 ft/s"
    assert statuses("mcasco-two-cars-no-bounce", work) == ["correct", "correct"]
    assert sides("m_A = 1.200 kg, v = 0,5 m/s") == [("m_A", "1200"), ("v", "0.5")]
    assert sides("m_A = 1.200 kg, v = 0.5 m/s") == [("m_A", "1.200"), ("v", "0.5")]  # points are decimals here
    assert sides("m = 1.200 kg") == [("m", "1.200")]


@pytest.mark.parametrize(
    ("text", "verdict"),
    [
        ("E_c avant = 352 J", "correct"),  # ½·4·144 + ½·8·16
        ("E_c après = 288 J", "correct"),
        ("E_kin vorher = 352 J", "correct"),
        ("E_kin,nachher = 288 J", "correct"),
        ("Energieverlust = 64 J", "correct"),
        ("perte d'énergie = 352 − 288 = 64 J", "correct"),
        ("pérdida de energía = 64 J", "correct"),
        ("E_k before = 352 J", "correct"),
        ("E_kin nachher = 352 J", "wrong"),
        ("perte d'énergie = 60 J", "wrong"),
    ],
)
def test_kinetic_energies_named_in_other_languages(text: str, verdict: str) -> None:
    assert statuses(DIRECT, text) == [verdict]


@pytest.mark.parametrize(
    ("text", "direction"),
    [
        ("v = 1,6 m/s (zurück)", -1),
        ("v = 1.6 m/s nach links", -1),
        ("v = 1.6 m/s vers la gauche", -1),
        ("v = 1.6 m/s hacia la izquierda", -1),
        ("v = 4 m/s nach rechts", 1),
        ("v = 4 m/s à droite", 1),
        ("v = 2 leftover", 0),
    ],
)
def test_a_direction_in_words_abroad(text: str, direction: int) -> None:
    (r,) = read_relations(text)
    assert r.direction == direction and r.sides[-1] in ("1.6", "4", "2")
