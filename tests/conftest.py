"""Shared fixtures: problems loaded from text, and the CLI run in-process."""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from dataclasses import dataclass

import pytest

import derive
from derive.cli import main
from derive.problem import loads


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
