"""Homework variants of chains (issue 15): each bundled chain's [vary] table draws variants
whose answers obey the physics, worked out here from the key's numbers (momentum along n
and the restitution law in each impact, energy before and after), the same for the same
seed; each variant's worked solution is ``derive solve`` of the file with its numbers
written in; its sheet gives the sign convention of every impact stage."""

from __future__ import annotations

import csv
import json
import math
import re
from decimal import Decimal
from pathlib import Path

import pytest
from support.chain_text import with_numbers

import derive
from derive.homework import variants
from derive.problem import loads
from derive.resources import bundled

ROOT = Path(__file__).resolve().parents[1]


def _chains_with_tables() -> list[str]:
    return sorted(
        name
        for name, path in bundled().items()
        if re.search(r'^kind = "chain"', path.read_text(), re.M) and "\n[vary]" in path.read_text()
    )


def test_at_least_six_chains_and_forty_problems_have_vary_tables() -> None:
    """Issue 15: >= 40 bundled problems with a [vary] table, chains among them."""
    tables = [p for p in bundled().values() if re.search(r"^\[vary\]", p.read_text(), re.M)]
    assert len(_chains_with_tables()) >= 6
    assert len(tables) >= 40


# ---------------------------------------------------------------- the physics, from the key's numbers

G_SI = 9.81


def _close(got: float, want: float, what: str) -> None:
    assert math.isclose(got, want, rel_tol=1e-9, abs_tol=1e-9), f"{what}: {got!r}, the physics gives {want!r}"


def _aqa(g: dict, r: dict) -> None:
    """A (m_A, v_A) meets B (m_B, v_B the other way); B then rebounds from a wall."""
    vA1, vB1 = g["v_A"], -g["v_B"]
    _close(g["m_A"] * vA1 + g["m_B"] * vB1, g["m_A"] * r["u_A"] + g["m_B"] * r["u_B"], "momentum along n")
    _close(g["e"] * (vA1 - vB1), r["u_B"] - r["u_A"], "restitution, A and B")
    _close(r["w_B"], -g["e_wall"] * r["u_B"], "restitution, B and the wall")
    assert r["u_A"] < 0 and r["u_A"] > r["w_B"], "the conditions: A moves back and B catches it"
    t1 = (g["m_A"] * vA1**2 + g["m_B"] * vB1**2) / 2
    assert (g["m_A"] * r["u_A"] ** 2 + g["m_B"] * r["u_B"] ** 2) / 2 <= t1 + 1e-12, "energy not gained"


def _pan(g: dict, r: dict) -> None:
    """Block falls h (½mv² = mgh), sticks to the pan (momentum, e = 0), spring k compresses
    x further from its static compression m_pan g/k: energy after the impact."""
    v1 = math.sqrt(2 * G_SI * g["h"])
    _close(r["v_1"], v1, "fall")
    M = g["m_block"] + g["m_pan"]
    _close(M * r["V"], g["m_block"] * v1, "momentum along n (plastic)")
    s0 = g["m_pan"] * G_SI / g["k"]
    x = r["x"]
    _close(g["k"] * ((s0 + x) ** 2 - s0**2) / 2, M * r["V"] ** 2 / 2 + M * G_SI * x, "energy, spring")


def _car(g: dict, r: dict) -> None:
    """Car strikes the SUV at rest, e = 0; the two skid d to rest (½MV² = μMgd, g = 9.8)."""
    M = g["m_car"] + g["m_suv"]
    _close(g["m_car"] * r["v_car"], M * r["V"], "momentum along n (plastic)")
    _close(r["V"] ** 2 / 2, g["mu_k"] * 9.8 * g["d_skid"], "work and energy, skid")


def _edexcel(g: dict, r: dict) -> None:
    """Equal masses at rest; A at v_0 strikes B, B strikes C, which moves off at v_C; one e."""
    e, uB = r["e"], r["u_B"]
    uA = g["v_0"] - uB  # momentum, equal masses
    _close(e * g["v_0"], uB - uA, "restitution, A and B")
    uB2 = uB - g["v_C"]
    _close(e * uB, g["v_C"] - uB2, "restitution, B and C")
    assert 0.2 - 1e-12 <= e <= 0.9 + 1e-12


def _hibbeler(g: dict, r: dict) -> None:
    """US units, g = 32.2 ft/s²: A falls h, strikes B at rest, B slides to rest (friction)."""
    gu = 32.2
    _close(r["v_1"], math.sqrt(2 * gu * g["h"]), "fall")
    _close(g["W_A"] * r["v_1"], g["W_A"] * r["u_A"] + g["W_B"] * r["u_B"], "momentum along n (weights)")
    _close(g["e"] * r["v_1"], r["u_B"] - r["u_A"], "restitution")
    _close(r["u_B"] ** 2 / 2, g["mu_k"] * gu * r["d_B"], "work and energy, slide")


