"""Faults while writing: a run killed at any moment, a read-only or a full output folder.

``derive variants`` writes a folder of outputs and ``derive handout`` one file; killed at
random moments (SIGKILL, SIGTERM, SIGINT), each leaves the old output or the new one,
never a mix; the temporary files a killed run leaves behind are removed by the next run.
A folder that cannot be written (read-only, full) is a one-line error, the old output kept.
"""

from __future__ import annotations

import errno
import os
import random
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from derive import fileio

ROOT = Path(__file__).resolve().parent.parent
PROBLEM = """title = "Two carts (homework)"
kind = "direct"
statement = "Cart A ({m_A}) at {v_A1} hits cart B ({m_B}); e = {e}."
[given]
m_A = "2 kg"
m_B = "3 kg"
e = 0.8
v_A1 = "4 m/s"
v_B1 = 0
[vary]
m_A = { min = "1 kg", max = "6 kg", step = "0.5 kg" }
v_A1 = { min = "1 m/s", max = "9 m/s", step = "0.5 m/s" }
e = { choices = [0.5, 0.6, 0.8] }
"""
KILLS = int(os.environ.get("DERIVE_KILLS", "8"))


def snapshot(folder: Path) -> dict[str, bytes] | None:
    if not folder.exists():
        return None
    return {p.name: p.read_bytes() for p in sorted(folder.iterdir())}


def derive_cmd(*args: str) -> list[str]:
    return [sys.executable, "-m", "derive", *args]


def run_to_end(cwd: Path, *args: str) -> float:
    start = time.monotonic()
    proc = subprocess.run(
        derive_cmd(*args), cwd=cwd, capture_output=True, text=True, timeout=600, env=_env(), check=False
    )
    assert proc.returncode == 0, proc.stderr
    return time.monotonic() - start


def _env() -> dict[str, str]:
    return {**os.environ, "PYTHONPATH": str(ROOT)}


def kill_at(cwd: Path, delay: float, sig: int, *args: str) -> None:
    proc = subprocess.Popen(
        derive_cmd(*args), cwd=cwd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=_env()
    )
    try:
        proc.wait(timeout=delay)
    except subprocess.TimeoutExpired:
        proc.send_signal(sig)
        proc.wait(timeout=120)


@pytest.mark.slow
def test_variants_killed_at_random_moments_leave_old_or_new(tmp_path: Path) -> None:
    (tmp_path / "hw.toml").write_text(PROBLEM)
    args_old = ("variants", "hw.toml", "--count", "25", "--seed", "1", "-o")
    args_new = ("variants", "hw.toml", "--count", "25", "--seed", "2", "-o")
    run_to_end(tmp_path, *args_old, "old")
    seconds = run_to_end(tmp_path, *args_new, "new")
    old, new = snapshot(tmp_path / "old"), snapshot(tmp_path / "new")
    assert old and new and old != new
    rng = random.Random(18)
    seen = set()
    for trial in range(KILLS):
        out = tmp_path / "out"
        if out.exists():
            shutil.rmtree(out)
        shutil.copytree(tmp_path / "old", out)
        delay = rng.uniform(0.2, seconds * 1.1)
        sig = rng.choice([signal.SIGKILL, signal.SIGKILL, signal.SIGTERM, signal.SIGINT])
        kill_at(tmp_path, delay, sig, *args_new, "out")
        now = snapshot(out)
        assert now in (old, new), f"trial {trial}: killed after {delay:.2f} s by {sig.name}: a mix"
        seen.add("old" if now == old else "new")
    run_to_end(tmp_path, *args_new, "out")  # the next run finishes, and sweeps what killed runs left
    assert snapshot(tmp_path / "out") == new
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hw.toml", "new", "old", "out"]


@pytest.mark.slow
def test_handout_killed_at_random_moments_leaves_old_or_new(tmp_path: Path) -> None:
    args = ("handout", "notes-4c11-two-spheres", "notes-4c12-cue-ball", "--no-theory", "-o")
    run_to_end(tmp_path, *args, "old.md", "--mode", "problems")
    seconds = run_to_end(tmp_path, *args, "new.md", "--mode", "solutions")
    old, new = (tmp_path / "old.md").read_bytes(), (tmp_path / "new.md").read_bytes()
    assert old != new
    rng = random.Random(19)
    for trial in range(KILLS):
        shutil.copy(tmp_path / "old.md", tmp_path / "h.md")
        delay = rng.uniform(0.2, seconds * 1.1)
        sig = rng.choice([signal.SIGKILL, signal.SIGTERM, signal.SIGINT])
        kill_at(tmp_path, delay, sig, *args, "h.md", "--mode", "solutions")
        assert (tmp_path / "h.md").read_bytes() in (old, new), f"trial {trial}: killed after {delay:.2f} s: a mix"
    run_to_end(tmp_path, *args, "h.md", "--mode", "solutions")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["h.md", "new.md", "old.md"]


# ---------------------------------------------------------------- a folder that cannot be written


@pytest.fixture
def hw(tmp_path: Path) -> Path:
    (tmp_path / "hw.toml").write_text(PROBLEM)
    return tmp_path / "hw.toml"


