"""Farahanchi's roller slider crank (model_variant 2) analysed as in the thesis, chapters 2-4.

    python -m pistonslap.analysis case --lam 0.05 --rho 0.015 [--e 0.9] [--forcing 1] [--cycles 1500] --out DIR
    python -m pistonslap.analysis forces --forces-tool EXE --out DIR      constraint forces (Figs 2.4-2.9) and sliding
        regions (Fig 2.10); EXE is the crate's `roller_forces` example (`cargo build --release --example roller_forces`
        puts it in target/release/examples/)
    python -m pistonslap.analysis thesis [--workers N | --scheduler ADDRESS] --out DIR      chapter 4: the 20 runs
        from each starting crank angle (the other starts swept on Dask into DIR/sweeps), summary table, figure sheets
    python -m pistonslap.analysis crosscheck [--clearance M ...]   variant 1 in the roller limit vs variant 2

The FMU runs in the thesis's units: rod_length = 1 m, piston_mass = 1 kg and crank_speed = 1 rad/s make its
parameters the thesis's xi, alpha, beta, lambda (damping_crank_pin) and rho ((bore - piston_diameter)/2), and
time the crank angle. Every impact comes from the impact log; its normal speed v (m/s) is the thesis's relative
rate |psi' - psi_wall'| times l*Lambda*Omega, from which psi' at impact is recovered.
"""

import csv
import itertools
import os
import subprocess
import sys
from pathlib import Path

import fmpy
import numpy as np
import pyarrow.parquet as pq

from .fmu import fmu_path, simulate_with_events
from .refusal import Parser, Refusal, check_start_values, number
from .response import ALPHA, BETA, CHAOTIC_TRANSIENT, CRANK_CYCLE, XI, Response, Run, classify, impacts_from_log

#: Piston diameter of the thesis runs; the bore adds the clearance 2*rho (only their difference matters).
_DIAMETER = 0.08

#: The thesis's classification of its chapter-4 runs (section 4.3, 4.4): (lambda, rho, e) -> response;
#: None where the thesis shows the impact profile but does not name the response type.
THESIS_RESPONSES = {
    (0.025, 0.010, 0.9): "transient chaos",
    (0.025, 0.015, 0.9): "transient chaos",
    (0.025, 0.020, 0.9): "chaos",
    (0.050, 0.010, 0.9): "chaos",
    (0.050, 0.015, 0.9): "periodic",
    (0.050, 0.020, 0.9): "chaos",
    (0.075, 0.010, 0.9): "transient chaos",
    (0.075, 0.015, 0.9): "chaos",
    (0.075, 0.020, 0.9): "chaos",
    (0.15, 0.010, 0.9): None,
    (0.15, 0.015, 0.9): None,
    (0.15, 0.020, 0.9): None,
    (0.20, 0.010, 0.9): None,
    (0.20, 0.015, 0.9): "chaos",
    (0.20, 0.020, 0.9): None,
    (0.25, 0.010, 0.9): "periodic",
    (0.25, 0.015, 0.9): "periodic",
    (0.25, 0.020, 0.9): "periodic",
    (0.050, 0.020, 0.7): "transient chaos",
    (0.050, 0.020, 0.5): "periodic",
}


def thesis_start_values(lam, rho, e, forcing=1, start=0.0):
    """FMU start values that make the run the thesis's (lambda, rho, e) with roller_forcing = `forcing`,
    from psi = psi' = 0 at crank angle `start`."""
    return {
        "model_variant": 2,
        "roller_forcing": forcing,
        "crank_mode": 1,
        "crank_radius": XI,
        "rod_length": 1.0,
        "rod_mass": ALPHA,
        "piston_mass": 1.0,
        "rod_inertia": BETA,
        "damping_crank_pin": lam,
        "piston_diameter": _DIAMETER,
        "bore": _DIAMETER + 2 * rho,
        "restitution": e,
        "crank_angle_start": start,
        "crank_speed": 1.0,
    }


