"""A vector typed with its unit vectors as the bare letters n and t (``v_A = -1.110 n + 3.051 t``,
``\\mathbf{n}``) where the derivation works on the n and t axes (derive/mathtext/vectors.py): one
relation per component, as with i and j. A lone ``3 t`` stays a number times a time.
Values worked by hand: 20 kg at 5 m/s meets 5 kg at 15 m/s, each at 37.6° to the line of impact,
e = 0.6; along it A's 3.962 and B's -11.885 become -1.109 and 8.399; across it B keeps
-15 sin 37.6° = -9.152."""

from __future__ import annotations

from support.checked import worst_lines

from derive.mathtext.vectors import split_vectors


def test_a_sum_of_numbers_times_n_and_t_is_a_vector() -> None:
    got = split_vectors(("v_B", "8.399 n - 9.152 t"))
    assert [tuple(s.replace(" ", "") for s in r) for r in got] == [("v_Bn", "8.399"), ("v_Bt", "-9.152")]


def test_a_number_times_t_alone_is_no_vector() -> None:
    assert split_vectors(("s", "3 t")) == [("s", "3 t")]


def test_the_velocity_after_as_n_and_t_is_judged_by_component() -> None:
    work = "v_B' = 8.399 n - 9.152 t\n"
    assert worst_lines("notes-4c11-two-spheres", work)[1][0] == "correct"
    slipped = "v_B' = 8.399 n + 9.152 t\n"  # B's t component with its sign lost
    assert worst_lines("notes-4c11-two-spheres", slipped)[1][0] == "wrong"
