"""One piece of a line split into its relations: at arrows and words such as "so" (in the
student's language), at ";", at a colon between two relations and at a comma before another.

Imports only mathtext's leaf modules.
"""

from __future__ import annotations

import re

from derive.mathtext.arrows import arrows_said
from derive.mathtext.laws import with_its_letters
from derive.mathtext.notes import GAP_THEN_NAME, SO_ABROAD, UNIT_THEN_NAME
from derive.mathtext.percents import per_cent_of
from derive.mathtext.sides import LONE_VALUE, html_marks

_ARROW = re.compile(
    r"⇔|⟺|<=>|⇒|⟹|→|=>|->|∴|\\(?:Rightarrow|Longrightarrow|Leftrightarrow|Longleftrightarrow|implies|rightarrow|to|therefore|iff)\b|(?<![\w.])(?:so|hence|thus|then|therefore|giving|gives|and|but|whereas|or|at|"
    + SO_ABROAD
    + r")(?![\w])",
    re.I,
)
_RELATION = re.compile(r"=|≈|≃|≅|∼|(?<=\s)~(?=\s)")


#: A name set equal to two values, the roots of a quadratic (``x = 5 or 2``, ``v = u/2 or 5u/6``).
_OR_VALUE = re.compile(
    r"(?<![\w\\])(?P<name>[A-Za-z](?:_\w+)?)\s*=\s*(?P<a>[^=;,]+?)\s+or\s+(?P<b>[^=;,\s][^=;,]*?)\s*$", re.I
)


def split_relations(plain: str) -> list[str]:
    """The relations of one piece: split at arrows, "so", ";" and at a comma (outside
    brackets) that comes before another relation."""
    plain = re.sub(r"(?<=\s)~(?=\s)|≃|≅|∼", "=", plain.replace("≈", "="))  # "v ~ 4": about, as ≈
    plain = re.sub(r"(?<=\s)&(?=\s+[^=&]*=)", " ; ", plain)  # "a = 1 & b = 2" in plain text: and
    plain = re.sub(
        r"(\d|\)|/s|J|kg)\s+y\s+(?=[A-Za-z][\w']*\s*=)", r"\1 ; ", plain
    )  # Spanish "and": "= 4 m/s y v_B = 8"
    plain = per_cent_of(_remarks_apart(plain))  # "(e = 0)": a remark; "KE after = 60% of before": of T_1
    plain = _OR_VALUE.sub(r"\g<name> = \g<a> or \g<name> = \g<b>", plain)  # x = 5 or 2: two roots
    parts: list[str] = []
    plain = re.sub(
        r"(?<=[A-Za-z)]{2})\.\s+|(?:(?<=[\w)°²³←→↑↓])|(?<=<-|->))(?<!i\.e)(?<!e\.g)\.\s+(?=[^\s(=≈+\-*/^,;:<>])"
        r"|(?<=[\w)])\s+\.\s+(?=[A-Z][a-z])",  # "$y = u$. Speed of Q …": the stop after the mathematics
        " ; ",
        plain,
    )  # a sentence ends (after an arrow too: "= 2 m/s ←. Taking → as positive")
    plain = UNIT_THEN_NAME.sub(_two_givens, plain)  # "m_p = 0.150kg v=35.0 m/s": two givens
    plain = _VERB_THEN_NAME.sub(" ; ", plain)  # "m_2 = 7500 kg has v_2i = 0": two givens, the verb dropped
    plain = GAP_THEN_NAME.sub(r"\1 ; ", plain)  # "x = 2      y = 3": side by side
    plain = _TIGHT_THEN_NAME.sub(r"=\1 ; ", plain)  # "ma=5 mb=3 e=3/4": givens listed, a space apart
    plain = arrows_said(html_marks(plain))  # v<sub>A</sub>; "(+→)": a convention; "= 1.6 m/s ←": to the left
    for chunk in _arrow_split(plain):
        for piece in _top_level_split(chunk, ";"):
            for part in _colon_split(piece):
                parts += with_its_letters(_comma_split(part))  # "v^2 = u^2 + 2as with u = 0, s = 2 m"
    return [p for p in parts if _RELATION.search(p)]


#: A value (its unit after it, if any) then a verb of what a body has or does, and a name set
#: equal to a value: two relations, the verb no part of either (``m_2 = 7500 kg has v_2i = 0``,
#: ``m_B = 2 kg is moving with velocity u_B = 3``). Words of a direction or a condition (``to the
#: left``, ``when e = 1``) are not such verbs: they say what the value is, or when.
_VERB_THEN_NAME = re.compile(
    r"(?<=[\d)])(?:\s*(?:kg|g|m/s|ft/s|km/h|mph|N|J|lb|slugs?|N\s?s))?\s+"
    r"(?:has|had|have|gets|got|goes|went|moves|moved|travels|travell?ed|is|was|are|were|starts|started|comes|came)"
    r"(?:\s+(?:a|an|the|velocity|speed|initially|now|still|initial|final|moving|travell?ing|going|with|of)){0,3}"
    r"\s+(?=[A-Za-z]\w{0,5}\s*=(?!=))",
    re.I,
)


#: A name typed against its "=" and a number against it, a space, then another name against its
#: "=" (``ma=5 mb=3 e=3/4``, phone-typed givens): two relations, not ``mb = 3e``; a product is typed
#: with its factors together (``v=2u=8``).
_TIGHT_THEN_NAME = re.compile(r"(?<=[\w)'])=([-+]?\d[\d.]*(?:/\d+)?)\s+(?=[A-Za-z]\w{0,5}'*=[^=\s])")