def _msu(g: dict, r: dict) -> None:
    """Bullet lodges in the block (e = 0), the block swings up (½V² = g h)."""
    M = g["m_bullet"] + g["m_block"]
    _close(g["m_bullet"] * g["v_0"], M * r["V"], "momentum along n (plastic)")
    _close(r["T_after"], M * r["V"] ** 2 / 2, "kinetic energy after")
    _close(r["V"] ** 2 / 2, G_SI * r["h_2"], "energy, swing")


def _bounce(g: dict, r: dict, v1: float) -> None:
    """A sphere strikes the ground at v1 (n down): it leaves at e v1, the ground's impulse is
    m(1 + e) v1, and it rises to (e v1)²/2g (g = 9.8)."""
    e = r["e_floor"] if "e_floor" in r else g["e_floor"]
    _close(r["v_1"], v1, "fall")
    _close(r["u"], -e * v1, "restitution with the ground")
    _close(r["J"], g["m"] * (v1 - r["u"]), "impulse = change of momentum")
    _close(r["v_2"], -r["u"], "rebound speed")
    _close(r["v_2"] ** 2 / 2, 9.8 * r["h_2"], "energy, rise")


def _ocr2006(g: dict, r: dict) -> None:
    _bounce(g, r, math.sqrt(2 * 9.8 * g["h_0"]))
    _close(r["h_2"], g["h_r"], "rebounds to the given height")


def _ocr2007(g: dict, r: dict) -> None:
    _bounce(g, r, math.sqrt(g["v_0"] ** 2 + 2 * 9.8 * g["h_0"]))
    _close(r["h_2"], g["h_0"], "rises back to its start")


def _ocr2015(g: dict, r: dict) -> None:
    v1 = math.sqrt(g["v_0"] ** 2 + 2 * 9.8 * g["h_0"])
    _bounce(g, r, v1)
    _close(r["E_lost"], g["m"] * (v1**2 - r["v_2"] ** 2) / 2, "energy lost in the bounce")


def _ocr2011(g: dict, r: dict) -> None:
    """A (m_A unknown) and B: speeds before and after given; B then strikes a wall and gets
    the impulse I_w."""
    vA1, vB1, vA2, vB2 = g["v_A"], -g["v_B"], g["s_A"], g["s_B"]
    _close(r["m_A"] * vA1 + g["m_B"] * vB1, r["m_A"] * vA2 + g["m_B"] * vB2, "momentum along n")
    _close(r["e"] * (vA1 - vB1), vB2 - vA2, "restitution, A and B")
    _close(r["w_B"], -r["e_wall"] * vB2, "restitution, B and the wall")
    _close(g["I_w"], g["m_B"] * (vB2 - r["w_B"]), "impulse of the wall = change of momentum")
    assert r["m_A"] > 0 and 0.1 - 1e-12 <= r["e"] <= 1 and 0.1 - 1e-12 <= r["e_wall"] <= 1


PHYSICS = {
    "chain-aqa-m3-2007-collide-again": _aqa,
    "chain-block-onto-spring-pan": _pan,
    "chain-car-rear-ends-suv-skid": _car,
    "chain-edexcel-m2-three-particles": _edexcel,
    "chain-hibbeler-15-58-suitcases": _hibbeler,
    "chain-msu-bullet-block-swings": _msu,
    "chain-ocr-m2-2006-drop-rebound": _ocr2006,
    "chain-ocr-m2-2007-rebounds-to-start": _ocr2007,
    "chain-ocr-m2-2011-find-e-mass-then-wall": _ocr2011,
    "chain-ocr-m2-2015-thrown-down-bounce": _ocr2015,
}


@pytest.mark.slow
@pytest.mark.parametrize("name", _chains_with_tables())
def test_each_chain_table_gives_a_class_of_forty_distinct_variants(name: str) -> None:
    """As for the single-impact tables (tests/test_variants.py): 40 students, 40 variants."""
    compiled = variants.compile_problem(derive.load(name))
    chosen = variants.draw(compiled, 40, seed=1)
    assert len({tuple(sorted(v.values.items())) for v in chosen}) == 40


def test_every_chain_table_has_its_physics_here() -> None:
    assert set(_chains_with_tables()) <= set(PHYSICS)


def _fixed(name: str) -> dict[str, float]:
    """The file's givens that do not vary (plain numbers in the key's units), for the physics."""
    sol = derive.solve(derive.load(name))
    return {g.name: float(g.value) for g in sol.problem.givens if g.value is not None}


