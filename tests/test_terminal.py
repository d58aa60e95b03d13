"""What reaches the terminal, and for how long: every command's standard output and error
show control characters from a file escaped, never raw; every command stops at its
time budget (``--timeout``) with one line, its outputs as they were.
"""

from __future__ import annotations

import gc
import json
import re
import signal
from collections.abc import Iterator
from pathlib import Path

import pytest

from derive import cli as cli_module
from derive.cli import OutOfTime, time_budget, visible

RAW = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u200e\u200f\u2028\u2029\u202a-\u202e\u2066-\u2069]")
EVIL = "\x1b]0;PWNED\x07\x1b[2J\x1b[31m\x9b1m\u202eevil\u2028x\x7f"
HOSTILE = (
    'title = {t}\nkind = "direct"\nsource = {t}\nstatement = {t}\nquestion = {t}\n'
    '[given]\nm_A = "2 kg"\nm_B = "3 kg"\ne = 0.8\nv_A1 = "4 m/s"\nv_B1 = 0\n'
    "[vary]\ne = {{ choices = [0.5, 0.8] }}\n"
)


def toml_string(text: str) -> str:
    return '"' + "".join(f"\\u{ord(c):04x}" if ord(c) < 32 or 0x7F <= ord(c) <= 0x9F else c for c in text) + '"'


@pytest.fixture
def evil(tmp_path: Path) -> Path:
    path = tmp_path / "evil.toml"
    path.write_text(HOSTILE.format(t=toml_string("Evil " + EVIL)), encoding="utf-8")
    return path


def clean(r) -> None:
    assert not RAW.search(r.out), repr(RAW.search(r.out))
    assert not RAW.search(r.err), repr(r.err)


def test_visible_shows_every_control_character_and_keeps_json() -> None:
    assert visible("a\tb\nc") == "a\tb\nc"
    assert visible("\x1b[31m") == "\\u001b[31m"
    assert visible("\u202e\x9b\x7f\r") == "\\u202e\\u009b\\u007f\\u000d"
    doc = json.dumps({"title": EVIL}, ensure_ascii=False)
    assert RAW.search(doc)  # JSON itself leaves DEL, C1 and U+2028 raw
    assert json.loads(visible(doc)) == {"title": EVIL}  # shown escaped, the same document


@pytest.mark.parametrize(
    "args",
    [
        ["solve", "{evil}"],
        ["solve", "{evil}", "-f", "json"],
        ["solve", "{evil}", "-f", "tex"],
        ["solve", "{evil}", "-f", "html"],
        ["check", "{evil}", "--answer", "v_B2=2.88", "--answer", "\x1b[2Jv_X=1"],
        ["check", "{evil}", "--answer", "v_B2=2.88", "--format", "json"],
        ["check", "{evil}", "--answer", "v_B2=2.88", "--format", "md"],
        ["variants", "{evil}", "--count", "2", "-o", "{tmp}/hw"],
        ["handout", "{evil}", "--no-theory", "-o", "{tmp}/h.md"],
        ["solve", "{tmp}/\x1b[31mmissing.toml"],
        ["check", "{evil}", "--answers", "{tmp}/no\x07such.toml"],
        ["solve", "{evil}", "--digits", "99"],
        ["\x1b[2Jnot-a-command"],
    ],
    ids=lambda a: " ".join(a)[:40],
)
def test_no_command_writes_a_raw_control_character(cli, evil: Path, tmp_path: Path, args: list[str]) -> None:
    r = cli(*(a.format(evil=evil, tmp=tmp_path) for a in args))
    clean(r)
    assert "Traceback" not in r.err and "internal error" not in r.err, r.err
    if args[0] in ("solve", "check") and r.code == 0:
        assert "PWNED" in r.out  # the text is there, shown


def test_list_shows_a_hostile_title_escaped(cli, evil: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    from derive import resources

    monkeypatch.setattr(resources, "bundled", lambda: {"evil": evil})
    r = cli("list")
    assert r.code == 0 and "Evil \\u001b]0;PWNED\\u0007" in r.out
    clean(r)


def test_a_file_error_names_the_key_escaped(cli, tmp_path: Path) -> None:
    path = tmp_path / "k.toml"
    path.write_text('title = "t"\nkind = "direct"\n"\\u001b[31m" = 1\n', encoding="utf-8")
    r = cli("solve", str(path))
    assert r.code == 2 and "\\x1b[31m: unknown field" in r.err
    clean(r)


# ---------------------------------------------------------------- the time budget


@pytest.fixture
def no_gc_callbacks() -> Iterator[None]:
    """No collector callbacks while a budget's alarm may fire: hypothesis adds one to a process
    that ran its tests, and an alarm landing inside it is swallowed as "unraisable", so the
    command would never learn its time was up (derive itself sets none)."""
    saved = gc.callbacks[:]
    gc.callbacks.clear()
    try:
        yield
    finally:
        gc.callbacks[:] = saved


def test_a_command_past_its_budget_stops_in_one_line(cli, tmp_path: Path, no_gc_callbacks: None) -> None:
    out = tmp_path / "s.md"
    out.write_text("old\n")
    r = cli("solve", "notes-4c11-two-spheres", "-o", str(out), "--timeout", "0.01")
    assert r.code == 1
    assert r.err == (
        "Error: derive solve stopped after 0.01 s, its time budget (--timeout SECONDS to change it, "
        "0 for no limit); its outputs were not changed\n"
    )
    assert out.read_text() == "old\n"
    assert [p.name for p in tmp_path.iterdir()] == ["s.md"]


def test_timeout_before_the_command_and_zero_for_none(cli, no_gc_callbacks: None) -> None:
    # a budget far shorter than any check (a warm process checks this one in milliseconds)
    assert cli("--timeout", "0.000001", "check", "notes-4c11-two-spheres", "-a", "v_B2n=8.4").code == 1
    r = cli("--timeout", "0", "solve", "notes-4c12-cue-ball", "-f", "json")
    assert r.code == 0 and json.loads(r.out)["title"].startswith("Example 4.C.12")


@pytest.mark.parametrize("value", ["-1", "nan", "inf", "soon", ""])
def test_a_bad_timeout_is_a_usage_error(cli, value: str) -> None:
    r = cli("solve", "notes-4c11-two-spheres", "--timeout", value)
    assert r.code == 2 and r.err.startswith("Error: usage: argument --timeout: expected a number of seconds"), r.err


def test_every_command_has_a_budget() -> None:
    commands = next(a for a in cli_module.build_parser()._actions if a.dest == "command").choices
    assert set(cli_module.TIME_BUDGETS) == set(commands) == {"solve", "check", "list", "variants", "handout", "plot"}
    assert all(0 < s <= 600 for s in cli_module.TIME_BUDGETS.values())


def test_time_budget_raises_and_puts_back_a_callers_alarm(no_gc_callbacks: None) -> None:
    fired = []
    old = signal.signal(signal.SIGALRM, lambda *a: fired.append(1))
    signal.setitimer(signal.ITIMER_REAL, 30)
    try:
        with pytest.raises(OutOfTime), time_budget(0.05):
            while True:
                pass
        remaining, _ = signal.getitimer(signal.ITIMER_REAL)
        assert 0 < remaining <= 30
        assert signal.getsignal(signal.SIGALRM) is not None and not fired
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def test_out_of_time_is_not_an_exception() -> None:
    """SymPy catches ``Exception`` in places: the time-out must not be swallowed there."""
    assert not issubclass(OutOfTime, Exception)
