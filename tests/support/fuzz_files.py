"""Files written the way users and attackers write them, from derive's declared schema.

Every field of every table (problem files, chain files with every stage type, answers
files) is a *slot*; file number k breaks slot k mod (number of slots), so each field
is broken many times a run, and one to three random slots more. A slot is set to a
value drawn for its type (right ones, wrong types, huge and tiny numbers, deep nesting,
control characters, TeX/HTML/MathJax payloads, Unicode), deleted, or joined by an
unknown key (a typo of a known one, or garbage). A few files are broken as bytes (a
byte-order mark, cut short, bad UTF-8, nested 1,000 deep). Everything follows from one
``random.Random(seed)``: the same seed writes the same files.
"""

from __future__ import annotations

import copy
import datetime as dt
import math
import random
import re
import tomllib
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from derive.problem.schema import ANSWERS, CHAIN, PROBLEM, STAGES, Field, Table

ROOT = Path(__file__).resolve().parents[2]

# ---------------------------------------------------------------- payloads

CONTROL = [
    "\x1b]0;PWNED\x07",
    "\x1b[2J\x1b[31m",
    "\x00",
    "\x07",
    "\r",
    "\x08\x08",
    "\x7f",
    "\x9b31m",
    "\u202e",
    "\u2028",
]
MARKUP = [
    r"\input{/etc/passwd}",
    r"\immediate\write18{touch pwned}",
    r"$x^2$",
    r"\(\frac{1}{2}\)",
    r"$$\input{x}$$",
    "<script>alert(1)</script>",
    '<img src=x onerror="alert(1)">',
    "{{ 7*7 }} {% raw %}",
    r"\VAR{title} \BLOCK{if 1}",
    "[x](javascript:alert(1))",
    "`code` **bold** # head",
    "}}}\\end{document}",
    "^^5cinput ^^M",
    "%%%% ####",
]
UNICODE = [
    "ß é Ω θ ° ½",
    "😀🚀",
    "\u200bzero\u200dwidth",
    "ｍ／ｓ",
    "١٢٣",
    "e\u0301\u0301\u0301",
    "\ufeffbom",
    "\U0010ffff",
]
NAMES = ["m_A", "m_B", "e", "v_A1", "v_B1", "v_0", "m", "h", "x", "theta", "u", "k_s", "g", "pi", "sin",
         # names SymPy knows (issue #29): constants, sets, functions, and results of another kind of impact
         "E", "I", "oo", "zoo", "nan", "S", "N", "Q", "O", "beta", "gamma", "lambda", "sqrt", "atan2",
         "theta_A2", "v_A2x", "beta_B2", "v_A2n"]  # fmt: skip
