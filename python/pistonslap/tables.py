"""CSV tables with units in their header (`name [unit]`), the per-cycle metrics of a simulation record, and which
rows of an impact log are side changes and slaps."""

import csv

import numpy as np

from .fmu import CENTRED, CYCLE, from_firing_tdc

#: Crank angle between samples (and communication points) of the demo and of a sweep's crank-train runs, deg: the
#: FMU's default experiment samples every 5e-5 s, 0.36° at 1200 rpm. The per-cycle peaks of sampled outputs
#: (`SAMPLED_METRICS`) and the FMU's liner-force rise rate (between communication points) are taken at this step.
SAMPLE_DEG = 0.36
#: The walls as the FMU's output names spell them: major thrust (+x), anti-thrust (−x).
WALLS = ("thrust", "antithrust")

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
    "cycle_skirt_fmep": "Pa",
}
#: The FMU's per-cycle landing outputs per wall (the last completed cycle from −360° to 360° about firing TDC): the
#: landings, the largest one's lateral kinetic energy at its start, the energy it took from the lateral motion and
#: tilt and its crank angle (rad from firing TDC), and the wall load's peak rise rate and peak.
LANDING_METRICS = {
    f"cycle_{what}_{wall}": unit
    for what, unit in (
        ("landings", "1"),
        ("landing_energy", "J"),
        ("landing_loss", "J"),
        ("landing_crank_angle", "rad"),
        ("max_liner_force_rate", "N/s"),
        ("max_liner_force", "N"),
    )
    for wall in WALLS
}
#: Figures of the same cycle taken from the samples: the thinnest film per side (dry: the smaller corner gap) and
#: its crank angle (rad from firing TDC), the largest net film force (magnitude) and asperity load.
SAMPLED_METRICS = {
    **{f"cycle_min_film_thickness_{wall}": "m" for wall in WALLS},
    **{f"cycle_min_film_crank_angle_{wall}": "rad" for wall in WALLS},
    "cycle_max_film_force": "N",
    "cycle_max_asperity_force": "N",
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


def landing_window(crank_angle, index):
    """Which samples of the record's accumulated `crank_angle` (rad, firing TDC at 0 mod 4π) lie in the last cycle
    from −360° to 360° about firing TDC that ended by sample `index`: the cycle the FMU's landing outputs at that
    sample describe (the run's first such cycle starts where the run does)."""
    end = np.floor((crank_angle[index] - CENTRED) / CYCLE) * CYCLE + CENTRED
    return (crank_angle >= end - CYCLE) & (crank_angle <= end)


def sampled_metrics(result, window):
    """`SAMPLED_METRICS` over the samples `window` (a mask) of `result`; NaN where the window holds none."""
    if not window.any():
        return dict.fromkeys(SAMPLED_METRICS, np.nan)
    rows, row = result[window], {}
    for wall in WALLS:
        film = rows[f"min_film_thickness_{wall}"]
        k = int(np.argmin(film))
        row[f"cycle_min_film_thickness_{wall}"] = float(film[k])
        row[f"cycle_min_film_crank_angle_{wall}"] = float(from_firing_tdc(rows["crank_angle"][k], CENTRED))
    row["cycle_max_film_force"] = float(np.abs(rows["film_force"]).max())
    row["cycle_max_asperity_force"] = float(rows["asperity_force"].max())
    return row


def cycle_row(result, index):
    """The per-cycle figures at sample `index`: the FMU's `CYCLE_METRICS` (the last engine cycle from firing TDC to
    firing TDC completed by then), its `LANDING_METRICS` and the `SAMPLED_METRICS` of the same cycle (the last one
    from −360° to 360° completed by then)."""
    row = {name: result[name][index] for name in {**CYCLE_METRICS, **LANDING_METRICS}}
    return dict(row, **sampled_metrics(result, landing_window(result["crank_angle"], index)))


def cycle_metrics(result):
    """The per-cycle figures (`cycle_row`) at the first sample after each engine cycle's end (firing TDC), with its
    time: `(table, units)` with columns time, cycle (1 = the first completed), `CYCLE_METRICS`, `LANDING_METRICS`,
    `SAMPLED_METRICS`."""
    count = result["cycle_count"]
    ends = np.flatnonzero(np.diff(count) > 0) + 1
    units = {**CYCLE_METRICS, **LANDING_METRICS, **SAMPLED_METRICS}
    types = {name: result.dtype[name] if name in result.dtype.names else np.dtype("f8") for name in units}
    table = np.zeros(len(ends), dtype=[("time", "f8"), ("cycle", "i4"), *types.items()])
    table["time"] = result["time"][ends]
    table["cycle"] = count[ends]
    for k, end in enumerate(ends):
        for name, value in cycle_row(result, end).items():
            table[name][k] = value
    return table, dict(units, time="s", cycle="1")


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


#: The figures of several cycles (`over_cycles`), named as a sweep's columns, with their units: per wall the landings
#: per cycle, the largest landing of all (its energy, loss and crank angle from firing TDC), the largest rise rate and
#: peak of the wall's load; the mean skirt FMEP; the thinnest film per side with its crank angle, the largest film
#: force and asperity load.
OVER_CYCLES = {
    **{
        f"{what}_{wall}": unit
        for what, unit in (
            ("landings_per_cycle", "1/cycle"),
            ("landing_energy", "J"),
            ("landing_loss", "J"),
            ("landing_crank_angle", "rad"),
            ("max_liner_force_rate", "N/s"),
            ("max_liner_force", "N"),
            ("min_film_thickness", "m"),
            ("min_film_crank_angle", "rad"),
        )
        for wall in WALLS
    },
    "skirt_fmep": "Pa",
    "max_film_force": "N",
    "max_asperity_force": "N",
}


def over_cycles(table):
    """`OVER_CYCLES` of the per-cycle rows `table` (of `cycle_metrics`): the largest landing per wall of all the rows
    with its loss and crank angle, the thinnest film per side with its crank angle, the other peaks the largest of
    the rows', landings per cycle and FMEP the rows' means; NaN for no row."""
    if len(table) == 0:
        return dict.fromkeys(OVER_CYCLES, np.nan)
    row = {"skirt_fmep": float(table["cycle_skirt_fmep"].mean())}
    for wall in WALLS:
        largest = table[int(np.argmax(table[f"cycle_landing_energy_{wall}"]))]
        thinnest = table[int(np.argmin(table[f"cycle_min_film_thickness_{wall}"]))]
        row |= {
            f"landings_per_cycle_{wall}": float(table[f"cycle_landings_{wall}"].mean()),
            f"landing_energy_{wall}": float(largest[f"cycle_landing_energy_{wall}"]),
            f"landing_loss_{wall}": float(largest[f"cycle_landing_loss_{wall}"]),
            f"landing_crank_angle_{wall}": float(largest[f"cycle_landing_crank_angle_{wall}"]),
            f"max_liner_force_rate_{wall}": float(table[f"cycle_max_liner_force_rate_{wall}"].max()),
            f"max_liner_force_{wall}": float(table[f"cycle_max_liner_force_{wall}"].max()),
            f"min_film_thickness_{wall}": float(thinnest[f"cycle_min_film_thickness_{wall}"]),
            f"min_film_crank_angle_{wall}": float(thinnest[f"cycle_min_film_crank_angle_{wall}"]),
        }
    row["max_film_force"] = float(table["cycle_max_film_force"].max())
    row["max_asperity_force"] = float(table["cycle_max_asperity_force"].max())
    return {name: row[name] for name in OVER_CYCLES}
