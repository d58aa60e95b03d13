"""Where the templates and bundled problems are, installed or in a checkout.

In a wheel they live inside the package (``derive/templates``,
``derive/problems``); in a source checkout, at the top of the repository.
"""

from __future__ import annotations

from pathlib import Path

_PKG = Path(__file__).resolve().parent


def _find(name: str) -> Path:
    for candidate in (_PKG / name, _PKG.parent / name):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"derive's {name} folder is missing from the installation")


def templates_dir() -> Path:
    """The folder of Jinja2 templates."""
    return _find("templates")


def problems_dir() -> Path:
    """The folder of bundled problem files."""
    return _find("problems")


def bundled() -> dict[str, Path]:
    """Bundled problems: name (file stem) -> path, sorted by name."""
    return {p.stem: p for p in sorted(problems_dir().glob("*.toml"))}
