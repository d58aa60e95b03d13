"""What a student's names stand for: declared, habitual, introduced, or inferred.

A derivation is written in the student's names, not derive's. They are read, in order:

1. **declared** in the file: a line ``let x = v_A2`` (also ``x := v_A2``, ``where x = v_A2``);
   a line ``positive: away from A`` or ``positive: reversed`` says the student's positive
   direction is opposite to derive's n (the line from A toward B);
2. **habits**: ``u_A, u_B`` (``u1, u2``, ``u``) before and ``v_A, v_B`` (``v1, v2``, ``v``)
   after (the A-level habit);
   ``v_G``, ``v_cm``, ``V`` the common velocity (m_A v_A1 + m_B v_B1)/(m_A + m_B);
   ``KE before``, ``KE after``, ``KE lost``, ``Delta KE``, ``loss of KE`` the energies;
   ``3eu`` and ``5mv_A`` products of names written side by side;
3. **introduced**: a line ``NAME = expression`` that uses only known names defines NAME
   for the lines after it (``v_G = (m_A u_A + m_B u_B)/(m_A + m_B)``);
4. **inferred**: a name still unknown (``x``, ``y``, ``w``) stands for the velocity (or
   common velocity, energy lost, impulse, unknown given) that makes the most of the
   derivation's relations hold, and the sign convention is the one that makes the values
   written hold (``u = -4`` for a speed of 4 toward the wall: the student's positive is
   derive's negative). What was inferred is said in the report.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterator, Mapping

import sympy

from derive.checking.afterlabels import after_label
from derive.checking.axisnames import letter_components
from derive.checking.centremass import common_velocity, moving_together
from derive.checking.centrenames import centre_names
from derive.checking.componentlabels import COMPONENT_OF, SIZE, component_words
from derive.checking.context import Context
from derive.checking.conventions import axis_sense, plus_said, sign_of
from derive.checking.forwardway import forward_said, forward_sign
from derive.checking.gluednames import GLUED_MASS
from derive.checking.instants import one_body_instants
from derive.checking.minusnames import minus_names
from derive.checking.namedlast import in_line_words, named_last, speed_along
from derive.checking.saidwords import SAID_PHRASES, times_beside_words
from derive.checking.saidwords import together as moving_off_together
from derive.checking.speedwords import one_speed_after
from derive.checking.spellings import (
    BODY_WHEN,
    angle_sum_in_degrees,
    body_when,
    greek_letters,
    impulse_name,
    marked_names,
    notes_names,
    subscript,
)
from derive.checking.tersenames import terse_names, terse_only
from derive.checking.wordnames import in_words, says_what
from derive.checking.wrapped import wrapped_sentences
from derive.mathtext.notation import glued_times, student
from derive.mathtext.reader import Relation
from derive.problem.expr import ParseError, parse
from derive.problem.units import DIMENSIONLESS, MASS

#: "KE just after", "KE immediately before": the moment said more closely, the same energy.
_JUST = r"(?:(?:just|immediately|right|directly)\s+)?"
_KE = r"KE"  # not "kinetic energy": in a sentence ("kinetic energy after is 60% of ...") it is prose
_EVENT = r"(?:\s+(?:the\s+)?(?:collision|impact|bounce|rebound|crash))?"  # "KE after the impact"
#: Phrases for the energies and speeds, rewritten as names before reading.
PHRASES = (
    (
        r"(?:(?:\\?Delta|Δ)\s*(?:KE|(?-i:T|E_?k|E|K))\b|(?<![A-Za-z\\])(?-i:d(?:KE|K|E_?k))(?![\w'])"  # dK: ΔK typed
        r"|(?<![A-Za-z])(?:KE|(?-i:K|E_?k))[\s_]*\(?(?:lost|loss)\b\)?|loss\s+(?:of|in)\s+(?:KE|kinetic\s+energy|energy)|KE\s+loss"
        r"|lost\s+KE|T_?\(?lost\)?|(?:kinetic\s+)?energy\s+lost|^\s*loss\s*$)",
        "T_lost",
    ),
    (rf"(?:{_KE}[\s_]*\(?{_JUST}(?:before|initial|1)\)?{_EVENT}|initial\s+{_KE}|T_1)", "T_1"),  # KE_{before}
    (rf"(?:{_KE}[\s_]*\(?{_JUST}(?:after|final|2)\)?{_EVENT}|final\s+{_KE}|T_2)", "T_2"),  # KE just after
    (BODY_WHEN, body_when),  # "speed of A before", "initial velocity of B", "A's initial speed", "B final velocity"
    (r"(?:final\s+)?speed\s+of\s+([AB])(?![\w'])(?:\s+after)?", r"speed_\1"),  # not "speed of approach"
    (r"(?<![\w'])([AB])['’]s\s+(?:final\s+)?speed(?:\s+after)?", r"speed_\1"),  # "B's speed = 3.6"
    (r"^\s*([AB])\s+(?:final\s+)?speed(?:\s+after)?\s*$", r"speed_\1"),  # a whole side "B speed", phone-typed
    (r"(?<![\w'])([AB])['’]s\s+(?:final\s+velocity|velocity\s+after)", lambda m: f"v_{m[1].upper()}2"),
    (r"(?<![\w'])([AB])['’]s\s+(?:initial\s+velocity|velocity\s+before)", lambda m: f"v_{m[1].upper()}1"),
    (r"\|\s*(?:v_?\(?([AB])2?\)?|([AB])_?p)\s*\|", r"speed_\1\2"),  # |v_A|, |v_(A2)|: A's speed after
    (r"direction\s+of\s+([AB])(?:\s+after)?", r"beta_\g<1>2"),  # from the line of centres (x, i)
    (r"(?<![\w'])([AB])\s+after\b", r"v_\1'"),  # "A after = -0.2": A's velocity after
    (r"(?<![\w'])([AB])\s+before\b", r"u_\1"),
    (r"magnitude\s+of\s+(?:the\s+)?impulse", "sqrt(J_n^2)"),
    (
        r"(?:rebound(?:ing)?\s+speed|speed\s+of\s+rebound|^\s*speed\s+after(?:\s+(?:the\s+)?(?:impact|rebound|bounce|collision))?\s*$)",
        "speed_after",  # A's speed after hitting a wall (a name only where B is fixed: inference._speeds)
    ),
    (
        r"speed\s+of\s+approach|approach(?:ing)?\s+speed|closing\s+speed|(?<=\()\s*approach\s*(?=\))",
        "speed_app",
    ),  # not "relative speed":
    (r"speed\s+of\s+separation|separation\s+speed", "speed_sep"),  # before or after?
)
PHRASES += SAID_PHRASES  # a wall's velocity and speed in words
#: Words after which a name is their object, not the quantity a side is (``Angle of A from n``; "speed of P" is P's).
_OBJECT_AFTER = frozenset({"from", "to", "with", "along", "between", "onto", "into", "towards", "toward"})
_DECLARE = re.compile(r"^\s*(?:let|where|with|set)\s+([A-Za-z]\w*)\s*(?:=|:=|be)\s*([A-Za-z]\w*)\s*$", re.I)
_POSITIVE = re.compile(r"^\s*positive\s*[:=]\s*(.+)$", re.I)
#: Names let be quantities said in words (``let a, b = velocities along the line of centres after (A, B)``).
_LET_WORDS = re.compile(
    r"^\s*(?:let|set|define)\s+[A-Za-z]\w*(?:\s*(?:,|and|&)\s*[A-Za-z]\w*)*\s*(?:=|:=|be|denote)\s*(?:the\s+)?"
    r"(?!(?:sqrt|sin|cos|tan|exp|log|ln)\b)[A-Za-z]{3,}\b(?!\s*[=(])",
    re.I,
)
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
#: Names of the common velocity.
COMMON = ("v_G", "v_g", "v_cm", "v_CM", "v_c", "u_G", "V_G", "V_cm", "V_CM", "v_com", "V_com", "v_COM", "V_c")
PREFIX = "?"


def placeholders(expr: sympy.Expr) -> set[sympy.Symbol]:
    """The student's names in ``expr`` not yet given a meaning (written with :data:`PREFIX`)."""
    return {s for s in expr.free_symbols if s.name.startswith(PREFIX)}


