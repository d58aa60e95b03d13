"""Generated physical problems for the verifier's corpus (tests/test_every_line.py).

Reproducible: the same seed gives the same problems, as TOML text, anywhere.
Every problem is physical by construction (the bodies approach, e lies in
[0, 1], an inverse problem's measured velocities come from a forward solution),
and the mix is the one issue #12 asks for: direct and oblique impacts, walls
and floors, symbolic givens, inverse problems ("?" unknowns) and chains; equal
masses other than 1 kg, tiny and huge magnitudes, angles near 0° and 90°.
"""

from __future__ import annotations

import random
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from fractions import Fraction

SEED = 12


@dataclass(frozen=True)
class Case:
    """One generated problem: a name that says what it is, and its TOML text."""

    name: str
    kind: str
    text: str


def _num(x: float | Fraction, figs: int = 3) -> str:
    """A number as a textbook writes a datum: a few significant figures, no float noise."""
    v = float(x)
    if v == 0:
        return "0"
    text = f"{v:.{figs}g}"
    if "e" in text:
        mant, exp = text.split("e")
        return f"{mant}e{int(exp)}"
    return text


class _Draw:
    """Random choices with the textbook's taste: round numbers, now and then extremes."""

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng

    def mass(self, scale: str = "normal") -> str:
        r = self.rng
        if scale == "tiny":
            return r.choice(["1.67e-27 kg", "9.11e-30 kg", "6.64e-27 kg", "3.35e-26 kg"])
        if scale == "huge":
            return r.choice(["5.97e24 kg", "7.35e22 kg", "2.5e5 kg", "1.2e6 kg"])
        if r.random() < 0.2:
            return f"{r.choice([50, 100, 150, 250, 500, 750])} g"
        return f"{_num(r.choice([0.2, 0.5, 1, 1.5, 2, 2.5, 3, 4, 5, 8, 10, 12, 20, 35]) * r.choice([1, 1, 1.2]))} kg"

    def e(self) -> str:
        r = self.rng
        return str(r.choice([0, 0.1, 0.25, 0.3, 0.4, 0.5, 0.6, 0.65, 0.7, 0.75, 0.8, 0.9, 0.95, 1]))

    def speed(self, scale: str = "normal", unit: str = "m/s") -> float:
        r = self.rng
        if scale == "tiny":
            return r.choice([2e6, 3.5e5, 1.2e7])
        if scale == "huge":
            return r.choice([1.2e3, 3.0e4, 7.5e3])
        return r.choice([0.5, 1, 1.5, 2, 2.5, 3, 4, 5, 6, 7.5, 8, 10, 12, 15, 20, 25]) * r.choice([1, 1, 1.1])

    def angle(self) -> float:
        r = self.rng
        if r.random() < 0.25:
            return r.choice([0.5, 1, 2, 88, 89, 89.5])
        return r.choice([10, 15, 20, 25, 30, 36.9, 37.6, 40, 45, 50, 53.1, 60, 70, 75, 80])


def _direct(d: _Draw, i: int) -> Case:
    r = d.rng
    scale = r.choice(["normal"] * 8 + ["tiny", "huge"])
    m_a = d.mass(scale)
    m_b = m_a if r.random() < 0.25 else d.mass(scale)
    va = d.speed(scale)
    vb = r.choice([0, 0, -d.speed(scale), va * r.choice([0.2, 0.5])])
    unit = r.choice(["m/s"] * 5 + ["km/h"]) if scale == "normal" else "m/s"
    text = f"""title = "generated direct impact {i}"
kind = "direct"
[given]
m_A = "{m_a}"
m_B = "{m_b}"
e = {d.e()}
v_A1 = "{_num(va)} {unit}"
v_B1 = "{_num(vb)} {unit}"
"""
    return Case(f"direct-{i:04d}", "direct", text)


def _us(d: _Draw, i: int) -> Case:
    r = d.rng
    w_a = r.choice([2, 5, 10, 15, 47, 100, 3000, 4500])
    w_b = w_a if r.random() < 0.3 else r.choice([1, 4, 8, 20, 47, 150, 2000])
    va, vb = d.speed(), r.choice([0, -d.speed()])
    unit = r.choice(["ft/s", "ft/s", "mi/h"])
    text = f"""title = "generated US impact {i}"
kind = "direct"
units = "US"
[given]
W_A = "{w_a} lb"
W_B = "{w_b} lb"
e = {d.e()}
v_A1 = "{_num(va)} {unit}"
v_B1 = "{_num(vb)} {unit}"
"""
    return Case(f"us-{i:04d}", "direct", text)


