"""Simulates one operating point of the FMU through fmpy and writes CSVs and plots of its last engine cycle.

    pistonslap demo [--engine NAME] [--params FILE.toml] [--set NAME=VALUE ...] [--pressure-trace FILE]
                    [--firing-tdc DEG] [--friction MU] [--out DIR] [--rpm RPM] [--peak-pressure BAR] [--clearance UM]
                    [--restitution E] [--pin-offset MM] [--cycles N] [--slap-threshold MM_PER_S] [--crank-0-720]
                    [--skirt-map DEG] [--liner-loads FILE.csv [--liner-load-step DEG] [--liner-load-spectrum]]
                    [--plots LIST] [--no-gif]

Values apply in that order, a later one over an earlier one: the engine preset, the parameter file, then the options.
What none sets keeps the FMU's default (Awrejcewicz & Kudra's engine: 1200 rpm, 80 bar, 80 µm, e = 0.5).
"""

import multiprocessing
import os
import shutil
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor
from functools import partial
from pathlib import Path

import fmpy
import numpy as np

from . import liner_load
from .cycle_figures import SETTLED, change, cycle_before, figures
from .fmu import CENTRED, CYCLE, FROM_FIRING_TDC, fmu_path, last_cycle, simulate_with_logs
from .presets import PRESETS, help_text
from .progress import Progress
from .refusal import Parser, Refusal, check_start_values, number
from .settings import add_parameter_options, in_display_units, parse_set, read_params, to_fmu, within_range
from .tables import LANDING_RUN_ON, SAMPLE_DEG, WALLS, cycle_metrics, energy_unit, slap_rows, write_table
from .trace_tdc import PlacedTrace

#: Magnification of clearance and tilt in the piston-position pictures.
MAGNIFICATION = 200
#: The plots `--plots` may name, costliest first (the order `draw` takes them in), and those drawn by default (the
#: animation takes most of a run's time).
PLOTS = ("gif", "positions", "slap", "motion", "film", "forces")
DEFAULT_PLOTS = ("slap", "forces", "motion", "positions", "film")


def _parser():
    parser = Parser(prog="pistonslap demo", description=__doc__.splitlines()[0])
    parser.add_argument("--engine", choices=PRESETS, help=f"engine preset: {help_text()}")
    add_parameter_options(parser, "FMU", "crank_speed=3000rpm, peak_pressure=90bar, bore=80.08mm")
    parser.add_argument(
        "--pressure-trace",
        type=Path,
        help="cylinder pressure over 720°: a CSV or text export (',', ';' or tab apart; units in [..], (..) or a row "
        "under the header; absolute unless the header says gauge); a bare name not in the working directory is "
        "looked up in the FMU's resources (full_load.csv, motored.csv)",
    )
    parser.add_argument(
        "--firing-tdc",
        type=float,
        metavar="DEG",
        help="firing TDC in the --pressure-trace's angles (default: the TDC, a multiple of 360°, nearest its peak)",
    )
    parser.add_argument("--friction", type=float, help="Coulomb friction coefficient at the liner (default 0)")
    parser.add_argument("--out", type=Path, default=Path("out"), help="output folder (default: out)")
    parser.add_argument("--rpm", type=float, help="crank speed, rpm (default 1200)")
    parser.add_argument("--peak-pressure", type=float, help="peak of the built-in gas pressure curve, bar (default 80)")
    parser.add_argument("--clearance", type=float, help="diametral clearance bore - piston diameter, µm (default 80)")
    parser.add_argument("--restitution", type=float, help="coefficient of restitution (default 0.5)")
    parser.add_argument("--pin-offset", type=float, help="pin offset toward the major-thrust side, mm (default 0)")
    parser.add_argument("--cycles", type=int, default=2, help="engine cycles (720° each) to simulate (default 2)")
    parser.add_argument(
        "--crank-0-720",
        action="store_true",
        help="draw the crank angle from 0 to 720° (default -360 to 360°; 0 = firing TDC either way)",
    )
    parser.add_argument(
        "--slap-threshold", type=float, help="impacts faster than this count as slaps, mm/s (default 10)"
    )
    parser.add_argument(
        "--skirt-map",
        type=float,
        metavar="DEG",
        help="lubricated skirt (skirt_model = 2): map its film pressure at this crank angle (0 = firing TDC) of the "
        "last cycle into skirt_map.csv and skirt_map.png",
    )
    parser.add_argument(
        "--liner-loads",
        type=Path,
        metavar="FILE.csv",
        help="write the liner's load for a structural model into this CSV: per wall the force, the mean force over "
        "each interval (impacts included), its point of application below the skirt top and moment, sampled every "
        "--liner-load-step over the cycles simulated (a second run, at that step)",
    )
    parser.add_argument(
        "--liner-load-step",
        type=float,
        metavar="DEG",
        help="crank angle between the liner-load samples, deg, dividing 720° "
        f"(default {liner_load.DEFAULT_STEP_DEG:g})",
    )
    parser.add_argument(
        "--liner-load-spectrum",
        action="store_true",
        help="also plot the liner load's spectrum in engine orders and third-octave bands (FILE_spectrum.png)",
    )
    parser.add_argument(
        "--plots",
        default=",".join(DEFAULT_PLOTS),
        metavar="LIST",
        help=f"the plots to draw, comma-separated, of {', '.join(PLOTS)} (film on oil only), 'all' or 'none' "
        f"(default {','.join(DEFAULT_PLOTS)}: gif, the animated piston positions, takes seconds more)",
    )
    parser.add_argument("--no-gif", action="store_true", help="draw no animation, whatever --plots says")
    return parser


