"""Unit vectors of the student's own: a frame turned from the line of centres, and dot products.

A student who keeps the question's axes (``i``, ``j`` along x and y) writes the line of centres'
unit vector in them, ``n̂ = cos 20° i + sin 20° j`` (also ``\\hat n = (\\cos 30°, \\sin 30°)``,
``e_n``; ``t̂`` likewise, or else n̂ turned a quarter turn counter-clockwise). A vector written in
``i`` and ``j`` after that is, on derive's n, its dot product with n̂: ``a i + b j`` has the n
component ``a cos 20° + b sin 20°`` (and on t its dot product with t̂). The line that declares
the unit vector is the frame, not a relation to mark. ``u_A · n̂`` (also ``u_A \\cdot \\hat n``,
``•``) is u_A's component along n, ``u_An``; a dot product of two vectors written out
(``(3, 4)·(0.6, 0.8)``, ``(3i + 4j)·(0.6i + 0.8j)``) is the sum of their components' products.
Unicode's hats (``î``, ``ĵ``, ``n̂``, ``x̂``) are the unit vectors ``i_hat``, ``n_hat``, ….
"""

from __future__ import annotations

import re
from collections.abc import Callable

#: Unit vectors along derive's own axes (never turned by a frame of the student's).
ALONG = {"n_hat": "n", "e_n": "n", "t_hat": "t", "e_t": "t"}
#: The unit vectors a frame's declaration and a dot product take: derive's, and bare n, t.
_NAMED = {**ALONG, "n": "n", "t": "t"}
#: The student's own unit vectors, derive's n and t where no frame turns them (i along the l.o.c.).
_OWN = {"i": "n", "i_hat": "n", "e_x": "n", "j": "t", "j_hat": "t", "e_y": "t"}
_HATTED = {"î": "i_hat", "ĵ": "j_hat", "x̂": "i_hat", "ŷ": "j_hat"}
#: A dot between two vectors: ``·``, ``⋅``, ``•``, ``∙``, ``\bullet`` (``\cdot`` reads as ``*``).
_DOT = re.compile(r"\s*(?:[·⋅•∙]|\\bullet|\\cdot)\s*")
_LEAD = re.compile(r"^(?:[A-Za-z][A-Za-z.]*\s+)+(?=\S+$)")  # "Unit vector along the l.o.c. n_hat"
_IJ = re.compile(r"(?<![A-Za-z_])(?:i|j|i_hat|j_hat|e_x|e_y)(?![A-Za-z_])")
_DERIVES = re.compile(r"(?<![A-Za-z_])(?:n_hat|t_hat|e_n|e_t)(?![A-Za-z_])")

Vector = Callable[[str], "dict[str, str] | None"]
Frame = dict[str, dict[str, str]]


class VectorNames(set):
    """The names split into components so far (``u`` in ``J = m(v - u)``), and the frame of
    unit vectors the student declared (derive's axis -> the unit vector's i and j components:
    ``{"n": {"n": "cos 20°", "t": "sin 20°"}}``, the reader's first axis ``n`` being i)."""

    frame: Frame | None = None


def hats(side: str) -> str:
    """``side`` with Unicode's hatted letters as the reader's unit vectors and a dot product's
    dot as ``·`` (``3î + 4ĵ`` -> ``3i_hat + 4j_hat``; ``u_A • n̂`` -> ``u_A · n_hat``)."""
    for k, v in _HATTED.items():
        side = side.replace(k, v)
    side = re.sub(r"([A-Za-z])\u0302", lambda m: {"x": "i", "y": "j"}.get(m[1], m[1]) + "_hat", side)
    return _DOT.sub(" · ", side) if _DOT.search(side) else side


def declared(sides: tuple[str, ...], vector_of: Vector) -> tuple[str, dict[str, str]] | None:
    """(derive's axis, the unit vector's i and j components) where ``sides`` declare the unit
    vector along or across the line of centres in the student's i and j (``n̂ = cos 20° i +
    sin 20° j``, ``\\hat t = (-\\sin 30°, \\cos 30°)``), else None."""
    if len(sides) != 2:
        return None
    name = _LEAD.sub("", sides[0].strip())
    axis = _NAMED.get(name)
    if axis is None or _DERIVES.search(sides[1]):
        return None
    part = vector_of(sides[1])
    if part is None or (not _IJ.search(sides[1]) and not sides[1].strip().startswith("(")):
        return None
    return axis, {"n": part.get("n", "0"), "t": part.get("t", "0")}


