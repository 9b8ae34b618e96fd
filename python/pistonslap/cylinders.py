"""A whole engine in one process (`pistonslap coupled --cylinders N --firing-order ...`): N PistonSlap instances,
each driven by its own EngineCycle instance, on one crank phased by the firing order (`firing_order`), stepped in
turn by the master of `coupled`; per cylinder and for the engine the skirt FMEP, the impacts and the largest landing
per wall.

The instances share nothing but the loaded libraries: a cylinder's record is bit for bit that of a run of its pair
alone with the same phase (python/tests/test_coupled_cylinders.py). The engine's speed is EngineCycle's, the same in
every cylinder; the cylinders do not load the crank, so they differ only by their phase and by how their start
settles out.
"""

import numpy as np

from .firing_order import phases, start_angles
from .fmu import CENTRED, CYCLE, from_firing_tdc, read_landing_log
from .master import COLUMNS, run_cylinders
from .progress import Progress
from .tables import (
    CYCLE_METRICS,
    LANDING_METRICS,
    LANDING_RUN_ON,
    WALLS,
    cycle_metrics,
    energy_unit,
    over_cycles,
    write_table,
)

#: PistonSlap outputs each cylinder's record holds beyond `master.COLUMNS`: what its per-cycle figures
#: (`tables.cycle_metrics`) are read from, and the wall loads drawn.
RECORDED = (
    "cycle_count",
    *CYCLE_METRICS,
    *LANDING_METRICS,
    *(f"min_film_thickness_{wall}" for wall in WALLS),
    "film_force",
    "asperity_force",
    *(f"liner_force_{wall}" for wall in WALLS),
)
#: The first of each cylinder's cycles reported (its n-th ends at its n-th firing TDC after the start; the first is
#: a part cycle but in cylinder 1): the two before it let the start settle out, as in the one-cylinder run's energy
#: per cycle.
FIRST_REPORTED = 3
#: Per cylinder and for the engine (cylinder 0): the figures of `summary` and their units; a landing's crank angle is
#: from its cylinder's firing TDC, `landing_cylinder_*` the cylinder it is in.
SUMMARY = {
    "cylinder": "1",
    "fires_after_cylinder_1": "deg",
    "skirt_fmep": "Pa",
    "impacts_per_cycle": "1/cycle",
    "impact_energy_per_cycle": "J/cycle",
    **{
        f"{what}_{wall}": unit
        for wall in WALLS
        for what, unit in (
            ("landings_per_cycle", "1/cycle"),
            ("landing_energy", "J"),
            ("landing_loss", "J"),
            ("landing_crank_angle", "deg"),
            ("landing_cylinder", "1"),
        )
    },
}


def start_values(order, engine_values, slap_values):
    """Each cylinder's `(engine_values, slap_values)`, by cylinder number: both FMUs start at its crank angle
    (`crank_angle_start`, `firing_order.start_angles`: cylinder 1 at its firing TDC, 0)."""
    return [
        ({**engine_values, "crank_angle_start": start}, {**slap_values, "crank_angle_start": start})
        for start in start_angles(order)
    ]


def fitted_step(step, order, speed):
    """The largest communication step up to about `step` (s) that divides the firing interval 4π/N at `speed` (rad/s)
    into whole steps: every cylinder then meets the communication points at the same crank angles of its own cycle
    (over a step PistonSlap sees the gas pressure's value and slope at the step's start), so that the cylinders
    differ only by how their start settles out. Off this grid, 7.2° steps in a six-cylinder engine (120°) change
    the largest landing on the lubricated skirt by 15 % from one cylinder to the next."""
    interval = CYCLE / len(order) / speed
    # 0.1 % longer than `step` at most: 1 ms at 125.66 rad/s (a hair under 1200 rpm) is 1/25.0008 of 180°
    return interval / np.ceil(interval / step * (1 - 1e-3))


def stop_time(cycles, speed, step):
    """The run's end, a whole number of steps: cylinder 1's `cycles` cycles, then the half cycle after them that
    the last one's landings (−360° to 360° about its end, `tables.landing_cycle`) take and `tables.LANDING_RUN_ON`
    on, so that the FMU has completed them; the other cylinders end their cycles before cylinder 1."""
    return np.ceil((cycles * CYCLE - CENTRED + LANDING_RUN_ON) / speed / step) * step


