"""A given velocity put in with its sign lost in the working of a quantity the line names
(``momentum after = 0.5(0.2) + 2v`` for an A that moves back at 0.2 m/s) is ``b_sign``, not an
arithmetic slip; the momentum and the value worked from it are carried. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: OCR MEI FMM 2023, A moving back: 0.5 kg at 6 m/s catches 2 kg at 2 m/s, A after -0.2 m/s.
#: True: 3 + 4 = 7 = 0.5(-0.2) + 2v, 2v = 7.1, v = 3.55. A's 0.2 taken forward: 7 = 0.1 + 2v,
#: 2v = 6.9, v = 3.45.
BACK = "ocr-mei-fmm-2023-a-speed-0p2-backward"


def test_a_given_velocity_after_with_its_sign_lost_in_the_momentum_after() -> None:
    work = "momentum before = 0.5(6) + 2(2) = 7\nmomentum after = 0.5(0.2) + 2v = 0.1 + 2v\n7 = 0.1 + 2v\nv = 3.45\n"
    found = worst_lines(BACK, work)
    assert found[1][0] == "correct"
    assert found[2] == ("wrong", "b_sign")
    assert found[3][0] == found[4][0] == "carried"