def plots_asked(args):
    """The plots to draw, of `PLOTS`."""
    text = args.plots.strip().lower()
    asked = PLOTS if text == "all" else () if text == "none" else tuple(w.strip() for w in text.split(",") if w.strip())
    unknown = [w for w in asked if w not in PLOTS]
    if unknown:
        raise Refusal(
            f"--plots {args.plots}: no plot {', '.join(unknown)}; give some of {', '.join(PLOTS)}, all or none"
        )
    return tuple(w for w in asked if not (args.no_gif and w == "gif"))


def check(args):
    """Refuses options no run can take before anything runs (the FMU checks the rest, `check_start_values`)."""
    if args.rpm is not None:
        number(args.rpm, "--rpm", low=0, low_open=True, unit=" rpm", meaning="the crank speed")
    if args.clearance is not None:
        number(
            args.clearance,
            "--clearance",
            low=0,
            low_open=True,
            unit=" µm",
            meaning="the diametral clearance c = D − d (bore minus piston diameter)",
        )
    if args.cycles < 1:
        raise Refusal(f"--cycles = {args.cycles}: give a whole number of engine cycles >= 1")
    if args.out.exists() and not args.out.is_dir():
        raise Refusal(f"--out {args.out}: is a file; give a folder (new or existing) for the results")
    plots_asked(args)
    if args.skirt_map is not None:
        number(
            args.skirt_map,
            "--skirt-map",
            low=-360,
            high=720,
            unit="°",
            meaning="the crank angle of the skirt map, within the cycle from firing TDC (-360…360° or 0…720°),",
        )
    if args.liner_loads is None and (args.liner_load_step is not None or args.liner_load_spectrum):
        raise Refusal("--liner-load-step and --liner-load-spectrum go with --liner-loads FILE.csv: give the file")
    if args.liner_loads is not None:
        if args.liner_loads.suffix.lower() != ".csv":
            raise Refusal(f"--liner-loads {args.liner_loads}: give a .csv file name")
        liner_load.samples_per_cycle(liner_load_step(args), "--liner-load-step")
    same_as_set(args)
    if args.firing_tdc is not None:
        if args.pressure_trace is None:
            raise Refusal("--firing-tdc places the firing TDC of a --pressure-trace: give the trace")
        number(args.firing_tdc, "--firing-tdc", unit="°", meaning="firing TDC")


def liner_load_step(args):
    """The liner-load sampling step asked for, deg."""
    return liner_load.DEFAULT_STEP_DEG if args.liner_load_step is None else args.liner_load_step


def all_start_values(args, md, defaults):
    """The start values (SI) of the preset, the parameter file, the options and --set, in that order, and the
    pressure trace to run (`trace_tdc.PlacedTrace`, or None)."""
    values = dict(PRESETS[args.engine].values) if args.engine else {}
    if args.params:
        values.update(read_params(args.params, md))
    values.update(start_values(args, dict(defaults, **values), md))
    if args.pressure_trace is not None:
        values.update(pressure_source=3, pressure_trace=str(args.pressure_trace))
    if args.friction is not None:
        values["friction"] = number(args.friction, "--friction", low=0, meaning="the friction coefficient")
    values.update(parse_set(args.set, md))
    if args.skirt_map is not None:
        values.update(
            skirt_map=str((args.out / SKIRT_MAP_PASSES).resolve()),
            skirt_map_crank_angle=np.radians(args.skirt_map % 720),
        )
    values = to_fmu(values, defaults)
    trace = values.get("pressure_trace") if values.get("pressure_source") == 3 else None
    return values, PlacedTrace(trace, args.firing_tdc, fmu_path()) if trace else None


