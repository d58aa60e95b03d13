"""One symbol table: a name from the notes -> its SymPy symbol and its LaTeX.

Names follow the notes: ``v_A1n`` is the velocity of A before (1) the impact,
component n. Every part of derive gets its symbols here, so a symbol made with
other assumptions never slips in and fails to cancel.
"""

from __future__ import annotations

import re
from functools import cache

import sympy
from sympy.printing.latex import translate

_SPECIAL_SUBS = {"lost": r"\mathrm{lost}"}


@cache
def symbol(name: str, kind: str = "real") -> sympy.Symbol:
    """The symbol for ``name``; ``kind`` sets its assumptions.

    ``kind`` is 'positive' (masses), 'nonnegative' (speeds, e) or 'real'.
    """
    if kind == "positive":
        return sympy.Symbol(name, positive=True)
    if kind == "nonnegative":
        return sympy.Symbol(name, nonnegative=True)
    return sympy.Symbol(name, real=True)


def kind_of(name: str, oblique: bool) -> str:
    """The assumptions the notes' meaning of ``name`` gives it."""
    if re.fullmatch(r"m(_[AB])?|M(_[AB])?|m|W_[AB]", name):
        return "positive"
    if name == "e":
        return "nonnegative"
    if oblique and name in ("v_A1", "v_B1", "v_A2", "v_B2"):
        return "positive"  # a symbolic speed is of a moving body; a number may be 0
    return "real"


#: The notes' names of a body's quantities (v_A1n, m_B, theta_A2); a chain's own names
#: (u_B, w_B) are not a body's and keep their letters.
_BODY_NAME = re.compile(
    r"(?P<head>(?:vec:)?(?:v|m|W|r|theta|beta|alpha|gamma|delta)_)(?P<body>[AB])(?P<tail>[12]?[nt]?[xy]?)"
)


def relabel(name: str, labels: tuple[str, str]) -> str:
    """A body's symbol under the page's letters: ``v_A1n`` -> ``v_B1n`` when A is called B."""
    if labels == ("A", "B"):
        return name
    m = _BODY_NAME.fullmatch(name)
    if m is None:
        return name
    return m["head"] + labels["AB".index(m["body"])] + m["tail"]


def latex_name(name: str) -> str:
    """LaTeX for a symbol name: ``v_A1n`` -> ``v_{A1n}``, ``theta_1`` -> ``\\theta_{1}``."""
    base, _, sub = name.partition("_")
    head = translate(base)
    if not sub:
        return head
    sub_tex = _SPECIAL_SUBS.get(sub)
    if sub_tex is None:
        sub_tex = r"\mathrm{" + sub + "}" if len(sub) > 3 and sub.isalpha() and sub.islower() else sub
        sub_tex = sub_tex.replace("_", r"\_")
    return f"{head}_{{{sub_tex}}}"


_VECTORS = {"e_t": r"\hat{e}_{t}", "e_n": r"\hat{e}_{n}", "e_x": r"\hat{\imath}", "e_y": r"\hat{\jmath}"}


@cache
def vector(name: str) -> sympy.Symbol:
    """A symbol printed as a vector: ``v_A2`` -> ``\\vec{v}_{A2}``, ``e_t`` -> ``\\hat{e}_{t}``."""
    return sympy.Symbol("vec:" + name, commutative=True)


def vector_latex(sym_name: str) -> str | None:
    """LaTeX for a :func:`vector` symbol's name, or None for an ordinary symbol."""
    if not sym_name.startswith("vec:"):
        return None
    name = sym_name[4:]
    if name in _VECTORS:
        return _VECTORS[name]
    base, _, sub = name.partition("_")
    return rf"\vec{{{translate(base)}}}_{{{sub}}}"
