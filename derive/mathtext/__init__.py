"""Typed mathematics read: the one reader of LaTeX and plain text for the checker and the verifier.
May import: nothing of derive (a leaf; no SymPy): checking/ and the verifier both read with it.

``tokens`` and ``parser`` read LaTeX into the expression tree of ``tree`` (numbers keep the
text they were shown with); ``display`` reads a displayed line's decorations. The verifier
reads derive's own pages with the parser strictly (its lenient mode, for what students type,
is not yet what ``latex`` uses: ``latex`` still rewrites a student's row as plain text by rules),
and ``reader.read_relations`` turns a text (plain
lines, Markdown, LaTeX) into its relations, each with its line and column and its sides in
plain syntax; ``vectors`` splits a relation between vectors by component; ``notation`` writes
students' habits (``20 v``, ``5 cos 37.6°``) out for the parser of problem files. It knows no
physics: checking/ and the verifier give the names their meaning.
"""