def _progress_printer(label, stop_time):
    """fmpy step_finished callback printing the percentage done, every 10 %."""
    state = {"next": 0.1}

    def step_finished(time, recorder):
        if time >= state["next"] * stop_time:
            done = time >= 0.999 * stop_time
            print(f"\r{label}: {100 * time / stop_time:3.0f} %", end="\n" if done else "", file=sys.stderr, flush=True)
            state["next"] += 0.1
        return True

    return step_finished


def simulate_case(lam, rho, e, forcing=1, cycles=1530, progress=True, log_path=None, start=0.0):
    """Runs the FMU for `cycles` crank cycles from psi = psi' = 0 at crank angle `start` and returns the `Run`
    (crank cycle k is theta in [2 pi k, 2 pi (k + 1)); the partial last one is not counted)."""
    stop_time = cycles * CRANK_CYCLE
    label = f"lambda={lam} rho={rho} e={e}"
    _, events = simulate_with_events(
        log_path=log_path,
        start_values=thesis_start_values(lam, rho, e, forcing, start),
        stop_time=stop_time,
        output_interval=CRANK_CYCLE,
        output=["impact_count"],
        step_finished=_progress_printer(label, stop_time) if progress else None,
    )
    return Run(lam=lam, rho=rho, e=e, forcing=forcing, cycles=cycles, **impacts_from_log(events, rho, start))


def _per_wall_sums(run, first_cycle, values, edges):
    """Per bin of `values` (one per impact), the sum of |psi'| of each wall's impacts from `first_cycle` on,
    over the total number N of those impacts (both walls): (upper, lower), both >= 0."""
    mask = run.window(first_cycle)
    total = max(int(mask.sum()), 1)
    sums = [
        np.histogram(
            values[mask & (run.wall == wall)], bins=edges, weights=np.abs(run.rate[mask & (run.wall == wall)])
        )[0]
        / total
        for wall in (1, -1)
    ]
    return sums[0], sums[1]


def impact_profile(run, first_cycle, bins=40):
    """Eq 3.6 over j bins of the impact location x in [1 - xi, 1 + xi]: (bin edges, upper profile >= 0,
    lower profile <= 0)."""
    edges = np.linspace(1 - XI, 1 + XI, bins + 1)
    upper, lower = _per_wall_sums(run, first_cycle, run.location, edges)
    return edges, upper, -lower


def impact_spectra(run, first_cycle, bins=72):
    """Eq 3.7 over j bins of the crank angle in [0, 2*pi): (bin edges, upper spectrum, lower spectrum), >= 0."""
    edges = np.linspace(0, CRANK_CYCLE, bins + 1)
    upper, lower = _per_wall_sums(run, first_cycle, run.theta, edges)
    return edges, upper, lower


def poincare_points(run, first_cycle):
    """Eq 3.4: (theta, psi') of the upper-wall impacts with psi' > 0."""
    mine = run.window(first_cycle) & (run.wall == 1) & (run.rate > 0)
    return run.theta[mine], run.rate[mine]


def summary(run, response, first_cycle):
    """One row of the summary table."""
    mask = run.window(first_cycle)
    cycles = run.cycles - first_cycle
    row = {"lambda": run.lam, "rho": run.rho, "e": run.e, "forcing": run.forcing, "response": str(response)}
    for name, wall in (("upper", 1), ("lower", -1)):
        mine = mask & (run.wall == wall)
        row[f"impacts_per_cycle_{name}"] = mine.sum() / cycles
        row[f"mean_impact_rate_{name}"] = float(np.abs(run.rate[mine]).mean()) if mine.any() else 0.0
    row["slides_per_cycle"] = (run.slide_cycle >= first_cycle).sum() / cycles
    thesis = THESIS_RESPONSES.get((run.lam, run.rho, run.e))
    row["thesis"] = thesis or "not stated"
    row["agrees"] = "" if thesis is None else ("yes" if response.kind == thesis else "no")
    return row


