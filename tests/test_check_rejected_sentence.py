"""A case turned down in words after its mathematics in ``$…$`` (``If $x = 0.8333u$ then $y =
0.3333u$, less than P's speed so P would go through Q -- impossible.``): the whole sentence is the
case rejected, its relations not marked; a relation in the sentence before it still is.

Worked by hand (byjus-4kg-ball-catches-8kg-ball): 4 kg at 12 m/s catches 8 kg at 4 m/s, e = 0.5:
80 = 4 v_A + 8 v_B and v_B − v_A = 4, so v_A = 4, v_B = 8. The values before (12, 4) also keep the
momentum, but A would pass through B: a case turned down.
"""

from __future__ import annotations

import pytest
from support.checked import line_statuses as statuses

from derive.mathtext.notes import unmarked

CATCH = "byjus-4kg-ball-catches-8kg-ball"


@pytest.mark.parametrize(
    "line",
    [
        "If $v_A = 12$ then $v_B = 4$, so A would go through B -- impossible.",
        "If $v_A = 12$ then $v_B = 4$, which is less than A's speed, impossible.",
        "If v_A = 12 then v_B = 4, so A would go through B -- impossible.",
    ],
)
def test_a_case_turned_down_after_its_mathematics_is_not_marked(line: str) -> None:
    assert statuses(CATCH, "$v_A = 4$, $v_B = 8$\n" + line) == ["correct"]


def test_a_relation_in_the_sentence_before_is_still_judged() -> None:
    line = "$v_A = 5$. If $v_A = 12$ then $v_B = 4$, so A would go through B -- impossible."
    assert statuses(CATCH, line) == ["wrong"]


def test_the_reader_semicolon_does_not_end_the_sentence_rejected() -> None:
    kept = unmarked("If  v_A = 12 ;  then  v_B = 4 ; , so A would go through B -- impossible.")
    assert "=" not in kept
    assert "v_A = 5" in unmarked("v_A = 5 ; . If  v_A = 12 ;  then  v_B = 4 ; , impossible.")
