"""The command line: success paths and every input error, each with its one-line message."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import pytest

DATA = Path(__file__).parent / "data"
PROBLEMS = Path(__file__).parent.parent / "problems"


def test_solve_bundled_to_stdout(cli) -> None:
    r = cli("solve", "notes-4c11-two-spheres")
    assert r.code == 0, r.err
    assert r.out.startswith("# Example 4.C.11")
    assert r.err == ""


def test_solve_json(cli) -> None:
    r = cli("solve", "notes-4c11-two-spheres", "--format", "json")
    assert r.code == 0
    assert json.loads(r.out)["results"]["v_A2n"]["shown"] == "-1.11"


def test_solve_to_file(cli, tmp_path: Path) -> None:
    out = tmp_path / "s.tex"
    r = cli("solve", "notes-4c12-cue-ball", "--format", "tex", "-o", str(out))
    assert r.code == 0, r.err
    assert out.read_text().startswith("\\documentclass")
    frag = tmp_path / "f.tex"
    assert cli("solve", "notes-4c12-cue-ball", "--format", "tex", "--fragment", "-o", str(frag)).code == 0
    assert "\\documentclass" not in frag.read_text()


def test_list(cli) -> None:
    r = cli("list")
    assert r.code == 0
    assert "notes-4c11-two-spheres" in r.out and "notes-4c12-cue-ball" in r.out


def write(tmp_path: Path, name: str, body: str) -> Path:
    path = tmp_path / name
    path.write_text(body)
    return path


BASE = """title = "t"
kind = "direct"
[given]
m_A = "2 kg"
m_B = "3 kg"
e = 0.5
v_A1 = "4 m/s"
v_B1 = "-1 m/s"
"""


@pytest.mark.parametrize(
    ("name", "body", "needles"),
    [
        ("missing-mass.toml", BASE.replace('m_B = "3 kg"\n', ""), ["missing-mass.toml", "m_B", "mass of B"]),
        (
            "unknown-unit.toml",
            BASE.replace('"2 kg"', '"2 stone"'),
            ["unknown-unit.toml:4", "m_A", "unknown unit 'stone'"],
        ),
        (
            "e-too-big.toml",
            BASE.replace("e = 0.5", "e = 1.3"),
            ["e-too-big.toml:6", "[given] e = 1.3", "between 0 and 1"],
        ),
        ("no-approach.toml", BASE.replace('"-1 m/s"', '"5 m/s"'), ["no-approach.toml", "do not approach", "-1.000"]),
        ("wrong-kind-unit.toml", BASE.replace('"4 m/s"', '"4 kg"'), ["v_A1", "expected a velocity"]),
        ("bad-kind.toml", BASE.replace('"direct"', '"sideways"'), ["bad-kind.toml:2", "kind", "direct"]),
        ("bad-toml.toml", BASE + "oops = = 1\n", ["bad-toml.toml:9", "not valid TOML"]),
        ("unknown-field.toml", "colour = 1\n" + BASE, ["colour", "unknown field"]),
        (
            "expr-injection.toml",
            BASE.replace('"4 m/s"', "\"__import__('os').system('true')\""),
            ["v_A1", "unexpected character"],
        ),
    ],
    ids=lambda v: v if isinstance(v, str) and v.endswith(".toml") else "",
)
def test_input_errors(cli, tmp_path: Path, name: str, body: str, needles: list[str]) -> None:
    path = write(tmp_path, name, body)
    r = cli("solve", str(path))
    assert r.code == 2
    assert r.out == ""
    assert r.err.startswith("Error: ")
    assert r.err.count("\n") == 1, r.err  # one line
    assert "Traceback" not in r.err
    for needle in needles:
        assert needle in r.err, (needle, r.err)


def test_missing_file_and_usage_errors(cli) -> None:
    r = cli("solve", "no-such-problem")
    assert r.code == 2 and "no bundled problem" in r.err
    r = cli("solve", "notes-4c11-two-spheres", "--format", "rtf")
    assert r.code == 2 and "invalid choice" in r.err
    r = cli("solve", "notes-4c11-two-spheres", "--format", "docx")
    assert r.code == 2 and "-o" in r.err
    r = cli("solve", "notes-4c11-two-spheres", "--digits", "0")
    assert r.code == 2 and "--digits" in r.err
    r = cli("solve", "notes-4c11-two-spheres", "--format", "pdf")
    assert r.code == 2 and "-o" in r.err


def test_debug_shows_the_traceback(cli, tmp_path: Path) -> None:
    path = write(tmp_path, "e.toml", BASE.replace("e = 0.5", "e = 2"))
    r = cli("--debug", "solve", str(path))
    assert r.code == 2
    assert "Traceback" in r.err


def test_output_never_overwrites_the_input(cli, tmp_path: Path) -> None:
    path = write(tmp_path, "p.toml", BASE)
    r = cli("solve", str(path), "-o", str(path))
    assert r.code == 2 and "refusing to overwrite the input" in r.err
    assert path.read_text() == BASE


def test_a_misspelled_bundled_name_gets_a_suggestion_not_the_whole_list(cli) -> None:
    """Issue 15: a typo printed all the bundled names on one line."""
    r = cli("solve", "notes-4c11-two-sphere")
    assert r.code == 2 and r.err.count("\n") == 1
    assert "did you mean notes-4c11-two-spheres?" in r.err
    assert "aqa-fm-specimen" not in r.err  # not the list
    r = cli("solve", "zzzz")
    assert r.code == 2 and "'derive list' names them" in r.err


@pytest.mark.parametrize(
    ("name", "starts"), [("out.pdf", b"%PDF"), ("out.json", b"{"), ("out.tex", b"\\"), ("out.txt", b"#")]
)
def test_the_output_format_follows_the_extension(cli, tmp_path: Path, name: str, starts: bytes) -> None:
    """Issue 15: -o out.pdf without --format wrote Markdown into out.pdf."""
    if name.endswith(".pdf") and shutil.which("pdflatex") is None:
        pytest.skip("no pdflatex")
    out = tmp_path / name
    r = cli("solve", "notes-4c11-two-spheres", "-o", str(out))
    assert r.code == 0, r.err
    assert out.read_bytes().lstrip().startswith(starts)


def test_variants_of_a_chain_without_a_vary_table_is_a_clear_error(cli, tmp_path: Path) -> None:
    """Issue 15: an internal error (AttributeError: 'ChainProblem' object has no attribute 'vary');
    a chain's [vary] table now draws variants, and a chain without one says so."""
    text = (PROBLEMS / "chain-aqa-m3-2007-collide-again.toml").read_text(encoding="utf-8")
    path = tmp_path / "no-vary.toml"
    path.write_text(text[: text.index("\n[vary]")] + "\n", encoding="utf-8")
    r = cli("variants", str(path), "--count", "2", "-o", str(tmp_path / "v"))
    assert r.code == 2 and "has no [vary] table" in r.err and "internal error" not in r.err
    r = cli("variants", "chain-aqa-m3-2007-collide-again", "--count", "2", "-o", str(tmp_path / "w"))
    assert r.code == 0, r.err


