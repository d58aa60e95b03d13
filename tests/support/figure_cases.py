"""Generated impacts for the figure tests: a reproducible generator of problem files.

Each case is a problem file (random masses, radii, speeds, angles from 0 to 90°,
walls and floors, now and then a line of impact at an angle to x) and its outcome,
worked here from the notes' equations (1)-(4) in floats: the figure needs only the
numbers, and solving 500 problems with SymPy would take minutes.
"""

from __future__ import annotations

import random
from dataclasses import dataclass

import sympy

from derive.physics.results import Result
from derive.problem import Problem, loads
from derive.steps.model import Solution
from derive.symbols import symbol

SURFACES = ("wall", "floor", "ground", "cushion", "barrier")


@dataclass(frozen=True)
class Case:
    text: str
    kind: str
    fixed: bool
    m_A: float
    m_B: float
    e: float
    A1: tuple[float, float]  # (n, t) components before the impact
    B1: tuple[float, float]


def _angle(rng: random.Random, body: str) -> tuple[str, tuple[float, float], float]:
    """[A]/[B] lines and the unit (n, t) direction: A moves toward +n, B toward -n."""
    import math

    sign_n = 1 if body == "A" else -1
    side = rng.choice(("+t", "-t"))
    s_t = 1 if side == "+t" else -1
    if rng.random() < 0.6:  # measured from the line of impact
        deg = rng.randint(0, 89 if body == "A" else 90)
        axis = "+n" if body == "A" else "-n"
        d = (sign_n * math.cos(math.radians(deg)), s_t * math.sin(math.radians(deg)))
        return f'angle = "{deg} deg"\nfrom = "{axis}"\ntoward = "{side}"\n', d, deg
    deg = rng.randint(1 if body == "A" else 0, 90)
    toward = "+n" if body == "A" else "-n"
    d = (sign_n * math.sin(math.radians(deg)), s_t * math.cos(math.radians(deg)))
    return f'angle = "{deg} deg"\nfrom = "{side}"\ntoward = "{toward}"\n', d, deg


def case(seed: int) -> Case:
    """One generated problem (the same seed, the same problem)."""
    rng = random.Random(seed)
    kind = "oblique" if rng.random() < 0.6 else "direct"
    fixed = rng.random() < 0.25
    m_A, m_B = round(rng.uniform(0.05, 50), 2), round(rng.uniform(0.05, 50), 2)
    e = round(rng.random(), 2)
    v_A = round(rng.uniform(0.5, 30), 1)
    v_B = 0.0 if fixed or rng.random() < 0.25 else round(rng.uniform(0.5, 30), 1)
    lines = [f'title = "generated {seed}"', f'kind = "{kind}"', "[given]", f'm_A = "{m_A} kg"', f"e = {e}"]
    if rng.random() < 0.7:
        lines += [f'r_A = "{rng.randint(10, 200)} mm"', f'r_B = "{rng.randint(10, 200)} mm"']
    tables = ""
    if kind == "direct":
        if v_B:  # toward A, or ahead of A and slower
            v_B = -v_B if rng.random() < 0.6 else min(v_B, round(v_A / 2, 1))
        A1, B1 = (v_A, 0.0), (v_B, 0.0)
        lines.append(f'v_A1 = "{v_A} m/s"')
        if not fixed:
            lines += [f'm_B = "{m_B} kg"', f'v_B1 = "{v_B} m/s"']
    else:
        text_A, dA, _ = _angle(rng, "A")
        A1 = (v_A * dA[0], v_A * dA[1])
        lines.append(f'v_A1 = "{v_A} m/s"')
        tables += "[A]\n" + text_A
        B1 = (0.0, 0.0)
        if not fixed:
            lines += [f'm_B = "{m_B} kg"', f'v_B1 = "{v_B} m/s"']
            if v_B:
                text_B, dB, _ = _angle(rng, "B")
                B1 = (v_B * dB[0], v_B * dB[1])
                tables += "[B]\n" + text_B
        if not fixed and rng.random() < 0.25:
            tables = f'[geometry]\nn_angle = "{rng.randint(0, 90)} deg"\n' + tables
    if fixed:
        tables += f'[B]\nfixed = true\nname = "{rng.choice(SURFACES)}"\n'
    text = "\n".join(lines) + "\n" + tables
    return Case(text, kind, fixed, m_A, m_B, e, A1, B1)


def outcome(c: Case) -> dict[str, float]:
    """Velocities after the impact from (1)-(4): t unchanged, momentum and restitution along n."""
    (a_n, a_t), (b_n, b_t) = c.A1, c.B1
    if c.fixed:
        out = {"A2n": -c.e * a_n, "A2t": a_t}
    else:
        v_A2n = (c.m_A * a_n + c.m_B * b_n - c.m_B * c.e * (a_n - b_n)) / (c.m_A + c.m_B)
        out = {"A2n": v_A2n, "A2t": a_t, "B2n": v_A2n + c.e * (a_n - b_n), "B2t": b_t}
    return out


def solution(c: Case) -> Solution:
    """The case as a Solution carrying only what a figure reads: the problem and the velocities."""
    problem = loads(c.text, path="generated.toml")
    assert isinstance(problem, Problem)
    results = {}
    for key, value in outcome(c).items():
        name = f"v_{key}" if c.kind == "oblique" else f"v_{key[:2]}"
        if c.kind == "direct" and key.endswith("t"):
            continue
        v = sympy.Float(value)
        results[name] = Result(name, symbol(name), v, v, v, "m/s", "generated")
    return Solution(problem, results, (), dict(problem.numeric()))


CASES = 500
