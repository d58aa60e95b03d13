"""Components a student labels in words (``Along the line of centres A has u sin 30°``,
``Component of A's velocity along the line of centres = …``): each relation's body.

Holds the phrases and :func:`body_labels`; imports only mathtext's Relation.
"""

from __future__ import annotations

import re
from dataclasses import replace

from derive.mathtext.reader import Relation

#: "the component of A's velocity" before "along the line of centres" (the body is its label).
#: Or "A's velocity" itself before the axis words ("A's velocity along line of centres = u cos(alpha)").
COMPONENT_OF = re.compile(
    r"^\s*(?:(?:the\s+)?component\s+of\s+([AB])['’]s\s+(?:initial\s+)?velocity\s+"
    r"|([AB])['’]s\s+(?:initial\s+)?velocity\s+(?=along\b|across\b|perp|parallel\b))",
    re.I,
)
#: A component named by its axis alone: "along the line of centres", "perpendicular to it".
_AXIS_ONLY = re.compile(
    r"^\s*(?:along|across|perpendicular(?:\s+to)?)(?:\s+(?:it|the\s+line(?:\s+of\s+(?:centres|impact))?))?\s*$", re.I
)


#: "Along the line of centres A has u sin 30°", "across it u cos 30°": a component, then its value.
_HAS = re.compile(
    r"^\s*((?:along|across|perpendicular\s+to)\s+(?:it|the\s+line\s+of\s+(?:centres|impact)))\s*,?\s*"
    r"(?:([AB])\s+has\s+)?(\S.*)$",
    re.I,
)


def body_labels(relations: list[Relation]) -> tuple[list[Relation], list[str]]:
    """The relations, a component's value named in words split off (``Along the line of centres
    A has u sin 30° = u/2`` -> ``along the line of centres = u sin 30° = u/2``), and each one's
    body: its lead-in (``A:``), else the body its first side names a component of
    (``Component of A's velocity along the line of centres = …``), else, for a component named
    by its axis alone (``perpendicular to the line of centres = …``), the body of such a
    component just before."""
    out, labels, body = [], [], ""
    for r in relations:
        r = _letter_lead(r)  # "perp: B 2sin60=1.732": B's lead-in, its colon left out
        m = COMPONENT_OF.match(r.sides[0])
        h = _HAS.match(r.sides[0]) if not r.label else None
        if m:
            body = (m.group(1) or m.group(2)).upper()
            labels.append(r.label or body)
        elif h and (h.group(2) or body):
            body = (h.group(2) or body).upper()
            r = replace(r, sides=(_unsigned(h.group(1), h.group(3)), h.group(3), *r.sides[1:]))
            labels.append(body)
        elif not r.label and body and _AXIS_ONLY.match(r.sides[0]):
            r = replace(r, sides=(_unsigned(r.sides[0], r.sides[1]), *r.sides[1:]))
            labels.append(body)
        else:
            body = "" if r.label else body
            if r.label and len(r.sides) > 1 and _AXIS_ONLY.match(r.sides[0]):  # "B: across = 15 sin 37.6°"
                r = replace(r, sides=(_unsigned(r.sides[0], r.sides[1]), *r.sides[1:]))
            labels.append(r.label)
        out.append(r)
    return out, labels


#: A body's letter before its value with the colon left out (``B 2cos60=1``, ``A 3(0.6)``): the
#: body's lead-in, never a product (a body's letter is no quantity).
_LETTER_LEAD = re.compile(r"^\s*([AB])\s+(?=[\d.(−-])(.+)$")
#: The axis a line's words before its colon name (``alongXY:``, ``perp:``, ``across:``, ``⊥:``).
_AXIS_HEAD = re.compile(r"^\s*(?:(along|par(?:a|allel)?\b|∥)|(perp|across|⊥))[^:]{0,24}:", re.I)  # not "Part (a):"


def _letter_lead(r: Relation) -> Relation:
    """``B 2cos60 = 1`` -> ``B: 2cos60 = 1``; under an axis's heading (``alongXY: …, B 2cos60=1``,
    ``perp: B 2sin60=1.732``) the body's component along that axis, ``B: along = 2cos60 = 1``."""
    m = _LETTER_LEAD.match(r.sides[0]) if len(r.sides) > 1 else None
    if m is None:
        return r
    head = _AXIS_HEAD.match(r.written)
    axis = ("along" if head.group(1) else "across") if head else ""
    return replace(r, sides=(*([axis] if axis else []), m.group(2), *r.sides[1:]), label=m.group(1))


def _unsigned(words: str, value: str) -> str:
    """The words naming the axis across the line of centres, marked where the value after them is
    written unsigned (``across it A has u sin 30°``): a size, in the student's own direction across."""
    if re.match(r"\s*(?:across|perpendicular)", words, re.I) and not value.lstrip().startswith("-"):
        return words + " " + SIZE
    return words


#: The mark :func:`_unsigned` puts on the words naming an axis across, read as ``A_T`` (:func:`.axisnames.letter_components`).
SIZE = "unsigned"