EXPRESSIONS = [
    "2*m_A", "m_A + m_B", "sqrt(2)*v_A1", "asin(75/123)", "atan2(1, 2)", "(v_A1 - v_B1)/2", "e^2", "-v_A1",
    "9^9^9", "(10^30)^64", "x^x", "1e999", "1e-999", "2^(2^64)", "exp(exp(exp(exp(exp(1)))))",
    "sin(sin(sin(sin(sin(1)))))", "((((((((((((((((((((((((((((((((((((((((((1))))))))))))))))))))))))))))))))))))))))))",
    "1" + "+1" * 400, "__import__('os').system('x')", "e.__class__", "lambda: 1", "1/(e - e)", "log(0)",
    "sqrt(-1)", "v_A1 + m_A", "1.2.3", "u*(1e30)^10", "w*(1e-30)^10", "0^(-1)", "atan2(0, 0)",
    "q = 1e99999999 m/s", "1e99999999", "v_0 = 40 m", "h_2 = 40 m", "= =", "",
    # issue #29: names SymPy knows, out-of-range inverse functions, a result that is 0 in a denominator
    "2*pi", "E + I", "oo", "zoo*u", "theta_A2", "v_A2x", "acos(v_B2/v_A2)", "asin(2)", "J_n/T_lost",
    "J_n/(e - e)", "1/3 kg", "-sqrt(2) m/s", "sin(100*e)", "tan(100*e)", "v_A2^63",
]  # fmt: skip
#: Relations for "show", "equations", a range's "where", conditions (issue #29: periodic ones,
#: one off by a tiny term, high powers, a result of another kind of impact).
RELATIONS = [
    "v_B2 = u*(1 + e)/3", "v_B2 = u*(1 + e)/3 + 1e-30*u", "v_B2 = u*(1.0000001 + e)/3", "sin(100*e) > 0",
    "sin(1000*e) > 0", "sin(100*e) + e > 0.5", "tan(100*e) = 1", "tan(10*e) = 1", "v_A2^63 < v_B2^63",
    "v_A2 < v_B2", "T_2 = 3/4*T_1", "v_A2 = 0 m/s", "theta_A2 = 0", "pi = 3", "E > 0", "v_A2 < 0",
]  # fmt: skip
#: Answers in E notation (issue #29): each must be judged at its own figures.
E_NOTATION = ["-1e1", "1e3", "0e9", "-0e3", "1e30", "1E2", "2.5e-3", "1e-320", "1e6", "-1.11e0", "3.05E+00"]
QUANTITIES = [
    "2 kg", "3.5 m/s", "-1 m/s", "0", "? kg", "?", "kg", "m/s", "36 km/h", "15 lb", "0.2 slug", "30 deg",
    "0.5 rad", "100 mm", "200 N/m", "9.8 m/s^2", "4e99 m/s", "1e30 kg", "1e-30 kg", "1e31 kg", "2 stone",
    "5 m/s/s", "nan kg", "inf m/s", "-0 kg", "1_000 kg", "0x10 kg", "１ kg",
    "1e3", "-1e1 m/s", "0e9 m/s", "2.5E-3 kg", "1/3 kg", "101 mm",
]  # fmt: skip
NUMBERS = [0, -0.0, 1, -1, 0.5, 1.3, 3, 10, 51, 2**63 - 1, -(2**63), 1e30, 1e31, 1e-30, 1e-31, 1e308, 5e-324,
           math.inf, -math.inf, math.nan]  # fmt: skip
WRONG_TYPES: list[Any] = [True, False, [], [1, "kg"], {}, {"a": 1}, dt.date(1979, 5, 27), dt.time(7, 32), 3.5, 2, "2"]


def text_payload(rng: random.Random) -> str:
    """A line of text with control characters, markup payloads and Unicode mixed in."""
    parts = [
        rng.choice(CONTROL + MARKUP + UNICODE + ["plain words", "Ball on a wall"]) for _ in range(rng.randint(1, 4))
    ]
    return " ".join(parts)


def value_for(f: Field, rng: random.Random) -> Any:
    """A value for field ``f``: usually one of its type (often a wrong or extreme one), sometimes any type."""
    if rng.random() < 0.15:  # a copy: a shared [] or {} later filled in could come to hold itself
        return copy.deepcopy(rng.choice([*WRONG_TYPES, *NUMBERS, text_payload(rng), deep_value(rng)]))
    t = f.type
    if f.name in ("show", "equation", "equations", "where", "condition", "conditions") and rng.random() < 0.6:
        return rng.choice(RELATIONS)
    if f.name in ("answer", "value") and rng.random() < 0.3:
        return rng.choice(E_NOTATION)
    if t in ("text", "line"):
        return rng.choice(
            [text_payload(rng), "x" * ((f.max_length or 60) + 1), "", " ", "ok", "a\x00b", "\n\n", rng.choice(UNICODE)]
        )
    if t == "boolean":
        return rng.choice([True, False, "false", "true", 0, 1, "yes"])
    if t in ("integer", "number"):
        return rng.choice([*NUMBERS, int(f.minimum or 0) - 1, int(f.maximum or 10) + 1, 10**4000, 3])
    if t == "choice":
        word = rng.choice(f.choices)
        return rng.choice([word, word.upper(), word + " ", word[:-1], "", text_payload(rng), *f.choices])
    if t in ("value", "expression", "tolerance"):
        return rng.choice([rng.choice(QUANTITIES), rng.choice(EXPRESSIONS), rng.choice(NUMBERS), text_payload(rng)])
    if t == "name":
        return rng.choice([*NAMES, "2x", "a b", "x" * 40, "new_name", "q_9", text_payload(rng), "again"])
    if t == "names":
        return rng.choice([["v_A2", "T_lost"], ["v_C2"], [], "v_A2", [1, 2], ["x" * 40] * 40, [text_payload(rng)]])
    if t == "unit":
        return rng.choice(["km/h", "mph", "stone", "", "m/s^9", text_payload(rng)])
    if t == "list":
        item = f.items
        if item is not None and item.type != "table":
            return [value_for(item, rng) for _ in range(rng.choice([0, 1, 2, 3, 40]))]
        return rng.choice([[], [1], "stage", [{"type": "fall"}]])
    assert t == "table"
    return rng.choice([{}, {"x": 1}, 5, "table", [{"a": 1}]])


