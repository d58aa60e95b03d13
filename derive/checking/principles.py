"""An energy balance stated in symbols before it is worked: ``T_1 + V_1 = T_2 + V_2``,
``KE_i + PE_i = KE_f + PE_f``, ``T_1 + ΣU_{1-2} = T_2``, ``K_A + U_A = K_B + U_B``. The student names
the principle a stage of the chain uses (the spring's, the rise's); a teacher marks it as the
method, right, though its names (V for a potential energy, U for a work) are none of derive's.

>>> [bool(energy_balance(s)) for s in (("T_1 + V_1", "T_2 + V_2"), ("T_1", "T_2"), ("u_A + v_A", "3"))]
[True, False, False]
"""

from __future__ import annotations

import re

#: A subscript: an instant or a place (``1``, ``i``, ``f``, ``A``, ``{1-2}``, ``(1→2)``, ``before``).
_SUB = r"(?:_?\s*[{(]?\s*[A-Za-z0-9]{1,6}(?:\s*(?:-|→|->|–|,)\s*[A-Za-z0-9]{1,2})?\s*[})]?)"
_KINETIC = rf"(?:KE|K\.E\.|E_?\{{?k\}}?|T|K){_SUB}"
_POTENTIAL = rf"(?:PE|P\.E\.|E_?\{{?p\}}?|V|U|V_?\{{?[eg]\}}?|E_?\{{?el\}}?){_SUB}"
_WORK = rf"(?:Σ\s*|\\?Sigma\s*|sum\s*)?(?:U|W){_SUB}"
_TERM = rf"(?:{_KINETIC}|{_POTENTIAL}|{_WORK})"
_SIDE = re.compile(rf"\s*[+-]?\s*{_TERM}(?:\s*[+-]\s*{_TERM})*\s*|\s*0\s*")


def energy_balance(sides: tuple[str, ...]) -> str:
    """Why a relation is an energy balance stated in symbols (every side a sum of kinetic
    energies, potential energies and works, a kinetic one and another kind among them), or ""."""
    if len(sides) < 2 or not all(_SIDE.fullmatch(s.replace("&", "")) for s in sides):
        return ""
    text = " ".join(sides)
    kinetic = re.search(rf"(?<![\w\\]){_KINETIC}", text)
    other = [m for m in re.finditer(rf"(?<![\w\\]){_TERM}", text) if not re.fullmatch(_KINETIC, m.group(0))]
    if not kinetic or not other:
        return ""
    return "The energy balance of the stage, stated before it is worked: right."