@pytest.mark.parametrize("name", sorted(PHYSICS))
def test_chain_variants_obey_the_physics(name: str, cli, tmp_path: Path) -> None:
    """N variants of each bundled chain table: distinct, every answer as the physics gives it
    from the variant's own numbers."""
    count = 6
    r = cli("variants", name, "--count", str(count), "--seed", "3", "-o", str(tmp_path / "hw"))
    assert r.code == 0, r.err
    key = json.loads((tmp_path / "hw" / "key.json").read_text(encoding="utf-8"))
    rows = key["variants"]
    assert len(rows) == count
    assert len({json.dumps(row["givens"], sort_keys=True) for row in rows}) == count
    fixed = _fixed(name)
    for row in rows:
        givens = {**fixed, **{n: g["value"] for n, g in row["givens"].items()}}
        results = {n: x["value"] for n, x in row["results"].items()}
        PHYSICS[name](givens, results)


# ---------------------------------------------------------------- reproducible, and derive solve's pages


def _files(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def test_the_same_seed_gives_the_same_files(cli, tmp_path: Path) -> None:
    name = "chain-aqa-m3-2007-collide-again"
    for out, seed in (("a", "5"), ("b", "5"), ("c", "6")):
        assert cli("variants", name, "-n", "4", "--seed", seed, "-o", str(tmp_path / out)).code == 0
    a, b, c = (_files(tmp_path / x) for x in "abc")
    assert a == b
    assert a["key.csv"] != c["key.csv"]


def _rewritten(name: str, row: dict) -> str:
    text = bundled()[name].read_text(encoding="utf-8")
    givens = {n: (Decimal(repr(g["value"])), g["unit"]) for n, g in row["givens"].items()}
    return with_numbers(text, givens)


@pytest.mark.parametrize(
    "name",
    ["chain-aqa-m3-2007-collide-again", "chain-block-onto-spring-pan", "chain-ocr-m2-2011-find-e-mass-then-wall"],
)
@pytest.mark.parametrize("fmt", ["md", "tex", "html"])
def test_a_variant_is_derive_solve_of_the_file_with_its_numbers(name: str, fmt: str, cli, tmp_path: Path) -> None:
    """Each variant's worked solution is, byte for byte, what ``derive solve`` writes for the
    chain file with the variant's numbers typed into its [given] table."""
    out = tmp_path / "hw"
    assert cli("variants", name, "-n", "2", "--seed", "4", "-f", fmt, "-o", str(out)).code == 0
    rows = json.loads((out / "key.json").read_text(encoding="utf-8"))["variants"]
    for row in rows:
        path = tmp_path / f"{name}-{row['variant']}.toml"
        path.write_text(_rewritten(name, row), encoding="utf-8")
        page = tmp_path / f"solved-{row['variant']}.{fmt}"
        assert cli("solve", str(path), "-f", fmt, "-o", str(page)).code == 0
        mine = (out / f"variant-{row['variant']:02d}.{fmt}").read_text(encoding="utf-8")
        assert mine == page.read_text(encoding="utf-8")


def test_a_variant_statement_reads_with_its_numbers() -> None:
    """{name} placeholders: the statement gives the variant's numbers as the file typed them
    (0.020 kg has three places: 0.015 kg; 4.0 kg has one: 2.0 kg)."""
    compiled = variants.compile_problem(derive.load("chain-msu-bullet-block-swings"))
    for v in variants.draw(compiled, 5, seed=1):
        page = variants.fill(compiled, v)
        said = page.split("**Given.**")[1].split("\n")[0]
        bullet = f"{Decimal(str(float(v.values['m_bullet']))):.3f}"
        block = f"{float(v.values['m_block']):.1f}"
        speed = int(v.values["v_0"])
        assert f"A {bullet} kg bullet moving at {speed} m/s lodges in a {block} kg block" in said, said


@pytest.mark.parametrize("name", sorted(PHYSICS))
def test_every_varied_given_of_a_chain_is_a_placeholder_of_its_statement(name: str) -> None:
    """A varied number the statement typed would contradict the variant's Given list."""
    problem = derive.load(name)
    said = (problem.statement or "") + (problem.question or "")
    for n in problem.vary:
        assert "{" + n + "}" in said or "{|" + n + "|}" in said, n


# ---------------------------------------------------------------- sheets: every impact's sign convention

WALL = "positive from B toward the wall"
SPHERES = "positive from the centre of A toward the centre of B"


@pytest.mark.parametrize("fmt", ["md", "tex", "html"])
def test_a_chain_sheet_gives_the_sign_convention_of_each_impact(fmt: str, cli, tmp_path: Path) -> None:
    """AQA 2007: A meets B (n from A to B), then B strikes the wall (n from B to the wall):
    the student's sheet says both, after each impact's title."""
    out = tmp_path / "hw"
    assert cli("variants", "chain-aqa-m3-2007-collide-again", "-n", "1", "-f", fmt, "-o", str(out)).code == 0
    sheet = (out / f"variant-01-problem.{fmt}").read_text(encoding="utf-8")
    words = re.sub(r"<[^>]+>|\$", "", sheet)
    assert "A and B collide: take" in words and "B strikes the wall: take" in words
    assert words.index(SPHERES) < words.index(WALL)


def test_a_chain_handout_sheet_and_the_lms_text_give_each_impact_convention(tmp_path: Path) -> None:
    from derive.homework.handout import build_handout
    from derive.homework.lms import moodle_xml

    doc, _ = build_handout(["chain-ocr-m2-2011-find-e-mass-then-wall"], title="S", theory=False, mode="problems")
    assert SPHERES in doc and WALL in doc
    compiled = variants.compile_problem(derive.load("chain-ocr-m2-2011-find-e-mass-then-wall"))
    xml = moodle_xml(compiled, variants.draw(compiled, 1, seed=1), result="e_wall")
    question = xml.split("<questiontext")[1].split("</questiontext>")[0]  # not the worked solution
    assert SPHERES in question and WALL in question


# ---------------------------------------------------------------- the key: each quantity once


def _header(folder: Path) -> list[str]:
    with open(folder / "key.csv", encoding="utf-8") as fh:
        return [cell.split(" [")[0] for cell in next(csv.reader(fh))]


@pytest.mark.parametrize("name", ["young-freedman-8-96-pucks-find-mass", "chain-ocr-m2-2011-find-e-mass-then-wall"])
def test_the_key_has_each_quantity_once(name: str, cli, tmp_path: Path) -> None:
    """Issue 15: young-freedman's key.csv listed v_A2 twice (a varied given, and a result).
    A given of the file is no result; the key's JSON has it among the givens only."""
    out = tmp_path / "yf"
    assert cli("variants", name, "-n", "3", "-o", str(out)).code == 0
    header = _header(out)
    assert len(header) == len(set(header)), header
    problem = derive.load(name)
    known = {g.name for g in problem.givens if not g.unknown}
    for row in json.loads((out / "key.json").read_text(encoding="utf-8"))["variants"]:
        assert not set(row["results"]) & known
        assert set(row["givens"]) == set(problem.vary)
    if name.startswith("young"):
        assert header.count("v_A2") == 1 and "m_B" in header and "v_B2" in header


def test_a_chain_key_says_whether_they_collide_again(cli, tmp_path: Path) -> None:
    out = tmp_path / "hw"
    assert cli("variants", "chain-aqa-m3-2007-collide-again", "-n", "3", "-o", str(out)).code == 0
    rows = json.loads((out / "key.json").read_text(encoding="utf-8"))["variants"]
    assert {row["results"]["again"]["shown"] for row in rows} == {"yes"}  # the conditions: as in the paper


# ---------------------------------------------------------------- bad tables


def _aqa_with(extra: str, vary: str | None = None) -> str:
    text = bundled()["chain-aqa-m3-2007-collide-again"].read_text(encoding="utf-8")
    if vary is not None:
        text = text[: text.index("\n[vary]")] + "\n[vary]\n" + vary
    return text.replace("\n[given]\n", f"\n{extra}\n[given]\n", 1) if extra else text


def test_a_chain_condition_naming_nothing_is_a_clear_error() -> None:
    text = _aqa_with("").replace('conditions = ["u_A < -0.1", "u_A > w_B"]', 'conditions = ["u_Q > 0"]')
    with pytest.raises(derive.InputError, match="conditions"):
        loads(text, path="bad.toml")


def test_a_chain_whose_draws_never_solve_says_why() -> None:
    """Every draw has B moving away from the wall: the wall's impact has no approach."""
    text = _aqa_with("", vary='m_B = { choices = ["2 kg", "3 kg"] }\nv_A = { choices = ["1 m/s"] }\n')
    compiled = variants.compile_problem(loads(text, path="far.toml"))
    with pytest.raises(derive.InputError, match="approach"):
        variants.draw(compiled, 2, seed=1)


def test_a_vary_value_that_is_no_decimal_in_the_typed_unit_is_refused() -> None:
    """A range value its min's unit cannot hold as a decimal (3 m/s + 1 km/h is 59/18 m/s) is a
    one-line error naming it; a choice is written as typed (10 km/h, not 2.78 m/s)."""
    text = _aqa_with("", vary='v_A = { min = "3 m/s", max = "4 m/s", step = "1 km/h" }\n')
    with pytest.raises(derive.InputError, match=r"\[vary\] v_A: 3\.2777+8? m/s is no decimal number in m/s"):
        variants.compile_problem(loads(text, path="third.toml"))
    text = _aqa_with("", vary='v_A = { choices = ["3 m/s", "10 km/h"] }\n')
    compiled = variants.compile_problem(loads(text, path="third.toml"))
    assert sorted(compiled.written["v_A"].values()) == ["10 km/h", "3 m/s"]
