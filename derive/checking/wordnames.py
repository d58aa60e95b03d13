"""Names a student declares in words, not with ``=``: "Let a and b be the velocities of A and B
along the line of centres after" (an oblique impact's components), "let x, y be the speeds of P
and Q after the collision", "x = velocity of A after" (a direct impact's velocities).
:func:`in_words` is what :func:`.naming.declarations` asks of each line.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.anglenames import velocities_in_words
from derive.checking.beforeangles import before_angles
from derive.checking.context import Context
from derive.checking.statementbodies import said_by_letter, statement_bodies
from derive.checking.towardwords import toward


def in_words(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names ``line`` declares in words, each with derive's name for what it stands for:
    a direct impact's velocities by body and time, an oblique impact's components along the line
    of centres (where the line says so)."""
    out = _direct(line, ctx)
    for name, x in [*_possessive(line, ctx).items(), *_angles(line, ctx).items()]:
        out.setdefault(name, x)
    for name, x in [*_along(line, ctx).items(), *_letters_for(line, ctx).items(), *_speeds_after(line, ctx).items()]:
        out.setdefault(name, x)
    for name, x in [*_components_said(line, ctx).items(), *said_by_letter(line, ctx).items()]:
        out.setdefault(name, x)
    return out


_LOC = r"(?:line\s+of\s+(?:centres|centers|impact)|l\.?\s?o\.?\s?c\b\.?|common\s+normal)"
_ALONG_WORDS = re.compile(
    rf"\b(?:along|parallel\s+to|in\s+the\s+direction\s+of)\s+(?:the\s+)?{_LOC}|\b(?:n|normal)[-\s]*components?\b", re.I
)  # "the n components", "the normal components": along the line of centres
_ACROSS_WORDS = re.compile(
    rf"\b(?:across|perpendicular\s+to|at\s+right\s+angles\s+to)\s+(?:the\s+)?(?:{_LOC}|it)\b|\btangential|\bcommon\s+tangent",
    re.I,
)
_ONE_NAME = r"[A-Za-z](?:_?\w{1,2})?"
#: Where a clause names its names: "is p", "are p and q", "has p", "let p, q be", "p, q = …".
_SAID_NAMES = (
    re.compile(
        rf"\b(?:is|are|be|=|has|have)\s+({_ONE_NAME}(?:\s*(?:,|and)\s*{_ONE_NAME})*)(?![\w'(/^*.]|\s*[-+*/^=(])"
        r"(?=\s*(?:$|[,;:)]|\.\s|(?:and|along|across|perpendicular|parallel|after|before|now|in|for|then|so|with)\b))",
        re.I,
    ),
    re.compile(rf"\b(?:let|where)\s+({_ONE_NAME}(?:\s*(?:,|and)\s*{_ONE_NAME})*)\s+(?:be|are|is|=|denotes?)\b", re.I),
    re.compile(rf"^\s*({_ONE_NAME}(?:\s*(?:,|and)\s*{_ONE_NAME})*)\s*(?:=|:|are\b|is\b)", re.I),
)
_TIME_AFTER = re.compile(r"\b(?:after(?:wards)?|now|final|new|leaves?|moves?\s+off)\b", re.I)
_TIME_BEFORE = re.compile(r"\b(?:before|initially|initial)\b", re.I)
_WHAT_WORDS = re.compile(r"\bcomponents?\b|\bvelocit(?:y|ies)\b|\bhas\b|\bhave\b", re.I)


