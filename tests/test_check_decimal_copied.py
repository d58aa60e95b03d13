"""A given copied with its decimal point moved (0.2 written 2), where the number it becomes is
also one of the problem's data (B's 2 kg), is ``copied_wrong``: the line holds with the problem
solved with that given so, and the lines worked from it are carried. Values by hand."""

from __future__ import annotations

from support.checked import worst_lines

#: OCR M2 2011: A (mass m) at 3 m/s meets B (0.2 kg) at 1.5 m/s toward it; after, A on at 2,
#: B back at 2.9. 3m - 0.2(1.5) = 2m + 0.2(2.9): m = 0.3 + 0.58 = 0.88 kg. B's 0.2 copied as 2
#: (A's 2 m/s is data too): 3m - 2(1.5) = 2m + 2(2.9), m = 3 + 5.8 = 8.8 kg.
OCR_2011 = "ocr-m2-2011-spheres-find-e-and-mass"

#: MEI FMM 2023: A 0.5 kg at 6, B 2 kg at 2, A back at 0.2 after. 3 + 4 = -0.1 + 2v, v = 3.55.
#: A's 0.2 copied as 2 (B's 2 kg and 2 m/s are data): 7 = -1 + 2v, v = 4; then
#: e = (4 - (-2))/(6 - 2) = 1.5 with the 2 carried on.
MEI_BACK = "ocr-mei-fmm-2023-a-speed-0p2-backward"


def test_a_mass_copied_ten_times_over_is_copied_wrong() -> None:
    found = worst_lines(OCR_2011, "3m - 2(1.5) = 2m + 2(2.9)\nm = 8.8 kg\n")
    assert found[1] == ("wrong", "copied_wrong")
    assert found[2][0] == "carried"


def test_a_speed_after_copied_ten_times_over_is_copied_wrong() -> None:
    work = "0.5(6) + 2(2) = 0.5(-2) + 2v\n7 = -1 + 2v\nv = 4\ne = (4 + 2)/(6 - 2) = 1.5\n"
    found = worst_lines(MEI_BACK, work)
    assert found[1] == ("wrong", "copied_wrong")
    assert [found[n][0] for n in (2, 3, 4)] == ["carried"] * 3
