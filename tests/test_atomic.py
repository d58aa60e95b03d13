"""Outputs are written atomically and never over the input: nothing is lost when a write fails.

derive.fileio.write_atomic writes a temporary file in the output's folder and
renames it over the output. A failure at any step leaves the old output whole
and no temporary file behind; ``-o`` naming the input file is refused.
"""

from __future__ import annotations

import os
import stat
from pathlib import Path

import pytest

from derive import fileio
from derive.errors import InputError, RenderError
from derive.fileio import write_atomic

PROBLEM = """title = "Two carts"
kind = "direct"

[given]
m_A = "2 kg"
m_B = "3 kg"
e = 0.5
v_A1 = "4 m/s"
v_B1 = "-1 m/s"
"""
OLD = "old output, complete\n" * 100


def _leftovers(folder: Path, keep: set[str]) -> list[str]:
    return sorted(p.name for p in folder.iterdir() if p.name not in keep)


# ---------------------------------------------------------------- write_atomic itself


def test_writes_a_new_file(tmp_path: Path) -> None:
    out = tmp_path / "s.md"
    write_atomic(out, "héllo\n")
    assert out.read_bytes() == "héllo\n".encode()
    assert stat.S_IMODE(out.stat().st_mode) == 0o644
    assert _leftovers(tmp_path, {"s.md"}) == []


def test_writes_bytes(tmp_path: Path) -> None:
    out = tmp_path / "s.pdf"
    write_atomic(out, b"%PDF-1.5\x00\xff")
    assert out.read_bytes() == b"%PDF-1.5\x00\xff"


def test_replaces_by_rename_not_in_place(tmp_path: Path) -> None:
    """A reader holding the old file keeps reading the old file: the new one is a new inode."""
    out = tmp_path / "s.md"
    out.write_text(OLD)
    out.chmod(0o600)
    with out.open() as reader:
        old_inode = out.stat().st_ino
        write_atomic(out, "new\n")
        assert reader.read() == OLD
    assert out.read_text() == "new\n"
    assert out.stat().st_ino != old_inode
    assert stat.S_IMODE(out.stat().st_mode) == 0o600  # the output's permissions are kept
    assert _leftovers(tmp_path, {"s.md"}) == []