def _components_said(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """``A's component along the line of centres after the impact is p``, ``let p, q be the
    components of A, B along the line of centres after``, ``after: A has p, B has q along the
    l.o.c.``: an oblique impact's components named in words, in any order of names and words.
    Each clause says one axis (along the line of centres, or across it) and one time (before or
    after); its names pair with the bodies it names, in order."""
    if not ctx.problem.oblique:
        return {}
    cut = re.split(r"(?<=[\w'’}])\s*=(?!\s*(?:the\s+)?(?:components?|velocit(?:y|ies))\b)", line, maxsplit=1)
    if len(cut) > 1 and "=" in cut[0]:
        return {}
    valued, line = len(cut) > 1, cut[0]  # "A's component along the l.o.c. is a = 4 cos 60°": the words before
    labels = set(ctx.problem.labels) | {"A", "B"} | set(statement_bodies(ctx))  # "the velocity of P after"
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    for clause in re.split(r"(?<!\bl\.o\.c)[;.](?:\s|$)", re.sub(r"\$|\\[()]|[{}]", " ", line)):
        a, c = _ALONG_WORDS.search(clause), _ACROSS_WORDS.search(clause)
        if a and c and a.start() < c.start():  # "A has p along the line of centres and u/2 across it"
            clause = clause[: c.start()]
        along, across = bool(_ALONG_WORDS.search(clause)), bool(_ACROSS_WORDS.search(clause))
        after, before = bool(_TIME_AFTER.search(clause)), bool(_TIME_BEFORE.search(clause))
        before = before or (valued and not after)  # a value at once, no time said: the given resolved
        if along == across or after == before or not _WHAT_WORDS.search(clause):
            continue
        bodies = [
            _body(m[1], ctx) for m in re.finditer(r"(?<![\w\\])([A-Z])(?:['’]s)?(?![\w])", clause) if m[1] in labels
        ]
        said = [
            n for p in _SAID_NAMES for m in p.finditer(clause) for n in re.split(r"\s*(?:,|\band\b)\s*", m[1].strip())
        ]
        said = list(
            dict.fromkeys(n for n in said if n not in labels and n not in names and n.lower() not in _NOT_NAMES)
        )
        bodies = [b for k, b in enumerate(bodies) if b and b not in bodies[:k]]
        if not bodies and len(said) == 2:
            bodies = ["A", "B"]  # "let p and q be the n components after": A's then B's, as listed
        if not said or len(said) != len(bodies):
            continue
        for name, b in zip(said, bodies, strict=True):
            x = getattr(ctx.model.nm, f"{b}{'2' if after else '1'}{'n' if along else 't'}", None)
            if x is not None:
                out.setdefault(name, x)
    return out


#: A body in words: ``A``, ``P``, ``sphere B``, ``the ball Q``.
_WHOSE = r"(?:(?:the\s+)?(?:sphere|ball|particle|disc|puck)\s+)?(\w+)"
_SPEED_OF = rf"(?:(?:the\s+)?(?:new\s+|final\s+|resultant\s+)?speed\s+of\s+{_WHOSE}|{_WHOSE}['’]s\s+(?:new\s+|final\s+|resultant\s+)?speed)"
_LATER = r"(?:\s+(?:just\s+|immediately\s+)?(?:after(?:wards)?|now)(?:\s+the\s+(?:impact|collision))?)"
#: "where V is A's speed after the collision", "let w be the speed of A after", "A's speed is now V",
#: "the speed of B afterwards = w", "A moves off with speed V": an oblique impact's speed after.
_SPEED_NAMED = (
    re.compile(
        rf"(?<![\w\\])([A-Za-z](?:_?\w{{1,2}})?)\s+(?:is|be|=|denotes?|represents?|for)\s+{_SPEED_OF}{_LATER}", re.I
    ),
    re.compile(
        rf"{_SPEED_OF}(?:{_LATER}|(?=\s+is\s+now))\s*(?:is\s+now|now\s+is|is|=|be)\s*([A-Za-z](?:_?\w{{1,2}})?)(?![\w'(])",
        re.I,
    ),
    re.compile(rf"\blet\s+{_SPEED_OF}{_LATER}?\s+be\s+([A-Za-z](?:_?\w{{1,2}})?)(?![\w'(])", re.I),
    re.compile(
        rf"\b{_WHOSE}\s+(?:now\s+)?moves\s+(?:off\s+|away\s+)?(?:along\s+(?:the\s+)?[\w\s.]{{1,30}}?\s+)?(?:with|at)\s+(?:a\s+)?speed\s+([A-Za-z](?:_?\w{{1,2}})?)(?![\w'(])",
        re.I,
    ),
)


_LETTER = rf"({_ONE_NAME})"
#: One body's speeds before and after, in one breath: "let the speed be u before and v after",
#: "its speed is u before the impact and v after it", "speeds u and v before and after".
_SPEEDS_BEFORE_AFTER = (
    re.compile(
        rf"\bspeed\s+(?:be\s+|is\s+|of\s+)?{_LETTER}\s+(?:just\s+)?before(?:\s+the\s+(?:impact|collision|bounce))?,?"
        rf"\s+and\s+{_LETTER}\s+(?:just\s+)?after",
        re.I,
    ),
    re.compile(rf"\bspeeds\s+(?:be\s+|are\s+)?{_LETTER}\s+and\s+{_LETTER}\s+before\s+and\s+after", re.I),
)


def _speeds_after(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """``where V is A's speed after the collision`` -> {V: v_A2}: a name for a body's speed after
    an oblique impact (its size, the speed derive works out), in either order of name and words."""
    if not ctx.problem.oblique:
        return {}
    plain = re.sub(r"\$|\\[()]|[{}]", " ", line)
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    for k, pattern in enumerate(_SPEED_NAMED):
        for m in pattern.finditer(plain):
            groups = [g for g in m.groups() if g]
            name, body = (groups[0], groups[1]) if k == 0 else (groups[-1], groups[0])
            b = _body(body, ctx)
            if b and f"v_{b}2" in names and name not in names and name.lower() not in _NOT_NAMES:
                out.setdefault(name, names[f"v_{b}2"][0])
    for pattern in _SPEEDS_BEFORE_AFTER if ctx.problem.fixed_B and "v_A2" in names else ():
        for m in pattern.finditer(plain):
            if m[2] not in names and m[2].lower() not in _NOT_NAMES:
                out.setdefault(m[2], names["v_A2"][0])  # the one body's speed after (before: the given)
    return out


#: A student's short name (``a``, ``e1``, ``u_A``, ``α``) and one of the problem's as typed in
#: prose (``alpha``, ``\\beta``, ``β``, ``e_1``, ``U``).
_MINE = r"(?:[A-Za-z](?:_?\w{1,2})?|[α-ω])"
_THEIRS = r"(?:\\?[A-Za-z]{2,7}(?:_\w{1,3})?|[A-Za-z](?:_?\w{1,3})?|[α-ω])"
_SEP = r"\s*(?:,|\band\b|&)\s*"
_FOR_WORDS = r"\s+(?:for|stands?\s+for|in\s+place\s+of|instead\s+of)\s+(?:the\s+(?:angle|given|letter)\s+)?"
#: "a for alpha", "e1 stands for e_1" (one pair), "a, b for α, β" (two lists, paired in order).
_FOR_ONE = re.compile(rf"(?<![\w\\])({_MINE}){_FOR_WORDS}({_THEIRS})(?![\w(])", re.I)
_FOR_LIST = re.compile(
    rf"(?<![\w\\])({_MINE}(?:{_SEP}{_MINE})+){_FOR_WORDS}({_THEIRS}(?:{_SEP}{_THEIRS})+)(?![\w(])", re.I
)
#: Words of one or two letters that are never a name in "… for …" ("as for", "so for").
_NOT_NAMES = frozenset({"as", "so", "is", "or", "if", "to", "in", "on", "of", "at", "by", "be", "it", "an", "do", "go"})


def _letters_for(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """``(a for alpha, b for beta)`` -> {a: alpha, b: beta}, and the list form ``a, b for α, β``:
    the student's short names for the problem's own (a given, a quantity the statement names),
    each paired with the one in the same place."""
    plain = re.sub(r"\$|\\[()]|[{}]", " ", line)
    names = ctx.equation_names()
    pairs = []
    for m in _FOR_LIST.finditer(plain):
        mine, theirs = re.split(_SEP, m[1].strip()), re.split(_SEP, m[2].strip())
        if len(mine) == len(theirs):
            pairs += zip(mine, theirs, strict=True)
    pairs += [(m[1], m[2]) for m in _FOR_ONE.finditer(plain)]
    out: dict[str, sympy.Expr] = {}
    for name, target in pairs:
        target = _GREEK_LETTERS.get(target, target.lstrip("\\"))
        name = _GREEK_LETTERS.get(name, name)
        if name.lower() in _NOT_NAMES or name == target or name in names or target not in names:
            continue
        out.setdefault(name, names[target][0])
    return out


#: "Let $a$ and $b$ be the velocities of A and B along the line of centres after": names in words.
_IN_WORDS = re.compile(
    r"\blet\s+(\w+)(?:\s+and\s+(\w+))?\s+be\s+(?:the\s+)?(?:final\s+)?velocit(?:y|ies)\s+of\s+([AB])"
    r"(?:\s+and\s+([AB]))?(\s+along\s+the\s+line\s+of\s+(?:centres|impact))?\s*,?\s*"
    r"(?:just\s+|immediately\s+)?(after|afterwards|before)\b",
    re.I,
)


def _along(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """``Let a and b be the velocities of A and B along the line of centres after`` -> {a: v_A2n,
    b: v_B2n}: a name declared in words, where they say whose, when, and (an oblique impact)
    along which line."""
    m = _IN_WORDS.search(re.sub(r"\$|\\[()]", "", line))
    if not m or (ctx.problem.oblique and not m.group(5)) or bool(m.group(2)) != bool(m.group(4)):
        return {}
    when = "1" if m.group(6).lower() == "before" else "2"
    out = {}
    for name, body in ((m.group(1), m.group(3)), (m.group(2), m.group(4))):
        x = getattr(ctx.model.nm, f"{body.upper()}{when}n", None) if name else None
        if x is not None:
            out[name] = x
    return out


#: Names declared in words: "let x, y be the speeds of P and Q after the collision", "x and y are
#: the velocities of A and B after", "x = velocity of A after".
_NAME_WORD = r"([A-Za-z](?:_\{?\w{1,3}\}?|\d{1,2}(?![\w.]))?)"  # v_B, v1 (not 3.2)
_WHAT = (
    r"(?:be|are|is|as|=|denote|represent|for)\s+(?:the\s+)?(?:final\s+)?(?:speeds?|velocit(?:y|ies)|vels?\.?)\s+of\s+"
)
_PAIR_WORDS = re.compile(
    rf"\b{_NAME_WORD}\s*(?:,|and)\s*{_NAME_WORD}\s+{_WHAT}(.{{1,30}}?)\s+and\s+(.{{1,30}}?)\s+(after|before)\b", re.I
)
_ONE_WORDS = re.compile(rf"\b{_NAME_WORD}\s*{_WHAT}(.{{1,30}}?)\s+(after|before)\b", re.I)
_BODY_WORDS = re.compile(r"\b(?:the|sphere|ball|particle|disc|body|puck|car|trolley)s?\b", re.I)


def _direct(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """The names a line declares in words (``Let $x$, $y$ be the speeds of P and Q after the
    collision``), for a direct impact: each the velocity of the body it names (by its letter,
    P and Q for A and B, or its mass: "the 3m particle"), after or before."""
    if ctx.problem.oblique:
        return {}
    plain = re.sub(r"\\[A-Za-z]+\{[^{}]*\}|\$|\\[()]|[{}]", " ", line)
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    found = [((m[1], m[3]), (m[2], m[4]), m[5], 1) for m in _PAIR_WORDS.finditer(plain)]
    found += [((m[1], m[2]), None, m[3], _backwards(m, plain)) for m in _ONE_WORDS.finditer(plain)]
    for first, second, when, sign in found:
        for name, body in (first, second) if second else (first,):
            b = _body(body, ctx)
            key = f"v_{b}{'2' if when.lower() == 'after' else '1'}"
            if b and key in names:
                out.setdefault(
                    name.replace("{", "").replace("}", ""), sign * toward(plain, when, b, ctx) * names[key][0]
                )
    return out


#: Words after a body's speed is named that say it moves backwards ("(P goes backwards)", "P
#: rebounds", "in the opposite direction", "to the left").
_BACKWARDS = re.compile(
    r"^[^;.=]{0,30}?\b(?:backwards?|back|reverses|rebounds?|bounces\s+back|in\s+the\s+opposite\s+direction"
    r"|the\s+other\s+way|to\s+the\s+left|leftwards?)\b",
    re.I,
)


def _backwards(m: re.Match[str], plain: str) -> int:
    """-1 where a name declared for a body's speed (not its velocity) is said, in the words just
    after, to be backwards ("let v be the speed of P after (P goes backwards)"): the mark scheme's
    v, the size of a velocity against derive's +n (from A toward B), is minus that velocity."""
    if not re.search(r"\bspeed", m.group(0), re.I):
        return 1
    tail = re.split(r"\band\s+[A-Za-z](?:_?\w{1,2})?\s+(?:the|be|is|as)\b", plain[m.end() :], maxsplit=1)[0]
    return -1 if _BACKWARDS.match(tail) else 1


def _body(words: str, ctx: Context) -> str:
    """ "A", "B" or "" for the words that name a body: its letter, P or Q, first or second, its mass."""
    w = re.sub(r"(?<=\d)(?:kg|g|lb)$", "", re.sub(r"\s+", "", _BODY_WORDS.sub(" ", words)))  # the 4 kg ball
    a, b = ctx.problem.labels
    if w in statement_bodies(ctx):  # the statement's P at rest: derive's B
        return statement_bodies(ctx)[w]
    if w in (a, "A", "P", "first"):
        return "A"
    if w in (b, "B", "Q", "second"):
        return "B"
    masses = {}
    for g in ctx.problem.givens:
        if g.name in ("m_A", "m_B"):
            x = g.value if g.value is not None else getattr(g, "definition", None)
            masses[g.name[-1]] = re.sub(r"[\s*]", "", str(x))
    hits = [k for k, v in masses.items() if v == w.replace("*", "")]
    return hits[0] if len(hits) == 1 else ""


#: "x = P's velocity after, y = Q's": a name set to a body's velocity, and the next ones by ellipsis.
_POSSESSIVE = re.compile(
    rf"\b{_NAME_WORD}\s*(?:=|is|be|denotes?|for)\s*(?:the\s+)?(\w+)['’]s\s+(?:final\s+)?(?:speed|velocity|vel\.?)"
    r"\s+(?:just\s+|immediately\s+)?(after|before)\b",
    re.I,
)
_ELLIPSIS = re.compile(rf"^\s*(?:,|;|and)\s*{_NAME_WORD}\s*(?:=|is|be|for)\s*(?:the\s+)?(\w+)['’]s\b(?!\s+\w)", re.I)


def _possessive(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """``x = P's velocity after, y = Q's`` -> {x: v_A2, y: v_B2}: a direct impact's velocities
    named by whose they are, a second name by ellipsis (the same quantity, the other body)."""
    if ctx.problem.oblique:
        return {}
    plain = re.sub(r"\\[A-Za-z]+\{[^{}]*\}|\$|\\[()]|[{}]|\*\*|__", " ", line)  # **p**: bold, p
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    for m in _POSSESSIVE.finditer(plain):
        when = "2" if m[3].lower() == "after" else "1"
        found = [(m[1], m[2])]
        more = _ELLIPSIS.match(plain[m.end() :])
        if more:
            found.append((more[1], more[2]))
        for name, body in found:
            b = _body(body, ctx)
            if b and f"v_{b}{when}" in names:  # "Q's speed before", Q moving toward P: minus its velocity
                out.setdefault(re.sub(r"[{}]", "", name), toward(m[0], m[3], b, ctx) * names[f"v_{b}{when}"][0])
    return out


#: Greek letters as typed (β) and as the parser names them (beta).
_GREEK_LETTERS = {"α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "θ": "theta", "φ": "phi", "ψ": "psi"}
_ANGLE_NAME = r"(\\?[A-Za-z]{1,7}|[αβγδθφψ])"
_PATH = r"(?:new\s+|final\s+)?(?:path|velocity|direction(?:\s+of\s+motion)?|motion)"
_AFTER = r"(?:\s+(?:after|afterwards|now)(?:\s+the\s+(?:impact|collision))?)?"
_WITH = (
    r"makes?\s+(?:an?\s+)?(?:acute\s+)?(?:angle\s+)?(?:of\s+)?{name}?\s*with\s+(?:the\s+)?"
    r"(line\s+of\s+(?:centres|centers|impact)|l\.?\s?o\.?\s?c\.?|wall|cushion|(?:common\s+)?tangent|plane\s+of\s+contact)"
)
#: "β is the angle Q's new path makes with the line of centres"; "A's path after makes angle α
#: with the l.o.c."; "θ = angle between B's velocity and the wall".
_ANGLE_IS = re.compile(
    rf"(?<![\w\\]){_ANGLE_NAME}\s+(?:is|=|denotes?|be)\s+(?:the\s+)?(?:acute\s+)?angle\s+(?:that\s+)?"
    rf"(?:the\s+)?(\w+)['’]s\s+{_PATH}{_AFTER}\s+{_WITH.format(name='')}",
    re.I,
)
#: "θ is the deflection (of A)", "A is deflected through θ": the angle its velocity turns through.
_DEFLECTION = re.compile(
    rf"(?<![\w\\]){_ANGLE_NAME}\s+(?:is|=|denotes?|be)\s+(?:the\s+)?(?:angle\s+of\s+)?deflection(?:\s+of\s+(\w+))?",
    re.I,
)
#: Words that say a velocity is the one after the impact (its new path, after, as it leaves).
_THEN = re.compile(r"\b(?:new|final|after(?:wards)?|now|rebound\w*|leaves?|leaving|bounces?|moves?\s+off)\b", re.I)
_DEFLECTED = re.compile(
    rf"\b(\w+)\s+(?:is\s+)?(?:deflected|deviated|turn(?:s|ed)?)\s+(?:through|by)\s+(?:an\s+angle\s+(?:of\s+)?)?{_ANGLE_NAME}\b",
    re.I,
)
#: "θ is the angle between A's new path and the line of centres" (either way round).
_LINE_WORDS = r"(line\s+of\s+(?:centres|centers|impact)|l\.?\s?o\.?\s?c\.?|wall|cushion|(?:common\s+)?tangent|plane\s+of\s+contact)"
_ANGLE_BETWEEN = re.compile(
    rf"(?<![\w\\]){_ANGLE_NAME}\s+(?:is|=|denotes?|be)\s+(?:the\s+)?(?:acute\s+)?angle\s+between\s+(?:the\s+)?"
    rf"(?:(\w+)['’]s\s+{_PATH}{_AFTER}\s+and\s+(?:the\s+)?{_LINE_WORDS}|{_LINE_WORDS}\s+and\s+(?:the\s+)?(\w+)['’]s\s+{_PATH}{_AFTER})",
    re.I,
)
_ANGLE_MAKES = re.compile(rf"(?:the\s+)?(\w+)['’]s\s+{_PATH}{_AFTER}\s+{_WITH.format(name=_ANGLE_NAME)}", re.I)
#: "the sphere leaves the wall at an angle φ to the wall", "B moves off at angle β to the line of
#: centres", "let it rebound making an angle φ with the cushion": a body's path after, by its verb.
_ANGLE_LEAVES = re.compile(
    r"(?:the\s+)?(\w+)\s+(?:leaves?|leaving|rebounds?|rebounding|bounces?\s+off|(?:moves?|goes|travels?)\s+(?:off|away)"
    r"|(?:now|then|afterwards)\s+(?:moves?|goes|travels?))"
    r"(?:\s+(?:from\s+)?(?:the\s+)?(?:wall|cushion|surface|it))?\s+(?:at|making)\s+(?:an?\s+)?(?:acute\s+)?angle\s+(?:of\s+)?"
    rf"{_ANGLE_NAME}\s+(?:to|with)\s+(?:the\s+)?{_LINE_WORDS}",
    re.I,
)


def _angles(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """``β is the angle Q's new path makes with the line of centres`` -> {beta: beta_A2}: an
    angle after the impact declared in words, from the line of centres (derive's beta, tan = t/n)
    or from the wall or tangent (derive's theta, tan = n/t). Where the words name no body derive
    knows (the statement's P and Q), the one body that leaves off the line of centres."""
    if not ctx.problem.oblique:
        return {}
    plain = velocities_in_words(re.sub(r"\$|\\[()]|\*\*|[{}]", " ", line), ctx)  # the angle v_A makes with
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    given = {g.name for g in ctx.problem.givens}  # the problem's α stays the given
    found = [(m[1], m[2], m[3]) for m in _ANGLE_IS.finditer(plain)]
    found += [(m[2], m[1], m[3]) for m in _ANGLE_MAKES.finditer(plain) if m[2]]
    found += [(m[1], m[2] or m[5], m[3] or m[4]) for m in _ANGLE_BETWEEN.finditer(plain)]
    if not _THEN.search(plain):  # "θ is the angle between A's velocity and the l.o.c.": a moving A's, as it comes in
        out, found = before_angles(ctx, found, given, (lambda b: _body(b, ctx), _GREEK_LETTERS, plain))
    found += [(m[2], m[1], m[3]) for m in _ANGLE_LEAVES.finditer(plain)]
    found += [(m[1], m[2] or "", "deflection") for m in _DEFLECTION.finditer(plain)]
    found += [(m[2], m[1], "deflection") for m in _DEFLECTED.finditer(plain)]
    for name, body, line_of in found:
        b = _leaving(_body(body, ctx), ctx) if line_of != "deflection" else _body(body, ctx) or "A"
        key = f"delta_{b}" if line_of == "deflection" else f"{'beta' if line_of[0] in 'lL' else 'theta'}_{b}2"
        if b and key in names:
            name = _GREEK_LETTERS.get(name.lstrip("\\"), name.lstrip("\\"))
            if name not in given:
                out.setdefault(name, -names[key][0] if _negative(ctx, key) else names[key][0])
    return out


def _negative(ctx: Context, name: str) -> bool:
    """Whether derive's angle ``name`` is negative (the acute angle a student names in words is
    its size: "leaves at an angle φ to the wall" where derive's θ_A2 is -18.4°)."""
    try:
        r = ctx.results[name]
    except (KeyError, LookupError):
        return False
    x = sympy.sympify(r.value if r.value is not None else r.closed)
    if x is None or x.is_number:
        return x is not None and bool(x.is_negative)
    try:  # in letters (tan β = e₁ tan α): its sign at the givens' admissible values
        x = ctx.num(x)
        point = ctx.sampler().points(x.free_symbols, n=1)[0]
        return bool(sympy.N(x.xreplace(point)).is_negative)
    except (TypeError, ValueError, IndexError, ArithmeticError):
        return False


def _leaving(body: str, ctx: Context) -> str:
    """``body`` where the words name one derive knows (moving on along the line of centres too: angle 0);
    where none, the one body whose velocity after has a component across it ("" where none or both)."""
    across = [b for b in "AB" if not _zero(ctx, f"v_{b}2t")]
    if body in across or body in ("A", "B"):
        return body
    return across[0] if len(across) == 1 else ""


def _zero(ctx: Context, name: str) -> bool:
    """Whether derive's result ``name`` is zero (or absent)."""
    try:
        r = ctx.results[name]
    except (KeyError, LookupError):
        return True
    x = r.closed if r.closed is not None else r.value
    return x is not None and sympy.sympify(x).is_zero is True


#: A relation that only says what a name is: ``x = P's velocity after``, ``y = Q's``,
#: ``v = velocity of A after``: a declaration, not a relation to judge.
#: Also a body's letter and words of when or which way (``Let x = Q along the line of centres after``).
_SAID = re.compile(
    r"^\s*(?:(?:let|where|with|set)\s+)?[A-Za-z](?:_?\w{1,3})?\s*=\s*(?:the\s+)?(?:\w+['’]s(?:\s+(?:final\s+|new\s+)?(?:speed|velocity|vel\b)|\s*$)"
    r"|(?:final\s+)?(?:speed|velocity|vel\.?)\s+of\s+"
    r"|(?-i:[A-Z])\s+(?:along|across|perpendicular|parallel|after|before|afterwards|initially|finally)\b)[^=]*$",
    re.I,
)


def says_what(relation: str) -> bool:
    """Whether ``relation`` (``x = P's velocity after``) only says in words what a name is."""
    return bool(_SAID.match(relation))