def run(order, cycles, step, speed, engine_values, slap_values, out, derivatives=True):
    """Runs the engine of firing order `order` (`firing_order.firing_order`) at `speed` (rad/s, EngineCycle's) for
    cylinder 1's `cycles` cycles (`stop_time`), each cylinder's landing log in `out`. Returns each cylinder's record
    (`master.COLUMNS` and `RECORDED`) and landing log."""
    logs = [out / f"cylinder_{k}_landing_log.csv" for k in range(1, len(order) + 1)]
    cylinders = [
        (engine, dict(slap, landing_log=str(log)))
        for (engine, slap), log in zip(start_values(order, engine_values, slap_values), logs, strict=True)
    ]
    stop = stop_time(cycles, speed, step)
    progress = Progress(f"pistonslap coupled: simulating {len(order)} cylinders", stop)
    records = run_cylinders(stop, step, cylinders, derivatives, step_finished=progress, recorded=RECORDED)
    progress.done()
    return records, [read_landing_log(log) for log in logs]


def cylinder_figures(record, landings, cycles):
    """One cylinder's figures over its cycles `FIRST_REPORTED` to `cycles` (`tables.over_cycles` of its
    `tables.cycle_metrics`): the mean skirt FMEP, impacts and their energy per cycle, per wall the landings per cycle
    and the largest landing (its energy, loss and crank angle from its firing TDC, rad); NaN for what no reported
    cycle completed."""
    table, _ = cycle_metrics(record, landings)
    reported = table[(table["cycle"] >= FIRST_REPORTED) & (table["cycle"] <= cycles)]
    figures = over_cycles(reported)
    row = {
        "skirt_fmep": figures["skirt_fmep"],
        "impacts_per_cycle": float(np.mean(reported["cycle_impacts"])),
        "impact_energy_per_cycle": float(np.mean(reported["cycle_impact_energy"])),
    }
    for wall in WALLS:
        for what in ("landings_per_cycle", "landing_energy", "landing_loss", "landing_crank_angle"):
            row[f"{what}_{wall}"] = figures[f"{what}_{wall}"]
    return row


def summary(order, records, landings, cycles, origin):
    """The `SUMMARY` table: a row per cylinder (`cylinder_figures`, crank angles in degrees from its firing TDC on
    the axis from `origin`), then the engine's (cylinder 0): the mean FMEP (the cylinders displace alike), the sums
    of impacts, their energy and landings, per wall the largest landing of all and its cylinder."""
    counted = ("cylinder", *(f"landing_cylinder_{wall}" for wall in WALLS))
    table = np.zeros(len(order) + 1, dtype=[(name, "i4" if name in counted else "f8") for name in SUMMARY])
    table["cylinder"] = np.arange(len(order) + 1)
    table["fires_after_cylinder_1"][1:] = np.degrees(phases(order))
    table["fires_after_cylinder_1"][0] = np.nan
    for k, (record, landing) in enumerate(zip(records, landings, strict=True), start=1):
        for name, value in cylinder_figures(record, landing, cycles).items():
            table[name][k] = value
        for wall in WALLS:
            table[f"landing_crank_angle_{wall}"][k] = np.degrees(
                from_firing_tdc(table[f"landing_crank_angle_{wall}"][k], origin)
            )
            table[f"landing_cylinder_{wall}"][k] = k
    cylinders, engine = table[1:], table[0]
    engine["skirt_fmep"] = np.mean(cylinders["skirt_fmep"])
    for name in ("impacts_per_cycle", "impact_energy_per_cycle", *(f"landings_per_cycle_{w}" for w in WALLS)):
        engine[name] = np.sum(cylinders[name])
    for wall in WALLS:
        energies = cylinders[f"landing_energy_{wall}"]
        if np.isfinite(energies).any():
            largest = cylinders[int(np.nanargmax(energies))]
            for what in ("landing_energy", "landing_loss", "landing_crank_angle", "landing_cylinder"):
                engine[f"{what}_{wall}"] = largest[f"{what}_{wall}"]
        else:
            for what in ("landing_energy", "landing_loss", "landing_crank_angle"):
                engine[f"{what}_{wall}"] = np.nan
    return np.concatenate([cylinders, table[:1]])


