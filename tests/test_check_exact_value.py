"""A number that is the problem's value exactly (4 for 4 m/s) is correct with nothing added: no
"±1 in the last digit" (which reads as if 3 or 5 would pass) and no "Expected: 4.000 m/s" beside
the student's own 4. A number right only at its figures keeps both."""

from __future__ import annotations

import derive

# BYJU'S: 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5: CLM 80 = 4a + 8b, NEL b - a = 4, so
# 12a = 48, a = 4 and b = 8 exactly (the published answer).
WORK = "4(12) + 8(4) = 4p + 8q\nq - p = 0.5(12 - 4)\n"


def _line(text: str, n: int) -> derive.checking.report.Item:
    report = derive.check(derive.load("byjus-4kg-ball-catches-8kg-ball"), derivation=WORK + text)
    return next(i for i in report.items if i.kind == "line" and i.name == str(n))


def test_the_exact_value_is_correct_with_no_slack_and_no_expected() -> None:
    item = _line("p = 4 m/s\nq = 8.0 m/s\n", 3)
    assert item.status == "correct" and item.expected == "" and "±1" not in item.message
    item = _line("p = 4 m/s\nq = 8.0 m/s\n", 4)
    assert item.status == "correct" and item.expected == "" and "±1" not in item.message


def test_a_value_right_only_at_its_figures_says_so() -> None:
    # 7.99 for 8: right at the 3 figures written (±1 in the last digit), with the value shown
    item = _line("p = 4 m/s\nq = 7.99 m/s\n", 4)
    assert item.status == "correct" and "±1 in the last digit" in item.message and item.expected.startswith("8.000")
