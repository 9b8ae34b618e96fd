"""CSV tables with units in their header (`name [unit]`), the per-cycle metrics of a simulation record, and which
rows of an impact log are side changes and slaps."""

import csv

import numpy as np

from .fmu import CENTRED, CYCLE, from_firing_tdc

#: Crank angle between samples (and communication points) of the demo and of a sweep's crank-train runs, deg: the
#: FMU's default experiment samples every 5e-5 s, 0.36° at 1200 rpm. The per-cycle peaks of sampled outputs
#: (`SAMPLED_METRICS`) and the FMU's liner-force rise rate (between communication points) are taken at this step.
SAMPLE_DEG = 0.36
#: Crank angle a run may go on past the end of the last cycle about a firing TDC it reports, rad: the FMU completes a
#: cycle's landing figures once the next cycle's first landing starts (`fmu.simulate_with_logs` stops there); 270°
#: at most, so that no later engine cycle (firing TDC to firing TDC) completes.
LANDING_RUN_ON = 1.5 * np.pi
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


def energy_unit(joules):
    """The unit to show an energy of about `joules` in: `(factor, name)` of mJ, µJ or nJ (a dry slap is millijoules,
    a landing on the film micro- or nanojoules)."""
    for factor, name in ((1e3, "mJ"), (1e6, "µJ")):
        if abs(joules) * factor >= 0.1:
            return factor, name
    return 1e9, "nJ"


def write_table(path, table, units):
    """Writes the structured array `table` as CSV, each column headed `name [unit]` (`[1]` for counts and other
    dimensionless values); `units` maps names to units (missing or None: dimensionless)."""
    names = table.dtype.names
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow([f"{name} [{units.get(name) or '1'}]" for name in names])
        writer.writerows(table.tolist())
    return path


def landing_cycle(angle):
    """The cycle from −360° to 360° about a firing TDC that an accumulated crank angle (rad) lies in: 0 about the
    firing TDC at 0, 1 about the one at 4π, …"""
    return np.floor((np.asarray(angle) - CENTRED) / CYCLE).astype(int)


def landing_starts(result, landings):
    """The accumulated crank angle of each landing's start: the landing log's rows, then the landing in progress at
    the record's end (which started where the last logged one ended); the log's angle within its cycle, the cycle
    from the record's crank angle at the landing's time."""
    if len(landings) == 0:
        return np.zeros(0)
    times = np.append(landings["time"], landings["end_time"].max())
    within = np.append(landings["crank_angle"], np.nan)
    accumulated = np.interp(times, result["time"], result["crank_angle"])
    within[-1] = from_firing_tdc(accumulated[-1])
    return within + CYCLE * np.round((accumulated - within) / CYCLE)


def described_at(result, landings, cycle):
    """The first sample at which the FMU's landing outputs (`LANDING_METRICS`) describe the landing cycle `cycle`
    (see `landing_cycle`), or None when the record ends first. The FMU completes a cycle once the crank is past it
    and the landing in progress started after it (a landing counts in the cycle it starts in, and ends where the
    next starts): the first sample after both."""
    starts = landing_starts(result, landings)
    later = starts[landing_cycle(starts) > cycle]
    if later.size == 0:
        return None
    completed = max(cycle * CYCLE - CENTRED, later.min())
    after = np.flatnonzero(result["crank_angle"] > completed)
    return int(after[0]) if after.size else None


def sampled_metrics(result, cycle):
    """`SAMPLED_METRICS` of the landing cycle `cycle` from the samples of `result` in it (from its start to before
    its end); NaN unless the record runs from before it to after it. (A run starting at crank angle 0 covers half of
    cycle 0: not reported.)"""
    angle = result["crank_angle"]
    if landing_cycle(angle[0]) >= cycle or landing_cycle(angle[-1]) <= cycle:
        return dict.fromkeys(SAMPLED_METRICS, np.nan)
    rows, row = result[landing_cycle(angle) == cycle], {}
    for wall in WALLS:
        film = rows[f"min_film_thickness_{wall}"]
        k = int(np.argmin(film))
        row[f"cycle_min_film_thickness_{wall}"] = float(film[k])
        row[f"cycle_min_film_crank_angle_{wall}"] = float(from_firing_tdc(rows["crank_angle"][k], CENTRED))
    row["cycle_max_film_force"] = float(np.abs(rows["film_force"]).max())
    row["cycle_max_asperity_force"] = float(rows["asperity_force"].max())
    return row