def text_table(table):
    """The summary as the terminal shows it: a line per cylinder and one for the engine."""
    energies = np.array([table[f"landing_energy_{w}"] for w in WALLS])
    factor, unit = energy_unit(np.max(energies[np.isfinite(energies)], initial=0.0))
    lines = [
        f"{'cylinder':>8} {'fires':>6} {'skirt FMEP':>10} {'impacts':>8} {'impact energy':>13}  "
        f"{'largest landing, major-thrust':>29}  {'largest landing, anti-thrust':>29}",
        f"{'':>8} {'[deg]':>6} {'[bar]':>10} {'/cycle':>8} {'[mJ/cycle]':>13}  "
        f"{f'[{unit} at deg, cylinder]':>29}  {f'[{unit} at deg, cylinder]':>29}",
    ]
    for row in table:
        name = str(row["cylinder"]) if row["cylinder"] else "engine"
        fires = "" if np.isnan(row["fires_after_cylinder_1"]) else f"{row['fires_after_cylinder_1']:.0f}"
        landings = [
            "none reported"
            if np.isnan(row[f"landing_energy_{w}"])
            else f"{row[f'landing_energy_{w}'] * factor:.3g} at {row[f'landing_crank_angle_{w}']:.1f}, "
            f"{row[f'landing_cylinder_{w}']}"
            for w in WALLS
        ]
        lines.append(
            f"{name:>8} {fires:>6} {row['skirt_fmep'] * 1e-5:>10.3g} {row['impacts_per_cycle']:>8.1f} "
            f"{row['impact_energy_per_cycle'] * 1e3:>13.3g}  {landings[0]:>29}  {landings[1]:>29}"
        )
    return "\n".join(lines)


def write(out, order, records, summary_table, units, origin):
    """`out/cylinder_K.csv` (each cylinder's record, `units` by name), `out/engine.csv` (the summary) and
    `out/side_forces.png`; returns the paths written."""
    import matplotlib.pyplot as plt

    written = [write_table(out / f"cylinder_{k}.csv", record, units) for k, record in enumerate(records, start=1)]
    written.append(write_table(out / "engine.csv", summary_table, SUMMARY))
    # The last whole cycle of cylinder 1 on the axis from `origin`, every cylinder's wall loads against it.
    angle = records[0]["engine_crank_angle"]
    end = np.floor((angle[-1] - origin) / CYCLE) * CYCLE + origin
    shown = (angle >= end - CYCLE) & (angle <= end)
    degrees = np.degrees(angle[shown] - end + CYCLE + origin)
    fig, axes = plt.subplots(
        len(order), 1, sharex=True, sharey=True, figsize=(9, 1.2 + 1.3 * len(order)), squeeze=False
    )
    for k, (ax, record, phase) in enumerate(zip(axes[:, 0], records, phases(order), strict=True), start=1):
        ax.plot(degrees, record["liner_force_thrust"][shown] * 1e-3, lw=1, color="C3", label="major-thrust wall")
        ax.plot(degrees, -record["liner_force_antithrust"][shown] * 1e-3, lw=1, color="C0", label="anti-thrust wall")
        for tdc in np.degrees(from_firing_tdc(phase, origin)) + np.array([0, 720]):  # one at either end of the axis
            ax.axvline(tdc, color="k", lw=0.8, ls="--")
        ax.set_ylabel(f"cylinder {k}\n[kN]")
    axes[0, 0].legend(fontsize="small", ncol=2, loc="upper right")
    axes[0, 0].set_title(
        f"Wall loads of each cylinder (anti-thrust negative), firing order {'-'.join(map(str, order))}; "
        "dashed: its firing TDC",
        fontsize="medium",
    )
    axes[-1, 0].set_xlabel("crank angle of cylinder 1 [deg]  (0 = its firing TDC)")
    axes[-1, 0].set_xlim(np.degrees(origin), np.degrees(origin) + 720)
    axes[-1, 0].set_xticks(np.arange(np.degrees(origin), np.degrees(origin) + 721, 90))
    fig.tight_layout()
    fig.savefig(out / "side_forces.png", dpi=120)
    plt.close(fig)
    return [*written, out / "side_forces.png"]


def record_units(model_description):
    """Units of a cylinder's record by column: PistonSlap's, the engine's crank angle and speed, the time."""
    units = {
        v.name: v.unit or (v.declaredType.unit if v.declaredType else None) for v in model_description.modelVariables
    }
    units.update(time="s", engine_crank_angle="rad", engine_crank_speed="rad/s")
    return {name: units.get(name) for name in (*COLUMNS, *RECORDED)}


def main(args, order, step, speed, engine, slap, origin, md):
    """`pistonslap coupled` with --cylinders or --firing-order, its arguments checked (`coupled.main`): runs the
    engine, prints the summary table, writes the files."""
    records, landings = run(order, args.cycles, step, speed, engine, slap, args.out, not args.held)
    table = summary(order, records, landings, args.cycles, origin)
    written = write(args.out, order, records, table, record_units(md), origin)
    print(
        f"{len(order)} cylinder{'s' * (len(order) > 1)}, firing order {'-'.join(map(str, order))}, "
        f"{len(records[0]) - 1} steps of {step:.3g} s; cycles {FIRST_REPORTED} to {args.cycles} of each cylinder:"
    )
    print(text_table(table))
    for path in [*written, *(args.out / f"cylinder_{k}_landing_log.csv" for k in range(1, len(order) + 1))]:
        print(f"wrote {path}")