#: The operating-point options: (option, the variable it sets, its unit, SI per unit).
OPTIONS = (
    ("rpm", "crank_speed", "rpm", np.pi / 30),
    ("peak_pressure", "peak_pressure", "bar", 1e5),
    ("clearance", "clearance", "µm", 1e-6),
    ("restitution", "restitution", "", 1.0),
    ("pin_offset", "pin_offset", "mm", 1e-3),
    ("slap_threshold", "slap_threshold", "", 1e-3),
    ("friction", "friction", "", 1.0),
)


def start_values(args, defaults, md):
    """FMU start values (SI) for the operating-point options given, each within its variable's declared range;
    `defaults` are the start values so far."""
    values = {}
    for option, name, unit, si in OPTIONS:
        typed = getattr(args, option)
        if typed is not None and option != "friction":
            where = f"--{option.replace('_', '-')} {typed:g}"
            values[name] = within_range(name, typed * si, md, where, (typed, unit) if unit else None)
    if "clearance" in values:
        values["bore"] = defaults["piston_diameter"] + values.pop("clearance")
    return values


def same_as_set(args):
    """Refuses an operating-point option and a --set of the same variable (or of the bore and the clearance)."""
    named = {a.partition("=")[0].strip() for a in args.set}
    for option, name, _, _ in OPTIONS:
        said = named & ({"bore", "clearance"} if name == "clearance" else {name})
        if getattr(args, option) is not None and said:
            raise Refusal(f"--{option.replace('_', '-')} and --set {said.pop()}=... say the same thing: give one")


def case_title(p, trace_name=None):
    """The operating point in the words of an engine test sheet; `p` holds every parameter by name (SI),
    `trace_name` names the pressure trace as the user gave it (default: the file's name)."""
    pressure = (
        f"pressure trace {trace_name or Path(p['pressure_trace']).name}"
        if p.get("pressure_source") == 3
        else f"peak pressure {p['peak_pressure'] * 1e-5:g} bar"
    )
    return (
        f"{p['crank_speed'] * 30 / np.pi:.0f} rpm, {pressure}, "
        f"clearance {(p['bore'] - p['piston_diameter']) * 1e6:g} µm, e = {p['restitution']:g}, "
        f"pin offset {p['pin_offset'] * 1e3:g} mm, slap threshold {p['slap_threshold'] * 1e3:g} mm/s"
    )


def summary(row, lubricated):
    """The cycle drawn in words: slaps (side changes) per wall with their energy, then all impacts; the
    landings per wall (the largest one's energy, its loss and crank angle) and the wall loads' peak and rise rate; the
    skirt FMEP and, on oil (`lubricated`), the thinnest film per side and the peak film and asperity loads. `row` is
    the last row of `tables.cycle_metrics` by column name, its slaps and impacts those of the cycle drawn
    (`cycle_figures.figures`)."""
    mj = 1e3
    walls = "; ".join(
        f"{row[f'cycle_slaps_{side}']} on the {name} wall, {row[f'cycle_slap_energy_{side}'] * mj:.3g} mJ "
        f"(largest {row[f'cycle_max_slap_energy_{side}'] * mj:.3g} mJ)"
        for side, name in zip(WALLS, WALL_NAMES, strict=True)
    )
    text = (
        f"The cycle drawn: {row['cycle_slap_events']} slaps (landings on the other wall): {walls}. "
        f"{row['cycle_impacts']} impacts (every bounce) dissipated {row['cycle_impact_energy'] * mj:.3g} mJ, "
        f"the largest {row['cycle_max_impact_energy_thrust'] * mj:.3g} mJ on the major-thrust wall and "
        f"{row['cycle_max_impact_energy_antithrust'] * mj:.3g} mJ on the anti-thrust wall."
    )
    landings = "; ".join(_landings(row, side, name) for side, name in zip(WALLS, WALL_NAMES, strict=True))
    text += f"\nLandings in the cycle from −360° to 360° about the last firing TDC: {landings}."
    text += f"\nSkirt friction: FMEP {row['cycle_skirt_fmep'] * 1e-5:.3g} bar"
    if lubricated:
        films = ", ".join(
            f"{row[f'cycle_min_film_thickness_{side}'] * 1e6:.3g} µm on the {name} side at "
            f"{np.degrees(row[f'cycle_min_film_crank_angle_{side}']):.1f}°"
            for side, name in zip(WALLS, WALL_NAMES, strict=True)
        )
        text += (
            f"; thinnest film {films}; peak film force {row['cycle_max_film_force'] * 1e-3:.3g} kN, peak asperity "
            f"load {row['cycle_max_asperity_force'] * 1e-3:.3g} kN"
        )
    return text + "."


