"""Vectors as students type them, written out as one relation per component.

``u_A = 9i + 12j`` (also ``9\\mathbf{i}``, ``3.05\\,\\hat e_t - 1.12\\,\\hat e_n``, ``î ĵ``) and
``A = (0, 4)`` or ``(4 cos 60°, 4 sin 60°) = (2, 2√3)`` (a component pair) are vectors: a
relation between vectors is one relation per component. The first axis (``i``, ``x``,
``e_n``, the first of a pair) is the line of centres, derive's n, and the second (``j``, ``y``,
``e_t``) is t. A name standing for a vector gets the axis' letter: ``u_A`` -> ``u_An``,
``v_A2`` -> ``v_A2n``, ``A`` -> ``A_n``, ``A'`` (after) -> ``A_n'``; ``A after`` is ``A'``.
"""

from __future__ import annotations

import re

from derive.mathtext.unitframe import Frame, VectorNames, add_to_frame, declared, dotted, hats, turned

#: Unit vectors, by the component they pick: n (the first axis) or t.
UNITS = {
    "i": "n",
    "i_hat": "n",
    "e_n": "n",
    "e_x": "n",
    "e_1": "n",
    "n_hat": "n",
    "j": "t",
    "j_hat": "t",
    "e_t": "t",
    "e_y": "t",
    "e_2": "t",
    "t_hat": "t",
}
_UNIT = "|".join(sorted((re.escape(u) for u in UNITS), key=len, reverse=True))
_TERM = re.compile(rf"^(.*?)({_UNIT})$")
_NAME = re.compile(r"^([A-Za-z][A-Za-z0-9_]*)('*)(?:\s+(before|after))?$")
#: A lead-in that names a body alone, before or after (``A before``, ``B'``, ``P after``): the name of
#: a vector of numbers after it.
_BODY_LABEL = re.compile(r"[A-Z]'*(?:\s+(?:before|after))?")
AXES = ("n", "t")


def split_vectors(
    sides: tuple[str, ...],
    axes: dict[str, tuple[str, int]] | None = None,
    head_on: bool = False,
    vectors: set[str] | None = None,
    label: str = "",
) -> list[tuple[str, ...]]:
    """The relations of ``sides``: one per component where it is a relation between vectors
    (and ``[sides]`` where it is not); ``axes``, where the student placed them in words, takes
    each unit vector's axis to the one it stands for, with its sign (``j`` away from a wall: -n).
    On a ``head_on`` impact a vector on one axis only (``u_A = 3 i``) is the velocity along the
    line of motion, the problem's one axis: one relation with the names as written (``u_A = 3``).
    ``vectors``: the names split into components so far (this call adds its own); a side written
    in them (``J = m(v - u) = 0.06(39.6 i)``) has on each axis their components (``m(v_n - u_n)``);
    ``label``: the words before it, a body's (``A before: 15 sin α i + 15 cos α j = 12i + 9j``) the
    vector's name where every side is a vector of numbers: that body's velocity, ``A = …``."""
    vectors = VectorNames() if vectors is None else vectors
    hatted = tuple(hats(s) for s in sides)  # 3î + 4ĵ, u_A • n̂
    unit = declared(hatted, _vector)  # "n̂ = cos 20° i + sin 20° j": the student's frame, no relation
    if unit is not None and isinstance(vectors, VectorNames):
        add_to_frame(vectors, *unit)
        return []
    frame = getattr(vectors, "frame", None)
    dots = tuple(dotted(h, _vector, component, frame) for h in hatted)  # u_A · n̂: u_An
    sides = tuple(d if d != h else s for s, h, d in zip(sides, hatted, dots, strict=True))
    parts = [_placed(_vector(d), d, axes, frame) for d in dots]
    if not any(p is not None for p in parts):
        return [sides]
    sides = dots
    if all(p is not None for p in parts) and _BODY_LABEL.fullmatch(label.strip()):
        sides, parts = (label.strip(), *sides), [None, *parts]  # "A before: 12i + 9j": A's velocity before
    # a lead-in in words before the first name ("After impact write v_A = a i + …"): the name
    first = re.sub(r"^(?:[A-Za-z]{2,}\s+)+(?=\S+$)", "", sides[0].strip()) if parts[0] is None else sides[0]
    sides = (first, *sides[1:]) if _NAME.match(first.strip()) else sides
    names = [
        None if p is not None else _NAME.match(s.strip()) or _in_vectors(s, vectors)
        for s, p in zip(sides, parts, strict=True)
    ]
    used = {a for p in parts if p is not None for a in p}
    if head_on and len(used) == 1:  # one axis: a side in numbers or names (m(v_after - v_before)) is along it
        names = [
            n if n is not None or p is not None else s.strip() for s, p, n in zip(sides, parts, names, strict=True)
        ]
    if any(p is None and n is None for p, n in zip(parts, names, strict=True)):
        return [sides]
    vectors |= {n.group(1) for n in names if isinstance(n, re.Match)}
    if head_on and len(used) == 1:
        (axis,) = used
        return [tuple(p[axis] if p is not None else _on_axis(n, "") for p, n in zip(parts, names, strict=True))]
    out = []
    for axis in AXES:
        row = []
        for p, n in zip(parts, names, strict=True):
            row.append(p.get(axis, "0") if p is not None else _on_axis(n, axis, vectors))
        if any(r != "0" for r in row):
            out.append(tuple(row))
    return out or [sides]


