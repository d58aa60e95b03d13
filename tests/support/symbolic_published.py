"""The published results of the symbolic / "show that" library (issue #14), as fixed strings.

Each bundled problem with an ``answers`` table has a row per printed result here. The
strings are the mark scheme's results, written in the problem's names (its givens, the
results derive computes, its ``[define]`` quantities) and in derive's sign conventions
(+n from A's centre toward B's); each problem file's top comment says how the mark
scheme's own directions map and where its printed form differs (speeds vs velocities).

They are literals of the test code, so SymPy's ``parse_expr`` only ever parses these,
never text from a problem file; the file's own ``answers`` strings must match them
(tests/test_symbolic_library_by_hand.py checks that without derive).

Rules:

- ``EXPR``: the result equals the expression (``simplify(a - b) == 0``, letters positive);
- ``TAN``: an angle; its tangent equals the tangent of the expression, and the two angles
  agree at sample values of the letters (so a reversed direction is not passed);
- ``RANGE``: the values of ``e`` for which the file's ``range = { of = "e", where = ... }``
  holds (the row's name is its ``where``), printed as ``"e > 1/3"``, compared as sets
  within 0 <= e <= 1; a range has no name, so the file says the printed set in a comment;
- ``DEGREES``: an angle printed in degrees (``"73"``), rounded to the printed places; not
  a string of the file (the file holds the exact form of the same result).
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass

import sympy

EXPR = "expr"
TAN = "tan"
RANGE = "range"
DEGREES = "degrees"


@dataclass(frozen=True)
class Row:
    name: str
    published: str
    rule: str = EXPR

    @property
    def in_answers(self) -> bool:
        """Whether the problem file's ``answers`` table holds this string."""
        return self.rule in (EXPR, TAN)


