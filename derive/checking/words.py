"""A derivation's report in a student's words: what derive took their names to mean, why a
line was not read, and what a slip is, without derive's internal names or numbers.

This module only words what the checks found (it judges nothing): ``meaning("v_A2n", p)``
is "A's velocity after the impact, along the line of centres"; :func:`name_note` says how a
student's name was read ("θ: read as the angle of A's velocity before the impact, from the
line of centres."); :func:`not_read` turns a reader's message ("unexpected character '\\'
at position 10") into one a student can act on ("derive could not read `\\lvert` here").
"""

from __future__ import annotations

import math
import re
from typing import Any

from derive.checking.numeric import number_of

#: Greek letters as a student sees them (their LaTeX and plain names are the keys).
GREEK_SHOWN = {
    "alpha": "α",
    "beta": "β",
    "gamma": "γ",
    "delta": "δ",
    "epsilon": "ε",
    "theta": "θ",
    "lambda": "λ",
    "mu": "μ",
    "phi": "φ",
    "psi": "ψ",
    "sigma": "σ",
    "tau": "τ",
    "omega": "ω",
}
#: The equations (1)-(4) in words, for a student who never numbered them.
EQUATION_WORDS = {
    1: "the conservation of A's momentum along the tangent (across the line of impact)",
    2: "the conservation of B's momentum along the tangent (across the line of impact)",
    3: "the conservation of momentum of A and B together along the line of impact",
    4: "Newton's law of restitution (separation = e × approach)",
}
#: The rest of a mistake's "where" in words (the stages of derive's page are not the student's).
_STAGE = re.compile(r"\s*\(stage \d+\)")
_EQUATIONS = re.compile(r"^(?:\(\d\)(?:,\s*)?)+:\s*")


def shown(name: str) -> str:
    """A student's name as they see it: ``theta`` -> θ, ``theta_1`` -> θ_1, ``v_A`` unchanged."""
    head, sep, tail = name.partition("_")
    return GREEK_SHOWN.get(head, head) + sep + tail


def _line(problem: Any) -> str:
    if getattr(problem, "fixed_B", False):
        return "the normal to the surface"
    return "the line of centres"


def _body(problem: Any, b: str) -> str:
    labels = getattr(problem, "labels", ("A", "B")) or ("A", "B")
    label = labels[0] if b == "A" else labels[1]
    return f"{label}'s"


def _axis(problem: Any, axis: str | None) -> str:
    axis = (axis or "").lstrip("+-")
    if axis == "n":
        return _line(problem)
    if axis == "t":
        return "the tangent (across the line of impact)"
    return f"the {axis} axis" if axis else "its axis"


#: After a velocity read in the centre of mass's frame (:mod:`.namenotes`).
_RELATIVE = " relative to the centre of mass"


def meaning(name: str, problem: Any) -> str:
    """derive's name ``name`` (``v_A2n``, ``theta_A1``, ``-v_B2``, ``T_lost``) in words,
    with the problem's labels for the bodies; a name it does not know is given as written."""
    if name == "-J_n":
        return "the impulse on A along the line of impact"  # B's impulse turned round: A's (n from A toward B)
    if name.startswith("-"):
        return meaning(name[1:], problem) + ", taken positive the other way"
    if name.endswith(_RELATIVE):  # a velocity in the centre of mass's frame (:mod:`.cmframe`)
        return meaning(name.removesuffix(_RELATIVE), problem) + _RELATIVE
    when = {"1": "before the impact", "2": "after the impact"}
    m = re.fullmatch(r"v_([AB])([12])([ntv]?)", name)  # v: the vector of both components
    if m:
        b, k, c = m.groups()
        oblique = getattr(problem, "oblique", False)
        what = "velocity" if c or not oblique else "speed"
        if c == "v":
            return f"{_body(problem, b)} velocity {when[k]} (the vector)"
        along = f", along {_line(problem)}" if c == "n" else ", along the tangent" if c == "t" else ""
        return f"{_body(problem, b)} {what} {when[k]}{along}"
    m = re.fullmatch(r"(theta|beta|alpha)_([AB])([12])", name)
    if m:
        kind, b, k = m.groups()
        motion = getattr(problem, f"motion_{b}", None) if k == "1" else None
        axis = getattr(motion, "axis_from", None) if motion is not None else ("t" if kind == "theta" else "n")
        return f"the angle of {_body(problem, b)} velocity {when[k]}, from {_axis(problem, axis)}"
    m = re.fullmatch(r"m_([AB])", name)
    if m:
        return f"{_body(problem, m.group(1))} mass"
    m = re.fullmatch(r"delta_([AB])", name)
    if m:
        return f"the angle {_body(problem, m.group(1))} velocity turns through in the impact (its deflection)"
    fixed = {
        "e": "the coefficient of restitution",
        "T_1": "the kinetic energy before the impact",
        "T_2": "the kinetic energy after the impact",
        "T_lost": "the kinetic energy lost",
        "J_n": "the impulse on B along the line of impact",
        "the common velocity": "the common velocity, the velocity of the centre of mass",
        "the fixed velocity": "the velocity of the fixed surface (0: it does not move)",
    }
    if name in fixed:
        return fixed[name]
    m = re.fullmatch(r"speed_([AB])(1?)", name)
    if m:
        return f"{_body(problem, m.group(1))} speed {'before' if m.group(2) else 'after'} the impact"
    return f"the given {name}"