def test_a_missing_given_names_the_key_that_looks_like_it(cli, tmp_path: Path) -> None:
    """Issue 15: a typo inside [given] (v_b1) was reported as "v_B1 is missing" alone."""
    path = tmp_path / "typo.toml"
    path.write_text(
        'title = "t"\nkind = "direct"\n[given]\nm_A = "2 kg"\nm_B = "3 kg"\ne = 0.5\nv_A1 = "4 m/s"\nv_b1 = "0 m/s"\n',
        encoding="utf-8",
    )
    r = cli("solve", str(path))
    assert r.code == 2 and r.err.count("\n") == 1
    assert "v_B1: is missing" in r.err and "(the file gives v_b1: did you mean v_B1?)" in r.err


@pytest.mark.parametrize(
    ("given", "missing", "typed"),
    [
        ('v_A1 = "4 m/s"\nv_b1 = "2 m/s"\n', "v_B1", "v_b1"),  # a speed with [B] angle, from, toward
        ('v_A1 = "4 m/s"\nv_B1n = "-1 m/s"\nv_B1T = "1 m/s"\n', "v_B1t", "v_B1T"),  # n-t components
        ('v_A1 = "4 m/s"\nv_B1x = "-1 m/s"\nv_B1Y = "1 m/s"\n', "v_B1y", "v_B1Y"),  # x-y components
    ],
    ids=["oblique-speed", "n-t", "x-y"],
)
def test_a_missing_oblique_given_names_the_key_that_looks_like_it(
    cli, tmp_path: Path, given: str, missing: str, typed: str
) -> None:
    """Issue 15: the oblique forms of the v_b1 typo name the unused key too."""
    path = tmp_path / "typo.toml"
    head = 'title = "t"\nkind = "oblique"\n[given]\nm_A = "2 kg"\nm_B = "3 kg"\ne = 0.5\n'
    angles = '[A]\nangle = "30 deg"\nfrom = "+n"\ntoward = "+t"\n[B]\nangle = "10 deg"\nfrom = "-n"\ntoward = "+t"\n'
    tables = angles if typed == "v_b1" else angles.split("[B]")[0]
    tables += '[geometry]\nn_angle = "20 deg"\n' if typed == "v_B1Y" else ""
    path.write_text(head + given + tables, encoding="utf-8")
    r = cli("solve", str(path))
    assert r.code == 2 and r.err.count("\n") == 1, r.err
    assert f"{missing}: is missing" in r.err and f"(the file gives {typed}: did you mean {missing}?)" in r.err