def _oblique(d: _Draw, i: int) -> Case:
    r = d.rng
    m_a = d.mass()
    m_b = m_a if r.random() < 0.3 else d.mass()
    va, ta = d.speed(), d.angle()
    a_toward = r.choice(["+t", "-t"])
    b = r.choice(["rest", "angle", "components"])
    lines = [f'm_A = "{m_a}"', f'm_B = "{m_b}"', f"e = {d.e()}", f'v_A1 = "{_num(va)} m/s"', f'theta_A = "{ta} deg"']
    tables = f'[A]\nangle = "theta_A"\nfrom = "+n"\ntoward = "{a_toward}"\n'
    if b == "rest":
        lines.append("v_B1 = 0")
    elif b == "angle":
        lines += [f'v_B1 = "{_num(d.speed())} m/s"', f'theta_B = "{d.angle()} deg"']
        tables += f'[B]\nangle = "theta_B"\nfrom = "-n"\ntoward = "{r.choice(["+t", "-t"])}"\n'
    else:
        lines += [f'v_B1n = "{_num(-d.speed() * 0.5)} m/s"', f'v_B1t = "{_num(d.speed() * r.choice([1, -1]))} m/s"']
    body = "\n".join(lines)
    text = f'title = "generated oblique impact {i}"\nkind = "oblique"\n[given]\n{body}\n{tables}'
    return Case(f"oblique-{i:04d}", "oblique", text)


def _geometry(d: _Draw, i: int) -> Case:
    r = d.rng
    phi = r.choice([0, 10, 20, 30, 45, 60])
    ta = phi + r.choice([-40, -20, 0, 15, 30])
    text = f"""title = "generated x-y impact {i}"
kind = "oblique"
[given]
m_A = "{d.mass()}"
m_B = "{d.mass()}"
e = {d.e()}
v_A1 = "{_num(d.speed())} m/s"
v_B1 = 0
[geometry]
n_angle = "{phi} deg"
[A]
angle = "{ta} deg"
from = "+x"
toward = "+y"
"""
    return Case(f"geometry-{i:04d}", "oblique", text)


def _wall(d: _Draw, i: int) -> Case:
    r = d.rng
    name = r.choice(["wall", "floor", "cushion"])
    if r.random() < 0.5:
        text = f"""title = "generated {name} impact {i}"
kind = "direct"
[given]
m_A = "{d.mass()}"
e = {d.e()}
v_A1 = "{_num(d.speed())} m/s"
[B]
fixed = true
name = "{name}"
"""
    else:
        text = f"""title = "generated oblique {name} impact {i}"
kind = "oblique"
[given]
m_A = "{d.mass()}"
e = {d.e()}
v_A1 = "{_num(d.speed())} m/s"
theta = "{d.angle()} deg"
[A]
angle = "theta"
from = "+n"
toward = "{r.choice(["+t", "-t"])}"
[B]
fixed = true
name = "{name}"
"""
    return Case(f"wall-{i:04d}", "wall", text)


def _symbolic(d: _Draw, i: int) -> Case:
    r = d.rng
    k = r.choice([1, 2, 3])
    form = r.choice(["mass", "speed", "both"])
    mass = '"kg"' if form != "speed" else f'"{d.mass()}"'
    speed = '"m/s"' if form != "mass" else f'"{_num(d.speed())} m/s"'
    text = f"""title = "generated symbolic impact {i}"
kind = "{r.choice(["direct", "oblique"])}"
[given]
m = {mass}
m_A = "{k}*m"
m_B = "m"
e = {d.e()}
v_A1 = {speed}
v_B1 = 0
theta = "{d.angle()} deg"
[A]
angle = "theta"
from = "+n"
toward = "+t"
"""
    if '"direct"' in text:
        text = text.split("theta =")[0]
    return Case(f"symbolic-{i:04d}", "symbolic", text)