_WORD = re.compile(r"(?<![\\\w])([A-Za-z][A-Za-z0-9_]*)('*)(?![\w(])")


def _in_vectors(side: str, vectors: set[str]) -> str | None:
    """``side`` where it is written in vectors named before (``m(v - u)``), else None."""
    return side.strip() if any(m.group(1) in vectors for m in _WORD.finditer(side)) else None


def _on_axis(n: re.Match | str, axis: str, vectors: set[str] = frozenset()) -> str:
    """A vector's name (or a side written in vectors) on ``axis``; ``""``: the velocity itself."""
    if isinstance(n, str):
        if not axis:
            return n
        return _WORD.sub(lambda w: component_name(w, axis) if w.group(1) in vectors else w.group(0), n)
    return component_name(n, axis) if axis else _plain(n)


def _placed(
    part: dict[str, str] | None, side: str, axes: dict[str, tuple[str, int]] | None, frame: Frame | None
) -> dict[str, str] | None:
    if part is None or frame:
        return part and turned(part, side, frame)  # n̂ = cos 20° i + sin 20° j: i and j turned
    if not axes:
        return part
    return {axes[a][0]: c if axes[a][1] > 0 else f"-({c})" for a, c in part.items()}


def _plain(m: re.Match) -> str:
    """A vector's name as a velocity's (``u_A``, ``A after`` -> ``A'``)."""
    primes = m.group(2) or ("'" if m.group(3) == "after" else "")
    return m.group(1) + primes


def component(name: str, axis: str) -> str:
    """The component on ``axis`` of the vector named ``name`` (``v_in`` -> ``v_inn``, ``A`` -> ``A_n``)."""
    m = _NAME.match(name)
    return component_name(m, axis) if m else f"{name}_{axis}"


def component_name(m: re.Match, axis: str) -> str:
    """The name of a vector's component: ``u_A`` -> ``u_An``, ``A`` -> ``A_n``, ``A'`` -> ``A_n'``."""
    name, primes, when = m.group(1), m.group(2), m.group(3) if m.re.groups > 2 else None
    if when == "after":
        primes = primes or "'"
    base = f"{name}{axis}" if "_" in name else f"{name}_{axis}"
    return base + primes


def _vector(side: str, depth: int = 0) -> dict[str, str] | None:
    """A side's components by axis, where it is a vector (a pair or a sum of unit vectors); a
    vector in more than 20 brackets, one in another, is none (each bracket is a call)."""
    if depth > 20:
        return None
    side = re.sub(r"^(?:[A-Za-z]+\s+)+(?=\()", "", side.strip())  # "A has components (2, 3)": the pair
    side = side.replace("−", "-").replace("–", "-")  # a minus typed as Unicode's
    pair = _pair(side)
    if pair is not None:
        return dict(zip(AXES, pair, strict=True))
    terms = _terms(side)
    if not terms:
        return None
    out: dict[str, list[str]] = {}
    bare: set[str] = set()  # the axes written as a bare n or t after a number
    for sign, term in terms:
        m = _TERM.match(term.strip())
        scaled = _scaled(term.strip(), depth) if m is None else None
        if scaled is not None:  # "15(cos a i + sin a j)": the number times each component
            for axis, c in scaled.items():
                out.setdefault(axis, []).append(sign + c)
            continue
        if m is None and (nt := _BARE_NT.match(term.strip())):  # "-1.110 n + 3.051 t"
            bare.add(nt.group(2))
            out.setdefault(nt.group(2), []).append(sign + (nt.group(1) or "1"))
            continue
        if m is None:
            return None
        coef = m.group(1)
        if not _coefficient(coef):
            return None  # "2pi", "v_Ai", "sin": not a coefficient of i
        coef = coef.strip().rstrip("*").strip() or "1"
        out.setdefault(UNITS[m.group(2)], []).append(sign + coef)
    if bare and set(out) != set(AXES):
        return None  # "3 t" alone: a number times a time, not a component
    return {axis: _joined(bits) for axis, bits in out.items()}


