"""A given copied wrongly and used both alone and inside a total with another given (a mass
and the two masses together): one slip, copied_wrong, and the lines worked from it carried.
Every value is worked by hand."""

from __future__ import annotations

from support.checked import lines


def test_a_mass_copied_wrongly_alone_and_in_the_total_mass_is_copied_wrong() -> None:
    # a 0.020 kg bullet at 300 m/s lodges in a 4.0 kg block: 6.0 = 4.02 V, V = 1.49 m/s.
    # With 0.20 kg: 60 = 4.20 V, V = 14.3: the line holds with the given as copied in both places
    for work in ("0.20(300) + 4.0(0) = 4.20 v\nv = 60/4.20 = 14.3 m/s\n", "0.2 x 300 = (0.2 + 4) V\nV = 14.3\n"):
        found = lines("msu-lectureonline-bullet-lodges-in-block", work)
        assert found[1][:2] == ("wrong", "copied_wrong"), work
        assert found[2][0] == "carried", work


def test_a_chain_mass_copied_wrongly_in_the_total_too_is_copied_wrong() -> None:
    # the skid: V^2 = 2(0.80)(9.8)(2.7) = 42.336, V = 6.507; the car (910 kg) into the SUV
    # (2100 kg): 910 v = 3010(6.507), v = 21.52. The SUV copied as 2000 kg, so 2910 in the total:
    # 910 v = 2910(6.507) = 18935, v = 20.81
    work = "V^2 = 2(0.80)(9.8)(2.7) = 42.34\nV = 6.507 m/s\n910 v + 2000(0) = 2910(6.507)\nv = 18935/910 = 20.81 m/s\n"
    found = lines("chain-car-rear-ends-suv-skid", work)
    assert found[1][0] == found[2][0] == "correct"
    assert found[3][:2] == ("wrong", "copied_wrong")
    assert found[4][0] == "carried"