def add_to_frame(names: VectorNames, axis: str, unit: dict[str, str]) -> None:
    """The unit vector of ``axis`` (its i and j components) into the frame; the other axis,
    where not declared, is it turned a quarter turn (t̂ is n̂ turned counter-clockwise)."""
    frame = dict(names.frame or {})
    frame[axis] = unit
    if axis == "n" and "t" not in (names.frame or {}):
        frame["t"] = {"n": f"-({unit['t']})", "t": unit["n"]}
    elif axis == "t" and "n" not in (names.frame or {}):
        frame["n"] = {"n": unit["t"], "t": f"-({unit['n']})"}
    names.frame = frame


def turned(part: dict[str, str], side: str, frame: Frame | None) -> dict[str, str]:
    """``part`` (a side's components on the reader's axes: i, j) on derive's n and t through the
    ``frame`` (its dot products with n̂ and t̂); as it is where there is no frame or the side is
    written in derive's own unit vectors (``5.76 n̂ + 33.8 t̂``)."""
    if not frame or _DERIVES.search(side):
        return part
    out = {}
    for axis in ("n", "t"):
        terms = [f"({c})*({frame[axis][a]})" for a, c in part.items() if frame[axis].get(a, "0").strip() != "0"]
        out[axis] = " + ".join(terms) or "0"
    return out


def dotted(side: str, vector_of: Vector, named: Callable[[str, str], str], frame: Frame | None = None) -> str:
    """``side`` with a dot product read: ``u_A · n_hat`` -> u_A's component along n (``named``
    gives it; ``u_A · i`` too where the student's i is the line of centres: no ``frame``),
    ``(3, 4) · (0.6, 0.8)`` -> ``(3)*(0.6) + (4)*(0.8)``; as it is where it is none."""
    units = _NAMED if frame else {**_NAMED, **_OWN}
    text = side.strip()
    if " · " in text:
        left, _, right = text.partition(" · ")
    else:  # "u_A * n_hat" (\cdot): only a name and one of derive's unit vectors, or two pairs
        m = re.fullmatch(r"(.+?)\s*\*\s*(n_hat|t_hat|e_n|e_t|i_hat|j_hat|\(.*\))", text)
        if m is None:
            return side
        left, right = m.group(1), m.group(2)
    left, right = left.strip(), right.strip()
    for a, b in ((left, right), (right, left)):
        if b in units and re.fullmatch(r"[A-Za-z][A-Za-z0-9_]*'*", a) and a not in units:
            return named(a, units[b])
    u, v = vector_of(left), vector_of(right)
    if u is None or v is None:
        return side
    terms = [f"({u[a]})*({v[a]})" for a in ("n", "t") if a in u and a in v]
    return " + ".join(terms) if terms else "0"


#: A unit vector along or across the line of centres declared in the student's own axes, as
#: typed: ``n̂ = cos 20° i + …``, ``\hat{n} = (\cos 30°, …)``, ``**t** = …``, ``e_n = …``.
_DECLARES = re.compile(
    r"(?:[nt]\u0302|\\hat\s*\{?\s*(?:\\(?:mathbf|boldsymbol|bm)\s*\{)?\s*(?:e\s*\}?\s*_\s*\{?\s*)?[nt]"
    r"|\\(?:mathbf|vec|boldsymbol)\s*\{?\s*\\hat\s*\{?\s*[nt]|\be_\{?[nt]\}?|\\mathbf\{[nt]\}|\*\*[nt]\*\*|\b[nt]_hat)"
    r"[\s}]*=\s*[^=\n]*?(?:\(|\\begin\{[pb]matrix\}|\\mathbf\{[ij]\}|\\hat|[îĵ]|\*\*[ij]\*\*|(?<![A-Za-z_\\])[ij](?![A-Za-z_]))"
)


def declares_frame(text: str) -> bool:
    """Whether ``text`` declares n̂ or t̂ in the student's own unit vectors (then its words that
    place ``i`` and ``j`` do not place them on n and t: the declaration does)."""
    return _DECLARES.search(text) is not None