def _inverse(d: _Draw, i: int) -> Case:
    """An inverse problem whose measured velocity comes from a forward solution (so it is physical)."""
    r = d.rng
    m_a, m_b = Fraction(r.choice([1, 2, 3, 4, 5, 6])), Fraction(r.choice([1, 2, 3, 5, 8]))
    e = Fraction(r.choice([0, 1, 2, 3, 4, 5, 6, 8, 10]), 10)
    va, vb = Fraction(r.choice([2, 3, 4, 5, 6, 8])), Fraction(r.choice([0, 0, -1, -2]))
    va2 = (m_a * va + m_b * vb - m_b * e * (va - vb)) / (m_a + m_b)
    vb2 = va2 + e * (va - vb)
    unknown = r.choice(["e", "m_B", "m_A", "v_A1"])
    if unknown == "e" and e == 1:
        e = Fraction(9, 10)
        va2 = (m_a * va + m_b * vb - m_b * e * (va - vb)) / (m_a + m_b)
        vb2 = va2 + e * (va - vb)
    given = {"m_A": f'"{m_a} kg"', "m_B": f'"{m_b} kg"', "e": str(float(e)), "v_A1": f'"{va} m/s"'}
    given[unknown] = '"? kg"' if unknown.startswith("m_") else ('"? m/s"' if unknown == "v_A1" else '"?"')
    shown = va2 if unknown != "v_A1" else vb2
    measured = "v_A2" if unknown != "v_A1" else "v_B2"
    body = "\n".join(f"{k} = {v}" for k, v in given.items())
    text = f"""title = "generated inverse impact {i}"
kind = "direct"
[given]
{body}
v_B1 = "{_num(vb)} m/s"
{measured} = "{_num(shown, 6)} m/s"
"""
    return Case(f"inverse-{i:04d}", "inverse", text)


def _chain(d: _Draw, i: int) -> Case:
    r = d.rng
    return r.choice(_CHAINS)(d, i)


def _chain_drop(d: _Draw, i: int) -> Case:
    r = d.rng
    unknown = r.random() < 0.4
    e = '"?"' if unknown else d.e()
    solve = f'\n[[stage]]\ntype = "solve"\ncondition = "h_2 = {_num(r.choice([0.4, 0.8, 1.0]))} m"\nfor = "e_f"\n'
    text = f"""title = "generated chain: drop and rebound {i}"
kind = "chain"
[given]
m = "{d.mass()}"
h_0 = "{_num(r.choice([1.5, 2, 3, 5]))} m"
e_f = {e}
[[stage]]
type = "fall"
height = "h_0"
result = "v_1"
[[stage]]
type = "impact"
kind = "direct"
given = {{ m_A = "m", e = "e_f", v_A1 = "v_1" }}
B = {{ fixed = true, name = "floor" }}
results = {{ v_A2 = "u" }}
[[stage]]
type = "define"
expr = "-u"
result = "v_2"
[[stage]]
type = "rise"
speed = "v_2"
result = "h_2"
""" + (solve if unknown else "")
    return Case(f"chain-drop-{i:04d}", "chain", text)


def _chain_three(d: _Draw, i: int) -> Case:
    r = d.rng
    m = d.mass()
    text = f"""title = "generated chain: three particles {i}"
kind = "chain"
[given]
m = "{m}"
e = {d.e()}
[[stage]]
type = "impact"
kind = "direct"
given = {{ m_A = "m", m_B = "m", e = "e", v_A1 = "{_num(d.speed())} m/s", v_B1 = "0 m/s" }}
results = {{ v_B2 = "u_B" }}
[[stage]]
type = "impact"
kind = "direct"
given = {{ m_A = "m", m_B = "{r.choice(["m", "2*m"])}", e = "e", v_A1 = "u_B", v_B1 = "0 m/s" }}
results = {{ v_B2 = "u_C" }}
"""
    return Case(f"chain-three-{i:04d}", "chain", text)


def _chain_slide(d: _Draw, i: int) -> Case:
    text = f"""title = "generated chain: collide and slide {i}"
kind = "chain"
[given]
m_A = "{d.mass()}"
m_B = "{d.mass()}"
mu = {d.rng.choice([0.2, 0.3, 0.5, 0.8])}
[[stage]]
type = "impact"
kind = "direct"
given = {{ e = 0, v_A1 = "{_num(d.speed())} m/s", v_B1 = "0 m/s" }}
results = {{ v_A2 = "V" }}
[[stage]]
type = "slide"
speed = "V"
mu = "mu"
result = "d"
"""
    return Case(f"chain-slide-{i:04d}", "chain", text)


