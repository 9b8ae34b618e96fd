"""Simulates the FMU's default experiment through fmpy and writes a CSV and plots of the last engine cycle.

    python -m pistonslap.demo [--out DIR] [--stop-time SECONDS] [--interval SECONDS]
"""

import argparse
from pathlib import Path

from fmpy.util import write_csv

from . import plots
from .fmu import fmu_path, last_cycle, simulate_with_events

#: 1e-4 s is 0.72° of crank angle at the default 1200 rpm: fine enough to draw the impacts.
DEFAULT_INTERVAL = 1e-4


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=Path("out"), help="output folder (default: out)")
    parser.add_argument("--stop-time", type=float, default=None, help="s (default: the FMU's default experiment)")
    parser.add_argument("--interval", type=float, default=DEFAULT_INTERVAL, help="communication step, s")
    args = parser.parse_args(argv)

    args.out.mkdir(parents=True, exist_ok=True)
    result, events = simulate_with_events(
        log_path=args.out / "impact_log.csv", stop_time=args.stop_time, output_interval=args.interval
    )
    csv = args.out / "demo.csv"
    write_csv(str(csv), result)

    cycle, phase = last_cycle(result["crank_angle"])
    times = result["time"][cycle]
    # the log's crank angle is already taken mod 4π, i.e. the phase within the cycle
    in_cycle = (events["time"] >= times[0]) & (events["time"] <= times[-1])
    written = [
        csv,
        args.out / "impact_log.csv",
        plots.piston_motion(phase[cycle], result[cycle], args.out / "piston_motion.png"),
        plots.impacts(phase[cycle], result[cycle], events[in_cycle], args.out / "impacts.png"),
        plots.crank_torque(phase[cycle], result[cycle], args.out / "crank_torque.png"),
    ]
    impacts = int((events["kind"] == "impact").sum())
    print(f"Simulated {fmu_path()} to t = {result['time'][-1]:g} s: {impacts} impacts, "
          f"{len(events) - impacts} sliding starts/releases; plotted the last engine cycle.")
    for path in written:
        print(f"wrote {path}")


if __name__ == "__main__":
    main()
