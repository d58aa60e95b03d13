"""Names read as a teacher reads them (:mod:`derive.checking.grounding`): a reading that gives
two names the other body's velocity *and* the other sign at once (a as -B's, b as -A's) is a
swap as much as a plain exchange is, and is kept only where the first relation the names stand
in bears it out, never from a later line whose value meets it by chance after a slip. Values
worked by hand from the givens."""

from __future__ import annotations

from support.checked import lines

# OCR FM 2023: A 5 kg at 4 m/s at 60° to the line of centres, B 3 kg at 6 m/s toward A, e = 3/4.
# True: A along 4 cos 60 = 2, across 4 sin 60 = 3.464; 10 - 18 = -8 = 5a + 3b, b - a = 0.75(8) = 6:
# a = -3.25, b = 2.75. The slip (sin for cos): along 3.46, so 17.3 - 18 = -0.7, b - a = 0.75(9.46)
# = 7.10, 8a = -0.7 - 21.3 = -22.0, a = -2.75 (by chance -b of the truth), b = 4.35: carried.
WORK = (
    "A before: along 4 sin 60 = 3.46, across 4 cos 60 = 2\n"
    "B before: along -6, across 0\n"
    "CLM: 5(3.46) + 3(-6) = 5a + 3b, so 5a + 3b = -0.7\n"
    "NEL: b - a = 0.75(3.46 + 6) = 7.10\n"
    "substitute: 5a + 3(a + 7.10) = -0.7\n"
    "8a = -22.0, a = -2.75\n"
    "b = -2.75 + 7.10 = 4.35\n"
)


def test_a_swapped_and_turned_reading_met_by_chance_after_a_slip_is_not_taken() -> None:
    found = lines("ocr-fm-2023-oblique-discs-60deg", WORK)
    assert found[1][:2] == ("wrong", "sin_cos_swapped")
    assert [found[n][0] for n in (3, 4, 5, 6, 7)] == ["carried"] * 5
