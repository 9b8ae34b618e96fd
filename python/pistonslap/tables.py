"""CSV tables with units in their header (`name [unit]`), the per-cycle metrics of a simulation record, and which
rows of an impact log are side changes and slaps."""

import csv

import numpy as np

#: The FMU's per-cycle outputs and their units: slaps (side changes) per wall, then all impacts.
CYCLE_METRICS = {
    "cycle_slap_events": "1",
    "cycle_slaps_thrust": "1",
    "cycle_slaps_antithrust": "1",
    "cycle_slap_energy_thrust": "J",
    "cycle_slap_energy_antithrust": "J",
    "cycle_max_slap_energy_thrust": "J",
    "cycle_max_slap_energy_antithrust": "J",
    "cycle_impacts": "1",
    "cycle_impact_energy": "J",
    "cycle_max_impact_energy_thrust": "J",
    "cycle_max_impact_energy_antithrust": "J",
}


def write_table(path, table, units):
    """Writes the structured array `table` as CSV, each column headed `name [unit]` (`[1]` for counts and other
    dimensionless values); `units` maps names to units (missing or None: dimensionless)."""
    names = table.dtype.names
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow([f"{name} [{units.get(name) or '1'}]" for name in names])
        writer.writerows(table.tolist())
    return path


def cycle_metrics(result):
    """The per-cycle outputs at the first sample after each engine cycle's end, with the end time:
    `(table, units)` with columns time, cycle (1 = the first completed) and `CYCLE_METRICS`."""
    count = result["cycle_count"]
    ends = np.flatnonzero(np.diff(count) > 0) + 1
    table = np.zeros(len(ends), dtype=[("time", "f8"), ("cycle", "i4")] + [(n, result.dtype[n]) for n in CYCLE_METRICS])
    table["time"] = result["time"][ends]
    table["cycle"] = count[ends]
    for name in CYCLE_METRICS:
        table[name] = result[name][ends]
    return table, dict(CYCLE_METRICS, time="s", cycle="1")


def side_changes(events):
    """Per row of the impact log `events`: a landing (impact or slide start) on the other wall than the landing
    before it. Corners 1, 2 are the anti-thrust wall at -D/2, 3, 4 the major-thrust wall at +D/2; the first landing
    of the log is no change."""
    landing = np.isin(events["kind"], ("impact", "slide"))
    wall = np.where(events["corner"][landing] <= 2, -1, 1)
    change = np.zeros(len(events), dtype=bool)
    change[np.flatnonzero(landing)[1:]] = wall[1:] != wall[:-1]
    return change


def slap_rows(events, slap_threshold):
    """Per row of the impact log `events`: a slap, the impact that lands the piston on the other wall (a side
    change), approaching faster than `slap_threshold` (m/s), as the FMU's cycle_slap outputs count them."""
    return side_changes(events) & (events["kind"] == "impact") & (events["normal_velocity_before"] > slap_threshold)
