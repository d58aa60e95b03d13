"""A chain's result in words, for an LMS question (the variants of a chain are made as any
problem's: :mod:`derive.homework.variants.compile`)."""

from __future__ import annotations

from derive.homework.variants.compile import Compiled


def chain_result_words(c: Compiled, name: str) -> list[tuple[str, str]]:
    """What a chain's result is, as text and mathematics (for an LMS question): an impact's
    result by the impact's own name ("v_A2 after A and B collide"), an energy stage's by what
    it finds ("the height reached"), a ``define`` stage's by its title, an unknown as such."""
    from derive.problem.chain import stage_results
    from derive.problem.schema.chain import STAGES
    from derive.symbols import latex_name, relabel
    from derive.writers.view.lines import heading_parts

    names = frozenset(c.givens) | frozenset(str(k) for k in c.solution.values)

    steps = {st.number: st for st in c.solution.stages}
    for i, raw in enumerate(c.problem.stages, 1):
        st = steps.get(i)
        title = str(st.title if st is not None else raw.get("title", f"stage {i}"))
        if raw["type"] == "impact" and st is not None and st.part is not None:
            for slot, new in (raw.get("results") or {}).items():
                if new == name:
                    lead = "t" + title[1:] if title.startswith("The ") else title
                    return [
                        ("math", latex_name(relabel(str(slot), st.part.problem.labels))),
                        ("text", " after "),
                        *heading_parts(lead, names),
                    ]
        elif any(new == name for _, new in stage_results(i, raw)):
            if raw["type"] in ("fall", "rise", "slide", "spring"):
                return [("text", STAGES[raw["type"]].meaning.partition(":")[0])]
            if title.startswith("The "):  # a define stage's title: "The rebound speed"
                return [("text", "t" + title[1:])]
            return [("text", f"the result of stage {i} ("), *heading_parts(title, names), ("text", ")")]
    g = c.givens.get(name)
    if g is not None and g.unknown:
        return [("text", "the unknown of the problem")]
    return [("text", "the result "), ("math", latex_name(name))]
