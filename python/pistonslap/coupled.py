"""`pistonslap coupled`: PistonSlap driven by its partner EngineCycle FMU through the master of `master.py`, one
cylinder or a whole engine (`cylinders.py`); `make coupled` writes `out/coupled/`.

The same system runs in Open Simulation Platform's libcosim from the OSP system structure file `OSP_SYSTEM`
(`run_libcosim`, inputs held): both masters give the same impacts at the same steps.
"""

import csv
from functools import partial
from pathlib import Path

import fmpy
import numpy as np

from . import cylinders
from .engine_cycle_presets import slap_geometry
from .firing_order import firing_order
from .fmu import CENTRED, CYCLE, FROM_FIRING_TDC, fmu_path, from_firing_tdc, read_impact_log
from .master import COLUMNS, ENGINE_FMU, run
from .presets import PRESETS as PISTON_PRESETS
from .progress import Progress
from .refusal import Parser, Refusal, check_start_values, number
from .settings import add_parameter_options, in_display_units, parse_set, read_params, to_fmu

#: The coupled system for libcosim: both FMUs, the two connections, pressure_source = 1, 1 ms fixed steps.
OSP_SYSTEM = Path(__file__).resolve().parent / "osp" / "OspSystemStructure.xml"

#: Coarsest communication step, in crank angle: over a step the gas pressure is held or follows the engine's slope,
#: so a coarser step moves the pressure peak against the piston's motion (a 360° step gives 2.5 times the impact
#: energy of 1 ms = 7.2° at 1200 rpm).
MAX_STEP_DEG = 10.0
#: The engine's speed of `pistonslap coupled` (EngineCycle's default), rad/s.
SPEED = 125.66


def run_libcosim(steps, osp_system=OSP_SYSTEM):
    """Runs the OSP system structure `osp_system` in libcosim (libcosimpy) for `steps` of its base step.

    Returns a structured array with PistonSlap's `impacts_in_step`, `impact_count` and `impact_energy_total` and
    EngineCycle's `crank_angle` after each step.
    """
    from libcosimpy.CosimExecution import CosimExecution
    from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
    from libcosimpy.CosimObserver import CosimObserver

    log_output_level(CosimLogLevel.ERROR)
    execution = CosimExecution.from_osp_config_file(str(osp_system))
    observer = CosimObserver.create_last_value()
    execution.add_observer(observer)
    slap, engine = execution.slave_index_from_instance_name("slap"), execution.slave_index_from_instance_name("engine")
    vr = {v.name: v.valueReference for v in fmpy.read_model_description(str(fmu_path())).modelVariables}
    engine_angle = next(
        v.valueReference for v in fmpy.read_model_description(str(ENGINE_FMU)).modelVariables if v.name == "crank_angle"
    )
    rows = np.zeros(
        steps,
        dtype=[
            ("impacts_in_step", "i8"),
            ("impact_count", "i8"),
            ("impact_energy_total", "f8"),
            ("engine_crank_angle", "f8"),
        ],
    )
    for k in range(steps):
        if not execution.step():
            raise RuntimeError(f"libcosim failed at step {k}")
        in_step, count = observer.last_integer_values(slap, [vr["impacts_in_step"], vr["impact_count"]])
        (energy,) = observer.last_real_values(slap, [vr["impact_energy_total"]])
        (angle,) = observer.last_real_values(engine, [engine_angle])
        rows[k] = (in_step, count, energy, angle)
    return rows


def energy_per_cycle(rows, first_cycle, last_cycle):
    """J: impact energy dissipated per engine cycle between the starts of two cycles (by PistonSlap's crank
    angle, at the first communication point at or after each start; the run's last point when it ends less than a
    step short of `last_cycle`). `ValueError` when the run does not reach `last_cycle`."""
    angle = rows["crank_angle"]
    if not first_cycle < last_cycle or last_cycle * CYCLE > angle[-1] + np.diff(angle).max():
        raise ValueError(
            f"cycles {first_cycle} to {last_cycle} are not within the run's {angle[-1] / CYCLE:.3g} cycles"
        )
    cycle = np.floor(angle / CYCLE)
    start = np.argmax(cycle >= first_cycle)
    end = np.argmax(cycle >= last_cycle) if cycle[-1] >= last_cycle else len(angle) - 1
    return (rows["impact_energy_total"][end] - rows["impact_energy_total"][start]) / (last_cycle - first_cycle)


