"""Checking hand work against a solution: answers, equations and typed derivations.
May import: writers, steps, physics, problem and the leaves; never homework, verifier or commands.

``check.check`` is the entry point (``derive.check``); ``answers`` reads answers
files and runs ``derive check``. Each kind of thing checked has its judge —
``number`` (at the figures written, with ``figures`` and ``rounding``),
``expression`` (a formula, read with ``notation``), ``equation`` (a table of
rules over ``relations``), ``lines`` (a derivation read by ``derivation``) — over
one ``context`` of the solved problem, and ``mistakes`` models the common slips.
``report`` words and lays out what they find.
"""
