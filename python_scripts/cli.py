"""Command line: ``mortarcontact run ProjectParameters.json`` and ``mortarcontact --version``.

User mistakes (bad files, names, values), unimplemented options and failed solutions are printed
as one clear message without a traceback, and the exit code is non-zero:
2 input error, 3 not implemented, 4 solution failure (non-convergence, singular system), 1 other.
"""
from __future__ import annotations

import argparse
import sys


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="mortarcontact",
                                     description="Mortar contact mechanics (Kratos-format cases).")
    parser.add_argument("--version", action="store_true", help="print the version and exit")
    commands = parser.add_subparsers(dest="command")
    run = commands.add_parser("run", help="run a case from its ProjectParameters.json")
    run.add_argument("parameters", help="path to ProjectParameters.json")
    run.add_argument("--no-progress", action="store_true", help="plain log instead of a progress bar")
    run.add_argument("--continue-on-non-convergence", action="store_true",
                     help="warn and go on when a step does not converge (Kratos' behaviour)")
    run.add_argument("--traceback", action="store_true", help="show Python tracebacks for errors")
    args = parser.parse_args(argv)

    if args.version:
        from . import __version__

        print(f"mortarcontact {__version__}")
        return 0
    if args.command != "run":
        parser.print_help()
        return 2

    from . import _core
    from .analysis_stage import run_case as run_case_cli
    from .utilities import secondary_process

    if secondary_process():
        # Under mpirun every rank runs the same case; rank 0 speaks for them all.
        _silence_this_process()
    try:
        analysis = run_case_cli(args.parameters, progress=not args.no_progress and sys.stdout.isatty(),
                                stop_on_non_convergence=not args.continue_on_non_convergence)
    except _core.InputError as error:
        return _fail(args, "input error", error, 2)
    except _core.NotImplementedFeatureError as error:
        return _fail(args, "not implemented", error, 3)
    except _core.SolutionError as error:
        return _fail(args, "solution failed", error, 4)
    except AssertionError as error:
        return _fail(args, "check failed", error, 5)
    print(analysis.Summary())
    return 0


def _silence_this_process() -> None:
    import os

    quiet = os.open(os.devnull, os.O_WRONLY)
    sys.stdout.flush()
    sys.stderr.flush()
    os.dup2(quiet, 1)  # the C++ log and PETSc write to the descriptors, not to sys.stdout
    os.dup2(quiet, 2)
    os.close(quiet)


def _fail(args, kind: str, error: Exception, code: int) -> int:
    if args.traceback:
        import traceback

        traceback.print_exc()
    print(f"mortarcontact: {kind}: {error}", file=sys.stderr)
    return code


if __name__ == "__main__":
    raise SystemExit(main())
