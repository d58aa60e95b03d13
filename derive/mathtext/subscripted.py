"""Marks after a name as engineering students type them: Unicode's subscripts (``(v_A)ₓ₁``,
``vₙ₂``, ``(v_B)ᵧ₁``) and a velocity's letter alone in brackets with its component and instant
glued after (``(v)t1``, ``(v)n2``, ``(v)_t2``: one body's), an angle's Greek letter with its instant
glued on (``θ2``, ``theta1``). Each is written with ASCII marks,
as :mod:`.bracketed` and the names' readers read them (``(v_A)_x1``, ``v_n2``, ``v_t1``)."""

from __future__ import annotations

import re

#: Unicode's subscript letters and digits (``ᵧ``, a subscript gamma, is typed for y).
_SUB = dict(zip("₀₁₂₃₄₅₆₇₈₉ₓᵧₙₜₐₑₒₕₖₗₘₚₛᵢⱼᵣᵤᵥ", "0123456789xyntaeohklmpsijruv", strict=True))
_RUN = re.compile(r"([\w)'])([" + "".join(_SUB) + r"]+)")
#: A velocity's letter alone in brackets, its component and instant after (``(v)t1``, ``(v)_n2``).
_BARE = re.compile(r"\(\s*([uvwUVW])\s*\)\s*_?\s*([ntxy][12]|[12][ntxy])(?![\w(])")
#: An angle's Greek letter (or its name) with its instant glued on (``θ2``, ``theta1``, ``φ2``).
_GREEK_DIGIT = re.compile(r"(?<![A-Za-z_\\])(alpha|beta|gamma|theta|phi|psi|[αβγθφϕψ])([12])(?![\w.])")


def ascii_subscripts(text: str) -> str:
    """``text`` with Unicode's subscripts as ``_`` and ASCII (after a bracket or a name with no
    subscript yet) or as more of the subscript (after ``v_A``), ``(v)t1`` as ``v_t1``, ``θ2`` as ``θ_2``."""

    def run(m: re.Match) -> str:
        marks = "".join(_SUB[c] for c in m.group(2))
        word = re.search(r"[A-Za-z_][\w]*$", text[: m.end(1)])
        glued = m.group(1) != ")" and word is not None and "_" in word.group(0)
        return m.group(1) + ("" if glued else "_") + marks

    text = _AXIS_SIGN.sub(lambda m: _AXIS_WORD[m.group(1).lstrip("\\")], text)  # "∥ = U cos α": parallel
    text = axis_subscripts(text)  # u∥, v_\perp: u_parallel, v_perpendicular
    return _GREEK_DIGIT.sub(r"\1_\2", _BARE.sub(r"\1_\2", _RUN.sub(run, text)))


#: A component named by the sign of its axis alone (``∥ = U cos α, ⊥ = U sin α``, ``\perp = …``):
#: the words parallel and perpendicular, which the names' readers place (at a wall: t and n).
_AXIS_SIGN = re.compile(r"(?<![\w_{^\\])(∥|⊥|\\parallel|\\perp)(?![A-Za-z0-9_}])(?=\s*=)")
_AXIS_WORD = {"∥": "parallel", "⊥": "perpendicular", "parallel": "parallel", "perp": "perpendicular"}


#: An axis's sign as a name's subscript: in LaTeX (``v_\perp``, ``v_{\parallel}``, ``v_{A,\perp}``),
#: in Unicode after ``_`` or glued to the letter (``u⊥``, ``v_A∥``, phone-typed). Each is the
#: subscript ``perpendicular`` or ``parallel`` the names' readers know (:mod:`derive.checking.namegrammar`;
#: in full, as ``v_perp`` would end in the ``p`` of a prime).
_SIGN_IN_SUB = re.compile(r"(_\{[^{}]*?)(\\perp|\\parallel|⊥|∥)(?![A-Za-z])\s*(?=[^{}]*\})")
_SIGN_AFTER = re.compile(
    r"(?<![A-Za-z\\])([A-Za-z](?:_[A-Za-z0-9]{1,2})?'?)(?:(_)\s*)?(\\perp|\\parallel|⊥|∥)(?![A-Za-z])"
)
_SIGN_SUB = {"\\perp": "perpendicular", "⊥": "perpendicular", "\\parallel": "parallel", "∥": "parallel"}


def axis_subscripts(text: str) -> str:
    r"""``text`` with an axis's sign after a name (``u∥``, ``v_\perp``, ``v_{A⊥}``) as the subscript
    ``parallel`` or ``perpendicular`` (``u_parallel``, ``v_perpendicular``); a sign alone is left to :data:`_AXIS_SIGN`."""
    text = _SIGN_IN_SUB.sub(lambda m: m.group(1) + _SIGN_SUB[m.group(2)], text)

    def after(m: re.Match) -> str:
        name, sign = m.group(1), _SIGN_SUB[m.group(3)]
        if "_" in name:  # v_A⊥: one more mark of the subscript
            return name + sign
        return name + "_" + sign

    return _SIGN_AFTER.sub(after, text)
