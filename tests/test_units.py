"""The unit factors are exact by definition; here they are checked against SymPy's
own unit system (imported only by this test, so derive never builds it at start-up)."""

from __future__ import annotations

import pytest
import sympy
import sympy.physics.units as u

from derive.problem.units import BASE_UNITS, parse_unit

SYMPY = {
    "mm": (u.millimeter, u.meter),
    "cm": (u.centimeter, u.meter),
    "km": (u.kilometer, u.meter),
    "in": (u.inch, u.meter),
    "ft": (u.foot, u.meter),
    "mi": (u.mile, u.meter),
    "g": (u.gram, u.kilogram),
    "lbm": (u.pound, u.kilogram),
    "min": (u.minute, u.second),
    "h": (u.hour, u.second),
}


@pytest.mark.parametrize("name", sorted(SYMPY))
def test_factor_agrees_with_sympy_physics_units(name: str) -> None:
    q, base = SYMPY[name]
    assert BASE_UNITS[name][0] == sympy.nsimplify(u.convert_to(q, base) / base)


def test_a_pound_force_is_a_pound_mass_under_standard_gravity() -> None:
    assert parse_unit("lb").factor == parse_unit("lbm").factor * sympy.Rational(980665, 100000)


def test_derive_does_not_import_the_unit_system() -> None:
    import subprocess
    import sys

    code = "import sys, derive.problem.units; print('sympy.physics.units' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code], capture_output=True, text=True).stdout.strip() == "False"
