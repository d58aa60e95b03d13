"""The command line: ``derive solve``, ``list``, ``check``, ``variants``, ``handout``, ``plot``. A thin layer over the library.

Exit codes: 0 done, 2 bad input or usage, 1 anything else (a run over its time budget too).

Every command has a time budget (:data:`TIME_BUDGETS`, ``--timeout SECONDS`` to change it,
0 for none): past it the command stops with a one-line error, and its outputs are as
they were. Whatever it prints goes through :func:`visible`: a control character from a
file (an ESC that would recolour the terminal or set its title) is shown as ``\\u001b``,
never sent raw; JSON stays valid, since that is how JSON writes it.
"""

import gc
import sys

from derive.commands import homework, listing, solve
from derive.commands.parser import FORMATS, FRAGMENT_PREAMBLE, TIME_BUDGETS, build_parser
from derive.commands.terminal import OutOfTime, one_line, terminal_safe, time_budget, visible
from derive.errors import DeriveError

__all__ = ["FORMATS", "FRAGMENT_PREAMBLE", "TIME_BUDGETS", "OutOfTime", "main", "run", "time_budget", "visible"]


def main(argv: list[str] | None = None) -> int:
    """Run the CLI; returns the exit code."""
    with terminal_safe():
        return _main(list(sys.argv[1:] if argv is None else argv))


def _main(argv: list[str]) -> int:
    debug = "--debug" in argv
    command = "derive"
    try:
        args = build_parser().parse_args(argv)
        command = f"derive {args.command}"
        _imports(args.command)
        commands = {
            "solve": solve.run_solve,
            "list": listing.run_list,
            "check": listing.run_check,
            "variants": homework.run_variants,
            "handout": homework.run_handout,
            "plot": solve.run_plot,
        }
        budget = args.timeout if args.timeout is not None else TIME_BUDGETS[args.command]
        with time_budget(budget):
            return commands[args.command](args)
    except OutOfTime as exc:
        if debug:
            _traceback()
        print(
            f"Error: {command} stopped after {exc.args[0]:g} s, its time budget (--timeout SECONDS to change it, "
            "0 for no limit); its outputs were not changed",
            file=sys.stderr,
        )
        return 1
    except DeriveError as exc:
        if debug:
            _traceback()
        print(f"Error: {one_line(str(exc))}", file=sys.stderr)
        return exc.exit_code
    except KeyboardInterrupt:
        print("Error: interrupted", file=sys.stderr)
        return 1
    except BrokenPipeError:  # the reader (head, less) stopped early: nothing to report
        import os

        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except Exception as exc:
        if debug:
            _traceback()
        else:
            print(
                f"Error: {one_line(f'internal error ({type(exc).__name__}: {exc})')}; run with --debug for the traceback",
                file=sys.stderr,
            )
        return 1


def _imports(command: str) -> None:
    """Import SymPy for every command but ``list`` (the one that does no algebra)."""
    if command != "list":
        import sympy  # noqa: F401


def _traceback() -> None:
    """The traceback of the error being handled, on standard error (``--debug``)."""
    import traceback  # only where --debug asks for it

    traceback.print_exc()


def run() -> None:
    """Console-script entry point."""
    code = main()
    # The process ends here. Its objects (SymPy's hundreds of thousands) are moved out of the
    # cyclic collector's reach, so that the interpreter's last collections do not walk them on
    # the way out: about 65-90 ms of a half-second command (issue #19). Outputs are written and
    # closed by now; standard streams are still flushed and atexit handlers still run.
    gc.freeze()
    sys.exit(code)


if __name__ == "__main__":
    run()
