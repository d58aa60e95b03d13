"""Golden pages: every bundled problem's page, and a few variants, compared byte for byte.

tests/golden/ holds what derive writes today, read and checked against the notes when it
was written (issue #25):

- ``pages/NAME.md``, ``.tex``, ``.json``: ``derive solve NAME`` in each format (the figures
  of an impact are inside the page: SVG in Markdown, TikZ in LaTeX);
- ``pages/NAME.svg``, ``.tikz``: the set-up figure a student's sheet shows (before the
  impact, nothing found: :func:`derive.writers.figure.setup_svg`);
- ``variants/NAME/``: ``derive variants NAME --count N --seed S`` (each variant's page and
  sheet, key.csv, key.json) for one single impact and one chain.

Each problem is solved once, in-process, for all its formats. A change that alters a page
fails here with the first line that differs. When the change is meant, rewrite the files
with ``DERIVE_UPDATE_GOLDEN=1 python -m pytest -n 0 tests/test_golden.py``, read the diff
(``git diff tests/golden``) and say in the commit which pages changed and why.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from support.output_cases import bundled_names, solution

import derive
from derive.writers.figure import setup_svg, setup_tikz

GOLDEN = Path(__file__).resolve().parent / "golden"
UPDATE = os.environ.get("DERIVE_UPDATE_GOLDEN", "") == "1"

#: The variants kept: (problem, format, count, seed).
VARIANTS = (
    ("notes-4c11-two-spheres", "md", 3, 1),
    ("notes-4c11-two-spheres", "tex", 2, 1),
    ("chain-aqa-m3-2007-collide-again", "md", 2, 1),
)


def _same(path: Path, text: str | bytes) -> None:
    """``text`` is what ``path`` holds, byte for byte (or, with DERIVE_UPDATE_GOLDEN=1, becomes it)."""
    data = text.encode("utf-8") if isinstance(text, str) else text
    if UPDATE:
        path.parent.mkdir(parents=True, exist_ok=True)
        if not path.is_file() or path.read_bytes() != data:
            path.write_bytes(data)
        return
    rel = path.relative_to(GOLDEN.parent)
    assert path.is_file(), f"{rel} is missing: run DERIVE_UPDATE_GOLDEN=1 python -m pytest -n 0 tests/test_golden.py"
    want = path.read_bytes()
    if want == data:
        return
    old, new = want.decode("utf-8").splitlines(), data.decode("utf-8").splitlines()
    line = next((i for i, (a, b) in enumerate(zip(old, new, strict=False)) if a != b), min(len(old), len(new)))
    was = old[line] if line < len(old) else "(end of file)"
    now = new[line] if line < len(new) else "(end of file)"
    pytest.fail(f"{rel}:{line + 1} differs\n  golden: {was[:300]}\n  now:    {now[:300]}", pytrace=False)


def _page_files(name: str) -> dict[str, str]:
    """Every golden file of one bundled problem: its name and its text, from one solve."""
    solved = solution(name)  # solved once per test process, shared with the other page tests
    files = {f"{name}.{fmt}": derive.render(solved, fmt) for fmt in ("md", "tex", "json")}
    files[f"{name}.svg"] = setup_svg(solved)
    files[f"{name}.tikz"] = setup_tikz(solved)
    return files


@pytest.mark.parametrize("name", bundled_names())
def test_bundled_page(name: str) -> None:
    """The page of each bundled problem in md, tex and json, and its set-up figure, as kept."""
    for file, text in _page_files(name).items():
        _same(GOLDEN / "pages" / file, text)


def _variant_folder(problem: str, fmt: str, count: int, seed: int) -> str:
    return f"{problem}-{fmt}-{count}-seed{seed}"


@pytest.mark.parametrize(("problem", "fmt", "count", "seed"), VARIANTS)
def test_variant_pages(problem: str, fmt: str, count: int, seed: int, tmp_path: Path) -> None:
    """``derive variants``' folder (pages, sheets, key.csv, key.json), as kept."""
    from derive.homework.variants import write_variants

    out = tmp_path / "out"
    assert write_variants(derive.load(problem), str(out), count=count, seed=seed, fmt=fmt) == []
    kept = GOLDEN / "variants" / _variant_folder(problem, fmt, count, seed)
    written = sorted(p.name for p in out.iterdir())
    if UPDATE and kept.is_dir():
        for stale in set(p.name for p in kept.iterdir()) - set(written):
            (kept / stale).unlink()
    elif not UPDATE:
        assert written == sorted(p.name for p in kept.iterdir()), f"files of {kept.name}"
    for file in written:
        _same(kept / file, (out / file).read_bytes())


def test_no_stale_golden_files() -> None:
    """Every file under tests/golden/ is one a test above writes (a problem renamed or
    removed leaves none behind)."""
    pages = {f"{n}.{ext}" for n in bundled_names() for ext in ("md", "tex", "json", "svg", "tikz")}
    folders = {_variant_folder(*v) for v in VARIANTS}
    if UPDATE:
        for path in (GOLDEN / "pages").iterdir():
            if path.name not in pages:
                path.unlink()
        return
    assert {p.name for p in (GOLDEN / "pages").iterdir()} == pages
    assert {p.name for p in (GOLDEN / "variants").iterdir()} == folders