class Open(Mapping):
    """The names a side may use: the problem's, the student's known ones, and a placeholder
    symbol for every other name that looks like one (a letter with a subscript, a single
    letter); words do not (so prose fails to parse and is trimmed)."""

    def __init__(self, known: dict[str, sympy.Expr], extra: set[str] = frozenset()) -> None:
        self.known = known
        self.extra = extra  # the student's names with a meaning (habits, declarations)
        self.placeholders: dict[str, sympy.Symbol] = {}

    def __getitem__(self, name: str) -> tuple[sympy.Expr, tuple]:
        if name in self.known:
            return self.known[name], DIMENSIONLESS
        if not name_like(name) and name not in self.extra:
            raise KeyError(name)
        sym = self.placeholders.setdefault(name, sympy.Symbol(PREFIX + name))
        return sym, DIMENSIONLESS

    def __contains__(self, name: object) -> bool:
        return isinstance(name, str) and (name in self.known or name in self.extra or name_like(name))

    def __iter__(self) -> Iterator[str]:
        return iter(self.known)

    def __len__(self) -> int:
        return len(self.known)


#: The readers of names declared in words, in order (the first reading of a name stands).
_WORD_READERS = (in_words, terse_names, named_last, speed_along, centre_names, one_speed_after, minus_names)


