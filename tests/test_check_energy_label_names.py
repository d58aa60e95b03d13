"""A kinetic energy's bare name given its instant by a label (``KE before: K = …``, ``KE after:
K' = …``) keeps that meaning on the lines after it (``KE lost = K − K'``), as a teacher reads a
name the student introduced. Every number is worked by hand from the problem file's givens."""

from __future__ import annotations

from support.checked import worst_lines

#: OCR M2 2006: A (2 kg) and B (1 kg) meet head-on at 5 m/s each, e = 0.8. By hand: 2x + y = 5
#: and y − x = 8, so x = −1, y = 7; the energy before ½(2)(25) + ½(1)(25) = 37.5 J, after
#: ½(2)(1) + ½(1)(49) = 25.5 J, lost 12 J.
MEET = "ocr-m2-2006-spheres-meet-at-5-ke-lost"


def test_the_labelled_names_in_the_energy_lost() -> None:
    work = (
        "Right positive; x, y after.\n"
        "2(5) + 1(-5) = 2x + y\n"
        "y - x = 0.8(5 + 5) = 8\n"
        "x = -1, y = 7\n"
        "KE before: K = 1/2(2)(5^2) + 1/2(1)(5^2) = 37.5\n"
        "KE after: K' = 1/2(2)(1^2) + 1/2(1)(7^2) = 25.5\n"
        "KE lost = K - K' = 12 J\n"
    )
    found = worst_lines(MEET, work)
    assert all(found[n][0] == "correct" for n in (2, 3, 4, 5, 6, 7)), found


def test_a_wrong_energy_after_carried_into_the_loss_by_its_name() -> None:
    # The half dropped after: K' = 2(1) + 1(49) = 51 (ke_formula), then K - K' = 37.5 - 51 = -13.5,
    # right given it: carried.
    work = (
        "Right positive; x, y after.\n"
        "2(5) + 1(-5) = 2x + y\n"
        "y - x = 8, x = -1, y = 7\n"
        "KE before: K = 1/2(2)(25) + 1/2(1)(25) = 37.5\n"
        "KE after: K' = 2(1^2) + 1(7^2) = 51\n"
        "KE lost = K - K' = -13.5\n"
    )
    found = worst_lines(MEET, work)
    assert found[5] == ("wrong", "ke_formula"), found
    assert found[6][0] == "carried", found


def test_latex_e_k_primed_under_words() -> None:
    work = (
        "Taking right as positive, $x$ and $y$ the velocities after.\n"
        "$$2(5) + 1(-5) = 2x + y, \\quad y - x = 0.8(10) = 8$$\n"
        "$$x = -1, \\quad y = 7$$\n"
        "Kinetic energy before: $E_k = \\tfrac12(2)(25) + \\tfrac12(1)(25) = 37.5$ J\n"
        "Kinetic energy after: $E_k' = \\tfrac12(2)(1) + \\tfrac12(1)(49) = 25.5$ J\n"
        "Energy lost: $E_k - E_k' = 12$ J\n"
    )
    found = worst_lines(MEET, work)
    assert all(found[n][0] == "correct" for n in (2, 3, 4, 5, 6)), found
