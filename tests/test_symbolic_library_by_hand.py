"""The symbolic library's published results follow from the notes' equations (1)-(4), without derive.

For every problem of ``tests/support/symbolic_published.py`` this module writes the impact out
again from the mark scheme's data in derive's conventions (n from A's centre toward B's;
a wall is B, fixed), solves

    (1) v_A2t = v_A1t            (2) v_B2t = v_B1t
    (3) m_A v_A1n + m_B v_B1n = m_A v_A2n + m_B v_B2n
    (4) e (v_A1n - v_B1n) = v_B2n - v_A2n

(with a wall: (1) and (4) with v_B = 0) with SymPy, plus any condition the question sets,
and checks each printed result against it. It is an independent check that the mark
scheme's answer follows from the notes with our sign conventions; it imports nothing of
derive, so it runs before the new problem-file syntax (issue #14) is implemented.

It also checks that each problem file's ``answers`` and ``show`` strings are the ones in
``tests/support/symbolic_published.py`` (the file is read with ``tomllib`` only).
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Callable
from dataclasses import dataclass, field
from functools import cache
from pathlib import Path

import pytest
import sympy
from support.symbolic_published import (
    DEGREES,
    EXPR,
    PUBLISHED,
    RANGE,
    SHOWN,
    TAN,
    Row,
    same_angle,
    same_degrees,
    values_of_e,
)
from sympy.parsing.sympy_parser import parse_expr

PROBLEMS = Path(__file__).resolve().parents[1] / "problems"

# Letters are positive (the problems' default); e is also at most 1, angles are acute.
m, u, U, v, k, lam, e, e_1 = sympy.symbols("m u U v k lam e e_1", positive=True)
alpha, theta = sympy.symbols("alpha theta", positive=True)
#: e where the question leaves it to find: any real root, so that the inadmissible ones show.
E = sympy.Symbol("e", real=True)
LETTERS = {s.name: s for s in (m, u, U, v, k, lam, e, e_1, alpha, theta)}

A1n, A1t, B1n, B1t = sympy.symbols("v_A1n v_A1t v_B1n v_B1t", real=True)
A2n, A2t, B2n, B2t = sympy.symbols("v_A2n v_A2t v_B2n v_B2t", real=True)

Results = dict[str, sympy.Expr]


@dataclass
class Case:
    """One impact written out from the mark scheme's data.

    ``before`` and ``after`` give velocity components (n, t) that are known; every other
    component is unknown. ``unknowns`` are givens the question leaves to find, fixed by
    ``conditions`` (expressions in the results equal to zero); ``keep`` chooses the
    admissible root. ``defines`` and ``ranges`` build the problem's ``[define]`` entries.
    """

    m_A: sympy.Expr
    m_B: sympy.Expr | None  # None: B is a fixed wall
    e: sympy.Expr
    before: dict[sympy.Symbol, sympy.Expr]
    after: dict[sympy.Symbol, sympy.Expr] = field(default_factory=dict)
    unknowns: tuple[sympy.Symbol, ...] = ()
    conditions: tuple[Callable[[Results], sympy.Expr], ...] = ()
    keep: Callable[[dict], bool] = lambda root: True
    defines: dict[str, Callable[[Results], sympy.Expr]] = field(default_factory=dict)
    ranges: dict[str, Callable[[Results], sympy.Basic]] = field(default_factory=dict)
    oblique: bool = False


def direct(m_A, m_B, e_, vA1, vB1=0, **kw) -> Case:
    return Case(m_A, m_B, e_, {A1n: vA1, A1t: 0, B1n: vB1, B1t: 0}, **kw)


def e_admissible(root: dict) -> bool:
    value = root.get(E)
    return value is None or bool(value.is_number and 0 <= value <= 1)


def components(speed: sympy.Expr, angle: sympy.Expr, along_n: bool) -> tuple[sympy.Expr, sympy.Expr]:
    """(n, t) of a velocity ``speed`` at ``angle`` from +n toward +t (along_n) or from +t toward +n."""
    if along_n:
        return speed * sympy.cos(angle), speed * sympy.sin(angle)
    return speed * sympy.sin(angle), speed * sympy.cos(angle)


WALL_A1n, WALL_A1t = components(U, alpha, along_n=False)

CASES: dict[str, Case] = {
    "edexcel-m2-2004-june-q5-2m-at-5u-hits-3m": direct(2 * m, 3 * m, e, 5 * u),
    "edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u": direct(2 * m, m, e, 2 * u, -u),
    "edexcel-m2-2011-june-q2-m-at-4u-hits-3m-show-e-gt-third": direct(
        m, 3 * m, e, 4 * u, ranges={"v_A2 < 0": lambda r: r["v_A2"] < 0}
    ),
    "edexcel-m2-2015-january-q7-m-at-3u-hits-2m-p-reverses": direct(
        m, 2 * m, e, 3 * u, ranges={"v_A2 < 0": lambda r: r["v_A2"] < 0}
    ),
    "edexcel-m2-2024-june-q5-m-hits-2m-speed-of-p": direct(m, 2 * m, e, u),
    "aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u": direct(
        m, 7 * m, e, 5 * u, u, ranges={"v_A2 < 0": lambda r: r["v_A2"] < 0}
    ),
    "cie-9231-p2-2012-june-q1-3m-hits-6m-show-ke-lost": direct(3 * m, 6 * m, e, u),
    "cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses": direct(
        2 * m, m, e, 4 * u, -3 * u, ranges={"v_A2 < 0": lambda r: r["v_A2"] < 0}
    ),
    "cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u": direct(5 * m, 2 * m, e, u, -2 * u),
    "cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u": direct(2 * m, 4 * m, e, 2 * u, -u),
    "wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest": direct(m, m, e, u),
    "edexcel-m2-2003-january-q6-2m-hits-m-e-one-third": direct(2 * m, m, sympy.Rational(1, 3), u),
    "edexcel-m2-undated-q7-4m-hits-5m-b-four-times-a": direct(4 * m, 5 * m, sympy.Rational(1, 2), u),
    # KE after = 3/4 m u^2; e unknown
    "edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters": direct(
        2 * m,
        m,
        E,
        u,
        unknowns=(E,),
        conditions=(lambda r: r["T_2"] - sympy.Rational(3, 4) * m * u**2,),
        keep=e_admissible,
    ),
    # after: P back at v, Q back at 3v/2; before unknown
    "edexcel-m2-2017-january-q5-both-reverse-find-speeds-before": Case(
        2 * m,
        3 * m,
        sympy.Rational(1, 5),
        {A1t: 0, B1t: 0},
        after={A2n: -v, B2n: sympy.Rational(3, 2) * v},
    ),
    # S brought to rest; e unknown
    "edexcel-m2-undated-q5-s-brought-to-rest-show-e": Case(
        m, k * m, E, {A1n: u, A1t: 0, B1n: lam * u, B1t: 0}, after={A2n: 0}, unknowns=(E,)
    ),
    # the impulse on each particle is 4mu; e unknown
    "cie-9231-p2-2012-june-q2-impulse-4mu-show-ke-lost": direct(
        3 * m, m, E, 2 * u, -u, unknowns=(E,), conditions=(lambda r: r["J_n"] - 4 * m * u,), keep=e_admissible
    ),
    # half the kinetic energy lost; e unknown
    "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost": direct(
        m, 9 * m, E, u, unknowns=(E,), conditions=(lambda r: r["T_lost"] - r["T_1"] / 2,), keep=e_admissible
    ),
    # wall, e = 3/4, 60% of the kinetic energy kept; alpha unknown (acute)
    "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke": Case(
        m,
        None,
        sympy.Rational(3, 4),
        {A1n: WALL_A1n, A1t: WALL_A1t},
        unknowns=(alpha,),
        conditions=(lambda r: r["T_2"] - sympy.Rational(3, 5) * r["T_1"],),
        keep=lambda root: bool(0 < root[alpha] < sympy.pi / 2),
        oblique=True,
    ),
    # cushion, coefficient e_1; beta is the rebound angle with the cushion
    "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta": Case(
        m, None, e_1, {A1n: WALL_A1n, A1t: WALL_A1t}, defines={"beta": lambda r: -r["theta_A2"]}, oblique=True
    ),
    # equal spheres, B at rest, line of centres at 30 deg to A's path
    "edexcel-m4-undated-q3-deflected-through-theta-line-at-30deg": Case(
        m,
        m,
        e,
        dict(zip((A1n, A1t), components(u, sympy.pi / 6, along_n=True), strict=True)) | {B1n: 0, B1t: 0},
        defines={"deflection": lambda r: r["beta_A2"] - sympy.pi / 6},
        oblique=True,
    ),
    # the same geometry, from the Pre-U specimen paper
    "pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg": Case(
        m,
        m,
        e,
        dict(zip((A1n, A1t), components(u, sympy.pi / 6, along_n=True), strict=True)) | {B1n: 0, B1t: 0},
        defines={"deflection": lambda r: r["beta_A2"] - sympy.pi / 6},
        oblique=True,
    ),
    # identical spheres, P at rest, Q at alpha to the line of centres
    "edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta": Case(
        m,
        m,
        e,
        dict(zip((A1n, A1t), components(u, alpha, along_n=True), strict=True)) | {B1n: 0, B1t: 0},
        oblique=True,
    ),
    # identical balls, B at rest, A's path at 30 deg (AQA 2007) and 60 deg (AQA 2016) to the line
    "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b": Case(
        m,
        m,
        e,
        dict(zip((A1n, A1t), components(u, sympy.pi / 6, along_n=True), strict=True)) | {B1n: 0, B1t: 0},
        oblique=True,
    ),
    "aqa-m3-2016-june-q6a-path-along-wall-line-at-60deg-show-speed-of-b": Case(
        m,
        m,
        e,
        dict(zip((A1n, A1t), components(u, sympy.pi / 3, along_n=True), strict=True)) | {B1n: 0, B1t: 0},
        oblique=True,
    ),
    # wall, tan(theta) = 3, paths before and after at right angles; e unknown
    "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles": Case(
        m,
        None,
        E,
        dict(zip((A1n, A1t), components(u, sympy.atan(3), along_n=False), strict=True)),
        unknowns=(E,),
        conditions=(lambda r: sympy.tan(r["theta_A2"]) * 3 + 1,),
        keep=e_admissible,
        oblique=True,
    ),
    # A (2m) and B (m), opposite directions, each at alpha to the line of centres
    "ocr-m3-2012-january-q2-opposite-directions-each-at-alpha": Case(
        2 * m,
        m,
        sympy.Rational(1, 2),
        {A1n: u * sympy.cos(alpha), A1t: u * sympy.sin(alpha), B1n: -u * sympy.cos(alpha), B1t: -u * sympy.sin(alpha)},
        oblique=True,
    ),
}


@cache
def solved(stem: str) -> Results:
    """The results of the problem ``stem``, worked out once per test session."""
    return solve(CASES[stem])


def solve(case: Case) -> Results:
    """The impact's results (derive's names), from equations (1)-(4) and the case's conditions."""
    comps: dict[sympy.Symbol, sympy.Expr] = {A1n: A1n, A1t: A1t, B1n: B1n, B1t: B1t, A2n: A2n, A2t: A2t}
    comps.update({B2n: B2n, B2t: B2t})
    comps.update(case.before)
    comps.update(case.after)
    if case.m_B is None:
        comps.update({B1n: 0, B1t: 0, B2n: 0, B2t: 0})
    c = comps
    eqs = [c[A2t] - c[A1t], case.e * (c[A1n] - c[B1n]) - (c[B2n] - c[A2n])]
    if case.m_B is not None:
        eqs += [c[B2t] - c[B1t], case.m_A * c[A1n] + case.m_B * c[B1n] - case.m_A * c[A2n] - case.m_B * c[B2n]]
    results = _named(case, c)
    eqs += [cond(results) for cond in case.conditions]
    unknown = [s for s, val in c.items() if val == s] + list(case.unknowns)
    roots = [r for r in sympy.solve(eqs, unknown, dict=True) if case.keep(r)]
    assert len(roots) == 1, f"expected one admissible root, got {roots}"
    root = roots[0]
    out = {name: sympy.simplify(sympy.sympify(val).subs(root)) for name, val in results.items()}
    for s in case.unknowns:
        out[s.name] = root[s]
    for s in (A1n, B1n):
        if c[s] == s and not case.oblique:  # a velocity before the impact, found
            out[s.name.removesuffix("n")] = root[s]
    for name, make in case.defines.items():
        out[name] = sympy.simplify(make(out))
    return out


