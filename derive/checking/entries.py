"""What a user gives to check, in any of the shapes it comes in: one record per answer or equation.

Answers come as a mapping ``{name: value}``, a list of ``"NAME=VALUE"``, the
command line's ``--answer``/``--equation`` options or an answers file
(:mod:`derive.checking.answers`); all become :class:`Answers` of :class:`Entry`.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from typing import Any

import sympy

from derive.errors import InputError

_LABEL = re.compile(r"^\s*(?:\(\s*([A-Za-z0-9]{1,8})\s*\)\s*:?|([A-Za-z0-9]{1,8})\s*:)\s*")


@dataclass(frozen=True)
class Entry:
    """One answer (``name = text``) or equation (``label = text``), with where it came from."""

    name: str
    raw: Any
    where: str | None = None
    field: str | None = None

    def error(self, what: str) -> InputError:
        """An :class:`InputError` that names this entry's file and field."""
        return InputError(what, where=self.where, field=self.field)


@dataclass(frozen=True)
class Answers:
    """Answers and equations to check, as read from a file or the command line."""

    answers: tuple[Entry, ...] = ()
    equations: tuple[Entry, ...] = ()
    tolerance: Any = None

    def merged(self, other: Answers) -> Answers:
        """These answers with ``other``'s added (``other`` wins for the same name)."""
        names = {e.name for e in other.answers}
        answers = tuple(e for e in self.answers if e.name not in names) + other.answers
        tol = other.tolerance if other.tolerance is not None else self.tolerance
        return Answers(answers, self.equations + other.equations, tol)


def parse_tolerance(value: Any, option: str = "--tolerance") -> sympy.Rational | None:
    """A relative tolerance: 0.01, "0.01" or "1%"; None stays None."""
    if value is None:
        return None
    if isinstance(value, sympy.Rational):
        value = str(sympy.Float(value, 15))
    text = str(value).strip() if not isinstance(value, bool) else ""
    pct = text.endswith("%")
    body = text[:-1].strip() if pct else text
    try:
        if isinstance(value, bool) or not re.fullmatch(r"(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d{1,2})?", body):
            raise ValueError
        tol = sympy.Rational(body) / (100 if pct else 1)
    except (ValueError, TypeError):
        raise InputError('expected a relative tolerance such as 0.01 or "1%"', field=f"{option} {value!r}") from None
    if not 0 < tol < 1:
        raise InputError("expected a relative tolerance between 0 and 1 (0 % and 100 %)", field=f"{option} {value!r}")
    return tol


def answer_option(text: str) -> Entry:
    """``NAME=VALUE`` from ``--answer``."""
    name, sep, value = text.partition("=")
    if not sep or not name.strip():
        raise InputError("expected NAME=VALUE, such as v_B2n=8.40 m/s", field=f"--answer {text!r}")
    return Entry(name.strip(), value.strip(), field=f"--answer {name.strip()}")


def equation_option(text: str) -> Entry:
    """``[LABEL:] LHS = RHS`` from ``--equation`` (the label as "3:" or "(3)")."""
    m = _LABEL.match(text)
    label = (m.group(1) or m.group(2)) if m else ""
    body = text[m.end() :] if m else text
    return Entry(label, body, field=f"--equation {text!r}")


def as_answers(answers: Any, equations: Any) -> Answers:
    """What :func:`~derive.checking.check.check` was given, as :class:`Answers`."""
    if isinstance(answers, Answers):
        base = answers
    elif answers is None:
        base = Answers()
    elif isinstance(answers, Mapping):
        if "answers" in answers or "equations" in answers:
            return as_answers(answers.get("answers"), answers.get("equations"))
        base = Answers(tuple(Entry(str(k), v, field=f"answers[{k}]") for k, v in answers.items()))
    elif isinstance(answers, Iterable) and not isinstance(answers, (str, bytes)):
        base = Answers(tuple(answer_option(str(a)) for a in answers))
    else:
        raise InputError("expected answers as a mapping {name: value} or a list of 'NAME=VALUE'", field="answers")
    if equations is None:
        return base
    if isinstance(equations, Mapping):
        eqs = tuple(Entry(str(k), v, field=f"equations[{k}]") for k, v in equations.items())
    elif isinstance(equations, Iterable) and not isinstance(equations, (str, bytes)):
        eqs = tuple(equation_option(str(x)) for x in equations)
    else:
        raise InputError("expected equations as a mapping {label: equation} or a list", field="equations")
    return Answers(base.answers, base.equations + eqs, base.tolerance)