def name_like(name: str) -> bool:
    """A name, not a word: ``x``, ``V``, ``u_A``, ``u1``, ``v_G`` (not ``of``, ``the``, ``KE``)."""
    if name in GREEK or (name.partition("_")[0] in GREEK and re.fullmatch(r"[A-Za-z]+_[A-Za-z0-9]{1,6}", name)):
        return True  # mu, delta_0, theta_2
    if re.fullmatch(r"[A-Za-z][A-Za-z0-9]{0,11}(?:_[A-Za-z0-9]{1,11}){1,3}", name):
        return True  # vel_after, speed_B_final: words joined by underscores are a name, never prose
    return len(name) == 1 or re.fullmatch(r"[A-Za-z]{1,2}(?:_[A-Za-z0-9]{1,6}|\d{1,2})", name) is not None


#: Greek letters students name things with (mu the reduced mass, omega, lambda).
GREEK = frozenset(
    {"mu", "lambda", "omega", "gamma", "epsilon", "alpha", "phi", "psi", "sigma", "tau", "delta", "theta", "beta"}
)


def rewrite(text: str, known: set[str], twins: frozenset[str] = frozenset()) -> str:
    """A side with the phrases named and names written side by side split (``3eu``, ``5mv_A``)."""
    text = impulse_name(text) or text  # "impulse on the ball": one name
    text = marked_names(re.sub(r"(?<![A-Za-z_])([A-Za-z][A-Za-z0-9_]*)([₀-₉]+)", subscript, text))  # v₁ -> v_1
    text = greek_letters(text, known)
    text = re.sub(r"\bK\.\s?E\b\.?", "KE", text, flags=re.I)  # K.E.
    for pattern, name in PHRASES:
        text = re.sub(pattern, name, text, flags=re.I)
    text = times_beside_words(text)  # "e x speed before": times, beside a quantity said in words
    text = re.sub(r"(?<![A-Za-z_])([uvVw])'_?([AB12])(?![A-Za-z0-9_])", r"\1_\2'", text)  # v'A: v_A' (engineers')
    text = re.sub(  # v' -> v_p; v_2'' (after a second impact) -> v_2pp
        r"(?<![A-Za-z_])([A-Za-z][A-Za-z0-9_]*)('+)",
        lambda m: m[1] + ("" if "_" in m[1] else "_") + "p" * len(m[2]),
        text,
    )
    text = _GLUED_DIVISOR.sub(r"/(\1)", text)  # 3m/5m, v^2/2g: the divisor is 5m, 2g
    text = glued_times(text)  # 0.5x0.8x1.2^2, before a number and the letters after it are spaced apart
    text = re.sub(r"(?<![\w.])(\d+\.?\d*)(?=[A-Za-z])(?![eE][-+]?\d+(?![\w.]))", r"\1 ", text)  # 3eu: 3 eu; 6.4E1
    text = re.sub(r"(?<![A-Za-z])(a?(?:sin|cos|tan))(?=\d)", r"\1 ", text)  # cos37.6 -> cos 37.6
    text = GLUED_MASS.sub(r"\1 \2_\3\4", text)  # mvA, 2mvQ: m times v_A (mu1 stays μ₁)
    text = re.sub(r"\b([uvVw])([AB12])(\d?[nt]?)\b", r"\1_\2\3", text)  # vA1n -> v_A1n
    text = (
        re.sub(  # vb: v_B (not the bullet's v_b1 beside the block's v_B1: ``twins``, :func:`.gluednames.twin_letters`)
            r"\b([uvVw])_?([ab])(\d?[nt]?)\b", lambda m: m[0] if m[2] in twins else f"{m[1]}_{m[2].upper()}{m[3]}", text
        )
    )
    text = re.sub(r"\b(sin|cos|tan)\s*\(\s*(\d+\.?\d*)\s*\)", r"\1(\2°)", text)  # a bare angle: degrees
    text = angle_sum_in_degrees(text)  # θ = α − 30, 90 − θ
    text = re.sub(r"\b(sin|cos|tan)\s+(\d+\.?\d*)(?![\d.°]|\s*(?:°|deg|rad))", r"\1(\2°)", text)

    def split(m: re.Match) -> str:
        word = m.group(0)
        head, _, sub = word.partition("_")
        if word in known or word in FUNCTION_WORDS or len(head) > 3:
            return word
        if _COMPONENT.fullmatch(word) and any(head[0] + a in known for a in "xyn"):
            return word  # vy' where vx is a name: a component after, never v times y' (16ux stays u times x)
        letters = list(head)
        if sub:
            letters[-1] += "_" + sub
        if len(letters) > 1 and all(x in known for x in letters):
            return " ".join(letters)
        if sub and head not in GREEK and len(letters) > 1 and all(x in known for x in letters[:-1]):
            return " ".join(letters)  # mv_Q: m times the student's own v_Q
        if re.fullmatch(r"\d[A-Z]", sub) and f"{head}_{sub[0]}" in known:  # e_1U: e_1 times U (not v_1i, v_1f)
            return f"{head}_{sub[0]} {sub[1]}"
        if len(word) == 2 and word[0] in known and word[1].isdigit():  # e1: e_1, or the one e; x0: x at the start
            sub = f"{word[0]}_{word[1]}"
            return sub if sub in known else word if word[1] == "0" else word[0]
        if len(word) == 2 and word[0] in known and not _SHORT_WORDS.fullmatch(word.lower()) and word not in GREEK:
            return " ".join(letters)  # gh: g times the student's own h
        return word

    return _NAME.sub(split, notes_names(text))