#: What each column of the summary table means (thesis units: rates are psi' in rad per rad of crank angle).
SUMMARY_LEGEND = {
    "lambda": "damping parameter λ (thesis eq 2.13)",
    "rho": "clearance ρ, half the diametral clearance over the rod length",
    "e": "coefficient of restitution",
    "forcing": "roller_forcing: 1 = f(τ) as printed in the thesis, 2 = corrected",
    "response": (
        "our classification from the first start (θ = 0): periodic (period in crank cycles, cycle where it "
        "settled), transient chaos (periodic only after 100 cycles) or chaos (no recurrence)"
    ),
    "impacts_per_cycle_upper": "impacts per crank cycle on the upper wall (ψ = ψ_max)",
    "mean_impact_rate_upper": "mean |ψ'| just before an upper-wall impact",
    "impacts_per_cycle_lower": "impacts per crank cycle on the lower wall (ψ = ψ_min)",
    "mean_impact_rate_lower": "mean |ψ'| just before a lower-wall impact",
    "slides_per_cycle": "sliding phases begun per crank cycle",
    "thesis": "the thesis's classification (sections 4.3, 4.4); 'not stated' where it shows the profile only",
    "agrees": "whether our response (first start) is the thesis's",
    "starts": "classifications over all starting crank angles (0 to 5 rad)",
    "periods": "period of each start's response in crank cycles (0 = none)",
    "reason": "why a run disagrees with the thesis",
}


#: Units of the summary's numeric columns (the others are text).
SUMMARY_UNITS = {
    "lambda": "1",
    "rho": "1",
    "e": "1",
    "forcing": "1",
    "impacts_per_cycle_upper": "1/cycle",
    "mean_impact_rate_upper": "rad/rad",
    "impacts_per_cycle_lower": "1/cycle",
    "mean_impact_rate_lower": "rad/rad",
    "slides_per_cycle": "1/cycle",
}


def disagreement_reason(row, response, kinds, cycles):
    """Why our classification of a run differs from the thesis's, from what the runs of `cycles` crank cycles
    from every start show; '' where they agree or the thesis states none."""
    thesis = THESIS_RESPONSES.get((row["lambda"], row["rho"], row["e"]))
    if thesis is None or response.kind == thesis:
        return ""
    if thesis in kinds:
        return (
            f"start-dependent: {kinds.count(thesis)} of {len(kinds)} starting crank angles give the thesis's "
            f"{thesis}; the thesis does not state its start"
        )
    if response.kind == "periodic" and thesis == "transient chaos":
        return (
            f"every start tried settles on a period (the first by cycle {response.settled}); a chaotic transient "
            "depends on the start, which the thesis does not state"
        )
    if response.kind == "transient chaos" and thesis == "periodic":
        return (
            f"the period appears only at cycle {response.settled}, after the {CHAOTIC_TRANSIENT} cycles allowed a "
            "transient; the thesis classified the run from its end"
        )
    if response.kind == "chaos" and "periodic" in kinds:
        return (
            f"coexisting responses: chaos from the first start over {cycles} cycles, a period from "
            f"{kinds.count('periodic')} of {len(kinds)} starts; the thesis does not state its start"
        )
    if response.kind == "chaos":
        return (
            f"no start tried recurs within {cycles} cycles (tolerance 1e-3); the thesis's {thesis} may need its own, "
            "unstated start, or a section read by eye looked settled"
        )
    return (
        f"every start tried ends on a period (periods {row['periods']} crank cycles; tolerance 1e-3); with "
        "roller_forcing = 1 the equations are the thesis's, so the integration or the thesis's reading of its "
        "Poincaré section differs: not resolved here"
    )


