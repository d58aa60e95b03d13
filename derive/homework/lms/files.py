"""Export files built in memory, checked all together, written only when all of them are built."""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from derive.errors import InputError


@dataclass
class Exports:
    """Export files built in memory: single files (path, text) with the folders they need
    (Moodle's XML), and whole folders (folder, name -> text: a PrairieLearn question), each
    with the option that named it, for messages."""

    files: list[tuple[Path, str]]
    folders: list[Path]
    trees: list[tuple[Path, dict[str, str]]] | None = None
    file_option: str = "--moodle"
    tree_option: str = "--prairielearn"

    def check(self, inputs: tuple[Path, ...] = (), output: str | Path | None = None) -> None:
        """Refuse, before anything is written, a path that cannot be written: a folder where a
        file goes, a file where a folder goes, an input file, the variants' folder ``output``.
        Each message names the option that gave the path."""
        out = _resolved(output) if output is not None else None
        for path, _ in self.files:
            where = _resolved(path)
            if out is not None and where == out:
                raise InputError(
                    f"is the variants' folder (-o); give a file name such as {Path(path) / 'moodle.xml'}",
                    where=str(path),
                    field=self.file_option,
                )
            if path.is_dir():
                raise InputError("is a folder, not a file", where=str(path), field=self.file_option)
            if any(where == _resolved(src) for src in inputs):
                raise InputError("is the input file; give another name", where=str(path), field=self.file_option)
        for folder, files in self.trees or ():
            where = _resolved(folder)
            if out is not None and where == out:
                raise InputError(
                    "is the variants' folder (-o); give a folder of its own", where=str(folder), field=self.tree_option
                )
            if folder.exists() and not folder.is_dir():
                raise InputError("exists and is not a folder", where=str(folder), field=self.tree_option)
            for name in files:
                target = folder / name
                if target.is_dir() or target.is_symlink():
                    raise InputError(
                        "is a folder or a link where derive writes a file; move it away",
                        where=str(target),
                        field=self.tree_option,
                    )

    def write(self, inputs: tuple[Path, ...] = ()) -> None:
        """Create the folders, then write each file atomically (never over one of ``inputs``).
        A new whole folder is written beside its place and renamed into it at once: a run
        stopped half-way leaves no folder. Into a folder that exists (it may hold the user's
        other files) each file is written atomically, every path checked first (:meth:`check`)."""
        from derive.fileio import folder_atomic, write_atomic

        for folder in self.folders:
            if folder.exists() and not folder.is_dir():
                raise InputError("exists and is not a folder", where=str(folder), field=self.file_option)
            folder.mkdir(parents=True, exist_ok=True)
        for path, text in self.files:
            write_atomic(path, text, inputs=inputs)
        for folder, files in self.trees or ():
            self.check(inputs)
            if folder.is_dir():
                for name, text in files.items():
                    write_atomic(folder / name, text, inputs=inputs)
                continue
            with folder_atomic(folder) as tmp:
                for name, text in files.items():
                    (tmp / name).write_text(text, encoding="utf-8")
                    os.chmod(tmp / name, 0o644)


def _resolved(path: str | Path) -> Path:
    try:
        return Path(path).resolve()
    except OSError:
        return Path(os.path.abspath(path))


def folder_exports(folder: str | Path, files: dict[str, str]) -> Exports:
    """The files (name -> text) to write into ``folder`` as a whole."""
    return Exports([], [], [(Path(folder), dict(files))])