#: A number glued to one name after a slash, the term ending there (``/5m``, ``/2g)``, not
#: ``/2mv^2``): one divisor, as the student means it.
_GLUED_DIVISOR = re.compile(r"/\s*(\d+\.?\d*[A-Za-z](?:_[A-Za-z0-9]+)?)(?=\s*(?:$|[)+\-=*/,;]))")


_BODY = re.compile(
    r"^(?:(?:for|sphere|ball|particle|disc|body|puck)\s+)?([AB])(?:'s)?(?:\s+(before|after|initially|finally))?$", re.I
)


def of_the_body(
    text: str, label: str, seen: set[str] = frozenset(), names: bool = True, keep: set[str] = frozenset()
) -> str:
    """A side under a body's lead-in (``A: u_x = 2``, ``B before: along = -6``) with the body in
    its names: ``u_x`` -> ``u_Ax``, ``v_y`` -> ``v_Ay``, ``u`` -> ``u_A``, ``along`` -> ``A_n``
    (``A_n'`` after), ``across`` and ``perpendicular`` -> ``A_t``. The problem's own names
    (``keep``: a given speed u) stay as they are."""
    m = _BODY.match(label.strip())
    if not m:  # "Perp: A's component after": a component said in words under its axis
        return after_label(component_words(text, label), label, seen - set(keep))
    body, after = m.group(1).upper(), (m.group(2) or "").lower() in ("after", "finally")

    def own(k: re.Match, name: str) -> str:
        return k.group(0) if k.group(0) in keep else name

    if names:  # a lead-in's body is in the names under it (not a body found from the words)
        text = re.sub(r"\b([uv])_?([xynt])\b", lambda k: own(k, f"{k.group(1)}_{body}{k.group(2)}"), text)
        text = re.sub(r"\b([uv])\b(?!_)", lambda k: own(k, f"{k.group(1)}_{body}"), text)
    prime = "'" if after else ""
    text = COMPONENT_OF.sub("", text)
    if re.fullmatch(r"\s*along(?:\s+(?:the\s+)?line(?:\s+of\s+cent(?:re|er)s)?)?\s*", text, re.I):  # alone
        return f"{body}_n{prime}"
    across = re.fullmatch(
        rf"\s*(?:across|perpendicular(?:\s+to)?)(?:\s+(?:it|(?:the\s+)?line(?:\s+of\s+cent(?:re|er)s)?))?\s*({SIZE})?\s*",
        text,
        re.I,
    )
    if across:
        return f"{body}_{'T' if across.group(1) else 't'}{prime}"
    return text


