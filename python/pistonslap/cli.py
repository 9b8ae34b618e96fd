"""The `pistonslap` command: `pistonslap demo ...`, `pistonslap analysis ...`, `pistonslap sweep ...`,
`pistonslap map ...`, `pistonslap coupled ...`, `pistonslap fmu-path`."""

import sys


def _fmu_path(argv):
    from .fmu import fmu_path

    if argv:
        raise SystemExit("usage: pistonslap fmu-path")
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
    if not argv or argv[0] not in COMMANDS:
        lines = [f"  {name:9} {help}" for name, (_, help) in COMMANDS.items()]
        print("usage: pistonslap COMMAND [ARGS]\n\ncommands:\n" + "\n".join(lines), file=sys.stderr)
        raise SystemExit(0 if argv[:1] in (["-h"], ["--help"]) else 2)
    command, _ = COMMANDS[argv[0]]
    command(argv[1:])


if __name__ == "__main__":
    main()
