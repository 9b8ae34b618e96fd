"""Running the packaged FMU: where it is, fmpy with PistonSlap's defaults, the impact log as an array."""

import csv
import os
import tempfile
from pathlib import Path

import fmpy
import numpy as np

#: One four-stroke engine cycle in crank angle (rad); firing TDC at 0 mod 4π.
CYCLE = 4 * np.pi

#: The FMU the package carries: `make fmu` copies the packaged FMU here, and the wheel includes it.
PACKAGED_FMU = Path(__file__).resolve().parent / "fmu" / "PistonSlap.fmu"

#: Rows of the `impact_log` CSV (SI units; the crank angle also in degrees from firing TDC in [-360, 360)), in the
#: order of its header (the line after the `#` line stating the conventions).
EVENT_DTYPE = np.dtype(
    [
        ("time", "f8"),
        ("crank_angle", "f8"),
        ("kind", "U8"),
        ("corner", "i4"),
        ("normal_velocity_before", "f8"),
        ("normal_velocity_after", "f8"),
        ("energy_lost", "f8"),
        ("position", "f8"),
        ("crank_angle_deg", "f8"),
        ("friction_energy_lost", "f8"),
    ]
)

#: Rows of the `landing_log` CSV, one per finished landing (the piston's arrival on a wall after it left the other,
#: whatever carries it: corners, asperities or film), in the order of its header; SI units, crank angles in rad from
#: firing TDC in [-2π, 2π), `wall` thrust or antithrust, `leading_end` top or bottom.
LANDING_DTYPE = np.dtype(
    [
        ("time", "f8"),
        ("crank_angle", "f8"),
        ("wall", "U10"),
        ("leading_end", "U6"),
        ("kinetic_energy", "f8"),
        ("max_approach_kinetic_energy", "f8"),
        ("energy_loss", "f8"),
        ("peak_force", "f8"),
        ("peak_force_crank_angle", "f8"),
        ("peak_force_rate", "f8"),
        ("impacts", "i4"),
        ("end_time", "f8"),
    ]
)


def fmu_path() -> Path:
    """The FMU to run: `$PISTONSLAP_FMU` if set, else the one this package carries (`PACKAGED_FMU`)."""
    path = Path(os.environ.get("PISTONSLAP_FMU", PACKAGED_FMU))
    if not path.is_file():
        raise FileNotFoundError(
            f"{path} is missing: run `make fmu` in the PistonSlap repository (it copies the FMU "
            "there), or set PISTONSLAP_FMU to a PistonSlap.fmu"
        )
    return path


def simulate(stop_time=None, output_interval=None, start_values=None, input=None, output=None, fmu=None, **fmpy_kwargs):
    """Runs the FMU through `fmpy.simulate_fmu` and returns its structured array (`time` + recorded variables).

    `stop_time=None` runs the FMU's default experiment; `output=None` records every output;
    `output_interval` is also the communication step (fmpy steps from one output point to the next).
    `fmu` is the FMU file or a folder it was extracted to (default `fmu_path()`).
    """
    return fmpy.simulate_fmu(
        str(fmu or fmu_path()),
        stop_time=stop_time,
        output_interval=output_interval,
        start_values=dict(start_values or {}),
        input=input,
        output=output,
        **fmpy_kwargs,
    )


def simulate_with_events(log_path=None, start_values=None, **kwargs):
    """Like `simulate`, with the FMU's `impact_log` switched on; returns `(result, events)`.

    The log goes to `log_path` when given (and stays there), else to a temporary file.
    """
    result, events, _ = simulate_with_logs(log_path, start_values=start_values, landings=False, **kwargs)
    return result, events


def simulate_with_logs(
    log_path=None,
    landing_log_path=None,
    start_values=None,
    landed_by=None,
    at_times=(),
    landings=True,
    step_finished=None,
    **kwargs,
):
    """Like `simulate`, with the FMU's `impact_log` and `landing_log` switched on; returns `(result, events,
    landings)`, the logs as arrays of `EVENT_DTYPE` and `LANDING_DTYPE` (with `landings` False: no landing log, no
    landing).

    Each log goes to its path when given (and stays there), else to a temporary file. With `landed_by` (s), the run
    stops at the first communication point after it at which a landing started after it (the FMU then has the
    figures of the landing cycle ending at `landed_by` complete, `tables.described_at`), at the latest at the stop
    time. `at_times` holds `(time, action)` pairs: each action is called once, at the first communication point at
    or after its time. A caller's own fmpy `step_finished` callback runs beside that watch.
    """
    with tempfile.TemporaryDirectory() as tmp:
        log = Path(log_path) if log_path is not None else Path(tmp) / "impact_log.csv"
        landing = Path(landing_log_path) if landing_log_path is not None else Path(tmp) / "landing_log.csv"
        values = dict(start_values or {}, impact_log=str(log))
        if landings:
            values["landing_log"] = str(landing)
        watch = (
            _Watch(landing if "landing_log" in values else None, landed_by, at_times) if landed_by or at_times else None
        )
        callbacks = [c for c in (watch, step_finished) if c is not None]

        def both(time, recorder):
            # Every callback runs at every point; the run goes on while all of them say so.
            said = [c(time, recorder) for c in callbacks]
            return all(s is not False for s in said)

        result = simulate(start_values=values, step_finished=both if callbacks else None, **kwargs)
        landings = read_landing_log(landing) if "landing_log" in values else np.zeros(0, LANDING_DTYPE)
        return result, read_impact_log(log), landings


