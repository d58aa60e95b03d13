"""What a student writes around a relation that is not part of it, as a teacher reads it.

A note after a relation: an equation's tag (``...(1)``, ``--(2)``, ``[3]``, ``eqn 4``), the
unrounded value in brackets (``V = 1.49 m/s (1.4925)``, ``e = 0.172 (5/29)``), a remark in square brackets
(``[w left, 2.9 right]``). A line the student withdraws (``<- no, wrong side``, ``(crossed
out)``, ``no wait, …``, ``~~x = 3~~``): what it withdraws is never marked. A sentence that turns
a root down in words (``if x = 5u/6 then y = u/3 < x, impossible``, ``… can't happen``): its
relations are a rejected case. A goal (``show e = …``, ``prove that …``): what is to be shown,
not a claim. Markdown's bold (``**CLM:**``) is layout.

>>> without_note("V = 1.49 m/s   (1.4925)")
('V = 1.49 m/s', '')
>>> without_note("12u = 7x + y      ...(1)")
('12u = 7x + y', '1')
>>> unmarked("M = 0.58 - 0.3 = 0.28   <- no, wrong side")
''
"""

from __future__ import annotations

import re

from derive.mathtext.asides import case_before, named_after
from derive.mathtext.bodysides import body_side
from derive.mathtext.latex import REJECTED
from derive.mathtext.notation import FUNCTIONS
from derive.mathtext.parser import GREEK
from derive.mathtext.roundedagain import without_rounded_again
from derive.mathtext.units import is_unit

_MATH = GREEK | FUNCTIONS | {"pi", "deg", "rad"}

#: Markdown bold or italics around words (``**CLM:**``, ``__Answer__``); not ``u**2``.
_BOLD = re.compile(r"(?<![\w*])(\*\*|__)(?=\S)([^*\n]*?\S)\1(?![\w*])")
#: Struck-out text (Markdown ``~~…~~``, LaTeX ``\sout{…}``, ``\st{…}``, ``\xout{…}``).
#: A bold letter glued to what is around it, a vector in Markdown (``9**i**``, ``**u**_A``).
_BOLD_LETTER = re.compile(r"\*\*([A-Za-z])\*\*")
_STRUCK = re.compile(r"~~[^~\n]*~~|\\(?:sout|st|xout)\{[^{}]*\}")
_NO = r"(?:no\b|nope|wrong|mistake|oops|error|ignore|scrap|scratch|cross(?:ed)?|not\s+this|redo|x\b|✗)"
#: A withdrawal of what comes before it on the line.
_WITHDRAWN = re.compile(
    rf"(?:<-+|←|⟵|<=+(?=\s*[A-Za-z]))\s*{_NO}|\?+\s*(?:no|nope)\b(?=\s*[-—–,.;:!])"  # "= -2.9? No -- …"
    rf"|[(\[]\s*(?:wrong|crossed\s+out|ignore(?:\s+this)?|scrap(?:\s+that)?|mistake|oops|withdrawn|redone\s+below)\s*[)\]]"
    r"|\b(?:no\s+wait|wait\s+no|oops|scratch\s+that|scrap\s+that|ignore\s+(?:this|that)(?:\s+line)?|crossed\s+out)\b",
    re.I,
)
#: A root or case turned down in words ("can't be right" is a doubt about the value, not a case
#: turned down: the line still stands and is marked).
_REJECTS = re.compile(
    r"\b(?:impossible|not\s+possible|(?:can't|cannot|can\s+not|couldn't|won't|doesn't|does\s+not)\s+"
    r"(?:happen|be(?!\s+(?:right|correct|true)\b)|work|occur)"
    r"|rejected|reject(?:\s+(?:it|this|that))?|discard(?:ed)?|not\s+physical|unphysical"
    r"|not\s+valid|invalid|no\s+good|not\s+allowed)\b",
    re.I,
)
#: The most rejections and goals looked at in one line.
_MOST = 8
#: A goal: what is to be shown, not a claim (``show e = …``, ``prove that …``, ``to show:``).
_GOAL = re.compile(r"\b(?:show|prove|verify|deduce)\s+(?:that\s+)?", re.I)  # with an "=" after it
#: Where a sentence ends in a line: a full stop before a capital, a semicolon.
_SENTENCE_END = re.compile(r"(?<=[\w)°²³])\.(?=\s+[A-Z(])|;")