def _named(case: Case, c: dict) -> Results:
    m_B = 0 if case.m_B is None else case.m_B
    T1 = (case.m_A * (c[A1n] ** 2 + c[A1t] ** 2) + m_B * (c[B1n] ** 2 + c[B1t] ** 2)) / 2
    T2 = (case.m_A * (c[A2n] ** 2 + c[A2t] ** 2) + m_B * (c[B2n] ** 2 + c[B2t] ** 2)) / 2
    r: Results = {"T_1": T1, "T_2": T2, "T_lost": T1 - T2, "J_n": -case.m_A * (c[A2n] - c[A1n])}
    if not case.oblique:
        r |= {"v_A2": c[A2n], "v_B2": c[B2n]}
        return r
    r |= {"v_A2n": c[A2n], "v_A2t": c[A2t], "v_B2n": c[B2n], "v_B2t": c[B2t]}
    for b, n, t in (("A", c[A2n], c[A2t]), ("B", c[B2n], c[B2t])):
        if case.m_B is None and b == "B":
            continue
        r |= {f"v_{b}2": sympy.sqrt(n**2 + t**2), f"theta_{b}2": sympy.atan2(n, t), f"beta_{b}2": sympy.atan2(t, n)}
    return r


def published(text: str) -> sympy.Expr:
    """A fixed string of tests/support/symbolic_published.py as SymPy (letters positive)."""
    return parse_expr(text.replace("^", "**"), local_dict=dict(LETTERS))