def glossary(solution: Any, names: Any = ()) -> dict[str, str]:
    """derive's names (``names``, and a chain's values) in words, for :func:`notes_in_words`;
    the key "positive" says the direction opposite to derive's n."""
    p = solution.problem
    out = {str(n): meaning(str(n), p) for n in names}
    out["the common velocity"] = meaning("the common velocity", p)
    out["the fixed velocity"] = meaning("the fixed velocity", p)
    out.update({f"v_{b}{k}v": meaning(f"v_{b}{k}v", p) for b in "AB" for k in "12"})  # a vector (_vectors)
    out.update(
        {
            f"v_{b}{k}{c}{_RELATIVE}": meaning(f"v_{b}{k}{c}{_RELATIVE}", p)
            for b in "AB"
            for k in "12"
            for c in ("", "n")
        }
    )
    stages = [st for st in getattr(solution, "stages", ()) or () if getattr(st, "values", None) is not None]
    for k, st in enumerate(stages if len(stages) > 1 else ()):  # a chain's stages (a single impact has one)
        before = {str(n) for n in st.values}
        after = stages[k + 1].values if k + 1 < len(stages) else (solution.values or {})
        title = getattr(st, "title", "") or getattr(st, "kind", "")
        for n in {str(n) for n in after} - before:
            out[n] = f"the chain's {n}, found in stage {k + 1} ({title[:1].lower() + title[1:]})"
    labels = getattr(p, "labels", ("A", "B")) or ("A", "B")
    out["positive"] = f"from {labels[1]} toward {labels[0]} along {_line(p)}"
    return out


def _meant(name: str, known: dict[str, str]) -> str:
    if name == "-J_n" and "J_n" in known:
        return meaning(name, None)
    if name.startswith("-") and name[1:] in known:
        return known[name[1:]] + ", taken positive the other way"
    return known.get(name, name)


def _pairs(listed: str, sep: str) -> list[tuple[str, str]]:
    out = []
    for part in listed.split(", "):
        name, found, what = part.partition(sep)
        if not found:
            return []
        out.append((name.strip(), what.strip()))
    return out


def notes_in_words(notes: tuple[str, ...] | list[str], known: dict[str, str]) -> list[str]:
    """The checker's notes on names ("Read v_A as v_A2n, theta as theta_A1.", "Inferred from
    the relations: x is v_A2.") as one sentence a name in the student's terms ("θ: read as the
    angle of A's velocity before the impact, from the line of centres."); other notes as they are."""
    out: list[str] = []
    forms = (
        ("Declared: ", " is ", "declared"),
        ("Read from the relations: ", " is ", "equated"),
        ("Inferred from the relations: ", " is ", "inferred"),
        ("Inferred from the values: ", " is ", "values"),
        ("Read ", " as ", "habit"),
    )
    # a name read by habit (v_An as v_A2n) means what derive's name means, where another note
    # says a student's name is it ("a is v_An")
    for note in notes:
        if note.startswith("Read ") and note.endswith("."):
            for student, name in _pairs(note[len("Read ") : -1], " as "):
                if name in known and student not in known:
                    known = {**known, student: known[name]}
    for note in notes:
        if note.startswith("Inferred from the values written: the positive direction"):
            where = known.get("positive", "opposite to derive's n")
            out.append(f"I took your positive direction to be {where} (from the values you wrote).")
            continue
        form = next((f for f in forms if note.startswith(f[0]) and note.endswith(".")), None)
        pairs = _pairs(note[len(form[0]) : -1], form[1]) if form else []
        if not pairs:
            out.append(note)
            continue
        if form[2] == "habit":
            pairs = _vectors(pairs)
        for student, name in pairs:
            if form[2] == "habit":
                student = re.sub(r"(?<=[A-Za-z0-9])_?p$", "′", student) if re.search(r"_\w*p$", student) else student
            if "*" in name and name.replace("*", "") == student:  # mu as m*u (not friction as mu_k*g*3010)
                out.append(product_note(student))
            else:
                out.append(name_note(_said(student), _meant(name, known), form[2]))
    return out