#: Markdown's inline code marks and a blockquote's mark at the start of a line.
_CODE_QUOTE = re.compile(r"`+|^\s*>+(?=\s)")


#: Markdown italics with one star around words and a space (``*v = 3 m/s*``); not ``2*u*3``.
_ITALIC = re.compile(r"(?:^|(?<=[\s(]))\*(?=[^\s*])([^*\n]*?\s[^*\n]*?[^\s*])\*(?=$|[\s.,;:)])")


def unbold(text: str) -> str:
    """``text`` without Markdown's layout: bold and italics around words (``**momentum:**``,
    ``*v = 3 m/s*``), inline code marks (```v_B = 2.4```), a blockquote's ``>``."""
    return _CODE_QUOTE.sub(" ", _ITALIC.sub(r"\1", _BOLD.sub(r"\2", _BOLD_LETTER.sub(r"\1", text))))


def unmarked(text: str) -> str:
    """``text`` without what a teacher does not mark: struck-out working, what a withdrawal note
    withdraws (all before it; the line after ``no wait,`` is kept), a case rejected in words
    (what comes before it in its sentence) and a goal to be shown (to the end of its sentence)."""
    text = _STRUCK.sub(" ", text)
    m = next(reversed(list(_WITHDRAWN.finditer(text))), None)  # the last: what comes after it stands
    if m is not None:
        after = text[m.end() :]
        text = after.lstrip(" ,;:.") if "=" in after else ""
    for pattern, whole in ((_REJECTS, True), (_GOAL, False)):
        for m in reversed(list(pattern.finditer(text))[:_MOST]):
            if _in_brackets(text, m.start()) or (not whole and m.end() > text.rfind("=")):
                continue  # "x = 3 (rejected)": the reader turns that relation down itself
            # a rejection turns down what comes before it in its sentence; a goal runs to the end
            start, end = (
                (_sentence_start(text, m.start()), m.end()) if whole else (m.start(), _sentence_end(text, m.end()))
            )
            start = case_before(text, m.start(), start) if whole else start  # "… through Q. Reject."
            start, end = (m.start(), named) if whole and (named := named_after(text, m.end())) else (start, end)
            text = text[:start] + " " * (end - start) + text[end:]
    return text


def _in_brackets(text: str, i: int) -> bool:
    head = text[:i]
    return head.count("(") > head.count(")") or head.count("[") > head.count("]")


def _sentence_start(text: str, i: int) -> int:
    ends = [m.end() for m in _SENTENCE_END.finditer(text, 0, i)]
    return ends[-1] if ends else 0


def _sentence_end(text: str, i: int) -> int:
    m = _SENTENCE_END.search(text, i)
    return m.start() if m else len(text)


