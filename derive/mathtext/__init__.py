"""Typed mathematics read into plain relations: the one reader of what people type.
May import: nothing of derive (a leaf; no SymPy): the checker and the verifier both read with it.

``reader.read_relations`` turns a text (plain lines, Markdown, LaTeX) into the relations
it holds, each with its line and column and its sides in plain syntax; ``latex`` rewrites
a row of LaTeX as plain text; ``notation`` writes students' habits (``20 v``, ``5 cos 37.6°``)
out for the parser. It knows no physics and imports nothing of derive's: checking/ (and
the verifier) read with it and give the names their meaning.
"""