def write(rows, out, origin=CENTRED, events=None, case="", synchronisation=False):
    """`out/coupled.csv` and the plots: pressure and impacts against crank angle from firing TDC (the axis from
    `origin`, rad: `CENTRED` -360...360°, or 0...720°), with `events` (the impact log) each impact coloured by its
    wall; with `synchronisation`, both FMUs' crank angles. Returns the paths written."""
    import matplotlib.pyplot as plt

    from .plots import SIDES

    out = Path(out)
    out.mkdir(parents=True, exist_ok=True)
    with open(out / "coupled.csv", "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(COLUMNS)
        writer.writerows(rows.tolist())
    written = [out / "coupled.csv", out / "pressure_and_impacts.png"]
    degrees = np.degrees(from_firing_tdc(rows["crank_angle"], origin))
    fig, (ax_p, ax_i) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
    fig.suptitle(
        f"PistonSlap driven by EngineCycle: {len(rows) - 1} steps of {rows['time'][1] - rows['time'][0]:g} s, "
        f"every cycle overlaid\n{case}",
        fontsize="medium",
    )
    # One line per engine cycle: broken where the angle wraps to the axis' start.
    wraps = np.flatnonzero(np.diff(degrees) < 0) + 1
    ax_p.plot(np.insert(degrees, wraps, np.nan), np.insert(rows["gas_pressure"] / 1e5, wraps, np.nan), lw=1)
    ax_p.set_ylabel("gas pressure (EngineCycle) [bar]")
    if events is None:
        hit = rows["impacts_in_step"] > 0
        ax_i.plot(degrees[hit], rows["max_impact_velocity_in_step"][hit], ".", ms=4)
        ax_i.set_ylabel("largest impact velocity in step [m/s]")
    else:
        impacts = events[events["kind"] == "impact"]
        for label, corners, colour in SIDES:
            mine = impacts[np.isin(impacts["corner"], corners)]
            angle = np.degrees(from_firing_tdc(mine["crank_angle"], origin))
            ax_i.plot(angle, mine["normal_velocity_before"], ".", ms=4, color=colour, label=f"{label}: {len(mine)}")
        ax_i.legend(fontsize="small", title="impacts, every cycle", title_fontsize="small")
        ax_i.set_ylabel("impact velocity [m/s]")
    ax_i.set_xlabel("crank angle [deg]  (0 = firing TDC)")
    ax_i.set_xlim(np.degrees(origin), np.degrees(origin) + 720)
    ax_i.set_xticks(np.arange(np.degrees(origin), np.degrees(origin) + 721, 90))
    fig.tight_layout()
    fig.savefig(out / "pressure_and_impacts.png", dpi=120)
    plt.close(fig)
    if not synchronisation:
        return written
    fig, (ax_a, ax_d) = plt.subplots(2, 1, sharex=True, figsize=(9, 6))
    ax_a.plot(rows["time"], rows["engine_crank_angle"], label="EngineCycle")
    ax_a.plot(rows["time"], rows["crank_angle"], "--", label="PistonSlap")
    ax_a.set_ylabel("crank angle [rad]")
    ax_a.legend()
    ax_d.plot(rows["time"], rows["crank_angle"] - rows["engine_crank_angle"])
    ax_d.set_ylabel("PistonSlap − EngineCycle [rad]")
    ax_d.set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(out / "crank_angles.png", dpi=120)
    plt.close(fig)
    return [*written, out / "crank_angles.png"]


#: PistonSlap's inputs and settings the engine drives: a preset's, a parameter file's or a --set's value of them is
#: not PistonSlap's to take.
DRIVEN = (
    "crank_speed",
    "gas_pressure",
    "pressure_source",
    "peak_pressure",
    "crank_mode",
    "load_torque",
    "crank_angle_start",
)
#: Default communication step: 1 ms, or this crank angle (1 ms at 1200 rpm) where 1 ms would be more, deg.
DEFAULT_STEP_DEG = 7.2


def _parser(presets):
    parser = Parser(prog="pistonslap coupled", description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", type=Path, default=Path("out/coupled"), help="output folder (default out/coupled)")
    parser.add_argument(
        "--cycles", type=int, default=20, help="engine cycles at the engine's constant speed, at least 3 (default 20)"
    )
    parser.add_argument(
        "--step",
        type=float,
        help=f"communication step, s (default 0.001, or {DEFAULT_STEP_DEG:g}° of crank angle where that is less; at "
        f"most {MAX_STEP_DEG:g}°; with --cylinders the largest step up to that dividing the firing interval 720°/N)",
    )
    parser.add_argument("--held", action="store_true", help="hold the inputs over each step (no derivatives)")
    parser.add_argument("--engine", help=f"EngineCycle preset: {', '.join(presets)} (default: the FMU's defaults)")
    parser.add_argument(
        "--piston",
        choices=PISTON_PRESETS,
        help="PistonSlap's engine preset for the piston, rod and clearance (the engine's bore, stroke and rod "
        "length win where --engine gives them; speed and pressure are the engine's)",
    )
    add_parameter_options(parser, "PistonSlap", "skirt_model=2 for the lubricated skirt, clearance=40um")
    parser.add_argument(
        "--cylinders",
        metavar="N",
        help="run a whole engine: N cylinders on one crank, each a PistonSlap and an EngineCycle instance, in one "
        "process; CSVs per cylinder, an engine summary and a plot (default: one cylinder)",
    )
    parser.add_argument(
        "--firing-order",
        metavar="1-3-4-2",
        help="the engine's firing order, cylinder 1 first, fired evenly every 720°/N (default for 1 to 6 cylinders "
        "the in-line engines' 1, 1-2, 1-2-3, 1-3-4-2, 1-2-4-5-3, 1-5-3-6-2-4)",
    )
    parser.add_argument(
        "--crank-0-720",
        action="store_true",
        help="draw the crank angle from 0 to 720° (default -360 to 360°; 0 = firing TDC either way)",
    )
    parser.add_argument(
        "--synchronisation",
        action="store_true",
        help="also plot both FMUs' crank angles and their difference (crank_angles.png), a check of the coupling",
    )
    return parser


def slap_start_values(args, engine, md):
    """PistonSlap's start values: the --piston preset, the geometry of the --engine preset, the parameter file and
    --set, in that order, without what the engine drives (`DRIVEN`)."""
    values = {k: v for k, v in PISTON_PRESETS[args.piston].values.items() if k not in DRIVEN} if args.piston else {}
    values.update(slap_geometry(engine) if args.engine else {})
    given = read_params(args.params, md) if args.params else {}
    given.update(parse_set(args.set, md))
    driven = sorted(set(given) & set(DRIVEN))
    if driven:
        raise Refusal(
            f"{', '.join(driven)}: the engine drives PistonSlap's crank and pressure; set them in EngineCycle"
        )
    values.update(given)
    defaults = {v.name: float(v.start) for v in md.modelVariables if v.type == "Real" and v.start is not None}
    return to_fmu(values, dict(defaults, **values))


def main(argv=None):
    from .engine_cycle_presets import PRESETS

    args = _parser(PRESETS).parse_args(argv)
    whole_engine = args.cylinders is not None or args.firing_order is not None
    order = firing_order(args.cylinders, args.firing_order) if whole_engine else None
    if whole_engine and args.synchronisation:
        raise Refusal("--synchronisation checks the one-cylinder run: leave it out with --cylinders")
    if args.engine is not None and args.engine not in PRESETS:
        raise Refusal(f"unknown --engine {args.engine!r} (presets: {', '.join(PRESETS)})")
    if args.cycles < 3:
        raise Refusal(f"--cycles = {args.cycles}: give at least 3 (the energy per cycle is counted after two)")
    if args.out.exists() and not args.out.is_dir():
        raise Refusal(f"--out {args.out}: is a file; give a folder (new or existing) for the results")
    engine = PRESETS[args.engine]["engine"] if args.engine else {}
    speed = engine.get("speed_start", SPEED)
    largest = np.radians(MAX_STEP_DEG) / speed
    step = min(1e-3, np.radians(DEFAULT_STEP_DEG) / speed) if args.step is None else args.step
    if whole_engine and args.step is None:
        step = cylinders.fitted_step(step, order, speed)
    number(step, "--step", low=0, low_open=True, unit=" s", meaning="the communication step")
    if step > largest:
        raise Refusal(
            f"--step = {step:g} s is {np.degrees(step * speed):.3g}° of crank angle at "
            f"{speed * 30 / np.pi:.0f} rpm: give at most {largest:.3g} s ({MAX_STEP_DEG:g}°), since over a "
            "step the gas pressure only follows its value and slope at the step's start"
        )
    md = fmpy.read_model_description(str(fmu_path()))
    slap = slap_start_values(args, engine, md)
    shown = partial(in_display_units, model_description=md)
    check_start_values({**slap, "pressure_source": 1, "crank_speed": speed}, fmu_path(), md, shown=shown)
    period = CYCLE / speed
    stop = round(args.cycles * period / step) * step
    origin = FROM_FIRING_TDC if args.crank_0_720 else CENTRED
    p = dict({v.name: float(v.start) for v in md.modelVariables if v.type == "Real" and v.start}, **slap)
    case = (
        f"engine {args.engine or 'EngineCycle defaults'} at {speed * 30 / np.pi:.0f} rpm; piston "
        f"{args.piston or 'PistonSlap defaults'}: clearance {(p['bore'] - p['piston_diameter']) * 1e6:g} µm, "
        f"e = {p['restitution']:g}, {'lubricated skirt' if p.get('skirt_model') == 2 else 'dry skirt'}"
    )
    print(case)
    args.out.mkdir(parents=True, exist_ok=True)
    if whole_engine:
        return cylinders.main(args, order, step, speed, engine, slap, origin, md)
    log = args.out / "impact_log.csv"
    progress = Progress("pistonslap coupled: simulating", stop)
    rows = run(
        stop,
        step,
        engine_values=engine,
        slap_values={**slap, "impact_log": str(log)},
        derivatives=not args.held,
        step_finished=progress,
    )
    progress.done()
    written = write(rows, args.out, origin, read_impact_log(log), case, args.synchronisation)
    print(
        f"{len(rows) - 1} steps of {step:.3g} s, {int(rows['impact_count'][-1])} impacts, "
        f"{energy_per_cycle(rows, 2, args.cycles):.4g} J per cycle after two cycles"
    )
    for path in [*written, log]:
        print(f"wrote {path}")