#: An equation's tag after a relation: ``(1)``, ``...(2)``, ``…(3)``, ``--(4)``, ``[1]``, ``{2}``,
#: ``eqn 1``, ``(eq. 2)``, ``(i)``; a number of 10 or more only after dots or a wide gap.
_TAG = re.compile(
    r"(?:(?P<gap>\s{2,}|\s*(?:\.{2,}|…|-{2,}|—)\s*)|\s)"
    r"(?:\(\s*(?:eqn?\.?\s*)?(?P<a>\d{1,2}[a-z]?|[ivx]{1,4})\s*\)|\[\s*(?P<b>\d{1,2}[a-z]?)\s*\]"
    r"|\{\s*(?P<c>\d{1,2})\s*\}|eqn?\.?\s*(?P<d>\d{1,2}))\s*$"
)
#: A part's label after a relation (``= 0.250 m/s   (a)``, ``… kg (b)(ii)``, ``-- part (c)``, ``[b]``,
#: ``Ans (a)``): after a gap, dots or a dash, or after a unit; not a factor (``= 2 (a)`` stays).
_PART_END = re.compile(
    r"(?:\s{2,}|\s*(?:\.{2,}|…|-{2,}|—|–)\s*|(?<=[A-Za-z/²³¹°.])\s+)"
    r"(?:(?:ans(?:wer)?\.?|part)\s*)?[(\[]\s*[a-h]\s*[)\]](?:\s*[(\[]\s*[ivx]{1,4}\s*[)\]])?\s*\.?\s*$",
    re.I,
)
#: A number in brackets after a value (its unrounded value, or more figures); a unit's words part at spaces only.
_UNROUNDED = re.compile(
    r"(?<![\w.])(?P<value>[-+]?\d[\d.]*)(?P<unit>(?:\s?[A-Za-z/^\-·*°%⁻¹²](?:[A-Za-z/^\-·*°%⁻¹²1]|\s(?=[A-Za-z/^\-·*°%⁻¹²]))*)?)"
    r"(?P<gap>\s+)\(\s*[≈=~]?\s*(?P<more>[-+]?\d[\d.]*(?:\s*/\s*\d+(?:\.\d+)?)?)[A-Za-z/^\-\s·*⁻¹°%]*\)(?P<later>\s*[A-Za-z][A-Za-z/^\-·*⁻¹²1]*(?:\s[A-Za-z][A-Za-z/^\-·*⁻¹²1]*)?)?\s*$"
)
#: A remark in square brackets after a relation, with a word in it (``[w left, 2.9 right]``).
_SQUARE = re.compile(r"\s+\[([^\[\]=^_]*)\]\s*$")


#: Words after a tick (``= u  ✓ speed of Q is u``): the student's comment on the line.
_AFTER_TICK = re.compile(r"\s*(?:✓|✔|☑|\\(?:checkmark|cmark|tick|ding\s*[{(]\s*5[12]\s*[})])(?![A-Za-z]))\s*[^=✓✔]*$")
#: A clause after a comma that says no more of the value (``= u(2 + 3e), in its original direction``).
_CLAUSE = re.compile(
    r"\s*(?:,|[—–])\s*(?:in|along|which|that|as|moving|travelling|going|directed|the|unchanged|unaltered|unaffected|constant"
    r"|conserved|same)\b"
    r"(?![^=\d]*\b(?:left|right|backwards?|forwards?|opposite|same|other\s+way)\b)[^=\d()\[\]]*$",
    re.I,
)