#: A velocity's letter glued to an axis's and primed (``vx'`` rewritten ``vx_p``): where the unprimed
#: name is the student's, the component after, as students name it.
_COMPONENT = re.compile(r"[uvwV][xyn]_p+")
#: Words of two letters, never two names side by side.
_SHORT_WORDS = re.compile(r"at|of|is|on|or|in|it|to|as|an|be|by|if|so|up|we|no|do|go|he|me|my|us|am|ok|ie|eg|re|vs")
FUNCTION_WORDS = frozenset(
    {"sin", "cos", "tan", "sqrt", "asin", "acos", "atan", "atan2", "exp", "log", "pi", "deg", "rad"}
)


def read_side(text: str, names: Open, first: bool, last: bool) -> sympy.Expr:
    """One side of a relation in the problem's symbols (placeholders for unknown names); where it does
    not read, the first side without its leading words, the last without its trailing ones (prose)."""
    if last:  # "e = 3/4. α is the angle …": the sentence ends at the number
        text = re.split(r"(?<=\d)\.\s+(?=[^\d\s.])", text, maxsplit=1)[0]
    try:
        return parse(student(text), names).expr
    except ParseError:
        if not (first or last):
            raise
    words = text.split()
    for k in range(1, len(words)):
        cut, piece = (words[-k:], words[:-k]) if last and not first else (words[:k], words[k:])
        if last and not first and not re.fullmatch(r"(?:[A-Za-z\s,.;:'’]|(?<=[A-Za-z])-(?=[A-Za-z]))+", " ".join(cut)):
            continue  # "(relative speed)^2": words inside the mathematics are not trimmed
        piece = " ".join(piece)
        if piece.strip() in ("A", "B") or (first and cut[-1].lower() in _OBJECT_AFTER):
            continue  # "Impulse on B = …": the body; "Angle of A from n = 25°": n is the angle's line, not it
        if first and _word_before(piece):
            continue  # "… multiplied by e = 1/2": the word by, not a name b_y times e
        try:
            return parse(student(piece), names).expr
        except ParseError:
            continue
    raise ParseError(f"could not read {text!r}")


def _word_before(piece: str) -> bool:
    """Whether prose trimmed to ``piece`` still opens with a short word before a name (``by e``)."""
    words = piece.split()
    return len(words) > 1 and _SHORT_WORDS.fullmatch(words[0]) is not None and words[1][:1].isalpha()