def summary_markdown(header, rows):
    """The summary table as markdown, followed by its legend."""
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += [
        "| " + " | ".join(f"{row[k]:.4g}" if isinstance(row[k], float) else str(row[k]) for k in header) + " |"
        for row in rows
    ]
    lines += ["", "Columns (thesis units: ψ' in rad per rad of crank angle):", ""]
    lines += [f"- `{name}`: {SUMMARY_LEGEND[name]}" for name in header]
    return "\n".join(lines) + "\n"


def write_csv(path, header, rows):
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(header)
        writer.writerows(rows)
    return path


def _case_name(run):
    return f"lam{run.lam:g}_rho{run.rho:g}_e{run.e:g}_f{run.forcing}"


def write_case(run, out, transient=30):
    """Classifies `run` and writes its impacts, profile, spectra and Poincare section as CSV and PNG."""
    from . import roller_plots

    out.mkdir(parents=True, exist_ok=True)
    name = _case_name(run)
    response = classify(run)
    write_csv(
        out / f"{name}_impacts.csv",
        [
            "cycle [1]",
            "theta [rad]",
            "wall [+1 upper, -1 lower]",
            "psi_rate [rad/rad]",
            "approach_rate [rad/rad]",
            "x [1]",
        ],
        zip(run.cycle, run.theta, run.wall, run.rate, run.approach, run.location, strict=True),
    )
    edges, upper, lower = impact_profile(run, transient)
    write_csv(
        out / f"{name}_profile.csv",
        ["x_from [1]", "x_to [1]", "upper [rad/rad]", "lower [rad/rad]"],
        zip(edges[:-1], edges[1:], upper, lower, strict=True),
    )
    sedges, supper, slower = impact_spectra(run, transient)
    write_csv(
        out / f"{name}_spectra.csv",
        ["theta_from [rad]", "theta_to [rad]", "upper [rad/rad]", "lower [rad/rad]"],
        zip(sedges[:-1], sedges[1:], supper, slower, strict=True),
    )
    title = f"λ={run.lam:g} ρ={run.rho:g} e={run.e:g}: {response}"
    roller_plots.case_sheet(
        poincare_points(run, transient), (edges, upper, lower), (sedges, supper, slower), title, out / f"{name}.png"
    )
    return response, summary(run, response, transient)


def constraint_force_csv(tool, lam, rho, forcing, samples=720):
    """f_u, f_l of eq 2.29 over one crank cycle, from the crate's `roller_forces` example at path `tool`."""
    return _run_tool(tool, ["cycle", str(lam), str(rho), str(forcing), str(samples)])


def sliding_regions_csv(tool, forcing, rho_max=0.03, lambda_max=0.4, n=120):
    """The regions of Fig 2.10 over (rho, lambda), from the crate's `roller_forces` example at path `tool`."""
    return _run_tool(tool, ["regions", str(forcing), str(rho_max), str(lambda_max), str(n)])


def _run_tool(tool, args):
    text = subprocess.run([str(tool), *args], check=True, capture_output=True, text=True).stdout
    rows = list(csv.reader(text.splitlines()))
    return rows[0], rows[1:]


#: Figures 2.4-2.9: (rho, lambda) of each constraint-force plot.
FORCE_FIGURES = {
    "2.4": (0.01, 0.01),
    "2.5": (0.01, 0.1),
    "2.6": (0.01, 0.25),
    "2.7": (0.02, 0.267),
    "2.9": (0.01, 0.35),
}


def write_forces(out, tool):
    """Constraint forces of Figs 2.4-2.9 and the region map of Fig 2.10, both forms of f, as CSV and PNG;
    `tool` is the crate's built `roller_forces` example."""
    from . import roller_plots

    out.mkdir(parents=True, exist_ok=True)
    curves = {}
    for fig, (rho, lam) in FORCE_FIGURES.items():
        for forcing in (1, 2):
            header, rows = constraint_force_csv(tool, lam, rho, forcing)
            write_csv(out / f"forces_fig{fig}_f{forcing}.csv", header, rows)
            curves[fig, forcing] = np.array(rows, dtype=float)
    regions = {}
    for forcing in (1, 2):
        header, rows = sliding_regions_csv(tool, forcing)
        write_csv(out / f"sliding_regions_f{forcing}.csv", header, rows)
        regions[forcing] = rows
    return roller_plots.forces_sheet(FORCE_FIGURES, curves, regions, out / "constraint_forces.png")