PUBLISHED: dict[str, tuple[Row, ...]] = {
    # ---------------------------------------------------------------- direct, e a letter
    "edexcel-m2-2004-june-q5-2m-at-5u-hits-3m": (
        Row("v_B2", "2*(1 + e)*u"),  # "Solving to y = 2(1+e)u"
        Row("v_A2", "2*u - 3*e*u"),  # "x = 2u - 3eu"
    ),
    "edexcel-m2-2010-january-q2-2m-at-2u-meets-m-at-u": (
        Row("v_A2", "u*(1 - e)"),  # "v1 = u(1-e)"
        Row("v_B2", "u*(1 + 2*e)"),  # "v2 = u(1 + 2e)"
    ),
    "edexcel-m2-2011-june-q2-m-at-4u-hits-3m-show-e-gt-third": (
        Row("v_A2", "(1 - 3*e)*u"),  # "v = (3e - 1)u", a speed backwards
        Row("v_A2 < 0", "e > 1/3", RANGE),  # "e > 1/3"
    ),
    "edexcel-m2-2015-january-q7-m-at-3u-hits-2m-p-reverses": (
        Row("v_B2", "u*(1 + e)"),  # "w = u(1+e)"
        Row("v_A2", "u*(1 - 2*e)"),  # "v = w - 3eu = u - 2ue"
        Row("v_A2 < 0", "e > 1/2", RANGE),  # "(1 >=) e > 1/2"
    ),
    "edexcel-m2-2024-june-q5-m-hits-2m-speed-of-p": (
        Row("v_A2", "-u*(2*e - 1)/3"),  # "v = u(2e - 1)/3", a speed backwards
    ),
    "aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u": (
        Row("v_B2", "u/2*(e + 3)"),  # "v_B = u/2 (e + 3)"
        Row("v_A2", "u/2*(3 - 7*e)"),  # "v_A = u/2 (3 - 7e)"
        Row("v_A2 < 0", "e > 3/7", RANGE),  # "e > 3/7"
    ),
    "cie-9231-p2-2012-june-q1-3m-hits-6m-show-ke-lost": (
        Row("v_A2", "(1 - 2*e)*u/3"),  # "v_A = 1/3 (1-2e)u"
        Row("v_B2", "(1 + e)*u/3"),  # "v_B = 1/3 (1+e)u"
        Row("T_lost", "m*u^2*(1 - e^2)"),  # "= mu^2(1-e^2) A.G."
    ),
    "cie-9231-p2-2014-november-q1-2m-at-4u-meets-m-at-3u-a-reverses": (
        Row("v_A2", "(5 - 7*e)*u/3"),  # "v_A = 1/3 (5-7e)u"
        Row("v_B2", "(5 + 14*e)*u/3"),  # "[v_B = 1/3 (5+14e)u]"
        Row("v_A2 < 0", "e > 5/7", RANGE),  # "e > 5/7 or 0.714"
    ),
    "cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u": (
        Row("v_B2", "u*(1 + 15*e)/7"),  # "1/7 u(1 + 15e)"
        Row("v_A2", "u*(1 - 6*e)/7"),  # "v_A = (u/7)(1 - 6e)"
    ),
    "cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u": (
        Row("v_A2", "-2*e*u"),  # "v_A = -2eu"
        Row("v_B2", "e*u"),  # "v_B = eu"
    ),
    "wjec-further-unit3-2019-june-q7-equal-spheres-b-at-rest": (
        Row("v_A2", "(1 - e)*u/2"),  # "v_A = 1/2 (1 - e)u"
        Row("v_B2", "(1 + e)*u/2"),  # "v_B = 1/2 (1 + e)u"
    ),
    # ---------------------------------------------------------------- direct, e a number
    "edexcel-m2-2003-january-q6-2m-hits-m-e-one-third": (
        Row("v_A2", "5/9*u"),  # "x = 5/9 u (*)"
        Row("v_B2", "8/9*u"),  # "y = 8/9 u (*)"
    ),
    "edexcel-m2-undated-q7-4m-hits-5m-b-four-times-a": (
        Row("v_A2", "u/6"),  # "v_1 = 1/6 u"
        Row("v_B2", "2/3*u"),  # "v_2 = 4/6 u = 4 x v_1"
    ),
    # ---------------------------------------------------------------- direct, unknowns
    "edexcel-m2-2013-june-q5-2m-hits-m-ke-three-quarters": (
        Row("v_B2", "u"),  # "vQ = u"
        Row("v_A2", "u/2"),  # "vP = u/2"
        Row("e", "1/2"),  # impact law on "vQ = u, vP = u/2" (its printed value cut off in the transcription)
    ),
    "edexcel-m2-2017-january-q5-both-reverse-find-speeds-before": (
        Row("v_A1", "8*v"),  # "u_P = 8v"
        Row("v_B1", "-9/2*v"),  # "u_Q = 4.5v", toward P
    ),
    "edexcel-m2-undated-q5-s-brought-to-rest-show-e": (
        Row("e", "(1 + k*lam)/(k*(1 - lam))"),  # "(1 + k lambda)/(k(1 - lambda)) = e"
        Row("v_B2", "u*(1 + k*lam)/k"),  # "u/k (1 + k lambda) = v"
    ),
    "cie-9231-p2-2012-june-q2-impulse-4mu-show-ke-lost": (
        Row("v_A2", "2*u/3"),  # "v_3m = 2u/3"
        Row("v_B2", "3*u"),  # "v_m = 3u"
        Row("T_lost", "4/3*m*u^2"),  # "= (4/3) mu^2 A.G."
    ),
    "cie-9231-p2-2014-june-q3-m-hits-9m-half-ke-lost": (
        Row("e", "2/3"),  # from "v_B = (1+e)u/10" = "u/6"
        Row("v_A2", "-u/2"),  # "v_A, v_B = -u/2, u/6"
        Row("v_B2", "u/6"),
    ),
    # ---------------------------------------------------------------- oblique and walls
    "edexcel-m4-2018-june-q2-wall-keeps-60-percent-of-ke": (
        Row("alpha", "atan(sqrt(32/3))", TAN),  # "tan(alpha) = v/u = sqrt(32/3)"
        Row("alpha", "73", DEGREES),  # "alpha = 73 deg"
    ),
    "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta": (
        Row("beta", "atan(e_1*tan(alpha))", TAN),  # "tan(beta) = e_1 tan(alpha) *"
    ),
    "edexcel-m4-undated-q3-deflected-through-theta-line-at-30deg": (
        Row("v_A2n", "u*sqrt(3)/4*(1 - e)"),  # "v_1 = u sqrt(3)/4 (1-e)"
        Row("deflection", "atan((1 + e)*sqrt(3)/(5 - 3*e))", TAN),  # "= (1+e) sqrt(3)/(5-3e) (*)"
    ),
    "pre-u-9795-2-2013-june-q12i-wall-rebound-at-right-angles": (
        Row("e", "1/9"),  # "=> e = 1/9"
    ),
    "pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg": (
        Row("v_A2n", "sqrt(3)/4*u*(1 - e)"),  # "v_1 = 1/4 sqrt(3) u (1 - e) (AG)"
        Row("deflection", "atan((1 + e)*sqrt(3)/(5 - 3*e))", TAN),  # printed in the question, (ii)
    ),
    "edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta": (
        Row("beta_A2", "atan(2*tan(alpha)/(1 - e))", TAN),  # "(1 - e) tan(beta) = 2 tan(alpha)", printed
    ),
    "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b": (
        Row("v_B2", "sqrt(3)/4*u*(1 + e)"),  # "sqrt(3)/4 u (1 + e)", printed in the question
    ),
    "aqa-m3-2016-june-q6a-path-along-wall-line-at-60deg-show-speed-of-b": (
        Row("v_B2", "1/4*u*(1 + e)"),  # "1/4 u (1 + e)", printed in the question
    ),
    "ocr-m3-2012-january-q2-opposite-directions-each-at-alpha": (
        Row("v_A2n", "0"),  # "a = 0"
        Row("v_B2n", "u*cos(alpha)"),  # "Comp of B's velocity along l.o.c. is u cos(alpha)"
        Row("v_B2", "u"),  # "B's speed unchanged"
        Row("theta_A2", "0", TAN),  # A moves "perp to l.o.c."
        Row("beta_B2", "-alpha", TAN),  # "Direction of B is at angle alpha to l.o.c."
    ),
}