def habits(ctx: Context, used: set[str] | None) -> dict[str, sympy.Expr]:
    """The habitual names the text uses that the problem does not define, -> what they stand for."""
    nm = ctx.model.nm
    oblique = ctx.problem.oblique
    before = {"A": nm.A1n, "B": nm.B1n}
    after = {"A": _post(ctx, "A"), "B": _post(ctx, "B")}
    out: dict[str, sympy.Expr] = {}
    given = {g.name for g in ctx.problem.givens if not g.unknown}
    theirs = used if used is None or "u" not in given else used - {"u"}  # u a given (speed u): not the habit
    u_used = used is None or any(re.fullmatch(r"u(?:_?[AB12ab]?[nt]?)?", n) for n in used)
    for body, one in (("A", "1"), ("B", "2")):
        for spelled in (f"u_{body}", f"u_{body.lower()}", f"u_{one}", f"u{one}"):
            out[spelled] = before[body]
        for spelled in (f"v_{body}", f"v_{body.lower()}", f"v_{one}", f"v{one}", f"V_{body}"):
            out[spelled] = after[body]  # the A-level habit (u before, v after), u's written or not
        for spelled in (f"u_{body}p", f"v_{body}p", f"u_{one}p", f"v_{one}p", f"u{one}_p", f"v{one}_p"):
            out[spelled] = after[body]  # primed: after the impact
        for plain, primed in ((f"v_{body}", f"v_{body}p"), (f"v_{one}", f"v_{one}p"), (f"v{one}", f"v{one}_p")):
            if used is not None and primed in used:
                out[plain] = before[body]  # v_A and v_A': v_A is the velocity before
        out[f"m{one}"] = out[f"m_{one}"] = ctx.model.m_A if body == "A" else ctx.model.m_B
        if oblique:
            primed = used is not None and any(f"v_{body}{c}p" in used for c in ("", "n", "t"))
            for c in "nt":
                out[f"u_{body}{c}"] = getattr(nm, f"{body}1{c}")
                out[f"v_{body}{c}p"] = getattr(nm, f"{body}2{c}")  # v_At': after
                if not primed:
                    out[f"v_{body}{c}"] = getattr(nm, f"{body}2{c}")  # v as v_A: after (unless v_A' is used)
                else:
                    out[f"v_{body}{c}"] = getattr(nm, f"{body}1{c}")  # v_An beside v_A', v_At': before
    out.update(one_body_instants(ctx, used))  # v_1, v_2 against a wall: before, after
    names = ctx.equation_names()
    for alias, name in (("theta_1", "theta"), ("theta", "theta_1"), ("theta_2", "theta_A2"), ("theta", "theta_A1")):
        if name in names:
            out.setdefault(alias, names[name][0])
    if oblique:
        out.update(letter_components(ctx, used))
    out["u"] = before["A"]
    if oblique:  # a single body's components
        out["u_n"], out["u_t"] = nm.A1n, nm.A1t
        if u_used:
            out["v_n"], out["v_t"] = nm.A2n, nm.A2t
    if fixed := ctx.problem.fixed_B:  # one body: its mass is m, v its velocity after
        out["m"] = ctx.model.m_A
        out["v"] = after["A"]
    if u_used and not ({"v_A2", "v_A2n"} & given):  # A's after given (S brought to rest): v is not A's
        out["v"] = after["A"]
    if moving_off_together(ctx.problem):  # they move off together: V after (v' too)
        out["V"] = out["v_f"] = out["v_2"] = out["v_p"] = out["V_p"] = moving_together(ctx, after["A"], after["B"])
    bare_u = theirs is None or bool({"u", "u_n", "u_t", "un", "ut"} & theirs) or bool(fixed)  # u_A, u_B: v not A's
    out.update(_lone(ctx, after, bare_u, used is not None and {"v", "V"} <= used))
    rest = {g.name[2] for g in ctx.problem.givens if g.name in ("v_A1", "v_B1") and g.value == 0} | set("B" * fixed)
    moving = [b for b, x in before.items() if x is not None and b not in rest]
    if used is not None and {"v", "v_p"} <= used and len(moving) == 1:  # v' = m v/(m + M): v before, v' after
        out["v"], out["v_p"] = before[moving[0]], out.get("v_p", after[moving[0]])
    for name in COMMON:
        out[name] = common_velocity(ctx)
    return {k: v for k, v in out.items() if (used is None or k in used) and k not in names and v is not None}