def landing_metrics(result, landings, cycle):
    """The FMU's `LANDING_METRICS` of the landing cycle `cycle`, read where they describe it (`described_at`), with
    its `SAMPLED_METRICS`; NaN for what the record does not hold."""
    index = described_at(result, landings, cycle)
    row = {name: np.nan if index is None else float(result[name][index]) for name in LANDING_METRICS}
    return dict(row, **sampled_metrics(result, cycle))


def cycle_metrics(result, landings):
    """The per-cycle figures, one row per engine cycle (firing TDC to firing TDC) the record completes: its end time,
    the cycle (1 = the first), those of the FMU's `CYCLE_METRICS` the record holds at the first sample after its end,
    and the landings (`landing_metrics`) of the cycle from −360° to 360° about the firing TDC that ends it (NaN where
    the record ends before the FMU completes it). `landings` is the run's landing log. Returns `(table, units)`."""
    count = result["cycle_count"]
    ends = np.flatnonzero(np.diff(count) > 0) + 1
    recorded = [name for name in CYCLE_METRICS if name in result.dtype.names]
    units = {**{name: CYCLE_METRICS[name] for name in recorded}, **LANDING_METRICS, **SAMPLED_METRICS}
    types = {name: result.dtype[name] if name in recorded else np.dtype("f8") for name in units}
    table = np.zeros(len(ends), dtype=[("time", "f8"), ("cycle", "i4"), *types.items()])
    table["time"] = result["time"][ends]
    table["cycle"] = count[ends]
    for k, end in enumerate(ends):
        row = {name: result[name][end] for name in recorded} | landing_metrics(result, landings, count[end])
        for name, value in row.items():
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
    the rows', landings per cycle and FMEP the rows' means; rows without a figure (NaN) left out, NaN for none."""
    row = {}
    for wall in WALLS:
        largest = ("landing_energy", "landing_loss", "landing_crank_angle")
        row |= _picked(table, np.nanargmax, {f"{name}_{wall}": f"cycle_{name}_{wall}" for name in largest})
        thinnest = ("min_film_thickness", "min_film_crank_angle")
        row |= _picked(table, np.nanargmin, {f"{name}_{wall}": f"cycle_{name}_{wall}" for name in thinnest})
        row[f"landings_per_cycle_{wall}"] = _reduced(table, np.mean, f"cycle_landings_{wall}")
        for name in ("max_liner_force_rate", "max_liner_force"):
            row[f"{name}_{wall}"] = _reduced(table, np.max, f"cycle_{name}_{wall}")
    row["skirt_fmep"] = _reduced(table, np.mean, "cycle_skirt_fmep")
    for name in ("max_film_force", "max_asperity_force"):
        row[name] = _reduced(table, np.max, f"cycle_{name}")
    return {name: row[name] for name in OVER_CYCLES}


def _reduced(table, reduce, column):
    """`reduce` of a column's finite values, NaN for none."""
    values = table[column][np.isfinite(table[column])]
    return float(reduce(values)) if values.size else np.nan


def _picked(table, pick, names):
    """From the row that `pick` (np.nanargmax, np.nanargmin) chooses by the first column of `names` ({key: column}),
    each column's value by its key; NaN when that column has no finite value."""
    first = table[next(iter(names.values()))]
    if not np.isfinite(first).any():
        return dict.fromkeys(names, np.nan)
    chosen = table[int(pick(first))]
    return {key: float(chosen[column]) for key, column in names.items()}