#: Chapter 4's runs as full-factorial (lambdas, rhos, restitutions) grids: both 3x3 (lambda, rho) grids at e = 0.9,
#: then e = 0.7, 0.5 at (0.05, 0.02).
THESIS_GRIDS = (((0.025, 0.05, 0.075, 0.15, 0.20, 0.25), (0.010, 0.015, 0.020), (0.9,)), ((0.05,), (0.02,), (0.7, 0.5)))
THESIS_RUNS = [run for grid in THESIS_GRIDS for run in itertools.product(*grid)]


#: Starting crank angles of the runs that test how the classification depends on the start (rad).
STARTS = (0.0, 1.0, 2.0, 3.0, 4.0, 5.0)


def thesis_sweeps(cycles, forcing, starts, model_description):
    """THESIS_GRIDS from the starting crank angles `starts` as sweep specs of `cycles` crank cycles, and the (lambda,
    rho) of each bore they sweep."""
    from .sweep_spec import parse

    swept = ("damping_crank_pin", "bore", "restitution", "crank_angle_start")
    fixed = {k: v for k, v in thesis_start_values(0.0, 0.0, 0.0, forcing).items() if k not in swept}
    specs, rhos = [], {}
    for i, (lams, grid_rhos, es) in enumerate(THESIS_GRIDS):
        bores = [thesis_start_values(0.0, rho, 0.0)["bore"] for rho in grid_rhos]
        rhos.update(zip(bores, grid_rhos, strict=True))
        raw = dict(
            name=f"thesis{i + 1}_f{forcing}_{cycles}cycles",
            cycles=cycles,
            skip_cycles=0,
            start=fixed,
            grid=dict(zip(swept, (list(lams), bores, list(es), list(starts)), strict=True)),
        )
        specs.append(parse(raw, model_description))
    return specs, rhos


def write_thesis(out, client, transient=30, cycles=1500, forcing=1, starts=STARTS):
    """Chapter 4: every run of THESIS_RUNS with `transient` + `cycles` crank cycles from each of `starts`, swept on
    the Dask `client`'s workers (into out/sweeps, resumable); a summary table (CSV and markdown) and figure sheets
    of the impact profiles and Poincare sections of the runs from the first start, run here."""
    from . import roller_plots
    from .sweep import run as run_sweep

    out.mkdir(parents=True, exist_ok=True)
    # the same cases from the other starting crank angles (transients, coexisting attractors), on the cluster
    specs, rhos = thesis_sweeps(transient + cycles, forcing, starts[1:], fmpy.read_model_description(str(fmu_path())))
    others = {}
    for spec in specs if len(starts) > 1 else ():
        path, _ = run_sweep(spec, out / "sweeps", client)
        for row in pq.read_table(path).to_pylist():
            key = (row["damping_crank_pin"], rhos[row["bore"]], row["restitution"])
            others.setdefault(key, {})[row["crank_angle_start"]] = Response(
                row["response"], row["period"], row["settled"]
            )
    runs, rows = [], []
    for lam, rho, e in THESIS_RUNS:
        run = simulate_case(lam, rho, e, forcing, transient + cycles)
        response, row = write_case(run, out / "cases", transient)
        responses = [response] + [others[lam, rho, e][s] for s in starts[1:]]
        kinds = [r.kind for r in responses]
        row["starts"] = ", ".join(
            f"{kinds.count(k)}× {k}" for k in ("periodic", "transient chaos", "chaos") if k in kinds
        )
        row["periods"] = " ".join(str(r.period) for r in responses)
        row["reason"] = disagreement_reason(row, response, kinds, transient + cycles)
        print(
            f"lambda={lam} rho={rho} e={e}: {response} (thesis: {row['thesis']}); "
            f"over {len(kinds)} starts: {row['starts']}"
        )
        runs.append((run, response))
        rows.append(row)
    header = list(rows[0])
    units = [f"{k} [{SUMMARY_UNITS[k]}]" if k in SUMMARY_UNITS else k for k in header]
    write_csv(out / "summary.csv", units, [[row[k] for k in header] for row in rows])
    (out / "summary.md").write_text(summary_markdown(header, rows))
    sheet = roller_plots.thesis_sheet(
        [(run, response, impact_profile(run, transient), poincare_points(run, transient)) for run, response in runs],
        out / "thesis_sheet.png",
    )
    return out / "summary.md", sheet


