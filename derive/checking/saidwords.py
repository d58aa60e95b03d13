"""Quantities a student says in words rather than names, as a teacher reads them: an ``x`` for
times beside one (``speed after = e x speed before``), and bodies said to move off together by
the problem's givens (the same velocity after given to both, as e = 0 is).
"""

from __future__ import annotations

import re

from derive.mathtext.bodysides import BODY_WORD_SIDE, named

#: A kinetic energy's name as students write it at home and abroad (E_k, E_kin, E_c: énergie cinétique).
_ENERGY = r"E_?(?:k|c|kin|cin)|KE|Ekin"
#: The energy lost, in German, French, Spanish and Italian.
_LOST = (
    r"(?:kinetischer\s+)?Energieverlust|Verlust\s+an\s+(?:kinetischer\s+)?Energie|perte\s+d['’]\s*[ée]nergie(?:\s+cin[ée]tique)?"
    r"|[ée]nergie\s+perdue|p[ée]rdida\s+de\s+energ[ií]a(?:\s+cin[ée]tica)?|energ[ií]a\s+perdida|perdita\s+di\s+energia"
)
#: Quantities said in words, as names (:func:`.naming.rewrite`; a wall's speeds and velocities valued in
#: ``inference._speeds`` where B is fixed): a speed before, a velocity before or after.
SAID_PHRASES = (
    (BODY_WORD_SIDE.pattern, lambda m: named(m) or m[0]),  # "speed B = 3U/4", phone-typed: B's speed after
    (r"(?<=speed_[AB])\s+(?:the\s+)?(?:collision|impact)\b", ""),  # "speed of B after the collision"
    (rf"(?:{_ENERGY})[\s_,]*(?:before|initial|vorher|avant|antes|prima|iniziale|initiale?)\b", "T_1"),
    (rf"(?:{_ENERGY})[\s_,]*(?:after|final|nachher|apr[eè]s|despu[eé]s|dopo|finale)(?!\w)", "T_2"),
    (rf"^\s*(?:{_LOST})\s*$", "T_lost"),
    (r"(?<![\w'])speed\s+before(?:\s+(?:the\s+)?(?:impact|bounce|collision))?(?![\w'])", "speed_before"),  # a wall's
    (  # "momentum after = 0.8(-1.2) + 0.4v", "total momentum before", "p before": the two bodies' momentum
        r"^\s*(?:the\s+)?(?:total\s+|system\s+)?(?:momentum|(?-i:p))\s*_?\s*(before|after)(?:\s+(?:the\s+)?(?:collision|impact))?\s*$",
        r"p_\1",
    ),
    (
        r"^\s*(?:the\s+)?(?:total\s+)?(?:(initial)|final)\s+(?:total\s+)?momentum\s*$",
        lambda m: "p_" + ("before" if m[1] else "after"),
    ),
    (
        r"^\s*(?:the\s+)?velocity\s+(after|before)(?:\s+(?:the\s+)?(?:impact|rebound|bounce|collision))?\s*$",
        r"velocity_\1",
    ),
)

#: An ``x`` for times beside a quantity said in words, rewritten as a name (``e x speed_before``,
#: ``speed_before x e``): never the letter x.
_TIMES_WORDS = re.compile(r"(?<=\S)\s+x\s+(?=(?:speed|velocity)_(?:after|before)\b)|(?<=_after|before)\s+x\s+(?=\S)")


def times_beside_words(text: str) -> str:
    """``text`` with each ``x`` beside a quantity said in words written as ``*`` (the impulse in
    words is :mod:`.wordlabels`' and :func:`.spellings.impulse_name`'s: signed as the student writes it)."""
    return _TIMES_WORDS.sub(" * ", text)


def together(problem: object) -> bool:
    """Whether the bodies move off together: e = 0 given, or the same velocity after given to both
    (``v_A2 = v_B2 = 6 m/s``: "they lock together and move off at 6 m/s")."""
    givens = getattr(problem, "givens", ())
    after = {g.name: g.value for g in givens if g.name in ("v_A2", "v_B2") and not g.unknown}
    return any(g.name == "e" and g.value == 0 for g in givens) or (len(after) == 2 and len(set(after.values())) == 1)