def _said(student: str) -> str:
    """A name read from words (``impulse_A``, ``dp_B``: :func:`~.spellings.impulse_name`) as the
    student wrote it: "impulse on A", "change in momentum of B"."""
    m = re.fullmatch(r"(impulse|dp)(?:_([AB]))?", student)
    if m is None:
        return student
    said = "impulse" if m[1] == "impulse" else "change in momentum"
    return f"{said} {'on' if m[1] == 'impulse' else 'of'} {m[2]}" if m[2] else said


def _vectors(pairs: list[tuple[str, str]]) -> list[tuple[str, str]]:
    """A vector's components read (``u_An`` as v_A1n, ``u_At`` as v_A1t) as the vector (``u_A``)."""
    read = dict(pairs)
    out: list[tuple[str, str]] = []
    for student, name in pairs:
        stem, c = student[:-1].rstrip("_") or student[:-1], student[-1:]
        other = student[:-1] + ("t" if c == "n" else "n")
        if c in ("n", "t") and other in read and name[-1:] == c and read[other][-1:] != c:
            if stem not in read and (stem, name[:-1] + "v") not in out:
                out.append((stem, name[:-1] + "v"))
            continue
        out.append((student, name))
    return out


def name_note(student: str, words: str, how: str) -> str:
    """One sentence on how a student's name was read (``words``: what it was taken to mean);
    ``how`` is "declared", "habit", "inferred" (from the relations), "equated" (set equal in
    a relation) or "values"."""
    if how == "declared":
        return f"{shown(student)}: {words} (as you declared)."
    if how == "habit":
        return f"{shown(student)}: read as {words}."
    if how == "values":
        return f"I took {shown(student)} to be {words} (from the values you wrote)."
    return f"I took {shown(student)} to be {words} (from your relations)."


def product_note(word: str) -> str:
    """A Greek letter's name typed in letters read as the givens it spells: ``mu`` as m × u
    (said as typed: a μ typed as the letter is the Greek name, never this)."""
    return (
        f"{word}: read as {' × '.join(word)} (the product of the given {' and '.join(word)}), not as a name of its own."
    )


def names_on(note: str) -> str | None:
    """The student's name a :func:`name_note` sentence is about (None for other notes)."""
    m = re.match(r"(?:I took )?(\S+?)(?::| to be )", note)
    return m.group(1) if m else None


def reminder(note: str) -> str:
    """A :func:`name_note` said again under a line that uses the name: "Here θ was read as …"."""
    m = re.match(r"(\S+): read as (.*)", note)
    if m:
        return f"Here {m.group(1)} was read as {m.group(2)}"
    m = re.match(r"(\S+): (.*) \(as you declared\)\.", note)
    if m:
        return f"Here {m.group(1)} is {m.group(2)}, as you declared."
    return f"Here {note}" if note.startswith("I ") else note


def on_line(name: str, written: str) -> bool:
    """Whether the student's ``name`` (as :func:`shown` gives it) is written on a line."""
    plain = re.sub(r"\\(?:mathbf|mathrm|boldsymbol|vec|text|bm)\s*\{([^{}]*)\}", r"\1", written)
    plain = re.sub(r"\\([A-Za-z]+)", r" \1 ", re.sub(r"[{}]", "", plain))  # \tan\theta: tan theta
    for greek, letter in GREEK_SHOWN.items():
        plain = re.sub(rf"\\?{greek}(?![A-Za-z])", letter, plain)
    spelled = re.escape(name).replace("_", "_?")  # v_1 is also written v1; v_B′ as v_B'
    spelled = spelled.replace("′", r"(?:′|'|\^\s*prime)")
    return re.search(rf"(?<![\w\\]){spelled}(?![\w'′])", plain) is not None