@pytest.mark.parametrize("code", [errno.EROFS, errno.EACCES, errno.ENOSPC])
def test_unwritable_folder_is_one_line_and_keeps_the_old(
    cli, hw: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, code: int
) -> None:
    out = tmp_path / "out"
    assert cli("variants", str(hw), "--count", "3", "-o", str(out)).code == 0
    old = snapshot(out)

    def refuse(*args: object, **kwargs: object) -> None:
        raise OSError(code, os.strerror(code))

    monkeypatch.setattr(fileio.tempfile, "mkdtemp", refuse)
    r = cli("variants", str(hw), "--count", "4", "--seed", "9", "-o", str(out))
    assert r.code == 1, r.err
    assert r.err.startswith("Error: ") and r.err.count("\n") == 1 and os.strerror(code) in r.err, r.err
    assert snapshot(out) == old


def test_folder_filling_up_while_written_keeps_the_old(cli, hw: Path, tmp_path: Path, monkeypatch) -> None:
    out = tmp_path / "out"
    assert cli("variants", str(hw), "--count", "3", "-o", str(out)).code == 0
    old = snapshot(out)
    real = Path.write_text
    calls = []

    def fills(self: Path, *args: object, **kwargs: object) -> int:
        calls.append(self)
        if len(calls) > 3:
            raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))
        return real(self, *args, **kwargs)

    monkeypatch.setattr(Path, "write_text", fills)
    r = cli("variants", str(hw), "--count", "6", "--seed", "9", "-o", str(out))
    monkeypatch.undo()
    assert r.code == 1 and r.err.count("\n") == 1 and "No space left on device" in r.err, r.err
    assert snapshot(out) == old
    assert sorted(p.name for p in tmp_path.iterdir()) == ["hw.toml", "out"]


def test_a_folder_with_other_files_is_not_replaced(cli, hw: Path, tmp_path: Path) -> None:
    out = tmp_path / "mine"
    out.mkdir()
    (out / "notes.txt").write_text("keep me")
    r = cli("variants", str(hw), "--count", "3", "-o", str(out))
    assert r.code == 2 and "holds files derive did not write (notes.txt)" in r.err, r.err
    assert snapshot(out) == {"notes.txt": b"keep me"}


def _mount_tmpfs(where: Path, size: str) -> bool:
    where.mkdir()
    if shutil.which("mount") is None or os.geteuid() != 0:
        return False
    proc = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(where)], capture_output=True)
    return proc.returncode == 0


@pytest.mark.slow
def test_a_real_full_and_read_only_folder(hw: Path, tmp_path: Path) -> None:
    """On a real small file system (tmpfs: needs root and mount; skipped elsewhere)."""
    disk = tmp_path / "disk"
    if not _mount_tmpfs(disk, "96k"):
        pytest.skip("cannot mount a tmpfs here")
    try:
        args = ("variants", str(hw), "--count", "60", "-o", str(disk / "out"))
        proc = subprocess.run(derive_cmd(*args), capture_output=True, text=True, env=_env(), timeout=600)
        assert proc.returncode == 1 and proc.stderr.count("\n") == 1, proc.stderr
        assert "No space left on device" in proc.stderr
        assert list(disk.iterdir()) == []  # nothing half-written, no temporary folder left
        subprocess.run(["mount", "-o", "remount,ro", str(disk)], check=True)
        for args in (
            ("variants", str(hw), "--count", "2", "-o", str(disk / "out")),
            ("solve", str(hw), "-o", str(disk / "s.md")),
        ):
            proc = subprocess.run(derive_cmd(*args), capture_output=True, text=True, env=_env(), timeout=600)
            assert proc.returncode == 1 and proc.stderr.count("\n") == 1, proc.stderr
            assert "Read-only file system" in proc.stderr and "Traceback" not in proc.stderr
    finally:
        subprocess.run(["umount", str(disk)], check=False)


def _children(pid: int) -> set[int]:
    """The processes whose parent is ``pid`` (read from /proc; Linux only)."""
    found = set()
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.add(int(stat.parent.name))
    return found


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="reads /proc")
def test_workers_end_when_variants_is_killed(tmp_path: Path) -> None:
    """``derive variants`` spreads its work over a pool of forked workers; SIGKILL on the
    command must not leave them waiting for ever (they ended only with the machine before)."""
    (tmp_path / "hw.toml").write_text(PROBLEM)
    proc = subprocess.Popen(
        derive_cmd("variants", "hw.toml", "--count", "400", "-o", "out"),
        cwd=tmp_path,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
        env=_env(),
    )
    deadline = time.monotonic() + 120
    workers: set[int] = set()
    while len(workers) < 2 and time.monotonic() < deadline and proc.poll() is None:
        workers = _children(proc.pid)
        time.sleep(0.1)
    if len(workers) < 2:
        proc.kill()
        proc.wait()
        pytest.skip("the run made no pool of workers here (one core, or it ended first)")
    proc.kill()
    proc.wait()
    deadline = time.monotonic() + 10
    while time.monotonic() < deadline and any(Path(f"/proc/{w}").exists() for w in workers):
        time.sleep(0.2)
    left = [
        w
        for w in workers
        if Path(f"/proc/{w}/stat").exists()
        and "Z" not in Path(f"/proc/{w}/stat").read_text().rsplit(")", 1)[1].split()[0]
    ]
    assert not left, f"workers {left} still run 10 s after their command was killed"
