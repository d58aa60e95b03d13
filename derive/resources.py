"""Where the templates and bundled problems are, installed or in a checkout.

In a wheel they live inside the package (``derive/templates``,
``derive/problems``); in a source checkout, at the top of the repository.
"""

from __future__ import annotations

import os
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


def cache_folder() -> Path:
    """derive's folder in the user's cache (XDG: ``$XDG_CACHE_HOME/derive``, by default
    ``~/.cache/derive``): compiled templates and records, never the temporary folder or the
    folder a command writes to. Raises RuntimeError where there is no home folder."""
    base = Path(os.environ.get("XDG_CACHE_HOME", ""))
    if not base.is_absolute():  # unset, or relative (which XDG says to ignore)
        base = Path.home() / ".cache"
    return base / "derive"


def cache_disabled() -> bool:
    """Whether the user turned derive's caches off (``DERIVE_NO_CACHE=1``; the older
    ``DERIVE_NO_TEMPLATE_CACHE=1`` too)."""
    return bool(os.environ.get("DERIVE_NO_CACHE") or os.environ.get("DERIVE_NO_TEMPLATE_CACHE"))


def private(path: Path) -> bool:
    """Whether ``path`` (a cache file or folder) is the user's own and nobody else can write
    to it: derive runs the code its caches hold, so a cache another user could have written
    is not read."""
    try:
        st = path.stat()
    except OSError:
        return False
    return st.st_uid == os.geteuid() and not st.st_mode & 0o022
