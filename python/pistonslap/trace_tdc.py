"""Firing TDC of a supplied pressure trace (`--pressure-trace`), stated or detected from its peak.

The FMU takes a trace's 0° as firing TDC (its crank angle 0 mod 4π), and the plots, the impact log and the per-cycle
outputs count from there. Indicating systems also export cycles from 0 to 720° with firing TDC at 360°, or with the
gas-exchange TDC at 0: such a trace, taken as it is, would fire half a cycle late against the crank. So the demo
places firing TDC before the run: where the user states it (`--firing-tdc DEG`, in the trace's own angles), or else
at the top dead centre (a multiple of 360° of the trace's angle) nearest the peak pressure, which a fired cycle
reaches 5–20° after firing TDC and a motored one at it. The FMU runs the trace with its angles shifted by −TDC
(`trace_file.Trace.for_fmu`), so that the −360…360° axis has firing TDC at 0.
"""

from pathlib import Path

import numpy as np

from . import trace_file
from .refusal import Refusal

#: Farthest the peak pressure may lie from the TDC taken as firing TDC, deg: late combustion peaks within ~40°
#: after TDC; farther than this the trace's angles are not counted from a TDC and firing TDC must be stated.
PEAK_FROM_TDC = 60.0


def detect_firing_tdc(angles, pressures):
    """(firing TDC, peak angle), deg in the trace's angles: the multiple of 360° nearest the peak pressure, or a
    `Refusal` when the peak lies more than `PEAK_FROM_TDC` from every TDC."""
    peak = float(angles[np.argmax(pressures)])
    tdc = 360.0 * round(peak / 360.0)
    if abs(peak - tdc) > PEAK_FROM_TDC:
        raise Refusal(
            f"the peak pressure lies at {peak:g}°, {abs(peak - tdc):g}° from the nearest TDC ({tdc:g}°): its "
            f"angles are not counted from a TDC; state firing TDC with --firing-tdc DEG"
        )
    return tdc, peak


def place_firing_tdc(trace, stated=None):
    """(the shift, deg, that puts firing TDC at the FMU's 0°, one line saying where firing TDC was taken) of the
    `trace_file.Trace` `trace`; `stated` is firing TDC in the trace's angles (deg) or None to detect it from the
    peak."""
    peak = float(trace.angles[np.argmax(trace.pressures)])
    if stated is None:
        try:
            tdc, peak = detect_firing_tdc(trace.angles, trace.pressures)
        except Refusal as refusal:
            raise Refusal(f"--pressure-trace {trace.name}: {refusal}") from None
    tdc = float(stated) if stated is not None else tdc
    how = "stated" if stated is not None else "detected: the TDC nearest the peak"
    said = f"pressure trace {trace.name}: {trace.reference}; peak at {peak:g}°, firing TDC at {tdc:g}° ({how})"
    if (tdc / 720.0).is_integer():
        return 0.0, said
    return -tdc, f"{said}; run with its angles shifted by {-tdc:g}°"


class PlacedTrace:
    """A pressure trace (`--pressure-trace`, or `pressure_trace` set otherwise) read as exported
    (`trace_file.load`, a bare name among the FMU `fmu`'s resources), its firing TDC placed (`firing_tdc` stated,
    or None), and written in the FMU's own form for a run into the folder the caller names: a scratch folder to check
    the start values, the results' folder once they are accepted, so that a refusal leaves nothing behind."""

    def __init__(self, path, firing_tdc, fmu):
        self.trace = trace_file.load(path, fmu)
        self.shift, self.said = place_firing_tdc(self.trace, firing_tdc)

    def write(self, folder, name="pressure_trace_as_run.csv"):
        """The trace as the FMU runs it, written into `folder` as `name`; its path."""
        path = Path(folder) / name
        path.write_text(self.trace.for_fmu(self.shift))
        return str(path.resolve())
