"""The liner's load for a structural (block, liner) model: per wall the normal force, its axial point of application
below the skirt top and its moment about the skirt top, sampled uniformly in crank angle; and its spectrum in engine
orders and third-octave bands.

The FMU is run at a communication step of exactly the sampling step (converted to time with the prescribed crank
speed): with the inputs held its trajectory does not depend on the step (points between integrator steps are served
from the integrator's dense output), and each step's `liner_impulse_*_in_step` is the impulse the wall took over the
interval ending at the sample, impacts included. So each row holds the force at its instant and the mean force over
the interval before it (that impulse over the interval's length): the mean carries the impacts, which the
instantaneous force (between impacts) does not.

    table, units = liner_loads({"crank_speed": 3000 * np.pi / 30}, cycles=2, step_deg=0.1)
    write_table("liner_loads.csv", table, units)
"""

import fmpy
import numpy as np

from .fmu import CENTRED, CYCLE, fmu_path, simulate
from .refusal import Refusal
from .tables import WALLS

#: Default sampling step, deg of crank angle.
DEFAULT_STEP_DEG = 0.1
#: Coarsest step accepted, deg: a structural model wants the load at least 72 times a cycle.
MAX_STEP_DEG = 10.0
#: The FMU's outputs a run records.
RECORDED = ["crank_angle"] + [
    name for wall in WALLS for name in (f"liner_force_{wall}", f"liner_moment_{wall}", f"liner_impulse_{wall}_in_step")
]


def columns():
    """The file's columns and their units: the sample's time and crank angle (firing TDC at 0; a sample ends its
    interval, so a cycle's samples run from one step after its start to its end), the cycle it lies in (1 = the
    first written), then per wall the force now, the mean force over the interval ending now, the point of
    application now (axial distance below the skirt top; empty where the wall carries no load) and the moment about
    the skirt top now."""
    units = {"time": "s", "cycle": "1", "crank_angle": "deg"}
    for wall in WALLS:
        units |= {
            f"liner_force_{wall}": "N",
            f"liner_force_mean_{wall}": "N",
            f"liner_force_height_{wall}": "m",
            f"liner_moment_{wall}": "N.m",
        }
    return units


def samples_per_cycle(step_deg, name="step_deg"):
    """The samples per engine cycle (720°) at `step_deg`, or a `Refusal`: the step must be positive, at most
    `MAX_STEP_DEG` and divide the cycle into whole samples (so that every cycle is sampled alike and the spectrum's
    harmonics fall on its lines); the refusal names the step `name`."""
    if not np.isfinite(step_deg) or not 0 < step_deg <= MAX_STEP_DEG:
        raise Refusal(f"{name} = {step_deg:g}°: give a step > 0 and <= {MAX_STEP_DEG:g}°")
    count = round(720 / step_deg)
    if abs(count * step_deg - 720) > 1e-9 * 720:
        raise Refusal(
            f"{name} = {step_deg:g}°: give a step that divides the 720° cycle into whole samples "
            "(0.05, 0.1, 0.2, 0.25, 0.5, 1, ...)"
        )
    return count


def liner_loads(start_values=None, cycles=2, step_deg=DEFAULT_STEP_DEG, origin=CENTRED, fmu=None):
    """The liner load over the last `cycles` complete engine cycles (on the crank-angle axis starting at `origin`:
    `CENTRED` −360…360°, or `FROM_FIRING_TDC` 0…720°) of a run from `start_values` (SI, by name; the crank
    prescribed, at `crank_speed`), sampled every `step_deg` of crank angle: `(table, units)` with the `columns()`,
    one row per sample, `cycles` · 720 / `step_deg` rows. The run ends where the demo's does, at the end of the
    `cycles`-th cycle; `fmu` is the FMU file or folder (default `fmu_path()`)."""
    per_cycle = samples_per_cycle(step_deg)
    start_values = dict(start_values or {})
    defaults = {v.name: v.start for v in fmpy.read_model_description(str(fmu or fmu_path())).modelVariables}
    if int(start_values.get("crank_mode", defaults["crank_mode"])) != 1:
        raise Refusal("liner loads are sampled at a fixed crank-angle step: give the prescribed crank (crank_mode = 1)")
    speed = float(start_values.get("crank_speed", defaults["crank_speed"]))
    step = CYCLE / per_cycle
    interval = step / speed
    steps = round((cycles * CYCLE - origin) / step)
    # fmpy's communication points are start + k · interval: the last is the stop time
    result = simulate(
        stop_time=steps * interval, output_interval=interval, start_values=start_values, output=RECORDED, fmu=fmu
    )
    return table_of(result, cycles, per_cycle, origin), columns()