#: A pointer after a relation (``<- answer``, ``← this one``); one that withdraws it is :func:`unmarked`'s.
_POINTER = re.compile(r"\s*(?:<-+|←|⟵)[^=<>]*$")
#: The figures it is given to (``(3 s.f.)``, ``(to 1 d.p.)``, ``(3sf)``, ``to 3 sig figs``).
_FIGURES = re.compile(
    r"(?:\s*\(\s*|\s+)(?:(?:to|correct\s+to|rounded\s+to)\s+)?\d\s?(?:s\.?\s?f\.?|d\.?\s?p\.?|sig\.?\s?figs?\.?"
    r"|significant\s+figures?|decimal\s+places?)\s?\)?\s*\.?\s*$",
    re.I,
)
#: The mark that ends a proof (``∎``, ``□``, ``\\qed``, ``QED``, ``Q.E.D.``, ``//``) and a bracket of
#: only ``!`` or ``?`` (``(!!)``): no part of the relation.
#: A mark scheme's marks after a line (``(A1)``, ``(M1 A1)``, ``(dM1)``, ``(A1ft)``): the marker's, not maths.
_SCHEME_MARKS = re.compile(
    r"(?<=[\w)\]}$.])\s+(?:\(\s*d?[MABE]\d(?:\s*(?:ft|cao|cso|oe))?(?:[\s,]+d?[MABE]\d(?:\s*(?:ft|cao|cso|oe))?)*\s*\)\s*)+$"
)
_END_MARK = re.compile(
    r"\s*(?:∎|□|■|◻|◼|▪|\\(?:qed|qedsymbol|blacksquare|square|Box)(?![A-Za-z])(?:\{\})?|\b(?:Q\.\s?E\.\s?D\.?|QED)(?!\w))"
    r"[\s.!$]*$|(?<=\s)//\s*$|\s*\(\s*[!?]+\s*\)\s*$"
)
#: A comment as code has it after the value (``= 4 m/s  // A carries on``, ``# check``): words.
_CODE_COMMENT = re.compile(r"(?<=[\w.)°])\s+(?://|#)\s*(?=[A-Za-z]).*$")
#: The value again in brackets in another unit, as an aside (``35.2 m/s (~127 km/h!!)``,
#: ``(about 9.8 N)``, ``(= 0.5 kJ)``); the unit inside must be a unit.
_CONVERTED = re.compile(
    r"(?<=[A-Za-z°%²³¹])(?P<gap>\s+)\(\s*(?:[≈~=]|about|approx\.?|around|roughly|i\.e\.?|so)?\s*"
    r"[-+]?\d[\d.,]*\s*(?:[x×*]\s*10\^?[-+]?\d+\s*)?(?P<unit>[^()=\d!?][^()=!?]*?)\s*[!?.]*\s*\)[!?.]*\s*$",
    re.I,
)
#: The same after a dash and a word that says it is the same value (``35.2 m/s - about 127 km/h``).
_DASH_CONVERTED = re.compile(
    r"(?<=[A-Za-z°%²³¹])(?P<gap>\s+)[-–—]+\s*(?:≈|~|about|approx\.?|around|roughly|i\.e\.?|so|that's|that\s+is)\s*"
    r"[-+]?\d[\d.,]*\s*(?P<unit>[^()=\d!?][^()=!?]*?)\s*[!?.]*\s*$",
    re.I,
)
#: Words that say a direction (kept for the reader: ``= 1.04 m/s (to the left)``).
_WAYS = re.compile(r"\b(?:left|right|(?:back|for)ward|opposite|same|other way|up|down|away from|off the|toward)", re.I)


def _remark_in_brackets(text: str) -> str:
    """``text`` without a remark in brackets at its end that starts with a word (``(from (1))``,
    ``(by CLM)``): brackets nested or not, no ``=`` in it, no direction in it."""
    if not text.endswith(")"):
        return text
    depth = 0
    for i in range(len(text) - 1, -1, -1):
        depth += {")": 1, "(": -1}.get(text[i], 0)
        if depth == 0:
            inner = text[i + 1 : -1]
            head = re.match(r"\s*([A-Za-z]{2,})\b", inner)
            if (
                i > 0
                and text[i - 1] == " "
                and head
                and head.group(1).lower() not in _MATH
                and "=" not in inner
                and not _WAYS.search(inner)
                and not REJECTED.search(inner)
                and not _REJECTS.search(inner)
            ):
                return text[:i].rstrip()
            return text
    return text