#: A number times a bare n or t (``1.110 n``, ``3.051t``): a component on the axis n or t, where a
#: vector is written with both (the notes' n and t axes, their unit vectors typed as the letters).
_BARE_NT = re.compile(r"^(\d+(?:\.\d+)?)?\s*\*?\s*([nt])$")


def _scaled(term: str, nested: int = 0) -> dict[str, str] | None:
    """``15(cos a i + sin a j)``, ``(u/sqrt(10))(i - 3j)``: a coefficient times a bracketed vector,
    by axis (each component times the coefficient); None where the term is not that."""
    if not term.endswith(")"):
        return None
    depth = 0
    for k in range(len(term) - 1, -1, -1):
        depth += {")": 1, "(": -1}.get(term[k], 0)
        if depth == 0:
            break
    coef, inner = term[:k].strip().rstrip("*").strip(), term[k + 1 : -1]
    if depth or (coef and not _coefficient(coef + " ")) or re.search(r"[A-Za-z]{2,}\d*$", coef):
        return None  # "sqrt(…)", "cos(…)": a function of the bracket, not a product
    pair = _pair(f"({inner.strip()})")
    part = dict(zip(AXES, pair, strict=True)) if pair is not None else _vector(inner, nested + 1)
    if part is None:
        return None
    return {axis: f"({coef})*({c})" if coef else f"({c})" for axis, c in part.items()}


def _coefficient(text: str) -> bool:
    """Whether ``text`` (what stands before a unit vector) is its coefficient: nothing, or it
    ends in a digit (not a name's: ``v_1i`` is a name), a bracket, a space or ``*``, or it is
    one letter (``ai``: a times i) or a number times one (``3bi``)."""
    if re.search(r"(?<![\d.])[A-Za-z]\w*\d$", text):
        return False  # "v_1i", "v1i": the name's own mark (A's initial), not v_1 times i
    if not text.strip() or re.search(r"[\d)*\s]$", text):
        return True
    # one letter, or a number times one (3b i: not 2pi)
    return re.fullmatch(r"\s*[A-Za-z]|\s*\d*\.?\d+\s*[A-Za-hj-oq-z]", text) is not None


def _joined(bits: list[str]) -> str:
    return " + ".join(bits).replace("+ -", "- ")


def _terms(side: str) -> list[tuple[str, str]]:
    """``3.05 e_t - 1.12 e_n`` -> [("", "3.05 e_t"), ("-", "1.12 e_n")]: the top-level terms."""
    out: list[tuple[str, str]] = []
    depth, start, sign = 0, 0, ""
    for k, c in enumerate(side):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if c in "+-" and depth == 0 and (k == 0 or side[:k].rstrip()[-1:] not in "*/^(eE"):
            if side[start:k].strip():
                out.append((sign, side[start:k].strip()))
            sign, start = c if c == "-" else "", k + 1
    if side[start:].strip():
        out.append((sign, side[start:].strip()))
    return out


def _pair(side: str) -> tuple[str, str] | None:
    """``(2, 2sqrt(3))`` -> ("2", "2sqrt(3)"); None where the side is not one pair."""
    if not (side.startswith("(") and side.endswith(")")):
        return None
    depth, comma = 0, None
    for k, c in enumerate(side):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth == 0 and k < len(side) - 1:
            return None  # "(a)(b)": not one bracket
        if c == "," and depth == 1:
            if comma is not None:
                return None
            comma = k
    if comma is None:
        return None
    first, second = side[1:comma].strip(), side[comma + 1 : -1].strip()
    return (first, second) if first and second else None
