"""Firing TDC of a supplied pressure trace (`--pressure-trace`), stated or detected from its peak.

The FMU takes a trace's 0° as firing TDC (its crank angle 0 mod 4π), and the plots, the impact log and the per-cycle
outputs count from there. Indicating systems also export cycles from 0 to 720° with firing TDC at 360°, or with the
gas-exchange TDC at 0: such a trace, taken as it is, would fire half a cycle late against the crank. So the demo
places firing TDC before the run: where the user states it (`--firing-tdc DEG`, in the trace's own angles), or else
at the top dead centre (a multiple of 360° of the trace's angle) nearest the peak pressure, which a fired cycle
reaches 5–20° after firing TDC and a motored one at it. A trace whose firing TDC is not at 0° is handed to the FMU
as a copy with its angles shifted by −TDC (pressures as written), so that the −360…360° axis has firing TDC at 0.
"""

from pathlib import Path

import numpy as np

from .refusal import Refusal

#: Farthest the peak pressure may lie from the TDC taken as firing TDC, deg: late combustion peaks within ~40°
#: after TDC; farther than this the trace's angles are not counted from a TDC and firing TDC must be stated.
PEAK_FROM_TDC = 60.0


def read_trace(path):
    """(header row, angles [deg], pressures in the file's unit, pressure cells as written) of a trace, or None
    when its rows are not all `angle, pressure` numbers (the FMU then refuses it naming the line)."""
    lines = [line.strip() for line in Path(path).read_text().splitlines()]
    rows = [line.split(",") for line in lines[1:] if line]
    try:
        angles = np.array([float(row[0]) for row in rows])
        pressures = np.array([float(row[1]) for row in rows])
    except (IndexError, ValueError):
        return None
    if len(rows) < 2:
        return None
    return lines[0], angles, pressures, [",".join(row[1:]).strip() for row in rows]


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


def place_firing_tdc(path, out, stated=None):
    """The trace the FMU should read, with firing TDC at its 0°, and one line saying where firing TDC was taken.

    `stated` is firing TDC in the trace's angles (deg) or None to detect it from the peak; a trace whose firing
    TDC is not at 0 (mod 720°) is written shifted into `out`."""
    trace = read_trace(path)
    if trace is None:
        return path, f"pressure trace {path}: not read here (the FMU checks it); its 0° taken as firing TDC"
    header, angles, pressures, cells = trace
    try:
        tdc, peak = detect_firing_tdc(angles, pressures)
    except Refusal as refusal:
        if stated is None:
            raise Refusal(f"--pressure-trace {path}: {refusal}") from None
        peak = float(angles[np.argmax(pressures)])
    how = "stated" if stated is not None else "detected: the TDC nearest the peak"
    tdc = float(stated) if stated is not None else tdc
    said = f"pressure trace {path}: peak at {peak:g}°, firing TDC at {tdc:g}° ({how})"
    if (tdc / 720.0).is_integer():
        return path, said
    shifted = Path(out) / f"{Path(path).stem}_firing_tdc_0.csv"
    Path(out).mkdir(parents=True, exist_ok=True)
    rows = "".join(f"{angle - tdc!r},{cell}\n" for angle, cell in zip(angles.tolist(), cells, strict=True))
    shifted.write_text(f"{header}\n{rows}")
    return shifted, f"{said}; its angles shifted by {-tdc:g}° into {shifted}"