#: A percentage in brackets after a value (``= 64 J (18.2%)``, ``(≈ 18 % of the KE lost)``): an aside.
_PERCENT = re.compile(r"(?:(?<=[A-Za-z])\s*|(?<=[\w.)])\s+)\(\s*[≈~=]?\s*(?:about\s+)?\d[\d.,]*\s*%[^()=]*\)\s*\.?\s*$")
#: The value said again in brackets as a speed and a direction (``= -0.025 m/s (i.e. 0.025 m/s ←)``,
#: ``= -1.6 (so 1.6 m/s away from the wall)``, ``= -3 (3 m/s to the left)``).
_RESTATED = re.compile(
    r"(?P<value>\d[\d.]*)(?P<mid>[^()=\d]{0,24}?)\s*\(\s*(?P<lead>(?:i\.?\s?e\.?,?|that\s+is,?|that's|which\s+is|so"
    r"|[=≈~]|about|approx\.?|a\s+speed\s+of|speed|\s)*)(?P<again>\d[\d.]*)(?P<rest>[^()=\d]*)\)\s*[.!]?\s*$",
    re.I,
)
#: What may follow the number said again: its unit, an arrow, a direction in words.
_SAID_AGAIN = re.compile(
    r"(?:\s|[←→⟵⟶↑↓/^\-<>.,]|\\(?:long)?(?:left|right|up|down)arrow|\\gets|\\to|m|s|ms|kg|N|Ns|J|ft|ft/s|km/h|mph"
    r"|to|the|in|of|from|towards?|away|left|right|leftwards|rightwards|backwards?|forwards?|up|upwards|down"
    r"|downwards|opposite|same|other|way|direction|original|wall|ground|floor|[AB])*",
    re.I,
)


def _restated_in_brackets(text: str) -> str:
    """``text`` without its value said again in brackets as a speed with a direction (the same
    number, a unit, an arrow or words): the student restating the answer, not a product."""
    m = _RESTATED.search(text)
    if m is None or not all(_SAID_AGAIN.fullmatch(m[k]) for k in ("mid", "rest")):
        return text
    if not (m["lead"].strip() or m["rest"].strip()):
        return text  # "2e --(2)": a tag, "= 1.6 (1.6)": the value to no more figures
    try:
        same = abs(float(m.group("value").rstrip(".")) - float(m.group("again").rstrip("."))) < 1e-12
    except ValueError:
        return text
    return text[: text.index("(", m.end("value"))].rstrip() if same else text


#: "So", "hence" and "and" as students abroad write them (German, French, Spanish, Italian, Dutch).
SO_ABROAD = (
    r"also|daher|damit|somit|folglich|und|donc|alors|d['’]où|ainsi|et|entonces|luego|por\s+(?:lo\s+)?tanto"
    r"|as[ií]\s+que|quindi|dunque|perciò|dus"
)


#: The longest note read after a relation (its patterns look at the end of a line only).
NOTE_CHARS = 200


def without_note(text: str) -> tuple[str, str]:
    """A relation without the note after it, and its tag where the note is one ("" where none)."""
    text = re.sub(r"\s{9,}", " " * 8, text.rstrip())  # a wide gap is a gap: bounded, as the work is
    text = without_rounded_again(_HAS_AFTER.sub("", text))  # "…, B has -12i"; "27.216m J (27.2m J)"
    head, tail = text[:-NOTE_CHARS], text[-NOTE_CHARS:]
    tail, tag = _note(tail, "=" in head)
    return (head + tail).rstrip(), tag


def _note(text: str, equals_before: bool) -> tuple[str, str]:
    """The end of a relation without its note, and the tag (see :func:`without_note`)."""
    text = _restated_in_brackets(text)  # "(so 0.2 m/s ←)": before the arrow is read as a pointer
    text = _PERCENT.sub("", text)  # "= 64 J (18.2%)": the share, an aside
    pointed = _POINTER.sub("", text)
    text = pointed if "=" in pointed or equals_before else text
    text = _CLAUSE.sub("", _AFTER_TICK.sub("", _END_MARK.sub("", _CODE_COMMENT.sub("", text))))
    text = _SCHEME_MARKS.sub("", text)  # "= 2u - 3eu (A1)": the mark scheme's mark
    m = _CONVERTED.search(text) or _DASH_CONVERTED.search(text)
    if m and is_unit(m.group("unit").strip()) and _after_unit(text[: m.start("gap")]):
        text = text[: m.start("gap")]
    text = _restated_in_brackets(_remark_in_brackets(_FIGURES.sub("", text)))
    m = _SQUARE.search(text)
    after_operator = (
        m is not None and re.search(r"[-+*/×·÷=(]\s*$", text[: m.start()]) is not None
    )  # "/ [(vA)1 - (vB)1]"
    if m and not after_operator and any(w.lower() not in _MATH for w in re.findall(r"[A-Za-z]{2,}", m.group(1))):
        text = text[: m.start()]  # "[w left, 2.9 right]"; "[(delta_0 + x)^2 - delta_0^2]" is mathematics
    m = _UNROUNDED.search(text)
    if m and _is_more_figures(m):  # a unit after the brackets is the value's: "0.174 (4/23) m/s"
        text = text[: m.start("gap")] + (f" {m['later'].strip()}" if m["later"] else "")
    text = _PART_END.sub("", text)
    m = _TAG.search(text)
    if m is None:
        return text, ""
    tag = m.group("a") or m.group("b") or m.group("c") or m.group("d")
    if tag.isdigit() and int(tag) >= 10 and not m.group("gap"):
        return text, ""  # "m g (40)": a factor, not a tag
    return text[: m.start()].rstrip(), tag


