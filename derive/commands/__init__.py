"""The commands of ``derive``'s command line, one module each, with their parser and the
terminal's safety (:mod:`derive.cli` runs them)."""
