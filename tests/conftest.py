"""Shared fixtures: problems loaded from text, and the CLI run in-process."""

from __future__ import annotations

import os
import textwrap
from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass

import pytest
from hypothesis import settings

import derive
from derive.cli import main
from derive.problem import loads

# In CI the property tests draw the same cases every run (a red CI is then reproducible
# and not a matter of luck); run locally, they draw new ones each time.
settings.register_profile("ci", derandomize=True, print_blob=True)
if os.environ.get("CI"):
    settings.load_profile("ci")


@dataclass
class CliResult:
    code: int
    out: str
    err: str


@pytest.fixture
def cli(capsys: pytest.CaptureFixture[str]) -> Callable[..., CliResult]:
    """Run ``derive ARGS...`` in-process; returns exit code, stdout, stderr."""

    def run(*args: str) -> CliResult:
        code = main(list(args))
        captured = capsys.readouterr()
        return CliResult(code, captured.out, captured.err)

    return run


@pytest.fixture
def problem_from() -> Callable[[str], derive.Problem]:
    """Build a Problem from TOML text (dedented)."""

    def build(text: str) -> derive.Problem:
        return loads(textwrap.dedent(text), path="test.toml")

    return build


# ---------------------------------------------------------------- fuzz summary (tests/test_fuzz.py)


def _fuzz_files_line(terminalreporter, summary: dict) -> None:
    """The file fuzzer's figures (tests/test_fuzz_files.py): files, outcomes, errors, slowest."""
    slowest = summary["slowest"][0] if summary["slowest"] else {}
    terminalreporter.write_line(
        f"fuzz files: {summary['files']} (seed {summary['seed']}) in {summary['seconds']} s; "
        f"by kind {summary['kinds']}; by command {summary['commands']}; "
        f"outcomes {summary['outcomes']}; errors by class {summary['errors_by_class']}; "
        f"failures {summary['failures']}; "
        f"slowest {slowest.get('seconds')} s ({slowest.get('kind')}, {slowest.get('command')})"
    )


def pytest_terminal_summary(terminalreporter, exitstatus, config) -> None:
    """Lines of figures: the fuzz cases run (DERIVE_FUZZ_SCALE scales them), the file
    fuzzer's figures, the verifier's lines."""
    # the verifier's corpus: lines checked, and pages with a known class of wrong line, as
    # the tests recorded them (user properties reach the summary from xdist workers too)
    lines: dict[str, int] = {}
    known: dict[str, int] = {}
    fuzz: dict | None = None
    cases: Counter[str] = Counter()
    mutants: list[tuple[str, dict]] = []
    for reports in terminalreporter.stats.values():
        for rep in reports:
            for key, value in getattr(rep, "user_properties", ()):
                if key == "verify_lines":
                    lines[value[0]] = value[1]
                elif key == "verify_known":
                    known[value[0]] = value[1]
                elif key == "verify_mutants" and rep.when == "call":
                    mutants.append(value)
                elif key == "fuzz_cases" and rep.when == "teardown":  # recorded as the test ends
                    cases.update(value)
                elif key == "fuzz_files":
                    fuzz = value  # on the call and teardown reports alike: shown once below
    if cases:
        parts = ", ".join(f"{k} {v}" for k, v in sorted(cases.items()))
        scale = os.environ.get("DERIVE_FUZZ_SCALE") or ("1" if os.environ.get("CI") else "0.25")
        terminalreporter.write_line(f"fuzz cases run: {sum(cases.values())} ({parts}; DERIVE_FUZZ_SCALE={scale})")
    if fuzz is not None:
        _fuzz_files_line(terminalreporter, fuzz)
    if lines:
        parts = ", ".join(f"{k} {v}" for k, v in sorted(lines.items()))
        terminalreporter.write_line(f"verify: {sum(lines.values())} lines checked ({parts})")
    if mutants:
        from test_verify_mutants import summary_line

        for line in summary_line(mutants):
            terminalreporter.write_line(line)
    if known:
        shown = ", ".join(f"{k} {v}" for k, v in sorted(known.items()))
        terminalreporter.write_line(f"verify: pages with a known class of wrong line (issue #12): {shown}")