#: An engine-sized roller slider crank for the cross-check (FMU defaults where they apply).
_CROSS = dict(
    crank_mode=1,
    crank_radius=0.04,
    rod_length=0.15,
    rod_mass=1.0,
    piston_mass=0.4,
    rod_inertia=0.0075,
    damping_crank_pin=0.00576,
    damping_piston_pin=0.0,
    piston_diameter=0.08,
    restitution=0.5,
    gravity=0.0,
    crank_speed=125.66,
    crank_angle_start=0.0,
)


def _cross_sequence(events, corners, min_speed):
    """Impacts faster than `min_speed` and releases, on `corners`: the part of a run that the variants share
    (the tails of impact accumulations end in sliding by different thresholds)."""
    keep = ((events["kind"] == "impact") & (events["normal_velocity_before"] > min_speed)) | (
        events["kind"] == "release"
    )
    events = events[keep & np.isin(events["corner"], corners)]
    # a contact released, re-closed and released again at one instant is one release here
    repeat = np.r_[
        False, (events["kind"][1:] == "release") & (events["kind"][:-1] == "release") & (np.diff(events["time"]) < 1e-9)
    ]
    return events[~repeat]


def cross_check(clearance, stop_time=0.05, min_speed=2e-3):
    """Variant 1 in the roller limit against variant 2 with roller_forcing = 2: the piston of
    variant 1 reduced to a short block (skirt 12 mm, pin in its middle, the least tilt inertia accepted; variant 1 needs
    a piston diagonal longer than the bore) on a uniform rod, no gravity, gas force or piston-pin damping.

    Returns (variant-1 sequence, variant-2 sequence) of impacts and releases on corner 1, the x = -D/2 wall
    in both variants (the thesis's upper wall, toward which the crank pin swings after TDC)."""
    common = dict(_CROSS, bore=_CROSS["piston_diameter"] + 2 * clearance)
    crank_train = dict(
        common,
        model_variant=1,
        skirt_length=0.012,
        pin_height=0.006,
        piston_com=0.0,
        rod_com=common["rod_length"] / 2,
        # The least tilt inertia the declared space accepts: a radius of gyration of 0.05 piston diameters.
        piston_inertia=common["piston_mass"] * (0.05 * common["piston_diameter"]) ** 2,
        pressure_source=1,
        gas_pressure=0.0,
    )
    roller = dict(common, model_variant=2, roller_forcing=2)
    runs = [
        simulate_with_events(start_values=values, stop_time=stop_time, output_interval=1e-3, output=["impact_count"])[1]
        for values in (crank_train, roller)
    ]
    return tuple(_cross_sequence(run, (1,), min_speed) for run in runs)


def check(args):
    """Refuses arguments no run can take, before anything runs; a case's parameters the FMU checks itself."""
    for name in ("transient", "cycles"):
        if getattr(args, name, 1) < (0 if name == "transient" else 1):
            raise Refusal(f"--{name} = {getattr(args, name)}: give a whole number >= {0 if name == 'transient' else 1}")
    if args.command == "case":
        check_start_values(thesis_start_values(args.lam, args.rho, args.e, args.forcing), fmu_path())
    elif args.command == "crosscheck":
        for clearance in args.clearance:
            number(clearance, "--clearance", low=0, low_open=True)
    elif args.command == "forces" and not args.forces_tool.is_file():
        raise Refusal(f"--forces-tool {args.forces_tool}: no such file (cargo build --release --example roller_forces)")
    elif args.command == "thesis" and args.scheduler is None and args.workers < 1:
        raise Refusal(f"--workers = {args.workers}: give at least 1")


