"""Closed forms factored once per problem *structure*, not once per problem (issue #19).

``sympy.factor`` of the general solution of (1)-(4), and of the kinetic energy lost, works
in the component symbols (v_A1n, m_A, e, ...): its input depends only on the structure of
the problem (direct or oblique, a fixed B, which pre-impact components are 0, which masses
are letters), never on its numbers. :data:`derive.physics.forms_table.FACTORED` holds the
factored form of each input the bundled problems make, as text (:func:`dump`: each node
and its ``args`` in order; ``srepr`` reorders a sum's terms and splits -4 into -1 * 4); a
hit is built back with evaluation off, so that it is the very tree ``factor`` gives
(rebuilding with evaluation on would distribute ``Mul(1/3, Add)``). Any other input is
factored as before.
``python benchmarks/forms_table.py`` writes the table again (tests/test_forms.py checks it).
"""

from __future__ import annotations

import sympy

_NAMESPACE: dict[str, object] = {}
#: While benchmarks/forms_table.py records: each input factored -> its factored form
#: (:func:`dump` text); every input is factored then, none read from the table.
_RECORDING: dict[str, str] | None = None


def factored(expr: sympy.Expr) -> sympy.Expr:
    """``sympy.factor(expr)``, read from the table when the structure is there."""
    from derive.physics.forms_table import FACTORED

    key = dump(expr)
    text = FACTORED.get(key)
    if text is not None and _RECORDING is None:
        return rebuild(text)
    out = sympy.factor(expr)
    if _RECORDING is not None:
        _RECORDING[key] = dump(out)
    return out


def dump(expr: sympy.Basic) -> str:
    """``expr`` as text that :func:`rebuild` turns into the same tree: a leaf as ``srepr``
    writes it (Integer(3), Symbol('m', positive=True), pi), any other node as its class
    and its ``args`` in their order."""
    if not expr.args:
        return sympy.srepr(expr)
    return f"{type(expr).__name__}({', '.join(dump(a) for a in expr.args)})"


def rebuild(text: str) -> sympy.Expr:
    """The expression :func:`dump` wrote as ``text``, exactly as written (no evaluation)."""
    if not _NAMESPACE:
        _NAMESPACE.update({name: getattr(sympy, name) for name in dir(sympy) if not name.startswith("_")})
        _NAMESPACE["__builtins__"] = {}
    with sympy.evaluate(False):
        return eval(text, _NAMESPACE)  # our own table, never user input
