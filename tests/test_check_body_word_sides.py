"""A body's speed or velocity said by the body's letter beside the word, as phones type it
(``speed B = 3U/4``, ``spd A after = 1.2``, ``B vel after = -3``): that body's quantity of the
problem, judged. It was the letter alone with a word before it, a name of the student's own that
the line "defines", so that a wrong speed after passed with a tick."""

from __future__ import annotations

import pytest

import derive

# Edexcel M2 June 2004 Q5: P (2m) at 5u hits Q (3m) at rest, e. By hand: 10mu = 2mx + 3my,
# y - x = 5eu -> 5y = 10u + 10eu, y = 2(1 + e)u = 2u + 2eu (Q's), x = y - 5eu = 2u - 3eu (P's).
EDEXCEL = "P after = x, Q after = y\n10mu = 2mx + 3my\ny - x = 5eu\n5y = 10u + 10eu\n"
# CIE 9231 2019 Q3: A (2m) at 2u, B (4m) at u toward it, e. By hand: 4mu - 4mu = 0 = 2ma + 4mb, so
# a = -2b; b - a = e(2u + u) = 3eu -> 3b = 3eu: b = eu (B's velocity after), a = -2eu (A's).
CIE = "take -> +ve\nclm 2m(2u)-4m(u)=2ma+4mb\n0=2a+4b so a=-2b\nnel b-a=e(2u+u)=3eu\n3b=3eu\n"


def _last(problem: str, work: str) -> derive.checking.report.Item:
    report = derive.check(derive.load(problem), derivation=work)
    n = str(len(work.splitlines()))
    return next(i for i in report.items if i.kind == "line" and i.name == n)


@pytest.mark.parametrize(
    ("problem", "work", "line", "status"),
    [
        ("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", EDEXCEL, "speed Q = 2u + 2eu", "correct"),
        ("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", EDEXCEL, "speed Q = 2u + 3eu", "wrong"),  # P's 3 in Q's
        ("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", EDEXCEL, "spd P after = 2u - 3eu", "correct"),
        ("edexcel-m2-2004-june-q5-2m-at-5u-hits-3m", EDEXCEL, "spd P after = 2u - 4eu", "wrong"),
        ("cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u", CIE, "B spd = eu", "correct"),
        ("cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u", CIE, "speed B = 3eu", "wrong"),  # 3b for b
        ("cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u", CIE, "vel A after = -2eu", "correct"),
        ("cie-9231-p2-2019-june-q3-2m-at-2u-meets-4m-at-u", CIE, "A vel after = 2eu", "wrong"),  # its sign
    ],
)
def test_a_body_s_speed_by_its_letter_beside_the_word_is_judged(
    problem: str, work: str, line: str, status: str
) -> None:
    item = _last(problem, work + line + "\n")
    assert item.status == status, item.message
    assert "Defines" not in item.message


def test_a_speed_by_the_letter_is_the_size_of_the_velocity_in_an_oblique_impact() -> None:
    # Example 4.C.11 of the notes: B after has n 8.4, t -9.15; its speed sqrt(8.4² + 9.15²) =
    # sqrt(70.56 + 83.72) = sqrt(154.28) = 12.42, not its n component 8.4
    work = "v_B2n = 8.4, v_B2t = -9.15\n"
    assert _last("notes-4c11-two-spheres", work + "speed B = 12.4\n").status == "correct"
    assert _last("notes-4c11-two-spheres", work + "speed B = 8.4\n").status == "wrong"


def test_a_velocity_by_the_letter_is_read_only_with_its_time_said() -> None:
    # "vel A = 6" may be a given velocity before as well as a result: only a speed, or a velocity
    # with its time said, is the body's quantity; a lowercase letter is the student's own name
    from derive.mathtext.bodysides import body_side

    assert body_side("vel A") is None
    assert body_side("B vel before") == "v_B1"
    assert body_side("final speed of B") == "speed_B"
    assert body_side("speed of approach") is None
    assert body_side("speed b") is None