def deep_value(rng: random.Random) -> Any:
    """Lists or tables nested deeply (TOML allows it; derive stops at 32 levels)."""
    depth = rng.choice([5, 31, 33, 200])
    value: Any = 1
    for _ in range(depth):
        value = [value] if rng.random() < 0.5 else {"a": value}
    return value


# ---------------------------------------------------------------- slots: every field of every table


@dataclass(frozen=True)
class Slot:
    """A place a file can be broken: ``kind`` of file, the path of its table, the field (or
    ``*`` for an entry of an open table)."""

    kind: str  # "problem", "chain", "answers"
    table: tuple[str | int, ...]
    field: Field | None
    stage_type: str = ""


def slots() -> list[Slot]:
    """Every field of every table of the schema, each stage type's too."""
    out: list[Slot] = []

    def walk(kind: str, table: Table, path: tuple[str | int, ...], stage_type: str = "") -> None:
        for f in table.fields:
            out.append(Slot(kind, path, f, stage_type))
            if f.type == "table" and f.table is not None:
                walk(kind, f.table, (*path, f.name), stage_type)
        if table.keys is not None:
            out.append(Slot(kind, path, table.keys, stage_type))
            if table.keys.type == "table" and table.keys.table is not None:
                walk(kind, table.keys.table, (*path, "*"), stage_type)
        out.append(Slot(kind, path, None, stage_type))  # an unknown key

    walk("problem", PROBLEM, ())
    walk("chain", CHAIN, ())
    for name, table in STAGES.items():
        walk("chain", table, ("stage", "#"), name)
    walk("answers", ANSWERS, ())
    return out


# ---------------------------------------------------------------- base files


def _load(path: Path) -> dict[str, Any]:
    return tomllib.loads(path.read_text(encoding="utf-8"))


