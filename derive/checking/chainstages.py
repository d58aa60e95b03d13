"""The stage a chain's derivation line is in: the heading each line is reported under."""

from __future__ import annotations

import re
from dataclasses import replace

import sympy

from derive.checking.context import Context
from derive.checking.numeric import number_of
from derive.checking.report import Item


def _stages(ctx: Context) -> list[tuple[str, set[sympy.Symbol]]]:
    """Each stage's heading ("Stage 1: The bullet lodges in the block") and the names of the
    values it finds (the chain's values known after it, not before)."""
    stages = list(getattr(ctx.solution, "stages", ()))
    out = []
    for k, st in enumerate(stages):
        before = {sympy.Symbol(str(n)) for n in getattr(st, "values", None) or {}}
        after = (stages[k + 1].values if k + 1 < len(stages) else ctx.solution.values) or {}
        found = {sympy.Symbol(str(n)) for n in after} - before
        out.append((f"Stage {k + 1}: {getattr(st, 'title', '') or getattr(st, 'kind', '')}", found))
    return out


def in_stages(ctx: Context, items: list[Item], known: tuple[dict, dict, dict], read: list) -> list[Item]:
    """Each line with the heading of its stage: the last stage whose values it names, or whose
    value a name of the student's own truly is (a line that names none is in the stage of the
    line before it). ``known``: the names inferred, the student's names' true values, the chain's."""
    stages = _stages(ctx)
    if len(stages) < 2:
        return items
    mapping, true_defs, values = known
    same = {}
    for p, x in true_defs.items():  # h = 1.49²/(2 g): h is the chain's h_2
        v = number_of(x.xreplace(values).xreplace(ctx.unit_subs()))
        for sym, y in values.items():
            w = number_of(y) if v is not None else None
            if w is not None and abs(v - w) <= 1e-6 * max(abs(w), 1e-12):
                same[p] = sym
    named = {str(r.line): set().union(*(x.xreplace(same).free_symbols for x in ex)) for r, _s, ex in read}
    inferred = {str(r.line): set().union(*(x.xreplace(mapping).free_symbols for x in ex)) for r, _s, ex in read}
    out, k = [], 0
    for item in items:
        used = named.get(item.name, set()) | {sympy.Symbol(w) for w in re.findall(r"\w+", item.written)}
        ks = [j for j, (_h, found) in enumerate(stages) if found & used]
        if not ks:  # a name inferred moves the line on by one stage at most (an inference can be wrong)
            ks = [j for j, (_h, found) in enumerate(stages) if found & inferred.get(item.name, set()) and j <= k + 1]
        k = max(ks) if ks else k
        out.append(replace(item, stage=stages[k][0]))
    return out