#: The walls in words, in the order of `tables.WALLS`.
WALL_NAMES = ("major-thrust", "anti-thrust")


def _landings(row, side, name):
    """One wall's landings in words (see `summary`)."""
    count = row[f"cycle_landings_{side}"]
    if np.isnan(count):
        return f"the {name} wall's not complete when the run ended (its last landing had not ended)"
    count = int(count)
    peaks = (
        f"wall load peak {row[f'cycle_max_liner_force_{side}'] * 1e-3:.3g} kN, rising at most "
        f"{row[f'cycle_max_liner_force_rate_{side}'] * 1e-6:.3g} kN/ms"
    )
    if count == 0:
        return f"none on the {name} wall, {peaks}"
    energy, loss = row[f"cycle_landing_energy_{side}"], row[f"cycle_landing_loss_{side}"]
    factor, unit = energy_unit(max(energy, loss))
    return (
        f"{count} on the {name} wall, the largest at {np.degrees(row[f'cycle_landing_crank_angle_{side}']):.1f}° "
        f"with {energy * factor:.3g} {unit} of lateral kinetic energy, the landing took {loss * factor:.3g} {unit}; "
        f"{peaks}"
    )


def main(argv=None):
    started = time.monotonic()
    args = _parser().parse_args(argv)
    check(args)
    asked = plots_asked(args)
    if asked or args.skirt_map is not None or args.liner_load_spectrum:
        try:
            from . import plots, skirt_map
        except ImportError as e:
            raise Refusal(f"pistonslap demo plots with matplotlib ({e}): pip install 'pistonslap[plot]'") from e
    else:
        plots = skirt_map = None
    md = fmpy.read_model_description(str(fmu_path()))
    defaults = {v.name: float(v.start) for v in md.modelVariables if v.type == "Real" and v.start is not None}
    values, trace = all_start_values(args, md, defaults)
    p = dict(defaults, **values)
    check_speed(p)
    check_liner_loads(args, p)
    # Checked before anything is written: the trace goes to a scratch folder, the skirt map to the null device.
    with tempfile.TemporaryDirectory() as scratch:
        checked = dict(values, skirt_map=os.devnull) if "skirt_map" in values else dict(values)
        if trace:
            checked["pressure_trace"] = trace.write(scratch)
        check_start_values(checked, fmu_path(), md, shown=partial(in_display_units, model_description=md))
    args.out.mkdir(parents=True, exist_ok=True)
    if trace:
        values["pressure_trace"] = trace.write(args.out)
    omega, origin = p["crank_speed"], FROM_FIRING_TDC if args.crank_0_720 else CENTRED
    interval = np.radians(SAMPLE_DEG) / omega
    # The cycle drawn ends at `drawn_end`: the one about the last firing TDC on the axis centred on firing TDC, the
    # one ending at it on the 0…720° axis. The run goes on past the cycle about the last firing TDC until the FMU
    # completed its landing figures (the next landing started), by LANDING_RUN_ON at most: no other cycle completes.
    drawn_end, landed_by = (args.cycles * CYCLE - origin) / omega, (args.cycles * CYCLE - CENTRED) / omega
    stop_time = landed_by + LANDING_RUN_ON / omega + interval

    progress = Progress("pistonslap demo: simulating", stop_time)
    simulating = time.monotonic()
    result, events, landings = simulate_with_logs(
        log_path=args.out / "impact_log.csv",
        landing_log_path=args.out / "landing_log.csv",
        start_values=values,
        stop_time=stop_time,
        output_interval=interval,
        landed_by=landed_by,
        # the FMU rewrites the skirt map at each pass: the drawn cycle's is the last one by its end
        at_times=[(drawn_end, lambda: keep_skirt_map(args.out))] if args.skirt_map is not None else (),
        step_finished=progress,
    )
    progress.done()
    simulated = time.monotonic() - simulating
    lubricated = p.get("skirt_model") == 2
    per_cycle = cycle_metrics(result, landings)
    case = case_title(p, trace.trace.name if trace else None)
    units = {v.name: v.unit or (v.declaredType.unit if v.declaredType else None) for v in md.modelVariables}
    units["time"] = "s"
    written = [
        write_table(args.out / "demo.csv", result, units),
        args.out / "impact_log.csv",
        args.out / "landing_log.csv",
        write_table(args.out / "cycles.csv", *per_cycle),
    ]
    if trace:
        written.append(Path(values["pressure_trace"]))

    cycle, angle = last_cycle(result["crank_angle"], origin=origin)
    times = result["time"][cycle]
    window = in_window(events["time"], times)
    in_cycle = events[window]
    geometry = (p["bore"], p["piston_diameter"], p["skirt_length"], p["pin_height"])
    half_clearance = (p["bore"] - p["piston_diameter"]) / 2
    drawn = {
        "motion": lambda: plots.piston_motion(
            angle[cycle], result[cycle], half_clearance, args.out / "piston_motion.png", case, origin, lubricated
        ),
        "slap": lambda: plots.slap(
            in_cycle,
            slap_rows(events, p["slap_threshold"])[window],
            p["slap_threshold"],
            args.out / "slap.png",
            case,
            origin,
            landings=landings[in_window(landings["time"], times)],
            loads=(angle[cycle], result[cycle]),
            lubricated=lubricated,
        ),
        "forces": lambda: plots.forces(angle[cycle], result[cycle], args.out / "forces.png", case, origin),
        "positions": lambda: plots.piston_positions(
            angle[cycle],
            result[cycle],
            in_cycle,
            geometry,
            MAGNIFICATION,
            args.out / "piston_positions.png",
            case,
            origin=origin,
        ),
        "gif": lambda: plots.piston_animation(
            angle[cycle],
            result[cycle],
            in_cycle,
            geometry,
            MAGNIFICATION,
            args.out / "piston_positions.gif",
            case,
            origin=origin,
        ),
        "film": lambda: plots.film(angle[cycle], result[cycle], args.out / "film.png", case, origin),
    }
    written += draw([name for name in PLOTS if name in asked and (lubricated or name != "film")], drawn)
    if args.skirt_map is not None:
        (args.out / SKIRT_MAP_PASSES).unlink(missing_ok=True)
        written += [
            args.out / "skirt_map.csv",
            skirt_map.plot(skirt_map.read(args.out / "skirt_map.csv"), args.out / "skirt_map.png", case),
        ]
    print(operating_point(args, case, trace))
    drawn_figures = figures(events, window, p["slap_threshold"])
    table = per_cycle[0]
    last = table[-1].tolist() if len(table) else [np.nan] * len(table.dtype.names)
    print(
        f"{args.cycles} cycle{'' if args.cycles == 1 else 's'} simulated to t = {result['time'][-1]:g} s in "
        f"{simulated:.1f} s ({fmu_path().name}). "
        + summary(dict(zip(table.dtype.names, last, strict=True), **drawn_figures), lubricated)
    )
    print(settling(result, events, cycle, origin, drawn_figures, p["slap_threshold"]))
    if lubricated and (warning := relaxation(result)):
        print(warning)
    if args.liner_loads is not None:
        written += write_liner_loads(args, values, omega, origin, case, plots)
    for path in written:
        print(f"wrote {path}")
    print(f"done in {time.monotonic() - started:.1f} s, of which the simulation {simulated:.1f} s")


