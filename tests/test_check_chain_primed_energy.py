"""A chain's kinetic energy named by its letter primed (``K'``, ``KE'``, ``E_k'``): the energy just
after the chain's impact, so a formula without its half is ``ke_formula`` there, not a line of the
student's own name judged as arithmetic only (derive/checking/chainnames.py, termslips.py).

Worked by hand from problems/chain-car-rear-ends-suv-skid.toml (910 kg car, 2100 kg SUV, the
skid 2.7 m at mu 0.80, g = 9.8): V^2 = 2(0.80)(9.8)(2.7) = 42.336, V = 6.5066 m/s; the kinetic
energy just after the impact is ½(3010)(42.336) = 63716 J. Without the half: 3010(42.336) =
127431 J (127400 at four figures), twice it."""

from __future__ import annotations

import pytest
from support.checked import lines

PROBLEM = "chain-car-rear-ends-suv-skid"


@pytest.mark.parametrize("name", ["K'", "KE'", "E_k'", "K_E′"])
def test_a_primed_energy_without_its_half_is_ke_formula(name: str) -> None:
    work = f"V^2 = 2(0.80)(9.8)(2.7) = 42.336\nV = 6.507 m/s\n{name} = (910 + 2100) V^2 = 3010 x 42.336 = 127400 J\n"
    found = lines(PROBLEM, work)
    assert found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "ke_formula")


def test_a_primed_energy_with_its_half_is_correct() -> None:
    work = "V^2 = 2(0.80)(9.8)(2.7) = 42.336\nV = 6.507 m/s\nK' = 0.5(3010)V^2 = 0.5 x 3010 x 42.336 = 63720 J\n"
    found = lines(PROBLEM, work)
    assert found[3][0] == "correct"