#: The "show that" results each problem file states (its ``show``), as fixed strings.
SHOWN: dict[str, tuple[str, ...]] = {
    "edexcel-m2-2003-january-q6-2m-hits-m-e-one-third": ("v_A2 = 5/9*u", "v_B2 = 8/9*u"),
    "edexcel-m2-2004-june-q5-2m-at-5u-hits-3m": ("v_B2 = 2*(1 + e)*u",),
    "edexcel-m2-undated-q5-s-brought-to-rest-show-e": ("e = (1 + k*lam)/(k*(1 - lam))",),
    "aqa-m3-2009-june-q6-m-at-5u-catches-7m-at-u": ("v_B2 = u/2*(e + 3)",),
    "cie-9231-p2-2012-june-q1-3m-hits-6m-show-ke-lost": ("T_lost = m*u^2*(1 - e^2)",),
    "cie-9231-p2-2012-june-q2-impulse-4mu-show-ke-lost": ("T_lost = 4/3*m*u^2",),
    "cie-9231-p2-2018-november-q2-5m-at-u-meets-2m-at-2u": ("v_B2 = u*(1 + 15*e)/7",),
    "edexcel-fm1-2023-june-q7a-cushion-show-tan-beta": ("tan(beta) = e_1*tan(alpha)",),
    "edexcel-m4-undated-q3-deflected-through-theta-line-at-30deg": ("tan(deflection) = (1 + e)*sqrt(3)/(5 - 3*e)",),
    "ocr-m3-2012-january-q2-opposite-directions-each-at-alpha": ("v_B2 = u",),
    "edexcel-m2-undated-q7-4m-hits-5m-b-four-times-a": ("v_B2 = 4*v_A2",),
    "pre-u-9795-2-specimen-q2-equal-balls-line-at-30deg": (
        "v_A2n = sqrt(3)/4*u*(1 - e)",
        "tan(deflection) = (1 + e)*sqrt(3)/(5 - 3*e)",
    ),
    "edexcel-m4-2005-june-q3-show-1-minus-e-tan-beta": ("(1 - e)*tan(beta_A2) = 2*tan(alpha)",),
    "aqa-m3-2007-june-q6a-b-at-rest-line-at-30deg-show-speed-of-b": ("v_B2 = sqrt(3)/4*u*(1 + e)",),
    "aqa-m3-2016-june-q6a-path-along-wall-line-at-60deg-show-speed-of-b": ("v_B2 = 1/4*u*(1 + e)",),
}


# ---------------------------------------------------------------- comparisons both test modules use

#: Sample ranges for the numeric angle check, by letter (others: 0.5 to 3).
SAMPLE = {"e": (0.05, 0.95), "e_1": (0.05, 0.95), "alpha": (0.1, 1.4), "theta": (0.1, 1.4), "lam": (0.05, 0.45)}


def same_angle(actual: sympy.Expr, expected: sympy.Expr) -> bool:
    """Equal tangents, and equal angles (mod 2 pi) at sample values of the letters.

    A difference of tangents that SymPy cannot bring to 0 but that is a constant (nested
    surds, as from solving for an angle) counts as 0 if it vanishes to 50 digits.
    """
    diff = sympy.simplify(sympy.tan(actual) - sympy.tan(expected))
    if diff != 0 and (diff.free_symbols or abs(sympy.N(diff, 60)) > sympy.Float("1e-50")):
        return False
    rng = random.Random(14)
    for _ in range(5):
        point = {s: rng.uniform(*SAMPLE.get(s.name, (0.5, 3.0))) for s in actual.free_symbols | expected.free_symbols}
        difference = float(sympy.N((actual - expected).subs(point)))
        if abs(math.remainder(difference, 2 * math.pi)) > 1e-9:
            return False
    return True


def same_degrees(actual_radians: sympy.Expr, printed: str) -> bool:
    """The angle, in degrees, rounded to the places the mark scheme printed."""
    places = len(printed.partition(".")[2])
    return round(float(sympy.N(actual_radians * 180 / sympy.pi, 30)), places) == float(printed)


def values_of_e(condition: sympy.Basic) -> sympy.Set:
    """The values of e in [0, 1] for which ``condition`` holds: a set, or a relation in e alone."""
    unit = sympy.Interval(0, 1)
    if isinstance(condition, sympy.Set):
        return condition & unit
    names = {s.name for s in condition.free_symbols}
    assert names == {"e"}, f"{condition}: a condition on e alone"
    real = {s: sympy.Symbol(s.name, real=True) for s in condition.free_symbols}
    return condition.xreplace(real).as_set() & unit
