"""An angle declared in words by the velocity it is of, named by the student's own name for it.

"Let $\\beta$ be the angle $\\mathbf{v}_A$ makes with the line of centres", "θ = angle between
\\vec v_{1f} and the wall", "phi is the angle v_2' makes with the l.o.c.": the velocity is named by a
letter, not in words, and the name says its body and its time as any name does (a body's letter or
the problem's label, 1 and 2 for the bodies where a letter gives no body, a prime, ``f`` or the
habit's v for after; at a wall or cushion the one body's, its digits times: ``v_2`` after). An angle after the impact from the line of centres is derive's beta, from
the wall or the tangent derive's theta (its size: the acute angle the words name). So declared, a
later relation in it (θ = β - 30°) is judged with β as that angle truly is, not as a slip before
made it.
"""

from __future__ import annotations

import re

import sympy

from derive.checking.context import Context

_GREEK = {"α": "alpha", "β": "beta", "γ": "gamma", "δ": "delta", "θ": "theta", "φ": "phi", "ψ": "psi", "varphi": "phi"}
_NAME = r"\\?(?P<name>alpha|beta|gamma|delta|theta|varphi|phi|psi|[αβγδθφψ]|[A-Za-z])"
_VEC = (
    r"(?:\\(?:mathbf|vec|boldsymbol|bm|overrightarrow|underline)\s*)?(?P<base>[uvwV])"
    r"\s*(?:_\s*(?P<marks>[A-Za-z0-9,]{1,4}))?\s*(?P<prime>'|′|\^\s*\\prime)?"
)
_LINE = (
    r"(?P<line>line\s+of\s+(?:centres|centers|impact)|l\.?\s?o\.?\s?c\b\.?|[nx]-?\s*axis|(?:common\s+)?tangent"
    r"|wall|cushion|plane\s+of\s+contact)"
)
_IS = rf"(?<![\w\\]){_NAME}\s+(?:is|=|denotes?|be)\s+(?:the\s+)?(?:acute\s+)?angle\s+"
_FORMS = (
    re.compile(
        rf"{_IS}(?:that\s+|which\s+)?(?:the\s+(?:velocity|vector)\s+)?{_VEC}\s+makes?\s+with\s+(?:the\s+)?{_LINE}"
    ),
    re.compile(rf"{_IS}between\s+(?:the\s+(?:velocity|vector)\s+)?{_VEC}\s+and\s+(?:the\s+)?{_LINE}"),
)


def vector_angles(line: str, ctx: Context) -> dict[str, sympy.Expr]:
    """{β: beta_A2} for each angle after the impact ``line`` declares by a velocity's name."""
    if not ctx.problem.oblique:
        return {}
    plain = re.sub(r"\$|\\[()]|\*\*|[{}]", " ", line)
    names = ctx.equation_names()
    given = {g.name for g in ctx.problem.givens}
    out: dict[str, sympy.Expr] = {}
    for form in _FORMS:
        for m in form.finditer(plain):
            body = _after_body(m, ctx)
            key = f"{'beta' if m['line'][0] in 'lLnNxX' else 'theta'}_{body}2" if body else ""
            name = _GREEK.get(m["name"], m["name"])
            if key in names and name not in given and name not in out:
                out[name] = -names[key][0] if _negative(ctx, key) else names[key][0]
    return out


def _after_body(m: re.Match, ctx: Context) -> str:
    """The body ("A", "B") whose velocity after the impact the name in ``m`` is; "" where it names
    a velocity before (``u_A``, ``v_{1i}``) or no body."""
    marks = (m["marks"] or "").replace(",", "")
    labels = dict(zip(ctx.problem.labels, "AB", strict=True)) | {"A": "A", "B": "B"}
    letters = [labels[c] for c in marks if c in labels]
    digits = [c for c in marks if c.isdigit()]
    if getattr(ctx.problem, "fixed_B", False) and set(letters) <= {"A"}:
        body, before = "A", "1" in digits or "0" in digits  # the one body at a wall: v_2, v_f, v' after
    elif letters:
        body = letters[0]
        before = "1" in digits or "0" in digits
    elif digits and digits[0] in "12":
        body, before = "A" if digits[0] == "1" else "B", "0" in digits
    else:
        return ""
    before = before or "i" in marks or (m["base"] == "u" and "f" not in marks and not m["prime"])
    return "" if before else body


def _negative(ctx: Context, key: str) -> bool:
    """Whether derive's angle ``key`` is negative at the givens (the words name its size)."""
    try:
        r = ctx.results[key]
        x = sympy.sympify(r.value if r.value is not None else r.closed)
        x = ctx.num(x)
        return bool(x.is_number and x.is_negative)
    except (KeyError, LookupError, TypeError, ValueError, sympy.SympifyError):
        return False
