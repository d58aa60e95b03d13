"""The commands of ``derive``'s command line, one module each, with their parser and the terminal's safety.
May import: every package of derive but the public API module (derive/__init__.py); :mod:`derive.cli` runs them."""