def equations_in_words(text: str) -> str:
    """A mistake's "where" for a student: "(1), (2), (3), (4): the n and t components before the
    impact (stage 1), and …" -> "the n and t components before the impact, and …"."""
    return _STAGE.sub("", _EQUATIONS.sub("", text))


_MATHS = ("sqrt", "sin", "cos", "tan", "atan", "asin", "acos", "arctan", "log", "exp", "deg", "rad", *GREEK_SHOWN)
#: Words in a relation (not a function or a Greek letter's name): "approach speed", "Substituting".
_WORDS = re.compile(rf"(?<![A-Za-z_\\])(?!(?:{'|'.join(_MATHS)})(?![A-Za-z]))[A-Za-z]{{3,}}(?:\s+[A-Za-z]{{2,}})*")
_COMMAND = re.compile(r"\\[A-Za-z]+|\\.")


def not_read(error: str, sides: tuple[str, ...] | list[str], written: str) -> str:
    """ "not read: …" for a student: which part of the line derive could not read, and what to
    write instead where that is clear (``mv_Q``: write ``m v_Q``)."""
    m = re.match(r"unknown name '([^']+)'", error)  # the expression parser's, with the names it knows
    if m:
        return _unknown_name(m.group(1))
    m = re.match(r"unknown names? (.*?)\.?$", error)
    if m:
        unknown = [n.strip("'\" ") for n in m.group(1).split(",") if n.strip("'\" ")]
        if len(unknown) == 1:
            return _unknown_name(unknown[0])
        shown_names = " and ".join(f"`{n}`" for n in unknown)
        return f"derive does not know the names {shown_names}: say what each is on a line of its own (for example `let {unknown[0]} = v_A2`)"
    m = re.match(r"could not read '(.*)'$", error)
    if m:
        part = m.group(1).replace("\\\\", "\\")
        if re.fullmatch(r"[A-Za-z]{2,}(?:\s+[A-Za-z]{2,})*", part):
            return f"derive could not read the words “{part}” as a quantity (write a quantity as a symbol, such as T_1 or v_A)"
        command = _COMMAND.search(part)
        return f"derive could not read “{command.group(0) if command else part}” here"
    text = " ".join(s for s in sides if s) or written
    words = None
    rest = written.replace(sides[0], " ", 1) if sides and sides[0] else written
    for part in (*sides[1:], rest, *sides[:1]):  # a first side in words ("KE lost") is a name
        words = words or _WORDS.search(re.sub(r"\\[A-Za-z]+|[{}$]", " ", part))
    if words and re.match(r"unexpected|expected", error):
        return (
            f"derive could not read the words “{words.group(0)}” in a relation "
            "(put words on a line of their own, and write a quantity as a symbol)"
        )
    m = re.match(r"unexpected character '(.*)' at position", error)
    if m:
        bad = m.group(1).encode().decode("unicode_escape") if m.group(1).startswith("\\") else m.group(1)
        return f"derive could not read “{_token(bad, text, written)}” here"
    m = re.match(r"unexpected '(.*)'(?: after the expression)?$", error)
    if m:
        return f"derive could not read “{_token(m.group(1), text, written)}” here"
    return f"derive could not read this line ({error})"


def _token(bad: str, text: str, written: str) -> str:
    """The command or character ``bad`` starts, with a little of the text around it."""
    for source in (written, text):
        if bad == "\\":
            m = _COMMAND.search(source)
            if m:
                return m.group(0)
        i = source.find(bad)
        if i >= 0:
            return source[max(0, i - 8) : i + len(bad) + 8].strip()
    return bad


def _unknown_name(name: str) -> str:
    m = re.fullmatch(r"([A-Za-z])([A-Za-z](?:_\w+)?)", name)
    if m:
        a, b = m.groups()
        return f"`{name}` — if you mean {a} × {b}, write {a} {b}"
    return f"derive does not know the name `{name}`: say what it is (for example `let {name} = v_A2`)"


#: Functions and constants a side of numbers may have (a side with any other letter has names).
_NUMERIC = re.compile(r"(?<![A-Za-z])(?:sqrt|sin|cos|tan|atan|asin|acos|arctan|log|ln|exp|pi|deg|rad)(?![A-Za-z])|°")
_NUMBER_UNIT = re.compile(r"^\s*\(?([-+]?(?:\d+\.?\d*|\.\d+))\)?\s*([^\d\s].*)$")
#: What a unit typed after a number looks like (m s^-1, m/s, ms-1, kg m s⁻¹): letters, and
#: exponents only after a letter; not a function, a bracketed term or a division by a number.
_UNIT_LIKE = re.compile(r"[A-Za-zµμΩ°%](?:[A-Za-zµμΩ°%\s/·*.]|\^[({]?[-−]?\d[)}]?|[-−]\d|[⁻¹²³])*")