_MODULES = """
import contextlib, io, sys
import derive.cli
with contextlib.redirect_stdout(io.StringIO()):
    code = derive.cli.main(sys.argv[1:])
print(code)
print(" ".join(sorted(sys.modules)))
"""


def _modules_of(*args: str) -> tuple[int, set[str]]:
    """The exit code of ``derive ARGS`` run in a fresh interpreter, and every module it imported."""
    import subprocess
    import sys

    r = subprocess.run([sys.executable, "-c", _MODULES, *args], capture_output=True, text=True, check=True)
    code, modules = r.stdout.splitlines()[-2:]
    return int(code), set(modules.split())


def _under(modules: set[str], *packages: str) -> list[str]:
    return sorted(m for m in modules if any(m == p or m.startswith(p + ".") for p in packages))


def test_each_command_imports_only_what_it_uses() -> None:
    """Start-up time (issue #19): a command imports only the parts it runs. A right answer
    needs no mistakes' model and no worked steps; JSON draws no figure and fills no
    template; the list reads titles only."""
    code, modules = _modules_of("check", "notes-4c11-two-spheres", "--answer", "v_A2n=-1.11")
    assert code == 0
    assert not _under(modules, "derive.checking.mistakes", "derive.steps.impact", "derive.writers.view", "jinja2")
    code, modules = _modules_of("solve", "notes-4c11-two-spheres", "-f", "json")
    assert code == 0
    assert not _under(modules, "derive.writers.figure", "derive.checking", "jinja2")
    code, modules = _modules_of("solve", "notes-4c11-two-spheres")
    assert code == 0
    assert not _under(modules, "derive.checking", "derive.display")
    code, modules = _modules_of("list")
    assert code == 0
    assert not _under(modules, "sympy", "jinja2")


_COLLECTOR = """
import contextlib, gc, io, sys
import derive.cli
from derive.commands import listing, solve
seen = {}
def spy(run):
    def command(args):
        seen.update(enabled=gc.isenabled(), sympy="sympy" in sys.modules, frozen=gc.get_freeze_count())
        return run(args)
    return command
solve.run_solve, listing.run_list = spy(solve.run_solve), spy(listing.run_list)
sys.argv = ["derive", *sys.argv[1:]]
with contextlib.redirect_stdout(io.StringIO()), contextlib.suppress(SystemExit):
    derive.cli.run()
print(seen["enabled"], seen["sympy"], seen["frozen"])
"""


@pytest.mark.parametrize("command", [["solve", "notes-4c11-two-spheres"], ["list"]])
def test_the_console_script_leaves_the_collector_alone(command: list[str]) -> None:
    """No collector tricks (issue #25): the command runs with the cyclic collector on and
    nothing frozen (``gc.freeze()`` happens only once the command has ended); ``list``
    imports no SymPy at all."""
    import subprocess
    import sys

    r = subprocess.run([sys.executable, "-c", _COLLECTOR, *command], capture_output=True, text=True, check=True)
    enabled, sympy_in, frozen = r.stdout.split()
    assert enabled == "True" and frozen == "0"
    assert sympy_in == ("True" if command[0] == "solve" else "False")


def test_a_wrong_answer_still_names_its_mistake(cli) -> None:
    """The mistakes' model, imported only for an answer that is not right, is there when
    one is. Example 4.C.11 resolved with sin and cos swapped, by hand: v_A1n = 5 sin 37.6°,
    v_B1n = -15 sin 37.6°, then (3) and (4) with 20 kg, 5 kg, e = 0.6 give v_A2n = -0.854 m/s."""
    import math

    s = math.sin(math.radians(37.6))
    a1n, b1n = 5 * s, -15 * s
    a2n = (20 * a1n + 5 * b1n - 5 * 0.6 * (a1n - b1n)) / 25
    r = cli("check", "notes-4c11-two-spheres", "--answer", f"v_A2n={a2n:.3f}")
    assert r.code == 1
    assert "is what this mistake gives" in r.out and "sin and cos swapped" in r.out