def settling(result, events, cycle, origin, drawn_figures, slap_threshold):
    """The main figures' change from the cycle before the drawn one (`cycle`, a mask of the samples), with a warning
    when they have not settled or the run holds no whole cycle before it."""
    before = cycle_before(result["crank_angle"], cycle, origin)
    if before is None:
        turned = (result["crank_angle"][-1] - result["crank_angle"][0]) / CYCLE
        return (
            f"Warning: the run holds no whole cycle before the one drawn (the crank turned {turned:.2g} engine "
            "cycles), whose figures may hold the start-up transient: give more --cycles to see whether they settled."
        )
    line, moved = change(
        drawn_figures, figures(events, in_window(events["time"], result["time"][before]), slap_threshold)
    )
    if moved:
        line += (
            f"\nWarning: not settled: the {', '.join(moved)} changed by more than {SETTLED:.0%} from the cycle before; "
            "give more --cycles."
        )
    return line


#: The share of the film's dissipation beyond which the work of its relaxation term says film_relaxation is too long.
RELAXATION_SHARE = 0.01


def relaxation(result):
    """A warning when the film's relaxation term did more work than `RELAXATION_SHARE` of the film's dissipation: the
    film then acts on the motion too late for the design (its damping at the rates film_relaxation ahead)."""
    work, film = result["film_relaxation_work"][-1], result["film_energy_total"][-1]
    if abs(work) <= RELAXATION_SHARE * abs(film):
        return None
    return (
        f"Warning: the film's relaxation term did {work:.3g} J of work beside the {film:.3g} J the film dissipated: "
        "its force lags the motion too much for this design; lower film_relaxation."
    )