def same_range(condition: sympy.Basic, expected: sympy.Basic) -> bool:
    """The values of e in [0, 1] for which ``condition`` (``expr < 0``) holds, against ``expected``.

    The letters other than e (u, m) are positive and only scale ``expr``: they are divided out.
    """
    assert isinstance(condition, sympy.StrictLessThan) and condition.rhs == 0, condition
    scale, rest = sympy.factor(condition.lhs).as_independent(e, as_Add=False)
    assert scale.is_positive or scale.is_negative, f"{scale}: the other letters must only scale the condition"
    holds = rest < 0 if scale.is_positive else rest > 0
    return values_of_e(holds) == values_of_e(expected)


# ------------------------------------------------------------------ the published results follow


ROWS = [pytest.param(stem, row, id=f"{stem}:{row.name}:{row.rule}") for stem, rows in PUBLISHED.items() for row in rows]


@pytest.mark.parametrize(("stem", "row"), ROWS)
def test_the_published_result_follows_from_equations_1_to_4(stem: str, row: Row) -> None:
    if row.rule == RANGE:
        assert same_range(CASES[stem].ranges[row.name](solved(stem)), published(row.published)), row
        return
    actual = solved(stem)[row.name]
    if row.rule == EXPR:
        assert sympy.simplify(actual - published(row.published)) == 0, f"{row.name} = {actual}, published {row}"
    elif row.rule == TAN:
        assert same_angle(actual, published(row.published)), f"{row.name} = {actual}, published {row}"
    elif row.rule == DEGREES:
        assert same_degrees(actual, row.published), f"{row.name} = {actual}, published {row}"
    else:
        raise AssertionError(f"unknown rule {row.rule}")