FAST_DIRECT = {
    "title": "Two carts",
    "kind": "direct",
    "given": {"m_A": "2 kg", "m_B": "3 kg", "e": 0.5, "v_A1": "4 m/s", "v_B1": "-1 m/s"},
}
FAST_WALL = {
    "title": "Wall",
    "kind": "direct",
    "given": {"m_A": "0.5 kg", "e": 0.8, "v_A1": "6 m/s"},
    "B": {"fixed": True, "name": "wall"},
}
FAST_VARY = {
    **FAST_DIRECT,
    "conditions": ["v_B2 > 0"],
    "vary": {"m_A": {"min": "1 kg", "max": "3 kg", "step": "0.5 kg"}, "e": {"choices": [0.5, 0.8]}},
}
#: A problem in letters that asks to show, a range and a definition (issue #29's kinds of input).
FAST_SYMBOLIC = {
    "title": "m strikes 2m at rest",
    "kind": "direct",
    "show": "v_B2 = u*(1 + e)/3",
    "range": {"of": "e", "where": "v_A2 < 0"},
    "given": {"m": "kg", "u": "m/s", "m_A": "m", "m_B": "2*m", "e": "e", "v_A1": "u", "v_B1": "0 m/s"},
    "define": {"q": "v_B2/v_A1"},
}
#: Inverse problems: an equation fixes e (and m_B).
FAST_INVERSE = {
    "title": "E",
    "kind": "direct",
    "equations": ["T_2 = 3/4*T_1", "v_A2 = 0 m/s"],
    "given": {"m_A": "2 kg", "m_B": "? kg", "e": "?", "v_A1": "4 m/s", "v_B1": 0},
}
FAST_CHAIN = {
    "title": "Drop and rebound",
    "kind": "chain",
    "given": {"m": "0.2 kg", "v_0": "5 m/s", "h_0": "1.6 m", "e_floor": 0.7, "k_s": "200 N/m", "mu_k": 0.3},
    "stage": [
        {"type": "fall", "height": "h_0", "speed": "v_0", "result": "v_1"},
        {
            "type": "impact",
            "kind": "direct",
            "given": {"m_A": "m", "e": "e_floor", "v_A1": "v_1"},
            "B": {"fixed": True, "name": "ground"},
            "results": {"v_A2": "u"},
        },
        {"type": "define", "expr": "-u", "result": "v_2"},
        {"type": "rise", "speed": "v_2", "result": "h_2"},
    ],
}
ANSWERS_BASE = {
    "answers": {"v_A2": "-0.5 m/s", "v_B2": 2},
    "equations": {"3": "2*v_A2 + 3*v_B2 = 5"},
    "tolerance": "1%",
}
#: A stage of each type, valid in FAST_CHAIN after its first stage.
STAGE_EXAMPLES = {
    "fall": {"type": "fall", "height": "h_0", "result": "w_1"},
    "rise": {"type": "rise", "speed": "v_1", "result": "w_2"},
    "slide": {"type": "slide", "speed": "v_1", "mu": "mu_k", "result": "w_3"},
    "spring": {"type": "spring", "speed": "v_1", "mass": "m", "k": "k_s", "vertical": True, "result": "w_4"},
    "impact": copy.deepcopy(FAST_CHAIN["stage"][1]) | {"results": {"v_A2": "w_5"}},
    "bounces": {"type": "bounces", "height": "h_0", "e": "e_floor", "count": 2},
    "again": {"type": "again", "behind": "v_1", "ahead": "v_0", "result": "w_6"},
    "define": {"type": "define", "expr": "2*v_1", "result": "w_7", "text": "Twice:"},
    "solve": {"type": "solve", "condition": "v_1 = 10 m/s", "for": "e_floor"},
}


def bases() -> dict[str, list[dict[str, Any]]]:
    """Valid files to break, by kind: fast ones (solved in a fraction of a second) often, the
    bundled problems (every feature of the format) now and then."""
    bundled = [_load(p) for p in sorted((ROOT / "problems").glob("*.toml"))]
    singles = [d for d in bundled if d.get("kind") != "chain"]
    chains = [d for d in bundled if d.get("kind") == "chain"]
    return {
        "problem": [FAST_DIRECT] * 40
        + [FAST_WALL] * 10
        + [FAST_VARY] * 5
        + [FAST_SYMBOLIC] * 5
        + [FAST_INVERSE] * 3
        + singles,
        "chain": [FAST_CHAIN] * 30 + chains,
        "answers": [ANSWERS_BASE],
    }


# ---------------------------------------------------------------- breaking a file


def _tables_at(doc: dict[str, Any], path: tuple[str | int, ...], rng: random.Random) -> list[dict[str, Any]]:
    """The tables of ``doc`` at ``path`` ("#": a stage, "*": an entry of an open table), made if missing."""
    found = [doc]
    for part in path:
        nxt: list[dict[str, Any]] = []
        for t in found:
            if part == "#":
                stages = t.get("stage")
                if isinstance(stages, list) and stages:
                    nxt.append(rng.choice([s for s in stages if isinstance(s, dict)] or [{}]))
            elif part == "*":
                nxt += [v for v in t.values() if isinstance(v, dict)][:1]
            else:
                v = t.setdefault(str(part), {})
                if isinstance(v, dict):
                    nxt.append(v)
        found = nxt
    return found