#: The plots being drawn by `draw`, which its forked processes inherit.
_DRAWING = {}


def _draw_one(name):
    return _DRAWING[name]()


def draw(names, drawing):
    """Draws the plots `names` of `drawing` (name → a function drawing it and returning its path) and returns their
    paths, in that order: in two forked processes where the machine has two cores (matplotlib draws on one)."""
    if len(names) < 2 or (os.cpu_count() or 1) < 2 or "fork" not in multiprocessing.get_all_start_methods():
        return [drawing[name]() for name in names]
    _DRAWING.clear()
    _DRAWING.update(drawing)
    try:
        with ProcessPoolExecutor(2, mp_context=multiprocessing.get_context("fork")) as pool:
            return list(pool.map(_draw_one, names))
    finally:
        _DRAWING.clear()


def operating_point(args, case, trace):
    """The run's first line: the engine, where its values came from, the operating point, and the trace's reading."""
    engine = f"engine {args.engine}" if args.engine else "engine: the FMU's defaults (Awrejcewicz & Kudra)"
    sources = [f"parameters {args.params}"] if args.params else []
    sources += ["--set " + " ".join(args.set)] if args.set else []
    line = f"{engine}{' with ' + ', '.join(sources) if sources else ''}; {case}"
    return line + (f"\n{trace.said}" if trace else "")


def check_speed(p):
    """Refuses a crank speed the demo cannot sample at (`p`: every start value, SI): it samples in crank angle."""
    if not p["crank_speed"] > 0:
        raise Refusal(
            f"crank_speed = {p['crank_speed'] * 30 / np.pi:g} rpm: the demo samples the cycle in crank angle; give a "
            "crank speed > 0 (crank_speed=1200rpm)"
        )


#: The file the FMU rewrites at each pass of the skirt map's crank angle; `keep_skirt_map` copies the drawn cycle's.
SKIRT_MAP_PASSES = "skirt_map_passes.csv"


def keep_skirt_map(out):
    """Keeps the skirt map of the last pass so far as skirt_map.csv in `out` (the FMU's file goes when the run
    ends)."""
    passes = out / SKIRT_MAP_PASSES
    if passes.exists():
        shutil.copyfile(passes, out / "skirt_map.csv")


def in_window(time, times):
    """Which of the instants `time` lie within the sampled instants `times` (from the first to the last)."""
    return (time >= times[0]) & (time <= times[-1])


def check_liner_loads(args, p):
    """Refuses --liner-loads where the load cannot be sampled uniformly in crank angle (`p`: every start value)."""
    if args.liner_loads is None:
        return
    if p.get("model_variant", 1) != 1:
        raise Refusal("--liner-loads: the liner loads are the crank train's (model_variant = 1)")
    if p.get("crank_mode", 1) != 1:
        raise Refusal(
            "--liner-loads samples at a fixed crank-angle step, which needs the prescribed crank speed (crank_mode = 1)"
        )


def write_liner_loads(args, values, omega, origin, case, plots):
    """Runs the FMU again at the --liner-load-step and writes the --liner-loads file (and, with
    --liner-load-spectrum, its spectrum's plot beside it); returns the paths written."""
    table, units = liner_load.liner_loads(values, args.cycles, liner_load_step(args), origin)
    args.liner_loads.parent.mkdir(parents=True, exist_ok=True)
    written = [write_table(args.liner_loads, table, units)]
    if args.liner_load_spectrum:
        spectrum = args.liner_loads.with_name(f"{args.liner_loads.stem}_spectrum.png")
        written.append(plots.liner_load_spectrum(table, omega, spectrum, case))
    return written


if __name__ == "__main__":
    main()