@pytest.mark.parametrize("stem", sorted(SHOWN))
def test_each_show_that_result_follows_from_equations_1_to_4(stem: str) -> None:
    results = solved(stem)
    names = dict(LETTERS) | {name: sympy.Symbol(name) for name in results}
    for text in SHOWN[stem]:
        lhs, rhs = (parse_expr(side.replace("^", "**"), local_dict=names) for side in text.split("="))
        values = {sympy.Symbol(name): val for name, val in results.items()}
        assert sympy.simplify((lhs - rhs).subs(values)) == 0, f"{stem}: {text} does not follow"


def test_the_two_roots_the_questions_reject_are_inadmissible() -> None:
    """Where a condition has two roots, the mark scheme's other root gives e outside [0, 1]."""
    case = CASES["edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters"]
    all_roots = Case(**{**case.__dict__, "keep": lambda root: True})
    with pytest.raises(AssertionError, match="one admissible root"):
        solve(all_roots)  # e = 1/2 and e = -1/2 ("vQ = u/3, vP = 5u/6")
    case = CASES["cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost"]
    with pytest.raises(AssertionError, match="one admissible root"):
        solve(Case(**{**case.__dict__, "keep": lambda root: True}))  # e = 2/3 and e = -2/3


# ------------------------------------------------------------------ the files hold these strings


def _compact(text: str) -> str:
    return re.sub(r"\s+", "", text)


def _file(stem: str) -> dict:
    with (PROBLEMS / f"{stem}.toml").open("rb") as f:
        return tomllib.load(f)


def test_every_problem_with_answers_is_checked_here() -> None:
    with_answers = set()
    for path in PROBLEMS.glob("*.toml"):
        with path.open("rb") as f:
            if "answers" in tomllib.load(f):
                with_answers.add(path.stem)
    assert with_answers == set(PUBLISHED)
    assert set(SHOWN) <= set(PUBLISHED)
    assert len(PUBLISHED) >= 15


@pytest.mark.parametrize("stem", sorted(PUBLISHED))
def test_the_file_states_the_published_strings(stem: str) -> None:
    data = _file(stem)
    expected = {row.name: _compact(row.published) for row in PUBLISHED[stem] if row.in_answers}
    assert {name: _compact(text) for name, text in data["answers"].items()} == expected
    ranges = data.get("range", [])
    ranges = [ranges] if isinstance(ranges, dict) else ranges
    wanted = [{"of": "e", "where": row.name} for row in PUBLISHED[stem] if row.rule == RANGE]
    assert [{k: _compact(v) for k, v in r.items()} for r in ranges] == [
        {k: _compact(v) for k, v in r.items()} for r in wanted
    ]
    shown = data.get("show", ())
    shown = (shown,) if isinstance(shown, str) else tuple(shown)
    assert tuple(_compact(s) for s in shown) == tuple(_compact(s) for s in SHOWN.get(stem, ()))
    source = data.get("source", "")
    assert "https://" in source and "mark scheme" in source, f"{stem}: cite the mark scheme and where it was read"
