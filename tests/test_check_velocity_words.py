"""A body's velocity in words in an oblique impact, on a line along the line of centres or for a body
with no t component (``Along the line of centres, A's velocity after = a``): its n component,
signed, not its speed.

Worked by hand (ocr-fm-2023-oblique-discs-60deg): A (5 kg) at 4 m/s at 60° to the line of centres,
B (3 kg) at 6 m/s along it toward A, e = 3/4. Along the line: A 4 cos 60° = 2, B −6; momentum
5(2) + 3(−6) = −8 = 5a + 3c; restitution c − a = 0.75(2 + 6) = 6; so 8a = −8 − 18 = −26,
a = −3.25, c = 2.75.
"""

from __future__ import annotations

from support.checked import line_statuses as statuses

DISCS = "ocr-fm-2023-oblique-discs-60deg"
WORK = "$5(2) + 3(-6) = 5a + 3c$\n$c - a = 0.75(2 + 6) = 6$\n$a = -3.25$, $c = 2.75$\n"


def test_velocities_after_in_words_along_the_line_of_centres_are_n_components() -> None:
    said = "Along the line of centres, A's velocity after $= a$ and B's velocity after $= c$:\n"
    assert statuses(DISCS, said + WORK) == ["correct"] * 4


def test_a_body_with_no_t_component_has_its_velocity_along_the_line() -> None:
    # ocr-m3-2013-b-turns-through-right-angle: equal masses; A at 0.3 m/s along the line of centres,
    # B at 0.6 m/s at 30° to it toward A, turned through 90°: B after 0.3/tan 60° = 0.1732 along it;
    # 0.3 − 0.6 cos 30° = 0.3 − 0.5196 = a + 0.1732, so A's velocity after is a = −0.3928.
    said = "Momentum, with A's velocity after $= a$:\n"
    work = "$m(0.3) + m(-0.6\\cos 30^\\circ) = ma + m(0.1732)$\n$a = -0.393$\n"
    assert statuses("ocr-m3-2013-b-turns-through-right-angle", said + work) == ["correct"] * 3


def test_a_wrong_component_is_still_wrong() -> None:
    said = "Along the line of centres, A's velocity after $= a$ and B's velocity after $= c$:\n"
    assert statuses(DISCS, said + WORK.replace("$a = -3.25$", "$a = 3.25$"))[-1] == "wrong"
