"""After a slip, a line of numbers worked from the student's wrong values is carried only where
it depends on the slip: put back the true value of each quantity those numbers were stated for,
and a line that still holds (a fraction the slip leaves alone) is correct. The same wrong
formula of a kinetic energy made afresh on the next energy is the same mistake again. Every
number is worked by hand from the problem's givens."""

from __future__ import annotations

from support.checked import lines, worst_lines

# OCR M2 2012: 0.8 kg at 4 m/s straight at a wall, e = 0.3: back at 1.2 m/s. True energies
# ½(0.8)(16) = 6.4 J and ½(0.8)(1.44) = 0.576 J, lost 5.824 J: 5.824/6.4 = 0.91 of it (1 - e²).
# Without the ½: 12.8 J and 1.152 J, lost 11.648 J, and 11.648/12.8 = 0.91 all the same.
WALL = "ocr-m2-2012-particle-hits-wall"


def test_a_fraction_the_slip_leaves_alone_is_correct_and_the_loss_it_moves_is_carried() -> None:
    work = (
        "v = 0.3(4) = 1.2 m/s\n"
        "KE before = 0.8(4^2) = 12.8 J\n"
        "KE after = 0.8(1.2^2) = 1.152 J\n"
        "KE lost = 12.8 - 1.152 = 11.648 J\n"
        "fraction of the KE lost: 11.648/12.8 = 0.91\n"
        "as a percentage 11.648/12.8 x 100 = 91 %\n"
    )
    found = worst_lines(WALL, work)
    assert found[2] == ("wrong", "ke_formula")
    assert found[4][0] == "carried"
    assert found[5][0] == "correct"
    assert found[6][0] == "correct"


def test_a_ratio_the_slip_moves_stays_carried() -> None:
    # The speed after over the student's 12.8 J is moved by the slip: 1.2/12.8 = 0.09375, where
    # with the true 6.4 J it is 0.1875. It is carried, not correct.
    work = "v = 0.3(4) = 1.2 m/s\nKE before = 0.8(4^2) = 12.8 J\n1.2/12.8 = 0.09375\n"
    found = worst_lines(WALL, work)
    assert found[2][0] == "wrong"
    assert found[3][0] == "carried"


def test_the_same_wrong_energy_formula_made_on_the_next_energy_is_the_same_mistake_again() -> None:
    # The same wall: both energies without the ½, the second the same mistake made again.
    work = "KE_1 = m u^2 = 0.8 x 4^2 = 12.8 J\nKE_2 = m v^2 = 0.8 x 1.2^2 = 1.152 J\n"
    found = lines(WALL, work)
    assert found[1][:2] == ("wrong", "ke_formula")
    assert found[2][0] == "wrong" and found[2][2] is True
