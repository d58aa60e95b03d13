"""A stage's quantities with their units as students type them, and a stage's own names.

A unit's letter glued to the number a relation of numbers comes to (``h = 784/19.6 = 40m``) is
the unit, not a product with a name (a number worked out is no number times a mass); an angular
frequency's unit (``s^-2``, ``rad/s``) after its number is a unit; and a name the student defines
by a formula in a name of their own never defined (``ω = sqrt(k/M)``, M the masses together),
worked in numbers, is known by its working (derive/mathtext/units.py, ownquantities.define).
Every number is worked by hand from the problem files' givens."""

from __future__ import annotations

from support.checked import lines


def test_glued_metres_and_newton_seconds_on_a_rebound_to_the_start() -> None:
    # chain-ocr-m2-2007-rebounds-to-start: 0.2 kg thrown down at 21 m/s from 40 m, g = 9.8.
    # v1² = 441 + 784 = 1225, v1 = 35; back up 40 m: v2² = 2(9.8)(40) = 784, v2 = 28; e = 28/35 = 0.8;
    # J = 0.2(28 + 35) = 12.6; h = 784/19.6 = 40 m (the start). m is the mass: 40m is no 40 × 0.2.
    work = (
        "down +ve\n"
        "v1^2 = 21^2 + 2(9.8)(40) = 441 + 784 = 1225\n"
        "v1 = 35m/s\n"
        "v2^2 = 2(9.8)(40) = 784 so v2 = 28m/s\n"
        "e = 28/35 = 0.8\n"
        "J = 0.2(28 + 35) = 12.6Ns\n"
        "check: h = 784/19.6 = 40m\n"
    )
    found = lines("chain-ocr-m2-2007-rebounds-to-start", work)
    assert [found[n][0] for n in (2, 3, 4, 5, 6, 7)] == ["correct"] * 6


def test_glued_metres_after_a_slip_are_carried() -> None:
    # chain-ocr-m2-2015-thrown-down-bounce: 0.2 kg (m) thrown down at 5 m/s from 1.6 m, e = 0.7, g = 9.8.
    # v1² = 25 + 31.36 = 56.36, v1 = 7.51; e copied as 0.8: v2 = 0.8(7.51) = 6.01 (true 5.26), the slip;
    # h = 6.01²/19.6 = 36.12/19.6 = 1.84 m (the slip's world: 0.8 × 7.50733 = 6.00587, h = 1.8403;
    # true 1.409): carried, its 1.84m no 1.84 × 0.2.
    work = "down positive\nv1^2 = 5^2 + 2(9.8)(1.6) = 25 + 31.36 = 56.36, v1 = 7.51\nv2 = 0.8(7.51) = 6.01 up\n"
    work += "h = 6.01^2/19.6 = 36.12/19.6 = 1.84m\n"
    found = lines("chain-ocr-m2-2015-thrown-down-bounce", work)
    assert found[3][:2] == ("wrong", "copied_wrong")
    assert found[4][0] == "carried"


def test_an_angular_frequency_in_rad_per_second_and_the_amplitude() -> None:
    # chain-block-onto-spring-pan: 30 kg falls 2 m onto a 10 kg pan, k = 20 kN/m, g = 9.81.
    # v² = 39.24, v = 6.264; 30(6.264) = 40V, V = 4.698; d = 294.3/20000 = 0.014715;
    # ω² = 20000/40 = 500 (s^-2), ω = 22.36 rad/s; A² = 0.014715² + (4.698/22.36)² = 0.00021653
    # + 0.044145 = 0.044362, A = 0.2106; x = d + A = 0.2253 (the problem's 0.225337).
    work = (
        "v^2 = 2(9.81)(2) = 39.24, v = 6.264 m/s\n"
        "30(6.264) = 40 V, V = 4.698 m/s\n"
        "d = 30(9.81)/20000 = 0.014715 m\n"
        "omega^2 = k/M = 20000/40 = 500 s^-2\n"
        "omega = sqrt(500) = 22.36 rad/s\n"
        "A = sqrt(d^2 + (V/omega)^2) = sqrt(0.014715^2 + (4.698/22.36)^2) = 0.2106 m\n"
        "x = d + A = 0.2253 m\n"
    )
    found = lines("chain-block-onto-spring-pan", work)
    assert [found[n][0] for n in (4, 5, 6, 7)] == ["correct"] * 4