@pytest.mark.parametrize("step", ["replace", "fsync", "write", "chmod"])
def test_failed_write_leaves_old_output_whole(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, step: str) -> None:
    out = tmp_path / "s.md"
    out.write_text(OLD)

    def fail(*args: object, **kwargs: object) -> None:
        raise OSError(28, "No space left on device")

    if step == "write":

        class Full:
            def __init__(self, fh) -> None:
                self.fh = fh

            def __enter__(self) -> Full:
                return self

            def __exit__(self, *exc: object) -> None:
                self.fh.close()

            def write(self, data: bytes) -> int:
                self.fh.write(data[: len(data) // 2])  # half of it reaches the disk, then it is full
                raise OSError(28, "No space left on device")

        real_fdopen = os.fdopen
        monkeypatch.setattr(fileio.os, "fdopen", lambda fd, *a, **k: Full(real_fdopen(fd, *a, **k)))
    else:
        monkeypatch.setattr(fileio.os, step, fail)
    with pytest.raises(RenderError) as info:
        write_atomic(out, "NEW " * 10_000)
    assert "No space left on device" in str(info.value) and str(out) in str(info.value)
    monkeypatch.undo()
    assert out.read_text() == OLD
    assert _leftovers(tmp_path, {"s.md"}) == []


@pytest.mark.parametrize("exc", [KeyboardInterrupt, RuntimeError, MemoryError])
def test_interrupted_write_leaves_old_output_whole(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, exc: type[BaseException]
) -> None:
    """Ctrl-C (or any other exception) between writing and renaming: old file intact, temp file removed."""
    out = tmp_path / "s.md"
    out.write_text(OLD)

    def boom(*args: object, **kwargs: object) -> None:
        raise exc()

    monkeypatch.setattr(fileio.os, "replace", boom)
    with pytest.raises(exc):
        write_atomic(out, "NEW\n")
    monkeypatch.undo()
    assert out.read_text() == OLD
    assert _leftovers(tmp_path, {"s.md"}) == []


def test_failed_new_file_leaves_nothing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    out = tmp_path / "s.md"

    def fail(*args: object) -> None:
        raise OSError(5, "Input/output error")

    monkeypatch.setattr(fileio.os, "replace", fail)
    with pytest.raises(RenderError):
        write_atomic(out, "x")
    monkeypatch.undo()
    assert list(tmp_path.iterdir()) == []


def test_refuses_the_input(tmp_path: Path) -> None:
    src = tmp_path / "p.toml"
    src.write_text(PROBLEM)
    for target in (src, tmp_path / "." / "p.toml", tmp_path / "sub" / ".." / "p.toml"):
        (tmp_path / "sub").mkdir(exist_ok=True)
        with pytest.raises(InputError) as info:
            write_atomic(target, "x", inputs=(src,))
        assert "refusing to overwrite the input" in str(info.value)
    assert src.read_text() == PROBLEM


def test_refuses_a_symlink_to_the_input(tmp_path: Path) -> None:
    src = tmp_path / "p.toml"
    src.write_text(PROBLEM)
    link = tmp_path / "out.md"
    link.symlink_to(src)
    with pytest.raises(InputError):
        write_atomic(link, "x", inputs=(src,))
    assert src.read_text() == PROBLEM and link.is_symlink()


def test_folder_and_missing_folder_are_clear_errors(tmp_path: Path) -> None:
    with pytest.raises(InputError) as info:
        write_atomic(tmp_path, "x")
    assert "folder" in str(info.value)
    with pytest.raises(InputError) as info:
        write_atomic(tmp_path / "nope" / "s.md", "x")
    assert "does not exist" in str(info.value)
    assert list(tmp_path.iterdir()) == []


def test_writes_into_a_device_instead_of_replacing_it(tmp_path: Path) -> None:
    """-o /dev/stdout (or a link to /dev/null): write into it; never replace the device or the link."""
    link = tmp_path / "sink"
    link.symlink_to(os.devnull)
    write_atomic(link, "x" * 1000)
    assert link.is_symlink() and os.readlink(link) == os.devnull
    assert _leftovers(tmp_path, {"sink"}) == []


# ---------------------------------------------------------------- through the command line


@pytest.fixture
def problem_file(tmp_path: Path) -> Path:
    path = tmp_path / "p.toml"
    path.write_text(PROBLEM)
    return path


@pytest.mark.parametrize("how", ["same", "dot", "absolute", "relative", "symlink"])
def test_cli_refuses_output_over_input(
    cli, problem_file: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, how: str
) -> None:
    monkeypatch.chdir(tmp_path)
    target = {
        "same": str(problem_file),
        "dot": "./p.toml",
        "absolute": str(problem_file.resolve()),
        "relative": "p.toml",
        "symlink": "link.md",
    }[how]
    if how == "symlink":
        (tmp_path / "link.md").symlink_to(problem_file)
    r = cli("solve", "p.toml" if how != "same" else str(problem_file), "-o", target)
    assert r.code == 2, r.err
    assert r.err.startswith("Error: ") and r.err.count("\n") == 1
    assert "refusing to overwrite the input" in r.err and "-o" in r.err
    assert problem_file.read_text() == PROBLEM
    assert _leftovers(tmp_path, {"p.toml", "link.md"}) == []


@pytest.mark.parametrize("fmt", ["md", "json", "tex"])
def test_cli_failed_write_keeps_old_output(
    cli, problem_file: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, fmt: str
) -> None:
    out = tmp_path / f"s.{fmt}"
    out.write_text(OLD)

    def fail(*args: object) -> None:
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(fileio.os, "replace", fail)
    r = cli("solve", str(problem_file), "--format", fmt, "-o", str(out))
    monkeypatch.undo()
    assert r.code == 1, r.err
    assert r.err.startswith("Error: ") and r.err.count("\n") == 1 and "No space left" in r.err
    assert out.read_text() == OLD
    assert _leftovers(tmp_path, {"p.toml", out.name}) == []


def test_cli_bad_input_leaves_existing_output_alone(cli, tmp_path: Path) -> None:
    bad = tmp_path / "bad.toml"
    bad.write_text(PROBLEM.replace("e = 0.5", "e = 1.5"))
    out = tmp_path / "s.md"
    out.write_text(OLD)
    r = cli("solve", str(bad), "-o", str(out))
    assert r.code == 2
    assert out.read_text() == OLD
    assert _leftovers(tmp_path, {"bad.toml", "s.md"}) == []


def test_cli_writes_the_output(cli, problem_file: Path, tmp_path: Path) -> None:
    out = tmp_path / "s.md"
    out.write_text(OLD)
    r = cli("solve", str(problem_file), "-o", str(out))
    assert r.code == 0, r.err
    assert out.read_text().startswith("# Two carts")
    assert _leftovers(tmp_path, {"p.toml", "s.md"}) == []
