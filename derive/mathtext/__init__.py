"""Typed mathematics read: the one reader of LaTeX and plain text for the checker and the verifier.
May import: nothing of derive (a leaf; no SymPy): checking/ and the verifier both read with it.

``tokens`` and ``parser`` read LaTeX into the expression tree of ``tree`` (numbers keep the
text they were shown with): they are the one grammar of LaTeX mathematics. The verifier reads
derive's own pages with the parser strictly (``display``: a displayed line's decorations);
``latex`` reads a student's row with the same parser leniently and prints the tree back as
plain text (what it does not take is kept as written, so the checker reports it not read);
``reader.read_relations`` turns a text (plain lines, Markdown, LaTeX) into its relations, each
with its line and column and its sides in plain syntax; ``vectors`` splits a relation between vectors by component; ``notation`` writes
students' habits (``20 v``, ``5 cos 37.6°``) out for the parser of problem files. It knows no
physics: checking/ and the verifier give the names their meaning.
"""
