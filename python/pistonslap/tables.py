"""CSV tables with units in their header (`name [unit]`), and the per-cycle metrics of a simulation record."""

import csv

import numpy as np

#: The FMU's per-cycle outputs and their units.
CYCLE_METRICS = {
    "cycle_slap_events": "1", "cycle_impact_energy": "J", "cycle_max_impact_energy_thrust": "J",
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