def _rounds_to(more: str, value: str) -> bool:
    """Whether ``more`` (``72.98``) rounds to ``value`` (``73.0``) at the places ``value`` has."""
    try:
        places = len(value.split(".")[1]) if "." in value else 0
        return len(more) > len(value) and abs(float(more) - float(value)) <= 0.5 * 10**-places + 1e-12
    except ValueError:
        return False


def _after_unit(text: str) -> bool:
    """Whether ``text`` ends in a number and its unit (``35.2 m/s``; not ``2u``)."""
    m = re.search(r"\d\s*([A-Za-z°%][A-Za-z°%/^\-·*⁻¹²³ ]*)$", text)
    return m is not None and is_unit(m.group(1).strip())


def _fraction_of(fraction: str, value: str) -> bool:
    """Whether ``fraction`` (``5/29``) rounds to ``value`` (``0.172``, two figures or more, with a
    decimal point) at the places ``value`` has: the exact value the decimal was rounded from."""
    top, bottom = (float(x) for x in fraction.split("/"))
    figures = len(value.replace(".", "").lstrip("0"))
    if "." not in value or figures < 2 or not bottom:
        return False
    return abs(top / bottom - float(value)) <= 0.5 * 10 ** -len(value.split(".")[1]) + 1e-12


def _is_more_figures(m: re.Match) -> bool:
    """Whether the bracketed number is the value before it to more figures, or a decimal after a
    unit or a wide gap (an aside): ``1.49 m/s (1.4925)``; ``0.2 (28)`` and ``2u (1.5)`` are products."""
    value, more, unit = m.group("value").lstrip("+-"), m.group("more").lstrip("+-"), m.group("unit").strip()
    if m["later"] and (unit or not is_unit(m["later"].strip())):
        return False  # "2 (3) x": not a unit after the brackets
    if "/" in more:  # the exact fraction it was rounded from: 0.172 (5/29)
        return _fraction_of(more, value) and (not unit or is_unit(unit))
    if "." not in more or (unit and not (is_unit(unit) or unit in ("%", "°"))):
        return False
    digits = value.replace(".", "").lstrip("0").rstrip("0") or "0"
    same = more.replace(".", "").lstrip("0").startswith(digits[:-1] or digits) or _rounds_to(more, value)
    return bool(same or _rounds_to(value, more) or unit or len(m.group("gap")) >= 2)  # or rounded: 0.7125 (0.713)


#: Words that lead into a relation's first side (``CoM velocity V``, ``so θ``, ``speed V``): prose
#: before a name; not "speed of A", "let x" (a declaration), "KE after" (a name in words).
_PROSE_HEAD = re.compile(
    r"^\s*(?:(?!(?:let|where|with|if|when|suppose|of|for|on|by|at|in|to|is|and|or|sub\w*|us\w+|put\w*|from|since"
    r"|given|because|as|assum\w+|tak\w+|call\w*)\s)[A-Za-z][A-Za-z']{2,}\s+)+"
    r"(?=(?:[A-Za-z]|[α-ωΑ-Ω]|(?:alpha|beta|gamma|theta|phi|psi|omega|lambda|mu)(?![A-Za-z]))"
    r"(?:_\{?\w{1,4}\}?|'{1,2}|\d)?\s*$)",
    re.I,
)