def student_text(plain: str) -> str:
    """A side in plain syntax as the student reads it: Greek names as letters (``theta`` -> θ)."""
    for greek, letter in GREEK_SHOWN.items():
        plain = re.sub(rf"\b{greek}\b", letter, plain)
    return plain


def numbers_only(text: str) -> bool:
    """Whether a side is arithmetic only (numbers, functions, π): its value is one the student
    can check with a calculator, not a sample value of derive's."""
    return re.search(r"[A-Za-zα-ωΑ-Ω]", _NUMERIC.sub(" ", text)) is None


def unequal(left_text: str, left: float, right_text: str, right: float) -> str:
    """Why an arithmetic line does not hold, with no number the student did not write and that
    is not the value of a side they wrote: "sqrt(22.5625) is 4.750, not 0.21"; the other side's
    value only where it is arithmetic; a number whose words after it were not read as a unit
    said so."""
    from derive.numbers import format_number  # a number as the report prints it

    value = format_number(left, 4)
    rt = right_text.strip()
    angle = re.fullmatch(r"\(?([-+]?(?:\d+\.?\d*|\.\d+))\s*(?:°|\*\s*deg|\^\\circ)\)?", rt)
    if angle:  # an angle written in degrees: the value in degrees too, not in radians
        return f"{left_text} is {format_number(math.degrees(left), 4)}°, not {angle.group(1)}° (an arithmetic slip)."
    if re.fullmatch(r"[-+]?\(?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?\)?", rt):
        return f"{left_text} is {value}, not {rt} (an arithmetic slip)."
    unit = _NUMBER_UNIT.match(rt)
    if unit and _UNIT_LIKE.fullmatch(unit.group(2)) and not _NUMERIC.search(unit.group(2)):
        # 4.75 m s^-1: the number as written, and the words after it not read as a unit
        number = unit.group(1)
        if abs(float(number) - left) <= 0.51 * 10 ** _last_place(number) + 1e-12 * abs(left):
            return (
                f"{left_text} is {value}, as you wrote, but what follows {number} was not read as a unit "
                "(write the unit as, for example, m/s)."
            )
    rt = tidy(student_text(rt))
    if numbers_only(rt):
        return f"{left_text} is {value}, but {rt} is {format_number(right, 4)} (an arithmetic slip)."
    return f"{left_text} is {value}, and it is not equal to {rt} (an arithmetic or algebra slip)."


def tidy(plain: str) -> str:
    """A side in plain syntax without the brackets the reader put round single terms:
    ``((2sqrt(3))/(3.25))`` -> ``2sqrt3/3.25``."""
    before = None
    while before != plain:
        before = plain
        plain = re.sub(r"\(([\w.]+)\)", r"\1", plain)
    while plain.startswith("(") and _closing(plain, 0) == len(plain) - 1:
        plain = plain[1:-1]
    return plain


def _closing(text: str, i: int) -> int:
    """The index of the bracket that closes the one at ``i`` (-1 where none does)."""
    depth = 0
    for k in range(i, len(text)):
        depth += {"(": 1, ")": -1}.get(text[k], 0)
        if depth == 0:
            return k
    return -1


def _last_place(number: str) -> int:
    """The power of ten of a written number's last figure (``4.75`` -> -2, ``120`` -> 0)."""
    digits = number.lstrip("+-")
    return -len(digits.split(".")[1]) if "." in digits else 0


def sides_unequal(text: str, left: Any, right: Any, point: dict) -> str:
    """Why a line of numbers is false, in the student's text: its two sides worked out (never
    sample values of symbolic givens: ``point`` holds them)."""
    lv, rv = (number_of(x.xreplace(point)) for x in (left, right))
    sides = text.split(" = ")
    if lv is None or rv is None or point:
        return "its two sides are not equal (an arithmetic or algebra slip)."
    left_text = re.sub(r"(?<=[\w).])([-+*/])", r" \1 ", sides[0]).replace(" * ", " ")
    return unequal(student_text(left_text), lv.real, sides[1], rv.real)