def table_of(result, cycles, per_cycle, origin=CENTRED):
    """The rows of the last `cycles` complete cycles (from `origin`) of the record `result` (of `RECORDED`, sampled
    `per_cycle` times a cycle): each sample's instant and the interval before it, the intervals tiling the cycles."""
    angle = result["crank_angle"]
    half = CYCLE / per_cycle / 2
    end = np.floor((angle[-1] + half - origin) / CYCLE) * CYCLE + origin
    rows = (angle > end - cycles * CYCLE + half) & (angle < end + half)
    rows[0] = False  # the start: no interval before it
    record, width = result[rows], np.diff(result["time"])[rows[1:]]
    table = np.zeros(len(record), dtype=[(name, "i4" if name == "cycle" else "f8") for name in columns()])
    table["time"] = record["time"]
    # samples 1, 2, ... from the first cycle's start; the cycle's last sample is at its end (in (origin, origin + 4π])
    index = np.rint((record["crank_angle"] - (end - cycles * CYCLE)) / (2 * half)).astype(int)
    table["cycle"] = (index - 1) // per_cycle + 1
    table["crank_angle"] = np.degrees(origin) + (index - (table["cycle"] - 1) * per_cycle) * (720 / per_cycle)
    for wall in WALLS:
        force, moment = record[f"liner_force_{wall}"], record[f"liner_moment_{wall}"]
        table[f"liner_force_{wall}"] = force
        table[f"liner_force_mean_{wall}"] = record[f"liner_impulse_{wall}_in_step"] / width
        table[f"liner_force_height_{wall}"] = np.divide(moment, force, out=np.full(len(force), np.nan), where=force > 0)
        table[f"liner_moment_{wall}"] = moment
    return table


#: Nominal centre frequencies of the third-octave bands (IEC 61260-1, base 10) from 10 Hz to 20 kHz, as labelled.
NOMINAL_BANDS = (
    10, 12.5, 16, 20, 25, 31.5, 40, 50, 63, 80, 100, 125, 160, 200, 250, 315, 400, 500, 630, 800,
    1000, 1250, 1600, 2000, 2500, 3150, 4000, 5000, 6300, 8000, 10000, 12500, 16000, 20000,
)  # fmt: skip


def order_spectrum(table, speed):
    """The spectrum of each wall's mean force (`liner_force_mean_*` of `table`, whole cycles uniformly sampled) in
    engine orders (multiples of the crank's rotation frequency; one engine cycle is order 0.5): `(orders,
    frequencies in Hz, {wall: RMS amplitude in N})`, the mean (order 0) left out, up to the Nyquist frequency."""
    count = len(table)
    cycles = round(table["cycle"].max() - table["cycle"].min() + 1)
    harmonics = np.arange(1, count // 2 + 1)
    orders = harmonics / (2 * cycles)
    rms = {}
    for wall in WALLS:
        line = np.abs(np.fft.rfft(table[f"liner_force_mean_{wall}"]))[1:] / count
        # a sine of amplitude A shows A/2 on its line: RMS A/√2 = √2 times the line; the Nyquist line is whole
        rms[wall] = line[: len(harmonics)] * np.where(harmonics == count / 2, 1.0, np.sqrt(2))
    return orders, orders * speed / (2 * np.pi), rms


def third_octaves(frequencies, rms):
    """Third-octave band levels of a line spectrum (`frequencies` in Hz, RMS amplitudes `rms` by wall in N): the
    bands of `NOMINAL_BANDS` from the first holding a line to the last lying wholly below the highest line; each
    band's RMS is the root of the sum of its lines' squares. `(nominal centres, {wall: band RMS in N})`."""
    exact = 1000 * 10 ** (np.round(10 * np.log10(np.array(NOMINAL_BANDS) / 1000)) / 10)
    lower, upper = exact * 10**-0.05, exact * 10**0.05
    keep = (upper > frequencies[0]) & (upper <= frequencies[-1])
    nominal = np.array(NOMINAL_BANDS)[keep]
    bands = {}
    for wall, amplitude in rms.items():
        bands[wall] = np.array(
            [
                np.sqrt(np.sum(amplitude[(frequencies >= lo) & (frequencies < hi)] ** 2))
                for lo, hi in zip(lower[keep], upper[keep], strict=True)
            ]
        )
    return nominal, bands


def decibels(rms):
    """Level in dB re 1 N of an RMS force in N (−inf for none)."""
    with np.errstate(divide="ignore"):
        return 20 * np.log10(np.asarray(rms) / 1.0)