def main(argv=None):
    parser = Parser(prog="pistonslap analysis", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    case = sub.add_parser("case", help="one run: impacts, Poincare section, impact profile and spectra")
    case.add_argument("--lam", type=float, required=True, help="damping parameter lambda")
    case.add_argument("--rho", type=float, required=True, help="clearance rho")
    case.add_argument("--e", type=float, default=0.9, help="coefficient of restitution")
    for p in (case, sub.add_parser("thesis", help="chapter 4: 20 runs, summary table, figure sheets")):
        p.add_argument("--forcing", type=int, default=1, choices=(1, 2), help="roller_forcing (1 = as printed)")
        p.add_argument("--transient", type=int, default=30, help="crank cycles before the statistics")
        p.add_argument("--cycles", type=int, default=1500, help="crank cycles of statistics")
    thesis = sub.choices["thesis"]
    thesis.add_argument(
        "--starts",
        type=float,
        nargs="+",
        default=list(STARTS),
        help="starting crank angles (rad); statistics and figures from the first",
    )
    where = thesis.add_mutually_exclusive_group()
    where.add_argument(
        "--workers",
        type=int,
        default=os.cpu_count(),
        help="Dask worker processes for the runs from the other starts (default: all cores)",
    )
    where.add_argument("--scheduler", help="address of a running Dask scheduler to use instead")
    forces = sub.add_parser("forces", help="constraint forces (Figs 2.4-2.9) and sliding regions (Fig 2.10)")
    forces.add_argument(
        "--forces-tool",
        type=Path,
        required=True,
        help="the built roller_forces example (target/release/examples/roller_forces)",
    )
    cross = sub.add_parser("crosscheck", help="variant 1 in the roller limit against variant 2 (roller_forcing = 2)")
    cross.add_argument(
        "--clearance", type=float, nargs="+", default=[10e-6, 20e-6, 40e-6, 80e-6, 160e-6, 320e-6], help="m"
    )
    for p in sub.choices.values():
        p.add_argument("--out", type=Path, default=Path("out/thesis"), help="output folder")
    args = parser.parse_args(argv)
    check(args)

    if args.command == "case":
        run = simulate_case(args.lam, args.rho, args.e, args.forcing, args.transient + args.cycles)
        response, row = write_case(run, args.out, args.transient)
        print(f"{response}; {row}")
    elif args.command == "crosscheck":
        for clearance in args.clearance:
            crank_train, roller = cross_check(clearance)
            n = min(len(crank_train), len(roller))
            same = len(crank_train) == len(roller) and np.all(crank_train["kind"] == roller["kind"])
            impacts = crank_train["kind"][:n] == "impact"
            speed = np.abs(
                crank_train["normal_velocity_before"][:n][impacts] / roller["normal_velocity_before"][:n][impacts] - 1
            )
            angle = np.abs(crank_train["time"][:n] - roller["time"][:n]) * _CROSS["crank_speed"]
            print(
                f"clearance {clearance * 1e6:g} um: {len(crank_train)} / {len(roller)} events, same sequence {same}; "
                f"largest crank-angle difference {angle.max():.1e} rad, "
                f"relative impact-velocity difference {speed.max():.1e}"
            )
    elif args.command == "forces":
        print(f"wrote {write_forces(args.out, args.forces_tool)}")
    else:
        from .sweep import connect

        with connect(args.workers, args.scheduler) as client:
            for path in write_thesis(args.out, client, args.transient, args.cycles, args.forcing, args.starts):
                print(f"wrote {path}")


if __name__ == "__main__":
    main()