#: A clause of words (and equations' tags: ``From (2),``) and a comma before a relation, and a verb that
#: leads in (``Energy lost, using ΔKE``).
_CLAUSE_HEAD = re.compile(
    r"^\s*(?:[A-Za-z][A-Za-z' ]*|(?=\(\s*\d))(?:\(\s*\d{1,2}[a-z]?\s*\)[A-Za-z' ]*)*,\s*(?:(?:using|use|by|from|taking)\s+(?=(?:Delta\s+)?\S+\s*$))?"
)


#: Words that lead into a side that is a number's working (``that's 0.3888/1.08``, ``which is 2 + 3``);
#: not a quantity's name in words (``KE before 2 + 3`` is not read so).
_WORDS_BEFORE_NUMBER = re.compile(
    r"^\s*(?:(?!(?:KE|GPE|PE|speed|velocity|energy|momentum|impulse|lost|loss|before|after|gain|total|mass)\b)"
    r"[A-Za-z]{2,}(?:'[a-z]+)?\s+)+(?=[\d.(])",  # not one letter: "m (v_2 - v_1)" is m times the bracket
    re.I,
)


#: A body said before a side in numbers, after a label (``impulses: on B 35000 x 0.3``, ``for A 2(3)``).
_ON_BODY = re.compile(r"^\s*(?:on|for)\s+(?-i:[A-Z])\s+(?=[\d.(])", re.I)


def name_after_words(side: str, math_words: frozenset[str]) -> str:
    """A first side that is words and then a name (``CoM velocity V``) as the name alone; a clause
    of words before a comma (``Energy lost, using ΔKE``) dropped; a body's letter beside the word
    speed or velocity (``speed B``) is one quantity, kept whole."""
    if body_side(side):
        return side
    side = _BODY_HAS.sub("", side, count=1)  # "A has 15 cos α i + 15 sin α j = 9i + 12j": A's, as vectors
    m = _CLAUSE_HEAD.match(side)
    if m and side[m.end() :].strip() and all(w.lower() not in math_words for w in re.findall(r"\w+", m.group(0))):
        side = side[m.end() :]
    m = _WORDS_BEFORE_NUMBER.match(side) or _ON_BODY.match(side)
    if m and all(w.lower() not in math_words for w in re.findall(r"[A-Za-z]+", m.group(0))):
        return side[m.end() :]  # "that's 0.3888/1.08", "on B 35000 x 0.3": the words lead in
    ref = _REFERENCE.match(side)  # "Y&F 8.96 blue puck m_b": the exercise's number, then words
    rest = side[ref.end() :] if ref else side
    m = _PROSE_HEAD.match(rest)
    if m is None or any(w.lower() in math_words for w in m.group(0).split()):
        return side
    return rest[m.end() :]


#: A body's letter and "has" before its velocity (``A has 15 cos α i + …``, ``B's velocity has``), and the
#: same clause after a relation, with no "=" in it (``…, B has -12i``).
_BODY_HAS = re.compile(
    r"^\s*(?:(?:initially|before|after(?:wards)?|finally|now)\s*,?\s+)?(?-i:[A-Z])(?:['’]s\s+velocity)?\s+has\s+"
    r"(?:(?:the\s+)?(?:components?|velocity)\s+)?(?=[-−\d(√.]|[A-Za-z](?![A-Za-z]{2}))",
    re.I,
)
_HAS_AFTER = re.compile(r"\s*,\s*(?:and\s+)?[A-Z](?:['’]s\s+velocity)?\s+has\s+[^=,;]{1,60}\.?\s*$")
#: An exercise's reference before the words that lead in to a name (``Y&F 8.96``, ``Ex. 13.13``, ``P8.96``).
_REFERENCE = re.compile(r"^\s*(?:[A-Za-z&]{1,8}\.?\s*)?\d{1,3}(?:\.\d{1,3})+[a-z]?\s+(?=[A-Za-z]{3})")