def _typo(word: str, rng: random.Random) -> str:
    if len(word) < 3:
        return word + "x"
    i = rng.randrange(len(word) - 1)
    return word[:i] + word[i + 1] + word[i] + word[i + 2 :]


def break_slot(doc: dict[str, Any], slot: Slot, rng: random.Random) -> str:
    """Break ``doc`` at ``slot`` (a stage slot: in a stage of that type put in the chain);
    returns what was done, for the tally."""
    if slot.stage_type:
        stages = doc.get("stage")
        if not isinstance(stages, list) or not all(isinstance(st, dict) for st in stages):
            return "nothing"
        target = copy.deepcopy(STAGE_EXAMPLES[slot.stage_type])
        stages.insert(rng.randint(1, len(stages)) if stages else 0, target)
        tables = _tables_at(target, slot.table[2:], rng)
    else:
        tables = _tables_at(doc, slot.table, rng)
    if not tables:
        return "nothing"
    table = tables[0]
    f = slot.field
    if f is None:
        known = [k for k in table if isinstance(k, str)] or ["title"]
        key = rng.choice([_typo(rng.choice(known), rng), text_payload(rng), "", " title", "Title", "x.y"])
        table[key] = rng.choice([1, "x", True])
        return "unknown key"
    name = f.name
    if name in OPEN_ENTRIES:  # an entry of an open table ([given], [vary], results, [answers] ...)
        name = rng.choice([*list(table)[:3], *NAMES, "2x", text_payload(rng), "x" * 33])
    if rng.random() < 0.12 and name in table:
        del table[name]
        return "deleted"
    table[name] = value_for(f, rng)
    return f"set {f.type}"


#: The names the schema gives the entries of its open tables.
OPEN_ENTRIES = ("value", "range", "unit", "answer", "equation", "new")


# ---------------------------------------------------------------- TOML text

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def toml_key(key: str) -> str:
    return key if _BARE.match(key) else toml_value(key)


