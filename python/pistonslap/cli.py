"""The `pistonslap` command: `pistonslap demo ...`, `pistonslap analysis ...`, `pistonslap sweep ...`,
`pistonslap map ...`, `pistonslap coupled ...`, `pistonslap fmu-path`.

A refusal (arguments a command cannot run with, a parameter the FMU refuses, a missing file) is one line on
stderr and exit status 2; any other failure is one line and exit status 1. `--debug` anywhere on the command line
shows the Python traceback instead.
"""

import sys

from .refusal import Refusal


def _fmu_path(argv):
    from .fmu import fmu_path

    if argv:
        raise Refusal("takes no arguments")
    print(fmu_path())


def _demo(argv):
    from . import demo

    demo.main(argv)


def _analysis(argv):
    from . import analysis

    analysis.main(argv)


def _sweep(argv):
    from . import sweep

    sweep.main(argv)


def _map(argv):
    from . import heat_map

    heat_map.main(argv)


def _coupled(argv):
    from . import coupled

    coupled.main(argv)


COMMANDS = {
    "demo": (_demo, "simulate an operating point, write CSVs and plots (pistonslap demo --help)"),
    "analysis": (_analysis, "model variant 2 analysed as in Farahanchi's thesis (pistonslap analysis --help)"),
    "sweep": (_sweep, "run a TOML sweep spec on Dask, resumable, into parquet (pistonslap sweep --help)"),
    "map": (_map, "heat map PNG of a sweep's metric or response class (pistonslap map --help)"),
    "coupled": (_coupled, "PistonSlap driven by the EngineCycle FMU, CSV and plots (pistonslap coupled --help)"),
    "fmu-path": (_fmu_path, "print the path of the FMU this package runs"),
}


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    debug = "--debug" in argv
    argv = [a for a in argv if a != "--debug"]
    if not argv or argv[0] not in COMMANDS:
        if argv[:1] in (["-h"], ["--help"]) or not argv:
            lines = [f"  {name:9} {help}" for name, (_, help) in COMMANDS.items()]
            print("usage: pistonslap [--debug] COMMAND [ARGS]\n\ncommands:\n" + "\n".join(lines), file=sys.stderr)
            raise SystemExit(0 if argv else 2)
        _fail(f"pistonslap: unknown command {argv[0]!r}; give one of {', '.join(COMMANDS)}", 2)
    command, _ = COMMANDS[argv[0]]
    if debug:
        return command(argv[1:])
    try:
        command(argv[1:])
    except Refusal as e:
        _fail(f"pistonslap {argv[0]}: {e}", 2)
    except SystemExit as e:
        if not isinstance(e.code, str):
            raise
        _fail(f"pistonslap {argv[0]}: {e.code}", 2)
    except (FileNotFoundError, IsADirectoryError, PermissionError) as e:
        _fail(f"pistonslap {argv[0]}: " + (f"{e.filename}: {e.strerror}" if e.filename else _one_line(e)), 2)
    except KeyboardInterrupt:
        _fail(f"pistonslap {argv[0]}: interrupted", 130)
    except Exception as e:
        _fail(f"pistonslap {argv[0]}: {type(e).__name__}: {_one_line(e)} (--debug shows the traceback)", 1)


def _one_line(error):
    return " ".join(str(error).split())


def _fail(line, status):
    print(" ".join(line.split("\n")), file=sys.stderr)
    raise SystemExit(status)


if __name__ == "__main__":
    main()
