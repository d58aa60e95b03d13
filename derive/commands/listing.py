"""``derive list`` and ``derive check``."""

from __future__ import annotations

import argparse
import sys

from derive.commands.terminal import one_line
from derive.errors import DeriveError


def run_list(args: argparse.Namespace) -> int:
    """derive list: the bundled problems with their titles."""
    from derive import problem, resources

    found = resources.bundled()
    width = max((len(n) for n in found), default=0) + 2
    for name, path in found.items():
        try:
            title = problem.title(path)
        except DeriveError as exc:
            title = f"(broken: {exc})"
        print(f"{name:{width}s}{title}")
    return 0


def run_check(args: argparse.Namespace) -> int:
    """derive check: the report on hand answers; its exit code says whether all were right."""
    from derive.checking.answers import run

    report, text = run(
        args.problem, args.answer, args.answers, args.equation, args.tolerance, args.format, args.derivation
    )
    sys.stdout.write(text)
    errors = [item for item in report.items if item.status == "error"]
    if errors:  # items that could not be read are in the report; the first is named here, in one line
        more = f" (and {len(errors) - 1} more, in the report)" if len(errors) > 1 else ""
        print(f"Error: {one_line(errors[0].message)}{more}", file=sys.stderr)
    return report.exit_code