def toml_value(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        if math.isinf(value):
            return "inf" if value > 0 else "-inf"
        text = repr(value)
        return text if any(c in text for c in ".en") else text + ".0"
    if isinstance(value, str):
        out = ['"']
        for ch in value:
            if ch in '\\"':
                out.append("\\" + ch)
            elif ord(ch) < 32 or ord(ch) == 127:
                out.append(f"\\u{ord(ch):04x}")
            else:
                out.append(ch)
        return "".join(out) + '"'
    if isinstance(value, (dt.datetime, dt.date, dt.time)):
        return value.isoformat()
    if isinstance(value, list):
        return "[" + ", ".join(toml_value(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{toml_key(k)} = {toml_value(v)}" for k, v in value.items()) + " }"
    raise TypeError(type(value))


def to_toml(doc: dict[str, Any]) -> str:
    """A document as a TOML file: plain keys, then a ``[table]`` per table, then ``[[stage]]`` tables."""
    lines = [f"{toml_key(k)} = {toml_value(v)}" for k, v in doc.items() if not _is_table(v) and not _is_stages(k, v)]
    for k, v in doc.items():
        if _is_table(v):
            lines.append(f"\n[{toml_key(k)}]")
            lines += [f"{toml_key(kk)} = {toml_value(vv)}" for kk, vv in v.items()]
    for k, v in doc.items():
        if _is_stages(k, v):
            for st in v:
                lines.append(f"\n[[{toml_key(k)}]]")
                lines += [f"{toml_key(kk)} = {toml_value(vv)}" for kk, vv in st.items()]
    return "\n".join(lines) + "\n"


def _is_table(v: Any) -> bool:
    return isinstance(v, dict) and bool(v)


def _is_stages(k: str, v: Any) -> bool:
    return k == "stage" and isinstance(v, list) and bool(v) and all(isinstance(s, dict) for s in v)


def corrupt(text: str, rng: random.Random) -> bytes:
    """A file broken as bytes: a byte-order mark, cut short, bad UTF-8, NUL, nested 1,000 deep, huge."""
    data = text.encode("utf-8")
    how = rng.randrange(10)
    if how == 0:
        return b"\xef\xbb\xbf" + data
    if how == 1:
        return data[: rng.randrange(len(data) + 1)]
    if how == 2:
        i = rng.randrange(len(data) + 1)
        return data[:i] + bytes(rng.randrange(256) for _ in range(rng.randint(1, 4))) + data[i:]
    if how == 3:
        return data + b"x = " + b"[" * 1000 + b"]" * 1000 + b"\n"
    if how == 4:
        return data + b"y = " + b"9" * 5000 + b"\n"
    if how == 5:
        return data.replace(b"\n", b"\r\n") + b"\x00"
    if how == 6:
        return data + ("a." * 300 + "b = 1\n").encode()
    if how == 7:  # one dotted key 20,000 parts deep, or a table header 5,000 (issue #29: 1.6 GB in tomllib)
        return data + (("x." * 20000 + "x = 1\n") if rng.random() < 0.5 else ("[" + "t." * 5000 + "t]\n")).encode()
    if how == 8:  # another encoding: UTF-16 (with its byte-order mark), or Latin-1
        return text.encode("utf-16") if rng.random() < 0.5 else text.encode("latin-1", "replace")
    return data.replace(b"e", "e\u0301".encode())  # decomposed accents everywhere


# ---------------------------------------------------------------- the campaign


#: How many more slots a file has broken besides its own (most files end in an error, a few are
#: worked out in full: a file that is worked out costs a hundred that are refused).
EXTRA_BREAKS = (0, 1, 1, 1, 2, 2, 3)
#: Which kind of file each of ten in a row is: problems, chains (every stage type), answers.
KIND_ROTATION = ("problem",) * 5 + ("chain",) * 4 + ("answers",)


@dataclass(frozen=True)
class Case:
    """One fuzz file: its kind, what was broken, its bytes and the command to run it with."""

    number: int
    kind: str
    broken: tuple[str, ...]
    data: bytes
    command: str  # "solve-json", "solve-md", "solve-tex", "variants", "check"


def cases(count: int, seed: int) -> Iterator[Case]:
    """``count`` fuzz files, the same for the same seed."""
    rng = random.Random(seed)
    all_slots = slots()
    by_kind = {kind: [s for s in all_slots if s.kind == kind] for kind in ("problem", "chain", "answers")}
    turns = {kind: 0 for kind in by_kind}
    pools = bases()
    for k in range(count):
        kind = KIND_ROTATION[k % len(KIND_ROTATION)]
        first = by_kind[kind][turns[kind] % len(by_kind[kind])]
        turns[kind] += 1
        doc = copy.deepcopy(rng.choice(pools[first.kind]))
        broken = [f"{first.kind}:{'.'.join(map(str, first.table)) or '-'}:{first.field.name if first.field else '?'}"]
        what = [break_slot(doc, first, rng)]
        for _ in range(rng.choice(EXTRA_BREAKS)):
            extra = rng.choice([s for s in all_slots if s.kind == first.kind])
            what.append(break_slot(doc, extra, rng))
        data = to_toml(doc).encode("utf-8")
        if rng.random() < 0.04:
            data = corrupt(data.decode("utf-8"), rng)
            what.append("bytes")
        if first.kind == "answers":
            command = "check"
        elif "vary" in doc and rng.random() < 0.02:
            command = "variants"
        else:
            command = rng.choices(["solve-json", "solve-md", "solve-tex"], [6, 3, 1])[0]
        yield Case(
            k + 1,
            first.kind + (f"/{first.stage_type}" if first.stage_type else ""),
            tuple(broken + what),
            data,
            command,
        )