#: A number and its unit, then a name set equal to something (``m_p = 0.150kg v=35.0 m/s``): a
#: new relation without a comma.
UNIT_THEN_NAME = re.compile(
    r"(=\s*[-+]?\d[\d.]*\s?(?:kg|g|m/s|ft/s|km/h|mph|N|J|lb|slugs?|N\s?s))\s+(?=[A-Za-z]\w{0,5}\s*=(?!=))"
)  # the number all of a side, its unit not one a product may end with (m, s)
#: A wide gap (three spaces or a tab) after a relation, then a name and "=": two relations set
#: side by side on one line, as a plain-text sheet lines them up (``(vA)n1 = 6.928 ft/s      (vA)t1 = 4``).
GAP_THEN_NAME = re.compile(r"(=[^=]*?\S)(?:[ ]{3,}|\t+)(?=(?:\([A-Za-z]\w{0,3}\)\w{0,3}|[A-Za-z]\w{0,5})'*\s*=(?!=))")
#: A remark after a relation's value: ``, i.e. 64 %``, a bracket with a word in it (``(reversed)``,
#: ``(p, q the velocities after):`` before a colon,
#: not ``(v_Abefore - v_Bbefore)``, whose words are marks of names, nor ``(u - lambda u)``, whose
#: only words are a Greek letter's or a function's names: mathematics).
_MATH_NAME = "|".join(sorted(GREEK | FUNCTIONS | {"sqrt", "sec", "cosec", "cot"}, key=len, reverse=True))
#: Terms joined by operators, ``(1 - lam)``, ``(u - lam u)``: mathematics whatever its names' letters
#: (a term a number or a short name, a one-letter name after it a product: ``lam u``; never a
#: word, ``(B - forwards)``).
_TERM = r"(?:\d[\d.]*|[A-Za-z]{1,3}\d?(?:_\w{1,4})?'*)(?:(?:\s+|\s*\*\s*)[A-Za-z](?![\w']))?"
_ALGEBRA = rf"\s*[-+−]?\s*{_TERM}(?:\s*[-+*/×−]\s*{_TERM})+\s*\)"
REMARK_END = re.compile(
    rf"(?:,\s*|\s+)(?:i\.\s?e\..*|\((?!{_ALGEBRA})(?=[^()]*(?<![\w])(?!(?:{_MATH_NAME})(?![A-Za-z]))[A-Za-z]{{3}})[^()]*\)\s*[.:;]?\s*"
    r"|\(\s*up\s*\)\s*[.:;]?\s*)$"  # "28 m/s (up)": a way in words of two letters, as "(down)" is
)


#: A quantity said equal to a number in words, with no ``=`` on the line: "The speed of B after the
#: collision is 8 m/s", "the kinetic energy lost was about 64 J", "B's velocity becomes 2.4 m/s".
_SAID_IS = re.compile(
    r"^(?P<subject>\s*(?:so\s+|hence\s+|therefore\s+)?(?:the\s+)?(?:[AB]['’]s\s+)?(?:final\s+|initial\s+|total\s+)?"
    r"(?:speed|velocity|KE|kinetic\s+energy|impulse|energy\s+lost|loss\s+(?:of|in)\s+(?:KE|kinetic\s+energy))"
    r"[A-Za-z'’ ]{0,40}?)\s+(?:is|was|will\s+be|becomes|equals)\s+(?:about\s+|approximately\s+|roughly\s+|now\s+)?"
    r"(?=[-+−]?\d)",
    re.I,
)


def said_is(text: str) -> str:
    """``text`` with a quantity said to be a number in words written as a relation ("the speed of B
    after the collision is 8 m/s" as ``… = 8 m/s``); a line with an ``=`` already as it is."""
    return text if "=" in text else _SAID_IS.sub(lambda m: f"{m['subject']} = ", text, count=1)