def _lone(ctx: Context, after: dict[str, sympy.Expr | None], u_used: bool, both: bool) -> dict[str, sympy.Expr]:
    """``v`` (``V``) alone where one velocity after is not given (``20v + 35(0.3)`` when B's is),
    or the bodies move off together (e = 0): that velocity; ``M`` where one mass is unknown.
    Where the text uses ``v`` and ``V`` (``both``) and they move off together, V is their
    velocity and v another quantity (the bullet's ``v = 300 m/s`` before)."""
    p = ctx.problem
    out: dict[str, sympy.Expr] = {}
    given = {g.name for g in p.givens if not g.unknown}
    open_ = [b for b in "AB" if not ({f"v_{b}2", f"v_{b}2n"} & given)]
    together = moving_off_together(p)
    lone = moving_together(ctx, after["A"], after["B"]) if together else after[open_[0]] if len(open_) == 1 else None
    if not p.oblique and not u_used and lone is not None:
        out["V"] = lone  # together: their common velocity after (:func:`moving_together`)
        if not (together and both):
            out["v"] = lone
    masses = [g.symbol for g in p.givens if g.unknown and g.dim == MASS]
    if len(masses) == 1:  # the one mass to find: M, or m where no given mass is written with m
        out["M"] = masses[0]
        if not any(str(s) == "m" for g in p.givens for x in (g.value, g.definition) if x for s in x.free_symbols):
            out["m"] = masses[0]
    return out


def _post(ctx: Context, body: str) -> sympy.Expr | None:
    nm = ctx.model.nm
    return getattr(nm, f"{body}2n")


def declaration(line: str) -> bool:
    """Whether ``line`` is a declaration (``let x = v_A2``, ``positive: …``), not a relation to judge."""
    line = re.sub(r"^\s*(?:#|%|//|<!--)\s*|\s*-->\s*$", "", line)
    return bool(_DECLARE.match(line) or _POSITIVE.match(line) or says_what(line) or terse_only(line))


def declares(r: Relation, first: bool) -> bool:
    """Whether the relation ``r`` is a declaration: its own text is one, or its line is one and it
    is the line's first relation (``Positive = away from the cushion.  u = -3.00``: only the first)."""
    if _LET_WORDS.match(r.written):
        return True  # "let a, b = velocities … (A, B)": every piece of it
    return declaration(" = ".join(r.sides)) or (first and declaration(r.written) and not _POSITIVE.match(r.written))


def declarations(
    text: str, ctx: Context, placed: Callable[[str], dict] | None = None
) -> tuple[dict[str, sympy.Expr], int]:
    """``let x = v_A2`` lines -> {x: v_A2}, and the sign of a ``positive:`` line (+1 where none);
    ``placed``: the unit vectors a line places (:func:`.frames.declared_axes`), whose sign it says."""
    names = ctx.equation_names()
    out: dict[str, sympy.Expr] = {}
    sign = 0
    for line in text.splitlines():
        line = in_line_words(re.sub(r"^\s*(?:#|%|//|<!--)\s*|\s*-->\s*$", "", line), ctx)  # "along XY"
        m = _DECLARE.match(line)
        if m and m.group(2) in names:
            out[m.group(1)] = names[m.group(2)][0]
        for reader in _WORD_READERS:  # "x = velocity of A after", "let B's velocity be v", "after it is -v", …
            out.update({k: v for k, v in reader(line, ctx).items() if k not in out})
        if not sign and not re.search(r"\bpositive\b|\+\s?ve\b", line, re.I):
            sign = axis_sense(line)  # "n along the line of impact (from A to B)": the student's positive
        if placed is not None and placed(line):
            continue  # "ĵ out of the wall (positive away from it)": a unit vector's way, the reader placed it
        m = _POSITIVE.match(line)
        if m:
            sign = sign_of(m.group(1).split(".")[0]) or sign
        elif re.search(r"\bpositive\b|\+\s?ve\b", line, re.I) and not sign:  # "taking A's direction as +ve"
            sign = sign_of(line)
        elif re.search(r"\b(?:both|each|all|measured|taken)\b[^.;]*?\bin\s+the\s+(?:direction|way)\b", line, re.I):
            sign = sign or sign_of(line)  # "x and y, both in the direction B was moving"
        elif not sign and (plus := plus_said(line)):
            sign = plus  # "(towards wall is +)", "(+ away from the wall)"
        if not sign and forward_said(line):
            sign = forward_sign(ctx)  # "Momentum (forward +)": the way the bodies go before the impact
    for said in wrapped_sentences(text):  # "let x and y be … along the" / "line of centres after"
        out.update({k: v for k, v in in_words(in_line_words(said, ctx), ctx).items() if k not in out})
    return out, sign
