"""A product of numbers worked wrongly in a momentum line, every term carried across alike, is
``arithmetic``, not a sign lost (``algebra``): a slip of rearranging is matched term by term, each
term against its own size (derive/checking/rearranging.termwise). Expected values by hand."""

from __future__ import annotations

from support.checked import lines

#: Young & Freedman 8.96: 0.0400 kg at 0.200 m/s, on at 0.050 m/s; B's velocity after 0.250 m/s:
#: 0.0400 × 0.200 = 0.00800, 0.0400 × 0.050 = 0.00200, so 0.00800 = 0.00200 + 0.250 m_B, m_B = 0.0240 kg.
PUCKS = "young-freedman-8-96-pucks-find-mass"


def test_a_small_product_worked_a_place_out_is_arithmetic() -> None:
    work = (
        "v_B2 = 0.250 m/s\n"
        "0.0400 x 0.200 = 0.0400 x 0.050 + 0.250 m_B\n"
        "0.00800 = 0.00020 + 0.250 m_B\n"  # 0.0400 x 0.050 worked as 0.00020: every term as it was
    )
    assert lines(PUCKS, work)[3][:2] == ("wrong", "arithmetic")


def test_a_number_moved_across_with_its_sign_kept_stays_algebra() -> None:
    work = "v_B2 = 0.250 m/s\n0.00800 = 0.00200 + 0.250 m_B\n0.250 m_B = 0.00800 + 0.00200\n"
    assert lines(PUCKS, work)[3][:2] == ("wrong", "algebra")  # the 0.00200 moved, its sign kept