def _chain_spring(d: _Draw, i: int) -> Case:
    r = d.rng
    text = f"""title = "generated chain: block onto a spring {i}"
kind = "chain"
[given]
m_1 = "{_num(r.choice([1, 2, 5, 10, 30]))} kg"
m_2 = "{_num(r.choice([1, 2, 5, 10]))} kg"
h = "{_num(r.choice([0.5, 1, 2]))} m"
k = "{r.choice([2, 5, 20])} kN/m"
[[stage]]
type = "fall"
height = "h"
result = "v_1"
[[stage]]
type = "impact"
kind = "direct"
given = {{ m_A = "m_1", m_B = "m_2", e = 0, v_A1 = "v_1", v_B1 = "0 m/s" }}
results = {{ v_A2 = "V" }}
[[stage]]
type = "spring"
speed = "V"
mass = "m_1 + m_2"
k = "k"
vertical = true
static = "m_2*g/k"
result = "x"
"""
    return Case(f"chain-spring-{i:04d}", "chain", text)


def _chain_again(d: _Draw, i: int) -> Case:
    text = f"""title = "generated chain: collide, wall, again? {i}"
kind = "chain"
[given]
m_A = "{d.mass()}"
m_B = "{d.mass()}"
e = {d.e()}
e_w = {d.e()}
[[stage]]
type = "impact"
kind = "direct"
given = {{ v_A1 = "{_num(d.speed())} m/s", v_B1 = "0 m/s" }}
results = {{ v_A2 = "u_A", v_B2 = "u_B" }}
[[stage]]
type = "impact"
kind = "direct"
given = {{ m_A = "m_B", e = "e_w", v_A1 = "u_B" }}
B = {{ fixed = true, name = "wall" }}
results = {{ v_A2 = "w_B" }}
[[stage]]
type = "again"
behind = "u_A"
ahead = "w_B"
"""
    return Case(f"chain-again-{i:04d}", "chain", text)


def _chain_bounces(d: _Draw, i: int) -> Case:
    text = f"""title = "generated chain: bounces {i}"
kind = "chain"
[given]
h_0 = "{_num(d.rng.choice([1, 2, 2.5, 4]))} m"
e_b = {d.rng.choice([0.5, 0.6, 0.8, 0.9])}
[[stage]]
type = "bounces"
height = "h_0"
e = "e_b"
count = {d.rng.choice([2, 3])}
"""
    return Case(f"chain-bounces-{i:04d}", "chain", text)


_CHAINS: list[Callable[[_Draw, int], Case]] = [
    _chain_drop,
    _chain_three,
    _chain_slide,
    _chain_spring,
    _chain_again,
    _chain_bounces,
]
#: (generator, weight): the mix of the corpus.
MIX: list[tuple[Callable[[_Draw, int], Case], int]] = [
    (_direct, 22),
    (_us, 6),
    (_oblique, 20),
    (_geometry, 5),
    (_wall, 13),
    (_symbolic, 10),
    (_inverse, 12),
    (_chain, 12),
]


def cases(count: int, seed: int = SEED) -> Iterator[Case]:
    """``count`` generated problems, the same for the same seed."""
    rng = random.Random(seed)
    draw = _Draw(rng)
    makers = [m for m, w in MIX for _ in range(w)]
    for i in range(count):
        yield rng.choice(makers)(draw, i)


#: Problems with a [vary] table, for homework variants drawn 200 at a time: equal
#: masses come up (m_A and m_B from the same range), e = 0 and e = 1, a wall, angles near 0° and 90°.
VARY = (
    Case(
        "vary-direct",
        "vary",
        """title = "generated homework: two carts"
kind = "direct"
[given]
m_A = "2 kg"
m_B = "3 kg"
e = 0.5
v_A1 = "4 m/s"
v_B1 = "-1 m/s"
[vary]
m_A = { min = "0.5 kg", max = "6 kg", step = "0.5 kg" }
m_B = { min = "0.5 kg", max = "6 kg", step = "0.5 kg" }
e = { choices = [0, 0.25, 0.5, 0.8, 1] }
v_A1 = { min = "1 m/s", max = "9 m/s", step = "0.5 m/s" }
""",
    ),
    Case(
        "vary-wall",
        "vary",
        """title = "generated homework: a ball against a wall"
kind = "oblique"
[given]
m_A = "0.2 kg"
e = 0.7
v_A1 = "10 m/s"
theta = "30 deg"
[vary]
m_A = { min = "0.1 kg", max = "2 kg", step = "0.1 kg" }
e = { choices = [0.3, 0.6, 0.9, 1] }
theta = { choices = ["1 deg", "15 deg", "30 deg", "45 deg", "60 deg", "89 deg"] }
v_A1 = { min = "2 m/s", max = "30 m/s", step = "2 m/s" }
[A]
angle = "theta"
from = "+n"
toward = "+t"
[B]
fixed = true
name = "wall"
""",
    ),
)