def _remarks_apart(plain: str) -> str:
    """Each bracket (its own brackets inside it balanced) that holds a relation, as a piece of its
    own: ``= 0.837 (check: sqrt(1.4/2) = sqrt(0.7) = 0.837)``, ``lock together (e = 0)``."""
    out, depth, start = [], 0, None
    for i, c in enumerate(plain):
        if c == "(":
            start = i if depth == 0 else start
            depth += 1
        elif c == ")" and depth:
            depth -= 1
            if depth == 0 and start is not None and "=" in plain[start:i]:
                out.append((start, i))
    for start, end in reversed(out):
        plain = f"{plain[:start]} ; {plain[start + 1 : end]} ; {plain[end + 1 :]}"
    return plain


#: A mass's name before its "=" (``m``, ``m_A``, ``M2``, ``mass``): a number after it in grams is a given.
_MASS_BEFORE = re.compile(r"(?:^|[\s,;:(])(?:[mM](?:_?\{?\w{1,3}\}?)?|mass(?:\s+of\s+\w+)?)\s*$")


def _two_givens(m: re.Match) -> str:
    """``m = 50 g v = 3`` -> two givens; but ``v^2 = 2 g h = 2(9.8)(2)``: g is gravity there,
    the number's "g" a gram only after a mass's name."""
    value = m.group(1)
    if re.search(r"\dg$|\d\sg$", value) and not _MASS_BEFORE.search(m.string[: m.start()]):
        return m.group(0)
    return value + " ; "


def _arrow_split(plain: str) -> list[str]:
    """``plain`` split at its arrows and words such as "so", outside brackets (``-1.2 (so speed
    1.2)`` is one piece)."""
    out, start = [], 0
    for m in _ARROW.finditer(plain):
        head = plain[: m.start()]
        if head.count("(") > head.count(")") or (m.group(0).lower() == "at" and re.search(r"[-+*/=()]\s*$", head)):
            continue  # "v = u + at": a product, not "at"
        out.append(plain[start : m.start()])
        start = m.end()
    return [*out, plain[start:]]


#: A lead-in after a comma at the end of a piece, before a colon (``…, y``, ``…, B after``), or a
#: one-word label after a relation's value and a space (``n: 4sin30 = 2   t: 4cos30 = 3.46``: t
#: leads in the next, not 2t; a unit stays the value's, ``m = 0.5 kg: T = …``).
_LEAD_END = re.compile(
    r"(?:,\s*([A-Za-z][\w' ]{0,30}?)|(?<=[\d)])\s+(?!(?:kg|g|m|s|N|J|Ns|lb|ft|mph|deg|rad|km|cm|mm|slugs?)\s*$)"
    r"([A-Za-z]\w{0,5}))\s*$"
)


def _colon_split(piece: str) -> list[str]:
    """``Substituting b = a + 6: 8a + 18 = -8`` -> two: a colon between two relations ends the
    first (one after words alone, ``CLM: …``, leads in and stays)."""
    bits = [b for b in re.split(r":(?!=)", piece)]
    out: list[str] = [bits[0]]
    for bit in bits[1:]:
        if "=" in bit and "=" in out[-1] and out[-1].count("(") == out[-1].count(")"):
            lead = _LEAD_END.search(out[-1])  # "x: 2cos60 = 1, y: 2sin60 = 1.73": y leads in the next
            if lead and "=" in out[-1][: lead.start()]:
                out[-1], bit = out[-1][: lead.start()], f"{lead.group(1) or lead.group(2)}:{bit}"
            out.append(bit)
        else:
            out[-1] += ":" + bit
    return out


#: A body's or a quantity's lead-in after a comma (``A: 4cos60 = 2, B: -6``): a piece of its own.
_LABEL = re.compile(r"^\s*[A-Za-z][\w' ]{0,30}:(?!=)")


#: An answer by its label, a value in words after it (``B: 3.05 m/s to the right``): no part of the
#: relation after its comma (``…, e = 0.7125``).
#: A sign convention before a comma (``up +ve, impulse = …``, ``taking left as positive, v = …``).
_SIGN_SAID = re.compile(r"(?:\+\s?ve|\bpositive|\(\+\))\s*(?:now|here|again|this\s+time)?\s*$", re.I)
_ANSWER = re.compile(r"^\s*[A-Za-z][\w' ]{0,30}:(?!=)\s*[-+]?\d[\d.]*\s*(?:[A-Za-z/ ]*)$")


def _comma_split(piece: str) -> list[str]:
    """``a = 1, b = 2`` -> two; ``atan2(a, b) = 3`` and ``x = 1, 2`` stay one; ``A: 2, B: -6``
    two."""
    bits = _top_level_split(piece, ",")
    out: list[str] = []
    for bit in bits:
        if out and (
            (
                "=" in bit
                and (
                    "=" in out[-1]
                    or _ANSWER.match(out[-1])
                    or _SIGN_SAID.search(out[-1])
                    or LONE_VALUE.fullmatch(out[-1])
                )
            )
            or _LABEL.match(bit)
        ):
            out.append(bit)  # "(at) 35.0 m/s, goalie M = 70.0 kg": the speed is no part of M's side
        elif out:
            out[-1] += "," + bit
        else:
            out.append(bit)
    return out


def _top_level_split(s: str, sep: str) -> list[str]:
    out, depth, start = [], 0, 0
    for i, c in enumerate(s):
        depth = max(0, depth + {"(": 1, "[": 1, "{": 1, ")": -1, "]": -1, "}": -1}.get(c, 0))  # "3) k=…": a list's mark
        if c == sep and depth == 0:
            out.append(s[start:i])
            start = i + 1
    out.append(s[start:])
    return out