#: A body's component said in words with its time (``A's component after``, ``B's final component``),
#: its axis said by the lead-in before it (``Perp: Q's component after = u sin α``, the statement's Q
#: already written as its body by :mod:`.bodywords`).
_COMPONENT_WORDS = re.compile(
    r"(?<![\w'])([AB])['’]s\s+(?:(initial|final)\s+)?component(?:\s+(before|after|initially|finally))?(?![\w'])",
    re.I,
)
_LOC = r"(?:\s+(?:to\s+)?(?:it|(?:the\s+)?(?:l\.?\s?o\.?\s?c\.?|line\s+of\s+(?:centres|centers|impact))))?"
_LEAD_N = re.compile(rf"(?:along|parallel(?:\s+to)?|par\.?|∥){_LOC}|(?:common\s+)?normal", re.I)
_LEAD_T = re.compile(rf"(?:perp(?:\.|endicular)?|⊥|across){_LOC}|(?:common\s+)?tangent(?:ial)?", re.I)


#: A body's component said in words with its axis first (``⊥ cpt A after``, ``perpendicular
#: component of A after``, ``A's along-loc component before``, ``B's perp cpt after``).
_AXIS = r"(?:(?P<n>along|parallel|par\.?|∥|normal)|(?P<t>perp(?:\.|endicular)?|⊥|across|tangential))" + _LOC
_CPT = r"(?:component|compt?|cpt)\.?"
_WHEN = r"(?P<when>before|after|initially|finally)(?:\s+(?:the\s+)?(?:impact|collision))?"
_AXIS_FIRST = re.compile(
    rf"(?<![\w'’])(?:the\s+)?(?:{_AXIS}[\s-]+{_CPT}(?:\s+of)?\s+(?P<body>[AB])(?:['’]s)?(?:\s+velocity)?"
    rf"|(?P<owner>[AB])['’]s\s+{_AXIS.replace('P<n>', 'P<n2>').replace('P<t>', 'P<t2>')}[\s-]+{_CPT})\s+{_WHEN}(?![\w'’])",
    re.I,
)


def _axis_first(m: re.Match) -> str:
    axis = "n" if m["n"] or m["n2"] else "t"
    time = "2" if m["when"].lower() in ("after", "finally") else "1"
    return f"v_{(m['body'] or m['owner']).upper()}{time}{axis}"


def component_words(text: str, label: str) -> str:
    """``A's component after`` under a lead-in naming the axis (``Perp:``, ``Along l.o.c.:``) as
    derive's name of that component (``v_A2t``): along the line of centres n, across it t; so
    too a component with its axis said before it (``⊥ cpt A after``: ``v_A2t``)."""
    whole = said_component(text)
    if whole:
        return whole
    text = _AXIS_FIRST.sub(_axis_first, text)
    lead = label.strip().rstrip(":").strip()
    axis = "n" if _LEAD_N.fullmatch(lead) else "t" if _LEAD_T.fullmatch(lead) else ""
    if not axis:
        return text

    def named(m: re.Match) -> str:
        when = (m[2] or m[3] or "").lower()
        time = "2" if when in ("final", "after", "finally") else "1" if when else ""
        return f"v_{m[1].upper()}{time}{axis}" if time else m[0]

    return _COMPONENT_WORDS.sub(named, text)


#: The words of a body's component named in words, in whatever order the student says them: the
#: body, the axis, the instant, and the words between (``Q's component perpendicular after``,
#: ``A after ⊥``, ``after, B along the l.o.c.``, ``the velocity of B across the line of centres
#: after``).
_WORD = re.compile(r"[A-Za-z.]+(?:['’]s)?|[∥⊥]|[,:-]")
_N_WORDS = {"along", "parallel", "par", "par.", "∥", "normal"}
_T_WORDS = {"perp", "perp.", "perpendicular", "⊥", "across", "tangential", "tangent"}
_TIMES = {"before": "1", "initially": "1", "initial": "1", "after": "2", "finally": "2", "final": "2"}
_FILLERS = {
    *[
        "the",
        "of",
        "to",
        "it",
        "its",
        "line",
        "centres",
        "centers",
        "impact",
        "collision",
        "l.o.c.",
        "l.o.c",
        "loc",
        "lc",
        "component",
        "compt",
        "cpt",
        "cpt.",
    ],
    *["velocity", "speed", "sphere", "ball", "particle", "disc", "puck", "body", ",", ":", "-"],
}


def said_component(side: str) -> str:
    """Derive's name of the component a side names in words alone (``v_A2t`` for ``Q's component
    perpendicular after``, the statement's Q already written A), whatever the order of its words:
    exactly one body, one axis and one instant, and nothing but words between; else ""."""
    words = _WORD.findall(side)
    if "".join(words).replace(" ", "") != re.sub(r"\s+", "", side) or not 3 <= len(words) <= 12:
        return ""
    bodies, axes, times = [], [], []
    for w in words:
        low = w.lower()
        if re.fullmatch(r"[AB](?:['’]s)?", w):
            bodies.append(w[0])
        elif low in _N_WORDS or low in _T_WORDS:
            axes.append("n" if low in _N_WORDS else "t")
        elif low in _TIMES:
            times.append(_TIMES[low])
        elif low not in _FILLERS:
            return ""
    if len(bodies) != 1 or len(axes) != 1 or len(times) != 1:
        return ""
    return f"v_{bodies[0]}{times[0]}{axes[0]}"
