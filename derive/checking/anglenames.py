"""An angle declared in words where the velocity it is the angle of is written as a name, not as
words: "Let β be the angle $\\mathbf{v}_A$ makes with the line of centres", "θ = the angle between
v_B and the wall", "phi is the angle v_1' makes with the l.o.c.", "Let $\\varphi$ denote the angle
between $\\vec{v}_{1f}$ and the line of centres", "β = angle between the vector v_B' and the line of
centres". A teacher reads the name as any name is read, by its body and its time: the body's letter
or the problem's label, 1 and 2 for the bodies where no letter gives one (at a wall or cushion the
one body's, its digits times: ``v_2`` after); after where it is primed, marked ``f`` or ``2``, or is
the habit's v (u, a mark ``i``, ``1`` or ``0`` are before). Each such name is put in words ("A's
velocity after", with "the vector" or "the velocity" before it taken in), and the line is read as
any declaration in words is (:func:`.wordnames.in_words`): an angle after the impact from the line of
centres is derive's beta, from the wall or the tangent derive's theta (its size, the acute angle the
words name). So declared, a later relation in it (θ = β − 30°) is judged with β as that angle truly
is, not as a slip before made it. A name of a velocity before is left as written: such an angle is
not declared here.
"""

from __future__ import annotations

import re

from derive.checking.context import Context

#: A velocity written as a name: ``v_A``, ``V_A'``, ``v'_A``, ``\mathbf{v}_A``, ``\vec v_B``,
#: ``v_{1f}`` (braces already dropped), ``u_1``; "the vector" or "the velocity" before it.
_VELOCITY_NAME = re.compile(
    r"(?:(?<![\w\\])the\s+(?:velocity|vector)\s+)?(?<![\w\\])"
    r"(?:\\(?:mathbf|vec|boldsymbol|bm|underline|overrightarrow)\s*)?(?P<base>[uvwV])\s*(?P<pre>['’′])?"
    r"\s*_\s*(?P<marks>[A-Za-z0-9,]{1,4})(?![A-Za-z0-9])(?:\s*(?P<prime>['’′]|\^\s*\\prime))?"
)

#: Words after the name that say already that it is after the impact.
_SAID_AFTER = re.compile(r"\s*(?:after|afterwards|now)\b", re.I)


def velocities_in_words(plain: str, ctx: Context) -> str:
    """``plain`` with each velocity after the impact written as a name put in words: ``the angle
    v_A makes with`` -> ``the angle A's velocity after makes with``; a velocity before, or a name of
    no body, as it is; LaTeX's variant of a Greek letter as the letter (``\\varphi``: φ)."""

    def words(m: re.Match) -> str:
        body = after_body(m, ctx)
        if not body:
            return m[0]
        said = _SAID_AFTER.match(plain, m.end()) is not None  # "v_A after the impact": said already
        return f"{body}'s velocity" + ("" if said else " after")

    plain = re.sub(r"\\var(phi|theta|epsilon)(?![A-Za-z])", r"\\\1", plain)  # \varphi: the letter φ
    return _VELOCITY_NAME.sub(words, plain)


def after_body(m: re.Match, ctx: Context) -> str:
    """The body ("A", "B") whose velocity after the impact the name in ``m`` is; "" where it names
    a velocity before (``u_A``, ``v_{1i}``) or no body."""
    marks = (m["marks"] or "").replace(",", "")
    labels = dict(zip(ctx.problem.labels, "AB", strict=True)) | {"A": "A", "B": "B"}
    letters = [labels[c] for c in marks if c in labels]
    digits = [c for c in marks if c.isdigit()]
    if getattr(ctx.problem, "fixed_B", False) and set(letters) <= {"A"}:
        body, before = "A", "1" in digits or "0" in digits  # the one body at a wall: v_2, v_f, v' after
    elif letters:
        body, before = letters[0], "1" in digits or "0" in digits
    elif digits and digits[0] in "12":
        body, before = "A" if digits[0] == "1" else "B", "0" in digits
    else:
        return ""
    before = before or "i" in marks or (m["base"] == "u" and "f" not in marks and not (m["prime"] or m["pre"]))
    return "" if before else body