class _Watch:
    """fmpy's `step_finished` callback of `simulate_with_logs`: calls the actions due, and stops the run once the
    landing log holds a landing that ended after `landed_by` (it ends where the next starts)."""

    def __init__(self, landing_log, landed_by, at_times):
        self.landing_log, self.landed_by, self.size, self.landed = landing_log, landed_by, 0, False
        self.due = sorted(at_times, key=lambda pair: pair[0])

    def __call__(self, time, _recorder):
        while self.due and time >= self.due[0][0] * (1 - 1e-12):
            self.due.pop(0)[1]()
        if self.landed:
            # one point more: a landing starting right at a communication point is taken in at the next
            return False
        if self.landed_by is not None and self.landing_log is not None and time > self.landed_by:
            self.landed = any(end > self.landed_by for end in self._new_ends())
        return True

    def _new_ends(self):
        """The end times of the landings logged since the last look."""
        size = self.landing_log.stat().st_size
        if size == self.size:
            return []
        with open(self.landing_log, "rb") as f:
            f.seek(self.size)
            rows = f.read().decode().splitlines()
        self.size = size
        return [float(row.rsplit(",", 1)[1]) for row in rows if row and not row.startswith(("#", "time"))]


def _read_log(path, dtype, what):
    """A CSV log of the FMU as a structured array of `dtype`, its header checked; lines starting with `#` (a
    statement of conventions) are skipped."""
    with open(path, newline="") as f:
        reader = csv.reader(line for line in f if not line.startswith("#"))
        header = tuple(next(reader, ()))
        if header != dtype.names:
            raise ValueError(f"{path}: header {header} is not the {what}'s {dtype.names}")
        types = [dtype[name].type for name in dtype.names]
        rows = []
        for number, row in enumerate(reader, start=1):
            if len(row) != len(types):
                raise ValueError(f"{path}: row {number} has {len(row)} fields, the header {len(types)}")
            rows.append(tuple(t(value) for t, value in zip(types, row, strict=True)))
    return np.array(rows, dtype=dtype)


def read_impact_log(path) -> np.ndarray:
    """The `impact_log` CSV as a structured array of `EVENT_DTYPE` (one row per impact, slide or release)."""
    return _read_log(path, EVENT_DTYPE, "impact log")


def read_landing_log(path) -> np.ndarray:
    """The `landing_log` CSV as a structured array of `LANDING_DTYPE` (one row per finished landing)."""
    return _read_log(path, LANDING_DTYPE, "landing log")


def input_signals(time, **signals) -> np.ndarray:
    """Input signals for fmpy: a structured array with `time` and one column per named input.

    fmpy interpolates them linearly and samples them at the start of each communication step,
    where the FMU holds them over the step.
    """
    time = np.asarray(time, dtype=float)
    table = np.zeros(len(time), dtype=[("time", "f8")] + [(name, "f8") for name in signals])
    table["time"] = time
    for name, values in signals.items():
        table[name] = values
    return table


#: Where an engine cycle's crank-angle axis starts, rad from firing TDC: -2π (the cycle centred on firing TDC,
#: -360°...360°, as engine people read it) or 0 (0...720°).
CENTRED, FROM_FIRING_TDC = -2 * np.pi, 0.0
#: How far short of its end a record's last cycle may stop and still count as complete, rad.
CYCLE_SLACK = np.radians(0.1)


def from_firing_tdc(crank_angle, origin=CENTRED):
    """The crank angle (rad, accumulated or within a cycle) from firing TDC, in [origin, origin + 4π)."""
    return np.mod(np.asarray(crank_angle) - origin, CYCLE) + origin


def last_cycle(crank_angle, slack=CYCLE_SLACK, origin=CENTRED):
    """The last complete engine cycle in a record of the accumulated crank angle, its axis starting at `origin`
    (rad from firing TDC, crank angle 0 mod 4π: `CENTRED` -2π or `FROM_FIRING_TDC` 0).

    Returns `(mask, angle)`: which samples lie in it, and their crank angle from firing TDC in [origin, origin + 4π].
    A cycle short of its end by less than `slack` counts as complete (the default 125.66 rad/s is a hair under
    1200 rpm). A record shorter than one cycle is returned whole, from its first sample's cycle.
    """
    crank_angle = np.asarray(crank_angle)
    start = (np.floor((crank_angle[-1] + slack - origin) / CYCLE) - 1) * CYCLE + origin
    if start < crank_angle[0] - slack:
        start = np.floor((crank_angle[0] - origin) / CYCLE) * CYCLE + origin
        return np.ones(len(crank_angle), dtype=bool), crank_angle - start + origin
    return (crank_angle >= start) & (crank_angle <= start + CYCLE), crank_angle - start + origin
