"""Export files built in memory, written only when all of them are built."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from derive.errors import InputError


@dataclass
class Exports:
    """Export files built in memory (path, text), and the folders they need."""

    files: list[tuple[Path, str]]
    folders: list[Path]

    def write(self, inputs: tuple[Path, ...] = ()) -> None:
        """Create the folders, then write each file atomically (never over one of ``inputs``)."""
        from derive.fileio import write_atomic

        for folder in self.folders:
            if folder.exists() and not folder.is_dir():
                raise InputError("exists and is not a folder", where=str(folder))
            folder.mkdir(parents=True, exist_ok=True)
        for path, text in self.files:
            write_atomic(path, text, inputs=inputs)


def folder_exports(folder: str | Path, files: dict[str, str]) -> Exports:
    """The files (name -> text) to write into ``folder``, and the folder itself."""
    return Exports([(Path(folder) / name, text) for name, text in files.items()], [Path(folder)])
